// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_INTEGER_SYSTEM_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_INTEGER_SYSTEM_H

// The caller's integer system [C | b] in a canonical sparse form: rows in compressed storage,
// entries of a row sorted by column, duplicates summed, zeros (explicit or cancelled) removed, and
// every row (with its b entry) divided by the gcd of its entries (Sec. 4.1, Alg. 1: "o <- gcd").
// The canonical form is independent of how the caller stored zeros or ordered entries, which makes
// the whole projection deterministic. Entries are int64 when all fit, CGAL::Gmpz otherwise.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/integer_ops.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// Rows in compressed sparse row storage.
template <typename Int>
struct Csr_rows
{
  std::vector<std::size_t> ptr;        // row i is [ptr[i], ptr[i+1])
  std::vector<std::uint32_t> col;
  std::vector<Int> val;
  std::vector<Int> b;
  void clear() { ptr.clear(); col.clear(); val.clear(); b.clear(); }
};

struct Integer_system
{
  std::size_t n_rows = 0, n_cols = 0;
  bool fits_int64 = true;              // which of the two stores is filled
  Csr_rows<std::int64_t> rows64;
  Csr_rows<CGAL::Gmpz> rowsz;
  std::vector<char> column_used;       // column has a nonzero entry
  std::size_t n_constrained_columns = 0;

  std::size_t nonzeros() const { return fits_int64 ? rows64.col.size() : rowsz.col.size(); }
  std::size_t constrained_columns() const { return n_constrained_columns; }
};

template <typename Int> const Csr_rows<Int>& rows_of(const Integer_system& s);
template <> inline const Csr_rows<std::int64_t>& rows_of<std::int64_t>(const Integer_system& s) { return s.rows64; }
template <> inline const Csr_rows<CGAL::Gmpz>& rows_of<CGAL::Gmpz>(const Integer_system& s) { return s.rowsz; }

// Converts a caller's integer into Int; false when it does not fit.
inline bool convert_integer(const CGAL::Gmpz& v, std::int64_t& out) { return to_int64(v, out); }
template <typename T> bool convert_integer(const T& v, std::int64_t& out) { return to_int64(v, out); }
template <typename T> bool convert_integer(const T& v, CGAL::Gmpz& out) { out = to_gmpz(v); return true; }

struct Too_large {};   // a value does not fit int64: rebuild in Gmpz

