// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_VERSION_H
#define CGAL_SEAMLESS_SNAPPING_VERSION_H

/// \ingroup PkgSeamlessSnappingRef
/// The package version, as in the top-level CMakeLists.txt (`project(... VERSION ...)`).
#define CGAL_SEAMLESS_SNAPPING_VERSION "0.1.0"

#endif // CGAL_SEAMLESS_SNAPPING_VERSION_H
