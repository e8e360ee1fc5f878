// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_TRACING_MAP_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_TRACING_MAP_H

// The map as the tracer, the face subdivision and the patch layout see it, built once per map.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/tracing/chart_geometry.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace tracing {

// The map as the tracer sees it: corner mesh, cut edges and cones, one rotation k per cut edge.
struct Tracing_map
{
  Corner_mesh cm;
  Seam_topology st;
  Cut_rotations rot;
  std::vector<int> fan_quarter_turns;   // per vertex: round(UV angle sum of its corners / 90 degrees); the seam
                                        // topology's quarter_turns away from the border (the same rounding of the
                                        // same sum, certified there), summed here only at border vertices
  std::vector<int> face_halfedge;       // per face: its smallest halfedge index
  std::vector<Exact_uv> sector_uv;      // per sector: the exact UV its corners share (their doubles), made once: a
                                        // whole-mesh pass (the face subdivision) copies handles instead of making
                                        // a rational per corner and use
};

// the exact UV of corner (target(h), face(h)): its doubles as rationals, made once per sector and shared
inline const Exact_uv& corner_uv(const Tracing_map& map, int h) { return map.sector_uv[std::size_t(map.st.sector_of[h])]; }

inline Status build_tracing_map(Tracing_map& map, double rotation_tolerance_degrees, std::string& message)
{
  const Corner_mesh& cm = map.cm;
  Status s = compute_seam_topology(cm, std::vector<signed char>(), map.st, message);
  if(s != SUCCESS) return s;
  s = fit_rotations(cm, map.st, std::vector<int>(), rotation_tolerance_degrees, map.rot, message);
  if(s != SUCCESS) return s;
  std::vector<double> sum(cm.n_vertices, 0.);
  for(int h = 0; h < cm.n_halfedges; ++h)
    if(!cm.is_border_halfedge(h) && cm.vertex_on_border[cm.target[h]]) sum[cm.target[h]] += corner_angle(cm, h);
  map.face_halfedge.assign(cm.n_faces, -1);
  for(int h : face_first_halfedges(cm)) map.face_halfedge[cm.face[h]] = h;
  map.sector_uv.clear();
  map.sector_uv.reserve(std::size_t(map.st.n_sectors));
  for(std::size_t i = 0; i < std::size_t(map.st.n_sectors); ++i)
    map.sector_uv.push_back(Exact_uv{FT(map.st.ubar[2 * i]), FT(map.st.ubar[2 * i + 1])});
  map.fan_quarter_turns.resize(cm.n_vertices);
  for(int v = 0; v < cm.n_vertices; ++v)
    map.fan_quarter_turns[v] = cm.vertex_on_border[v] ? int(std::lround(sum[v] / (std::acos(-1.) / 2))) : map.st.quarter_turns[v];
  return SUCCESS;
}

} // namespace tracing
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_TRACING_MAP_H
