// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_MATRICES_CORNER_UV_MATRICES_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_MATRICES_CORNER_UV_MATRICES_H

// libigl's (V, F, UV, FUV) matrices <-> a Surface_mesh with a corner UV map.
//   V   #V x 3 positions,          F   #F x 3 vertex indices (0-based, counter-clockwise),
//   UV  #UV x 2 texture coords,    FUV #F x 3 indices into UV (corner k of face f has UV row FUV(f, k)).
// The matrices go through the OBJ reader's soup -> mesh step (IO/OBJ.h), so they get the same
// checks (indices in range, finite values, manifold and oriented connectivity, optional welding of
// bit-identical vertices) and the same messages, with "F:<row>" in place of a file line.

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/Status.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

typedef CGAL::Simple_cartesian<double> Matrix_kernel;
typedef CGAL::Surface_mesh<Matrix_kernel::Point_3> Matrix_mesh;
typedef Matrix_mesh::Property_map<Matrix_mesh::Halfedge_index, Matrix_kernel::Point_2> Matrix_uv_map;

// The mesh and corner map of the matrices, and for each face row f and corner k the halfedge
// whose target is that corner (uv[h] = UV of target(h) in face(h)).
struct Matrix_mesh_with_uv
{
  Matrix_mesh mesh;
  Matrix_uv_map uv;
  std::vector<std::array<Matrix_mesh::Halfedge_index, 3> > corner;   // [f][k]: target(h) is corner k of row f
};

template <class DV, class DF, class DUV, class DFUV>
Status mesh_from_matrices(const Eigen::MatrixBase<DV>& V, const Eigen::MatrixBase<DF>& F,
                          const Eigen::MatrixBase<DUV>& UV, const Eigen::MatrixBase<DFUV>& FUV, bool weld,
                          Matrix_mesh_with_uv& out, std::string& message)
{
  auto fail = [&](const std::string& why) { message = why; return INVALID_INPUT; };
  if(V.cols() != 3) return fail("V must have 3 columns (x, y, z), it has " + std::to_string(V.cols()));
  if(F.cols() != 3) return fail("F must have 3 columns (triangles), it has " + std::to_string(F.cols()));
  if(UV.cols() != 2) return fail("UV must have 2 columns (u, v), it has " + std::to_string(UV.cols()));
  if(FUV.rows() != F.rows() || FUV.cols() != 3)
    return fail("FUV must be #F x 3 = " + std::to_string(F.rows()) + " x 3, it is " + std::to_string(FUV.rows()) +
                " x " + std::to_string(FUV.cols()));
  IO::internal::Obj_soup soup;
  soup.points.resize(std::size_t(V.rows()));
  for(Eigen::Index i = 0; i < V.rows(); ++i)
    for(int c = 0; c < 3; ++c) soup.points[std::size_t(i)][c] = double(V(i, c));
  soup.uvs.resize(std::size_t(UV.rows()));
  for(Eigen::Index i = 0; i < UV.rows(); ++i)
    for(int c = 0; c < 2; ++c) {
      const double x = double(UV(i, c));
      if(!std::isfinite(x)) return fail("UV(" + std::to_string(i) + ", " + std::to_string(c) + ") is not finite");
      soup.uvs[std::size_t(i)][c] = x;
    }
  for(Eigen::Index f = 0; f < F.rows(); ++f) {
    std::array<std::size_t, 3> fv, ft;
    for(int k = 0; k < 3; ++k) {
      const long long v = (long long)(F(f, k)), t = (long long)(FUV(f, k));
      if(v < 0 || v >= (long long)(V.rows()))
        return fail("F(" + std::to_string(f) + ", " + std::to_string(k) + ") = " + std::to_string(v) +
                    " is not a row of V (0.." + std::to_string(V.rows() - 1) + ")");
      if(t < 0 || t >= (long long)(UV.rows()))
        return fail("FUV(" + std::to_string(f) + ", " + std::to_string(k) + ") = " + std::to_string(t) +
                    " is not a row of UV (0.." + std::to_string(UV.rows() - 1) + ")");
      fv[k] = std::size_t(v);
      ft[k] = std::size_t(t);
    }
    soup.face_v.push_back(fv);
    soup.face_vt.push_back(ft);
    soup.face_line.push_back(std::size_t(f));
  }
  for(const std::array<double, 3>& p : soup.points)
    for(double x : p)
      if(!std::isfinite(x)) return fail("V has a value that is not finite");

  Matrix_mesh_with_uv& result = out;   // a fresh object of the caller's
  result.uv = result.mesh.add_property_map<Matrix_mesh::Halfedge_index, Matrix_kernel::Point_2>("h:uv").first;
  const Status s = IO::internal::build_mesh(soup, weld, result.mesh, get(CGAL::vertex_point, result.mesh), result.uv,
                                            IO::internal::Soup_naming{"V, F", true}, message, &result.corner);
  return s;
}

// New (UV, FUV) from the corner map: FUV keeps its indices and UV its rows wherever every corner
// that shares a UV row got the same value; a row shared by corners whose values now differ keeps
// its first value and the others get new rows appended (never happens for corners of one sector).
template <class DUV, class DFUV>
void matrices_from_corner_uv(const Matrix_mesh_with_uv& m, const Eigen::MatrixBase<DUV>& UV,
                             const Eigen::MatrixBase<DFUV>& FUV, Eigen::MatrixXd& UV_out, Eigen::MatrixXi& FUV_out)
{
  std::vector<std::array<double, 2> > rows(std::size_t(UV.rows()));
  std::vector<char> set(rows.size(), 0);
  std::map<std::pair<std::size_t, std::pair<double, double> >, std::size_t> extra;   // (row, value) -> new row
  Eigen::MatrixXi fuv(FUV.rows(), 3);
  for(std::size_t i = 0; i < rows.size(); ++i) rows[i] = {double(UV(Eigen::Index(i), 0)), double(UV(Eigen::Index(i), 1))};
  for(std::size_t f = 0; f < m.corner.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      const std::size_t r = std::size_t(FUV(Eigen::Index(f), k));
      const Matrix_kernel::Point_2 p = get(m.uv, m.corner[f][std::size_t(k)]);
      std::size_t target = r;
      if(!set[r]) { rows[r] = {p.x(), p.y()}; set[r] = 1; }
      else if(!(rows[r][0] == p.x() && rows[r][1] == p.y())) {
        auto ins = extra.emplace(std::make_pair(r, std::make_pair(p.x(), p.y())), rows.size());
        if(ins.second) { rows.push_back({p.x(), p.y()}); set.push_back(1); }
        target = ins.first->second;
      }
      fuv(Eigen::Index(f), k) = int(target);
    }
  UV_out.resize(Eigen::Index(rows.size()), 2);
  for(std::size_t i = 0; i < rows.size(); ++i) { UV_out(Eigen::Index(i), 0) = rows[i][0]; UV_out(Eigen::Index(i), 1) = rows[i][1]; }
  FUV_out = fuv;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_MATRICES_CORNER_UV_MATRICES_H
