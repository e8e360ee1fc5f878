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

// Flip repair after snapping (Sec. 5.4, Sec. 6): a UV triangle whose orientation became negative
// is fixed "by parametrically moving one of the vertices of the inverted triangle into the kernel
// of its 1-ring", i.e. into the intersection of the half-planes spanned by the link edges of the
// vertex, while every constraint row keeps holding exactly.
//
// A move displaces the sectors of one *move group* by one displacement t:
//   free sector      a sector in no row of the full system (no cut edge, no align edge): x_s += t,
//                    t in R^2, any double (no row mentions it);
//   cut branch       the two sectors (u^+, u^-) of a non-node vertex inside a cut branch with
//                    rotation k (Sec. 5.3): u^+ += t, u^- += R^k t. Both transition rows of the
//                    vertex, R^k (u_i^+ - u_{i+1}^+) - (u_i^- - u_{i+1}^-) = 0, keep holding since
//                    R^k t - R^k t = 0; t is rounded to the grid F_delta so that the sums stay exact;
//   align branch     the sector of a non-node vertex inside an align branch with aligned component
//                    c: only component 1 - c moves (x_s += s e_{1-c}), the constant one stays;
//   node sectors     and every other sector: fixed.
// The corners of a group form its fan (for a cut-branch vertex: one fan per side, each in its own
// chart). For a corner q of the fan and the other two corners a, b of its face (counter-clockwise),
// the face stays positive iff orient(q + M t, a, b) > 0 (M = I or R^k), a half-plane in t:
//   (M^T n) . t > -orient(q, a, b),   n = (a_v - b_v, b_u - a_u)   (n is the left normal of a -> b).
// The kernel is clipped in doubles (a convex polygon, or an interval for align groups). Candidates
// are the points of the kernel, shrunk by a growing margin, closest to t = 0 (the smallest move that
// works; the last one is the centroid of the smallest non-empty shrunk kernel). Each candidate is
// only accepted after exact tests on the doubles that would be stored:
//   - CGAL::orientation (exact predicate) on every face of the group's fans: a positive face stays
//     positive, a degenerate one does not become negative, and the number of negative faces drops;
//   - every row of the full system that mentions a changed variable evaluates to zero exactly.
// So a move never adds a flip nor breaks a constraint; the number of flips decreases monotonically.
// Flips introduced by snapping are repaired first, then flips already present in the input.
// Bound: every moved coordinate stays within max_i |x_i - ubar_i| (the largest change made by
// snapping) of its input value, so the repair never increases the maximal change. (Without it,
// the dragon of the shared data gets a few more of its introduced flips repaired, but by moves of
// up to 1% of the UV diagonal in regions that are folded in the input; 16 times the bound repairs
// nothing more there than the bound itself.)

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/exact_uv_check.h>
#include <CGAL/Seamless_snapping/internal/projection/fixed_point_grid.h>
#include <CGAL/Seamless_snapping/internal/surface/reduced_system.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mpzf.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

struct Flip_repair_result
{
  std::size_t flips_input = 0;          // negative faces of ubar
  std::size_t flips_before = 0;         // negative faces of x on entry (after snapping)
  std::size_t flips_after = 0;          // negative faces of x on exit
  std::size_t introduced_before = 0;    // negative on entry, not in the input
  std::size_t unrepaired = 0;           // negative on exit, not in the input
  std::size_t moves = 0;                // accepted moves
  std::vector<int> unrepaired_faces;    // face indices (Corner_mesh numbering), ascending
};

