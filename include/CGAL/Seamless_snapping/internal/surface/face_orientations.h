// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_FACE_ORIENTATIONS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_FACE_ORIENTATIONS_H

// The exact orientation of the UV triangles of a map x (2 values per sector), and their counts: what
// the flip repair, the untangling, the winding counts and the report are made from.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// Non-positive UV triangles of one UV map (exact orientation test).
struct Orientation_counts
{
  std::size_t negative = 0;             // flipped: negative orientation
  std::size_t degenerate = 0;           // zero area
};

// Orientation of every face (CGAL::NEGATIVE, ZERO, POSITIVE), corner values from `x` (2 per sector).
inline std::vector<signed char> face_orientations(const Corner_mesh& cm, const Seam_topology& st, const std::vector<double>& x)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  std::vector<signed char> o(cm.n_faces, 0);
  for(int h = 0; h < cm.n_halfedges; ++h) {
    if(cm.is_border_halfedge(h) || h > cm.next[h] || h > cm.prev[h]) continue;   // once per face
    const int s0 = st.sector_of[h], s1 = st.sector_of[cm.next[h]], s2 = st.sector_of[cm.prev[h]];
    o[cm.face[h]] = static_cast<signed char>(CGAL::orientation(P(x[2 * s0], x[2 * s0 + 1]), P(x[2 * s1], x[2 * s1 + 1]),
                                                              P(x[2 * s2], x[2 * s2 + 1])));
  }
  return o;
}

// Counts the non-positive faces of `o`; with `input`, only those that are positive in `input`
// (the ones introduced since).
inline Orientation_counts count_orientations(const std::vector<signed char>& o,
                                             const std::vector<signed char>* input = nullptr)
{
  Orientation_counts c;
  for(std::size_t f = 0; f < o.size(); ++f) {
    if(input != nullptr && (*input)[f] != CGAL::POSITIVE) continue;
    c.negative += o[f] == CGAL::NEGATIVE;
    c.degenerate += o[f] == CGAL::ZERO;
  }
  return c;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_FACE_ORIENTATIONS_H
