// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_CONNECTION_CONSTRAINTS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_CONNECTION_CONSTRAINTS_H

// Connection constraints (Eq. 6) and cycle constraints (Eq. 8), Sec. 5.1, and their reduction to
// node variables (Sec. 5.3, "Connections and Cycles"). The semantics are documented with the public
// `Connection_constraint`; here is how the rows are built.
//
// Path h_0, ..., h_{n-1} from a = w_0 to b = w_n. Corners are halfedges (corner convention: the
// corner of halfedge g is (target(g), face(g))).
//   F_i: face(h_i), or face(opposite(h_i)) if h_i is a border halfedge;
//   c_i: the corner of w_i in F_i     (prev(h_i), resp. opposite(h_i));
//   d_i: the corner of w_{i+1} in F_i (h_i,       resp. prev(opposite(h_i))).
//   q_i: quarter turns from the frame of F_i to the frame of F_0. q_0 = 0; between d_{i-1} and c_i
//        the strip turns around w_i, and crossing from face(g) into the next face across the edge
//        of a halfedge g' of face(g) gives q <- q - k(g') (R^k(g') maps the frame of face(g') to the
//        frame of face(opposite(g'))).
// Row (over sector variables, k = component):
//   sum_i [ R^{q_i} (x_{s(d_i)} - x_{s(c_i)}) ]_k = 0.
// Inside one sector the terms of consecutive halfedges cancel (same sector, same q): what remains
// are the two endpoint sectors and, at each cut edge crossed around an inner vertex w, the pair
// R^{q} x_{s_before} - R^{q'} x_{s_after}, i.e. the translation of Eq. (7) at w.
//
// Turning around w_i (from corner g to corner g', both with target w_i): clockwise (the left
// side of the path), g <- opposite(next(g)) crossing the edge of next(g); if that meets the border,
// counter-clockwise, g <- prev(opposite(g)) crossing the edge of g. A manifold vertex always allows
// one of the two.
//
// Reduction (Sec. 5.3): path endpoints are nodes (node rule 2). At a crossing at an inner vertex
// w_{t+1} of a cut branch (sectors u^+, u^- of the branch plan), the pair is R^q applied to
// +-(u^- - R^k u^+) (the branch's translation, Eq. 7); the cumulative equations (Eq. 9) give
//   u^-_{t+1} = u_0^- - R^k u_0^+ + R^k u^+_{t+1},
// and substituting this for every implied sector u^- leaves node variables only (the u^+ terms
// cancel), i.e. t = u^-_{t+1} - R^k u^+_{t+1} turns into t = u_0^- - R^k u_0^+.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/reduced_system.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// A connection or cycle constraint in the numbering of `Corner_mesh` (-1: not a halfedge of the mesh).
struct Connection_path
{
  std::vector<int> halfedges;
  int component = 0;
};

// No connection_constraints parameter: nothing to convert.
template <class TriangleMesh>
void connection_paths_from_parameter(const TriangleMesh&, CGAL::internal_np::Param_not_found, std::vector<Connection_path>& out)
{
  out.clear();
}

// Converts a range of Connection_constraint<halfedge_descriptor> to the numbering of `Corner_mesh`
// (positions in the enumeration `halfedges(tm)`, as build_corner_mesh() numbers them).
template <class TriangleMesh, class ConnectionRange>
void connection_paths_from_parameter(const TriangleMesh& tm, const ConnectionRange& range, std::vector<Connection_path>& out)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  out.clear();
  auto him = CGAL::get_initialized_halfedge_index_map(tm);
  std::size_t max_h = 0;
  for(halfedge_descriptor h : halfedges(tm)) max_h = (std::max)(max_h, std::size_t(get(him, h)) + 1);
  std::vector<int> hpos(max_h, -1);
  int n = 0;
  for(halfedge_descriptor h : halfedges(tm)) hpos[get(him, h)] = n++;
  for(const auto& c : range) {
    Connection_path p;
    p.component = int(c.component);
    for(const halfedge_descriptor& h : c.path) {
      if(h == boost::graph_traits<TriangleMesh>::null_halfedge()) { p.halfedges.push_back(-1); continue; }   // no index
      const std::size_t i = std::size_t(get(him, h));                       // to read (Polyhedron_3: a null pointer)
      p.halfedges.push_back(i < max_h ? hpos[i] : -1);
    }
    out.push_back(p);
  }
}

inline std::string connection_name(std::size_t j) { return "connection constraint " + std::to_string(j); }

// Constraint_rows::edge of the rows of a pinned corner h (pinned_corners.h): below every
// connection constraint's -1 - j
constexpr int pinned_row_base = -(1 << 30);
inline int pinned_row_origin(int h) { return pinned_row_base - h; }

