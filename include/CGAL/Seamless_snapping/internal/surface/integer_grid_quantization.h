// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_INTEGER_GRID_QUANTIZATION_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_INTEGER_GRID_QUANTIZATION_H

// Quantization (quantize(true), beyond the paper): integer translations for the cut edges of a seamless map that is
// not near an integer-grid map (a map whose translations were never made integers, e.g. Directional's rot-seamless
// output), chosen so that around every interior vertex the transitions compose to the identity where it is not a cone,
// and to a rotation about an integer point next to the cone (within a grid cell of it in each coordinate, or 2 in a
// coordinate that an aligned chain through it fixes: aligned_candidates(), or within 2 cells where all the nearer points
// collide: diffuse_rounding()'s ring) where it is one.
//
// The cut graph is peeled from its leaves: an interior vertex all of whose cut edges but one have their translations
// determines that one from its own condition (the composition around it is linear in that translation, through a
// rotation, so it is solved exactly in integers): a vertex that is not a cone composes to the identity; a cone takes,
// of the four integer points around its position, the one that brings that translation nearest to the input's (error
// diffusion: the rounding of the parts already peeled reaches it through the known translations, and each cone takes
// up what it can, so that it does not add up along the graph: on the rot-seamless dragon of ../shared/data, 870 cones,
// the largest change of the map at grid scale 16 drops from 26 to 3.7 grid cells, RMS 1.08 -> 0.22, against each cone
// at its nearest point), unless a cone placed before near it (sharing a face, or within 2 grid cells of the point)
// holds that point already (two cones on one point force zero-area triangles) and is not one that the snap's
// merge_cone_pairs(true) will merge with it, or the point makes a face whose three corners are placed cones (whose
// shape the translations then fix) non-positive: then the next of the four, then those of the ring around them within 2
// cells. Where no such vertex is left, the cut edges
// that close the cycles of the graph still open (around the handles of the surface, or between its charts where the
// cuts split it) take their translations rounded, all at once, the first time; then, on cut paths between border
// vertices (which have no condition), one cut edge at the border. In each part of the graph that does not reach the
// border, one cone is left to the end (quantization_roots()) and takes the point that the others' choices give it.
// add_integer_grid_rows() checks every vertex exactly afterwards and refuses (INFEASIBLE, nothing written) where a
// condition fails, as for any other choice of integer translations.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/surface/cone_merging.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/integer_grid_constraints.h>
#include <CGAL/Seamless_snapping/internal/surface/isoline_classes.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// Per vertex: whether it is the root of its part of the cut graph, the vertex left to take the rounding of the others:
// in each part without a border vertex (a border vertex has no condition: the part is peeled towards it), a cone,
// one of +-90 degrees if there is one (a rotation by a quarter turn has an integer fixed point wherever the
// translation's coordinates add up to an even number, which the quarter-turn cones' contributions do; a half turn
// asks for both even), the one of least index. Without a cone the part has no root. `zero_t`: translations that are all
// 0 (only the rotations of the compositions around the vertices are read).
inline std::vector<char> quantization_roots(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                            const std::vector<int>& corner_of, const std::vector<long>& zero_t)
{
  Union_find part(cm.n_vertices);                               // the parts of the cut graph
  for(int e : st.cut_edges) {
    const int h = cm.edge_halfedge[std::size_t(e)];
    part.unite(cm.target[h], cm.target[cm.opp[h]]);
  }
  std::vector<char> bordered(std::size_t(cm.n_vertices), 0);
  std::vector<int> best(std::size_t(cm.n_vertices), -1), best_k(std::size_t(cm.n_vertices), 0);
  for(int v = 0; v < cm.n_vertices; ++v) {
    if(st.cut_degree[std::size_t(v)] == 0) continue;
    const int p = part.find(v);
    if(cm.vertex_on_border[v]) { bordered[std::size_t(p)] = 1; continue; }
    if(corner_of[std::size_t(v)] < 0) continue;
    int K;
    long T[2];
    compose_around(cm, st, rot, zero_t, corner_of[std::size_t(v)], K, T);
    const bool quarter = K % 2 != 0;
    if(K % 4 != 0 && (best[std::size_t(p)] < 0 || (quarter && best_k[std::size_t(p)] % 2 == 0))) {
      best[std::size_t(p)] = v;
      best_k[std::size_t(p)] = K;
    }
  }
  std::vector<char> root(std::size_t(cm.n_vertices), 0);
  for(int v = 0; v < cm.n_vertices; ++v)
    if(part.find(v) == v && !bordered[std::size_t(v)] && best[std::size_t(v)] >= 0) root[std::size_t(best[std::size_t(v)])] = 1;
  return root;
}

