// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_FACE_SUBDIVISION_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_FACE_SUBDIVISION_H

// The faces of the map cut by the segments of traces (the arcs of a motorcycle graph): the UV triangle
// of every face, in its own chart, becomes a set of convex polygons. The segments are inserted in the
// order they were laid (Raw_segment::order). A trace stops at every trail laid before it (T-junction),
// so each segment lies in one polygon and ends on its boundary: it splits that polygon in two, or, when
// it runs along the polygon's boundary, marks those sides. One exception: a segment along a side of its face
// whose trace had the right of way where another trace reached the side at the same time and stopped there
// (a meeting on an edge, motorcycle_graph.h): that trace's segment, laid first, cut the side, and the
// segment is inserted in parts, between the side's points. All points are exact (CGAL::Gmpq; the sign tests
// filtered by interval arithmetic on their double enclosures, orientation_sign()) and are
// identified across faces: a vertex by its index, a point of an edge by its parameter along the edge
// (the same from both sides of an exact cut), a point inside a face by its UV in that face's chart.
// A segment that fits no polygon (possible on inexact maps only) is counted, not inserted.

#include <CGAL/Seamless_snapping/internal/tracing/isoline_tracer.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace tracing {

// A point of the subdivision. AT_VERTEX: `vertex`; ON_EDGE: the point at parameter t from the source
// to the target of `halfedge` (the edge's `edge_halfedge`); IN_FACE: `uv` in the chart of `face`.
struct Layout_vertex
{
  Location_kind kind = AT_VERTEX;
  int vertex = -1, halfedge = -1, face = -1;
  FT t = zero_rational();
  Exact_uv uv;
};

struct Layout_polygon
{
  int face = -1;              // the face of the map it lies in
  std::vector<int> vertex;    // Layout_vertex indices, counter-clockwise in the chart of `face`
  std::vector<Exact_uv> uv;   // their UVs in that chart
  std::vector<Uv_box> box;    // their UVs' double intervals (the filter of the sign tests)
  std::vector<char> arc;      // arc[i] != 0: the side from corner i to corner i + 1 lies on a trace
};

struct Face_subdivision
{
  std::vector<Layout_vertex> vertices;   // the mesh's vertices first, with their indices
  std::vector<Layout_polygon> polygons;
  std::size_t unplaced = 0;              // segments that fit no polygon (inexact maps)
  std::string first_unplaced;
};

class Face_subdivider
{
public:
  Face_subdivider(const Tracing_map& map, Face_subdivision& out) : map_(map), cm_(map.cm), out_(out) {}

  // subdivides every face by `segments` (in any order; inserted by Raw_segment::order, a segment whose end lies on
  // a segment inserted later (a trace that stopped on a trail whose crossing of the face ended after the stop) once
  // that one is in). Two segments that end at one point inside a face (traces that met head-on) are one chord. Every
  // face must be positively oriented in UV.
  void run(std::vector<const Raw_segment*> segments)
  {
    out_ = Face_subdivision();
    out_.vertices.resize(std::size_t(cm_.n_vertices));
    for(int v = 0; v < cm_.n_vertices; ++v) out_.vertices[std::size_t(v)].vertex = v;
    std::sort(segments.begin(), segments.end(),
              [](const Raw_segment* a, const Raw_segment* b) { return a->order < b->order; });
    // where the segments' ends lie (located once), and the points of every edge
    std::vector<std::array<Place, 2> > ends;
    ends.reserve(segments.size());
    edge_params_.assign(std::size_t(cm_.n_edges), {});
    for(const Raw_segment* s : segments) {
      const Uv_box from(s->from.uv), to(s->to.uv);
      ends.push_back({{place(s->face, s->from.uv, from), place(s->face, s->to.uv, to)}});
      for(const Place& q : ends.back())
        if(q.kind == ON_EDGE) edge_params_[std::size_t(cm_.edge[q.h])].push_back(q.t);
    }
    edge_point_.assign(std::size_t(cm_.n_edges), {});
    for(std::size_t e = 0; e < edge_params_.size(); ++e) {
      std::vector<FT>& t = edge_params_[e];
      std::sort(t.begin(), t.end());
      t.erase(std::unique(t.begin(), t.end()), t.end());
      edge_point_[e].assign(t.size(), -1);
    }
    face_polygons_.assign(std::size_t(cm_.n_faces), {});
    out_.polygons.reserve(std::size_t(cm_.n_faces) + segments.size());   // a segment splits at most one polygon in two
    for(int f = 0; f < cm_.n_faces; ++f) initial_polygon(f);
    std::vector<std::vector<std::size_t> > waiting(std::size_t(cm_.n_faces));   // per face: segments with an end not
    for(std::size_t i = 0; i < segments.size(); ++i) {                        // yet on a piece's boundary
      std::vector<std::size_t>& w = waiting[std::size_t(segments[i]->face)];
      if(insert_segment(*segments[i], ends[i], false)) insert_waiting(segments, ends, w, false);
      else w.push_back(i);
    }
    for(std::vector<std::size_t>& w : waiting) if(!w.empty()) insert_waiting(segments, ends, w, true);
  }

private:
  struct Place                                         // where a segment's end lies
  {
    Location_kind kind;
    int h;                                             // the corner (AT_VERTEX) or the side's halfedge (ON_EDGE)
    FT t;                                              // ON_EDGE: the parameter along the edge (edge_parameter())
    Uv_box box;                                        // the end's UV box
  };

