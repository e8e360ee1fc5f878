// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// libFuzzer target: the bytes are a polygon mesh of quads and triangles (quad_patches_bytes.h), built face by face
// with CGAL::Euler::add_face() into a Surface_mesh, then one face removed where the mesh allows it
// (CGAL::Euler::remove_face(): removed elements) and the garbage collected or not; then quad_mesh_patches(). It checks
//  - SUCCESS only on a quad mesh; then every quad is in one patch (its count that patch's), its bottom side one of its
//    halfedges; a rectangle patch holds width x height quads, each in a cell of the rectangle, each cell once; on a
//    mesh with nodes every patch is a rectangle (the theorem the documentation cites);
//  - any other status writes nothing (the output map keeps its values);
//  - quad_layout(): SUCCESS exactly when quad_mesh_patches() succeeds with rectangles, else nothing added; a valid face
//    graph with one face per patch and the Euler characteristic of the mesh (isolated vertices not counted), every
//    face with 4 corners and sides of its patch's width, height, width, height, each arc as long on both sides;
//  - on a connected mesh with nodes: the mesh as a map of its own (its quads cut in four, its patches as charts,
//    patch_chart_map.h) is a seamless map whose motorcycle graph traced in exact time (build_motorcycle_graph(), a
//    second implementation that shares no code with quad_mesh_patches()) has the same patches (sizes), nodes and arcs.
// Any violation aborts (a finding); the sanitizers catch reads out of range. Build: -DSEAMLESS_SNAPPING_FUZZ=ON.

#include "quad_patches_bytes.h"
#include "../Seamless_snapping/patch_chart_map.h"

#include <CGAL/Seamless_snapping/quad_layout.h>
#include <CGAL/Seamless_snapping/quad_mesh_patches.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <tuple>
#include <vector>

