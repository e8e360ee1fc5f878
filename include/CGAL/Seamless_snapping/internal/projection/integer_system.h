// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_INTEGER_SYSTEM_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_INTEGER_SYSTEM_H

// The caller's integer system [C | b] in a canonical sparse form: rows in compressed storage,
// entries of a row sorted by column, duplicates summed, zeros (explicit or cancelled) removed, and
// every row (with its b entry) divided by the gcd of its entries (Sec. 4.1, Alg. 1: "o <- gcd").
// The canonical form is independent of how the caller stored zeros or ordered entries, which makes
// the whole projection deterministic. Entries are int64 when all fit, CGAL::Gmpz otherwise.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/projection/default_init_allocator.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_ops.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// Look-ahead, in entries, of the loops that stream over rows whose columns are random: they
// prefetch what the entry this far ahead will touch (the elimination, evaluation and final check).
constexpr std::size_t prefetch_distance = 32;

// One nonzero of a sparse integer row.
template <typename Int>
struct Sparse_entry
{
  std::uint32_t col;
  Int val;
};

// Rows in compressed sparse row storage (entries of row i: e[ptr[i]] .. e[ptr[i+1]-1]); sized, then
// written in full (not zeroed first: Default_init_vector).
template <typename Int>
struct Csr_rows
{
  Default_init_vector<std::size_t> ptr;
  Default_init_vector<Sparse_entry<Int> > e;
  Default_init_vector<Int> b;
  void clear() { ptr.clear(); e.clear(); b.clear(); }
};

struct Integer_system
{
  std::size_t n_rows = 0, n_cols = 0;
  bool fits_int64 = true;              // which of the two stores is filled
  Csr_rows<std::int64_t> rows64;
  Csr_rows<CGAL::Gmpz> rowsz;
  std::vector<std::uint8_t> column_rows;    // per column: the number of rows it has a nonzero entry in, 3 for 3 or more
  std::size_t n_constrained_columns = 0;    // columns in at least one row
  std::size_t n_columns_in_two_rows = 0;    // columns in exactly two rows (see Irref_eliminator::run())

  std::size_t nonzeros() const { return fits_int64 ? rows64.e.size() : rowsz.e.size(); }
  std::size_t constrained_columns() const { return n_constrained_columns; }
  bool column_used(std::size_t c) const { return column_rows[c] != 0; }
};

// Converts a caller's integer into Int; false when it does not fit.
inline bool convert_integer(const CGAL::Gmpz& v, std::int64_t& out) { return to_int64(v, out); }
template <typename T> bool convert_integer(const T& v, std::int64_t& out) { return to_int64(v, out); }
template <typename T> bool convert_integer(const T& v, CGAL::Gmpz& out) { out = to_gmpz(v); return true; }

