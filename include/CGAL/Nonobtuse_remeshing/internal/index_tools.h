// SPDX-License-Identifier: GPL-3.0-or-later
//
// Indices as the Marching Cubes phases use them: disjoint sets of 0..n-1,
// and 64-bit keys of index pairs (edges).

#ifndef CGAL_NONOBTUSE_REMESHING_INTERNAL_INDEX_TOOLS_H
#define CGAL_NONOBTUSE_REMESHING_INTERNAL_INDEX_TOOLS_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Nonobtuse_remeshing {
namespace internal {

// Disjoint sets of the indices 0..n-1, with path halving. join(a, b) makes
// the representative of b's set the representative of the union, always:
// the stitching numbers the output vertices by these representatives, so the
// choice is part of the output (CGAL's Union_find, by rank, would renumber
// them).
class Index_sets
{
public:
  explicit Index_sets(std::size_t n = 0) { reset(n); }

  void reset(std::size_t n)
  {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), std::size_t(0));
  }

  std::size_t find(std::size_t x)
  {
    while(parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }

  void join(std::size_t a, std::size_t b)
  {
    const std::size_t rb = find(b);
    parent_[find(a)] = rb;
  }

  // The representative of each index.
  std::vector<std::size_t> representatives()
  {
    std::vector<std::size_t> root(parent_.size());
    for(std::size_t i = 0; i < root.size(); ++i) root[i] = find(i);
    return root;
  }

private:
  std::vector<std::size_t> parent_;
};

// The key of the ordered pair (u, v) of indices below 2^32.
inline std::uint64_t pair_key(std::size_t u, std::size_t v) { return (std::uint64_t(u) << 32) | std::uint64_t(v); }

// The key of the edge {u, v}, whichever its direction.
inline std::uint64_t edge_key(std::size_t u, std::size_t v) { return pair_key((std::min)(u, v), (std::max)(u, v)); }

} // namespace internal
} // namespace Nonobtuse_remeshing
} // namespace CGAL

#endif // CGAL_NONOBTUSE_REMESHING_INTERNAL_INDEX_TOOLS_H
