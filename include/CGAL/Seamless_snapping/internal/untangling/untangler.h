// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_UNTANGLER_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_UNTANGLER_H

// Untangling inside the exact constraint space, in floating point: the UV triangles that are not
// positively oriented are made positive by moving the UVs of the vertices near them along the null space
// of the constraint rows (region_space.h), so that every transition, alignment, integer translation,
// cone position and pin keeps holding (up to rounding; the exact snap follows).
//
// 1. Untangling. The fold-overs are grouped into clusters (faces sharing a vertex); each cluster gets the
//    region of the vertices within k face rings of it (overlapping regions merge). All regions form one
//    problem, each of its independent parts (independent_parts.h) optimized on its own (its own eps, steps
//    and stopping test; see untangle()) on the energy sum area(ref) f_eps(J) of the faces touching them (Garanzha et al.
//    2021, untangling_energy.h; references: reference_shapes.h; faces proven non-positive in every
//    solution, forced_folds.h, are left out) by Newton's method on the reduced variables (element
//    Hessians projected onto the PSD cone, N^T H N factored by a sparse LDL^T with one symbolic analysis, once
//    per eps: the next Newton steps of the same eps reuse that factorization with the new gradient, which makes
//    the untangling 1.1-2x faster on the shared maps with the same fold-overs left, bench_snap --untangle; Armijo
//    backtracking) and the paper's continuation in eps: after each minimization, with E_prev / E the energy
//    before / after it and D_min the smallest det J, sigma = max(1 - E / E_prev, 0.3) (the paper has 0.1; see
//    Untangle_options::sigma_min),
//    mu = (1 - sigma) chi(D_min, eps), eps <- 2 sqrt(mu (mu - D_min)) while D_min < mu, else 1e-9; done
//    when D_min > 0 and E changes by less than a relative 1e-5, given up when the number of non-positive
//    faces has not dropped for `stall` updates. A region's result is kept if it has fewer non-positive
//    faces than before (or as many, less inverted, where it had any); the clusters still folded try the next k (1, 2, 4,
//    8, 16; up to 8 in the second sweep, Untangle_options::wound_rings), from the map so far.
// 2. Minimal-change polish. The eps continuation lets the regions drift (eps ~ 1 favours other shapes
//    than the references), so every region made fold-free is then pulled back towards the exact snap of
//    the input: minimize sum_l (x_l - target_l)^2 / h^2 + lambda sum area f_eps(J) / mean area, with a tiny
//    eps (a barrier: f grows like 1 / det J), lambda = 1e-3, over the moved vertices and 1 ring around
//    them (Untangle_options::polish_rings), each independent part of that region set on its own (independent_parts.h: its own steps and
//    stopping test; the 302K-face bunny's polish 2.0 -> 1.2 s in one run), by Newton steps whose line search never lets a
//    face go below det J = polish_min_det (Smith and
//    Schaefer's flip-free step bound, shifted): every iterate stays fold-free, and the change shrinks to
//    what keeps the faces positive with a margin (this follows the study in ../research/untangling_study.md);
//    until a step lowers the energy by less than a relative Untangle_options::polish_tolerance. The
//    vertices of the faces not positive, or wound, or below polish_min_det at the start stay where they are
//    (with the bound at 0, the dragon's faces at det J ~ 1e-12 held every polish step below 1e-7 of a grid
//    cell: 23-40 Newton steps that changed the map by nothing measurable). Every
//    other step reuses the previous factorization (the proximity part of the Hessian is constant): the
//    polish 1.3-1.6x faster on the shared maps, the same max change, RMS within 7 %, bench_snap --untangle.
// Faces far from the fold-overs keep their UVs bit for bit; the result is a floating-point map, never
// claimed exact: the pipeline snaps it exactly and checks every triangle exactly afterwards.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>
#include <CGAL/Seamless_snapping/internal/timing.h>
#include <CGAL/Seamless_snapping/internal/untangling/independent_parts.h>
#include <CGAL/Seamless_snapping/internal/untangling/reference_shapes.h>
#include <CGAL/Seamless_snapping/internal/untangling/region_problem.h>
#include <CGAL/Seamless_snapping/internal/untangling/region_space.h>
#include <CGAL/Seamless_snapping/internal/untangling/untangling_energy.h>
#include <CGAL/Seamless_snapping/internal/untangling/vertex_windings.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

