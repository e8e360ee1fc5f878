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
#include <CGAL/Seamless_snapping/internal/threads.h>

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

// The arguments (y, x) of atan2 for the signed UV angle at the corner h of its triangle (corner_angle()).
inline void corner_angle_arguments(const Corner_mesh& cm, int h, double& y, double& x)
{
  const int hn = cm.next[h], hp = cm.prev[h];
  double ax = cm.u[hn] - cm.u[h], ay = cm.v[hn] - cm.v[h];
  double bx = cm.u[hp] - cm.u[h], by = cm.v[hp] - cm.v[h];
  // the angle does not depend on the scale: bring the edge vectors to magnitude ~1 by a power of 2
  // (exact) so that the products below neither underflow nor overflow, also for tiny triangles
  const double m = (std::max)({std::fabs(ax), std::fabs(ay), std::fabs(bx), std::fabs(by)});
  if(m > 0) {   // (std::frexp and std::ldexp, bit for bit: corner_mesh.h)
    const int e = binary_exponent(m);
    ax = scale_by_power_of_two(ax, -e); ay = scale_by_power_of_two(ay, -e);
    bx = scale_by_power_of_two(bx, -e); by = scale_by_power_of_two(by, -e);
  }
  y = ax * by - ay * bx;
  x = ax * bx + ay * by;
}

// Signed UV angle (radians) at the corner h of its triangle: from the edge to the next vertex to
// the edge to the previous vertex, positive for a counter-clockwise (non-flipped) UV triangle.
inline double corner_angle(const Corner_mesh& cm, int h)
{
  double y, x;
  corner_angle_arguments(cm, h, y, x);
  return std::atan2(y, x);
}

// atan2(y, x) for x != 0 and y != 0 within 3e-9: octant reduction to atan(t), t in (0, 1], then
// atan(t) = pi/6 + atan(s), s = (sqrt(3) t - 1) / (sqrt(3) + t), for t > tan(pi/12), so that |s| <= 0.268,
// and atan(s) by its Taylor series up to s^11: an alternating series whose terms decrease, so the error is
// below the first omitted term, 0.268^13 / 13 < 2.9e-9 (the rounding of the few operations adds < 1e-14).
// Only used to certify rounded angle sums (compute_seam_topology()), never as a result.
inline double atan2_within_3e_9(double y, double x)
{
  const double pi = 3.141592653589793, half_pi = 1.5707963267948966, sixth_pi = 0.5235987755982988;
  const double sqrt3 = 1.7320508075688772, tan_twelfth_pi = 0.2679491924311227;
  const double ax = std::fabs(x), ay = std::fabs(y);
  const bool steep = ay > ax;
  double t = steep ? ax / ay : ay / ax, base = 0;
  if(t > tan_twelfth_pi) { t = (sqrt3 * t - 1) / (sqrt3 + t); base = sixth_pi; }
  // the coefficients 1/3, 1/5, ..., 1/11 rounded to doubles, as literals: with -frounding-math (CGAL's flags)
  // the compiler does not fold 1. / 3 and would divide five times per call
  const double c3 = 0.3333333333333333, c5 = 0.2, c7 = 0.14285714285714285, c9 = 0.1111111111111111,
               c11 = 0.09090909090909091;
  const double t2 = t * t;
  double r = base + t * (1 + t2 * (-c3 + t2 * (c5 + t2 * (-c7 + t2 * (c9 + t2 * (-c11))))));
  if(steep) r = half_pi - r;
  if(x < 0) r = pi - r;
  return y < 0 ? -r : r;
}

// The corners' loops below read the UVs of next(h) and prev(h), which in a mesh whose faces are not listed in
// order of adjacency lie far from h (the 302K-face bunny of ../shared/large: 63 % of the interior halfedges
// more than 512 apart): what halfedge h + this distance will read is prefetched.
constexpr int seam_prefetch_distance = 16;
inline void prefetch_uv(const Corner_mesh& cm, int h)
{
  __builtin_prefetch(&cm.u[std::size_t(h)]);
  __builtin_prefetch(&cm.v[std::size_t(h)]);
}

