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

#include <cmath>
#include <cstdint>
#include <limits>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

struct Fixed_point_grid
{
  // Exponents are clamped so that s stays a normal double and delta stays finite.
  static constexpr int min_exponent = -1020 + 52;
  static constexpr int max_exponent = 1023;

  int K = 0;           // delta = 2^K
  double delta = 1;    // the range is (-delta, delta)
  double quantum = 0;  // s = 2^(K-52)

  Fixed_point_grid() : Fixed_point_grid(0) {}
  explicit Fixed_point_grid(int k)
  {
    K = k < min_exponent ? min_exponent : (k > max_exponent ? max_exponent : k);
    delta = std::ldexp(1.0, K);
    quantum = std::ldexp(1.0, K - 52);
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
  static Fixed_point_grid from_max_abs(double max_abs, int margin_bits)
  {
    return Fixed_point_grid(exponent_of(max_abs) + margin_bits);
  }

  // F_delta(v) = (v + s_v delta) - s_v delta with s_v the sign of v ([EBCK13], Sec. 4.3).
  // Rounds v to a multiple of the quantum (to nearest in the default rounding mode). The
  // volatile stores keep the two operations from being folded even by aggressive optimizers.
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
    const double z = v / quantum;            // exact: quantum is a power of 2 (no underflow: K - 52 >= -1020)
    return z == std::trunc(z);
  }

  // z = v / s, for v in F_delta; exact.
  std::int64_t to_integer(double v) const { return std::int64_t(v / quantum); }
  // v = z s; exact for |z| <= 2^53.
  double from_integer(std::int64_t z) const { return double(z) * quantum; }
  // the largest |z| of a grid point inside (-delta, delta)
  static constexpr std::int64_t max_integer() { return (std::int64_t(1) << 52) - 1; }
};

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_FIXED_POINT_GRID_H
