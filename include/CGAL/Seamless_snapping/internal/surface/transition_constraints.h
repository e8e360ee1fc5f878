// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_TRANSITION_CONSTRAINTS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_TRANSITION_CONSTRAINTS_H

// The full (unreduced) constraint system C u = b over the sector variables (Sec. 5.1, 5.2):
// variable 2s is u and 2s+1 is v of sector s. The transition and alignment rows below are
// homogeneous (b = 0); inhomogeneous rows (integer b in UV units, e.g. the integer translations of
// an integer-grid map) are stated over node sectors and carried by Constraint_rows::rhs.
//
// - Transition constraint, Eq. (4), two rows per cut edge e, with h = halfedge(e), o = opposite(h),
//   i = face(h), j = face(o), a = source(h), b = target(h), k = k(h):
//       R^k (U_a^i - U_b^i) - (U_a^j - U_b^j) = 0      (component c = 0 and c = 1)
//   where U_a^i is the sector variable of corner prev(h), U_b^i of h, U_a^j of o, U_b^j of prev(o).
// - Alignment constraint, Eq. (5), one row per align edge, in the face of its halfedge g:
//       U_a|c - U_b|c = 0,  c the component that is constant along the edge (1: edge parallel to the
//   u axis, 0: parallel to the v axis), U_a of corner prev(g), U_b of corner g.
// Align edges: border edges whose UV direction is within the alignment tolerance of an axis (when
// boundary alignment is on; degenerate border edges, shorter than 1e-6 times the UV diagonal, are
// not aligned), and the caller's constrained edges (their component is inferred the same way; an
// edge that is not near an axis is refused).

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
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

// Integer rows with small coefficients over the sector variables, with an integer right-hand side
// per row (sum_k coef_k x_{col_k} = rhs, rhs in UV units, default 0), compressed row storage.
// Duplicate columns of a row are summed and zero entries dropped; rows that cancel completely are
// not stored: 0 = 0 holds for every x, and 0 = b != 0 for none (its edge goes to `contradictions`).
struct Constraint_rows
{
  std::vector<std::size_t> start = std::vector<std::size_t>(1, 0);
  std::vector<int> col, coef;
  std::vector<long> rhs;   // per row: b_i
  std::vector<int> edge;   // per row: the mesh edge it comes from (for messages)
  std::vector<int> contradictions;   // `from_edge` of rows that cancelled to 0 = b != 0

  std::size_t size() const { return start.size() - 1; }
  bool add(std::vector<std::pair<int, int> > terms, int from_edge, long b = 0)
  {
    std::sort(terms.begin(), terms.end());
    const std::size_t before = col.size();
    for(std::size_t i = 0; i < terms.size();) {
      int c = terms[i].first, sum = 0;
      for(; i < terms.size() && terms[i].first == c; ++i) sum += terms[i].second;
      if(sum != 0) { col.push_back(c); coef.push_back(sum); }
    }
    if(col.size() == before) {
      if(b != 0) contradictions.push_back(from_edge);
      return false;
    }
    start.push_back(col.size());
    rhs.push_back(b);
    edge.push_back(from_edge);
    return true;
  }
};

struct Align_edges
{
  std::vector<int> edges;         // ids, ascending
  std::vector<int> component;     // per edge: the constant component (0 or 1), -1 if not an align edge
  std::vector<int> halfedge;      // per edge: the halfedge g whose face the row uses (-1 if none)
};

// the coordinates of the two ends of align edge e (its constant component)
inline void align_edge_ends(const Corner_mesh& cm, const Seam_topology& st, const Align_edges& al, int e,
                            std::size_t& a, std::size_t& b)
{
  a = 2 * std::size_t(st.sector_of[cm.prev[al.halfedge[std::size_t(e)]]]) + std::size_t(al.component[std::size_t(e)]);
  b = 2 * std::size_t(st.sector_of[al.halfedge[std::size_t(e)]]) + std::size_t(al.component[std::size_t(e)]);
}

// the corner of vertex w in the face used by align edge e
inline int align_corner(const Corner_mesh& cm, const Align_edges& al, int e, int w)
{
  const int g = al.halfedge[e];
  return cm.target[g] == w ? g : cm.prev[g];
}

