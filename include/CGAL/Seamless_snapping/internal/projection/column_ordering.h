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

// A fill-reducing order of the columns of [C | b] for the IRREF (Sec. 4.1). The IRREF takes, in
// every row, the column that comes first in the order as the pivot: the implied variables are
// those the order puts first, the free ones those it keeps for last. The IRREF depends only on
// which columns end up free: a free column's IRREF column is the circuit (smallest dependent set)
// that ties it to implied columns before it in the order, so a good order makes these short.
// Three orders, chosen by the shape of the row graph (rows adjacent when they share a column),
// measured by the widest level of a breadth-first search against the number of levels:
//  - wide fronts (more than 2 rows per level: closed surface-like row graphs, e.g. per-corner
//    systems, one vt per face corner, where every edge is cut and the rows form the medial graph of
//    the mesh): the front order (front_column_order()). A column then becomes free where the front
//    closes a short cycle (a face, a vertex ring), which keeps its circuit local; COLAMD (approximate
//    minimum degree on C^T C), which takes low-degree columns all over the mesh first, leaves
//    longer ones (measured: duck_miq_8 1.35M instead of 1.97M IRREF nonzeros, fandisk 1.29M
//    instead of 1.69M);
//  - thin fronts (at most 1 row per level: the seams of cut meshes, chains of cut edges): the
//    static minimum degree order (static_degree_column_order(): columns by the number of other
//    columns they share a row with), whose circuits are there the shortest of the three and which
//    costs a fraction of COLAMD (IRREF nonzeros static / COLAMD / front: dragon-full 23.5k / 25.0k
//    / 86.9k, dragon-rot 26.57k / 26.56k, horsers 2.7k / 3.3k / 5.0k, decimated-knight 2.3k / 2.5k
//    / 5.7k, retinal 1.5k / 2.5k; dragon-full initialize 7.8 -> 4.9 ms);
//  - in between (a flat disc seen from its boundary, as test_projection's per-corner grid): COLAMD
//    (there 39.8k IRREF nonzeros; the front order 69.2k, the static degree order 104.6k: on a
//    two-dimensional graph the degrees do not change where the elimination goes, COLAMD's do).
// COLAMD is used when the build defines CGAL_SEAMLESS_SNAPPING_HAS_COLAMD (the package's CMake does
// when SuiteSparse's colamd library is found; Debian: libsuitesparse-dev). Without it there is no
// order (none of the three) and the IRREF keeps its own pivot rule alone. The order depends only
// on the canonical system, so results stay deterministic; they may differ between builds with and
// without COLAMD (another exact solution: another set of free variables is rounded to the grid).

#include <CGAL/Seamless_snapping/internal/projection/integer_system.h>

#include <algorithm>
#include <cmath>
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

// The pattern of C by columns: the rows of column k in row[start[k] .. start[k + 1]), increasing.
// Precondition (here and in the orders below): the columns are numbered 0..nc-1 and each occurs in
// a row (the IRREF's input is so numbered, see Irref_eliminator::number_columns()).
struct Column_rows
{
  std::vector<std::size_t> start;
  std::vector<std::uint32_t> row;

  template <typename Int>
  Column_rows(const Csr_rows<Int>& rows, std::size_t nc) : start(nc + 1, 0), row(rows.e.size())
  {
    for(const Sparse_entry<Int>& x : rows.e) ++start[std::size_t(x.col) + 1];
    for(std::size_t k = 0; k < nc; ++k) start[k + 1] += start[k];
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for(std::size_t i = 0; i + 1 < rows.ptr.size(); ++i)
      for(std::size_t q = rows.ptr[i]; q < rows.ptr[i + 1]; ++q) row[next[rows.e[q].col]++] = std::uint32_t(i);
  }
  std::size_t columns() const { return start.size() - 1; }
};

