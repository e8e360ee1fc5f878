// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_INTEGER_GRID_CONSTRAINTS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_INTEGER_GRID_CONSTRAINTS_H

// Integer-grid map (IGM) constraints (Bommes et al. 2009/2013): every transition u -> R^k u + t has
// an integer t, every cone of the field sits on an integer point, aligned edges lie on integer
// isolines. Rows with integer right-hand sides, appended to the full system after the homogeneous
// rows of Eq. (4)/(5); the reduction substitutes Eq. (9) (connection_constraints.h).
//
// Translation of the cut edge e, h = halfedge(e), o = opposite(h), a = source(h), k = k(h): with
// U^i the sector of a in face(h) (corner prev(h)) and U^j the sector of a in face(o) (corner o),
//   t_e = U^j - R^k U^i                     (Eq. 3/7; the rows of Eq. 4 make it the same at target(h))
// Rows: (U^j)_c - sign_c (U^i)_{col_c} = round(t_e)_c, c = 0, 1.
// Alignment edge e with component c, face of its halfedge g: (U_{prev g})_c = round(ubar)_c.
//
// Checks, before any row is built (nothing is written on failure):
// - "near an integer": |t - round(t)| <= tolerance in grid units (both ends of the edge) for every
//   cut edge, and for every align edge its isoline value at both ends; otherwise INVALID_INPUT
//   with advice (the input is not near an IGM: scale it, or snap without the integer-grid mode).
// - around every interior vertex with cut edges, the rounded transitions, composed in turn
//   (crossing halfedge g' from face(g') to face(opposite(g')): p -> R^k(g') p + t(g')), give
//   p -> R^K p + T. K = 0 mod 4 (not a cone of the field): T must be 0, else the rounded
//   translations contradict each other (INFEASIBLE). K != 0: the unique fixed point
//   p = (I - R^K)^{-1} T (a cone) must be an integer point (INFEASIBLE otherwise, e.g. a
//   half-integer forced by an odd translation around a 180 degree cone).
// The rows of the cone's sectors then force it onto that integer point exactly; no separate cone
// rows are needed. Vertices whose UV angle sum is not 2*pi but whose rotations compose to the
// identity (fold-overs next to them) are not cones of the field: they are not pinned, and are
// reported by vertex.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/exact_uv_check.h>
#include <CGAL/Seamless_snapping/internal/surface/index_lists.h>
#include <CGAL/Seamless_snapping/internal/surface/isoline_classes.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// default of Snap_options::integer_grid_tolerance: max distance (grid units) of a translation or
// isoline value from an integer
constexpr double default_integer_grid_tolerance = 1e-3;

// the sectors i (face(h) side) and j (face(opposite(h)) side) of the source of h (front = true) or
// of its target (front = false)
inline void translation_corners(const Corner_mesh& cm, const Seam_topology& st, int h, bool front, int& si, int& sj)
{
  const int o = cm.opp[h];
  si = st.sector_of[front ? cm.prev[h] : h];
  sj = st.sector_of[front ? o : cm.prev[o]];
}

// t = U^j - R^k U^i at the source (front) or target of h, from the sector values x (2 per sector),
// in doubles (rounded; for rounding to integers and for tolerances only)
inline void translation(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot, int h, bool front,
                        const std::vector<double>& x, double t[2])
{
  int si, sj;
  translation_corners(cm, st, h, front, si, sj);
  const Quarter_turn R(rot.k[h]);
  for(int c = 0; c < 2; ++c) t[c] = x[2 * sj + c] - R.sign[c] * x[2 * si + R.col[c]];
}

inline bool is_integer(const CGAL::Gmpq& q) { return q.denominator() == 1; }

// a finite double is an integer iff it equals its integer part
inline bool is_integer(double x) { return std::trunc(x) == x; }

// true iff (a + b) 2^s is an integer, exactly: in integers (dyadic_sum.h), in rational arithmetic when a and b
// span too much
inline bool is_integer_sum(double a, double b, int s)
{
  Dyadic_sum t;
  t.add(1, a); t.add(1, b);
  if(t.fits()) return t.is_integer(s);
  const CGAL::Gmpq scale = s >= 0 ? CGAL::Gmpq(CGAL::Gmpz(1) << s) : CGAL::Gmpq(CGAL::Gmpz(1), CGAL::Gmpz(1) << -s);
  return is_integer((CGAL::Gmpq(a) + CGAL::Gmpq(b)) * scale);
}