struct Untangle_options
{
  std::vector<int> rings = {1, 2, 4, 8, 16};  // region sizes tried in turn, per cluster of fold-overs
  std::vector<int> wound_rings = {1, 2, 4, 8};// the same in the second sweep (also wound vertices). k = 16 there changed
                                              // no count on any map where it ran (duck_qc_8 default and IGM, the 302K
                                              // bunny of ../shared/large) and cost 0.1 / 0.43 / 0.8-1.2 s. Without the
                                              // second sweep (measured 2026-11-29): fandisk (default mode) 2 wound
                                              // vertices left instead of 0, duck_miq_8 8 instead of 0, duck_qc_8 12
                                              // instead of 4. Starting it at eps0 = 100 or 1000 (nearly the Dirichlet
                                              // energy: a harmonic start) or from a least-squares fit of the Jacobians
                                              // to the input's rotations did not remove duck_qc_8's 4
  int max_outer = 300;                        // eps updates per attempt
  int max_newton = 3;                         // Newton steps per eps
  int stall = 20;                             // eps updates without fewer non-positive faces before an attempt gives up
  double eps0 = 1;                            // the first eps (J is relative to the reference: D ~ 1)
  double sigma_min = 0.3;                     // floor of sigma in the eps update (the paper: 0.1; 0.3 halves the Newton
                                              // steps on the shared maps with as good or better results, bench_snap --untangle)
  bool polish = true;                         // step 2
  int polish_rings = 1;                       // rings of vertices around the moved ones that the polish may move too. Against
                                              // 2 (the 5 folded maps of ../shared/data x {--untangle, IGM, IGM with pairs merged /
                                              // separated / both}, seamless_snap reports, one run each): the same fold-overs,
                                              // zero-area triangles and wound vertices, max / RMS change equal to 3 digits
                                              // (duck_miq_8's max 0.2229 -> 0.2223 cells), 10-31 % fewer sectors moved (duck_miq_8
                                              // 2738 -> 2103, the 302K bunny of ../shared/large 32735 -> 24192), the untangling
                                              // faster in 23 of the 25 runs (the bunny 2.5-3.1 -> 1.7-1.8 s in two runs each);
                                              // but the dragon (full-seamless, default mode) with 3 negative triangles instead of
                                              // 2 and 41 wound vertices instead of 40: face 8353, nearly degenerate in the input
                                              // (two of its corners almost on one point at (-44, 24)), whose orientation after
                                              // the snap follows moves far below a grid cell.
                                              // 0: the RMS change up to 9 % larger (duck_miq_8, duck_qc_8 default mode)
  double polish_lambda = 1e-3;
  int polish_iterations = 50;
  double polish_tolerance = 1e-4;             // the polish stops at a relative energy decrease below this (against
                                              // 1e-8: the same max / RMS change to 4 digits on the shared maps but
                                              // fandisk's 0.1710 -> 0.1709 cells, untangling 10-20 % faster)
  double polish_min_det = 1e-6;               // det J (area / reference area) that the polish keeps every face above;
                                              // the vertices of faces below it at the start stay. Against 0 (the plain
                                              // flip-free bound), the dragon (full-seamless): IGM change 1.87 / 0.107 ->
                                              // 1.05 / 0.045 cells (max / RMS), same defects; default mode RMS 0.678 ->
                                              // 0.539, 4 more wound vertices at corners of forced zero-area triangles;
                                              // the other shared maps the same to 4 digits but duck_qc_8 IGM's RMS
                                              // 0.0271 -> 0.0257 (bench_snap --untangle)
  double work_per_face = 400;                 // budget of the untangling (step 1): face evaluations (energy or
                                              // derivatives of one face) per face of the mesh; deterministic
  unsigned threads = 1;                       // >= 2: two halves of the independent parts at once (independent_parts.h);
                                              // the same results
};

