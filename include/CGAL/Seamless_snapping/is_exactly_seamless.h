// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_IS_EXACTLY_SEAMLESS_H
#define CGAL_SEAMLESS_SNAPPING_IS_EXACTLY_SEAMLESS_H

#include <CGAL/Seamless_snapping/diagnose_seamlessness.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/exact_uv_check.h>
#include <CGAL/Seamless_snapping/internal/surface/snap_inputs.h>
#include <CGAL/Seamless_snapping/internal/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

namespace internal {

// Reads the parameters of `np` (Snap_inputs: seam_edge_map, rotation_map, edge_is_constrained_map, the
// options), builds the corner mesh and returns `check(cm, seam_override, given_k, aligned, options)`; false if the corner mesh
// cannot be built (empty mesh, non-triangle face, non-finite UV).
template <class TriangleMesh, class HalfedgeUVMap, class NamedParameters, class Check>
bool check_with_overrides(const TriangleMesh& tm, HalfedgeUVMap uv, const NamedParameters& np, const Check& check)
{
  const Snap_inputs<TriangleMesh, NamedParameters> in(tm, np);
  typedef boost::graph_traits<TriangleMesh> GT;
  Corner_mesh cm;
  std::vector<signed char> seam_override;
  std::vector<int> given_k;
  std::vector<char> aligned;
  return corner_mesh_and_overrides(tm, uv,
                                   [&](typename GT::edge_descriptor e) { return in.seam_of(e); }, in.has_seams,
                                   [&](typename GT::halfedge_descriptor h) { return in.rotation_of(h); }, in.has_rotations,
                                   [&](typename GT::edge_descriptor e) { return in.constrained_of(e); }, in.has_constrained,
                                   cm, seam_override, given_k, aligned) &&
         check(cm, seam_override, given_k, aligned, in.options);
}

} // namespace internal

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * tests, in exact rational arithmetic (`CGAL::Gmpq`, zero tolerance), whether a per-corner UV map is
 * seamless up to rotations by multiples of 90 degrees (Eq. 3/4 of Mandad & Campen 2019): for every cut
 * edge, with UV vectors `d_i = UV(b) - UV(a)` in one face and `d_j` in the other, there is a `k` in
 * {0, 1, 2, 3} with `R^k d_i == d_j` exactly (`R(x, y) = (-y, x)`). Doubles are dyadic rationals, so
 * the test has no rounding.
 *
 * Also checked: with `seam_edge_map`, every interior edge that is not a seam must be continuous (same UVs
 * on both sides); with `rotation_map`, `k` must be the given one; with `edge_is_constrained_map`, each
 * constrained edge must be exactly parallel to the u or v axis in UV (Eq. 5).
 *
 * \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`, triangles only
 * \tparam HalfedgeUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%halfedge_descriptor`
 *         as key type and a 2D point type with `double` coordinates as value type
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the triangle mesh
 * \param uv the corner UV map: `get(uv, h)` is the UV of the corner (`target(h)`, `face(h)`)
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{seam_edge_map}
 *     \cgalParamDescription{which interior edges are seams}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
 *                    as key type and `bool` as value type}
 *     \cgalParamDefault{the interior edges whose two faces disagree (as numbers) on an endpoint UV}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::seam_edge_map()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{rotation_map}
 *     \cgalParamDescription{for `h = halfedge(e, tm)` of each seam, the quarter turns `k` counter-clockwise from the
 *                           UV frame of `face(h)` to that of `face(opposite(h))` (modulo 4)}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%halfedge_descriptor`
 *                    as key type and an integer type as value type}
 *     \cgalParamDefault{any `k` is accepted}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::rotation_map()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{edge_is_constrained_map}
 *     \cgalParamDescription{edges that must be exactly parallel to the u or v axis}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
 *                    as key type and `bool` as value type}
 *     \cgalParamDefault{no such edges}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{connection_constraints}
 *     \cgalParamDescription{connection and cycle constraints (Eq. 6-8) that must hold exactly, stated as for
 *                           `snap_seamless_parameterization()` (rotations fitted or from `rotation_map`)}
 *     \cgalParamType{a range of `Connection_constraint<boost::graph_traits<TriangleMesh>::%halfedge_descriptor>`}
 *     \cgalParamDefault{none}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::connection_constraints()`; with it, a map whose
 *                     rotations cannot be fitted gives `false`. `diagnose_seamlessness()` says which row fails and by how much}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return `true` iff all the above holds exactly. An empty mesh, a non-triangle face or a non-finite UV
 *         gives `false`.
 *
 * \sa `snap_seamless_parameterization()`
 */
template <class TriangleMesh, class HalfedgeUVMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
bool is_exactly_seamless(const TriangleMesh& tm, HalfedgeUVMap uv,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  if(!internal::check_with_overrides(tm, uv, np,
         [](const internal::Corner_mesh& cm, const std::vector<signed char>& seam_override, const std::vector<int>& given_k,
            const std::vector<char>& aligned, const internal::Snap_options&) {
           return internal::is_exactly_seamless_impl(cm, seam_override, given_k, aligned);
         }))
    return false;
  if(CGAL::parameters::is_default_parameter<NamedParameters, snap_np::connection_constraints_t>::value) return true;
  // connection and cycle constraints (Eq. 6-8): their rows as the snap states them, exactly
  const Seamless_diagnosis<TriangleMesh> d = diagnose_seamlessness(tm, uv, np);
  return d.status == SUCCESS && d.violated_connections == 0;
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_IS_EXACTLY_SEAMLESS_H
