// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_CONE_MERGING_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_CONE_MERGING_H

// Integer-grid mode, beyond the paper: merging collapsed cone pairs (Snap_options::merge_cone_pairs).
//
// Integer-grid-map solvers sometimes round a +90 and a -90 degree cone (valence 3 and 5) onto one integer point:
// the rounded translations fix both cones there, the map between them collapses, and no locally injective map
// with these transitions exists (the geodesic between the cones would have length 0), so the untangling cannot
// remove the fold-overs around them and no quad mesh follows the map (quad_extraction.h names such pairs).
// libQEx contracts the pair into one regular quad vertex. Here the field itself is changed, exactly and as
// little as possible: along the shortest path of cut edges from cone A to cone B on which every vertex lies
// within `merge_cone_reach` grid cells of the common integer point p, the rotation of every cut edge changes by
// dk = -K_A (quarter turns, oriented from A to B) and its integer translation so that the transition still maps
// p to p:
//   k' = k + dk,   t' = t + (R^k - R^k') p_i     (p_i: p in the chart of the face on the left of the path)
// Around A the rotations then sum to K_A + dk = 0, around B to K_B - dk = K_A + K_B = 0 (a dipole), around the
// path's other vertices the changes cancel; every composition around a vertex of the path fixes p and has no
// rotation, so it is the identity, as add_integer_grid_rows() checks exactly. A and B are then regular points
// of the field (4 quarter turns), the snap's rows hold the new transitions, and the untangling makes the map
// around them locally injective. Cancelling pairs (K_A + K_B = 0 mod 4) are merged first, each cone at most once.
// Then any other pair is joined the same way: A becomes a regular point and B takes both indices (K_A + K_B around
// it: two +90 degree cones make a cone of valence 2, two -90 degree ones of valence 6), as long as B's valence in
// the quad mesh stays at least 2 (valence 4 - index; a valence-1 point has no quad mesh; a half-turn cone counts as
// valence 2 or 6, whichever allows the join, see Cone_valences); B may take further cones. The map around A is then
// free to open up. Two joined cones on one point whose rotations cancel (two valence-6 points, each made of two -90
// degree cones) join into one valence-8 point (a regular point of the field that the map winds twice around). On the
// dragon (full-seamless) 179 pairs merged, 80 of them joined and 2 into valence-8 points, leave no negative and 8
// zero-area triangles after the untangling instead of 20 and 138 (cancelling pairs only), at 4 points where three +90
// degree cones lie: joined they would make valence 1, so one of them has to move off the point (cone_separation.h,
// with its trials). A path may pass other cones on the same point (their rotation about it is kept). Pairs that no such cut path joins get
// one through the mesh: cut_edges_to_add() finds its edges, the snap makes them cut edges (rotation 0, the input's
// UVs continuous there) before its rows are built, and the merge then runs along them.

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/integer_grid_constraints.h>
#include <CGAL/Seamless_snapping/internal/surface/quad_valences.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// how far (grid cells, Euclidean) from the cones' common integer point the cut path between them may run, at grid
// scales S <= 1 (reach_at_grid_scale())
constexpr double default_merge_cone_reach = 1.0;

// A reach of the searches for cone pairs (`cells` at grid scale 1: default_merge_cone_reach,
// default_separate_cone_reach) at grid scale S: S times as many cells for S > 1 (the same part of the map), as many for
// S up to 1. For the merge (S cells): the map, and the paths between the cones that the rounding puts onto one point,
// are S times as long in cells as at S = 1; with 1 cell at every scale, bench_quad on ../shared/data at S = 2 / 4 / 8
// merged fewer pairs than at S = 1 and left more irregular vertices in the quad mesh (duck_qc_8 28 / 32 / refused for a
// fold-over, against 24 at S = 1; fandisk and duck_miq_8 32 at S = 8 against 28) and the dragon (full-seamless) refused
// at 4 and 8 (cancelling pairs that the input puts exactly onto one point, left with fold-overs next to them); with S
// cells each of them has the irregular vertices it has at S = 1, and the dragon its quad mesh at 2 to 16 (with both
// reaches capped at their values for S = 8 it was refused at 16 again). Unlike 1 cell, S cells do not keep the path
// from going around a third cone: other cones may lie as close as a cell to the point, and the exact checks do not see
// it (the rotation changes cancel at every vertex of the path). Such a merge changes the field where the untangling
// cannot follow; the fold-overs left are reported and extract_quad_mesh() refuses the map. Far too long a reach does
// that (the dragon with 64 S cells: 201 fold-overs left instead of 0, the snap 2.8 -> 10 s); with S cells no map of
// ../shared/data at S = 2, 4 or 8 (bench_quad, also --quantize) was refused that had been accepted with 1 cell.
inline double reach_at_grid_scale(double cells, double grid_scale)
{
  return cells * (std::max)(1.0, grid_scale);
}