class Flip_repair
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;

  struct Member { int sector; int k; };             // sector moves by R^k t (t in the group's parameter space)
  struct Group
  {
    int kind = 0;                                  // 0 free, 1 cut branch, 2 align branch
    int n = 0;
    Member m[2];
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
  std::vector<std::size_t> sc_start; std::vector<int> sc_corner;   // sector -> its corners (CSR)
  std::vector<std::size_t> vr_start; std::vector<int> vr_row;      // variable -> rows (CSR)
  std::vector<int> group_of;                       // per sector: group index, -1 = fixed
  std::vector<Group> groups;

public:
  Flip_repair(const Corner_mesh& cm_, const Seam_topology& st_, const Reduced_system& rs,
              const Constraint_rows& full, const Fixed_point_grid& grid_, std::vector<double>& x_)
    : cm(cm_), st(st_), rows(full), grid(grid_), x(x_)
  {
    const int ns = st.n_sectors;
    face_corner.assign(cm.n_faces, -1);
    std::vector<std::size_t> count(ns + 1, 0);
    for(int h = 0; h < cm.n_halfedges; ++h) {
      if(cm.is_border_halfedge(h)) continue;
      if(face_corner[cm.face[h]] < 0) face_corner[cm.face[h]] = h;
      ++count[st.sector_of[h] + 1];
    }
    sc_start.assign(ns + 1, 0);
    for(int s = 0; s < ns; ++s) sc_start[s + 1] = sc_start[s] + count[s + 1];
    sc_corner.assign(sc_start[ns], -1);
    std::vector<std::size_t> fill(sc_start.begin(), sc_start.end() - 1);
    for(int h = 0; h < cm.n_halfedges; ++h)
      if(!cm.is_border_halfedge(h)) sc_corner[fill[st.sector_of[h]]++] = h;

    const std::size_t nv = 2 * std::size_t(ns);
    vr_start.assign(nv + 1, 0);
    for(int c : rows.col) ++vr_start[c + 1];
    for(std::size_t v = 0; v < nv; ++v) vr_start[v + 1] += vr_start[v];
    vr_row.assign(vr_start[nv], -1);
    std::vector<std::size_t> vfill(vr_start.begin(), vr_start.end() - 1);
    for(std::size_t i = 0; i < rows.size(); ++i)
      for(std::size_t k = rows.start[i]; k < rows.start[i + 1]; ++k) vr_row[vfill[rows.col[k]]++] = int(i);

    // move groups: the inner sectors of the branches, then the sectors in no row. A sector that
    // would belong to two groups (not expected) stays fixed, and so do its partners.
    std::vector<Group> candidates;
    for(const Cut_branch_plan& p : rs.cut_branches)
      for(const std::pair<int, int>& s : p.inner) {
        Group g; g.kind = 1; g.n = 2; g.m[0] = Member{s.first, 0}; g.m[1] = Member{s.second, p.k};
        candidates.push_back(g);
      }
    for(const Align_branch_plan& p : rs.align_branches)
      for(int s : p.inner) {
        Group g; g.kind = 2; g.n = 1; g.m[0] = Member{s, 0}; g.axis = 1 - p.component;
        candidates.push_back(g);
      }
    std::vector<int> uses(ns, 0);
    for(const Group& g : candidates) for(int i = 0; i < g.n; ++i) ++uses[g.m[i].sector];
    group_of.assign(ns, -1);
    for(const Group& g : candidates) {
      bool unique = true;
      for(int i = 0; i < g.n; ++i) unique = unique && uses[g.m[i].sector] == 1;
      if(!unique) continue;
      for(int i = 0; i < g.n; ++i) group_of[g.m[i].sector] = int(groups.size());
      groups.push_back(g);
    }
    for(int s = 0; s < ns; ++s) {
      if(uses[s] > 0 || vr_start[2 * s + 2] != vr_start[2 * s]) continue;   // on a branch, or in some row
      Group g; g.kind = 0; g.n = 1; g.m[0] = Member{s, 0};
      group_of[s] = int(groups.size());
      groups.push_back(g);
    }
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

  // Runs the repair on x. `ubar`: the input (for the input flips and the move bound).
  Flip_repair_result run(const std::vector<double>& ubar)
  {
    Flip_repair_result r;
    std::vector<char> input_flip(cm.n_faces, 0);
    std::vector<int> introduced, inherited;
    for(int f = 0; f < cm.n_faces; ++f) {
      input_flip[f] = face_orientation(f, ubar) == CGAL::NEGATIVE;
      r.flips_input += input_flip[f];
      if(face_orientation(f, x) != CGAL::NEGATIVE) continue;
      ++r.flips_before;
      (input_flip[f] ? inherited : introduced).push_back(f);
    }
    r.introduced_before = introduced.size();
    ubar_ = &ubar;
    double snap_change = 0;
    for(std::size_t i = 0; i < x.size(); ++i) snap_change = (std::max)(snap_change, std::fabs(x[i] - ubar[i]));
    const double limit = snap_change;
    for(int pass = 0; pass < 4; ++pass) {
      bool progress = false;
      for(int f : introduced) progress = try_face(f, limit, r) || progress;
      for(int f : inherited) progress = try_face(f, limit, r) || progress;
      if(!progress) break;
    }
    for(int f = 0; f < cm.n_faces; ++f) {
      if(face_orientation(f, x) != CGAL::NEGATIVE) continue;
      ++r.flips_after;
      if(!input_flip[f]) { ++r.unrepaired; r.unrepaired_faces.push_back(f); }
    }
    return r;
  }

private:
  bool try_face(int f, double max_move, Flip_repair_result& r)
  {
    if(face_orientation(f, x) != CGAL::NEGATIVE) return false;
    // prefer groups that move freely, then align, then cut-branch groups
    int order[3] = {-1, -1, -1};
    for(int i = 0; i < 3; ++i) order[i] = group_of[face_sector(f, i)];
    std::stable_sort(order, order + 3, [&](int a, int b) { return rank(a) < rank(b); });
    for(int g : order) {
      if(g < 0) continue;
      if(try_move(groups[g], f, max_move)) { ++r.moves; return true; }
    }
    return false;
  }

  int rank(int g) const { return g < 0 ? 3 : (groups[g].kind == 0 ? 0 : (groups[g].kind == 2 ? 1 : 2)); }

  // the faces of the group's fans, with their moved corner
  void group_faces(const Group& g, std::vector<int>& corners, std::vector<int>& member) const
  {
    corners.clear(); member.clear();
    for(int i = 0; i < g.n; ++i)
      for(std::size_t k = sc_start[g.m[i].sector]; k < sc_start[g.m[i].sector + 1]; ++k) {
        corners.push_back(sc_corner[k]);
        member.push_back(i);
      }
  }

  static double exact_orient_to_double(double qx, double qy, double ax, double ay, double bx, double by)
  {
    const CGAL::Mpzf o = (CGAL::Mpzf(ax) - CGAL::Mpzf(qx)) * (CGAL::Mpzf(by) - CGAL::Mpzf(qy)) -
                         (CGAL::Mpzf(ay) - CGAL::Mpzf(qy)) * (CGAL::Mpzf(bx) - CGAL::Mpzf(qx));
    return o.to_double();
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

    // current orientations (exact) and half-planes in the parameter space
    std::vector<CGAL::Orientation> old_sign(corners.size());
    std::vector<Halfplane> all, required;
    std::size_t old_negative = 0;
    double L = 0;
    for(std::size_t i = 0; i < corners.size(); ++i) {
      const int c = corners[i];
      const int s = st.sector_of[c], sa = st.sector_of[cm.next[c]], sb = st.sector_of[cm.prev[c]];
      const double qx = x[2 * s], qy = x[2 * s + 1];
      const double ax = x[2 * sa], ay = x[2 * sa + 1], bx = x[2 * sb], by = x[2 * sb + 1];
      old_sign[i] = CGAL::orientation(P(qx, qy), P(ax, ay), P(bx, by));
      if(old_sign[i] == CGAL::NEGATIVE) ++old_negative;
      L = (std::max)({L, std::fabs(ax - qx), std::fabs(ay - qy), std::fabs(bx - qx), std::fabs(by - qy)});
      const double n[2] = {ay - by, bx - ax};
      if(n[0] == 0 && n[1] == 0) continue;      // a == b: the face is degenerate whatever we do
      double mn[2];                              // M^T n, M = R^k: (R^k)^T = R^-k
      rotate_quarter_turns(-g.m[member[i]].k, n[0], n[1], mn[0], mn[1]);
      Halfplane p;
      if(dim == 1) { p.g[0] = mn[g.axis]; p.g[1] = 0; }
      else { p.g[0] = mn[0]; p.g[1] = mn[1]; }
      p.norm = std::sqrt(n[0] * n[0] + n[1] * n[1]);
      p.h = -exact_orient_to_double(qx, qy, ax, ay, bx, by);
      all.push_back(p);
      if(old_sign[i] != CGAL::NEGATIVE || cm.face[c] == target) required.push_back(p);
    }
    if(old_negative == 0 || !(L > 0)) return false;
    L *= 4;
    // |new - ubar| <= max_move for every moved coordinate: (R^k t)_c = sign_c t_{col_c} within
    // [lo, hi] = [ubar - x - max_move, ubar - x + max_move]; the margin does not shrink these
    for(int i = 0; i < g.n; ++i) {
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
      for(int i = 0; i < g.n; ++i)
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
        if(attempt(g, t, dim, corners, old_sign, old_negative, max_move)) return true;
      }
      if(any) {
        double t[2] = {0, 0};
        if(dim == 1) t[0] = 0.5 * (last[0] + last[1]);
        else centroid(last, t);
        if(attempt(g, t, dim, corners, old_sign, old_negative, max_move)) return true;
      }
    }
    return false;
  }

  // Applies the displacement (after rounding) if every exact test passes.
  bool attempt(const Group& g, const double tau[2], int dim, const std::vector<int>& corners,
               const std::vector<CGAL::Orientation>& old_sign,
               std::size_t old_negative, double max_move)
  {
    double t[2] = {0, 0};
    if(dim == 1) t[g.axis] = tau[0];
    else { t[0] = tau[0]; t[1] = tau[1]; }
    if(g.kind == 1) { t[0] = grid.round(t[0]); t[1] = grid.round(t[1]); }
    if(!std::isfinite(t[0]) || !std::isfinite(t[1]) || (t[0] == 0 && t[1] == 0)) return false;

    double old_value[4], new_value[4];
    bool changed = false;
    for(int i = 0; i < g.n; ++i) {
      double d[2];
      rotate_quarter_turns(g.m[i].k, t[0], t[1], d[0], d[1]);
      for(int c = 0; c < 2; ++c) {
        old_value[2 * i + c] = x[2 * g.m[i].sector + c];
        new_value[2 * i + c] = old_value[2 * i + c] + d[c];
        if(!std::isfinite(new_value[2 * i + c])) return false;
        if(!(std::fabs(new_value[2 * i + c] - (*ubar_)[2 * g.m[i].sector + c]) <= max_move)) return false;
        changed = changed || new_value[2 * i + c] != old_value[2 * i + c];
      }
    }
    if(!changed) return false;
    auto assign = [&](const double* val) {
      for(int i = 0; i < g.n; ++i) for(int c = 0; c < 2; ++c) x[2 * g.m[i].sector + c] = val[2 * i + c];
    };
    assign(new_value);

    bool ok = true;
    std::size_t new_negative = 0;
    for(std::size_t i = 0; i < corners.size() && ok; ++i) {
      const int c = corners[i];
      const int s = st.sector_of[c], sa = st.sector_of[cm.next[c]], sb = st.sector_of[cm.prev[c]];
      const CGAL::Orientation o = CGAL::orientation(P(x[2 * s], x[2 * s + 1]), P(x[2 * sa], x[2 * sa + 1]),
                                                    P(x[2 * sb], x[2 * sb + 1]));
      if(o == CGAL::NEGATIVE) ++new_negative;
      if(old_sign[i] == CGAL::POSITIVE && o != CGAL::POSITIVE) ok = false;
      if(old_sign[i] == CGAL::ZERO && o == CGAL::NEGATIVE) ok = false;
    }
    ok = ok && new_negative < old_negative;
    // every row that mentions a changed variable holds exactly
    for(int i = 0; i < g.n && ok; ++i)
      for(int c = 0; c < 2 && ok; ++c) {
        if(new_value[2 * i + c] == old_value[2 * i + c]) continue;
        const std::size_t var = 2 * std::size_t(g.m[i].sector) + c;
        for(std::size_t k = vr_start[var]; k < vr_start[var + 1] && ok; ++k)
          if(!exact_row_residual(rows, std::size_t(vr_row[k]), x).is_zero()) ok = false;
      }
    if(!ok) assign(old_value);
    return ok;
  }
};

