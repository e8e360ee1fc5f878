// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_SAFE_DOT_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_SAFE_DOT_H

// The safe dot product, Alg. 5 (Sec. 4.3): r = sum_i c_i x_i with integer c_i and x_i in F_delta,
// x_i given by their grid integers z_i = x_i / s,
// evaluated in double arithmetic so that no intermediate value leaves [-delta, delta]; every
// operation is then exact (see fixed_point_grid.h). Summands c_i x_i are |c_i| copies of +-|x_i|;
// the accumulator alternates: while r < 0 a positive summand is added, otherwise a negative one
// (while any is left). Copies are taken k at a time, k as large as the range allows
// (k = min(c, floor((delta - r) / |x|))), not one by one; k is computed on the grid integers
// (z = v / s), so no rounded division can overshoot.
//
// Because every x_i is a grid multiple, the exact value of the sum is also available as an integer
// sum_i c_i z_i (128-bit, or Gmpz when that overflows). We compute it first (Grid_sum):
//  - if |sum| >= 2^52 the result is outside (-delta, delta): OUT_OF_RANGE (Alg. 5 would get stuck);
//  - if sum_i |c_i z_i| < 2^52, no partial sum in any order can leave the range, and the result is
//    the integer sum (fast path; this is the common case on seamless systems);
//  - otherwise Alg. 5 runs in doubles. Its alternation needs about sum|c_i x_i| / delta steps, which
//    is unbounded when large positive and negative summands cancel (e.g. coefficients 2^40 and
//    -2^40); after a fixed number of steps the remaining summands are taken from the exact integer
//    sum instead. A completed Alg. 5 must agree with the integer sum (else STUCK: an internal error).

#include <CGAL/Seamless_snapping/internal/projection/fixed_point_grid.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_ops.h>

#include <CGAL/Gmpz.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

enum Safe_dot_result { SAFE_DOT_OK = 0, SAFE_DOT_OUT_OF_RANGE, SAFE_DOT_STUCK };

// One summand: `count` copies of `value` (count > 0, value > 0 on the grid).
struct Safe_dot_summand { std::int64_t count; double value; };

// Scratch buffers, reused across calls to avoid allocations in the evaluation loop.
struct Safe_dot_workspace { std::vector<Safe_dot_summand> pos, neg; };

// The exact integer value sum_i c_i z_i and sum_i |c_i z_i| in 128 bits (`overflow` when they do
// not fit; the caller then redoes the sum in Gmpz).
struct Grid_sum
{
  __int128 sum = 0, magnitude = 0;
  bool overflow = false;
  static constexpr std::int64_t D = std::int64_t(1) << 52;   // delta / s
  // With grid integers (|z| < 2^52) each product is below 2^115, so fewer than 2^12 terms cannot
  // overflow either 128-bit sum: such sums may use add_unchecked().
  static constexpr std::size_t unchecked_terms = std::size_t(1) << 12;

  void add(std::int64_t c, std::int64_t z)
  {
    const __int128 p = (__int128)c * z;                      // |p| < 2^126: no overflow
    const __int128 ap = p < 0 ? -p : p;
    overflow |= __builtin_add_overflow(sum, p, &sum) | __builtin_add_overflow(magnitude, ap, &magnitude);
  }
  void add_unchecked(std::int64_t c, std::int64_t z)        // precondition: see unchecked_terms
  {
    const __int128 p = (__int128)c * z;
    sum += p;
    magnitude += p < 0 ? -p : p;
  }
  template <typename Int>
  void add(const Int& c, std::int64_t z)
  {
    std::int64_t c64;
    if(!Integer_ops<Int>::to_int64(c, c64)) overflow = true;
    else add(c64, z);
  }
  template <typename Int>
  void add_unchecked(const Int& c, std::int64_t z)
  {
    std::int64_t c64;
    if(!Integer_ops<Int>::to_int64(c, c64)) overflow = true;
    else add_unchecked(c64, z);
  }
  // Alg. 5 needs no step here: no partial sum in any order can leave (-delta, delta), and the
  // result is the integer sum.
  bool is_safe() const { return !overflow && magnitude < D; }
};