// false (with `message`: `what` lies too far) unless |x| < 2^52 grid units, where the integers an integer-grid map holds
// are exact
inline bool within_exact_integers(double x, const std::string& what, std::string& message)
{
  if(std::fabs(x) < 0x1p52) return true;
  message = what + " 2^52 grid units or more from the origin, beyond the integers an integer-grid map holds exactly; "
            "scale the map down (grid_scale / --grid-scale)";
  return false;
}

// The integer point p of a cone at target(g0) whose last open cut edge is `crossed`, given the composition T0 of the
// integer translations around it (that of `crossed` 0): of the integer points next to its input position x (floor or
// ceiling in each coordinate), the one whose translation of `crossed` is nearest the input's: the translations of the
// known edges differ from the input's (their rounding, from the parts of the cut graph already peeled) by E = T0 -
// T0bar (T0bar: the same composition of the input's translations), and the translation of `crossed` then differs from
// the input's by M^T ((I - R^K)(p - x) - E), M a rotation: p minimizes |(I - R^K)(p - x) - E| (error diffusion: each
// cone takes up what it can of the rounding that reaches it, so that it does not add up along the cut graph). On output
// p[0..3] are the four points in that order (ties: nearest to x first, then the order floor/ceil of u, of v);
// peel_cut_graph() takes the first that no neighbouring cone holds. With `ring`, instead the integer points one beyond
// those four (floor - 1 .. ceil + 1 in each coordinate, but the four: 12, 10 where x is an integer in one coordinate, 8
// in both), in the same order, for a cone whose four points all collide (the rot-seamless dragon of ../shared/data
// quantized at grid scale 2: a cone took the point of another one, two zero-area triangles forced). Returns the number
// of points.
inline int diffuse_rounding(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot, const std::vector<double>& ubar,
                            std::vector<double>& tbar, int crossed, int g0, int K, const long T0[2], long (*p)[2],
                            bool ring = false)
{
  const double saved[2] = {tbar[2 * std::size_t(crossed)], tbar[2 * std::size_t(crossed) + 1]};
  tbar[2 * std::size_t(crossed)] = 0; tbar[2 * std::size_t(crossed) + 1] = 0;
  int Kb;
  double Tb[2];
  compose_translations_around(cm, st, rot, tbar, g0, Kb, Tb);
  tbar[2 * std::size_t(crossed)] = saved[0]; tbar[2 * std::size_t(crossed) + 1] = saved[1];
  const int s = st.sector_of[std::size_t(g0)];
  const double x[2] = {ubar[2 * std::size_t(s)], ubar[2 * std::size_t(s) + 1]};
  const double E[2] = {double(T0[0]) - Tb[0], double(T0[1]) - Tb[1]};
  const Quarter_turn R(K);
  const long lo[2] = {long(std::floor(x[0])), long(std::floor(x[1]))}, hi[2] = {long(std::ceil(x[0])), long(std::ceil(x[1]))};
  long q[16][2];
  int n = 0;
  if(!ring)                                                     // floor or ceiling in each coordinate
    for(int a = 0; a < 2; ++a)
      for(int b = 0; b < 2; ++b) { q[n][0] = a == 0 ? lo[0] : hi[0]; q[n][1] = b == 0 ? lo[1] : hi[1]; ++n; }
  else
    for(long u = lo[0] - 1; u <= hi[0] + 1; ++u)
      for(long v = lo[1] - 1; v <= hi[1] + 1; ++v)
        if(!((u == lo[0] || u == hi[0]) && (v == lo[1] || v == hi[1]))) { q[n][0] = u; q[n][1] = v; ++n; }
  std::pair<double, int> order[16];
  for(int i = 0; i < n; ++i) {
    const double d[2] = {double(q[i][0]) - x[0], double(q[i][1]) - x[1]};
    double err = 0;
    for(int c = 0; c < 2; ++c) {
      const double r = d[c] - R.sign[c] * d[R.col[c]] - E[c];
      err += r * r;
    }
    err += 1e-9 * (d[0] * d[0] + d[1] * d[1]);                   // ties: the point nearest to the input
    order[i] = {err, i};
  }
  std::stable_sort(order, order + n, [](const std::pair<double, int>& u, const std::pair<double, int>& w) { return u.first < w.first; });
  for(int i = 0; i < n; ++i) { p[i][0] = q[order[i].second][0]; p[i][1] = q[order[i].second][1]; }
  return n;
}

