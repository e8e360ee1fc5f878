// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_ISOLINE_TRACER_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_ISOLINE_TRACER_H

// The isoline tracer as a resumable state machine: one call of step() crosses one face (and passes
// the vertex it may end at): plan() the crossing, then execute() it, so that several traces can advance
// together in exact time (the event simulation of the motorcycle graph, motorcycle_graph.h).
// Stops (Trace_end): cone, border, target, closed loop, earlier trace (the trails of a
// Trail_registry, with the times their traces passed), step limit; or an inconsistency of the map,
// reported with its place.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/Trace_end.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/tracing/chart_geometry.h>
#include <CGAL/Seamless_snapping/internal/tracing/face_crossing.h>
#include <CGAL/Seamless_snapping/internal/tracing/tracing_map.h>
#include <CGAL/Seamless_snapping/internal/tracing/vertex_passage.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace tracing {

enum Location_kind { AT_VERTEX = 0, ON_EDGE = 1, IN_FACE = 2 };

struct Raw_point
{
  Location_kind kind = IN_FACE;
  int h = -1;          // AT_VERTEX: corner (target = the vertex); ON_EDGE: halfedge of the edge; both in the segment's face
  Exact_uv uv;         // in the chart of the segment's face
};

// location of a point x of the closed UV triangle of face(h): a corner (h, next, next-next, in this
// order) it equals, else a side it lies on (its halfedge), else the interior
inline Raw_point locate_in_face(const Corner_mesh& cm, int h, const Exact_uv& x, const Uv_box& X)
{
  const int c[3] = {h, cm.next[h], cm.next[cm.next[h]]};   // the rationals only where x's box X cannot decide
  for(int i = 0; i < 3; ++i)
    if(X.may_be(cm.u[c[i]], cm.v[c[i]]) && equals_double(x.u, cm.u[c[i]]) && equals_double(x.v, cm.v[c[i]]))
      return Raw_point{AT_VERTEX, c[i], x};
  for(int j = 0; j < 3; ++j)
    if(corner_side_sign(cm, cm.prev[c[j]], c[j], x, X) == 0) return Raw_point{ON_EDGE, c[j], x};
  return Raw_point{IN_FACE, -1, x};
}

inline Raw_point locate_in_face(const Corner_mesh& cm, int h, const Exact_uv& x)
{
  return locate_in_face(cm, h, x, Uv_box(x));
}

struct Raw_segment
{
  int face = -1;
  int m = 0;           // direction in the face's chart
  Raw_point from, to;
  std::size_t order = 0; // when it was laid, among the segments of all traces of one Trail_registry
};

// Trails of traces, per face (paths in that face's chart) and per vertex, with the exact times (parametric lengths
// from the start) at which their traces pass: the clock of the motorcycle graph (motorcycle_graph.h).
struct Trail_registry
{
  // a path of `trace` in the face's chart from a, reached at `time`, towards b along direction m: the whole crossing
  // the trace planned when it entered the face; it ends earlier if the trace stops (end_time)
  struct Stored { int trace; Exact_uv a, b; FT time; int m; };
  // a trace that must stop at time `time`, where it reaches the trail of `hit`, which passed there at `hit_time` (or
  // at the same time and has the right of way), found when the trail of `hit` was planned (Isoline_stepper::plan());
  // `meet`: it reaches there at the same time as `hit` and others perhaps (decided when it gets there)
  struct Stop_request { int trace; FT time; int hit; FT hit_time; bool meet; };
  std::vector<std::vector<Stored> > per_face;
  // a trace that reached a vertex: in the chart of face(corner) (target(corner) = the vertex), with direction m
  struct Arrival { int trace, corner, m; };
  // per vertex: the traces that got there first (through it or from it), all at one time, vertex_time (they decide
  // together); the first of them is the one a later trace stops on
  std::vector<std::vector<Arrival> > vertex_arrivals;
  std::vector<FT> vertex_time;
  std::vector<char> ended;            // per trace: it has ended, at end_time
  std::vector<FT> end_time;
  std::vector<Stop_request> requests; // for the scheduler
  std::size_t laid = 0;               // segments laid so far (Raw_segment::order)
  void init(const Corner_mesh& cm, std::size_t traces)
  {
    per_face.assign(cm.n_faces, {});
    vertex_arrivals.assign(cm.n_vertices, {}); vertex_time.assign(cm.n_vertices, FT(0));
    ended.assign(traces, 0); end_time.assign(traces, FT(0));
    requests.clear(); laid = 0;
  }
  // whether `trace` reached the point of its trail that it reaches at `time` (its trail there exists): it has not
  // ended before; for a trace alive, the events up to now (>= time) have not stopped it
  bool reached(int trace, const FT& time) const { return !ended[std::size_t(trace)] || !(end_time[std::size_t(trace)] < time); }
};