// The UV bounding box, the cut edges and the sectors of compute_seam_topology(); st.quarter_turns and st.is_cone
// are left alone (cone_quarter_turns()).
inline Status compute_cuts_and_sectors(const Corner_mesh& cm, const std::vector<signed char>& seam_override,
                                       Seam_topology& st, std::string& message)
{
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
  // per corner c, the next corner of its sector across edge(c) (prev(opp(c))) and the one across edge(next(c))
  // (opp(next(c))), or -1 where that edge is cut or on the border: written here, edge by edge, where prev(h) and
  // prev(o) are read anyway, so that the sector walks below read one array per step (instead of next or prev, and a
  // mark per halfedge): on the 302K-face bunny of ../shared/large the walks 25-33 -> 10-12 ms, this loop 7 -> 9 ms
  std::vector<int> across(nh, -1), back(nh, -1);
  for(int e = 0; e < cm.n_edges; ++e) {
    if(e + seam_prefetch_distance < cm.n_edges) {     // the corners before h and before o (h and o are 2e, 2e + 1)
      const int g = cm.edge_halfedge[std::size_t(e + seam_prefetch_distance)];
      prefetch_uv(cm, cm.prev[std::size_t(g)]);
      prefetch_uv(cm, cm.prev[std::size_t(cm.opp[std::size_t(g)])]);
    }
    if(cm.is_border_edge(e)) continue;
    const int h = cm.edge_halfedge[e], o = cm.opp[h];
    bool cut;
    if(!seam_override.empty() && seam_override[e] >= 0) cut = seam_override[e] != 0;
    else cut = !same_uv(cm, h, cm.prev[o]) || !same_uv(cm, cm.prev[h], o);
    if(!cut) {
      const int ph = cm.prev[h], po = cm.prev[o];
      across[h] = po; across[o] = ph;
      back[po] = h; back[ph] = o;
      continue;
    }
    st.is_cut[e] = 1;
    st.cut_edges.push_back(e);
    ++st.cut_degree[cm.target[h]];
    ++st.cut_degree[cm.target[o]];
  }

  // sectors: corners joined across non-cut interior edges. Around a vertex the corners form a fan (a
  // path or a cycle: corner c meets prev(opp(c)) across edge(c) and opp(next(c)) across edge(next(c))),
  // so each sector is walked once from its smallest halfedge, in both directions; the sectors are numbered
  // in the order of their smallest halfedges (as a union-find with the smallest representative did).
  // The walk touches as few arrays as it can (its loads are random); the UVs are compared afterwards, in
  // halfedge order: a corner whose UV differs from its sector's first corner is an error, the smallest one named.
  st.sector_of.assign(nh, -1);
  for(int h = 0; h < nh; ++h) {
    if(cm.is_border_halfedge(h) || st.sector_of[h] >= 0) continue;
    const int s = st.n_sectors++;
    st.sector_corner.push_back(h);
    st.sector_of[h] = s;
    bool closed = false;
    for(int c = across[h]; c >= 0; c = across[c]) {       // across edge(c)
      if(c == h) { closed = true; break; }
      st.sector_of[c] = s;
    }
    if(!closed)
      for(int c = back[h]; c >= 0; c = back[c]) st.sector_of[c] = s;   // across edge(next(c))
  }
  st.ubar.resize(2 * std::size_t(st.n_sectors));
  for(int s = 0; s < st.n_sectors; ++s) {
    st.ubar[2 * std::size_t(s)] = cm.u[st.sector_corner[s]];
    st.ubar[2 * std::size_t(s) + 1] = cm.v[st.sector_corner[s]];
  }
  int mismatch = nh;
  for(int h = 0; h < nh && mismatch == nh; ++h)
    if(!cm.is_border_halfedge(h)) {
      const std::size_t s = std::size_t(st.sector_of[h]);
      if(cm.u[h] != st.ubar[2 * s] || cm.v[h] != st.ubar[2 * s + 1]) mismatch = h;
    }
  if(mismatch < nh) {
    const int h = mismatch, s = st.sector_of[h];
    message = "the corners of vertex " + std::to_string(cm.target[h]) + " in faces " +
              std::to_string(cm.face[h]) + " and " + std::to_string(cm.face[st.sector_corner[s]]) +
              " have different UVs but are joined by edges that are not seams (check the seam_edge_map)";
    return INVALID_INPUT;
  }
  return SUCCESS;
}

