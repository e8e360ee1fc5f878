// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_DIAGNOSE_SEAMLESSNESS_H
#define CGAL_SEAMLESS_SNAPPING_DIAGNOSE_SEAMLESSNESS_H

#include <CGAL/Seamless_snapping/Snap_report.h>
#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/parameters.h>
#include <CGAL/Seamless_snapping/internal/surface/exact_uv_check.h>
#include <CGAL/Seamless_snapping/internal/surface/snap_inputs.h>
#include <CGAL/Seamless_snapping/internal/surface/snap_pipeline.h>

#include <CGAL/Mpzf.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * The result of `diagnose_seamlessness()`: how many of the constraint rows that
 * `snap_seamless_parameterization()` would enforce hold exactly, and where the worst one fails.
 * \tparam TriangleMesh the mesh type
 */
template <class TriangleMesh>
struct Seamless_diagnosis
{
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  Status status = INVALID_INPUT;  ///< `SUCCESS` iff the constraints could be extracted; otherwise the snap's own status (e.g. `NOT_QUARTER_TURN_SEAMLESS`)
  std::string message;            ///< why the extraction failed, or a one-line summary
  bool exact = false;             ///< every row holds exactly (rational arithmetic), valid with `SUCCESS`
  std::size_t rows = 0;           ///< rows checked: 2 per cut edge (Eq. 4), 1 per align edge (Eq. 5), 1 per connection or cycle constraint (Eq. 6-8)
  std::size_t violated_rows = 0;  ///< rows with a nonzero exact residual
  std::size_t violated_connections = 0; ///< of those, rows of connection and cycle constraints

  /// \name The worst violated row (largest exact |C_i u - b_i|), when `violated_rows > 0`
  /// @{
  long row = -1;                  ///< its index among the rows
  std::string kind;               ///< "transition", "alignment", "transition or alignment" (an aligned cut edge) or "connection"
  edge_descriptor edge;           ///< the edge the row comes from (valid unless `kind` is "connection")
  std::size_t connection = 0;     ///< index of the connection constraint (when `kind` is "connection")
  std::vector<halfedge_descriptor> corners; ///< one corner (target(h), face(h)) per sector in the row
  std::string residual;           ///< the exact residual, in UV units, as a decimal fraction "p/q" or integer "p"
  double residual_double = 0;     ///< the same, rounded to double
  /// @}
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 * checks the corner UV map `uv` against exactly the constraints that `snap_seamless_parameterization()`
 * would enforce with the same named parameters (fitted or given rotations `k`, boundary and feature
 * alignment with the alignment tolerance, connection and cycle constraints), evaluating every row in
 * rational arithmetic (Sec. 5, Eq. 4-8), and reports the worst violated row: where it is (edge,
 * connection constraint, corners of its sectors) and its exact residual. Nothing is modified.
 *
 * \param tm a triangle mesh, \param uv its corner UV map (as for the snap),
 * \param np the named parameters of `snap_seamless_parameterization()` (those that do not change
 *        the constraints, e.g. `repair_flips`, are ignored)
 */
template <class TriangleMesh, class HalfedgeUVMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Seamless_diagnosis<TriangleMesh> diagnose_seamlessness(const TriangleMesh& tm, HalfedgeUVMap uv,
                                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh> GT;
  Seamless_diagnosis<TriangleMesh> d;
  const internal::Snap_inputs<TriangleMesh, NamedParameters> in(tm, np);
  internal::Snap_state<TriangleMesh> S;
  Snap_report report;
  d.status = internal::extract_seams(tm, uv, [&](typename GT::edge_descriptor e) { return in.seam_of(e); }, in.has_seams,
                                     [&](typename GT::halfedge_descriptor h) { return in.rotation_of(h); }, in.has_rotations,
                                     [&](typename GT::edge_descriptor e) { return in.constrained_of(e); }, in.has_constrained,
                                     in.options, S, report, d.message);
  if(d.status == SUCCESS) d.status = internal::build_constraints(in.options, S, report, d.message);
  if(d.status != SUCCESS) return d;

  const internal::Constraint_rows& rows = S.full;
  d.rows = rows.size();
  CGAL::Mpzf worst(0);
  for(std::size_t i = 0; i < rows.size(); ++i) {
    CGAL::Mpzf r = internal::exact_row_residual(rows, i, S.st.ubar);   // C_i u - b_i
    if(r.is_zero()) continue;
    ++d.violated_rows;
    if(rows.edge[i] < 0) ++d.violated_connections;
    if(r.sign() == CGAL::NEGATIVE) r = -r;
    if(d.row < 0 || CGAL::compare(worst, r) == CGAL::SMALLER) { worst = r; d.row = long(i); }
  }
  d.exact = d.violated_rows == 0;
  if(d.exact) {
    d.message = "all " + std::to_string(d.rows) + " constraint rows hold exactly";
    return d;
  }
  const std::size_t i = std::size_t(d.row);
  const int edge = rows.edge[i];
  std::string where;
  if(edge >= 0) {
    const std::size_t ei = std::size_t(edge);
    const bool cut = S.st.is_cut[ei] != 0;
    const bool aligned = S.al.component.size() > ei && S.al.component[ei] >= 0;
    d.kind = cut && aligned ? "transition or alignment" : (cut ? "transition" : "alignment");
    d.edge = S.desc.edges[ei];
    where = "edge " + internal::vertex_pair_name(S.cm, S.cm.edge_halfedge[ei]);
  } else {
    d.kind = "connection";
    d.connection = std::size_t(-1 - edge);
    where = internal::connection_name(d.connection);
  }
  for(std::size_t k = rows.start[i]; k < rows.start[i + 1]; ++k) {
    const int sector = rows.col[k] / 2;
    const auto h = S.desc.halfedges[std::size_t(S.st.sector_corner[std::size_t(sector)])];
    if(d.corners.empty() || d.corners.back() != h) d.corners.push_back(h);
  }
  // the pipeline works on the UVs scaled by 2^-uv_exponent (exactly); the residual goes back to UV units
  const int e = S.cm.uv_exponent;
  CGAL::Gmpq residual(internal::exact_row_residual(rows, i, S.st.ubar));
  const CGAL::Gmpz power = CGAL::Gmpz(1) << (unsigned long)(e < 0 ? -e : e);
  residual = e < 0 ? residual / CGAL::Gmpq(power) : residual * CGAL::Gmpq(power);
  std::ostringstream os;
  os << residual;
  d.residual = os.str();
  d.residual_double = CGAL::to_double(residual);
  d.message = std::to_string(d.violated_rows) + " of " + std::to_string(d.rows) + " constraint rows are violated; worst: row " +
              std::to_string(d.row) + " (" + d.kind + ", " + where + "), residual " +
              internal::format_double(d.residual_double, 6) + " UV units (exactly " + d.residual + ")";
  return d;
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_DIAGNOSE_SEAMLESSNESS_H