struct Trace_target
{
  int vertex = -1;                                 // a vertex, and/or a point (set_target_point()):
  std::vector<std::pair<int, Exact_uv> > points;   // per face that holds it, the point in that face's chart
  int point_vertex = -1;                           // the vertex the point is, if it is one

  bool at_vertex(int v) const { return v == vertex || v == point_vertex; }
};

// The target point uv of the closed UV triangle of face(h), in that face's chart; where it lies inside an edge, also in
// the chart of the face beyond it (the same place along the edge), and where it is a corner, also that vertex: a trace
// that met the point in another face of it than the one given went past it (along the edge, through the vertex)
inline void set_target_point(const Tracing_map& map, int h, const Exact_uv& uv, Trace_target& t)
{
  const Corner_mesh& cm = map.cm;
  t.points.emplace_back(cm.face[h], uv);
  const int c[3] = {h, cm.next[h], cm.prev[h]};
  for(int e : c)
    if(corner_uv(map, e) == uv) { t.point_vertex = cm.target[e]; return; }
  for(int e : c) {                                 // the edge source(e) -> target(e): A -> B in face(h)
    const int o = cm.opp[e];
    const Exact_uv& A = corner_uv(map, cm.prev[e]);
    const Exact_uv& B = corner_uv(map, e);
    if(cm.face[o] < 0 || A == B || CGAL::sign(orientation_determinant(A, B, uv)) != CGAL::ZERO) continue;
    const FT du = B.u - A.u, dv = B.v - A.v;
    const FT s = CGAL::abs(du) >= CGAL::abs(dv) ? (uv.u - A.u) / du : (uv.v - A.v) / dv;
    if(!(CGAL::is_positive(s) && s < 1)) continue;
    const Exact_uv& A2 = corner_uv(map, o);        // source(e) and target(e) in face(o)
    const Exact_uv& B2 = corner_uv(map, cm.prev[o]);
    t.points.emplace_back(cm.face[o], Exact_uv{A2.u + s * (B2.u - A2.u), A2.v + s * (B2.v - A2.v)});
    return;
  }
}

struct Trace_run
{
  int id = 0;
  int face_h = -1;            // a halfedge of the current face: p and m are in its chart
  Exact_uv p;
  int m = 0;
  Raw_point loc;              // where p is
  bool at_start = true;       // no segment yet, or only the crossing of a zero-area face (pass_collapsed_face())
  bool along_border = false;  // left the last vertex along a border edge
  int start_vertex = -1, start_corner = -1, start_m = 0, start_face = -1;
  Exact_uv start_p;
  std::size_t steps = 0;
  double length = 0;          // parametric length, rounded (for reports only)
  FT time = zero_rational();  // parametric length at p, exact (the clock of the motorcycle graph)
  // the next event, planned in the current face (Isoline_stepper::plan()): the exit `ex`, or a stop at `stop_at`
  // along the direction (reason stop_end; EARLIER_TRACE: on the trail of `hit`, which passes there at `hit_time`)
  Face_exit ex;
  bool planned = false, stops = false, path_registered = false;
  bool meet = false;          // the stop is a meeting inside the face or on an edge: stop or go on is decided there
  bool vertex_meeting = false;// arrived at the vertex target(face_h) with direction m: stop or go on is decided there
  int event_phase = 0;        // 1: a meeting, decided after the other events at its time (all arrivals known)
  FT stop_at = zero_rational(), hit_time = zero_rational(), event_time = zero_rational();
  FT passed_until = FT(-1);   // meetings up to this time are decided (it went on)
  Trace_end stop_end = Trace_end::LENGTH_LIMIT;
  int hit = -1;
  bool finished = false;
  Trace_end end = Trace_end::LENGTH_LIMIT;
  std::string detail;
  int hit_trace = -1;         // EARLIER_TRACE: the trace that was hit
  std::size_t inexact_transfers = 0; // cut crossings where R^k X + t missed the edge point
  std::vector<Raw_segment> segments;
};

class Isoline_stepper
{
public:
  const Tracing_map& map;
  Trail_registry* trails = nullptr;
  const Trace_target* target = nullptr;
  std::size_t max_steps = 0;

  explicit Isoline_stepper(const Tracing_map& m) : map(m), max_steps(std::size_t(20) * m.cm.n_faces + 100) {}

  // the message of a trace stopped at the face limit (it was empty)
  std::string length_limit_message() const
  {
    return "stopped after " + std::to_string(max_steps) + " face crossings, the limit (max_faces)";
  }

  const Corner_mesh& cm() const { return map.cm; }

  void finish(Trace_run& r, Trace_end e, const std::string& detail) const
  {
    r.finished = true; r.end = e; r.detail = detail;
    if(trails && r.id >= 0 && std::size_t(r.id) < trails->ended.size()) {
      trails->ended[std::size_t(r.id)] = 1;
      trails->end_time[std::size_t(r.id)] = r.time;
    }
  }

