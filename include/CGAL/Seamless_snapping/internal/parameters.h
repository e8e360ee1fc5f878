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
enum minimal_change_t    { minimal_change };    // bool: snap the L2-closest point of the full system (default true)
enum vertex_weight_map_t { vertex_weight_map }; // vertex -> double > 0: weight of the vertex's UVs in the L2 change
enum integer_grid_map_t  { integer_grid_map };  // bool: integer translations, cones on integer points (default false)
enum grid_scale_t        { grid_scale };        // double, a power of two: grid lines at multiples of 1/S (default 1)
enum vt_per_corner_t     { vt_per_corner };     // bool, OBJ writing: one vt per face corner (libQEx's layout)
enum pinned_corner_map_t { pinned_corner_map }; // halfedge -> bool: the UV of that corner is kept bit-identical
enum untangle_t          { untangle };          // bool: remove fold-overs inside the constraint space (default: integer_grid_map)
enum merge_cone_pairs_t  { merge_cone_pairs };  // bool: integer-grid mode, merge +-90 degree cone pairs rounded onto one point (default false)
enum separate_cone_pairs_t { separate_cone_pairs };  // bool: integer-grid mode, move cone pairs rounded onto one point apart (default false)
enum quantize_t          { quantize };          // bool: integer-grid mode, choose integer translations for a map not near an integer grid (default false)
enum max_untangle_change_t{ max_untangle_change };// double, grid cells: largest UV move the untangling may make (default: any)
enum vertex_origin_map_t { vertex_origin_map }; // quad mesh vertex -> Quad_vertex_origin: where it lies on the map (extract_quad_mesh)
enum face_origin_map_t   { face_origin_map };   // quad mesh face -> std::vector of the map's faces it covers (extract_quad_mesh)
enum max_grid_cells_t    { max_grid_cells };    // std::size_t: cells the faces' UV bounding boxes may hold (extract_quad_mesh)
enum split_valence_one_cones_t { split_valence_one_cones };  // bool: one quad for the 2 x 2 cells at a 90-degree cone (extract_quad_mesh, default true)
enum fill_branched_cells_t { fill_branched_cells };  // bool: quads for a cell covered m > 1 times around a branch point (extract_quad_mesh, default true)
enum number_of_threads_t { number_of_threads }; // unsigned: threads for independent steps (default 1; 0 = the machine's cores)
} // namespace snap_np

// The package's own named parameters, as an X-macro list (like CGAL's parameters_interface.h):
// SS_NP(tag type, function name). Every use below expands this one list.
#define CGAL_SEAMLESS_SNAPPING_NAMED_PARAMETERS(SS_NP)       \
  SS_NP(seam_edge_map_t,           seam_edge_map)            \
  SS_NP(rotation_map_t,            rotation_map)             \
  SS_NP(align_boundary_t,          align_boundary)           \
  SS_NP(use_reduced_system_t,      use_reduced_system)       \
  SS_NP(alignment_tolerance_t,     alignment_tolerance)      \
  SS_NP(rotation_tolerance_t,      rotation_tolerance)       \
  SS_NP(weld_vertices_t,           weld_vertices)            \
  SS_NP(connection_constraints_t,  connection_constraints)   \
  SS_NP(repair_flips_t,            repair_flips)             \
  SS_NP(minimal_change_t,          minimal_change)           \
  SS_NP(vertex_weight_map_t,       vertex_weight_map)        \
  SS_NP(integer_grid_map_t,        integer_grid_map)         \
  SS_NP(grid_scale_t,              grid_scale)               \
  SS_NP(vt_per_corner_t,           vt_per_corner)            \
  SS_NP(pinned_corner_map_t,       pinned_corner_map)        \
  SS_NP(untangle_t,                untangle)                 \
  SS_NP(max_untangle_change_t,     max_untangle_change)      \
  SS_NP(merge_cone_pairs_t,        merge_cone_pairs)         \
  SS_NP(separate_cone_pairs_t,     separate_cone_pairs)      \
  SS_NP(quantize_t,                quantize)                 \
  SS_NP(vertex_origin_map_t,       vertex_origin_map)        \
  SS_NP(face_origin_map_t,         face_origin_map)          \
  SS_NP(max_grid_cells_t,          max_grid_cells)           \
  SS_NP(split_valence_one_cones_t, split_valence_one_cones)  \
  SS_NP(fill_branched_cells_t,     fill_branched_cells)      \
  SS_NP(number_of_threads_t,       number_of_threads)

