// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_CLOSED_UNCUT_PARTS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_CLOSED_UNCUT_PARTS_H

// The parts of a map that fold in every map with the same constraints, whatever the UVs: a connected part of the
// mesh with no border edge and no cut edge. Its corners at a vertex are one sector (no cut edge: no transition), so
// every map satisfying the constraints gives it one UV per vertex, a continuous map of a closed surface into the
// plane; and such a map has a UV triangle that is not positive: were all of them positive, the map would be open
// (around each point it is z -> z^w, w >= 1 the winding number there), so its image would be open and compact in
// the plane, which no nonempty subset of the plane is. Typical inputs: UVs made by a projection or left at one
// point on a closed mesh; a closed surface is parametrized only with cuts (seams). The untangling leaves such parts
// alone (untangle_stage()) and the explanation says why (explain_folds_stage()).

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/untangling/reference_shapes.h>   // Face_corners

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// Per face: the number of faces of its part if it lies in a closed part without cut edges (see above), else 0; the
// parts searched are those of the faces `seeds`. Every such part has a non-positive face, so the non-positive faces
// as seeds find them all. A search stops at the first border or cut edge it meets, or at a face of a part known to
// have one: a part with cuts costs a few faces, a part without is walked once, whole.
inline std::vector<int> closed_uncut_part_sizes(const Corner_mesh& cm, const Seam_topology& st, const Face_corners& fc,
                                                const std::vector<int>& seeds)
{
  enum : signed char { UNKNOWN = 0, UNCUT = 1, CUT = 2 };
  std::vector<signed char> state(std::size_t(cm.n_faces), UNKNOWN);
  std::vector<int> size(std::size_t(cm.n_faces), 0), part, todo;
  for(int seed : seeds) {
    if(state[std::size_t(seed)] != UNKNOWN) continue;
    part.assign(1, seed);
    todo.assign(1, seed);
    state[std::size_t(seed)] = UNCUT;                  // reached (provisional until the search ends)
    bool cut = false;
    while(!todo.empty() && !cut) {
      const int f = todo.back();
      todo.pop_back();
      for(int h : fc.halfedge[std::size_t(f)]) {
        const int o = cm.opp[h];
        if(cm.is_border_halfedge(o) || st.is_cut[std::size_t(cm.edge[h])]) { cut = true; break; }
        const int g = cm.face[o];
        if(state[std::size_t(g)] == CUT) { cut = true; break; }
        if(state[std::size_t(g)] == UNKNOWN) { state[std::size_t(g)] = UNCUT; part.push_back(g); todo.push_back(g); }
      }
    }
    for(int f : part) {
      state[std::size_t(f)] = cut ? CUT : UNCUT;
      size[std::size_t(f)] = cut ? 0 : int(part.size());
    }
  }
  return size;
}

// why a non-positive face or a wrongly wound vertex in such a part (of `faces` faces) is one
inline std::string closed_uncut_part_reason(int faces)
{
  return "it lies in a closed part of the surface (" + std::to_string(faces) + " faces, no border) without cut edges: "
         "every map satisfying the constraints has one UV per vertex there, a continuous map of a closed surface into "
         "the plane, and such a map always has UV triangles that are not positive (were all positive, its image would "
         "be open and compact in the plane), so no untangling removes them all; a closed surface is parametrized with "
         "cuts (seams), e.g. from a cross field";
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_CLOSED_UNCUT_PARTS_H
