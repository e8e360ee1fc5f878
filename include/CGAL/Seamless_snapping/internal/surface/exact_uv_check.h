// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_EXACT_UV_CHECK_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_EXACT_UV_CHECK_H

// Exact evaluation of constraint rows on double values, and the exact seamlessness test of a
// corner UV map. Doubles are dyadic rationals: each one converts to CGAL::Mpzf (a multiprecision
// binary float whose +, -, * are exact) or CGAL::Gmpq without error, and every row is evaluated
// exactly, with zero tolerance.

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Mpzf.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// residual sum_j C_ij x_j - b_i of row i, exactly (CGAL::Mpzf: exact sums and products of doubles;
// |b_i| < 2^53 is exact as a double)
inline CGAL::Mpzf exact_row_residual(const Constraint_rows& rows, std::size_t i, const std::vector<double>& x)
{
  CGAL_precondition(rows.rhs[i] < (long(1) << 53) && rows.rhs[i] > -(long(1) << 53));
  CGAL::Mpzf r = -CGAL::Mpzf(double(rows.rhs[i]));
  for(std::size_t k = rows.start[i]; k < rows.start[i + 1]; ++k)
    r = r + CGAL::Mpzf(x[rows.col[k]]) * CGAL::Mpzf(double(rows.coef[k]));
  return r;
}

// Index of the first row with a nonzero exact residual, or -1 when every row holds exactly.
inline long first_violated_row(const Constraint_rows& rows, const std::vector<double>& x)
{
  for(std::size_t i = 0; i < rows.size(); ++i)
    if(!exact_row_residual(rows, i, x).is_zero()) return long(i);
  return -1;
}

// max_i |sum_j C_ij x_j - b_i|, computed exactly, then rounded to double.
inline double max_abs_residual(const Constraint_rows& rows, const std::vector<double>& x)
{
  CGAL::Mpzf m(0);
  for(std::size_t i = 0; i < rows.size(); ++i) {
    CGAL::Mpzf r = exact_row_residual(rows, i, x);
    if(r.sign() == CGAL::NEGATIVE) r = -r;
    if(CGAL::compare(m, r) == CGAL::SMALLER) m = r;
  }
  return m.to_double();
}

// The exact sum a + b of two doubles as the pair (s, e), s = fl(a + b), e = a + b - s (Knuth's TwoSum: an
// error-free transformation in round-to-nearest without overflow). The pair is a function of the exact sum,
// and determines it: two exact sums are equal iff their pairs are.
inline void two_sum(double a, double b, double& s, double& e)
{
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}

// true iff x - y == z - w exactly (the differences of doubles need not be doubles): x + w == z + y, compared as
// TwoSum pairs; with a value beyond 2^1000 (where a sum might overflow) in rational arithmetic instead.
inline bool same_difference(double x, double y, double z, double w)
{
  const double big = 0x1p1000;
  if(!(std::fabs(x) < big && std::fabs(y) < big && std::fabs(z) < big && std::fabs(w) < big))
    return CGAL::Gmpq(x) - CGAL::Gmpq(y) == CGAL::Gmpq(z) - CGAL::Gmpq(w);
  double s1, e1, s2, e2;
  two_sum(x, w, s1, e1);
  two_sum(z, y, s2, e2);
  return s1 == s2 && e1 == e2;
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

// The exact test behind is_exactly_seamless().
// `seam_override[e]`: as in compute_seam_topology(); `given_k[e]`: k of halfedge(e) or empty (any k);
// `aligned[e]`: edges that must be axis-parallel in UV, or empty. With `why`, a failure names the
// first edge that fails and how.
inline bool is_exactly_seamless_impl(const Corner_mesh& cm, const std::vector<signed char>& seam_override,
                                     const std::vector<int>& given_k, const std::vector<char>& aligned,
                                     std::string* why = nullptr)
{
  auto fail = [&](int h, const std::string& what) {
    if(why != nullptr) *why = "edge " + vertex_pair_name(cm, h) + " " + what;
    return false;
  };
  for(int e = 0; e < cm.n_edges; ++e) {
    const int h = cm.edge_halfedge[e], o = cm.opp[h];
    if(!aligned.empty() && aligned[e]) {
      const int g = cm.is_border_halfedge(h) ? o : h;
      // doubles: the difference is zero iff the two coordinates are equal
      if(cm.u[g] != cm.u[cm.prev[g]] && cm.v[g] != cm.v[cm.prev[g]])
        return fail(h, "is constrained (edge_is_constrained_map) but not parallel to the u or v axis in UV");
    }
    if(cm.is_border_edge(e)) continue;
    const bool continuous = same_uv(cm, h, cm.prev[o]) && same_uv(cm, cm.prev[h], o);
    const bool seam = (!seam_override.empty() && seam_override[e] >= 0) ? seam_override[e] != 0 : !continuous;
    if(!seam) {
      if(!continuous) return fail(h, "is not a seam (seam_edge_map) but its two faces disagree on its UVs");
      continue;
    }
    if(!given_k.empty()) {
      if(!exact_transition_holds(cm, h, given_k[e]))
        return fail(h, "(a cut edge): the rotation by k = " + std::to_string(given_k[e]) + " quarter turns (rotation_map) "
                       "does not map the UV edge vector of one face exactly onto the other's");
    } else {
      bool some = false;
      for(int k = 0; k < 4 && !some; ++k) some = exact_transition_holds(cm, h, k);
      if(!some)
        return fail(h, "(a cut edge between faces " + std::to_string(cm.face[h]) + " and " + std::to_string(cm.face[o]) +
                       "): no rotation by a multiple of 90 degrees maps the UV edge vector of one face exactly onto the "
                       "other's: the map is not exactly seamless");
    }
  }
  return true;
}

// Builds the corner mesh of `tm` and evaluates the overrides (callables on descriptors) per edge,
// in the form is_exactly_seamless_impl() takes them. False if the corner mesh cannot be built.
template <class TriangleMesh, class HalfedgeUVMap, class SeamOf, class RotationOf, class ConstrainedOf>
bool corner_mesh_and_overrides(const TriangleMesh& tm, HalfedgeUVMap uvmap, const SeamOf& seam_of, bool has_seams,
                               const RotationOf& rotation_of, bool has_rotations,
                               const ConstrainedOf& constrained_of, bool has_constrained, Corner_mesh& cm,
                               std::vector<signed char>& seam_override, std::vector<int>& given_k,
                               std::vector<char>& aligned)
{
  Corner_mesh_descriptors<TriangleMesh> desc;
  std::string message;
  if(build_corner_mesh(tm, uvmap, cm, desc, message) != SUCCESS) return false;
  seam_override.clear(); given_k.clear(); aligned.clear();
  if(has_seams) {
    seam_override.resize(cm.n_edges);
    for(int e = 0; e < cm.n_edges; ++e) seam_override[e] = seam_of(desc.edges[e]) ? 1 : 0;
  }
  if(has_rotations) {
    given_k.resize(cm.n_edges);
    for(int e = 0; e < cm.n_edges; ++e) given_k[e] = int(rotation_of(desc.halfedges[cm.edge_halfedge[e]]));
  }
  if(has_constrained) {
    aligned.resize(cm.n_edges);
    for(int e = 0; e < cm.n_edges; ++e) aligned[e] = constrained_of(desc.edges[e]) ? 1 : 0;
  }
  return true;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_EXACT_UV_CHECK_H