struct Untangle_statistics
{
  int rings = 0;                         // largest k tried
  std::size_t attempts = 0;              // optimizations of step 1 (one per k and sweep)
  std::size_t region_vertices = 0;       // of the largest region
  std::size_t dimension = 0;             // of the largest null space
  std::size_t outer_iterations = 0, newton_steps = 0, polish_steps = 0;
  std::size_t not_positive = 0;          // faces not positive at the end (floating point; excluded faces not counted)
  double work = 0;                       // face evaluations of step 1
  double polish_ms = 0;                  // wall-clock time of step 2
  bool budget_spent = false;             // step 1 stopped at its budget (Untangle_options::work_per_face)
};

class Untangler
{
public:
  // `target`: per vertex the angle sums (quarter turns) a locally injective map has there (vertex_windings.h);
  // valence 0 where the untangling should not try to reach it
  Untangler(const Corner_mesh& cm, const Seam_topology& st, const Constraint_rows& rows, const Face_corners& fc,
            const std::vector<Reference_triangle>& refs, const std::vector<char>& excluded, const Target_valences& target)
    : cm_(cm), st_(st), rows_(rows), fc_(fc), refs_(refs), excluded_(excluded), target_(target),
      incidence_(rows, 2 * std::size_t(st.n_sectors))
  {}

  // Untangles x (2 values per sector, an exact solution of the rows on input) in place (see the header).
  // Two sweeps over the ring sizes: the first aims at the non-positive faces only, the second also at the
  // vertices wound other than their valence; a region's result is kept when it has fewer non-positive faces,
  // or as many and fewer faces around wrongly wound vertices, or both as many and a larger smallest det J where it
  // had non-positive faces (a region of wound vertices only, whose windings stay, keeps its UVs: on the 5 folded maps
  // of ../shared/data x 5 modes the same defects but on the dragon in default mode face 8353, now positive, and one
  // wound vertex fewer: a face nearly degenerate in the input (two of its corners almost on one point), whose
  // orientation after the snap follows moves far below a grid cell; the
  // change and the sectors moved the same or smaller, e.g. the dragon's 11430 -> 10366 sectors
  // and max / RMS 1.39 / 0.050 -> 1.39 / 0.046 cells, its IGM with pairs merged 1.28 / 0.051 -> 1.16 / 0.048)
  // `turns`: the angle sums of x per vertex (vertex_quarter_turns()), where the caller has them
  Status run(std::vector<double>& x, const Untangle_options& opt, Untangle_statistics& stats, std::string& message,
             const std::vector<int>* turns = nullptr)
  {
    stats = Untangle_statistics();
    budget_ = opt.work_per_face * double(fc_.halfedge.size());
    const std::vector<double> target = x;
    Map_state state = map_state(x, turns);
    for(int sweep = 0; sweep < 2; ++sweep) {
      for(int k : sweep == 0 ? opt.rings : opt.wound_rings) {
        if(stats.work > budget_) { stats.budget_spent = true; break; }
        std::vector<int> targets;
        for(std::size_t f = 0; f < state.face.size(); ++f)
          if(state.face[f] == NON_POSITIVE || (sweep == 1 && state.face[f] == WOUND)) targets.push_back(int(f));
        if(targets.empty()) break;
        stats.rings = (std::max)(stats.rings, k);
        Status s = attempt(rings_around(targets, k, nullptr), state, x, opt, stats, message);
        if(s != SUCCESS) return s;
      }
    }
    std::vector<int> bad;
    for(std::size_t f = 0; f < state.face.size(); ++f) if(state.face[f] != GOOD) bad.push_back(int(f));
    if(opt.polish) {
      const std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
      Status s = polish(x, target, bad, opt, stats, message);
      stats.polish_ms = ms_since(t);
      if(s != SUCCESS) return s;
    }
    stats.not_positive = 0;
    for(std::size_t f = 0; f < fc_.halfedge.size(); ++f) stats.not_positive += !excluded_[f] && !(face_det(int(f), x) > 0) ? 1 : 0;
    return SUCCESS;
  }

private:
  enum Face_state : signed char { GOOD = 0, WOUND = 1, NON_POSITIVE = 2 };