  // Start at the vertex target(corner), direction m in the chart of face(corner): the sector that
  // contains the ray is found as in a vertex passage; at a cone, the ray in that chart where the chart shows it
  // (chart_wedge_of_start_ray()), else the one reached counter-clockwise from the corner.
  void start_at_vertex(Trace_run& r, int corner, int m) const
  {
    r.start_vertex = cm().target[corner];
    Vertex_fan fan = vertex_fan(map.cm, map.rot, corner, m);
    if(fan.degenerate) return finish(r, Trace_end::DEGENERATE_VERTEX, "start vertex " + std::to_string(r.start_vertex));
    // the ray that the chart of face(corner) shows around v, from the corner of that chart whose angle holds it (the
    // same chart: the same m; the ray is then on its first edge or counter-clockwise of it, below); at a cone, turning
    // counter-clockwise from `corner` reached another ray or none
    const int in_chart = chart_wedge_of_start_ray(fan, cm(), map.st.is_cut);
    if(in_chart > 0) fan = vertex_fan(map.cm, map.rot, fan.wedges[std::size_t(in_chart)].corner, m);
    // the ray along d_m: on the first edge of the start corner (lifted 0), else the first one
    // counter-clockwise from it (lifted 8); on an open fan also the one clockwise from it (lifted 0)
    // A ray along an edge is taken, as in a vertex passage, in the wedge where it is e_b (so that a
    // closed loop comes back to the same corner and direction), past the wedges of zero width (the end corners of
    // zero-area triangles along the ray), which contain no ray in a vertex passage either.
    std::vector<int> found;
    if(fan.wedges[fan.start].La == 0) {
      const int n = int(fan.wedges.size());
      int i = fan.start;
      do i = fan.closed ? (i + n - 1) % n : i - 1;
      while(i >= 0 && i != fan.start && fan.wedges[i].La == fan.wedges[i].Lb);
      if(i == fan.start) i = -1;
      if(i >= 0) { depart(r, fan.wedges[i].corner, ray_direction(fan.wedges[i], fan.wedges[i].Lb)); found.push_back(i); }
      else { depart(r, fan.wedges[fan.start].corner, fan.wedges[fan.start].m); found.push_back(fan.start); }
    } else {
      wedges_containing(fan, 8, found);
      if(!fan.closed) wedges_containing(fan, 0, found);
      if(found.size() == 1) depart(r, fan.wedges[found[0]].corner, direction_mod4(fan.wedges[found[0]].m));
    }
    if(found.size() != 1)   // (the count was printed as if it were the direction)
      return finish(r, Trace_end::INVALID_START,
                    found.empty() ? "no sector of vertex " + std::to_string(r.start_vertex) + " contains the start direction " +
                                        std::to_string(m) + (fan.closed ? std::string() : " (a border vertex: the ray leaves the surface)")
                                  : std::to_string(found.size()) + " sectors of vertex " + std::to_string(r.start_vertex) +
                                        " contain the start direction " + std::to_string(m));
    r.start_corner = r.face_h; r.start_m = r.m;
    register_vertex(r, r.start_vertex, r.start_corner, r.start_m);
  }

  // Start at the point p of the closed UV triangle of face(h); on an edge, the trace begins in the
  // neighbouring face when d_m points out of this one.
  void start_at_point(Trace_run& r, int h, const Exact_uv& p, int m) const
  {
    const int c[3] = {h, cm().next[h], cm().next[cm().next[h]]};
    for(int i = 0; i < 3; ++i)
      if(corner_uv(map, c[i]) == p) return start_at_vertex(r, c[i], m);
    FT det[3];
    for(int j = 0; j < 3; ++j)
      det[j] = orientation_determinant(corner_uv(map, cm().prev[c[j]]), corner_uv(map, c[j]), p);
    for(int j = 0; j < 3; ++j)
      if(CGAL::is_negative(det[j]) || face_orientation(cm(), h) <= 0)
        return finish(r, Trace_end::INVALID_START, "the start point is not inside the (non-folded) UV triangle of face " +
                                                   std::to_string(cm().face[h]));
    r.face_h = h; r.p = p; r.m = direction_mod4(m);
    r.loc = Raw_point{IN_FACE, -1, p};
    for(int j = 0; j < 3; ++j) if(CGAL::is_zero(det[j])) r.loc = Raw_point{ON_EDGE, c[j], p};
    if(r.loc.kind == ON_EDGE && cross_face(map, h, p, r.m).kind == NO_PROGRESS) {
      const int e = r.loc.h;
      if(cm().is_border_halfedge(cm().opp[e]))
        return finish(r, Trace_end::INVALID_START, "the start direction leaves the mesh through a border edge");
      const Exact_uv& A = corner_uv(map, cm().prev[e]);
      const Exact_uv& B = corner_uv(map, e);
      const Edge_transfer tr = transfer_through_edge(map, e, p, lerp_parameter(A, B, p), r.m);
      if(tr.kind != TRANSFER_EDGE)
        return finish(r, Trace_end::INVALID_START, "the start point does not continue across its edge");
      r.face_h = cm().opp[e]; r.p = tr.point; r.m = tr.m; r.loc = Raw_point{ON_EDGE, cm().opp[e], tr.point};
    }
    r.start_face = cm().face[r.face_h]; r.start_p = r.p; r.start_m = r.m;
  }