// The front order: breadth-first over the rows (two rows adjacent when they share a column), a
// row's columns numbered in index order when first met. Each connected component is searched from
// a central row, so that the front stays short: the row closest to both ends of a pseudo-diameter
// (a row farthest from the component's first row, and a row farthest from that one). On the
// per-corner systems that is 6% fewer IRREF nonzeros than from the first row (duck_miq_8 1.35M
// instead of 1.44M, fandisk 1.29M instead of 1.36M); from a peripheral row, 4-9% more.
// The shape: seen from the first end of the pseudo-diameter, the widest level of the largest
// component against its number of levels (per-corner systems: duck_miq_8 692 rows in 151 levels,
// fandisk 513 in 162; seams of cut meshes: decimated-knight 20 in 39, dragon 52 in 242, horsers
// 12 in 89; test_projection's flat per-corner grid, a disc without rotations: 92 in 48). Only for
// a WIDE_FRONT is the order computed; otherwise `position` is left untouched. A component with
// more than half of the rows is the largest one: when its front is not wide the search stops there,
// after two of its four searches (dragon: 1.1 -> 0.6 ms). The bounds are no clean divide: the front
// order's gain is measured on closed surfaces with cones only, the static degree order's on seams.
enum Front_shape { THIN_FRONT, MEDIUM_FRONT, WIDE_FRONT };

inline Front_shape front_shape(std::size_t width, std::size_t levels)
{
  return width > 2 * levels ? WIDE_FRONT : (width <= levels ? THIN_FRONT : MEDIUM_FRONT);
}

template <typename Int>
Front_shape front_column_order(const Csr_rows<Int>& rows, const Column_rows& cols, std::vector<std::uint32_t>& position)
{
  const std::size_t n_rows = rows.ptr.size() - 1;
  const std::uint32_t unseen = std::uint32_t(-1);
  std::vector<std::uint32_t> queue, from_a(n_rows, unseen), from_b(n_rows, unseen);
  std::vector<std::uint32_t> scanned(cols.columns(), 0);   // the last search that went through a column
  std::uint32_t searches = 0;
  queue.reserve(n_rows);
  // Breadth-first from `start` (dist: unseen on its component): distances in dist, the rows
  // reached in `queue` in order; returns the last one, a farthest row. forget() resets them.
  // A column's rows are all reached from the first row that meets it, so it is gone through
  // once per search (same levels and queue; dragon full-seamless: 4% of initialize less).
  auto search = [&](std::uint32_t start, std::vector<std::uint32_t>& dist) {
    ++searches;
    queue.clear();
    dist[start] = 0;
    queue.push_back(start);
    for(std::size_t head = 0; head < queue.size(); ++head) {
      const std::uint32_t i = queue[head];
      for(std::size_t q = rows.ptr[i]; q < rows.ptr[i + 1]; ++q) {
        const std::size_t k = rows.e[q].col;
        if(scanned[k] == searches) continue;
        scanned[k] = searches;
        for(std::size_t t = cols.start[k]; t < cols.start[k + 1]; ++t) {
          const std::uint32_t r = cols.row[t];
          if(dist[r] == unseen) { dist[r] = dist[i] + 1; queue.push_back(r); }
        }
      }
    }
    return queue.back();
  };
  auto forget = [&](std::vector<std::uint32_t>& dist) { for(const std::uint32_t i : queue) dist[i] = unseen; };
  std::vector<std::uint32_t> order(cols.columns(), unseen), count;
  std::uint32_t numbered = 0;
  std::size_t largest = 0, levels = 0, width = 0;
  for(std::size_t first = 0; first < n_rows; ++first) {
    if(from_b[first] != unseen) continue;                  // in a component already numbered
    const std::uint32_t a = search(std::uint32_t(first), from_a);
    forget(from_a);
    const std::uint32_t b = search(a, from_a);
    if(queue.size() > largest) {                           // the shape, seen from a
      largest = queue.size();
      levels = std::size_t(from_a[b]) + 1;
      count.assign(levels, 0);
      for(const std::uint32_t i : queue) ++count[from_a[i]];
      width = *std::max_element(count.begin(), count.end());
      if(2 * largest > n_rows && front_shape(width, levels) != WIDE_FRONT) return front_shape(width, levels);   // the largest: decided
    }
    search(b, from_b);
    std::uint32_t center = queue[0], eccentricity = unseen;
    for(const std::uint32_t i : queue) {
      const std::uint32_t e = std::max(from_a[i], from_b[i]);
      if(e < eccentricity || (e == eccentricity && i < center)) { eccentricity = e; center = i; }
    }
    forget(from_a);
    search(center, from_a);
    for(const std::uint32_t i : queue)
      for(std::size_t q = rows.ptr[i]; q < rows.ptr[i + 1]; ++q)
        if(order[rows.e[q].col] == unseen) order[rows.e[q].col] = numbered++;
  }
  if(front_shape(width, levels) != WIDE_FRONT) return front_shape(width, levels);
  position.swap(order);                                    // every column occurs in a row: all are numbered
  return WIDE_FRONT;
}

