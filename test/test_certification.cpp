// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact angle certification: hand-built boundary cases, the filter against the
// exact path, and whole meshes against an independent rational oracle.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/nonobtuse_remeshing.h>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/cpp_int.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>

namespace NR = CGAL::Nonobtuse_remeshing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Rational = boost::multiprecision::cpp_rational;
using Big_float = boost::multiprecision::cpp_bin_float_50;

namespace {

Mesh triangle(const Point& a, const Point& b, const Point& c)
{
  Mesh m;
  m.add_face(m.add_vertex(a), m.add_vertex(b), m.add_vertex(c));
  return m;
}

// Oracle: the angle at `apex` in degrees, with 50 significant digits (the
// corner vectors are exact differences of doubles, taken in rationals).
Big_float oracle_angle(const Point& apex, const Point& p, const Point& q)
{
  Rational u[3], v[3];
  for(int i = 0; i < 3; ++i) {
    u[i] = Rational(p[i]) - Rational(apex[i]);
    v[i] = Rational(q[i]) - Rational(apex[i]);
  }
  const Rational d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const Rational l = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  const Big_float cosine = Big_float(d) / sqrt(Big_float(l));
  return acos(cosine) * 180 / boost::math::constants::pi<Big_float>();
}

double ulp_step(double x, int direction)
{
  return std::nextafter(x, direction > 0 ? HUGE_VAL : -HUGE_VAL);
}

} // namespace

TEST(AngleCertification, RightIsoscelesWithDyadicCoordinatesPasses)
{
  const Point a(0.375, 1.25, -2.5), b(1.375, 1.25, -2.5), c(0.375, 2.25, -2.5);
  const auto cert = NR::certify_angle_bounds(triangle(a, b, c));
  EXPECT_TRUE(cert.is_certified());
  EXPECT_EQ(cert.too_large_corners, 0u);
  EXPECT_EQ(cert.max_angle, 90.);
  EXPECT_EQ(cert.min_angle, 45.);
}

TEST(AngleCertification, OneUlpTurnsTheRightAngleObtuseOrAcute)
{
  const Point a(0.375, 1.25, -2.5), b(1.375, 1.25, -2.5);
  // Moving c by one ulp in x opens or closes the right angle at a.
  const Point obtuse(ulp_step(0.375, -1), 2.25, -2.5);
  const auto bad = NR::certify_angle_bounds(triangle(a, b, obtuse));
  EXPECT_FALSE(bad.is_certified());
  EXPECT_EQ(bad.too_large_corners, 1u);
  EXPECT_EQ(bad.too_small_corners, 0u);
  ASSERT_EQ(bad.offending_faces.size(), 1u);
  EXPECT_GT(oracle_angle(a, b, obtuse), Big_float(90));

  const Point acute(ulp_step(0.375, +1), 2.25, -2.5);
  const auto good = NR::certify_angle_bounds(triangle(a, b, acute));
  EXPECT_TRUE(good.is_certified());
  EXPECT_LT(oracle_angle(a, b, acute), Big_float(90));
}

// A = 0, u = (1,1,0), v = (1,2,1): u.v = 3, |u|^2 |v|^2 = 12, cos^2 = 3/4, so
// the angle at A is exactly 30 degrees. With B = 1.5 u the triangle is an
// exact 30-60-90 triangle; with B = 1.75 u the other two angles are inside.
TEST(AngleCertification, ExactThirtySixtyNinetyTriangle)
{
  const Point a(0, 0, 0), b(1.5, 1.5, 0), c(1, 2, 1);
  const Mesh m = triangle(a, b, c);
  EXPECT_TRUE(NR::certify_angle_bounds(m).is_certified());
  const auto strict = NR::certify_angle_bounds(m, NR::parameters::min_angle(30.0001));
  EXPECT_FALSE(strict.is_certified());
  EXPECT_EQ(strict.too_small_corners, 1u);
  EXPECT_FALSE(strict.bounds_exact);
  // Just below the right angle is too strict as well.
  EXPECT_EQ(NR::certify_angle_bounds(m, NR::parameters::max_angle(89.9999)).too_large_corners, 1u);
}

