// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_SEAM_MESH_UV_H
#define CGAL_SEAMLESS_SNAPPING_SEAM_MESH_UV_H

#include <CGAL/Seamless_snapping/Status.h>

#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// The UV map of Surface_mesh_parameterization (SMP) is keyed by the seam-mesh vertex_descriptor,
// but it is usually a halfedge map of the underlying mesh: a seam-mesh vertex converts to its
// canonical halfedge. Both key types are accepted; the cast is the identity for the former.
template <class Map, class SeamVertex>
typename boost::property_traits<Map>::key_type seam_vertex_key(const SeamVertex& v)
{
  return static_cast<typename boost::property_traits<Map>::key_type>(v);
}

// Copies a 2D point into another 2D point type: bit for bit when the types are equal, otherwise
// through the constructor from the two coordinates.
template <class To, class From>
To convert_uv(const From& p)
{
  if constexpr(std::is_same<To, From>::value) return p;
  else return To(p.x(), p.y());
}

// The corner of the underlying mesh `tm` that represents the seam-mesh vertex `v`: its canonical
// halfedge `halfedge(v)` (whose target is the vertex of `tm`), unless that is a border halfedge of
// `tm`, which it is for every border vertex of `tm` that is not on a seam (CGAL_CONVENTIONS,
// Sec. 3); then the corner `prev(opposite(h))`, which has the same target and lies in the same
// (only) wedge of the vertex.
template <class TM, class SEM, class SVM>
typename boost::graph_traits<TM>::halfedge_descriptor
representative_corner(const CGAL::Seam_mesh<TM, SEM, SVM>& mesh,
                      typename boost::graph_traits<CGAL::Seam_mesh<TM, SEM, SVM> >::vertex_descriptor v)
{
  typedef typename boost::graph_traits<TM>::halfedge_descriptor TM_halfedge;
  const TM& tm = mesh.mesh();
  const TM_halfedge h = static_cast<TM_halfedge>(v);
  return is_border(h, tm) ? prev(opposite(h, tm), tm) : h;
}

