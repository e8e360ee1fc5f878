// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SAFE_DOT_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SAFE_DOT_H

// The safe dot product, Alg. 5 (Sec. 4.3): r = sum_i c_i x_i with integer c_i and x_i in F_delta,
// evaluated in double arithmetic so that no intermediate value leaves [-delta, delta]. Every
// operation is then exact (see fixed_point_grid.h). Summands c_i x_i are taken as |c_i| copies of
// +-|x_i|; the accumulator r alternates: while r < 0 a positive summand is added, otherwise a
// negative one (while any is left). Copies are taken k at a time, with k as large as the range
// allows (k = min(c, floor((delta - r) / |x|))), not one by one. k is computed in integers on the
// grid (z = v / s), so no rounded division can overshoot. When the summands' magnitudes add up
// to less than delta, any order is safe and the sum is taken directly (the fast path).

#include <CGAL/Seamless_snapping/internal/fixed_point_grid.h>
#include <CGAL/Seamless_snapping/internal/integer_ops.h>

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// One summand: `count` copies of `value` (count > 0, value on the grid, nonzero).
struct Safe_dot_summand { std::int64_t count; double value; };

// Scratch buffers, reused across calls to avoid allocations in the evaluation loop.
struct Safe_dot_workspace { std::vector<Safe_dot_summand> pos, neg; };

// Computes sum c_i x_i into `result`. Returns false when the accumulation gets stuck, i.e. the
// next copy would leave [-delta, delta] (then the exact result is itself outside the range, as the
// alternation keeps every partial sum between the result and the range of the summands; Sec. 4.3),
// or when a coefficient is so large that a single copy-count cannot be represented.
// Preconditions: every x_i is in F_delta (grid.contains(x_i)).
template <typename Int>
bool safe_dot(const std::vector<std::pair<Int, double> >& terms, const Fixed_point_grid& grid,
              double& result, Safe_dot_workspace& ws)
{
  typedef Integer_ops<Int> Ops;
  ws.pos.clear(); ws.neg.clear();
  const double s = grid.quantum;
  // Fast path: when sum |c_i| |x_i| < delta, no partial sum in any order can leave the range, so
  // the alternation is unnecessary and the sum is accumulated directly (in grid integers).
  __int128 magnitude = 0, sum = 0;
  bool small = true;
  for(const auto& t : terms) {
    if(Ops::is_zero(t.first) || t.second == 0) continue;
    std::int64_t c;
    if(!Ops::to_int64(Ops::abs(t.first), c) || c > (std::int64_t(1) << 53))
      return false;   // |c| x would exceed 2^53 s >= delta for any nonzero grid value x
    const std::int64_t X = std::int64_t(std::fabs(t.second) / s);     // exact
    const bool positive = (Ops::sign(t.first) > 0) == (t.second > 0);
    if(small) {
      magnitude += (__int128)c * X;
      sum += positive ? (__int128)c * X : -(__int128)c * X;
      if(magnitude >= ((__int128)1 << 52)) small = false;
    }
    (positive ? ws.pos : ws.neg).push_back(Safe_dot_summand{c, std::fabs(t.second)});
  }
  if(small) { result = double(std::int64_t(sum)) * s; return true; }
  // Deterministic order: as given. (Any order is exact; the alternation is what bounds the range.)
  std::size_t ip = 0, in = 0;
  double r = 0;
  const std::int64_t D = std::int64_t(1) << 52;    // delta / s
  while(ip < ws.pos.size() || in < ws.neg.size()) {
    const bool take_pos = ip < ws.pos.size() && (r < 0 || in == ws.neg.size());
    Safe_dot_summand& t = take_pos ? ws.pos[ip] : ws.neg[in];
    const std::int64_t R = std::int64_t(r / s);     // exact, |R| <= D
    const std::int64_t X = std::int64_t(t.value / s);// exact, 0 < X < D
    const std::int64_t room = take_pos ? D - R : D + R;   // (delta - r)/s  or  (r + delta)/s, in [0, 2D]
    const std::int64_t k = std::min<std::int64_t>(t.count, room / X);
    if(k == 0) return false;                         // stuck: the next copy leaves the range
    const double kx = double(k) * t.value;           // exact: k X <= room <= 2^53
    r = take_pos ? r + kx : r - kx;                  // exact: result in [-delta, delta]
    t.count -= k;
    if(t.count == 0) { if(take_pos) ++ip; else ++in; }
  }
  result = r;
  return true;
}

template <typename Int>
bool safe_dot(const std::vector<std::pair<Int, double> >& terms, const Fixed_point_grid& grid, double& result)
{
  Safe_dot_workspace ws;
  return safe_dot(terms, grid, result, ws);
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SAFE_DOT_H
