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

#include <cmath>
#include <utility>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace tracing {

typedef CGAL::Gmpq FT;

// 0 as one number that copies share: CGAL::Gmpq's default constructor makes (allocates) a new number each time, and the
// tracer's values are mostly made empty and then assigned; they start as copies of this one instead (its count of
// references is atomic in CGAL, and no Gmpq operation changes a shared number)
inline const FT& zero_rational()
{
  static const FT zero(0);
  return zero;
}

// 1, shared likewise
inline const FT& one_rational()
{
  static const FT one(1);
  return one;
}

struct Exact_uv
{
  FT u = zero_rational(), v = zero_rational();
  bool operator==(const Exact_uv& o) const { return u == o.u && v == o.v; }
  bool operator!=(const Exact_uv& o) const { return !(*this == o); }
};

inline int direction_mod4(int m) { return ((m % 4) + 4) % 4; }

// direction code (0..7) relative to m of a vector whose components have the signs su, sv; -1 for the zero vector
inline int direction_code_of_signs(int m, int su, int sv)
{
  int sa, ss;                                               // the signs of its (along, side) (header)
  switch(direction_mod4(m)) {
    case 0: sa = su;  ss = sv;  break;
    case 1: sa = sv;  ss = -su; break;
    case 2: sa = -su; ss = -sv; break;
    default: sa = -sv; ss = su; break;
  }
  if(sa == 0 && ss == 0) return -1;
  if(ss == 0) return sa > 0 ? 0 : 4;
  if(sa == 0) return ss > 0 ? 2 : 6;
  if(ss > 0) return sa > 0 ? 1 : 3;
  return sa < 0 ? 5 : 7;
}

// direction code (0..7) of the vector (xu, xv) relative to m; -1 for the zero vector
inline int direction_code(int m, const FT& xu, const FT& xv)
{
  return direction_code_of_signs(m, CGAL::sign(xu), CGAL::sign(xv));
}

// A GMP rational for intermediate values computed in place (mpq_sub(t, ...) into it): it allocates only when its limbs
// grow, where a CGAL::Gmpq expression makes a new number per operation (three allocations each: the handle's
// representation and the numerator's and denominator's limbs) and frees it again. The primitives below compute so and
// make a CGAL::Gmpq only for their results; signs and equalities make none, and values start as copies of one shared
// zero (zero_rational()). Tracing the 302K-face bunny of ../shared/large (untangled) with its layout allocated 90.6M
// times before, 24.1M times so (the separatrices 27.0M -> 7.2M, their conversion to Trace_points 14.5M -> 1.6M, the
// face subdivision 27.4M -> 6.1M, the patches 17.4M -> 6.3M), with the same output bit for bit.
struct Gmp_rational
{
  mpq_t q;
  Gmp_rational() { mpq_init(q); }
  ~Gmp_rational() { mpq_clear(q); }
  Gmp_rational(const Gmp_rational&) = delete;
  Gmp_rational& operator=(const Gmp_rational&) = delete;
};

// the calling thread's intermediate rationals, for the primitives below only (none of them calls another while it
// uses them)
inline Gmp_rational* scratch_rationals()
{
  thread_local Gmp_rational t[8];
  return t;
}

// t[0] = (b - a) x (c - a) (cross) or (b - a) . (c - a), exactly, from the coordinates' rationals; t[0..2] are written
// (t: scratch_rationals(); the coordinates may be others of its slots)
inline void cross_or_dot_in(mpq_srcptr au, mpq_srcptr av, mpq_srcptr bu, mpq_srcptr bv, mpq_srcptr cu, mpq_srcptr cv,
                            bool cross, Gmp_rational* t)
{
  mpq_sub(t[0].q, bu, au);                                 // cross: (bu - au)(cv - av) - (bv - av)(cu - au)
  mpq_sub(t[1].q, cross ? cv : cu, cross ? av : au);       // dot:   (bu - au)(cu - au) + (bv - av)(cv - av)
  mpq_mul(t[0].q, t[0].q, t[1].q);
  mpq_sub(t[1].q, bv, av);
  mpq_sub(t[2].q, cross ? cu : cv, cross ? au : av);
  mpq_mul(t[1].q, t[1].q, t[2].q);
  if(cross) mpq_sub(t[0].q, t[0].q, t[1].q);
  else mpq_add(t[0].q, t[0].q, t[1].q);
}

// t[0] = (b - a) x (c - a), exactly (t: scratch_rationals())
inline void orientation_determinant_in(const Exact_uv& a, const Exact_uv& b, const Exact_uv& c, Gmp_rational* t)
{
  cross_or_dot_in(a.u.mpq(), a.v.mpq(), b.u.mpq(), b.v.mpq(), c.u.mpq(), c.v.mpq(), true, t);
}

