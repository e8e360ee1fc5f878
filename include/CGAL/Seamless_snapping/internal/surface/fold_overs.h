// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_FOLD_OVERS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_FOLD_OVERS_H

// The faces that keep a corner UV map from being locally injective: fold-overs (negatively oriented
// UV triangles) and zero-area UV triangles, found with the exact orientation predicate on the corner
// UVs (CGAL's filtered predicate on doubles: exact). Quad extraction and quad valences need a map
// without fold-overs (extract_quad_mesh(), quad_valences()): each face of a fold-free map covers its UV
// triangle once, counter-clockwise. Of the zero-area triangles they accept those with three distinct
// (collinear) corners, the limit of a thin positively oriented triangle, collapsed onto their longest
// side (quad/collapsed_faces.h); not those with two corners at one UV point.

#include <CGAL/Seamless_snapping/internal/io/name_lists.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/face_orientations.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

struct Fold_overs
{
  std::vector<int> negative;     // faces (Corner_mesh numbering) whose UV triangle is negatively oriented
  std::vector<int> degenerate;   // faces whose UV triangle has zero area
  std::vector<int> collinear;    // those of them with three distinct corners (no side of length zero)

  bool empty() const { return negative.empty() && degenerate.empty(); }
  // a fold-over, or a zero-area triangle with two corners at one UV point: no quad mesh follows the map
  bool blocks_quads() const { return !negative.empty() || collinear.size() < degenerate.size(); }

  // "N fold-overs (faces a b c ...) and M zero-area UV triangles (faces ...)", at most 10 faces each
  std::string describe() const
  {
    auto list = [](const std::vector<int>& f) { return first_ten(f, [](int i) { return std::to_string(i); }); };
    return std::to_string(negative.size()) + " fold-overs (negatively oriented UV triangles" +
           (negative.empty() ? "" : ": faces" + list(negative)) + ") and " + std::to_string(degenerate.size()) +
           " zero-area UV triangles" + (degenerate.empty() ? "" : " (faces" + list(degenerate) + ")");
  }
};

inline Fold_overs find_fold_overs(const Corner_mesh& cm)
{
  Fold_overs r;
  const std::vector<signed char> o = face_orientations(cm);
  for(int f = 0; f < cm.n_faces; ++f) {
    if(o[std::size_t(f)] == CGAL::NEGATIVE) r.negative.push_back(f);
    if(o[std::size_t(f)] == CGAL::ZERO) r.degenerate.push_back(f);
  }
  if(r.degenerate.empty()) return r;
  std::vector<int> corner(std::size_t(cm.n_faces), -1);          // of the zero-area faces: a halfedge
  for(int h = 0; h < cm.n_halfedges; ++h)
    if(!cm.is_border_halfedge(h) && o[std::size_t(cm.face[h])] == CGAL::ZERO) corner[std::size_t(cm.face[h])] = h;
  auto same = [&](int a, int b) { return cm.u[a] == cm.u[b] && cm.v[a] == cm.v[b]; };
  for(int f : r.degenerate) {
    const int h = corner[std::size_t(f)], a = cm.prev[h], c = cm.next[h];
    if(!same(a, h) && !same(h, c) && !same(c, a)) r.collinear.push_back(f);   // zero area, three distinct corners
  }
  return r;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_FOLD_OVERS_H
