// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_QUAD_VALENCES_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_QUAD_VALENCES_H

// The quad valence of every vertex of an exactly seamless, fold-free map: the number of integer-grid
// directions that leave it, i.e. the degree of its vertex in the quad mesh when it is an integer point
// (extract_quad_mesh()): its UV angle sum in quarter turns at an interior vertex (4 at a regular vertex,
// 3 or 5 at a +-90 degree cone), the axis directions in its closed fan at a border vertex.
//
// Exact, with sign tests only. The quadrant of a nonzero vector d is q(d) = floor(angle(d) / 90 deg),
// i.e. [0, 90) -> 0, [90, 180) -> 1, ...: it needs the signs of d_x and d_y only, and d = b - c of two
// doubles has the sign of the comparison of b and c, exactly. A rotation by 90 degrees adds 1 to it
// (mod 4). A corner (v; a, b) of a face (a after v, b before v, counter-clockwise) turns the direction
// v->a into v->b by its signed angle phi in (-180, 180) degrees, whose sign is orientation(v, a, b)
// (exact predicate); the number of quadrant boundaries it crosses, counted with that sign, is
//   (q(b - v) - q(a - v)) mod 4  if phi > 0,    -((q(a - v) - q(b - v)) mod 4)  if phi < 0,
//   0                             if the two directions coincide (a zero-area corner of angle 0).
// It does not change when both vectors are rotated by a quarter turn, so each corner is evaluated in
// its own face. Around a vertex of an exactly seamless map consecutive corners share their edge
// direction after the transition (a rotation by k quarter turns, exact), so the counts telescope in
// the unfolded fan: from the direction theta_0 of its first edge, their sum is
//   floor((theta_0 + Theta) / 90) - floor(theta_0 / 90)
// for the angle sum Theta. At an interior vertex Theta is a multiple of 90 degrees: the sum is
// Theta / 90, the axis directions in [theta_0, theta_0 + Theta). A border fan holds the axis directions
// of the closed interval [theta_0, theta_0 + Theta): the sum, plus 1 when theta_0 is itself an axis
// direction (its first edge is exactly axis-parallel). On a fold-free map (every corner of angle in
// (0, 180) degrees) every count is determined; a corner of 180 degrees or a zero-length edge (only in a
// zero-area triangle) leaves it undetermined, and fold-overs make the sum a signed winding number that
// no quad mesh has (quad_valences() refuses such maps). A zero-area triangle with three distinct
// corners is taken as the limit of a thin positive one (as the quad extraction collapses it,
// quad/collapsed_faces.h): its middle corner turns by +180 degrees, which crosses exactly 2 quadrant
// boundaries from any direction, its two others by 0. Where its long side is a border edge, the face folds onto the
// border and its middle vertex is a border point of the quad mesh (on_border). Interior in the mesh, the rest of its
// fan is a border fan whose first edge runs along the long side: its middle corner counts 1 if the long side is
// axis-parallel, else 0; a border vertex of the mesh (an ear: a short side on the border too) has its border fan's
// first edge counted already, and the corner counts 0. (Counted 2, a point of a straight axis-parallel border was called
// valence 4 where the quad mesh has 3, an ear's corner 4 where it has 2, and the extraction's own check failed on
// them, 2026-11-30.)

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// The valence nearest 4 of a quad vertex whose field rotations sum to K quarter turns (mod 4, field_rotation_sums()):
// its angle sum is K quarter turns modulo 4, so 4, 5 (a -90 degree cone), 3 (a +90 degree one), and for a half turn
// 2 or 6 (`six`), which the rotations cannot tell apart
inline int valence_of_rotation_sum(int K, bool six)
{
  return K == 0 ? 4 : K == 1 ? 5 : K == 3 ? 3 : (six ? 6 : 2);
}

struct Quad_valence_result
{
  std::vector<int> valence;          // per vertex (Corner_mesh numbering)
  std::vector<char> on_border;       // per vertex: on the border of the quad mesh (a border vertex of the mesh, or the
                                     // middle vertex of a zero-area face whose long side is a border edge)
  std::vector<int> border;           // the vertices with on_border
};

// q(b - a): the quadrant of the vector from a to b (-1 if a == b)
inline int quadrant(double ax, double ay, double bx, double by)
{
  // by the signs (sx, sy) of the vector: quadrant 0 = {x > 0, y >= 0}, 1 = {x <= 0, y > 0}, 2 = {x < 0, y <= 0},
  // 3 = {x >= 0, y < 0}; a table instead of branches (the signs of UV edges are unpredictable)
  static const int table[9] = {2, 2, 1,  3, -1, 1,  3, 0, 0};   // index 3 (sx + 1) + (sy + 1)
  const int sx = (bx > ax) - (bx < ax), sy = (by > ay) - (by < ay);
  return table[3 * (sx + 1) + (sy + 1)];
}

