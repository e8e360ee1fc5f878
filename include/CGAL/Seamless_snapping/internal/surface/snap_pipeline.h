// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_SNAP_PIPELINE_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_SNAP_PIPELINE_H

// The surface pipeline behind snap_seamless_parameterization() (Sec. 5):
//   1. extract   corner mesh, cut edges, sectors, cones, rotations k, align edges,
//                the full system of rows (+ integer-grid rows)  (Sec. 5, 5.1)   extract_seams, build_constraints
//   2. reduce    nodes, branches, node system C                  (Sec. 5.3)      reduce_stage
//   3a. spread   the L2-closest point of the FULL system, in floating point     least_squares_stage
//                (all constrained sectors move, weighted; beyond Sec. 4.2)
//   3. project   C through Exact_constraint_projection on F_delta (Sec. 4)       project_stage
//                starting from the point of 3a, not from ubar
//   4. propagate non-node sectors along the branches              (Sec. 5.3.1)   project_node_system
//                also from the point of 3a: the exact result stays within grid rounding of it
//   4b. untangle the fold-overs of the exact map inside the constraint space, in floating point, then
//                3.-4. again from the untangled map (untangling/, beyond the paper)         untangle_stage
//   5. repair    flipped/degenerate triangles: group and node moves, exactly (Sec. 5.4, 7)   repair_stage
//   5b. explain  every triangle still not positive: proven forced by the constraints or not  explain_folds_stage
//   6. verify    every row of the full system, exactly (Gmpq), before anything is written   verify_stage
//   7. write     the corners of the changed sectors into the caller's map                   write_stage
// With use_reduced_system = false, step 4 is skipped and the full system goes to step 3.
//
// One grid for everything: K = e(max |ubar|) + 1 over all constrained sector coordinates
// (Fixed_point_grid::from_max_abs(max, 1)), passed to the projection via
// Projection_options::delta_exponent, so that node values and propagated values are multiples of
// the same quantum 2^(K-52). If steps 3-4 leave (-delta, delta) (RANGE_EXCEEDED), they are redone
// from ubar with K + 4, up to 5 times (large changes come from connection/cycle constraints that the
// input violates by much; transition constraints alone never need it).

#include <CGAL/Seamless_snapping/Exact_constraint_projection.h>
#include <CGAL/Seamless_snapping/Snap_report.h>
#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/io/name_lists.h>
#include <CGAL/Seamless_snapping/internal/surface/cone_merging.h>
#include <CGAL/Seamless_snapping/internal/surface/cone_separation.h>
#include <CGAL/Seamless_snapping/internal/surface/connection_constraints.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/exact_uv_check.h>
#include <CGAL/Seamless_snapping/internal/projection/fixed_point_grid.h>
#include <CGAL/Seamless_snapping/internal/projection/least_squares_projection.h>
#include <CGAL/Seamless_snapping/internal/surface/flip_repair.h>
#include <CGAL/Seamless_snapping/internal/surface/integer_grid_constraints.h>
#include <CGAL/Seamless_snapping/internal/surface/integer_grid_quantization.h>
#include <CGAL/Seamless_snapping/internal/surface/pinned_corners.h>
#include <CGAL/Seamless_snapping/internal/surface/propagation.h>
#include <CGAL/Seamless_snapping/internal/surface/reduced_system.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>
#include <CGAL/Seamless_snapping/internal/threads.h>
#include <CGAL/Seamless_snapping/internal/timing.h>
#include <CGAL/Seamless_snapping/internal/untangling/closed_uncut_parts.h>
#include <CGAL/Seamless_snapping/internal/untangling/mirrored_components.h>
#include <CGAL/Seamless_snapping/internal/untangling/forced_folds.h>
#include <CGAL/Seamless_snapping/internal/untangling/untangler.h>
#include <CGAL/Seamless_snapping/internal/untangling/winding_defects.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>

#include <Eigen/Sparse>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

struct Snap_options
{
  bool align_boundary = true;
  bool use_reduced_system = true;
  bool verbose = false;
  double alignment_tolerance = 1e-3;   // degrees
  double rotation_tolerance = 1;       // degrees
  bool repair_flips = true;            // Sec. 5.4: move one vertex of a flipped triangle into its 1-ring kernel
  bool minimal_change = true;          // step 3a: snap the L2-closest point of the full system instead of ubar
  std::vector<Connection_path> connections;  // connection (Eq. 6) and cycle (Eq. 8) constraints
  bool integer_grid_map = false;       // integer translations, cones on integer points, integer isolines
  double integer_grid_tolerance = default_integer_grid_tolerance;   // grid units
  double grid_scale = 1;               // S = 2^s: the integer grid of the map is at multiples of 1/S; UVs are scaled by S inside
  std::vector<int> pinned_corners;     // halfedges (pipeline numbering) whose corner UV is kept bit-identical (pinned_corners.h)
  bool untangle = false;               // step 4b: remove fold-overs inside the constraint space (default: integer_grid_map)
  double max_untangle_change = HUGE_VAL;   // grid cells: an untangled map that moves a UV further is not used
  bool merge_cone_pairs = false;       // integer-grid mode: merge +-90 degree cone pairs rounded onto one point (cone_merging.h)
  bool separate_cone_pairs = false;    // integer-grid mode: move cone pairs rounded onto one point apart (cone_separation.h)
  bool quantize = false;               // integer-grid mode: a map not near an integer grid gets integer translations
                                       // chosen for it (integer_grid_quantization.h) instead of being refused
  bool untangle_polish = true;         // step 4b's minimal-change polish (untangler.h); off in the separation trials
  double untangle_budget = 1;          // step 4b's work budget, a fraction of Untangle_options::work_per_face; 1/2 in the trials
  unsigned threads = 1;                // >= 2: independent steps on two threads (internal/threads.h); the same results
};

// number of cut edges whose UV vector is zero on at least one side (the edge collapsed to a point
// in that face, which is then degenerate), corner values from `x`
inline std::size_t count_collapsed_cut_edges(const Corner_mesh& cm, const Seam_topology& st, const std::vector<double>& x)
{
  std::size_t n = 0;
  auto zero = [&](int h) {   // UV of target(h) == UV of source(h), both seen from face(h)
    const int a = st.sector_of[h], b = st.sector_of[cm.prev[h]];
    return x[2 * a] == x[2 * b] && x[2 * a + 1] == x[2 * b + 1];
  };
  for(int e : st.cut_edges) {
    const int h = cm.edge_halfedge[e];
    if(zero(h) || zero(cm.opp[h])) ++n;
  }
  return n;
}

// variables (2s + c) used by `rows`, in increasing order, and the inverse map (-1 = unused)
inline void used_variables(const Constraint_rows& rows, std::size_t n_vars, std::vector<int>& vars, std::vector<int>& column_of)
{
  column_of.assign(n_vars, -1);
  for(int c : rows.col) column_of[c] = 0;
  vars.clear();
  for(std::size_t i = 0; i < n_vars; ++i)
    if(column_of[i] >= 0) { column_of[i] = int(vars.size()); vars.push_back(int(i)); }
}

// The IRREF of a constraint system (an initialized Exact_constraint_projection), kept for the next projection of the
// same rows on the same grid: the snap of the untangled map projects the node system of the snap of the input again
// (the IRREF of the 302K-face bunny's node system, 4K nodes: about 3 % of its untangling and second snap)
struct Projection_cache
{
  Constraint_rows rows;                  // the system it was built for, compared in full
  int K = 0;
  bool minimal_change = false;
  std::vector<int> vars;                 // used_variables() of rows
  std::shared_ptr<const Exact_constraint_projection> projection;   // shared by copies of the state, never changed

  bool holds(const Constraint_rows& r, int k, bool mc) const
  {
    return projection != nullptr && K == k && minimal_change == mc && rows.start == r.start && rows.col == r.col &&
           rows.coef == r.coef && rows.rhs == r.rhs;
  }
};

// the projection of the values of x at vars by the initialized `projection`, written to x at vars
inline Status project_initialized(const Exact_constraint_projection& projection, const Fixed_point_grid& grid,
                                  const std::vector<int>& vars, std::vector<double>& x, Snap_report& report,
                                  std::string& message)
{
  std::vector<double> xbar(vars.size()), xs;
  for(std::size_t j = 0; j < vars.size(); ++j) xbar[j] = x[vars[j]];
  Projection_report pr = projection.project(xbar, xs);
  report.evaluate_ms = pr.project_ms;
  if(pr.status != SUCCESS) { message = "exact projection of the constraint system: " + pr.message; return pr.status; }
  if(pr.delta_exponent != grid.K) {
    message = "the projection used the grid 2^" + std::to_string(pr.delta_exponent) + " instead of 2^" + std::to_string(grid.K);
    return EXACTNESS_CHECK_FAILED;
  }
  for(std::size_t j = 0; j < vars.size(); ++j) x[vars[j]] = xs[j];
  return SUCCESS;
}

// Projects x onto {C x = b} for the rows `rows` (over sector variables, b = rows.rhs) with the core,
// on `grid` (the addendum's Eq. 2' when b != 0).
// Writes the constrained variables of x (others untouched). With a cache, an IRREF of the same rows on the same grid
// is reused (the report keeps the IRREF's numbers and time from when it was computed), and a new one is kept in it.
inline Status project_rows(const Constraint_rows& rows, const Fixed_point_grid& grid, bool minimal_change,
                           std::vector<double>& x, Snap_report& report, std::string& message, unsigned threads = 1,
                           Projection_cache* cache = nullptr)
{
  report.system_rows = rows.size();
  if(cache != nullptr && cache->holds(rows, grid.K, minimal_change)) {
    report.system_columns = cache->vars.size();
    return project_initialized(*cache->projection, grid, cache->vars, x, report, message);
  }
  std::vector<int> vars, column_of;
  used_variables(rows, x.size(), vars, column_of);
  std::vector<Eigen::Triplet<long> > triplets;
  triplets.reserve(rows.col.size());
  for(std::size_t i = 0; i < rows.size(); ++i)
    for(std::size_t k = rows.start[i]; k < rows.start[i + 1]; ++k)
      triplets.emplace_back(int(i), column_of[rows.col[k]], long(rows.coef[k]));
  report.system_columns = vars.size();

  Projection_options options;
  options.delta_exponent = grid.K;
  options.minimal_change = minimal_change;   // x is the L2-closest point of the full system (step 3a): the
                                             // core's own projection only refines how it is rounded
  options.fill_reducing_order = false;       // node systems are numbered by sectors, where the pivot rule fills in
                                             // little; with COLAMD's order (another choice of free variables) the
                                             // dragon's repair left 2 unforced degenerate triangles, not 0 (not
                                             // measured with the static degree order of column_ordering.h)
  options.number_of_threads = threads;       // the implied rows in two halves (the same bits)
  auto projection = std::make_shared<Exact_constraint_projection>(options);
  Status s = projection->initialize(rows.size(), vars.size(), triplets, rows.rhs);
  const Irref_statistics& stats = projection->statistics();
  report.irref_ms = stats.initialize_ms;
  if(s != SUCCESS) { message = "IRREF of the constraint system: " + projection->message(); return s; }
  report.free_variables = stats.free_variables;
  report.implied_variables = stats.implied_variables;
  report.max_abs_coefficient = stats.max_abs_coefficient;
  if(cache != nullptr) {
    cache->rows = rows;
    cache->K = grid.K;
    cache->minimal_change = minimal_change;
    cache->vars = vars;
    cache->projection = projection;
  }
  return project_initialized(*projection, grid, vars, x, report, message);
}