  const Tracing_map& map_;
  const Corner_mesh& cm_;
  Face_subdivision& out_;
  std::vector<std::vector<FT> > edge_params_;             // per edge: the parameters of its points along its edge_halfedge, ascending
  std::vector<std::vector<int> > edge_point_;             // per edge: the Layout_vertex of each of them, or -1
  std::vector<std::vector<int> > face_polygons_;          // per face: indices into out_.polygons
  std::vector<char> on_p_, on_q_;                         // insert_segment(): the sides whose lines hold its ends
  struct Point_id { int id = -1; };                       // a Layout_vertex, -1 until made
  std::map<std::tuple<int, FT, FT>, Point_id> face_point_;   // (face, u, v) -> Layout_vertex

  int corner(int f, int i) const
  {
    int h = map_.face_halfedge[std::size_t(f)];
    for(; i > 0; --i) h = cm_.next[h];
    return h;
  }

  // parameter along the edge_halfedge of the edge of h, of the point p of h's side (chart of face(h))
  FT edge_parameter(int h, const Exact_uv& p) const
  {
    const FT t = lerp_parameter(corner_uv(map_, cm_.prev[h]), corner_uv(map_, h), p);
    return cm_.edge_halfedge[std::size_t(cm_.edge[h])] == h ? t : one_minus(t);
  }

  // where the point p (box `box`) of the closed UV triangle of face f lies
  Place place(int f, const Exact_uv& p, const Uv_box& box) const
  {
    const Raw_point r = locate_in_face(cm_, map_.face_halfedge[std::size_t(f)], p, box);
    return Place{r.kind, r.h, r.kind == ON_EDGE ? edge_parameter(r.h, p) : zero_rational(), box};
  }

  // the Layout_vertex of the point of edge(q.h) at parameter q.t, or -1; k: the index of q.t in the edge's parameters,
  // or -1 (looked up)
  int& edge_point_id(const Place& q, std::ptrdiff_t k)
  {
    const std::size_t e = std::size_t(cm_.edge[q.h]);
    const std::vector<FT>& t = edge_params_[e];
    if(k < 0) k = std::lower_bound(t.begin(), t.end(), q.t) - t.begin();
    CGAL_assertion(std::size_t(k) < t.size() && t[std::size_t(k)] == q.t);
    return edge_point_[e][std::size_t(k)];
  }

  // the Layout_vertex of the point p of face f at its place q, made the first time it is asked for (k: as above)
  int vertex_id(int f, const Exact_uv& p, const Place& q, std::ptrdiff_t k = -1)
  {
    if(q.kind == AT_VERTEX) return cm_.target[q.h];
    int& id = q.kind == ON_EDGE ? edge_point_id(q, k) : face_point_[std::make_tuple(f, p.u, p.v)].id;
    if(id >= 0) return id;
    Layout_vertex lv;
    lv.kind = q.kind;
    if(q.kind == ON_EDGE) { lv.halfedge = cm_.edge_halfedge[std::size_t(cm_.edge[q.h])]; lv.t = q.t; }
    else { lv.face = f; lv.uv = p; }
    id = int(out_.vertices.size());
    out_.vertices.push_back(lv);
    return id;
  }

