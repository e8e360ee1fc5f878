// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_SEAM_TOPOLOGY_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_SEAM_TOPOLOGY_H

// Cut edges, sectors and cones of a corner UV map (Sec. 5 and 5.3).
//
// - Cut edge: an interior edge whose two faces disagree on the UV of an endpoint, compared as
//   numbers (with h = halfedge(e), o = opposite(h): uv[h] != uv[prev(o)] or uv[prev(h)] != uv[o]),
//   unless the caller says which edges are seams.
// - Sector: around a vertex, a maximal fan of corners joined across non-cut interior edges
//   (separated by cut edges and the border). Its corners share one UV: the sector variable.
//   Sector s owns the variables 2s (u) and 2s+1 (v).
// - Cone: an interior vertex whose signed UV angle sum, rounded to quarter turns, is not 4
//   (fold-overs can give any count, also 0 or negative ones; such vertices are cones too).

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

struct Seam_topology
{
  std::vector<char> is_cut;         // per edge
  std::vector<int> cut_edges;       // ids of the cut edges, ascending
  std::vector<int> cut_degree;      // per vertex: number of incident cut edges
  std::vector<int> sector_of;       // per halfedge: sector of the corner (target(h), face(h)); -1 on the border
  std::vector<int> sector_corner;   // per sector: its first corner (smallest halfedge index)
  int n_sectors = 0;
  std::vector<double> ubar;         // 2 per sector: the input UV of the sector (u at 2s, v at 2s+1)
  std::vector<int> quarter_turns;   // per vertex: round(UV angle sum / 90 degrees); 4 on the border
  std::vector<char> is_cone;        // per vertex
  double uv_min[2] = {0, 0}, uv_max[2] = {0, 0};
  double uv_diagonal = 0;           // diagonal of the UV bounding box of all corners

  int sector_vertex(const Corner_mesh& cm, int s) const { return cm.target[sector_corner[s]]; }
};

// Union-find with path halving; the representative is the smallest element, for determinism.
struct Union_find
{
  std::vector<int> parent;
  explicit Union_find(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) { while(parent[x] != x) { parent[x] = parent[parent[x]]; x = parent[x]; } return x; }
  void unite(int a, int b)
  {
    a = find(a); b = find(b);
    if(a == b) return;
    if(a < b) parent[b] = a; else parent[a] = b;
  }
};

inline bool same_uv(const Corner_mesh& cm, int h1, int h2)
{
  return cm.u[h1] == cm.u[h2] && cm.v[h1] == cm.v[h2];
}

inline std::string vertex_pair_name(const Corner_mesh& cm, int h)
{
  return "(" + std::to_string(cm.source(h)) + ", " + std::to_string(cm.target[h]) + ")";
}

// Signed UV angle (radians) at the corner h of its triangle: from the edge to the next vertex to
// the edge to the previous vertex, positive for a counter-clockwise (non-flipped) UV triangle.
inline double corner_angle(const Corner_mesh& cm, int h)
{
  const int hn = cm.next[h], hp = cm.prev[h];
  double ax = cm.u[hn] - cm.u[h], ay = cm.v[hn] - cm.v[h];
  double bx = cm.u[hp] - cm.u[h], by = cm.v[hp] - cm.v[h];
  // the angle does not depend on the scale: bring the edge vectors to magnitude ~1 by a power of 2
  // (exact) so that the products below neither underflow nor overflow, also for tiny triangles
  const double m = (std::max)({std::fabs(ax), std::fabs(ay), std::fabs(bx), std::fabs(by)});
  if(m > 0) {
    int e; std::frexp(m, &e);
    ax = std::ldexp(ax, -e); ay = std::ldexp(ay, -e); bx = std::ldexp(bx, -e); by = std::ldexp(by, -e);
  }
  return std::atan2(ax * by - ay * bx, ax * bx + ay * by);
}

