// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_STATUS_H
#define CGAL_SEAMLESS_SNAPPING_STATUS_H

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * The outcome of every computation of the package. Anything but `SUCCESS` comes with a message
 * that names the place (row, column, edge, sector) and leaves the caller's data untouched.
 */
enum Status
{
  SUCCESS = 0,              ///< all constraints hold exactly; outputs were written
  INVALID_INPUT,            ///< bad data: NaN/Inf, size mismatch, empty or non-manifold mesh, bad index, ...
  INFEASIBLE,               ///< no solution: a zero row with nonzero right-hand side, or no dyadic solution (the congruences of addendum Eq. 2' hold on no grid of powers of two: no solution in doubles exists, e.g. 3 x = 1)
  RANGE_EXCEEDED,           ///< a value (implied variable, lcm-rounded free variable, right-hand side) leaves the fixed-point range (-delta, delta) (Sec. 4.3, Sec. 7), or dyadic solutions exist only on a grid finer than that range allows
  SAFE_DOT_FAILED,          ///< the safe dot product (Alg. 5) could not proceed without leaving (-delta, delta)
  NOT_QUARTER_TURN_SEAMLESS,///< a transition of the input is not a rotation by a multiple of 90 degrees (e.g. 120 degree orbifolds)
  EXACTNESS_CHECK_FAILED,   ///< the final exact check found a violated constraint (an internal error; reported, never hidden)
  FOLD_OVERS                ///< the UV map has fold-overs (negatively oriented UV triangles) or zero-area UV triangles, listed in the result: it is not locally injective, as quad extraction needs (`extract_quad_mesh()`, `quad_valences()`)
};

/// returns a short, distinct, human-readable name of `s`.
inline const char* status_name(Status s)
{
  switch(s) {                                    // no default: -Wswitch flags a missing code
    case SUCCESS:                   return "SUCCESS";
    case INVALID_INPUT:             return "INVALID_INPUT";
    case INFEASIBLE:                return "INFEASIBLE";
    case RANGE_EXCEEDED:            return "RANGE_EXCEEDED";
    case SAFE_DOT_FAILED:           return "SAFE_DOT_FAILED";
    case NOT_QUARTER_TURN_SEAMLESS: return "NOT_QUARTER_TURN_SEAMLESS";
    case EXACTNESS_CHECK_FAILED:    return "EXACTNESS_CHECK_FAILED";
    case FOLD_OVERS:                return "FOLD_OVERS";
  }
  return "UNKNOWN_STATUS";
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_STATUS_H