struct Cone_merge
{
  int a = -1, b = -1;                 // the cones (vertices), a < b not implied: a is where the path starts
  std::vector<int> path;              // its halfedges, from a to b
  int b_valence = 4;                  // b's valence in the quad mesh afterwards (4: a regular point; a is one; 8: a regular
                                      // point of the field wound twice)
};

// Per vertex, its valence in the quad mesh (4 - the cone's index): rotation sum K = 1 -> 5, K = 3 -> 3 (the angle sum
// is K quarter turns modulo 4), K = 2 -> 2 or 6. The UV angle sum picks one for K = 2, but next to fold-overs it is
// meaningless (the dragon's half-turn cones have angle sums of -2 and 5 quarter turns), so a half-turn cone that no
// merge has touched yet may take the other when only that makes a join possible (`either`): a +90 degree cone
// (valence 3) and a half-turn cone join into a valence-5 point with valence 6 for it, never into valence 1.
struct Cone_valences
{
  std::vector<int> valence;
  std::vector<char> either;

  Cone_valences(const std::vector<int>& K, const std::vector<int>& quarter_turns)
    : valence(K.size(), 4), either(K.size(), 0)
  {
    for(std::size_t v = 0; v < K.size(); ++v) {
      valence[v] = valence_of_rotation_sum(K[v], quarter_turns[v] >= 6);
      either[v] = K[v] == 2;
    }
  }
  // the valence of the point that a and b joined make (valence_a + valence_b - 4, the given valences first, then the
  // other of a half-turn cone's two): at least 2 (no quad mesh has a vertex of valence 1 or 0) and a multiple of 4
  // exactly when their rotations cancel (4, or 8 for two valence-6 points: a point where the rotations compose to the
  // identity is a regular point of the field, wound once or twice); 0 if no choice gives one
  int joined(int a, int b, bool cancelling) const
  {
    const int va = valence[std::size_t(a)], vb = valence[std::size_t(b)];
    const int other_a = either[std::size_t(a)] ? 8 - va : va, other_b = either[std::size_t(b)] ? 8 - vb : vb;
    for(int sum : {va + vb, other_a + vb, va + other_b, other_a + other_b})
      if(sum - 4 >= 2 && cancelling == ((sum - 4) % 4 == 0)) return sum - 4;
    return 0;
  }
  // a regular point now, b the joined one
  void join(int a, int b, int joined_valence)
  {
    valence[std::size_t(b)] = joined_valence;
    valence[std::size_t(a)] = 4;
    either[std::size_t(a)] = either[std::size_t(b)] = 0;
  }
};

// p -> R^k p + t on an integer point
inline void apply_transition(int k, const long* t, long p[2])
{
  const Quarter_turn R(k);
  const long q0 = R.sign[0] * p[R.col[0]] + t[0], q1 = R.sign[1] * p[R.col[1]] + t[1];
  p[0] = q0; p[1] = q1;
}