// The values of the grid F_delta (normalized UVs) scaled back to the caller's UV units by
// 2^uv_exponent must be doubles: the quantum 2^(K+E-52) at least the smallest subnormal 2^-1074 and
// delta = 2^(K+E) at most 2^1024. Otherwise the map is too close to the limits of double for an
// exact snap at its scale: RANGE_EXCEEDED.
inline Status check_grid_fits_uv_scale(const Fixed_point_grid& grid, int uv_exponent, std::string& message)
{
  const int K = grid.K + uv_exponent;
  if(grid.in_range && K - 52 >= -1074 && K <= 1024) return SUCCESS;
  if(!grid.in_range) {   // in the corner mesh's units (grid units with a grid scale other than 1, or pinned corners)
    message = grid.range_message() + ", in units of 2^" + std::to_string(uv_exponent) + " UV units (the grid scale or " +
              "the pinned corners set them); a grid scale nearer 1 keeps it in range";
    return RANGE_EXCEEDED;
  }
  message = "the UV map is too " + std::string(K - 52 < -1074 ? "small" : "large") + " for exact snapping in doubles: " +
            "its fixed-point grid F_delta (Sec. 4.3) has delta = 2^" + std::to_string(K) + " and quantum 2^" +
            std::to_string(K - 52) + " in UV units, but doubles need a quantum of at least 2^-1074 and delta of at most 2^1024; " +
            "scale the UVs by a power of 2 into the range of double";
  return RANGE_EXCEEDED;
}

// What the stages hand down, in data-flow order (each stage reads what the ones before it wrote).
template <class TriangleMesh>
struct Snap_state
{
  // 1. extract
  Corner_mesh cm;
  Corner_mesh_descriptors<TriangleMesh> desc;
  Seam_topology st;
  Cut_rotations rot;
  Align_edges al;
  Pinned_sectors pins;                   // the sectors of the pinned corners, their values in corner-mesh units
  Constraint_rows full;                  // every row (Eq. 4, 5, 6-8) over sector variables (2s + c)
  std::size_t first_connection_row = 0;
  std::vector<char> path_endpoints;      // vertices that end a connection/cycle path (become nodes)
  std::vector<int> constrained_vars;     // variables used by `full`, increasing
  std::vector<double> vertex_weights;    // per vertex, for step 3a (empty: all 1); larger = moves less
  std::vector<double> points;            // per vertex its 3D position (x, y, z), for step 4b (empty without untangling)
  std::vector<int> merged_valence;       // per vertex of a merged cone pair (Snap_options::merge_cone_pairs): its valence
                                         // in the quad mesh now (4: a regular point); 0 elsewhere
  std::vector<int> separation_rank;      // per vertex: the rank of the shift of the separated pair whose first cone it is
                                         // (solve_with_separation_trials()); empty: the shifts nearest to the input
  std::vector<Cone_separation> separations;   // Snap_options::separate_cone_pairs: the pairs moved apart
  std::vector<long> translations;        // integer-grid mode: the integer translation of every cut halfedge in grid units
                                         // (round_translations(), after merging and separating), 2 per halfedge
  std::vector<signed char> input_orientations;   // per face: orientation of its UV triangle in ubar (exact), for steps 4b, 5 and 5b
  Fixed_point_grid grid;                 // common F_delta of node and propagated values
  int grid_exponent = 0;                 // s of the grid scale 2^s (uv_exponent = -s when the corner mesh is in grid units,
                                         // less with pinned corners)
  // 2. reduce
  Reduced_system rs;
  Projection_cache node_projection;      // the IRREF of rs.node_rows, for the next snap of the same rows
  // 3a. the floating-point L2-closest point of the full system (= ubar without minimal_change)
  std::vector<double> start;
  // 3.-5. project, propagate, repair
  std::vector<double> x;                 // the result, one value per sector variable
  std::vector<double> oriented_x;        // the x of which x_orientations are the face orientations (orientations_of_x())
  std::vector<signed char> x_orientations;
  bool already_exact = false;            // ubar satisfies every row: x = ubar, nothing is written
  std::string flip_note;
  std::string untangle_note;
  std::vector<char> mirrored;            // 4b. per face: in a mirrored component, left alone by the untangling (empty: none)
  std::size_t collapsed_in_input = 0;    // cut edges of zero UV length on one side in ubar
  std::size_t written = 0;
};

// sector values x (corner-mesh scale) in grid units (the caller's UVs times the grid scale 2^s), for
// the integer-grid counts: x itself when the corner mesh is in grid units (uv_exponent = -s), else
// x * 2^(uv_exponent + s) (exact within the double range; the counts are diagnostics)
template <class TriangleMesh>
std::vector<double> in_grid_units(const Snap_state<TriangleMesh>& S, const std::vector<double>& x)
{
  const int e = S.cm.uv_exponent + S.grid_exponent;
  if(e == 0) return x;
  std::vector<double> g(x.size());
  for(std::size_t i = 0; i < x.size(); ++i) g[i] = scale_by_power_of_two(x[i], e);
  return g;
}

typedef Timing_clock Snap_clock;

// 1a. corner mesh, cut edges, sectors, cones, rotations k, align edges (Sec. 5, 5.1)
template <class TriangleMesh, class HalfedgeUVMap, class SeamOf, class RotationOf, class ConstrainedOf>
Status extract_seams(const TriangleMesh& tm, HalfedgeUVMap uvmap, const SeamOf& seam_of, bool has_seams,
                     const RotationOf& rotation_of, bool has_rotations,
                     const ConstrainedOf& constrained_of, bool has_constrained, const Snap_options& opt,
                     Snap_state<TriangleMesh>& S, Snap_report& report, std::string& message)
{
  int& grid_exponent = S.grid_exponent;   // the grid scale is 2^grid_exponent
  // the tolerances: finite and not negative (a NaN compared false everywhere: alignment_tolerance = NaN aligned nothing,
  // rotation_tolerance = NaN refused every map); max_untangle_change: not negative, +infinity (no bound) allowed
  const std::pair<const char*, double> tolerances[] = {{"alignment_tolerance", opt.alignment_tolerance},
                                                       {"rotation_tolerance", opt.rotation_tolerance},
                                                       {"max_untangle_change", opt.max_untangle_change}};
  for(const std::pair<const char*, double>& t : tolerances)
    if(!(t.second >= 0) || (std::isinf(t.second) && t.first != tolerances[2].first)) {
      message = std::string(t.first) + " = " + format_double(t.second, 17) + ": it must be " +
                (t.first == tolerances[2].first ? "a number >= 0 (or infinity: no bound)" : "a finite number >= 0");
      return INVALID_INPUT;
    }
  // the integer-grid options without integer_grid_map did nothing, and SUCCESS said nothing of it (the Python module
  // and the command line refuse them too)
  const std::pair<const char*, bool> grid_options[] = {{"merge_cone_pairs", opt.merge_cone_pairs},
                                                       {"separate_cone_pairs", opt.separate_cone_pairs},
                                                       {"quantize", opt.quantize}};
  for(const std::pair<const char*, bool>& g : grid_options)
    if(g.second && !opt.integer_grid_map) {
      message = std::string(g.first) + "(true) needs integer_grid_map(true): it acts on the integer translations and "
                "the cones' integer points of an integer-grid map";
      return INVALID_INPUT;
    }
  if(!grid_scale_exponent(opt.grid_scale, grid_exponent)) {
    message = "the grid scale " + format_double(opt.grid_scale, 17) + " is not a power of two, so it cannot be applied " +
              "exactly; use 2^j, or scale the map yourself";
    return INVALID_INPUT;
  }
  Status s = build_corner_mesh(tm, uvmap, S.cm, S.desc, message);
  // from here on: UVs times 2^-uv_exponent; for integer-grid maps (and any grid scale 2^s other than 1)
  // uv_exponent = -s, so the corner mesh holds the UVs in grid units and integer right-hand sides stay integers;
  // with pinned corners uv_exponent is at most the lowest bit of every pinned value, so that they are integers too
  int exponent = -grid_exponent, pin_exponent = 0;
  bool forced = opt.integer_grid_map || grid_exponent != 0;
  if(s == SUCCESS && pin_unit_exponent(S.cm, opt.pinned_corners, pin_exponent)) {
    exponent = (std::min)(forced ? exponent : natural_uv_exponent(S.cm), pin_exponent);
    forced = true;
  }
  if(s == SUCCESS) s = normalize_uv_scale(S.cm, message, forced ? &exponent : nullptr);
  if(s != SUCCESS) return s;
  const Corner_mesh& cm = S.cm;
  report.faces = std::size_t(cm.n_faces);

  std::vector<signed char> seam_override;
  std::vector<int> given_k;
  std::vector<char> constrained;
  if(has_seams) {
    seam_override.assign(cm.n_edges, -1);
    for(int e = 0; e < cm.n_edges; ++e) seam_override[e] = seam_of(S.desc.edges[e]) ? 1 : 0;
  }
  if(has_constrained) {
    constrained.assign(cm.n_edges, 0);
    for(int e = 0; e < cm.n_edges; ++e) constrained[e] = constrained_of(S.desc.edges[e]) ? 1 : 0;
  }
  s = compute_seam_topology(cm, seam_override, S.st, message, opt.threads);
  if(s != SUCCESS) return s;
  if(has_rotations) {
    given_k.assign(cm.n_edges, 0);
    for(int e : S.st.cut_edges) given_k[e] = int(rotation_of(S.desc.halfedges[cm.edge_halfedge[e]]));
  }
  s = fit_rotations(cm, S.st, given_k, opt.rotation_tolerance, S.rot, message);
  if(s != SUCCESS) return s;
  if(opt.integer_grid_map && opt.merge_cone_pairs) {
    // cone pairs on one integer point that no cut path near the point joins: a path through the mesh near it
    // becomes cut edges (rotation 0, continuous UVs), along which build_constraints() merges them
    const std::vector<int> added = cut_edges_to_add(cm, S.st, S.rot, in_grid_units(S, S.st.ubar), opt.integer_grid_tolerance,
                                                    reach_at_grid_scale(default_merge_cone_reach, opt.grid_scale));
    if(!added.empty()) {
      seam_override.assign(cm.n_edges, 0);
      given_k.assign(cm.n_edges, 0);
      for(int e : S.st.cut_edges) { seam_override[e] = 1; given_k[e] = S.rot.k[cm.edge_halfedge[e]]; }
      for(int e : added) seam_override[e] = 1;
      s = compute_seam_topology(cm, seam_override, S.st, message, opt.threads);
      if(s == SUCCESS) s = fit_rotations(cm, S.st, given_k, opt.rotation_tolerance, S.rot, message);
      if(s != SUCCESS) return s;
      report.added_cut_edges = added.size();
    }
  }
  collect_pinned_sectors(cm, S.st, opt.pinned_corners, S.pins);
  report.cut_edges = S.st.cut_edges.size();
  report.sectors = std::size_t(S.st.n_sectors);
  report.uv_diagonal = cm.to_uv(S.st.uv_diagonal);
  for(char c : S.st.is_cone) report.cones += c ? 1 : 0;
  s = find_align_edges(cm, S.st, opt.align_boundary, opt.alignment_tolerance, constrained, S.al, message);
  if(s != SUCCESS) return s;
  report.align_edges = S.al.edges.size();
  return SUCCESS;
}

