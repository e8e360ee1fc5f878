// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_EXTRACTION_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_EXTRACTION_H

// Quad mesh extraction from an exact, fold-free integer-grid map (extract_quad_mesh()), in three stages:
//   1. check_quad_input(): an exact IGM (is_exact_integer_grid_map_impl(), which also gives the rotation k
//      of every cut edge), no fold-overs, no zero-area triangles but collinear ones with three distinct
//      corners (collapsed onto their long side: collapsed_faces.h), the UVs in grid units (multiplied by the
//      grid scale, exactly) and within 2^30, every vertex whose quad valence is not 4 (quad_valences(): a
//      cone) on an integer point, and not of valence 1, unless the repairs below handle it (a cone of valence 1 split,
//      a branch point of 4m quarter turns off the integer points filled); the map's Euler characteristic, border loops and
//      exact UV area, for the verification;
//   2. the cells: the pieces of the faces (cell_pieces.h) stitched by the edges' transitions (quad_cells.h); where
//      asked (Quad_options), the cells covered several times around branch points filled with quads
//      (branched_cells.h) and the 2 x 2 cells at each cone of valence 1 made one quad (valence_one_cones.h);
//   3. the quad mesh: 3D positions (barycentric coordinates of each integer point, in double), the cells
//      added face by face as Euler::add_face() adds them (on index arrays, internal/mesh/halfedge_arrays.h:
//      a face with a corner twice or an edge already taken in its direction is refused), then copied onto a
//      Surface_mesh, which must be manifold (else refused, with what is wrong), measured, and verified against
//      the map (quad_mesh_checks.h).
// No tracing and no rational construction before stage 3: every decision is an exact predicate on
// doubles and integers (the tracer's and the patch layout's rationals are not needed on the grid).

#include <CGAL/Seamless_snapping/Quad_mesh_report.h>
#include <CGAL/Seamless_snapping/internal/quad/branched_cells.h>
#include <CGAL/Seamless_snapping/internal/quad/cell_pieces.h>
#include <CGAL/Seamless_snapping/internal/quad/quad_cells.h>
#include <CGAL/Seamless_snapping/internal/mesh/halfedge_arrays.h>
#include <CGAL/Seamless_snapping/internal/quad/quad_mesh_checks.h>
#include <CGAL/Seamless_snapping/internal/quad/valence_one_cones.h>
#include <CGAL/Seamless_snapping/internal/surface/cone_merging.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/fold_overs.h>
#include <CGAL/Seamless_snapping/internal/surface/integer_grid_constraints.h>
#include <CGAL/Seamless_snapping/internal/surface/quad_valences.h>
#include <CGAL/Seamless_snapping/internal/surface/uv_area.h>
#include <CGAL/Seamless_snapping/internal/timing.h>
#include <CGAL/Seamless_snapping/internal/untangling/closed_uncut_parts.h>
#include <CGAL/Seamless_snapping/internal/untangling/winding_defects.h>

#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

// the largest |UV coordinate| in grid units
constexpr double max_grid_coordinate = 0x1p30;

struct Quad_extraction
{
  Corner_mesh cm;                                  // the map, UVs in grid units
  Quad_cells cells;
  Cell_repairs repairs;                            // what the repairs of stage 2 changed
  std::vector<std::array<double, 3> > positions;   // per quad vertex
  Quad_surface mesh;                               // the verified quad mesh (vertices cells.points, faces cells.quads)
};

// What the quad mesh is verified against (UVs in grid units): the quad valences, the cones (interior vertices of
// valence other than 4), the Euler characteristic, the border loops, and twice the UV area, exactly (uv_area.h).
inline Map_facts map_facts(const Corner_mesh& cm)
{
  Map_facts facts;
  Quad_valence_result q = quad_valences(cm);
  facts.valence.swap(q.valence);
  facts.on_border.swap(q.on_border);
  facts.twice_area = twice_uv_area(cm);
  std::vector<char> used(std::size_t(cm.n_vertices), 0);
  for(int h = 0; h < cm.n_halfedges; ++h)
    if(!cm.is_border_halfedge(h)) used[std::size_t(cm.target[h])] = 1;
  std::size_t vertices = 0;
  for(int v = 0; v < cm.n_vertices; ++v) {
    vertices += used[std::size_t(v)];
    facts.cones += !facts.on_border[std::size_t(v)] && used[std::size_t(v)] && facts.valence[std::size_t(v)] != 4 ? 1 : 0;
  }
  std::vector<char> walked(std::size_t(cm.n_halfedges), 0);
  for(int h = 0; h < cm.n_halfedges; ++h) {
    if(!cm.is_border_halfedge(h) || walked[std::size_t(h)]) continue;
    ++facts.boundary_loops;
    for(int g = h; !walked[std::size_t(g)]; g = cm.next[g]) walked[std::size_t(g)] = 1;
  }
  facts.euler_characteristic = int(vertices) - cm.n_edges + cm.n_faces;
  return facts;
}

