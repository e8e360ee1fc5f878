// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_ROTATION_FIT_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_ROTATION_FIT_H

// Rotation k of the transition across each cut edge (Eq. 3/4), and the check that the input is
// seamless up to rotations by multiples of 90 degrees.
//
// Convention: k(h) in {0,1,2,3} is the number of quarter turns counter-clockwise that map the frame
// of face(h) to the frame of face(opposite(h)): R^k (U_a^i - U_b^i) = U_a^j - U_b^j with
// i = face(h), j = face(opposite(h)), a = source(h), b = target(h), R(x, y) = (-y, x).
// k(opposite(h)) = -k(h) mod 4.
//
// Fitting (when the caller gives no rotations): ONE k per seam arc, i.e. per chain of cut edges
// between cones, border vertices and vertices whose cut-degree is not 2, maximizing
//   sum over the arc's edges of dot(R^k d_i, d_j)
// (d_i, d_j: the edge's UV vector on either side, both oriented along the arc). Long edges
// dominate, so near-zero-length cut edges, whose direction is noise, get the rotation of their arc
// (cf. [EBCK13] for the per-edge version). Except in an exactly seamless map (every cut edge has a k
// for which its transition holds exactly, exact_transition_holds()): there every cut edge keeps that k
// where the arc's k does not hold exactly on it (a nonzero edge has one such k; an edge of UV length 0
// holds for every k and keeps the arc's). Arcs run through cones whose UV angle sum is hidden (e.g. two
// cones that an integer-grid snap put onto one point: the angles at a corner with a side of length 0
// mean nothing), and the arc's k then misses a rotation change there; near-zero edges next to such
// points hold exactly for another k than their arc's. Without this, the package's own exact output of
// such a map was refused, or moved, when read again (the dragon's integer-grid map, test_constraints).
//
// Check: every non-degenerate cut edge must have |angle(R^k d_i, d_j)| <= rotation tolerance and
// | |d_j| - |d_i| | <= tolerance (in radians) * max(|d_i|, |d_j|) (a rigid motion keeps lengths),
// otherwise the input is refused with NOT_QUARTER_TURN_SEAMLESS (e.g. 120 degree orbifolds).
// Degenerate: the UV length on one side is below 1e-6 times the UV bounding-box diagonal.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/dyadic_sum.h>
#include <CGAL/Seamless_snapping/internal/surface/edge_chains.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// relative UV length under which a cut edge counts as degenerate (its direction is not checked)
constexpr double degenerate_cut_edge_length = 1e-6;

// (x, y) -> R^k (x, y), R(x, y) = (-y, x), for any signed number type (double, CGAL::Gmpq, integers); exact
// (negations and swaps only); (rx, ry) may be (x, y) itself
template <class T>
void rotate_quarter_turns(int k, T x, T y, T& rx, T& ry)
{
  switch(((k % 4) + 4) % 4) {
    case 0: rx = x;  ry = y;  break;
    case 1: rx = -y; ry = x;  break;
    case 2: rx = -x; ry = -y; break;
    default: rx = y; ry = -x; break;
  }
}

// The 2x2 integer matrix R^k as (column, sign) per output component: (R^k x)_c = sign[c] * x_{col[c]}.
struct Quarter_turn
{
  int col[2]; int sign[2];
  explicit Quarter_turn(int k)
  {
    switch(((k % 4) + 4) % 4) {
      case 0: col[0] = 0; sign[0] = 1;  col[1] = 1; sign[1] = 1;  break;
      case 1: col[0] = 1; sign[0] = -1; col[1] = 0; sign[1] = 1;  break;
      case 2: col[0] = 0; sign[0] = -1; col[1] = 1; sign[1] = -1; break;
      default: col[0] = 1; sign[0] = 1; col[1] = 0; sign[1] = -1; break;
    }
  }
};

struct Cut_rotations
{
  std::vector<int> k;              // per halfedge (cut edges only; 0 elsewhere)
  std::vector<char> degenerate;    // per edge (cut edges only)
  std::size_t n_degenerate = 0;
  std::size_t n_arcs = 0;
  double max_deviation_degrees = 0;// over non-degenerate cut edges
};

// UV vectors of the cut edge of h on both sides, oriented source(h) -> target(h):
// d_i in face(h), d_j in face(opposite(h)).
inline void transition_vectors(const Corner_mesh& cm, int h, double di[2], double dj[2])
{
  const int o = cm.opp[h];
  di[0] = cm.du(h);  di[1] = cm.dv(h);
  dj[0] = -cm.du(o); dj[1] = -cm.dv(o);
}

// true iff x - y == z - w exactly (the differences of doubles need not be doubles): x - y - z + w == 0 in
// integers (dyadic_sum.h), in rational arithmetic when the four values span too much
inline bool same_difference(double x, double y, double z, double w)
{
  Dyadic_sum r;
  r.add(1, x); r.add(-1, y); r.add(-1, z); r.add(1, w);
  if(r.fits()) return r.is_zero();
  return CGAL::Gmpq(x) - CGAL::Gmpq(y) == CGAL::Gmpq(z) - CGAL::Gmpq(w);
}