// twice the signed area of the UV triangle (a, b, c)
inline FT orientation_determinant(const Exact_uv& a, const Exact_uv& b, const Exact_uv& c)
{
  Gmp_rational* t = scratch_rationals();
  orientation_determinant_in(a, b, c, t);
  return FT(t[0].q);
}

// CGAL::sign(orientation_determinant(a, b, c)), with no number made
inline int orientation_determinant_sign(const Exact_uv& a, const Exact_uv& b, const Exact_uv& c)
{
  Gmp_rational* t = scratch_rationals();
  orientation_determinant_in(a, b, c, t);
  return mpq_sgn(t[0].q);
}

// P + a * d_m
inline Exact_uv advance(const Exact_uv& p, int m, const FT& a)
{
  const int q = direction_mod4(m);                         // +u, +v, -u, -v: one coordinate changes, in place
  const FT& pc = q % 2 == 0 ? p.u : p.v;
  Gmp_rational* t = scratch_rationals();
  if(q < 2) mpq_add(t[0].q, pc.mpq(), a.mpq());
  else mpq_sub(t[0].q, pc.mpq(), a.mpq());
  return q % 2 == 0 ? Exact_uv{FT(t[0].q), p.v} : Exact_uv{p.u, FT(t[0].q)};
}

// a - b, or b - a where `negated`, made once
inline FT difference(const FT& a, const FT& b, bool negated)
{
  Gmp_rational* t = scratch_rationals();
  if(negated) mpq_sub(t[0].q, b.mpq(), a.mpq());
  else mpq_sub(t[0].q, a.mpq(), b.mpq());
  return FT(t[0].q);
}

// the side coordinate of the vector x - p relative to direction m (header): dv, -du, -dv, du for m = 0..3
inline FT side_difference(int m, const Exact_uv& x, const Exact_uv& p)
{
  const int q = direction_mod4(m);
  return q % 2 == 0 ? difference(x.v, p.v, q == 2) : difference(x.u, p.u, q == 1);
}

// the along coordinate of the vector x - p relative to direction m (header): du, dv, -du, -dv for m = 0..3
inline FT along_difference(int m, const Exact_uv& x, const Exact_uv& p)
{
  const int q = direction_mod4(m);
  return q % 2 == 0 ? difference(x.u, p.u, q >= 2) : difference(x.v, p.v, q >= 2);
}

// (along, side) of the vector x - p relative to direction m, each made once (in place: no number for the difference,
// none for a negation)
inline void frame_difference(int m, const Exact_uv& x, const Exact_uv& p, FT& along, FT& side)
{
  along = along_difference(m, x, p);
  side = side_difference(m, x, p);
}

// the sign of side_difference(m, x, p): one comparison, no number made
inline int side_sign(int m, const Exact_uv& x, const Exact_uv& p)
{
  const int q = direction_mod4(m);                         // side: dv, -du, -dv, du
  const int c = q % 2 == 0 ? mpq_cmp(x.v.mpq(), p.v.mpq()) : mpq_cmp(x.u.mpq(), p.u.mpq());
  const int s = (c > 0) - (c < 0);
  return q == 1 || q == 2 ? -s : s;
}

// s_i / (s_i - s_j): the parameter from i to j where a coordinate that is s_i at i and s_j != s_i at j is 0
inline FT crossing_parameter(const FT& si, const FT& sj)
{
  Gmp_rational* t = scratch_rationals();
  mpq_sub(t[0].q, si.mpq(), sj.mpq());
  mpq_div(t[0].q, si.mpq(), t[0].q);
  return FT(t[0].q);
}

// t[0] = a + lambda (b - a) (t: scratch_rationals())
inline void lerp_scalar_in(const FT& a, const FT& b, const FT& lambda, Gmp_rational* t)
{
  mpq_sub(t[0].q, b.mpq(), a.mpq());
  mpq_mul(t[0].q, t[0].q, lambda.mpq());
  mpq_add(t[0].q, t[0].q, a.mpq());
}

// a + lambda (b - a)
inline FT lerp_scalar(const FT& a, const FT& b, const FT& lambda)
{
  Gmp_rational* t = scratch_rationals();
  lerp_scalar_in(a, b, lambda, t);
  return FT(t[0].q);
}

// a + lambda (b - a) == x, with no number made
inline bool lerp_scalar_equals(const FT& a, const FT& b, const FT& lambda, const FT& x)
{
  Gmp_rational* t = scratch_rationals();
  lerp_scalar_in(a, b, lambda, t);
  return mpq_equal(t[0].q, x.mpq()) != 0;
}

