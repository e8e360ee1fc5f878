// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_FLIP_REPAIR_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_FLIP_REPAIR_H

// Flip repair after snapping (Sec. 5.4, Sec. 6, generalized as Sec. 7 suggests): a UV triangle
// whose orientation got worse than in the input (negative, or degenerate = zero area) is fixed by
// moving vertices while every constraint row keeps holding exactly. Orientations are ordered
// NEGATIVE < ZERO < POSITIVE; a move is kept only if no triangle gets worse and one gets better
// (relaxed moves, 4., excepted).
//
// 1. Group moves (Sec. 5.4: "parametrically moving one of the vertices of the inverted triangle
//    into the kernel of its 1-ring"). A move displaces the sectors of one *move group* by t:
//   free sector      a sector in no row of the full system (no cut edge, no align edge): x_s += t,
//                    t in R^2, any double (no row mentions it);
//   cut branch       the two sectors (u^+, u^-) of a non-node vertex inside a cut branch with
//                    rotation k (Sec. 5.3): u^+ += t, u^- += R^k t. Both transition rows of the
//                    vertex, R^k (u_i^+ - u_{i+1}^+) - (u_i^- - u_{i+1}^-) = 0, keep holding since
//                    R^k t - R^k t = 0; t is rounded to the grid F_delta so that the sums stay exact;
//   align branch     the sector of a non-node vertex inside an align branch with aligned component
//                    c: only component 1 - c moves (x_s += s e_{1-c}), the constant one stays.
//    The corners of a group form its fan (for a cut-branch vertex: one fan per side, each in its
//    own chart). For a corner q of the fan and the other two corners a, b of its face
//    (counter-clockwise), the face is positive iff orient(q + M t, a, b) > 0 (M = I or R^k), a
//    half-plane in t:  (M^T n) . t > -orient(q, a, b),  n = (a_v - b_v, b_u - a_u).
//    The kernel is clipped in doubles (a convex polygon, or an interval for align groups).
//    Candidates are the points of the kernel, shrunk by a growing margin, closest to t = 0 (the
//    smallest move that works; the last one is the centroid of the smallest non-empty kernel).
// 2. Node moves, for introduced faces that group moves cannot fix (typically two cones a few grid
//    steps apart, Sec. 5.3 makes cones nodes): the node vertices of the face, alone (radius 0),
//    with the vertices sharing a row of the node system C (radius 1), or their neighbours too
//    (radius 2), move by d with C_local d = 0 (C_local: the rows of C that mention the moved
//    sectors; the other sectors stay), from an exact integer basis of that null space
//    (local_null_space.h) times +-m grid quanta (each basis vector, then pairs). A cone is the
//    fixed point of its transition, so it moves only with the other ends of its branches. The
//    non-node sectors of the branches starting at a moved node follow by the propagation of
//    Sec. 5.3.1 (u^- = u_0^- - R^k u_0^+ + R^k u^+, exact integer sums on F_delta; aligned
//    components are copied). Of all candidates the one with the largest gain is kept.
// 3. Cluster moves, for faces that 1. and 2. cannot fix: a group with its *followers*, the free
//    sectors that share a face with one of its sectors and lie within 2 max_move of it; each follower
//    moves by the displacement of its sector (R^k t). Snapping moves constrained sectors by up to
//    max_move and leaves free ones in place, so a sliver whose free corner sat that close to a moved
//    one in the input blocks every move of the group alone; moved together it keeps its shape. The
//    half-plane of a face is the sum of those of its moved corners (exact for corners moved by one
//    M t). Example (integer-grid map of the Directional dragon): a vertex of a cut branch one grid
//    step from a cone, with a free vertex 0.2 steps next to it on the other side of the cut.
// 4. Relaxed moves, for faces made worse by snapping only, after 1.-3. failed: group and cluster
//    moves that may let other faces fall back to their input orientation (never below it); accepted
//    iff the total deficit sum_f max(0, input_f - o_f) decreases, or stays and the gain is positive.
//    Example: two cones forced onto one integer point P with faces (a, P, b) and (a, b, P') (P' = P)
//    on both sides of the edge ab: one orientation is minus the other in every exact solution. In the
//    input the first was positive, the second negative; snapping swapped them; the relaxed move swaps
//    them back (no face ends worse than in the input).
// 5. Joint moves, for faces made worse by snapping that 1.-4. cannot repair: a node move of 2. (radius
//    0, 1, 2; each basis vector, then pairs, times +-m grid quanta) together with a group or cluster
//    move of a vertex of the face, computed for the x of the node move and tested as one change;
//    strict, then relaxed as in 4. Example (Directional dragon, plain snapping, face 3085): a sliver
//    of area 0.12 square quanta between two node vertices next to a cone and a vertex of a cut
//    branch; neither the node vertices nor the branch vertex can move alone.
// Every candidate is only accepted after exact tests on the doubles that would be stored:
//   - CGAL::orientation (exact predicate) on every face around a changed sector: none gets worse,
//     at least one gets better (relaxed moves: see 4.);
//   - every row of the full system that mentions a changed variable evaluates to zero exactly
//     (and the pipeline checks every row again at the end, verify_stage).
// So the number of bad faces decreases monotonically (relaxed moves decrease the deficit, which no
// move increases) and exactness is never traded. Faces made worse by snapping
// are repaired first (moves 1.-5.), then faces flipped in the input (moves 1. and 3.).
// Bound: every moved coordinate stays within max_i |x_i - ubar_i| (the largest change made by
// snapping) of its input value, so the repair never increases the maximal change.
// What is left is explained: a face is *forced degenerate* when u_s - u_t = 0 for two of its
// sectors is a rational combination of constraint rows (exact rank test), e.g. two cones joined by
// a cut branch with rotation k != 0, (R^k - I)(u_s - u_t) = 0: no exact solution of these
// constraints has that face positive.

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/index_lists.h>
#include <CGAL/Seamless_snapping/internal/surface/exact_uv_check.h>
#include <CGAL/Seamless_snapping/internal/surface/face_orientations.h>
#include <CGAL/Seamless_snapping/internal/projection/fixed_point_grid.h>
#include <CGAL/Seamless_snapping/internal/surface/local_null_space.h>
#include <CGAL/Seamless_snapping/internal/surface/reduced_system.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>
#include <CGAL/Seamless_snapping/internal/surface/uv_area.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// A face the repair works on, from its orientation now and in the input: worse than in the input
// (introduced), or negative (inherited).
inline bool is_repair_target(signed char now, signed char input) { return now < input || now == CGAL::NEGATIVE; }

