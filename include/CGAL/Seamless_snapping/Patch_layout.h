// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_PATCH_LAYOUT_H
#define CGAL_SEAMLESS_SNAPPING_PATCH_LAYOUT_H

#include <CGAL/Seamless_snapping/Status.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * The refined mesh of a patch layout: a `CGAL::Surface_mesh` with convex polygonal faces, in which every
 * arc of the motorcycle graph is a chain of edges. Its property maps:
 * - `"e:is_arc"` (`std::uint8_t`, 0 or 1): the edge lies on an arc (a separatrix);
 * - `"f:patch_id"` (`std::int32_t`): the patch of the face, 0 to `patches.size() - 1`;
 * - `"f:input_face"` (`std::int32_t`): the index of the traced mesh's face the polygon lies in
 *   (the face's rank in `faces(tm)`);
 * - `"h:uv"` (`Point_2`): the UV of the corner (`target(h)`, `face(h)`) in the chart of that input face,
 *   rounded to double (the exact values are rationals).
 *
 * `CGAL::IO::write_PLY()` writes `is_arc` (edge element) and `patch_id`, `input_face` (face element) with it;
 * `write_patch_layout_OBJ()` writes OBJ with one group per patch, one `vt` per corner and the arcs as lines.
 */
typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Layout_mesh;

/*!
 * \ingroup PkgSeamlessSnappingRef
 * One patch of a layout (a connected component of the surface minus the arcs) and its checked properties.
 * Angles and areas are measured in the UV charts (UV units).
 */
struct Layout_patch
{
  std::size_t polygons = 0;           ///< faces of the refined mesh in the patch
  int euler_characteristic = 0;       ///< of the open patch (faces - inner edges + inner vertices): 1 for a disk
  std::size_t boundary_loops = 0;     ///< closed walks along its boundary (arcs and border edges)
  std::size_t corners = 0;            ///< boundary vertices where the UV angle inside the patch is not a half turn
  std::size_t right_angle_corners = 0;///< of those, the ones with a quarter turn
  bool on_border = false;             ///< some of its boundary is border of the mesh
  bool unfolds = false;               ///< its polygons unfold into one chart, every inner edge agreeing exactly
  bool is_rectangle = false;          ///< unfolded, its UV image is the axis-aligned rectangle `width` x `height`: exact, see below
  CGAL::Gmpq width, height;           ///< of the bounding box of the unfolded patch, exact
  CGAL::Gmpq area;                    ///< UV area of the patch, exact (sum of its polygons)

  /// the open patch is a disk with one boundary loop
  bool is_disk() const { return euler_characteristic == 1 && boundary_loops == 1; }
  /// a disk with exactly 4 corners, all right angles, whose UV image is an axis-aligned rectangle
  bool is_quad() const { return is_disk() && corners == 4 && right_angle_corners == 4 && is_rectangle; }
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * The patch layout of a motorcycle graph: the faces of the traced mesh cut along the separatrices, exactly
 * (every cut point is a rational point of a face chart, identified across faces by its parameter along the
 * edge), the refined mesh, and the patches with their properties (Sec. 6.2 of Mandad & Campen 2019).
 *
 * `is_rectangle` is decided exactly: the patch is unfolded into the chart of one of its faces through the
 * transitions `R^k u + t` of the cut edges it contains (every inner edge must agree exactly, `unfolds`), the
 * sum of its polygons' areas must equal the area of the bounding box, and every boundary vertex must lie on
 * the box's boundary. Corners are counted from the UV angle sums at boundary vertices (rounded to quarter
 * turns). On an exactly seamless, locally injective map whose border (if any) lies on isolines every patch is a
 * quad (the layout is valid); where the border is not aligned, the patches along it are not rectangles.
 *
 * `euler_characteristic` is `nodes - arcs + patches` with the graph of arc and border edges; it equals
 * `surface_euler_characteristic` when every patch is an open disk.
 */
struct Patch_layout
{
  Status status = INVALID_INPUT;       ///< `SUCCESS`: the refined mesh was built (the patches may still be invalid)
  std::string message;                 ///< why not, or what is wrong
  Layout_mesh mesh;                    ///< the refined mesh (see `Layout_mesh`)
  std::vector<Layout_patch> patches;   ///< indexed by `"f:patch_id"`
  std::size_t quad_patches = 0;        ///< patches with `is_quad()`
  std::size_t nodes = 0;               ///< vertices of the arc/border graph with a degree other than 2, cones and border corners
  std::size_t arcs = 0;                ///< chains of arc/border edges between nodes (closed chains without a node are not counted)
  int euler_characteristic = 0;        ///< nodes - arcs + patches
  int surface_euler_characteristic = 0;///< vertices - edges + faces of the traced mesh
  std::vector<Layout_mesh::Vertex_index> node_vertices;              ///< the nodes, as vertices of `mesh`
  std::vector<std::vector<Layout_mesh::Vertex_index> > arc_chains;   ///< every arc as the vertices of `mesh` from one node to the next along arc and border edges
  std::size_t unplaced_segments = 0;   ///< trace segments that fit no piece of their face (inexact maps only)
  CGAL::Gmpq uv_area;                  ///< UV area of the traced mesh, exact (sum over its faces); 0 where no layout was built
  double subdivision_ms = 0;           ///< wall time (ms) of cutting the faces along the traces (exact polygons)
  double mesh_ms = 0;                  ///< wall time (ms) of building `mesh` from the polygons
  double measure_ms = 0;               ///< wall time (ms) of finding and measuring the patches and the arc/border graph

  /// every patch is a quad, every segment was placed, and the Euler characteristics agree
  bool is_valid() const
  {
    return status == SUCCESS && unplaced_segments == 0 && quad_patches == patches.size() && !patches.empty() &&
           euler_characteristic == surface_euler_characteristic;
  }
};

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_PATCH_LAYOUT_H
