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

// Small integer matrices, exactly: whether rows lie in the row space of A (Exact_row_space), and an
// integer basis of the null space {d : A d = 0} of A. Both from the reduced row echelon form over Q
// (CGAL::Gmpq, on sparse rows: these matrices have a few entries per row). Null space: one basis
// vector per free column (1 there, minus the pivot rows' entries at the pivot columns), scaled by
// the lcm of its denominators and divided by the gcd of its entries. Used by the flip repair
// (flip_repair.h) for the moves of a few node vertices that keep every row of the node system
// exact, and for the faces that the constraints force to be degenerate. Vectors with an entry of
// magnitude >= `max_entry` are dropped (they would not give small moves on the grid F_delta).

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>

#include <gmp.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// A sparse row over Q: (column, nonzero value), columns increasing.
typedef std::vector<std::pair<std::size_t, CGAL::Gmpq> > Sparse_rational_row;

// the rows of the dense integer matrix `a` (n_rows x n_cols, row-major) as sparse rows
inline std::vector<Sparse_rational_row> sparse_rows(std::size_t n_rows, std::size_t n_cols, const std::vector<long>& a)
{
  std::vector<Sparse_rational_row> m(n_rows);
  for(std::size_t i = 0; i < n_rows; ++i)
    for(std::size_t j = 0; j < n_cols; ++j)
      if(a[i * n_cols + j] != 0) m[i].emplace_back(j, CGAL::Gmpq(a[i * n_cols + j]));
  return m;
}

// the entry of `row` in column `col` (nullptr: zero)
inline const CGAL::Gmpq* sparse_entry(const Sparse_rational_row& row, std::size_t col)
{
  auto it = std::lower_bound(row.begin(), row.end(), col,
                             [](const std::pair<std::size_t, CGAL::Gmpq>& e, std::size_t c) { return e.first < c; });
  return it != row.end() && it->first == col ? &it->second : nullptr;
}

// a -= f * b, exactly; entries that cancel are removed
inline void subtract_multiple(Sparse_rational_row& a, const CGAL::Gmpq& f, const Sparse_rational_row& b)
{
  Sparse_rational_row out;
  out.reserve(a.size() + b.size());
  std::size_t i = 0, j = 0;
  while(i < a.size() || j < b.size()) {
    if(j == b.size() || (i < a.size() && a[i].first < b[j].first)) { out.push_back(std::move(a[i++])); continue; }
    if(i == a.size() || b[j].first < a[i].first) { out.emplace_back(b[j].first, -(f * b[j].second)); ++j; continue; }
    CGAL::Gmpq v = a[i].second - f * b[j].second;
    if(!CGAL::is_zero(v)) out.emplace_back(a[i].first, std::move(v));
    ++i; ++j;
  }
  a.swap(out);
}

// Reduced row echelon form of the rows `m` in place (Gauss-Jordan over Q): afterwards the first
// pivot_col.size() rows are the nonzero rows, row i with a leading 1 in column pivot_col[i] and zeros in
// the other pivot columns; the remaining rows are empty.
inline void reduced_row_echelon(std::vector<Sparse_rational_row>& m, std::vector<int>& pivot_col)
{
  pivot_col.clear();
  std::size_t r = 0;
  // every row from r on starts at column >= c: the next pivot column is the smallest leading column
  while(r < m.size()) {
    std::size_t p = m.size();
    for(std::size_t i = r; i < m.size(); ++i)
      if(!m[i].empty() && (p == m.size() || m[i].front().first < m[p].front().first)) p = i;
    if(p == m.size()) break;
    std::swap(m[p], m[r]);
    const std::size_t c = m[r].front().first;
    const CGAL::Gmpq inv = CGAL::Gmpq(1) / m[r].front().second;
    for(auto& e : m[r]) e.second *= inv;
    for(std::size_t i = 0; i < m.size(); ++i) {
      if(i == r) continue;
      const CGAL::Gmpq* f = sparse_entry(m[i], c);
      if(f != nullptr) { const CGAL::Gmpq g = *f; subtract_multiple(m[i], g, m[r]); }
    }
    pivot_col.push_back(int(c));
    ++r;
  }
}

// The row space of a small integer matrix `a` (n_rows x n_cols, row-major), reduced once: which
// integer rows lie in it.
class Exact_row_space
{
public:
  Exact_row_space(std::size_t n_rows, std::size_t n_cols, const std::vector<long>& a)
    : n_cols_(n_cols), m_(sparse_rows(n_rows, n_cols, a))
  {
    reduced_row_echelon(m_, pivot_col_);
  }
  // true iff the row `v` (n_cols entries) is a rational combination of the rows of `a`: v minus
  // v[pivot] times each pivot row, in order, is zero
  bool contains(const std::vector<long>& v) const
  {
    Sparse_rational_row w = sparse_rows(1, n_cols_, v).front();
    for(std::size_t i = 0; i < pivot_col_.size() && !w.empty(); ++i) {
      const CGAL::Gmpq* f = sparse_entry(w, std::size_t(pivot_col_[i]));
      if(f != nullptr) { const CGAL::Gmpq g = *f; subtract_multiple(w, g, m_[i]); }
    }
    return w.empty();
  }

private:
  std::size_t n_cols_;
  std::vector<Sparse_rational_row> m_;
  std::vector<int> pivot_col_;
};

// `a`: n_rows x n_cols, row-major. Appends the basis vectors (n_cols entries each) to `basis`.
inline void integer_null_space(std::size_t n_rows, std::size_t n_cols, const std::vector<long>& a, long max_entry,
                               std::vector<std::vector<long> >& basis)
{
  std::vector<Sparse_rational_row> m = sparse_rows(n_rows, n_cols, a);
  std::vector<int> pivot_col;
  reduced_row_echelon(m, pivot_col);
  std::vector<char> is_pivot(n_cols, 0);
  for(int c : pivot_col) is_pivot[std::size_t(c)] = 1;
  for(std::size_t f = 0; f < n_cols; ++f) {
    if(is_pivot[f]) continue;
    std::vector<CGAL::Gmpq> v(n_cols, CGAL::Gmpq(0));
    v[f] = 1;
    for(std::size_t i = 0; i < pivot_col.size(); ++i)
      if(const CGAL::Gmpq* e = sparse_entry(m[i], f)) v[std::size_t(pivot_col[i])] = -*e;
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
