// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_PATCH_LAYOUT_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_PATCH_LAYOUT_H

// The patch layout of traced separatrices, in three stages:
//   1. refined_mesh():   the face subdivision as a Surface_mesh (one polygon per piece) with is_arc,
//                        input_face and the corner UVs;
//   2. patches:          connected components of the faces, arcs as constrained edges (PMP);
//   3. measure_patches(): per patch the open Euler characteristic, the boundary walk (loops, corners
//                        from UV angle sums), the exact unfolding into one chart and the rectangle test;
//                        then the arc/border graph (nodes, arcs, Euler characteristic).

#include <CGAL/Seamless_snapping/Patch_layout.h>
#include <CGAL/Seamless_snapping/internal/surface/uv_area.h>
#include <CGAL/Seamless_snapping/internal/timing.h>
#include <CGAL/Seamless_snapping/internal/tracing/face_subdivision.h>

#include <CGAL/Mpzf.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <queue>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace tracing {

typedef Layout_mesh::Vertex_index Layout_vertex_index;
typedef Layout_mesh::Halfedge_index Layout_halfedge_index;
typedef Layout_mesh::Face_index Layout_face_index;
typedef Layout_mesh::Edge_index Layout_edge_index;

// X -> R^k X + t composed with other transitions (Edge_transition maps a chart into another)
inline Edge_transition inverse(const Edge_transition& T)
{
  if(T.is_identity()) return T;
  const Exact_uv r = rotate(-T.k, T.t);
  return Edge_transition{direction_mod4(-T.k), Exact_uv{-r.u, -r.v}};
}
inline Edge_transition compose(const Edge_transition& A, const Edge_transition& B)   // A after B
{
  if(B.is_identity()) return A;
  if(A.is_identity()) return B;
  const Exact_uv r = rotate(A.k, B.t);
  return Edge_transition{direction_mod4(A.k + B.k), Exact_uv{r.u + A.t.u, r.v + A.t.v}};
}

// The UV area of the polygon p (counter-clockwise), exactly: the shoelace sum on GMP's rationals in three numbers
// reused across the corners. The same value as the CGAL::Gmpq expression sum of (a.u b.v - a.v b.u) / 2, which makes
// a new number (and allocates) per operation: on the 302K-face bunny of ../shared/large, untangled and traced, the
// 240,796 polygons of the input faces that traces split took 1217 ms so.
inline FT polygon_area(const std::vector<Exact_uv>& p)
{
  Gmp_rational twice, term, other;
  for(std::size_t i = 0; i < p.size(); ++i) {
    const Exact_uv& a = p[i];
    const Exact_uv& b = p[(i + 1) % p.size()];
    mpq_mul(term.q, a.u.mpq(), b.v.mpq());
    mpq_mul(other.q, a.v.mpq(), b.u.mpq());
    mpq_sub(term.q, term.q, other.q);
    mpq_add(twice.q, twice.q, term.q);
  }
  mpq_div_2exp(twice.q, twice.q, 1);
  return FT(twice.q);
}

// index of the corner of polygon P whose vertex is id
inline std::size_t corner_of(const Layout_polygon& P, int id)
{
  return std::size_t(std::find(P.vertex.begin(), P.vertex.end(), id) - P.vertex.begin());
}

// CGAL::to_double(x), read off its enclosing interval X where that is one double (x is that double: an input corner)
inline double as_double(const FT& x, const std::pair<double, double>& X)
{
  return X.first == X.second ? X.first : CGAL::to_double(x);
}