// x_j - R^k x_i (the translation of h at one end) is an integer vector, exactly: in integers (dyadic_sum.h),
// with Gmpq when the two values span too much
inline bool exact_integer_translation(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot, int h,
                                      bool front, const std::vector<double>& x)
{
  int si, sj;
  translation_corners(cm, st, h, front, si, sj);
  const Quarter_turn R(rot.k[h]);
  for(int c = 0; c < 2; ++c) {
    Dyadic_sum t;
    t.add(1, x[2 * sj + c]);
    t.add(-R.sign[c], x[2 * si + R.col[c]]);
    if(t.fits()) {
      if(!t.is_integer()) return false;
      continue;
    }
    const CGAL::Gmpq q = CGAL::Gmpq(x[2 * sj + c]) - CGAL::Gmpq(double(R.sign[c])) * CGAL::Gmpq(x[2 * si + R.col[c]]);
    if(!is_integer(q)) return false;
  }
  return true;
}

struct Integer_grid_counts
{
  std::size_t integer_translations = 0;
  std::size_t field_cones = 0;
  std::size_t cones_on_integer_points = 0;
};

// per interior vertex: the sum of the rotations k crossed once around it (mod 4), -1 elsewhere
inline std::vector<int> field_rotation_sums(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot)
{
  std::vector<int> K(cm.n_vertices, -1);
  for(int v = 0; v < cm.n_vertices; ++v) if(!cm.vertex_on_border[v]) K[v] = 0;
  for(int e : st.cut_edges)       // cut edges are interior: both halfedges, both endpoints
    for(int h : {cm.edge_halfedge[e], cm.opp[cm.edge_halfedge[e]]})
      if(K[cm.source(h)] >= 0) K[cm.source(h)] += rot.k[h];
  for(int& k : K) if(k >= 0) k = ((k % 4) + 4) % 4;
  return K;
}

inline Integer_grid_counts count_integer_structure(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                                   const std::vector<double>& x)
{
  Integer_grid_counts n;
  for(int e : st.cut_edges) {
    const int h = cm.edge_halfedge[e];
    if(exact_integer_translation(cm, st, rot, h, true, x) && exact_integer_translation(cm, st, rot, h, false, x))
      ++n.integer_translations;
  }
  const std::vector<int> K = field_rotation_sums(cm, st, rot);
  std::vector<char> on_integer(cm.n_vertices, 1);
  for(int h = 0; h < cm.n_halfedges; ++h) {
    if(cm.is_border_halfedge(h) || K[cm.target[h]] <= 0) continue;
    const int s = st.sector_of[h];
    if(!is_integer(x[2 * s]) || !is_integer(x[2 * s + 1])) on_integer[cm.target[h]] = 0;
  }
  for(int v = 0; v < cm.n_vertices; ++v)
    if(K[v] > 0) { ++n.field_cones; if(on_integer[v]) ++n.cones_on_integer_points; }
  return n;
}

// true iff every corner of every cone of the field is within `tolerance` of an integer point below 2^52 at 2^exponent
// times the grid of x (exponent >= 0; scaling by a power of two is exact)
inline bool cones_near_integers(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                const std::vector<double>& x, double tolerance, int exponent = 0)
{
  auto near = [&](double a) {
    a = std::ldexp(a, exponent);
    return std::fabs(a) < 0x1p52 && std::fabs(a - std::nearbyint(a)) <= tolerance;
  };
  const std::vector<int> K = field_rotation_sums(cm, st, rot);
  for(int h = 0; h < cm.n_halfedges; ++h) {
    if(cm.is_border_halfedge(h) || K[cm.target[h]] <= 0) continue;
    const int s = st.sector_of[h];
    if(!near(x[2 * s]) || !near(x[2 * s + 1])) return false;
  }
  return true;
}

struct Integer_grid_rows_result
{
  std::vector<int> cones;                 // vertices pinned to integer points (cones of the field)
  std::vector<int> not_field_cones;       // UV angle sum != 2*pi, rotations compose to the identity
};

inline std::string point_name(double a, double b)
{
  return "(" + format_double(a, 17) + ", " + format_double(b, 17) + ")";
}

// t(opposite(h)) = -R^{-k} t(h), with k(opposite(h)) = -k(h)
inline void set_opposite_translation(const Corner_mesh& cm, const Cut_rotations& rot, int h, std::vector<long>& t)
{
  const int o = cm.opp[h];
  const Quarter_turn Ri(-rot.k[h]);
  for(int c = 0; c < 2; ++c) t[2 * o + c] = -Ri.sign[c] * t[2 * h + Ri.col[c]];
}

// true iff both ends of every align edge of `al` lie within `tolerance` of one integer isoline below 2^52 at 2^exponent
// times the grid of x (exponent >= 0)
inline bool align_edges_near_isolines(const Corner_mesh& cm, const Seam_topology& st, const Align_edges& al,
                                      const std::vector<double>& x, double tolerance, int exponent)
{
  for(int e : al.edges) {
    std::size_t ia, ib;
    align_edge_ends(cm, st, al, e, ia, ib);
    const double a = std::ldexp(x[ia], exponent), b = std::ldexp(x[ib], exponent), r = std::nearbyint(a);
    if(!(std::fabs(r) < 0x1p52 && std::fabs(a - r) <= tolerance && std::fabs(b - r) <= tolerance)) return false;
  }
  return true;
}