// what a row of the full system comes from: Constraint_rows::edge, e >= 0 a mesh edge,
// pinned_row_base < e < 0 the connection constraint -1 - e, e <= pinned_row_base the pinned corner
// pinned_row_base - e
inline std::string row_origin_name(const Corner_mesh& cm, int e)
{
  if(e <= pinned_row_base) {
    const int h = pinned_row_base - e;
    return "pinned corner (vertex " + std::to_string(cm.target[h]) + ", face " + std::to_string(cm.face[h]) + ")";
  }
  return e >= 0 ? "edge " + vertex_pair_name(cm, cm.edge_halfedge[e]) : connection_name(std::size_t(-1 - e));
}

// Turns around vertex target(from) from corner `from` to corner `to` (see the header comment),
// updating the quarter turns q. Returns false if both directions meet the border (non-manifold).
inline bool turn_around_vertex(const Corner_mesh& cm, const Cut_rotations& rot, int from, int to, int& q)
{
  const int limit = cm.n_halfedges;   // more steps than any vertex degree
  int g = from, qq = q, steps = 0;
  bool ok = true;
  while(g != to) {                    // clockwise: the left side of the path
    const int crossed = cm.next[g];
    qq -= rot.k[crossed];
    g = cm.opp[crossed];
    if(cm.face[g] < 0 || ++steps > limit) { ok = false; break; }
  }
  if(ok) { q = qq; return true; }
  g = from; qq = q; steps = 0;
  while(g != to) {                    // counter-clockwise: the right side
    qq -= rot.k[g];
    g = cm.prev[cm.opp[g]];
    if(cm.face[g] < 0 || ++steps > limit) return false;
  }
  q = qq;
  return true;
}

// Checks the paths and appends one row per constraint to `rows` (Eq. 6 / Eq. 8 with Eq. 7), with
// `edge` = -1 - j for constraint j. A row that cancels completely (e.g. a path that goes back and
// forth over one edge) holds for every u and is not stored. `endpoints[v]` is set for the two end
// vertices of every path (nodes, Sec. 5.3). On INVALID_INPUT nothing is appended.
inline Status add_connection_rows(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                  const std::vector<Connection_path>& paths, Constraint_rows& rows,
                                  std::vector<char>& endpoints, std::string& message)
{
  endpoints.assign(cm.n_vertices, 0);
  // validation first, so that an invalid constraint leaves `rows` unchanged
  for(std::size_t j = 0; j < paths.size(); ++j) {
    const Connection_path& p = paths[j];
    if(p.component != 0 && p.component != 1) {
      message = connection_name(j) + ": component " + std::to_string(p.component) + " is neither 0 (u) nor 1 (v)";
      return INVALID_INPUT;
    }
    if(p.halfedges.empty()) {
      message = connection_name(j) + ": the path is empty";
      return INVALID_INPUT;
    }
    for(std::size_t i = 0; i < p.halfedges.size(); ++i) {
      const int h = p.halfedges[i];
      if(h < 0 || h >= cm.n_halfedges) {
        message = connection_name(j) + ": halfedge " + std::to_string(i) + " of the path is not a halfedge of the mesh";
        return INVALID_INPUT;
      }
      if(cm.face[h] < 0 && cm.face[cm.opp[h]] < 0) {
        message = connection_name(j) + ": halfedge " + std::to_string(i) + " of the path " + vertex_pair_name(cm, h) +
                  " has no incident face";
        return INVALID_INPUT;
      }
      if(i > 0 && cm.source(h) != cm.target[p.halfedges[i - 1]]) {
        message = connection_name(j) + ": the path is not connected: halfedge " + std::to_string(i - 1) + " " +
                  vertex_pair_name(cm, p.halfedges[i - 1]) + " ends at vertex " + std::to_string(cm.target[p.halfedges[i - 1]]) +
                  " but halfedge " + std::to_string(i) + " " + vertex_pair_name(cm, h) + " starts at vertex " +
                  std::to_string(cm.source(h));
        return INVALID_INPUT;
      }
    }
  }

  std::vector<std::pair<int, int> > terms;
  for(std::size_t j = 0; j < paths.size(); ++j) {
    const Connection_path& p = paths[j];
    const int comp = p.component;
    terms.clear();
    int q = 0, d_prev = -1;
    // +- (R^q x_s)_comp
    auto add_point = [&](int corner, int sign) {
      const Quarter_turn R(q);
      terms.emplace_back(2 * st.sector_of[corner] + R.col[comp], sign * R.sign[comp]);
    };
    for(std::size_t i = 0; i < p.halfedges.size(); ++i) {
      const int h = p.halfedges[i];
      int c, d;
      if(cm.face[h] >= 0) { c = cm.prev[h]; d = h; }
      else { c = cm.opp[h]; d = cm.prev[cm.opp[h]]; }
      if(i > 0 && !turn_around_vertex(cm, rot, d_prev, c, q)) {
        message = connection_name(j) + ": cannot go around vertex " + std::to_string(cm.target[c]) +
                  " without crossing the border (non-manifold vertex)";
        return INVALID_INPUT;
      }
      add_point(d, 1);
      add_point(c, -1);
      d_prev = d;
    }
    rows.add(terms, -1 - int(j));
    endpoints[cm.source(p.halfedges.front())] = 1;
    endpoints[cm.target[p.halfedges.back()]] = 1;
  }
  return SUCCESS;
}