// Stage 1. Returns false (and a message) if a polygon cannot be added (not a manifold refinement).
inline bool refined_mesh(const Tracing_map& map, const Face_subdivision& S,
                         const std::vector<std::array<double, 3> >& position, Layout_mesh& mesh, std::string& message)
{
  typedef Layout_mesh::Point Point_3;
  const Corner_mesh& cm = map.cm;
  mesh.clear();
  std::size_t corners = 0;                                 // every corner is a halfedge: the mesh's sizes known, its
  for(const Layout_polygon& P : S.polygons) corners += P.vertex.size();   // arrays never grow (and copy) while built
  mesh.reserve(Layout_mesh::size_type(S.vertices.size()), Layout_mesh::size_type(corners / 2 + 1),
               Layout_mesh::size_type(S.polygons.size()));
  for(const Layout_vertex& lv : S.vertices) {
    std::array<double, 3> p = {{0, 0, 0}};
    if(lv.kind == AT_VERTEX) p = position[std::size_t(lv.vertex)];
    else if(lv.kind == ON_EDGE) {
      const double t = CGAL::to_double(lv.t);
      const std::array<double, 3>& a = position[std::size_t(cm.source(lv.halfedge))];
      const std::array<double, 3>& b = position[std::size_t(cm.target[lv.halfedge])];
      for(int i = 0; i < 3; ++i) p[i] = (1 - t) * a[i] + t * b[i];
    } else {
      Exact_uv c[3];
      const int h = map.face_halfedge[std::size_t(lv.face)];
      const int hc[3] = {h, cm.next[h], cm.prev[h]};
      for(int i = 0; i < 3; ++i) c[i] = corner_uv(map, hc[i]);
      FT b[3];
      barycentric(c, lv.uv, b);
      for(int i = 0; i < 3; ++i)
        for(int j = 0; j < 3; ++j) p[j] += CGAL::to_double(b[i]) * position[std::size_t(cm.target[hc[i]])][j];
    }
    mesh.add_vertex(Point_3(p[0], p[1], p[2]));
  }
  auto is_arc = mesh.add_property_map<Layout_edge_index, std::uint8_t>("e:is_arc", 0).first;
  auto input_face = mesh.add_property_map<Layout_face_index, std::int32_t>("f:input_face", -1).first;
  auto uv = mesh.add_property_map<Layout_halfedge_index, CGAL::Epick::Point_2>("h:uv").first;
  std::vector<Layout_vertex_index> vs;
  for(std::size_t k = 0; k < S.polygons.size(); ++k) {
    const Layout_polygon& P = S.polygons[k];
    vs.clear();
    for(int id : P.vertex) vs.push_back(Layout_vertex_index(std::uint32_t(id)));
    const Layout_face_index f = mesh.add_face(vs);
    if(f == Layout_mesh::null_face()) {
      message = "the piece " + std::to_string(k) + " of face " + std::to_string(P.face) +
                " cannot be added to the refined mesh (not a manifold refinement)";
      return false;
    }
    put(input_face, f, std::int32_t(P.face));
    for(Layout_halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const std::size_t i = corner_of(P, int(mesh.target(h)));
      put(uv, h, CGAL::Epick::Point_2(as_double(P.uv[i].u, P.box[i].u), as_double(P.uv[i].v, P.box[i].v)));
      if(P.arc[(i + P.vertex.size() - 1) % P.vertex.size()]) put(is_arc, mesh.edge(h), std::uint8_t(1));
    }
  }
  return true;
}

// Stage 3: the properties of every patch (patch_id set) and of the arc/border graph.
class Patch_measurer
{
public:
  Patch_measurer(const Tracing_map& map, const Face_subdivision& S, Patch_layout& L)
    : map_(map), S_(S), L_(L), mesh_(L.mesh)
  {
    is_arc_ = mesh_.property_map<Layout_edge_index, std::uint8_t>("e:is_arc").first;
    patch_ = mesh_.property_map<Layout_face_index, std::int32_t>("f:patch_id").first;
  }

