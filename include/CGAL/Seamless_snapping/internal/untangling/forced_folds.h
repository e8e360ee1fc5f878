// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_FORCED_FOLDS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_FORCED_FOLDS_H

// Which non-positive UV triangles are non-positive in EVERY exact solution of the constraints, and why
// (proofs, exactly): no untangler can change them; only other constraint data (e.g. re-rounding the
// integer translations so that two cones do not land on one integer point) can.
//
// Let x be an exact solution and L a set of rows of the full system. Every solution of the full system
// solves L, and the solutions of L over the columns they mention are x + N w (N from the exact IRREF of
// L, region_space.h). A linear form l(x) is the same in every solution of L iff l is a rational
// combination of L's rows iff l N = 0; for l = x_i - x_j that is: the rows of N of x_i and x_j are equal
// (exactly, as rationals val / pivot). Its value is then l(x).
// For a face with corners p0, p1, p2 (counter-clockwise) let a, b, c, d be the components of p1 - p0
// and p2 - p0; twice its signed area is ad - bc. The face is non-positive in every solution when
// - two of its corners are one sector (one UV variable): it has zero area (ONE_SECTOR);
// - the two components of one of its edge vectors are fixed at 0: two corners are forced onto one UV
//   point, e.g. two cones rounded onto one integer point (COINCIDENT_CORNERS);
// - a, b, c, d are all fixed: the triangle is only translated, and its orientation is that in x (RIGID,
//   e.g. three cones on collinear or clockwise integer points);
// - each product ad and bc has a factor fixed at 0 (e.g. all corners on one integer isoline): zero
//   area (ZERO_AREA).
// L: the rows that mention a variable of a sector within `radius` face rings of the faces examined
// (every column of those rows stays free); a proof from L is a proof for the full system. A face is not
// claimed forced otherwise (the test is sound; with a larger L it could prove more).

#include <CGAL/Seamless_snapping/Snap_report.h>
#include <CGAL/Seamless_snapping/internal/projection/irref.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_system.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>
#include <CGAL/Seamless_snapping/internal/untangling/reference_shapes.h>
#include <CGAL/Seamless_snapping/internal/untangling/region_space.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpz.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// For every column of the local system (a homogeneous IRREF, irref.h): its row of N in lowest terms, flat. A free
// column c has the unit row {c: 1}; the implied column of pivot row r has {col[k]: -val[k] / pivot[r]} over the
// terms k of row r, stored as the integers -val[k] / g over the denominator pivot[r] / g (> 0), g the gcd of them all,
// sorted by column. Two rows are equal as vectors of rationals iff their stored forms are equal (the comparison
// of exact rational maps it replaced, without a rational per entry: the fold proofs of the 302K-face bunny of
// ../shared/large, 598 faces, 32 -> 18 ms, minimum of 5 runs, the same explanations there and on the shared maps).
template <typename Int>
struct Null_space_rows
{
  std::vector<std::size_t> start;      // per column c: its terms are [start[c], start[c + 1])
  std::vector<std::uint32_t> col;
  std::vector<Int> num;
  std::vector<Int> den;                // per column

  // Integer_overflow (int64) where a reduced entry does not fit
  explicit Null_space_rows(const Irref<Int>& irref)
  {
    typedef Integer_ops<Int> Ops;
    std::vector<std::size_t> row_of(irref.n_cols, irref.rank());
    for(std::size_t r = 0; r < irref.rank(); ++r) row_of[irref.pivot_col[r]] = r;
    std::vector<std::pair<std::uint32_t, Int> > terms;
    start.push_back(0);
    for(std::size_t c = 0; c < irref.n_cols; ++c) {
      if(irref.kind[c] != IMPLIED_COLUMN) {
        col.push_back(std::uint32_t(c)); num.push_back(Ops::from_int64(1)); den.push_back(Ops::from_int64(1));
        start.push_back(col.size());
        continue;
      }
      const std::size_t r = row_of[c];
      Int g = irref.pivot[r];
      terms.clear();
      for(std::size_t k = irref.ptr[r]; k < irref.ptr[r + 1]; ++k) {
        terms.emplace_back(irref.col[k], Ops::neg(irref.val[k]));
        g = Ops::gcd(g, irref.val[k]);
      }
      std::sort(terms.begin(), terms.end(),
                [](const std::pair<std::uint32_t, Int>& a, const std::pair<std::uint32_t, Int>& b) { return a.first < b.first; });
      for(const std::pair<std::uint32_t, Int>& t : terms) { col.push_back(t.first); num.push_back(Ops::exact_div(t.second, g)); }
      den.push_back(Ops::exact_div(irref.pivot[r], g));
      start.push_back(col.size());
    }
  }

