// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_SNAP_INPUTS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_SNAP_INPUTS_H

// The named parameters of snap_seamless_parameterization(), read once, for every function that
// must see the same constraints as the snap (the snap itself, diagnose_seamlessness()).

#include <CGAL/Seamless_snapping/internal/parameters.h>
#include <CGAL/Seamless_snapping/internal/surface/connection_constraints.h>
#include <CGAL/Seamless_snapping/internal/surface/snap_pipeline.h>
#include <CGAL/Seamless_snapping/internal/threads.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <array>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

template <class TriangleMesh, class NamedParameters>
struct Snap_inputs
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;

  typedef CGAL::Constant_property_map<edge_descriptor, bool> Default_seam_map;
  typedef typename internal_np::Lookup_named_param_def<snap_np::seam_edge_map_t, NamedParameters,
                                                       Default_seam_map>::type Seam_map;
  typedef CGAL::Constant_property_map<halfedge_descriptor, int> Default_rotation_map;
  typedef typename internal_np::Lookup_named_param_def<snap_np::rotation_map_t, NamedParameters,
                                                       Default_rotation_map>::type Rotation_map;
  typedef CGAL::Constant_property_map<edge_descriptor, bool> Default_constrained_map;
  typedef typename internal_np::Lookup_named_param_def<internal_np::edge_is_constrained_t, NamedParameters,
                                                       Default_constrained_map>::type Constrained_map;
  typedef CGAL::Constant_property_map<vertex_descriptor, double> Default_weight_map;
  typedef typename internal_np::Lookup_named_param_def<snap_np::vertex_weight_map_t, NamedParameters,
                                                       Default_weight_map>::type Weight_map;

  typedef CGAL::Constant_property_map<halfedge_descriptor, bool> Default_pinned_map;
  typedef typename internal_np::Lookup_named_param_def<snap_np::pinned_corner_map_t, NamedParameters,
                                                       Default_pinned_map>::type Pinned_map;

  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Vertex_point_map;

  Seam_map seams;
  bool has_seams;
  Rotation_map rotations;
  bool has_rotations;
  Constrained_map constrained;
  bool has_constrained;
  Weight_map weights;             // of the minimal change
  bool has_weights;
  Vertex_point_map points;        // 3D positions: the reference shapes of the untangling
  Snap_options options;

  Snap_inputs(const TriangleMesh& tm, const NamedParameters& np)
    : seams(CGAL::parameters::choose_parameter<Seam_map>(CGAL::parameters::get_parameter(np, snap_np::seam_edge_map),
                                                         Default_seam_map(false))),
      has_seams(!CGAL::parameters::is_default_parameter<NamedParameters, snap_np::seam_edge_map_t>::value),
      rotations(CGAL::parameters::choose_parameter<Rotation_map>(CGAL::parameters::get_parameter(np, snap_np::rotation_map),
                                                                 Default_rotation_map(0))),
      has_rotations(!CGAL::parameters::is_default_parameter<NamedParameters, snap_np::rotation_map_t>::value),
      constrained(CGAL::parameters::choose_parameter<Constrained_map>(
          CGAL::parameters::get_parameter(np, internal_np::edge_is_constrained), Default_constrained_map(false))),
      has_constrained(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::edge_is_constrained_t>::value),
      weights(CGAL::parameters::choose_parameter<Weight_map>(CGAL::parameters::get_parameter(np, snap_np::vertex_weight_map),
                                                             Default_weight_map(1.))),
      has_weights(!CGAL::parameters::is_default_parameter<NamedParameters, snap_np::vertex_weight_map_t>::value),
      points(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tm)))
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    const Snap_options defaults;
    options.align_boundary = choose_parameter(get_parameter(np, snap_np::align_boundary), defaults.align_boundary);
    options.use_reduced_system = choose_parameter(get_parameter(np, snap_np::use_reduced_system), defaults.use_reduced_system);
    options.alignment_tolerance = choose_parameter(get_parameter(np, snap_np::alignment_tolerance), defaults.alignment_tolerance);
    options.rotation_tolerance = choose_parameter(get_parameter(np, snap_np::rotation_tolerance), defaults.rotation_tolerance);
    options.repair_flips = choose_parameter(get_parameter(np, snap_np::repair_flips), defaults.repair_flips);
    options.minimal_change = choose_parameter(get_parameter(np, snap_np::minimal_change), defaults.minimal_change);
    options.verbose = choose_parameter(get_parameter(np, internal_np::verbose), defaults.verbose);
    options.integer_grid_map = choose_parameter(get_parameter(np, snap_np::integer_grid_map), defaults.integer_grid_map);
    options.grid_scale = choose_parameter(get_parameter(np, snap_np::grid_scale), defaults.grid_scale);
    options.untangle = choose_parameter(get_parameter(np, snap_np::untangle), options.integer_grid_map);
    options.max_untangle_change = choose_parameter(get_parameter(np, snap_np::max_untangle_change), defaults.max_untangle_change);
    options.merge_cone_pairs = choose_parameter(get_parameter(np, snap_np::merge_cone_pairs), defaults.merge_cone_pairs);
    options.separate_cone_pairs = choose_parameter(get_parameter(np, snap_np::separate_cone_pairs), defaults.separate_cone_pairs);
    options.quantize = choose_parameter(get_parameter(np, snap_np::quantize), defaults.quantize);
    options.threads = number_of_threads_parameter(np, defaults.threads);
    // connection and cycle constraints, in the halfedge numbering of the pipeline
    connection_paths_from_parameter(tm, CGAL::parameters::get_parameter_reference(np, snap_np::connection_constraints),
                                    options.connections);
    // pinned corners, in the halfedge numbering of the pipeline (the enumeration order of halfedges(tm))
    if(!CGAL::parameters::is_default_parameter<NamedParameters, snap_np::pinned_corner_map_t>::value) {
      const Pinned_map pinned = choose_parameter<Pinned_map>(get_parameter(np, snap_np::pinned_corner_map),
                                                             Default_pinned_map(false));
      int n = 0;
      for(halfedge_descriptor h : halfedges(tm)) {
        if(bool(get(pinned, h))) options.pinned_corners.push_back(n);
        ++n;
      }
    }
  }

  bool seam_of(edge_descriptor e) const { return bool(get(seams, e)); }
  int rotation_of(halfedge_descriptor h) const { return int(get(rotations, h)); }
  bool constrained_of(edge_descriptor e) const { return bool(get(constrained, e)); }
  double weight_of(vertex_descriptor v) const { return double(get(weights, v)); }
  std::array<double, 3> point_of(vertex_descriptor v) const
  {
    const auto& p = get(points, v);
    return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  }
};

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_SNAP_INPUTS_H
