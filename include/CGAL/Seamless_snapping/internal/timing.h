// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_TIMING_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_TIMING_H

// The wall-clock milliseconds of the reports' timing fields (Snap_report, Projection_report,
// Quad_mesh_report, the untangling's statistics): a monotonic clock, so a field never goes negative.

#include <chrono>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

typedef std::chrono::steady_clock Timing_clock;

// milliseconds from t to now
inline double ms_since(Timing_clock::time_point t)
{
  return std::chrono::duration<double, std::milli>(Timing_clock::now() - t).count();
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_TIMING_H
