// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef SS_TEST_PATCH_CHART_MAP_H
#define SS_TEST_PATCH_CHART_MAP_H

// A quad mesh whose patches are rectangles (quad_mesh_patches()) as a map of its own, for test_quad and
// fuzz_quad_patches: each quad cut into four triangles at its center, the UV of each corner its cell corner in its patch
// (the center's the cell's center; a diagonal could be an edge of another quad on a mesh of fuzzed quads). Every patch is
// a chart, the trails are seams with quarter-turn transitions and integer translations, the nodes are cones (their
// valence in quarter turns), and every trace of its motorcycle graph runs along mesh edges, so that every meeting of
// traces is at a vertex or on an edge. Its traced motorcycle graph (build_motorcycle_graph()) is the quad mesh's:
// traced_layout_mismatch() compares them.

#include <CGAL/Seamless_snapping/Motorcycle_graph.h>
#include <CGAL/Seamless_snapping/quad_layout.h>
#include <CGAL/Seamless_snapping/quad_mesh_patches.h>

#include <CGAL/Gmpq.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace SS_test {

namespace SS = CGAL::Seamless_snapping;

// Adds to the empty triangle mesh t the quads of q (whose vertices but the isolated ones are added in their order, then
// a center per quad), four triangles each, with their cell corners as corner UVs (uv: halfedge of t -> 2D point); pm:
// the locations quad_mesh_patches() wrote.
// False if a triangle cannot be added.
template <class QuadMesh, class PatchMap, class TriangleMesh, class UVMap>
bool patch_chart_map(const QuadMesh& q, PatchMap pm, TriangleMesh& t, UVMap uv)
{
  typedef typename boost::property_traits<UVMap>::value_type Point_2;
  std::vector<typename TriangleMesh::Vertex_index> to_t;
  for(auto v : q.vertices()) {
    if(q.is_isolated(v)) continue;
    if(to_t.size() <= std::size_t(v)) to_t.resize(std::size_t(v) + 1);
    to_t[std::size_t(v)] = t.add_vertex(typename TriangleMesh::Point(q.point(v).x(), q.point(v).y(), q.point(v).z()));
  }
  for(auto f : q.faces()) {
    const SS::Quad_patch_location<QuadMesh> l = get(pm, f);
    const auto b = l.bottom;                                   // from (i, j) to (i + 1, j)
    const typename QuadMesh::Vertex_index c[4] = {q.source(b), q.target(b), q.target(q.next(b)), q.target(q.next(q.next(b)))};
    const Point_2 p[4] = {Point_2(l.i, l.j), Point_2(l.i + 1, l.j), Point_2(l.i + 1, l.j + 1), Point_2(l.i, l.j + 1)};
    double x = 0, y = 0, z = 0;
    for(auto v : c) { x += q.point(v).x() / 4; y += q.point(v).y() / 4; z += q.point(v).z() / 4; }
    const auto center = t.add_vertex(typename TriangleMesh::Point(x, y, z));
    for(int s = 0; s < 4; ++s) {
      const auto a = to_t[std::size_t(c[s])], e = to_t[std::size_t(c[(s + 1) % 4])];
      const auto g = t.add_face(a, e, center);
      if(g == TriangleMesh::null_face()) return false;
      for(auto k : CGAL::halfedges_around_face(t.halfedge(g), t))
        put(uv, k, t.target(k) == a ? p[s] : t.target(k) == e ? p[(s + 1) % 4] : Point_2(l.i + 0.5, l.j + 0.5));
    }
  }
  return true;
}

// The motorcycle graph g traced on a map against the patches and the layout of a quad mesh q of it at grid scale S (an
// integer-grid map's, or q's own patch_chart_map() at 1): every traced patch a rectangle whose width and height times S
// are integers, the sorted (shorter, longer) sides those of q's patches, the nodes and arcs quad_layout()'s vertices and
// arcs but those that split loops (an arc from a node back to itself is one arc of the traced layout, two in a
// halfedge graph). Returns what differs, empty if nothing.
template <class TriangleMesh, class QuadMesh>
std::string traced_layout_mismatch(const SS::Motorcycle_graph<TriangleMesh>& g, const QuadMesh& q, double S)
{
  const SS::Patch_layout& L = g.layout;
  if(g.failed != 0 || L.status != SS::SUCCESS || L.unplaced_segments != 0)
    return std::to_string(g.failed) + " failed traces; layout: " + L.message;
  std::vector<std::pair<int, int> > traced, quads;
  for(const SS::Layout_patch& p : L.patches) {
    const CGAL::Gmpq w = p.width * CGAL::Gmpq(S), h = p.height * CGAL::Gmpq(S);
    const int wi = int(CGAL::to_double(w)), hi = int(CGAL::to_double(h));
    if(!p.is_quad() || CGAL::Gmpq(wi) != w || CGAL::Gmpq(hi) != h) return "a traced patch that is not a rectangle of cells";
    traced.emplace_back((std::min)(wi, hi), (std::max)(wi, hi));
  }
  std::vector<SS::Quad_patch_location<QuadMesh> > locations(q.number_of_faces());
  const SS::Quad_patches r = SS::quad_mesh_patches(q, boost::make_iterator_property_map(locations.begin(), get(boost::face_index, q)));
  for(const SS::Quad_patch& p : r.patches) quads.emplace_back((std::min)(p.width, p.height), (std::max)(p.width, p.height));
  std::sort(traced.begin(), traced.end());
  std::sort(quads.begin(), quads.end());
  QuadMesh layout;
  auto arcs = layout.template add_property_map<typename QuadMesh::Halfedge_index, SS::Quad_layout_arc<QuadMesh> >("h:arc").first;
  const SS::Quad_layout ql = SS::quad_layout(q, layout, arcs);
  if(traced == quads && L.nodes + ql.loop_splits == ql.vertices && L.arcs + ql.loop_splits == ql.arcs) return "";
  return "traced " + std::to_string(traced.size()) + " patches, " + std::to_string(L.nodes) + " nodes, " +
         std::to_string(L.arcs) + " arcs; the quad mesh " + std::to_string(quads.size()) + " patches, " +
         std::to_string(ql.vertices) + " vertices, " + std::to_string(ql.arcs) + " arcs (" + std::to_string(ql.loop_splits) +
         " loops split)" +
         (traced.size() == quads.size() && traced != quads ? " (other sizes)" : "");
}

} // namespace SS_test

#endif // SS_TEST_PATCH_CHART_MAP_H