  void run()
  {
    // a polygon alone in its input face is the whole triangle (with points on its sides): its area is the triangle's,
    // an exact determinant of the corners' doubles (most faces: no trace crosses them), summed exactly in Mpzf per
    // patch and made a rational once
    std::vector<int> pieces(std::size_t(map_.cm.n_faces), 0);
    for(const Layout_polygon& P : S_.polygons) ++pieces[std::size_t(P.face)];
    std::vector<CGAL::Mpzf> twice_whole_faces(L_.patches.size(), CGAL::Mpzf(0));
    for(Layout_face_index f : mesh_.faces()) {
      Layout_patch& p = patch(f);
      ++p.polygons;
      const int face = polygon(f).face;
      if(pieces[std::size_t(face)] == 1)
        twice_whole_faces[std::size_t(get(patch_, f))] += twice_triangle_area(map_.face_halfedge[std::size_t(face)]);
      else p.area += polygon_area(polygon(f).uv);
    }
    for(std::size_t k = 0; k < L_.patches.size(); ++k)
      if(!CGAL::is_zero(twice_whole_faces[k])) L_.patches[k].area += FT(CGAL::Gmpq(twice_whole_faces[k])) / 2;
    open_euler_characteristics();
    unfold();
    measure_boxes();
    walk_boundaries();
    for(Layout_patch& p : L_.patches) {
      p.is_rectangle = p.is_rectangle && p.unfolds && p.width * p.height == p.area;
      if(p.is_quad()) ++L_.quad_patches;
    }
    graph();
  }

private:
  const Tracing_map& map_;
  const Face_subdivision& S_;
  Patch_layout& L_;
  const Layout_mesh& mesh_;
  Layout_mesh::Property_map<Layout_edge_index, std::uint8_t> is_arc_;
  Layout_mesh::Property_map<Layout_face_index, std::int32_t> patch_;
  std::vector<Edge_transition> to_patch_;                    // per face: its input chart -> the patch chart
  typedef std::pair<double, double> Interval;
  std::vector<std::array<FT, 4> > box_;                      // per patch: umin, umax, vmin, vmax
  std::vector<std::array<Interval, 4> > box_interval_;       // their double intervals

  const Layout_polygon& polygon(Layout_face_index f) const { return S_.polygons[std::size_t(f)]; }
  // twice the UV area of the input face of h, exactly
  CGAL::Mpzf twice_triangle_area(int h) const
  {
    const Corner_mesh& cm = map_.cm;
    const int a = cm.prev[h], c = cm.next[h];
    return twice_triangle_uv_area(cm.u[a], cm.v[a], cm.u[h], cm.v[h], cm.u[c], cm.v[c]);
  }
  Layout_patch& patch(Layout_face_index f) const { return L_.patches[std::size_t(get(patch_, f))]; }
  bool cuts(Layout_halfedge_index h) const { return get(is_arc_, mesh_.edge(h)) != 0 || mesh_.is_border(mesh_.edge(h)); }
  bool patch_boundary(Layout_halfedge_index h) const { return !mesh_.is_border(h) && cuts(h); }
  // exact UV of the corner (target(h), face(h)) in the chart of its input face
  const Exact_uv& corner(Layout_halfedge_index h) const
  {
    const Layout_polygon& P = polygon(mesh_.face(h));
    return P.uv[corner_of(P, int(mesh_.target(h)))];
  }
  // its double interval
  const Uv_box& corner_box(Layout_halfedge_index h) const
  {
    const Layout_polygon& P = polygon(mesh_.face(h));
    return P.box[corner_of(P, int(mesh_.target(h)))];
  }
  // the corners of g and h are one point in the chart of their patch; where both faces have the same transition into the
  // patch, the corners themselves are compared (a transition is one-to-one), without applying it
  bool agree(Layout_halfedge_index g, Layout_halfedge_index h) const
  {
    const Edge_transition& A = to_patch_[std::size_t(mesh_.face(g))];
    const Edge_transition& B = to_patch_[std::size_t(mesh_.face(h))];
    if(A == B) return corner(g) == corner(h);
    return A.agrees(corner(g), B, corner(h));
  }