// `constrained[e]` (possibly empty): the caller's align edges.
inline Status find_align_edges(const Corner_mesh& cm, const Seam_topology& st, bool align_boundary,
                               double tolerance_degrees, const std::vector<char>& constrained,
                               Align_edges& al, std::string& message)
{
  al = Align_edges();
  al.component.assign(cm.n_edges, -1);
  al.halfedge.assign(cm.n_edges, -1);
  const double tol = tolerance_degrees * std::acos(-1.) / 180;
  const double min_length = degenerate_cut_edge_length * st.uv_diagonal;
  for(int e = 0; e < cm.n_edges; ++e) {
    const bool given = !constrained.empty() && constrained[e];
    const bool border = cm.is_border_edge(e);
    if(!given && !(border && align_boundary)) continue;
    int g = cm.edge_halfedge[e];
    if(cm.is_border_halfedge(g)) g = cm.opp[g];
    const double du = cm.du(g), dv = cm.dv(g);
    const double length = std::hypot(du, dv);
    int c = -1;
    if(length > 0 && length >= min_length) {
      if(std::atan2(std::fabs(dv), std::fabs(du)) <= tol) c = 1;        // parallel to the u axis: v constant
      else if(std::atan2(std::fabs(du), std::fabs(dv)) <= tol) c = 0;   // parallel to the v axis: u constant
    }
    if(c < 0) {
      if(!given) continue;
      message = "align edge " + vertex_pair_name(cm, g) + " (face " + std::to_string(cm.face[g]) + ") has UV vector (" +
                format_double(cm.to_uv(du), 17) + ", " + format_double(cm.to_uv(dv), 17) + "), " +
                (length < min_length ? std::string("too short to infer its aligned component")
                                     : "not within " + format_double(tolerance_degrees) + " degrees of the u or v axis");
      return INVALID_INPUT;
    }
    al.edges.push_back(e);
    al.component[e] = c;
    al.halfedge[e] = g;
  }
  return SUCCESS;
}

// The sectors at the two ends of a cut edge, given by its halfedge h: at end m (0: the source of h, 1: its target)
// i[m] in the chart of h's face and j[m] in the chart of the opposite face; the transition of h maps each i[m] to
// j[m] (the rows of Eq. (4) below, the integer translations of add_integer_grid_rows(), relate_cut_edge())
struct Cut_edge_ends
{
  int i[2], j[2];
};

inline Cut_edge_ends cut_edge_ends(const Corner_mesh& cm, const Seam_topology& st, int h)
{
  const int o = cm.opp[h];
  return {{st.sector_of[cm.prev[h]], st.sector_of[h]}, {st.sector_of[o], st.sector_of[cm.prev[o]]}};
}

// Eq. (4): the two rows of the cut edge e (component c = 0, 1)
inline void add_transition_rows(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                                int e, Constraint_rows& rows)
{
  const int h = cm.edge_halfedge[e];
  const Cut_edge_ends s = cut_edge_ends(cm, st, h);
  const Quarter_turn R(rot.k[h]);
  for(int c = 0; c < 2; ++c)
    rows.add({ {2 * s.i[0] + R.col[c], R.sign[c]}, {2 * s.i[1] + R.col[c], -R.sign[c]},
               {2 * s.j[0] + c, -1}, {2 * s.j[1] + c, 1} }, e);
}

// Eq. (5): the row of the align edge e
inline void add_alignment_row(const Corner_mesh& cm, const Seam_topology& st, const Align_edges& al,
                              int e, Constraint_rows& rows)
{
  std::size_t a, b;
  align_edge_ends(cm, st, al, e, a, b);
  rows.add({ {int(a), 1}, {int(b), -1} }, e);
}

inline void build_full_system(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                              const Align_edges& al, Constraint_rows& rows)
{
  rows = Constraint_rows();
  for(int e : st.cut_edges) add_transition_rows(cm, st, rot, e, rows);
  for(int e : al.edges) add_alignment_row(cm, st, al, e, rows);
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_TRANSITION_CONSTRAINTS_H