// number of faces with negative orientation in `x` but not in `ubar` (exact predicate)
inline std::size_t count_introduced_flips(const Corner_mesh& cm, const Seam_topology& st,
                                          const std::vector<double>& ubar, const std::vector<double>& x)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  std::size_t n = 0;
  for(int h = 0; h < cm.n_halfedges; ++h) {
    if(cm.is_border_halfedge(h) || h > cm.next[h] || h > cm.prev[h]) continue;   // once per face
    const int s[3] = {st.sector_of[h], st.sector_of[cm.next[h]], st.sector_of[cm.prev[h]]};
    auto negative = [&](const std::vector<double>& y) {
      return CGAL::orientation(P(y[2 * s[0]], y[2 * s[0] + 1]), P(y[2 * s[1]], y[2 * s[1] + 1]),
                               P(y[2 * s[2]], y[2 * s[2] + 1])) == CGAL::NEGATIVE;
    };
    if(negative(x) && !negative(ubar)) ++n;
  }
  return n;
}

// Repairs flips of `x` (2 values per sector) in place; see the header comment.
inline Flip_repair_result repair_flips(const Corner_mesh& cm, const Seam_topology& st, const Reduced_system& rs,
                                       const Constraint_rows& full, const Fixed_point_grid& grid,
                                       const std::vector<double>& ubar, std::vector<double>& x)
{
  Flip_repair fr(cm, st, rs, full, grid, x);
  return fr.run(ubar);
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_FLIP_REPAIR_H