  // the triangle of f with the points of its edges, counter-clockwise
  void initial_polygon(int f)
  {
    Layout_polygon P;
    P.face = f;
    std::size_t n = 3;                                       // its corners: the triangle's and its edges' points
    for(int i = 0; i < 3; ++i) n += edge_params_[std::size_t(cm_.edge[corner(f, i)])].size();
    P.vertex.reserve(n); P.uv.reserve(n); P.box.reserve(n);
    for(int i = 0; i < 3; ++i) {
      const int c = corner(f, i), h = cm_.next[c];          // the side from corner c to corner next(c) is halfedge h
      const Exact_uv& A = corner_uv(map_, c);
      P.vertex.push_back(cm_.target[c]);
      P.uv.push_back(A);
      P.box.emplace_back(cm_.u[c], cm_.v[c]);
      const std::vector<FT>& ts = edge_params_[std::size_t(cm_.edge[h])];
      if(ts.empty()) continue;
      const bool along = cm_.edge_halfedge[std::size_t(cm_.edge[h])] == h;
      const Exact_uv& B = corner_uv(map_, h);
      for(std::size_t k = 0; k < ts.size(); ++k) {           // strictly inside the side: its place is known
        const std::size_t i = along ? k : ts.size() - 1 - k;
        const FT& t_edge = ts[i];
        const Exact_uv p = lerp(A, B, along ? t_edge : one_minus(t_edge));
        const Uv_box p_box(p);
        P.vertex.push_back(vertex_id(f, p, Place{ON_EDGE, h, t_edge, p_box}, std::ptrdiff_t(i)));
        P.uv.push_back(p);
        P.box.push_back(p_box);
      }
    }
    P.arc.assign(P.vertex.size(), 0);
    face_polygons_[std::size_t(f)].push_back(int(out_.polygons.size()));
    out_.polygons.push_back(std::move(P));
  }

  // the side of the line of side i of P on which x (with its box X) lies
  static int side_sign(const Layout_polygon& P, std::size_t i, const Exact_uv& x, const Uv_box& X)
  {
    const std::size_t j = (i + 1) % P.uv.size();
    return orientation_sign(P.uv[i], P.box[i], P.uv[j], P.box[j], x, X);
  }

  // whether x (with its box X) lies in the closed polygon P; if so, on[i] != 0 where it lies on the line of side i
  static bool contains(const Layout_polygon& P, const Exact_uv& x, const Uv_box& X, std::vector<char>& on)
  {
    on.assign(P.uv.size(), 0);
    for(std::size_t i = 0; i < P.uv.size(); ++i) {
      const int s = side_sign(P, i, x, X);
      if(s < 0) return false;
      on[i] = s == 0;
    }
    return true;
  }

  // makes p a corner of every polygon of face f that has p inside one of its sides
  void add_corner(int f, const Exact_uv& p, const Uv_box& box, int id)
  {
    for(int k : face_polygons_[std::size_t(f)]) {
      Layout_polygon& P = out_.polygons[std::size_t(k)];
      if(std::find(P.uv.begin(), P.uv.end(), p) != P.uv.end()) continue;
      for(std::size_t i = 0; i < P.uv.size(); ++i) {
        const std::size_t j = (i + 1) % P.uv.size();
        if(side_sign(P, i, p, box) != 0) continue;
        if(direction_sign(P.uv[i], P.box[i], P.uv[j], P.box[j], p, box) <= 0 ||
           direction_sign(P.uv[j], P.box[j], P.uv[i], P.box[i], p, box) <= 0)
          continue;                                          // not strictly between the side's ends
        P.uv.insert(P.uv.begin() + std::ptrdiff_t(i + 1), p);
        P.box.insert(P.box.begin() + std::ptrdiff_t(i + 1), box);
        P.vertex.insert(P.vertex.begin() + std::ptrdiff_t(i + 1), id);
        P.arc.insert(P.arc.begin() + std::ptrdiff_t(i + 1), P.arc[i]);
        break;
      }
    }
  }

  // whether the common end X of the waiting segments w[k] and w[l] lies strictly inside another waiting segment: then
  // their traces did not meet head-on there but stopped on that one's trail from both sides (two T-junctions at one
  // point), and that segment, once its own end is on a boundary, puts X on one
  bool inside_another(const std::vector<const Raw_segment*>& segments, const std::vector<std::array<Place, 2> >& ends,
                      const std::vector<std::size_t>& w, std::size_t k, std::size_t l) const
  {
    const Exact_uv& x = segments[w[k]]->to.uv;
    const Uv_box& X = ends[w[k]][1].box;
    for(std::size_t i = 0; i < w.size(); ++i) {
      if(i == k || i == l) continue;
      const Raw_segment& c = *segments[w[i]];
      const Uv_box& A = ends[w[i]][0].box;
      const Uv_box& B = ends[w[i]][1].box;
      if(orientation_sign(c.from.uv, A, c.to.uv, B, x, X) == 0 && direction_sign(c.from.uv, A, c.to.uv, B, x, X) > 0 &&
         direction_sign(c.to.uv, B, c.from.uv, A, x, X) > 0)
        return true;
    }
    return false;
  }

