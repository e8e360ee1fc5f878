// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_EVALUATION_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_EVALUATION_H

// Evaluation of the implied values, Sec. 4.3, Alg. 3 (with Alg. 4 makeDIV and Alg. 5 safeDot),
// corrected for b != 0 by the addendum's Eq. (2'); followed by an exact check of every row of the
// caller's system before anything is returned.
//
// Data flow of one projection (each step depends only on the ones before):
//   grid        K, delta = 2^K, quantum s = 2^(K-52)          from max |x̄|, max |b̂|  (or given)
//   rhs_grid    B_j = b̂_j / s (exact integers)                 depends on grid
//   shifts      z0: particular solution of the congruences     depends on rhs_grid   (b != 0 only)
//   free        x_i = s (z0_i + l_i round((x̄_i/s - z0_i)/l_i)) depends on grid, shifts (Alg. 4)
//   implied     x_pi(j) = (b̂_j - safeDot(Ĉ_j, x)) / p_j        depends on free       (Alg. 3, 5; Eq. 2')
//   check       C z = b / s in exact integers, every row      depends on free, implied

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/Projection_report.h>
#include <CGAL/Seamless_snapping/internal/projection/divisibility_congruences.h>
#include <CGAL/Seamless_snapping/internal/projection/fixed_point_grid.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_ops.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_system.h>
#include <CGAL/Seamless_snapping/internal/projection/irref.h>
#include <CGAL/Seamless_snapping/internal/projection/rounding_refinement.h>
#include <CGAL/Seamless_snapping/internal/projection/row_grids.h>
#include <CGAL/Seamless_snapping/internal/projection/safe_dot.h>
#include <CGAL/Seamless_snapping/internal/threads.h>

#include <CGAL/Gmpz.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// v * 2^e exactly (e may be negative); false when the result is not an integer.
inline bool scale_by_power_of_two(const CGAL::Gmpz& v, int e, CGAL::Gmpz& out)
{
  CGAL::Gmpz r;                                 // fresh: `out` may share a representation
  if(e >= 0) { mpz_mul_2exp(r.mpz(), v.mpz(), (unsigned long)e); out = r; return true; }
  if(v != 0 && mpz_scan1(v.mpz(), 0) < (unsigned long)(-e)) return false;   // not divisible by 2^-e
  mpz_tdiv_q_2exp(r.mpz(), v.mpz(), (unsigned long)(-e));
  out = r;
  return true;
}

// Alg. 4 (makeDIV), generalized by a shift: the grid integer z nearest to X = x̄/s with z ≡ z0 (mod l).
// Returns false when no such z lies inside the grid range |z| < 2^52.
inline bool make_div(double xbar, const Fixed_point_grid& grid, const CGAL::Gmpz& l, const CGAL::Gmpz& z0, std::int64_t& z)
{
  const std::int64_t Z_MAX = Fixed_point_grid::max_integer();
  const double X = std::nearbyint(xbar / grid.quantum);          // |X| <= 2^52 as |x̄| < delta
  CGAL::Gmpz Xz = Integer_ops<CGAL::Gmpz>::from_int64(std::int64_t(X));
  CGAL::Gmpz d = Xz - z0, q, twice_d = d * 2 + l, two_l = l * 2;
  mpz_fdiv_q(q.mpz(), twice_d.mpz(), two_l.mpz());              // q = round(d / l), halves up
  for(int t : {0, 1, -1}) {                                      // the nearest candidate inside the range
    CGAL::Gmpz cand = z0 + (q + t) * l;
    std::int64_t c;
    if(Integer_ops<CGAL::Gmpz>::to_int64(cand, c) && c <= Z_MAX && c >= -Z_MAX) { z = c; return true; }
  }
  return false;
}

// make_div() for z0 = 0 and 0 < l <= 2^20 (the common case: pivots 2 or 4, b = 0), in int64: the
// same z without multiprecision numbers (|2X + l| < 2^54, |(q + 1) l| < 2^53).
inline bool make_div(double xbar, const Fixed_point_grid& grid, std::int64_t l, std::int64_t& z)
{
  CGAL_precondition(l > 0 && l <= (std::int64_t(1) << 20));
  const std::int64_t Z_MAX = Fixed_point_grid::max_integer();
  const std::int64_t X = std::int64_t(std::nearbyint(xbar / grid.quantum));
  const std::int64_t num = 2 * X + l, den = 2 * l;
  const std::int64_t q = num / den - std::int64_t(num % den < 0);   // floor: round(X / l), halves up
  for(int t : {0, 1, -1}) {
    const std::int64_t cand = (q + t) * l;
    if(cand <= Z_MAX && cand >= -Z_MAX) { z = cand; return true; }
  }
  return false;
}