// The integer point p given in the chart of face(h_in) (h_in: target v), carried around v on the side of face(h_in)
// to the chart of face(h_out) (h_out: source v) through the transitions of the cut edges in between. With `known`
// (per edge), false where a cut edge in between is not marked (its translation is not chosen yet; p is then carried
// only partly), else true
inline bool carry_around(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                         const std::vector<long>& t, int h_in, int h_out, long p[2],
                         const std::vector<char>* known = nullptr)
{
  for(int g = h_in; cm.next[g] != h_out; g = cm.opp[cm.next[g]]) {
    const int crossed = cm.next[g];
    if(!st.is_cut[cm.edge[crossed]]) continue;
    if(known != nullptr && !(*known)[std::size_t(cm.edge[crossed])]) return false;
    apply_transition(rot.k[crossed], &t[2 * std::size_t(crossed)], p);
  }
  return true;
}

// The search for a field cone's partner: what it reads (the cut graph, the rotations and rounded integer translations,
// which merges change between searches, the input UVs `ubar` in grid units, the field's rotation sums K) and, per
// vertex, the mark of the search that reached it last (-1: none; no clearing between searches with different marks)
struct Cone_partner_search
{
  const Corner_mesh& cm;
  const Seam_topology& st;
  const Cut_rotations& rot;
  const std::vector<long>& t;
  const std::vector<double>& ubar;
  const std::vector<int>& K;
  const std::vector<int> corner_of;                 // first_corners()
  std::vector<int> reached_from;

  Cone_partner_search(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                      const std::vector<long>& t, const std::vector<double>& ubar, const std::vector<int>& K)
    : cm(cm), st(st), rot(rot), t(t), ubar(ubar), K(K), corner_of(first_corners(cm)),
      reached_from(std::size_t(cm.n_vertices), -1)
  {}

  // What a search asks for: paths of cut edges only or of any edges, partners b with K[a] + K[b] = 0 mod 4 only or
  // any; with `valences`, only partners that Cone_valences::joined() lets a join (a quad mesh vertex of valence 2 or
  // more, a multiple of 4 exactly when the rotations cancel); never a `taken` one (nullptr: none is)
  struct Query
  {
    double reach;
    bool cut_edges_only = true;
    bool cancelling_only = true;
    const std::vector<char>* taken = nullptr;
    const Cone_valences* valences = nullptr;
    const std::vector<char>* known = nullptr;       // per edge: the cut edges whose translation t holds (nullptr: all);
                                                    // paths do not cross the others
  };

  // The shortest path (of the kind q asks for) from field cone a to a partner b that the rounded transitions carry
  // onto a's integer point, every vertex of it within q.reach of that point; empty if none. Other cones on the
  // point may lie on the path (the changes then keep their rotation about that point); cones elsewhere may not.
  // `mark`: the search's mark in reached_from (one per search).
  Cone_merge find(int a, int mark, const Query& q)
  {
    struct State { int h; long p[2]; int parent; };   // p: a's point in the chart of face(h), h arriving at target(h)
    std::vector<State> states;
    auto seen = [&](int v) { return reached_from[std::size_t(v)] == mark; };
    reached_from[std::size_t(a)] = mark;
    // every cut halfedge leaving target(g_in) (except the one back along g_in), with a's point p carried from the
    // chart of face(g_in) to the chart of its face
    auto push_from = [&](int g_in, const long p[2], bool back_allowed, int parent) {
      int g = g_in;
      do {
        const int out = cm.next[g];
        if((!q.cut_edges_only || st.is_cut[cm.edge[out]]) && (back_allowed || out != cm.opp[g_in]) &&
           !seen(cm.target[out])) {
          State s{out, {p[0], p[1]}, parent};
          if(carry_around(cm, st, rot, t, g_in, out, s.p, q.known)) states.push_back(s);
        }
        g = cm.opp[out];
      } while(g != g_in);
    };
    long pa[2];
    const int ga = corner_of[std::size_t(a)];
    if(!integer_cone_point(cm, st, rot, t, ga, pa)) return Cone_merge();
    push_from(ga, pa, true, -1);
    for(std::size_t i = 0; i < states.size(); ++i) {
      const State s = states[i];
      const int w = cm.target[s.h];
      if(seen(w) || cm.vertex_on_border[w]) continue;
      reached_from[std::size_t(w)] = mark;
      const double* x = &ubar[2 * std::size_t(st.sector_of[s.h])];     // w in the chart of face(s.h)
      if(std::hypot(x[0] - double(s.p[0]), x[1] - double(s.p[1])) > q.reach) continue;
      if(K[std::size_t(w)] < 0) continue;              // a cone whose point is not known yet (peel_cut_graph()): no path
      if(K[std::size_t(w)] > 0) {
        long pw[2];
        if(!integer_cone_point(cm, st, rot, t, s.h, pw) || pw[0] != s.p[0] || pw[1] != s.p[1])
          continue;                                    // a cone elsewhere: the path does not pass through it
        const bool cancelling = (K[std::size_t(a)] + K[std::size_t(w)]) % 4 == 0;
        const bool no_quad_vertex = q.valences != nullptr && q.valences->joined(a, w, cancelling) == 0;
        if((q.taken != nullptr && (*q.taken)[std::size_t(w)]) || (q.cancelling_only && !cancelling) || no_quad_vertex) {
          push_from(s.h, s.p, false, int(i));          // a cone on the point: the path may pass it
          continue;
        }
        Cone_merge m;
        m.a = a; m.b = w;
        for(int j = int(i); j >= 0; j = states[std::size_t(j)].parent) m.path.push_back(states[std::size_t(j)].h);
        std::reverse(m.path.begin(), m.path.end());
        return m;
      }
      push_from(s.h, s.p, false, int(i));
    }
    return Cone_merge();
  }
};