// true iff R^k d_i == d_j exactly (d = UV(target) - UV(source) on each side of the edge of h).
inline bool exact_transition_holds(const Corner_mesh& cm, int h, int k)
{
  const int o = cm.opp[h];
  const int ph = cm.prev[h], po = cm.prev[o];
  // d_i = uv[h] - uv[prev h] (face of h); d_j = uv[prev o] - uv[o] (face of o); (R^k d_i)_c = sign_c (d_i)_col_c
  const Quarter_turn R(k);
  for(int c = 0; c < 2; ++c) {
    const std::vector<double>& in = R.col[c] == 0 ? cm.u : cm.v;
    const std::vector<double>& out = c == 0 ? cm.u : cm.v;
    const bool same = R.sign[c] > 0 ? same_difference(in[h], in[ph], out[po], out[o])
                                    : same_difference(in[ph], in[h], out[po], out[o]);
    if(!same) return false;
  }
  return true;
}

// std::hypot(x, y) >= length, decided from x^2 + y^2 where that is far enough from length^2 (relative 1e-9, against
// rounding errors of a few ulp in the squares and in std::hypot) and both are normal numbers, else by std::hypot
// itself: the same answer as std::hypot, without its cost on almost every edge (48K calls, 2.5 ms on the 302K-face bunny)
inline bool length_at_least(double x, double y, double length)
{
  const double q = x * x + y * y, l2 = length * length;
  if(q >= 0x1p-1000 && l2 >= 0x1p-1000 && q <= 0x1p+1000 && l2 <= 0x1p+1000) {
    if(q >= l2 * (1 + 1e-9)) return true;
    if(q <= l2 * (1 - 1e-9)) return false;
  }
  return std::hypot(x, y) >= length;
}