struct Flip_repair_result
{
  Orientation_counts input;             // faces of ubar
  Orientation_counts before;            // faces of x on entry (after snapping)
  Orientation_counts after;             // faces of x on exit
  Orientation_counts introduced_before; // on entry, among the faces positive in the input
  Orientation_counts introduced_after;  // on exit, among the faces positive in the input
  std::size_t moves = 0;                // accepted moves (all kinds)
  std::size_t node_moves = 0;           // of which moves of node vertices (local null space of C)
  std::size_t cluster_moves = 0;        // of which group moves with free neighbours, or relaxed (Flip_repair::cluster_move)
  std::size_t joint_moves = 0;          // of the node moves, those with a group or cluster move (Flip_repair::try_joint_move)
  std::size_t joint_candidates = 0;     // node moves tried as the first half of a joint move (the search's cost)
  std::size_t relaxed_moves = 0;        // of these, moves that let faces fall back to their input orientation
  std::vector<int> unrepaired_faces;    // positive in the input, not on exit (Corner_mesh numbering), ascending
  std::size_t forced_degenerate = 0;    // of these, faces degenerate in every exact solution (forced_degenerate())
  std::string reasons;                  // why they could not be repaired
};

class Flip_repair
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;

  struct Member { int sector; int k; };             // sector moves by R^k t (t in the group's parameter space)
  struct Group
  {
    int kind = 0;                                  // 0 free, 1 cut branch, 2 align branch
    std::vector<Member> m;                         // the group's sectors; in a cluster move, then its followers
    int axis = -1;                                 // align: the moving component (1 - c); -1: t in R^2
  };
  struct Halfplane { double g[2]; double h; double norm; };   // g . tau >= h (+ margin * norm)

  const Corner_mesh& cm;
  const Seam_topology& st;
  const Constraint_rows& rows;
  const Fixed_point_grid& grid;
  std::vector<double>& x;
  const std::vector<double>* ubar_ = nullptr;
  std::vector<int> face_corner;                    // per face: one of its halfedges
  Index_lists sector_corners;                      // sector -> its corners
  Index_lists var_rows;                            // variable -> the rows that mention it
  std::vector<int> group_of;                       // per sector: group index, -1 = fixed
  std::vector<Group> groups;
  std::vector<signed char> orient_;                // current orientation per face (exact)
  std::vector<unsigned char> joint_tries_;         // per face: passes that searched joint moves for it (at most 2)
  std::size_t joint_candidates_ = 0;               // node moves tried in joint moves so far
  // The joint-move search tries at most this many node moves per repair. Measured (test_constraints, random
  // connection constraints that flip 30-900 faces): up to 830k candidates per repair, 40 us each, for 0-2
  // joint moves found; Directional's dragon needs 6 (default mode) and tries 4.1-4.5k without success in the
  // other runs. The budget keeps a repair below about a second; what it leaves is reported (explain()).
  static constexpr std::size_t joint_budget = 20000;
  bool joint_budget_spent() const { return joint_candidates_ >= joint_budget; }
  std::vector<signed char> input_;                 // orientation per face in the input ubar (exact)
  bool relaxed_ = false;                           // faces may fall back to their input orientation (see orientation_gain)
  struct Change;
  const Change* prefix_ = nullptr;                 // joint moves: the node move that x holds (try_joint_move)
  std::vector<std::pair<int, double> > prefix_new_; // its new values
  // node moves
  const Reduced_system& rs;
  Index_lists vertex_sectors;                                      // vertex -> its sectors
  Index_lists var_node_rows;                                       // variable -> rows of the node system C
  Index_lists cut_from, align_from;                                // sector -> branches that start at it (u_0)
  std::vector<int> col_of;                                         // variable -> column of the local system, -1
  std::vector<int> face_stamp; int stamp = 0;
  mutable std::vector<signed char> forced_;                        // per face: forced_degenerate(), -1 = not computed yet
  struct Local_null_space
  {
    std::vector<int> vars;                       // the sector variables of the cluster
    std::vector<std::vector<long> > basis;       // integer basis of {d : C_local d = 0}, one entry per variable
    std::vector<std::vector<int> > support;      // per basis vector: the positions of its nonzero entries
    bool ok = false;
  };
  std::vector<std::array<int, 3> > null_space_of_;                 // per face and radius: index into null_spaces_, -1
  std::vector<Local_null_space> null_spaces_;                      // (they depend on C only, not on x: kept across passes)