// The static minimum degree order: columns by their degree in the column graph of C (the number of
// columns, itself included, that share a row with it), ties by index; the degrees are those of the
// input, not updated as the elimination goes (that is what COLAMD approximates). Dense rows (more
// than 10 sqrt(nc) entries, COLAMD's default) are left out of the degrees, as COLAMD leaves them
// out of its order: the cost is then at most 10 sqrt(nc) per nonzero, not the square of a row.
template <typename Int>
void static_degree_column_order(const Csr_rows<Int>& rows, const Column_rows& cols, std::vector<std::uint32_t>& position)
{
  const std::size_t nc = cols.columns();
  const std::size_t dense = std::max<std::size_t>(16, std::size_t(10 * std::sqrt(double(nc))));
  std::vector<std::size_t> mark(nc, std::size_t(-1)), degree(nc, 0);
  for(std::size_t k = 0; k < nc; ++k)
    for(std::size_t t = cols.start[k]; t < cols.start[k + 1]; ++t) {
      const std::size_t r = cols.row[t];
      if(rows.ptr[r + 1] - rows.ptr[r] > dense) continue;
      for(std::size_t q = rows.ptr[r]; q < rows.ptr[r + 1]; ++q) {
        const std::size_t j = rows.e[q].col;
        if(mark[j] != k) { mark[j] = k; ++degree[k]; }
      }
    }
  std::vector<std::size_t> first;                          // counting sort by degree: stable, so ties go by index
  for(std::size_t k = 0; k < nc; ++k) {
    if(std::size_t(degree[k]) + 2 > first.size()) first.resize(std::size_t(degree[k]) + 2, 0);
    ++first[std::size_t(degree[k]) + 1];
  }
  for(std::size_t d = 0; d + 1 < first.size(); ++d) first[d + 1] += first[d];
  position.resize(nc);
  for(std::size_t k = 0; k < nc; ++k) position[k] = std::uint32_t(first[degree[k]]++);
}

// position[c] = place of column c in the order, for the nc columns of `rows` (each occurs in a row,
// see Column_rows); `front`: whether it is the front order. Returns false, with `position` empty, when no order is available (no COLAMD,
// or it failed, e.g. out of memory).
template <typename Int>
bool fill_reducing_column_order(const Csr_rows<Int>& rows, std::size_t nc, std::vector<std::uint32_t>& position, bool& front)
{
  position.clear();
  front = false;
#ifdef CGAL_SEAMLESS_SNAPPING_HAS_COLAMD
  typedef SuiteSparse_long Index;                          // 64-bit: no overflow of COLAMD's workspace size
  const std::size_t n_rows = rows.ptr.size() - 1, nnz = rows.e.size();
  try {
    const Column_rows cols(rows, nc);
    const Front_shape shape = front_column_order(rows, cols, position);
    if(shape == WIDE_FRONT) { front = true; return true; }
    if(shape == THIN_FRONT) { static_degree_column_order(rows, cols, position); return true; }
    // COLAMD reads the matrix by column and keeps its workspace in the same array (A), and writes
    // the order into p: both are copies.
    std::vector<Index> p(cols.start.begin(), cols.start.end()), A(colamd_l_recommended(Index(nnz), Index(n_rows), Index(nc)));
    if(A.size() < nnz) return false;
    std::copy(cols.row.begin(), cols.row.end(), A.begin());
    double knobs[COLAMD_KNOBS];
    Index stats[COLAMD_STATS];
    colamd_l_set_defaults(knobs);
    if(!colamd_l(Index(n_rows), Index(nc), Index(A.size()), A.data(), p.data(), knobs, stats)) return false;
    position.resize(nc);
    for(std::size_t k = 0; k < nc; ++k) position[std::size_t(p[k])] = std::uint32_t(k);   // p: the order
  } catch(const std::bad_alloc&) {
    position.clear();
    return false;
  }
  return true;
#else
  (void)rows; (void)nc;
  return false;
#endif
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_COLUMN_ORDERING_H
