// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_FIXED_POINT_GRID_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_FIXED_POINT_GRID_H

// The fixed-point subset F_delta of the doubles (Sec. 4.3, after [EBCK13]).
//
// With delta = 2^K, F_delta is the set of doubles v with |v| < delta that are integer multiples of
// the quantum s = 2^(K-52). Every sum, difference and integer multiple of values of F_delta is
// computed exactly in double arithmetic as long as the result stays in (-delta, delta): the result
// is a multiple of s below 2^52 s in magnitude, hence representable with 53 significant bits.
// We therefore often work with the integer z = v / s (|z| < 2^52), which is exact as s is a power of 2.

#include <CGAL/assertions.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// A variable in the evaluation: the grid integer z of its result (x = s z; 0 until evaluated) beside
// its input x̄ (the value snapped: x̄ itself, or its floating-point projection). The final check reads
// both at the random columns of the caller's rows (the exact check and x̄'s violation), so they share
// one record: one cache line per entry instead of two on large shuffled systems, whose columns
// leave the cache.
struct Grid_variable
{
  std::int64_t z;
  double xbar;
};

struct Fixed_point_grid
{
  // The exponents for which F_delta is made of doubles and the rounding below is exact: delta = 2^K
  // must be a normal double (K >= -1022, so that the doubles in [delta, 2 delta) are spaced by the
  // quantum 2^(K-52) >= 2^-1074, the smallest subnormal) and finite (K <= 1023). Every value of
  // F_delta is then a double, and scaling the input by 2^j scales every grid operation by 2^j
  // exactly (scale covariance) as long as K + j stays in this range. A grid asked for outside it is
  // not silently moved to the nearest exponent (that would break the covariance): `in_range` is
  // false and the callers refuse with RANGE_EXCEEDED (`range_message()`).
  static constexpr int min_exponent = -1022;
  static constexpr int max_exponent = 1023;

  int K = 0;           // delta = 2^K (as asked for, also when out of range; from_max_abs() keeps it one past the range)
  bool in_range = true;// min_exponent <= K <= max_exponent
  double delta = 1;    // the range is (-delta, delta)
  double quantum = 0;  // s = 2^(K-52)
  double inverse_quantum = 0;   // 1/s = 2^(52-K) where that is a double (K > -972), else 0

  Fixed_point_grid() : Fixed_point_grid(0) {}
  explicit Fixed_point_grid(int k) : K(k), in_range(k >= min_exponent && k <= max_exponent)
  {
    // out of range: a valid (clamped) grid, so that nothing is undefined, but callers refuse it
    const int kk = k < min_exponent ? min_exponent : (k > max_exponent ? max_exponent : k);
    delta = std::ldexp(1.0, kk);
    quantum = std::ldexp(1.0, kk - 52);
    if(52 - kk <= 1023) inverse_quantum = std::ldexp(1.0, 52 - kk);
  }

  // why a grid with `in_range == false` cannot be used
  std::string range_message() const
  {
    const char* beyond = K == min_exponent - 1 ? " or less" : K == max_exponent + 1 ? " or more" : "";   // from_max_abs()
    return "the fixed-point range delta = 2^" + std::to_string(K) + beyond + " is outside the range of double grids 2^" +
           std::to_string(min_exponent) + " ... 2^" + std::to_string(max_exponent) +
           " (Sec. 4.3): the values are too " + (K < min_exponent ? "small" : "large") +
           " for exact fixed-point arithmetic in doubles";
  }

  // The binary exponent e of v: |v| < 2^e (e = 0 is returned for v = 0, so that an all-zero input
  // still gets a sensible grid). ceil(log2|v|) <= e, so K = e + margin is at least the paper's K.
  static int exponent_of(double v)
  {
    if(v == 0 || !std::isfinite(v)) return 0;
    int e; std::frexp(v, &e);   // |v| = m 2^e, m in [0.5, 1)  =>  |v| < 2^e
    return e;
  }

  // K = e(max_abs) + margin_bits (Sec. 4.3: K = max_i ceil(log2 |x_i|) + 1, "the additional 1 adds a margin").
  // The sum is formed in 64 bits: a margin near the limits of int (delta_margin_bits = -2^31) must not wrap around
  // (undefined, and it made "too small" read "too large"); beyond the range of double grids K is kept one past it
  static Fixed_point_grid from_max_abs(double max_abs, int margin_bits)
  {
    const long long k = static_cast<long long>(exponent_of(max_abs)) + margin_bits;
    return Fixed_point_grid(k < min_exponent ? min_exponent - 1 : k > max_exponent ? max_exponent + 1 : static_cast<int>(k));
  }

  // F_delta(v) = (v + s_v delta) - s_v delta with s_v the sign of v ([EBCK13], Sec. 4.3).
  // Rounds v to a multiple of the quantum (to nearest in the default rounding mode). The
  // volatile stores keep the two operations from being folded even by aggressive optimizers.
  // The result may lie on or beyond the range boundary (or be infinite for K = 1023): callers test
  // contains().
  double round(double v) const
  {
    const double sd = v < 0 ? -delta : delta;
    volatile double t = v + sd;
    volatile double r = t - sd;
    return r;
  }

  // true iff v is in F_delta: |v| < delta and v is a multiple of the quantum.
  bool contains(double v) const
  {
    if(!(std::fabs(v) < delta)) return false;
    const double z = v / quantum;            // exact: quantum is a power of 2 and |z| < 2^52
    return z == std::trunc(z);
  }

  // z = v / s. Precondition: contains(v) (then |z| < 2^52 and the conversion is exact); use
  // to_integer_checked() for a value not known to be on the grid. Multiplying by 1/s, a power of 2,
  // gives the same z (both are exact) without a division: the evaluation converts every variable.
  std::int64_t to_integer(double v) const
  {
    CGAL_precondition(contains(v));
    return std::int64_t(inverse_quantum != 0 ? v * inverse_quantum : v / quantum);
  }
  // z = v / s if v is in F_delta; false (z untouched) otherwise, e.g. for a value outside (-delta, delta),
  // whose conversion to an integer could overflow.
  bool to_integer_checked(double v, std::int64_t& z) const
  {
    if(!contains(v)) return false;
    z = to_integer(v);
    return true;
  }
  // v = z s; exact for |z| <= 2^53.
  double from_integer(std::int64_t z) const { return double(z) * quantum; }
  // the largest |z| of a grid point inside (-delta, delta)
  static constexpr std::int64_t max_integer() { return (std::int64_t(1) << 52) - 1; }
};

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_FIXED_POINT_GRID_H
