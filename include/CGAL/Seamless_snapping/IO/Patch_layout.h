// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_IO_PATCH_LAYOUT_H
#define CGAL_SEAMLESS_SNAPPING_IO_PATCH_LAYOUT_H

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/Patch_layout.h>
#include <CGAL/Seamless_snapping/Status.h>

#include <CGAL/IO/PLY.h>

#include <cstdint>
#include <sstream>
#include <string>

namespace CGAL {
namespace Seamless_snapping {
namespace IO {

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * writes the refined mesh of a patch layout as OBJ: the vertices (`v`, bit-exact shortest decimals), one `vt` per
 * corner (its UV in the chart of its input face, `"h:uv"`), the faces grouped by patch (`g patch_<id>` before
 * the faces of each patch, in patch order) and, with `arc_lines`, every arc edge as a line element (`l i j`).
 * Viewers show the patches as groups and the layout as lines. CGAL's `CGAL::IO::read_OBJ()` refuses line
 * elements: write without them to read the polygons back with CGAL (or use `write_patch_layout_PLY()`, which
 * keeps `is_arc` and `patch_id`). The file is written atomically (a temporary file, then renamed).
 *
 * \return `SUCCESS`, or `INVALID_INPUT` with `message` when the layout has no mesh (its status is not
 *         `SUCCESS`) or the file cannot be written
 */
inline Status write_patch_layout_OBJ(const std::string& filename, const Patch_layout& layout, std::string& message,
                                     bool arc_lines = true)
{
  typedef Layout_mesh::Face_index Face_index;
  typedef Layout_mesh::Halfedge_index Halfedge_index;
  if(layout.status != SUCCESS) {
    message = "the layout has no refined mesh: " + layout.message;
    return INVALID_INPUT;
  }
  const Layout_mesh& m = layout.mesh;
  auto uv = m.property_map<Halfedge_index, CGAL::Epick::Point_2>("h:uv").first;
  auto patch = m.property_map<Face_index, std::int32_t>("f:patch_id").first;
  auto is_arc = m.property_map<Layout_mesh::Edge_index, std::uint8_t>("e:is_arc").first;
  std::string out = "# patch layout: " + std::to_string(layout.patches.size()) + " patches (" +
                    std::to_string(layout.quad_patches) + " quads)" + (arc_lines ? ", arcs as 'l' lines" : "") +
                    "; numbers read back to the same doubles\n";
  for(auto v : m.vertices()) {
    out += "v ";
    for(int i = 0; i < 3; ++i) { internal::append_double(out, m.point(v)[i]); out += i < 2 ? " " : "\n"; }
  }
  std::vector<std::vector<Face_index> > by_patch(layout.patches.size());
  for(Face_index f : m.faces()) by_patch[std::size_t(get(patch, f))].push_back(f);
  std::string faces;
  std::size_t vt = 0;
  for(std::size_t p = 0; p < by_patch.size(); ++p) {
    faces += "g patch_" + std::to_string(p) + "\n";
    for(Face_index f : by_patch[p]) {
      faces += "f";
      for(Halfedge_index h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
        out += "vt ";
        internal::append_double(out, get(uv, h).x());
        out += " ";
        internal::append_double(out, get(uv, h).y());
        out += "\n";
        faces += " " + std::to_string(std::size_t(m.target(h)) + 1) + "/" + std::to_string(++vt);
      }
      faces += "\n";
    }
  }
  out += faces;
  for(auto e : m.edges())
    if(arc_lines && get(is_arc, e))
      out += "l " + std::to_string(std::size_t(m.vertex(e, 0)) + 1) + " " + std::to_string(std::size_t(m.vertex(e, 1)) + 1) + "\n";
  if(internal::write_text_atomically(filename, out, message) != SUCCESS) return INVALID_INPUT;
  message = "patch layout (" + std::to_string(m.number_of_faces()) + " polygons) written to " + filename;
  return SUCCESS;
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * writes the refined mesh of a patch layout as ASCII PLY with CGAL's writer (`CGAL::IO::write_PLY()`, 17
 * significant digits): the face properties `patch_id` and `input_face` and the edge property `is_arc`
 * (an `edge` element), readable back into a `Surface_mesh` with `CGAL::IO::read_PLY()`.
 *
 * \return `SUCCESS`, or `INVALID_INPUT` with `message` when the layout has no mesh or the file cannot be written
 */
inline Status write_patch_layout_PLY(const std::string& filename, const Patch_layout& layout, std::string& message)
{
  if(layout.status != SUCCESS) {
    message = "the layout has no refined mesh: " + layout.message;
    return INVALID_INPUT;
  }
  std::ostringstream os;
  if(!CGAL::IO::write_PLY(os, layout.mesh, CGAL::parameters::stream_precision(17))) {
    message = "CGAL::IO::write_PLY failed";
    return INVALID_INPUT;
  }
  if(internal::write_text_atomically(filename, os.str(), message) != SUCCESS) return INVALID_INPUT;
  message = "patch layout (" + std::to_string(layout.mesh.number_of_faces()) + " polygons) written to " + filename;
  return SUCCESS;
}

} // namespace IO
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_IO_PATCH_LAYOUT_H