// The seam-mesh vertex of the corner (target(h), face(h)) of `tm`, for a non-border halfedge `h`.
template <class TM, class SEM, class SVM>
typename boost::graph_traits<CGAL::Seam_mesh<TM, SEM, SVM> >::vertex_descriptor
seam_vertex_of_corner(const CGAL::Seam_mesh<TM, SEM, SVM>& mesh,
                      typename boost::graph_traits<TM>::halfedge_descriptor h)
{
  typedef typename boost::graph_traits<CGAL::Seam_mesh<TM, SEM, SVM> >::halfedge_descriptor Seam_halfedge;
  return target(Seam_halfedge(h, false /* not the virtual border side of a seam */), mesh);
}

} // namespace internal

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * converts a UV map on a `CGAL::Seam_mesh`, as computed by the parameterizers of
 * \ref PkgSurfaceMeshParameterization "Surface_mesh_parameterization", into the corner UV map of
 * this package on the underlying mesh `tm = mesh.mesh()`.
 *
 * A vertex of the seam mesh is a wedge of a vertex of `tm`: the fan of faces between two seams
 * (or the whole 1-ring when the vertex is on no seam). For every non-border halfedge `h` of `tm`,
 * `corner_uv[h]` is set to the UV of the seam-mesh vertex of the corner (`target(h)`, `face(h)`).
 * For every border halfedge `h` of `tm`, `corner_uv[h]` is set to the UV of the corner
 * `prev(opposite(h))` (same target, the face next to the border), so that the result can also be
 * read back through the `Seam_mesh` view (see `corner_uv_to_seam_mesh_uv()`), whose vertices may be
 * represented by border halfedges. All values are copied bit for bit when the two value types are
 * the same.
 *
 * `corner_uv` may be the very same map as `seam_uv`: SMP stores the UV of each seam-mesh vertex on
 * one halfedge of `tm` only (its canonical halfedge), and this call then fills in all the other
 * corners in place. All values are read before the first one is written.
 *
 * As for `<CGAL/boost/graph/Seam_mesh.h>` itself, include the header of `TriangleMesh` (e.g.
 * `<CGAL/Surface_mesh.h>`) before this header.
 *
 * \tparam TriangleMesh the underlying mesh of the seam mesh, a model of `FaceListGraph` and
 *         `HalfedgeListGraph`
 * \tparam SeamEdgeMap, SeamVertexMap the seam property maps of the `Seam_mesh`
 * \tparam VertexUVMap a model of `ReadablePropertyMap` whose key type is
 *         `boost::graph_traits<Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap> >::%vertex_descriptor`
 *         or `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` (the two ways SMP's `VertexUVmap`
 *         is used), and a 2D point type as value type
 * \tparam HalfedgeUVMap a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%halfedge_descriptor`
 *         as key type and a 2D point type as value type (the same as that of `VertexUVMap`, or constructible
 *         from its two coordinates)
 *
 * \param mesh the seam mesh the UVs were computed on
 * \param seam_uv the UV of every vertex of `mesh`
 * \param corner_uv receives the corner UV map: `corner_uv[h]` is the UV of (`target(h)`, `face(h)`)
 *
 * \sa `corner_uv_to_seam_mesh_uv()`, `snap_seamless_parameterization()`
 */
template <class TriangleMesh, class SeamEdgeMap, class SeamVertexMap, class VertexUVMap, class HalfedgeUVMap>
void seam_mesh_uv_to_corner_uv(const CGAL::Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap>& mesh,
                               VertexUVMap seam_uv, HalfedgeUVMap corner_uv)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<HalfedgeUVMap>::value_type      Corner_UV;
  const TriangleMesh& tm = mesh.mesh();

  // read everything first: `corner_uv` may alias `seam_uv`
  std::vector<std::pair<halfedge_descriptor, Corner_UV> > staged;
  staged.reserve(std::size_t(num_halfedges(tm)));
  for(halfedge_descriptor h : halfedges(tm)) {
    if(is_border(h, tm)) continue;
    const auto v = internal::seam_vertex_of_corner(mesh, h);
    staged.emplace_back(h, internal::convert_uv<Corner_UV>(get(seam_uv, internal::seam_vertex_key<VertexUVMap>(v))));
  }
  for(halfedge_descriptor h : halfedges(tm)) {
    if(!is_border(h, tm)) continue;
    const auto v = internal::seam_vertex_of_corner(mesh, prev(opposite(h, tm), tm));
    staged.emplace_back(h, internal::convert_uv<Corner_UV>(get(seam_uv, internal::seam_vertex_key<VertexUVMap>(v))));
  }
  for(const auto& s : staged) put(corner_uv, s.first, s.second);
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * converts a corner UV map on `tm = mesh.mesh()` back into a UV map on the `CGAL::Seam_mesh`
 * `mesh`, e.g. after `snap_seamless_parameterization()`, so that it can be used with the
 * \ref PkgSurfaceMeshParameterization "Surface_mesh_parameterization" API (`IO::output_uvmap_to_off()`, ...).
 *
 * Each seam-mesh vertex gets the UV of one of its corners: that of its canonical halfedge
 * `halfedge(v, mesh)` when this is a face halfedge of `tm`; when it is a border halfedge `h` of `tm`
 * (the case for every border vertex of `tm` that is on no seam), that of the corner `prev(opposite(h))`.
 * Reading the border halfedge itself would be wrong: a corner map has no UV there.
 *
 * Before anything is written, every corner of `tm` is compared with the UV of its seam-mesh vertex: all
 * corners of a wedge must have the same UV (as numbers, with `operator==` of the value type), i.e.
 * `corner_uv` may only be discontinuous across the seams of `mesh`.
 *
 * \tparam TriangleMesh the underlying mesh of the seam mesh, a model of `FaceListGraph` and `HalfedgeListGraph`
 * \tparam SeamEdgeMap, SeamVertexMap the seam property maps of the `Seam_mesh`
 * \tparam HalfedgeUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%halfedge_descriptor`
 *         as key type and a 2D point type as value type
 * \tparam VertexUVMap a model of `WritablePropertyMap` whose key type is
 *         `boost::graph_traits<Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap> >::%vertex_descriptor`
 *         or `boost::graph_traits<TriangleMesh>::%halfedge_descriptor`, and a 2D point type as value type
 *         (the same as that of `HalfedgeUVMap`, or constructible from its two coordinates)
 *
 * \param mesh the seam mesh
 * \param corner_uv the corner UV map: `corner_uv[h]` is the UV of (`target(h)`, `face(h)`); border
 *        halfedges are not read
 * \param seam_uv receives the UV of every vertex of `mesh` (it may be the same map as `corner_uv`)
 * \param message on failure, which corner disagrees with its wedge, and how many do; on success a one-line summary
 *
 * \return `SUCCESS`, or `INVALID_INPUT` when the mesh has no faces or two corners of one seam-mesh vertex have
 *         different UVs (the corner map has a discontinuity that is not a seam of `mesh`, or a NaN); `seam_uv` is then
 *         left untouched.
 *
 * \sa `seam_mesh_uv_to_corner_uv()`
 */