// Where the classes (isoline_classes.h) fix a coordinate of the cone's coordinates x_a, x_a + 1 (input position x, an
// aligned chain through it reaching a placed cone or closing a cycle), the points with that coordinate and the other
// floor or ceiling of x, after the four of diffuse_rounding() in p[4..7], those within 2 grid cells of x; their number.
// Without them (the four only), the cubes with features of test_quad scaled by 1.3 / 1.7 (2 and 3 squares per side)
// and libigl's scaled by 1.3 (grid scales 1, 2) and 1.7 (grid scale 1) were INFEASIBLE. (collides()' search reaches
// vertices within quantization_cone_reach of the point: for these farther points it may miss a cone on it.)
inline int aligned_candidates(Isoline_classes& classes, bool aligned, int a, const double x[2], long p[8][2])
{
  if(!aligned) return 0;
  std::vector<long> want[2];
  for(int c = 0; c < 2; ++c) {
    const Isoline_classes::Relation r = classes.find(std::size_t(a + c));
    long value;
    if(!classes.fixed(r.root, value))
      want[c] = {long(std::floor(x[c])), long(std::ceil(x[c]))};
    else if(std::fabs(double(r.sign) * double(value) + double(r.offset) - x[c]) <= 2)
      want[c] = {r.sign * value + r.offset};
    else
      return 0;                                                   // beyond 2 cells: none
  }
  if(want[0].size() == 2 && want[1].size() == 2) return 0;      // nothing fixed: the four of diffuse_rounding()
  int n = 0;
  for(long u : want[0])
    for(long w : want[1]) {
      bool seen = false;
      for(int i = 0; i < 4 + n; ++i) seen = seen || (p[i][0] == u && p[i][1] == w);
      if(!seen) { p[4 + n][0] = u; p[4 + n][1] = w; ++n; }
    }
  return n;
}

// How far (grid cells, Euclidean, at the input's UVs) from a cone's candidate point peel_cut_graph() looks for placed
// cones on that point: 2, since a cone lies up to sqrt(2) from the integer point it takes. (collapsed_cone_pairs() uses
// 1, where a path of 2 could go around a third cone and call two far cones a pair; here such a false pair only costs
// the cone its next candidate.) Against 1, with the pairs that merging joins allowed, measured at 1bc0fbd (before the
// rule for triangles of three cones): the rot-seamless dragon of ../shared/data at grid scale 1 with 17 negative / 10
// zero-area triangles left instead of 21 / 8, 102 wound vertices instead of 99; the 302K bunny of ../shared/large the
// same defects at grid scale 8 and 16. It stays 2 at every grid scale: 2 S cells at S > 1, like the merge's reach, gave
// the rot-seamless dragon and retinal_miq with --quantize at S = 2 to 16 the same refusals and irregular vertices
// (2026-11-30, bench_quad)
constexpr double quantization_cone_reach = 2.0;

