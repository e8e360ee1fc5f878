// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_MIRRORED_COMPONENTS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_MIRRORED_COMPONENTS_H

// The mirrored parts of a map: the connected components of the mesh (faces joined by their interior edges, cut edges
// included) with more negative than positive UV triangles, those of closed parts without cut edges
// (closed_uncut_parts.h, which fold in every map) not counted. Such a component was parametrized mirrored (its v axis
// flipped, as a texture convention of some tools does, or its faces reversed): untangling it would turn the whole
// component over, far from the input (the horse of ../shared/data with u -> -u: all 6000 triangles "untangled", UVs
// moved by up to 13,000 grid cells), so the untangling leaves it alone (untangle_stage()). Per component, not per map:
// the horse with a mirrored copy of the sphere beside it (7280 faces, 1280 of them negative) had its sphere turned
// over, moved by up to 280 grid cells, as a map that is not mirrored as a whole.

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>   // Union_find

#include <CGAL/enum.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// Per face: 1 if it lies in a mirrored component (see above). `orientation`: per face, the sign of its UV triangle;
// `closed`: per face, the size of its closed uncut part or 0 (closed_uncut_part_sizes(), or empty: none).
inline std::vector<char> mirrored_component_faces(const Corner_mesh& cm, const std::vector<signed char>& orientation,
                                                  const std::vector<int>& closed)
{
  Union_find component(cm.n_faces);
  for(int h = 0; h < cm.n_halfedges; ++h)
    if(!cm.is_border_halfedge(h) && !cm.is_border_halfedge(cm.opp[h])) component.unite(cm.face[h], cm.face[cm.opp[h]]);
  std::vector<long> balance(std::size_t(cm.n_faces), 0);      // per component (its root): negative - positive faces
  for(int f = 0; f < cm.n_faces; ++f)
    if(closed.empty() || closed[std::size_t(f)] == 0)
      balance[std::size_t(component.find(f))] += orientation[std::size_t(f)] == CGAL::NEGATIVE ? 1
                                                 : orientation[std::size_t(f)] == CGAL::POSITIVE ? -1 : 0;
  std::vector<char> mirrored(std::size_t(cm.n_faces), 0);
  for(int f = 0; f < cm.n_faces; ++f) mirrored[std::size_t(f)] = balance[std::size_t(component.find(f))] > 0 ? 1 : 0;
  return mirrored;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_MIRRORED_COMPONENTS_H
