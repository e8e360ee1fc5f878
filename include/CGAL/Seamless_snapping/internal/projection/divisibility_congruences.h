// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_DIVISIBILITY_CONGRUENCES_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_DIVISIBILITY_CONGRUENCES_H

// The inhomogeneous case, addendum Eq. (2'):
//     x_pi(j) = (b̂_j - sum_i Ĉ_ji x_i) / Ĉ_jpi(j).
// On the grid s Z (z = x / s integer, B_j = b̂_j / s), an implied value is on the grid iff
//     sum_i Ĉ_ji z_i ≡ B_j   (mod p_j),  p_j = Ĉ_jpi(j),
// for every row with p_j != 1: a system of linear congruences in the free variables, i.e. the
// linear Diophantine system  sum_i Ĉ_ji z_i + p_j w_j = B_j. We look for one particular integer
// solution z0 with a column-style Hermite normal form (unimodular column operations by extended
// gcd, [CD94]-style), separately for each group of rows coupled by shared free variables; groups
// with B_j ≡ 0 for all rows take z0 = 0. If the triangular system has no integer solution, none
// exists on this grid (the transformation is unimodular); the same congruences modulo the odd parts of
// the p_j then tell whether a finer grid of powers of two has one (2 is a unit there): if so, the
// system has dyadic solutions that the fixed-point range cannot hold (RANGE_EXCEEDED), else none in
// doubles at all (INFEASIBLE).
// Every z = z0 + (multiples of the divisors l_i of Alg. 4) is then a solution too, since l_i is a
// multiple of every pivot p_j of a row containing i; evaluation rounds x̄ to that shifted lattice.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_ops.h>
#include <CGAL/Seamless_snapping/internal/projection/irref.h>

