// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_PROPAGATION_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_PROPAGATION_H

// Steps 2 and 3 of Sec. 5.3.1: values of the non-node sectors along the branches, once the node
// sectors are exact and on the grid F_delta.
//
// Cut branch, row t < m-1 of Eq. (9):  R^k (u_0^+ - u_{t+1}^+) - (u_0^- - u_{t+1}^-) = 0.
//   u_{t+1}^+ is free: u_{t+1}^+ <- F_delta(ubar_{t+1}^+) (step 2);
//   u_{t+1}^- has a unit coefficient: u_{t+1}^- = u_0^- - R^k u_0^+ + R^k u_{t+1}^+, per component
//   a sum of three grid values with coefficients +-1, evaluated by the safe dot product (Alg. 5),
//   hence exactly (step 3).
// With split_node_offset (minimal-change mode, `target` = the L2-closest point y): the node values
//   differ from y by a few quanta, and u_{t+1}^- inherits delta = (u_0^- - y_0^-) - R^k (u_0^+ - y_0^+)
//   on every sector of the branch. Step 2 then rounds y_{t+1}^+ - R^-k delta / 2 instead of y_{t+1}^+,
//   which splits delta evenly between the two sides (the minimizer of |a|^2 + |delta + R^k a|^2);
//   only the choice of a free value changes, so exactness is untouched.
// Align branch with component c: u_{t+1}|c <- u_0|c (exact copy); the other component is untouched.
// The branch rows are homogeneous (reduced_system.h): rows with b != 0 are node rows, solved by the
// projection, so no constant enters here.
// A result outside (-delta, delta) is RANGE_EXCEEDED, a stuck safe dot SAFE_DOT_FAILED.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/projection/fixed_point_grid.h>
#include <CGAL/Seamless_snapping/internal/surface/reduced_system.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/projection/safe_dot.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// `x`: 2 values per sector; on entry the node sectors hold their exact values (on the grid) and
// every other sector its input value. `target`: the values the free sectors are rounded from (ubar,
// or its L2-closest point). On success, the non-node sectors of the branches are set.
inline Status propagate_along_branches(const Reduced_system& rs, const std::vector<double>& target,
                                       const Fixed_point_grid& grid, std::vector<double>& x, std::string& message,
                                       bool split_node_offset = false)
{
  Safe_dot_workspace ws;
  std::vector<std::pair<std::int64_t, std::int64_t> > terms(3);   // (coefficient, grid integer)
  std::size_t branch = 0;
  for(const Cut_branch_plan& p : rs.cut_branches) {
    const Quarter_turn R(p.k);
    double shift[2] = {0, 0};                                     // -R^-k delta / 2
    if(split_node_offset)
      for(int c = 0; c < 2; ++c) {
        const double delta = (x[2 * p.u0_minus + c] - target[2 * p.u0_minus + c])
                           - R.sign[c] * (x[2 * p.u0_plus + R.col[c]] - target[2 * p.u0_plus + R.col[c]]);
        shift[R.col[c]] = -0.5 * R.sign[c] * delta;
      }
    for(const std::pair<int, int>& s : p.inner) {
      const int plus = s.first, minus = s.second;
      for(int c = 0; c < 2; ++c) {
        x[2 * plus + c] = grid.round(target[2 * plus + c] + shift[c]);
        if(!grid.contains(x[2 * plus + c])) {
          message = "sector " + std::to_string(plus) + " (cut branch " + std::to_string(branch) +
                    "): its input value leaves the fixed-point range (-delta, delta), delta = 2^" + std::to_string(grid.K);
          return RANGE_EXCEEDED;
        }
      }
      for(int c = 0; c < 2; ++c) {
        // (u^-)_c = (u_0^-)_c - sign_c (u_0^+)_{col_c} + sign_c (u^+)_{col_c}
        const int var[3] = {2 * p.u0_minus + c, 2 * p.u0_plus + R.col[c], 2 * plus + R.col[c]};
        const std::int64_t coef[3] = {1, -R.sign[c], R.sign[c]};
        for(int t = 0; t < 3; ++t) {
          std::int64_t z = 0;
          if(!grid.to_integer_checked(x[var[t]], z)) {   // a node value (or its input) off the grid F_delta
            message = "sector " + std::to_string(var[t] / 2) + " (cut branch " + std::to_string(branch) + "): its value " +
                      format_double(x[var[t]], 17) + " is not in the fixed-point grid F_delta, delta = 2^" + std::to_string(grid.K);
            return RANGE_EXCEEDED;
          }
          terms[t] = std::make_pair(coef[t], z);
        }
        double r = 0;
        const Safe_dot_result sr = safe_dot(terms, grid, r, ws);
        if(sr == SAFE_DOT_STUCK) {
          message = "safe dot product (Alg. 5) stuck for sector " + std::to_string(minus) + " on cut branch " +
                    std::to_string(branch) + " (an internal error: its summands lie in F_delta, delta = 2^" + std::to_string(grid.K) + ")";
          return SAFE_DOT_FAILED;
        }
        if(sr == SAFE_DOT_OUT_OF_RANGE || !grid.contains(r)) {
          message = "implied value of sector " + std::to_string(minus) + " on cut branch " + std::to_string(branch) +
                    " leaves the fixed-point range (-delta, delta), delta = 2^" + std::to_string(grid.K);
          return RANGE_EXCEEDED;
        }
        x[2 * minus + c] = r;
      }
    }
    ++branch;
  }
  for(const Align_branch_plan& p : rs.align_branches)
    for(int s : p.inner) x[2 * s + p.component] = x[2 * p.u0 + p.component];
  return SUCCESS;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_PROPAGATION_H