// 1b. the full system (transitions, alignment, connections and cycles), input statistics, the grid
template <class TriangleMesh>
Status build_constraints(const Snap_options& opt, Snap_state<TriangleMesh>& S, Snap_report& report, std::string& message)
{
  const std::vector<double> ubar_grid = in_grid_units(S, S.st.ubar);
  const Integer_grid_counts before = count_integer_structure(S.cm, S.st, S.rot, ubar_grid);
  report.integer_translations_before = before.integer_translations;
  report.field_cones = before.field_cones;
  report.cones_on_integer_points_before = before.cones_on_integer_points;
  report.near_integer_grid_map = near_integer_structure(S.cm, S.st, S.rot, S.al, ubar_grid, 1e-6);
  std::vector<long>& translations = S.translations;   // integer-grid mode: rounded, changed by merging and separating
  std::vector<char> moved;                   // per vertex: on a path along which separating moved cones
  std::vector<int>& merged = S.merged_valence;
  merged.assign(S.cm.n_vertices, 0);
  if(opt.integer_grid_map) {
    // a map within one grid cell has at most one integer point in its UV bounding box: the cones (each on an integer
    // point in an integer-grid map) would all fall onto it (a map of 1e-300 UVs at grid scale 1 was "near" an
    // integer-grid map, every translation rounding to 0, and untangled for seconds to 147 negative triangles)
    const int e = S.cm.uv_exponent + S.grid_exponent;
    const double w = scale_by_power_of_two(S.st.uv_max[0] - S.st.uv_min[0], e);
    const double h = scale_by_power_of_two(S.st.uv_max[1] - S.st.uv_min[1], e);
    // With fewer cones the same holds for the translations: a period of a map smaller than a cell is about as large as
    // the map, and rounding it to an integer collapses the map (the hex torus scaled by 1e-7: all 67 rounded to 0, 220
    // negative triangles, 34 left after the untangling, reported as SUCCESS). Counted: translations that the rounding
    // moves by more than 1e-3 of the map's extent (not the noise of a seam whose translation is 0 up to 1e-13)
    std::size_t inexact = 0;
    if(w < 1 && h < 1)
      for(int c_e : S.st.cut_edges) {
        double t[2];
        translation(S.cm, S.st, S.rot, S.cm.edge_halfedge[c_e], true, ubar_grid, t);
        if(std::fabs(t[0] - std::nearbyint(t[0])) > 1e-3 * (std::max)(w, h) ||
           std::fabs(t[1] - std::nearbyint(t[1])) > 1e-3 * (std::max)(w, h)) ++inexact;
      }
    if(w < 1 && h < 1 && (report.field_cones >= 2 || inexact > 0)) {
      message = "the map spans less than one grid cell (its UV bounding box is " + format_double(w) + " x " +
                format_double(h) + " grid units) but has " + (report.field_cones >= 2
                  ? std::to_string(report.field_cones) + " cones, which an integer-grid map puts on integer points: they " +
                    "would all fall onto one point"
                  : std::to_string(inexact) + " cut edges whose translations are off the integers by more than 1e-3 of "
                    "its size, which an integer-grid map rounds: the map would collapse") +
                "; scale the map up (grid_scale / --grid-scale 2^k)";
      return INVALID_INPUT;
    }
    // quantize(true) and a map not near an integer-grid map (a translation, a cone or an align edge off the integers):
    // integer translations chosen for it instead of rounded
    report.quantized = opt.quantize && !near_integer_structure(S.cm, S.st, S.rot, S.al, ubar_grid, opt.integer_grid_tolerance);
    const double merge_reach = reach_at_grid_scale(default_merge_cone_reach, opt.grid_scale);
    const Status rounded = report.quantized ? quantize_translations(S.cm, S.st, S.rot, S.al, ubar_grid,
                                                                    opt.merge_cone_pairs ? merge_reach : 0., translations,
                                                                    message)
                                            : round_translations(S.cm, S.st, S.rot, ubar_grid, opt.integer_grid_tolerance,
                                                                 translations, message, opt.grid_scale, &S.al);
    if(rounded != SUCCESS) return rounded;
    if(opt.merge_cone_pairs)
      for(const Cone_merge& m : merge_collapsed_cone_pairs(S.cm, S.st, S.rot, translations, ubar_grid, merge_reach)) {
        report.merged_cone_pairs.emplace_back(std::size_t(m.a), std::size_t(m.b));
        report.merged_cut_edges += m.path.size();
        merged[m.a] = 4;
        merged[m.b] = m.b_valence;
        report.field_cones -= m.b_valence % 4 == 0 ? 2 : 1;
        report.joined_cone_pairs += m.b_valence % 4 == 0 ? 0 : 1;
      }
    if(opt.separate_cone_pairs) {
      moved.assign(S.cm.n_vertices, 0);
      S.separations = separate_collapsed_cone_pairs(S.cm, S.st, S.rot, translations, ubar_grid,
                                                    reach_at_grid_scale(default_separate_cone_reach, opt.grid_scale),
                                                    S.separation_rank);
      for(const Cone_separation& c : S.separations) {
        report.separated_cone_pairs.emplace_back(std::size_t((std::min)(c.a, c.b)), std::size_t((std::max)(c.a, c.b)));
        report.separated_cut_edges += c.path.size();
        moved[std::size_t(c.a)] = 1;
        for(int h : c.path) moved[std::size_t(S.cm.target[h])] = 1;   // b, and cones on the point that the path passes
      }
    }
  }
  build_full_system(S.cm, S.st, S.rot, S.al, S.full);
  S.first_connection_row = S.full.size();
  Status s = add_connection_rows(S.cm, S.st, S.rot, opt.connections, S.full, S.path_endpoints, message);
  if(s != SUCCESS) return s;
  mark_pinned_nodes(S.cm, S.st, S.pins, S.path_endpoints);
  if(opt.integer_grid_map) {
    Integer_grid_rows_result igm;
    // a quantized map's cones move to the points its translations give them, its align edges to the nearest isolines
    s = add_integer_grid_rows(S.cm, S.st, S.rot, S.al, ubar_grid, translations, -(S.cm.uv_exponent + S.grid_exponent),
                              report.quantized ? HUGE_VAL : opt.integer_grid_tolerance, S.full, igm, message, moved,
                              opt.grid_scale);
    const int finest = finest_pinned_corner(S.pins);
    if(s == RANGE_EXCEEDED && finest >= 0) {           // the unit of the rows is that pin's lowest bit: name it
      const std::size_t end = message.rfind("; nothing was written");
      message.insert(end == std::string::npos ? message.size() : end, " (the finest bits are those of " +
                     pinned_corner_name(S.cm, finest) + ", its UV " + uv_name(S.cm, finest) + ")");
    }
    if(s != SUCCESS) return s;
    if(!S.full.contradictions.empty()) {
      message = "integer-grid row of " + row_origin_name(S.cm, S.full.contradictions.front()) +
                " reads 0 = b != 0 (both sides of the cut edge are one sector); nothing was written";
      return INFEASIBLE;
    }
    report.pinned_cones = igm.cones.size();
    for(int v : igm.not_field_cones) if(!merged[v]) report.not_field_cones.push_back(std::size_t(v));
  }
  s = add_pinned_rows(S.cm, S.pins, S.full, message);
  if(s != SUCCESS) return s;
  report.pinned_sectors = S.pins.sector.size();
  report.constraints = S.full.size();
  std::vector<int> column_of;
  used_variables(S.full, 2 * std::size_t(S.st.n_sectors), S.constrained_vars, column_of);
  std::vector<char> sector_used(S.st.n_sectors, 0);
  for(int v : S.constrained_vars) sector_used[v / 2] = 1;
  for(char c : sector_used) report.constrained_sectors += c ? 1 : 0;

  const std::vector<double>& ubar = S.st.ubar;
  const double diagonal = S.st.uv_diagonal;
  const double violation = max_abs_residual(S.full, ubar);
  report.max_input_violation = diagonal > 0 ? violation / diagonal : violation;
  double max_abs = 0;
  for(int v : S.constrained_vars) max_abs = (std::max)(max_abs, std::fabs(ubar[v]));
  S.grid = Fixed_point_grid::from_max_abs(max_abs, 1);   // may grow on RANGE_EXCEEDED (project_stage)
  s = check_pins_on_grid(S.cm, S.pins, S.grid, message);
  if(s != SUCCESS) return s;
  S.input_orientations = face_orientations(S.cm);   // = face_orientations(S.cm, S.st, ubar)
  const Orientation_counts input = count_orientations(S.input_orientations);
  report.flips_before = input.negative;
  report.degenerate_before = input.degenerate;
  S.collapsed_in_input = count_collapsed_cut_edges(S.cm, S.st, ubar);
  return SUCCESS;
}

