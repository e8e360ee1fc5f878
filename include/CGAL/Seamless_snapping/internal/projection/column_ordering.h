// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_COLUMN_ORDERING_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_COLUMN_ORDERING_H

// A fill-reducing order of the columns of [C | b] for the IRREF (Sec. 4.1): COLAMD (approximate
// minimum degree on the column intersection graph C^T C, SuiteSparse). When the IRREF takes, in
// every row, the column that comes first in this order as the pivot, the implied variables are
// those the order eliminates first and the free ones those it keeps for last (on per-corner seam
// systems: the node sectors), which keeps the rows of the IRREF short.
//
// COLAMD is used when the build defines CGAL_SEAMLESS_SNAPPING_HAS_COLAMD (the package's CMake does
// when SuiteSparse's colamd library is found; Debian: libsuitesparse-dev). Without it there is no
// order and the IRREF keeps its own pivot rule alone. The order depends only on the canonical
// system, so results stay deterministic; they may differ between builds with and without COLAMD
// (another exact solution: another set of free variables is rounded to the grid).

#include <CGAL/Seamless_snapping/internal/projection/integer_system.h>

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#ifdef CGAL_SEAMLESS_SNAPPING_HAS_COLAMD
#include <colamd.h>
#endif

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

constexpr bool has_fill_reducing_column_order()
{
#ifdef CGAL_SEAMLESS_SNAPPING_HAS_COLAMD
  return true;
#else
  return false;
#endif
}

// position[c] = place of column c in the order (columns in no row come last). Returns false, with
// `position` empty, when no order is available (no COLAMD, or it failed, e.g. out of memory).
template <typename Int>
bool fill_reducing_column_order(const Csr_rows<Int>& rows, std::size_t n_cols, std::vector<std::uint32_t>& position)
{
  position.clear();
#ifdef CGAL_SEAMLESS_SNAPPING_HAS_COLAMD
  typedef SuiteSparse_long Index;                          // 64-bit: no overflow of COLAMD's workspace size
  const std::size_t n_rows = rows.ptr.size() - 1, nnz = rows.e.size();
  // COLAMD reads the matrix by column (row indices of each column) and keeps its workspace in the
  // same array: compressed to the columns that occur in a row.
  std::vector<Index> compact(n_cols, -1), original;          // in column order: ties in COLAMD go by index
  for(const Sparse_entry<Int>& x : rows.e) compact[x.col] = 0;
  for(std::size_t c = 0; c < n_cols; ++c) if(compact[c] == 0) { compact[c] = Index(original.size()); original.push_back(Index(c)); }
  const Index nc = Index(original.size());
  std::vector<Index> p(std::size_t(nc) + 1, 0);
  for(const Sparse_entry<Int>& x : rows.e) ++p[std::size_t(compact[x.col]) + 1];
  for(Index c = 0; c < nc; ++c) p[std::size_t(c) + 1] += p[std::size_t(c)];
  try {
    std::vector<Index> A(colamd_l_recommended(Index(nnz), Index(n_rows), nc));
    if(A.size() < nnz) return false;
    {
      std::vector<Index> next(p.begin(), p.end() - 1);
      for(std::size_t i = 0; i < n_rows; ++i)
        for(std::size_t q = rows.ptr[i]; q < rows.ptr[i + 1]; ++q) A[std::size_t(next[std::size_t(compact[rows.e[q].col])]++)] = Index(i);
    }
    double knobs[COLAMD_KNOBS];
    Index stats[COLAMD_STATS];
    colamd_l_set_defaults(knobs);
    if(!colamd_l(Index(n_rows), nc, Index(A.size()), A.data(), p.data(), knobs, stats)) return false;
  } catch(const std::bad_alloc&) {
    return false;
  }
  position.assign(n_cols, std::uint32_t(nc));
  for(Index k = 0; k < nc; ++k) position[original[std::size_t(p[std::size_t(k)])]] = std::uint32_t(k);   // p: the order
  return true;
#else
  (void)rows; (void)n_cols;
  return false;
#endif
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_COLUMN_ORDERING_H