// The cones of compute_seam_topology(): per vertex, its UV angle sum in quarter turns (4 on the border) and whether
// that is not 4. Reads the corner mesh only.
inline void cone_quarter_turns(const Corner_mesh& cm, std::vector<int>& quarter_turns, std::vector<char>& is_cone)
{
  const int nh = cm.n_halfedges;
  // cones: quarter_turns[v] = lround(angle sum / (pi / 2)), the angle sum being the sum of the corners'
  // std::atan2 angles in halfedge order. The sums are first taken of atan2_within_3e_9(), which is several
  // times cheaper than std::atan2; a vertex whose approximate sum is provably rounded to the same number of
  // quarter turns as the std::atan2 sum keeps it, the others (a corner angle of 0 or pi, or a sum within
  // about 1e-8 of an odd multiple of 45 degrees) are summed with std::atan2 as before. The bound: per corner,
  // 3e-9 for the approximation and 2 ulp(pi) for std::atan2 (glibc's atan2 is within 1 ulp); per sum of n
  // terms of magnitude at most pi, a rounding error of at most n^2 u pi for each of the two sums.
  const double quarter = std::acos(-1.) / 2;
  struct Vertex_sum { double approximate = 0; int corners = 0; bool exact = false; };   // exact: std::atan2 needed
  std::vector<Vertex_sum> sums(cm.n_vertices);     // one cache line per vertex for the random accesses below
  for(int h = 0; h < nh; ++h) {
    if(h + seam_prefetch_distance < nh) {
      prefetch_uv(cm, cm.next[std::size_t(h + seam_prefetch_distance)]);
      prefetch_uv(cm, cm.prev[std::size_t(h + seam_prefetch_distance)]);
      __builtin_prefetch(&sums[std::size_t(cm.target[std::size_t(h + seam_prefetch_distance)])], 1);   // the bunny: 23-29 -> 19-20 ms
    }
    if(cm.is_border_halfedge(h)) continue;
    const int v = cm.target[h];
    double y, x;
    corner_angle_arguments(cm, h, y, x);
    ++sums[v].corners;
    if(y == 0 || x == 0) { sums[v].exact = true; continue; }    // signed zeros and angles of exactly 0, +-pi/2, pi
    sums[v].approximate += atan2_within_3e_9(y, x);
  }
  quarter_turns.assign(cm.n_vertices, 4);
  is_cone.assign(cm.n_vertices, 0);
  bool any_exact = false;
  for(int v = 0; v < cm.n_vertices; ++v) {
    if(cm.vertex_on_border[v] || sums[v].corners == 0 || sums[v].exact) { any_exact = any_exact || sums[v].exact; continue; }
    const double n = double(sums[v].corners);
    const double bound = (n * (3e-9 + 1e-14 + 1e-15) + 2 * n * n * 3.5e-16) / quarter + 1e-12;
    const double turns = sums[v].approximate / quarter;
    const double k = std::nearbyint(turns);
    if(std::fabs(turns - k) <= 0.5 - bound && std::fabs(k) < 1e9) {
      quarter_turns[v] = int(k);
      is_cone[v] = quarter_turns[v] != 4;
    } else {
      sums[v].exact = true;
      any_exact = true;
    }
  }
  if(any_exact) {
    std::vector<double> angle_sum(cm.n_vertices, 0.);
    for(int h = 0; h < nh; ++h)
      if(!cm.is_border_halfedge(h) && sums[cm.target[h]].exact) angle_sum[cm.target[h]] += corner_angle(cm, h);
    for(int v = 0; v < cm.n_vertices; ++v) {
      if(cm.vertex_on_border[v] || sums[v].corners == 0 || !sums[v].exact) continue;   // border or isolated vertex
      quarter_turns[v] = int(std::lround(angle_sum[v] / quarter));
      is_cone[v] = quarter_turns[v] != 4;
    }
  }
}

// `seam_override[e]`: -1 = decide from the UVs, 0 = not a seam, 1 = seam (the caller's seam_edge_map).
// Border edges are never cut edges. The cones and the sectors share nothing that either writes: with `threads` >= 2
// they are found on two threads (internal/threads.h), the same results.
inline Status compute_seam_topology(const Corner_mesh& cm, const std::vector<signed char>& seam_override,
                                    Seam_topology& st, std::string& message, unsigned threads = 1)
{
  st = Seam_topology();
  Status s = SUCCESS;
  run_concurrently(threads, [&] { s = compute_cuts_and_sectors(cm, seam_override, st, message); },
                   [&] { cone_quarter_turns(cm, st.quarter_turns, st.is_cone); });
  return s;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_SEAM_TOPOLOGY_H
