// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_DYADIC_SUM_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_DYADIC_SUM_H

// Exact sums  sum_k c_k x_k + b  of doubles x_k with integer coefficients c_k and an integer b, in
// integers: every finite double is a dyadic rational m 2^e (m an integer below 2^53), so the sum is
// M 2^L with L the smallest exponent of its terms and M an integer, held in one __int128 when the
// terms span at most about 70 binary orders of magnitude (always the case for the values of a UV map
// on the grid F_delta of the exact snap, whose values are integer multiples of one quantum below
// 2^53 quanta, and for the few corners of one seam of an input map). The exact checks of the pipeline
// (rows of the full system, seam transitions, integer translations) ask only "is it zero", "is it an
// integer" or "which is larger", which M and L answer exactly, with zero tolerance. A sum that does not
// fit says so (fits() false); the caller then evaluates it with CGAL::Mpzf or CGAL::Gmpq, as before
// issue 26. Per term this costs a few integer operations instead of a multiprecision number (Mpzf:
// about 270 instructions per term of a row; Gmpq: allocations).

#include <cmath>
#include <cstdint>
#include <cstring>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

class Dyadic_sum
{
public:
  typedef __int128 Int;

  // adds c * x (x finite)
  void add(long c, double x)
  {
    if(c == 0 || x == 0 || !ok_) return;
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int biased = int((bits >> 52) & 0x7FF);
    std::uint64_t m = bits & ((std::uint64_t(1) << 52) - 1);
    int e = -1074;                                       // subnormal: m 2^-1074
    if(biased == 0x7FF) { ok_ = false; return; }         // not finite
    if(biased != 0) { m |= std::uint64_t(1) << 52; e = biased - 1075; }
    const int tz = __builtin_ctzll(m);                   // m != 0 since x != 0
    m >>= tz;
    e += tz;
    const bool negative = (bits >> 63) != 0;
    add_term(negative ? -Int(m) * c : Int(m) * c, e);
  }

  // adds the integer b
  void add_integer(long b)
  {
    if(b == 0 || !ok_) return;
    add_term(Int(b), 0);
  }

  // false: the terms span too many binary orders of magnitude for one __int128 (or a term was not finite);
  // the sum is then unknown and must be evaluated otherwise
  bool fits() const { return ok_; }
  bool is_zero() const { return m_ == 0; }
  // the sum times 2^s is an integer
  bool is_integer(int s = 0) const
  {
    const long e = long(e_) + s;
    if(m_ == 0 || e >= 0) return true;
    if(e <= -127) return false;                           // 0 < |m_| < 2^126
    const Int a = m_ < 0 ? -m_ : m_, mask = (Int(1) << -e) - 1;
    return (a & mask) == 0;
  }
  // -1, 0, 1: |this| compared with |other| (both fit)
  int compare_magnitude(const Dyadic_sum& other) const
  {
    const Int a = m_ < 0 ? -m_ : m_, b = other.m_ < 0 ? -other.m_ : other.m_;
    if(a == 0 || b == 0) return a == b ? 0 : (a == 0 ? -1 : 1);
    const int la = bit_length(a) + e_, lb = bit_length(b) + other.e_;   // 2^(l-1) <= |value| < 2^l
    if(la != lb) return la < lb ? -1 : 1;
    // same leading bit: align the one with the larger exponent to the other's (no overflow: it ends at that bit)
    const Int x = e_ >= other.e_ ? a << (e_ - other.e_) : a, y = e_ >= other.e_ ? b : b << (other.e_ - e_);
    return x == y ? 0 : (x < y ? -1 : 1);
  }

private:
  Int m_ = 0;          // the sum is m_ 2^e_
  int e_ = 0;
  bool ok_ = true;
  int magnitude_ = 0;  // bound on the bit length of |m_|: every term and the sum stay below 2^125

  static int bit_length(Int a)   // a > 0
  {
    const std::uint64_t hi = std::uint64_t(a >> 64), lo = std::uint64_t(a);
    return hi != 0 ? 128 - __builtin_clzll(hi) : 64 - __builtin_clzll(lo);
  }

  // t 2^e with |t| < 2^116 (53-bit mantissa times a coefficient below 2^63)
  void add_term(Int t, int e)
  {
    const int lt = bit_length(t < 0 ? -t : t);
    if(m_ == 0 && magnitude_ == 0) { m_ = t; e_ = e; magnitude_ = lt; return; }
    if(e < e_) {                                          // rescale the sum to the smaller exponent
      const int shift = e_ - e;
      if(magnitude_ + shift > 120) { ok_ = false; return; }
      m_ *= Int(1) << shift;                              // (a left shift of a negative value is undefined)
      magnitude_ += shift;
      e_ = e;
    }
    const int shift = e - e_;
    if(lt + shift > 120) { ok_ = false; return; }
    m_ += t * (Int(1) << shift);
    magnitude_ = (magnitude_ > lt + shift ? magnitude_ : lt + shift) + 1;   // |a + b| < 2 max(|a|, |b|)
    if(magnitude_ > 124) ok_ = false;
  }
};

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_DYADIC_SUM_H