// 1c. the weights of step 3a, per vertex: positive and finite
template <class TriangleMesh, class WeightOf>
Status read_vertex_weights(const WeightOf& weight_of, Snap_state<TriangleMesh>& S, std::string& message)
{
  S.vertex_weights.resize(S.desc.vertices.size());
  for(std::size_t v = 0; v < S.desc.vertices.size(); ++v) {
    S.vertex_weights[v] = double(weight_of(S.desc.vertices[v]));
    if(!(std::isfinite(S.vertex_weights[v]) && S.vertex_weights[v] > 0)) {
      message = "vertex_weight_map: the weight of vertex " + std::to_string(v) + " is " +
                format_double(S.vertex_weights[v], 17) + ", not a positive finite number";
      return INVALID_INPUT;
    }
  }
  return SUCCESS;
}

// 1d. the 3D position of every vertex, for the reference shapes of the untangling (step 4b)
template <class TriangleMesh, class PointOf>
void read_vertex_points(const PointOf& point_of, Snap_state<TriangleMesh>& S)
{
  S.points.resize(3 * S.desc.vertices.size());
  for(std::size_t v = 0; v < S.desc.vertices.size(); ++v) {
    const std::array<double, 3> p = point_of(S.desc.vertices[v]);
    for(int c = 0; c < 3; ++c) S.points[3 * v + std::size_t(c)] = p[std::size_t(c)];
  }
}

// 2. nodes, branches and the node system (Sec. 5.3), connection rows reduced to node variables
template <class TriangleMesh>
Status reduce_stage(Snap_state<TriangleMesh>& S, Snap_report& report, std::string& message)
{
  build_reduced_system(S.cm, S.st, S.rot, S.al, S.rs, S.path_endpoints);
  Status s = add_reduced_connection_rows(S.cm, S.st, S.full, S.first_connection_row, S.rs, message);
  if(s != SUCCESS) { message = "node system: " + message; return s; }
  report.nodes = S.rs.n_nodes;
  report.cut_branches = S.rs.cut_branches.size();
  report.align_branches = S.rs.align_branches.size();
  return SUCCESS;
}

// 3a. y = argmin sum_s w_s |u_s - ubar_s|^2 s.t. every row of the full system (Eq. 4, 5, 6-8), in
// floating point (least_squares_projection.h); w_s = the weight of the sector's vertex. Only values
// change: the cut graph, the sectors and the rotations stay those of the input.
template <class TriangleMesh>
Status least_squares_stage(const Snap_options& opt, Snap_state<TriangleMesh>& S, Snap_report& report, std::string& message)
{
  S.start = S.st.ubar;
  if(!opt.minimal_change || S.full.size() == 0) return SUCCESS;
  const Snap_clock::time_point t = Snap_clock::now();
  const std::vector<int>& vars = S.constrained_vars;
  std::vector<int> column_of(S.start.size(), -1);
  for(std::size_t j = 0; j < vars.size(); ++j) column_of[vars[j]] = int(j);
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(S.full.col.size());
  for(std::size_t i = 0; i < S.full.size(); ++i)
    for(std::size_t k = S.full.start[i]; k < S.full.start[i + 1]; ++k)
      entries.emplace_back(int(i), column_of[S.full.col[k]], double(S.full.coef[k]));
  Least_squares_projection::Matrix C(Eigen::Index(S.full.size()), Eigen::Index(vars.size()));
  C.setFromTriplets(entries.begin(), entries.end());
  std::vector<double> weights;
  if(!S.vertex_weights.empty()) {
    std::vector<double> sector_weight(S.st.n_sectors, 1.);
    for(int h = 0; h < S.cm.n_halfedges; ++h)
      if(S.st.sector_of[h] >= 0) sector_weight[S.st.sector_of[h]] = S.vertex_weights[S.cm.target[h]];
    for(int v : vars) weights.push_back(sector_weight[v / 2]);
  }
  Least_squares_projection ls;
  Status s = ls.initialize(C, weights, message);
  if(s != SUCCESS) { message = "minimal-change projection: " + message; return s; }
  std::vector<double> xbar(vars.size()), y;
  for(std::size_t j = 0; j < vars.size(); ++j) xbar[j] = S.st.ubar[vars[j]];
  // b: the right-hand sides (integer-grid rows, pinned corners), integers in corner-mesh units, exact in double
  const std::vector<double> b(S.full.rhs.begin(), S.full.rhs.end());
  ls.project(b, xbar, y);
  for(std::size_t j = 0; j < vars.size(); ++j) S.start[vars[j]] = y[j];
  report.least_squares_ms = ms_since(t);
  return SUCCESS;
}

// 3.+4. the node system through the core on `S.grid`, then the non-node sectors along the branches
// (Sec. 5.3.1), both from S.start. Node sectors used by the propagation but absent from C (e.g. the
// node of a closed loop, whose node rows cancel) are free: rounded to the grid.
template <class TriangleMesh>
Status project_node_system(Snap_state<TriangleMesh>& S, bool minimal_change, Snap_report& report, std::string& message,
                           unsigned threads)
{
  const Reduced_system& rs = S.rs;
  const std::vector<double>& start = S.start;
  Status s = project_rows(rs.node_rows, S.grid, minimal_change, S.x, report, message, threads, &S.node_projection);
  if(s != SUCCESS) { message = "node system: " + message; return s; }
  std::vector<int> node_vars, node_column_of;
  used_variables(rs.node_rows, S.x.size(), node_vars, node_column_of);
  int off_grid = -1;    // a free node variable whose input is outside (-delta, delta)
  auto fix_free_node_var = [&](int var) {
    if(node_column_of[var] >= 0 || node_column_of[var] == -2) return;
    S.x[var] = S.grid.round(start[var]);
    node_column_of[var] = -2;
    if(off_grid < 0 && !S.grid.contains(S.x[var])) off_grid = var;
  };
  for(const Cut_branch_plan& p : rs.cut_branches)
    for(int c = 0; c < 2; ++c) { fix_free_node_var(2 * p.u0_plus + c); fix_free_node_var(2 * p.u0_minus + c); }
  for(const Align_branch_plan& p : rs.align_branches) fix_free_node_var(2 * p.u0 + p.component);
  if(off_grid >= 0) {
    message = "node sector " + std::to_string(off_grid / 2) + " (vertex " + std::to_string(S.st.sector_vertex(S.cm, off_grid / 2)) +
              ") is in no row of the node system, and its input value " + format_double(S.cm.to_uv(start[off_grid]), 17) +
              " (UV units) lies outside the fixed-point range (-delta, delta) of the constrained values, delta = 2^" +
              std::to_string(S.grid.K);
    return RANGE_EXCEEDED;
  }
  const Snap_clock::time_point t = Snap_clock::now();
  s = propagate_along_branches(rs, start, S.grid, S.x, message, minimal_change);
  report.propagate_ms = ms_since(t);
  if(s != SUCCESS) message = "propagation: " + message;
  return s;
}

// 3.-4. from S.start (the input, its L2-closest point, or the untangled map), with retries:
// RANGE_EXCEEDED is retried on a grid with 4 more bits of range (up to 5 times): constraints that the
// input violates by a lot (connection and cycle constraints added after the fact) move implied values
// further than the margin of Sec. 4.3 allows.
template <class TriangleMesh>
Status snap_from_start(const Snap_options& opt, Snap_state<TriangleMesh>& S, Snap_report& report, std::string& message)
{
  auto failed = [&](Status st) {   // the grid of the messages is that of the normalized UVs
    if(st == INFEASIBLE) message += pinned_infeasible_hint(S.cm, S.pins);
    if(st == INFEASIBLE && report.quantized && !S.al.edges.empty() && S.pins.empty())
      message += "; the map was quantized (quantize(true)) and has " + std::to_string(S.al.edges.size()) + " align edges: "
                 "the quantization puts each cone on the isolines of the aligned chains through it where it can, but "
                 "the last cone of each part of the cut graph and the translations rounded on its cycles take what the "
                 "others leave; snap without the alignment (no feature edges, align_boundary(false)) or at another grid "
                 "scale";
    if(S.cm.uv_exponent != 0)
      message += " (delta and grid values refer to the UVs scaled by 2^" + std::to_string(-S.cm.uv_exponent) + ")";
    return st;
  };
  Status s = SUCCESS;
  for(int retry = 0;; ++retry) {
    S.x = S.start;
    s = opt.use_reduced_system ? project_node_system(S, opt.minimal_change, report, message, opt.threads)
                               : project_rows(S.full, S.grid, opt.minimal_change, S.x, report, message, opt.threads);
    if(s != SUCCESS && !opt.use_reduced_system) message = "full system: " + message;
    if(s != RANGE_EXCEEDED || retry == 5) return s == SUCCESS ? s : failed(s);
    S.grid = Fixed_point_grid(S.grid.K + 4);
    std::string why;
    if(check_grid_fits_uv_scale(S.grid, S.cm.uv_exponent, why) != SUCCESS ||
       check_pins_on_grid(S.cm, S.pins, S.grid, why) != SUCCESS) {
      failed(s);
      message += "; a larger grid does not help: " + why;
      return s;
    }
  }
}

// the start of 3.-4.: ubar, or its L2-closest point (3a); nothing to do for an input that is already exact. Needs
// neither the node system nor anything reduce_stage() writes: solve_stages() runs the two together
template <class TriangleMesh>
Status start_stage(const Snap_options& opt, Snap_state<TriangleMesh>& S, Snap_report& report, std::string& message)
{
  S.x = S.st.ubar;
  S.already_exact = first_violated_row(S.full, S.st.ubar) < 0;
  if(S.already_exact) return SUCCESS;
  const Status s = check_grid_fits_uv_scale(S.grid, S.cm.uv_exponent, message);
  if(s != SUCCESS) return s;
  return least_squares_stage(opt, S, report, message);
}