  // One face: plan() the crossing, then execute() it.
  void step(Trace_run& r) const
  {
    plan(r);
    if(!r.finished) execute(r);
  }

  // Plans r's crossing of its current face: the exit `r.ex`, or the first stop before it (target, closed loop, a
  // trail). With a Trail_registry (the motorcycle graph), r's path is registered as a trail of the face from now on,
  // and a trail stops r where its trace passed earlier; where r passes first, the other trace gets a stop request
  // (Trail_registry::requests), since it reaches r's trail later. Traces that reach a point at the same time: head-on
  // both stop; at right angles the one heading a quarter turn counter-clockwise from the other goes on (the rule of
  // quad_mesh_patches(), so that on an integer-grid map both partitions agree). May finish r (no valid crossing).
  void plan(Trace_run& r) const
  {
    if(r.finished) return;
    const Corner_mesh& M = cm();
    int orientation = face_orientation(M, r.face_h);
    while(orientation == 0 && pass_collapsed_face(r)) {
      if(r.finished || r.vertex_meeting) return;               // through the face to a vertex: a meeting there
      orientation = face_orientation(M, r.face_h);
    }
    const int f = M.face[r.face_h];
    if(orientation <= 0)
      return finish(r, Trace_end::FOLDED_FACE, "face " + std::to_string(f) + " is flipped or degenerate in UV");
    const Face_exit ex = cross_face(map, r.face_h, r.p, r.m);
    if(ex.kind == NO_PROGRESS) {
      if(r.loc.kind == ON_EDGE && !r.at_start)
        return finish(r, Trace_end::OSCILLATION_AT_CUT, "behind the cut edge " + vertex_pair_name(M, r.loc.h) +
                                                        ", the direction points back onto it (face " + std::to_string(f) + ")");
      return finish(r, Trace_end::NO_CONTINUATION_AT_VERTEX, "no progress in face " + std::to_string(f));
    }
    r.ex = ex;
    r.planned = true;
    r.stops = false;
    r.meet = false;
    r.hit = -1;
    if(trails && !r.path_registered) register_path(r, f);
    // stops inside the crossing at parameter a in (0, ex.along], or [0, ex.along] after the start; the earliest wins,
    // ties keep the first found (target, closed loop, then trails in their order)
    const bool include_start = !r.at_start;
    auto consider = [&](const FT& a, Trace_end e, int trace, const FT& trace_time, bool at_once, bool meet) {
      if(CGAL::is_negative(a) || (CGAL::is_zero(a) && !include_start && !at_once) || a > ex.along) return;
      if(r.stops && !(a < r.stop_at) && !(a == r.stop_at && r.meet && !meet)) return;   // a stop beats a meeting there
      r.stops = true; r.stop_at = a; r.stop_end = e; r.hit = trace; r.hit_time = trace_time; r.meet = meet;
    };
    auto on_line = [&](const Exact_uv& x, FT& a) {
      if(side_sign(r.m, x, r.p) != 0) return false;
      a = along_difference(r.m, x, r.p);
      return true;
    };
    FT a = zero_rational();
    if(target)
      for(const std::pair<int, Exact_uv>& q : target->points)
        if(q.first == f && on_line(q.second, a)) consider(a, Trace_end::TARGET, -1, FT(0), false, false);
    if(r.start_face == f && r.start_m == r.m && on_line(r.start_p, a) && !r.at_start)
      consider(a, Trace_end::CLOSED_LOOP, -1, FT(0), false, false);
    if(trails)
      for(const Trail_registry::Stored& t : trails->per_face[f]) meet_trail(r, t, ex.along, include_start, consider);
    r.event_time = r.time + (r.stops ? r.stop_at : ex.along);
    r.event_phase = r.stops && r.meet ? 1 : 0;
  }