// max(0, f(0), ..., f(n-1)) for f(i) >= 0, in four independent chains of comparisons instead of one,
// whose every step waits for the one before (max is exact: the same value); the passes over all n
// variables of the evaluation (2M variables: measure_change() 7.1 -> 4.6 ms)
template <typename F>
double max_of_nonnegative(std::size_t n, F f)
{
  double m[4] = {0., 0., 0., 0.};
  std::size_t i = 0;
  for(; i + 4 <= n; i += 4)
    for(int k = 0; k < 4; ++k) m[k] = std::max(m[k], f(i + std::size_t(k)));
  for(; i < n; ++i) m[0] = std::max(m[0], f(i));
  return std::max(std::max(m[0], m[1]), std::max(m[2], m[3]));
}

// The change from xbar to out, in the report: max |out_i - xbar_i| and how many variables changed.
inline void measure_change(const std::vector<double>& xbar, const std::vector<double>& out, Projection_report& report)
{
  std::size_t changed = 0;
  report.max_abs_change = max_of_nonnegative(out.size(), [&](std::size_t i) {
    changed += std::size_t(out[i] != xbar[i]);
    return std::fabs(out[i] - xbar[i]);
  });
  report.changed_variables = changed;
}

// A successful projection, in the report.
inline void report_success(const Integer_system& sys, const std::vector<double>& xbar, const std::vector<double>& out,
                           Projection_report& report)
{
  measure_change(xbar, out, report);
  report.status = SUCCESS;
  report.message = "all " + std::to_string(sys.n_rows) + " rows hold exactly; " + std::to_string(report.changed_variables)
                   + " of " + std::to_string(out.size()) + " variables changed, by at most " + std::to_string(report.max_abs_change);
}

// |C_i x̄ - b_i| / ||C_i||_2 of one row, in double arithmetic, summed entry by entry (the term of
// Projection_report::input_violation, the largest over the rows)
struct Row_violation
{
  double r, norm2 = 0;
  template <typename Int> explicit Row_violation(const Int& b) : r(-Integer_ops<Int>::to_double(b)) {}
  template <typename Int> void add(const Int& c, double x)
  {
    const double cd = Integer_ops<Int>::to_double(c);
    r += cd * x;
    norm2 += cd * cd;
  }
  double value() const { return norm2 > 0 ? std::fabs(r) / std::sqrt(norm2) : 0.; }
};

// max_i |C_i x̄ - b_i| / ||C_i||_2 (Projection_report::input_violation), by a pass of its own where
// the evaluation's final check (rows_hold_exactly(), which measures it in its pass) did not run or
// measured another vector: failures, the minimal-change mode. x̄ prefetched as in the other passes
// over the rows (their columns are random on large shuffled systems).
template <typename Int>
double scaled_input_violation(const Csr_rows<Int>& rows, const std::vector<double>& xbar)
{
  const std::size_t entries = rows.e.size();
  double worst = 0;
  for(std::size_t i = 0; i < rows.b.size(); ++i) {
    Row_violation v(rows.b[i]);
    for(std::size_t q = rows.ptr[i]; q < rows.ptr[i + 1]; ++q) {
      if(q + prefetch_distance < entries) __builtin_prefetch(&xbar[rows.e[q + prefetch_distance].col]);
      v.add(rows.e[q].val, xbar[rows.e[q].col]);
    }
    worst = std::max(worst, v.value());
  }
  return worst;
}
inline double scaled_input_violation(const Integer_system& sys, const std::vector<double>& xbar)
{
  return sys.fits_int64 ? scaled_input_violation(sys.rows64, xbar) : scaled_input_violation(sys.rowsz, xbar);
}

