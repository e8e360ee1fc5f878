// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_IO_CUT_MESH_H
#define CGAL_SEAMLESS_SNAPPING_IO_CUT_MESH_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace IO {

/// \ingroup PkgSeamlessSnappingRef
/// What `cut_mesh_test()` counts.
struct Cut_mesh_test
{
  std::size_t border_edges = 0;   ///< border edges of the mesh
  std::size_t duplicated = 0;     ///< of those, the ones whose two endpoints both have a copy at a bit-identical 3D point
  /// many border edges between duplicated vertices (at least 3, and at least half of the border edges): a cut mesh,
  /// whose seams are borders unless it is read with `weld_vertices(true)`
  bool is_cut_mesh() const { return duplicated >= 3 && 2 * duplicated >= border_edges; }
};

/// \ingroup PkgSeamlessSnappingRef
/// Tells a "cut mesh" (libigl and Directional write their parametrizations so: the vertices duplicated along the seams,
/// one 3D vertex per UV vertex) read without `weld_vertices(true)`: its seams are then mesh borders, so nothing across
/// them is seen (no cut edge, no cone), and the command-line programs read such an input again with welding.
/// Compares the 3D points bit for bit (`CGAL::to_double()` of their coordinates); O(n log n) in the vertices.
/// \tparam TriangleMesh a model of `FaceListGraph` with an internal vertex point property map
template <class TriangleMesh>
Cut_mesh_test cut_mesh_test(const TriangleMesh& tm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef std::array<double, 3> Key;
  const auto vpm = get(CGAL::vertex_point, tm);
  auto key = [&](typename GT::vertex_descriptor v) {
    const auto& p = get(vpm, v);
    return Key{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  std::vector<Key> points;
  for(typename GT::vertex_descriptor v : vertices(tm)) points.push_back(key(v));
  std::sort(points.begin(), points.end());
  auto copies = [&](typename GT::vertex_descriptor v) {
    const Key k = key(v);
    const auto range = std::equal_range(points.begin(), points.end(), k);
    return std::size_t(range.second - range.first);
  };
  Cut_mesh_test t;
  for(typename GT::edge_descriptor e : edges(tm)) {
    const typename GT::halfedge_descriptor h = halfedge(e, tm);
    if(!is_border(h, tm) && !is_border(opposite(h, tm), tm)) continue;
    ++t.border_edges;
    if(copies(source(h, tm)) > 1 && copies(target(h, tm)) > 1) ++t.duplicated;
  }
  return t;
}

} // namespace IO
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_IO_CUT_MESH_H