  // Carries out the planned event: the stop (if the trail that stops r is still there: its trace reached the point;
  // else r is planned again), or the crossing to the exit and on into the next face or through the vertex there.
  void execute(Trace_run& r) const
  {
    if(r.finished || !r.planned) return;
    r.planned = false;
    if(r.vertex_meeting) {
      r.vertex_meeting = false;
      const int v = cm().target[r.face_h];
      if(!goes_on_at_vertex(r)) {
        r.hit_trace = r.hit;
        return finish(r, Trace_end::EARLIER_TRACE, "T-junction at vertex " + std::to_string(v));
      }
      Fan_wedge w;
      int T = 0;
      bool along_border = false;
      if(continuation(r, r.face_h, r.m, w, T, along_border)) leave_vertex(r, v, w, T, along_border);
      return;
    }
    const int f = cm().face[r.face_h];
    if(r.stops && r.meet && goes_on_at_meeting(r)) { r.passed_until = r.event_time; return plan(r); }
    if(r.stops) {
      if(r.hit >= 0 && trails && !trails->reached(r.hit, r.hit_time)) return plan(r);
      const FT stop_at = r.stop_at;
      if(CGAL::is_positive(stop_at)) {
        push_segment(r, f, locate_in_face(cm(), r.face_h, advance(r.p, r.m, stop_at)));
        r.length += CGAL::to_double(stop_at);
        r.time = r.event_time;                                 // r.time + stop_at
      }
      r.hit_trace = r.hit;
      return finish(r, r.stop_end, r.stop_end == Trace_end::EARLIER_TRACE ? "T-junction with trace " + std::to_string(r.hit) : "");
    }
    const Face_exit& ex = r.ex;                             // the next plan() replaces it, not cross_edge()
    const Raw_point to = ex.kind == EXIT_VERTEX ? Raw_point{AT_VERTEX, ex.h, ex.point} : Raw_point{ON_EDGE, ex.h, ex.point};
    push_segment(r, f, to);
    ++r.steps;
    r.length += CGAL::to_double(ex.along);
    r.time = r.event_time;                                     // r.time + ex.along
    r.at_start = false;
    r.path_registered = false;

    if(ex.kind == EXIT_VERTEX) return arrive_at_vertex(r, ex.h, r.m);
    cross_edge(r, ex.h, ex.point, ex.lambda);
  }

  // The trace leaves face(h) at x inside the side of h (edge parameter lambda from source(h)), direction r.m.
  void cross_edge(Trace_run& r, int h, const Exact_uv& x, const FT& lambda) const
  {
    const Corner_mesh& M = cm();
    const int o = M.opp[h];
    if(M.is_border_halfedge(o))
      return finish(r, r.along_border ? Trace_end::FELL_OFF_BORDER : Trace_end::BORDER, "border edge " + vertex_pair_name(M, h));
    const Edge_transfer tr = transfer_through_edge(map, h, x, lambda, r.m);
    if(tr.kind == TRANSFER_MISSED)
      return finish(r, Trace_end::MISSED_AT_CUT, "behind the cut edge " + vertex_pair_name(M, h) +
                                                 ", the isoline misses the edge in face " + std::to_string(M.face[o]));
    if(!tr.exact) ++r.inexact_transfers;
    r.along_border = false;
    r.m = tr.m; r.p = tr.point;
    if(tr.kind == TRANSFER_VERTEX) { r.face_h = tr.corner; return arrive_at_vertex(r, tr.corner, tr.m); }
    r.face_h = o;
    r.loc = Raw_point{ON_EDGE, o, tr.point};
    if(r.steps >= max_steps) finish(r, Trace_end::LENGTH_LIMIT, length_limit_message());
  }

  // A face of zero UV area with three distinct corners (collinear: the limit of a thin positive triangle, the face
  // beyond its long side on one side of its line, those beyond its short sides on the other, as the quad extraction
  // collapses it) is crossed without advancing in UV: from r.p on its line through the side that holds r.p inside and
  // has the direction on its outer side (not the side the trace came in through), or, arrived at its middle corner, on
  // from that vertex. The crossing is a segment of zero UV length all the same: its ends are different points of the
  // surface (of two sides, or a side and the middle vertex), so the polyline stays connected in 3D. It takes no time
  // (parametric length), so a trace that started at the middle corner is still at its start beyond it: the rays that
  // leave a cone there across the line (two where the line is not an axis) reach the long side together and do not
  // meet there. False (nothing done) where that does not apply: a side of length zero, a direction along the line, no
  // such side.
  bool pass_collapsed_face(Trace_run& r) const
  {
    const Corner_mesh& M = cm();
    const int c[3] = {r.face_h, M.next[r.face_h], M.next[M.next[r.face_h]]};
    for(int i = 0; i < 3; ++i)
      if(corner_uv(map, c[i]) == corner_uv(map, c[(i + 1) % 3])) return false;
    const int entry = r.loc.kind == ON_EDGE ? r.loc.h : -1;
    const Exact_uv d = advance(Exact_uv{FT(0), FT(0)}, r.m, FT(1));
    auto lay = [&](const Raw_point& to) { push_segment(r, M.face[r.face_h], to); ++r.steps; };
    for(int g : c) {                               // the side of g: from corner prev(g) to corner g
      const Exact_uv& A = corner_uv(map, M.prev[g]);
      const Exact_uv& B = corner_uv(map, g);
      if(g == entry || r.p == A || r.p == B) continue;
      const FT lambda = lerp_parameter(A, B, r.p);
      if(!(CGAL::is_positive(lambda) && lambda < FT(1))) continue;
      if(!CGAL::is_negative((B.u - A.u) * d.v - (B.v - A.v) * d.u)) continue;   // not to the right of A -> B
      lay(Raw_point{ON_EDGE, g, r.p});
      cross_edge(r, g, r.p, lambda);
      return true;
    }
    if(entry >= 0)
      for(int g : c)
        if(corner_uv(map, g) == r.p) { lay(Raw_point{AT_VERTEX, g, r.p}); r.face_h = g; arrive_at_vertex(r, g, r.m); return true; }
    return false;
  }