// 3.-4. from the start of start_stage(), see snap_from_start()
template <class TriangleMesh>
Status project_stage(const Snap_options& opt, Snap_state<TriangleMesh>& S, Snap_report& report, std::string& message)
{
  if(S.already_exact) {     // nothing to project, nothing to write
    const Constraint_rows& system = opt.use_reduced_system ? S.rs.node_rows : S.full;
    std::vector<int> system_vars, system_column_of;
    used_variables(system, 2 * std::size_t(S.st.n_sectors), system_vars, system_column_of);
    report.system_rows = system.size();
    report.system_columns = system_vars.size();
    return SUCCESS;
  }
  return snap_from_start(opt, S, report, message);
}

// the change from `b` to `a` (2 values per sector) in UV units: its largest magnitude, its RMS over all
// sector coordinates and the number of sectors that moved
struct Uv_change
{
  double max = 0, rms = 0;
  std::size_t moved_sectors = 0;
};

template <class TriangleMesh>
Uv_change measure_uv_change(const Snap_state<TriangleMesh>& S, const std::vector<double>& a, const std::vector<double>& b)
{
  // summed in corner-mesh units (normalized), then scaled: the same bits as in the caller's units wherever those neither
  // overflow nor underflow, and an RMS for maps scaled by 2^-500 (it was 0 next to a positive max) or 2^1000 (NaN)
  Uv_change c;
  double sum = 0, max = 0;
  for(std::size_t i = 0; i < a.size(); ++i) {
    const double d = std::fabs(a[i] - b[i]);
    max = (std::max)(max, d);
    sum += d * d;
    if(i % 2 == 1 && (a[i] != b[i] || a[i - 1] != b[i - 1])) ++c.moved_sectors;
  }
  c.max = S.cm.to_uv(max);
  c.rms = a.empty() ? 0. : S.cm.to_uv(std::sqrt(sum / double(a.size())));
  return c;
}

// per face: positively oriented in the input (exact test, step 2)
template <class TriangleMesh>
std::vector<char> input_positive_faces(const Snap_state<TriangleMesh>& S)
{
  const std::vector<signed char>& o = S.input_orientations;
  std::vector<char> positive(o.size());
  for(std::size_t f = 0; f < o.size(); ++f) positive[f] = o[f] == CGAL::POSITIVE ? 1 : 0;
  return positive;
}

// per vertex: the angle sum in quarter turns a locally injective map has there (vertex_windings.h); at the cones of
// merged pairs, the valence the merge gave them (4: a regular point of the field; at a joined cone any other member
// of its class of at least 2 as well). K: field_rotation_sums() of S
template <class TriangleMesh>
Target_valences target_valences(const Snap_state<TriangleMesh>& S, const Face_corners& fc, const std::vector<int>& K)
{
  Target_valences target = vertex_valences(S.cm, K, S.st.quarter_turns, input_positive_faces(S), S.points, fc.halfedge);
  for(std::size_t v = 0; v < S.merged_valence.size(); ++v)
    if(S.merged_valence[v] != 0) {
      target.valence[v] = S.merged_valence[v];
      target.any_in_class[v] = S.merged_valence[v] != 4;
    }
  return target;
}

// face_orientations() of S.x (exact), computed again only when S.x changed since the last call
template <class TriangleMesh>
const std::vector<signed char>& orientations_of_x(Snap_state<TriangleMesh>& S)
{
  if(S.oriented_x.empty() || S.oriented_x != S.x) {
    S.x_orientations = face_orientations(S.cm, S.st, S.x);
    S.oriented_x = S.x;
  }
  return S.x_orientations;
}

// the faces whose UV triangle is not positively oriented, from their orientations `o`
inline std::vector<int> non_positive_faces(const std::vector<signed char>& o)
{
  std::vector<int> faces;
  for(std::size_t f = 0; f < o.size(); ++f) if(o[f] != CGAL::POSITIVE) faces.push_back(int(f));
  return faces;
}

// integer-grid mode: the collapsed cone pairs of the map S.x (collapsed_cone_pairs(), cone_merging.h)
template <class TriangleMesh>
std::vector<std::pair<int, int> > collapsed_cone_pairs_of_x(const Snap_state<TriangleMesh>& S)
{
  return collapsed_cone_pairs(S.cm, S.st, S.rot, S.translations, in_grid_units(S, S.x), default_collapsed_cone_reach);
}

// 4b. untangling (beyond the paper: Sec. 5.4 and 7 repair only what the snap introduces): the faces of
// the exact map S.x that are not positive, unless proven so in every exact solution (forced_folds.h),
// are made positive by moving the UVs near them inside the constraint space, in floating point
// (untangler.h); the result is snapped exactly like the input (3.-4. from it) and checked like it.
// Not used (S.x stays the snap of the input) when it moved a UV more than max_untangle_change grid cells.
template <class TriangleMesh>
Status untangle_stage(const Snap_options& opt, Snap_state<TriangleMesh>& S, Snap_report& report, std::string& message)
{
  report.untangle = opt.untangle;
  report.grid_scale = opt.grid_scale;
  const Orientation_counts snapped = count_orientations(orientations_of_x(S));
  report.flips_before_untangling = report.flips_after_untangling = snapped.negative;
  report.degenerate_before_untangling = report.degenerate_after_untangling = snapped.degenerate;
  const Uv_change snap = measure_uv_change(S, S.x, S.st.ubar);
  report.snap_max_change = snap.max;
  report.snap_rms_change = snap.rms;
  S.mirrored.clear();
  report.uv_mirrored = false;
  if(!opt.untangle && snapped.negative == 0) return SUCCESS;
  // the mirrored components (mirrored_components.h) and the closed parts without cut edges (closed_uncut_parts.h), which
  // fold in every map: left alone, faces and windings
  const Face_corners fc(S.cm);
  const std::vector<int> non_positive = non_positive_faces(orientations_of_x(S));
  const std::vector<int> closed = closed_uncut_part_sizes(S.cm, S.st, fc, non_positive);
  std::size_t mirrored_faces = 0, mirrored_negative = 0;
  if(snapped.negative > 0) {
    const std::vector<signed char>& o = orientations_of_x(S);   // (each call compares x with the x of its cache)
    S.mirrored = mirrored_component_faces(S.cm, o, closed);
    for(std::size_t f = 0; f < S.mirrored.size(); ++f)
      if(S.mirrored[f]) { ++mirrored_faces; mirrored_negative += o[f] == CGAL::NEGATIVE ? 1 : 0; }
    if(mirrored_faces == 0) S.mirrored.clear();
  }
  report.uv_mirrored = mirrored_faces > 0;
  auto left_alone = [&](std::size_t f) { return closed[f] > 0 || (!S.mirrored.empty() && S.mirrored[f]); };
  if(report.uv_mirrored && opt.untangle)
    S.untangle_note = (mirrored_faces == std::size_t(S.cm.n_faces)
                           ? "; the untangling did not run: the map is mirrored (" + std::to_string(mirrored_negative) +
                             " of its " + std::to_string(mirrored_faces) + " UV triangles are negative): "
                           : "; the untangling left the mirrored parts of the map alone (connected components with more "
                             "negative than positive UV triangles: " + std::to_string(mirrored_negative) + " of their " +
                             std::to_string(mirrored_faces) + " are negative): ") + mirrored_map_advice();
  if(!opt.untangle) return SUCCESS;
  Target_valences target = target_valences(S, fc, field_rotation_sums(S.cm, S.st, S.rot));
  const std::vector<int> turns = vertex_quarter_turns(S.cm, S.st, S.x, orientations_of_x(S));
  auto wound_at = [&](int v) { return target.wound(std::size_t(v), turns[std::size_t(v)]); };
  std::vector<char> from_3d(std::size_t(S.cm.n_faces), 0);
  for(std::size_t f = 0; f < fc.halfedge.size(); ++f)
    for(int h : fc.halfedge[f])
      if(wound_at(S.cm.target[h])) from_3d[f] = 1;
  // the windings within 2 face rings of a cone pair that the integer translations collapse onto one point
  // (collapsed_cone_pairs(), those near the wrongly wound vertices and the vertices of non-positive faces) are not
  // targets: no move separates the cones
  std::size_t wound = 0;
  if(opt.integer_grid_map) {
    std::vector<int> seeds;
    for(int v = 0; v < S.cm.n_vertices; ++v) if(wound_at(v)) seeds.push_back(v);
    for(int f : non_positive) for(int h : fc.halfedge[std::size_t(f)]) seeds.push_back(S.cm.target[h]);
    const std::vector<std::pair<int, int> > pairs = collapsed_cone_pairs_near(S.cm, fc, collapsed_cone_pairs_of_x(S), seeds);
    for(int v : vertices_near_collapsed_cones(S.cm, fc, pairs, 2)) target.valence[std::size_t(v)] = 0;
  }
  for(std::size_t f = 0; f < closed.size(); ++f)
    if(left_alone(f)) for(int h : fc.halfedge[f]) target.valence[std::size_t(S.cm.target[h])] = 0;
  std::size_t targets = 0;                                     // non-positive faces to untangle
  for(int f : non_positive) targets += left_alone(std::size_t(f)) ? 0 : 1;
  for(int v = 0; v < S.cm.n_vertices; ++v) wound += wound_at(v) ? 1 : 0;
  if(targets + wound == 0) return SUCCESS;
  const Snap_clock::time_point t = Snap_clock::now();
  report.untangled = true;
  const Variable_rows incidence(S.full, S.x.size());
  std::vector<char> excluded(std::size_t(S.cm.n_faces), 0);   // proven non-positive in every solution, or left alone
  for(std::size_t f = 0; f < closed.size(); ++f) excluded[f] = left_alone(f) ? 1 : 0;
  Forced_fold_prover prover(S.cm, S.st, S.full, fc, incidence);
  for(const Fold_explanation& e : prover.explain(non_positive, S.x)) excluded[e.face] |= e.forced() ? 1 : 0;
  const std::vector<Reference_triangle> refs = reference_triangles(S.cm, S.st, fc, S.st.ubar, S.points, from_3d);
  Untangler untangler(S.cm, S.st, S.full, fc, refs, excluded, target);
  std::vector<double> y = S.x;
  Untangle_statistics stats;
  Untangle_options untangle_options;
  untangle_options.polish = opt.untangle_polish;
  untangle_options.work_per_face *= opt.untangle_budget;
  untangle_options.threads = opt.threads;
  Status s = untangler.run(y, untangle_options, stats, message, &turns);
  if(s != SUCCESS) return s;
  report.untangle_rings = stats.rings;
  report.untangle_polish_ms = stats.polish_ms;
  report.untangle_attempts = stats.attempts;
  report.untangle_newton_steps = stats.newton_steps;
  report.untangle_polish_steps = stats.polish_steps;
  report.untangle_budget_spent = stats.budget_spent;
  report.untangle_region_vertices = stats.region_vertices;
  const Orientation_counts untangled = count_orientations(face_orientations(S.cm, S.st, y));
  report.flips_after_untangling = untangled.negative;
  report.degenerate_after_untangling = untangled.degenerate;
  const Uv_change move = measure_uv_change(S, y, S.x);
  report.untangle_max_change = move.max;
  report.untangle_rms_change = move.rms;
  report.untangle_moved_sectors = move.moved_sectors;
  report.untangle_ms = ms_since(t);
  if(move.max * opt.grid_scale > opt.max_untangle_change) {
    report.untangle_refused = true;
    S.untangle_note = "; the untangled map was not used: it moved a UV by " + format_double(move.max * opt.grid_scale) +
                      " grid cells, more than max_untangle_change = " + format_double(opt.max_untangle_change);
    return SUCCESS;
  }
  if(move.moved_sectors == 0) return SUCCESS;
  // the untangled map, snapped exactly (on failure the snap of the input stays, and the message says so)
  const std::vector<double> x_snap = S.x;
  const Fixed_point_grid grid = S.grid;
  std::string why;
  s = check_grid_fits_uv_scale(S.grid, S.cm.uv_exponent, why);
  S.start = y;
  if(s == SUCCESS) s = snap_from_start(opt, S, report, why);
  if(s != SUCCESS) {
    S.x = x_snap;
    S.grid = grid;
    report.untangle_refused = true;
    S.untangle_note = "; the untangled map was not used: its exact snap failed (" + std::string(status_name(s)) + ": " + why + ")";
  } else {
    S.already_exact = false;
  }
  report.untangle_ms = ms_since(t);
  return SUCCESS;
}