#include <CGAL/Gmpz.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// Column HNF solver for A y = B over Z (A: R x N, dense). Unimodular column operations bring A to
// lower-triangular H = A U; H y' = B is solved by forward substitution with exact divisibility
// checks, and y = U y'. U is never formed: the 2x2 column operations are recorded and applied to y'
// in reverse order. Rows above the current one are already zero right of their pivot, so each
// operation only touches the rows below. Returns false iff there is no integer solution.
//
// Entry growth: when row r has a "modulus column" (modulus_col[r] = c: column c equals p e_r, as the
// w_j columns of the congruence system do), that column stays untouched until row r is processed,
// so entries of row r can be reduced modulo p at any time by a unimodular column operation that
// changes nothing else. Doing so after every operation keeps every entry below max |p| (without it,
// the HNF coefficients explode).
inline bool solve_integer_system(std::vector<std::vector<CGAL::Gmpz> > A, const std::vector<CGAL::Gmpz>& B,
                                 std::vector<CGAL::Gmpz>& y,
                                 const std::vector<std::size_t>& modulus_col = std::vector<std::size_t>())
{
  typedef CGAL::Gmpz Z;
  const std::size_t R = A.size(), N = R == 0 ? 0 : A[0].size();
  struct Op { std::size_t c1, c2; Z a, b, c, d; };   // (col c1, col c2) <- (a col c1 + b col c2, c col c1 + d col c2)
  std::vector<Op> ops;
  Z x, w;
  const std::size_t NONE = std::size_t(-1);
  auto has_modulus = [&](std::size_t r) { return r < modulus_col.size() && modulus_col[r] != NONE; };
  // entry (r, c) <- entry mod p_r, by col_c -= q col_{modulus_col[r]} (changes only that entry)
  auto reduce = [&](std::size_t r, std::size_t c) {
    const std::size_t mc = modulus_col[r];
    if(c == mc || A[r][c] == 0) return;
    const Z& p = A[r][mc];
    Z q; mpz_fdiv_q(q.mpz(), A[r][c].mpz(), p.mpz());
    if(q == 0) return;
    A[r][c] = Integer_ops<Z>::mod_floor(A[r][c], p);
    ops.push_back(Op{c, mc, Z(1), Z(-q), Z(0), Z(1)});
  };
  auto col_op = [&](std::size_t r0, std::size_t c1, std::size_t c2, const Z& a, const Z& b, const Z& c, const Z& d) {
    for(std::size_t r = r0; r < R; ++r) {
      if(A[r][c1] == 0 && A[r][c2] == 0) continue;
      x = A[r][c1]; w = A[r][c2];
      A[r][c1] = a * x + b * w; A[r][c2] = c * x + d * w;
    }
    ops.push_back(Op{c1, c2, a, b, c, d});
    for(std::size_t r = r0 + 1; r < R; ++r)
      if(has_modulus(r)) { reduce(r, c1); reduce(r, c2); }
  };
  std::size_t rank = 0;
  std::vector<std::size_t> pivot_row;                 // H column t has its leading entry in row pivot_row[t]
  for(std::size_t r = 0; r < R && rank < N; ++r) {
    if(has_modulus(r)) for(std::size_t t = rank; t < N; ++t) reduce(r, t);
    for(std::size_t t = rank + 1; t < N; ++t) {
      if(A[r][t] == 0) continue;
      if(A[r][rank] == 0) { col_op(r, rank, t, Z(0), Z(1), Z(1), Z(0)); continue; }   // swap (det -1: still unimodular)
      Z g, s, u;
      mpz_gcdext(g.mpz(), s.mpz(), u.mpz(), A[r][rank].mpz(), A[r][t].mpz());
      Z a = A[r][rank] / g, b = A[r][t] / g;
      col_op(r, rank, t, s, u, Z(-b), a);              // det = s a + u b = 1
    }
    if(A[r][rank] != 0) { pivot_row.push_back(r); ++rank; }
  }
  std::vector<Z> yp(N, Z(0));
  for(std::size_t r = 0, t = 0; r < R; ++r) {
    Z rest = B[r];
    for(std::size_t q = 0; q < t; ++q) if(A[r][q] != 0 && yp[q] != 0) rest -= A[r][q] * yp[q];
    if(t < rank && pivot_row[t] == r) {
      if(!mpz_divisible_p(rest.mpz(), A[r][t].mpz())) return false;
      yp[t] = Integer_ops<Z>::exact_div(rest, A[r][t]);   // never write through mpz() of a shared copy
      ++t;
    } else if(rest != 0) {
      return false;
    }
  }
  // y = U y' = E_1 E_2 ... E_k y': apply the recorded operations in reverse order. An operation
  // acting on columns (c1, c2) as [[a, c], [b, d]] maps (v_c1, v_c2) to (a v_c1 + c v_c2, b v_c1 + d v_c2).
  for(std::size_t k = ops.size(); k-- > 0; ) {
    const Op& o = ops[k];
    if(yp[o.c1] == 0 && yp[o.c2] == 0) continue;
    x = yp[o.c1]; w = yp[o.c2];
    yp[o.c1] = o.a * x + o.c * w;
    yp[o.c2] = o.b * x + o.d * w;
  }
  y.swap(yp);
  return true;
}