  // a map's angle sums per vertex and per face its state: NON_POSITIVE (det J <= 0 in floating point, as the
  // energy sees it; excluded faces are GOOD), else WOUND if a corner's vertex is wound other than its valence,
  // else GOOD
  struct Map_state
  {
    std::vector<int> turns;
    std::vector<signed char> face;
  };

  signed char face_state(std::size_t f, const std::vector<double>& x, const std::vector<int>& turns) const
  {
    if(excluded_[f]) return GOOD;
    if(!(face_det(int(f), x) > 0)) return NON_POSITIVE;
    for(int h : fc_.halfedge[f]) {
      const std::size_t v = std::size_t(cm_.target[h]);
      if(target_.wound(v, turns[v])) return WOUND;
    }
    return GOOD;
  }

  Map_state map_state(const std::vector<double>& x, const std::vector<int>* turns) const
  {
    Map_state m;
    m.turns = turns != nullptr ? *turns : vertex_quarter_turns(cm_, st_, x, face_orientations(cm_, st_, x));
    m.face.resize(fc_.halfedge.size());
    for(std::size_t f = 0; f < fc_.halfedge.size(); ++f) m.face[f] = face_state(f, x, m.turns);
    return m;
  }

  // The state of the map y, which differs from the map of `base` at most in the sectors of the vertices `moved`
  // (the same as map_state(y), computed only where it can differ): the angle sums of the vertices of the faces
  // around the moved vertices, and the states of the faces around those.
  Map_state updated_state(const Map_state& base, const std::vector<double>& y, const std::vector<int>& moved) const
  {
    Map_state m = base;
    std::vector<char> seen(std::size_t(cm_.n_vertices), 0), done(fc_.halfedge.size(), 0), was_moved = seen;
    std::vector<int> changed, corners;
    for(int v : moved) {
      if(was_moved[std::size_t(v)]) continue;                  // `moved` repeats a vertex per variable of its sectors
      was_moved[std::size_t(v)] = 1;
      for(int f : fc_.vertex_faces[v])
        for(int h : fc_.halfedge[std::size_t(f)])
          if(!seen[std::size_t(cm_.target[h])]) { seen[std::size_t(cm_.target[h])] = 1; changed.push_back(cm_.target[h]); }
    }
    for(int w : changed) {
      corners.clear();
      for(int f : fc_.vertex_faces[w])
        for(int h : fc_.halfedge[std::size_t(f)]) if(cm_.target[h] == w) corners.push_back(h);
      std::sort(corners.begin(), corners.end());
      m.turns[std::size_t(w)] = vertex_quarter_turns_at(cm_, st_, y, w, corners);
    }
    for(int w : changed)
      for(int g : fc_.vertex_faces[w]) {
        const std::size_t f = std::size_t(g);
        if(!done[f]) { done[f] = 1; m.face[f] = face_state(f, y, m.turns); }
      }
    return m;
  }