// extract_quad_mesh()'s named parameters
struct Quad_options
{
  std::size_t max_grid_cells = 0;
  bool split_valence_one_cones = true;   // valence_one_cones.h
  bool fill_branched_cells = true;       // branched_cells.h
};

// a vertex of angle sum q (quarter turns) whose cells fill_branched_cells() fills, off the integer points
inline bool is_branch_point(int q) { return q >= 8 && q % 4 == 0; }

// the UV of corner h lies inside an open cell: neither coordinate an integer (grid units)
inline bool in_open_cell(const Corner_mesh& cm, int h)
{
  return cm.u[h] != std::floor(cm.u[h]) && cm.v[h] != std::floor(cm.v[h]);
}

// Quad_mesh_report::advice with FOLD_OVERS, where untangling can remove the faces
constexpr const char* untangle_advice = "untangle the map first (the snap with untangle(true)), which removes such faces "
                                        "unless the constraints force them (Snap_report::folds says which)";

// Where some of the faces `faces` lie in closed parts of the surface without cut edges, which every map into the plane
// folds (closed_uncut_parts.h), that reason as the end of the FOLD_OVERS message; else "" (untangling may help)
inline std::string closed_uncut_reason(const Corner_mesh& cm, const std::vector<int>& faces)
{
  Seam_topology st;
  std::string ignored;
  if(compute_seam_topology(cm, {}, st, ignored) == SUCCESS) {
    const std::vector<int> closed = closed_uncut_part_sizes(cm, st, Face_corners(cm), faces);
    std::size_t n = 0;
    for(int f : faces) n += closed[std::size_t(f)] > 0 ? 1 : 0;
    if(n > 0)
      return "; " + std::to_string(n) + " of them lie in closed parts of the surface without cut edges, where every map "
             "into the plane folds (were all its triangles positive, its image would be open and compact in the plane): "
             "the UVs are no parametrization there, and no untangling helps; a closed surface is parametrized with cuts "
             "(seams)";
  }
  return std::string();
}

// The collapsed cone pairs within coincident_cone_rings face rings of vertex v (winding_defects.h, cone_merging.h's
// collapsed_cone_pairs() on the map's own integer translations) as a clause of a message, or "" if none: the nearest
// named_collapsed_pairs of them named, the others counted. `edge_k`: the
// rotation of halfedge(e) of every cut edge e (is_exact_integer_grid_map_impl()).
inline std::string collapsed_cone_pairs_clause(const Corner_mesh& cm, const std::vector<int>& edge_k, int v)
{
  Seam_topology st;
  std::string ignored;
  if(compute_seam_topology(cm, {}, st, ignored) != SUCCESS) return std::string();
  Cut_rotations rot;
  rot.k.assign(std::size_t(cm.n_halfedges), 0);
  for(int e : st.cut_edges) {
    const int h = cm.edge_halfedge[std::size_t(e)];
    rot.k[std::size_t(h)] = edge_k[std::size_t(e)];
    rot.k[std::size_t(cm.opp[h])] = (4 - edge_k[std::size_t(e)]) % 4;
  }
  std::vector<long> t;   // integers: is_exact_integer_grid_map_impl() proved them exactly; rounding recovers them
  if(round_translations(cm, st, rot, st.ubar, 1e-6, t, ignored) != SUCCESS) return std::string();
  const std::vector<std::pair<int, int> > pairs = collapsed_cone_pairs(cm, st, rot, t, st.ubar, default_collapsed_cone_reach);
  std::string clause;
  const std::vector<std::pair<int, int> > near = collapsed_cone_pairs_near(cm, Face_corners(cm), pairs, {v});
  for(std::size_t i = 0; i < near.size() && i < named_collapsed_pairs; ++i)
    clause += std::string(clause.empty() ? "" : ",") + " " + std::to_string(near[i].first) + " and " + std::to_string(near[i].second);
  if(clause.empty()) return clause;
  clause += more_collapsed_pairs_clause(near.size());
  return "; it lies next to cones that the map's integer translations put onto one integer point (vertices" + clause +
         "): the translations fix both cones on that point, so no move of the UVs separates them, and the map winds "
         "wrongly around them, where no quad mesh follows it; snap with merge_cone_pairs(true) (seamless_quad's default), "
         "which makes such a pair regular points of the field where the cut between them runs within one grid cell of "
         "that point (S cells at grid scale S > 1; libQEx merges such pairs too), or choose integer translations that "
         "keep the cones apart";
}