// The final check of the evaluation: every row of the caller's canonical system holds for the grid
// integers z of the result, sum_k C_ik z_k == b_i / s, in exact integer arithmetic; false with the
// first violated row otherwise. Every z_k is a grid integer (|z_k| < 2^52), so with int64 coefficients
// (|C_ik| <= 2^63) and b_i = 0 a row of fewer than 2^12 entries is summed in 128 bits without an
// overflow test (the common case); other rows in Gmpz.
// The same pass measures the violation of the x̄ evaluated (`violation`, as scaled_input_violation();
// valid when true is returned): one pass over the rows instead of two, reading z_k and x̄_k from one
// record (Grid_variable).
template <typename Int>
bool rows_hold_exactly(const Csr_rows<Int>& rows, const Fixed_point_grid& grid, const Grid_variable* var,
                       double& violation, std::size_t& violated)
{
  const std::size_t entries = rows.e.size();
  violation = 0;
  for(std::size_t i = 0; i < rows.b.size(); ++i) {
    const std::size_t first = rows.ptr[i], last = rows.ptr[i + 1];
    Row_violation v(rows.b[i]);
    if constexpr(std::is_same<Int, std::int64_t>::value) {
      if(rows.b[i] == 0 && last - first < Grid_sum::unchecked_terms) {
        __int128 acc = 0;
        for(std::size_t q = first; q < last; ++q) {
          if(q + prefetch_distance < entries) __builtin_prefetch(&var[rows.e[q + prefetch_distance].col]);
          acc += (__int128)rows.e[q].val * var[rows.e[q].col].z;
          v.add(rows.e[q].val, var[rows.e[q].col].xbar);
        }
        if(acc != 0) { violated = i; return false; }
        violation = std::max(violation, v.value());
        continue;
      }
    }
    CGAL::Gmpz acc(0), rhs;
    for(std::size_t q = first; q < last; ++q) {
      acc += to_gmpz(rows.e[q].val) * to_gmpz(var[rows.e[q].col].z);
      v.add(rows.e[q].val, var[rows.e[q].col].xbar);
    }
    if(!(scale_by_power_of_two(to_gmpz(rows.b[i]), 52 - grid.K, rhs) && acc == rhs)) { violated = i; return false; }
    violation = std::max(violation, v.value());
  }
  return true;
}

// The first failing IRREF row of evaluate_implied_rows() (row = -1: none), with its status and message
struct Row_failure { std::size_t row = std::size_t(-1); Status status = SUCCESS; std::string message; };