  // inserts the waiting segments `w` of a face that fit now, until none does; then, with `stuck`, two that end at one
  // point inside the face (traces that met head-on, not on another waiting segment: inside_another()) as one chord,
  // and again; the rest as unplaced
  void insert_waiting(const std::vector<const Raw_segment*>& segments, const std::vector<std::array<Place, 2> >& ends,
                      std::vector<std::size_t>& w, bool stuck)
  {
    for(;;) {
      bool progress = false;
      for(std::size_t k = 0; k < w.size() && !progress; ++k)
        if(insert_segment(*segments[w[k]], ends[w[k]], false)) { w.erase(w.begin() + std::ptrdiff_t(k)); progress = true; }
      if(progress) continue;
      if(!stuck) return;
      for(std::size_t k = 0; k < w.size() && !progress; ++k)
        for(std::size_t l = k + 1; l < w.size() && !progress; ++l) {
          const Raw_segment& a = *segments[w[k]];
          const Raw_segment& b = *segments[w[l]];
          if(a.to.kind != IN_FACE || b.to.kind != IN_FACE || a.to.uv != b.to.uv || direction_mod4(a.m - b.m) != 2 ||
             inside_another(segments, ends, w, k, l))
            continue;
          Raw_segment chord = a;
          chord.to = b.from;
          insert_segment(chord, {{ends[w[k]][0], ends[w[l]][0]}}, true);
          w.erase(w.begin() + std::ptrdiff_t(l));
          w.erase(w.begin() + std::ptrdiff_t(k));
          progress = true;
        }
      if(progress) continue;
      for(std::size_t i : w) insert_segment(*segments[i], ends[i], true);
      w.clear();
      return;
    }
  }

  // The segment s along a side of its face, with points of that side strictly between its ends (see the header), in
  // parts from point to point (insert_segment() each); false (nothing done) if s runs along no side or no point of
  // the side lies between its ends
  bool insert_along_side(const Raw_segment& s, const std::array<Place, 2>& ends, bool last_try)
  {
    const int f = s.face;
    for(int i = 0; i < 3; ++i) {
      const int h = corner(f, i), a = cm_.prev[h];                // the side from corner a to corner h
      if(corner_side_sign(cm_, a, h, s.from.uv, ends[0].box) != 0 || corner_side_sign(cm_, a, h, s.to.uv, ends[1].box) != 0)
        continue;
      const Exact_uv& A = corner_uv(map_, a);
      const Exact_uv& B = corner_uv(map_, h);
      const FT tp = lerp_parameter(A, B, s.from.uv), tq = lerp_parameter(A, B, s.to.uv);
      const bool along = cm_.edge_halfedge[std::size_t(cm_.edge[h])] == h;
      std::vector<FT> cuts;                                     // parameters from A to B, strictly between the ends
      for(const FT& t_edge : edge_params_[std::size_t(cm_.edge[h])]) {
        const FT t = along ? t_edge : one_minus(t_edge);
        if((tp < t && t < tq) || (tq < t && t < tp)) cuts.push_back(t);
      }
      if(cuts.empty()) return false;
      std::sort(cuts.begin(), cuts.end());
      if(tq < tp) std::reverse(cuts.begin(), cuts.end());
      Raw_segment part = s;
      Place from = ends[0];
      for(std::size_t k = 0; k <= cuts.size(); ++k) {
        Place to = ends[1];
        part.to = s.to;
        if(k < cuts.size()) {
          part.to = Raw_point{ON_EDGE, h, lerp(A, B, cuts[k])};
          to = place(f, part.to.uv, Uv_box(part.to.uv));
        }
        insert_segment(part, {{from, to}}, last_try);         // along a piece's side now (else counted as unplaced)
        part.from = part.to;
        from = to;
      }
      return true;
    }
    return false;
  }

