// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_ROW_GRIDS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_ROW_GRIDS_H

// Evaluation on one grid per IRREF row, for homogeneous systems (b = 0) whose variables span many
// binary orders of magnitude (e.g. a doubling chain, x_{i+1} = 2 x_i, N = 100). One common F_delta
// (Sec. 4.3) has a quantum above the smallest values, which then round to 0; the exact solution in
// doubles near x̄ that Addendum A of the paper says may exist elsewhere in F is lost.
//
// Here every IRREF row j  p_j x_pi(j) + sum_i Ĉ_ji x_i = 0  gets its own quantum 2^E_j, fine enough
// for the row's own values: E_j = e(s_j) + margin - 53 with s_j = max(|x̄_pi(j)|, sum_i |Ĉ_ji x̄_i / p_j|)
// (e(v): |v| < 2^e(v), fixed_point_grid.h). A free variable x_i is a multiple of 2^F_i, where F_i is the
// smallest exponent that makes every summand Ĉ_ji x_i / p_j of every row j containing it a multiple
// of 2^E_j (F_i = max_j E_j + v2(p_j) - v2(Ĉ_ji), v2 = number of trailing zero bits), and of the odd
// part of its divisor (Alg. 4: lcm of its rows' pivots). Then the implied value
//     x_pi(j) = -sum_i Ĉ_ji x_i / p_j
// is an exact integer multiple N_j of 2^E_j, computed in Gmpz (no partial sum needs to stay in a
// range: the integer sum is exact, which is all the safe dot product of Alg. 5 ensures). x_pi(j) is
// written only if N_j 2^E_j is exactly a double (its odd part has at most 53 bits, no overflow or
// underflow); otherwise the attempt fails, nothing is returned, and the caller keeps its result.
// Every row of the caller's C is checked exactly afterwards (exact_check_dyadic), as on one grid.
//
// The choice of every exponent depends only on x̄ through binary exponents, so the result scales
// with x̄ by powers of two (away from the subnormal range), and is deterministic.

#include <CGAL/Seamless_snapping/internal/projection/fixed_point_grid.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_ops.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_system.h>
#include <CGAL/Seamless_snapping/internal/projection/irref.h>

#include <CGAL/Gmpz.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// the exponent range of the finite doubles: every double is a multiple of 2^min_quantum_exponent
constexpr int min_quantum_exponent = -1074;

// v2(a): trailing zero bits of a != 0
inline int two_adic_valuation(const CGAL::Gmpz& a) { return int(mpz_scan1(a.mpz(), 0)); }

// x = m 2^e with an integer m (m = 0 for x = 0; e = min_quantum_exponent for subnormals)
inline void split_dyadic(double x, CGAL::Gmpz& m, int& e)
{
  int ex;
  const double f = std::frexp(x, &ex);                 // x = f 2^ex, |f| in [0.5, 1)
  e = std::max(ex - 53, min_quantum_exponent);
  const double scaled = std::ldexp(f, ex - e);         // an integer below 2^53 in magnitude: exact
  mpz_set_d(m.mpz(), scaled);
}

// m 2^e as a double, if it is one exactly
inline bool dyadic_to_double(const CGAL::Gmpz& m, int e, double& out)
{
  if(m == 0) { out = 0; return true; }
  const int t = two_adic_valuation(m);
  CGAL::Gmpz odd;
  mpz_tdiv_q_2exp(odd.mpz(), m.mpz(), (unsigned long)t);
  const long bits = long(mpz_sizeinbase(odd.mpz(), 2));
  const long low = long(e) + t;                        // the lowest set bit: 2^low
  if(bits > 53 || low < min_quantum_exponent || low + bits > 1024) return false;
  out = std::ldexp(mpz_get_d(odd.mpz()), int(low));    // odd part below 2^53: exact; no overflow or underflow
  return true;
}

// a 2^s for s of either sign; s < 0 requires 2^-s | a (checked by the callers' choice of exponents)
inline CGAL::Gmpz shift_exact(const CGAL::Gmpz& a, long s)
{
  CGAL::Gmpz r;
  if(s >= 0) mpz_mul_2exp(r.mpz(), a.mpz(), (unsigned long)s);
  else       mpz_tdiv_q_2exp(r.mpz(), a.mpz(), (unsigned long)(-s));
  return r;
}

// Every row of the caller's C (b = 0) holds exactly for the doubles x: per row, the sum of
// C_ik m_k 2^(e_k - e_min) over its entries is 0, with x_k = m_k 2^e_k.
inline bool exact_check_dyadic(const Integer_system& sys, const std::vector<double>& x, std::size_t& bad_row)
{
  const std::size_t n = x.size();
  std::vector<CGAL::Gmpz> m(n);
  std::vector<int> e(n);
  for(std::size_t k = 0; k < n; ++k) split_dyadic(x[k], m[k], e[k]);
  const auto& ptr = sys.fits_int64 ? sys.rows64.ptr : sys.rowsz.ptr;
  for(std::size_t i = 0; i < sys.n_rows; ++i) {
    const bool nonzero_b = sys.fits_int64 ? sys.rows64.b[i] != 0 : sys.rowsz.b[i] != 0;
    int e_min = INT_MAX;
    for(std::size_t q = ptr[i]; q < ptr[i + 1]; ++q)
      e_min = std::min(e_min, e[sys.fits_int64 ? sys.rows64.e[q].col : sys.rowsz.e[q].col]);
    CGAL::Gmpz acc(0);
    for(std::size_t q = ptr[i]; q < ptr[i + 1]; ++q) {
      const std::size_t c = sys.fits_int64 ? sys.rows64.e[q].col : sys.rowsz.e[q].col;
      const CGAL::Gmpz coef = sys.fits_int64 ? to_gmpz(sys.rows64.e[q].val) : sys.rowsz.e[q].val;
      acc += coef * shift_exact(m[c], long(e[c]) - e_min);
    }
    if(nonzero_b || acc != 0) { bad_row = i; return false; }
  }
  return true;
}

