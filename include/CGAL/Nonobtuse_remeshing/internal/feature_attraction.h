// SPDX-License-Identifier: GPL-3.0-or-later
//
// Feature attraction in deform-to-fit (beyond the thesis): the input's
// vertices and points along its sharp and border edges (the feature samples
// of closest_triangle.h) each attract their nearest mesh vertex, so that the
// fitted mesh keeps the input's tips, creases and border corners. This finds
// the owner of each sample; the optimizer adds the attraction to the owner's
// objective (fit_objective.h).

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_FEATURE_ATTRACTION_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_FEATURE_ATTRACTION_H

#include <CGAL/Nonobtuse_remeshing/internal/epick_points.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// Builds `tree` on the pool's workers: the same tree on any number.
template <typename Tree, typename Pool>
void build(Tree& tree, const Pool& pool)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(pool.workers() > 1) {
    tree.template build<Parallel_tag>();
    return;
  }
#endif
  (void)pool;
  tree.template build<Sequential_tag>();
}

// The owner of every feature sample as the mesh's vertices move: its
// nearest vertex (the lowest index among equally near ones), or, for a
// border sample, the nearest of the vertices flagged as fitting the input's
// border (a border sample has none when no vertex is flagged).
//
// Between two calls most vertices keep their place. A sample whose owner did
// not move can then only pass to a vertex that moved and is now at most as
// near: each moved vertex looks for such samples in a search tree over the
// samples, built once. The other samples search the trees over the vertices,
// which are rebuilt only when a vertex has moved farther than `reach` since
// they were built. Until then, with m the farthest move since, a sample's
// nearest vertex now is within its nearest distance then plus m, so it was
// within that distance plus 2m then, and a range search of the old tree
// finds it. The owners are exact either way.
class Feature_sample_owners
{
  using Point = Epick::Point_3;
  using Traits = Search_traits_3<Epick>;
  using Point_map = typename Pointer_property_map<Point>::const_type;
  using Adapter = Search_traits_adapter<std::size_t, Point_map, Traits>;
  using Distance = Distance_adapter<std::size_t, Point_map, Euclidean_distance<Traits> >;
  using Search = Orthogonal_k_neighbor_search<Adapter, Distance>;
  using Tree = typename Search::Tree;
  using Sphere = Fuzzy_sphere<Adapter>;

public:
  Feature_sample_owners(const std::vector<std::pair<Point, bool> >& samples, const std::vector<bool>& on_border,
                        double reach)
    : samples_(samples), on_border_(on_border), reach_(reach), nearest_(samples.size()),
      squared_(samples.size(), 0.)
  {
    for(const auto& sample : samples_) sample_points_.push_back(sample.first);
    const std::vector<Point>& sample_points = sample_points_;
    sample_map_ = make_property_map(sample_points);
    std::vector<std::size_t> group[2];
    for(std::size_t s = 0; s < samples_.size(); ++s) group[samples_[s].second ? 1 : 0].push_back(s);
    for(int g = 0; g < 2; ++g)
      if(!group[g].empty()) {
        sample_trees_[g] =
            std::make_unique<Tree>(group[g].begin(), group[g].end(), typename Tree::Splitter(), Adapter(sample_map_));
        sample_trees_[g]->template build<Sequential_tag>();
      }
  }