namespace parameters {

// A pack of named parameters that chains both CGAL's and the package's parameters in one
// expression, in any order: `SS::parameters::verbose(true).repair_flips(false).geom_traits(k)`.
// It *is* a CGAL::Named_function_parameters (public base, no data of its own), so CGAL's
// get_parameter()/choose_parameter() and every CGAL function taking named parameters accept it.
// (CGAL 5.5 cannot get new member functions on Named_function_parameters; CGAL >= 6 has the
// same idea for its packages.)
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> cgal_parameters;
  typedef Named_function_parameters<T, Tag, Base> self;

  Named_function_parameters() : cgal_parameters() {}
  explicit Named_function_parameters(const T& v) : cgal_parameters(v) {}
  Named_function_parameters(const T& v, const Base& b) : cgal_parameters(v, b) {}

#define CGAL_add_named_parameter(X, Y, Z)                                                 \
  template <typename K>                                                                   \
  Named_function_parameters<K, CGAL::internal_np::X, self> Z(const K& k) const            \
  { return Named_function_parameters<K, CGAL::internal_np::X, self>(k, *this); }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define CGAL_SEAMLESS_SNAPPING_MEMBER(TAG, NAME)                                          \
  template <typename K>                                                                   \
  Named_function_parameters<K, snap_np::TAG, self> NAME(const K& k) const                 \
  { return Named_function_parameters<K, snap_np::TAG, self>(k, *this); }
  CGAL_SEAMLESS_SNAPPING_NAMED_PARAMETERS(CGAL_SEAMLESS_SNAPPING_MEMBER)
#undef CGAL_SEAMLESS_SNAPPING_MEMBER
};

// Everything else of CGAL::parameters (default_values(), choose_parameter(), ...) is reachable as
// CGAL::Seamless_snapping::parameters::xxx as well. The functions declared below hide CGAL's
// functions of the same name in qualified calls, so that SS::parameters::NAME(v) always starts a
// chainable pack.
using namespace CGAL::parameters;

// CGAL's parameters as free functions that start a chainable pack
#define CGAL_add_named_parameter(X, Y, Z)                                                 \
  template <typename K>                                                                   \
  Named_function_parameters<K, CGAL::internal_np::X> Z(const K& k)                        \
  { return Named_function_parameters<K, CGAL::internal_np::X>(k); }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

// The package's parameters as free functions.
// NAME(v)     : starts a new pack.
// NAME(v, np) : appends to an existing pack `np` (older spelling, kept for compatibility;
//               prefer np.NAME(v)).
#define CGAL_SEAMLESS_SNAPPING_FREE_FUNCTION(TAG, NAME)                                   \
  template <typename K>                                                                   \
  Named_function_parameters<K, snap_np::TAG> NAME(const K& k)                             \
  { return Named_function_parameters<K, snap_np::TAG>(k); }                               \
  template <typename K, typename T, typename Tag, typename Base>                           \
  Named_function_parameters<K, snap_np::TAG, CGAL::Named_function_parameters<T, Tag, Base> > \
  NAME(const K& k, const CGAL::Named_function_parameters<T, Tag, Base>& np)               \
  { return Named_function_parameters<K, snap_np::TAG,                                     \
                                     CGAL::Named_function_parameters<T, Tag, Base> >(k, np); }
CGAL_SEAMLESS_SNAPPING_NAMED_PARAMETERS(CGAL_SEAMLESS_SNAPPING_FREE_FUNCTION)
#undef CGAL_SEAMLESS_SNAPPING_FREE_FUNCTION

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

#undef CGAL_SEAMLESS_SNAPPING_NAMED_PARAMETERS

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PARAMETERS_H
