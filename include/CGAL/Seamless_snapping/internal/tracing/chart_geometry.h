// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_CHART_GEOMETRY_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_CHART_GEOMETRY_H

// Exact geometry in the chart of one face (the UV coordinates of its three corners), for isoline
// tracing (Sec. 6.2). Doubles are dyadic rationals and convert to CGAL::Gmpq without error; every
// predicate below is exact (zero tolerance).
//
// Trace directions are the four axis directions d_m = R^m (1, 0), m in {0, 1, 2, 3}:
// +u, +v, -u, -v, with R(x, y) = (-y, x) the counter-clockwise quarter turn (as in rotation_fit.h).
// Relative to a point P and a direction m, a point x has the coordinates
//   along(x) = <d_m, x - P>   and   side(x) = cross(d_m, x - P)   (positive: left of the ray).
// The direction code of a nonzero vector x relative to m lists the 8 classes counter-clockwise:
//   0 on d_m, 1 strictly between d_m and R d_m, 2 on R d_m, ..., 7 strictly between R^3 d_m and d_m.

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace tracing {

typedef CGAL::Gmpq FT;

struct Exact_uv
{
  FT u, v;
  bool operator==(const Exact_uv& o) const { return u == o.u && v == o.v; }
  bool operator!=(const Exact_uv& o) const { return !(*this == o); }
};

// UV of the corner (target(h), face(h)), exactly
inline Exact_uv corner_uv(const Corner_mesh& cm, int h) { return Exact_uv{FT(cm.u[h]), FT(cm.v[h])}; }

inline int direction_mod4(int m) { return ((m % 4) + 4) % 4; }

// (along, side) of the vector x relative to direction m
inline void frame_coordinates(int m, const FT& xu, const FT& xv, FT& along, FT& side)
{
  switch(direction_mod4(m)) {
    case 0: along = xu;  side = xv;  break;
    case 1: along = xv;  side = -xu; break;
    case 2: along = -xu; side = -xv; break;
    default: along = -xv; side = xu; break;
  }
}

// P + a * d_m
inline Exact_uv advance(const Exact_uv& p, int m, const FT& a)
{
  switch(direction_mod4(m)) {
    case 0: return Exact_uv{p.u + a, p.v};
    case 1: return Exact_uv{p.u, p.v + a};
    case 2: return Exact_uv{p.u - a, p.v};
    default: return Exact_uv{p.u, p.v - a};
  }
}

// direction code (0..7) of the vector (xu, xv) relative to m; -1 for the zero vector
inline int direction_code(int m, const FT& xu, const FT& xv)
{
  FT a, s;
  frame_coordinates(m, xu, xv, a, s);
  const int sa = CGAL::sign(a), ss = CGAL::sign(s);
  if(sa == 0 && ss == 0) return -1;
  if(ss == 0) return sa > 0 ? 0 : 4;
  if(sa == 0) return ss > 0 ? 2 : 6;
  if(ss > 0) return sa > 0 ? 1 : 3;
  return sa < 0 ? 5 : 7;
}

// twice the signed area of the UV triangle (a, b, c)
inline FT orientation_determinant(const Exact_uv& a, const Exact_uv& b, const Exact_uv& c)
{
  return (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
}

// Double intervals enclosing the two coordinates of an Exact_uv (CGAL::to_interval), to decide signs and equalities
// without the rationals where the doubles suffice.
struct Uv_box
{
  std::pair<double, double> u, v;
  explicit Uv_box(const Exact_uv& p) : u(CGAL::to_interval(p.u)), v(CGAL::to_interval(p.v)) {}
  Uv_box(double pu, double pv) : u(pu, pu), v(pv, pv) {}              // a point of doubles: exact
  bool may_be(double pu, double pv) const { return u.first <= pu && pu <= u.second && v.first <= pv && pv <= v.second; }
};

// the sign of (b - a) x (c - a) from intervals enclosing the six coordinates: 1 or -1 where the interval of the
// determinant decides it, 0 where it does not (a filter: the caller then decides it exactly)
inline int filtered_orientation_sign(const std::pair<double, double>& au, const std::pair<double, double>& av,
                                     const std::pair<double, double>& bu, const std::pair<double, double>& bv,
                                     const std::pair<double, double>& cu, const std::pair<double, double>& cv)
{
  CGAL::Protect_FPU_rounding<true> upward;
  typedef CGAL::Interval_nt<false> I;
  const I d = (I(bu) - I(au)) * (I(cv) - I(av)) - (I(bv) - I(av)) * (I(cu) - I(au));
  return d.inf() > 0 ? 1 : d.sup() < 0 ? -1 : 0;
}

// the sign of orientation_determinant(a, b, c), exactly: filtered on the boxes, else (always where it is zero) 0 where c
// is a or b, else by the rationals. In the face subdivision most signs the filter leaves are those of a polygon's
// corner against its own sides (the duck_miq_8 untangled: 19,684 of 25,710; the rot-seamless dragon 99,600 of 150,638)
inline int orientation_sign(const Exact_uv& a, const Uv_box& A, const Exact_uv& b, const Uv_box& B, const Exact_uv& c,
                            const Uv_box& C)
{
  const int s = filtered_orientation_sign(A.u, A.v, B.u, B.v, C.u, C.v);
  if(s != 0) return s;
  if(c == a || c == b) return 0;
  return CGAL::sign(orientation_determinant(a, b, c));
}

// the sign of (b - a) . (c - a), exactly: filtered on the boxes, else by the rationals
inline int direction_sign(const Exact_uv& a, const Uv_box& A, const Exact_uv& b, const Uv_box& B, const Exact_uv& c,
                          const Uv_box& C)
{
  {
    CGAL::Protect_FPU_rounding<true> upward;
    typedef CGAL::Interval_nt<false> I;
    const I d = (I(B.u) - I(A.u)) * (I(C.u) - I(A.u)) + (I(B.v) - I(A.v)) * (I(C.v) - I(A.v));
    if(d.inf() > 0) return 1;
    if(d.sup() < 0) return -1;
  }
  return CGAL::sign((b.u - a.u) * (c.u - a.u) + (b.v - a.v) * (c.v - a.v));
}

// the same for orientation_determinant(corner_uv(cm, a), corner_uv(cm, b), c)
inline int corner_side_sign(const Corner_mesh& cm, int a, int b, const Exact_uv& c, const Uv_box& C)
{
  const Uv_box A(cm.u[a], cm.v[a]), B(cm.u[b], cm.v[b]);
  const int s = filtered_orientation_sign(A.u, A.v, B.u, B.v, C.u, C.v);
  return s != 0 ? s : CGAL::sign(orientation_determinant(corner_uv(cm, a), corner_uv(cm, b), c));
}

// sign of the UV orientation of face(h) (corners prev(h), h, next(h)): +1 counter-clockwise
inline int face_orientation(const Corner_mesh& cm, int h)
{
  // the sign of the exact determinant of the corners' doubles: CGAL's filtered predicate, no rationals
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  const int a = cm.prev[h], c = cm.next[h];
  return int(CGAL::orientation(P(cm.u[a], cm.v[a]), P(cm.u[h], cm.v[h]), P(cm.u[c], cm.v[c])));
}

// barycentric coordinates of p with respect to the corners (c[0], c[1], c[2]) of a non-degenerate
// UV triangle: the exact ratios of signed areas
inline void barycentric(const Exact_uv c[3], const Exact_uv& p, FT b[3])
{
  const FT total = orientation_determinant(c[0], c[1], c[2]);
  b[0] = orientation_determinant(p, c[1], c[2]) / total;
  b[1] = orientation_determinant(c[0], p, c[2]) / total;
  b[2] = FT(1) - b[0] - b[1];
}

// The point at parameter lambda from a to b.
inline Exact_uv lerp(const Exact_uv& a, const Exact_uv& b, const FT& lambda)
{
  return Exact_uv{a.u + lambda * (b.u - a.u), a.v + lambda * (b.v - a.v)};
}

// The parameter lambda of a point p of the line through a != b: p = lerp(a, b, lambda).
inline FT lerp_parameter(const Exact_uv& a, const Exact_uv& b, const Exact_uv& p)
{
  return a.u != b.u ? (p.u - a.u) / (b.u - a.u) : (p.v - a.v) / (b.v - a.v);
}

} // namespace tracing
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_CHART_GEOMETRY_H