  void open_euler_characteristics()
  {
    for(Layout_patch& p : L_.patches) p.euler_characteristic = int(p.polygons);
    for(Layout_edge_index e : mesh_.edges())
      if(!get(is_arc_, e) && !mesh_.is_border(e)) --patch(mesh_.face(mesh_.halfedge(e))).euler_characteristic;
    for(Layout_vertex_index v : mesh_.vertices()) {
      if(mesh_.is_isolated(v) || mesh_.is_border(v)) continue;
      bool inner = true;
      for(Layout_halfedge_index h : CGAL::halfedges_around_target(v, mesh_)) inner = inner && !cuts(h);
      if(inner) ++patch(mesh_.face(mesh_.halfedge(v))).euler_characteristic;
    }
  }

  // x < y, where X and Y enclose x and y: by the intervals where they decide it, else exactly
  static bool less(const FT& x, const Interval& X, const FT& y, const Interval& Y)
  {
    if(X.second < Y.first) return true;
    if(Y.second <= X.first) return false;
    return x < y;
  }

  // x == y, where X and Y enclose x and y: by the intervals where they decide it (disjoint, or both one double), else
  // exactly
  static bool equal(const FT& x, const Interval& X, const FT& y, const Interval& Y)
  {
    if(X.second < Y.first || Y.second < X.first) return false;
    if(X.first == X.second && Y.first == Y.second) return true;
    return x == y;
  }

  // whether the corner of h, in the chart of its patch, lies on a side of the patch's box b (B: its intervals)
  bool on_box(Layout_halfedge_index h, const std::array<FT, 4>& b, const std::array<Interval, 4>& B) const
  {
    if(to_patch_[std::size_t(mesh_.face(h))].is_identity()) {
      const Layout_polygon& P = polygon(mesh_.face(h));
      const std::size_t i = corner_of(P, int(mesh_.target(h)));   // one search for the corner and its box
      const Exact_uv& x = P.uv[i];
      const Uv_box& X = P.box[i];
      return equal(x.u, X.u, b[0], B[0]) || equal(x.u, X.u, b[1], B[1]) || equal(x.v, X.v, b[2], B[2]) ||
             equal(x.v, X.v, b[3], B[3]);
    }
    const Edge_transition& T = to_patch_[std::size_t(mesh_.face(h))];   // x = T(corner(h)), coordinate by coordinate
    Gmp_rational* s = scratch_rationals();
    for(int c = 0; c < 2; ++c) {
      T.apply_coordinate(c, corner(h), s[0].q);
      if(mpq_equal(s[0].q, b[std::size_t(2 * c)].mpq()) || mpq_equal(s[0].q, b[std::size_t(2 * c + 1)].mpq())) return true;
    }
    return false;
  }

  // the transition from the chart of input face(g) into the chart of input face(opposite(g)), g a
  // halfedge of the refined mesh on an edge of the input mesh
  Edge_transition across(Layout_halfedge_index g) const
  {
    const Corner_mesh& cm = map_.cm;
    const int fa = polygon(mesh_.face(g)).face, fb = polygon(mesh_.face(mesh_.opposite(g))).face;
    if(fa == fb) return Edge_transition();
    const Layout_vertex& s = S_.vertices[std::size_t(mesh_.source(g))];
    const Layout_vertex& t = S_.vertices[std::size_t(mesh_.target(g))];
    int hin = -1;
    for(const Layout_vertex* x : {&s, &t})
      if(x->kind == ON_EDGE) hin = cm.face[x->halfedge] == fa ? x->halfedge : cm.opp[x->halfedge];
    if(hin < 0) {                                  // both at vertices: the side of fa from s to t
      int h = map_.face_halfedge[std::size_t(fa)];
      for(int i = 0; i < 3 && hin < 0; ++i, h = cm.next[h])
        if(cm.source(h) == s.vertex && cm.target[h] == t.vertex) hin = h;
    }
    return hin < 0 ? Edge_transition() : edge_transition(map_, hin, false);
  }

