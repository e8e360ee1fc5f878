// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_CONE_SEPARATION_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_CONE_SEPARATION_H

// Integer-grid mode, beyond the paper: separating collapsed cone pairs (Snap_options::separate_cone_pairs).
//
// Where the rounded translations put two cones A and B of the field onto one integer point p (cone_merging.h says
// why no locally injective map then exists), the field is kept and the rounding is changed instead: along the
// shortest path of cut edges h_1 .. h_m from A to B near p (Cone_partner_search::find(), any indices), the side of the path
// on the left of it (the faces of the h_i) is moved by an integer vector e relative to the right side. In the chart
// of face(h_i), e_i is e carried around the path's vertices on the left side (rotations only), and
//   t'(h_i) = t(h_i) - R^{k(h_i)} e_i          (the transition h_i now maps p - e_i where it mapped p).
// Around a vertex of the path other than A and B the composed transition becomes tau(e_i) o C o tau(-e_i): still the
// identity at a regular vertex (add_integer_grid_rows() checks it exactly); A's and B's fixed points move. Of the
// shifts e in {(+-1, +-1), (+-2, 0), (0, +-2)} (one of them moves a 90 or 180 degree cone to a neighbouring integer
// point), those that leave every cone of the path on an integer point, A and B on different points and neither on the
// point of another cone that a path of edges (cut or not) near it reaches are tried, and the one that puts A and B
// nearest (sum of squared distances, grid units) to their input positions is kept; in the order above on ties (or,
// with `rank`, the one the caller ranks: the pipeline tries them, solve_with_separation_trials() in
// snap_pipeline.h). The untangling then moves the map to the new transitions. Pairs no cut path near p joins are left
// (and reported as collapsed where defects remain next to them), and so are pairs whose indices cancel (K_A + K_B = 0
// mod 4): the shift moves both cones by the same vector (merge_cone_pairs is for those). Measured effect: Seamless_snapping.txt,
// "Separating cone pairs".

#include <CGAL/Seamless_snapping/internal/surface/cone_merging.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/integer_grid_constraints.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// default reach of the separation: how far (grid cells, Euclidean) from the cones' common integer point the cut path
// between them may run (2: duck_qc_8 in integer-grid mode gets both of its pairs joined by such paths separated, and no
// negative triangle left; 1 separates one of them), at grid scales S <= 1; 2 S cells for S > 1 (reach_at_grid_scale():
// the map and the cut paths between its cones are S times as long in grid cells; with 2 cells at every scale the dragon
// (full-seamless) at S = 2 kept a pair whose cut runs 2-4 cells from the point, and its quad mesh was refused)
constexpr double default_separate_cone_reach = 2.0;

struct Cone_separation
{
  int a = -1, b = -1;                 // the cones (vertices)
  std::vector<int> path;              // cut halfedges from a to b
  long shift[2] = {0, 0};             // e, in the chart of face(path.front())
  int admissible = 0;                 // the number of shifts that separate the pair (see the header comment)
  int rank = 0;                       // the chosen shift's position among them
};

// The vector e (chart of face(h_in), h_in: target v) carried around v on the side of face(h_in) to the chart of
// face(h_out) (h_out: source v): the difference of the images of e and of the origin
inline void carry_vector_around(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                const std::vector<long>& t, int h_in, int h_out, long e[2])
{
  long o[2] = {0, 0};
  carry_around(cm, st, rot, t, h_in, h_out, o);
  carry_around(cm, st, rot, t, h_in, h_out, e);
  e[0] -= o[0]; e[1] -= o[1];
}

// Moves the left side of `path` by e (see the header comment): changes t on the path's halfedges and their opposites.
inline void shift_left_side(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                            const std::vector<int>& path, const long shift[2], std::vector<long>& t)
{
  long e[2] = {shift[0], shift[1]};
  const long zero[2] = {0, 0};
  for(std::size_t i = 0; i < path.size(); ++i) {
    const int h = path[i];
    if(i > 0) carry_vector_around(cm, st, rot, t, path[i - 1], h, e);
    long re[2] = {e[0], e[1]};
    apply_transition(rot.k[h], zero, re);
    t[2 * std::size_t(h)] -= re[0];
    t[2 * std::size_t(h) + 1] -= re[1];
    set_opposite_translation(cm, rot, h, t);
  }
}