// true iff every cut-edge translation (at both ends), every corner of every cone of the field and both ends of every
// align edge of `al` (one isoline each) are within `tolerance` of an integer (the input "looks like" an integer-grid map)
inline bool near_integer_structure(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot, const Align_edges& al,
                                   const std::vector<double>& x, double tolerance)
{
  auto near = [tolerance](double a) { return std::fabs(a - std::nearbyint(a)) <= tolerance; };
  for(int e : st.cut_edges)
    for(bool front : {true, false}) {
      double t[2];
      translation(cm, st, rot, cm.edge_halfedge[e], front, x, t);
      if(!near(t[0]) || !near(t[1])) return false;
    }
  return cones_near_integers(cm, st, rot, x, tolerance) && align_edges_near_isolines(cm, st, al, x, tolerance, 0);
}

// The smallest k in 1..max_k such that at 2^k times the grid of `ubar` (grid units) every cut-edge translation (at both
// ends), every corner of every cone of the field and both ends of every align edge of `al` are within `tolerance`
// of an integer (one isoline per align edge) below 2^52, 0 if none: a map whose grid lines lie at multiples of 2^-k
// (scaling by a power of two is exact, so these are the values that grid scale gives; the half-integer points of 180
// degree cones, for one, are integers at twice the grid scale). Each k stops at the first translation off the integers.
inline int finer_grid_exponent(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                               const std::vector<double>& ubar, double tolerance, const Align_edges& al, int max_k = 30)
{
  for(int k = 1; k <= max_k; ++k) {
    bool all = true;
    for(std::size_t i = 0; i < st.cut_edges.size() && all; ++i) {
      const int h = cm.edge_halfedge[std::size_t(st.cut_edges[i])];
      double ta[2], tb[2];
      translation(cm, st, rot, h, true, ubar, ta);
      translation(cm, st, rot, h, false, ubar, tb);
      for(int c = 0; c < 2 && all; ++c) {
        const double a = std::ldexp(ta[c], k), b = std::ldexp(tb[c], k), r = std::nearbyint(a);
        all = std::fabs(r) < 0x1p52 && std::fabs(b) < 0x1p52 && std::fabs(a - r) <= tolerance && std::fabs(b - r) <= tolerance;
      }
    }
    if(all && cones_near_integers(cm, st, rot, ubar, tolerance, k) && align_edges_near_isolines(cm, st, al, ubar, tolerance, k))
      return k;
  }
  return 0;
}

// The end of a refusal of the integer-grid checks at `grid_scale` (the caller's, > 0; with the align edges `al`): where
// finer_grid_exponent() finds a finer grid scale, that one named ("; at grid scale ..."); else (or without `al`) `otherwise`
inline std::string finer_grid_advice(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                     const Align_edges* al, const std::vector<double>& ubar, double tolerance,
                                     double grid_scale, const std::string& otherwise)
{
  const int k = grid_scale > 0 && al != nullptr ? finer_grid_exponent(cm, st, rot, ubar, tolerance, *al) : 0;
  if(k == 0 || !std::isfinite(std::ldexp(grid_scale, k))) return otherwise;   // (no grid scale beyond the doubles named)
  const std::string finer = format_double(std::ldexp(grid_scale, k), 17);   // a power of two, read back exactly
  return "; at grid scale " + finer + " (" + std::to_string(1L << k) + " times this one) every translation, cone and " +
         "align edge is within " + format_double(tolerance) + " of an integer: its grid lines lie at multiples of 1/" + finer +
         "; snap with that grid scale (grid_scale / --grid-scale " + finer + ")";
}