// One attempt with `margin` extra bits per row (see the header). Returns false, and leaves `x`
// untouched, when b != 0, when a value would not be exactly a double, or when the exact check fails.
template <typename Int>
bool evaluate_on_row_grids(const Irref<Int>& ir, const Integer_system& sys, const std::vector<double>& xbar,
                           int margin, std::vector<double>& x, int& finest_exponent)
{
  typedef Integer_ops<Int> Ops;
  if(!ir.homogeneous) return false;
  const std::size_t n = ir.n_cols, m = ir.rank();

  // -- row exponents E_j, and v2 of the pivots
  std::vector<int> E(m, INT_MIN), a(m, 0);             // INT_MIN: the row's values are all 0
  for(std::size_t j = 0; j < m; ++j) {
    const double p = std::fabs(Ops::to_double(ir.pivot[j]));
    double s = std::fabs(xbar[ir.pivot_col[j]]);
    double sum = 0;
    for(std::size_t q = ir.ptr[j]; q < ir.ptr[j + 1]; ++q)
      sum += std::fabs(Ops::to_double(ir.val[q])) * std::fabs(xbar[ir.col[q]]) / p;
    s = std::max(s, sum);
    if(!std::isfinite(s)) return false;
    a[j] = two_adic_valuation(to_gmpz(ir.pivot[j]));
    if(s > 0) E[j] = Fixed_point_grid::exponent_of(s) + margin - 53;
  }

  // -- free variables: F_i, then x_i = round(x̄_i / (o_i 2^F_i)) o_i 2^F_i (o_i: odd part of the divisor)
  std::vector<long> F(n, min_quantum_exponent);
  for(std::size_t j = 0; j < m; ++j) {
    if(E[j] == INT_MIN) continue;
    for(std::size_t q = ir.ptr[j]; q < ir.ptr[j + 1]; ++q)
      F[ir.col[q]] = std::max(F[ir.col[q]], long(E[j]) + a[j] - two_adic_valuation(to_gmpz(ir.val[q])));
  }
  std::vector<double> out(xbar);
  std::vector<CGAL::Gmpz> mant(n);                     // x_i = mant_i 2^F_i for the free variables
  finest_exponent = INT_MAX;
  for(std::size_t i = 0; i < n; ++i) {
    if(ir.kind[i] != FREE_COLUMN) continue;
    if(F[i] > 1023) return false;
    // a fresh destination: CGAL::Gmpz copies share their representation, and an in-place write
    // through to_gmpz()'s copy would change the IRREF's divisor for every later projection
    const CGAL::Gmpz divisor = to_gmpz(Ops::abs(ir.divisor_of(i)));
    CGAL::Gmpz odd;
    mpz_tdiv_q_2exp(odd.mpz(), divisor.mpz(), (unsigned long)two_adic_valuation(divisor));
    CGAL::Gmpz mx; int ex;
    split_dyadic(xbar[i], mx, ex);                     // x̄_i = mx 2^ex
    const long k = long(ex) - F[i];
    if(k >= 0) mx = shift_exact(mx, k);                // x̄_i / 2^F_i is an integer
    // round(mx 2^k / odd) for k < 0, halves up: floor((2 mx + D) / (2 D)), D = odd 2^-k
    CGAL::Gmpz D = k >= 0 ? odd : shift_exact(odd, -k), num = mx * 2 + D, den = D * 2, qz;
    mpz_fdiv_q(qz.mpz(), num.mpz(), den.mpz());
    mant[i] = qz * odd;
    if(!dyadic_to_double(mant[i], int(F[i]), out[i])) return false;
    if(mant[i] != 0) finest_exponent = std::min(finest_exponent, int(F[i]));
  }

  // -- implied variables: N_j = -sum_i Ĉ_ji mant_i 2^(F_i - E_j) / p_j, exact in Gmpz
  for(std::size_t j = 0; j < m; ++j) {
    const std::size_t pc = ir.pivot_col[j];
    if(E[j] == INT_MIN) { out[pc] = 0; continue; }
    CGAL::Gmpz S(0);
    for(std::size_t q = ir.ptr[j]; q < ir.ptr[j + 1]; ++q) {
      const std::uint32_t c = ir.col[q];
      if(mant[c] == 0) continue;
      // Ĉ 2^(F_c - E_j) has v2 >= v2(p_j) >= 0 by the choice of F_c: an integer
      S += shift_exact(to_gmpz(ir.val[q]) * mant[c], F[c] - long(E[j]));
    }
    const CGAL::Gmpz p = to_gmpz(ir.pivot[j]);
    if(!mpz_divisible_p(S.mpz(), p.mpz())) return false;   // cannot happen (odd parts divide the divisors)
    const CGAL::Gmpz N = -Integer_ops<CGAL::Gmpz>::exact_div(S, p);
    if(!dyadic_to_double(N, E[j], out[pc])) return false;
    if(N != 0) finest_exponent = std::min(finest_exponent, E[j]);
  }

  std::size_t bad_row = 0;
  if(!exact_check_dyadic(sys, out, bad_row)) return false;
  x.swap(out);
  return true;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_ROW_GRIDS_H