// The implied variables of the IRREF rows [begin, end) (Alg. 3 with Alg. 5; Eq. 2' for b != 0), from the free ones
// (var[i].z, out[i] set): var and out of each row's implied variable written. B: the right-hand side on the grid
// (empty for b = 0), z0 the shifts of Eq. 2'. A row reads free variables only and writes its own implied one, so
// disjoint ranges of rows may run at once. Stops at the first failing row.
// With z_i = z0_i + p_j t_i (z_i - z0_i is a multiple of l_i, hence of p_j), Eq. (2') reads
//     z_pi(j) = c0_j - sum_i Ĉ_ji (z_i - z0_i) / p_j,   c0_j = (B_j - sum_i Ĉ_ji z0_i) / p_j,
// where c0_j is an exact integer (z0 solves the congruences). So every summand is divided by the
// pivot *before* the safe dot product, as in the paper's Alg. 3, and the range argument of Sec. 4.3
// holds for b != 0 as well; for b = 0, z0 = 0 and c0 = 0.
template <typename Int>
Row_failure evaluate_implied_rows(const Irref<Int>& ir, const std::vector<CGAL::Gmpz>& B,
                                  const std::map<std::uint32_t, CGAL::Gmpz>& z0, const Fixed_point_grid& grid,
                                  const std::vector<double>& xbar, Grid_variable* var, std::vector<double>& out,
                                  std::size_t begin, std::size_t end)
{
  typedef Integer_ops<Int> Ops;
  const bool shifted = !B.empty();                         // b != 0: constants c0_j and shifts z0
  const std::size_t terms_total = ir.col.size();
  std::vector<std::pair<Int, std::int64_t> > terms;     // (coefficient, grid integer) of the summands
  Safe_dot_workspace ws;
  CGAL::Gmpz c0;                                         // reused: no allocation per row
  auto fail = [](std::size_t j, Status st, const std::string& msg) { return Row_failure{j, st, msg}; };
  for(std::size_t j = begin; j < end; ++j) {
    const Int& p = ir.pivot[j];
    const bool unit = Ops::is_unit(p);
    if(unit && !shifted && z0.empty()) {
      // The common case (seamless systems): z_pi(j) = -sum_i Ĉ_ji z_i. When the sum of magnitudes
      // is below 2^52, this is the safe dot product's own fast path (safe_dot.h): no partial sum
      // can leave the range, and the value is the exact integer sum.
      Grid_sum acc;
      const std::size_t first = ir.ptr[j], last = ir.ptr[j + 1];
      const bool bounded = last - first < Grid_sum::unchecked_terms;
      for(std::size_t q = first; q < last; ++q) {
        if(q + prefetch_distance < terms_total) __builtin_prefetch(&var[ir.col[q + prefetch_distance]].z);
        if(bounded) acc.add_unchecked(ir.val[q], var[ir.col[q]].z);
        else        acc.add(ir.val[q], var[ir.col[q]].z);
      }
      if(acc.is_safe()) {
        const std::int64_t zp = -std::int64_t(acc.sum);
        var[ir.pivot_col[j]].z = zp;
        out[ir.pivot_col[j]] = grid.from_integer(zp);
        continue;
      }                                                    // else: the general path below
    }
    std::int64_t p64 = 1;
    if(!unit && !Ops::to_int64(p, p64)) p64 = 0;          // huge pivot: every z_i (resp. z_i - z0_i) must be 0
    if(shifted) c0 = B[j];
    terms.clear();
    for(std::size_t q = ir.ptr[j]; q < ir.ptr[j + 1]; ++q) {
      const std::uint32_t c = ir.col[q];
      auto it = z0.empty() ? z0.end() : z0.find(c);
      std::int64_t t;                                        // (z_c - z0_c) / p_j
      if(it == z0.end()) {
        t = var[c].z;
        if(t == 0) continue;
        if(unit) { terms.push_back(std::make_pair(Ops::neg(ir.val[q]), t)); continue; }   // the common case
        if(p64 == 0 || var[c].z % p64 != 0) {
          return fail(j, EXACTNESS_CHECK_FAILED, "internal error: free variable " + std::to_string(c)
                                                 + " is not divisible by the pivot " + Ops::to_string(p) + " of IRREF row "
                                                 + std::to_string(j) + " (Alg. 4)");
        }
        t = var[c].z / p64;
      } else {                                               // shifted (b != 0): exact in Gmpz
        c0 -= to_gmpz(ir.val[q]) * it->second;
        CGAL::Gmpz d = to_gmpz(var[c].z) - it->second;
        const CGAL::Gmpz pz = to_gmpz(p);
        if(!mpz_divisible_p(d.mpz(), pz.mpz())) {
          return fail(j, EXACTNESS_CHECK_FAILED, "internal error: free variable " + std::to_string(c)
                                                 + " is not congruent to its shift modulo the pivot " + Ops::to_string(p)
                                                 + " of IRREF row " + std::to_string(j) + " (Eq. 2')");
        }
        d = Integer_ops<CGAL::Gmpz>::exact_div(d, pz);
        if(!Integer_ops<CGAL::Gmpz>::to_int64(d, t) || t > Fixed_point_grid::max_integer() || t < -Fixed_point_grid::max_integer()) {
          return fail(j, RANGE_EXCEEDED, "the shifted free variable " + std::to_string(c)
                                         + " is outside the fixed-point range (Eq. 2')");
        }
        if(t == 0) continue;
      }
      terms.push_back(std::make_pair(Ops::neg(ir.val[q]), t));
    }
    if(shifted && c0 != 0) {
      const CGAL::Gmpz pz = to_gmpz(p);
      if(!mpz_divisible_p(c0.mpz(), pz.mpz())) {
        return fail(j, EXACTNESS_CHECK_FAILED, "internal error: IRREF row " + std::to_string(j)
                                               + " violates its divisibility congruence (Eq. 2')");
      }
      c0 = Integer_ops<CGAL::Gmpz>::exact_div(c0, pz);   // c0 may share B[j]'s representation: no in-place write
      // c0 may lie outside the range where the implied value does not (2^60 x0 + x1 = 2^60 at x0 = 1: c0 = 2^60 grid
      // units, the value 0): it enters the safe dot as q copies of 2^51 grid units and the rest r in [0, 2^51), each
      // a grid integer, and the safe dot decides on the sum (refused alone, such a row moved the map to a coarser
      // grid, with a change of 1e18 in that example)
      std::int64_t c064;
      if(Integer_ops<CGAL::Gmpz>::to_int64(c0, c064) && c064 <= Fixed_point_grid::max_integer() && c064 >= -Fixed_point_grid::max_integer()) {
        terms.push_back(std::make_pair(Ops::from_int64(1), c064));
      } else {
        constexpr int split = 51;
        CGAL::Gmpz q, rest;
        mpz_fdiv_q_2exp(q.mpz(), c0.mpz(), split);
        mpz_fdiv_r_2exp(rest.mpz(), c0.mpz(), split);
        std::int64_t q64 = 0, rest64 = 0;
        if(!Integer_ops<CGAL::Gmpz>::to_int64(q, q64) || !Integer_ops<CGAL::Gmpz>::to_int64(rest, rest64) ||
           q64 == (std::numeric_limits<std::int64_t>::min)()) {   // (whose magnitude the safe dot could not take)
          return fail(j, RANGE_EXCEEDED, "the constant part (b̂_j - Ĉ_j z0) / p_j of IRREF row " + std::to_string(j)
                                         + " is 2^114 grid units or more, far outside the fixed-point range (Eq. 2', Sec. 7)");
        }
        terms.push_back(std::make_pair(Ops::from_int64(q64), std::int64_t(1) << split));
        if(rest64 != 0) terms.push_back(std::make_pair(Ops::from_int64(1), rest64));
      }
    }
    double r = 0;
    const Safe_dot_result sr = safe_dot(terms, grid, r, ws);
    if(sr == SAFE_DOT_OUT_OF_RANGE) {
      return fail(j, RANGE_EXCEEDED, "implied variable " + std::to_string(ir.pivot_col[j]) + " (IRREF row " + std::to_string(j)
                                     + ") leaves the fixed-point range (-2^" + std::to_string(grid.K) + ", 2^" + std::to_string(grid.K)
                                     + ") (Sec. 7; its input was " + std::to_string(xbar[ir.pivot_col[j]])
                                     + "): x̄ is far from satisfying this constraint, or a larger delta margin is needed");
    }
    if(sr == SAFE_DOT_STUCK) {
      return fail(j, SAFE_DOT_FAILED, "the safe dot product (Alg. 5) for implied variable " + std::to_string(ir.pivot_col[j])
                                      + " (IRREF row " + std::to_string(j) + ") got stuck although its exact value lies inside (-2^"
                                      + std::to_string(grid.K) + ", 2^" + std::to_string(grid.K) + ")");
    }
    if(!(std::fabs(r) < grid.delta)) {
      return fail(j, RANGE_EXCEEDED, "implied variable " + std::to_string(ir.pivot_col[j]) + " (IRREF row " + std::to_string(j)
                                     + ") leaves the fixed-point range (-2^" + std::to_string(grid.K) + ", 2^" + std::to_string(grid.K)
                                     + ") (Sec. 7); its input was " + std::to_string(xbar[ir.pivot_col[j]]));
    }
    var[ir.pivot_col[j]].z = grid.to_integer(r);
    out[ir.pivot_col[j]] = r;
  }
  return Row_failure();
}

