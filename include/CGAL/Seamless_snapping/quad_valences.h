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
#include <CGAL/Seamless_snapping/internal/surface/fold_overs.h>
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
  Status status = SUCCESS;                 ///< `SUCCESS`, `INVALID_INPUT` or `FOLD_OVERS` (see `message`)
  std::string message;                     ///< why the valences could not be computed
  std::vector<int> valence;                ///< per vertex, in the order of `vertices(tm)`: the number of integer-grid directions leaving it (see `quad_valences()`)
  std::vector<std::size_t> border;         ///< vertices on the border of the quad mesh (their valence counts the directions
                                           ///< of their closed fan): the border vertices, and the middle vertex of a
                                           ///< zero-area triangle whose long side is a border edge
  std::vector<std::size_t> fold_overs;     ///< `FOLD_OVERS`: the faces (ranks in `faces(tm)`) whose UV triangle is negatively oriented
  std::vector<std::size_t> zero_area_faces;///< `FOLD_OVERS`: the faces whose UV triangle has zero area (all of them, when one has two corners at one UV point)
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * computes the quad valence of every vertex of an exactly seamless, fold-free per-corner UV map: the number of
 * integer-grid directions (the axis directions of its charts) that leave the vertex into the surface. It is the
 * valence of the vertex in the quad mesh of an integer-grid map (`extract_quad_mesh()`) wherever the vertex is an
 * integer point: at an interior vertex its UV angle sum in quarter turns (4 at a regular vertex, 3 and 5 at cones
 * of -90 and +90 degrees), at a border vertex the axis directions in its closed fan (3 on a straight border along
 * an isoline, 2 at a convex right-angle corner); the same at a vertex that a zero-area triangle folds onto the border
 * (below). Quad extractors that guess it from floating-point angle sums can be
 * told it instead; libQEx reads it from a VVAL file (`IO::write_VVAL()`).
 *
 * It is computed with exact sign tests only: per corner, the signed number of quadrant boundaries that the
 * corner's angle sweeps (the quadrants of the two edge vectors from exact comparisons, the sense of the turn from
 * the exact orientation predicate); around a vertex of an exactly seamless map these counts telescope, exactly.
 *
 * Maps with fold-overs are refused (`FOLD_OVERS`, the faces listed): there the angle sum is a signed winding number
 * (each flipped triangle winds its corners back by 360 degrees in all), which no quad mesh has, and a quad extractor
 * that trusts it leaves holes. A zero-area UV triangle whose three corners are distinct (collinear) is counted as the
 * limit of a thin positively oriented triangle (its middle corner 180 degrees, its others 0), as
 * `extract_quad_mesh()` collapses it onto its longest side; where that side is a border edge, the middle vertex is a
 * border point of the quad mesh (in `border`, its valence that of a border fan); one with two corners at one UV point
 * is refused too.
 * So is a vertex inside the quad mesh of valence 1 (an angle sum of 90 degrees: a cone of the map's own, or a cone of 5 quarter
 * turns that the map winds back to 1): no quad mesh has it as a vertex (`extract_quad_mesh()` makes the 2 x 2 cells at such
 * a cone one quad with `split_valence_one_cones`, the default, where nothing else lies in them, else refuses the map; a
 * VVAL file has no valence for it either way).
 *
 * \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`, triangles only
 * \tparam HalfedgeUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%halfedge_descriptor`
 *         as key type and a 2D point type with `double` coordinates as value type
 *
 * \param tm the triangle mesh
 * \param uv the corner UV map: `get(uv, h)` is the UV of the corner (`target(h)`, `face(h)`)
 *
 * \return the valences; `INVALID_INPUT` (nothing computed) if the map is not exactly seamless
 *         (`is_exactly_seamless()`), is empty, has a face that is not a triangle or a non-finite UV, or has an interior
 *         vertex of valence 1 (`message` names it); `FOLD_OVERS`
 *         (nothing computed) if a UV triangle is negatively oriented or has two corners at one UV point (all the
 *         zero-area triangles are listed then).
 *
 * \sa `snap_seamless_parameterization()` with `integer_grid_map(true)`, `extract_quad_mesh()`, `IO::write_VVAL()`
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
  const internal::Fold_overs folds = internal::find_fold_overs(cm);
  if(folds.blocks_quads()) {
    r.status = FOLD_OVERS;
    r.message = "the map has " + folds.describe() + ": no quad mesh has the signed angle sums next to them; make the map "
                "fold-free first";
    r.fold_overs.assign(folds.negative.begin(), folds.negative.end());
    r.zero_area_faces.assign(folds.degenerate.begin(), folds.degenerate.end());
    return r;
  }
  const internal::Quad_valence_result q = internal::quad_valences(cm);
  for(int v = 0; v < cm.n_vertices; ++v)
    if(q.valence[std::size_t(v)] == 1 && !q.on_border[std::size_t(v)]) {
      r.status = INVALID_INPUT;
      r.message = "vertex " + std::to_string(v) + " has a UV angle sum of 1 quarter turn (a cone of valence 1): the quad "
                  "there would have its two sides at the cone on one edge, a corner twice; no quad mesh has it "
                  "(extract_quad_mesh() makes the 2 x 2 cells at such a cone one quad, or refuses it)";
      const int w = internal::vertex_winding_twice(cm, q.valence);
      if(w >= 0)
        r.message += "; vertex " + std::to_string(w) + " has " + std::to_string(q.valence[std::size_t(w)]) +
                     " quarter turns: most likely a cone of 5 wound back to 1, its missing turns there (a cone pair "
                     "put onto one integer point: merge_cone_pairs(true))";
      return r;
    }
  r.valence = q.valence;
  r.border.assign(q.border.begin(), q.border.end());
  return r;
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_QUAD_VALENCES_H
