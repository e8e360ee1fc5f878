// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_IS_EXACT_INTEGER_GRID_MAP_H
#define CGAL_SEAMLESS_SNAPPING_IS_EXACT_INTEGER_GRID_MAP_H

#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/exact_uv_check.h>
#include <CGAL/Seamless_snapping/internal/surface/integer_grid_constraints.h>
#include <CGAL/Seamless_snapping/internal/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * tests, in exact rational arithmetic (`CGAL::Gmpq`, zero tolerance), whether a per-corner UV map is an
 * integer-grid map (IGM, Bommes et al. 2009/2013), the input quad extractors such as libQEx expect:
 * - it is exactly seamless (`is_exactly_seamless()`, with the same parameters);
 * - every cut edge has an integer translation: with `h = halfedge(e)`, `o = opposite(h)` and the rotation `k`
 *   of the edge, `t = UV(o) - R^k UV(prev(h))` (the UVs of `source(h)` in the two faces, Eq. 3/7) has integer
 *   coordinates (`k` is the given one (`rotation_map`), else the one for which the transition holds exactly; only a
 *   zero-length cut edge, whose UV image is a point, fits several: of those it takes the one that makes an end of it
 *   whose other cut edges have their `k` no cone, edge after edge, else the least: a map with such edges is
 *   accepted where this choice leaves no cone off the integer points; pass `rotation_map` to test given rotations);
 * - every cone of the field (an interior vertex around which these `k` do not sum to a multiple of 4) has integer
 *   UVs in all its corners;
 * - every edge of `edge_is_constrained_map` lies on an integer isoline (its constant coordinate is an integer).
 * All UVs are first multiplied by `grid_scale` (exactly: a power of two).
 *
 * \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`, triangles only
 * \tparam HalfedgeUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%halfedge_descriptor`
 *         as key type and a 2D point type with `double` coordinates as value type
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the triangle mesh
 * \param uv the corner UV map: `get(uv, h)` is the UV of the corner (`target(h)`, `face(h)`)
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters": `seam_edge_map`, `rotation_map`,
 *        `edge_is_constrained_map` as for `is_exactly_seamless()`, and
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{grid_scale}
 *     \cgalParamDescription{`S`: the integer grid is at multiples of `1/S` in UV units}
 *     \cgalParamType{`double`, a power of two}
 *     \cgalParamDefault{1}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::grid_scale()`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return `true` iff all the above holds exactly. An empty mesh, a non-triangle face, a non-finite UV or a
 *         `grid_scale` that is not a power of two gives `false`.
 *
 * \sa `snap_seamless_parameterization()` with `integer_grid_map(true)`, `is_exactly_seamless()`
 */
template <class TriangleMesh, class HalfedgeUVMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
bool is_exact_integer_grid_map(const TriangleMesh& tm, HalfedgeUVMap uv,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::check_with_overrides(tm, uv, np,
      [](const internal::Corner_mesh& cm, const std::vector<signed char>& seam_override, const std::vector<int>& given_k,
         const std::vector<char>& aligned, const internal::Snap_options& options) {
        int scale_exponent = 0;
        return internal::grid_scale_exponent(options.grid_scale, scale_exponent) &&
               internal::is_exact_integer_grid_map_impl(cm, seam_override, given_k, aligned, scale_exponent);
      });
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_IS_EXACT_INTEGER_GRID_MAP_H