// 5. flip repair (Sec. 5.4, generalized): moves that keep every row exact, each checked exactly
template <class TriangleMesh>
void repair_stage(const Snap_options& opt, Snap_state<TriangleMesh>& S, Snap_report& report)
{
  const std::vector<signed char>& input = S.input_orientations;
  const std::vector<signed char>& snapped = orientations_of_x(S);
  const Orientation_counts after = count_orientations(snapped), introduced = count_orientations(snapped, &input);
  report.flips_after = report.flips_after_repair = after.negative;
  report.degenerate_after = report.degenerate_after_repair = after.degenerate;
  report.flips_introduced = report.flips_unrepaired = introduced.negative;
  report.degenerate_introduced = report.degenerate_unrepaired = introduced.degenerate;
  if(!opt.repair_flips || S.already_exact) return;
  const Snap_clock::time_point t = Snap_clock::now();
  const Flip_repair_result fr = repair_flips(S.cm, S.st, S.rs, S.full, S.grid, S.st.ubar, S.x, &input, &snapped);
  report.repair_ms = ms_since(t);
  report.flips_after_repair = fr.after.negative;
  report.degenerate_after_repair = fr.after.degenerate;
  report.flips_unrepaired = fr.introduced_after.negative;
  report.degenerate_unrepaired = fr.introduced_after.degenerate;
  report.repair_moves = fr.moves;
  report.repair_node_moves = fr.node_moves;
  report.repair_cluster_moves = fr.cluster_moves;
  report.repair_relaxed_moves = fr.relaxed_moves;
  report.degenerate_forced = fr.forced_degenerate;
  if(!fr.unrepaired_faces.empty()) {
    S.flip_note = "; " + std::to_string(fr.introduced_after.negative) + " flipped and " +
                  std::to_string(fr.introduced_after.degenerate) +
                  " degenerate UV triangle(s) introduced by snapping could not be repaired (faces";
    S.flip_note += first_ten(fr.unrepaired_faces, [](int f) { return std::to_string(f); }) + ")";
    S.flip_note += "; " + fr.reasons;
  }
}

// 5b. every UV triangle of the result that is not positive, explained: proven non-positive in every
// exact solution of the constraints (forced_folds.h), or not (never a SUCCESS that hides a fold-over)
template <class TriangleMesh>
void explain_folds_stage(const Snap_options& opt, Snap_state<TriangleMesh>& S, Snap_report& report)
{
  const std::vector<signed char>& orientations = orientations_of_x(S);
  const std::vector<int> faces = non_positive_faces(orientations);
  if(faces.empty() && !opt.untangle) return;   // windings are checked where the untangling ran or folds remain
  const Face_corners fc(S.cm);
  const std::vector<std::pair<int, int> > pairs =
      opt.integer_grid_map ? collapsed_cone_pairs_of_x(S) : std::vector<std::pair<int, int> >();
  std::set<std::pair<int, int> > collapsed;   // the cone pairs within coincident_cone_rings of a defect
  auto name_collapsed_pairs = [&](int v, std::string& message) {   // the nearest few within coincident_cone_rings of v
    std::vector<int> rings;
    const std::vector<std::pair<int, int> > near = collapsed_cone_pairs_near(S.cm, fc, pairs, {v}, &rings);
    const std::size_t named = (std::min)(near.size(), named_collapsed_pairs);
    for(std::size_t i = 0; i < near.size(); ++i) {
      collapsed.insert(std::minmax(near[i].first, near[i].second));
      if(i < named)
        message += "; the cones at vertices " + std::to_string(near[i].first) + " and " + std::to_string(near[i].second) +
                   " nearby (" + (rings[i] == 0 ? "one of them is vertex " + std::to_string(v) :
                                  std::to_string(rings[i]) + " face ring" + (rings[i] == 1 ? "" : "s") + " away") + ") are " +
                   "rounded onto one integer point (a cone pair the integer translations collapse)";
    }
    if(near.size() > named) message += more_collapsed_pairs_clause(near.size()) + " (Snap_report::collapsed_cone_pairs)";
  };
  // the closed parts without cut edges, where every map folds (closed_uncut_parts.h), with the size of each
  const std::vector<int> closed = closed_uncut_part_sizes(S.cm, S.st, fc, faces);
  for(int size : closed) report.closed_uncut_faces += size > 0 ? 1 : 0;
  std::vector<int> closed_part_of(std::size_t(S.cm.n_vertices), 0);   // per vertex: the size of its closed uncut part
  for(std::size_t f = 0; f < closed.size(); ++f)
    if(closed[f] > 0) for(int h : fc.halfedge[f]) closed_part_of[std::size_t(S.cm.target[h])] = closed[f];
  std::vector<int> forced_face(std::size_t(S.cm.n_vertices), -1);   // per vertex: a face proven non-positive at it
  // the proofs of the faces (this thread) and the windings of the vertices share nothing either writes: on two threads
  // with number_of_threads >= 2
  Target_valences target;
  std::vector<int> turns, K;
  run_concurrently(opt.threads, [&] {
    if(!faces.empty()) {
      const Variable_rows incidence(S.full, S.x.size());
      Forced_fold_prover prover(S.cm, S.st, S.full, fc, incidence);
      report.folds = prover.explain(faces, S.x);
      for(Fold_explanation& e : report.folds) {
        if(e.forced()) {
          ++report.folds_forced;
          for(std::size_t v : e.vertices) if(forced_face[v] < 0) forced_face[v] = int(e.face);
          continue;
        }
        if(closed[e.face] > 0) { e.message = closed_uncut_part_reason(closed[e.face]); continue; }
        if(!opt.untangle) e.message = "not proven forced by the constraints; untangling was not asked for (untangle(true))";
        else if(!S.mirrored.empty() && S.mirrored[e.face])
          e.message = "not proven forced by the constraints; it lies in a mirrored part of the map (a connected component "
                      "with more negative than positive UV triangles), which the untangling leaves alone: " +
                      std::string(mirrored_map_advice());
        else if(report.untangle_refused) e.message = "not proven forced by the constraints; the untangled map was not used";
        else if(report.untangle_rings > 0)   // the regions grew up to untangle_rings around the faces still non-positive
          e.message = "not proven forced by the constraints; the untangling did not make it positive (its regions grew to " +
                      std::to_string(report.untangle_rings) + " face rings around the fold-overs" +
                      (report.untangle_budget_spent ? ", then it stopped at its work budget)" : ")");
        name_collapsed_pairs(S.cm.target[fc.halfedge[e.face][0]], e.message);
      }
    }
  }, [&] {
    K = field_rotation_sums(S.cm, S.st, S.rot);
    target = target_valences(S, fc, K);
    turns = vertex_quarter_turns(S.cm, S.st, S.x, orientations);
  });
  // windings; at a corner of a face proven non-positive no solution is locally injective (its triangles are not all
  // positive), whatever the angle sum
  for(int v = 0; v < S.cm.n_vertices; ++v) {
    if(!target.wound(std::size_t(v), turns[std::size_t(v)])) continue;
    Winding_defect d;
    d.vertex = std::size_t(v);
    d.angle_sum = turns[std::size_t(v)];
    d.valence = target.valence[std::size_t(v)];
    d.forced = forced_face[std::size_t(v)] >= 0;
    d.message = "the UV triangles around vertex " + std::to_string(v) + " wind " + std::to_string(d.angle_sum) +
                " quarter turns around it, not " + std::to_string(d.valence) + ": the map is not locally injective there";
    if(d.forced)
      d.message += "; it is a corner of face " + std::to_string(forced_face[std::size_t(v)]) + ", which the constraints " +
                   "force to be non-positive in every exact solution (folds): no map satisfying them is locally injective here";
    if(closed_part_of[std::size_t(v)] > 0) d.message += "; " + closed_uncut_part_reason(closed_part_of[std::size_t(v)]);
    name_collapsed_pairs(v, d.message);
    report.winding_defects.push_back(d);
  }
  // cone merging (cone_merging.h) makes the pairs whose cone indices cancel regular points of the field
  for(const std::pair<int, int>& c : collapsed) {
    report.collapsed_cone_pairs.emplace_back(std::size_t(c.first), std::size_t(c.second));
    report.cancelling_collapsed_cone_pairs += (K[std::size_t(c.first)] + K[std::size_t(c.second)]) % 4 == 0 ? 1 : 0;
  }
}