// The translation of every cut edge rounded to an integer vector, per halfedge (2 per halfedge, at its source;
// 0 on the other edges): t(h) maps the chart of face(h) to that of face(opposite(h)), p -> R^k(h) p + t(h).
// INVALID_INPUT with advice if a translation is farther than `tolerance` (grid units) from an integer at either end
// (with grid_scale > 0, the caller's: naming a finer grid scale at which none is, if one is, finer_grid_advice(), which
// also checks the align edges `al` there);
// RANGE_EXCEEDED if one is 2^52 grid units or more (beyond the integers that the rows hold).
inline Status round_translations(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                 const std::vector<double>& ubar, double tolerance, std::vector<long>& t,
                                 std::string& message, double grid_scale = 0, const Align_edges* al = nullptr)
{
  t.assign(2 * std::size_t(cm.n_halfedges), 0);
  std::size_t far = 0;
  std::string first_far;
  for(int e : st.cut_edges) {
    const int h = cm.edge_halfedge[e];
    double ta[2], tb[2];
    translation(cm, st, rot, h, true, ubar, ta);
    translation(cm, st, rot, h, false, ubar, tb);
    bool near = true, in_range = true;
    for(int c = 0; c < 2; ++c) {
      const double r = std::nearbyint(ta[c]);
      in_range = in_range && std::fabs(r) < 0x1p52 && std::fabs(tb[c]) < 0x1p52;   // converted to long only then (else UB)
      near = near && std::fabs(ta[c] - r) <= tolerance && std::fabs(tb[c] - r) <= tolerance;
      t[2 * h + c] = std::fabs(r) < 0x1p52 ? long(r) : 0;
    }
    auto both = [&] {                 // formatted only for a message
      return ta[0] == tb[0] && ta[1] == tb[1] ? point_name(ta[0], ta[1])
                                             : point_name(ta[0], ta[1]) + " at one end and " + point_name(tb[0], tb[1]) + " at the other";
    };
    if(!in_range) {
      message = "cut edge " + vertex_pair_name(cm, h) + " has the translation " + both() + " (grid units): 2^52 or more, " +
                "beyond the integers an integer-grid map holds exactly; scale the map down (grid_scale / --grid-scale)";
      return RANGE_EXCEEDED;
    }
    if(!near) {
      if(far++ == 0) first_far = "edge " + vertex_pair_name(cm, h) + " has translation " + both();
      continue;
    }
    set_opposite_translation(cm, rot, h, t);
  }
  if(far > 0) {
    // where finer_grid_advice() searched the grid scales up to 2^30 times this one and none fits, the map is not an
    // integer-grid map at any of them: its translations were never made integers (quantized)
    const bool searched = grid_scale > 0 && al != nullptr;
    message = "the input is not near an integer-grid map: " + std::to_string(far) + " of " +
              std::to_string(st.cut_edges.size()) + " cut-edge translations are farther than " + format_double(tolerance) +
              " from integers (first: " + first_far + ")" +
              finer_grid_advice(cm, st, rot, al, ubar, tolerance, grid_scale,
                                searched ? "; nor are they at any grid scale up to 2^30 times this one: the map is seamless "
                                           "but not quantized (its translations are not integers at any power-of-two "
                                           "scale, as in Directional's rot-seamless output or a map before MIQ's integer "
                                           "rounding; if its grid lines lie at another spacing, scale its UVs by that "
                                           "first): quantize it (quantize(true) / --quantize, at a grid scale that "
                                           "separates its cones)"
                                         : "; scale the map so that its grid lines fall on integers (grid_scale / "
                                           "--grid-scale, a power of two)") +
              ", or snap without integer_grid_map (--integer-grid) for an exactly seamless map";
    return INVALID_INPUT;
  }
  return SUCCESS;
}

// Every interior vertex's first interior corner (a halfedge with the vertex as target), -1 for the others
inline std::vector<int> first_corners(const Corner_mesh& cm)
{
  std::vector<int> corner_of(cm.n_vertices, -1);
  for(int h = 0; h < cm.n_halfedges; ++h)
    if(!cm.is_border_halfedge(h) && corner_of[cm.target[h]] < 0) corner_of[cm.target[h]] = h;
  return corner_of;
}

// The transitions (rotations k, integer translations t) composed once around the target of corner g0, starting
// in the chart of face(g0): p -> R^K p + T, K in 0..3
// (the same for translations of any number type: integer_grid_quantization.h composes the input's real ones too)
template <class Number>
void compose_translations_around(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                 const std::vector<Number>& t, int g0, int& K, Number T[2])
{
  K = 0; T[0] = 0; T[1] = 0;
  int g = g0;
  do {
    const int crossed = cm.next[g];          // source(crossed) = target(g0)
    if(st.is_cut[cm.edge[crossed]]) {
      const Quarter_turn R(rot.k[crossed]);
      const Number T0 = R.sign[0] * T[R.col[0]] + t[2 * crossed], T1 = R.sign[1] * T[R.col[1]] + t[2 * crossed + 1];
      T[0] = T0; T[1] = T1;
      K += rot.k[crossed];
    }
    g = cm.opp[crossed];
  } while(g != g0);
  K = ((K % 4) + 4) % 4;
}

inline void compose_around(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                           const std::vector<long>& t, int g0, int& K, long T[2])
{
  compose_translations_around(cm, st, rot, t, g0, K, T);
}

// 2p for the fixed point p of q -> R^K q + T, K = 1, 2, 3: (I - R^K) p = T gives p = T/2 (K = 2),
// ((T0 - T1)/2, (T0 + T1)/2) (K = 1), ((T0 + T1)/2, (T1 - T0)/2) (K = 3)
inline void fixed_point_times_2(int K, const long T[2], long num[2])
{
  if(K == 2) { num[0] = T[0]; num[1] = T[1]; }
  else if(K == 1) { num[0] = T[0] - T[1]; num[1] = T[0] + T[1]; }
  else { num[0] = T[0] + T[1]; num[1] = T[1] - T[0]; }
}

