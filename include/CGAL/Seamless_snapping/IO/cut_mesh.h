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
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace IO {

/// \ingroup PkgSeamlessSnappingRef
/// What `cut_mesh_test()` counts.
struct Cut_mesh_test
{
  std::size_t border_edges = 0;   ///< border edges of the mesh
  std::size_t twinned = 0;        ///< of those, the ones with a twin: another border edge between the same two 3D points
                                  ///< (bit-identical), i.e. the two sides of a seam
  /// a border edge with a twin (a seam cut open): a cut mesh, whose seams are borders unless it is read with
  /// `weld_vertices(true)`
  bool is_cut_mesh() const { return twinned >= 2; }
};

/// \ingroup PkgSeamlessSnappingRef
/// Tells a "cut mesh" (libigl and Directional write their parametrizations so: the vertices duplicated along the seams,
/// one 3D vertex per UV vertex) read without `weld_vertices(true)`: its seams are then pairs of border edges at the same
/// 3D points, so nothing across them is seen (no cut edge, no cone), and the command-line programs read such an input
/// again with welding. A map with a real border as well (Directional's lilium: 168 of its 354 border edges are seam
/// sides) is one too. Compares the 3D points bit for bit (`CGAL::to_double()` of their coordinates); O(n log n).
/// \tparam TriangleMesh a model of `FaceListGraph` with an internal vertex point property map
template <class TriangleMesh>
Cut_mesh_test cut_mesh_test(const TriangleMesh& tm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef std::array<std::uint64_t, 3> Point;   // the bits of the coordinates: -0 and 0 differ, as in the weld
  const auto vpm = get(CGAL::vertex_point, tm);
  auto bits = [](double x) { std::uint64_t b; std::memcpy(&b, &x, sizeof b); return b; };
  auto point = [&](typename GT::vertex_descriptor v) {
    const auto& p = get(vpm, v);
    return Point{{bits(CGAL::to_double(p.x())), bits(CGAL::to_double(p.y())), bits(CGAL::to_double(p.z()))}};
  };
  std::vector<std::array<Point, 2> > sides;   // per border edge its two points, in order
  for(typename GT::edge_descriptor e : edges(tm)) {
    const typename GT::halfedge_descriptor h = halfedge(e, tm);
    if(!is_border(h, tm) && !is_border(opposite(h, tm), tm)) continue;
    std::array<Point, 2> s{{point(source(h, tm)), point(target(h, tm))}};
    if(s[1] < s[0]) std::swap(s[0], s[1]);
    sides.push_back(s);
  }
  std::sort(sides.begin(), sides.end());
  Cut_mesh_test t;
  t.border_edges = sides.size();
  for(std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while(j < sides.size() && sides[j] == sides[i]) ++j;
    if(j - i > 1) t.twinned += j - i;
    i = j;
  }
  return t;
}

/// \ingroup PkgSeamlessSnappingRef
/// How `read_welding_cut_meshes()` read an input.
struct Welding_read
{
  bool ok = false;                ///< the input was read (by the read that counts)
  bool welded = false;            ///< it was read with its vertices welded
  Cut_mesh_test cut;              ///< of the input read as it is (empty when it was not read so, or that read failed)
  std::string unwelded_error;     ///< why the input read as it is was refused, where the welded read was used instead

  /// a line for the user when the input was welded without being asked to (`weld == false`), else empty
  std::string note(bool asked) const
  {
    if(!welded || asked) return std::string();
    if(unwelded_error.empty())
      return "welded automatically: " + std::to_string(cut.twinned) + " of " + std::to_string(cut.border_edges) +
             " border edges lie on another one at bit-identical 3D points (a cut mesh; --no-weld keeps them apart)";
    return "welded automatically: read as it is, the input is refused (" + unwelded_error + "); with the vertices at "
           "bit-identical 3D points welded it is a valid mesh (a cut mesh with a hole at a seam; --no-weld keeps them apart)";
  }
};

/// \ingroup PkgSeamlessSnappingRef
/// Reads an input as the command-line programs do with cut meshes (`cut_mesh_test()`): `read(weld, message)` reads it
/// into the caller's mesh `tm`, its vertices welded or not (`weld_vertices()` of `read_OBJ_with_corner_uvs()`), and
/// returns whether it succeeded (`message`: the reader's). With `weld` it reads welded; with `no_weld` as it is (and
/// tests it, `Welding_read::cut`); else as it is first, then welded when that is a cut mesh, or when that read was
/// refused but the welded one is not (a cut mesh with a hole at a seam has vertices there at which two fans of faces
/// meet, non-manifold, until the two sides of its seams are welded). Where both reads fail, `message` is the one of the
/// input as it is.
/// \tparam TriangleMesh a model of `FaceListGraph` with an internal vertex point property map
/// \tparam Read a callable `bool(bool weld, std::string& message)`
template <class TriangleMesh, class Read>
Welding_read read_welding_cut_meshes(const TriangleMesh& tm, bool weld, bool no_weld, std::string& message, const Read& read)
{
  Welding_read r;
  r.welded = weld && !no_weld;
  r.ok = read(r.welded, message);
  if(r.welded) return r;
  if(r.ok) {
    r.cut = cut_mesh_test(tm);
    if(no_weld || !r.cut.is_cut_mesh()) return r;
    r.welded = true;
    r.ok = read(true, message);
    return r;
  }
  if(no_weld) return r;
  std::string welded_message;
  if(read(true, welded_message)) {
    r.ok = r.welded = true;
    r.unwelded_error = message;
    message = welded_message;
  }
  return r;
}

} // namespace IO
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_IO_CUT_MESH_H
