// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_FACE_CROSSING_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_FACE_CROSSING_H

// Crossing one face along an axis direction, and moving a crossing point through a cut edge
// (Sec. 6.2), exactly.
//
// Face crossing: P is a point of the closed UV triangle of the face, d_m the direction. The points
// P + a d_m of the triangle form an interval [a0, a1] (the triangle is convex); the trace advances in
// this face iff a1 > 0, and leaves it at P + a1 d_m: through a vertex or through the interior of an edge.
//
// Edge transition: the exit point X on the edge of halfedge h (face i) continues in face j =
// face(opposite(h)) as X' = R^k X + t, k = k(h) (rotation_fit.h), t = UV_j(w) - R^k UV_i(w) computed
// exactly from the corner UVs of an endpoint w of the edge. On an exactly seamless map X' lies on the
// edge in face j and does not depend on w. On an inexact map it may not: the coordinate that is
// constant along the isoline is kept, X' is placed on the edge in face j at that coordinate, and an
// isoline that misses the edge on the other side is reported (never guessed). Keeping that coordinate
// (a dyadic translation of the start's) keeps the rationals small on long traces.

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/tracing/chart_geometry.h>
#include <CGAL/Seamless_snapping/internal/tracing/tracing_map.h>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace tracing {

enum Exit_kind { NO_PROGRESS, EXIT_EDGE, EXIT_VERTEX };

struct Face_exit
{
  Exit_kind kind = NO_PROGRESS;
  int h = -1;          // EXIT_EDGE: halfedge of the face whose edge (source(h) -> target(h)) is crossed;
                       // EXIT_VERTEX: the corner halfedge of the face whose target is the vertex
  FT lambda = zero_rational();   // EXIT_EDGE: parameter of the exit point from source(h) to target(h)
  FT along = zero_rational();    // a1 > 0: parametric length of the crossing
  Exact_uv point;      // P + a1 d_m, in the chart of the face
};

// `h0`: any halfedge of the face; `p` in its chart, in the closed triangle.
inline Face_exit cross_face(const Tracing_map& map, int h0, const Exact_uv& p, int m)
{
  const Corner_mesh& cm = map.cm;
  const int c[3] = {h0, cm.next[h0], cm.next[cm.next[h0]]};
  const Exact_uv* uv[3];
  const FT& z = zero_rational();                // copies of one 0, assigned below (no number made)
  FT a[3] = {z, z, z}, s[3] = {z, z, z};
  int ss[3];
  for(int i = 0; i < 3; ++i) {
    uv[i] = &corner_uv(map, c[i]);
    frame_difference(m, *uv[i], p, a[i], s[i]);
    ss[i] = CGAL::sign(s[i]);
  }
  Face_exit best;
  for(int j = 0; j < 3; ++j) {
    if(ss[j] == 0 && CGAL::is_positive(a[j]) && (best.kind == NO_PROGRESS || a[j] > best.along)) {
      best.kind = EXIT_VERTEX; best.h = c[j]; best.along = a[j];
    }
    const int i = (j + 2) % 3;                 // the edge of c[j] runs from corner c[i] to corner c[j]
    if(ss[i] * ss[j] < 0) {
      const FT lambda = crossing_parameter(s[i], s[j]);
      const FT along = lerp_scalar(a[i], a[j], lambda);
      if(CGAL::is_positive(along) && (best.kind == NO_PROGRESS || along > best.along)) {
        best.kind = EXIT_EDGE; best.h = c[j]; best.along = along; best.lambda = lambda;
      }
    }
  }
  if(best.kind == EXIT_VERTEX) best.point = *uv[best.h == c[0] ? 0 : (best.h == c[1] ? 1 : 2)];
  else if(best.kind == EXIT_EDGE) best.point = advance(p, m, best.along);
  return best;
}

inline Exact_uv rotate(int k, const Exact_uv& x)
{
  const Quarter_turn R(k);                                  // (R^k x)_c = +- x_col: a number made only for a sign
  Gmp_rational* t = scratch_rationals();
  Exact_uv r;
  for(int c = 0; c < 2; ++c) {
    const FT& xc = R.col[c] == 0 ? x.u : x.v;
    FT& rc = c == 0 ? r.u : r.v;
    if(R.sign[c] > 0) rc = xc;
    else { mpq_neg(t[0].q, xc.mpq()); rc = FT(t[0].q); }
  }
  return r;
}

