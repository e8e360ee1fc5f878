// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_REDUCED_SYSTEM_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_REDUCED_SYSTEM_H

// The reduced constraint system of Sec. 5.3: nodes, branches, cumulative equations.
//
// Nodes (Sec. 5.3, plus the cases a chain decomposition needs):
//   cones; vertices with cut-degree 1 or > 2; border vertices with a cut edge; vertices with a cut
//   edge and an align edge; vertices with align edges of different components; vertices whose
//   align-degree is 1 or > 2; vertices of cut-degree 2 where the rotation k changes along the chain
//   or whose two sides do not continue (sector structure), and the smallest vertex of a closed
//   cut (or align) loop without any node; the endpoints of connection and cycle constraints
//   (their rows are reduced to node variables in connection_constraints.h).
// Branches: the chains of cut (resp. align) edges between nodes; k (resp. the aligned component)
//   is constant along a branch.
//
// Cut branch w_0, ..., w_m, h_i the halfedge w_i -> w_{i+1}, + side = face(h_i) (left), - side =
// face(opposite(h_i)); u_i^+ / u_i^- the sectors of w_i on the two sides. The transition rows
//   tau_i: R^k (u_i^+ - u_{i+1}^+) - (u_i^- - u_{i+1}^-) = 0
// are replaced by their cumulative sums (Eq. 9)
//   sum_{i<=t} tau_i: R^k (u_0^+ - u_{t+1}^+) - (u_0^- - u_{t+1}^-) = 0,   t = 0, ..., m-1.
// The row t = m-1 has node sectors only and goes to the node system C (2 rows per cut branch);
// the rows t < m-1 are solved for u_{t+1}^- after choosing u_{t+1}^+ freely (propagation).
// Align branch with component c: node row u_0|c - u_m|c = 0 (1 row per align branch); the rows
// t < m-1 give u_{t+1}|c = u_0|c.
// Right-hand sides: the rows of Eq. (4) and (5) are homogeneous, so the cumulative rows (Eq. 9)
// and the branch rows have b = 0; rows with b != 0 (connection/cycle constraints, integer-grid rows)
// enter the node system by substitution (connection_constraints.h) and keep their b there.

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/edge_chains.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

struct Cut_branch_plan
{
  int k = 0;                                  // rotation along the branch, for h_0 ... h_{m-1}
  int u0_plus = -1, u0_minus = -1;            // node sectors at w_0
  std::vector<std::pair<int, int> > inner;    // (u_{t+1}^+, u_{t+1}^-), t = 0 .. m-2: non-node sectors
};

struct Align_branch_plan
{
  int component = 0;
  int u0 = -1;                                // node sector at w_0
  std::vector<int> inner;                     // u_{t+1}, t = 0 .. m-2: non-node sectors
};

struct Reduced_system
{
  std::vector<char> is_node;                  // per vertex
  std::size_t n_nodes = 0;                    // node vertices with a cut or align edge
  std::vector<Cut_branch_plan> cut_branches;
  std::vector<Align_branch_plan> align_branches;
  Constraint_rows node_rows;                  // the node system C x = b over sector variables
};

