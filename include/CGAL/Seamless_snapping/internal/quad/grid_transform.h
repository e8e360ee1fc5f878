// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_GRID_TRANSFORM_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_GRID_TRANSFORM_H

// Transitions between face charts of an integer-grid map, on the integer grid: p -> R^k p + t with
// R(x, y) = (-y, x) and an integer vector t (Eq. 3/7; in an exact IGM every t is an integer vector in
// grid units). They map integer points to integer points and unit cells to unit cells; composed and
// inverted in 64-bit integers. The rational twin for points off the grid is tracing::Edge_transition.
//
// A unit cell is named by its lower-left corner c = (i, j): the closed square [i, i+1] x [j, j+1].
// Its image under R^k is the square whose lower-left corner is R^k c + o_k, with o_0 = (0, 0),
// o_1 = (-1, 0), o_2 = (-1, -1), o_3 = (0, -1) (the rotated unit square's lower-left corner).

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>   // rotate_quarter_turns()

#include <CGAL/assertions.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

struct Grid_point
{
  std::int64_t u = 0, v = 0;
  bool operator==(const Grid_point& o) const { return u == o.u && v == o.v; }
  bool operator!=(const Grid_point& o) const { return !(*this == o); }
  bool operator<(const Grid_point& o) const { return v < o.v || (v == o.v && u < o.u); }   // row by row
};

inline int quarter_turns_mod4(int k) { return ((k % 4) + 4) % 4; }

// R^k p
inline Grid_point rotate(int k, const Grid_point& p)
{
  Grid_point r;
  rotate_quarter_turns(k, p.u, p.v, r.u, r.v);
  return r;
}

struct Grid_transform
{
  int k = 0;          // quarter turns counter-clockwise, 0..3
  Grid_point t;

  Grid_point apply(const Grid_point& p) const
  {
    const Grid_point r = rotate(k, p);
    return Grid_point{r.u + t.u, r.v + t.v};
  }
  // the lower-left corner of the image of the unit cell with lower-left corner c
  Grid_point apply_to_cell(const Grid_point& c) const
  {
    static const std::int64_t o[4][2] = {{0, 0}, {-1, 0}, {-1, -1}, {0, -1}};
    const Grid_point p = apply(c);
    return Grid_point{p.u + o[k][0], p.v + o[k][1]};
  }
  bool operator==(const Grid_transform& o) const { return k == o.k && t == o.t; }
  bool operator!=(const Grid_transform& o) const { return !(*this == o); }
};

// A after B: p -> A(B(p))
inline Grid_transform compose(const Grid_transform& A, const Grid_transform& B)
{
  const Grid_point r = rotate(A.k, B.t);
  return Grid_transform{quarter_turns_mod4(A.k + B.k), Grid_point{r.u + A.t.u, r.v + A.t.v}};
}

inline Grid_transform inverse(const Grid_transform& T)
{
  const Grid_point r = rotate(-T.k, T.t);
  return Grid_transform{quarter_turns_mod4(-T.k), Grid_point{-r.u, -r.v}};
}

// The transition of every interior halfedge h, from the chart of face(h) to that of face(opposite(h)):
// k = edge_k[e] for h = halfedge(e) (-k for its opposite), t = UV_j(a) - R^k UV_i(a) at a = source(h)
// (Eq. 3/7). Precondition: the UVs are in grid units, |u|, |v| < 2^52, and every t is an integer vector
// (an exact integer-grid map, checked by is_exact_integer_grid_map_impl()): the difference of two doubles
// whose exact value is an integer that a double represents is computed exactly.
inline std::vector<Grid_transform> halfedge_transitions(const Corner_mesh& cm, const std::vector<int>& edge_k)
{
  std::vector<Grid_transform> T(std::size_t(cm.n_halfedges));
  for(int e = 0; e < cm.n_edges; ++e) {
    if(cm.is_border_edge(e)) continue;
    const int h = cm.edge_halfedge[std::size_t(e)], o = cm.opp[h], ph = cm.prev[h];
    const int k = quarter_turns_mod4(edge_k[std::size_t(e)]);
    double ru, rv;
    rotate_quarter_turns(k, cm.u[ph], cm.v[ph], ru, rv);
    const double tu = cm.u[o] - ru, tv = cm.v[o] - rv;
    CGAL_assertion(tu == std::floor(tu) && tv == std::floor(tv));
    T[std::size_t(h)] = Grid_transform{k, Grid_point{std::int64_t(tu), std::int64_t(tv)}};
    T[std::size_t(o)] = inverse(T[std::size_t(h)]);
  }
  return T;
}

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_GRID_TRANSFORM_H
