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
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// how far (face rings) from a wrongly wound vertex a collapsed cone pair is named as lying next to it
constexpr int coincident_cone_rings = 16;
// how many of the collapsed cone pairs near a defect a message names (the nearest; the others are counted)
constexpr std::size_t named_collapsed_pairs = 3;

// the clause that counts the collapsed cone pairs near a defect beyond the named_collapsed_pairs a message names
// ("" if none are left out)
inline std::string more_collapsed_pairs_clause(std::size_t near)
{
  if(near <= named_collapsed_pairs) return std::string();
  const std::size_t more = near - named_collapsed_pairs;
  return "; " + std::to_string(more) + " more such pair" + (more == 1 ? "" : "s") + " within " +
         std::to_string(coincident_cone_rings) + " face rings";
}

// The vertices within `rings` face rings of `seeds` (the seeds first, each vertex once, ring by ring), found
// breadth first through the faces of each vertex (the cost is that of the rings, not of the mesh: the vertices
// reached are kept in a hash map, not in a mark per vertex of the mesh, since the messages call this once per
// defect); `ring_of`, if given, receives each of them with its ring (0: the seeds)
inline std::vector<int> vertices_within_face_rings(const Corner_mesh& cm, const Face_corners& fc, const std::vector<int>& seeds,
                                                   int rings, std::unordered_map<int, int>* ring_of = nullptr)
{
  std::unordered_map<int, int> own;
  std::unordered_map<int, int>& ring = ring_of != nullptr ? *ring_of : own;
  ring.clear();
  std::vector<int> out;
  for(int w : seeds)
    if(ring.emplace(w, 0).second) out.push_back(w);
  std::size_t ring_begin = 0;
  for(int r = 0; r < rings && ring_begin < out.size(); ++r) {
    const std::size_t ring_end = out.size();
    for(std::size_t i = ring_begin; i < ring_end; ++i)
      for(int f : fc.vertex_faces[out[i]])
        for(int h : fc.halfedge[std::size_t(f)])
          if(ring.emplace(cm.target[h], r + 1).second) out.push_back(cm.target[h]);
    ring_begin = ring_end;
  }
  return out;
}

// The pairs of `pairs` (collapsed_cone_pairs(), cone_merging.h) with a cone within coincident_cone_rings face rings
// of a vertex of `seeds`, nearest first (in the order of `pairs` among as near ones); `rings`, if given, receives the
// face rings between the seeds and each pair's nearer cone
inline std::vector<std::pair<int, int> > collapsed_cone_pairs_near(const Corner_mesh& cm, const Face_corners& fc,
                                                                   const std::vector<std::pair<int, int> >& pairs,
                                                                   const std::vector<int>& seeds,
                                                                   std::vector<int>* rings = nullptr)
{
  if(rings != nullptr) rings->clear();
  if(pairs.empty()) return {};
  std::unordered_map<int, int> ring_of;
  vertices_within_face_rings(cm, fc, seeds, coincident_cone_rings, &ring_of);
  auto ring = [&](int w) {
    const auto it = ring_of.find(w);
    return it != ring_of.end() ? it->second : -1;
  };
  std::vector<std::pair<int, std::size_t> > found;   // (ring, index into pairs)
  for(std::size_t i = 0; i < pairs.size(); ++i) {
    const int a = ring(pairs[i].first), b = ring(pairs[i].second);
    if(a >= 0 || b >= 0) found.emplace_back(a < 0 ? b : b < 0 ? a : (std::min)(a, b), i);
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const std::pair<int, std::size_t>& x, const std::pair<int, std::size_t>& y) { return x.first < y.first; });
  std::vector<std::pair<int, int> > out;
  for(const std::pair<int, std::size_t>& c : found) {
    out.push_back(pairs[c.second]);
    if(rings != nullptr) rings->push_back(c.first);
  }
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
