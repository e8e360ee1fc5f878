// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PARAMETERS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Seamless_snapping {

// Tags of the package's own named parameters. Do NOT name this namespace `internal_np`:
// inside CGAL::Seamless_snapping it would hide CGAL::internal_np (vertex_point, verbose, ...).
namespace snap_np {
enum seam_edge_map_t     { seam_edge_map };     // edge -> bool: overrides the bit-exact cut-edge test
enum rotation_map_t      { rotation_map };      // halfedge -> int k: quarter turns from face(h) to face(opposite(h))
enum align_boundary_t    { align_boundary };    // bool: align axis-parallel boundary edges (default true)
enum use_reduced_system_t{ use_reduced_system };// bool: node system of Sec. 5.3 (default true) or full sector system
enum alignment_tolerance_t{ alignment_tolerance };// double: max angle (degrees) for "axis-parallel"
enum rotation_tolerance_t{ rotation_tolerance };// double: max angle (degrees) between a transition and k*90 degrees
enum weld_vertices_t     { weld_vertices };     // bool, OBJ reading: merge vertices with bit-identical positions
enum connection_constraints_t{ connection_constraints };// range of Connection_constraint: Eq. (6), and Eq. (8) for closed paths
enum repair_flips_t      { repair_flips };      // bool: repair UV flips introduced by snapping (Sec. 5.4, default true)
} // namespace snap_np

namespace parameters {

// Everything from CGAL::parameters (verbose(), geom_traits(), default_values(), ...) is
// reachable as CGAL::Seamless_snapping::parameters::xxx as well.
using namespace CGAL::parameters;

// NAME(v)     : starts a new pack, like CGAL::parameters::NAME(v).
// NAME(v, np) : appends to an existing pack `np` (CGAL 5.5 packs cannot get new member functions).
#define CGAL_SEAMLESS_SNAPPING_ADD_NAMED_PARAMETER(TAG, NAME)                          \
  template <typename K>                                                                \
  CGAL::Named_function_parameters<K, snap_np::TAG>                                     \
  NAME(const K& k)                                                                     \
  { return CGAL::Named_function_parameters<K, snap_np::TAG>(k); }                      \
  template <typename K, typename T, typename Tag, typename Base>                       \
  CGAL::Named_function_parameters<K, snap_np::TAG,                                     \
                                  CGAL::Named_function_parameters<T, Tag, Base> >      \
  NAME(const K& k, const CGAL::Named_function_parameters<T, Tag, Base>& np)            \
  { return CGAL::Named_function_parameters<K, snap_np::TAG,                            \
                 CGAL::Named_function_parameters<T, Tag, Base> >(k, np); }

CGAL_SEAMLESS_SNAPPING_ADD_NAMED_PARAMETER(seam_edge_map_t,       seam_edge_map)
CGAL_SEAMLESS_SNAPPING_ADD_NAMED_PARAMETER(rotation_map_t,        rotation_map)
CGAL_SEAMLESS_SNAPPING_ADD_NAMED_PARAMETER(align_boundary_t,      align_boundary)
CGAL_SEAMLESS_SNAPPING_ADD_NAMED_PARAMETER(use_reduced_system_t,  use_reduced_system)
CGAL_SEAMLESS_SNAPPING_ADD_NAMED_PARAMETER(alignment_tolerance_t, alignment_tolerance)
CGAL_SEAMLESS_SNAPPING_ADD_NAMED_PARAMETER(rotation_tolerance_t,  rotation_tolerance)
CGAL_SEAMLESS_SNAPPING_ADD_NAMED_PARAMETER(weld_vertices_t,       weld_vertices)
CGAL_SEAMLESS_SNAPPING_ADD_NAMED_PARAMETER(connection_constraints_t, connection_constraints)
CGAL_SEAMLESS_SNAPPING_ADD_NAMED_PARAMETER(repair_flips_t,        repair_flips)
#undef CGAL_SEAMLESS_SNAPPING_ADD_NAMED_PARAMETER

// combine(np1, np2): every entry of np2 stacked on top of np1 (CGAL >= 5.6 offers the member
// np1.combine(np2); CGAL 5.5.1 does not).
template <typename A, typename T, typename Tag>
CGAL::Named_function_parameters<T, Tag, A>
combine(const A& a, const CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& b)
{ return CGAL::Named_function_parameters<T, Tag, A>(b.v, a); }

template <typename A, typename T, typename Tag, typename Base>
auto combine(const A& a, const CGAL::Named_function_parameters<T, Tag, Base>& b)
{
  auto inner = combine(a, static_cast<const Base&>(b));
  return CGAL::Named_function_parameters<T, Tag, decltype(inner)>(b.v, inner);
}

} // namespace parameters
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PARAMETERS_H