// Every vertex inside the quad mesh (not `on_border`, quad_valences()) of quad valence other than 4 must lie on an
// integer point (a field cone does in an IGM; a vertex of 8 quarter turns need not) and must not be of valence 1 (its
// cell would have a corner twice), but for what the repairs in `opt` handle after the cells are made (a cone of valence
// 1 split, a branch point inside an open cell filled; one on a grid line is refused). Where such a vertex lies next to
// a collapsed cone pair, the message says so; a cone of valence 1 in a map where no vertex winds twice is most likely
// the map's own singularity, and the message says that instead.
inline Status check_cones(const Corner_mesh& cm, const std::vector<int>& valence, const std::vector<char>& on_border,
                          const std::vector<int>& edge_k, const Quad_options& opt, std::string& message)
{
  for(int h = 0; h < cm.n_halfedges; ++h) {
    const int v = cm.target[h], q = valence[std::size_t(v)];
    if(cm.is_border_halfedge(h) || on_border[std::size_t(v)] || q == 4) continue;
    const bool on_integer = cm.u[h] == std::floor(cm.u[h]) && cm.v[h] == std::floor(cm.v[h]);
    if(on_integer && (q != 1 || opt.split_valence_one_cones)) continue;
    const bool in_cell = in_open_cell(cm, h);
    if(in_cell && opt.fill_branched_cells && is_branch_point(q)) continue;
    message = "vertex " + std::to_string(v) + " has a UV angle sum of " + std::to_string(q) + " quarter turns ";
    if(q != 1) {
      message += "but is not on an integer point: the map branches inside a cell" + collapsed_cone_pairs_clause(cm, edge_k, v);
      if(in_cell && is_branch_point(q))
        message += "; fill_branched_cells(true) (the default; seamless_quad without --no-branch-fill) fills that cell's "
                   "sheets with quads";
    } else {
      message += "(a cone of valence 1): the cell at it would be a quad whose two sides at the cone are one edge, "
                 "a corner twice, which no polygon mesh has; split_valence_one_cones(true) (the default; seamless_quad "
                 "without --no-cone-split) makes the 2 x 2 cells at it one quad";
      if(vertex_winding_twice(cm, valence) >= 0) message += collapsed_cone_pairs_clause(cm, edge_k, v);
      else message += "; its triangles are not folded and no vertex of the map winds around its point by 7 quarter "
                      "turns or more (where a cone wound back from 5 quarter turns to 1 would leave the 4 it lacks), "
                      "so this is most likely a cone of the map itself, a singularity of index 3/4 of its field: its "
                      "quad mesh as unit cells needs a cross field whose singularities have index at most 1/2";
    }
    return INVALID_INPUT;
  }
  return SUCCESS;
}

// The refusal of a vertex that a repair was to handle (a cone of valence 1, a branch point inside a cell: check_cones()
// let it through) but whose own cell is cut by the border, so that the quad mesh would leave it out unseen.
inline Status unreached_repair(int v, int quarter_turns, std::string& message)
{
  message = "vertex " + std::to_string(v) + " has a UV angle sum of " + std::to_string(quarter_turns) + " quarter turn" +
            (quarter_turns == 1 ? " (a cone of valence 1)" : "s off the integer points (a branch point inside a cell)") +
            ", and the cell at it is cut by the border (not on integer isolines): it is neither a quad nor can it be " +
            (quarter_turns == 1 ? "split" : "filled") + ", so the quad mesh would leave it out; a larger grid_scale makes "
            "the cells smaller";
  return INVALID_INPUT;
}