// Alg. 5 on terms (c_i, z_i): result = s sum_i c_i z_i, computed in doubles without leaving the range.
template <typename Int>
Safe_dot_result safe_dot(const std::vector<std::pair<Int, std::int64_t> >& terms, const Fixed_point_grid& grid,
                         double& result, Safe_dot_workspace& ws)
{
  typedef Integer_ops<Int> Ops;
  const std::int64_t D = Grid_sum::D;
  Grid_sum exact;
  for(const auto& t : terms) exact.add(t.first, t.second);
  __int128 sum = exact.sum;
  if(exact.overflow) {                             // redo in Gmpz
    CGAL::Gmpz big(0);
    for(const auto& t : terms) big += to_gmpz(t.first) * Integer_ops<CGAL::Gmpz>::from_int64(t.second);
    std::int64_t v;
    if(!Integer_ops<CGAL::Gmpz>::to_int64(big, v) || v >= D || v <= -D) return SAFE_DOT_OUT_OF_RANGE;
    sum = v;
  }
  if(sum >= D || sum <= -D) return SAFE_DOT_OUT_OF_RANGE;
  if(exact.is_safe()) { result = grid.from_integer(std::int64_t(sum)); return SAFE_DOT_OK; }   // fast path

  // Alg. 5 in doubles.
  ws.pos.clear(); ws.neg.clear();
  for(const auto& t : terms) {
    if(Ops::is_zero(t.first) || t.second == 0) continue;
    std::int64_t c;
    if(!Ops::to_int64(Ops::abs(t.first), c) || c > (std::int64_t(1) << 53)) {
      // |c x| > 2 delta: Alg. 5 would need more than 2^(#bits of c - 53) steps; the integer sum is exact.
      result = grid.from_integer(std::int64_t(sum));
      return SAFE_DOT_OK;
    }
    const bool positive = (Ops::sign(t.first) > 0) == (t.second > 0);
    (positive ? ws.pos : ws.neg).push_back(Safe_dot_summand{c, std::fabs(grid.from_integer(t.second))});
  }
  const double s = grid.quantum;
  std::size_t ip = 0, in = 0, steps = 0;
  const std::size_t max_steps = 4 * (ws.pos.size() + ws.neg.size()) + 64;
  double r = 0;
  while(ip < ws.pos.size() || in < ws.neg.size()) {
    if(++steps > max_steps) {                      // slow cancellation: take the exact integer sum
      result = grid.from_integer(std::int64_t(sum));
      return SAFE_DOT_OK;
    }
    const bool take_pos = ip < ws.pos.size() && (r < 0 || in == ws.neg.size());
    Safe_dot_summand& t = take_pos ? ws.pos[ip] : ws.neg[in];
    const std::int64_t R = std::int64_t(r / s);     // exact, |R| <= D
    const std::int64_t X = std::int64_t(t.value / s);// exact, 0 < X < D
    const std::int64_t room = take_pos ? D - R : D + R;   // (delta - r)/s  or  (r + delta)/s, in [0, 2D]
    const std::int64_t k = std::min<std::int64_t>(t.count, room / X);
    if(k == 0) return SAFE_DOT_STUCK;                // cannot happen when |sum| < delta (see header)
    const double kx = double(k) * t.value;           // exact: k X <= room <= 2^53
    r = take_pos ? r + kx : r - kx;                  // exact: result in [-delta, delta]
    t.count -= k;
    if(t.count == 0) { if(take_pos) ++ip; else ++in; }
  }
  if(r != grid.from_integer(std::int64_t(sum))) return SAFE_DOT_STUCK;   // Alg. 5 and the integer sum disagree
  result = r;
  return SAFE_DOT_OK;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_SAFE_DOT_H