  // optimizes the regions from x (state `before`) and keeps each region's result if it is better; `before`
  // becomes the state of the new x
  Status attempt(const std::vector<std::vector<int> >& regions, Map_state& before, std::vector<double>& x,
                 const Untangle_options& opt, Untangle_statistics& stats, std::string& message)
  {
    Region_problem problem;
    Status s = build(problem, regions, x, nullptr, stats, message);
    if(s != SUCCESS) return s;
    ++stats.attempts;
    std::vector<double> w(problem.dimension(), 0.);
    std::vector<std::size_t> bad_before, unused;
    std::vector<double> det_before, det_after;
    problem.region_state(w, regions.size(), bad_before, det_before);
    untangle(problem, opt, w, stats);
    problem.region_state(w, regions.size(), unused, det_after);
    std::vector<double> y = x;
    std::vector<int> moved;
    for(std::size_t l = 0; l < problem.vars.size(); ++l) {
      y[std::size_t(problem.vars[l])] += problem.displacement(l, w);
      moved.push_back(st_.sector_vertex(cm_, problem.vars[l] / 2));
    }
    const Map_state after = updated_state(before, y, moved);
    std::vector<long> fewer_non_positive(regions.size(), 0), fewer_wound(regions.size(), 0);
    for(const Region_problem::Face& e : problem.faces) {
      if(e.region < 0) continue;
      const std::size_t f = std::size_t(e.face), r = std::size_t(e.region);
      fewer_non_positive[r] += long(before.face[f] == NON_POSITIVE) - long(after.face[f] == NON_POSITIVE);
      fewer_wound[r] += long(before.face[f] == WOUND) - long(after.face[f] == WOUND);
    }
    std::vector<int> kept;
    for(std::size_t l = 0; l < problem.vars.size(); ++l) {
      const std::size_t r = std::size_t(problem.var_region[l]);
      const bool better = fewer_non_positive[r] > 0 ||
                          (fewer_non_positive[r] == 0 && (fewer_wound[r] > 0 ||
                                                          (fewer_wound[r] == 0 && bad_before[r] > 0 && det_after[r] > det_before[r])));
      if(better) { x[std::size_t(problem.vars[l])] = y[std::size_t(problem.vars[l])]; kept.push_back(moved[l]); }
    }
    before = updated_state(before, x, kept);
    return SUCCESS;
  }

  double face_det(int f, const std::vector<double>& x) const
  {
    double p[3][2];
    for(int m = 0; m < 3; ++m) {
      const std::size_t s = std::size_t(st_.sector_of[fc_.halfedge[std::size_t(f)][m]]);
      p[m][0] = x[2 * s];
      p[m][1] = x[2 * s + 1];
    }
    return untangling_determinant(refs_[std::size_t(f)].jacobian(p));
  }

  Status build(Region_problem& problem, const std::vector<std::vector<int> >& regions, const std::vector<double>& x,
               const std::vector<double>* target, Untangle_statistics& stats, std::string& message) const
  {
    Status s = problem.build(cm_, st_, rows_, incidence_, fc_, refs_, excluded_, regions, x, target, message);
    if(s != SUCCESS) { message = "untangling: null space of the region's constraint rows: " + message; return s; }
    stats.dimension = (std::max)(stats.dimension, problem.dimension());
    for(const std::vector<int>& r : regions) stats.region_vertices = (std::max)(stats.region_vertices, r.size());
    return SUCCESS;
  }

  // The vertex sets of the regions: k face rings around each cluster of `faces`, overlapping ones merged.
  // Vertices with `blocked` set are not entered (they stay fixed).
  std::vector<std::vector<int> > rings_around(const std::vector<int>& faces, int k, const std::vector<char>* blocked) const
  {
    std::vector<int> owner(std::size_t(cm_.n_vertices), -1);   // the seed face (index in `faces`) that reached a vertex
    Union_find uf(int(faces.size()));
    std::vector<std::vector<int> > fronts(faces.size());
    auto reach = [&](int v, std::size_t i, std::vector<int>& front) {
      if(blocked != nullptr && (*blocked)[std::size_t(v)]) return;
      if(owner[std::size_t(v)] < 0) { owner[std::size_t(v)] = int(i); front.push_back(v); }
      else uf.unite(owner[std::size_t(v)], int(i));
    };
    for(std::size_t i = 0; i < faces.size(); ++i)
      for(int h : fc_.halfedge[std::size_t(faces[i])]) reach(cm_.target[h], i, fronts[i]);
    for(int ring = 0; ring < k; ++ring)
      for(std::size_t i = 0; i < faces.size(); ++i) {
        std::vector<int> next;
        for(int v : fronts[i])
          for(int f : fc_.vertex_faces[v])
            for(int h : fc_.halfedge[std::size_t(f)]) reach(cm_.target[h], i, next);
        fronts[i].swap(next);
      }
    std::vector<int> index(faces.size(), -1);
    std::vector<std::vector<int> > out;
    for(int v = 0; v < cm_.n_vertices; ++v) {
      if(owner[std::size_t(v)] < 0) continue;
      const std::size_t r = std::size_t(uf.find(owner[std::size_t(v)]));
      if(index[r] < 0) { index[r] = int(out.size()); out.emplace_back(); }
      out[std::size_t(index[r])].push_back(v);
    }
    return out;
  }

