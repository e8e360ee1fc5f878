// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_MOTORCYCLE_GRAPH_H
#define CGAL_SEAMLESS_SNAPPING_MOTORCYCLE_GRAPH_H

#include <CGAL/Seamless_snapping/Patch_layout.h>
#include <CGAL/Seamless_snapping/trace_isoline.h>
#include <CGAL/Seamless_snapping/internal/tracing/motorcycle_graph.h>
#include <CGAL/Seamless_snapping/internal/timing.h>
#include <CGAL/Seamless_snapping/internal/tracing/patch_layout.h>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * The separatrices of a motorcycle graph and how they ended (the study of Sec. 6.2 of Mandad & Campen 2019).
 */
template <class TriangleMesh>
struct Motorcycle_graph
{
  Status status = INVALID_INPUT;                          ///< `SUCCESS` iff the map could be read (see `Isoline_tracer::status()`)
  std::string message;
  std::vector<Isoline_trace<TriangleMesh> > separatrices; ///< index = the trace index used by `Isoline_trace::hit_trace`
  std::vector<int> source_kind;                           ///< per separatrix: 0 cone, 1 border corner, 2 seed (no cones nor corners)
  std::array<std::size_t, number_of_trace_ends> ends{};   ///< number of separatrices per `Trace_end`
  std::size_t failed = 0;                                 ///< separatrices that ended in an inconsistency (`is_failure()`)
  std::size_t cones = 0;                                  ///< cones (interior vertices whose angle sum is not 4 quarter turns)
  std::size_t border_corners = 0;                         ///< border vertices whose fan is not a half turn
  std::size_t cones_with_wrong_ray_count = 0;             ///< cones of n quarter turns that do not emit n rays (inexact maps)
  bool seeded = false;                                    ///< no cones and no border corners: four seeded traces (+u, +v, -u, -v) instead
  Patch_layout layout;                                    ///< the patches and the refined mesh (if requested; see `build_motorcycle_graph()`)
  double trace_ms = 0;                                    ///< wall time (ms) of tracing the separatrices (the layout's phases: in `layout`)
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * traces the separatrices of the motorcycle graph of the map read by `tracer` ([CBK15]; Sec. 6.2 of Mandad & Campen
 * 2019): from every cone of `n` quarter turns its `n` axis rays, from every border corner the axis rays strictly inside
 * its fan. The traces start together and move at unit speed in UV (time = parametric length, exact rationals: an event
 * simulation, each face crossing and each meeting an event); each stops at a cone, the border, or where it reaches the
 * trail of a trace that passed there earlier (a T-junction, `EARLIER_TRACE`). Traces that reach a point at the same
 * time: two head-on both stop (their trails join), and of two at right angles the one heading a quarter turn
 * counter-clockwise from the other goes on (the rule of `quad_mesh_patches()`), decided once all that get there at
 * that time have arrived, inside a face, on an edge or at a vertex. So the graph depends on the map, not on its
 * triangulation or numbering: on an integer-grid map the patches are those of the quad mesh of `extract_quad_mesh()`
 * cut by `quad_mesh_patches()`, with the same sizes, nodes and arcs (`test_quad` checks this on every covering quad
 * mesh it extracts, and on the quad mesh itself triangulated with its patches as charts, where every meeting is at a
 * vertex). Without cones and border corners (a torus), four traces (+u, +v, -u, -v) are
 * seeded at the first corner of the mesh, and `seeded` is set.
 *
 *
 * With `with_layout`, the faces are then cut along all separatrices, exactly, into the patch layout
 * (`Patch_layout`: the refined mesh with `is_arc` and `patch_id`, and the checked properties of every patch);
 * its status is `INVALID_INPUT` with a message if a UV triangle of the map is flipped or degenerate.
 *
 * \param tracer the tracer of the map (`Isoline_tracer`); its status is the graph's when it is not `SUCCESS`
 * \param max_faces step limit per trace (0: 20 times the number of faces, plus 100)
 * \param with_layout build `layout` as well
 */
template <class TriangleMesh, class HalfedgeUVMap>
Motorcycle_graph<TriangleMesh> build_motorcycle_graph(const Isoline_tracer<TriangleMesh, HalfedgeUVMap>& tracer,
                                                      std::size_t max_faces = 0, bool with_layout = true)
{
  Motorcycle_graph<TriangleMesh> g;
  g.status = tracer.status();
  g.message = tracer.message();
  if(g.status != SUCCESS) return g;
  const internal::tracing::Tracing_map& map = tracer.tracing_map();
  const internal::tracing::Separatrix_seeds seeds = internal::tracing::separatrix_seeds(map);
  std::vector<internal::tracing::Trace_run> runs;
  internal::tracing::Trail_registry trails;
  const internal::Timing_clock::time_point t = internal::Timing_clock::now();
  internal::tracing::trace_separatrices(map, seeds, max_faces, runs, trails);
  g.trace_ms = internal::ms_since(t);
  g.cones = seeds.cones;
  g.border_corners = seeds.border_corners;
  g.cones_with_wrong_ray_count = seeds.cones_with_wrong_ray_count;
  g.seeded = seeds.seeded;
  g.source_kind = seeds.source_kind;
  for(const internal::tracing::Trace_run& r : runs) {
    g.separatrices.push_back(tracer.convert(r));
    ++g.ends[int(r.end)];
    if(is_failure(r.end)) ++g.failed;
  }
  if(with_layout) internal::tracing::build_patch_layout(map, runs, tracer.vertex_positions(), g.layout);
  else g.layout.message = "not requested";
  return g;
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_MOTORCYCLE_GRAPH_H