// The transition R^k x + t of the edge of h from face(h) to face(opposite(h)), anchored at the
// endpoint target(h) (anchor_target) or source(h): t = UV_j(w) - R^k UV_i(w).
struct Edge_transition
{
  int k = 0;
  Exact_uv t;
  // R^0 x + 0 (no rational arithmetic: most transitions of a patch layout are the identity)
  bool is_identity() const { return k == 0 && CGAL::is_zero(t.u) && CGAL::is_zero(t.v); }
  bool operator==(const Edge_transition& o) const { return k == o.k && t == o.t; }
  // out = coordinate c (0: u, 1: v) of R^k x + t, in place: t_c +- x_col (chart_geometry.h)
  void apply_coordinate(int c, const Exact_uv& x, mpq_t out) const
  {
    const Quarter_turn R(k);
    const FT& xc = R.col[c] == 0 ? x.u : x.v;
    const FT& tc = c == 0 ? t.u : t.v;
    if(R.sign[c] > 0) mpq_add(out, tc.mpq(), xc.mpq());
    else mpq_sub(out, tc.mpq(), xc.mpq());
  }
  Exact_uv apply(const Exact_uv& x) const
  {
    if(is_identity()) return x;
    Gmp_rational* s = scratch_rationals();
    Exact_uv r;
    for(int c = 0; c < 2; ++c) {
      apply_coordinate(c, x, s[0].q);
      (c == 0 ? r.u : r.v) = FT(s[0].q);
    }
    return r;
  }
  // apply(x) == B.apply(y), with no number made
  bool agrees(const Exact_uv& x, const Edge_transition& B, const Exact_uv& y) const
  {
    Gmp_rational* s = scratch_rationals();
    for(int c = 0; c < 2; ++c) {
      if(is_identity()) mpq_set(s[0].q, (c == 0 ? x.u : x.v).mpq()); else apply_coordinate(c, x, s[0].q);
      if(B.is_identity()) mpq_set(s[1].q, (c == 0 ? y.u : y.v).mpq()); else B.apply_coordinate(c, y, s[1].q);
      if(!mpq_equal(s[0].q, s[1].q)) return false;
    }
    return true;
  }
};

inline Edge_transition edge_transition(const Tracing_map& map, int h, bool anchor_target)
{
  const Corner_mesh& cm = map.cm;
  const int o = cm.opp[h];
  Edge_transition T;
  T.k = map.rot.k[h];
  // corner of the anchor in face(h) and in face(o)
  const int wi = anchor_target ? h : cm.prev[h];
  const int wj = anchor_target ? cm.prev[o] : o;
  double ru, rv;                                  // R^k of the anchor's doubles, exactly (negations and a swap)
  rotate_quarter_turns(T.k, cm.u[wi], cm.v[wi], ru, rv);
  if(ru == cm.u[wj] && rv == cm.v[wj]) return T;  // t = 0 (an edge that is no cut: no rational arithmetic)
  const Exact_uv r = rotate(T.k, corner_uv(map, wi));
  const Exact_uv& q = corner_uv(map, wj);
  T.t = Exact_uv{q.u - r.u, q.v - r.v};
  return T;
}

enum Transfer_kind { TRANSFER_EDGE, TRANSFER_VERTEX, TRANSFER_MISSED };

struct Edge_transfer
{
  Transfer_kind kind = TRANSFER_MISSED;
  int m = 0;           // direction in face(opposite(h))
  Exact_uv point;      // in the chart of face(opposite(h))
  int corner = -1;     // TRANSFER_VERTEX: the corner of face(opposite(h)) hit exactly
  bool exact = false;  // X' = R^k X + t lies on the edge (always on an exactly seamless map)
};

// Moves the exit point `x` (on the edge of h, at parameter lambda from source(h)) with direction m
// into face(opposite(h)), which must exist.
inline Edge_transfer transfer_through_edge(const Tracing_map& map, int h, const Exact_uv& x, const FT& lambda, int m)
{
  const Corner_mesh& cm = map.cm;
  const int o = cm.opp[h];
  Edge_transfer out;
  out.m = direction_mod4(m + map.rot.k[h]);
  const Exact_uv q = edge_transition(map, h, mpq_cmp_ui(lambda.mpq(), 1, 2) > 0).apply(x);   // lambda > 1/2
  // the edge in face(o), from source(h) (corner o) to target(h) (corner prev(o))
  const Exact_uv& A = corner_uv(map, o);
  const Exact_uv& B = corner_uv(map, cm.prev[o]);
  const int gA = side_sign(out.m, A, q), gB = side_sign(out.m, B, q);   // A and B relative to the line of q
  if(gA * gB < 0) {
    out.kind = TRANSFER_EDGE;
    out.point = lerp(A, B, crossing_parameter(side_difference(out.m, A, q), side_difference(out.m, B, q)));
    out.exact = out.point == q;
  } else if(gA == 0 && gB != 0) {
    out.kind = TRANSFER_VERTEX; out.corner = o; out.point = A; out.exact = A == q;
  } else if(gB == 0 && gA != 0) {
    out.kind = TRANSFER_VERTEX; out.corner = cm.prev[o]; out.point = B; out.exact = B == q;
  }
  return out;
}

} // namespace tracing
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_FACE_CROSSING_H
