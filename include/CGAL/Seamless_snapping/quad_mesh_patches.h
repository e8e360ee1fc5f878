// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_QUAD_MESH_PATCHES_H
#define CGAL_SEAMLESS_SNAPPING_QUAD_MESH_PATCHES_H

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/io/json_string.h>
#include <CGAL/Seamless_snapping/internal/quad/quad_mesh_arrays.h>
#include <CGAL/Seamless_snapping/internal/quad/quad_patches.h>
#include <CGAL/Seamless_snapping/internal/timing.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <chrono>
#include <iterator>
#include <cstddef>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * Where a quad lies in the grid of its patch (`quad_mesh_patches()`): the cell `(i, j)`, and the quad's halfedge
 * along the bottom side of that cell, which runs from the cell's corner `(i, j)` to `(i + 1, j)`; `next()` of it runs
 * along the right side, and so on. On a rectangle patch of `width` x `height` quads, `0 <= i < width` and
 * `0 <= j < height`; the patch's grid vertex `(i, j)` is then `source(bottom)` of cell `(i, j)` (or `target()` of
 * the bottom side of cell `(i - 1, j)`, and so on at the top and right borders of the patch).
 */
template <class PolygonMesh>
struct Quad_patch_location
{
  std::size_t patch = 0;                                                  ///< index into `Quad_patches::patches`
  int i = 0, j = 0;                                                       ///< the cell in the patch's grid
  typename boost::graph_traits<PolygonMesh>::halfedge_descriptor bottom;  ///< the quad's halfedge along the cell's bottom side (+i)
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 * returns the rank, 0 to 3, of the quad's vertex at its cell's corner `(i, j)` in the order in which
 * `vertices_around_face(halfedge(f, qm), qm)` lists its vertices (the targets of `halfedge(f, qm)`, `next()`, ...), as
 * file formats and index arrays list the quad: the next vertex in that order is at `(i + 1, j)`.
 * \pre `l` is the location of face `f` that `quad_mesh_patches()` wrote
 */
template <class PolygonMesh>
int patch_corner_rank(const PolygonMesh& qm, typename boost::graph_traits<PolygonMesh>::face_descriptor f,
                      const Quad_patch_location<PolygonMesh>& l)
{
  int k = 0;                                   // l.bottom is halfedge k of the face: from its vertex k - 1 to vertex k
  for(auto h = halfedge(f, qm); h != l.bottom && k < 4; h = next(h, qm)) ++k;
  return (k + 3) % 4;
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 * One patch of `quad_mesh_patches()`: quads connected across edges that no motorcycle ran along.
 */
struct Quad_patch
{
  std::size_t quads = 0;     ///< quads in the patch
  bool rectangle = false;    ///< the quads form a `width` x `height` grid: a disk of quads whose sides on its boundary, and only those, are motorcycle trails or border edges
  int width = 0;             ///< rectangle: quads along `i` (0 otherwise)
  int height = 0;            ///< rectangle: quads along `j` (0 otherwise)
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 * The result of `quad_mesh_patches()`.
 */
struct Quad_patches
{
  Status status = INVALID_INPUT;     ///< `SUCCESS`, or `INVALID_INPUT` (nothing written): a face is not a quad, a vertex is not manifold
  std::string message;               ///< what was found, or why not (naming the face or vertex)
  std::vector<Quad_patch> patches;   ///< indexed by `Quad_patch_location::patch`, numbered in the order of their quads of smallest face index
  std::size_t rectangles = 0;        ///< patches with `rectangle` set
  std::size_t nodes = 0;             ///< interior vertices of valence other than 4 and border vertices with other than 2 quads
  std::size_t motorcycles = 0;       ///< traces started (one per edge with two quads at each node; from the first vertex where there is no node)
  std::size_t stops_on_trails = 0;   ///< motorcycles that ended at a regular vertex of a trail laid before (T-junctions, head-on meetings)
  std::size_t separatrix_edges = 0;  ///< edges some motorcycle ran along
  double total_ms = 0;               ///< wall clock

  /// `SUCCESS` and every patch a rectangle
  bool all_rectangles() const { return status == SUCCESS && rectangles == patches.size(); }

  /// returns the report as one JSON object (patch sizes as `[width, height]`, `[0, 0]` for a patch that is not a rectangle)
  std::string to_json() const
  {
    std::ostringstream o;
    o << std::setprecision(17) << "{\n  \"status\": " << IO::internal::json_string(status_name(status))
      << ",\n  \"message\": " << IO::internal::json_string(message) << ",\n  \"patches\": " << patches.size()
      << ",\n  \"rectangles\": " << rectangles << ",\n  \"all_rectangles\": " << (all_rectangles() ? "true" : "false")
      << ",\n  \"nodes\": " << nodes << ",\n  \"motorcycles\": " << motorcycles << ",\n  \"stops_on_trails\": " << stops_on_trails
      << ",\n  \"separatrix_edges\": " << separatrix_edges << ",\n  \"sizes\": [";
    for(std::size_t p = 0; p < patches.size(); ++p) o << (p ? ", " : "") << "[" << patches[p].width << ", " << patches[p].height << "]";
    o << "],\n  \"total_ms\": " << IO::internal::json_number(total_ms) << "\n}\n";
    return o.str();
  }
};

namespace internal {

// quad_mesh_patches() up to its output map: qm as arrays (m, d), its patches and cells (c), the report (SUCCESS, or
// INVALID_INPUT and why not); also the first steps of quad_layout()
template <class PolygonMesh, class NamedParameters>
Quad_patches quad_mesh_patch_cells(const PolygonMesh& qm, const NamedParameters& np, quad::Quad_arrays& m,
                                   quad::Quad_mesh_descriptors<PolygonMesh>& d, quad::Quad_patch_cells& c)
{
  const auto t0 = std::chrono::steady_clock::now();
  Quad_patches r;
  r.message = quad::quad_mesh_arrays(qm, np, m, d);
  if(!r.message.empty()) { r.total_ms = ms_since(t0); return r; }
  const quad::Vertex_fans fans(m);
  r.message = quad::quad_mesh_defect(m, fans);
  if(!r.message.empty()) { r.message = "not a manifold quad mesh: " + r.message; r.total_ms = ms_since(t0); return r; }
  c = quad::quad_patch_cells(m, fans);
  for(const quad::Quad_patch_cells::Patch& p : c.patches) {
    Quad_patch q;
    q.quads = p.quads; q.rectangle = p.rectangle; q.width = p.width; q.height = p.height;
    r.patches.push_back(q);
    r.rectangles += p.rectangle ? 1 : 0;
  }
  r.nodes = c.nodes; r.motorcycles = c.motorcycles; r.stops_on_trails = c.stops_on_trails;
  for(char t : c.trail) r.separatrix_edges += t ? 1 : 0;
  r.separatrix_edges /= 2;
  r.status = SUCCESS;
  r.message = std::to_string(r.patches.size()) + " patches (" + std::to_string(r.rectangles) + " rectangles), " +
              std::to_string(r.nodes) + " nodes, " + std::to_string(r.motorcycles) + " motorcycles, " +
              std::to_string(r.separatrix_edges) + " separatrix edges";
  r.total_ms = ms_since(t0);
  return r;
}

} // namespace internal

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * partitions a quad mesh into patches with the motorcycle graph of the mesh (Eppstein, Goodrich, Kim and Tamstorf,
 * "Motorcycle graphs: canonical quad mesh partitioning", SGP 2008), the combinatorial counterpart of the
 * motorcycle graph that `Motorcycle_graph` traces in a map, and gives every quad its cell in the grid of its patch:
 * the structure of a quad layout (T-junctions on patch borders) that spline fitting and patch-based remeshing use.
 * No coordinate is read: the result depends on the connectivity of `qm` only.
 *
 * Nodes are the interior vertices of valence other than 4 (on a mesh of `extract_quad_mesh()`, the cones of the map)
 * and the border vertices with other than 2 quads; from each, a motorcycle leaves along each of its edges that has a
 * quad on both sides. All move together, one edge per round, and stop at a vertex a trail reached in an earlier round
 * (a node, the border, or a trail laid before: a T-junction). Where motorcycles reach a regular interior vertex first
 * in the same round, one goes straight on (the opposite edge) and the others stop there: two that meet head-on both
 * stop, and of two that arrive at right angles the one heading a quarter turn counter-clockwise from the other goes on.
 * The rule reads the orientation of the mesh, never an index, so the patches do not depend on the numbering of its
 * elements, but on a connected part without nodes (a torus, a cylinder with straight borders), which gets
 * motorcycles from its first vertex. The patches are the quads connected across edges that no motorcycle ran along.
 *
 * Each patch is then checked to be a rectangle: a grid of `width` x `height` quads, every cell once, whose sides on
 * the rectangle's boundary, and only those, are trails or border edges (a patch may meet itself across a trail: a band
 * cut open once). Eppstein et al. show that on a mesh with nodes every patch is one (so did every mesh the tests and
 * 600,000 fuzzed meshes gave); the check is made anyway, and a patch that is not keeps its quads with
 * `Quad_patch::rectangle` false and the cells its grid walk gave them.
 *
 * Refused (`INVALID_INPUT`, `patch_map` not written, the message naming the element): a face that is not a quad, a
 * vertex whose quads form several fans, index maps that do not number the elements `0 .. n - 1` (a `Surface_mesh` with
 * removed elements: call `collect_garbage()` first).
 *
 * \tparam PolygonMesh a model of `FaceListGraph` and `HalfedgeListGraph`, quads only, manifold
 * \tparam FacePatchMap a model of `WritablePropertyMap` with `boost::graph_traits<PolygonMesh>::%face_descriptor` as
 *         key type and `Quad_patch_location<PolygonMesh>` as value type
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param qm the quad mesh, e.g. the output of `extract_quad_mesh()`
 * \param patch_map receives, per quad, its patch, its cell and its bottom side (written only on `SUCCESS`)
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_index_map}
 *     \cgalParamDescription{a property map associating to each vertex of `qm` a unique index between `0` and the number of vertices minus 1}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
 *     \cgalParamDefault{an automatically indexed internal map}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{halfedge_index_map}
 *     \cgalParamDescription{the same for the halfedges}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<PolygonMesh>::%halfedge_descriptor` as key type and `std::size_t` as value type}
 *     \cgalParamDefault{an automatically indexed internal map}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{face_index_map}
 *     \cgalParamDescription{the same for the faces}
 *     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<PolygonMesh>::%face_descriptor` as key type and `std::size_t` as value type}
 *     \cgalParamDefault{an automatically indexed internal map}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return the patches and their sizes, the nodes and motorcycles (`Quad_patches`)
 *
 * \sa `extract_quad_mesh()`, `Motorcycle_graph`, `Patch_layout`
 */
template <class PolygonMesh, class FacePatchMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Quad_patches quad_mesh_patches(const PolygonMesh& qm, FacePatchMap patch_map,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto t0 = std::chrono::steady_clock::now();
  internal::quad::Quad_arrays m;
  internal::quad::Quad_mesh_descriptors<PolygonMesh> d;
  internal::quad::Quad_patch_cells c;
  Quad_patches r = internal::quad_mesh_patch_cells(qm, np, m, d, c);
  if(r.status != SUCCESS) return r;
  for(std::size_t f = 0; f < d.face.size(); ++f) {
    Quad_patch_location<PolygonMesh> l;
    l.patch = std::size_t(c.patch[f]);
    l.i = c.cell[f][0]; l.j = c.cell[f][1];
    l.bottom = d.halfedge[std::size_t(c.bottom[f])];
    put(patch_map, d.face[f], l);
  }
  r.total_ms = internal::ms_since(t0);
  return r;
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_QUAD_MESH_PATCHES_H
