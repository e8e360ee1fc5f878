// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_INTEGER_GRID_QUANTIZATION_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_INTEGER_GRID_QUANTIZATION_H

// Quantization (quantize(true), beyond the paper): integer translations for the cut edges of a seamless map that is
// not near an integer-grid map (a map whose translations were never made integers, e.g. Directional's rot-seamless
// output), chosen so that around every interior vertex the transitions compose to the identity where it is not a cone,
// and to a rotation about an integer point where it is one, that point the one nearest to the cone in the map.
//
// The cut graph is peeled from its leaves: an interior vertex all of whose cut edges but one have their translations
// determines that one from its own condition (the composition around it is linear in that translation, through a
// rotation, so it is solved exactly in integers): a vertex that is not a cone composes to the identity; a cone's fixed
// point is the integer point nearest to its position. Where no such vertex is left (cycles of the cut graph, around the
// handles of the surface; cut paths that end on the border, whose border vertices have no condition), one cut edge
// that has none takes its translation rounded. A vertex whose cut edges were all determined from elsewhere (the last
// one of each tree of the cut graph, where the others' rounding adds up) is not solved for: add_integer_grid_rows()
// checks every vertex exactly afterwards and refuses (INFEASIBLE, nothing written) where its condition fails, as for
// any other choice of integer translations.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/integer_grid_constraints.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>

#include <cmath>
#include <deque>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// Per vertex: whether it is the root of its part of the cut graph, the vertex left to take the rounding of the others:
// in each part without a border vertex (a border vertex has no condition: the part is peeled towards it), a cone,
// one of +-90 degrees if there is one (a rotation by a quarter turn has an integer fixed point wherever the
// translation's coordinates add up to an even number, which the quarter-turn cones' contributions do; a half turn
// asks for both even), the one of least index. Without a cone the part has no root.
inline std::vector<char> quantization_roots(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                            const std::vector<int>& corner_of)
{
  Union_find part(cm.n_vertices);                               // the parts of the cut graph
  for(int e : st.cut_edges) {
    const int h = cm.edge_halfedge[std::size_t(e)];
    part.unite(cm.target[h], cm.target[cm.opp[h]]);
  }
  const std::vector<long> zero(2 * std::size_t(cm.n_halfedges), 0);
  std::vector<char> bordered(std::size_t(cm.n_vertices), 0);
  std::vector<int> best(std::size_t(cm.n_vertices), -1), best_k(std::size_t(cm.n_vertices), 0);
  for(int v = 0; v < cm.n_vertices; ++v) {
    if(st.cut_degree[std::size_t(v)] == 0) continue;
    const int p = part.find(v);
    if(cm.vertex_on_border[v]) { bordered[std::size_t(p)] = 1; continue; }
    if(corner_of[std::size_t(v)] < 0) continue;
    int K;
    long T[2];
    compose_around(cm, st, rot, zero, corner_of[std::size_t(v)], K, T);
    const bool quarter = K % 2 != 0;
    if(K % 4 != 0 && (best[std::size_t(p)] < 0 || (quarter && best_k[std::size_t(p)] % 2 == 0))) {
      best[std::size_t(p)] = v;
      best_k[std::size_t(p)] = K;
    }
  }
  std::vector<char> root(std::size_t(cm.n_vertices), 0);
  for(int v = 0; v < cm.n_vertices; ++v)
    if(part.find(v) == v && !bordered[std::size_t(v)] && best[std::size_t(v)] >= 0) root[std::size_t(best[std::size_t(v)])] = 1;
  return root;
}