// the signed number of quadrant boundaries crossed by a corner from the quadrants qa, qb of its edges
// (quadrant(): -1 for an edge of length 0) and the orientation o of its triangle; false if undetermined
inline bool quarter_crossings(int qa, int qb, CGAL::Orientation o, int& crossings)
{
  if(qa < 0 || qb < 0) return false;
  if(o == CGAL::COLLINEAR) {
    if(qa != qb) return false;           // opposite directions: +-180 degrees
    crossings = 0;
    return true;
  }
  crossings = o == CGAL::LEFT_TURN ? ((qb - qa) % 4 + 4) % 4 : -(((qa - qb) % 4 + 4) % 4);
  return true;
}

// the signed number of quadrant boundaries crossed by the corner at q of the triangle (q, a, b)
// (counter-clockwise: from the edge to a to the edge to b); false if undetermined
inline bool corner_quarter_crossings(const double q[2], const double a[2], const double b[2], int& crossings)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  return quarter_crossings(quadrant(q[0], q[1], a[0], a[1]), quadrant(q[0], q[1], b[0], b[1]),
                           CGAL::orientation(P(q[0], q[1]), P(a[0], a[1]), P(b[0], b[1])), crossings);
}

// the same for the corner h of the corner mesh (its UVs)
inline bool corner_quarter_crossings(const Corner_mesh& cm, int h, int& crossings)
{
  const int a = cm.next[h], b = cm.prev[h];
  const double q[2] = {cm.u[h], cm.v[h]}, pa[2] = {cm.u[a], cm.v[a]}, pb[2] = {cm.u[b], cm.v[b]};
  return corner_quarter_crossings(q, pa, pb, crossings);
}

// Precondition: the corner UVs of `cm` form an exactly seamless map without fold-overs and without
// zero-area triangles that have two corners at one UV point (find_fold_overs().blocks_quads() is false).
inline Quad_valence_result quad_valences(const Corner_mesh& cm)
{
  Quad_valence_result r;
  r.valence.assign(cm.n_vertices, 0);
  r.on_border = cm.vertex_on_border;
  for(int h = 0; h < cm.n_halfedges; ++h) {
    if(cm.is_border_halfedge(h)) continue;
    const int v = cm.target[h];
    int c = 0;
    if(!corner_quarter_crossings(cm, h, c)) {        // the middle corner of collinear ones (no zero-length edge)
      CGAL_assertion((cm.u[h] != cm.u[cm.next[h]] || cm.v[h] != cm.v[cm.next[h]]) &&
                     (cm.u[h] != cm.u[cm.prev[h]] || cm.v[h] != cm.v[cm.prev[h]]));
      const int l = cm.prev[h];                      // the long side
      if(cm.is_border_halfedge(cm.opp[l])) {        // (a border vertex: its own first edge counted already, below)
        c = !cm.vertex_on_border[v] && (cm.u[l] == cm.u[cm.prev[l]] || cm.v[l] == cm.v[cm.prev[l]]) ? 1 : 0;
        r.on_border[std::size_t(v)] = 1;
      } else {
        c = 2;
      }
    }
    r.valence[v] += c;
    const int a = cm.next[h];                        // v -> target(a): the first edge of a border fan
    if(cm.is_border_halfedge(cm.opp[a]) && (cm.u[a] == cm.u[h] || cm.v[a] == cm.v[h])) ++r.valence[v];
  }
  for(int v = 0; v < cm.n_vertices; ++v)
    if(r.on_border[std::size_t(v)]) r.border.push_back(v);
  return r;
}

// An interior vertex that winds around its point by 7 quarter turns or more, or -1. A cone of 5 quarter turns wound
// back to 1 (valence 1, which no quad mesh has) leaves its 4 missing quarter turns at such a vertex (the angle sums are
// fixed by the Euler characteristic), not always nearby: the dragon's are 4 to more than 40 face rings away. Without
// one, a cone of 1 is most likely the map's own.
inline int vertex_winding_twice(const Corner_mesh& cm, const std::vector<int>& valence)
{
  for(int w = 0; w < cm.n_vertices; ++w)
    if(!cm.vertex_on_border[w] && valence[std::size_t(w)] >= 7) return w;
  return -1;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_QUAD_VALENCES_H