// `given_k[e]`: the caller's rotation for halfedge(e) (edge_halfedge), or empty to fit.
inline Status fit_rotations(const Corner_mesh& cm, const Seam_topology& st, const std::vector<int>& given_k,
                            double tolerance_degrees, Cut_rotations& rot, std::string& message)
{
  rot = Cut_rotations();
  rot.k.assign(cm.n_halfedges, 0);
  rot.degenerate.assign(cm.n_edges, 0);
  const double min_length = degenerate_cut_edge_length * st.uv_diagonal;
  for(int e : st.cut_edges) {
    double di[2], dj[2];
    transition_vectors(cm, cm.edge_halfedge[e], di, dj);
    if(!(length_at_least(di[0], di[1], min_length) && length_at_least(dj[0], dj[1], min_length)) || min_length == 0) {
      rot.degenerate[e] = 1;
      ++rot.n_degenerate;
    }
  }

  // The UV vectors of the angle computations below are scaled by a power of two (exact; angles and the comparison of
  // the scores do not change) where their products could overflow to Inf or underflow to 0: integer-grid mode keeps the
  // caller's scale (e.g. UVs of 1e300 or 1e-300 grid units; one vt of 1e300 in a map of unit UVs). Per seam arc for the
  // scores (one factor for all its edges), per edge for the deviation; vectors within 2^-400 .. 2^400 keep their
  // values, so other maps keep every number bit for bit.
  auto shift_of = [](double m) { return std::isfinite(m) && (m > 0x1p+400 || (m > 0 && m < 0x1p-400)) ? -binary_exponent(m) : 0; };
  auto largest = [](const double di[2], const double dj[2]) {
    return (std::max)({std::fabs(di[0]), std::fabs(di[1]), std::fabs(dj[0]), std::fabs(dj[1])});
  };
  auto scale = [](int shift, double di[2], double dj[2]) {
    if(shift != 0)
      for(int c = 0; c < 2; ++c) { di[c] = scale_by_power_of_two(di[c], shift); dj[c] = scale_by_power_of_two(dj[c], shift); }
  };

  auto set_k = [&](int h, int k) {
    k = ((k % 4) + 4) % 4;
    rot.k[h] = k;
    rot.k[cm.opp[h]] = (4 - k) % 4;
  };

  if(!given_k.empty()) {
    for(int e : st.cut_edges) set_k(cm.edge_halfedge[e], given_k[e]);
  } else {
    std::vector<char> stop(cm.n_vertices, 0);
    for(int v = 0; v < cm.n_vertices; ++v)
      stop[v] = st.is_cone[v] || cm.vertex_on_border[v] || st.cut_degree[v] != 2;
    Edge_chains arcs;
    decompose_into_chains(cm, st.is_cut, stop, arcs);
    rot.n_arcs = arcs.chains.size();
    for(const std::vector<int>& arc : arcs.chains) {
      double score[4] = {0, 0, 0, 0}, arc_largest = 0;
      auto add_scores = [&](int shift) {   // the scores of the arc's edges, their vectors scaled by 2^shift
        for(int h : arc) {
          double di[2], dj[2];
          transition_vectors(cm, h, di, dj);
          arc_largest = (std::max)(arc_largest, largest(di, dj));
          scale(shift, di, dj);
          for(int k = 0; k < 4; ++k) {
            double rx, ry;
            rotate_quarter_turns(k, di[0], di[1], rx, ry);
            score[k] += rx * dj[0] + ry * dj[1];
          }
        }
      };
      add_scores(0);
      if(const int arc_shift = shift_of(arc_largest)) {   // again, scaled (an arc beyond 2^-400 .. 2^400 only)
        for(double& x : score) x = 0;
        add_scores(arc_shift);
      }
      int best = 0;
      for(int k = 1; k < 4; ++k) if(score[k] > score[best]) best = k;
      for(int h : arc) set_k(h, best);
    }
    // an exactly seamless map keeps the rotation that each of its cut edges has exactly
    std::vector<std::pair<int, int> > exact;
    for(int e : st.cut_edges) {
      const int h = cm.edge_halfedge[e];
      if(exact_transition_holds(cm, h, rot.k[h])) continue;
      int k = 0;
      while(k < 4 && !exact_transition_holds(cm, h, k)) ++k;
      if(k == 4) { exact.clear(); break; }          // not exactly seamless: the fitted rotations stay
      exact.emplace_back(h, k);
    }
    for(const std::pair<int, int>& hk : exact) set_k(hk.first, hk.second);
  }

  // every non-degenerate transition must be a rotation by k * 90 degrees, up to the tolerance. An edge whose
  // deviation is bounded above by at most the largest one so far and by the tolerance (|angle| <= |sin| / cos for an
  // acute angle; relative 1e-12 against rounding) changes neither, and passes: its std::atan2 is not needed; nor are
  // its lengths' std::hypot where the squared lengths pass the length test by far (relative 1e-9, a tolerance of at
  // least 1e-6 radians). On the 302K-face bunny 4 of the 5 ms of this loop; the same results
  const double rad = std::acos(-1.) / 180, radians = tolerance_degrees * rad;
  const double min_length_ratio2 = radians >= 1e-6 && radians < 1 ? (1 - 0.5 * radians) * (1 - 0.5 * radians) * (1 + 1e-9) : HUGE_VAL;
  for(int e : st.cut_edges) {
    if(rot.degenerate[e]) continue;
    const int h = cm.edge_halfedge[e];
    double di[2], dj[2], r[2];
    transition_vectors(cm, h, di, dj);
    const int shift = shift_of(largest(di, dj));
    scale(shift, di, dj);
    rotate_quarter_turns(rot.k[h], di[0], di[1], r[0], r[1]);
    const double sine = r[0] * dj[1] - r[1] * dj[0], cosine = r[0] * dj[0] + r[1] * dj[1];
    const double bound = cosine > 0 ? std::fabs(sine) / cosine / rad * (1 + 1e-12) : HUGE_VAL;
    const double qi = di[0] * di[0] + di[1] * di[1], qj = dj[0] * dj[0] + dj[1] * dj[1];
    if(bound <= rot.max_deviation_degrees && bound <= tolerance_degrees && qi >= 0x1p-1000 && qj >= 0x1p-1000 &&
       qi <= 0x1p+1000 && qj <= 0x1p+1000 && (std::min)(qi, qj) >= (std::max)(qi, qj) * min_length_ratio2)
      continue;
    const double deviation = std::fabs(std::atan2(sine, cosine)) / rad;
    if(deviation > rot.max_deviation_degrees) rot.max_deviation_degrees = deviation;
    if(!(deviation <= tolerance_degrees)) {
      const double angle = std::atan2(di[0] * dj[1] - di[1] * dj[0], di[0] * dj[0] + di[1] * dj[1]) / rad;
      message = "cut edge " + vertex_pair_name(cm, h) + " (faces " + std::to_string(cm.face[h]) + ", " +
                std::to_string(cm.face[cm.opp[h]]) + "): the transition rotates its UV vector by " +
                format_double(angle) + " degrees, " + format_double(deviation) + " degrees away from " +
                std::to_string(rot.k[h] * 90) + " degrees (k = " + std::to_string(rot.k[h]) +
                (given_k.empty() ? ", fitted on its seam arc" : ", given") + "); the rotation tolerance is " +
                format_double(tolerance_degrees) + " degrees: not a quarter-turn seamless parametrization";
      return NOT_QUARTER_TURN_SEAMLESS;
    }
    if(shift != 0) transition_vectors(cm, h, di, dj);   // the lengths at the corner mesh's scale (std::hypot does not overflow)
    const double li = std::hypot(di[0], di[1]), lj = std::hypot(dj[0], dj[1]);
    if(!(std::fabs(li - lj) <= tolerance_degrees * rad * (std::max)(li, lj))) {
      message = "cut edge " + vertex_pair_name(cm, h) + " (faces " + std::to_string(cm.face[h]) + ", " +
                std::to_string(cm.face[cm.opp[h]]) + "): its UV lengths on the two sides differ (" +
                format_double(cm.to_uv(li), 17) + " vs " + format_double(cm.to_uv(lj), 17) + "), more than the rotation tolerance of " +
                format_double(tolerance_degrees) + " degrees allows: the transition is not a rigid motion";
      return NOT_QUARTER_TURN_SEAMLESS;
    }
  }
  return SUCCESS;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_ROTATION_FIT_H