// Builds the canonical rows in Int, visiting the caller's entries twice (count, then place: a
// counting sort by row in linear time, without an intermediate copy). Throws Integer_overflow (int64
// only) when a value or a sum of duplicates does not fit.
template <typename Int, typename BRange, typename Visit>
Status build_rows(std::size_t n_rows, std::size_t n_cols, const BRange& b, Visit& visit,
                  Csr_rows<Int>& out, std::string& message)
{
  typedef Integer_ops<Int> Ops;
  typedef Sparse_entry<Int> Entry;
  out.clear();
  out.ptr.assign(n_rows + 1, 0);
  bool bad_index = false;
  std::size_t bad_r = 0, bad_c = 0;
  // Entries come by row, then by strictly increasing column, when their keys (r, c) -> r 2^32 + c + 1
  // increase strictly (the caller's sizes are below 2^32, see build_integer_system()).
  bool ordered = true;
  std::uint64_t last_key = 0;
  visit([&](std::size_t r, std::size_t c, const auto& v) {      // pass 1: count
    if(r >= n_rows || c >= n_cols) { if(!bad_index) { bad_index = true; bad_r = r; bad_c = c; } return; }
    Int iv;
    if(!convert_integer(v, iv)) throw Integer_overflow();
    if(Ops::is_zero(iv)) return;                                  // explicit zeros are not entries
    ++out.ptr[r + 1];
    const std::uint64_t key = (std::uint64_t(r) << 32) + c + 1;
    ordered = ordered & (key > last_key);
    last_key = key;
  });
  if(bad_index) {
    message = "entry (" + std::to_string(std::int64_t(bad_r)) + ", " + std::to_string(std::int64_t(bad_c)) + ") is outside the "
            + std::to_string(n_rows) + " x " + std::to_string(n_cols) + " matrix";   // negative indices print as such
    return INVALID_INPUT;
  }
  for(std::size_t i = 0; i < n_rows; ++i) out.ptr[i + 1] += out.ptr[i];
  out.e.resize(out.ptr[n_rows]);
  {
    std::vector<std::size_t> pos(out.ptr.begin(), out.ptr.end() - 1);
    visit([&](std::size_t r, std::size_t c, const auto& v) {    // pass 2: place
      Int iv;
      convert_integer(v, iv);
      if(!Ops::is_zero(iv)) out.e[pos[r]++] = Entry{std::uint32_t(c), iv};
    });
  }
  // Sort each row by column, sum duplicates, drop zeros (unless the input came canonical: ordered by
  // row and strictly by column, so no duplicates), divide by the gcd of the row and b_i.
  out.b.resize(n_rows);
  std::size_t w = 0;
  for(std::size_t i = 0; i < n_rows; ++i) {
    const std::size_t first = out.ptr[i], last = out.ptr[i + 1];
    for(std::size_t q = first + 1; q < last && !ordered; ++q) {   // insertion sort: rows are short
      Entry x = out.e[q];
      std::size_t t = q;
      for(; t > first && out.e[t - 1].col > x.col; --t) out.e[t] = out.e[t - 1];
      out.e[t] = x;
    }
    const std::size_t row_begin = w;
    if(ordered) w = last;                                         // already canonical: nothing to merge (w == first here)
    else for(std::size_t q = first; q < last; ) {
      const std::uint32_t c = out.e[q].col;
      Int v = out.e[q].val;
      for(++q; q < last && out.e[q].col == c; ++q) v = Ops::add(v, out.e[q].val);
      if(!Ops::is_zero(v)) out.e[w++] = Entry{c, v};
    }
    Int bi;
    if(!convert_integer(b[i], bi)) throw Integer_overflow();
    Int g = Ops::abs(bi);
    for(std::size_t k = row_begin; k < w && !Ops::is_unit(g); ++k) g = Ops::gcd(g, out.e[k].val);
    if(!Ops::is_zero(g) && !Ops::is_unit(g)) {
      for(std::size_t k = row_begin; k < w; ++k) out.e[k].val = Ops::exact_div(out.e[k].val, g);
      bi = Ops::exact_div(bi, g);
    }
    out.b[i] = bi;
    out.ptr[i] = row_begin;
  }
  out.ptr[n_rows] = w;
  out.e.resize(w);
  // out.ptr[i] was overwritten with the new start of row i before row i+1 was read: rows only shrink.
  return SUCCESS;
}

// Integer_system::column_rows and the counts derived from it (canonical rows: the entries of a row
// have distinct columns). Only 0, 1, 2 and "more" are told apart, so a byte per column counts, up to 3:
// on shuffled rows the counts are random accesses, and bytes keep them in a quarter of the cache
// that 32-bit counts take (1M-row shuffled seamless system: 12.8 -> 7.6 ms; along chains 3.5 -> 3.8 ms).
inline void count_column_rows(Integer_system& sys)
{
  std::vector<std::uint8_t>& rows = sys.column_rows;
  rows.assign(sys.n_cols, 0);
  auto count = [&](std::uint32_t c) { const std::uint8_t r = rows[c]; rows[c] = std::uint8_t(r + (r < 3)); };
  if(sys.fits_int64) { for(const auto& x : sys.rows64.e) count(x.col); }
  else               { for(const auto& x : sys.rowsz.e)  count(x.col); }
  sys.n_constrained_columns = sys.n_columns_in_two_rows = 0;
  for(const std::uint8_t r : rows) {              // no branch: which columns occur follows no pattern
    sys.n_constrained_columns += std::size_t(r != 0);
    sys.n_columns_in_two_rows += std::size_t(r == 2);
  }
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
  } catch(const Integer_overflow&) {            // a value or a sum of duplicates does not fit int64
    sys.rows64.clear();
    sys.fits_int64 = false;
    st = build_rows<CGAL::Gmpz>(n_rows, n_cols, b, visit, sys.rowsz, message);
  }
  if(st != SUCCESS) return st;
  count_column_rows(sys);
  return SUCCESS;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_INTEGER_SYSTEM_H