  // breadth-first unfolding of every patch into the chart of its first face; checks every inner edge
  void unfold()
  {
    to_patch_.assign(mesh_.number_of_faces(), Edge_transition());
    std::vector<char> seen(mesh_.number_of_faces(), 0);
    for(Layout_patch& p : L_.patches) p.unfolds = true;
    for(Layout_face_index f0 : mesh_.faces()) {
      if(seen[std::size_t(f0)]) continue;
      seen[std::size_t(f0)] = 1;
      std::queue<Layout_face_index> queue;
      queue.push(f0);
      while(!queue.empty()) {
        const Layout_face_index f = queue.front();
        queue.pop();
        for(Layout_halfedge_index h : CGAL::halfedges_around_face(mesh_.halfedge(f), mesh_)) {
          if(cuts(h)) continue;
          const Layout_halfedge_index o = mesh_.opposite(h);
          const Layout_face_index g = mesh_.face(o);
          if(!seen[std::size_t(g)]) {
            seen[std::size_t(g)] = 1;
            to_patch_[std::size_t(g)] = compose(to_patch_[std::size_t(f)], inverse(across(h)));
            queue.push(g);
          }
        }
      }
    }
    for(Layout_edge_index e : mesh_.edges()) {           // both sides of every inner edge agree exactly
      const Layout_halfedge_index h = mesh_.halfedge(e), o = mesh_.opposite(h);
      if(cuts(h)) continue;
      if(!agree(h, mesh_.prev(o)) || !agree(o, mesh_.prev(h))) patch(mesh_.face(h)).unfolds = false;
    }
  }

  // The box of every patch in its chart (after unfold()): each polygon's box in its face's chart, mapped into the
  // patch (a quarter turn maps a box onto a box, corner to corner). The comparisons are decided on double intervals
  // where those are disjoint or one same double (the 302K-face bunny of ../shared/large, untangled: 435,629
  // polygons, this pass 1.3 s on the rationals alone)
  void measure_boxes()
  {
    box_.assign(L_.patches.size(), std::array<FT, 4>());
    box_interval_.assign(L_.patches.size(), std::array<Interval, 4>());
    std::vector<char> first(L_.patches.size(), 1);
    for(Layout_face_index f : mesh_.faces()) {
      const Layout_polygon& P = polygon(f);
      std::array<std::size_t, 4> c = {{0, 0, 0, 0}};      // the corners of least u, largest u, least v, largest v
      for(std::size_t i = 1; i < P.uv.size(); ++i) {
        if(less(P.uv[i].u, P.box[i].u, P.uv[c[0]].u, P.box[c[0]].u)) c[0] = i;
        if(less(P.uv[c[1]].u, P.box[c[1]].u, P.uv[i].u, P.box[i].u)) c[1] = i;
        if(less(P.uv[i].v, P.box[i].v, P.uv[c[2]].v, P.box[c[2]].v)) c[2] = i;
        if(less(P.uv[c[3]].v, P.box[c[3]].v, P.uv[i].v, P.box[i].v)) c[3] = i;
      }
      const Edge_transition& T = to_patch_[std::size_t(f)];
      std::array<const FT*, 4> x = {{&P.uv[c[0]].u, &P.uv[c[1]].u, &P.uv[c[2]].v, &P.uv[c[3]].v}};
      std::array<Interval, 4> X = {{P.box[c[0]].u, P.box[c[1]].u, P.box[c[2]].v, P.box[c[3]].v}};
      Exact_uv a, z;
      if(!T.is_identity()) {
        a = T.apply(Exact_uv{*x[0], *x[2]});
        z = T.apply(Exact_uv{*x[1], *x[3]});
        x = {{&(std::min)(a.u, z.u), &(std::max)(a.u, z.u), &(std::min)(a.v, z.v), &(std::max)(a.v, z.v)}};
        for(int k = 0; k < 4; ++k) X[std::size_t(k)] = interval_of(*x[std::size_t(k)]);
      }
      const std::size_t p = std::size_t(get(patch_, f));
      std::array<FT, 4>& b = box_[p];
      std::array<Interval, 4>& B = box_interval_[p];
      for(std::size_t k = 0; k < 4; ++k) {
        const bool lower = k % 2 == 0;                    // b[0], b[2]: minima; b[1], b[3]: maxima
        if(first[p] || (lower ? less(*x[k], X[k], b[k], B[k]) : less(b[k], B[k], *x[k], X[k]))) { b[k] = *x[k]; B[k] = X[k]; }
      }
      first[p] = 0;
    }
    for(std::size_t p = 0; p < L_.patches.size(); ++p) {
      L_.patches[p].width = box_[p][1] - box_[p][0];
      L_.patches[p].height = box_[p][3] - box_[p][2];
      L_.patches[p].is_rectangle = true;                  // until a boundary vertex is off the box
    }
  }