// Builds the canonical rows in Int. Throws Too_large (int64 only) when a value or a sum of
// duplicates does not fit.
template <typename Int, typename BRange, typename Visit>
Status build_rows(std::size_t n_rows, std::size_t n_cols, const BRange& b, Visit& visit,
                  Csr_rows<Int>& out, std::string& message)
{
  typedef Integer_ops<Int> Ops;
  struct Raw { std::uint32_t r, c; };
  std::vector<Raw> raw;
  std::vector<Int> raw_val;
  bool bad_index = false;
  std::size_t bad_r = 0, bad_c = 0;
  visit([&](std::size_t r, std::size_t c, const auto& v) {
    if(r >= n_rows || c >= n_cols) { if(!bad_index) { bad_index = true; bad_r = r; bad_c = c; } return; }
    Int iv;
    if(!convert_integer(v, iv)) throw Too_large();
    if(Ops::is_zero(iv)) return;                         // explicit zeros are not entries
    raw.push_back(Raw{std::uint32_t(r), std::uint32_t(c)});
    raw_val.push_back(iv);
  });
  if(bad_index) {
    message = "entry (" + std::to_string(bad_r) + ", " + std::to_string(bad_c) + ") is outside the "
            + std::to_string(n_rows) + " x " + std::to_string(n_cols) + " matrix";
    return INVALID_INPUT;
  }
  // Counting sort by row (linear time), then each row by column.
  out.clear();
  out.ptr.assign(n_rows + 1, 0);
  for(const Raw& e : raw) ++out.ptr[e.r + 1];
  for(std::size_t i = 0; i < n_rows; ++i) out.ptr[i + 1] += out.ptr[i];
  std::vector<std::size_t> pos(out.ptr.begin(), out.ptr.end() - 1);
  std::vector<std::pair<std::uint32_t, Int> > sorted(raw.size());
  for(std::size_t k = 0; k < raw.size(); ++k) sorted[pos[raw[k].r]++] = std::make_pair(raw[k].c, raw_val[k]);
  raw.clear(); raw.shrink_to_fit(); raw_val.clear(); raw_val.shrink_to_fit();

  out.col.reserve(sorted.size());
  out.val.reserve(sorted.size());
  out.b.resize(n_rows);
  std::vector<std::size_t> new_ptr(n_rows + 1, 0);
  for(std::size_t i = 0; i < n_rows; ++i) {
    auto first = sorted.begin() + std::ptrdiff_t(out.ptr[i]), last = sorted.begin() + std::ptrdiff_t(out.ptr[i + 1]);
    std::stable_sort(first, last, [](const std::pair<std::uint32_t, Int>& a, const std::pair<std::uint32_t, Int>& b)
                                  { return a.first < b.first; });
    const std::size_t row_begin = out.col.size();
    for(auto it = first; it != last; ) {             // sum duplicates
      std::uint32_t c = it->first; Int v = it->second;
      for(++it; it != last && it->first == c; ++it) v = Ops::add(v, it->second);
      if(!Ops::is_zero(v)) { out.col.push_back(c); out.val.push_back(v); }
    }
    Int bi;
    if(!convert_integer(b[i], bi)) throw Too_large();
    // divide the row and its b entry by their gcd
    Int g = bi < 0 ? Ops::neg(bi) : bi;
    for(std::size_t k = row_begin; k < out.col.size() && !Ops::is_unit(g); ++k) g = Ops::gcd(g, out.val[k]);
    if(!Ops::is_zero(g) && !Ops::is_unit(g)) {
      for(std::size_t k = row_begin; k < out.col.size(); ++k) out.val[k] = Ops::exact_div(out.val[k], g);
      bi = Ops::exact_div(bi, g);
    }
    out.b[i] = bi;
    new_ptr[i + 1] = out.col.size();
  }
  out.ptr.swap(new_ptr);
  return SUCCESS;
}

// Fills `sys` from the caller's entries (visit(add) calls add(row, col, value) for every entry).
template <typename BRange, typename Visit>
Status build_integer_system(std::size_t n_rows, std::size_t n_cols, const BRange& b, Visit visit,
                            Integer_system& sys, std::string& message)
{
  sys = Integer_system();
  sys.n_rows = n_rows; sys.n_cols = n_cols;
  if(std::size_t(b.size()) != n_rows) {
    message = "b has " + std::to_string(std::size_t(b.size())) + " entries, C has " + std::to_string(n_rows) + " rows";
    return INVALID_INPUT;
  }
  if(n_cols >= std::size_t(std::numeric_limits<std::uint32_t>::max()) ||
     n_rows >= std::size_t(std::numeric_limits<std::uint32_t>::max())) {
    message = "systems with 2^32 or more rows or columns are not supported";
    return INVALID_INPUT;
  }
  Status st;
  try {
    st = build_rows<std::int64_t>(n_rows, n_cols, b, visit, sys.rows64, message);
    sys.fits_int64 = true;
  } catch(const Too_large&) {
    sys.rows64.clear();
    sys.fits_int64 = false;
    st = build_rows<CGAL::Gmpz>(n_rows, n_cols, b, visit, sys.rowsz, message);
  } catch(const Integer_overflow&) {
    sys.rows64.clear();
    sys.fits_int64 = false;
    st = build_rows<CGAL::Gmpz>(n_rows, n_cols, b, visit, sys.rowsz, message);
  }
  if(st != SUCCESS) return st;
  sys.column_used.assign(n_cols, 0);
  const std::vector<std::uint32_t>& cols = sys.fits_int64 ? sys.rows64.col : sys.rowsz.col;
  for(std::uint32_t c : cols) sys.column_used[c] = 1;
  sys.n_constrained_columns = std::size_t(std::count(sys.column_used.begin(), sys.column_used.end(), char(1)));
  return SUCCESS;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_INTEGER_SYSTEM_H
