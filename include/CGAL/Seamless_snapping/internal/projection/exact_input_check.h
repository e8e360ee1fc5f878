// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_EXACT_INPUT_CHECK_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_EXACT_INPUT_CHECK_H

// Does x̄ (doubles, any exponents) already satisfy every row of the caller's C x = b exactly?
// Then the projection returns x̄ bit-identical instead of moving it onto a grid F_delta.
//
// Per row (64-bit coefficients), a floating-point filter first: the double sum s of the terms
// C_ij x̄_j and -b_i is off by less than gamma (|b_i| + sum |C_ij x̄_j|), gamma = (nnz + 3) 2^-52
// (one rounding of the coefficient, one of the product, one per addition, each of relative size
// 2^-53, with a factor 2 to spare; 2^-1000 absolute covers underflow), so |s| above that proves the
// row violated; most inexact inputs are rejected at their first row.
// Otherwise the row is summed exactly in CGAL::Mpzf (exact sums and products of doubles and integers).

#include <CGAL/Seamless_snapping/internal/projection/integer_ops.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_system.h>

#include <CGAL/Gmpz.h>
#include <CGAL/Mpzf.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

inline bool satisfies_exactly(const Integer_system& sys, const std::vector<double>& x)
{
  for(std::size_t i = 0; i < sys.n_rows; ++i) {
    if(sys.fits_int64) {
      const Csr_rows<std::int64_t>& R = sys.rows64;
      // filter: coefficients up to 2^63 are rounded to double once more, hence the + 3
      double s = -double(R.b[i]), magnitude = std::fabs(double(R.b[i]));
      for(std::size_t q = R.ptr[i]; q < R.ptr[i + 1]; ++q) {
        const double t = double(R.e[q].val) * x[R.e[q].col];
        s += t; magnitude += std::fabs(t);
      }
      const double gamma = double(R.ptr[i + 1] - R.ptr[i] + 3) * 0x1p-52;
      if(std::isfinite(magnitude) && std::fabs(s) > gamma * magnitude * (1 + 0x1p-50) + 0x1p-1000) return false;
      CGAL::Mpzf acc = -CGAL::Mpzf(long(R.b[i]));
      for(std::size_t q = R.ptr[i]; q < R.ptr[i + 1]; ++q)
        acc = acc + CGAL::Mpzf(long(R.e[q].val)) * CGAL::Mpzf(x[R.e[q].col]);
      if(!acc.is_zero()) return false;
    } else {
      const Csr_rows<CGAL::Gmpz>& R = sys.rowsz;
      CGAL::Mpzf acc = -CGAL::Mpzf(R.b[i]);
      for(std::size_t q = R.ptr[i]; q < R.ptr[i + 1]; ++q)
        acc = acc + CGAL::Mpzf(R.e[q].val) * CGAL::Mpzf(x[R.e[q].col]);
      if(!acc.is_zero()) return false;
    }
  }
  return true;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_EXACT_INPUT_CHECK_H
