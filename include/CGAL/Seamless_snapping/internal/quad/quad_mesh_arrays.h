// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_MESH_ARRAYS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_MESH_ARRAYS_H

// The caller's polygon mesh as index arrays (Quad_arrays, quad_patches.h) through its index maps, for
// quad_mesh_patches() and quad_layout(): the descriptors of the elements by index, and a refusal where an index map
// does not number the elements 0 .. n - 1 (no array is read out of its range).

#include <CGAL/Seamless_snapping/internal/quad/quad_patches.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

template <class PolygonMesh>
struct Quad_mesh_descriptors
{
  typedef boost::graph_traits<PolygonMesh> GT;
  std::vector<typename GT::vertex_descriptor> vertex;
  std::vector<typename GT::halfedge_descriptor> halfedge;
  std::vector<typename GT::face_descriptor> face;
};

// Fills m and d from qm (vertex, halfedge and face index maps from np); empty on success, else why not.
template <class PolygonMesh, class NamedParameters>
std::string quad_mesh_arrays(const PolygonMesh& qm, const NamedParameters& np, Quad_arrays& m, Quad_mesh_descriptors<PolygonMesh>& d)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  const auto vim = CGAL::get_initialized_vertex_index_map(qm, np);
  const auto him = CGAL::get_initialized_halfedge_index_map(qm, np);
  const auto fim = CGAL::get_initialized_face_index_map(qm, np);
  // the sizes of the ranges (num_faces() of a Surface_mesh may count removed faces), which the indices must fill
  const std::size_t nh = std::size_t(std::distance(halfedges(qm).begin(), halfedges(qm).end())),
                    nf = std::size_t(std::distance(faces(qm).begin(), faces(qm).end())),
                    nv = std::size_t(std::distance(vertices(qm).begin(), vertices(qm).end()));
  m = Quad_arrays();
  m.n_vertices = int(nv);
  m.next.resize(nh); m.opp.resize(nh); m.target.resize(nh); m.face.resize(nh); m.face_halfedge.resize(nf);
  d.vertex.resize(nv); d.halfedge.resize(nh); d.face.resize(nf);
  std::vector<char> seen_v(nv, 0), seen_f(nf, 0), seen_h(nh, 0);
  std::string message;
  auto not_indexed = [&](std::size_t i, std::vector<char>& seen, const char* what) {
    if(i < seen.size() && !seen[i]) { seen[i] = 1; return false; }
    message = std::string("the ") + what + " index map gives " + std::to_string(i) + (i < seen.size() ? " twice" :
              ", not below the number of " + std::string(what) + "s " + std::to_string(seen.size())) +
              " (a Surface_mesh with removed elements: collect_garbage() first; else pass an index map)";
    return true;
  };
  for(typename GT::vertex_descriptor v : vertices(qm)) {
    const std::size_t i = std::size_t(get(vim, v));
    if(not_indexed(i, seen_v, "vertex")) return message;
    d.vertex[i] = v;
  }
  for(typename GT::face_descriptor f : faces(qm)) {
    const std::size_t i = std::size_t(get(fim, f));
    if(not_indexed(i, seen_f, "face")) return message;
    d.face[i] = f;
  }
  for(typename GT::halfedge_descriptor h : halfedges(qm)) {
    const std::size_t i = std::size_t(get(him, h));
    if(not_indexed(i, seen_h, "halfedge")) return message;
    d.halfedge[i] = h;
    m.next[i] = int(get(him, next(h, qm)));
    m.opp[i] = int(get(him, opposite(h, qm)));
    m.target[i] = int(get(vim, target(h, qm)));
    m.face[i] = is_border(h, qm) ? -1 : int(get(fim, face(h, qm)));
  }
  for(std::size_t f = 0; f < nf; ++f) m.face_halfedge[f] = int(get(him, halfedge(d.face[f], qm)));
  return message;
}

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_MESH_ARRAYS_H
