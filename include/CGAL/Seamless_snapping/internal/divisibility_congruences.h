// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_DIVISIBILITY_CONGRUENCES_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_DIVISIBILITY_CONGRUENCES_H

// The inhomogeneous case, addendum Eq. (2'):
//     x_pi(j) = (b̂_j - sum_i Ĉ_ji x_i) / Ĉ_jpi(j).
// On the grid s Z (z = x / s integer, B_j = b̂_j / s), an implied value is on the grid iff
//     sum_i Ĉ_ji z_i ≡ B_j   (mod p_j),  p_j = Ĉ_jpi(j),
// for every row with p_j != 1: a system of linear congruences in the free variables, i.e. the
// linear Diophantine system  sum_i Ĉ_ji z_i + p_j w_j = B_j. We look for one particular integer
// solution z0 with a column-style Hermite normal form (unimodular column operations by extended
// gcd, [CD94]-style), separately for each group of rows coupled by shared free variables; groups
// with B_j ≡ 0 for all rows take z0 = 0. If the triangular system has no integer solution, none
// exists (the transformation is unimodular) and the system is INFEASIBLE on this grid.
// Every z = z0 + (multiples of the divisors l_i of Alg. 4) is then a solution too, since l_i is a
// multiple of every pivot p_j of a row containing i; evaluation rounds x̄ to that shifted lattice.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/integer_ops.h>
#include <CGAL/Seamless_snapping/internal/irref.h>

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

// Dense column HNF solver for A y = B over Z (A: R x N, full row rank R <= N).
// Returns false iff there is no integer solution; y gets one solution.
inline bool solve_integer_system(std::vector<std::vector<CGAL::Gmpz> > A, const std::vector<CGAL::Gmpz>& B,
                                 std::vector<CGAL::Gmpz>& y)
{
  typedef CGAL::Gmpz Z;
  const std::size_t R = A.size(), N = R == 0 ? 0 : A[0].size();
  std::vector<std::vector<Z> > U(N, std::vector<Z>(N, Z(0)));      // unimodular, A U = H
  for(std::size_t i = 0; i < N; ++i) U[i][i] = 1;
  auto col_op = [&](std::size_t c1, std::size_t c2, const Z& a, const Z& b, const Z& c, const Z& d) {
    // (col c1, col c2) <- (a col c1 + b col c2, c col c1 + d col c2), det = a d - b c = 1
    for(std::size_t r = 0; r < R; ++r) {
      Z x = A[r][c1], w = A[r][c2];
      A[r][c1] = a * x + b * w; A[r][c2] = c * x + d * w;
    }
    for(std::size_t r = 0; r < N; ++r) {
      Z x = U[r][c1], w = U[r][c2];
      U[r][c1] = a * x + b * w; U[r][c2] = c * x + d * w;
    }
  };
  std::size_t rank = 0;
  std::vector<std::size_t> pivot_row;                               // H column t has its leading entry in row pivot_row[t]
  for(std::size_t r = 0; r < R && rank < N; ++r) {
    for(std::size_t t = rank + 1; t < N; ++t) {
      if(A[r][t] == 0) continue;
      if(A[r][rank] == 0) { col_op(rank, t, Z(0), Z(1), Z(1), Z(0)); continue; }   // swap (det -1 is fine: still unimodular)
      Z g, s, u;
      mpz_gcdext(g.mpz(), s.mpz(), u.mpz(), A[r][rank].mpz(), A[r][t].mpz());
      Z a = A[r][rank] / g, b = A[r][t] / g;
      col_op(rank, t, s, u, Z(-b), a);                              // det = s a + u b = 1
    }
    if(A[r][rank] != 0) { pivot_row.push_back(r); ++rank; }
  }
  // Solve H y' = B: columns 0..rank-1 are lower-triangular in rows pivot_row[], other rows must agree.
  std::vector<Z> yp(N, Z(0));
  for(std::size_t r = 0, t = 0; r < R; ++r) {
    Z rest = B[r];
    for(std::size_t q = 0; q < t; ++q) rest -= A[r][q] * yp[q];
    if(t < rank && pivot_row[t] == r) {
      if(!mpz_divisible_p(rest.mpz(), A[r][t].mpz())) return false;
      Z v; mpz_divexact(v.mpz(), rest.mpz(), A[r][t].mpz());
      yp[t] = v; ++t;
    } else if(rest != 0) {
      return false;
    }
  }
  y.assign(N, Z(0));
  for(std::size_t i = 0; i < N; ++i)
    for(std::size_t t = 0; t < rank; ++t) if(yp[t] != 0) y[i] += U[i][t] * yp[t];
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
    std::vector<std::vector<Z> > A(R, std::vector<Z>(N, Z(0)));
    std::vector<Z> rhs(R);
    for(std::size_t r = 0; r < R; ++r) {
      const std::size_t j = G[r];
      Z p = to_gmpz(ir.pivot[j]);
      for(std::size_t q = ir.ptr[j]; q < ir.ptr[j + 1]; ++q) {
        const std::size_t c = std::size_t(std::lower_bound(cols.begin(), cols.end(), ir.col[q]) - cols.begin());
        Z v = to_gmpz(ir.val[q]);
        mpz_fdiv_r(v.mpz(), v.mpz(), p.mpz());                       // coefficients matter modulo p only
        A[r][c] = v;
      }
      A[r][cols.size() + r] = p;
      mpz_fdiv_r(rhs[r].mpz(), B[j].mpz(), p.mpz());
    }
    std::vector<Z> y;
    if(!solve_integer_system(A, rhs, y)) {
      message = "no solution on the grid F_delta: the divisibility conditions of rows ";
      for(std::size_t r = 0; r < R && r < 5; ++r) message += (r ? ", " : "") + std::to_string(G[r]);
      message += R > 5 ? ", ..." : "";
      message += " of the IRREF (addendum, Eq. 2') have no integer solution (e.g. 3 x = 1: 1/3 is not dyadic)";
      return INFEASIBLE;
    }
    for(std::size_t c = 0; c < cols.size(); ++c) {
      Z l = to_gmpz(ir.divisor[cols[c]]);
      Z v; mpz_fdiv_r(v.mpz(), y[c].mpz(), l.mpz());
      if(v != 0) z0[cols[c]] = v;
    }
  }
  return SUCCESS;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_DIVISIBILITY_CONGRUENCES_H
