// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_SNAP_REPORT_H
#define CGAL_SEAMLESS_SNAPPING_SNAP_REPORT_H

#include <CGAL/Seamless_snapping/Status.h>

#include <cstddef>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * What `snap_seamless_parameterization()` did. Lengths (violations, changes) are in UV units
 * divided by the diagonal of the UV bounding box of the input ("relative").
 */
struct Snap_report
{
  Status status = INVALID_INPUT;       ///< `SUCCESS` iff the UV map was written and is exactly seamless
  std::string message;                 ///< reason of a failure (names edge/sector/row), or a summary

  /// \name Counts
  /// @{
  std::size_t faces = 0;
  std::size_t cut_edges = 0;           ///< interior edges whose two faces disagree on an endpoint UV
  /// cut edges whose UV vector is zero on one side in the result (in the input, or created by the
  /// snap): the transition (Eq. 4) then makes it zero on both sides, and the faces at this edge are
  /// degenerate in UV. On `SUCCESS`, a nonzero count is also stated in `message`.
  std::size_t collapsed_cut_edges = 0;
  std::size_t cones = 0;               ///< interior vertices whose UV angle sum is not 2*pi (singularities)
  std::size_t sectors = 0;             ///< corner groups between cut edges around vertices (one UV variable pair each)
  std::size_t constrained_sectors = 0; ///< sectors that appear in some constraint
  std::size_t align_edges = 0;         ///< edges with an alignment constraint (Eq. 5)
  std::size_t constraints = 0;         ///< rows of the full (unreduced) system: 2 per cut edge + 1 per align edge (+ others)
  std::size_t nodes = 0;               ///< node vertices (Sec. 5.3)
  std::size_t cut_branches = 0;        ///< chains of cut edges between nodes
  std::size_t align_branches = 0;      ///< chains of align edges between nodes
  std::size_t system_rows = 0;         ///< rows of the system given to the exact projection (node system when reduced)
  std::size_t system_columns = 0;      ///< its columns
  std::size_t free_variables = 0;      ///< of that system
  std::size_t implied_variables = 0;   ///< of that system
  std::string max_abs_coefficient = "0"; ///< max |entry| of its IRREF
  bool reduced = true;                 ///< true: node system of Sec. 5.3; false: full sector system
  /// @}

  /// \name Magnitudes (relative to the UV bounding-box diagonal)
  /// @{
  double uv_diagonal = 0;              ///< diagonal of the input UV bounding box (UV units)
  double max_input_violation = 0;      ///< max over constraint rows of |C ū - b|, exact residual rounded to double, relative
  double max_change = 0;               ///< max |u - ū| over all UV coordinates, relative
  double mean_change = 0;              ///< mean |u - ū| over the coordinates of constrained sectors, relative
  std::size_t flips_before = 0;        ///< UV triangles with negative orientation in the input (exact test)
  std::size_t degenerate_before = 0;   ///< UV triangles with zero area in the input (exact test)
  std::size_t flips_after = 0;         ///< negative UV triangles after snapping, before the flip repair
  std::size_t degenerate_after = 0;    ///< zero-area UV triangles after snapping, before the flip repair
  std::size_t flips_introduced = 0;    ///< of `flips_after`: triangles positive in the input
  std::size_t degenerate_introduced = 0; ///< of `degenerate_after`: triangles positive in the input
  std::size_t flips_after_repair = 0;  ///< negative UV triangles at the end (= `flips_after` without repair)
  std::size_t degenerate_after_repair = 0; ///< zero-area UV triangles at the end
  std::size_t flips_unrepaired = 0;    ///< of `flips_after_repair`: triangles positive in the input (introduced, not repaired)
  std::size_t degenerate_unrepaired = 0; ///< of `degenerate_after_repair`: triangles positive in the input
  std::size_t degenerate_forced = 0;   ///< of the unrepaired triangles: those degenerate in every exact solution (two corners forced to one UV point by the constraints)
  std::size_t repair_moves = 0;        ///< accepted flip-repair moves
  std::size_t repair_node_moves = 0;   ///< of which moves of node vertices (with their branches) in the null space of the node system
  std::size_t repair_cluster_moves = 0; ///< of which moves of a vertex together with the free vertices next to it, or moves that let a triangle fall back to its input orientation
  std::size_t repair_relaxed_moves = 0; ///< of `repair_cluster_moves`: moves that repair a triangle made worse by snapping by letting others fall back to their input orientation (e.g. flipped as in the input), never below it
  /// @}

