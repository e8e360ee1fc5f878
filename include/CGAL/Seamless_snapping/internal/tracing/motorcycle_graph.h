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
// turn) the axis rays strictly inside its fan. All traces start at time 0 and move at unit speed (time =
// parametric length); each stops at a cone, the border, or where it reaches the trail of a trace that
// passed there earlier (T-junction); traces that reach a point at the same time: head-on both stop, at
// right angles the one heading a quarter turn counter-clockwise from the other goes on. The result depends
// neither on the triangulation nor on the numbering.
// A map without cones and border corners (a torus, a cylinder) gets four seeded traces, +u, +v, -u and -v, from the
// first corner (in halfedge order) whose vertex is interior: with all four the seed is a node with right angles only (with two,
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
    // the first corner of an interior vertex (from a border vertex, e.g. the first corner of a cylinder, a ray leaves
    // the surface: invalid_start, one failed trace on an exact map); the first corner where every vertex is on the border
    S.seeded = true;
    int seed = -1;
    for(int h = 0; h < cm.n_halfedges && (seed < 0 || cm.vertex_on_border[cm.target[seed]]); ++h)
      if(!cm.is_border_halfedge(h) && (seed < 0 || !cm.vertex_on_border[cm.target[h]])) seed = h;
    if(seed >= 0)
      for(int m : {0, 1, 2, 3}) { S.corner.push_back(seed); S.m.push_back(m); S.source_kind.push_back(2); }
  }
  return S;
}

// Traces all separatrices together; runs[i] is separatrix i. An event simulation in exact time (parametric length):
// each trace's next event is the exit of its current face, a stop on a trail planned there, or a meeting (traces that
// reach a point at the same time: inside a face, on an edge, at a vertex), decided once every trace that gets there
// then has arrived (Isoline_stepper::plan(), execute()); the earliest event first, meetings after the other events
// of their time (then the smaller index: the outcome does not depend on it). A stop whose trail turns out not to
// reach its point (the other trace stopped before it) is planned again; a trace whose trail another one reaches
// later gets that one stopped (stop requests).
inline void trace_separatrices(const Tracing_map& map, const Separatrix_seeds& S, std::size_t max_steps,
                               std::vector<Trace_run>& runs, Trail_registry& trails)
{
  trails.init(map.cm, S.corner.size());
  Isoline_stepper stepper(map);
  stepper.trails = &trails;
  if(max_steps > 0) stepper.max_steps = max_steps;
  runs.assign(S.corner.size(), Trace_run());
  struct Event { FT time; int phase, trace; unsigned version; };    // phase 1: meetings, after the other events then
  auto later = [](const Event& a, const Event& b) {
    return b.time < a.time || (a.time == b.time && (b.phase < a.phase || (a.phase == b.phase && b.trace < a.trace)));
  };
  std::priority_queue<Event, std::vector<Event>, decltype(later)> queue(later);
  std::vector<unsigned> version(runs.size(), 0);
  auto schedule = [&](int i) {
    const Trace_run& r = runs[std::size_t(i)];
    if(!r.finished) queue.push(Event{r.event_time, r.event_phase, i, ++version[std::size_t(i)]});
  };
  auto serve_requests = [&] {
    for(const Trail_registry::Stop_request& q : trails.requests) {
      Trace_run& u = runs[std::size_t(q.trace)];
      if(u.finished || !u.planned || u.vertex_meeting || u.event_time < q.time || (q.meet && !(u.passed_until < q.time)) ||
         (u.event_time == q.time && u.stops && (q.meet || !u.meet)))   // at the same time a stop beats a meeting
        continue;
      u.stops = true; u.meet = q.meet; u.stop_at = q.time - u.time; u.stop_end = Trace_end::EARLIER_TRACE;
      u.hit = q.hit; u.hit_time = q.hit_time; u.event_time = q.time; u.event_phase = q.meet ? 1 : 0;
      schedule(q.trace);
    }
    trails.requests.clear();
  };
  for(std::size_t i = 0; i < runs.size(); ++i) {
    runs[i].id = int(i);
    if(S.source_kind[i] == 2) stepper.start_at_vertex(runs[i], S.corner[i], S.m[i]);   // finds the sector
    else stepper.start_in_wedge(runs[i], S.corner[i], S.m[i]);
  }
  for(std::size_t i = 0; i < runs.size(); ++i) {
    stepper.plan(runs[i]);
    serve_requests();
    schedule(int(i));
  }
  while(!queue.empty()) {
    const Event e = queue.top();
    queue.pop();
    Trace_run& r = runs[std::size_t(e.trace)];
    if(e.version != version[std::size_t(e.trace)] || r.finished) continue;
    stepper.execute(r);
    if(!r.finished && !r.planned) stepper.plan(r);
    serve_requests();
    schedule(e.trace);
  }
}

} // namespace tracing
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_MOTORCYCLE_GRAPH_H