  void run_to_end(Trace_run& r) const { while(!r.finished) step(r); }

  // Start at target(corner) along d_m in the chart of face(corner), a ray of the corner's wedge.
  void start_in_wedge(Trace_run& r, int corner, int m) const
  {
    r.start_vertex = cm().target[corner];
    depart(r, corner, direction_mod4(m));
    r.start_corner = corner; r.start_m = r.m;
    register_vertex(r, r.start_vertex, r.start_corner, r.start_m);
  }

private:
  void depart(Trace_run& r, int corner, int m) const
  {
    r.face_h = corner; r.m = m; r.p = corner_uv(map, corner);
    r.loc = Raw_point{AT_VERTEX, corner, r.p};
  }

  // r reaches (or leaves, at its start) the vertex v now, in the chart of face(corner) with direction m: the first
  // trace there, or one of those that got there at the same time
  void register_vertex(const Trace_run& r, int v, int corner, int m) const
  {
    if(!trails) return;
    std::vector<Trail_registry::Arrival>& arrivals = trails->vertex_arrivals[std::size_t(v)];
    if(arrivals.empty()) trails->vertex_time[std::size_t(v)] = r.time;
    else if(!(trails->vertex_time[std::size_t(v)] == r.time)) return;
    arrivals.push_back(Trail_registry::Arrival{r.id, corner, m});
  }

  // Who goes on where traces meet at one time (quad_mesh_patches()'s rule): `others` are the headings of the others
  // relative to r's (quarter turns counter-clockwise) and their traces. r stops if one meets it head-on, or if one at a
  // quarter turn counter-clockwise from it is not met head-on itself (its partner would be at three quarter turns):
  // returns that trace, else -1 (r goes on).
  static int meeting_stop(const std::vector<std::pair<int, int> >& others)
  {
    auto at = [&](int rel) { for(const auto& o : others) if(o.first == rel) return o.second; return -1; };
    if(at(2) >= 0) return at(2);
    return at(1) >= 0 && at(3) < 0 ? at(1) : -1;
  }

  // r's planned crossing as a trail of face f (and of the face across a side it runs along, in that chart)
  void register_path(Trace_run& r, int f) const
  {
    r.path_registered = true;
    const Exact_uv& b = r.ex.point;
    trails->per_face[f].push_back(Trail_registry::Stored{r.id, r.p, b, r.time, r.m});
    const int c[3] = {r.face_h, cm().next[r.face_h], cm().next[cm().next[r.face_h]]};
    const Uv_box P(r.p), Q(b);
    for(int h : c) {
      if(cm().is_border_halfedge(cm().opp[h]) || corner_side_sign(cm(), cm().prev[h], h, r.p, P) != 0 ||
         corner_side_sign(cm(), cm().prev[h], h, b, Q) != 0)
        continue;
      const Edge_transition T = edge_transition(map, h, false);
      trails->per_face[cm().face[cm().opp[h]]].push_back(
          Trail_registry::Stored{r.id, T.apply(r.p), T.apply(b), r.time, direction_mod4(r.m + T.k)});
    }
  }

  // At a meeting inside r's face or on one of its edges (execute()): the traces whose trails reach the point X of r's
  // planned stop at the same time T, r among them, decide by meeting_stop(); their paths through X are registered in
  // r's face or, for a point of an edge, in the face across it (headings carried over by the edge's rotation). False
  // (r stops, r.hit set) also where a trail passed X before T.
  bool goes_on_at_meeting(Trace_run& r) const
  {
    const Exact_uv X = advance(r.p, r.m, r.stop_at);
    const FT T = r.event_time;
    const Raw_point where = locate_in_face(cm(), r.face_h, X);
    std::vector<std::pair<int, int> > others;                  // (heading relative to r's, trace)
    auto scan = [&](int f, const Exact_uv& x, int k) {          // k: the rotation from r's chart to f's
      for(const Trail_registry::Stored& t : trails->per_face[std::size_t(f)]) {
        if(t.trace == r.id || side_sign(t.m, x, t.a) != 0) continue;
        const FT a = along_difference(t.m, x, t.a);
        if(CGAL::is_negative(a)) continue;
        if(along_difference(t.m, t.b, t.a) < a || !trails->reached(t.trace, t.time + a)) continue;
        if(t.time + a < T) { r.hit = t.trace; r.hit_time = t.time + a; return false; }
        const std::pair<int, int> o(direction_mod4(t.m - k - r.m), t.trace);
        if(t.time + a == T && std::find(others.begin(), others.end(), o) == others.end()) others.push_back(o);
      }
      return true;
    };
    if(!scan(cm().face[r.face_h], X, 0)) return false;
    if(where.kind == ON_EDGE && !cm().is_border_halfedge(cm().opp[where.h])) {
      const Edge_transition E = edge_transition(map, where.h, false);
      if(!scan(cm().face[cm().opp[where.h]], E.apply(X), E.k)) return false;
    }
    r.hit = meeting_stop(others);
    r.hit_time = T;
    return r.hit < 0;
  }