public:
  Flip_repair(const Corner_mesh& cm_, const Seam_topology& st_, const Reduced_system& rs_,
              const Constraint_rows& full, const Fixed_point_grid& grid_, std::vector<double>& x_)
    : cm(cm_), st(st_), rows(full), grid(grid_), x(x_), rs(rs_)
  {
    const int ns = st.n_sectors;
    face_corner.assign(cm.n_faces, -1);
    for(int h = 0; h < cm.n_halfedges; ++h)
      if(!cm.is_border_halfedge(h) && face_corner[cm.face[h]] < 0) face_corner[cm.face[h]] = h;
    sector_corners.build(ns, [&](auto emit) {
      for(int h = 0; h < cm.n_halfedges; ++h) if(!cm.is_border_halfedge(h)) emit(st.sector_of[h], h);
    });
    const std::size_t nv = 2 * std::size_t(ns);
    rows_by_variable(nv, rows, var_rows);
    rows_by_variable(nv, rs.node_rows, var_node_rows);
    col_of.assign(nv, -1);
    face_stamp.assign(cm.n_faces, 0);
    forced_.assign(cm.n_faces, -1);
    null_space_of_.assign(cm.n_faces, std::array<int, 3>{{-1, -1, -1}});
    vertex_sectors.build(cm.n_vertices, [&](auto emit) { for(int t = 0; t < ns; ++t) emit(st.sector_vertex(cm, t), t); });
    cut_from.build(ns, [&](auto emit) {
      for(std::size_t b = 0; b < rs.cut_branches.size(); ++b) {
        emit(rs.cut_branches[b].u0_plus, int(b));
        if(rs.cut_branches[b].u0_minus != rs.cut_branches[b].u0_plus) emit(rs.cut_branches[b].u0_minus, int(b));
      }
    });
    align_from.build(ns, [&](auto emit) {
      for(std::size_t b = 0; b < rs.align_branches.size(); ++b) emit(rs.align_branches[b].u0, int(b));
    });

    // move groups: the inner sectors of the branches, then the sectors in no row. A sector that
    // would belong to two groups (not expected) stays fixed, and so do its partners.
    std::vector<Group> candidates;
    for(const Cut_branch_plan& p : rs.cut_branches)
      for(const std::pair<int, int>& s : p.inner) {
        Group g; g.kind = 1; g.m = {Member{s.first, 0}, Member{s.second, p.k}};
        candidates.push_back(std::move(g));
      }
    for(const Align_branch_plan& p : rs.align_branches)
      for(int s : p.inner) {
        Group g; g.kind = 2; g.m = {Member{s, 0}}; g.axis = 1 - p.component;
        candidates.push_back(std::move(g));
      }
    std::vector<int> uses(ns, 0);
    for(const Group& g : candidates) for(const Member& mb : g.m) ++uses[mb.sector];
    group_of.assign(ns, -1);
    groups.reserve(candidates.size() + std::size_t(ns));
    for(Group& g : candidates) {
      bool unique = true;
      for(const Member& mb : g.m) unique = unique && uses[mb.sector] == 1;
      if(!unique) continue;
      for(const Member& mb : g.m) group_of[mb.sector] = int(groups.size());
      groups.push_back(std::move(g));
    }
    for(int s = 0; s < ns; ++s) {
      if(uses[s] > 0 || !var_rows[2 * s].empty() || !var_rows[2 * s + 1].empty()) continue;   // on a branch, or in some row
      Group g; g.kind = 0; g.m = {Member{s, 0}};
      group_of[s] = int(groups.size());
      groups.push_back(std::move(g));
    }
  }

  // variable -> the rows of r that mention it, in row order
  static void rows_by_variable(std::size_t nv, const Constraint_rows& r, Index_lists& out)
  {
    out.build(int(nv), [&](auto emit) {
      for(std::size_t i = 0; i < r.size(); ++i)
        for(std::size_t k = r.start[i]; k < r.start[i + 1]; ++k) emit(r.col[k], int(i));
    });
  }

  int face_sector(int f, int i) const
  {
    int h = face_corner[f];
    for(int j = 0; j < i; ++j) h = cm.next[h];
    return st.sector_of[h];
  }

  CGAL::Orientation face_orientation(int f, const std::vector<double>& y) const
  {
    const int s0 = face_sector(f, 0), s1 = face_sector(f, 1), s2 = face_sector(f, 2);
    return CGAL::orientation(P(y[2 * s0], y[2 * s0 + 1]), P(y[2 * s1], y[2 * s1 + 1]), P(y[2 * s2], y[2 * s2 + 1]));
  }

  // Runs the repair on x. `ubar`: the input (for the input flips and the move bound); `input` and
  // `current`: face_orientations() of ubar and x when the caller has them (else computed here).
  Flip_repair_result run(const std::vector<double>& ubar, const std::vector<signed char>* input_orientations = nullptr,
                         const std::vector<signed char>* current_orientations = nullptr)
  {
    Flip_repair_result r;
    input_ = input_orientations != nullptr ? *input_orientations : face_orientations(cm, st, ubar);
    const std::vector<signed char>& input = input_;
    orient_ = current_orientations != nullptr ? *current_orientations : face_orientations(cm, st, x);
    joint_tries_.assign(orient_.size(), 0);
    r.input = count_orientations(input);
    r.before = count_orientations(orient_);
    r.introduced_before = count_orientations(orient_, &input);
    // targets: faces worse than in the input (introduced), then faces flipped in the input
    std::vector<int> introduced, inherited;
    for(int f = 0; f < cm.n_faces; ++f) {
      if(!is_repair_target(orient_[f], input[f])) continue;
      if(orient_[f] < input[f]) introduced.push_back(f);
      else inherited.push_back(f);
    }
    ubar_ = &ubar;
    double snap_change = 0;
    for(std::size_t i = 0; i < x.size(); ++i) snap_change = (std::max)(snap_change, std::fabs(x[i] - ubar[i]));
    const double limit = snap_change;
    for(int pass = 0; pass < 8; ++pass) {
      bool progress = false;
      for(int f : introduced) progress = (orient_[f] < input[f] && try_face(f, limit, true, r)) || progress;
      if(pass < 4) for(int f : inherited) progress = try_face(f, limit, false, r) || progress;
      if(!progress) break;
    }
    r.joint_candidates = joint_candidates_;
    r.after = count_orientations(orient_);
    r.introduced_after = count_orientations(orient_, &input);
    for(int f = 0; f < cm.n_faces; ++f)
      if(input[f] == CGAL::POSITIVE && orient_[f] != CGAL::POSITIVE) r.unrepaired_faces.push_back(f);
    if(!r.unrepaired_faces.empty()) r.reasons = explain(r.unrepaired_faces, limit);
    for(int f : r.unrepaired_faces) r.forced_degenerate += forced_degenerate(f) ? 1 : 0;   // cached by explain()
    return r;
  }

