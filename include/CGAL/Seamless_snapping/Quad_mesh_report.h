// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_QUAD_MESH_REPORT_H
#define CGAL_SEAMLESS_SNAPPING_QUAD_MESH_REPORT_H

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/io/json_string.h>

#include <CGAL/Gmpq.h>

#include <cstddef>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * The result of `extract_quad_mesh()`: the status, what was checked on the input map, and the measured properties
 * of the quad mesh. Areas are in grid units (UV units times `grid_scale`, squared), faces are numbered by their rank
 * in `faces(tm)` and vertices by their rank in `vertices(tm)`.
 *
 * On `SUCCESS` the quad mesh was written and every guarantee of `extract_quad_mesh()` was verified on it.
 */
struct Quad_mesh_report
{
  Status status = INVALID_INPUT;    ///< `SUCCESS`, or why nothing was written: `INVALID_INPUT`, `FOLD_OVERS`, `RANGE_EXCEEDED`, `EXACTNESS_CHECK_FAILED`
  std::string message;              ///< what was done, or why not (naming the edge, vertex, face or cell)
  std::string advice;               ///< with `FOLD_OVERS`, where untangling can remove the faces that block the mesh: that advice (untangle the map first: the snap with `untangle(true)`), also the end of `message`; empty otherwise (e.g. the faces lie in closed parts of the surface without cut edges, where every map folds: `message` says so)

  /// \name The input map
  /// (measured as the checks of the input go: where a check refuses the map, the fields after it stay 0, e.g.
  /// `uv_area` and `input_euler_characteristic` on `FOLD_OVERS`)
  /// @{
  std::size_t faces = 0;                       ///< faces of the map
  int input_euler_characteristic = 0;          ///< V - E + F of the map
  std::size_t input_boundary_loops = 0;        ///< border loops of the map
  std::size_t cones = 0;                       ///< vertices inside the quad mesh (not in `Quad_valences::border`) whose quad valence (`quad_valences()`) is not 4
  std::vector<std::size_t> fold_overs;         ///< `FOLD_OVERS`: faces whose UV triangle is negatively oriented
  std::vector<std::size_t> zero_area_faces;    ///< faces whose UV triangle has zero area: with `FOLD_OVERS` all of them, on `SUCCESS` those collapsed onto their longest side (three distinct collinear corners)
  CGAL::Gmpq uv_area;                          ///< the exact UV area of the map in grid units (sum of its triangles)
  /// @}

  /// \name The quad mesh
  /// @{
  std::size_t quads = 0;                       ///< faces of the quad mesh: its complete cells (the 2 x 2 cells at a split cone one quad)
  std::size_t quad_vertices = 0;               ///< vertices: the integer points of the map that are corners of complete cells
  std::size_t quad_edges = 0;                  ///< edges: unit segments of integer isolines
  std::size_t border_edges = 0;                ///< edges with one quad
  std::size_t boundary_loops = 0;              ///< closed chains of border edges (holes, on a closed map)
  std::size_t non_manifold_vertices = 0;       ///< vertices whose quads do not form one fan (0 on `SUCCESS`)
  std::size_t non_manifold_edges = 0;          ///< with a failure: edges of the cells with more than two quads or twice the same direction
  std::size_t repeated_vertex_quads = 0;       ///< with a failure: cells with a corner twice (e.g. at a cone of 90 degrees)
  int euler_characteristic = 0;                ///< V - E + F of the quad mesh
  std::size_t irregular_vertices = 0;          ///< interior quad vertices whose valence is not 4
  std::vector<std::size_t> valence_histogram;  ///< entry `d`: the quad vertices with `d` edges (border vertices included)
  std::size_t incomplete_cells = 0;            ///< cells cut by a border that is not on an integer isoline: dropped, not in the mesh
  std::vector<std::size_t> filled_branch_points; ///< the vertices (of the map, in the order of `vertices(tm)`) around which the map winds `m > 1` times off the integer points, whose cell, covered `m` times, was filled with `2m - 1` quads (`fill_branched_cells`): each is no quad vertex, and `4(m - 1)` corners of those quads have valence 5 for it
  std::vector<std::size_t> split_cones;        ///< the cones of valence 1 (90 degrees; vertices of the map, in the order of `vertices(tm)`) whose 2 x 2 cells became one quad (`split_valence_one_cones`): each is no quad vertex, and three corners of that quad have valence 3 for it
  std::vector<std::size_t> absorbed_cones;     ///< the cones of valence 1 whose cell (a quad with a corner twice) shares a side with a branched cell and was filled with it (`fill_branched_cells`, with `split_valence_one_cones`): each is no quad vertex, its two other corners have two edges and one fewer for it, and the fill's `2m - 1` quads cover the area `m + k` with `k` such cells
  /// @}