// Finds z0 (per column, reduced into [0, divisor)) such that every row j with p_j != 1 has
// sum_i Ĉ_ji z0_i ≡ B_j (mod p_j). `B` holds b̂_j / s per pivot row (exact integers).
// Columns without a shift are left out of z0.
template <typename Int>
Status solve_divisibility_congruences(const Irref<Int>& ir, const std::vector<CGAL::Gmpz>& B,
                                      std::map<std::uint32_t, CGAL::Gmpz>& z0, std::string& message)
{
  typedef Integer_ops<Int> Ops;
  typedef CGAL::Gmpz Z;
  z0.clear();
  const std::size_t m = ir.rank();
  // rows that pose a congruence
  std::vector<std::size_t> rows;
  for(std::size_t j = 0; j < m; ++j) if(!Ops::is_unit(ir.pivot[j])) rows.push_back(j);
  if(rows.empty()) return SUCCESS;
  // group rows coupled through shared free columns (union-find over rows)
  std::vector<std::size_t> parent(rows.size());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t a) { while(parent[a] != a) a = parent[a] = parent[parent[a]]; return a; };
  std::map<std::uint32_t, std::size_t> first_row_of_col;
  for(std::size_t r = 0; r < rows.size(); ++r)
    for(std::size_t q = ir.ptr[rows[r]]; q < ir.ptr[rows[r] + 1]; ++q) {
      auto ins = first_row_of_col.insert(std::make_pair(ir.col[q], r));
      if(!ins.second) parent[find(r)] = find(ins.first->second);
    }
  std::map<std::size_t, std::vector<std::size_t> > groups;            // deterministic order
  for(std::size_t r = 0; r < rows.size(); ++r) groups[find(r)].push_back(rows[r]);
  for(const auto& grp : groups) {
    const std::vector<std::size_t>& G = grp.second;
    bool trivial = true;
    for(std::size_t j : G) {
      Z p = to_gmpz(ir.pivot[j]);
      if(!mpz_divisible_p(B[j].mpz(), p.mpz())) { trivial = false; break; }
    }
    if(trivial) continue;                                            // z0 = 0 satisfies the whole group
    std::vector<std::uint32_t> cols;
    for(std::size_t j : G) for(std::size_t q = ir.ptr[j]; q < ir.ptr[j + 1]; ++q) cols.push_back(ir.col[q]);
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
    const std::size_t R = G.size(), N = cols.size() + R;
    if(N > 4000) {
      message = "the divisibility congruences of the inhomogeneous system (addendum, Eq. 2') couple "
                + std::to_string(N) + " unknowns; the dense Diophantine solver is limited to 4000";
      return RANGE_EXCEEDED;
    }
    // the congruences modulo p_j, or (odd_only) modulo the odd parts of p_j: those decide whether any dyadic solution
    // exists (2 is a unit of Z[1/2], so the conditions modulo powers of two vanish on a fine enough grid)
    std::vector<Z> y;
    std::vector<std::size_t> modulus_col(R);
    for(std::size_t r = 0; r < R; ++r) modulus_col[r] = cols.size() + r;   // the w_j column: p_j e_j
    auto solvable = [&](bool odd_only) {
      std::vector<std::vector<Z> > A(R, std::vector<Z>(N, Z(0)));
      std::vector<Z> rhs(R);
      for(std::size_t r = 0; r < R; ++r) {
        const std::size_t j = G[r];
        Z p = to_gmpz(ir.pivot[j]);
        if(odd_only) while(p != 0 && mpz_even_p(p.mpz())) p /= Z(2);   // (the same lattice for p and -p)
        for(std::size_t q = ir.ptr[j]; q < ir.ptr[j + 1]; ++q) {
          const std::size_t c = std::size_t(std::lower_bound(cols.begin(), cols.end(), ir.col[q]) - cols.begin());
          A[r][c] = Integer_ops<Z>::mod_floor(to_gmpz(ir.val[q]), p);  // coefficients matter modulo p only
        }
        A[r][cols.size() + r] = p;
        rhs[r] = Integer_ops<Z>::mod_floor(B[j], p);
      }
      return solve_integer_system(A, rhs, y, modulus_col);
    };
    if(!solvable(false)) {
      std::string rows_named;
      for(std::size_t r = 0; r < R && r < 5; ++r) rows_named += (r ? ", " : "") + std::to_string(G[r]);
      rows_named += R > 5 ? ", ..." : "";
      if(solvable(true)) {   // a dyadic solution exists, on a finer grid than the values' range allows
        message = "no solution on the grid F_delta: the divisibility conditions of rows " + rows_named + " of the IRREF "
                  "(addendum, Eq. 2') hold only on a finer grid: the system has solutions in dyadic rationals, but they "
                  "need more bits between their largest and smallest digits than the fixed-point range has (Sec. 7)";
        return RANGE_EXCEEDED;
      }
      message = "no solution on the grid F_delta: the divisibility conditions of rows " + rows_named + " of the IRREF "
                "(addendum, Eq. 2') have no integer solution on any grid of powers of two: no solution in doubles exists "
                "(e.g. 3 x = 1: 1/3 is not dyadic)";
      return INFEASIBLE;
    }
    for(std::size_t c = 0; c < cols.size(); ++c) {
      const Z v = Integer_ops<Z>::mod_floor(y[c], to_gmpz(ir.divisor_of(cols[c])));
      if(v != 0) z0[cols[c]] = v;
    }
  }
  return SUCCESS;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_DIVISIBILITY_CONGRUENCES_H