// The implied rows run in two halves on two threads only where each half has this many IRREF terms (a thread's start
// costs about as much as a few thousand terms)
constexpr std::size_t min_terms_per_thread = std::size_t(1) << 14;

// One attempt on a given grid. `refine`: minimal-change mode, xbar is the floating-point projection
// and the free grid integers are chosen jointly (rounding_refinement.h) instead of rounded one by one.
// `max_abs`: max |x̄_i| over the constrained columns where the caller knows it, else negative; a grid
// whose range contains it contains every x̄_i, and the scan for values outside the range is left out.
// `threads` >= 2: the implied rows in two halves at once (below; the same results).
template <typename Int>
void evaluate_on_grid(const Irref<Int>& ir, const Integer_system& sys, const std::vector<double>& xbar,
                      const Fixed_point_grid& grid, std::vector<double>& x, Projection_report& report, bool refine = false,
                      double max_abs = -1, unsigned threads = 1)
{
  typedef Integer_ops<Int> Ops;
  const std::size_t n = ir.n_cols, m = ir.rank();
  auto fail = [&](Status s, const std::string& msg) { report.status = s; report.message = msg; };
  report.delta_exponent = grid.K; report.delta = grid.delta; report.quantum = grid.quantum;
  if(!grid.in_range) { fail(RANGE_EXCEEDED, grid.range_message()); return; }
  auto outside = [&](std::size_t i) { return ir.kind[i] != UNCONSTRAINED_COLUMN && !(std::fabs(xbar[i]) < grid.delta); };
  bool any_outside = false;                     // without a branch per column: which are constrained follows no pattern
  if(!(max_abs >= 0 && max_abs < grid.delta))
    for(std::size_t i = 0; i < n; ++i) any_outside = any_outside | outside(i);
  for(std::size_t i = 0; i < n && any_outside; ++i)
    if(outside(i)) {
      fail(RANGE_EXCEEDED, "|x̄[" + std::to_string(i) + "]| is outside the fixed-point range (-2^" + std::to_string(grid.K)
                           + ", 2^" + std::to_string(grid.K) + ")");
      return;
    }

  // -- right-hand side on the grid: B_j = b̂_j / s must be an integer (any size: only the constants
  //    c0_j derived from it below must lie in the range)
  std::vector<CGAL::Gmpz> B;
  if(!ir.homogeneous) {
    B.resize(m);
    for(std::size_t j = 0; j < m; ++j) {
      if(Ops::is_zero(ir.rhs[j])) continue;
      if(!scale_by_power_of_two(to_gmpz(ir.rhs[j]), 52 - grid.K, B[j])) {
        fail(RANGE_EXCEEDED, "b̂ of IRREF row " + std::to_string(j) + " (" + Ops::to_string(ir.rhs[j])
                             + ") is not a multiple of the quantum 2^" + std::to_string(grid.K - 52) + " of the grid F_delta:"
                             + " the values are too large for a grid fine enough for b");
        return;
      }
    }
  }

  // -- shifts z0 (addendum, Eq. 2'): only for b != 0 with non-unit pivots
  std::map<std::uint32_t, CGAL::Gmpz> z0;
  if(!ir.homogeneous && !ir.unit_pivots) {
    std::string msg;
    Status st = solve_divisibility_congruences(ir, B, z0, msg);
    if(st != SUCCESS) { fail(st, msg); return; }
  }

  // -- free variables (Alg. 3 "fix free variable", Alg. 4 makeDIV); unconstrained ones keep x̄
  std::vector<double> out(xbar);
  // grid integers z of the constrained variables (0 until evaluated) and x̄; written once (a
  // std::vector would zero it first: 2M variables, a second pass of 7 ms; a Default_init_vector was
  // measured slower here, in project() right after initialize(): 100k-row shuffled system 5.8 -> 6.7 ms)
  const std::unique_ptr<Grid_variable[]> var(new Grid_variable[n]);
  for(std::size_t i = 0; i < n; ++i) var[i] = Grid_variable{0, xbar[i]};
  const CGAL::Gmpz zero(0);                     // the shift of unshifted variables (multiprecision makeDIV)
  for(const std::uint32_t i : ir.free_columns) {
    const Int& l_i = ir.divisor_of(i);            // the divisor of Alg. 4 (1 where all pivots are)
    const bool unit = Ops::is_unit(l_i);
    const auto it = z0.empty() ? z0.end() : z0.find(i);
    if(unit && it == z0.end()) {
      out[i] = grid.round(xbar[i]);             // F_delta(x̄_i)
      if(!(std::fabs(out[i]) < grid.delta)) {
        fail(RANGE_EXCEEDED, "free variable " + std::to_string(i) + " rounds to the boundary of the fixed-point range");
        return;
      }
      var[i].z = grid.to_integer(out[i]);
    } else {
      std::int64_t l = 0;
      const bool small = it == z0.end() && Ops::to_int64(l_i, l) && l <= (std::int64_t(1) << 20);
      if(!(small ? make_div(xbar[i], grid, l, var[i].z)
                 : make_div(xbar[i], grid, to_gmpz(l_i), it == z0.end() ? zero : it->second, var[i].z))) {
        fail(RANGE_EXCEEDED, "free variable " + std::to_string(i) + " must be a multiple of " + Ops::to_string(l_i)
                             + " grid quanta (lcm of its rows' pivots, Alg. 4), and no such multiple lies in the fixed-point range");
        return;
      }
      out[i] = grid.from_integer(var[i].z);
    }
  }
  if(refine) refine_free_rounding(ir, grid, var.get(), out);

  // -- implied variables (Alg. 3 with Alg. 5; Eq. 2' for b != 0): with `threads` >= 2 the rows are cut into two
  //    halves of about as many terms, evaluated at once; the first failing row (in row order) is reported, as on one thread
  const std::size_t terms_total = ir.col.size();
  Row_failure failure, second_failure;
  if(threads >= 2 && terms_total >= min_terms_per_thread * 2) {
    const std::size_t half = std::size_t(std::lower_bound(ir.ptr.begin(), ir.ptr.begin() + std::ptrdiff_t(m) + 1, terms_total / 2)
                                         - ir.ptr.begin());   // the first row starting past half of the terms
    run_concurrently(2, [&] { failure = evaluate_implied_rows(ir, B, z0, grid, xbar, var.get(), out, 0, half); },
                        [&] { second_failure = evaluate_implied_rows(ir, B, z0, grid, xbar, var.get(), out, half, m); });
    if(failure.row == std::size_t(-1)) failure = second_failure;
  } else {
    failure = evaluate_implied_rows(ir, B, z0, grid, xbar, var.get(), out, 0, m);
  }
  if(failure.row != std::size_t(-1)) { fail(failure.status, failure.message); return; }

  // -- exact check of every row of the caller's (canonical) system
  std::size_t violated = 0;
  double violation = 0;
  if(!(sys.fits_int64 ? rows_hold_exactly(sys.rows64, grid, var.get(), violation, violated)
                      : rows_hold_exactly(sys.rowsz, grid, var.get(), violation, violated))) {
    fail(EXACTNESS_CHECK_FAILED, "internal error: row " + std::to_string(violated) + " of C x = b is violated after evaluation");
    return;
  }

  report_success(sys, xbar, out, report);
  report.input_violation = violation;
  x.swap(out);
}

