// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_LOCAL_NULL_SPACE_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_LOCAL_NULL_SPACE_H

// Small dense integer matrices, exactly: whether rows lie in the row space of A, and
// an integer basis of the null space {d : A d = 0} of A:
// reduced row echelon form over Q (CGAL::Gmpq), one basis vector per free column (1 there, minus
// the pivot rows' entries at the pivot columns), scaled by the lcm of its denominators and divided
// by the gcd of its entries. Used by the flip repair (flip_repair.h) for the moves of a few node
// vertices that keep every row of the node system exact. Vectors with an entry of magnitude
// >= `max_entry` are dropped (they would not give small moves on the grid F_delta).

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>

#include <gmp.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// Reduced row echelon form of `m` (n_rows x n_cols, row-major) in place; the pivot column of each
// nonzero row, in order.
inline void reduced_row_echelon(std::vector<CGAL::Gmpq>& m, std::size_t n_rows, std::size_t n_cols,
                                std::vector<int>& pivot_col)
{
  pivot_col.clear();
  std::size_t r = 0;
  for(std::size_t c = 0; c < n_cols && r < n_rows; ++c) {
    std::size_t p = r;
    while(p < n_rows && CGAL::is_zero(m[p * n_cols + c])) ++p;
    if(p == n_rows) continue;
    if(p != r) for(std::size_t j = 0; j < n_cols; ++j) std::swap(m[p * n_cols + j], m[r * n_cols + j]);
    const CGAL::Gmpq inv = CGAL::Gmpq(1) / m[r * n_cols + c];
    for(std::size_t j = 0; j < n_cols; ++j) m[r * n_cols + j] *= inv;
    for(std::size_t i = 0; i < n_rows; ++i) {
      if(i == r || CGAL::is_zero(m[i * n_cols + c])) continue;
      const CGAL::Gmpq f = m[i * n_cols + c];
      for(std::size_t j = 0; j < n_cols; ++j) m[i * n_cols + j] -= f * m[r * n_cols + j];
    }
    pivot_col.push_back(int(c));
    ++r;
  }
}

// true iff every row of `b` (n_b x n_cols) is a rational combination of the rows of `a`
// (n_rows x n_cols): rank [a; b] = rank a.
inline bool rows_in_row_space(std::size_t n_rows, std::size_t n_cols, const std::vector<long>& a,
                              std::size_t n_b, const std::vector<long>& b)
{
  std::vector<CGAL::Gmpq> m(a.begin(), a.end());
  std::vector<int> pivots;
  reduced_row_echelon(m, n_rows, n_cols, pivots);
  const std::size_t rank = pivots.size();
  m.insert(m.end(), b.begin(), b.end());
  reduced_row_echelon(m, n_rows + n_b, n_cols, pivots);
  return pivots.size() == rank;
}

// `a`: n_rows x n_cols, row-major. Appends the basis vectors (n_cols entries each) to `basis`.
inline void integer_null_space(std::size_t n_rows, std::size_t n_cols, const std::vector<long>& a, long max_entry,
                               std::vector<std::vector<long> >& basis)
{
  std::vector<CGAL::Gmpq> m(a.begin(), a.end());
  std::vector<int> pivot_col;
  reduced_row_echelon(m, n_rows, n_cols, pivot_col);
  std::vector<char> is_pivot(n_cols, 0);
  for(int c : pivot_col) is_pivot[std::size_t(c)] = 1;
  for(std::size_t f = 0; f < n_cols; ++f) {
    if(is_pivot[f]) continue;
    std::vector<CGAL::Gmpq> v(n_cols, CGAL::Gmpq(0));
    v[f] = 1;
    for(std::size_t i = 0; i < pivot_col.size(); ++i) v[std::size_t(pivot_col[i])] = -m[i * n_cols + f];
    CGAL::Gmpz l(1), g(0);
    for(const CGAL::Gmpq& q : v) mpz_lcm(l.mpz(), l.mpz(), q.denominator().mpz());
    std::vector<CGAL::Gmpz> z(n_cols);
    for(std::size_t j = 0; j < n_cols; ++j) {
      z[j] = v[j].numerator() * (l / v[j].denominator());
      mpz_gcd(g.mpz(), g.mpz(), z[j].mpz());
    }
    std::vector<long> out(n_cols, 0);
    bool small = true;
    for(std::size_t j = 0; j < n_cols && small; ++j) {
      const CGAL::Gmpz e = z[j] / g;                        // exact: g divides every entry
      small = mpz_cmpabs_ui(e.mpz(), static_cast<unsigned long>(max_entry)) < 0;
      if(small) out[j] = mpz_get_si(e.mpz());
    }
    if(small) basis.push_back(out);
  }
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_LOCAL_NULL_SPACE_H
