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
#include <CGAL/Seamless_snapping/internal/io/json_string.h>

#include <cstddef>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * Why a UV triangle is not positively oriented at the end of `snap_seamless_parameterization()`: all but
 * `FOLD_NOT_PROVEN_FORCED` are proofs, found exactly from the constraint rows, that the triangle is negative or
 * degenerate in every map that satisfies the same constraints (so no untangling can help; only other constraint
 * data, e.g. integer translations rounded differently, can).
 */
enum Fold_reason
{
  FOLD_NOT_PROVEN_FORCED = 0,  ///< no proof found: the untangling (if it ran) did not make the triangle positive
  FOLD_CORNERS_IN_ONE_SECTOR,  ///< two corners are one sector (one UV variable): zero area in every map
  FOLD_COINCIDENT_CORNERS,     ///< the constraints force two corners onto one UV point (e.g. two cones rounded onto one integer point)
  FOLD_RIGID_TRIANGLE,         ///< the constraints fix the triangle's shape (it can only be translated) and it is negative or degenerate
  FOLD_ZERO_AREA_FORCED        ///< the constraints put the three corners on one isoline
};

/// the name of a `Fold_reason` value, e.g. `"COINCIDENT_CORNERS"`
inline const char* fold_reason_name(Fold_reason r)
{
  switch(r) {
    case FOLD_CORNERS_IN_ONE_SECTOR: return "CORNERS_IN_ONE_SECTOR";
    case FOLD_COINCIDENT_CORNERS: return "COINCIDENT_CORNERS";
    case FOLD_RIGID_TRIANGLE: return "RIGID_TRIANGLE";
    case FOLD_ZERO_AREA_FORCED: return "ZERO_AREA_FORCED";
    default: return "NOT_PROVEN_FORCED";
  }
}

