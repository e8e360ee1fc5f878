// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_QUAD_VALENCES_H
#define CGAL_SEAMLESS_SNAPPING_QUAD_VALENCES_H

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/quad_valences.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * The result of `quad_valences()`.
 */
struct Quad_valences
{
  Status status = SUCCESS;                 ///< `SUCCESS`, or `INVALID_INPUT` (see `message`)
  std::string message;                     ///< why the valences could not be computed
  std::vector<int> valence;                ///< per vertex, in the order of `vertices(tm)`: the signed UV angle sum in quarter turns
  std::vector<std::size_t> approximate;    ///< interior vertices whose valence is the rounded floating-point angle sum (a corner of +-180 degrees or a zero-length edge)
  std::vector<std::size_t> border;         ///< border vertices: rounded floating-point angle sum as well (quad extractors ignore it)
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * computes the quad valence of every vertex of an exactly seamless per-corner UV map: its signed UV angle sum in
 * quarter turns (4 at a regular vertex, 3 and 5 at cones of -90 and +90 degrees), the number of integer-grid
 * edges that leave the vertex in an integer-grid map. Quad extractors guess it from floating-point angle sums,
 * which fold-overs and degenerate triangles make ambiguous; libQEx reads it from a VVAL file
 * (`IO::write_VVAL()`).
 *
 * It is computed with exact sign tests only: per corner, the signed number of quadrant boundaries that the
 * corner's angle sweeps (the quadrants of the two edge vectors from exact comparisons, the sense of the turn from
 * the exact orientation predicate); around an interior vertex of an exactly seamless map these counts add up to
 * the angle sum divided by 90 degrees, exactly, fold-overs (negative corners) included. Where a corner has an
 * angle of 180 degrees (a zero-area triangle whose vertex lies between the two others) or a zero-length edge, the
 * count is undetermined: the vertex gets the floating-point angle sum rounded to quarter turns and is listed in
 * `Quad_valences::approximate`; border vertices get that rounding too. Fold-overs count with their sign: each
 * negatively oriented triangle winds its three corners back by 360 degrees in all (on a closed mesh without
 * degenerate triangles, the sum of `4 - valence` is `4 chi + 4 F-`, with `F-` the flipped triangles), so a vertex
 * next to fold-overs may get a valence of 0 or less; its class mod 4 is still that of the seam rotations around it.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`, triangles only
 * \tparam HalfedgeUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%halfedge_descriptor`
 *         as key type and a 2D point type with `double` coordinates as value type
 *
 * \param tm the triangle mesh
 * \param uv the corner UV map: `get(uv, h)` is the UV of the corner (`target(h)`, `face(h)`)
 *
 * \return the valences; `INVALID_INPUT` (nothing computed) if the map is not exactly seamless
 *         (`is_exactly_seamless()`), is empty, has a face that is not a triangle or a non-finite UV.
 *
 * \sa `snap_seamless_parameterization()` with `integer_grid_map(true)`, `IO::write_VVAL()`
 */
template <class TriangleMesh, class HalfedgeUVMap>
Quad_valences quad_valences(const TriangleMesh& tm, HalfedgeUVMap uv)
{
  Quad_valences r;
  internal::Corner_mesh cm;
  internal::Corner_mesh_descriptors<TriangleMesh> d;
  r.status = internal::build_corner_mesh(tm, uv, cm, d, r.message);
  if(r.status != SUCCESS) return r;
  if(!is_exactly_seamless(tm, uv)) {
    r.status = INVALID_INPUT;
    r.message = "the map is not exactly seamless, so its angle sums need not be multiples of 90 degrees; snap it first "
                "(snap_seamless_parameterization())";
    return r;
  }
  const internal::Quad_valence_result q = internal::quad_valences(cm);
  r.valence = q.valence;
  r.approximate.assign(q.approximate.begin(), q.approximate.end());
  r.border.assign(q.border.begin(), q.border.end());
  return r;
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_QUAD_VALENCES_H