// 6. every row of the full system, exactly (Gmpq), before anything is written; change statistics
template <class TriangleMesh>
Status verify_stage(const Snap_state<TriangleMesh>& S, Snap_report& report, std::string& message)
{
  const long bad = first_violated_row(S.full, S.x);
  if(bad >= 0) {
    const int e = S.full.edge[std::size_t(bad)];
    message = "row " + std::to_string(bad) + " of the full system (" + row_origin_name(S.cm, e) +
              ") does not hold exactly after snapping; nothing was written";
    return EXACTNESS_CHECK_FAILED;
  }
  const std::vector<double>& ubar = S.st.ubar;
  for(std::size_t i = 0; i < S.x.size(); ++i) {   // the written values are exact at the caller's scale
    if(S.x[i] == ubar[i] || scale_by_power_of_two(S.cm.to_uv(S.x[i]), -S.cm.uv_exponent) == S.x[i]) continue;
    message = "the snapped UV " + format_double(S.x[i], 17) + " * 2^" + std::to_string(S.cm.uv_exponent) + " of sector " +
              std::to_string(i / 2) + " is not a double (below the smallest subnormal 2^-1074 or above the largest double): " +
              "the UV map is too close to the limits of double for exact snapping at its scale; nothing was written";
    return RANGE_EXCEEDED;
  }
  report.collapsed_cut_edges = count_collapsed_cut_edges(S.cm, S.st, S.x);
  const double diagonal = S.st.uv_diagonal;
  auto relative = [diagonal](double a) { return diagonal > 0 ? a / diagonal : a; };
  double max_change = 0, sum_change = 0;
  for(std::size_t i = 0; i < S.x.size(); ++i) max_change = (std::max)(max_change, std::fabs(S.x[i] - ubar[i]));
  for(int v : S.constrained_vars) sum_change += std::fabs(S.x[v] - ubar[v]);
  report.max_change = relative(max_change);
  const Uv_change total = measure_uv_change(S, S.x, ubar);
  report.total_max_change = total.max;
  report.total_rms_change = total.rms;
  if(!report.untangled || report.untangle_refused) { report.snap_max_change = total.max; report.snap_rms_change = total.rms; }
  const Integer_grid_counts after = count_integer_structure(S.cm, S.st, S.rot, in_grid_units(S, S.x));
  report.integer_translations_after = after.integer_translations;
  report.cones_on_integer_points_after = after.cones_on_integer_points;
  report.mean_change = S.constrained_vars.empty() ? 0. : relative(sum_change / double(S.constrained_vars.size()));
  return SUCCESS;
}

// 7. the corners of the changed sectors (and border halfedges that mirror them) into the caller's map
template <class TriangleMesh, class HalfedgeUVMap>
void write_stage(HalfedgeUVMap uvmap, Snap_state<TriangleMesh>& S)
{
  typedef typename boost::property_traits<HalfedgeUVMap>::value_type Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT FT;
  const Corner_mesh& cm = S.cm;
  const std::vector<double>& ubar = S.st.ubar;
  std::vector<char> changed(S.st.n_sectors, 0);
  for(int i = 0; i < S.st.n_sectors; ++i)
    changed[i] = !(S.x[2 * i] == ubar[2 * i] && S.x[2 * i + 1] == ubar[2 * i + 1]);
  for(int h = 0; h < cm.n_halfedges; ++h) {
    int corner = h;
    if(cm.is_border_halfedge(h)) {
      // a border halfedge that holds the UV of the corner (target(h), face(prev(opposite(h))))
      // (the Seam_mesh convention) is kept in sync with it
      corner = cm.prev[cm.opp[h]];
      const auto p = get(uvmap, S.desc.halfedges[h]);
      if(!(CGAL::to_double(p.x()) == cm.to_uv(cm.u[corner]) && CGAL::to_double(p.y()) == cm.to_uv(cm.v[corner]))) continue;
    }
    const int sec = S.st.sector_of[corner];
    if(!changed[sec]) continue;
    put(uvmap, S.desc.halfedges[h], Point_2(FT(cm.to_uv(S.x[2 * sec])), FT(cm.to_uv(S.x[2 * sec + 1]))));
    ++S.written;
  }
}

template <class TriangleMesh>
std::string success_summary(const Snap_options& opt, const Snap_state<TriangleMesh>& S, const Snap_report& report)
{
  std::string summary = S.already_exact ? "the input is already exactly seamless; nothing was changed"
                                        : "exactly seamless; " + std::to_string(S.written) + " corner UVs written";
  summary += " (" + std::to_string(report.cut_edges) + " cut edges, " + std::to_string(report.align_edges) +
             " align edges, " + std::to_string(report.constraints) + " constraints, " +
             (opt.use_reduced_system ? std::to_string(report.nodes) + " nodes, " : std::string()) +
             "system " + std::to_string(report.system_rows) + " x " + std::to_string(report.system_columns) + ")";
  if(report.collapsed_cut_edges > 0)
    summary += "; " + std::to_string(report.collapsed_cut_edges) + " cut edge(s) have zero UV length (" +
               std::to_string(S.collapsed_in_input) + " of them already on one side in the input): the transition "
               "collapses them on both sides, so their faces are degenerate in UV";
  if(opt.integer_grid_map) {
    summary += "; integer-grid map: " + std::to_string(report.integer_translations_after) + " of " +
               std::to_string(report.cut_edges) + " cut edges with integer translations, " +
               std::to_string(report.cones_on_integer_points_after) + " of " + std::to_string(report.field_cones) +
               " cones on integer points";
    if(!report.merged_cone_pairs.empty()) {
      summary += "; " + std::to_string(report.merged_cone_pairs.size()) + " cone pair(s) that the rounded translations put " +
                 "onto one integer point merged into regular points of the field (" +
                 (report.joined_cone_pairs > 0 ? std::to_string(report.joined_cone_pairs) + " of them into one cone with both "
                                                 "indices, whose partner became regular; " : std::string()) +
                 std::to_string(report.merged_cut_edges) + " cut edges with a new rotation, " +
                 std::to_string(report.added_cut_edges) + " of them new):";
      summary += first_ten(report.merged_cone_pairs, pair_name("+"));
    }
    if(!report.separated_cone_pairs.empty()) {
      summary += "; " + std::to_string(report.separated_cone_pairs.size()) + " cone pair(s) that the rounded translations put " +
                 "onto one integer point moved apart, each cone onto a neighbouring integer point (" +
                 std::to_string(report.separated_cut_edges) + " cut edges with a new translation):";
      summary += first_ten(report.separated_cone_pairs, pair_name("|"));
    }
    if(!report.not_field_cones.empty()) {
      summary += "; not pinned: " + std::to_string(report.not_field_cones.size()) + " vertices whose UV angle sum is not " +
                 "2 pi but whose rotations compose to the identity (fold-overs next to them, not cones of the field):";
      summary += first_ten(report.not_field_cones, [](std::size_t v) { return std::to_string(v); });
    }
  }
  if(!S.pins.empty())
    summary += "; " + std::to_string(S.pins.sector.size()) + " pinned sector(s) kept bit-identical";
  if(report.untangled)
    summary += "; untangled: " + std::to_string(report.flips_before_untangling) + " negative and " +
               std::to_string(report.degenerate_before_untangling) + " zero-area UV triangle(s) before, moving " +
               std::to_string(report.untangle_moved_sectors) + " sectors by at most " +
               format_double(report.untangle_max_change * report.grid_scale) + " grid cells (" +
               std::to_string(report.untangle_rings) + " ring(s))";
  if(!report.folds.empty()) {
    std::size_t negative = 0;
    for(const Fold_explanation& e : report.folds) negative += e.negative ? 1 : 0;
    summary += "; " + std::to_string(negative) + " negative and " + std::to_string(report.folds.size() - negative) +
               " zero-area UV triangle(s) remain, " + std::to_string(report.folds_forced) +
               " of them proven forced by the constraints (Snap_report::folds)";
    if(report.closed_uncut_faces > 0)
      summary += "; " + std::to_string(report.closed_uncut_faces) + " faces lie in closed parts of the surface without cut " +
                 "edges, whose maps into the plane always fold (Snap_report::closed_uncut_faces): a closed surface is " +
                 "parametrized with cuts (seams)";
  } else if(report.untangled) {
    summary += "; every UV triangle is positively oriented";
  }
  if(!report.winding_defects.empty()) {
    std::size_t forced = 0;
    for(const Winding_defect& w : report.winding_defects) forced += w.forced ? 1 : 0;
    summary += "; not locally injective at " + std::to_string(report.winding_defects.size()) +
               " vertices whose UV angle sum is not their valence (Snap_report::winding_defects" +
               (forced == 0 ? std::string(")")
                            : std::string(", ") + std::to_string(forced) + " of them proven forced: corners of faces proven non-positive)");
  }
  const std::size_t cancelling = report.cancelling_collapsed_cone_pairs;
  if(!report.collapsed_cone_pairs.empty())
    summary += "; " + std::to_string(report.collapsed_cone_pairs.size()) + " cone pair(s) rounded onto one integer point " +
               "lie next to these defects (Snap_report::collapsed_cone_pairs), " + std::to_string(cancelling) + " with cancelling indices" +
               (opt.merge_cone_pairs || cancelling == 0 ? std::string()
                                                        : std::string(" (merge_cone_pairs(true), --merge-cone-pairs, makes those regular points)"));
  return summary + S.flip_note + S.untangle_note;
}

// 1b-5b: the full system, its exact solution (with the untangling and the repair) and the explanation of what is
// left; S: the state after step 1a
template <class TriangleMesh>
Status solve_stages(const Snap_options& opt, Snap_state<TriangleMesh>& S, Snap_report& report, std::string& message)
{
  Snap_clock::time_point t = Snap_clock::now();
  Status s = build_constraints(opt, S, report, message);
  report.extract_ms += ms_since(t);
  if(s != SUCCESS) return s;
  // 2. and 3a. share nothing that either writes: on two threads with number_of_threads >= 2
  Status reduced = SUCCESS, started = SUCCESS;
  std::string start_message;
  run_concurrently(opt.threads, [&] {
    const Snap_clock::time_point t_reduce = Snap_clock::now();
    reduced = reduce_stage(S, report, message);
    report.reduce_ms = opt.use_reduced_system ? ms_since(t_reduce) : 0.;
  }, [&] { started = start_stage(opt, S, report, start_message); });
  if(reduced != SUCCESS) return reduced;
  if(started != SUCCESS) { message = start_message; return started; }
  s = project_stage(opt, S, report, message);
  if(s == SUCCESS) s = untangle_stage(opt, S, report, message);
  if(s != SUCCESS) return s;
  repair_stage(opt, S, report);
  restore_pinned_values(S.pins, S.x);
  t = Snap_clock::now();
  explain_folds_stage(opt, S, report);
  report.explain_ms = ms_since(t);
  return SUCCESS;
}

