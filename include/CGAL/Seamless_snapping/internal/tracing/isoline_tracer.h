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
// the vertex it may end at), so that several traces can advance together (motorcycle graph).
// Stops (Trace_end): cone, border, target, closed loop, earlier trace (the trails of a
// Trail_registry), step limit; or an inconsistency of the map, reported with its place.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/Trace_end.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/tracing/chart_geometry.h>
#include <CGAL/Seamless_snapping/internal/tracing/face_crossing.h>
#include <CGAL/Seamless_snapping/internal/tracing/tracing_map.h>
#include <CGAL/Seamless_snapping/internal/tracing/vertex_passage.h>

#include <cmath>
#include <string>
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
    if(X.may_be(cm.u[c[i]], cm.v[c[i]]) && corner_uv(cm, c[i]) == x) return Raw_point{AT_VERTEX, c[i], x};
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

// Trails of earlier traces, per face (segments in that face's chart) and per vertex.
struct Trail_registry
{
  struct Stored { int trace; Exact_uv a, b; };
  std::vector<std::vector<Stored> > per_face;
  std::vector<int> vertex_trace;      // -1 or the first trace through (or from) the vertex
  std::vector<int> ended_on;          // per trace: the trace it ended on (EARLIER_TRACE), else -1
  std::size_t laid = 0;               // segments laid so far (Raw_segment::order)
  void init(const Corner_mesh& cm) { per_face.assign(cm.n_faces, {}); vertex_trace.assign(cm.n_vertices, -1); ended_on.clear(); laid = 0; }
  int ended_on_trace(int trace) const { return trace >= 0 && std::size_t(trace) < ended_on.size() ? ended_on[std::size_t(trace)] : -1; }
};

struct Trace_target
{
  int vertex = -1;     // a vertex, or
  int face = -1;       // a point of a face, in its chart
  Exact_uv uv;
};

struct Trace_run
{
  int id = 0;
  int face_h = -1;            // a halfedge of the current face: p and m are in its chart
  Exact_uv p;
  int m = 0;
  Raw_point loc;              // where p is
  bool at_start = true;       // no segment yet
  bool along_border = false;  // left the last vertex along a border edge
  int start_vertex = -1, start_corner = -1, start_m = 0, start_face = -1;
  Exact_uv start_p;
  std::size_t steps = 0;
  double length = 0;          // parametric length, rounded (for scheduling and reports only)
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

  const Corner_mesh& cm() const { return map.cm; }

  void finish(Trace_run& r, Trace_end e, const std::string& detail) const
  {
    r.finished = true; r.end = e; r.detail = detail;
    if(trails && e == Trace_end::EARLIER_TRACE && r.id >= 0) {
      if(trails->ended_on.size() <= std::size_t(r.id)) trails->ended_on.resize(std::size_t(r.id) + 1, -1);
      trails->ended_on[std::size_t(r.id)] = r.hit_trace;
    }
  }