// The branch points that fill_branched_cells() is to fill: per vertex 1 where the map winds around it more than once
// inside an open cell (check_cones() let them through); empty where there is none or `opt` does not fill.
inline std::vector<char> branch_vertices(const Corner_mesh& cm, const Map_facts& facts, const Quad_options& opt)
{
  std::vector<char> branch;
  if(!opt.fill_branched_cells) return branch;
  for(int h = 0; h < cm.n_halfedges; ++h) {
    const int v = cm.target[h];
    if(cm.is_border_halfedge(h) || facts.on_border[std::size_t(v)] || !is_branch_point(facts.valence[std::size_t(v)]) ||
       !in_open_cell(cm, h))
      continue;
    branch.resize(std::size_t(cm.n_vertices), 0);
    branch[std::size_t(v)] = 1;
  }
  return branch;
}

// The repairs of stage 2 on the stitched cells: the branched cells filled (branched_cells.h), then the cones of
// valence 1 split (valence_one_cones.h); refused where one of them fails or where a vertex they were to handle has no
// cell to repair (unreached_repair()). The report lists what was done, on success only.
inline Status repair_cells(const Corner_mesh& cm, const Map_facts& facts, const std::vector<int>& edge_k,
                           const std::vector<char>& branch_vertex, Quad_extraction& out, Quad_mesh_report& r)
{
  std::vector<char> reached(branch_vertex.size(), 0);   // before the fill empties the list
  for(const Quad_cells::Branched& br : out.cells.branched) reached[std::size_t(br.vertex)] = 1;
  int failed = -1;
  Status s = fill_branched_cells(out.cells, facts.valence, out.repairs, failed, r.message);
  if(failed >= 0) r.message += collapsed_cone_pairs_clause(cm, edge_k, failed);
  for(std::size_t v = 0; v < branch_vertex.size() && s == SUCCESS; ++v)
    if(branch_vertex[v] && !reached[v]) s = unreached_repair(int(v), facts.valence[v], r.message);
  if(s != SUCCESS) return s;
  std::vector<int> ones;                               // the quad vertices at cones of valence 1 (only with the split)
  reached.assign(std::size_t(cm.n_vertices), 0);
  for(int v : out.repairs.absorbed_cones) reached[std::size_t(v)] = 1;
  for(std::size_t i = 0; i < out.cells.points.size(); ++i) {
    const Integer_point& p = out.cells.points[i];
    if(p.kind != AT_VERTEX || facts.on_border[std::size_t(p.element)] || facts.valence[std::size_t(p.element)] != 1) continue;
    ones.push_back(int(i));
    reached[std::size_t(p.element)] = 1;
  }
  for(int v = 0; v < cm.n_vertices; ++v)
    if(facts.valence[std::size_t(v)] == 1 && !facts.on_border[std::size_t(v)] && !reached[std::size_t(v)])
      return unreached_repair(v, 1, r.message);
  s = split_valence_one_cones(out.cells, ones, out.repairs, r.message);
  if(s != SUCCESS) return s;
  r.split_cones.assign(out.repairs.split_cones.begin(), out.repairs.split_cones.end());
  r.filled_branch_points.assign(out.repairs.filled_vertices.begin(), out.repairs.filled_vertices.end());
  r.absorbed_cones.assign(out.repairs.absorbed_cones.begin(), out.repairs.absorbed_cones.end());
  return SUCCESS;
}

