// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_NAME_LISTS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_NAME_LISTS_H

// The lists of faces, vertices and vertex pairs in report messages: at most ten names, " ..." after them.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// " n_0 n_1 ... n_9 ...": the names of the first ten items, " ..." if there are more
template <class T, class Name>
std::string first_ten(const std::vector<T>& items, Name name)
{
  std::string s;
  for(std::size_t i = 0; i < items.size() && i < 10; ++i) s += " " + name(items[i]);
  return items.size() > 10 ? s + " ..." : s;
}

// names a vertex pair "a<separator>b"
inline auto pair_name(const char* separator)
{
  return [separator](const std::pair<std::size_t, std::size_t>& p) {
    return std::to_string(p.first) + separator + std::to_string(p.second);
  };
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_NAME_LISTS_H