  /// \name Times (wall clock, ms)
  /// @{
  double check_ms = 0;      ///< the exact checks of the input (integer-grid map, fold-overs, cones)
  double cells_ms = 0;      ///< the pieces of the faces and the cells stitched from them
  double mesh_ms = 0;       ///< the positions, the mesh and the verification of its guarantees
  double total_ms = 0;      ///< everything, writing the output included
  /// @}

  /// the quad mesh covers the whole map: `SUCCESS` and no cell dropped; then `quads` equals `uv_area` (less 3 per entry
  /// of `split_cones`, plus `m - 1` per entry of `filled_branch_points`, less 1 per entry of `absorbed_cones`)
  bool covers_map() const { return status == SUCCESS && incomplete_cells == 0; }

  /// returns the report as one JSON object (`uv_area` as a string "p/q", or "p" when it is an integer)
  std::string to_json() const
  {
    std::ostringstream o;
    o << std::setprecision(17) << "{\n";
    auto str = [&](const char* k, const std::string& v) {
      o << "  \"" << k << "\": " << IO::internal::json_string(v) << ",\n";
    };
    auto num = [&](const char* k, double v) { o << "  \"" << k << "\": " << IO::internal::json_number(v) << ",\n"; };
    auto list = [&](const char* k, const std::vector<std::size_t>& v) {
      o << "  \"" << k << "\": [";
      for(std::size_t i = 0; i < v.size(); ++i) o << (i ? ", " : "") << v[i];
      o << "],\n";
    };
    std::ostringstream area;                       // "p/q", or "p" for an integer (as Python's Fraction prints it)
    area << uv_area.numerator();
    if(uv_area.denominator() != 1) area << "/" << uv_area.denominator();
    str("status", status_name(status));
    str("message", message);
    str("advice", advice);
    num("faces", double(faces)); num("input_euler_characteristic", input_euler_characteristic);
    num("input_boundary_loops", double(input_boundary_loops)); num("cones", double(cones));
    list("fold_overs", fold_overs); list("zero_area_faces", zero_area_faces);
    str("uv_area", area.str());
    num("quads", double(quads)); num("quad_vertices", double(quad_vertices)); num("quad_edges", double(quad_edges));
    num("border_edges", double(border_edges)); num("boundary_loops", double(boundary_loops));
    num("non_manifold_vertices", double(non_manifold_vertices)); num("non_manifold_edges", double(non_manifold_edges));
    num("repeated_vertex_quads", double(repeated_vertex_quads));
    num("euler_characteristic", euler_characteristic); num("irregular_vertices", double(irregular_vertices));
    list("valence_histogram", valence_histogram);
    num("incomplete_cells", double(incomplete_cells));
    list("split_cones", split_cones);
    list("filled_branch_points", filled_branch_points);
    list("absorbed_cones", absorbed_cones);
    o << "  \"covers_map\": " << (covers_map() ? "true" : "false") << ",\n";
    num("check_ms", check_ms); num("cells_ms", cells_ms); num("mesh_ms", mesh_ms);
    o << "  \"total_ms\": " << IO::internal::json_number(total_ms) << "\n}\n";
    return o.str();
  }
};

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_QUAD_MESH_REPORT_H
