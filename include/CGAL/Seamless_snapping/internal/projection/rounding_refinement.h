// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_ROUNDING_REFINEMENT_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_ROUNDING_REFINEMENT_H

// Minimal-change mode: a better choice of the free grid integers than independent rounding.
//
// With a target y that satisfies C y = b (the floating-point projection), rounding every free
// variable to its nearest grid point moves each implied variable by sum_i Ĉ_ji rho_i (rho_i the
// rounding errors), which grows with the length of the IRREF row. In grid units (Y = y / s, z the
// grid integers, unit pivots and b = 0: z_pi(j) = -sum_i Ĉ_ji z_i) we lower
//   E(z) = sum_free (z_i - Y_i)^2 + sum_j (z_pi(j) - Y_pi(j))^2
// by integer coordinate descent: for one free i at a time the best integer step t is the rounded
// minimizer of the quadratic in t; it is taken when E drops. Only the choice of grid points changes:
// the implied values are then evaluated exactly as always (Alg. 3, 5) and every row is checked.
// The implied errors r_j = z_pi(j) - Y_pi(j) are tracked as -sum_i Ĉ_ji (z_i - Y_i) - rho_j, where
// rho_j = Y_pi(j) + sum_i Ĉ_ji Y_i is the small residual of y in row j, summed accurately (fma and
// TwoSum), since its terms are up to 2^52 in grid units.

#include <CGAL/Seamless_snapping/internal/projection/fixed_point_grid.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_ops.h>
#include <CGAL/Seamless_snapping/internal/projection/irref.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// var: grid integers z with the free ones rounded, and the target y (var[i].xbar); changes the z of
// free variables only (and `out` with them).
template <typename Int>
void refine_free_rounding(const Irref<Int>& ir, const Fixed_point_grid& grid, Grid_variable* var,
                          std::vector<double>& out)
{
  typedef Integer_ops<Int> Ops;
  if(!(ir.homogeneous && ir.unit_pivots)) return;
  const std::size_t n = ir.n_cols, m = ir.rank();
  std::vector<double> Y(n);
  for(std::size_t i = 0; i < n; ++i) Y[i] = var[i].xbar / grid.quantum;         // exact: a power of 2
  // columns of Ĉ (free variables -> rows), and the implied errors r_j
  std::vector<std::size_t> cptr(n + 1, 0);
  for(std::uint32_t c : ir.col) ++cptr[c + 1];
  for(std::size_t i = 0; i < n; ++i) cptr[i + 1] += cptr[i];
  std::vector<std::uint32_t> crow(ir.col.size());
  std::vector<double> cval(ir.col.size());
  std::vector<double> r(m);
  {
    std::vector<std::size_t> pos(cptr.begin(), cptr.end() - 1);
    for(std::size_t j = 0; j < m; ++j) {
      double s = Y[ir.pivot_col[j]], err = 0, dev = 0;
      for(std::size_t q = ir.ptr[j]; q < ir.ptr[j + 1]; ++q) {
        const std::uint32_t c = ir.col[q];
        const double v = Ops::to_double(ir.val[q]);
        crow[pos[c]] = std::uint32_t(j); cval[pos[c]++] = v;
        const double p = v * Y[c], pe = std::fma(v, Y[c], -p);
        const double t = s + p, w = t - s;
        err += ((s - (t - w)) + (p - w)) + pe;
        s = t;
        dev -= v * (double(var[c].z) - Y[c]);
      }
      r[j] = dev - (s + err);
    }
  }
  const double z_max = double(Fixed_point_grid::max_integer());
  for(int pass = 0; pass < 8; ++pass) {
    std::size_t moves = 0;
    for(std::size_t i = 0; i < n; ++i) {
      if(ir.kind[i] != FREE_COLUMN || cptr[i] == cptr[i + 1]) continue;
      const double e = double(var[i].z) - Y[i];
      double g = e, h = 1;                                   // E(t) - E(0) = 2 g t + h t^2
      for(std::size_t q = cptr[i]; q < cptr[i + 1]; ++q) { g -= r[crow[q]] * cval[q]; h += cval[q] * cval[q]; }
      const double t = std::nearbyint(-g / h);
      if(t == 0 || !(2 * g * t + h * t * t < 0) || !(std::fabs(double(var[i].z) + t) <= z_max)) continue;
      var[i].z += std::int64_t(t);
      out[i] = grid.from_integer(var[i].z);
      for(std::size_t q = cptr[i]; q < cptr[i + 1]; ++q) r[crow[q]] -= cval[q] * t;
      ++moves;
    }
    if(moves == 0) break;
  }
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_ROUNDING_REFINEMENT_H