// Appends to rs.node_rows the rows [first, rows.size()) of the full system `rows` (connection and
// cycle rows, integer-grid rows) with every implied sector u^- of a cut branch replaced by
// u_0^- - R^k u_0^+ + R^k u^+ (Eq. 9), and the aligned component of every inner sector of an align
// branch by that of u_0. Rows that become identical (e.g. the translation rows of the edges of one
// branch) are added once; a row that becomes 0 = b != 0 is INFEASIBLE. The non-node variables of
// the rows must be implied ones (path endpoints are forced nodes in `build_reduced_system`);
// fails (an internal error) if a non-node variable is left over.
inline Status add_reduced_connection_rows(const Corner_mesh& cm, const Seam_topology& st, const Constraint_rows& rows,
                                          std::size_t first, Reduced_system& rs, std::string& message)
{
  if(first >= rows.size()) return SUCCESS;
  // implied[s] = index of the cut branch and position of the inner pair whose u^- is s
  std::vector<std::pair<int, int> > implied(st.n_sectors, std::make_pair(-1, -1));
  for(std::size_t b = 0; b < rs.cut_branches.size(); ++b)
    for(std::size_t t = 0; t < rs.cut_branches[b].inner.size(); ++t)
      implied[rs.cut_branches[b].inner[t].second] = std::make_pair(int(b), int(t));
  // aligned[2s + c] = the variable u_0|c of the align branch with inner sector s and component c
  std::vector<int> aligned(2 * std::size_t(st.n_sectors), -1);
  for(const Align_branch_plan& p : rs.align_branches)
    for(int s : p.inner) aligned[2 * s + p.component] = 2 * p.u0 + p.component;
  std::set<std::vector<long> > seen;   // reduced rows added so far: (col, coef)..., rhs

  for(std::size_t i = first; i < rows.size(); ++i) {
    std::map<int, long long> row;
    std::vector<std::pair<int, long long> > substitute;
    for(std::size_t e = rows.start[i]; e < rows.start[i + 1]; ++e) {
      const int var = rows.col[e];
      if(implied[var / 2].first >= 0) substitute.emplace_back(var, rows.coef[e]);
      else row[aligned[var] >= 0 ? aligned[var] : var] += rows.coef[e];
    }
    for(const std::pair<int, long long>& sv : substitute) {
      const int s = sv.first / 2, c = sv.first % 2;
      const long long a = sv.second;
      const Cut_branch_plan& p = rs.cut_branches[std::size_t(implied[s].first)];
      const int plus = p.inner[std::size_t(implied[s].second)].first;
      const Quarter_turn R(p.k);
      // (u^-)_c = (u_0^-)_c - sign_c (u_0^+)_{col_c} + sign_c (u^+)_{col_c}
      row[2 * p.u0_minus + c] += a;
      row[2 * p.u0_plus + R.col[c]] -= a * R.sign[c];
      row[2 * plus + R.col[c]] += a * R.sign[c];
    }
    std::vector<std::pair<int, int> > terms;
    for(const std::pair<const int, long long>& t : row) {
      if(t.second == 0) continue;
      const int v = st.sector_vertex(cm, t.first / 2);
      if(!rs.is_node[v]) {
        message = row_origin_name(cm, rows.edge[i]) + ": after the substitution of Eq. (9) the row still has " +
                  "the non-node sector " + std::to_string(t.first / 2) + " (vertex " + std::to_string(v) +
                  "): internal error of the reduction";
        return EXACTNESS_CHECK_FAILED;
      }
      if(t.second > (std::numeric_limits<int>::max)() || t.second < -(std::numeric_limits<int>::max)()) {
        message = row_origin_name(cm, rows.edge[i]) + ": coefficient overflow in the reduced row";
        return RANGE_EXCEEDED;
      }
      terms.emplace_back(t.first, int(t.second));
    }
    std::vector<long> key;
    for(const std::pair<int, int>& t : terms) { key.push_back(t.first); key.push_back(t.second); }
    key.push_back(rows.rhs[i]);
    if(!seen.insert(key).second) continue;
    if(!rs.node_rows.add(terms, rows.edge[i], rows.rhs[i]) && rows.rhs[i] != 0) {
      message = row_origin_name(cm, rows.edge[i]) + ": after the substitution of Eq. (9) the row reads 0 = " +
                std::to_string(rows.rhs[i]) + ": the constraints contradict each other";
      return INFEASIBLE;
    }
  }
  return SUCCESS;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_CONNECTION_CONSTRAINTS_H
