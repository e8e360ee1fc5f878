// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_INDEX_LISTS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_INDEX_LISTS_H

// A list of ints per key 0..n-1, all in one array (compressed sparse rows), filled by a counting sort:
// two int arrays instead of a vector per key (24 bytes per key even when empty: the flip repair's two
// per-sector lists took 8.4 MB on a 302K-face map, 1.4 MB this way). Each list keeps the order in which its
// items were given. Fewer than 2^31 items in all (like the int halfedge and row indices of Corner_mesh and
// Constraint_rows).

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

struct Index_lists
{
  struct Range
  {
    const int* first;
    const int* last;
    const int* begin() const { return first; }
    const int* end() const { return last; }
    bool empty() const { return first == last; }
    int size() const { return int(last - first); }
  };

  // `each(emit)` calls emit(key, item) for every item, twice in the same order (once to count, once to place)
  template <class Each>
  void build(int n, const Each& each)
  {
    start.assign(std::size_t(n) + 1, 0);
    each([&](int key, int) { ++start[std::size_t(key) + 1]; });
    for(std::size_t k = 0; k < std::size_t(n); ++k) start[k + 1] += start[k];
    item.assign(std::size_t(start.back()), -1);
    std::vector<int> fill(start.begin(), start.end() - 1);
    each([&](int key, int value) { item[std::size_t(fill[std::size_t(key)]++)] = value; });
  }

  Range operator[](int key) const
  {
    const int* base = item.data();
    return Range{base + start[std::size_t(key)], base + start[std::size_t(key) + 1]};
  }

  std::vector<int> start;   // n + 1 offsets into `item`
  std::vector<int> item;
};

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_INDEX_LISTS_H
