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
//   1. extract   corner mesh, cut edges, sectors, cones, rotations k, align edges   (Sec. 5, 5.1)
//   2. reduce    nodes, branches, node system C                                    (Sec. 5.3)
//   3. project   C through Exact_constraint_projection on the common grid F_delta  (Sec. 4)
//   4. propagate non-node sectors along the branches                               (Sec. 5.3.1)
//  4b. repair    flips by moving one sector group into its 1-ring kernel, exactly  (Sec. 5.4)
//   5. verify    every row of the full system, exactly (Gmpq), before anything is written
//   6. write     the corners of the changed sectors into the caller's map
// With use_reduced_system = false, steps 2 and 4 are skipped and the full system goes to step 3.
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
#include <CGAL/Seamless_snapping/internal/surface/connection_constraints.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/exact_uv_check.h>
#include <CGAL/Seamless_snapping/internal/projection/fixed_point_grid.h>
#include <CGAL/Seamless_snapping/internal/surface/flip_repair.h>
#include <CGAL/Seamless_snapping/internal/surface/propagation.h>
#include <CGAL/Seamless_snapping/internal/surface/reduced_system.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_traits.h>

#include <Eigen/Sparse>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
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
  std::vector<Connection_path> connections;  // connection (Eq. 6) and cycle (Eq. 8) constraints
};

// number of UV triangles with negative orientation (exact predicate), corner values from `x`
inline std::size_t count_flips(const Corner_mesh& cm, const Seam_topology& st, const std::vector<double>& x)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  std::size_t flips = 0;
  for(int h = 0; h < cm.n_halfedges; ++h) {
    if(cm.is_border_halfedge(h) || h > cm.next[h] || h > cm.prev[h]) continue;   // once per face
    const int s0 = st.sector_of[h], s1 = st.sector_of[cm.next[h]], s2 = st.sector_of[cm.prev[h]];
    const P p0(x[2 * s0], x[2 * s0 + 1]), p1(x[2 * s1], x[2 * s1 + 1]), p2(x[2 * s2], x[2 * s2 + 1]);
    if(CGAL::orientation(p0, p1, p2) == CGAL::NEGATIVE) ++flips;
  }
  return flips;
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