// true iff target(g) is a cone of the field (the transitions around it rotate) whose fixed point p is an integer
// point; p in the chart of face(g)
inline bool integer_cone_point(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                               const std::vector<long>& t, int g, long p[2])
{
  int K;
  long T[2], num[2];
  compose_around(cm, st, rot, t, g, K, T);
  if(K == 0) return false;
  fixed_point_times_2(K, T, num);
  if(num[0] % 2 != 0 || num[1] % 2 != 0) return false;
  p[0] = num[0] / 2; p[1] = num[1] / 2;
  return true;
}

// The isoline of each align edge (`isoline`, per edge) from its class (isoline_classes.h): the align edges that share a
// corner's variable (the edges of one straight side in one chart) or that the cut edges join across the charts (with
// the translations t) lie on one isoline, that of the cones on them (their integer points) where there are, else the
// integer nearest the mean of their ends (in the coordinate of the class's root). Rounded edge by edge, the first end
// of each, the edges of a quantized side at u = 8.5 (+- 1e-9) went to the isolines 8 and 9, rows that contradict each
// other; rounded per chart, the cube with its edges as features, quantized, put the cones of one edge on two isolines.
// INFEASIBLE where the translations and the align edges contradict each other (no isoline fits a class), INVALID_INPUT
// where an edge's ends are farther than `tolerance` from its isoline (not for the classes of cones that
// cone_separation.h moved, `moved_cones`), RANGE_EXCEEDED beyond 2^52.
inline Status align_isolines(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot, const Align_edges& al,
                             const std::vector<double>& ubar, const std::vector<long>& t, double tolerance,
                             const std::vector<char>& moved_cones, double grid_scale, std::vector<long>& isoline,
                             std::string& message)
{
  isoline.assign(std::size_t(cm.n_edges), 0);
  if(al.edges.empty()) return SUCCESS;
  Isoline_classes classes(2 * std::size_t(st.n_sectors));
  relate_align_edges(cm, st, al, classes);
  for(int e : st.cut_edges) relate_cut_edge(cm, st, rot, t, cm.edge_halfedge[e], classes);
  if(classes.conflict()) {
    const std::size_t x = classes.conflict_a();
    const int v = st.sector_vertex(cm, int(x / 2));
    message = classes.range_exceeded()
      ? "the isolines of the align edges through vertex " + std::to_string(v) + ", composed across the cut edges' " +
        "translations, reach 2^62 grid units; scale the map down (grid_scale / --grid-scale); nothing was written"
      : "the integer translations and the align edges contradict each other at vertex " + std::to_string(v) + " (" +
        (x % 2 == 0 ? "u" : "v") + "): an aligned chain through it, followed across the cut edges, would lie on two " +
        "isolines at once (it joins cones at different isolines, or returns onto another isoline); nothing was written";
    return classes.range_exceeded() ? RANGE_EXCEEDED : INFEASIBLE;
  }
  std::vector<double> root_sum(classes.size(), 0.), root_ends(classes.size(), 0.);
  std::vector<char> moved(classes.size(), 0);                    // per root: a class of a moved cone
  for(int e : al.edges) {
    std::size_t ends[2];
    align_edge_ends(cm, st, al, e, ends[0], ends[1]);
    for(std::size_t x : ends) {
      const Isoline_classes::Relation r = classes.find(x);
      root_sum[r.root] += double(r.sign) * (ubar[x] - double(r.offset));
      root_ends[r.root] += 1;
      if(!moved_cones.empty() && moved_cones[std::size_t(st.sector_vertex(cm, int(x / 2)))]) moved[r.root] = 1;
    }
  }
  for(int e : al.edges) {
    const int g = al.halfedge[e], c = al.component[e];
    std::size_t ia, ib;
    align_edge_ends(cm, st, al, e, ia, ib);
    const double a = ubar[ia], b = ubar[ib];
    const Isoline_classes::Relation root = classes.find(ia);
    long fixed;
    const double r = double(root.sign) * (classes.fixed(root.root, fixed) ? double(fixed)
                                          : std::nearbyint(root_sum[root.root] / root_ends[root.root])) + double(root.offset);
    auto where = [&] {                // formatted only for a message
      return "align edge " + vertex_pair_name(cm, g) + " lies on the isoline " + (c == 0 ? "u" : "v") + " = " +
             (a == b ? format_double(a, 17) : format_double(a, 17) + " .. " + format_double(b, 17));
    };
    if(!(std::fabs(r) < 0x1p52 && std::fabs(b) < 0x1p52)) {
      message = where() + " (grid units): 2^52 or more, beyond the integers an integer-grid map holds exactly; scale the map " +
                "down (grid_scale / --grid-scale)";
      return RANGE_EXCEEDED;
    }
    if(!moved[root.root] && !(std::fabs(a - r) <= tolerance && std::fabs(b - r) <= tolerance)) {
      const bool ends_near = std::fabs(a - std::nearbyint(a)) <= tolerance && std::fabs(b - std::nearbyint(b)) <= tolerance;
      message = "the input is not near an integer-grid map: " + where() +
                (!ends_near ? ", farther than " + format_double(tolerance) + " from an integer"
                 : std::nearbyint(a) != std::nearbyint(b) ? ", its ends on two different integer isolines (an align edge runs along one)"
                 : ", near the integer " + format_double(std::nearbyint(a)) + " but not near the isoline " + format_double(r) +
                   " of the aligned chain it belongs to (one isoline for the chain, the chains that the cut edges join with "
                   "it and the cones on them)") +
                finer_grid_advice(cm, st, rot, &al, ubar, tolerance, grid_scale, "; scale the map (grid_scale / --grid-scale)") +
                ", or snap without integer_grid_map (--integer-grid)";
      return INVALID_INPUT;
    }
    isoline[std::size_t(e)] = long(r);
  }
  return SUCCESS;
}