  // At a meeting at the vertex target(r.face_h), which r reached with direction r.m (execute()): the traces that got
  // there at the same time decide by meeting_stop(), their arrival directions carried around the fan into r's chart
  bool goes_on_at_vertex(Trace_run& r) const
  {
    const std::vector<Trail_registry::Arrival>& arrivals = trails->vertex_arrivals[std::size_t(cm().target[r.face_h])];
    if(arrivals.size() == 1) return true;                      // r alone
    const Vertex_fan fan = vertex_fan(cm(), map.rot, r.face_h, r.m);
    std::vector<std::pair<int, int> > others;
    for(const Trail_registry::Arrival& a : arrivals)
      for(const Fan_wedge& w : fan.wedges)
        if(a.trace != r.id && w.corner == a.corner) others.emplace_back(direction_mod4(a.m - w.m), a.trace);
    r.hit = meeting_stop(others);
    r.hit_time = r.time;
    return r.hit < 0;
  }

  // Where r's crossing [0, along] (from r.p along r.m, at r.time) and the trail t share a point, the trace that passes
  // it later stops there: r through consider(x, EARLIER_TRACE, trace, its time there), t's trace by a request. Both at
  // the same time: a meeting inside the face or on an edge (a meeting event for both, decided in execute()), none at a
  // vertex (arrive_at_vertex() decides) or at r's start. A trail of a trace that has ended reaches as far as it went;
  // r's own trail stops r only where r passed before (a trace meets its own path at the same time only at its head). A
  // crossing that starts along a trail laid before stops at once, also at the start (the arc exists already).
  template <class Consider>
  void meet_trail(const Trace_run& r, const Trail_registry::Stored& t, const FT& along, bool include_start,
                  Consider& consider) const
  {
    const bool self = t.trace == r.id;
    if(self && !(t.time < r.time)) return;                     // its path now
    const bool t_ended = trails->ended[std::size_t(t.trace)] != 0;
    const int gA = side_sign(r.m, t.a, r.p), gB = side_sign(r.m, t.b, r.p);
    if(gA * gB > 0) return;                                    // t's path on one side of r's line
    FT aA = zero_rational(), sA = zero_rational(), aB = zero_rational(), sB = zero_rational();
    frame_difference(r.m, t.a, r.p, aA, sA);
    frame_difference(r.m, t.b, r.p, aB, sB);
    // decides at r's parameter x, where t's trace passes at time tt (r at time tr): see plan()
    auto meet = [&](const FT& x, const FT& tt, bool at_once) {   // at_once: along t from x = 0 on
      if(t_ended && trails->end_time[std::size_t(t.trace)] < tt) return;      // t's trace stopped before
      const FT tr = r.time + x;
      bool r_stops = tt < tr, t_stops = tr < tt;
      if(tt == tr && !self) {                                  // a meeting (at a vertex: arrive_at_vertex() decides;
        if(CGAL::is_zero(x) && !include_start) return;         // at r's start: none)
        if(locate_in_face(cm(), r.face_h, advance(r.p, r.m, x)).kind == AT_VERTEX) return;
        if(r.passed_until < tr) consider(x, Trace_end::EARLIER_TRACE, t.trace, tt, false, true);
        if(!t_ended) trails->requests.push_back(Trail_registry::Stop_request{t.trace, tt, r.id, tr, true});
        return;
      }
      if(self) { if(!(tt < tr)) return; t_stops = false; }
      if(r_stops) consider(x, Trace_end::EARLIER_TRACE, t.trace, tt, at_once && CGAL::is_zero(x), false);
      if(t_stops && !t_ended && !(CGAL::is_zero(x) && !include_start))
        trails->requests.push_back(Trail_registry::Stop_request{t.trace, tt, r.id, tr, false});
    };
    if(gA == 0 && gB == 0) {                                   // collinear
      const FT lo = aA < aB ? aA : aB, hi = aA < aB ? aB : aA;
      const FT x0 = CGAL::is_positive(lo) ? lo : FT(0), x1 = hi < along ? hi : along;
      if(x1 < x0) return;
      if(aA < aB) {                                            // the same direction: r ahead of t, or t of r
        meet(x0, t.time + (x0 - aA), CGAL::is_positive(x1));
        return;
      }
      const FT xs = (t.time + aA - r.time) / 2;                // head-on: they meet at xs
      const FT x = xs < x0 ? x0 : x1 < xs ? x1 : xs;
      meet(x, t.time + (aA - x), CGAL::is_positive(x1));
      return;
    }
    const FT x = lerp_scalar(aA, aB, crossing_parameter(sA, sB));
    if(CGAL::is_negative(x) || along < x) return;
    const Exact_uv X = advance(r.p, r.m, x);
    meet(x, t.time + along_difference(t.m, X, t.a), false);
  }

