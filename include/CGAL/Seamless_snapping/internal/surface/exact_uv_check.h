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
#include <CGAL/Seamless_snapping/internal/surface/dyadic_sum.h>
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

// the same residual in integers (dyadic_sum.h); it may not fit (then use exact_row_residual())
inline Dyadic_sum dyadic_row_residual(const Constraint_rows& rows, std::size_t i, const std::vector<double>& x)
{
  Dyadic_sum r;
  r.add_integer(-rows.rhs[i]);
  for(std::size_t k = rows.start[i]; k < rows.start[i + 1]; ++k) r.add(rows.coef[k], x[rows.col[k]]);
  return r;
}

// true iff row i holds exactly for x: in integers, or with CGAL::Mpzf when the values span too much
inline bool row_holds_exactly(const Constraint_rows& rows, std::size_t i, const std::vector<double>& x)
{
  const Dyadic_sum r = dyadic_row_residual(rows, i, x);
  return r.fits() ? r.is_zero() : exact_row_residual(rows, i, x).is_zero();
}

// Index of the first row with a nonzero exact residual, or -1 when every row holds exactly.
inline long first_violated_row(const Constraint_rows& rows, const std::vector<double>& x)
{
  for(std::size_t i = 0; i < rows.size(); ++i)
    if(!row_holds_exactly(rows, i, x)) return long(i);
  return -1;
}

// max_i |sum_j C_ij x_j - b_i|, computed exactly, then rounded to double (CGAL::Mpzf::to_double() of the
// first row with the largest residual; the rows are compared in integers where they fit).
inline double max_abs_residual(const Constraint_rows& rows, const std::vector<double>& x)
{
  long best = -1;                 // the first row with the largest |residual| so far
  Dyadic_sum best_sum;            // its residual, when it fits
  bool best_fits = true;
  CGAL::Mpzf best_mpzf(0);        // its residual, when it or a later row does not fit
  auto abs_mpzf = [&](std::size_t i) { CGAL::Mpzf r = exact_row_residual(rows, i, x); return r.sign() == CGAL::NEGATIVE ? -r : r; };
  for(std::size_t i = 0; i < rows.size(); ++i) {
    const Dyadic_sum r = dyadic_row_residual(rows, i, x);
    if(r.fits() && best_fits) {
      if(r.compare_magnitude(best_sum) > 0) { best = long(i); best_sum = r; }
      continue;
    }
    if(best_fits) { best_mpzf = best < 0 ? CGAL::Mpzf(0) : abs_mpzf(std::size_t(best)); best_fits = false; }
    const CGAL::Mpzf a = abs_mpzf(i);
    if(CGAL::compare(best_mpzf, a) == CGAL::SMALLER) { best = long(i); best_mpzf = a; }
  }
  if(best < 0) return 0.;
  return abs_mpzf(std::size_t(best)).to_double();
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