  bool equal(std::size_t a, std::size_t b) const
  {
    const std::size_t n = start[a + 1] - start[a];
    if(!(den[a] == den[b]) || start[b + 1] - start[b] != n) return false;
    for(std::size_t i = 0; i < n; ++i)
      if(col[start[a] + i] != col[start[b] + i] || !(num[start[a] + i] == num[start[b] + i])) return false;
    return true;
  }
};

class Forced_fold_prover
{
public:
  Forced_fold_prover(const Corner_mesh& cm, const Seam_topology& st, const Constraint_rows& rows, const Face_corners& fc,
                     const Variable_rows& incidence)
    : cm_(cm), st_(st), rows_(rows), fc_(fc), incidence_(incidence) {}

  // the explanation of every face of `faces` (non-positive in the exact solution x); `forced()` tells
  // whether it is proven non-positive in every solution
  std::vector<Fold_explanation> explain(const std::vector<int>& faces, const std::vector<double>& x, int radius = 2)
  {
    std::vector<Fold_explanation> out;
    if(faces.empty()) return out;
    build_local_system(faces, radius);
    for(int f : faces) out.push_back(explain_face(f, x));
    return out;
  }

private:
  void build_local_system(const std::vector<int>& faces, int radius)
  {
    // sectors of the vertices within `radius` face rings of the faces
    std::vector<char> in(std::size_t(cm_.n_vertices), 0);
    std::vector<int> front;
    for(int f : faces)
      for(int h : fc_.halfedge[std::size_t(f)])
        if(!in[std::size_t(cm_.target[h])]) { in[std::size_t(cm_.target[h])] = 1; front.push_back(cm_.target[h]); }
    for(int r = 0; r < radius; ++r) {
      std::vector<int> next;
      for(int v : front)
        for(int f : fc_.vertex_faces[v])
          for(int h : fc_.halfedge[std::size_t(f)])
            if(!in[std::size_t(cm_.target[h])]) { in[std::size_t(cm_.target[h])] = 1; next.push_back(cm_.target[h]); }
      front.swap(next);
    }
    std::vector<int> local_rows;
    for(int h = 0; h < cm_.n_halfedges; ++h) {
      if(cm_.face[h] < 0 || !in[std::size_t(cm_.target[h])]) continue;
      for(int c = 0; c < 2; ++c) {
        const std::size_t v = 2 * std::size_t(st_.sector_of[h]) + std::size_t(c);
        for(std::size_t k = incidence_.start[v]; k < incidence_.start[v + 1]; ++k) local_rows.push_back(incidence_.row[k]);
      }
    }
    std::sort(local_rows.begin(), local_rows.end());
    local_rows.erase(std::unique(local_rows.begin(), local_rows.end()), local_rows.end());
    columns_.clear();
    for(int r : local_rows)
      for(std::size_t k = rows_.start[std::size_t(r)]; k < rows_.start[std::size_t(r) + 1]; ++k) columns_.push_back(rows_.col[k]);
    std::sort(columns_.begin(), columns_.end());
    columns_.erase(std::unique(columns_.begin(), columns_.end()), columns_.end());
    const std::vector<long> b(local_rows.size(), 0);
    Integer_system sys;
    std::string message;
    small_rows_.reset();
    big_rows_.reset();
    if(build_integer_system(local_rows.size(), columns_.size(), b, [&](auto add) {
         for(std::size_t i = 0; i < local_rows.size(); ++i) {
           const std::size_t r = std::size_t(local_rows[i]);
           for(std::size_t k = rows_.start[r]; k < rows_.start[r + 1]; ++k)
             add(i, column(rows_.col[k]), std::int64_t(rows_.coef[k]));
         }
       }, sys, message) != SUCCESS) { columns_.clear(); return; }
    try {
      Irref<std::int64_t> irref;
      if(compute_irref(sys, irref, message, PIVOT_RULE) == SUCCESS) small_rows_.reset(new Null_space_rows<std::int64_t>(irref));
    } catch(const Integer_overflow&) {
      small_rows_.reset();
      Irref<CGAL::Gmpz> irref;
      if(compute_irref(sys, irref, message, PIVOT_RULE) == SUCCESS) big_rows_.reset(new Null_space_rows<CGAL::Gmpz>(irref));
    }
    if(!small_rows_ && !big_rows_) columns_.clear();
  }

  std::size_t column(int var) const
  {
    return std::size_t(std::lower_bound(columns_.begin(), columns_.end(), var) - columns_.begin());
  }

  // true iff x_i - x_j is the same in every solution
  bool fixed_difference(int i, int j) const
  {
    if(i == j) return true;
    const std::size_t a = column(i), b = column(j);
    if(a >= columns_.size() || columns_[a] != i || b >= columns_.size() || columns_[b] != j) return false;   // a variable in no row moves freely
    return small_rows_ ? small_rows_->equal(a, b) : big_rows_->equal(a, b);
  }