  // Start at the vertex target(corner), direction m in the chart of face(corner): the sector that
  // contains the ray is found as in a vertex passage.
  void start_at_vertex(Trace_run& r, int corner, int m) const
  {
    r.start_vertex = cm().target[corner];
    const Vertex_fan fan = vertex_fan(map.cm, map.rot, corner, m);
    if(fan.degenerate) return finish(r, Trace_end::DEGENERATE_VERTEX, "start vertex " + std::to_string(r.start_vertex));
    // the ray along d_m: on the first edge of the start corner (lifted 0), else the first one
    // counter-clockwise from it (lifted 8); on an open fan also the one clockwise from it (lifted 0)
    // A ray along an edge is taken, as in a vertex passage, in the wedge where it is e_b (so that a
    // closed loop comes back to the same corner and direction).
    std::vector<int> found;
    if(fan.wedges[fan.start].La == 0) {
      const int i = fan.closed ? int(fan.wedges.size()) - 1 : fan.start - 1;
      if(i >= 0) { depart(r, fan.wedges[i].corner, ray_direction(fan.wedges[i], fan.wedges[i].Lb)); found.push_back(i); }
      else { depart(r, fan.wedges[fan.start].corner, fan.wedges[fan.start].m); found.push_back(fan.start); }
    } else {
      wedges_containing(fan, 8, found);
      if(!fan.closed) wedges_containing(fan, 0, found);
      if(found.size() == 1) depart(r, fan.wedges[found[0]].corner, direction_mod4(fan.wedges[found[0]].m));
    }
    if(found.size() != 1)
      return finish(r, Trace_end::INVALID_START, "no unique sector of vertex " + std::to_string(r.start_vertex) +
                                                 " contains the start direction (" + std::to_string(found.size()) + ")");
    r.start_corner = r.face_h; r.start_m = r.m;
    register_vertex(r, r.start_vertex);
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

  void step(Trace_run& r) const
  {
    if(r.finished) return;
    const Corner_mesh& M = cm();
    const int f = M.face[r.face_h];
    const int orientation = face_orientation(M, r.face_h);
    if(orientation == 0 && pass_collapsed_face(r)) return;
    if(orientation <= 0)
      return finish(r, Trace_end::FOLDED_FACE, "face " + std::to_string(f) + " is flipped or degenerate in UV");
    const Face_exit ex = cross_face(map, r.face_h, r.p, r.m);
    if(ex.kind == NO_PROGRESS) {
      if(r.loc.kind == ON_EDGE && !r.at_start)
        return finish(r, Trace_end::OSCILLATION_AT_CUT, "behind the cut edge " + vertex_pair_name(M, r.loc.h) +
                                                        ", the direction points back onto it (face " + std::to_string(f) + ")");
      return finish(r, Trace_end::NO_CONTINUATION_AT_VERTEX, "no progress in face " + std::to_string(f));
    }
    // stops inside the segment: target, closed loop, earlier trails (earliest along the segment)
    // candidates at parameter a in (0, ex.along], or [0, ex.along] after the start; the earliest wins,
    // ties keep the first found (target, closed loop, then trails in their order)
    const bool include_start = !r.at_start;
    FT stop_at;
    Trace_end stop = Trace_end::LENGTH_LIMIT;
    bool stopped = false;
    int hit = -1;
    auto consider = [&](const FT& a, Trace_end e, int trace) {
      if(CGAL::is_negative(a) || (CGAL::is_zero(a) && !include_start) || a > ex.along) return;
      if(stopped && !(a < stop_at)) return;
      stop_at = a; stop = e; stopped = true; hit = trace;
    };
    auto on_line = [&](const Exact_uv& x, FT& a) {
      FT s;
      frame_coordinates(r.m, x.u - r.p.u, x.v - r.p.v, a, s);
      return CGAL::is_zero(s);
    };
    FT a;
    if(target && target->face == f && on_line(target->uv, a)) consider(a, Trace_end::TARGET, -1);
    if(r.start_face == f && r.start_m == r.m && on_line(r.start_p, a) && !r.at_start) consider(a, Trace_end::CLOSED_LOOP, -1);
    if(trails)
      for(const Trail_registry::Stored& t : trails->per_face[f]) {
        FT aA, sA, aB, sB;
        frame_coordinates(r.m, t.a.u - r.p.u, t.a.v - r.p.v, aA, sA);
        frame_coordinates(r.m, t.b.u - r.p.u, t.b.v - r.p.v, aB, sB);
        const int gA = CGAL::sign(sA), gB = CGAL::sign(sB);
        if(gA == 0 && gB == 0) {                                   // collinear: first common point
          const FT lo = aA < aB ? aA : aB, hi = aA < aB ? aB : aA;
          if(CGAL::is_positive(lo)) consider(lo, Trace_end::EARLIER_TRACE, t.trace);
          else if(CGAL::is_positive(hi) || (CGAL::is_zero(hi) && include_start)) { // along it from P: stop at P
            stop_at = FT(0); stop = Trace_end::EARLIER_TRACE; stopped = true; hit = t.trace;
          }
        } else if(gA * gB <= 0) {
          const FT x = aA + (sA / (sA - sB)) * (aB - aA);
          // a trace that ended on this one at its current point (both reached it in one round) is a T-junction
          // onto this trace, which goes on (stopping too would leave a corner of two arcs, a 270-degree patch corner)
          if(CGAL::is_zero(x) && trails->ended_on_trace(t.trace) == r.id) continue;
          consider(x, Trace_end::EARLIER_TRACE, t.trace);
        }
      }
    if(stopped) {
      const Exact_uv x = advance(r.p, r.m, stop_at);
      if(CGAL::is_positive(stop_at)) push_segment(r, f, locate_in_face(cm(), r.face_h, x));
      r.hit_trace = hit;
      return finish(r, stop, stop == Trace_end::EARLIER_TRACE ? "T-junction with trace " + std::to_string(hit) : "");
    }

    const Raw_point to = ex.kind == EXIT_VERTEX ? Raw_point{AT_VERTEX, ex.h, ex.point} : Raw_point{ON_EDGE, ex.h, ex.point};
    push_segment(r, f, to);
    ++r.steps;
    r.length += CGAL::to_double(ex.along);
    r.at_start = false;

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
    if(r.steps >= max_steps) finish(r, Trace_end::LENGTH_LIMIT, "");
  }

  // A face of zero UV area with three distinct corners (collinear: the limit of a thin positive triangle, the face
  // beyond its long side on one side of its line, those beyond its short sides on the other, as the quad extraction
  // collapses it) is crossed without advancing: from r.p on its line through the side that holds r.p inside and has
  // the direction on its outer side (not the side the trace came in through), or, arrived at its middle corner, on
  // from that vertex. False (nothing done) where that does not apply: a side of length zero, a direction along the
  // line, no such side.
  bool pass_collapsed_face(Trace_run& r) const
  {
    const Corner_mesh& M = cm();
    const int c[3] = {r.face_h, M.next[r.face_h], M.next[M.next[r.face_h]]};
    for(int i = 0; i < 3; ++i)
      if(corner_uv(map, c[i]) == corner_uv(map, c[(i + 1) % 3])) return false;
    const int entry = r.loc.kind == ON_EDGE ? r.loc.h : -1;
    const Exact_uv d = advance(Exact_uv{FT(0), FT(0)}, r.m, FT(1));
    for(int g : c) {                               // the side of g: from corner prev(g) to corner g
      const Exact_uv& A = corner_uv(map, M.prev[g]);
      const Exact_uv& B = corner_uv(map, g);
      if(g == entry || r.p == A || r.p == B) continue;
      const FT lambda = lerp_parameter(A, B, r.p);
      if(!(CGAL::is_positive(lambda) && lambda < FT(1))) continue;
      if(!CGAL::is_negative((B.u - A.u) * d.v - (B.v - A.v) * d.u)) continue;   // not to the right of A -> B
      ++r.steps;
      cross_edge(r, g, r.p, lambda);
      return true;
    }
    if(entry >= 0)
      for(int g : c)
        if(corner_uv(map, g) == r.p) { ++r.steps; r.face_h = g; arrive_at_vertex(r, g, r.m); return true; }
    return false;
  }

  void run_to_end(Trace_run& r) const { while(!r.finished) step(r); }

  // Start at target(corner) along d_m in the chart of face(corner), a ray of the corner's wedge.
  void start_in_wedge(Trace_run& r, int corner, int m) const
  {
    r.start_vertex = cm().target[corner];
    depart(r, corner, direction_mod4(m));
    r.start_corner = corner; r.start_m = r.m;
    register_vertex(r, r.start_vertex);
  }

private:
  void depart(Trace_run& r, int corner, int m) const
  {
    r.face_h = corner; r.m = m; r.p = corner_uv(map, corner);
    r.loc = Raw_point{AT_VERTEX, corner, r.p};
  }

  void register_vertex(const Trace_run& r, int v) const
  {
    if(trails && trails->vertex_trace[v] < 0) trails->vertex_trace[v] = r.id;
  }

  void push_segment(Trace_run& r, int f, const Raw_point& to) const
  {
    Raw_segment s;
    s.face = f; s.m = r.m; s.from = r.loc; s.from.uv = r.p; s.to = to;
    if(trails) {
      s.order = trails->laid++;
      trails->per_face[f].push_back(Trail_registry::Stored{r.id, r.p, to.uv});
      // a segment along an edge is a trail of the face on the other side too (in its chart)
      const int c[3] = {r.face_h, cm().next[r.face_h], cm().next[cm().next[r.face_h]]};
      const Uv_box P(r.p), Q(to.uv);
      for(int h : c) {
        if(cm().is_border_halfedge(cm().opp[h]) || corner_side_sign(cm(), cm().prev[h], h, r.p, P) != 0 ||
           corner_side_sign(cm(), cm().prev[h], h, to.uv, Q) != 0)
          continue;
        const Edge_transition T = edge_transition(map, h, false);
        trails->per_face[cm().face[cm().opp[h]]].push_back(Trail_registry::Stored{r.id, T.apply(r.p), T.apply(to.uv)});
      }
    }
    r.segments.push_back(std::move(s));
  }

  // the trace reached the vertex target(corner) in the chart of face(corner), direction m
  void arrive_at_vertex(Trace_run& r, int corner, int m) const
  {
    const Corner_mesh& M = cm();
    const int v = M.target[corner];
    const std::string where = "vertex " + std::to_string(v);
    if(target && target->vertex == v) return finish(r, Trace_end::TARGET, where);
    if(map.st.is_cone[v]) return finish(r, Trace_end::CONE, where);
    if(trails && trails->vertex_trace[v] >= 0 && v != r.start_vertex) {
      r.hit_trace = trails->vertex_trace[v];
      return finish(r, Trace_end::EARLIER_TRACE, "T-junction at " + where);
    }
    const Vertex_fan fan = vertex_fan(M, map.rot, corner, m);
    if(fan.degenerate) return finish(r, Trace_end::DEGENERATE_VERTEX, where + " has a zero-length UV edge");
    const int back = fan.wedges[fan.start].La <= 4 ? 4 : 12;     // lifted value of the ray back along the trace
    std::vector<int> found;
    wedges_containing(fan, back - 4, found);
    wedges_containing(fan, back + 4, found);
    const bool arrived_along_border = !fan.closed &&
        (fan.wedges.front().La == back || fan.wedges.back().Lb == back);
    if(found.size() == 1) {
      const Fan_wedge& w = fan.wedges[found[0]];
      const int T = (w.La < back + 4 && back + 4 <= w.Lb) || (!fan.closed && found[0] == 0 && w.La == back + 4)
                    ? back + 4 : back - 4;
      depart(r, w.corner, ray_direction(w, T));
      r.along_border = arrived_along_border;
      if(v == r.start_vertex && r.face_h == r.start_corner && r.m == r.start_m)
        return finish(r, Trace_end::CLOSED_LOOP, where);
      register_vertex(r, v);
      if(r.steps >= max_steps) finish(r, Trace_end::LENGTH_LIMIT, "");
      return;
    }
    if(found.empty() && !fan.closed)
      return finish(r, arrived_along_border && map.fan_quarter_turns[v] == 2 ? Trace_end::FELL_OFF_BORDER : Trace_end::BORDER,
                    "border " + where);
    return finish(r, found.empty() ? Trace_end::NO_CONTINUATION_AT_VERTEX : Trace_end::SEVERAL_CONTINUATIONS_AT_VERTEX,
                  where + ": " + std::to_string(found.size()) + " continuing sectors");
  }
};

} // namespace tracing
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_ISOLINE_TRACER_H