TEST(AngleCertification, ThirtyDegreeCornerAcceptedExactlyWhenAtLeastThirty)
{
  const Point a(0, 0, 0), b(1.75, 1.75, 0);
  const double c0[3] = {1, 2, 1};
  int accepted = 0, rejected = 0;
  for(int k = 0; k < 3; ++k)
    for(int direction : {-1, +1}) {
      double moved[3] = {c0[0], c0[1], c0[2]};
      moved[k] = ulp_step(moved[k], direction);
      const Point c(moved[0], moved[1], moved[2]);
      const Big_float angle = oracle_angle(a, b, c);
      ASSERT_NE(angle, Big_float(30)) << "a one-ulp move must leave the exact boundary";
      const bool truly_within = angle > 30 && oracle_angle(b, c, a) <= 90 && oracle_angle(c, a, b) <= 90;
      const auto cert = NR::certify_angle_bounds(triangle(a, b, c));
      EXPECT_EQ(cert.is_certified(), truly_within) << "coordinate " << k << " direction " << direction;
      (truly_within ? accepted : rejected) += 1;
    }
  EXPECT_GT(accepted, 0);  // both sides of the boundary were built
  EXPECT_GT(rejected, 0);
  EXPECT_TRUE(NR::certify_angle_bounds(triangle(a, b, Point(1, 2, 1))).is_certified());
}

// u = (a, a, 0) and v = (a, -a, 0) with a = 1 + 2^-30 are exactly orthogonal,
// but a*a is not a double: intervals cannot decide u.v >= 0, the exact path
// must.
TEST(AngleCertification, ExactPathDecidesWhatIntervalsCannot)
{
  const double a = 1. + std::ldexp(1., -30);
  const double o[3] = {0, 0, 0}, b[3] = {a, a, 0}, c[3] = {a, -a, 0};
  const NR::Angle_bounds bounds;
  {
    CGAL::Protect_FPU_rounding<true> protection;
    EXPECT_THROW(NR::internal::triangle_verdict_with<CGAL::Interval_nt_advanced>({o, b, c}, bounds),
                 CGAL::Uncertain_conversion_exception);
  }
  EXPECT_TRUE(NR::internal::triangle_verdict({o, b, c}, bounds).within_bounds());
  // one ulp further apart: obtuse at the origin; one ulp closer: acute
  const double wide[3] = {a, -ulp_step(a, +1), 0}, narrow[3] = {a, -ulp_step(a, -1), 0};
  const auto obtuse = NR::internal::triangle_verdict({o, b, wide}, bounds);
  EXPECT_TRUE(obtuse.corners[0].too_large);
  EXPECT_FALSE(NR::internal::triangle_verdict({o, b, narrow}, bounds).corners[0].too_large);
}

TEST(AngleCertification, PolygonMeshesAreRefused)
{
  Mesh quad;
  quad.add_face(quad.add_vertex(Point(0, 0, 0)), quad.add_vertex(Point(1, 0, 0)),
                quad.add_vertex(Point(1, 1, 0)), quad.add_vertex(Point(0, 1, 0)));
  EXPECT_THROW(NR::certify_angle_bounds(quad), NR::Bad_input);
}

TEST(AngleCertification, HugeAndTinyCoordinatesMeasureCorrectly)
{
  for(double scale : {1e-170, 1e170}) {
    const auto cert = NR::certify_angle_bounds(
        triangle(Point(0, 0, 0), Point(scale, 0, 0), Point(0, scale, 0)));
    EXPECT_TRUE(cert.is_certified());
    EXPECT_EQ(cert.max_angle, 90.) << scale;
    EXPECT_NEAR(cert.min_angle, 45., 1e-12) << scale;
  }
}

TEST(AngleCertification, DegenerateFacesFail)
{
  // zero area: three collinear points; angles 0, 0 and 180 would pass [0, 180]
  const auto flat = NR::certify_angle_bounds(triangle(Point(0, 0, 0), Point(1, 1, 1), Point(2, 2, 2)),
                                             NR::parameters::combine(NR::parameters::min_angle(0.),
                                                                     NR::parameters::max_angle(180.)));
  EXPECT_FALSE(flat.is_certified());
  EXPECT_EQ(flat.degenerate_faces, 1u);
  // zero-length edge
  const auto pinched = NR::certify_angle_bounds(triangle(Point(0, 0, 0), Point(0, 0, 0), Point(1, 0, 0)));
  EXPECT_FALSE(pinched.is_certified());
  EXPECT_EQ(pinched.degenerate_faces, 1u);
  // an empty mesh certifies nothing
  EXPECT_FALSE(NR::certify_angle_bounds(Mesh()).is_certified());
}

