// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_MATRICES_H
#define CGAL_SEAMLESS_SNAPPING_MATRICES_H

#include <CGAL/Seamless_snapping/Snap_report.h>
#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/matrices/corner_uv_matrices.h>
#include <CGAL/Seamless_snapping/internal/parameters.h>
#include <CGAL/Seamless_snapping/is_exact_integer_grid_map.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>

#include <Eigen/Core>

#include <string>

namespace CGAL {
namespace Seamless_snapping {

namespace internal {

// `check(mesh with uv)` on the mesh that V, F, UV, FUV describe (welded with `weld_vertices(true)`);
// false for matrices that do not describe a valid mesh
template <class DerivedV, class DerivedF, class DerivedUV, class DerivedFUV, class NamedParameters, class Check>
bool check_on_matrices(const Eigen::MatrixBase<DerivedV>& V, const Eigen::MatrixBase<DerivedF>& F,
                       const Eigen::MatrixBase<DerivedUV>& UV, const Eigen::MatrixBase<DerivedFUV>& FUV,
                       const NamedParameters& np, const Check& check)
{
  const bool weld = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, snap_np::weld_vertices), false);
  Matrix_mesh_with_uv m;
  std::string message;
  return mesh_from_matrices(V, F, UV, FUV, weld, m, message) == SUCCESS && check(m);
}

} // namespace internal

/*!
 * \ingroup PkgSeamlessSnappingRef
 * Matrix entry point in libigl's convention: the same computation as the mesh version of
 * `snap_seamless_parameterization()` (Sec. 4-5), on a triangle mesh given as matrices.
 *
 * \param V   `#V x 3` vertex positions (any real scalar type)
 * \param F   `#F x 3` vertex indices per face, 0-based, counter-clockwise (any integer type)
 * \param UV  `#UV x 2` texture coordinates (UV units)
 * \param FUV `#F x 3` indices into `UV`, 0-based: corner `k` of face `f` has the UV `UV.row(FUV(f, k))`.
 *            Seams are where the two faces of an edge use different UV values for a vertex.
 * \param UV_out, FUV_out the result, written on `SUCCESS` only. `FUV_out` equals `FUV`, and `UV_out` equals
 *            `UV` except for the moved rows, unless corners that shared a UV row were snapped to different
 *            values; such corners get new rows appended to `UV_out` (they never occur for corners of one sector).
 * \param np  the named parameters of the mesh version (`weld_vertices(true)` merges bit-identical rows of `V`
 *            first: use it when `V` has duplicated vertices along the seams, as cut meshes do).
 *
 * \return the `Snap_report` of the mesh version; `INVALID_INPUT` also for matrices of the wrong shape, an
 *         index out of range, a non-finite value, or connectivity that is not an oriented 2-manifold
 *         (the message names the matrix, row and column). On any failure `UV_out` and `FUV_out` are untouched.
 *         The vertex numbers in the messages of the snap itself (a cone, a cut edge "(a, b)") count the vertices of
 *         the mesh built from the matrices: the rows of `V` that `F` uses, in their order, and with `weld_vertices(true)`
 *         the rows at one bit-identical position as one vertex (its first row); they are rows of `V` where every row
 *         is used and distinct.
 */
template <class DerivedV, class DerivedF, class DerivedUV, class DerivedFUV,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Snap_report snap_seamless_parameterization(const Eigen::MatrixBase<DerivedV>& V, const Eigen::MatrixBase<DerivedF>& F,
                                           const Eigen::MatrixBase<DerivedUV>& UV, const Eigen::MatrixBase<DerivedFUV>& FUV,
                                           Eigen::MatrixXd& UV_out, Eigen::MatrixXi& FUV_out,
                                           const NamedParameters& np = CGAL::parameters::default_values())
{
  const bool weld = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, snap_np::weld_vertices), false);
  internal::Matrix_mesh_with_uv m;
  Snap_report report;
  report.status = internal::mesh_from_matrices(V, F, UV, FUV, weld, m, report.message);
  if(report.status != SUCCESS) return report;
  report = snap_seamless_parameterization(m.mesh, m.uv, np);
  if(report.status == SUCCESS) internal::matrices_from_corner_uv(m, UV, FUV, UV_out, FUV_out);
  return report;
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 * Matrix version of `is_exactly_seamless()` (libigl convention, see the matrix version of
 * `snap_seamless_parameterization()` for `V`, `F`, `UV`, `FUV` and `weld_vertices`). Returns `false`
 * for matrices that do not describe a valid mesh.
 */
template <class DerivedV, class DerivedF, class DerivedUV, class DerivedFUV,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
bool is_exactly_seamless(const Eigen::MatrixBase<DerivedV>& V, const Eigen::MatrixBase<DerivedF>& F,
                         const Eigen::MatrixBase<DerivedUV>& UV, const Eigen::MatrixBase<DerivedFUV>& FUV,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::check_on_matrices(V, F, UV, FUV, np, [&](const internal::Matrix_mesh_with_uv& m) {
    return is_exactly_seamless(m.mesh, m.uv, np);
  });
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 * Matrix version of `is_exact_integer_grid_map()` (libigl convention, see the matrix version of
 * `snap_seamless_parameterization()` for `V`, `F`, `UV`, `FUV` and `weld_vertices`; `grid_scale` as in
 * the mesh version). Returns `false` for matrices that do not describe a valid mesh.
 */
template <class DerivedV, class DerivedF, class DerivedUV, class DerivedFUV,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
bool is_exact_integer_grid_map(const Eigen::MatrixBase<DerivedV>& V, const Eigen::MatrixBase<DerivedF>& F,
                               const Eigen::MatrixBase<DerivedUV>& UV, const Eigen::MatrixBase<DerivedFUV>& FUV,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::check_on_matrices(V, F, UV, FUV, np, [&](const internal::Matrix_mesh_with_uv& m) {
    return is_exact_integer_grid_map(m.mesh, m.uv, np);
  });
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_MATRICES_H
