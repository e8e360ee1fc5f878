// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_VERTEX_WINDINGS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_VERTEX_WINDINGS_H

// Local injectivity at the vertices. Positive triangles are not enough: the UV triangles around an
// interior vertex can wind around it twice (an angle sum of 8 quarter turns at a regular vertex, a branch
// point) or too little (1 instead of 5 at a cone), and the map is then not locally injective there
// although no triangle is flipped. The angle sum of a vertex, in quarter turns, is fixed modulo 4 by the
// seam rotations around it (a fold-over changes it by a multiple of 4): it is K modulo 4, K the sum of the
// rotations of the cut edges around it (field_rotation_sums()). Its *valence* is the member of that class the
// map should have: the input's own angle sum where the input has no non-positive triangle at the vertex and its
// angle sum is in the class; else 4 at a regular vertex, 5 and 3 at the cones of classes 1 and 3, and 2 or 6
// for class 2 (2 where the 3D angle sum is below 2 pi, a convex corner, else 6; 2 without 3D positions). The
// input's angle sum leaves the class where its UV triangles are degenerate (an angle of 0 or pi is a guess) and
// where merged cone pairs changed the rotations (cone_merging.h). Where the class alone gives the valence of a
// cone (the input does not fix its index) and at joined cones, any other member of the class of at least 2 is a
// valid quad vertex too and is accepted (Target_valences): the field's rotations cannot tell a 2 from a 6.
// The angle sums of a map are counted exactly where the exact sign tests of quad_valences.h decide them
// (every corner of a positive or negative triangle), else rounded from floating-point angles.

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/face_orientations.h>
#include <CGAL/Seamless_snapping/internal/surface/quad_valences.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// the UVs in the map x (2 values per sector) of the corner h and of the next and previous corners of its face
inline void corner_uvs(const Corner_mesh& cm, const Seam_topology& st, const std::vector<double>& x, int h,
                       double q[2], double a[2], double b[2])
{
  auto uv = [&](int g, double p[2]) { const std::size_t s = std::size_t(st.sector_of[g]); p[0] = x[2 * s]; p[1] = x[2 * s + 1]; };
  uv(h, q); uv(cm.next[h], a); uv(cm.prev[h], b);
}

// the signed floating-point angle at q from a to b
inline double corner_uv_angle(const double q[2], const double a[2], const double b[2])
{
  const double ax = a[0] - q[0], ay = a[1] - q[1], bx = b[0] - q[0], by = b[1] - q[1];
  return std::atan2(ax * by - ay * bx, ax * bx + ay * by);
}

inline int quarter_turns_of_angle(double angle) { return int(std::lround(angle / (std::acos(-1.) / 2))); }

// per vertex, the angle sum of the map x (2 values per sector) in quarter turns; border and isolated vertices: 4.
// `orientations`: the exact orientation of every face of x (face_orientations())
inline std::vector<int> vertex_quarter_turns(const Corner_mesh& cm, const Seam_topology& st, const std::vector<double>& x,
                                             const std::vector<signed char>& orientations)
{
  struct Count { int turns = 0; char exact = 1, has_corner = 0; };   // one cache line access per corner
  std::vector<Count> count(std::size_t(cm.n_vertices));
  bool all_exact = true;
  const std::vector<int> first = face_first_halfedges(cm);
  const std::size_t d = std::size_t(seam_prefetch_distance);
  for(std::size_t j = 0; j < first.size(); ++j) {   // exact counts, once per face: its orientation holds at its 3 corners
    // what the faces ahead read far away (in meshes whose faces are not listed in order of adjacency): their corners'
    // sectors and vertices 2d ahead, the sectors' values and the vertices' counts d ahead (the 302K-face bunny of
    // ../shared/large: 25-31 -> 9 ms, with face_first_halfedges())
    if(j + 2 * d < first.size())
      for(int c : {first[j + 2 * d], cm.next[std::size_t(first[j + 2 * d])], cm.prev[std::size_t(first[j + 2 * d])]}) {
        __builtin_prefetch(&st.sector_of[std::size_t(c)]);
        __builtin_prefetch(&cm.target[std::size_t(c)]);
      }
    if(j + d < first.size())
      for(int c : {first[j + d], cm.next[std::size_t(first[j + d])], cm.prev[std::size_t(first[j + d])]}) {
        __builtin_prefetch(&x[2 * std::size_t(st.sector_of[std::size_t(c)])]);
        __builtin_prefetch(&count[std::size_t(cm.target[std::size_t(c)])], 1);
      }
    const int h = first[j];
    const int corner[3] = {h, cm.next[h], cm.prev[h]};
    double p[3][2];
    for(int i = 0; i < 3; ++i) {
      const std::size_t s = std::size_t(st.sector_of[corner[i]]);
      p[i][0] = x[2 * s]; p[i][1] = x[2 * s + 1];
    }
    const CGAL::Orientation o = CGAL::Orientation(orientations[std::size_t(cm.face[h])]);
    for(int i = 0; i < 3; ++i) {
      const double* q = p[i];
      const double* a = p[(i + 1) % 3];
      const double* b = p[(i + 2) % 3];
      Count& n = count[std::size_t(cm.target[corner[i]])];
      n.has_corner = 1;
      const int qa = quadrant(q[0], q[1], a[0], a[1]), qb = quadrant(q[0], q[1], b[0], b[1]);
      int c = 0;
      if(quarter_crossings(qa, qb, o, c)) n.turns += c;
      else { n.exact = 0; all_exact = false; }
    }
  }
  if(!all_exact) {   // floating-point angles where the exact count is undetermined, summed in corner order
    std::vector<double> angle(std::size_t(cm.n_vertices), 0.);
    for(int h = 0; h < cm.n_halfedges; ++h) {
      const std::size_t v = std::size_t(cm.target[h]);
      if(cm.is_border_halfedge(h) || count[v].exact) continue;
      double q[2], a[2], b[2];
      corner_uvs(cm, st, x, h, q, a, b);
      angle[v] += corner_uv_angle(q, a, b);
    }
    for(std::size_t v = 0; v < count.size(); ++v)
      if(!count[v].exact) count[v].turns = quarter_turns_of_angle(angle[v]);
  }
  std::vector<int> turns(count.size());
  for(std::size_t v = 0; v < count.size(); ++v)
    turns[v] = cm.vertex_on_border[v] || !count[v].has_corner ? 4 : count[v].turns;
  return turns;
}