  // 1. Newton's method with the eps continuation, per independent part (independent_parts.h): each part has its
  // own eps, steps and stopping test, and gives up when neither it nor the whole problem has had fewer non-positive
  // faces for `stall` updates (a part giving up on its own progress alone left duck_qc_8, IGM, with 12 negative
  // triangles instead of 2). Against one eps and one step for all regions (bench_snap --untangle): the 302K-face
  // bunny's untangling 4.6-5.0 -> 3.2-4.0 s with 16 wound vertices left instead of 18; the dragon (full-seamless,
  // default mode) with a change of max 2.9 / RMS 0.083 grid cells instead of 12.8 / 0.54, 52 wound vertices instead
  // of 64; duck_qc_8 (default) 4 wound vertices instead of 2, its IGM 30 % slower; the other shared maps the same
  // defects (the manual's untangling table)
  void untangle(Region_problem& p, const Untangle_options& opt, std::vector<double>& w, Untangle_statistics& stats) const
  {
    if(p.dimension() == 0 || p.faces.empty()) return;
    Independent_parts parts(p, opt.threads);
    const std::size_t n = std::size_t(parts.n);
    std::vector<char> active(n, 1);
    std::vector<double> eps(n, opt.eps0), E_prev, D, E, slope, t;
    std::vector<std::size_t> bad, last_bad(n, 0), fewest_bad(n, p.faces.size() + 1);
    std::vector<int> last_progress(n, 0);
    std::size_t fewest_total = p.faces.size() + 1;
    int last_total = 0;
    Eigen::VectorXd d;
    parts.values(p, w, eps, 0, active, E_prev, D);
    for(int outer = 0; outer < opt.max_outer && parts.any(active); ++outer) {
      if(stats.work > budget_) { stats.budget_spent = true; break; }
      ++stats.outer_iterations;
      E = E_prev;
      std::vector<char> stepping = active;
      for(int it = 0; it < opt.max_newton && parts.any(stepping); ++it) {
        ++stats.newton_steps;
        stats.work += parts.work(stepping);
        parts.newton_directions(p, w, eps, 0, it == 0, stepping, d, slope);
        t.assign(n, 1.);
        stats.work += parts.line_search(p, w, d, slope, t, eps, 0, 1e-9, stepping, E, D);
      }
      // D is at w (the line search's for the parts that moved, else that of E_prev's pass); the faces not positive at
      // w are counted only in the parts with D <= 0 (none elsewhere)
      std::vector<char> folded(n, 0);
      for(std::size_t c = 0; c < n; ++c) folded[c] = active[c] && D[c] <= 0;
      std::vector<double> E_unused, D_unused;
      if(parts.any(folded)) parts.values(p, w, eps, 0, folded, E_unused, D_unused, &bad);
      else bad.assign(n, 0);
      std::size_t total_bad = 0;                             // of all parts (those stopped: when they stopped)
      for(std::size_t c = 0; c < n; ++c) {
        if(active[c]) last_bad[c] = folded[c] ? bad[c] : 0;
        total_bad += last_bad[c];
      }
      if(total_bad < fewest_total) { fewest_total = total_bad; last_total = outer; }
      for(std::size_t c = 0; c < n; ++c) {
        if(!active[c]) continue;
        const double sigma = (std::max)(1 - E[c] / E_prev[c], opt.sigma_min);
        const double mu = (1 - sigma) * untangling_chi(D[c], eps[c]);
        const bool done = D[c] > 0 && std::fabs(E_prev[c] - E[c]) <= 1e-5 * std::fabs(E[c]);
        eps[c] = D[c] < mu ? (std::max)(1e-9, 2 * std::sqrt(mu * (mu - D[c]))) : 1e-9;
        if(done) active[c] = 0;
        else if(D[c] <= 0) {                                    // stalled: the region is too small for a fold-free map
          if(bad[c] < fewest_bad[c]) { fewest_bad[c] = bad[c]; last_progress[c] = outer; }
          else if(outer - last_progress[c] >= opt.stall && outer - last_total >= opt.stall) active[c] = 0;
        }
      }
      parts.values(p, w, eps, 0, active, E_prev, D);
    }
  }

