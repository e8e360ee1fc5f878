// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_WINDING_DEFECTS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_WINDING_DEFECTS_H

// The interior vertices at which a map is not locally injective although the triangles around them may
// all be positive: their UV angle sum is not their valence (vertex_windings.h), e.g. 8 quarter turns at a
// regular vertex next to a cone that has 1 instead of 5. The pipeline gives each a message; where a collapsed
// cone pair lies within a few face rings (two cones that the integer translations carry onto one integer point
// along a path of edges near it, collapsed_cone_pairs() of cone_merging.h, with the search that merging and
// separating use), the message names it: a +-90 degree cone pair collapsed onto one grid point, which the
// singularity-separating conditions of integer-grid-map solvers (Bommes et al. 2013) rule out, and which the
// untangling leaves as a winding defect (the pair is a fact, that it causes the defect a suspicion).
// Here: the face rings around vertices, and which collapsed pairs lie near a vertex.

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/untangling/reference_shapes.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// how far (face rings) from a wrongly wound vertex a collapsed cone pair is named as lying next to it
constexpr int coincident_cone_rings = 16;

// The vertices within `rings` face rings of `seeds` (the seeds first, each vertex once, ring by ring), found
// breadth first through the faces of each vertex (the cost is that of the rings, not of the mesh)
inline std::vector<int> vertices_within_face_rings(const Corner_mesh& cm, const Face_corners& fc, const std::vector<int>& seeds,
                                                   int rings)
{
  std::vector<char> near(std::size_t(cm.n_vertices), 0);
  std::vector<int> out;
  for(int w : seeds)
    if(!near[std::size_t(w)]) { near[std::size_t(w)] = 1; out.push_back(w); }
  std::size_t ring_begin = 0;
  for(int r = 0; r < rings && ring_begin < out.size(); ++r) {
    const std::size_t ring_end = out.size();
    for(std::size_t i = ring_begin; i < ring_end; ++i)
      for(int f : fc.vertex_faces[out[i]])
        for(int h : fc.halfedge[std::size_t(f)]) {
          const int w = cm.target[h];
          if(!near[std::size_t(w)]) { near[std::size_t(w)] = 1; out.push_back(w); }
        }
    ring_begin = ring_end;
  }
  return out;
}

// The pairs of `pairs` (collapsed_cone_pairs(), cone_merging.h) with a cone within coincident_cone_rings face rings
// of a vertex of `seeds`
inline std::vector<std::pair<int, int> > collapsed_cone_pairs_near(const Corner_mesh& cm, const Face_corners& fc,
                                                                   const std::vector<std::pair<int, int> >& pairs,
                                                                   const std::vector<int>& seeds)
{
  if(pairs.empty()) return {};
  std::vector<int> near = vertices_within_face_rings(cm, fc, seeds, coincident_cone_rings);
  std::sort(near.begin(), near.end());
  std::vector<std::pair<int, int> > out;
  for(const std::pair<int, int>& c : pairs)
    if(std::binary_search(near.begin(), near.end(), c.first) || std::binary_search(near.begin(), near.end(), c.second))
      out.push_back(c);
  return out;
}

// The vertices within `rings` face rings of the cones of `pairs`
inline std::vector<int> vertices_near_collapsed_cones(const Corner_mesh& cm, const Face_corners& fc,
                                                      const std::vector<std::pair<int, int> >& pairs, int rings)
{
  std::vector<int> cones;
  for(const std::pair<int, int>& c : pairs) { cones.push_back(c.first); cones.push_back(c.second); }
  return vertices_within_face_rings(cm, fc, cones, rings);
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_WINDING_DEFECTS_H