// Checks the rounded translations `t` (round_translations(), possibly changed by cone_merging.h) around every
// vertex (see the header comment) and appends the integer-grid rows to `rows`.
// `ubar`: the input sector values in grid units; the right-hand sides are the integers times
// 2^rhs_shift (rhs_shift >= 0: the corner mesh is in units of 2^-rhs_shift grid units, finer than the
// grid when corners are pinned, pinned_corners.h). `moved_cones` (per vertex, or empty): the vertices of the paths along
// which cone_separation.h moved cones (its ends, and cones on the point that it passes): their input position is not
// compared with the point the translations force. `grid_scale` (> 0: the caller's): a cone or align edge refused names a
// finer grid scale at which every translation, cone and align edge is near an integer, if there is one
// (finer_grid_advice()).
// On failure nothing is appended.
inline Status add_integer_grid_rows(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                    const Align_edges& al, const std::vector<double>& ubar, const std::vector<long>& t,
                                    int rhs_shift, double tolerance, Constraint_rows& rows,
                                    Integer_grid_rows_result& result, std::string& message,
                                    const std::vector<char>& moved_cones = std::vector<char>(), double grid_scale = 0)
{
  result = Integer_grid_rows_result();
  // the rotations and rounded translations composed around every interior vertex with cut edges
  const std::vector<int> corner_of = first_corners(cm);
  for(int v = 0; v < cm.n_vertices; ++v) {
    if(cm.vertex_on_border[v] || corner_of[v] < 0) continue;
    if(st.cut_degree[v] == 0) {           // no transition around it: not a cone of the field
      if(st.is_cone[v]) result.not_field_cones.push_back(v);
      continue;
    }
    int K;
    long T[2];
    const int g0 = corner_of[v];
    compose_around(cm, st, rot, t, g0, K, T);
    if(K == 0) {
      if(T[0] != 0 || T[1] != 0) {
        message = "the rounded translations around vertex " + std::to_string(v) + " contradict each other: composed once " +
                  "around it they translate by (" + std::to_string(T[0]) + ", " + std::to_string(T[1]) +
                  ") instead of 0 (face " + std::to_string(cm.face[g0]) + "); nothing was written";
        return INFEASIBLE;
      }
      if(st.is_cone[v]) result.not_field_cones.push_back(v);
      continue;
    }
    long num[2];
    fixed_point_times_2(K, T, num);
    if(num[0] % 2 != 0 || num[1] % 2 != 0) {
      message = "cone at vertex " + std::to_string(v) + " (rotation " + std::to_string(90 * K) + " degrees): the rounded " +
                "transitions around it have the fixed point " + point_name(num[0] / 2., num[1] / 2.) + " (frame of face " +
                std::to_string(cm.face[g0]) + "), not an integer point" +
                finer_grid_advice(cm, st, rot, &al, ubar, tolerance, grid_scale, "") + "; nothing was written";
      return INFEASIBLE;
    }
    const int s = st.sector_of[g0];
    if((moved_cones.empty() || !moved_cones[std::size_t(v)]) &&
       (std::fabs(ubar[2 * s] - double(num[0] / 2)) > tolerance || std::fabs(ubar[2 * s + 1] - double(num[1] / 2)) > tolerance)) {
      message = "cone at vertex " + std::to_string(v) + " sits at " + point_name(ubar[2 * s], ubar[2 * s + 1]) +
                " (face " + std::to_string(cm.face[g0]) + ") but its rounded transitions force it to (" +
                std::to_string(num[0] / 2) + ", " + std::to_string(num[1] / 2) + "), farther than " + format_double(tolerance) +
                finer_grid_advice(cm, st, rot, &al, ubar, tolerance, grid_scale, "") + "; nothing was written";
      return INFEASIBLE;
    }
    result.cones.push_back(v);
  }

  std::vector<long> isoline;
  const Status aligned = align_isolines(cm, st, rot, al, ubar, t, tolerance, moved_cones, grid_scale, isoline, message);
  if(aligned != SUCCESS) return aligned;

  // the right-hand sides in corner-mesh units, |b| < 2^62
  long max_abs = 0;
  for(int e : st.cut_edges) max_abs = (std::max)({max_abs, std::labs(t[2 * cm.edge_halfedge[e]]), std::labs(t[2 * cm.edge_halfedge[e] + 1])});
  for(int e : al.edges) max_abs = (std::max)(max_abs, std::labs(isoline[e]));
  if(rhs_shift < 0 || rhs_shift > 61 || (max_abs >> (61 - rhs_shift)) != 0) {
    message = "the integer-grid rows need right-hand sides up to " + std::to_string(max_abs) + " grid units in units of 2^" +
              std::to_string(-rhs_shift) + " grid units (set by the lowest bit of the pinned UVs), more than 62 bits; " +
              "pin UVs with fewer bits below the grid unit; nothing was written";
    return RANGE_EXCEEDED;
  }
  for(int e : st.cut_edges) {
    const int h = cm.edge_halfedge[e];
    const Cut_edge_ends s = cut_edge_ends(cm, st, h);
    const Quarter_turn R(rot.k[h]);
    for(int c = 0; c < 2; ++c)
      rows.add({ {2 * s.j[0] + c, 1}, {2 * s.i[0] + R.col[c], -R.sign[c]} }, e, t[2 * h + c] * (1L << rhs_shift));
  }
  for(int e : al.edges) {
    std::size_t a, b;
    align_edge_ends(cm, st, al, e, a, b);
    rows.add({ {int(a), 1} }, e, isoline[std::size_t(e)] * (1L << rhs_shift));
  }
  return SUCCESS;
}