// Stage 1. `cm` as built from the caller's mesh; on success its UVs are in grid units.
inline Status check_quad_input(Corner_mesh& cm, int scale_exponent, const Quad_options& opt, std::vector<int>& edge_k,
                               Map_facts& facts, std::vector<int>& collinear, Quad_mesh_report& r)
{
  r.faces = std::size_t(cm.n_faces);
  std::string why;
  if(!is_exact_integer_grid_map_impl(cm, {}, {}, {}, scale_exponent, &why, &edge_k)) {
    r.message = "not an exact integer-grid map: " + why + "; snap it with integer_grid_map(true) first";
    return INVALID_INPUT;
  }
  const Fold_overs folds = find_fold_overs(cm);
  r.fold_overs.assign(folds.negative.begin(), folds.negative.end());
  r.zero_area_faces.assign(folds.degenerate.begin(), folds.degenerate.end());
  if(folds.blocks_quads()) {
    std::vector<int> blocking = folds.negative;
    blocking.insert(blocking.end(), folds.degenerate.begin(), folds.degenerate.end());
    r.message = "the map has " + folds.describe() + (folds.collinear.size() < folds.degenerate.size() ?
                "; " + std::to_string(folds.degenerate.size() - folds.collinear.size()) + " of them with two corners at one UV point" : "") +
                ": its integer isolines do not form quads there";
    const std::string closed = closed_uncut_reason(cm, blocking);
    if(closed.empty()) r.advice = untangle_advice;
    r.message += closed.empty() ? "; " + r.advice : closed;
    return FOLD_OVERS;
  }
  collinear = folds.collinear;
  const int exponent = -scale_exponent;
  const Status s = normalize_uv_scale(cm, r.message, &exponent);
  if(s != SUCCESS) return s;
  for(int h = 0; h < cm.n_halfedges; ++h)
    if(!cm.is_border_halfedge(h) && !(std::fabs(cm.u[h]) < max_grid_coordinate && std::fabs(cm.v[h]) < max_grid_coordinate)) {
      r.message = "the UV of corner (vertex " + std::to_string(cm.target[h]) + ", face " + std::to_string(cm.face[h]) +
                  ") is 2^30 grid units or more from the origin: the quad mesh would be too large";
      return RANGE_EXCEEDED;
    }

  facts = map_facts(cm);
  r.input_euler_characteristic = facts.euler_characteristic;
  r.input_boundary_loops = facts.boundary_loops;
  r.cones = facts.cones;
  r.uv_area = CGAL::Gmpq(facts.twice_area) / 2;
  return check_cones(cm, facts.valence, facts.on_border, edge_k, opt, r.message);
}

// The 3D point of an integer point p: the combination of the vertices of its edge or face with the
// barycentric coordinates of p, evaluated in double precision (p itself is exact: Integer_point). On an
// edge the parameter is (p - a)_c / (b - a)_c along the coordinate c in which the edge is longer: two
// differences of exact numbers and a quotient, each rounded once. In a face the coordinates are ratios of
// the 2x2 determinants of the corners relative to p, rounded.
template <class Point3>
std::array<double, 3> integer_point_position(const Corner_mesh& cm, const Integer_point& p,
                                             const std::vector<Point3>& vertex_point)
{
  auto xyz = [&](int h) {
    const Point3& q = vertex_point[std::size_t(cm.target[h])];
    return std::array<double, 3>{{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}};
  };
  if(p.kind == AT_VERTEX) return xyz(p.halfedge);
  const double pu = double(p.uv.u), pv = double(p.uv.v);
  int corner[3];
  double w[3];
  if(p.kind == ON_EDGE) {                          // from source(h) (corner prev(h)) to target(h)
    corner[0] = cm.prev[p.halfedge]; corner[1] = p.halfedge; corner[2] = -1;
    const double du = cm.u[corner[1]] - cm.u[corner[0]], dv = cm.v[corner[1]] - cm.v[corner[0]];
    const double lambda = std::fabs(du) >= std::fabs(dv) ? (pu - cm.u[corner[0]]) / du : (pv - cm.v[corner[0]]) / dv;
    w[0] = 1 - lambda; w[1] = lambda; w[2] = 0;
  } else {
    corner[0] = p.halfedge; corner[1] = cm.next[p.halfedge]; corner[2] = cm.next[corner[1]];
    double x[3], y[3];
    for(int i = 0; i < 3; ++i) { x[i] = cm.u[corner[i]] - pu; y[i] = cm.v[corner[i]] - pv; }
    double total = 0;
    for(int i = 0; i < 3; ++i) {                   // twice the area of (p, corner i+1, corner i+2)
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      w[i] = x[j] * y[k] - y[j] * x[k];
      total += w[i];
    }
    for(double& wi : w) wi /= total;
  }
  std::array<double, 3> r{{0, 0, 0}};
  for(int i = 0; i < 3; ++i) {
    if(corner[i] < 0) continue;
    const std::array<double, 3> q = xyz(corner[i]);
    for(int k = 0; k < 3; ++k) r[std::size_t(k)] += w[i] * q[std::size_t(k)];
  }
  return r;
}