// how far (face rings) around a separated cone pair solve_with_separation_trials() counts defects
constexpr int separation_trial_rings = 3;

// per vertex, what a snap left there: 2 on a face not positive (a fold-over), else 1 if wound other than its valence
template <class TriangleMesh>
std::vector<char> defect_marks(const Snap_state<TriangleMesh>& S, const Snap_report& report, const Face_corners& fc)
{
  std::vector<char> bad(std::size_t(S.cm.n_vertices), 0);
  for(const Winding_defect& d : report.winding_defects) bad[d.vertex] = 1;
  for(const Fold_explanation& e : report.folds) for(int h : fc.halfedge[e.face]) bad[std::size_t(S.cm.target[h])] = 2;
  return bad;
}

// the defect_marks() within separation_trial_rings face rings of the cones of c: the vertices on faces left not
// positive (a fold-over near the pair) and the other vertices wound other than their valence
struct Defects_near { std::size_t folded = 0, wound = 0; std::size_t score() const { return 2 * folded + wound; } };

inline Defects_near defects_near(const Corner_mesh& cm, const Face_corners& fc, const std::vector<char>& bad,
                                 const Cone_separation& c)
{
  Defects_near n;
  for(int v : vertices_within_face_rings(cm, fc, {c.a, c.b}, separation_trial_rings)) {
    n.folded += bad[std::size_t(v)] == 2 ? 1 : 0;
    n.wound += bad[std::size_t(v)] == 1 ? 1 : 0;
  }
  return n;
}

// 1b-5b with separate_cone_pairs (integer-grid mode, untangling): which shift moves a collapsed cone pair apart
// (cone_separation.h) decides what the untangling can reach, but where the input itself puts the cones onto one point
// (the dragon's three +90 degree cones at (6, 38)) every shift is as near to the input, and the first in a fixed order
// was taken. So after the snap with those shifts, the pairs with defects near them (separation_trial_rings) try their
// other shifts: trial r snaps with each such pair moved by its r-th admissible shift (the others as before), each pair
// takes the shift with the fewest defects near it (defects_near(); its first one on ties), and the snap with the chosen
// shifts replaces the first only if it has fewer defects in all (faces not positive + wound vertices). Only fold-overs
// (faces not positive) near a pair start its trials: wound vertices alone did not pay for them (duck_qc_8 in
// integer-grid mode, pairs separated but not merged: 8 trials, 17x the time, the same defects). Pairs near each other
// are taken to be independent; the result is checked as always. Costs one snap per rank tried and one more
// (Snap_report::separation_trials); with opt.threads >= 2 the trial snaps run two at a time, each on one thread.
template <class TriangleMesh>
Status solve_with_separation_trials(const Snap_options& opt, Snap_state<TriangleMesh>& S, Snap_report& report,
                                    std::string& message)
{
  const bool trials = opt.integer_grid_map && opt.separate_cone_pairs && opt.untangle;
  Snap_state<TriangleMesh> extracted;
  Snap_report extracted_report;
  if(trials) { extracted = S; extracted_report = report; }
  Status s = solve_stages(opt, S, report, message);
  if(s != SUCCESS || !trials || S.separations.empty()) return s;
  const Face_corners fc(S.cm);
  std::map<int, std::vector<std::size_t> > defects;         // per first cone of a pair with fold-overs near it: per
                                                            // rank, Defects_near::score()
  std::vector<int> rank(std::size_t(S.cm.n_vertices), -1), first_rank = rank;
  int ranks = 0;
  const std::vector<char> first_bad = defect_marks(S, report, fc);
  for(const Cone_separation& c : S.separations) {
    first_rank[std::size_t(c.a)] = c.rank;
    const Defects_near n = defects_near(S.cm, fc, first_bad, c);
    if(n.folded == 0 || c.admissible < 2) continue;
    defects[c.a].assign(std::size_t(c.admissible), std::numeric_limits<std::size_t>::max());
    defects[c.a][std::size_t(c.rank)] = n.score();
    ranks = (std::max)(ranks, c.admissible);
  }
  Snap_options trial = opt;          // the polish keeps every face's orientation (it only pulls the map back towards the
  trial.untangle_polish = false;     // input), so the trials leave it out: the same defects at about 2/3 of the time
  trial.untangle_budget = 0.5;       // a trial only ranks shifts: half the work budget (the dragon, full-seamless, the only
                                     // shared map with trials, one run each: the same output with pairs merged and
                                     // separated, 9.4 -> 7.5 s; separated only the same defects, change 3.64 / 0.195 ->
                                     // 2.48 / 0.178 cells (max / RMS), 19.9 -> 14.0 s; a quarter of the budget: one more
                                     // negative triangle there; every other output of the shared maps unchanged)
  const Snap_clock::time_point trials_start = Snap_clock::now();
  auto snap_with = [&](const std::vector<int>& r, const Snap_options& o, Snap_state<TriangleMesh>& T, Snap_report& R) {
    T = extracted;
    T.separation_rank = r;
    R = extracted_report;
    std::string unused;
    return solve_stages(o, T, R, unused) == SUCCESS;
  };
  // the trials: rank r for every pair with trials (its first rank where it has no r-th), those that move a pair
  std::vector<std::vector<int> > trial_rank;
  std::vector<int> trial_r;
  for(int r = 0; r < ranks; ++r) {
    bool new_shift = false;
    for(const auto& d : defects) {
      rank[std::size_t(d.first)] = r < int(d.second.size()) ? r : first_rank[std::size_t(d.first)];
      new_shift = new_shift || rank[std::size_t(d.first)] != first_rank[std::size_t(d.first)];
    }
    if(new_shift) { trial_rank.push_back(rank); trial_r.push_back(r); }
  }
  // two at a time with number_of_threads >= 2, each on one thread (the untangler's results do not depend on its
  // threads), then scored in rank order: the same choice whatever the threads
  trial.threads = 1;
  Snap_state<TriangleMesh> T, T2;
  Snap_report R, R2;
  auto score = [&](int r, const Snap_state<TriangleMesh>& t, const Snap_report& rr) {
    const std::vector<char> bad = defect_marks(t, rr, fc);
    for(const Cone_separation& c : t.separations) {
      auto d = defects.find(c.a);
      if(d != defects.end() && c.rank == r) d->second[std::size_t(r)] = defects_near(t.cm, fc, bad, c).score();
    }
  };
  for(std::size_t k = 0; k < trial_rank.size();) {
    if(opt.threads >= 2 && k + 1 < trial_rank.size()) {    // two at once (T2 held only then)
      bool ok = false, ok2 = false;
      run_concurrently(opt.threads, [&] { ok = snap_with(trial_rank[k], trial, T, R); },
                       [&] { ok2 = snap_with(trial_rank[k + 1], trial, T2, R2); });
      if(ok) score(trial_r[k], T, R);
      if(ok2) score(trial_r[k + 1], T2, R2);
      k += 2;
    } else {
      if(snap_with(trial_rank[k], trial, T, R)) score(trial_r[k], T, R);
      k += 1;
    }
  }
  report.separation_trials += trial_rank.size();
  T2 = Snap_state<TriangleMesh>();
  bool changed = false;
  rank = first_rank;
  for(const auto& d : defects) {
    int& best = rank[std::size_t(d.first)];
    for(int r = 0; r < int(d.second.size()); ++r) if(d.second[std::size_t(r)] < d.second[std::size_t(best)]) best = r;
    changed = changed || best != first_rank[std::size_t(d.first)];
  }
  const bool snapped = changed && snap_with(rank, opt, T, R);
  report.separation_trials += changed ? 1 : 0;
  report.separation_ms = ms_since(trials_start);
  if(!snapped) return SUCCESS;
  if(R.folds.size() + R.winding_defects.size() < report.folds.size() + report.winding_defects.size()) {
    R.separation_trials = report.separation_trials;
    R.separation_ms = report.separation_ms;
    S = std::move(T);
    report = std::move(R);
  }
  return SUCCESS;
}

// The pipeline: the stages above in order; the caller's map is written only after step 6 passed.
// The overrides are given per edge/halfedge descriptor through callables, evaluated after the
// corner mesh is built (they need its numbering).
template <class TriangleMesh, class HalfedgeUVMap, class SeamOf, class RotationOf, class ConstrainedOf, class WeightOf,
          class PointOf>
Snap_report snap_pipeline(const TriangleMesh& tm, HalfedgeUVMap uvmap, const SeamOf& seam_of, bool has_seams,
                          const RotationOf& rotation_of, bool has_rotations,
                          const ConstrainedOf& constrained_of, bool has_constrained,
                          const WeightOf& weight_of, bool has_weights, const PointOf& point_of, const Snap_options& opt)
{
  const Snap_clock::time_point t_start = Snap_clock::now();
  Snap_report report;
  report.reduced = opt.use_reduced_system;
  auto finish = [&](Status s, const std::string& message) {
    report.status = s;
    report.message = message;
    report.total_ms = ms_since(t_start);
    if(opt.verbose)
      std::cout << "snap_seamless_parameterization: " << status_name(s) << ": " << message << std::endl;
    return report;
  };
  Snap_state<TriangleMesh> S;
  std::string message;

  Snap_clock::time_point t = Snap_clock::now();
  Status s = extract_seams(tm, uvmap, seam_of, has_seams, rotation_of, has_rotations, constrained_of, has_constrained,
                           opt, S, report, message);
  if(s == SUCCESS && has_weights) s = read_vertex_weights(weight_of, S, message);
  if(s != SUCCESS) return finish(s, message);
  if(opt.untangle) read_vertex_points(point_of, S);
  report.extract_ms = ms_since(t);
  s = solve_with_separation_trials(opt, S, report, message);
  if(s != SUCCESS) return finish(s, message);

  t = Snap_clock::now();
  s = verify_stage(S, report, message);
  report.verify_ms = ms_since(t);
  if(s != SUCCESS) return finish(s, message);

  t = Snap_clock::now();
  write_stage(uvmap, S);
  report.write_ms = ms_since(t);
  return finish(SUCCESS, success_summary(opt, S, report));
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_SNAP_PIPELINE_H