// the same at one vertex v from all its corners `corners` in ascending order (the floating-point sum is then
// the one vertex_quarter_turns() takes, bit for bit)
inline int vertex_quarter_turns_at(const Corner_mesh& cm, const Seam_topology& st, const std::vector<double>& x, int v,
                                   const std::vector<int>& corners)
{
  if(cm.vertex_on_border[std::size_t(v)] || corners.empty()) return 4;
  int turns = 0;
  double q[2], a[2], b[2];
  for(int h : corners) {
    corner_uvs(cm, st, x, h, q, a, b);
    int c = 0;
    if(!corner_quarter_crossings(q, a, b, c)) {
      double angle = 0;
      for(int g : corners) { corner_uvs(cm, st, x, g, q, a, b); angle += corner_uv_angle(q, a, b); }
      return quarter_turns_of_angle(angle);
    }
    turns += c;
  }
  return turns;
}

// The valences the untangling aims at and the report checks: per vertex `valence` (0: none); where `any_in_class`
// is set, every member of its class of at least 2 is accepted as well (see the header)
struct Target_valences
{
  std::vector<int> valence;
  std::vector<char> any_in_class;

  // the map winds `turns` quarter turns around v, which it should not
  bool wound(std::size_t v, int turns) const
  {
    const int q = valence[v];
    if(q == 0 || turns == q) return false;
    return !(any_in_class[v] && turns >= 2 && (turns - q) % 4 == 0);
  }
};

// per vertex, its valence (see the header); `K`: per vertex, its class (field_rotation_sums(), -1 on the border);
// `turns`: the input's angle sums
inline Target_valences vertex_valences(const Corner_mesh& cm, const std::vector<int>& K, const std::vector<int>& turns,
                                        const std::vector<char>& input_positive, const std::vector<double>& points,
                                        const std::vector<std::array<int, 3> >& face_halfedges)
{
  std::vector<char> from_class(std::size_t(cm.n_vertices), 0);   // 1: the valence follows from the class alone
  for(std::size_t f = 0; f < face_halfedges.size(); ++f)
    if(!input_positive[f]) for(int h : face_halfedges[f]) from_class[std::size_t(cm.target[h])] = 1;
  for(std::size_t v = 0; v < from_class.size(); ++v)
    if(turns[v] <= 0 || ((turns[v] - K[v]) % 4 + 4) % 4 != 0) from_class[v] = 1;
  // the 3D angle sums, only at the vertices of class 2 whose valence follows from the class
  std::vector<double> angle3(std::size_t(cm.n_vertices), 0.);
  if(!points.empty())
    for(const std::array<int, 3>& h : face_halfedges)
      for(int m = 0; m < 3; ++m) {
        const std::size_t q = std::size_t(cm.target[h[std::size_t(m)]]);
        if(!from_class[q] || K[q] != 2) continue;
        const std::size_t a = std::size_t(cm.target[h[std::size_t((m + 1) % 3)]]), b = std::size_t(cm.target[h[std::size_t((m + 2) % 3)]]);
        double e1[3], e2[3], dot = 0, l1 = 0, l2 = 0;
        for(int c = 0; c < 3; ++c) {
          e1[c] = points[3 * a + std::size_t(c)] - points[3 * q + std::size_t(c)];
          e2[c] = points[3 * b + std::size_t(c)] - points[3 * q + std::size_t(c)];
          dot += e1[c] * e2[c]; l1 += e1[c] * e1[c]; l2 += e2[c] * e2[c];
        }
        if(l1 > 0 && l2 > 0) angle3[q] += std::acos((std::max)(-1., (std::min)(1., dot / std::sqrt(l1 * l2))));
      }
  const std::size_t n = std::size_t(cm.n_vertices);
  Target_valences target{std::vector<int>(n, 4), std::vector<char>(n, 0)};
  for(int v = 0; v < cm.n_vertices; ++v) {
    const std::size_t i = std::size_t(v);
    if(cm.vertex_on_border[i]) continue;
    if(!from_class[i]) { target.valence[i] = turns[i]; continue; }
    const bool convex = points.empty() || angle3[i] < 2 * std::acos(-1.);   // class 2: 2 if convex, else 6
    target.valence[i] = valence_of_rotation_sum(K[i], !convex);
    target.any_in_class[i] = K[i] != 0;
  }
  return target;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_VERTEX_WINDINGS_H
