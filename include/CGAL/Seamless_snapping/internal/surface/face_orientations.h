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
#include <utility>
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

// Orientation of every face (CGAL::NEGATIVE, ZERO, POSITIVE) of the UV triangle of corners h, next(h), prev(h) with the
// values uv(h) (a pair of doubles), the UVs of the faces d ahead prefetched (next(h) and prev(h) lie far from h where the
// faces are not listed in order of adjacency).
template <class Prefetch, class Uv>
std::vector<signed char> face_orientations(const Corner_mesh& cm, const Prefetch& prefetch, const Uv& uv)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  std::vector<signed char> o(cm.n_faces, 0);
  const std::vector<int> first = face_first_halfedges(cm);
  const std::size_t n = first.size(), d = std::size_t(seam_prefetch_distance);
  for(std::size_t i = 0; i < n; ++i) {
    if(i + d < n) {
      const int g = first[i + d];
      prefetch(g); prefetch(cm.next[std::size_t(g)]); prefetch(cm.prev[std::size_t(g)]);
    }
    const int h = first[i];
    const std::pair<double, double> a = uv(h), b = uv(cm.next[std::size_t(h)]), c = uv(cm.prev[std::size_t(h)]);
    o[std::size_t(cm.face[std::size_t(h)])] =
      static_cast<signed char>(CGAL::orientation(P(a.first, a.second), P(b.first, b.second), P(c.first, c.second)));
  }
  return o;
}

// ... of a map x (2 values per sector)
inline std::vector<signed char> face_orientations(const Corner_mesh& cm, const Seam_topology& st, const std::vector<double>& x)
{
  return face_orientations(cm, [&](int h) { __builtin_prefetch(&x[2 * std::size_t(st.sector_of[std::size_t(h)])]); },
                           [&](int h) {
                             const std::size_t s = std::size_t(st.sector_of[std::size_t(h)]);
                             return std::make_pair(x[2 * s], x[2 * s + 1]);
                           });
}

// ... of the corner UVs of `cm`: the input map's, face_orientations(cm, st, st.ubar) (the corners of a sector share one
// UV, which compute_seam_topology() checks), and the map of a corner mesh without sectors (fold_overs.h); each UV read
// once and directly. On the 302K-face bunny of ../shared/large, with face_first_halfedges(): 11-13 -> 6 ms
inline std::vector<signed char> face_orientations(const Corner_mesh& cm)
{
  return face_orientations(cm, [&](int h) { prefetch_uv(cm, h); },
                           [&](int h) { return std::make_pair(cm.u[std::size_t(h)], cm.v[std::size_t(h)]); });
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