// `seam_override[e]`: -1 = decide from the UVs, 0 = not a seam, 1 = seam (the caller's seam_edge_map).
// Border edges are never cut edges.
inline Status compute_seam_topology(const Corner_mesh& cm, const std::vector<signed char>& seam_override,
                                    Seam_topology& st, std::string& message)
{
  st = Seam_topology();
  const int nh = cm.n_halfedges;

  // UV bounding box
  bool first = true;
  for(int h = 0; h < nh; ++h) {
    if(cm.is_border_halfedge(h)) continue;
    const double p[2] = {cm.u[h], cm.v[h]};
    for(int c = 0; c < 2; ++c) {
      if(first || p[c] < st.uv_min[c]) st.uv_min[c] = p[c];
      if(first || p[c] > st.uv_max[c]) st.uv_max[c] = p[c];
    }
    first = false;
  }
  st.uv_diagonal = std::hypot(st.uv_max[0] - st.uv_min[0], st.uv_max[1] - st.uv_min[1]);

  // cut edges
  st.is_cut.assign(cm.n_edges, 0);
  st.cut_degree.assign(cm.n_vertices, 0);
  for(int e = 0; e < cm.n_edges; ++e) {
    if(cm.is_border_edge(e)) continue;
    const int h = cm.edge_halfedge[e], o = cm.opp[h];
    bool cut;
    if(!seam_override.empty() && seam_override[e] >= 0) cut = seam_override[e] != 0;
    else cut = !same_uv(cm, h, cm.prev[o]) || !same_uv(cm, cm.prev[h], o);
    if(!cut) continue;
    st.is_cut[e] = 1;
    st.cut_edges.push_back(e);
    ++st.cut_degree[cm.target[h]];
    ++st.cut_degree[cm.target[o]];
  }

  // sectors: corners joined across non-cut interior edges
  Union_find uf(nh);
  for(int e = 0; e < cm.n_edges; ++e) {
    if(st.is_cut[e] || cm.is_border_edge(e)) continue;
    const int h = cm.edge_halfedge[e], o = cm.opp[h];
    uf.unite(h, cm.prev[o]);      // corners of target(h)
    uf.unite(cm.prev[h], o);      // corners of source(h)
  }
  st.sector_of.assign(nh, -1);
  std::vector<int> sector_of_root(nh, -1);
  for(int h = 0; h < nh; ++h) {
    if(cm.is_border_halfedge(h)) continue;
    const int r = uf.find(h);
    if(sector_of_root[r] < 0) {
      sector_of_root[r] = st.n_sectors++;
      st.sector_corner.push_back(h);
      st.ubar.push_back(cm.u[h]);
      st.ubar.push_back(cm.v[h]);
    }
    const int s = sector_of_root[r];
    st.sector_of[h] = s;
    if(!same_uv(cm, h, st.sector_corner[s])) {
      message = "the corners of vertex " + std::to_string(cm.target[h]) + " in faces " +
                std::to_string(cm.face[h]) + " and " + std::to_string(cm.face[st.sector_corner[s]]) +
                " have different UVs but are joined by edges that are not seams (check the seam_edge_map)";
      return INVALID_INPUT;
    }
  }

  // cones
  std::vector<double> angle_sum(cm.n_vertices, 0.);
  std::vector<char> has_corner(cm.n_vertices, 0);
  for(int h = 0; h < nh; ++h)
    if(!cm.is_border_halfedge(h)) { angle_sum[cm.target[h]] += corner_angle(cm, h); has_corner[cm.target[h]] = 1; }
  st.quarter_turns.assign(cm.n_vertices, 4);
  st.is_cone.assign(cm.n_vertices, 0);
  const double quarter = std::acos(-1.) / 2;
  for(int v = 0; v < cm.n_vertices; ++v) {
    if(cm.vertex_on_border[v] || !has_corner[v]) continue;   // border or isolated vertex
    st.quarter_turns[v] = int(std::lround(angle_sum[v] / quarter));
    st.is_cone[v] = st.quarter_turns[v] != 4;
  }
  return SUCCESS;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_SEAM_TOPOLOGY_H
