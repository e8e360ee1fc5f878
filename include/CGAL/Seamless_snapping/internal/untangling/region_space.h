// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_REGION_SPACE_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_REGION_SPACE_H

// The maps that satisfy the same constraints as a given exact solution x0 and agree with it outside a
// region of sector variables: x = x0 + N w, where the columns of N span the null space of the rows of
// the full system (Eq. 4, 5, 6-8, integer-grid rows, pinned corners) restricted to the region's
// variables, every other variable held at its value in x0. The restricted rows are homogeneous in the
// displacement, so their right-hand sides do not matter.
//
// N comes from the exact integer reduced row echelon form of those rows (irref.h, the core's IRREF,
// Sec. 4.1): a free column j gives the basis vector with 1 at j and -val / pivot at the pivot column of
// every row that holds j; an unconstrained column is free too. N is exact up to the rounding of
// val / pivot to double, so a displacement N w keeps every row up to rounding of the order of the
// double precision; the exact snap afterwards (Sec. 4) makes them hold exactly again.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/projection/irref.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_system.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>

#include <CGAL/Gmpz.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// For every variable the rows of `rows` that mention it (the transpose of its pattern).
struct Variable_rows
{
  std::vector<std::size_t> start;   // per variable: [start[v], start[v + 1]) in `row`
  std::vector<int> row;

  Variable_rows(const Constraint_rows& rows, std::size_t n_vars) : start(n_vars + 1, 0)
  {
    for(int c : rows.col) ++start[std::size_t(c) + 1];
    for(std::size_t v = 0; v < n_vars; ++v) start[v + 1] += start[v];
    row.resize(rows.col.size());
    std::vector<std::size_t> pos(start.begin(), start.end() - 1);
    for(std::size_t i = 0; i < rows.size(); ++i)
      for(std::size_t k = rows.start[i]; k < rows.start[i + 1]; ++k) row[pos[std::size_t(rows.col[k])]++] = int(i);
  }
};

struct Region_space
{
  std::vector<int> vars;                 // the region's variables (2s + c), increasing
  std::size_t dimension = 0;             // of w
  // the displacement of vars[l] is sum of coef[k] w[w_index[k]], k in [ptr[l], ptr[l + 1])
  std::vector<std::size_t> ptr;
  std::vector<int> w_index;
  std::vector<double> coef;
};

template <typename Int>
void region_basis_from_irref(const Irref<Int>& irref, Region_space& out)
{
  typedef Integer_ops<Int> Ops;
  const std::size_t n = out.vars.size();
  std::vector<int> w_of(n, -1);
  out.dimension = 0;
  for(std::size_t c = 0; c < n; ++c)
    if(irref.kind[c] != IMPLIED_COLUMN) w_of[c] = int(out.dimension++);
  std::vector<std::vector<std::pair<int, double> > > entries(n);
  for(std::size_t c = 0; c < n; ++c)
    if(w_of[c] >= 0) entries[c].emplace_back(w_of[c], 1.);
  for(std::size_t r = 0; r < irref.rank(); ++r) {
    const double p = Ops::to_double(irref.pivot[r]);
    std::vector<std::pair<int, double> >& e = entries[irref.pivot_col[r]];
    for(std::size_t k = irref.ptr[r]; k < irref.ptr[r + 1]; ++k)
      e.emplace_back(w_of[irref.col[k]], -Ops::to_double(irref.val[k]) / p);
  }
  out.ptr.assign(1, 0);
  out.w_index.clear();
  out.coef.clear();
  for(std::size_t c = 0; c < n; ++c) {
    for(const auto& e : entries[c]) { out.w_index.push_back(e.first); out.coef.push_back(e.second); }
    out.ptr.push_back(out.w_index.size());
  }
}

// The space of the variables `vars` (increasing) with the rows of `rows` that mention one of them. `order`: how the
// IRREF takes its pivots (irref.h), which decides the basis N: the same space, but not as sparse with one as with another.
inline Status build_region_space(const Constraint_rows& rows, const Variable_rows& incidence, const std::vector<int>& vars,
                                 Pivot_order order, Region_space& out, std::string& message)
{
  out = Region_space();
  out.vars = vars;
  std::vector<int> local_rows;
  for(int v : vars)
    for(std::size_t k = incidence.start[std::size_t(v)]; k < incidence.start[std::size_t(v) + 1]; ++k)
      local_rows.push_back(incidence.row[k]);
  std::sort(local_rows.begin(), local_rows.end());
  local_rows.erase(std::unique(local_rows.begin(), local_rows.end()), local_rows.end());
  auto local = [&](int var) -> long {
    auto it = std::lower_bound(vars.begin(), vars.end(), var);
    return it != vars.end() && *it == var ? long(it - vars.begin()) : -1;
  };
  const std::vector<long> b(local_rows.size(), 0);
  Integer_system sys;
  Status s = build_integer_system(local_rows.size(), vars.size(), b, [&](auto add) {
    for(std::size_t i = 0; i < local_rows.size(); ++i) {
      const std::size_t r = std::size_t(local_rows[i]);
      for(std::size_t k = rows.start[r]; k < rows.start[r + 1]; ++k) {
        const long l = local(rows.col[k]);
        if(l >= 0) add(i, std::size_t(l), std::int64_t(rows.coef[k]));
      }
    }
  }, sys, message);
  if(s != SUCCESS) return s;
  try {
    Irref<std::int64_t> irref;
    s = compute_irref(sys, irref, message, order);
    if(s == SUCCESS) region_basis_from_irref(irref, out);
  } catch(const Integer_overflow&) {
    Irref<CGAL::Gmpz> irref;
    s = compute_irref(sys, irref, message, order);
    if(s == SUCCESS) region_basis_from_irref(irref, out);
  }
  return s;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_REGION_SPACE_H