#define FUZZ_REQUIRE(cond, what) \
  do { if(!(cond)) { std::fprintf(stderr, "fuzz_quad_patches: violated: %s (%s)\n", what, #cond); std::abort(); } } while(0)

typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;
namespace SS = CGAL::Seamless_snapping;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const SS_fuzz::Quad_soup soup = SS_fuzz::quad_soup_from_bytes(data, size);
  Mesh m;
  std::vector<Mesh::Vertex_index> vs;
  for(int v = 0; v < soup.vertices; ++v) vs.push_back(m.add_vertex(Mesh::Point(v, v % 7, v % 3)));
  std::vector<Mesh::Face_index> removed;
  for(const SS_fuzz::Quad_soup::Face& f : soup.faces) {
    std::vector<Mesh::Vertex_index> corners;
    for(int c = 0; c < (f.triangle ? 3 : 4); ++c) corners.push_back(vs[std::size_t(f.v[std::size_t(c)])]);
    if(std::set<Mesh::Vertex_index>(corners.begin(), corners.end()).size() != corners.size()) continue;
    const Mesh::Face_index added = CGAL::Euler::add_face(corners, m);
    if(added != Mesh::null_face() && f.removed) removed.push_back(added);
  }
  // one face removed (the first asked for; Euler::remove_face() needs a valid mesh whose vertices have one fan each:
  // on others, and after several removals, it can leave halfedges pointing at vertices it removed)
  if(!removed.empty() && CGAL::is_valid_polygon_mesh(m)) {
    std::vector<int> border_in(m.num_vertices(), 0);
    bool one_fan = true;
    for(Mesh::Halfedge_index h : m.halfedges()) if(m.is_border(h)) one_fan &= ++border_in[std::size_t(m.target(h))] == 1;
    if(one_fan) CGAL::Euler::remove_face(m.halfedge(removed.front()), m);
  }
  if(soup.collect_garbage) m.collect_garbage();

  SS::Quad_patch_location<Mesh> untouched;
  untouched.patch = 123456789;
  std::vector<SS::Quad_patch_location<Mesh> > locations(m.num_faces(), untouched);   // indices of removed faces too
  const SS::Quad_patches r = SS::quad_mesh_patches(m, boost::make_iterator_property_map(locations.begin(), get(boost::face_index, m)));
  (void)r.to_json();
  if(r.status != SS::SUCCESS) {
    for(const SS::Quad_patch_location<Mesh>& l : locations) FUZZ_REQUIRE(l.patch == 123456789, "nothing written on failure");
    return 0;
  }
  FUZZ_REQUIRE(CGAL::is_quad_mesh(m), "SUCCESS only on quads");
  std::vector<std::size_t> count(r.patches.size(), 0);
  std::set<std::tuple<std::size_t, int, int> > cells;
  for(Mesh::Face_index f : m.faces()) {
    const SS::Quad_patch_location<Mesh>& l = locations[std::size_t(f)];
    FUZZ_REQUIRE(l.patch < r.patches.size() && m.face(l.bottom) == f, "a patch and a bottom side of the quad");
    ++count[l.patch];
    const SS::Quad_patch& P = r.patches[l.patch];
    if(!P.rectangle) continue;
    FUZZ_REQUIRE(0 <= l.i && l.i < P.width && 0 <= l.j && l.j < P.height, "a cell of the rectangle");
    FUZZ_REQUIRE(cells.insert(std::make_tuple(l.patch, l.i, l.j)).second, "each cell once");
  }
  std::size_t rectangles = 0, quads = 0;
  for(std::size_t p = 0; p < r.patches.size(); ++p) {
    const SS::Quad_patch& P = r.patches[p];
    FUZZ_REQUIRE(count[p] == P.quads && P.quads > 0, "the patch's quads");
    FUZZ_REQUIRE(!P.rectangle || P.quads == std::size_t(P.width) * std::size_t(P.height), "width x height quads");
    rectangles += P.rectangle ? 1 : 0;
    quads += P.quads;
  }
  FUZZ_REQUIRE(quads == m.number_of_faces() && rectangles == r.rectangles, "the patches cover the quads");
  FUZZ_REQUIRE(r.nodes == 0 || r.all_rectangles(), "with nodes, every patch a rectangle (Eppstein et al. 2008)");

  Mesh L;
  auto arcs = L.add_property_map<Mesh::Halfedge_index, SS::Quad_layout_arc<Mesh> >("h:arc").first;
  const SS::Quad_layout q = SS::quad_layout(m, L, arcs);
  (void)q.to_json();
  FUZZ_REQUIRE((q.status == SS::SUCCESS) == r.all_rectangles(), "a layout exactly when every patch is a rectangle");
  if(q.status != SS::SUCCESS) { FUZZ_REQUIRE(L.is_empty(), "nothing added on failure"); return 0; }
  long isolated = 0;
  for(Mesh::Vertex_index v : m.vertices()) isolated += m.is_isolated(v) ? 1 : 0;
  const long chi = long(m.number_of_vertices()) - isolated - long(m.number_of_edges()) + long(m.number_of_faces());
  FUZZ_REQUIRE(CGAL::is_valid_face_graph(L) && L.number_of_faces() == r.patches.size(), "a face graph, a face per patch");
  FUZZ_REQUIRE(long(L.number_of_vertices()) - long(L.number_of_edges()) + long(L.number_of_faces()) == chi, "the Euler characteristic");
  for(Mesh::Halfedge_index h : L.halfedges())
    FUZZ_REQUIRE(get(arcs, h).length > 0 && get(arcs, h).length == get(arcs, L.opposite(h)).length, "an arc as long on both sides");
  for(Mesh::Face_index f : L.faces()) {
    std::vector<int> sides;
    int run = 0;
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(L.halfedge(f), L)) {
      run += get(arcs, h).length;
      if(get(arcs, h).corner) { sides.push_back(run); run = 0; }
    }
    const SS::Quad_patch& P = r.patches[std::size_t(f)];
    FUZZ_REQUIRE(sides.size() == 4 && run == 0 && sides[0] == P.width && sides[2] == P.width && sides[1] == P.height &&
                 sides[3] == P.height, "4 corners, sides of the patch's width and height");
  }
  // the mesh as a map of its own, traced (parts without nodes are seeded by quad_mesh_patches() alone: one part only)
  std::vector<std::size_t> component(m.num_faces());
  const auto cm = boost::make_iterator_property_map(component.begin(), get(boost::face_index, m));
  if(r.nodes == 0 || CGAL::Polygon_mesh_processing::connected_components(m, cm) != 1) return 0;
  Mesh t;
  auto uv = t.add_property_map<Mesh::Halfedge_index, CGAL::Simple_cartesian<double>::Point_2>("h:uv").first;
  FUZZ_REQUIRE(SS_test::patch_chart_map(m, boost::make_iterator_property_map(locations.begin(), get(boost::face_index, m)), t, uv),
               "the quads cut in four");
  const SS::Isoline_tracer<Mesh, decltype(uv)> tracer(t, uv);
  FUZZ_REQUIRE(tracer.status() == SS::SUCCESS, "the patch charts are a map the tracer reads");
  const std::string mismatch = SS_test::traced_layout_mismatch(SS::build_motorcycle_graph(tracer), m, 1);
  if(!mismatch.empty()) std::fprintf(stderr, "fuzz_quad_patches: %s\n", mismatch.c_str());
  FUZZ_REQUIRE(mismatch.empty(), "the traced motorcycle graph of the patch charts is the quad mesh's");
  return 0;
}