// The common grid F_delta of Sec. 4.3: K = e(max |x̄_i|) + margin over the constrained x̄ (the
// paper's choice). If that grid is too small for the solution (RANGE_EXCEEDED) and b != 0, one more
// attempt uses K from max(|x̄_i|, |b̂_j / p_j|): the values the implied variables take when the free
// ones are 0.
template <typename Int>
void evaluate_on_common_grid(const Irref<Int>& ir, const Integer_system& sys, const std::vector<double>& xbar,
                             const Projection_options& options, std::vector<double>& x, Projection_report& report)
{
  typedef Integer_ops<Int> Ops;
  const bool refine = options.minimal_change;
  double max_b = 0;
  const double max_x = max_of_nonnegative(ir.n_cols, [&](std::size_t i) {
    return ir.kind[i] != UNCONSTRAINED_COLUMN ? std::fabs(xbar[i]) : 0.;
  });
  for(std::size_t j = 0; j < ir.rank(); ++j)
    if(!Ops::is_zero(ir.rhs[j]))
      max_b = std::max(max_b, std::fabs(Ops::to_double(ir.rhs[j]) / Ops::to_double(ir.pivot[j])));
  const Fixed_point_grid g1 = Fixed_point_grid::from_max_abs(max_x, options.delta_margin_bits);
  const unsigned threads = resolve_number_of_threads(options.number_of_threads);
  evaluate_on_grid(ir, sys, xbar, g1, x, report, refine, max_x, threads);
  if(report.status != RANGE_EXCEEDED || max_b <= max_x) return;
  const Fixed_point_grid g2 = Fixed_point_grid::from_max_abs(std::max(max_x, max_b), options.delta_margin_bits);
  if(g2.K == g1.K) return;
  Projection_report second;
  evaluate_on_grid(ir, sys, xbar, g2, x, second, refine, max_x, threads);
  if(second.status == SUCCESS) report = second;
  else report.message += " (also with delta = 2^" + std::to_string(g2.K) + " from |b̂_j / p_j|: " + second.message + ")";
}