template <class TriangleMesh, class SeamEdgeMap, class SeamVertexMap, class HalfedgeUVMap, class VertexUVMap>
Status corner_uv_to_seam_mesh_uv(const CGAL::Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap>& mesh,
                                 HalfedgeUVMap corner_uv, VertexUVMap seam_uv, std::string& message)
{
  typedef CGAL::Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap>       Seam_mesh;
  typedef typename boost::graph_traits<Seam_mesh>::vertex_descriptor      seam_vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor   vertex_descriptor;
  typedef typename boost::property_traits<VertexUVMap>::value_type        Seam_UV;
  const TriangleMesh& tm = mesh.mesh();
  if(faces(tm).empty()) {                          // as the snap refuses it (it was "wrote the UVs of 0 seam-mesh vertices")
    message = "the mesh has no faces";
    return INVALID_INPUT;
  }

  // 1. every corner must agree with the representative corner of its seam-mesh vertex
  std::size_t disagreeing = 0;
  halfedge_descriptor first_bad = boost::graph_traits<TriangleMesh>::null_halfedge();
  for(halfedge_descriptor h : halfedges(tm)) {
    if(is_border(h, tm)) continue;
    const halfedge_descriptor r = internal::representative_corner(mesh, internal::seam_vertex_of_corner(mesh, h));
    if(!(get(corner_uv, h) == get(corner_uv, r))) {
      if(disagreeing++ == 0) first_bad = h;
    }
  }
  if(disagreeing != 0) {
    std::size_t position = 0;                        // of target(first_bad) in vertices(tm), for the message
    for(vertex_descriptor v : vertices(tm)) { if(v == target(first_bad, tm)) break; ++position; }
    message = std::to_string(disagreeing) + " corner" + (disagreeing == 1 ? "" : "s") +
              " of the corner UV map differ from another corner of the same seam-mesh vertex (first at vertex #" +
              std::to_string(position) + " in the order of vertices(tm)): the map is discontinuous across an edge "
              "that is not a seam of the Seam_mesh, or has a NaN";
    return INVALID_INPUT;
  }

  // 2. read all, then write (`seam_uv` may alias `corner_uv`)
  std::vector<std::pair<seam_vertex_descriptor, Seam_UV> > staged;
  staged.reserve(std::size_t(num_vertices(mesh)));
  for(seam_vertex_descriptor v : vertices(mesh))
    staged.emplace_back(v, internal::convert_uv<Seam_UV>(get(corner_uv, internal::representative_corner(mesh, v))));
  for(const auto& s : staged) put(seam_uv, internal::seam_vertex_key<VertexUVMap>(s.first), s.second);
  message = "wrote the UVs of " + std::to_string(staged.size()) + " seam-mesh vertices";
  return SUCCESS;
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 * same as the overload with a message, without the message.
 */
template <class TriangleMesh, class SeamEdgeMap, class SeamVertexMap, class HalfedgeUVMap, class VertexUVMap>
Status corner_uv_to_seam_mesh_uv(const CGAL::Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap>& mesh,
                                 HalfedgeUVMap corner_uv, VertexUVMap seam_uv)
{
  std::string message;
  return corner_uv_to_seam_mesh_uv(mesh, corner_uv, seam_uv, message);
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_SEAM_MESH_UV_H