  // 2. the minimal-change polish of the fold-free regions around the vertices that moved
  Status polish(std::vector<double>& x, const std::vector<double>& target, const std::vector<int>& bad,
                const Untangle_options& opt, Untangle_statistics& stats, std::string& message) const
  {
    std::vector<char> blocked(std::size_t(cm_.n_vertices), 0);   // vertices of faces still bad or nearly degenerate stay
    auto block = [&](std::size_t f) { for(int h : fc_.halfedge[f]) blocked[std::size_t(cm_.target[h])] = 1; };
    for(int f : bad) block(std::size_t(f));
    for(std::size_t f = 0; f < fc_.halfedge.size(); ++f)
      if(!excluded_[f] && !(face_det(int(f), x) >= opt.polish_min_det)) block(f);
    std::vector<int> seeds;                                      // faces with a moved corner
    for(std::size_t f = 0; f < fc_.halfedge.size(); ++f)
      for(int h : fc_.halfedge[f]) {
        const std::size_t s = std::size_t(st_.sector_of[h]);
        if(!blocked[std::size_t(cm_.target[h])] && (x[2 * s] != target[2 * s] || x[2 * s + 1] != target[2 * s + 1])) {
          seeds.push_back(int(f));
          break;
        }
      }
    if(seeds.empty()) return SUCCESS;
    const std::vector<std::vector<int> > regions = rings_around(seeds, opt.polish_rings, &blocked);
    Region_problem p;
    Status s = build(p, regions, x, &target, stats, message);
    if(s != SUCCESS || p.dimension() == 0) return s;
    double area = 0;
    for(const Region_problem::Face& e : p.faces) area += e.area;
    const double lambda = opt.polish_lambda * double(p.faces.size()) / area;   // per unit of mean area
    std::vector<double> w(p.dimension(), 0.);
    // the energy is lambda-weighted f (barrier) + proximity; group_values() weighs proximity, so scale by 1 / lambda
    const std::vector<double> eps(1, 1e-12);
    const double weight = 1 / lambda;
    Independent_parts parts(p, opt.threads);                                  // each part steps and stops on its own
    std::vector<char> active(std::size_t(parts.n), 1);
    std::vector<double> E, D, slope, t;
    Eigen::VectorXd d;
    parts.values(p, w, eps, weight, active, E, D);
    for(int c = 0; c < parts.n; ++c) active[std::size_t(c)] = D[std::size_t(c)] > 0;   // not fold-free: stays
    for(int it = 0; it < opt.polish_iterations && parts.any(active); ++it) {
      ++stats.polish_steps;
      parts.newton_directions(p, w, eps, weight, it % 2 == 0, active, d, slope);   // odd steps: the last factorizations
      t.assign(std::size_t(parts.n), HUGE_VAL);
      parts.positive_steps(p, w, d, opt.polish_min_det, active, t);
      for(double& tc : t) tc = (std::min)(1., 0.8 * tc);
      parts.line_search(p, w, d, slope, t, eps, weight, opt.polish_tolerance, active, E, D);
    }
    for(std::size_t l = 0; l < p.vars.size(); ++l) x[std::size_t(p.vars[l])] += p.displacement(l, w);
    return SUCCESS;
  }

  const Corner_mesh& cm_;
  const Seam_topology& st_;
  const Constraint_rows& rows_;
  const Face_corners& fc_;
  const std::vector<Reference_triangle>& refs_;
  const std::vector<char>& excluded_;
  const Target_valences& target_;
  Variable_rows incidence_;
  double budget_ = 0;                                          // face evaluations of step 1 (run())
};

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_UNTANGLER_H