private:
  bool try_face(int f, double max_move, bool node_moves, Flip_repair_result& r)
  {
    if(orient_[f] == CGAL::POSITIVE) return false;
    int order[3];
    face_groups(f, order);
    for(int g : order) {
      if(g < 0) continue;
      if(try_move(groups[g], f, max_move)) { ++r.moves; return true; }
    }
    // then the node vertices of the face, alone and with their neighbours in C
    for(int radius = 0; radius < 3 && node_moves; ++radius)
      if(try_node_move(f, radius, max_move)) { ++r.moves; ++r.node_moves; return true; }
    // then the groups with the free sectors next to them (cluster moves), for faces made worse by
    // snapping also relaxed (a face may fall back to its input orientation)
    for(int relaxed = 0; relaxed < (node_moves ? 2 : 1); ++relaxed) {
      relaxed_ = relaxed == 1;
      bool done = false;
      for(int i = 0; i < 3 && !done; ++i) {
        if(order[i] < 0) continue;
        Group cluster;
        if(relaxed_ && try_move(groups[order[i]], f, max_move)) done = true;
        else if(cluster_move(groups[order[i]], max_move, cluster) && try_move(cluster, f, max_move)) done = true;
      }
      relaxed_ = false;
      if(done) { ++r.moves; ++r.cluster_moves; r.relaxed_moves += relaxed; return true; }
    }
    // then node moves with a group or cluster move of a vertex of the face (joint moves), strict, then relaxed
    // (not for faces degenerate in every exact solution: no move repairs them); the search is costly (every
    // node move times every group move), so a face gets it in two passes at most: many flips (e.g. after
    // random connection constraints) would otherwise repeat it in every pass; and a repair tries at most
    // joint_budget candidates in all
    if(node_moves && (joint_tries_[std::size_t(f)] >= 2 || joint_budget_spent())) return false;
    if(node_moves) ++joint_tries_[std::size_t(f)];
    for(int relaxed = 0; relaxed < 2 && node_moves && !forced_degenerate(f); ++relaxed) {
      relaxed_ = relaxed == 1;
      bool done = false;
      for(int radius = 0; radius < 3 && !done; ++radius) done = try_joint_move(f, radius, max_move);
      relaxed_ = false;
      if(done) { ++r.moves; ++r.node_moves; ++r.joint_moves; return true; }
    }
    return false;
  }

  // The group g with its followers: the free sectors (in no row) that share a face with a sector of g
  // and lie within 2 max_move of it (L-infinity, in that face's chart); each moves with its sector
  // (by R^k t). Snapping moves constrained sectors by up to max_move and leaves free ones in place,
  // so a free vertex that sat this close to a moved one in the input (a sliver) is moved along.
  // false if g has no followers.
  bool cluster_move(const Group& g, double max_move, Group& cluster) const
  {
    cluster = g;
    for(std::size_t i = 0; i < g.m.size(); ++i) {
      const int s = g.m[i].sector;
      for(int corner : sector_corners[s])
        for(int h : {cm.next[corner], cm.prev[corner]}) {
          const int t = st.sector_of[h];
          if(group_of[t] < 0 || groups[std::size_t(group_of[t])].kind != 0 || group_of[t] == group_of[s]) continue;
          if(!(std::fabs(x[2 * t] - x[2 * s]) <= 2 * max_move && std::fabs(x[2 * t + 1] - x[2 * s + 1]) <= 2 * max_move)) continue;
          bool known = false;
          for(const Member& mb : cluster.m) known = known || mb.sector == t;
          if(!known) cluster.m.push_back(Member{t, g.m[i].k});
        }
    }
    return cluster.m.size() > g.m.size();
  }

  int rank(int g) const { return g < 0 ? 3 : (groups[g].kind == 0 ? 0 : (groups[g].kind == 2 ? 1 : 2)); }

  // the move groups of the corners of face f (-1: fixed), those that move freely first, then align,
  // then cut-branch groups
  void face_groups(int f, int order[3]) const
  {
    for(int i = 0; i < 3; ++i) order[i] = group_of[face_sector(f, i)];
    std::stable_sort(order, order + 3, [&](int a, int b) { return rank(a) < rank(b); });
  }

  // Node-move candidates, in the order of the search: visit(combo) for one basis vector times +-m,
  // m in `scales` (each_single_move), or two basis vectors times +-m each (each_pair_move); stops
  // and returns true at the first visit that returns true.
  template <class Visit>
  static bool each_single_move(std::size_t n, std::initializer_list<long> scales, Visit visit)
  {
    std::vector<std::pair<int, long> > combo;
    for(long m : scales)
      for(std::size_t i = 0; i < n; ++i)
        for(long sign : {1L, -1L}) { combo.assign(1, std::make_pair(int(i), sign * m)); if(visit(combo)) return true; }
    return false;
  }
  template <class Visit>
  static bool each_pair_move(std::size_t n, std::initializer_list<long> scales, Visit visit)
  {
    std::vector<std::pair<int, long> > combo;
    for(long m : scales)
      for(std::size_t i = 0; i < n; ++i)
        for(std::size_t j = i + 1; j < n; ++j)
          for(long si : {1L, -1L}) for(long sj : {1L, -1L}) {
            combo.assign(1, std::make_pair(int(i), si * m));
            combo.emplace_back(int(j), sj * m);
            if(visit(combo)) return true;
          }
    return false;
  }

  // the faces of the group's fans, with their moved corner
  void group_faces(const Group& g, std::vector<int>& corners, std::vector<int>& member) const
  {
    corners.clear(); member.clear();
    for(int i = 0; i < int(g.m.size()); ++i)
      for(int corner : sector_corners[g.m[i].sector]) {
        corners.push_back(corner);
        member.push_back(i);
      }
  }

  // the exact orientation, rounded to the nearest double: Mpzf::to_double() rounds by the 64-bit limbs, 1 ulp apart
  // for x and 2^j x (the half-planes of a kernel, and the move chosen in it, were then not scale covariant)
  static double exact_orient_to_double(double qx, double qy, double ax, double ay, double bx, double by)
  {
    return nearest_double(twice_triangle_uv_area(qx, qy, ax, ay, bx, by));
  }

  // Clips the convex polygon `poly` (2D) by g . t >= h.
  static void clip(std::vector<double>& poly, const double g[2], double h, std::vector<double>& tmp)
  {
    tmp.clear();
    const std::size_t n = poly.size() / 2;
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      const double pi[2] = {poly[2 * i], poly[2 * i + 1]}, pj[2] = {poly[2 * j], poly[2 * j + 1]};
      const double vi = g[0] * pi[0] + g[1] * pi[1] - h, vj = g[0] * pj[0] + g[1] * pj[1] - h;
      if(vi >= 0) { tmp.push_back(pi[0]); tmp.push_back(pi[1]); }
      if((vi >= 0) != (vj >= 0)) {
        const double a = vi / (vi - vj);
        tmp.push_back(pi[0] + a * (pj[0] - pi[0]));
        tmp.push_back(pi[1] + a * (pj[1] - pi[1]));
      }
    }
    poly.swap(tmp);
  }

  // the point of the convex polygon closest to the origin (the polygon is non-empty)
  static void closest_to_origin(const std::vector<double>& poly, double out[2])
  {
    const std::size_t n = poly.size() / 2;
    bool inside = n >= 3;
    for(std::size_t i = 0; i < n && inside; ++i) {
      const std::size_t j = (i + 1) % n;
      const double cr = poly[2 * i] * poly[2 * j + 1] - poly[2 * i + 1] * poly[2 * j];   // orient(pi, pj, 0)
      if(cr < 0) inside = false;
    }
    if(inside) {   // the polygon is counter-clockwise when built from a ccw box
      out[0] = 0; out[1] = 0;
      return;
    }
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      const double ax = poly[2 * i], ay = poly[2 * i + 1];
      const double dx = poly[2 * j] - ax, dy = poly[2 * j + 1] - ay;
      const double dd = dx * dx + dy * dy;
      double a = dd > 0 ? -(ax * dx + ay * dy) / dd : 0;
      a = a < 0 ? 0 : (a > 1 ? 1 : a);
      const double px = ax + a * dx, py = ay + a * dy, d = px * px + py * py;
      if(d < best) { best = d; out[0] = px; out[1] = py; }
    }
  }

  static void centroid(const std::vector<double>& poly, double out[2])
  {
    const std::size_t n = poly.size() / 2;
    out[0] = out[1] = 0;
    for(std::size_t i = 0; i < n; ++i) { out[0] += poly[2 * i]; out[1] += poly[2 * i + 1]; }
    out[0] /= double(n); out[1] /= double(n);
  }

  // the kernel of the group's fans shrunk by `margin`: a polygon (2D) or an interval (1D, as 2 values)
  bool kernel(const std::vector<Halfplane>& hp, int dim, double L, double margin, std::vector<double>& poly,
              std::vector<double>& tmp) const
  {
    if(dim == 1) {
      double lo = -L, hi = L;
      for(const Halfplane& p : hp) {
        const double h = p.h + margin * p.norm;
        if(p.g[0] > 0) lo = (std::max)(lo, h / p.g[0]);
        else if(p.g[0] < 0) hi = (std::min)(hi, h / p.g[0]);
        else if(h > 0) return false;
      }
      if(!(lo < hi)) return false;
      poly.assign({lo, hi});
      return true;
    }
    poly.assign({-L, -L, L, -L, L, L, -L, L});
    for(const Halfplane& p : hp) {
      clip(poly, p.g, p.h + margin * p.norm, tmp);
      if(poly.size() < 6) return false;
    }
    return true;
  }

  bool try_move(const Group& g, int target, double max_move)
  {
    std::vector<int> corners, member;
    group_faces(g, corners, member);
    const int dim = g.axis >= 0 ? 1 : 2;

    // current orientations (exact) and half-planes in the parameter space, per face of the fans: a
    // corner q moved by M t (M = R^k of its member) changes orient(q, a, b) by (M^T n) . t,
    // n = (a_v - b_v, b_u - a_u) (a, b the next corners counter-clockwise); these add up over the
    // moved corners of the face (exact when they move by the same M t: a cluster move)
    struct Fan_face { int face; int corner; CGAL::Orientation sign; double G[2]; };
    std::vector<Fan_face> faces;
    double L = 0;
    for(std::size_t i = 0; i < corners.size(); ++i) {
      const int c = corners[i];
      const int s = st.sector_of[c], sa = st.sector_of[cm.next[c]], sb = st.sector_of[cm.prev[c]];
      const double qx = x[2 * s], qy = x[2 * s + 1];
      const double ax = x[2 * sa], ay = x[2 * sa + 1], bx = x[2 * sb], by = x[2 * sb + 1];
      L = (std::max)({L, std::fabs(ax - qx), std::fabs(ay - qy), std::fabs(bx - qx), std::fabs(by - qy)});
      const double n[2] = {ay - by, bx - ax};
      double mn[2];                              // M^T n, M = R^k: (R^k)^T = R^-k
      rotate_quarter_turns(-g.m[member[i]].k, n[0], n[1], mn[0], mn[1]);
      std::size_t j = 0;
      while(j < faces.size() && faces[j].face != cm.face[c]) ++j;
      if(j == faces.size())
        faces.push_back(Fan_face{cm.face[c], c, CGAL::orientation(P(qx, qy), P(ax, ay), P(bx, by)), {0, 0}});
      faces[j].G[0] += mn[0];
      faces[j].G[1] += mn[1];
    }
    std::vector<Halfplane> all, required;
    std::size_t old_bad = 0;
    for(const Fan_face& ff : faces) {
      if(ff.sign != CGAL::POSITIVE) ++old_bad;
      if(ff.G[0] == 0 && ff.G[1] == 0) continue;     // e.g. a == b: the face is degenerate whatever we do
      const int c = ff.corner;
      const int s = st.sector_of[c], sa = st.sector_of[cm.next[c]], sb = st.sector_of[cm.prev[c]];
      Halfplane p;
      if(dim == 1) { p.g[0] = ff.G[g.axis]; p.g[1] = 0; }
      else { p.g[0] = ff.G[0]; p.g[1] = ff.G[1]; }
      p.norm = std::sqrt(ff.G[0] * ff.G[0] + ff.G[1] * ff.G[1]);
      p.h = -exact_orient_to_double(x[2 * s], x[2 * s + 1], x[2 * sa], x[2 * sa + 1], x[2 * sb], x[2 * sb + 1]);
      all.push_back(p);
      if(floor_of(ff.face, ff.sign) != CGAL::NEGATIVE || ff.face == target) required.push_back(p);
    }
    if(old_bad == 0 || !(L > 0)) return false;
    L *= 4;
    // |new - ubar| <= max_move for every moved coordinate: (R^k t)_c = sign_c t_{col_c} within
    // [lo, hi] = [ubar - x - max_move, ubar - x + max_move]; the margin does not shrink these
    for(int i = 0; i < int(g.m.size()); ++i) {
      const Quarter_turn R(g.m[i].k);
      for(int c = 0; c < 2; ++c) {
        const int var = 2 * g.m[i].sector + c;
        const double lo = (*ubar_)[var] - x[var] - max_move, hi = (*ubar_)[var] - x[var] + max_move;
        double e[2] = {0, 0};
        if(dim == 1) { if(R.col[c] != g.axis) continue; e[0] = R.sign[c]; }
        else e[R.col[c]] = R.sign[c];
        Halfplane p_lo, p_hi;                 // e . t >= lo  and  -e . t >= -hi
        p_lo.g[0] = e[0]; p_lo.g[1] = e[1]; p_lo.h = lo; p_lo.norm = 0;
        p_hi.g[0] = -e[0]; p_hi.g[1] = -e[1]; p_hi.h = -hi; p_hi.norm = 0;
        all.push_back(p_lo); all.push_back(p_hi); required.push_back(p_lo); required.push_back(p_hi);
      }
    }

    // quantum of the moved values: the grid for cut branches, else the spacing of the doubles there
    double q = grid.quantum;
    if(g.kind != 1) {
      double mx = 0;
      for(int i = 0; i < int(g.m.size()); ++i)
        mx = (std::max)({mx, std::fabs(x[2 * g.m[i].sector]), std::fabs(x[2 * g.m[i].sector + 1])});
      q = std::nextafter(mx, std::numeric_limits<double>::infinity()) - mx;
    }
    // margins from a few quanta upwards: the first candidate that passes is the smallest move
    const double m0 = 4 * q;

    std::vector<double> poly, last, tmp;
    for(const std::vector<Halfplane>* hp : {&all, &required}) {
      if(hp == &required && required.size() == all.size()) break;
      bool any = false;
      double margin = m0;
      for(int step = 0; step < 40; ++step, margin *= 4) {
        if(!kernel(*hp, dim, L, margin, poly, tmp)) break;
        any = true;
        last = poly;
        double t[2] = {0, 0};
        if(dim == 1) { const double lo = poly[0], hi = poly[1]; t[0] = lo > 0 ? lo : (hi < 0 ? hi : 0); }
        else closest_to_origin(poly, t);
        if(attempt(g, t, dim, max_move)) return true;
      }
      if(any) {
        double t[2] = {0, 0};
        if(dim == 1) t[0] = 0.5 * (last[0] + last[1]);
        else centroid(last, t);
        if(attempt(g, t, dim, max_move)) return true;
      }
    }
    return false;
  }

  // Applies the displacement (after rounding) if every exact test passes.
  bool attempt(const Group& g, const double tau[2], int dim, double max_move)
  {
    double t[2] = {0, 0};
    if(dim == 1) t[g.axis] = tau[0];
    else { t[0] = tau[0]; t[1] = tau[1]; }
    if(g.kind == 1) { t[0] = grid.round(t[0]); t[1] = grid.round(t[1]); }
    if(!std::isfinite(t[0]) || !std::isfinite(t[1]) || (t[0] == 0 && t[1] == 0)) return false;

    Change ch;
    if(prefix_ != nullptr) ch.old = prefix_->old;          // a joint move: x already holds the node move
    for(int i = 0; i < int(g.m.size()); ++i) {
      double d[2];
      rotate_quarter_turns(g.m[i].k, t[0], t[1], d[0], d[1]);
      for(int c = 0; c < 2; ++c) ch.set(x, 2 * g.m[i].sector + c, x[2 * g.m[i].sector + c] + d[c]);
    }
    const bool ok = commit_if_better(ch, max_move, false) > 0;
    if(!ok && prefix_ != nullptr)                              // undone with the group move: apply the node move again
      for(const std::pair<int, double>& v : prefix_new_) x[v.first] = v.second;
    return ok;
  }

  // Joint moves, for faces made worse by snapping that 1.-4. cannot repair: a node move (as in
  // try_node_move) together with a group or cluster move of a vertex of the face, computed for the
  // node move's x and accepted as one change (every test on the union). Example (Directional dragon,
  // plain snapping): a sliver between two node vertices next to a cone and a cut-branch vertex; the
  // node vertices cannot move without flipping the sliver further, nor the branch vertex alone
  // without flipping its other faces.
  bool try_joint_move(int f, int radius, double max_move)
  {
    const Local_null_space& ns = local_null_space(f, radius);
    if(!ns.ok) return false;
    int order[3];
    face_groups(f, order);
    if(order[0] < 0) return false;                       // no corner can move (fixed ones sort last)
    auto consider = [&](const std::vector<std::pair<int, long> >& combo) {
      if(joint_budget_spent()) return true;                          // stops the enumeration (not a move)
      ++joint_candidates_;
      Change pre;
      if(!apply_node_move(ns, combo, pre) || pre.old.empty()) { pre.undo(x); return false; }
      prefix_ = &pre;
      prefix_new_.clear();
      for(const std::pair<int, double>& v : pre.old) prefix_new_.emplace_back(v.first, x[v.first]);
      bool done = false;
      for(int i = 0; i < 3 && !done; ++i) {
        if(order[i] < 0 || (i > 0 && order[i] == order[i - 1])) continue;
        Group cluster;
        done = try_move(groups[order[i]], f, max_move) ||
               (cluster_move(groups[order[i]], max_move, cluster) && try_move(cluster, f, max_move));
      }
      prefix_ = nullptr;
      if(!done) pre.undo(x);
      return done;
    };
    const bool stopped = each_single_move(ns.basis.size(), {1, 2, 3, 4, 6, 8, 12, 16}, consider) ||
                         each_pair_move(ns.basis.size(), {1, 2, 4}, consider);
    return stopped && !joint_budget_spent();              // at the budget: stopped without a move
  }

  // A tentative change of x: (variable, old value); x holds the new values while it is tested.
  struct Change
  {
    std::vector<std::pair<int, double> > old;
    void set(std::vector<double>& y, int var, double value)
    {
      if(y[var] == value) return;
      old.emplace_back(var, y[var]);
      y[var] = value;
    }
    void undo(std::vector<double>& y) const
    {
      for(std::size_t i = old.size(); i-- > 0;) y[old[i].first] = old[i].second;
    }
  };

  // Exact orientations of the faces around the changed sectors: the total gain in orientation
  // (NEGATIVE < ZERO < POSITIVE), or -1 if a face gets worse. `updates` receives the new values.
  // Relaxed (for faces made worse by snapping that strict moves cannot repair): a face may also fall
  // back to its input orientation, e.g. a face that snapping unflipped flips back as in the input;
  // the score is then led by the decrease of the total deficit sum_f max(0, input_f - o_f) (how much
  // the faces are worse than in the input), which never increases, then the gain.
  long orientation_gain(const Change& ch, std::vector<std::pair<int, signed char> >* updates)
  {
    ++stamp;
    long gain = 0, deficit_decrease = 0;
    for(const std::pair<int, double>& v : ch.old) {
      const int s = v.first / 2;
      for(int corner : sector_corners[s]) {
        const int f = cm.face[corner];
        if(face_stamp[f] == stamp) continue;
        face_stamp[f] = stamp;
        const signed char o = static_cast<signed char>(face_orientation(f, x));
        if(o < floor_of(f, CGAL::Orientation(orient_[f]))) return -1;
        gain += o - orient_[f];
        deficit_decrease += (std::max)(0, input_[f] - orient_[f]) - (std::max)(0, input_[f] - o);
        if(updates != nullptr && o != orient_[f]) updates->emplace_back(f, o);
      }
    }
    return relaxed_ ? deficit_decrease * (1L << 20) + gain : gain;   // |gain| <= 2 * (faces around a move) < 2^20
  }

  // the lowest orientation face f may take in a move: its current one; relaxed, its input one if lower
  CGAL::Orientation floor_of(int f, CGAL::Orientation current) const
  {
    return relaxed_ && input_[f] < current ? CGAL::Orientation(input_[f]) : current;
  }

  // every changed value is finite and within `max_move` of the input, and every row of the full
  // system that mentions a changed variable holds exactly
  bool exact_and_bounded(const Change& ch, double max_move) const
  {
    for(const std::pair<int, double>& v : ch.old)
      if(!std::isfinite(x[v.first]) || !(std::fabs(x[v.first] - (*ubar_)[v.first]) <= max_move)) return false;
    for(const std::pair<int, double>& v : ch.old)
      for(int row : var_rows[v.first])
        if(!row_holds_exactly(rows, std::size_t(row), x)) return false;
    return true;
  }

  // Keeps the change (x already holds it) iff it is exact, bounded, makes no face worse and at
  // least one face better; otherwise undoes it. `dry_run`: always undoes, returns the gain.
  long commit_if_better(const Change& ch, double max_move, bool dry_run)
  {
    if(ch.old.empty()) return 0;
    std::vector<std::pair<int, signed char> > updates;
    bool bounded = true;
    for(const std::pair<int, double>& v : ch.old)
      bounded = bounded && std::isfinite(x[v.first]) && std::fabs(x[v.first] - (*ubar_)[v.first]) <= max_move;
    const long gain = bounded ? orientation_gain(ch, dry_run ? nullptr : &updates) : -1;
    if(dry_run || gain <= 0 || !exact_and_bounded(ch, max_move)) { ch.undo(x); return dry_run ? gain : 0; }
    for(const std::pair<int, signed char>& u : updates) orient_[u.first] = u.second;
    return gain;
  }

  // ---- node moves: a few node vertices move together inside the null space of the node system C
  // (Sec. 5.3): d with C_local d = 0, where C_local are the rows of C that mention the moved node
  // sectors (all other sectors stay), computed exactly (local_null_space.h). Cones are fixed
  // points of their transitions and move only together with the other ends of their branches,
  // hence radius 1 (the vertices sharing a row of C). The values of the non-node sectors follow
  // by the propagation of Sec. 5.3.1 (u^- = u_0^- - R^k u_0^+ + R^k u^+, exact integer sums on
  // F_delta). Candidates: each basis vector, then each pair, times +-m grid quanta.

  // vertices of the node system near face f: its node vertices (radius 0), and those sharing a
  // row of C with them (radius 1); their sector variables in `vars`
  bool node_cluster(int f, int radius, std::vector<int>& vars) const
  {
    std::vector<int> vertices;
    for(int i = 0; i < 3; ++i) {
      const int v = st.sector_vertex(cm, face_sector(f, i));
      if(rs.is_node[v] && std::find(vertices.begin(), vertices.end(), v) == vertices.end()) vertices.push_back(v);
    }
    if(vertices.empty()) return false;
    for(int level = 0; level < radius; ++level)
    for(std::size_t i = 0, n_level = vertices.size(); i < n_level; ++i)
      for(int sector : vertex_sectors[vertices[i]])
        for(int c = 0; c < 2; ++c) {
          const int var = 2 * sector + c;
          for(int row : var_node_rows[var]) {
            const Constraint_rows& C = rs.node_rows;
            for(std::size_t e = C.start[std::size_t(row)]; e < C.start[std::size_t(row) + 1]; ++e) {
              const int w = st.sector_vertex(cm, C.col[e] / 2);
              if(std::find(vertices.begin(), vertices.end(), w) == vertices.end()) vertices.push_back(w);
            }
          }
        }
    vars.clear();
    for(int v : vertices)
      for(int sector : vertex_sectors[v]) { vars.push_back(2 * sector); vars.push_back(2 * sector + 1); }
    return vars.size() <= 96;
  }

  // u^- of the pair `in` of the cut branch p from u_0^+, u_0^-, u^+ (Sec. 5.3.1), exactly on F_delta
  bool propagate_pair(const Cut_branch_plan& p, const std::pair<int, int>& in, Change& ch)
  {
    const Quarter_turn R(p.k);
    for(int c = 0; c < 2; ++c) {
      const double v[3] = {x[2 * p.u0_minus + c], x[2 * p.u0_plus + R.col[c]], x[2 * in.first + R.col[c]]};
      if(!grid.contains(v[0]) || !grid.contains(v[1]) || !grid.contains(v[2])) return false;
      const std::int64_t z = grid.to_integer(v[0]) - R.sign[c] * (grid.to_integer(v[1]) - grid.to_integer(v[2]));
      if(z > Fixed_point_grid::max_integer() || -z > Fixed_point_grid::max_integer()) return false;
      ch.set(x, 2 * in.second + c, grid.from_integer(z));
    }
    return true;
  }

  // x += sum_i coef_i basis_i (grid integers) on `vars`, then the propagation; false if a value
  // leaves F_delta (x is then partly changed: undo `ch`)
  bool apply_node_move(const Local_null_space& ns, const std::vector<std::pair<int, long> >& combo, Change& ch)
  {
    const std::vector<int>& vars = ns.vars;
    std::vector<int> js;                         // the variables moved by some vector of the combination, increasing
    for(const std::pair<int, long>& c : combo) js.insert(js.end(), ns.support[c.first].begin(), ns.support[c.first].end());
    std::sort(js.begin(), js.end());
    js.erase(std::unique(js.begin(), js.end()), js.end());
    for(int j : js) {
      long d = 0;
      for(const std::pair<int, long>& c : combo) d += c.second * ns.basis[c.first][j];
      if(d == 0) continue;
      if(!grid.contains(x[vars[j]])) return false;
      const std::int64_t z = grid.to_integer(x[vars[j]]) + d;
      if(z > Fixed_point_grid::max_integer() || -z > Fixed_point_grid::max_integer()) return false;
      ch.set(x, vars[j], grid.from_integer(z));
    }
    const std::size_t n_node_changes = ch.old.size();
    for(std::size_t i = 0; i < n_node_changes; ++i) {
      const int s = ch.old[i].first / 2;
      if(i > 0 && ch.old[i - 1].first / 2 == s) continue;
      for(int b : cut_from[s])
        for(const std::pair<int, int>& in : rs.cut_branches[std::size_t(b)].inner)
          if(!propagate_pair(rs.cut_branches[std::size_t(b)], in, ch)) return false;
      for(int b : align_from[s]) {
        const Align_branch_plan& p = rs.align_branches[std::size_t(b)];
        for(int in : p.inner) ch.set(x, 2 * in + p.component, x[2 * p.u0 + p.component]);
      }
    }
    return true;
  }

  // the node cluster of face f at `radius` and an integer basis of the null space of C on it (computed once)
  const Local_null_space& local_null_space(int f, int radius)
  {
    int& index = null_space_of_[f][radius];
    if(index >= 0) return null_spaces_[std::size_t(index)];
    index = int(null_spaces_.size());
    null_spaces_.emplace_back();
    Local_null_space& ns = null_spaces_.back();
    std::vector<int>& vars = ns.vars;
    if(!node_cluster(f, radius, vars)) return ns;
    // the rows of C that mention the cluster, restricted to its columns
    const Constraint_rows& C = rs.node_rows;
    for(std::size_t j = 0; j < vars.size(); ++j) col_of[vars[j]] = int(j);
    std::vector<int> local_rows;
    for(int var : vars)
      for(int row : var_node_rows[var]) local_rows.push_back(row);
    std::sort(local_rows.begin(), local_rows.end());
    local_rows.erase(std::unique(local_rows.begin(), local_rows.end()), local_rows.end());
    std::vector<long> a(local_rows.size() * vars.size(), 0);
    for(std::size_t i = 0; i < local_rows.size(); ++i)
      for(std::size_t e = C.start[local_rows[i]]; e < C.start[local_rows[i] + 1]; ++e)
        if(col_of[C.col[e]] >= 0) a[i * vars.size() + std::size_t(col_of[C.col[e]])] += C.coef[e];
    for(int var : vars) col_of[var] = -1;
    integer_null_space(local_rows.size(), vars.size(), a, 1L << 16, ns.basis);
    for(const std::vector<long>& b : ns.basis) {
      ns.support.emplace_back();
      for(std::size_t j = 0; j < b.size(); ++j) if(b[j] != 0) ns.support.back().push_back(int(j));
    }
    ns.ok = !ns.basis.empty();
    return ns;
  }

  bool try_node_move(int f, int radius, double max_move)
  {
    const Local_null_space& ns = local_null_space(f, radius);
    if(!ns.ok) return false;
    // the best candidate: largest gain, then the smallest move (the order of the search)
    std::vector<std::pair<int, long> > best;
    long best_gain = 0;
    auto consider = [&](const std::vector<std::pair<int, long> >& combo) {
      Change ch;
      const bool ok = apply_node_move(ns, combo, ch);
      const long gain = ok ? commit_if_better(ch, max_move, true) : (ch.undo(x), -1);
      if(gain > best_gain) { best_gain = gain; best = combo; }
      return false;                                      // try them all
    };
    each_single_move(ns.basis.size(), {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 64, 128}, consider);
    if(best_gain == 0) each_pair_move(ns.basis.size(), {1, 2, 4, 8, 16}, consider);
    if(best_gain == 0) return false;
    Change ch;
    if(!apply_node_move(ns, best, ch)) { ch.undo(x); return false; }
    return commit_if_better(ch, max_move, false) > 0;
  }

  // true iff the constraints force two corners of face f to one UV point, so that the face is
  // degenerate in every exact solution: for sectors s, t of the face, u_s - u_t = 0 (both
  // components, right-hand side 0) is a rational combination of rows (C x = b, b included) of the
  // full system touching s or t and of rows of the node system C (sums of full rows, Eq. 9) near f
  // (radius 2). Example: a cut branch with rotation k != 0 between two vertices with one sector
  // each, such as two cones joined by a lone cut edge, (R^k - I)(u_s - u_t) = 0.
  bool forced_degenerate(int f) const
  {
    if(forced_[f] < 0) forced_[f] = compute_forced_degenerate(f) ? 1 : 0;
    return forced_[f] == 1;
  }

  bool compute_forced_degenerate(int f) const
  {
    std::vector<int> vars;
    node_cluster(f, 2, vars);
    for(int i = 0; i < 3; ++i) { vars.push_back(2 * face_sector(f, i)); vars.push_back(2 * face_sector(f, i) + 1); }
    std::vector<std::pair<const Constraint_rows*, int> > local;
    for(int var : vars) {
      for(int row : var_node_rows[var]) local.emplace_back(&rs.node_rows, row);
      for(int row : var_rows[var]) local.emplace_back(&rows, row);
    }
    std::sort(local.begin(), local.end());
    local.erase(std::unique(local.begin(), local.end()), local.end());
    std::vector<int> cols;
    for(const auto& r : local)
      for(std::size_t e = r.first->start[r.second]; e < r.first->start[r.second + 1]; ++e) cols.push_back(r.first->col[e]);
    for(int i = 0; i < 3; ++i) { cols.push_back(2 * face_sector(f, i)); cols.push_back(2 * face_sector(f, i) + 1); }
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
    if(local.empty() || cols.size() > 256) return false;
    for(int i = 0; i < 3; ++i)
      if(face_sector(f, i) == face_sector(f, (i + 1) % 3)) return true;   // two corners in one sector
    auto column = [&](int var) { return std::size_t(std::lower_bound(cols.begin(), cols.end(), var) - cols.begin()); };
    const std::size_t nc = cols.size() + 1;            // the last column: the right-hand side b
    std::vector<long> a(local.size() * nc, 0);
    for(std::size_t i = 0; i < local.size(); ++i) {
      const Constraint_rows& r = *local[i].first;
      for(std::size_t e = r.start[local[i].second]; e < r.start[local[i].second + 1]; ++e) a[i * nc + column(r.col[e])] += r.coef[e];
      a[i * nc + nc - 1] = r.rhs[std::size_t(local[i].second)];
    }
    const Exact_row_space row_space(local.size(), nc, a);
    for(int i = 0; i < 3; ++i) {
      const int s = face_sector(f, i), t = face_sector(f, (i + 1) % 3);
      bool both = true;
      for(int c = 0; c < 2 && both; ++c) {
        std::vector<long> b(nc, 0);
        b[column(2 * s + c)] = 1;
        b[column(2 * t + c)] = -1;
        both = row_space.contains(b);
      }
      if(both) return true;
    }
    return false;
  }

  // why the faces positive in the input and not at the end could not be repaired
  std::string explain(const std::vector<int>& faces, double max_move) const
  {
    std::size_t forced = 0;
    int other = -1;
    for(int f : faces) {
      if(forced_degenerate(f)) ++forced;
      else if(other < 0) other = f;
    }
    std::ostringstream o;
    o << std::setprecision(3);
    if(forced > 0)
      o << forced << " of them are degenerate in every exact solution: two of their corners are forced to one UV point "
        << "by the constraints (u_s - u_t = 0 is a combination of constraint rows, e.g. two cones joined by a cut branch "
        << "with rotation k != 0: (R^k - I)(u_s - u_t) = 0)";
    if(other >= 0)
      o << (forced > 0 ? "; " : "") << "face " << other << ": no move of its vertices (alone or with the free vertices next "
        << "to them), of their node neighbours in C or of their branches, alone or jointly, within " << max_move / grid.quantum
        << " grid steps keeps every row exact and makes no face worse than now or than in the input"
        << (joint_budget_spent() ? " (joint moves: the search stopped at its budget of " + std::to_string(joint_budget) +
                                 " candidates)" : std::string());
    return o.str();
  }
};