// Projects x onto {C x = 0} for the rows `rows` (over sector variables) with the core, on `grid`.
// Writes the constrained variables of x (others untouched).
inline Status project_rows(const Constraint_rows& rows, const Fixed_point_grid& grid, std::vector<double>& x,
                           Snap_report& report, std::string& message)
{
  std::vector<int> vars, column_of;
  used_variables(rows, x.size(), vars, column_of);
  std::vector<Eigen::Triplet<long> > triplets;
  triplets.reserve(rows.col.size());
  for(std::size_t i = 0; i < rows.size(); ++i)
    for(std::size_t k = rows.start[i]; k < rows.start[i + 1]; ++k)
      triplets.emplace_back(int(i), column_of[rows.col[k]], long(rows.coef[k]));
  std::vector<double> xbar(vars.size()), xs;
  for(std::size_t j = 0; j < vars.size(); ++j) xbar[j] = x[vars[j]];
  report.system_rows = rows.size();
  report.system_columns = vars.size();

  Projection_options options;
  options.delta_exponent = grid.K;
  Exact_constraint_projection projection(options);
  const std::vector<long> b(rows.size(), 0);
  Status s = projection.initialize(rows.size(), vars.size(), triplets, b);
  const Irref_statistics& stats = projection.statistics();
  report.irref_ms = stats.initialize_ms;
  if(s != SUCCESS) { message = "IRREF of the constraint system: " + projection.message(); return s; }
  report.free_variables = stats.free_variables;
  report.implied_variables = stats.implied_variables;
  report.max_abs_coefficient = stats.max_abs_coefficient;
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

// The overrides are given per edge/halfedge descriptor through callables, evaluated after the
// corner mesh is built (they need its numbering).
template <class TriangleMesh, class HalfedgeUVMap, class SeamOf, class RotationOf, class ConstrainedOf>
Snap_report snap_pipeline(TriangleMesh& tm, HalfedgeUVMap uvmap, const SeamOf& seam_of, bool has_seams,
                          const RotationOf& rotation_of, bool has_rotations,
                          const ConstrainedOf& constrained_of, bool has_constrained, const Snap_options& opt)
{
  typedef std::chrono::steady_clock Clock;
  auto ms_since = [](Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); };
  const Clock::time_point t_start = Clock::now();
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

  // 1. extraction ------------------------------------------------------------------------------
  Clock::time_point t = Clock::now();
  std::string message;
  Corner_mesh cm;
  Corner_mesh_descriptors<TriangleMesh> desc;
  Status s = build_corner_mesh(tm, uvmap, cm, desc, message);
  if(s != SUCCESS) return finish(s, message);
  report.faces = std::size_t(cm.n_faces);

  std::vector<signed char> seam_override;
  std::vector<int> given_k;
  std::vector<char> constrained;
  if(has_seams) {
    seam_override.assign(cm.n_edges, -1);
    for(int e = 0; e < cm.n_edges; ++e) seam_override[e] = seam_of(desc.edges[e]) ? 1 : 0;
  }
  if(has_constrained) {
    constrained.assign(cm.n_edges, 0);
    for(int e = 0; e < cm.n_edges; ++e) constrained[e] = constrained_of(desc.edges[e]) ? 1 : 0;
  }

  Seam_topology st;
  s = compute_seam_topology(cm, seam_override, st, message);
  if(s != SUCCESS) return finish(s, message);
  report.cut_edges = st.cut_edges.size();
  report.sectors = std::size_t(st.n_sectors);
  report.uv_diagonal = st.uv_diagonal;
  for(char c : st.is_cone) report.cones += c ? 1 : 0;

  if(has_rotations) {
    given_k.assign(cm.n_edges, 0);
    for(int e : st.cut_edges) given_k[e] = int(rotation_of(desc.halfedges[cm.edge_halfedge[e]]));
  }
  Cut_rotations rot;
  s = fit_rotations(cm, st, given_k, opt.rotation_tolerance, rot, message);
  if(s != SUCCESS) return finish(s, message);

  Align_edges al;
  s = find_align_edges(cm, st, opt.align_boundary, opt.alignment_tolerance, constrained, al, message);
  if(s != SUCCESS) return finish(s, message);
  report.align_edges = al.edges.size();

  Constraint_rows full;
  build_full_system(cm, st, rot, al, full);
  // connection and cycle constraints (Eq. 6-8): one row each, appended to the full system
  const std::size_t first_connection_row = full.size();
  std::vector<char> path_endpoints;
  s = add_connection_rows(cm, st, rot, opt.connections, full, path_endpoints, message);
  if(s != SUCCESS) return finish(s, message);
  report.constraints = full.size();
  const std::size_t n_vars = 2 * std::size_t(st.n_sectors);
  std::vector<int> constrained_vars, column_of;
  used_variables(full, n_vars, constrained_vars, column_of);
  {
    std::vector<char> sector_used(st.n_sectors, 0);
    for(int v : constrained_vars) sector_used[v / 2] = 1;
    for(char c : sector_used) report.constrained_sectors += c ? 1 : 0;
  }
  const double diagonal = st.uv_diagonal;
  auto relative = [diagonal](double a) { return diagonal > 0 ? a / diagonal : a; };
  const std::vector<double>& ubar = st.ubar;
  report.max_input_violation = relative(max_abs_residual(full, ubar));
  double max_abs = 0;
  for(int v : constrained_vars) max_abs = (std::max)(max_abs, std::fabs(ubar[v]));
  Fixed_point_grid grid = Fixed_point_grid::from_max_abs(max_abs, 1);   // may grow on RANGE_EXCEEDED (below)
  report.flips_before = count_flips(cm, st, ubar);
  report.extract_ms = ms_since(t);

  // 2. reduction ---------------------------------------------------------------------------------
  t = Clock::now();
  Reduced_system rs;
  build_reduced_system(cm, st, rot, al, rs, path_endpoints);
  s = add_reduced_connection_rows(cm, st, full, first_connection_row, rs, message);
  if(s != SUCCESS) return finish(s, "node system: " + message);
  report.nodes = rs.n_nodes;
  report.cut_branches = rs.cut_branches.size();
  report.align_branches = rs.align_branches.size();
  report.reduce_ms = ms_since(t);
  if(!opt.use_reduced_system) report.reduce_ms = 0;

  std::vector<double> x = ubar;
  const bool already_exact = first_violated_row(full, ubar) < 0;
  if(already_exact) {     // x = ubar satisfies every row: nothing to project, nothing to write
    const Constraint_rows& system = opt.use_reduced_system ? rs.node_rows : full;
    std::vector<int> system_vars, system_column_of;
    used_variables(system, n_vars, system_vars, system_column_of);
    report.system_rows = system.size();
    report.system_columns = system_vars.size();
  } else {
    // Steps 3 and 4 on the grid; RANGE_EXCEEDED is retried on a grid with 4 more bits of range (up to
    // 5 times): constraints that the input violates by a lot (connection and cycle constraints added
    // after the fact) move implied values further than the margin of Sec. 4.3 allows.
    std::string prefix;
    for(int retry = 0;; ++retry) {
      x = ubar;
      if(opt.use_reduced_system) {
        // 3. node system ---------------------------------------------------------------------------
        prefix = "node system: ";
        s = project_rows(rs.node_rows, grid, x, report, message);
        if(s == SUCCESS) {
          // node sectors used by the propagation but absent from C (e.g. the node of a closed loop,
          // whose node rows cancel): free, rounded to the grid
          std::vector<int> node_vars, node_column_of;
          used_variables(rs.node_rows, n_vars, node_vars, node_column_of);
          auto fix_free_node_var = [&](int var) {
            if(node_column_of[var] < 0) { x[var] = grid.round(ubar[var]); node_column_of[var] = -2; }
          };
          for(const Cut_branch_plan& p : rs.cut_branches)
            for(int c = 0; c < 2; ++c) { fix_free_node_var(2 * p.u0_plus + c); fix_free_node_var(2 * p.u0_minus + c); }
          for(const Align_branch_plan& p : rs.align_branches) fix_free_node_var(2 * p.u0 + p.component);
          // 4. propagation -------------------------------------------------------------------------
          prefix = "propagation: ";
          t = Clock::now();
          s = propagate_along_branches(rs, ubar, grid, x, message);
          report.propagate_ms = ms_since(t);
        }
      } else {
        prefix = "full system: ";
        s = project_rows(full, grid, x, report, message);
      }
      if(s != RANGE_EXCEEDED || retry == 5) break;
      grid = Fixed_point_grid(grid.K + 4);
    }
    if(s != SUCCESS) return finish(s, prefix + message);
  }

  // 4b. flip repair (Sec. 5.4): moves that keep every row exact, each checked exactly -----------
  report.flips_after = count_flips(cm, st, x);
  report.flips_after_repair = report.flips_after;
  std::string flip_note;
  if(opt.repair_flips && !already_exact) {
    t = Clock::now();
    const Flip_repair_result fr = repair_flips(cm, st, rs, full, grid, ubar, x);
    report.repair_ms = ms_since(t);
    report.flips_after_repair = fr.flips_after;
    report.flips_unrepaired = fr.unrepaired;
    report.repair_moves = fr.moves;
    if(fr.unrepaired > 0) {
      flip_note = "; " + std::to_string(fr.unrepaired) + " flip(s) introduced by snapping could not be repaired locally (faces";
      for(std::size_t i = 0; i < fr.unrepaired_faces.size() && i < 10; ++i) flip_note += " " + std::to_string(fr.unrepaired_faces[i]);
      flip_note += fr.unrepaired_faces.size() > 10 ? " ...)" : ")";
    }
  } else {
    report.flips_unrepaired = count_introduced_flips(cm, st, ubar, x);
  }

  // 5. exact verification of every row of the full system ------------------------------------
  t = Clock::now();
  const long bad = first_violated_row(full, x);
  report.verify_ms = ms_since(t);
  if(bad >= 0) {
    const int e = full.edge[std::size_t(bad)];
    return finish(EXACTNESS_CHECK_FAILED,
                  "row " + std::to_string(bad) + " of the full system (" +
                  (e >= 0 ? "edge " + vertex_pair_name(cm, cm.edge_halfedge[e]) : connection_name(std::size_t(-1 - e))) +
                  ") does not hold exactly after snapping; nothing was written");
  }

  // statistics ---------------------------------------------------------------------------------
  double max_change = 0, sum_change = 0;
  for(std::size_t i = 0; i < n_vars; ++i) max_change = (std::max)(max_change, std::fabs(x[i] - ubar[i]));
  for(int v : constrained_vars) sum_change += std::fabs(x[v] - ubar[v]);
  report.max_change = relative(max_change);
  report.mean_change = constrained_vars.empty() ? 0. : relative(sum_change / double(constrained_vars.size()));

  // 6. write the corners of the changed sectors (and border halfedges that mirror them) --------
  typedef typename boost::property_traits<HalfedgeUVMap>::value_type Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT FT;
  std::vector<char> changed(st.n_sectors, 0);
  for(int i = 0; i < st.n_sectors; ++i)
    changed[i] = !(x[2 * i] == ubar[2 * i] && x[2 * i + 1] == ubar[2 * i + 1]);
  std::size_t written = 0;
  for(int h = 0; h < cm.n_halfedges; ++h) {
    int corner = h;
    if(cm.is_border_halfedge(h)) {
      // a border halfedge that holds the UV of the corner (target(h), face(prev(opposite(h))))
      // (the Seam_mesh convention) is kept in sync with it
      corner = cm.prev[cm.opp[h]];
      const auto p = get(uvmap, desc.halfedges[h]);
      if(!(CGAL::to_double(p.x()) == cm.u[corner] && CGAL::to_double(p.y()) == cm.v[corner])) continue;
    }
    const int sec = st.sector_of[corner];
    if(!changed[sec]) continue;
    put(uvmap, desc.halfedges[h], Point_2(FT(x[2 * sec]), FT(x[2 * sec + 1])));
    ++written;
  }

  report.total_ms = ms_since(t_start);
  std::string summary = already_exact ? "the input is already exactly seamless; nothing was changed"
                                      : "exactly seamless; " + std::to_string(written) + " corner UVs written";
  summary += " (" + std::to_string(report.cut_edges) + " cut edges, " + std::to_string(report.align_edges) +
             " align edges, " + std::to_string(report.constraints) + " constraints, " +
             (opt.use_reduced_system ? std::to_string(report.nodes) + " nodes, " : std::string()) +
             "system " + std::to_string(report.system_rows) + " x " + std::to_string(report.system_columns) + ")";
  summary += flip_note;
  return finish(SUCCESS, summary);
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_SNAP_PIPELINE_H