TEST(AngleCertification, InvalidBoundsAreRejected)
{
  EXPECT_THROW(NR::Angle_bounds(95., 90.), NR::Bad_parameter);
  EXPECT_THROW(NR::Angle_bounds(-1., 90.), NR::Bad_parameter);
  EXPECT_THROW(NR::Angle_bounds(30., 181.), NR::Bad_parameter);
  EXPECT_THROW(NR::Angle_bounds(std::nan(""), 90.), NR::Bad_parameter);
}

// The exactly tested bounds and the conservatively rounded ones agree with the
// oracle on random triangles; the filtered predicate agrees with the exact
// path everywhere, including right at the boundaries.
TEST(AngleCertification, FilteredPredicateMatchesExactAndOracle)
{
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> coordinate(-1., 1.);
  std::uniform_int_distribution<int> ulps(-2, 2);
  const double bound_pairs[][2] = {{30, 90}, {35, 85}, {20, 120}, {45, 135}, {0, 180}, {33.3, 91.7}};
  int decided_by_oracle = 0, decided_in_doubles = 0;
  for(const auto& pair : bound_pairs) {
    const NR::Angle_bounds bounds(pair[0], pair[1]);
    for(int trial = 0; trial < 3000; ++trial) {
      Point p[3];
      if(trial % 2 == 0) {
        for(Point& q : p) q = Point(coordinate(rng), coordinate(rng), coordinate(rng));
      } else {
        // the exact 30-60-90 triangle, scaled by a power of two, translated on
        // a dyadic lattice, with a few ulps of noise
        const double s = std::ldexp(1., int(rng() % 20) - 10);
        const double t[3] = {std::ldexp(double(rng() % 64), -3), std::ldexp(double(rng() % 64), -3), 0.5};
        const double base[3][3] = {{0, 0, 0}, {1.5, 1.5, 0}, {1, 2, 1}};
        for(int i = 0; i < 3; ++i) {
          double c[3];
          for(int k = 0; k < 3; ++k) {
            c[k] = base[i][k] * s + t[k];
            for(int n = ulps(rng); n != 0; n -= (n > 0 ? 1 : -1)) c[k] = ulp_step(c[k], n);
          }
          p[i] = Point(c[0], c[1], c[2]);
        }
      }
      const double raw[3][3] = {{p[0].x(), p[0].y(), p[0].z()},
                                {p[1].x(), p[1].y(), p[1].z()},
                                {p[2].x(), p[2].y(), p[2].z()}};
      const std::array<const double*, 3> t = {raw[0], raw[1], raw[2]};
      const auto filtered = NR::internal::triangle_verdict(t, bounds);
      const auto exact = NR::internal::triangle_verdict_with<CGAL::Exact_rational>(t, bounds);
      if(NR::internal::surely_within_bounds(t, bounds)) {
        ASSERT_TRUE(exact.within_bounds()) << "the double filter accepted a triangle outside the bounds";
        ++decided_in_doubles;
      }
      ASSERT_EQ(filtered.degenerate, exact.degenerate);
      for(int i = 0; i < 3 && !exact.degenerate; ++i) {
        ASSERT_EQ(filtered.corners[i].too_small, exact.corners[i].too_small);
        ASSERT_EQ(filtered.corners[i].too_large, exact.corners[i].too_large);
        // Conservative: never accept a corner that the oracle puts outside the
        // requested bounds; agree with it away from the 1e-9 degree band.
        const Big_float angle = oracle_angle(p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
        if(angle < pair[0]) ASSERT_TRUE(exact.corners[i].too_small);
        if(angle > pair[1]) ASSERT_TRUE(exact.corners[i].too_large);
        if(angle > pair[0] + 1e-9) { ASSERT_FALSE(exact.corners[i].too_small); ++decided_by_oracle; }
        if(angle < pair[1] - 1e-9) ASSERT_FALSE(exact.corners[i].too_large);
      }
    }
  }
  EXPECT_GT(decided_by_oracle, 10000);
  EXPECT_GT(decided_in_doubles, 1000);  // the filter does decide the clear cases
}

// The double filter leaves to the exact path what it cannot bound: scales
// where products would overflow or underflow, exact right angles, and
// angles a few ulps from a bound.
TEST(AngleCertification, DoubleFilterDefersAtExtremesAndBoundaries)
{
  const NR::Angle_bounds bounds;
  const double base[3][3] = {{0, 0, 0}, {2, 0.1, 0}, {1, 1.5, 0.2}};  // well inside [30, 90]
  for(int exponent : {-1000, -700, -300, -150, 0, 150, 300, 700, 1000}) {
    double c[3][3];
    for(int i = 0; i < 3; ++i)
      for(int k = 0; k < 3; ++k) c[i][k] = std::ldexp(base[i][k], exponent);
    const std::array<const double*, 3> t = {c[0], c[1], c[2]};
    const bool in_range = exponent >= -150 && exponent <= 150;
    EXPECT_EQ(NR::internal::surely_within_bounds(t, bounds), in_range) << "2^" << exponent;
    EXPECT_EQ(NR::internal::triangle_verdict(t, bounds).within_bounds(),
              NR::internal::triangle_verdict_with<CGAL::Exact_rational>(t, bounds).within_bounds())
        << "2^" << exponent;
  }
  const double o[3] = {0, 0, 0}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0};  // exactly 90 degrees at o
  EXPECT_FALSE(NR::internal::surely_within_bounds({o, x, y}, bounds));
  EXPECT_TRUE(NR::internal::triangle_verdict({o, x, y}, bounds).within_bounds());
  const double a = 1. + std::ldexp(1., -30), b[3] = {a, a, 0}, narrow[3] = {a, -ulp_step(a, -1), 0};
  EXPECT_FALSE(NR::internal::surely_within_bounds({o, b, narrow}, bounds));  // 90 degrees minus an ulp
}