  // `ends`: the places of s.from and s.to. False (nothing done) if an end lies inside the piece that holds the segment
  // and not `last_try` (a segment inserted later may put it on a boundary); on the last try such a segment is unplaced
  bool insert_segment(const Raw_segment& s, const std::array<Place, 2>& ends, bool last_try)
  {
    const Exact_uv& p = s.from.uv;
    const Exact_uv& q = s.to.uv;
    if(p == q) return true;
    const int f = s.face;
    const Uv_box& p_box = ends[0].box;
    const Uv_box& q_box = ends[1].box;
    int pick = -1;
    bool inside = false;
    for(int k : face_polygons_[std::size_t(f)]) {
      const Layout_polygon& P = out_.polygons[std::size_t(k)];
      if(!contains(P, p, p_box, on_p_) || !contains(P, q, q_box, on_q_)) continue;
      // the open segment runs inside P unless both ends lie on the line of one side (the orientation determinant is
      // affine in the point: the midpoint lies on a side's line iff both ends do)
      bool along = false;
      for(std::size_t i = 0; i < on_p_.size() && !along; ++i) along = on_p_[i] && on_q_[i];
      if(!along) { pick = k; inside = true; break; }
      if(pick < 0) pick = k;                                 // along its boundary
    }
    // an end strictly inside the piece (on_p_, on_q_: of the piece picked inside, the last one tested)
    const bool dangling = inside && (std::find(on_p_.begin(), on_p_.end(), 1) == on_p_.end() ||
                                     std::find(on_q_.begin(), on_q_.end(), 1) == on_q_.end());
    if(dangling && !last_try) return false;
    if(pick < 0 && insert_along_side(s, ends, last_try)) return true;
    if(pick < 0 || dangling) {
      if(out_.unplaced++ == 0)
        out_.first_unplaced = "a segment of trace in face " + std::to_string(f) + (pick < 0 ? " fits no piece of the face" : " ends inside a piece");
      return true;
    }
    const int ip = vertex_id(f, p, ends[0]), iq = vertex_id(f, q, ends[1]);
    add_corner(f, p, p_box, ip);
    add_corner(f, q, q_box, iq);
    Layout_polygon& P = out_.polygons[std::size_t(pick)];
    const std::size_t n = P.uv.size();
    const std::size_t i = std::size_t(std::find(P.vertex.begin(), P.vertex.end(), ip) - P.vertex.begin());
    const std::size_t j = std::size_t(std::find(P.vertex.begin(), P.vertex.end(), iq) - P.vertex.begin());
    // an end that add_corner() did not make a corner of the piece: exact signs never leave one so, but a floating-point
    // environment that breaks interval arithmetic can (valgrind, which ignores the rounding mode CGAL sets, did, and
    // then read past the piece's corners); the segment is counted as not placed, nothing is read out of range
    if(i == n || j == n) {
      if(out_.unplaced++ == 0)
        out_.first_unplaced = "a segment of trace in face " + std::to_string(f) + " whose end is no corner of its piece";
      return true;
    }
    if(!inside) {              // along the boundary: mark the straight way from i to j (forward or backward)
      bool straight = true;
      for(std::size_t k = (i + 1) % n; k != j && straight; k = (k + 1) % n)
        straight = orientation_sign(p, p_box, q, q_box, P.uv[k], P.box[k]) == 0;
      for(std::size_t k = straight ? i : j; k != (straight ? j : i); k = (k + 1) % n) P.arc[k] = 1;
      return true;
    }
    Layout_polygon A, B;
    A.face = B.face = f;
    for(Layout_polygon* X : {&A, &B}) {                        // corners i..j and j..i
      const std::size_t m = (X == &A ? j + n - i : i + n - j) % n + 1;
      X->vertex.reserve(m); X->uv.reserve(m); X->box.reserve(m); X->arc.reserve(m);
    }
    for(std::size_t k = i; ; k = (k + 1) % n) {
      A.vertex.push_back(P.vertex[k]); A.uv.push_back(P.uv[k]); A.box.push_back(P.box[k]); A.arc.push_back(k == j ? 1 : P.arc[k]);
      if(k == j) break;
    }
    for(std::size_t k = j; ; k = (k + 1) % n) {
      B.vertex.push_back(P.vertex[k]); B.uv.push_back(P.uv[k]); B.box.push_back(P.box[k]); B.arc.push_back(k == i ? 1 : P.arc[k]);
      if(k == i) break;
    }
    P = std::move(A);
    face_polygons_[std::size_t(f)].push_back(int(out_.polygons.size()));
    out_.polygons.push_back(std::move(B));
    return true;
  }
};

} // namespace tracing
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_FACE_SUBDIVISION_H
