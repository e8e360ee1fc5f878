// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors


#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_UV_AREA_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_UV_AREA_H

// Twice the signed UV area of a corner UV map, exactly: the sum over the faces of det(a, b, c) = a x b + b x c + c x a
// (the shoelace formula about the origin), in which the two terms of an edge whose faces agree on its UVs cancel
// exactly; what is left are the terms of the sides on cut edges and on the border, each an exact product of doubles,
// summed in CGAL::Mpzf (exact for sums and products of doubles, without the gcds of a rational).

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>

#include <CGAL/Mpzf.h>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// twice the signed area of the UV triangle (a, b, c) of doubles, (b - a) x (c - a), exactly
inline CGAL::Mpzf twice_triangle_uv_area(double au, double av, double bu, double bv, double cu, double cv)
{
  typedef CGAL::Mpzf Z;
  return (Z(bu) - Z(au)) * (Z(cv) - Z(av)) - (Z(bv) - Z(av)) * (Z(cu) - Z(au));
}

inline CGAL::Mpzf twice_uv_area(const Corner_mesh& cm)
{
  CGAL::Mpzf sum = 0;
  for(int h = 0; h < cm.n_halfedges; ++h) {
    if(cm.is_border_halfedge(h)) continue;
    const int a = cm.prev[h], o = cm.opp[h];                         // the side from corner a to corner h
    if(!cm.is_border_halfedge(o) && cm.u[h] == cm.u[cm.prev[o]] && cm.v[h] == cm.v[cm.prev[o]] && cm.u[a] == cm.u[o] &&
       cm.v[a] == cm.v[o])
      continue;                                                     // cancels with the opposite side
    sum += CGAL::Mpzf(cm.u[a]) * CGAL::Mpzf(cm.v[h]) - CGAL::Mpzf(cm.v[a]) * CGAL::Mpzf(cm.u[h]);
  }
  return sum;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_UV_AREA_H