// x == d exactly (d a finite double), with no number made
inline bool equals_double(const FT& x, double d)
{
  Gmp_rational* t = scratch_rationals();
  mpq_set_d(t[0].q, d);
  return mpq_equal(x.mpq(), t[0].q) != 0;
}

// The interval of the two doubles nearest to x (one double where x is one): CGAL::to_interval(x), which goes through
// MPFR and allocates, computed from the truncation mpq_get_d() and one exact comparison instead
inline std::pair<double, double> interval_of(const FT& x)
{
  const double d = mpq_get_d(x.mpq());                    // |d| <= |x|, no double strictly between them
  if(!std::isfinite(d)) return CGAL::to_interval(x);
  Gmp_rational* t = scratch_rationals();
  mpq_set_d(t[0].q, d);
  const int c = mpq_cmp(x.mpq(), t[0].q);
  if(c == 0) return {d, d};
  return c > 0 ? std::make_pair(d, std::nextafter(d, HUGE_VAL)) : std::make_pair(std::nextafter(d, -HUGE_VAL), d);
}

// 1 - x
inline FT one_minus(const FT& x)
{
  Gmp_rational* t = scratch_rationals();
  mpq_set_ui(t[0].q, 1, 1);
  mpq_sub(t[0].q, t[0].q, x.mpq());
  return FT(t[0].q);
}

// Double intervals enclosing the two coordinates of an Exact_uv (interval_of()), to decide signs and equalities
// without the rationals where the doubles suffice.
struct Uv_box
{
  std::pair<double, double> u, v;
  explicit Uv_box(const Exact_uv& p) : u(interval_of(p.u)), v(interval_of(p.v)) {}
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
  return orientation_determinant_sign(a, b, c);
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
  Gmp_rational* t = scratch_rationals();
  cross_or_dot_in(a.u.mpq(), a.v.mpq(), b.u.mpq(), b.v.mpq(), c.u.mpq(), c.v.mpq(), false, t);
  return mpq_sgn(t[0].q);
}

// the same for the corners a and b (their doubles cm.u, cm.v) and the point c: the sign of (b - a) x (c - a)
inline int corner_side_sign(const Corner_mesh& cm, int a, int b, const Exact_uv& c, const Uv_box& C)
{
  const Uv_box A(cm.u[a], cm.v[a]), B(cm.u[b], cm.v[b]);
  const int s = filtered_orientation_sign(A.u, A.v, B.u, B.v, C.u, C.v);
  if(s != 0) return s;
  Gmp_rational* t = scratch_rationals();                // the corners' doubles as rationals in t[3..6]
  mpq_set_d(t[3].q, cm.u[a]); mpq_set_d(t[4].q, cm.v[a]);
  mpq_set_d(t[5].q, cm.u[b]); mpq_set_d(t[6].q, cm.v[b]);
  cross_or_dot_in(t[3].q, t[4].q, t[5].q, t[6].q, c.u.mpq(), c.v.mpq(), true, t);
  return mpq_sgn(t[0].q);
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
  Gmp_rational* t = scratch_rationals();                // t[0..2]: orientation_determinant_in(); t[3]: the total
  orientation_determinant_in(c[0], c[1], c[2], t);
  mpq_swap(t[3].q, t[0].q);
  mpq_set_ui(t[4].q, 1, 1);                              // t[4]: 1 - b[0] - b[1]
  for(int i = 0; i < 2; ++i) {
    orientation_determinant_in(i == 0 ? p : c[0], i == 0 ? c[1] : p, c[2], t);
    mpq_div(t[0].q, t[0].q, t[3].q);
    mpq_sub(t[4].q, t[4].q, t[0].q);
    b[i] = FT(t[0].q);
  }
  b[2] = FT(t[4].q);
}

// The point at parameter lambda from a to b.
inline Exact_uv lerp(const Exact_uv& a, const Exact_uv& b, const FT& lambda)
{
  return Exact_uv{lerp_scalar(a.u, b.u, lambda), lerp_scalar(a.v, b.v, lambda)};
}

// The parameter lambda of a point p of the line through a != b: p = lerp(a, b, lambda).
inline FT lerp_parameter(const Exact_uv& a, const Exact_uv& b, const Exact_uv& p)
{
  const bool by_u = a.u != b.u;
  const FT& ac = by_u ? a.u : a.v;
  Gmp_rational* t = scratch_rationals();
  mpq_sub(t[0].q, (by_u ? p.u : p.v).mpq(), ac.mpq());
  mpq_sub(t[1].q, (by_u ? b.u : b.v).mpq(), ac.mpq());
  mpq_div(t[0].q, t[0].q, t[1].q);
  return FT(t[0].q);
}

} // namespace tracing
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_CHART_GEOMETRY_H