// A RANGE_EXCEEDED of b != 0 with non-unit pivots may hide a system without any solution in doubles (3 x = 1 at
// x̄ = 1e90: b̂ is not on the grid that x̄ asks for, which is checked first): the divisibility congruences on the
// unit grid (B = b̂) decide that whatever the grid, since their solvability modulo the odd parts of the pivots does
// not change when B is scaled by a power of two (solve_divisibility_congruences()); INFEASIBLE then, with its message
template <typename Int>
void refine_range_failure(const Irref<Int>& ir, Projection_report& report)
{
  if(report.status != RANGE_EXCEEDED || ir.homogeneous || ir.unit_pivots) return;
  std::vector<CGAL::Gmpz> B(ir.rank());
  for(std::size_t j = 0; j < B.size(); ++j) B[j] = to_gmpz(ir.rhs[j]);
  std::map<std::uint32_t, CGAL::Gmpz> z0;
  std::string message;
  if(solve_divisibility_congruences(ir, B, z0, message) == INFEASIBLE) {
    report.status = INFEASIBLE;
    report.message = message;
  }
}

// Alg. 3 driver: evaluates on the common grid (given in the options, or chosen from x̄), and flags a
// change that is huge relative to the input's violation (Projection_report::large_change).
// Without a given grid, b = 0, and a large change or RANGE_EXCEEDED, the evaluation with one quantum
// per IRREF row (row_grids.h) is tried, and kept if it is exact and changes x̄ less.
// Precondition: every x̄_i is finite (Exact_constraint_projection::project() checks it).
template <typename Int>
void evaluate(const Irref<Int>& ir, const Integer_system& sys, const std::vector<double>& xbar,
              const Projection_options& options, std::vector<double>& x, Projection_report& report)
{
  // x̄'s violation: measured by the final check of a successful evaluation, else by a pass of its own
  // (a second grid's report replaces the first one)
  double violation = 0;
  auto flag = [&](Projection_report& r) {
    r.input_violation = violation;
    r.large_change = r.status == SUCCESS && r.max_abs_change > Projection_report::large_change_factor * r.input_violation;
  };
  auto flag_first = [&](Projection_report& r) {
    violation = r.status == SUCCESS ? r.input_violation : scaled_input_violation(sys, xbar);
    flag(r);
  };
  if(options.delta_exponent) {
    evaluate_on_grid(ir, sys, xbar, Fixed_point_grid(*options.delta_exponent), x, report, options.minimal_change, -1,
                     resolve_number_of_threads(options.number_of_threads));
    flag_first(report);
    refine_range_failure(ir, report);
    return;
  }
  evaluate_on_common_grid(ir, sys, xbar, options, x, report);
  flag_first(report);
  refine_range_failure(ir, report);
  // a large change or no room on one grid: one quantum per IRREF row (b = 0, row_grids.h), kept if
  // it is exact and moves x̄ less
  // (not when the common grid itself lies outside the doubles: that refusal keeps the scale covariance)
  if(!ir.homogeneous || !Fixed_point_grid(report.delta_exponent).in_range
     || !(report.large_change || report.status == RANGE_EXCEEDED)) return;
  for(int margin : { 0, 2 }) {
    std::vector<double> y;
    int finest = 0;
    if(!evaluate_on_row_grids(ir, sys, xbar, margin, y, finest)) continue;
    Projection_report r;
    report_success(sys, xbar, y, r);
    if(report.status == SUCCESS && !(r.max_abs_change < report.max_abs_change)) return;
    r.delta_exponent = report.delta_exponent; r.delta = report.delta;
    r.quantum = finest == INT_MAX ? report.quantum : std::ldexp(1., finest);
    r.per_row_grids = true;
    r.message += " (one grid per IRREF row: the common grid F_delta " + std::string(report.status == SUCCESS
                 ? "changed x̄ by " + std::to_string(report.max_abs_change) : "failed: " + report.message) + ")";
    flag(r);
    report = r;
    x.swap(y);
    return;
  }
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_EVALUATION_H