// `forced_nodes[v]` (optional): further node vertices, the endpoints of connection and cycle
// constraints (node rule 2 of Sec. 5.3).
inline void build_reduced_system(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                 const Align_edges& al, Reduced_system& rs,
                                 const std::vector<char>& forced_nodes = std::vector<char>())
{
  rs = Reduced_system();
  const int nv = cm.n_vertices;
  std::vector<int> align_degree(nv, 0), align_mask(nv, 0);
  std::vector<char> is_align(cm.n_edges, 0);
  for(int e : al.edges) {
    is_align[e] = 1;
    const int h = cm.edge_halfedge[e];
    for(int w : {cm.target[h], cm.source(h)}) { ++align_degree[w]; align_mask[w] |= 1 << al.component[e]; }
  }

  // nodes
  rs.is_node.assign(nv, 0);
  std::vector<std::vector<int> > cut_halfedges_out(nv);     // cut halfedges with source v
  for(int e : st.cut_edges) {
    const int h = cm.edge_halfedge[e];
    cut_halfedges_out[cm.source(h)].push_back(h);
    cut_halfedges_out[cm.target[h]].push_back(cm.opp[h]);
  }
  std::vector<std::vector<int> > align_edges_at(nv);
  for(int e : al.edges) {
    const int h = cm.edge_halfedge[e];
    align_edges_at[cm.source(h)].push_back(e);
    align_edges_at[cm.target[h]].push_back(e);
  }
  for(int v = 0; v < nv; ++v) {
    const int cd = st.cut_degree[v], ad = align_degree[v];
    bool node = st.is_cone[v] || cd == 1 || cd > 2 || (cm.vertex_on_border[v] && cd > 0) ||
                (cd > 0 && ad > 0) || align_mask[v] == 3 || (ad > 0 && ad != 2) ||
                (!forced_nodes.empty() && forced_nodes[v]);
    if(!node && cd == 2) {
      // v inside a chain h_in -> h_out: same k, and the + and - sides continue through v
      const int h_out = cut_halfedges_out[v][1];
      const int h_in = cm.opp[cut_halfedges_out[v][0]];
      const int plus_in = st.sector_of[h_in], minus_in = st.sector_of[cm.prev[cm.opp[h_in]]];
      const int plus_out = st.sector_of[cm.prev[h_out]], minus_out = st.sector_of[cm.opp[h_out]];
      node = rot.k[h_in] != rot.k[h_out] || plus_in != plus_out || minus_in != minus_out || plus_in == minus_in;
    }
    if(!node && ad == 2) {
      const int e0 = align_edges_at[v][0], e1 = align_edges_at[v][1];
      node = st.sector_of[align_corner(cm, al, e0, v)] != st.sector_of[align_corner(cm, al, e1, v)];
    }
    rs.is_node[v] = node;
  }

  // cut branches
  Edge_chains chains;
  decompose_into_chains(cm, st.is_cut, rs.is_node, chains);
  for(int v : chains.loop_starts) rs.is_node[v] = 1;
  for(const std::vector<int>& ch : chains.chains) {
    Cut_branch_plan p;
    const int h0 = ch.front(), hm = ch.back();
    p.k = rot.k[h0];
    p.u0_plus = st.sector_of[cm.prev[h0]];
    p.u0_minus = st.sector_of[cm.opp[h0]];
    for(std::size_t t = 0; t + 1 < ch.size(); ++t)
      p.inner.emplace_back(st.sector_of[ch[t]], st.sector_of[cm.prev[cm.opp[ch[t]]]]);
    const int um_plus = st.sector_of[hm], um_minus = st.sector_of[cm.prev[cm.opp[hm]]];
    const Quarter_turn R(p.k);
    for(int c = 0; c < 2; ++c)
      rs.node_rows.add({ {2 * p.u0_plus + R.col[c], R.sign[c]}, {2 * um_plus + R.col[c], -R.sign[c]},
                         {2 * p.u0_minus + c, -1}, {2 * um_minus + c, 1} }, cm.edge[hm]);
    rs.cut_branches.push_back(p);
  }

  // align branches
  decompose_into_chains(cm, is_align, rs.is_node, chains);
  for(int v : chains.loop_starts) rs.is_node[v] = 1;
  for(const std::vector<int>& ch : chains.chains) {
    Align_branch_plan p;
    const int e0 = cm.edge[ch.front()], em = cm.edge[ch.back()];
    p.component = al.component[e0];
    p.u0 = st.sector_of[align_corner(cm, al, e0, cm.source(ch.front()))];
    for(std::size_t t = 0; t + 1 < ch.size(); ++t)
      p.inner.push_back(st.sector_of[align_corner(cm, al, cm.edge[ch[t]], cm.target[ch[t]])]);
    const int um = st.sector_of[align_corner(cm, al, em, cm.target[ch.back()])];
    rs.node_rows.add({ {2 * p.u0 + p.component, 1}, {2 * um + p.component, -1} }, em);
    rs.align_branches.push_back(p);
  }

  for(int v = 0; v < nv; ++v)
    if(rs.is_node[v] && (st.cut_degree[v] > 0 || align_degree[v] > 0 || (!forced_nodes.empty() && forced_nodes[v])))
      ++rs.n_nodes;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_REDUCED_SYSTEM_H