/// What to do with a map whose `Snap_report::uv_mirrored` is true (the untangling leaves its mirrored components
/// alone): the words the package's messages use
inline const char* mirrored_map_advice()
{
  return "mirror its UVs (e.g. v -> -v, a texture convention some tools flip) or reverse the orientation of its faces";
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 * One UV triangle that is negatively oriented or degenerate in the result, and why.
 */
struct Fold_explanation
{
  std::size_t face = 0;                 ///< index of the face in `faces(tm)` order
  bool negative = false;                ///< negatively oriented (else zero area)
  Fold_reason reason = FOLD_NOT_PROVEN_FORCED;
  std::vector<std::size_t> vertices;    ///< its three vertices (indices in `vertices(tm)` order), counter-clockwise
  std::string message;                  ///< the reason in words, naming the vertices (and their UVs where the proof fixes them)
  /// proven negative or degenerate in every exact solution of the constraints
  bool forced() const { return reason != FOLD_NOT_PROVEN_FORCED; }
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 * One interior vertex at which the result is not locally injective although the UV triangles around it may all
 * be positive: they wind around it by `angle_sum` quarter turns instead of its `valence` (4 at a regular vertex;
 * at a cone the member of its class modulo 4 nearest to 4, i.e. 3 or 5, and 2 or 6 for a 180 degree cone by the
 * sign of its 3D angle defect), e.g. 8 at a regular vertex next to a cone that has 1 instead of 5.
 */
struct Winding_defect
{
  std::size_t vertex = 0;               ///< index of the vertex in `vertices(tm)` order
  int angle_sum = 0;                    ///< its UV angle sum in quarter turns (counted exactly where exact sign tests decide it)
  int valence = 4;                      ///< the angle sum a locally injective map has there (at a cone whose index the input does not fix, e.g. inside its fold-overs, and at a joined cone, every other member of its class modulo 4 of at least 2 is accepted too and not reported)
  bool forced = false;                  ///< proven: the vertex is a corner of a face that is non-positive in every exact solution of the constraints (a forced `Fold_explanation` in `folds`), so no map satisfying them is locally injective here
  std::string message;                  ///< in words; names the forced face at the vertex, if any, and a cone pair rounded onto one integer point nearby, if any
};

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
  bool near_integer_grid_map = false;         ///< the input's translations, field cones and align edges (each on one isoline) are all within 1e-6 of integers (it looks like an IGM)
  bool quantized = false;                      ///< `quantize`: the input was not near an integer-grid map, and its integer translations were chosen by the quantization (each cone onto one of the four integer points around it, or onto one within 2 grid cells where those four collide) instead of rounded
  std::size_t pinned_cones = 0;                ///< `integer_grid_map`: field cones forced onto integer points
  std::vector<std::size_t> not_field_cones;    ///< `integer_grid_map`: vertices (indices in `vertices(tm)` order) whose UV angle sum is not 2 pi but whose rotations compose to the identity (fold-overs next to them); not pinned
  std::vector<std::pair<std::size_t, std::size_t> > merged_cone_pairs; ///< `merge_cone_pairs`: the cone pairs (vertex indices) that the rounded translations put onto one integer point, merged: the first vertex is now a regular point of the field, the second too when their indices cancel (a +90 and a -90 degree cone), else one cone with both indices (`joined_cone_pairs`); not counted in `field_cones`
  std::vector<std::pair<std::size_t, std::size_t> > collapsed_cone_pairs; ///< `integer_grid_map`: the cone pairs (vertex indices, smaller first) that the rounded translations put onto one integer point (joined by a path of edges within one grid cell of that point, along which the transitions carry one cone onto the other), found next to the `winding_defects` and to the `folds` not proven forced (within 16 face rings); each is named in the message of such a defect or fold next to it
  std::size_t cancelling_collapsed_cone_pairs = 0; ///< of `collapsed_cone_pairs`, those whose rotations k sum to a multiple of 4 (a +90 and a -90 degree cone): `merge_cone_pairs(true)` makes such pairs regular points
  std::size_t merged_cut_edges = 0;            ///< `merge_cone_pairs`: cut edges whose rotation k (and translation) changed to merge them
  std::size_t joined_cone_pairs = 0;           ///< `merge_cone_pairs`: of `merged_cone_pairs`, those whose indices do not cancel: the second vertex of the pair is now one cone with both indices (valence 2 for two +90 degree cones, 6 for two -90), the first a regular point
  std::size_t added_cut_edges = 0;             ///< `merge_cone_pairs`: of those, edges that were not cut edges (no cut path near the pair's point joined it; the UVs are split there in the result)
  std::vector<std::pair<std::size_t, std::size_t> > separated_cone_pairs; ///< `separate_cone_pairs`: the cone pairs (vertex indices, smaller first) that the rounded translations put onto one integer point, moved apart (each cone onto a neighbouring integer point); counted in `field_cones`
  std::size_t separated_cut_edges = 0;         ///< `separate_cone_pairs`: cut edges whose integer translation changed to separate them
  std::size_t separation_trials = 0;           ///< `separate_cone_pairs` with `untangle`: extra snaps made to choose the shifts of the separated pairs with defects near them (each pair's shifts tried; 0 when none is left with defects); their time is `separation_ms`
  std::size_t pinned_sectors = 0;              ///< `pinned_corner_map`: sectors (UV pairs) kept bit-identical because one of their corners is pinned
  /// @}

  /// \name Untangling (beyond the paper: fold-overs removed inside the constraint space)
  /// The counts after snapping (`flips_after`, `degenerate_after`) and after repair refer to the map snapped
  /// from the untangled one when the untangling ran.
  /// @{
  bool untangle = false;               ///< the untangling step was asked for (`untangle(true)`)
  bool untangled = false;              ///< it ran: the exact snap of the input had non-positive UV triangles
  std::size_t flips_before_untangling = 0;      ///< negative UV triangles of the exact snap of the input (exact test)
  std::size_t degenerate_before_untangling = 0; ///< zero-area UV triangles of the exact snap of the input
  std::size_t flips_after_untangling = 0;       ///< negative UV triangles of the untangled floating-point map (exact test on its doubles)
  std::size_t degenerate_after_untangling = 0;  ///< zero-area UV triangles of the untangled floating-point map
  std::size_t folds_forced = 0;        ///< of the non-positive UV triangles at the end: those proven so in every exact solution
  std::size_t closed_uncut_faces = 0;  ///< faces in closed connected parts of the mesh (no border edge) without cut edges: every map satisfying the constraints is one UV per vertex there, a continuous map of a closed surface into the plane, which always has non-positive UV triangles (not per face: at least one of the part); their `folds` say so, and the untangling leaves such parts alone (e.g. UVs made by a projection, or all at one point, on a closed mesh)
  std::vector<Fold_explanation> folds; ///< every non-positive UV triangle at the end, with its reason
  std::vector<Winding_defect> winding_defects; ///< every interior vertex at the end whose UV angle sum is not its valence (not locally injective there)
  bool untangle_refused = false;       ///< the untangled map moved more than `max_untangle_change`: it was not used
  bool uv_mirrored = false;            ///< a connected component of the mesh has more negative than positive UV triangles in the exact snap of the input (those of closed parts without cut edges not counted, see `closed_uncut_faces`): that part of the map is mirrored (e.g. its v axis flipped, a texture convention some tools use), and the untangling leaves it alone (it would turn the whole component over); the other components are untangled
  bool untangle_budget_spent = false;  ///< the untangling stopped at its work budget (400 face evaluations per face of the mesh) with fold-overs left
  int untangle_rings = 0;              ///< the largest number of face rings around the fold-overs that an attempt moved (1, 2, 4, 8 or 16)
  std::size_t untangle_region_vertices = 0;  ///< vertices of that region
  std::size_t untangle_moved_sectors = 0;    ///< sectors whose UV the untangling changed (with respect to the exact snap of the input)
  /// optimizations of the untangling's first step: one per ring size tried (the regions of that size together)
  std::size_t untangle_attempts = 0;
  /// Newton iterations of those optimizations (each: the gradient, a sparse LDL^T factorization or the last one again,
  /// a line search, in every region still stepping): where the untangling's time goes
  std::size_t untangle_newton_steps = 0;
  std::size_t untangle_polish_steps = 0;     ///< Newton iterations of the minimal-change polish (at most 50)
  double grid_scale = 1;               ///< UV units to grid cells: a change of `c` UV units is `c * grid_scale` grid cells
  double untangle_max_change = 0;      ///< max |u_untangled - u_snap| over all UV coordinates, UV units (the move beyond the snap)
  double untangle_rms_change = 0;      ///< RMS of u_untangled - u_snap over all UV coordinates of all sectors, UV units
  double snap_max_change = 0;          ///< max |u_snap - ū|: the change of the snap alone (without untangling), UV units
  double snap_rms_change = 0;          ///< its RMS over all UV coordinates of all sectors, UV units
  double total_max_change = 0;         ///< max |u - ū| of the result, UV units
  double total_rms_change = 0;         ///< its RMS over all UV coordinates of all sectors, UV units
  /// @}

  /// \name Timings (milliseconds, wall clock)
  /// @{
  double extract_ms = 0, reduce_ms = 0, irref_ms = 0, evaluate_ms = 0, propagate_ms = 0, verify_ms = 0, total_ms = 0;
  double repair_ms = 0;                ///< flip repair
  double least_squares_ms = 0;         ///< the floating-point L2-closest point of the full system (minimal-change mode)
  double untangle_ms = 0;              ///< untangling: fold-over proofs, floating-point optimization and the second exact snap
  double untangle_polish_ms = 0;       ///< of `untangle_ms`: the minimal-change polish after the fold-overs are removed (the optimization's second step)
  double separation_ms = 0;            ///< the separation trials (`separation_trials`) and the snap with the shifts they chose; in `total_ms` only
  double explain_ms = 0;               ///< the faces left not positive, their proofs (`folds`), and the windings (`winding_defects`)
  double write_ms = 0;                 ///< writing the result into the caller's UV map
  /// @}

  /// returns the report as one JSON object (numbers with 17 significant digits).
  std::string to_json() const
  {
    std::ostringstream o;
    o << std::setprecision(17);
    auto str = [&](const char* k, const std::string& v, bool comma = true) {
      o << "  \"" << k << "\": " << IO::internal::json_string(v) << (comma ? ",\n" : "\n");
    };
    auto num = [&](const char* k, double v) { o << "  \"" << k << "\": " << IO::internal::json_number(v) << ",\n"; };
    auto vertex_pairs = [&](const char* k, const std::vector<std::pair<std::size_t, std::size_t> >& v) {
      o << "  \"" << k << "\": [";
      for(std::size_t i = 0; i < v.size(); ++i) o << (i ? ", " : "") << "[" << v[i].first << ", " << v[i].second << "]";
      o << "],\n";
    };
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
    o << "  \"quantized\": " << (quantized ? "true" : "false") << ",\n";
    num("pinned_cones", double(pinned_cones)); num("not_field_cones", double(not_field_cones.size()));
    vertex_pairs("merged_cone_pairs", merged_cone_pairs);
    vertex_pairs("collapsed_cone_pairs", collapsed_cone_pairs);
    num("cancelling_collapsed_cone_pairs", double(cancelling_collapsed_cone_pairs));
    vertex_pairs("separated_cone_pairs", separated_cone_pairs);
    num("separated_cut_edges", double(separated_cut_edges)); num("separation_trials", double(separation_trials));
    num("merged_cut_edges", double(merged_cut_edges)); num("joined_cone_pairs", double(joined_cone_pairs)); num("added_cut_edges", double(added_cut_edges));
    num("pinned_sectors", double(pinned_sectors));
    o << "  \"untangle\": " << (untangle ? "true" : "false") << ",\n";
    o << "  \"untangled\": " << (untangled ? "true" : "false") << ",\n";
    num("flips_before_untangling", double(flips_before_untangling));
    num("degenerate_before_untangling", double(degenerate_before_untangling));
    num("flips_after_untangling", double(flips_after_untangling));
    num("degenerate_after_untangling", double(degenerate_after_untangling));
    num("folds_forced", double(folds_forced));
    num("closed_uncut_faces", double(closed_uncut_faces));
    o << "  \"folds\": [";
    for(std::size_t i = 0; i < folds.size(); ++i) {
      const Fold_explanation& f = folds[i];
      o << (i ? ",\n    " : "\n    ") << "{\"face\": " << f.face << ", \"negative\": " << (f.negative ? "true" : "false")
        << ", \"reason\": \"" << fold_reason_name(f.reason) << "\", \"forced\": " << (f.forced() ? "true" : "false")
        << ", \"vertices\": [" << f.vertices[0] << ", " << f.vertices[1] << ", " << f.vertices[2] << "], \"message\": "
        << IO::internal::json_string(f.message) << "}";
    }
    o << (folds.empty() ? "],\n" : "\n  ],\n");
    o << "  \"winding_defects\": [";
    for(std::size_t i = 0; i < winding_defects.size(); ++i) {
      const Winding_defect& w = winding_defects[i];
      o << (i ? ",\n    " : "\n    ") << "{\"vertex\": " << w.vertex << ", \"angle_sum\": " << w.angle_sum << ", \"valence\": "
        << w.valence << ", \"forced\": " << (w.forced ? "true" : "false") << ", \"message\": " << IO::internal::json_string(w.message) << "}";
    }
    o << (winding_defects.empty() ? "],\n" : "\n  ],\n");
    o << "  \"untangle_refused\": " << (untangle_refused ? "true" : "false") << ",\n";
    o << "  \"uv_mirrored\": " << (uv_mirrored ? "true" : "false") << ",\n";
    o << "  \"untangle_budget_spent\": " << (untangle_budget_spent ? "true" : "false") << ",\n";
    num("untangle_rings", double(untangle_rings)); num("untangle_region_vertices", double(untangle_region_vertices));
    num("untangle_moved_sectors", double(untangle_moved_sectors)); num("untangle_attempts", double(untangle_attempts));
    num("untangle_newton_steps", double(untangle_newton_steps));
    num("untangle_polish_steps", double(untangle_polish_steps));
    num("grid_scale", grid_scale);
    num("untangle_max_change", untangle_max_change); num("untangle_rms_change", untangle_rms_change);
    num("untangle_max_change_cells", untangle_max_change * grid_scale);
    num("snap_max_change", snap_max_change); num("snap_rms_change", snap_rms_change);
    num("snap_max_change_cells", snap_max_change * grid_scale);
    num("total_max_change", total_max_change); num("total_rms_change", total_rms_change);
    num("total_max_change_cells", total_max_change * grid_scale); num("total_rms_change_cells", total_rms_change * grid_scale);
    num("extract_ms", extract_ms); num("reduce_ms", reduce_ms); num("irref_ms", irref_ms);
    num("evaluate_ms", evaluate_ms); num("propagate_ms", propagate_ms); num("verify_ms", verify_ms);
    num("repair_ms", repair_ms); num("least_squares_ms", least_squares_ms); num("untangle_ms", untangle_ms);
    num("untangle_polish_ms", untangle_polish_ms);
    num("separation_ms", separation_ms);
    num("explain_ms", explain_ms); num("write_ms", write_ms);
    o << "  \"total_ms\": " << IO::internal::json_number(total_ms) << "\n}\n";
    return o.str();
  }
};

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_SNAP_REPORT_H
