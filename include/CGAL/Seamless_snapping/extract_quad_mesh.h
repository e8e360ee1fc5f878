// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_EXTRACT_QUAD_MESH_H
#define CGAL_SEAMLESS_SNAPPING_EXTRACT_QUAD_MESH_H

#include <CGAL/Seamless_snapping/Quad_mesh_report.h>
#include <CGAL/Seamless_snapping/internal/parameters.h>
#include <CGAL/Seamless_snapping/internal/quad/extract_quad_mesh_impl.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * The default of `extract_quad_mesh()`'s `max_grid_cells`: `2^24` unit cells of the integer grid in the UV bounding
 * boxes of the faces, in all. The work is linear in them (every grid point of a face's box is tested against the
 * face's sides) and so is the memory: about 290 bytes per quad at the peak, with the cells, the quad mesh and its
 * copy into the caller's mesh (measured: 6.3 GB for the 22.2M quads of a fuzzed map of 80 triangles with UVs
 * up to 52,000 grid units); `2^24` keeps the peak near 5 GB.
 */
constexpr std::size_t default_max_grid_cells = std::size_t(1) << 24;

/*!
 * \ingroup PkgSeamlessSnappingRef
 * Where a vertex of the quad mesh of `extract_quad_mesh()` lies on the triangle mesh, and its integer UV.
 * `(u, v)` are grid units: the UV in the chart of `face` is `(u, v) / grid_scale`, exactly.
 */
