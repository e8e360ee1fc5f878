// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_REFERENCE_SHAPES_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_REFERENCE_SHAPES_H

// The reference shape of every face for the untangling energy (untangling_energy.h): the shape the
// untangler pulls the UV triangle towards, i.e. the term that keeps the map close to the input.
// - A face whose input UV triangle is positive and not too thin (longest edge^2 / (2 area) <= 10, i.e.
//   an aspect ratio up to 10) keeps its input UV triangle: there J = I, the energy is at its minimum,
//   and the untangler has no reason to move it.
// - Any other face (flipped, degenerate or a sliver in the input, or next to a vertex whose input angle
//   sum is not its valence, vertex_windings.h) gets its 3D triangle, laid flat and
//   scaled by the UV/3D scale around it (the mean over its corners of the median sqrt(A_uv / A_3d) of the
//   good faces at the vertex; the median over all good faces where a vertex has none), or, when the 3D
//   triangle is itself that thin or no 3D positions are given, an equilateral triangle of the UV area
//   the scale gives (or the median UV area of the good faces).

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/index_lists.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/untangling/untangling_energy.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

constexpr double reference_max_aspect = 10;

// The corners of every face, counter-clockwise: halfedges h, next(h), next(next(h)) (the corner of
// target(h) in face(h)), from the smallest halfedge of the face; and the faces of every vertex.
struct Face_corners
{
  std::vector<std::array<int, 3> > halfedge;   // per face
  Index_lists vertex_faces;                    // per vertex: the faces of its corners, in increasing face order

  explicit Face_corners(const Corner_mesh& cm) : halfedge(std::size_t(cm.n_faces), std::array<int, 3>{{-1, -1, -1}})
  {
    for(int h : face_first_halfedges(cm)) halfedge[std::size_t(cm.face[h])] = {{h, cm.next[h], cm.prev[h]}};
    vertex_faces.build(cm.n_vertices, [&](auto emit) {
      for(std::size_t f = 0; f < halfedge.size(); ++f)
        for(int h : halfedge[f]) emit(cm.target[h], int(f));
    });
  }
};

// twice the signed area and the thinness longest edge^2 / (2 area) of a triangle (2D)
inline double twice_area_2(const double a[2], const double b[2], const double c[2])
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

inline double thinness(double twice_area, double e0, double e1, double e2)
{
  return twice_area > 0 ? (std::max)({e0, e1, e2}) / twice_area : HUGE_VAL;   // e_i: squared edge lengths
}