// After a shift: every vertex of the path but its ends composes to the identity or is a cone on an integer point,
// both ends are cones on integer points, and A's point carried along the left side differs from B's. `qa`, `qb`:
// A's point in the chart of face(h_1), B's in the chart of face(h_m).
inline bool separated(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot, const std::vector<long>& t,
                      const std::vector<int>& path, long qa[2], long qb[2])
{
  for(std::size_t i = 0; i + 1 < path.size(); ++i) {
    int K;
    long T[2], q[2];
    compose_around(cm, st, rot, t, path[i], K, T);
    if(K == 0 ? (T[0] != 0 || T[1] != 0) : !integer_cone_point(cm, st, rot, t, path[i], q)) return false;
  }
  if(!integer_cone_point(cm, st, rot, t, cm.prev[path.front()], qa) || !integer_cone_point(cm, st, rot, t, path.back(), qb))
    return false;
  long p[2] = {qa[0], qa[1]};
  for(std::size_t i = 1; i < path.size(); ++i) carry_around(cm, st, rot, t, path[i - 1], path[i], p);
  return p[0] != qb[0] || p[1] != qb[1];
}

// Separates the collapsed cone pairs (see the header comment): changes the integer translations t of
// round_translations() (after merging, if any) along each path. `ubar` in grid units. `rank` (empty, or per vertex):
// for the pair whose first cone is a, the rank[a]-th shift that separates it (0 = the first in the order above) if
// there are that many, else (and for rank[a] < 0) the one nearest to the input. Returns the separations, in order of
// the first cone; each cone is in at most one.
inline std::vector<Cone_separation> separate_collapsed_cone_pairs(const Corner_mesh& cm, const Seam_topology& st,
                                                                  const Cut_rotations& rot, std::vector<long>& t,
                                                                  const std::vector<double>& ubar, double reach,
                                                                  const std::vector<int>& rank = std::vector<int>())
{
  static const long shifts[8][2] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}, {2, 0}, {-2, 0}, {0, 2}, {0, -2}};
  const std::vector<int> K = field_rotation_sums(cm, st, rot);
  std::vector<char> taken(std::size_t(cm.n_vertices), 0);
  Cone_partner_search search(cm, st, rot, t, ubar, K), check(cm, st, rot, t, ubar, K);
  int mark = 0;                                        // of the searches of `check`
  std::vector<Cone_separation> out;
  auto input_point = [&](int h, double x[2]) {       // the input UV of target(h) in the chart of face(h)
    x[0] = ubar[2 * std::size_t(st.sector_of[h])]; x[1] = ubar[2 * std::size_t(st.sector_of[h]) + 1];
  };
  for(int a = 0; a < cm.n_vertices; ++a) {
    if(K[std::size_t(a)] <= 0 || taken[std::size_t(a)] || st.cut_degree[a] == 0) continue;
    const Cone_merge m = search.find(a, a, Cone_partner_search::Query{reach, true, false, &taken, nullptr});
    if(m.path.empty()) continue;
    double xa[2], xb[2];
    input_point(cm.prev[m.path.front()], xa);
    input_point(m.path.back(), xb);
    std::vector<std::pair<int, double> > admissible;   // the shifts that separate the pair, with their distance d
    for(int s = 0; s < 8; ++s) {                       // each shift applied to t and undone (t is additive in e)
      const long undo[2] = {-shifts[s][0], -shifts[s][1]};
      shift_left_side(cm, st, rot, m.path, shifts[s], t);
      long qa[2], qb[2];
      bool ok = separated(cm, st, rot, t, m.path, qa, qb);
      for(int c : {m.a, m.b})                          // neither cone now on the point of another one near it (any edges)
        ok = ok && check.find(c, mark++, Cone_partner_search::Query{reach, false, false, nullptr, nullptr}).path.empty();
      shift_left_side(cm, st, rot, m.path, undo, t);
      if(!ok) continue;
      double d = 0;
      for(int c = 0; c < 2; ++c) d += (double(qa[c]) - xa[c]) * (double(qa[c]) - xa[c]) + (double(qb[c]) - xb[c]) * (double(qb[c]) - xb[c]);
      admissible.emplace_back(s, d);
    }
    if(admissible.empty()) continue;
    int chosen_rank = 0;                               // the wanted rank, else the nearest (the first on ties)
    const int wanted = rank.empty() ? -1 : rank[std::size_t(a)];
    if(wanted >= 0 && wanted < int(admissible.size())) chosen_rank = wanted;
    else
      for(int r = 1; r < int(admissible.size()); ++r)
        if(admissible[std::size_t(r)].second < admissible[std::size_t(chosen_rank)].second) chosen_rank = r;
    const int chosen = admissible[std::size_t(chosen_rank)].first;
    shift_left_side(cm, st, rot, m.path, shifts[chosen], t);
    taken[std::size_t(m.a)] = taken[std::size_t(m.b)] = 1;
    Cone_separation sep;
    sep.a = m.a; sep.b = m.b; sep.path = m.path;
    sep.shift[0] = shifts[chosen][0]; sep.shift[1] = shifts[chosen][1];
    sep.admissible = int(admissible.size());
    sep.rank = chosen_rank;
    out.push_back(sep);
  }
  return out;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_CONE_SEPARATION_H