  // UV angle (radians) of the corner of face(h) at target(h)
  double corner_angle(Layout_halfedge_index h) const
  {
    const Exact_uv& c = corner(h);
    const Exact_uv& a = corner(mesh_.prev(h));
    const Exact_uv& b = corner(mesh_.next(h));
    const FT ax = b.u - c.u, ay = b.v - c.v, bx = a.u - c.u, by = a.v - c.v;
    const FT cross = ax * by - ay * bx, dot = ax * bx + ay * by;
    if(CGAL::is_zero(cross)) return CGAL::is_negative(dot) ? std::acos(-1.) : 0.;   // straight, exactly
    // in (0, pi): convex pieces. Both divided by the larger first (exactly): for UVs beyond about 2^+-255 the products
    // overflowed or underflowed in to_double(), and a map scaled by 2^600 or 2^-600 lost its quad patches
    const FT m = (std::max)(CGAL::abs(cross), CGAL::abs(dot));
    return std::atan2(CGAL::to_double(cross / m), CGAL::to_double(dot / m));
  }

  // corner_angle(h) within 1e-9 radians or so, from the corners' double intervals (no rationals), where those decide
  // that the angle is not 0 or pi and are narrow against the vectors; else corner_angle(h) itself
  double filtered_corner_angle(Layout_halfedge_index h) const
  {
    const Uv_box& c = corner_box(h);
    const Uv_box& a = corner_box(mesh_.prev(h));
    const Uv_box& b = corner_box(mesh_.next(h));
    bool decided = false;
    double y = 0, x = 0;
    {
      CGAL::Protect_FPU_rounding<true> upward;           // (restored before atan2)
      typedef CGAL::Interval_nt<false> I;
      const I ax = I(b.u) - I(c.u), ay = I(b.v) - I(c.v), bx = I(a.u) - I(c.u), by = I(a.v) - I(c.v);
      const I cross = ax * by - ay * bx, dot = ax * bx + ay * by;
      const double scale = (std::max)(CGAL::abs(cross).inf(), CGAL::abs(dot).inf());
      decided = cross.inf() > 0 && cross.sup() - cross.inf() <= 1e-12 * scale && dot.sup() - dot.inf() <= 1e-12 * scale;
      y = cross.inf() + (cross.sup() - cross.inf()) / 2;
      x = dot.inf() + (dot.sup() - dot.inf()) / 2;
    }
    return decided ? std::atan2(y, x) : corner_angle(h);
  }

