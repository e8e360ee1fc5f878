// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_QUAD_LAYOUT_H
#define CGAL_SEAMLESS_SNAPPING_QUAD_LAYOUT_H

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/io/json_string.h>
#include <CGAL/Seamless_snapping/internal/quad/quad_layout.h>
#include <CGAL/Seamless_snapping/internal/timing.h>
#include <CGAL/Seamless_snapping/quad_mesh_patches.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <chrono>
#include <cstddef>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * One side of an arc of `quad_layout()`: a layout halfedge. The arc is a chain of `length` edges of the quad mesh,
 * along a motorcycle trail or the border, between two layout vertices.
 */
template <class PolygonMesh>
struct Quad_layout_arc
{
  typename boost::graph_traits<PolygonMesh>::halfedge_descriptor first;  ///< the halfedge of the quad mesh that starts the chain on this side (in the patch; a border halfedge of the quad mesh on the border); the next one along the chain is `next(opposite(next(h)))` inside a patch, `next(h)` on the border
  int length = 0;        ///< quad edges in the chain (the arc's integer length, the same on both sides)
  long patch = -1;       ///< the patch on this side (the layout halfedge's face; index into `Quad_patches::patches`), -1 on the border
  bool corner = false;   ///< in a patch: the layout halfedge ends at a corner of the patch's rectangle (false: at a T-junction, a vertex on a side of the rectangle)
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 * returns the vertex of the quad mesh `qm` at the layout vertex `v`: the source of the chain of the layout halfedge
 * leaving `v` (`next(halfedge(v))`).
 * \pre `v` is a vertex that `quad_layout()` added to `layout`, `arc_map` the map it wrote
 */
template <class PolygonMesh, class LayoutGraph, class LayoutArcMap>
typename boost::graph_traits<PolygonMesh>::vertex_descriptor
layout_quad_vertex(const PolygonMesh& qm, const LayoutGraph& layout, const LayoutArcMap& arc_map,
                   typename boost::graph_traits<LayoutGraph>::vertex_descriptor v)
{
  return source(get(arc_map, next(halfedge(v, layout), layout)).first, qm);
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 * The result of `quad_layout()`.
 */
struct Quad_layout
{
  Status status = INVALID_INPUT;     ///< `SUCCESS`, or `INVALID_INPUT` (nothing added to the layout): not a manifold quad mesh, or a patch is not a rectangle
  std::string message;               ///< what was built, or why not
  Quad_patches patches;              ///< the patches (as `quad_mesh_patches()` reports them); face `k` of the layout is patch `k`
  std::size_t vertices = 0;          ///< layout vertices: the quad vertices at a corner of some patch (nodes, border corners, T-junctions), and those that split a loop
  std::size_t arcs = 0;              ///< layout edges
  std::size_t border_arcs = 0;       ///< arcs on the border of the mesh
  std::size_t t_junctions = 0;       ///< (patch, vertex) incidences where the vertex lies on a side of the patch's rectangle, not at a corner (T-junctions, and the vertices that split loops)
  std::size_t self_adjacent_arcs = 0;///< arcs with one patch on both sides (a band cut open once)
  std::size_t loop_splits = 0;       ///< of the vertices, those that split a loop (at the middle of its chain; no corner of a patch)
  std::size_t non_simple_faces = 0;  ///< faces that meet a vertex twice (their polygon lists it twice)
  bool polygon_mesh = false;         ///< no self-adjacent arc and no non-simple face: then the layout is a polygon mesh (`CGAL::is_valid_polygon_mesh()`); a self-adjacent arc makes it a valid face graph only
  long euler_characteristic = 0;     ///< V - E + F of the layout, that of the quad mesh
  double total_ms = 0;               ///< wall clock, the patches included

  /// returns the report as one JSON object (the patches as in `Quad_patches::to_json()`)
  std::string to_json() const
  {
    std::ostringstream o;
    o << std::setprecision(17) << "{\n  \"status\": " << IO::internal::json_string(status_name(status))
      << ",\n  \"message\": " << IO::internal::json_string(message) << ",\n  \"vertices\": " << vertices
      << ",\n  \"arcs\": " << arcs << ",\n  \"faces\": " << patches.patches.size() << ",\n  \"border_arcs\": " << border_arcs
      << ",\n  \"t_junctions\": " << t_junctions << ",\n  \"self_adjacent_arcs\": " << self_adjacent_arcs
      << ",\n  \"non_simple_faces\": " << non_simple_faces << ",\n  \"loop_splits\": " << loop_splits
      << ",\n  \"polygon_mesh\": " << (polygon_mesh ? "true" : "false") << ",\n  \"euler_characteristic\": " << euler_characteristic
      << ",\n  \"total_ms\": " << IO::internal::json_number(total_ms) << "\n}\n";
    return o.str();
  }
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * builds the quad layout of a quad mesh: the coarse polygon mesh whose faces are the rectangle patches of
 * `quad_mesh_patches()` (its motorcycle graph), whose vertices are the quad vertices at their corners (nodes, corners
 * of the border, and T-junctions, where a trail ends on another) and whose edges, the arcs, are the chains of quad
 * edges along the trails and the border between them. A face has its rectangle's 4 corners and, on its sides,
 * the T-junctions of the patches across: the structure T-spline and patch-based remeshing pipelines start from
 * (what QuadWild users ask for as the "coarse mesh" of a tracing). Combinatorial only, linear in the size of `qm`.
 *
 * The layout has the Euler characteristic of `qm`; each arc has an integer length (quad edges), the same on both
 * sides, and the lengths of a face's sides between its corners are its patch's width, height, width, height.
 * An arc that would run from a vertex back to itself (a trail that returns to its node; the two loops of a torus
 * without nodes) is split at the middle vertex of its chain, which becomes a layout vertex too: CGAL's halfedge graphs
 * have no loop edge. A patch may lie on both sides of an arc (a band cut open once: a ring of quads seeded once) or meet a
 * vertex twice (the torus: one face around the vertex where its loops cross; 1 of the horse's 109 patches). A self-adjacent arc
 * makes the layout a valid face graph (`CGAL::is_valid_face_graph()`) but not a polygon mesh;
 * `Quad_layout::polygon_mesh` is set where neither occurs. Two arcs may join the same two layout vertices (parallel
 * arcs: the horse's layout has 280 arcs between 279 pairs of vertices); `layout` has them as two edges, but a face list
 * written to a file (OBJ, OFF, PLY) names faces by vertices only, and a reader that makes one edge per vertex pair merges
 * them (the horse's layout read back so has Euler characteristic 3): read it with the arcs' count in mind.
 *
 * The layout's elements are added to `layout` (faces in the order of the patches); their positions are those of the
 * quad vertices. Refused (`INVALID_INPUT`, nothing added): what `quad_mesh_patches()` refuses, and a patch that is not
 * a rectangle (none is known: see `quad_mesh_patches()`).
 *
 * \tparam PolygonMesh a model of `FaceListGraph` and `HalfedgeListGraph`, quads only, manifold
 * \tparam LayoutGraph a model of `MutableFaceGraph`
 * \tparam LayoutArcMap a model of `WritablePropertyMap` with `boost::graph_traits<LayoutGraph>::%halfedge_descriptor`
 *         as key type and `Quad_layout_arc<PolygonMesh>` as value type
 * \tparam NamedParameters1 a sequence of \ref bgl_namedparameters "Named Parameters" for `qm`
 * \tparam NamedParameters2 a sequence of \ref bgl_namedparameters "Named Parameters" for `layout`
 *
 * \param qm the quad mesh, e.g. the output of `extract_quad_mesh()`
 * \param layout receives the layout
 * \param arc_map receives, per layout halfedge, its chain of quad edges, its patch and whether it ends at a corner
 * \param np1 an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 * \param np2 an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{(np1) the positions of the quad vertices; (np2) where the layout's vertices get them (the point type of np2 constructible from that of np1)}
 *     \cgalParamType{a model of `ReadablePropertyMap` (np1) or `WritablePropertyMap` (np2) with the graph's vertex descriptor as key type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, qm)` (np1), `boost::get(CGAL::vertex_point, layout)` (np2)}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vertex_index_map, halfedge_index_map, face_index_map}
 *     \cgalParamDescription{(np1) as in `quad_mesh_patches()`}
 *     \cgalParamType{models of `ReadablePropertyMap` with the descriptors of `qm` as key type and `std::size_t` as value type}
 *     \cgalParamDefault{automatically indexed internal maps}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return the layout's counts and the patches (`Quad_layout`)
 *
 * \sa `quad_mesh_patches()`, `extract_quad_mesh()`, `Patch_layout` (the layout traced in a map)
 */
template <class PolygonMesh, class LayoutGraph, class LayoutArcMap,
          class NamedParameters1 = CGAL::parameters::Default_named_parameters,
          class NamedParameters2 = CGAL::parameters::Default_named_parameters>
Quad_layout quad_layout(const PolygonMesh& qm, LayoutGraph& layout, LayoutArcMap arc_map,
                        const NamedParameters1& np1 = CGAL::parameters::default_values(),
                        const NamedParameters2& np2 = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<LayoutGraph> LT;
  const auto t0 = std::chrono::steady_clock::now();
  internal::quad::Quad_arrays m;
  internal::quad::Quad_mesh_descriptors<PolygonMesh> d;
  internal::quad::Quad_patch_cells c;
  Quad_layout r;
  r.patches = internal::quad_mesh_patch_cells(qm, np1, m, d, c);
  internal::quad::Quad_layout_arrays a;
  r.message = r.patches.status != SUCCESS ? r.patches.message : internal::quad::quad_layout(m, c, a);
  if(!r.message.empty()) { r.message = "no quad layout: " + r.message; r.total_ms = internal::ms_since(t0); return r; }

  const auto vpm1 = parameters::choose_parameter(parameters::get_parameter(np1, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, qm));
  auto vpm2 = parameters::choose_parameter(parameters::get_parameter(np2, internal_np::vertex_point), get_property_map(CGAL::vertex_point, layout));
  std::vector<typename LT::vertex_descriptor> lv(a.vertex.size());
  for(std::size_t i = 0; i < lv.size(); ++i) {
    lv[i] = add_vertex(layout);
    put(vpm2, lv[i], get(vpm1, d.vertex[std::size_t(a.vertex[i])]));
  }
  std::vector<typename LT::halfedge_descriptor> lh(a.first.size());
  for(std::size_t k = 0; k + 1 < lh.size(); k += 2) {                 // layout halfedges 2k, 2k + 1: the sides of arc k
    lh[k] = halfedge(add_edge(layout), layout);
    lh[k + 1] = opposite(lh[k], layout);
  }
  std::vector<typename LT::face_descriptor> lf(c.patches.size());
  for(typename LT::face_descriptor& f : lf) f = add_face(layout);
  std::vector<char> has_halfedge(lv.size(), 0);
  for(std::size_t l = 0; l < lh.size(); ++l) {
    const std::size_t v = std::size_t(a.target[l]);
    set_target(lh[l], lv[v], layout);
    set_next(lh[l], lh[std::size_t(a.next[l])], layout);
    set_face(lh[l], a.face[l] >= 0 ? lf[std::size_t(a.face[l])] : LT::null_face(), layout);
    if(!has_halfedge[v] || a.face[l] < 0) { set_halfedge(lv[v], lh[l], layout); has_halfedge[v] = 1; }   // a border one where there is one
    Quad_layout_arc<PolygonMesh> arc;
    arc.first = d.halfedge[std::size_t(a.first[l])];
    arc.length = a.length[l];
    arc.patch = a.face[l];
    arc.corner = a.corner[l] != 0;
    put(arc_map, lh[l], arc);
    r.border_arcs += a.face[l] < 0 ? 1 : 0;
  }
  for(std::size_t p = 0; p < lf.size(); ++p) set_halfedge(lf[p], lh[std::size_t(a.face_halfedge[p])], layout);

  r.vertices = lv.size();
  r.arcs = lh.size() / 2;
  r.t_junctions = a.t_junctions;
  r.self_adjacent_arcs = a.self_adjacent_arcs;
  r.loop_splits = a.loop_splits;
  r.euler_characteristic = long(r.vertices) - long(r.arcs) + long(lf.size());
  std::vector<int> met(lv.size(), -1);                            // per vertex: the last face that met it
  for(std::size_t p = 0; p < lf.size(); ++p) {
    bool twice = false;
    int l = a.face_halfedge[p];
    do {
      int& m = met[std::size_t(a.target[std::size_t(l)])];
      twice = twice || m == int(p);
      m = int(p);
      l = a.next[std::size_t(l)];
    } while(l != a.face_halfedge[p]);
    r.non_simple_faces += twice ? 1 : 0;
  }
  r.polygon_mesh = r.self_adjacent_arcs == 0 && r.non_simple_faces == 0;
  r.status = SUCCESS;
  r.message = std::to_string(lf.size()) + " patches, " + std::to_string(r.vertices) + " vertices, " + std::to_string(r.arcs) +
              " arcs (" + std::to_string(r.border_arcs) + " on the border), " + std::to_string(r.t_junctions) + " T-junctions" +
              (r.polygon_mesh ? "" : "; not a polygon mesh: " + std::to_string(r.self_adjacent_arcs) +
                                     " arcs with one patch on both sides, " + std::to_string(r.non_simple_faces) +
                                     " faces meeting a vertex twice");
  r.total_ms = internal::ms_since(t0);
  return r;
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_QUAD_LAYOUT_H
