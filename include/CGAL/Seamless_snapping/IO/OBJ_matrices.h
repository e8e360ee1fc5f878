// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_IO_OBJ_MATRICES_H
#define CGAL_SEAMLESS_SNAPPING_IO_OBJ_MATRICES_H

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/Status.h>

#include <Eigen/Core>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace IO {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * reads an OBJ file with per-corner texture coordinates into libigl-style matrices, in the file's own
 * layout: `V` (`#v` x 3) and `UV` (`#vt` x 2) in file order, `F` and `FUV` (`#f` x 3) with 0-based indices.
 * Same syntax and checks as `read_OBJ_with_corner_uvs()` (triangles only, indices in range, finite
 * numbers; no mesh is built, so connectivity is not checked here). The doubles are read bit for bit.
 * The matrices are written only on `SUCCESS`; otherwise `message` says why, as `"<filename>:<line>: <reason>"`
 * for an error in the file.
 *
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{weld_vertices}
 *     \cgalParamDescription{merge `v` lines with bit-identical coordinates into one row of `V` (the first in the file;
 *                           the rows keep the file order of their first occurrence, and `F` refers to them): the
 *                           cut meshes of libigl/Directional, whose vertices are duplicated along the seams, become the
 *                           closed surface again. `0.0` and `-0.0` are not merged.}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{`false`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::weld_vertices()`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{number_of_threads}
 *     \cgalParamDescription{with 2 or more, a file of 4 MiB or more is parsed in two halves at once, on two threads
 *                           (the same matrices and messages as on one thread); `0` takes the machine's cores}
 *     \cgalParamType{unsigned integer}
 *     \cgalParamDefault{`1`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::number_of_threads()`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \sa `write_OBJ_matrices()`, `read_OBJ_with_corner_uvs()`
 */
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
Status read_OBJ_matrices(const std::string& filename, Eigen::MatrixXd& V, Eigen::MatrixXi& F,
                         Eigen::MatrixXd& UV, Eigen::MatrixXi& FUV, std::string& message,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const bool weld = choose_parameter(get_parameter(np, snap_np::weld_vertices), false);

  internal::Obj_soup soup;
  if(internal::parse_obj_file(filename, soup, message, Seamless_snapping::internal::number_of_threads_parameter(np)) != SUCCESS)
    return INVALID_INPUT;
  if(soup.points.size() > std::size_t(2147483647) || soup.uvs.size() > std::size_t(2147483647)) {
    message = filename + ": more vertices or texture coordinates than 32-bit indices hold";
    return INVALID_INPUT;
  }
  // row of V of each file vertex: its own, or with welding the row of the first bit-identical one
  std::vector<std::size_t> rep, row(soup.points.size());
  const std::size_t welded = internal::weld_representatives(soup.points, weld, rep);
  std::size_t rows = 0;
  for(std::size_t i = 0; i < soup.points.size(); ++i) row[i] = rep[i] == i ? rows++ : row[rep[i]];
  Eigen::MatrixXd v(Eigen::Index(rows), 3), uv(Eigen::Index(soup.uvs.size()), 2);
  Eigen::MatrixXi f(Eigen::Index(soup.face_v.size()), 3), fuv(Eigen::Index(soup.face_v.size()), 3);
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    if(rep[i] == i)
      for(int c = 0; c < 3; ++c) v(Eigen::Index(row[i]), c) = soup.points[i][std::size_t(c)];
  for(std::size_t i = 0; i < soup.uvs.size(); ++i)
    for(int c = 0; c < 2; ++c) uv(Eigen::Index(i), c) = soup.uvs[i][std::size_t(c)];
  for(std::size_t i = 0; i < soup.face_v.size(); ++i)
    for(int k = 0; k < 3; ++k) {
      f(Eigen::Index(i), k) = int(row[soup.face_v[i][std::size_t(k)]]);
      fuv(Eigen::Index(i), k) = int(soup.face_vt[i][std::size_t(k)]);
    }
  V.swap(v); F.swap(f); UV.swap(uv); FUV.swap(fuv);
  message = "read " + std::to_string(F.rows()) + " faces, " + std::to_string(V.rows()) + " vertices, " +
            std::to_string(UV.rows()) + " texture coordinates from " + filename;
  if(weld) message += "; welded " + std::to_string(welded) + " duplicated vertices";
  return SUCCESS;
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 * writes libigl-style matrices as an OBJ file: every row of `V` as a `v` line and of `UV` as a `vt` line,
 * in order, and every face as `f v/vt v/vt v/vt` (1-based), each number the shortest decimal that reads
 * back to the same double, bit for bit. Written atomically (temporary file + rename); `INVALID_INPUT` without
 * writing anything for matrices of the wrong shape, an index out of range or a non-finite value.
 */
template <class DV, class DF, class DUV, class DFUV>
Status write_OBJ_matrices(const std::string& filename, const Eigen::MatrixBase<DV>& V, const Eigen::MatrixBase<DF>& F,
                          const Eigen::MatrixBase<DUV>& UV, const Eigen::MatrixBase<DFUV>& FUV, std::string& message)
{
  auto fail = [&](const std::string& why) { message = "not writing '" + filename + "': " + why; return INVALID_INPUT; };
  if(V.cols() != 3 || UV.cols() != 2 || F.cols() != 3 || FUV.cols() != 3 || FUV.rows() != F.rows())
    return fail("expected V #V x 3, F #F x 3, UV #UV x 2, FUV #F x 3");
  std::string text;
  text.reserve(std::size_t(64 * (V.rows() + UV.rows() + F.rows())));
  // one line per row of M: `record` and the row's values; false (with `message`) at a non-finite value
  auto append_rows = [&](const char* record, const char* name, const auto& M) {
    for(Eigen::Index i = 0; i < M.rows(); ++i) {
      text += record;
      for(Eigen::Index c = 0; c < M.cols(); ++c) {
        const double x = double(M(i, c));
        if(!std::isfinite(x)) {
          fail(std::string(name) + "(" + std::to_string(i) + ", " + std::to_string(c) + ") is not finite");
          return false;
        }
        text += ' ';
        internal::append_double(text, x);
      }
      text += '\n';
    }
    return true;
  };
  if(!append_rows("v", "V", V) || !append_rows("vt", "UV", UV)) return INVALID_INPUT;
  for(Eigen::Index f = 0; f < F.rows(); ++f) {
    text += "f";
    for(int k = 0; k < 3; ++k) {
      const long long v = (long long)(F(f, k)), t = (long long)(FUV(f, k));
      if(v < 0 || v >= (long long)(V.rows()) || t < 0 || t >= (long long)(UV.rows()))
        return fail("face " + std::to_string(f) + " has an index out of range");
      text += ' ' + std::to_string(v + 1) + '/' + std::to_string(t + 1);
    }
    text += '\n';
  }
  if(internal::write_text_atomically(filename, text, message) != SUCCESS) return INVALID_INPUT;
  message = "wrote " + std::to_string(F.rows()) + " faces, " + std::to_string(V.rows()) + " vertices, " +
            std::to_string(UV.rows()) + " texture coordinates to " + filename;
  return SUCCESS;
}

} // namespace IO
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_IO_OBJ_MATRICES_H
