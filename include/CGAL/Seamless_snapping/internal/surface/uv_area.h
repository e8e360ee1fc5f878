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

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// twice the signed area of the UV triangle (a, b, c) of doubles, (b - a) x (c - a), exactly
inline CGAL::Mpzf twice_triangle_uv_area(double au, double av, double bu, double bv, double cu, double cv)
{
  typedef CGAL::Mpzf Z;
  return (Z(bu) - Z(au)) * (Z(cv) - Z(av)) - (Z(bv) - Z(av)) * (Z(cu) - Z(au));
}

// The double nearest to z (ties to even), or z.to_double() when that is 0 or not finite (underflow, overflow).
// CGAL::Mpzf::to_double() is not correctly rounded: it rounds the top 64-bit limb to a double and adds the next limb
// (rounded again), so its error depends on where the limb boundaries fall in z's bits, that is on z's binary exponent:
// z and 2^j z could convert to doubles that are not 2^j apart (1 ulp off; measured on random triangles of doubles in
// [-1, 1): 2.5-6% of the conversions are not the nearest double). The flip repair's kernels (Sec. 5.4 group moves) are
// built from such orientations, in UVs normalized by different powers of two at grid scale 1 and 2^-j: a half-plane
// 1 ulp off moved a vertex 1 ulp differently. The nearest double scales with z by every 2^j that keeps it normal.
inline double nearest_double(const CGAL::Mpzf& z)
{
  double d = z.to_double();   // within about an ulp of z
  if(d == 0 || !std::isfinite(d)) return d;
  const CGAL::Mpzf twice_z = z + z;
  const double inf = std::numeric_limits<double>::infinity();
  for(;;) {                   // d moves towards z, one double at a time, until no neighbour is nearer
    const double up = std::nextafter(d, inf), down = std::nextafter(d, -inf);
    if(std::isfinite(up) && CGAL::Mpzf(d) + CGAL::Mpzf(up) < twice_z) { d = up; continue; }
    if(std::isfinite(down) && twice_z < CGAL::Mpzf(d) + CGAL::Mpzf(down)) { d = down; continue; }
    break;
  }
  // a tie (z halfway between d and a neighbour): the neighbour if its last significand bit is 0
  std::uint64_t bits;
  std::memcpy(&bits, &d, sizeof bits);
  if((bits & 1) != 0) {
    const double up = std::nextafter(d, inf), down = std::nextafter(d, -inf);
    if(std::isfinite(up) && CGAL::Mpzf(d) + CGAL::Mpzf(up) == twice_z) return up;
    if(std::isfinite(down) && CGAL::Mpzf(d) + CGAL::Mpzf(down) == twice_z) return down;
  }
  return d;
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