// Whole meshes: counts of corners out of [30, 90] from an independent exact
// rational evaluation (boost cpp_rational), and the angle range in long double.
class MeshCertification : public ::testing::TestWithParam<std::string> {};

TEST_P(MeshCertification, AgreesWithIndependentEvaluation)
{
  Mesh mesh;
  NR::read_triangle_mesh(std::string(NONOBTUSE_TEST_DATA) + "/" + GetParam(), mesh);
  std::size_t too_small = 0, too_large = 0, bad_faces = 0;
  long double lo = 180, hi = 0;
  for(auto f : faces(mesh)) {
    Point p[3];
    int i = 0;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) p[i++] = mesh.point(v);
    bool bad = false;
    for(i = 0; i < 3; ++i) {
      const Point &a = p[i], &b = p[(i + 1) % 3], &c = p[(i + 2) % 3];
      Rational u[3], v[3];
      for(int k = 0; k < 3; ++k) { u[k] = Rational(b[k]) - Rational(a[k]); v[k] = Rational(c[k]) - Rational(a[k]); }
      const Rational d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
      const Rational l = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      const bool small = d > 0 && 4 * d * d > 3 * l;  // cos > sqrt(3)/2
      const bool large = d < 0;                        // cos < 0
      too_small += small;
      too_large += large;
      bad = bad || small || large;
      long double uu[3], vv[3];
      for(int k = 0; k < 3; ++k) { uu[k] = (long double)b[k] - a[k]; vv[k] = (long double)c[k] - a[k]; }
      const long double dot = uu[0] * vv[0] + uu[1] * vv[1] + uu[2] * vv[2];
      const long double cx = uu[1] * vv[2] - uu[2] * vv[1], cy = uu[2] * vv[0] - uu[0] * vv[2],
                        cz = uu[0] * vv[1] - uu[1] * vv[0];
      const long double angle = std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot) * 180 / 3.14159265358979323846264338327950288L;
      lo = std::min(lo, angle);
      hi = std::max(hi, angle);
    }
    bad_faces += bad;
  }
  const auto cert = NR::certify_angle_bounds(mesh);
  EXPECT_EQ(cert.faces, num_faces(mesh));
  EXPECT_EQ(cert.too_small_corners, too_small);
  EXPECT_EQ(cert.too_large_corners, too_large);
  EXPECT_EQ(cert.degenerate_faces, 0u);
  EXPECT_EQ(cert.offending_faces.size(), bad_faces);
  EXPECT_EQ(cert.is_certified(), bad_faces == 0);
  EXPECT_NEAR(cert.min_angle, double(lo), 1e-9);
  EXPECT_NEAR(cert.max_angle, double(hi), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(SampleMeshes, MeshCertification,
                         ::testing::Values("sphere.off", "cube-meshed.off", "pig.off",
                                           "nefertiti.off", "rotor.off"),
                         [](const auto& info) {
                           std::string name = info.param.substr(0, info.param.find('.'));
                           for(char& ch : name) if(ch == '-') ch = '_';
                           return name;
                         });