  // the quarter turns of the patch's corner at target(h): its fan of corners from boundary halfedge h around target(h) to
  // the next boundary halfedge (fan: its halfedges; not Tracing_map::fan_quarter_turns, the whole vertex's), std::lround
  // of the sum of corner_angle(): where the filtered sum is within a quarter of a quarter turn of an integer, the exact
  // one rounds to the same (its corners differ by far less), else it is summed
  long patch_corner_quarter_turns(Layout_halfedge_index h, std::vector<Layout_halfedge_index>& fan) const
  {
    const double quarter = std::acos(-1.) / 2;
    fan.clear();
    double angle = 0;
    Layout_halfedge_index g = h;
    for(std::size_t guard = 0; guard <= mesh_.number_of_halfedges(); ++guard) {
      fan.push_back(g);
      angle += filtered_corner_angle(g);
      if(patch_boundary(mesh_.next(g))) break;
      g = mesh_.opposite(mesh_.next(g));
    }
    const long q = std::lround(angle / quarter);
    if(std::fabs(angle / quarter - double(q)) <= 0.25) return q;
    angle = 0;
    for(Layout_halfedge_index k : fan) angle += corner_angle(k);
    return std::lround(angle / quarter);
  }

  // walks every boundary loop of every patch (interior on the left): loops, corners, box test
  void walk_boundaries()
  {
    std::vector<char> done(mesh_.number_of_halfedges(), 0);
    std::vector<Layout_halfedge_index> fan;
    for(Layout_halfedge_index h0 : mesh_.halfedges()) {
      if(done[std::size_t(h0)] || !patch_boundary(h0)) continue;
      Layout_patch& p = patch(mesh_.face(h0));
      const std::size_t id = std::size_t(get(patch_, mesh_.face(h0)));
      ++p.boundary_loops;
      Layout_halfedge_index h = h0;
      do {
        done[std::size_t(h)] = 1;
        if(mesh_.is_border(mesh_.opposite(h))) p.on_border = true;
        if(!on_box(h, box_[id], box_interval_[id])) p.is_rectangle = false;
        const long q = patch_corner_quarter_turns(h, fan);
        if(q != 2) { ++p.corners; if(q == 1) ++p.right_angle_corners; }
        h = mesh_.next(fan.back());
      } while(h != h0 && !done[std::size_t(h)]);
    }
  }

  // the arcs as vertex chains from node to node along arc and border edges
  void arc_chains()
  {
    std::vector<char> is_node(mesh_.number_of_vertices(), 0), used(mesh_.number_of_edges(), 0);
    for(Layout_vertex_index v : L_.node_vertices) is_node[std::size_t(v)] = 1;
    for(Layout_vertex_index v : L_.node_vertices)
      for(Layout_halfedge_index h0 : CGAL::halfedges_around_source(v, mesh_)) {
        if(!cuts(h0) || used[std::size_t(mesh_.edge(h0))]) continue;
        std::vector<Layout_vertex_index> chain(1, v);
        Layout_halfedge_index h = h0;
        for(;;) {
          used[std::size_t(mesh_.edge(h))] = 1;
          const Layout_vertex_index w = mesh_.target(h);
          chain.push_back(w);
          if(is_node[std::size_t(w)]) break;
          bool next = false;                               // w has degree 2: the other cut edge
          for(Layout_halfedge_index g : CGAL::halfedges_around_source(w, mesh_))
            if(cuts(g) && !used[std::size_t(mesh_.edge(g))]) { h = g; next = true; break; }
          if(!next) break;
        }
        L_.arc_chains.push_back(std::move(chain));
      }
  }