// The peeling of the cut graph (see the header) into t (its cut halfedges' entries; the others stay 0), each cone that
// determines an edge at the point diffuse_rounding() chooses, the vertices of `root` left to the end; `merge_reach` as
// in quantize_translations().
inline Status peel_cut_graph(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                             const Align_edges& al, const std::vector<double>& ubar, const std::vector<int>& corner_of,
                             const std::vector<char>& root, double merge_reach, std::vector<long>& t, std::string& message)
{
  // the classes of the coordinates that the align edges and the translations known so far tie together
  // (isoline_classes.h); without align edges they are not needed
  const bool aligned = !al.edges.empty();
  Isoline_classes classes(aligned ? 2 * std::size_t(st.n_sectors) : 0);
  if(aligned) relate_align_edges(cm, st, al, classes);
  std::vector<double> tbar(t.size(), 0.);                       // the input's real translations, at their sources
  for(int e : st.cut_edges) {
    const int h = cm.edge_halfedge[std::size_t(e)];
    for(int g : {h, cm.opp[h]}) translation(cm, st, rot, g, true, ubar, &tbar[2 * std::size_t(g)]);
  }
  std::vector<char> known(std::size_t(cm.n_edges), 0);
  std::vector<int> open(std::size_t(cm.n_vertices), 0);        // per vertex: its cut edges without a translation yet
  for(int e : st.cut_edges) {
    const int h = cm.edge_halfedge[std::size_t(e)];
    for(int g : {h, cm.opp[h]}) { t[2 * std::size_t(g)] = 0; t[2 * std::size_t(g) + 1] = 0; }
    ++open[std::size_t(cm.target[h])];
    ++open[std::size_t(cm.target[cm.opp[h]])];
  }
  std::deque<int> ready;                                        // interior vertices with one cut edge open
  auto is_ready = [&](int v) {
    return open[std::size_t(v)] == 1 && !cm.vertex_on_border[v] && corner_of[std::size_t(v)] >= 0 && !root[std::size_t(v)];
  };
  for(int v = 0; v < cm.n_vertices; ++v) if(is_ready(v)) ready.push_back(v);
  auto settle = [&](int h) {                                    // t of h set: its opposite, the counts, the queue
    set_opposite_translation(cm, rot, h, t);
    if(aligned) relate_cut_edge(cm, st, rot, t, h, classes);
    known[std::size_t(cm.edge[h])] = 1;
    for(int v : {cm.target[h], cm.target[cm.opp[h]]})
      if(--open[std::size_t(v)] == 1 && is_ready(v)) ready.push_back(v);
  };
  std::size_t next_free = 0;                                    // st.cut_edges before it all have translations
  std::vector<std::array<long, 2> > point(std::size_t(cm.n_vertices));   // per placed cone its point, chart of face(corner_of[v])
  std::vector<int> placed_K = field_rotation_sums(cm, st, rot);   // per cone placed or being placed its rotation sum
  for(int& k : placed_K) k = k > 0 ? -1 : 0;                     // (1..3); -1: a cone not placed yet; 0: no cone
  Cone_partner_search near_cones(cm, st, rot, t, ubar, placed_K);   // cone_merging.h
  int search_mark = 0;
  bool cycles_opened = false;                                   // the cut edges closing cycles have been chosen
  // Whether the cone v at the point p (chart of face(g0); t holds the translation of its last open cut edge, `crossed`,
  // that puts it there) would make a face of three placed cones non-positive (RIGID_TRIANGLE) or lie on the point of a
  // placed cone (two cones on one point force zero-area triangles: COINCIDENT_CORNERS) that either shares a face with
  // it (both carried into that face's chart) or that a path of edges reaches, its vertices (at the input's UVs) within
  // quantization_cone_reach of p, crossing cut edges whose translations are known only (the search of
  // collapsed_cone_pairs()). With `merge_reach` > 0, a cone that merge_collapsed_cone_pairs() will find (a path of cut
  // edges within merge_reach) is no collision: the pair becomes regular points or one cone of the quad mesh
  // (an optimistic guess: the merge takes each cone once and joins no pair into a vertex of valence below 2), and the
  // faces around v are not checked then. Checking them too, that partner left out, was worse where the cells are as
  // large as the distances between the cones (measured at 17cdc4c): the rot-seamless dragon at grid scale 1 / 2 with
  // 11 / 2 negative and 14 / 4 zero-area triangles left, 94 / 17 wound vertices, instead of 7 / 2, 4 / 2 and 61 / 13
  // (4 to 16 the same).
  auto collides = [&](int v, int g0, int crossed, const long p[2]) {
    known[std::size_t(cm.edge[crossed])] = 1;
    const Cone_merge near = near_cones.find(v, search_mark++, Cone_partner_search::Query{quantization_cone_reach, false, false,
                                                                                         nullptr, nullptr, &known});
    const bool merged = !near.path.empty() && merge_reach > 0 &&
                        near_cones.find(v, search_mark++, Cone_partner_search::Query{merge_reach, true, false,
                                                                                     nullptr, nullptr, &known}).b == near.b;
    known[std::size_t(cm.edge[crossed])] = 0;
    if(!near.path.empty()) return !merged;
    int g = g0;
    do {
      long a[2] = {p[0], p[1]}, q[2][2];                         // in the chart of face(g): v's point, the others' points
      carry_around(cm, st, rot, t, g0, cm.next[g], a);           // cone_merging.h
      bool both = true;
      for(int i = 0; i < 2; ++i) {                               // the other corners of face(g)
        const int h = i == 0 ? cm.next[g] : cm.prev[g], w = cm.target[h];
        if(placed_K[std::size_t(w)] <= 0) { both = false; continue; }   // (w != v: placed_K > 0 means placed)
        q[i][0] = point[std::size_t(w)][0]; q[i][1] = point[std::size_t(w)][1];
        carry_around(cm, st, rot, t, corner_of[std::size_t(w)], cm.next[h], q[i]);
        if(a[0] == q[i][0] && a[1] == q[i][1]) return true;
      }
      // a face of three cones keeps its shape in every map with these translations (RIGID_TRIANGLE): it must be
      // positive (the points are below 2^52: exact as doubles)
      typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
      if(both && CGAL::orientation(P(double(a[0]), double(a[1])), P(double(q[0][0]), double(q[0][1])),
                                   P(double(q[1][0]), double(q[1][1]))) != CGAL::LEFT_TURN)
        return true;
      g = cm.opp[cm.next[g]];
    } while(g != g0);
    return false;
  };
  // whether the translation of `crossed` in t contradicts the align edges, given the translations known (an aligned
  // chain between two cones at different isolines, or across cut edges onto another isoline than its own)
  auto contradicts_alignment = [&](int crossed) {
    if(!aligned || classes.conflict()) return false;
    classes.checkpoint();
    relate_cut_edge(cm, st, rot, t, crossed, classes);
    const bool contradiction = classes.conflict();
    classes.rollback();
    return contradiction;
  };
  auto choose_rounded = [&](int e) {                          // a free choice: e's translation, rounded
    const int h = cm.edge_halfedge[std::size_t(e)];
    double ta[2];
    translation(cm, st, rot, h, true, ubar, ta);
    for(int c = 0; c < 2; ++c) {
      if(!within_exact_integers(ta[c], "the translation of cut edge " + vertex_pair_name(cm, h) + " lies", message))
        return false;
      t[2 * std::size_t(h) + std::size_t(c)] = long(std::nearbyint(ta[c]));
    }
    settle(h);
    return true;
  };
  for(;;) {
    while(!ready.empty()) {
      const int v = ready.front();
      ready.pop_front();
      if(open[std::size_t(v)] != 1) continue;
      // the open cut edge, as the halfedge crossed from v (compose_around() reads t at the crossed halfedge)
      const int g0 = corner_of[std::size_t(v)];
      int crossed = -1, g = g0;
      do {
        const int c = cm.next[g];
        if(st.is_cut[std::size_t(cm.edge[c])] && !known[std::size_t(cm.edge[c])]) crossed = c;
        g = cm.opp[c];
      } while(g != g0);
      // the composition around v is T0 + M t(crossed), M a rotation; the condition asks for T = p - R^K p
      int K;
      long T0[2], M[2][2];
      compose_around(cm, st, rot, t, g0, K, T0);
      for(int c = 0; c < 2; ++c) {
        t[2 * std::size_t(crossed)] = c == 0; t[2 * std::size_t(crossed) + 1] = c == 1;
        long Tc[2];
        compose_around(cm, st, rot, t, g0, K, Tc);
        M[0][c] = Tc[0] - T0[0]; M[1][c] = Tc[1] - T0[1];
      }
      // the translation of `crossed` that makes the composition T = p - R^K p (p = 0 where v is not a cone)
      auto solve = [&](const long p[2]) {
        long need[2] = {0, 0};
        if(K % 4 != 0) {
          const Quarter_turn R(K);
          for(int c = 0; c < 2; ++c) need[c] = p[c] - R.sign[c] * p[R.col[c]];
        }
        const long b[2] = {need[0] - T0[0], need[1] - T0[1]};
        for(int c = 0; c < 2; ++c) {
          const long x = M[0][c] * b[0] + M[1][c] * b[1];                                    // M^T b
          // (the known translations and the points are below 2^52: no overflow)
          if(!within_exact_integers(double(x), "the translation chosen for cut edge " + vertex_pair_name(cm, crossed) + " is",
                                    message))
            return false;
          t[2 * std::size_t(crossed) + std::size_t(c)] = x;
        }
        set_opposite_translation(cm, rot, crossed, t);            // read by collides()' searches, set again by settle()
        return true;
      };
      if(K % 4 != 0) {                                          // a cone: its fixed point, an integer point next to it
        const int s = st.sector_of[std::size_t(g0)];
        for(int c = 0; c < 2; ++c)
          if(!within_exact_integers(std::nearbyint(ubar[2 * std::size_t(s) + std::size_t(c)]),
                                    "cone at vertex " + std::to_string(v) + " lies", message))
            return RANGE_EXCEEDED;
        long p[8][2];
        diffuse_rounding(cm, st, rot, ubar, tbar, crossed, g0, K, T0, p);
        const int n = 4 + aligned_candidates(classes, aligned, 2 * s, &ubar[2 * std::size_t(s)], p);
        // of the four in diffuse_rounding()'s order (and those on the isolines of aligned chains through v), the first
        // that contradicts no align edge and does not put v onto the point of a cone placed near it; else the same of the
        // ring around the four, those within quantization_cone_reach of x (collides()' search finds the cones on points
        // that far); else the first candidate that contradicts no align edge (of the four, then of the ring); else the first
        const double* x = &ubar[2 * std::size_t(s)];
        bool in_range = true;                                   // solve() kept every translation below 2^52
        // the first of the candidates c[0 .. m) within `reach` of x that contradicts no align edge and puts v onto the
        // point of no cone placed near it (-1: none); `first_consistent`: the first that contradicts no align edge
        auto first_free = [&](long (*c)[2], int m, double reach, int& first_consistent) {
          first_consistent = -1;
          for(int i = 0; i < m; ++i) {
            if(std::hypot(double(c[i][0]) - x[0], double(c[i][1]) - x[1]) > reach) continue;
            if(!(in_range = solve(c[i]))) return -1;
            if(contradicts_alignment(crossed)) continue;
            if(first_consistent < 0) first_consistent = i;
            if(!collides(v, g0, crossed, c[i])) return i;
          }
          return -1;
        };
        placed_K[std::size_t(v)] = (K % 4 + 4) % 4;
        int consistent = -1, ring_consistent = -1;
        int chosen = first_free(p, n, HUGE_VAL, consistent);
        long ring[16][2];
        long (*take)[2] = p;
        if(chosen < 0 && in_range) {                            // every one collides: the ring around them
          chosen = first_free(ring, diffuse_rounding(cm, st, rot, ubar, tbar, crossed, g0, K, T0, ring, true),
                              quantization_cone_reach, ring_consistent);
          if(chosen < 0 && consistent < 0) chosen = ring_consistent;
          if(chosen >= 0) take = ring;
        }
        if(!in_range) return RANGE_EXCEEDED;
        if(chosen < 0) chosen = (std::max)(consistent, 0);
        if(!solve(take[chosen])) return RANGE_EXCEEDED;         // t holds the chosen one's translation
        point[std::size_t(v)] = {{take[chosen][0], take[chosen][1]}};
      } else {
        const long p[2] = {0, 0};
        if(!solve(p)) return RANGE_EXCEEDED;
      }
      settle(crossed);
    }
    while(next_free < st.cut_edges.size() && known[std::size_t(st.cut_edges[next_free])]) ++next_free;
    if(next_free == st.cut_edges.size()) return SUCCESS;
    // Stuck: every vertex with one open cut edge is a root or on the border. The first time, the open cut edges that
    // close cycles of the open graph (a spanning forest of it kept, in the order of st.cut_edges) are the free
    // choices: a free choice on an edge that no cycle holds (a bridge) cuts a part off its root and its border
    // vertices, where at the end two vertices share their last open edge and the condition of one of them is left
    // unmet (the full-seamless dragon of ../shared/data, quantized anew: INFEASIBLE at a regular vertex, the
    // translations around it composing to (1, 1)). What is left is a forest, whose leaves peel.
    if(!cycles_opened) {
      cycles_opened = true;
      Union_find forest(cm.n_vertices);
      std::vector<int> closing;
      for(std::size_t i = next_free; i < st.cut_edges.size(); ++i) {
        const int e = st.cut_edges[i], h = cm.edge_halfedge[std::size_t(e)];
        if(known[std::size_t(e)]) continue;
        const int a = forest.find(cm.target[h]), b = forest.find(cm.target[cm.opp[h]]);
        if(a == b) closing.push_back(e);
        else forest.unite(a, b);
      }
      for(int e : closing)
        if(!choose_rounded(e)) return RANGE_EXCEEDED;
      if(!closing.empty()) continue;
    }
    // a tree whose leaves are border vertices or its root: a cut edge at the border (a path between two border vertices)
    int e = st.cut_edges[next_free];
    for(std::size_t i = next_free; i < st.cut_edges.size(); ++i) {
      const int f = st.cut_edges[i], g = cm.edge_halfedge[std::size_t(f)];
      if(!known[std::size_t(f)] && (cm.vertex_on_border[cm.target[g]] || cm.vertex_on_border[cm.target[cm.opp[g]]])) { e = f; break; }
    }
    if(!choose_rounded(e)) return RANGE_EXCEEDED;
  }
}

// `al`: the align edges. `ubar`: the sector values in grid units. `merge_reach`: 0, or the reach of the merge of collapsed
// cone pairs that the snap does afterwards (Snap_options::merge_cone_pairs; reach_at_grid_scale(): S cells at grid scale S >
// 1; predicted with 1 cell there, the rot-seamless dragon at S = 4 kept 867 irregular quad vertices instead of 865, the
// 302K bunny of ../shared/large at S = 8 / 16 100 / 81 wound vertices instead of 93 / 84). `t`: 2 per halfedge, as round_translations() makes them. RANGE_EXCEEDED
// (with `message`) when a translation or a cone lies 2^52 grid units or more from the origin.
inline Status quantize_translations(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                    const Align_edges& al, const std::vector<double>& ubar, double merge_reach,
                                    std::vector<long>& t, std::string& message)
{
  t.assign(2 * std::size_t(cm.n_halfedges), 0);
  const std::vector<int> corner_of = first_corners(cm);
  const std::vector<char> root = quantization_roots(cm, st, rot, corner_of, t);   // t: all 0 yet
  return peel_cut_graph(cm, st, rot, al, ubar, corner_of, root, merge_reach, t, message);
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_INTEGER_GRID_QUANTIZATION_H