// Stages 1-3 on a corner mesh built from the caller's mesh; `vertex_point` in the numbering of cm.
template <class Point3>
Status extract_quads(int scale_exponent, const Quad_options& opt, const std::vector<Point3>& vertex_point,
                     Quad_extraction& out, Quad_mesh_report& r)
{
  auto t0 = std::chrono::steady_clock::now();
  Corner_mesh& cm = out.cm;
  Map_facts facts;
  std::vector<int> edge_k, collinear;
  Status s = check_quad_input(cm, scale_exponent, opt, edge_k, facts, collinear, r);
  r.check_ms = ms_since(t0);
  if(s != SUCCESS) return s;

  t0 = std::chrono::steady_clock::now();
  std::vector<int> face_halfedge(std::size_t(cm.n_faces), -1);
  for(int h : face_first_halfedges(cm)) face_halfedge[std::size_t(cm.face[h])] = h;
  const std::vector<Grid_transform> transition = halfedge_transitions(cm, edge_k);
  const Collapsed_faces collapsed(cm.n_faces, collinear);
  const std::vector<char> branch_vertex = branch_vertices(cm, facts, opt);
  {
    Cell_pieces pieces;                              // freed before the mesh is built (the peak memory: see below)
    s = collect_cell_pieces(cm, face_halfedge, collapsed.is_collapsed, opt.max_grid_cells, pieces, r.message);
    if(s == SUCCESS) s = stitch_cells(cm, face_halfedge, transition, pieces, collapsed, branch_vertex, out.cells, r.message);
  }
  if(s == SUCCESS) s = repair_cells(cm, facts, edge_k, branch_vertex, out, r);
  r.cells_ms = ms_since(t0);
  if(s != SUCCESS) return s;
  r.incomplete_cells = out.cells.incomplete;
  if(out.cells.quads.empty()) {                      // no mesh to make (the checks below would fail as internal errors)
    r.message = "the map holds no whole cell of the integer grid (UV area " +
                format_double(CGAL::to_double(facts.twice_area) / 2) + " grid cells" +
                (out.cells.incomplete > 0 ? ", " + std::to_string(out.cells.incomplete) + " cells cut by the border" : std::string()) +
                "): no quad mesh; a larger grid_scale makes the cells smaller";
    return INVALID_INPUT;
  }

  t0 = std::chrono::steady_clock::now();
  const Quad_cells& cells = out.cells;
  out.positions.clear();
  for(const Integer_point& p : cells.points) out.positions.push_back(integer_point_position(cm, p, vertex_point));
  // the cells as faces (Euler::add_face() on index arrays: refused where it refuses them), then onto the mesh; the
  // arrays are freed before the mesh is measured and copied into the caller's (extract_quad_mesh_impl.h). With the
  // pieces freed before them, the 22.2M quads of a fuzzed map peak at 6.3 GB instead of 7.0 (about 290 bytes per quad,
  // at the copy: this mesh and the caller's, the cells and the positions)
  Quad_surface& m = out.mesh;
  m.clear();
  std::size_t refused = 0;
  {
    Halfedge_arrays a(cells.points.size(), cells.quads.size(), 4);
    for(const std::array<int, 4>& q : cells.quads) refused += a.add_face(q) ? 0 : 1;
    std::vector<Quad_surface::Vertex_index> vs;
    std::vector<Quad_surface::Halfedge_index> hs;
    std::vector<Quad_surface::Face_index> fs;
    copy_to(a, m, vs, hs, fs);
    for(std::size_t i = 0; i < vs.size(); ++i)
      m.point(vs[i]) = Quad_surface::Point(out.positions[i][0], out.positions[i][1], out.positions[i][2]);
  }
  measure_quad_mesh(m, r);
  if(refused > 0 || r.non_manifold_vertices > 0) {
    std::string first;
    analyze_quad_soup(cells.quads, r, first);
    r.message = "the " + std::to_string(cells.quads.size()) + " cells do not form a polygon mesh (" +
                std::to_string(refused) + " could not be added: " + std::to_string(r.repeated_vertex_quads) +
                " with a corner twice, " + std::to_string(r.non_manifold_edges) + " edges of more than two cells or " +
                "twice in one direction; " + std::to_string(r.non_manifold_vertices) + " vertices whose cells form "
                "several fans" + (first.empty() ? "" : "; " + first) + "): the integer grid is too coarse for the surface "
                "(use a larger grid_scale)";
    r.mesh_ms = ms_since(t0);
    return INVALID_INPUT;
  }
  const bool verified = verify_quad_guarantees(m, cells, facts, out.repairs, r, r.message);
  r.mesh_ms = ms_since(t0);
  return verified ? SUCCESS : EXACTNESS_CHECK_FAILED;
}

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_EXTRACTION_H