// `ubar`: the sector values in grid units. `t`: 2 per halfedge, as round_translations() makes them. RANGE_EXCEEDED
// (with `message`) when a translation or a cone lies 2^52 grid units or more from the origin.
inline Status quantize_translations(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                    const std::vector<double>& ubar, std::vector<long>& t, std::string& message)
{
  t.assign(2 * std::size_t(cm.n_halfedges), 0);
  std::vector<char> known(std::size_t(cm.n_edges), 0);
  std::vector<int> open(std::size_t(cm.n_vertices), 0);        // per vertex: its cut edges without a translation yet
  for(int e : st.cut_edges) {
    const int h = cm.edge_halfedge[std::size_t(e)];
    ++open[std::size_t(cm.target[h])];
    ++open[std::size_t(cm.target[cm.opp[h]])];
  }
  const std::vector<int> corner_of = first_corners(cm);
  const std::vector<char> root = quantization_roots(cm, st, rot, corner_of);
  std::deque<int> ready;                                        // interior vertices with one cut edge open
  auto is_ready = [&](int v) {
    return open[std::size_t(v)] == 1 && !cm.vertex_on_border[v] && corner_of[std::size_t(v)] >= 0 && !root[std::size_t(v)];
  };
  for(int v = 0; v < cm.n_vertices; ++v) if(is_ready(v)) ready.push_back(v);
  auto settle = [&](int h) {                                    // t of h set: its opposite, the counts, the queue
    set_opposite_translation(cm, rot, h, t);
    known[std::size_t(cm.edge[h])] = 1;
    for(int v : {cm.target[h], cm.target[cm.opp[h]]})
      if(--open[std::size_t(v)] == 1 && is_ready(v)) ready.push_back(v);
  };
  auto too_far = [&](double x, const std::string& what) {
    if(std::fabs(x) < 0x1p52) return false;
    message = what + " lies 2^52 grid units or more from the origin, beyond the integers an integer-grid map holds "
              "exactly; scale the map down (grid_scale / --grid-scale)";
    return true;
  };
  std::size_t next_free = 0;                                    // st.cut_edges before it all have translations
  for(;;) {
    while(!ready.empty()) {
      const int v = ready.front();
      ready.pop_front();
      if(open[std::size_t(v)] != 1) continue;
      // the open cut edge, as the halfedge crossed from v (compose_around() reads t at the crossed halfedge)
      const int g0 = corner_of[std::size_t(v)];
      int crossed = -1, g = g0;
      do {
        const int c = cm.next[g];
        if(st.is_cut[std::size_t(cm.edge[c])] && !known[std::size_t(cm.edge[c])]) crossed = c;
        g = cm.opp[c];
      } while(g != g0);
      // the composition around v is T0 + M t(crossed), M a rotation; the condition asks for T = p - R^K p
      int K;
      long T0[2], M[2][2];
      compose_around(cm, st, rot, t, g0, K, T0);
      for(int c = 0; c < 2; ++c) {
        t[2 * std::size_t(crossed)] = c == 0; t[2 * std::size_t(crossed) + 1] = c == 1;
        long Tc[2];
        compose_around(cm, st, rot, t, g0, K, Tc);
        M[0][c] = Tc[0] - T0[0]; M[1][c] = Tc[1] - T0[1];
      }
      long need[2] = {0, 0};
      if(K % 4 != 0) {                                          // a cone: its fixed point, the integer point nearest to it
        const int s = st.sector_of[g0];
        const double pu = std::nearbyint(ubar[2 * std::size_t(s)]), pv = std::nearbyint(ubar[2 * std::size_t(s) + 1]);
        if(too_far(pu, "cone at vertex " + std::to_string(v)) || too_far(pv, "cone at vertex " + std::to_string(v)))
          return RANGE_EXCEEDED;
        const long p[2] = {long(pu), long(pv)};
        const Quarter_turn R(K);
        for(int c = 0; c < 2; ++c) need[c] = p[c] - R.sign[c] * p[R.col[c]];
      }
      const long b[2] = {need[0] - T0[0], need[1] - T0[1]};
      for(int c = 0; c < 2; ++c) t[2 * std::size_t(crossed) + std::size_t(c)] = M[0][c] * b[0] + M[1][c] * b[1];   // M^T b
      settle(crossed);
    }
    while(next_free < st.cut_edges.size() && known[std::size_t(st.cut_edges[next_free])]) ++next_free;
    if(next_free == st.cut_edges.size()) return SUCCESS;
    // a free choice: a cut edge at the border if one is open (a path between two border vertices), else any
    int e = st.cut_edges[next_free];
    for(std::size_t i = next_free; i < st.cut_edges.size(); ++i) {
      const int f = st.cut_edges[i], g = cm.edge_halfedge[std::size_t(f)];
      if(!known[std::size_t(f)] && (cm.vertex_on_border[cm.target[g]] || cm.vertex_on_border[cm.target[cm.opp[g]]])) { e = f; break; }
    }
    const int h = cm.edge_halfedge[std::size_t(e)];           // its translation, rounded
    double ta[2];
    translation(cm, st, rot, h, true, ubar, ta);
    for(int c = 0; c < 2; ++c) {
      if(too_far(ta[c], "the translation of cut edge " + vertex_pair_name(cm, h))) return RANGE_EXCEEDED;
      t[2 * std::size_t(h) + std::size_t(c)] = long(std::nearbyint(ta[c]));
    }
    settle(h);
  }
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_INTEGER_GRID_QUANTIZATION_H