// how far (grid cells, Euclidean) from two cones' common integer point p the path between them may run for
// collapsed_cone_pairs() to call them collapsed: 1, so that the path cannot go around a third cone (the other cones
// lie on integer points other than p, at distance 1 or more, and the path, made of segments inside the disk of radius
// 1 around p, passes none of them); with 2 the duck_miq_8 map in integer-grid mode with merged pairs has a "pair"
// 1449, 9657 whose path goes around a cone (the untangling makes the map locally injective there). It stays 1 at every
// grid scale, unlike the merge's reach (reach_at_grid_scale()): the reports name no pair that a third cone could part, and
// at S > 1 may miss pairs that the merge joins (duck_qc_8 with --keep-cone-pairs at S = 8: 1 pair named, 4 with S cells)
constexpr double default_collapsed_cone_reach = 1.0;

// The collapsed cone pairs of a map, as a finding (nothing changes): for every interior field cone a on an integer
// point, the partner b (any indices) that the shortest path of edges (cut or not) with every vertex within `reach` of
// a's point reaches, the transitions (rotations, integer translations t) along it carrying b's point onto a's; `x`:
// the map in grid units (2 values per sector). The search that merging and separating use (Cone_partner_search), here
// along any edges; a chart composition along paths around other cones would put far-apart cones onto one point too.
// Each pair once, (smaller vertex, larger), sorted.
inline std::vector<std::pair<int, int> > collapsed_cone_pairs(const Corner_mesh& cm, const Seam_topology& st,
                                                              const Cut_rotations& rot, const std::vector<long>& t,
                                                              const std::vector<double>& x, double reach)
{
  const std::vector<int> K = field_rotation_sums(cm, st, rot);
  Cone_partner_search search(cm, st, rot, t, x, K);
  std::vector<std::pair<int, int> > pairs;
  for(int a = 0; a < cm.n_vertices; ++a) {
    if(K[std::size_t(a)] <= 0 || cm.vertex_on_border[a]) continue;
    const Cone_merge m = search.find(a, a, Cone_partner_search::Query{reach, false, false, nullptr, nullptr});
    if(!m.path.empty()) pairs.emplace_back((std::min)(a, m.b), (std::max)(a, m.b));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

// Merges the collapsed cone pairs (see the header comment): changes rot.k and the integer translations t of
// round_translations() along each path. `ubar` in grid units. Returns the merges, in order of the first cone.
// With cut_edges_only = false the paths may use edges that are not cut edges (for cut_edges_to_add() only: the
// transitions are then changed on edges that the snap does not treat as cut edges).
inline std::vector<Cone_merge> merge_collapsed_cone_pairs(const Corner_mesh& cm, const Seam_topology& st,
                                                          Cut_rotations& rot, std::vector<long>& t,
                                                          const std::vector<double>& ubar, double reach,
                                                          bool cut_edges_only = true)
{
  std::vector<int> K = field_rotation_sums(cm, st, rot);     // merged cones become 0: later paths pass them
  Cone_valences valences(K, st.quarter_turns);
  std::vector<char> taken(std::size_t(cm.n_vertices), 0);
  Cone_partner_search search(cm, st, rot, t, ubar, K);
  std::vector<Cone_merge> merges;
  for(int pass = 0; pass < 2; ++pass)                        // cancelling pairs first, then any pair (see the header)
  for(int a = 0; a < cm.n_vertices; ++a) {
    if(K[std::size_t(a)] <= 0 || taken[std::size_t(a)] || st.cut_degree[a] == 0) continue;
    Cone_partner_search::Query q{reach, cut_edges_only, pass == 0, &taken, pass == 0 ? nullptr : &valences};
    Cone_merge m = search.find(a, pass * cm.n_vertices + a, q);
    if(m.path.empty()) continue;
    const int dk = (4 - K[std::size_t(a)]) % 4;
    K[std::size_t(m.b)] = (K[std::size_t(m.a)] + K[std::size_t(m.b)]) % 4;
    K[std::size_t(m.a)] = 0;
    m.b_valence = pass == 0 ? 4 : valences.joined(m.a, m.b, K[std::size_t(m.b)] == 0);
    valences.join(m.a, m.b, m.b_valence);
    taken[std::size_t(m.a)] = 1;
    taken[std::size_t(m.b)] = K[std::size_t(m.b)] == 0;    // a cone that took another's index may take more
    long p[2];
    integer_cone_point(cm, st, rot, t, cm.prev[m.path.front()], p);   // checked by the search
    for(std::size_t i = 0; i < m.path.size(); ++i) {
      const int h = m.path[i];
      if(i > 0) carry_around(cm, st, rot, t, m.path[i - 1], h, p);
      // t' = t + (R^k - R^k') p: the new transition maps p (chart of face(h)) where the old one did
      long old_image[2] = {p[0], p[1]};
      apply_transition(rot.k[h], &t[2 * std::size_t(h)], old_image);
      const int k_new = (rot.k[h] + dk) % 4;
      long new_image[2] = {p[0], p[1]};
      const long zero[2] = {0, 0};
      apply_transition(k_new, zero, new_image);
      for(int c = 0; c < 2; ++c) t[2 * std::size_t(h) + c] = old_image[c] - new_image[c];
      rot.k[h] = k_new;
      rot.k[cm.opp[h]] = (4 - k_new) % 4;
      set_opposite_translation(cm, rot, h, t);
    }
    merges.push_back(m);
  }
  return merges;
}

// The edges to make cut edges so that merge_collapsed_cone_pairs() can merge the pairs that no cut path near their
// point joins: the edges, not cut edges, of the paths through the mesh (within `reach` of the point) that join them
// after the merges along cut paths. The new cut edges have rotation 0 and translation 0 in the input (its UVs are
// continuous there) until the merge changes them. Empty if the translations are not near integers.
inline std::vector<int> cut_edges_to_add(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                         const std::vector<double>& ubar, double tolerance, double reach)
{
  std::vector<long> t;
  std::string ignored;
  if(round_translations(cm, st, rot, ubar, tolerance, t, ignored) != SUCCESS) return {};
  Cut_rotations r = rot;
  merge_collapsed_cone_pairs(cm, st, r, t, ubar, reach);
  std::vector<int> edges;
  for(const Cone_merge& m : merge_collapsed_cone_pairs(cm, st, r, t, ubar, reach, false))
    for(int h : m.path) if(!st.is_cut[cm.edge[h]]) edges.push_back(cm.edge[h]);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_CONE_MERGING_H
