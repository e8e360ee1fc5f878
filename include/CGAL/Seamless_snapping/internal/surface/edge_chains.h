// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_EDGE_CHAINS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_EDGE_CHAINS_H

// Decomposition of a set of edges into chains between "stop" vertices. Used twice:
// - seam arcs (one fitted rotation per arc): the cut edges between cones, border vertices and
//   vertices whose cut-degree is not 2;
// - branches (Sec. 5.3): the cut edges, resp. align edges, between nodes.
//
// A chain is the sequence of halfedges h_0, ..., h_{m-1} with target(h_i) = source(h_{i+1}),
// w_0 = source(h_0) and w_m = target(h_{m-1}) stop vertices, every inner vertex a non-stop vertex
// with exactly two edges of the set. A vertex with a number of set edges other than 2 always stops
// a chain. A closed loop without any stop vertex starts and ends at its smallest vertex index,
// which is reported in `loop_starts` (for branches it becomes a node).

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/index_lists.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

struct Edge_chains
{
  std::vector<std::vector<int> > chains;   // halfedge sequences
  std::vector<int> loop_starts;            // start vertices of closed loops without stop vertex
};

// `in_set[e]` != 0 for the edges of the set; `stop[v]` != 0 for the stop vertices.
// Deterministic: chains are started from stop vertices in increasing index order, each along its
// outgoing set halfedges in increasing halfedge index order.
inline void decompose_into_chains(const Corner_mesh& cm, const std::vector<char>& in_set,
                                  const std::vector<char>& stop, Edge_chains& out)
{
  out.chains.clear(); out.loop_starts.clear();
  // outgoing set halfedges per vertex, in increasing halfedge index order
  std::vector<int> set_halfedges;
  for(int h = 0; h < cm.n_halfedges; ++h) if(in_set[cm.edge[h]]) set_halfedges.push_back(h);
  Index_lists outgoing;
  outgoing.build(cm.n_vertices, [&](auto emit) { for(int h : set_halfedges) emit(cm.source(h), h); });
  auto degree = [&](int v) { return outgoing[v].size(); };
  auto outgoing_at = [&](int v, int i) { return outgoing[v].begin()[i]; };
  std::vector<char> used(cm.n_edges, 0);
  auto is_stop = [&](int v) { return stop[v] || degree(v) != 2; };

  auto walk = [&](int h0) {
    std::vector<int> chain;
    int h = h0;
    for(;;) {
      chain.push_back(h);
      used[cm.edge[h]] = 1;
      const int w = cm.target[h];
      if(is_stop(w)) break;
      const int hn = (cm.edge[outgoing_at(w, 0)] == cm.edge[h]) ? outgoing_at(w, 1) : outgoing_at(w, 0);
      if(used[cm.edge[hn]]) break;     // closed loop: back at its start
      h = hn;
    }
    out.chains.push_back(std::move(chain));
  };

  for(int v = 0; v < cm.n_vertices; ++v) {
    if(!is_stop(v)) continue;
    for(int i = 0; i < degree(v); ++i)
      if(!used[cm.edge[outgoing_at(v, i)]]) walk(outgoing_at(v, i));
  }
  // loops without stop vertices; the first vertex met with an unused edge is the loop's smallest
  for(int v = 0; v < cm.n_vertices; ++v) {
    if(degree(v) == 0 || used[cm.edge[outgoing_at(v, 0)]]) continue;
    out.loop_starts.push_back(v);
    walk(outgoing_at(v, 0));
  }
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_EDGE_CHAINS_H