  /// (vertex, sample) for every sample with an owner, sorted, for the
  /// vertices at `points`; the samples that are not kept are searched for
  /// in parallel.
  template <typename Pool>
  std::vector<std::pair<std::size_t, std::size_t> > operator()(const std::vector<Point>& points, Pool& pool)
  {
    double move = 0.;
    if(built_.size() == points.size())
      for(std::size_t i = 0; i < points.size(); ++i)
        move = (std::max)(move, CGAL::squared_distance(points[i], built_[i]));
    move = std::sqrt(move);
    const bool rebuild = built_.size() != points.size() || !(move <= reach_);
    if(rebuild) build_trees(points, pool);
    const std::size_t none = points.size();
    // The kept samples: their owner did not move, so it stays unless a moved
    // vertex comes as near (none after a rebuild, which searches them all).
    std::vector<bool> kept(samples_.size(), false);
    if(!rebuild) update_kept_samples(points, kept, pool);
    pool.for_each(samples_.size(), [&](std::size_t s, int) {
      if(kept[s]) return;
      nearest_[s] = none;
      const Tree* tree = samples_[s].second ? border_.get() : all_.get();
      if(!tree) return;
      if(rebuild) {
        const Search search(*tree, samples_[s].first, 1, 0., true, Distance(map_));
        nearest_[s] = search.begin()->first;
        distance_[s] = std::sqrt(search.begin()->second);
        squared_[s] = CGAL::squared_distance(points[nearest_[s]], samples_[s].first);
        return;
      }
      std::vector<std::size_t> candidates;
      const double radius = distance_[s] + 2. * move;
      tree->search(std::back_inserter(candidates), Sphere(samples_[s].first, radius * (1. + 1e-9) + 1e-300, 0.,
                                                          Adapter(map_)));
      double best = std::numeric_limits<double>::infinity();
      for(std::size_t c : candidates) {
        const double d = CGAL::squared_distance(points[c], samples_[s].first);
        if(d < best || (d == best && c < nearest_[s])) {
          best = d;
          nearest_[s] = c;
        }
      }
      squared_[s] = best;
    });
    last_ = points;
    std::vector<std::pair<std::size_t, std::size_t> > owner;
    owner.reserve(samples_.size());
    for(std::size_t s = 0; s < samples_.size(); ++s)
      if(nearest_[s] != none) owner.emplace_back(nearest_[s], s);
    std::sort(owner.begin(), owner.end());
    return owner;
  }

private:
  // Marks the kept samples and hands each to the nearest of its owner and
  // the moved vertices (the lowest index among equally near ones): a
  // moved vertex searches the samples within the farthest kept owner's
  // distance of its group.
  template <typename Pool>
  void update_kept_samples(const std::vector<Point>& points, std::vector<bool>& kept, Pool& pool)
  {
    std::vector<bool> moved(points.size());
    std::vector<std::size_t> movers;
    for(std::size_t i = 0; i < points.size(); ++i) {
      moved[i] = !(points[i] == last_[i]);
      if(moved[i]) movers.push_back(i);
    }
    double farthest[2] = {-1., -1.};  // squared, per group (off and on the border); -1: no kept sample
    for(std::size_t s = 0; s < samples_.size(); ++s)
      if(nearest_[s] != points.size() && !moved[nearest_[s]]) {
        kept[s] = true;
        double& f = farthest[samples_[s].second ? 1 : 0];
        f = (std::max)(f, squared_[s]);
      }
    // the searches on the workers, the hand-overs in the movers' order (a
    // sample goes to the nearest, the lowest index among equally near ones,
    // whatever the order)
    std::vector<std::vector<std::pair<std::size_t, double> > > near(movers.size());
    pool.for_each(movers.size(), [&](std::size_t j, int) {
      const std::size_t c = movers[j];
      std::vector<std::size_t> found;
      for(int g = 0; g < 2; ++g) {
        if(farthest[g] < 0. || (g == 1 && !on_border_[c])) continue;  // border samples: border vertices only
        found.clear();
        const double radius = std::sqrt(farthest[g]) * (1. + 1e-9) + 1e-300;
        sample_trees_[g]->search(std::back_inserter(found), Sphere(points[c], radius, 0., Adapter(sample_map_)));
        for(std::size_t s : found)
          if(kept[s]) near[j].emplace_back(s, CGAL::squared_distance(points[c], samples_[s].first));
      }
    });
    for(std::size_t j = 0; j < movers.size(); ++j)
      for(const auto& [s, d] : near[j])
        if(d < squared_[s] || (d == squared_[s] && movers[j] < nearest_[s])) {
          nearest_[s] = movers[j];
          squared_[s] = d;
        }
  }

  template <typename Pool>
  void build_trees(const std::vector<Point>& points, Pool& pool)
  {
    built_ = points;
    const std::vector<Point>& built = built_;
    map_ = make_property_map(built);
    std::vector<std::size_t> everywhere, on_border;
    for(std::size_t i = 0; i < built_.size(); ++i) {
      everywhere.push_back(i);
      if(on_border_[i]) on_border.push_back(i);
    }
    all_.reset();
    border_.reset();
    if(!everywhere.empty()) {
      all_ = std::make_unique<Tree>(everywhere.begin(), everywhere.end(), typename Tree::Splitter(), Adapter(map_));
      build(*all_, pool);
    }
    if(!on_border.empty()) {
      border_ = std::make_unique<Tree>(on_border.begin(), on_border.end(), typename Tree::Splitter(), Adapter(map_));
      build(*border_, pool);
    }
    distance_.assign(samples_.size(), 0.);
  }

  const std::vector<std::pair<Point, bool> >& samples_;
  const std::vector<bool>& on_border_;
  const double reach_;
  std::vector<Point> sample_points_;
  Point_map sample_map_;
  std::unique_ptr<Tree> sample_trees_[2];  // over the samples off and on the border
  std::vector<Point> built_;  // the vertices' positions when the trees were built
  std::vector<Point> last_;   // and at the previous call
  Point_map map_;
  std::unique_ptr<Tree> all_, border_;
  std::vector<double> distance_;      // each sample's nearest distance when the trees were built
  std::vector<std::size_t> nearest_;  // each sample's owner at the previous call
  std::vector<double> squared_;       // and its squared distance then
};

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_FEATURE_ATTRACTION_H