  void push_segment(Trace_run& r, int f, const Raw_point& to) const
  {
    Raw_segment s;
    s.face = f; s.m = r.m; s.from = r.loc; s.from.uv = r.p; s.to = to;
    if(trails) s.order = trails->laid++;
    r.segments.push_back(std::move(s));
  }

  // the trace reached the vertex target(corner) in the chart of face(corner), direction m. With a Trail_registry: it
  // stops where a trace passed before; else it waits there for those that arrive at the same time (a meeting at the
  // vertex, execute()), registered as one of them
  void arrive_at_vertex(Trace_run& r, int corner, int m) const
  {
    const Corner_mesh& M = cm();
    const int v = M.target[corner];
    const std::string where = "vertex " + std::to_string(v);
    if(target && target->at_vertex(v)) return finish(r, Trace_end::TARGET, where);
    if(map.st.is_cone[v]) return finish(r, Trace_end::CONE, where);
    const bool meeting = trails && v != r.start_vertex;
    if(meeting && !trails->vertex_arrivals[std::size_t(v)].empty() && trails->vertex_time[std::size_t(v)] < r.time) {
      r.hit_trace = trails->vertex_arrivals[std::size_t(v)].front().trace;
      return finish(r, Trace_end::EARLIER_TRACE, "T-junction at " + where);
    }
    Fan_wedge w;
    int T = 0;
    bool along_border = false;
    if(!continuation(r, corner, m, w, T, along_border)) return;
    if(meeting) {
      register_vertex(r, v, corner, m);
      r.face_h = corner; r.m = m;
      r.planned = true; r.vertex_meeting = true; r.stops = false; r.meet = false;
      r.event_time = r.time; r.event_phase = 1;
      return;
    }
    leave_vertex(r, v, w, T, along_border);
  }

  // The wedge w of the vertex target(corner) that continues a trace arriving in the chart of face(corner) with direction
  // m straight on, and the ray's lifted value T in it; false (r finished: a border, a zero-length edge, no or several
  // continuing wedges) if there is none.
  bool continuation(Trace_run& r, int corner, int m, Fan_wedge& w, int& T, bool& arrived_along_border) const
  {
    const Corner_mesh& M = cm();
    const int v = M.target[corner];
    const std::string where = "vertex " + std::to_string(v);
    const Vertex_fan fan = vertex_fan(M, map.rot, corner, m);
    if(fan.degenerate) { finish(r, Trace_end::DEGENERATE_VERTEX, where + " has a zero-length UV edge"); return false; }
    const int back = fan.wedges[fan.start].La <= 4 ? 4 : 12;     // lifted value of the ray back along the trace
    std::vector<int> found;
    wedges_containing(fan, back - 4, found);
    wedges_containing(fan, back + 4, found);
    arrived_along_border = !fan.closed && (fan.wedges.front().La == back || fan.wedges.back().Lb == back);
    if(found.size() == 1) {
      w = fan.wedges[found[0]];
      T = (w.La < back + 4 && back + 4 <= w.Lb) || (!fan.closed && found[0] == 0 && w.La == back + 4) ? back + 4 : back - 4;
      return true;
    }
    if(found.empty() && !fan.closed)
      finish(r, arrived_along_border && map.fan_quarter_turns[v] == 2 ? Trace_end::FELL_OFF_BORDER : Trace_end::BORDER,
             "border " + where);
    else
      finish(r, found.empty() ? Trace_end::NO_CONTINUATION_AT_VERTEX : Trace_end::SEVERAL_CONTINUATIONS_AT_VERTEX,
             where + ": " + std::to_string(found.size()) + " continuing sectors");
    return false;
  }

  // leaves the vertex v by the wedge w along its ray T (continuation())
  void leave_vertex(Trace_run& r, int v, const Fan_wedge& w, int T, bool arrived_along_border) const
  {
    depart(r, w.corner, ray_direction(w, T));
    r.along_border = arrived_along_border;
    if(v == r.start_vertex && r.face_h == r.start_corner && r.m == r.start_m)
      return finish(r, Trace_end::CLOSED_LOOP, "vertex " + std::to_string(v));
    if(r.steps >= max_steps) finish(r, Trace_end::LENGTH_LIMIT, length_limit_message());
  }

};

} // namespace tracing
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_ISOLINE_TRACER_H