template <class TriangleMesh>
struct Quad_vertex_origin
{
  typedef boost::graph_traits<TriangleMesh> GT;
  enum Location { VERTEX, EDGE, FACE };
  Location location = FACE;                   ///< a vertex of the triangle mesh, a point inside an edge, or inside a face
  typename GT::halfedge_descriptor halfedge;  ///< `VERTEX`: a halfedge whose target is the vertex; `EDGE`: a halfedge of the edge; `FACE`: a halfedge of the face
  typename GT::face_descriptor face;          ///< `face(halfedge)`: the face in whose UV chart `(u, v)` is given
  std::int64_t u = 0, v = 0;                  ///< the integer UV in the chart of `face`, in grid units
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * extracts the quad mesh of an exact, fold-free integer-grid map: its vertices are the integer points of the map
 * (at vertices, inside edges and inside faces of `tm`; one vertex per point of the surface, identified across cut
 * edges through their exact transitions `R^k u + t`), its edges the unit segments of the integer isolines, its faces
 * the unit cells of the grid. Everything is decided with exact predicates on the doubles of the map (no tracing, no
 * rounding, no tolerance). Only the 3D positions are rounded: every quad vertex is the combination of the vertices
 * of its face (or edge) with the barycentric coordinates of its integer point, evaluated in `double`; the exact
 * location is its integer UV (`vertex_origin_map`).
 *
 * The map is checked exactly first, and nothing is written if a check fails:
 * - it must be an exact integer-grid map at `grid_scale` (`is_exact_integer_grid_map()`; e.g. the output of
 *   `snap_seamless_parameterization()` with `integer_grid_map(true)`), else `INVALID_INPUT` naming the edge or cone
 *   that is not exact or not integer;
 * - no UV triangle may be negatively oriented or have two corners at one UV point, else `FOLD_OVERS` with the
 *   fold-overs and zero-area triangles listed in `Quad_mesh_report::fold_overs` and
 *   `Quad_mesh_report::zero_area_faces`. A zero-area triangle with three distinct (collinear) corners, e.g. one whose
 *   corners are cones that the constraints put onto collinear integer points, is the limit of a thin positive
 *   triangle: it is collapsed onto its longest side, where the faces on its two sides meet (the cells its long side
 *   runs through are glued across it and cover it, `Quad_mesh_report::zero_area_faces` lists it, and its middle
 *   corner counts 180 degrees in `quad_valences()`; where its long side is a border edge, its middle vertex is a border
 *   point of the quad mesh, in `Quad_valences::border`);
 * - every vertex inside the quad mesh (not in `Quad_valences::border`) whose quad valence (`quad_valences()`) is not 4
 *   must lie on an integer point (the cones of
 *   the field do in an integer-grid map; a vertex with an angle sum of 8 quarter turns might not), else
 *   `INVALID_INPUT`. A cone of valence 1 (90 degrees, a singularity of index 3/4 of the field, e.g. in Directional's
 *   maps) has no cell: the one at it would have two sides glued into one edge, which no polygon mesh has. With
 *   `split_valence_one_cones` (the default) its 2 x 2 cells (the cone at one corner, seven integer points of the surface)
 *   become one quad: the cone is no quad vertex, the three corners of that quad next to the glued sides lose one edge
 *   each (valence 3 where they had 4: the cone's index carried by three vertices of index 1/4), and the mesh around it
 *   is unchanged; `Quad_mesh_report::split_cones` lists such cones. A cone whose 2 x 2 cells are not that (another
 *   cone at one of the two integer points next to it, a dropped cell among the four, cells that meet themselves or another
 *   split's: a larger `grid_scale` helps), a cone whose own cell is cut by the border, or any cone of valence 1
 *   without `split_valence_one_cones`, gives `INVALID_INPUT`. A vertex around which the map winds `m > 1` times (an
 *   angle sum of `4m` quarter turns, e.g. a regular vertex the untangling left wound twice) is a branch point: on an
 *   integer point a quad vertex of valence `4m`; inside an open cell (no coordinate an integer) that cell is covered `m`
 *   times, a `4m`-gon of its corners' `m` surface points each, and with `fill_branched_cells` (the default) it becomes
 *   `2m - 1` quads, a ladder of rungs between those corners that repeats no edge (the branch point is no quad vertex,
 *   the `4(m - 1)` ends of the rungs have one edge more, valence 5 where they had 4; `Quad_mesh_report::filled_branch_points`
 *   lists them). The cell of a cone of valence 1 that shares a side with the branched cell is filled with it (the
 *   two are one disk bounded by the same `4m` points; the cone is no quad vertex, the two other corners of its cell have
 *   two edges and one fewer, and the `2m - 1` quads cover the area `m + k` with `k` such cells; the rungs then end at
 *   those corners where they can; `Quad_mesh_report::absorbed_cones` lists such cones; needs `split_valence_one_cones`,
 *   without which every cone of valence 1 is refused). Refused (`INVALID_INPUT`, named): a branch point on a grid line off the integer points, one whose cell is
 *   not surrounded by quads (another branch point, a cone other than such a cone of valence 1, or a dropped cell next to
 *   it that joins two of its corners), one
 *   whose own cell is cut by the border, and any without
 *   `fill_branched_cells`;
 * - the cells must form a polygon mesh: a cell that wraps around a handle (a torus of side 1 in grid units) or cells
 *   sharing more than a side (a grid too coarse for the surface) give `INVALID_INPUT`, with advice to use a larger
 *   `grid_scale`; a UV coordinate of absolute value `2^30` grid units or more, or more than `max_grid_cells` cells in the faces' UV bounding boxes
 *   give `RANGE_EXCEEDED`;
 * - the map must hold at least one whole cell (a map of zero UV area, or one whose cells the border cuts all, has no
 *   quad mesh), else `INVALID_INPUT` with its UV area and advice to use a larger `grid_scale`.
 *
 * Guarantees on `SUCCESS`, each verified on the result before it is written (a violation would be reported as
 * `EXACTNESS_CHECK_FAILED`, an internal error, never hidden): every face is a quad; the mesh is manifold; a closed map
 * gives a closed mesh; every quad vertex of the map's interior has the valence that `quad_valences()` gives its
 * point (4 away from the mesh vertices), so the irregular vertices are exactly the cones, of valence 4 minus their
 * index in quarter turns; and if no cell was dropped (`Quad_mesh_report::covers_map()`), the number of quads equals the
 * exact UV area of the map in grid units and `V - E + F` equals that of `tm`. Where cones of valence 1 were split,
 * the three corners of each merged quad next to the glued sides have one edge fewer than `quad_valences()` gives
 * their point, and the quads are 3 fewer per split cone than the UV area; where branched cells were filled, the rungs'
 * ends have one edge more and the quads are `m - 1` more per cell (every other quad is one unit cell).
 *
 * Border: a cell cut by a border edge that does not lie on an integer isoline is incomplete; it is dropped (not in
 * the mesh) and counted in `Quad_mesh_report::incomplete_cells`, with the status still `SUCCESS`: the quad mesh then
 * covers the map minus those cells, and its border follows the integer isolines next to the map's border.
 *
 * The quad mesh is added to `qm` (which is typically empty); vertex `i` of the mesh is the `i`-th added. On failure
 * `qm` is not changed.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`, triangles only
 * \tparam HalfedgeUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%halfedge_descriptor`
 *         as key type and a 2D point type with `double` coordinates as value type
 * \tparam QuadMesh a model of `MutableFaceGraph`
 * \tparam NamedParameters_in a sequence of \ref bgl_namedparameters "Named Parameters"
 * \tparam NamedParameters_out a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param tm the triangle mesh
 * \param uv the corner UV map: `get(uv, h)` is the UV of the corner (`target(h)`, `face(h)`), in UV units
 * \param qm the mesh that receives the quad mesh
 * \param np_in an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{the 3D positions of the vertices of `tm`}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
 *                    as key type and a 3D point type as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{grid_scale}
 *     \cgalParamDescription{`S`: the integer grid of the map is at multiples of `1/S` in UV units}
 *     \cgalParamType{`double`, a power of two}
 *     \cgalParamDefault{1}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::grid_scale()`; the result does not depend on
 *                     the scale of the map: a map scaled by `2^j` with `grid_scale(2^-j)` gives the same quad mesh}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{max_grid_cells}
 *     \cgalParamDescription{the largest number of unit cells of the integer grid that the UV bounding boxes of the
 *                           faces may hold in all (each face's box counted on its own); more give `RANGE_EXCEEDED`,
 *                           nothing written. It bounds the work and the memory, which are linear in it: about 290
 *                           bytes per quad at the peak (the cells, the quad mesh and its copy into `qm`)}
 *     \cgalParamType{`std::size_t`}
 *     \cgalParamDefault{`default_max_grid_cells` (`2^24`: 16.8M cells, about 5 GB at most)}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::max_grid_cells()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{split_valence_one_cones}
 *     \cgalParamDescription{if `true`, the 2 x 2 cells at each cone of valence 1 (90 degrees) become one quad whose three
 *                           corners next to the cone have valence 3 (see above); if `false`, such a cone gives
 *                           `INVALID_INPUT` and every quad is a unit cell}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::split_valence_one_cones()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{fill_branched_cells}
 *     \cgalParamDescription{if `true`, a cell covered `m > 1` times around a branch point inside it becomes `2m - 1`
 *                           quads, with the cell of a cone of valence 1 next to it (see above); if `false`, such a
 *                           vertex gives `INVALID_INPUT`}
 *     \cgalParamType{`bool`}
 *     \cgalParamDefault{`true`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::fill_branched_cells()`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \param np_out an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{receives the 3D position of every vertex of the quad mesh. A `QuadMesh` of the type the
 *                           extraction builds, `CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>`,
 *                           gets the quad mesh appended whole (`Surface_mesh::join()`), so its own points are set too}
 *     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<QuadMesh>::%vertex_descriptor` as key
 *                    type and a point type constructible from three `double` as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, qm)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_origin_map}
 *     \cgalParamDescription{receives, per vertex of the quad mesh, where it lies on `tm` and its integer UV}
 *     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<QuadMesh>::%vertex_descriptor` as key
 *                    type and `Quad_vertex_origin<TriangleMesh>` as value type}
 *     \cgalParamDefault{none}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::vertex_origin_map()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{face_origin_map}
 *     \cgalParamDescription{receives, per quad, the faces of `tm` it covers (those whose UV triangle meets its open
 *                           cell), in the order of `faces(tm)`; a quad made by a repair gets those of all the cells it
 *                           replaces (the 2 x 2 cells of a split cone; each quad of a filled cell all faces of that cell)}
 *     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<QuadMesh>::%face_descriptor` as key
 *                    type and `std::vector<boost::graph_traits<TriangleMesh>::%face_descriptor>` as value type}
 *     \cgalParamDefault{none}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::face_origin_map()`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return the report: status, message, what was checked and the measured quad mesh (`Quad_mesh_report`).
 *
 * \sa `snap_seamless_parameterization()` with `integer_grid_map(true)`, `is_exact_integer_grid_map()`, `quad_valences()`
 */
template <class TriangleMesh, class HalfedgeUVMap, class QuadMesh,
          class NamedParameters_in = CGAL::parameters::Default_named_parameters,
          class NamedParameters_out = CGAL::parameters::Default_named_parameters>
Quad_mesh_report extract_quad_mesh(const TriangleMesh& tm, HalfedgeUVMap uv, QuadMesh& qm,
                                   const NamedParameters_in& np_in = CGAL::parameters::default_values(),
                                   const NamedParameters_out& np_out = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef boost::graph_traits<QuadMesh> QT;

  // input: vertex point map, grid scale, the bound on the grid cells
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters_in>::const_type VPM_in;
  const VPM_in vpm_in = choose_parameter(get_parameter(np_in, CGAL::internal_np::vertex_point),
                                         get_const_property_map(CGAL::vertex_point, tm));
  const double grid_scale = choose_parameter(get_parameter(np_in, snap_np::grid_scale), 1.);
  const std::size_t max_grid_cells = choose_parameter(get_parameter(np_in, snap_np::max_grid_cells),
                                                      default_max_grid_cells);
  internal::quad::Quad_options opt;
  opt.max_grid_cells = max_grid_cells;
  opt.split_valence_one_cones = choose_parameter(get_parameter(np_in, snap_np::split_valence_one_cones), true);
  opt.fill_branched_cells = choose_parameter(get_parameter(np_in, snap_np::fill_branched_cells), true);
  // output: vertex point map, origins
  typedef typename CGAL::GetVertexPointMap<QuadMesh, NamedParameters_out>::type VPM_out;
  VPM_out vpm_out = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point),
                                     get_property_map(CGAL::vertex_point, qm));
  typedef Quad_vertex_origin<TriangleMesh> Origin;
  typedef std::vector<typename GT::face_descriptor> Covered_faces;
  typedef CGAL::Constant_property_map<typename QT::vertex_descriptor, Origin> No_origin_map;
  typedef CGAL::Constant_property_map<typename QT::face_descriptor, Covered_faces> No_face_origin_map;
  typedef typename internal_np::Lookup_named_param_def<snap_np::vertex_origin_map_t, NamedParameters_out,
                                                       No_origin_map>::type Origin_map;
  typedef typename internal_np::Lookup_named_param_def<snap_np::face_origin_map_t, NamedParameters_out,
                                                       No_face_origin_map>::type Face_origin_map;
  Origin_map origin_map = choose_parameter<Origin_map>(get_parameter(np_out, snap_np::vertex_origin_map));
  Face_origin_map face_origin_map = choose_parameter<Face_origin_map>(get_parameter(np_out, snap_np::face_origin_map));

  const bool covered_faces = !CGAL::parameters::is_default_parameter<NamedParameters_out, snap_np::face_origin_map_t>::value;
  return internal::quad::extract_quad_mesh_impl(tm, uv, vpm_in, grid_scale, opt, qm, vpm_out, origin_map,
                                                face_origin_map, covered_faces);
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_EXTRACT_QUAD_MESH_H