// `from_3d`: faces that get the 3D reference in any case (e.g. those around a vertex whose input UV angle
// sum is not its valence: their input triangles are part of a fold, even where positive)
inline std::vector<Reference_triangle> reference_triangles(const Corner_mesh& cm, const Seam_topology& st,
                                                           const Face_corners& fc, const std::vector<double>& ubar,
                                                           const std::vector<double>& points, const std::vector<char>& from_3d)
{
  const std::size_t nf = std::size_t(cm.n_faces);
  std::vector<Reference_triangle> ref(nf);
  std::vector<char> good(nf, 0);
  std::vector<double> uv_area(nf, 0), xyz_area(nf, 0);
  auto uv_of = [&](int h, double p[2]) { const int s = st.sector_of[h]; p[0] = ubar[2 * s]; p[1] = ubar[2 * s + 1]; };
  auto xyz = [&](int h, int c) { return points[3 * std::size_t(cm.target[h]) + c]; };
  auto sq3 = [&](int a, int b) {
    double d = 0;
    for(int c = 0; c < 3; ++c) d += (xyz(b, c) - xyz(a, c)) * (xyz(b, c) - xyz(a, c));
    return d;
  };
  std::vector<double> good_areas;
  for(std::size_t f = 0; f < nf; ++f) {
    const std::array<int, 3>& h = fc.halfedge[f];
    double p[3][2];
    for(int m = 0; m < 3; ++m) uv_of(h[m], p[m]);
    const double a2 = twice_area_2(p[0], p[1], p[2]);
    auto sq2 = [&](int i, int j) { return (p[j][0] - p[i][0]) * (p[j][0] - p[i][0]) + (p[j][1] - p[i][1]) * (p[j][1] - p[i][1]); };
    uv_area[f] = 0.5 * a2;
    if(!from_3d[f] && thinness(a2, sq2(0, 1), sq2(1, 2), sq2(2, 0)) <= reference_max_aspect && ref[f].set(p[0], p[1], p[2])) {
      good[f] = 1;
      good_areas.push_back(uv_area[f]);
    }
    if(!points.empty()) {
      const double e1[3] = {xyz(h[1], 0) - xyz(h[0], 0), xyz(h[1], 1) - xyz(h[0], 1), xyz(h[1], 2) - xyz(h[0], 2)};
      const double e2[3] = {xyz(h[2], 0) - xyz(h[0], 0), xyz(h[2], 1) - xyz(h[0], 1), xyz(h[2], 2) - xyz(h[0], 2)};
      const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      xyz_area[f] = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
  }
  auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  // UV / 3D length scale of a good face; per vertex the median over its good faces, else over all good faces. Computed
  // only for the vertices of the other faces, which are few (the 302K-face bunny of ../shared/large: 62 -> 23 ms against
  // a list of scales for every vertex, the same references)
  auto face_scale = [&](std::size_t f) { return std::sqrt(uv_area[f] / xyz_area[f]); };
  auto has_scale = [&](std::size_t f) { return good[f] && xyz_area[f] > 0; };
  double median_uv_area = -1, global_scale = -1;     // computed where first needed
  std::vector<double> scales;
  auto vertex_scale = [&](int v) {
    scales.clear();
    for(int g : fc.vertex_faces[v]) if(has_scale(std::size_t(g))) scales.push_back(face_scale(std::size_t(g)));
    if(!scales.empty()) return median(scales);
    if(global_scale < 0) {
      for(std::size_t g = 0; g < nf; ++g) if(has_scale(g)) scales.push_back(face_scale(g));
      global_scale = scales.empty() ? 0. : median(scales);
    }
    return global_scale;
  };
  for(std::size_t f = 0; f < nf; ++f) {
    if(good[f]) continue;
    const std::array<int, 3>& h = fc.halfedge[f];
    double scale = 0;
    for(int m = 0; m < 3; ++m) scale += vertex_scale(cm.target[h[m]]) / 3;
    const double r0[2] = {0, 0};
    if(xyz_area[f] > 0 && scale > 0) {
      // the 3D triangle in its plane: h[0] at the origin, h[1] on the x axis
      const double l01 = std::sqrt(sq3(h[0], h[1]));
      const double cross2 = 2 * xyz_area[f];
      double dot = 0;
      for(int c = 0; c < 3; ++c) dot += (xyz(h[1], c) - xyz(h[0], c)) * (xyz(h[2], c) - xyz(h[0], c));
      const double r1[2] = {scale * l01, 0}, r2[2] = {scale * dot / l01, scale * cross2 / l01};
      if(thinness(cross2, sq3(h[0], h[1]), sq3(h[1], h[2]), sq3(h[2], h[0])) <= reference_max_aspect && ref[f].set(r0, r1, r2))
        continue;
    }
    // equilateral triangle of area A: side a with (sqrt(3) / 4) a^2 = A
    if(median_uv_area < 0) {
      if(good_areas.empty()) good_areas.push_back(1.);   // no usable face at all: unit areas
      median_uv_area = median(good_areas);
    }
    const double A = (xyz_area[f] > 0 && scale > 0) ? scale * scale * xyz_area[f] : median_uv_area;
    const double a = std::sqrt(4 * A / std::sqrt(3.));
    const double r1[2] = {a, 0}, r2[2] = {0.5 * a, 0.5 * std::sqrt(3.) * a};
    if(!ref[f].set(r0, r1, r2)) {
      const double u1[2] = {1, 0}, u2[2] = {0.5, 0.5 * std::sqrt(3.)};
      ref[f].set(r0, u1, u2);
    }
  }
  return ref;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_REFERENCE_SHAPES_H