// Repairs flips of `x` (2 values per sector) in place; see the header comment. `input_orientations`,
// `current_orientations`: face_orientations() of ubar and x, if the caller has them. A map with no face to
// repair (none worse than in the input, none negative: most maps) returns before the repair builds its
// indices (on the order of the mesh's own size: half of a clean map's snap time went there).
inline Flip_repair_result repair_flips(const Corner_mesh& cm, const Seam_topology& st, const Reduced_system& rs,
                                       const Constraint_rows& full, const Fixed_point_grid& grid,
                                       const std::vector<double>& ubar, std::vector<double>& x,
                                       const std::vector<signed char>* input_orientations = nullptr,
                                       const std::vector<signed char>* current_orientations = nullptr)
{
  std::vector<signed char> own_input, own_current;
  if(input_orientations == nullptr) { own_input = face_orientations(cm, st, ubar); input_orientations = &own_input; }
  if(current_orientations == nullptr) { own_current = face_orientations(cm, st, x); current_orientations = &own_current; }
  const std::vector<signed char>& input = *input_orientations;
  const std::vector<signed char>& current = *current_orientations;
  bool targets = false;
  for(std::size_t f = 0; f < current.size() && !targets; ++f) targets = is_repair_target(current[f], input[f]);
  if(!targets) {
    Flip_repair_result r;
    r.input = count_orientations(input);
    r.before = r.after = count_orientations(current);
    r.introduced_before = r.introduced_after = count_orientations(current, &input);
    return r;
  }
  Flip_repair fr(cm, st, rs, full, grid, x);
  return fr.run(ubar, input_orientations, current_orientations);
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_FLIP_REPAIR_H