// grid scale S (UV units per grid unit: the integer grid of the map is at multiples of 1/S) -> s with
// S = 2^s; false if S is not a power of two (a non-dyadic scale cannot be applied exactly)
inline bool grid_scale_exponent(double S, int& s)
{
  if(!(S > 0) || !std::isfinite(S)) return false;
  int e;
  const double m = std::frexp(S, &e);
  if(m != 0.5) return false;
  s = e - 1;
  return true;
}

// The exact test behind is_exact_integer_grid_map(): the map is exactly seamless
// (is_exactly_seamless_impl) and, with every UV multiplied by 2^scale_exponent (exact in Gmpq),
// - every cut edge has, for its rotation k (given, or among the k for which the transition holds
//   exactly), an integer translation t = U^j - R^k U^i;
// - every interior vertex around which these k sum to K != 0 mod 4 (a cone of the field) has
//   integer UVs in all its corners.
//   Only a zero-length cut edge can have several such k (its UV image, a point, says nothing of its rotation):
//   it takes the one that leaves an end of it with all its other cut edges decided no cone (K = 0 mod 4), in
//   turn, else its least. (The least at once made a vertex between two zero-length cut edges at a half-integer point
//   a cone of 180 degrees, not on an integer point, in a map that the snap had made an exact integer-grid map with
//   its own rotations: the full-seamless dragon of ../shared/data scaled by 1.5 and quantized, without untangling);
// - every edge of `aligned` lies on an integer isoline (its constant coordinate is an integer).
// With `why`, a failure says which edge or cone fails and how; with `edge_k`, on success, the k of
// halfedge(e) of every cut edge e (0 for the other edges).
inline bool is_exact_integer_grid_map_impl(const Corner_mesh& cm, const std::vector<signed char>& seam_override,
                                           const std::vector<int>& given_k, const std::vector<char>& aligned,
                                           int scale_exponent, std::string* why = nullptr,
                                           std::vector<int>* edge_k = nullptr)
{
  if(!is_exactly_seamless_impl(cm, seam_override, given_k, aligned, why)) return false;
  auto U = [&](int h, int c) { return c == 0 ? cm.u[h] : cm.v[h]; };   // the corner UVs; grid units: times 2^scale_exponent
  auto fail = [&](const std::string& what) {
    if(why != nullptr) *why = what + " (grid scale 2^" + std::to_string(scale_exponent) + "): not an integer-grid map";
    return false;
  };
  std::vector<int> K(cm.n_vertices, 0), k_of(cm.n_edges, 0);
  std::vector<unsigned char> choices(std::size_t(cm.n_edges), 0);   // per seam edge: bit k where k fits; 0: decided
  std::vector<int> open(std::size_t(cm.n_vertices), 0);              // per vertex: its seam edges not decided
  auto decide = [&](int e, int k) {
    const int h = cm.edge_halfedge[e];
    k_of[e] = k;
    K[cm.source(h)] += k;
    K[cm.target[h]] -= k;     // k(opposite(h)) = -k, seen from the other end
  };
  for(int e = 0; e < cm.n_edges; ++e) {
    const int h = cm.edge_halfedge[e], o = cm.opp[h];
    // (before the border test: constrained border edges were never checked, and a border edge on v = 0.5 passed)
    if(!aligned.empty() && aligned[e]) {
      const int g = cm.is_border_halfedge(h) ? o : h;
      const int c = cm.u[g] == cm.u[cm.prev[g]] ? 0 : 1;   // exactly axis-parallel (checked above)
      if(!is_integer_sum(U(g, c), 0, scale_exponent))
        return fail("constrained edge " + vertex_pair_name(cm, h) + " lies on the isoline " + (c == 0 ? "u" : "v") +
                    " = " + format_double(std::ldexp(U(g, c), scale_exponent), 17) + " in grid units, not an integer one");
    }
    if(cm.is_border_edge(e)) continue;
    const bool continuous = same_uv(cm, h, cm.prev[o]) && same_uv(cm, cm.prev[h], o);
    const bool seam = (!seam_override.empty() && seam_override[e] >= 0) ? seam_override[e] != 0 : !continuous;
    if(!seam) continue;
    unsigned fits = 0;
    for(int k = 0; k < 4; ++k) {
      if(!given_k.empty() && ((k - given_k[e]) % 4 + 4) % 4 != 0) continue;
      if(!exact_transition_holds(cm, h, k)) continue;
      const Quarter_turn R(k);
      bool integral = true;      // t at source(h): U(o) - R^k U(prev h)
      for(int c = 0; c < 2 && integral; ++c)
        integral = is_integer_sum(U(o, c), -R.sign[c] * U(cm.prev[h], R.col[c]), scale_exponent);
      if(integral) fits |= 1u << k;
    }
    if(fits == 0)
      return fail("cut edge " + vertex_pair_name(cm, h) + " (faces " + std::to_string(cm.face[h]) + ", " +
                  std::to_string(cm.face[o]) + "): its translation is not an integer vector");
    if((fits & (fits - 1)) == 0) { decide(e, fits == 1 ? 0 : fits == 2 ? 1 : fits == 4 ? 2 : 3); continue; }
    choices[std::size_t(e)] = static_cast<unsigned char>(fits);
    ++open[std::size_t(cm.source(h))];
    ++open[std::size_t(cm.target[h])];
  }
  // the zero-length cut edges, in turn: one at a vertex with no other open seam edge first, else the first open one
  std::vector<int> undecided;
  for(int e = 0; e < cm.n_edges; ++e) if(choices[std::size_t(e)] != 0) undecided.push_back(e);
  Index_lists edges_at;                                          // per vertex its undecided edges
  edges_at.build(cm.n_vertices, [&](auto emit) {
    for(int e : undecided) { emit(cm.source(cm.edge_halfedge[e]), e); emit(cm.target[cm.edge_halfedge[e]], e); }
  });
  std::vector<int> ready;
  for(int v = 0; v < cm.n_vertices; ++v) if(open[std::size_t(v)] == 1) ready.push_back(v);
  std::size_t next = 0;
  for(;;) {
    int e = -1, k = -1;
    while(e < 0 && !ready.empty()) {
      const int v = ready.back();
      ready.pop_back();
      if(open[std::size_t(v)] != 1) continue;
      for(int f : edges_at[v])
        if(choices[std::size_t(f)] != 0) e = f;
      if(e < 0) continue;                                           // (open counts them: not reached)
      const bool source = cm.source(cm.edge_halfedge[e]) == v;
      const int want = ((source ? -K[v] : K[v]) % 4 + 4) % 4;      // the k that makes K[v] = 0 mod 4
      if(choices[std::size_t(e)] & (1u << want)) k = want;
    }
    while(e < 0 && next < undecided.size()) if(choices[std::size_t(undecided[next++])] != 0) e = undecided[next - 1];
    if(e < 0) break;
    if(k < 0) while(!(choices[std::size_t(e)] & (1u << ++k))) {}
    choices[std::size_t(e)] = 0;
    decide(e, k);
    for(int v : {cm.source(cm.edge_halfedge[e]), cm.target[cm.edge_halfedge[e]]})
      if(--open[std::size_t(v)] == 1) ready.push_back(v);
  }
  for(int h = 0; h < cm.n_halfedges; ++h) {
    const int v = cm.target[h];
    if(cm.is_border_halfedge(h) || cm.vertex_on_border[v] || (K[v] % 4 + 4) % 4 == 0) continue;
    if(!is_integer_sum(U(h, 0), 0, scale_exponent) || !is_integer_sum(U(h, 1), 0, scale_exponent))
      return fail("cone at vertex " + std::to_string(v) + " (rotation " + std::to_string(90 * ((K[v] % 4 + 4) % 4)) +
                  " degrees) has the UV " + point_name(std::ldexp(U(h, 0), scale_exponent), std::ldexp(U(h, 1), scale_exponent)) +
                  " in face " + std::to_string(cm.face[h]) + " in grid units, not an integer point");
  }
  if(edge_k != nullptr) edge_k->swap(k_of);
  return true;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_INTEGER_GRID_CONSTRAINTS_H