  // the graph of arc and border edges: nodes, arcs, Euler characteristic of the layout
  void graph()
  {
    std::vector<int> degree(mesh_.number_of_vertices(), 0);
    std::size_t graph_edges = 0, graph_vertices = 0;
    for(Layout_edge_index e : mesh_.edges()) {
      if(!cuts(mesh_.halfedge(e))) continue;
      ++graph_edges;
      ++degree[std::size_t(mesh_.vertex(e, 0))];
      ++degree[std::size_t(mesh_.vertex(e, 1))];
    }
    for(std::size_t v = 0; v < degree.size(); ++v) {
      if(degree[v] == 0) continue;
      ++graph_vertices;
      const Corner_mesh& cm = map_.cm;
      const bool input_vertex = v < std::size_t(cm.n_vertices);
      const bool corner = input_vertex && (cm.vertex_on_border[v] ? map_.fan_quarter_turns[v] != 2 : map_.st.is_cone[v] != 0);
      if(degree[v] != 2 || corner) L_.node_vertices.push_back(Layout_vertex_index(std::uint32_t(v)));
    }
    L_.nodes = L_.node_vertices.size();
    L_.arcs = graph_edges - graph_vertices + L_.nodes;
    arc_chains();
    L_.euler_characteristic = int(L_.nodes) - int(L_.arcs) + int(L_.patches.size());
    const Corner_mesh& cm = map_.cm;
    L_.surface_euler_characteristic = cm.n_vertices - cm.n_edges + cm.n_faces;
  }
};

// The layout of the traces `runs` on `map` (vertex positions in 3D for the refined mesh).
inline void build_patch_layout(const Tracing_map& map, const std::vector<Trace_run>& runs,
                               const std::vector<std::array<double, 3> >& position, Patch_layout& L)
{
  const Corner_mesh& cm = map.cm;
  L = Patch_layout();
  std::size_t folded = 0;
  for(int f = 0; f < cm.n_faces; ++f) folded += face_orientation(cm, map.face_halfedge[std::size_t(f)]) <= 0 ? 1 : 0;
  if(folded > 0) {
    L.message = std::to_string(folded) + " faces are flipped or degenerate in UV: a patch layout needs a locally "
                "injective map";
    return;
  }
  L.uv_area = CGAL::Gmpq(twice_uv_area(cm)) / 2;                  // every face positive: the sum of their areas
  std::vector<const Raw_segment*> segments;
  for(const Trace_run& r : runs)
    for(const Raw_segment& s : r.segments) segments.push_back(&s);
  Timing_clock::time_point t = Timing_clock::now();
  Face_subdivision S;
  Face_subdivider(map, S).run(segments);
  L.unplaced_segments = S.unplaced;
  L.subdivision_ms = ms_since(t);
  t = Timing_clock::now();
  const bool built = refined_mesh(map, S, position, L.mesh, L.message);
  L.mesh_ms = ms_since(t);
  if(!built) return;
  t = Timing_clock::now();
  auto patch_id = L.mesh.add_property_map<Layout_face_index, std::int32_t>("f:patch_id", -1).first;
  auto is_arc = L.mesh.property_map<Layout_edge_index, std::uint8_t>("e:is_arc").first;
  const std::size_t n = CGAL::Polygon_mesh_processing::connected_components(
      L.mesh, patch_id, CGAL::parameters::edge_is_constrained_map(is_arc));
  L.patches.assign(n, Layout_patch());
  Patch_measurer(map, S, L).run();
  L.measure_ms = ms_since(t);
  L.status = SUCCESS;
  if(S.unplaced > 0) L.message = std::to_string(S.unplaced) + " trace segments not inserted; first: " + S.first_unplaced;
  else if(!L.is_valid()) {                                          // say why it is not a quad layout
    L.message = "not a quad layout:";
    if(L.quad_patches < L.patches.size())
      L.message += " " + std::to_string(L.patches.size() - L.quad_patches) + " of " + std::to_string(L.patches.size()) +
                   " patches are not quads (disks with 4 right-angle corners and a rectangle as UV image)";
    if(L.euler_characteristic != L.surface_euler_characteristic)
      L.message += std::string(L.quad_patches < L.patches.size() ? ";" : "") + " the Euler characteristic of the layout is " +
                   std::to_string(L.euler_characteristic) + ", of the surface " + std::to_string(L.surface_euler_characteristic) +
                   " (a patch that is not a disk)";
    if(L.patches.empty()) L.message += " no patch";
  }
}

} // namespace tracing
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_PATCH_LAYOUT_H
