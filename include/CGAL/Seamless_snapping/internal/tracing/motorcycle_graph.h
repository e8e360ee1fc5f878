// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_MOTORCYCLE_GRAPH_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_MOTORCYCLE_GRAPH_H

// Separatrices of the motorcycle graph [CBK15, CZ17]: from every cone of n quarter turns the n rays
// along the axis directions, and from every border corner (a border vertex whose fan is not a half
// turn) the axis rays strictly inside its fan. All traces advance together, one face at a time, the
// one with the smallest parametric length first (ties: smaller index), and each stops at a cone, the
// border, or the trail laid so far by any trace (T-junction). A ray that starts along an existing trail
// (the other end of an arc already traced) stops at once, with no segment.
// A map without cones and border corners (a torus) gets four seeded traces, +u, +v, -u and -v, from the
// first corner of the first vertex: with all four the seed is a node with right angles only (with two,
// the angle between +v and +u the other way round would be a 270 degree patch corner).

#include <CGAL/Seamless_snapping/internal/tracing/isoline_tracer.h>

#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace tracing {

struct Separatrix_seeds
{
  std::vector<int> corner, m, source_kind;   // per separatrix; kind 0 cone, 1 border corner, 2 seed
  std::size_t cones = 0, border_corners = 0;
  std::size_t cones_with_wrong_ray_count = 0; // rays found != the cone's quarter turns (inexact map)
  bool seeded = false;
};

inline Separatrix_seeds separatrix_seeds(const Tracing_map& map)
{
  const Corner_mesh& cm = map.cm;
  Separatrix_seeds S;
  std::vector<int> vertex_corner(cm.n_vertices, -1);
  for(int h = 0; h < cm.n_halfedges; ++h)
    if(!cm.is_border_halfedge(h) && vertex_corner[cm.target[h]] < 0) vertex_corner[cm.target[h]] = h;
  for(int v = 0; v < cm.n_vertices; ++v) {
    const int h0 = vertex_corner[v];
    if(h0 < 0) continue;
    const bool border = cm.vertex_on_border[v] != 0;
    if(border ? map.fan_quarter_turns[v] == 2 : !map.st.is_cone[v]) continue;
    if(border) ++S.border_corners; else ++S.cones;
    const Vertex_fan fan = vertex_fan(cm, map.rot, h0, 0);
    if(fan.degenerate) continue;
    const int lo = fan.closed ? fan.wedges[fan.start].La : fan.wedges.front().La;
    const int hi = fan.wedges.back().Lb;
    int rays = 0;
    for(int T = lo + 1; fan.closed ? T <= hi : T < hi; ++T) {
      if(T % 2 != 0) continue;
      std::vector<int> found;
      wedges_containing(fan, T, found);
      for(int i : found) {
        S.corner.push_back(fan.wedges[i].corner);
        S.m.push_back(ray_direction(fan.wedges[i], T));
        S.source_kind.push_back(border ? 1 : 0);
        ++rays;
      }
    }
    if(!border && rays != map.st.quarter_turns[v]) ++S.cones_with_wrong_ray_count;
  }
  if(S.cones == 0 && S.border_corners == 0) {
    S.seeded = true;
    for(int h = 0; h < cm.n_halfedges; ++h)
      if(!cm.is_border_halfedge(h)) {
        for(int m : {0, 1, 2, 3}) { S.corner.push_back(h); S.m.push_back(m); S.source_kind.push_back(2); }
        break;
      }
  }
  return S;
}

// Traces all separatrices together; runs[i] is separatrix i.
inline void trace_separatrices(const Tracing_map& map, const Separatrix_seeds& S, std::size_t max_steps,
                               std::vector<Trace_run>& runs, Trail_registry& trails)
{
  trails.init(map.cm);
  Isoline_stepper stepper(map);
  stepper.trails = &trails;
  if(max_steps > 0) stepper.max_steps = max_steps;
  runs.assign(S.corner.size(), Trace_run());
  typedef std::pair<double, int> Key;
  std::priority_queue<Key, std::vector<Key>, std::greater<Key> > queue;
  for(std::size_t i = 0; i < runs.size(); ++i) {
    runs[i].id = int(i);
    if(S.source_kind[i] == 2) stepper.start_at_vertex(runs[i], S.corner[i], S.m[i]);   // finds the sector
    else stepper.start_in_wedge(runs[i], S.corner[i], S.m[i]);
    if(runs[i].finished) continue;
    queue.push(Key(0., int(i)));
  }
  while(!queue.empty()) {
    const int i = queue.top().second;
    queue.pop();
    stepper.step(runs[i]);
    if(!runs[i].finished) queue.push(Key(runs[i].length, i));
  }
}

} // namespace tracing
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_MOTORCYCLE_GRAPH_H