  /// \name Integer-grid structure (both modes; grid units: UVs times the grid scale)
  /// @{
  std::size_t integer_translations_before = 0; ///< cut edges whose translation (Eq. 3/7) is exactly an integer vector at both ends, in the input
  std::size_t integer_translations_after = 0;  ///< the same in the result
  std::size_t field_cones = 0;                 ///< interior vertices whose rotations k sum to a non-multiple of 4 (cones of the field)
  std::size_t cones_on_integer_points_before = 0; ///< field cones with integer UVs in every corner, in the input
  std::size_t cones_on_integer_points_after = 0;  ///< the same in the result
  bool near_integer_grid_map = false;         ///< the input's translations and field cones are all within 1e-6 of integers (it looks like an IGM)
  std::size_t pinned_cones = 0;                ///< `integer_grid_map`: field cones forced onto integer points
  std::vector<std::size_t> not_field_cones;    ///< `integer_grid_map`: vertices (indices in `vertices(tm)` order) whose UV angle sum is not 2 pi but whose rotations compose to the identity (fold-overs next to them); not pinned
  std::size_t pinned_sectors = 0;              ///< `pinned_corner_map`: sectors (UV pairs) kept bit-identical because one of their corners is pinned
  /// @}

  /// \name Timings (milliseconds, wall clock)
  /// @{
  double extract_ms = 0, reduce_ms = 0, irref_ms = 0, evaluate_ms = 0, propagate_ms = 0, verify_ms = 0, total_ms = 0;
  double repair_ms = 0;                ///< flip repair
  double least_squares_ms = 0;         ///< the floating-point L2-closest point of the full system (minimal-change mode)
  /// @}

  /// returns the report as one JSON object (numbers with 17 significant digits).
  std::string to_json() const
  {
    std::ostringstream o;
    o << std::setprecision(17);
    auto str = [&](const char* k, const std::string& v, bool comma = true) {
      o << "  \"" << k << "\": \"";
      for(char c : v) { if(c == '"' || c == '\\') o << '\\'; if(c == '\n') { o << "\\n"; continue; } o << c; }
      o << "\"" << (comma ? ",\n" : "\n");
    };
    auto num = [&](const char* k, double v) { o << "  \"" << k << "\": " << v << ",\n"; };
    o << "{\n";
    str("status", status_name(status));
    str("message", message);
    num("faces", double(faces)); num("cut_edges", double(cut_edges)); num("cones", double(cones));
    num("sectors", double(sectors)); num("constrained_sectors", double(constrained_sectors));
    num("align_edges", double(align_edges)); num("constraints", double(constraints));
    num("collapsed_cut_edges", double(collapsed_cut_edges));
    num("nodes", double(nodes)); num("cut_branches", double(cut_branches)); num("align_branches", double(align_branches));
    num("system_rows", double(system_rows)); num("system_columns", double(system_columns));
    num("free_variables", double(free_variables)); num("implied_variables", double(implied_variables));
    str("max_abs_coefficient", max_abs_coefficient);
    o << "  \"reduced\": " << (reduced ? "true" : "false") << ",\n";
    num("uv_diagonal", uv_diagonal); num("max_input_violation", max_input_violation);
    num("max_change", max_change); num("mean_change", mean_change);
    num("flips_before", double(flips_before)); num("degenerate_before", double(degenerate_before));
    num("flips_after", double(flips_after)); num("degenerate_after", double(degenerate_after));
    num("flips_introduced", double(flips_introduced)); num("degenerate_introduced", double(degenerate_introduced));
    num("flips_after_repair", double(flips_after_repair)); num("degenerate_after_repair", double(degenerate_after_repair));
    num("flips_unrepaired", double(flips_unrepaired)); num("degenerate_unrepaired", double(degenerate_unrepaired));
    num("degenerate_forced", double(degenerate_forced));
    num("repair_moves", double(repair_moves)); num("repair_node_moves", double(repair_node_moves));
    num("repair_cluster_moves", double(repair_cluster_moves)); num("repair_relaxed_moves", double(repair_relaxed_moves));
    num("integer_translations_before", double(integer_translations_before));
    num("integer_translations_after", double(integer_translations_after));
    num("field_cones", double(field_cones));
    num("cones_on_integer_points_before", double(cones_on_integer_points_before));
    num("cones_on_integer_points_after", double(cones_on_integer_points_after));
    o << "  \"near_integer_grid_map\": " << (near_integer_grid_map ? "true" : "false") << ",\n";
    num("pinned_cones", double(pinned_cones)); num("not_field_cones", double(not_field_cones.size()));
    num("pinned_sectors", double(pinned_sectors));
    num("extract_ms", extract_ms); num("reduce_ms", reduce_ms); num("irref_ms", irref_ms);
    num("evaluate_ms", evaluate_ms); num("propagate_ms", propagate_ms); num("verify_ms", verify_ms);
    num("repair_ms", repair_ms); num("least_squares_ms", least_squares_ms);
    o << "  \"total_ms\": " << total_ms << "\n}\n";
    return o.str();
  }
};

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_SNAP_REPORT_H
