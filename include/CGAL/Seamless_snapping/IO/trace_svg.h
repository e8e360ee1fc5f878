// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_IO_TRACE_SVG_H
#define CGAL_SEAMLESS_SNAPPING_IO_TRACE_SVG_H

#include <CGAL/Seamless_snapping/Motorcycle_graph.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace CGAL {
namespace Seamless_snapping {
namespace IO {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * draws the UV triangles of `tm` (grey; flipped ones red) and the separatrices of `g` in the charts of their
 * faces (blue; a trace that ended in an inconsistency orange, with a red circle at its end) as an SVG image,
 * `width` pixels wide. When `g` has a patch layout, its polygons are filled by patch: quad patches in pastel
 * colours (one per patch), the others in salmon. UV coordinates are rounded to double for drawing only.
 */
template <class TriangleMesh, class HalfedgeUVMap>
void write_motorcycle_graph_svg(std::ostream& os, const TriangleMesh& tm, HalfedgeUVMap uv,
                                const Motorcycle_graph<TriangleMesh>& g, double width = 1000)
{
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for(auto h : halfedges(tm)) {
    if(is_border(h, tm)) continue;
    const auto p = get(uv, h);
    lo[0] = (std::min)(lo[0], double(p.x())); hi[0] = (std::max)(hi[0], double(p.x()));
    lo[1] = (std::min)(lo[1], double(p.y())); hi[1] = (std::max)(hi[1], double(p.y()));
  }
  if(!(lo[0] <= hi[0])) lo[0] = hi[0] = lo[1] = hi[1] = 0;   // no corner
  // half coordinates: the span of UVs near +-DBL_MAX overflowed (NaN in the image); the minimum from the corners
  // themselves (it started at 1e300, which moved maps beyond 1e305 off the image)
  const double half_span = (std::max)((std::max)(0.5 * hi[0] - 0.5 * lo[0], 0.5 * hi[1] - 0.5 * lo[1]), 1e-300);
  const double s = width / half_span, height = (0.5 * hi[1] - 0.5 * lo[1]) * s;
  auto X = [&](double u) { return (0.5 * u - 0.5 * lo[0]) * s + 5; };
  auto Y = [&](double v) { return height - (0.5 * v - 0.5 * lo[1]) * s + 5; };
  char buf[256];
  std::snprintf(buf, sizeof buf, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\">\n",
                width + 10, height + 10);
  os << buf << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if(g.layout.status == SUCCESS) {
    const Layout_mesh& lm = g.layout.mesh;
    auto luv = lm.property_map<Layout_mesh::Halfedge_index, CGAL::Epick::Point_2>("h:uv").first;
    auto patch = lm.property_map<Layout_mesh::Face_index, std::int32_t>("f:patch_id").first;
    for(auto f : lm.faces()) {
      const std::size_t p = std::size_t(get(patch, f));
      if(g.layout.patches[p].is_quad())
        std::snprintf(buf, sizeof buf, "<polygon fill=\"hsl(%d,45%%,84%%)\" stroke=\"none\" points=\"", int((p * 137) % 360));
      else std::snprintf(buf, sizeof buf, "<polygon fill=\"#ff9c8c\" stroke=\"none\" points=\"");
      os << buf;
      for(auto h : CGAL::halfedges_around_face(lm.halfedge(f), lm)) {
        std::snprintf(buf, sizeof buf, "%.2f,%.2f ", X(get(luv, h).x()), Y(get(luv, h).y()));
        os << buf;
      }
      os << "\"/>\n";
    }
  }
  for(auto f : faces(tm)) {
    auto h = halfedge(f, tm);
    const auto a = get(uv, h), b = get(uv, next(h, tm)), c = get(uv, next(next(h, tm), tm));
    typedef CGAL::Epick::Point_2 P;          // the exact orientation (a determinant in doubles overflows near DBL_MAX)
    const bool positive = CGAL::orientation(P(double(a.x()), double(a.y())), P(double(b.x()), double(b.y())),
                                            P(double(c.x()), double(c.y()))) == CGAL::LEFT_TURN;
    std::snprintf(buf, sizeof buf, "<polygon points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\" fill=\"%s\" stroke=\"#ccc\" stroke-width=\"0.3\"/>\n",
                  X(a.x()), Y(a.y()), X(b.x()), Y(b.y()), X(c.x()), Y(c.y()), positive ? "none" : "#f88");
    os << buf;
  }
  for(const Isoline_trace<TriangleMesh>& t : g.separatrices) {
    const bool bad = is_failure(t.end);
    for(const auto& seg : t.segments) {
      std::snprintf(buf, sizeof buf, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" stroke-width=\"%s\"/>\n",
                    X(CGAL::to_double(seg.source.u)), Y(CGAL::to_double(seg.source.v)),
                    X(CGAL::to_double(seg.target.u)), Y(CGAL::to_double(seg.target.v)),
                    bad ? "#f80" : "#1f4fd0", bad ? "2" : "1");
      os << buf;
    }
    if(bad && !t.segments.empty()) {
      const auto& e = t.segments.back().target;
      std::snprintf(buf, sizeof buf, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"8\" fill=\"none\" stroke=\"red\" stroke-width=\"2\"/>\n",
                    X(CGAL::to_double(e.u)), Y(CGAL::to_double(e.v)));
      os << buf;
    }
  }
  os << "</svg>\n";
}

} // namespace IO
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_IO_TRACE_SVG_H
