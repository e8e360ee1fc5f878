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
// regular vertex next to a cone that has 1 instead of 5. Each gets a message; where two cones lie on one
// integer point within a few face rings (the integer translations carry one onto the other along a face
// path), the message names them: a +-90 degree cone pair collapsed onto one grid point, which the
// singularity-separating conditions of integer-grid-map solvers (Bommes et al. 2013) rule out, and which
// the untangling leaves as a winding defect (a suspicion, not a proof).

#include <CGAL/Seamless_snapping/Snap_report.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/integer_grid_constraints.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/untangling/reference_shapes.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// how far (face rings) a cone pair on one integer point is looked for around a wrongly wound vertex
constexpr int coincident_cone_rings = 16;

// p -> R^k p + t
struct Chart_map
{
  int k = 0;
  double t[2] = {0, 0};
  void apply(const double p[2], double q[2]) const
  {
    const Quarter_turn R(k);
    for(int c = 0; c < 2; ++c) q[c] = R.sign[c] * p[R.col[c]] + t[c];
  }
};

// The cone pairs that one of the `rings` face rings around vertex v maps onto one UV point, in the chart of
// a face of v (transitions composed along the faces reached first, breadth first). The cones are those of the
// field: K[w] > 0 (field_rotation_sums()).
inline std::vector<std::pair<int, int> > coincident_cones_near(const Corner_mesh& cm, const Seam_topology& st,
                                                               const Cut_rotations& rot, const std::vector<int>& K,
                                                               const Face_corners& fc, const std::vector<double>& x,
                                                               int v, int rings)
{
  if(fc.vertex_faces[v].empty()) return {};
  const int start = *fc.vertex_faces[v].begin();
  std::map<int, Chart_map> to_start;             // face -> its chart in the start face's chart
  std::vector<int> front;
  to_start[start] = Chart_map();
  front.push_back(start);
  std::map<std::pair<double, double>, int> cone_at;
  std::vector<std::pair<int, int> > pairs;
  auto uv = [&](int h, double p[2]) { const std::size_t s = std::size_t(st.sector_of[h]); p[0] = x[2 * s]; p[1] = x[2 * s + 1]; };
  for(int ring = 0; ring <= rings && !front.empty(); ++ring) {
    std::vector<int> next;
    for(int f : front) {
      const Chart_map& M = to_start[f];
      for(int h : fc.halfedge[std::size_t(f)]) {
        const int w = cm.target[h];
        if(K[std::size_t(w)] > 0) {
          double p[2], q[2];
          uv(h, p);
          M.apply(p, q);
          auto it = cone_at.insert({{q[0], q[1]}, w}).first;
          if(it->second != w) pairs.emplace_back((std::min)(it->second, w), (std::max)(it->second, w));
        }
        const int o = cm.opp[h];
        if(cm.face[o] < 0 || to_start.count(cm.face[o])) continue;
        // the chart of face(o) -> the chart of f: inverse of p -> R^k p + t (k = rot.k[h] across a cut edge)
        const int k = st.is_cut[std::size_t(cm.edge[h])] ? rot.k[h] : 0;
        double pa[2], qa[2];
        uv(cm.prev[h], pa);                        // source(h) in f
        uv(o, qa);                                 // source(h) in face(o)
        const Quarter_turn Ri(-k);
        Chart_map back;                            // q -> R^-k (q - (qa - R^k pa)) = R^-k q + (pa - R^-k qa)
        back.k = -k;
        for(int c = 0; c < 2; ++c) back.t[c] = pa[c] - Ri.sign[c] * qa[Ri.col[c]];
        Chart_map composed;                        // M after back
        composed.k = M.k + back.k;
        M.apply(back.t, composed.t);
        to_start[cm.face[o]] = composed;
        next.push_back(cm.face[o]);
      }
    }
    front.swap(next);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

// The vertices within `rings` face rings of `seeds` (the seeds first, each vertex once, ring by ring)
inline std::vector<int> vertices_within_face_rings(const Corner_mesh& cm, const Face_corners& fc, const std::vector<int>& seeds,
                                                   int rings)
{
  std::vector<char> near(std::size_t(cm.n_vertices), 0);
  std::vector<int> out;
  for(int w : seeds)
    if(!near[std::size_t(w)]) { near[std::size_t(w)] = 1; out.push_back(w); }
  for(int r = 0; r < rings; ++r) {
    std::vector<int> next;
    for(const std::array<int, 3>& h : fc.halfedge) {
      bool touches = false;
      for(int q : h) touches = touches || (near[std::size_t(cm.target[q])] == 1);
      if(!touches) continue;
      for(int q : h) if(!near[std::size_t(cm.target[q])]) { near[std::size_t(cm.target[q])] = 2; next.push_back(cm.target[q]); }
    }
    for(int v : next) near[std::size_t(v)] = 1;
    out.insert(out.end(), next.begin(), next.end());
    if(next.empty()) break;
  }
  return out;
}

// The vertices within `rings` face rings of the cones of the collapsed cone pairs found around `seeds`
inline std::vector<int> vertices_near_collapsed_cones(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                                      const Face_corners& fc, const std::vector<double>& x,
                                                      std::vector<int> seeds, int rings)
{
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  std::vector<int> cones;
  const std::vector<int> K = field_rotation_sums(cm, st, rot);
  for(int v : seeds)
    for(const std::pair<int, int>& c : coincident_cones_near(cm, st, rot, K, fc, x, v, coincident_cone_rings))
      for(int w : {c.first, c.second}) cones.push_back(w);
  return vertices_within_face_rings(cm, fc, cones, rings);
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_WINDING_DEFECTS_H