  Fold_explanation explain_face(int f, const std::vector<double>& x) const
  {
    typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
    Fold_explanation e;
    e.face = std::size_t(f);
    const std::array<int, 3>& h = fc_.halfedge[std::size_t(f)];
    int s[3];
    for(int m = 0; m < 3; ++m) { s[m] = st_.sector_of[h[m]]; e.vertices.push_back(std::size_t(cm_.target[h[m]])); }
    auto point = [&](int m) { return P(x[2 * std::size_t(s[m])], x[2 * std::size_t(s[m]) + 1]); };
    const CGAL::Orientation o = CGAL::orientation(point(0), point(1), point(2));
    e.negative = o == CGAL::NEGATIVE;
    auto vname = [&](int m) {
      return "vertex " + std::to_string(cm_.target[h[m]]) + (st_.is_cone[std::size_t(cm_.target[h[m]])] ? " (a cone)" : "");
    };
    auto uv_name = [&](int m) {
      return "(" + format_double(cm_.to_uv(x[2 * std::size_t(s[m])]), 17) + ", " +
             format_double(cm_.to_uv(x[2 * std::size_t(s[m]) + 1]), 17) + ")";
    };
    for(int m = 0; m < 3; ++m) {
      const int n = (m + 1) % 3;
      if(s[m] == s[n]) {
        e.reason = FOLD_CORNERS_IN_ONE_SECTOR;
        e.message = "its corners at " + vname(m) + " and " + vname(n) + " are one sector (one UV variable): zero area in every map";
        return e;
      }
    }
    for(int m = 0; m < 3; ++m) {
      const int n = (m + 1) % 3;
      if(x[2 * std::size_t(s[m])] == x[2 * std::size_t(s[n])] && x[2 * std::size_t(s[m]) + 1] == x[2 * std::size_t(s[n]) + 1] &&
         fixed_difference(2 * s[m], 2 * s[n]) && fixed_difference(2 * s[m] + 1, 2 * s[n] + 1)) {
        e.reason = FOLD_COINCIDENT_CORNERS;
        e.message = "the constraints force its corners at " + vname(m) + " and " + vname(n) + " onto one UV point " +
                    uv_name(m) + " in every exact solution (a combination of constraint rows reads u_a - u_b = 0)";
        return e;
      }
    }
    // edge vectors p1 - p0 = (a, c), p2 - p0 = (b, d) in components; fixed[] and their values
    bool fixed[2][2];
    bool zero[2][2];
    for(int m = 1; m < 3; ++m)
      for(int c = 0; c < 2; ++c) {
        fixed[m - 1][c] = fixed_difference(2 * s[m] + c, 2 * s[0] + c);
        zero[m - 1][c] = fixed[m - 1][c] && x[2 * std::size_t(s[m]) + std::size_t(c)] == x[2 * std::size_t(s[0]) + std::size_t(c)];
      }
    if(fixed[0][0] && fixed[0][1] && fixed[1][0] && fixed[1][1]) {
      e.reason = FOLD_RIGID_TRIANGLE;
      e.message = "the constraints fix its shape (its corners at " + vname(0) + " " + uv_name(0) + ", " + vname(1) + " " +
                  uv_name(1) + ", " + vname(2) + " " + uv_name(2) + " move only together, by one translation): it is " +
                  (e.negative ? "negatively oriented" : "degenerate (collinear corners)") + " in every exact solution";
      return e;
    }
    // twice the area: (p1 - p0)_u (p2 - p0)_v - (p1 - p0)_v (p2 - p0)_u
    if((zero[0][0] || zero[1][1]) && (zero[0][1] || zero[1][0])) {
      e.reason = FOLD_ZERO_AREA_FORCED;
      e.message = "the constraints put its three corners (" + vname(0) + ", " + vname(1) + ", " + vname(2) +
                  ") on one isoline: zero area in every exact solution";
      return e;
    }
    e.reason = FOLD_NOT_PROVEN_FORCED;
    e.message = "not proven forced by the constraints; the untangling did not make it positive";
    return e;
  }

  const Corner_mesh& cm_;
  const Seam_topology& st_;
  const Constraint_rows& rows_;
  const Face_corners& fc_;
  const Variable_rows& incidence_;
  std::vector<int> columns_;                 // variables of the local system, increasing
  std::unique_ptr<Null_space_rows<std::int64_t> > small_rows_;   // per column, from the int64 IRREF, or
  std::unique_ptr<Null_space_rows<CGAL::Gmpz> > big_rows_;       // from the Gmpz one where int64 overflows
};

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_FORCED_FOLDS_H
