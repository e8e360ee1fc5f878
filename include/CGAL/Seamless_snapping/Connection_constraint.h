// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_CONNECTION_CONSTRAINT_H
#define CGAL_SEAMLESS_SNAPPING_CONNECTION_CONSTRAINT_H

#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * A connection constraint (Eq. 6 of Mandad & Campen 2019) or, when its path is closed, a cycle
 * constraint (Eq. 8): the vertices `a` and `b` at the two ends of `path` must lie on one common
 * isocurve of the parametrization, the isocurve on which the UV coordinate `component` (0 = u,
 * 1 = v) is constant, *in the UV frame of the first face of the path*. For a cycle (`a == b`) the
 * isocurve through `a` must close up after going once around the path instead of spiralling.
 *
 * Pass a range of these to `snap_seamless_parameterization()` with the named parameter
 * `connection_constraints`.
 *
 * \tparam HalfedgeDescriptor `boost::graph_traits<TriangleMesh>::%halfedge_descriptor`
 *
 * <b>Path.</b> `path` is a nonempty sequence of halfedges `h_0, ..., h_{n-1}` of the mesh with
 * `target(h_i) == source(h_{i+1})`; `a = source(h_0)`, `b = target(h_{n-1})`. Vertices and edges may
 * repeat. Border halfedges are allowed.
 *
 * <b>Face strip and transport.</b> The constraint is evaluated along a strip of faces, which fixes
 * the accumulated transition `g_p` of Eq. (6): halfedge `h_i` is read in its face `face(h_i)` (in
 * `face(opposite(h_i))` if `h_i` is a border halfedge), and at each inner vertex `w` of the path the
 * strip goes around `w` from the face of `h_{i-1}` to the face of `h_i` through the faces on the
 * *left* of the path (clockwise around `w`), or, at a border vertex where the left side is cut by the
 * border, through the faces on the right. At a vertex whose UV angle sum is 360 degrees both sides
 * give the same constraint; at a cone they differ by the cone's holonomy, so the side matters. The
 * UV vector of each halfedge in its face is rotated by the product of the transition rotations of
 * the cut edges crossed so far (rotations `k` as in `rotation_map`), and the sum over the path must
 * have a zero `component`-th coordinate:
 * \code
 *   sum_i ( R^{q_i} (uv(target(h_i), F_i) - uv(source(h_i), F_i)) )[component] = 0
 * \endcode
 * with `F_i` the face of `h_i` and `R^{q_i}` the rotation from the frame of `F_i` to the frame of
 * the first face. This is Eq. (6) with the translations of Eq. (7) taken at the path's vertices;
 * the closing of a cycle adds nothing, because Eq. (7) at `a` makes the transition around the
 * loop map `a` to itself up to the same sum. All coefficients are integers (usually +-1).
 *
 * <b>Validity</b> (checked; otherwise `INVALID_INPUT` and the UV map is not touched): `path` is
 * nonempty, its halfedges are halfedges of the mesh and consecutive ones are connected, and
 * `component` is 0 or 1.
 */
template <typename HalfedgeDescriptor>
struct Connection_constraint
{
  typedef HalfedgeDescriptor halfedge_descriptor;

  std::vector<HalfedgeDescriptor> path;  ///< halfedges from `a` to `b`, `target(path[i]) == source(path[i+1])`
  int component = 0;                     ///< the UV coordinate that agrees: 0 = u, 1 = v (in the frame of the first face)

  Connection_constraint() {}
  /// a constraint on coordinate `component` along `path`
  Connection_constraint(std::vector<HalfedgeDescriptor> path, int component)
    : path(std::move(path)), component(component) {}
};

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_CONNECTION_CONSTRAINT_H
