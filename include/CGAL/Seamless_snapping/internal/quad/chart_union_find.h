// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_CHART_UNION_FIND_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_CHART_UNION_FIND_H

// Union-find over elements that each live in a chart, carrying the chart transition to the root's
// chart (a weighted union-find: element x stores the transform from its chart to its parent's). Two
// elements joined twice must be joined by the same transition: a join that closes a cycle with a
// composed transition other than the identity (holonomy, e.g. around a cone inside a cell) is
// refused and reported by unite(). The representative of a set is its smallest element, so the
// result does not depend on the order of the joins (determinism).

#include <CGAL/Seamless_snapping/internal/quad/grid_transform.h>

#include <numeric>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

class Chart_union_find
{
public:
  explicit Chart_union_find(int n) : parent_(std::size_t(n)), to_parent_(std::size_t(n))
  {
    std::iota(parent_.begin(), parent_.end(), 0);
  }

  // the representative of x, and in `to_root` the transition from the chart of x to the representative's
  int find(int x, Grid_transform& to_root)
  {
    const int p = parent_[std::size_t(x)];
    if(p == x) { to_root = Grid_transform(); return x; }                       // a root
    if(parent_[std::size_t(p)] == p) { to_root = to_parent_[std::size_t(x)]; return p; }   // a child of the root
    int r = x;
    while(parent_[std::size_t(r)] != r) r = parent_[std::size_t(r)];
    path_.clear();
    for(int y = x; y != r; y = parent_[std::size_t(y)]) path_.push_back(y);
    Grid_transform acc;                                       // from the chart of the node above to the root's
    for(std::size_t i = path_.size(); i-- > 0; ) {            // nearest the root first; path compression
      const std::size_t y = std::size_t(path_[i]);
      acc = compose(acc, to_parent_[y]);
      to_parent_[y] = acc;
      parent_[y] = r;
    }
    to_root = path_.empty() ? Grid_transform() : to_parent_[std::size_t(x)];
    return r;
  }

  // joins a and b, T mapping the chart of a to that of b; false (nothing changed) if they are joined
  // already by another transition
  bool unite(int a, int b, const Grid_transform& T)
  {
    Grid_transform A, B;
    const int ra = find(a, A), rb = find(b, B);
    const Grid_transform ra_to_rb = compose(B, compose(T, inverse(A)));
    if(ra == rb) return ra_to_rb == Grid_transform();
    if(ra < rb) { parent_[std::size_t(rb)] = ra; to_parent_[std::size_t(rb)] = inverse(ra_to_rb); }
    else        { parent_[std::size_t(ra)] = rb; to_parent_[std::size_t(ra)] = ra_to_rb; }
    return true;
  }

private:
  std::vector<int> parent_;
  std::vector<Grid_transform> to_parent_;
  std::vector<int> path_;
};

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_CHART_UNION_FIND_H
