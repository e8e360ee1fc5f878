// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// Tests of the tracing layer (Sec. 6.2): trace_isoline / Isoline_tracer and the motorcycle graph.
//   trace: grid                   exact stops (border vertex, target vertex, rational start point), trace back
//   trace: torus                  isolines close exactly (CLOSED_LOOP), from a vertex and from a rational point
//   trace: bear orbifold, snapped every separatrix ends regularly (cone, border, T-junction), n rays per cone,
//                                 every trace traced back from its end returns to its cone exactly
//   trace: bear orbifold, input   terminates; inconsistencies are reported by kind
//   trace: cut invariance         the snapped bear with 4 and 12 face rings around a cone re-charted by a quarter
//                                 turn (the cut graph moves): the same separatrices, ends, nodes, arcs, patch sizes
//                                 and refined-mesh points, bit for bit; the map times 2^j: the same, sizes times 2^j
//   trace: shared data, snapped   the same properties on every snapped shared map without fold-overs
//                                 (files up to 1 MB; up to 600 kB and no bear with --sanitizer-subset); the maps
//                                 with fold-overs (the knight) untangled first: fold-free, a valid layout; in
//                                 integer-grid mode (a forced zero-area face): traced through, the layout refused
//   trace: collapsed face         a zero-area face with three distinct corners is crossed exactly, also from its
//                                 middle corner; the polyline stays connected in 3D (the crossing is a segment of
//                                 zero UV length)
//   (every valid layout above)    the same motorcycle graph from the map renumbered: its vertices and faces shuffled,
//                                 each face's corners rotated (the event simulation in exact time and its tie rule read
//                                 no index): as many separatrices ending per reason, patches of the same exact sizes,
//                                 nodes, arcs

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Seamless_snapping/internal/inputs/orbifold_tutte_input.h>

#include "mesh_test_support.h"
#include "connection_test_utils.h"

#include <CGAL/Seamless_snapping/IO/Patch_layout.h>
#include <CGAL/Seamless_snapping/IO/trace_svg.h>
#include <CGAL/Seamless_snapping/Motorcycle_graph.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <CGAL/Seamless_snapping/trace_isoline.h>
#include <CGAL/Seamless_snapping/internal/inputs/orbifold_tutte_input.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/IO/OBJ.h>

#include <array>
#include <cassert>
#include <random>
#include <cstdio>
#include <set>
#include <sstream>

typedef Mesh::Face_index face_descriptor;
typedef SS::Isoline_tracer<Mesh, UV_map> Tracer;
typedef SS::Isoline_trace<Mesh> Trace;
typedef SS::Trace_point<Mesh> Point;

static SS::Trace_direction reverse(SS::Trace_direction d) { return SS::Trace_direction((int(d) + 2) % 4); }

// traces back from the end of t (reverse direction, in the chart of the last segment's face), with
// t's start as the target
static Trace trace_back(const Mesh& m, const Tracer& tracer, const Trace& t)
{
  const SS::Trace_segment<Mesh>& last = t.segments.back();
  const Point& a = t.segments.front().source;
  const Point& b = last.target;
  SS::Trace_options<Mesh> o;
  if(a.location == Point::VERTEX) { o.has_target_vertex = true; o.target_vertex = target(a.halfedge, m); }
  else { o.has_target_point = true; o.target_face = a.face; o.target_u = a.u; o.target_v = a.v; }
  if(b.location == Point::VERTEX) return tracer.trace_from_vertex(b.halfedge, reverse(last.direction), o);
  return tracer.trace_from_point(last.face, b.u, b.v, reverse(last.direction), o);
}

static bool same_surface_point(const Mesh& m, const Point& a, const Point& b)
{
  if(a.location == Point::VERTEX || b.location == Point::VERTEX)
    return a.location == b.location && target(a.halfedge, m) == target(b.halfedge, m);
  return a.face == b.face && a.u == b.u && a.v == b.v;
}

static void check_layout(const Mesh& m, UV_map uv, const SS::Motorcycle_graph<Mesh>& g, const std::string& what);
static void check_independent_of_numbering(const Mesh& m, UV_map uv, const SS::Motorcycle_graph<Mesh>& g,
                                           const std::string& what);

// ---------------------------------------------------------------------------------------------
static void test_grid()
{
  const int n = 5;
  Mesh m;
  std::vector<vertex_descriptor> vs = triangulated_grid(m, n, true);
  UV_map uv = uv_of(m);
  uv_from_xy(m, uv);
  Tracer tracer(m, uv);
  assert(tracer.status() == SS::SUCCESS);
  auto corner_of = [&](vertex_descriptor v) {
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, m)) if(!m.is_border(h)) return h;
    return halfedge_descriptor();
  };
  // from (1, 1) along +u: border vertex (n, 1), exactly
  Trace t = tracer.trace_from_vertex(corner_of(vs[(n + 1) + 1]), SS::Trace_direction::PLUS_U);
  assert(t.end == SS::Trace_end::BORDER);
  const Point& e = t.segments.back().target;
  assert(e.location == Point::VERTEX && target(e.halfedge, m) == vs[(n + 1) + n]);
  assert(e.u == CGAL::Gmpq(n) && e.v == CGAL::Gmpq(1));
  // with a target vertex on the way
  SS::Trace_options<Mesh> o;
  o.has_target_vertex = true; o.target_vertex = vs[(n + 1) + 3];
  t = tracer.trace_from_vertex(corner_of(vs[(n + 1) + 1]), SS::Trace_direction::PLUS_U, o);
  assert(t.end == SS::Trace_end::TARGET && target(t.segments.back().target.halfedge, m) == vs[(n + 1) + 3]);
  // a target point on the way given in the chart of any face whose closed triangle holds it: at a vertex (3, 1) or on an
  // edge (5/2, 1) it was met only in the face given, and a trace along the edges of the other faces went past it
  for(const std::array<CGAL::Gmpq, 2>& q : {std::array<CGAL::Gmpq, 2>{{3, 1}}, std::array<CGAL::Gmpq, 2>{{CGAL::Gmpq(5, 2), 1}}}) {
    int holding = 0;
    for(face_descriptor f : m.faces()) {
      bool inside = true;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
        const Point_2 a = get(uv, m.prev(h)), b = get(uv, h);   // exact: small integers
        inside = inside && (b.x() - a.x()) * (q[1] - a.y()) - (b.y() - a.y()) * (q[0] - a.x()) >= 0;
      }
      if(!inside) continue;
      ++holding;
      SS::Trace_options<Mesh> to;
      to.has_target_point = true; to.target_face = f; to.target_u = q[0]; to.target_v = q[1];
      t = tracer.trace_from_vertex(corner_of(vs[(n + 1) + 1]), SS::Trace_direction::PLUS_U, to);
      assert(t.end == SS::Trace_end::TARGET && t.segments.back().target.u == q[0] && t.segments.back().target.v == q[1]);
    }
    assert(holding == (q[0] == 3 ? 6 : 2));
  }
  // from a rational point inside a face along +v: the border at v = n, u kept exactly
  const CGAL::Gmpq u0(1, 3), v0(1, 7);
  face_descriptor f0;
  for(face_descriptor f : m.faces()) {
    Trace probe = tracer.trace_from_point(f, u0, v0, SS::Trace_direction::PLUS_V);
    if(probe.end != SS::Trace_end::INVALID_START) { f0 = f; t = probe; break; }
  }
  assert(t.end == SS::Trace_end::BORDER);
  assert(t.segments.back().target.u == u0 && t.segments.back().target.v == CGAL::Gmpq(n));
  for(const auto& s : t.segments) {
    assert(s.source.u == u0 && s.target.u == u0);               // an isoline: u constant, exactly
    CGAL::Gmpq sum = s.target.barycentric[0] + s.target.barycentric[1] + s.target.barycentric[2];
    assert(sum == 1);
  }
  // trace back: returns to the start point exactly
  Trace back = trace_back(m, tracer, t);
  assert(back.end == SS::Trace_end::TARGET);
  assert(back.segments.back().target.u == u0 && back.segments.back().target.v == v0);
  // a start point outside the face is refused
  Trace bad = tracer.trace_from_point(f0, CGAL::Gmpq(-1), CGAL::Gmpq(-1), SS::Trace_direction::PLUS_U);
  assert(bad.end == SS::Trace_end::INVALID_START);
  // a direction, a start or a target that is none of the mesh's: INVALID_START saying which (a target vertex threw
  // std::out_of_range, a halfedge beyond the mesh's read past the end of an array)
  const halfedge_descriptor start = corner_of(vs[(n + 1) + 1]);
  bad = tracer.trace_from_vertex(start, SS::Trace_direction(7));
  assert(bad.end == SS::Trace_end::INVALID_START && bad.message.find("direction 7") != std::string::npos);
  bad = tracer.trace_from_vertex(halfedge_descriptor(m.number_of_halfedges() + 10), SS::Trace_direction::PLUS_U);
  assert(bad.end == SS::Trace_end::INVALID_START && bad.message.find("no halfedge") != std::string::npos);
  o.target_vertex = Mesh::Vertex_index(m.number_of_vertices() + 10);
  bad = tracer.trace_from_vertex(start, SS::Trace_direction::PLUS_U, o);
  assert(bad.end == SS::Trace_end::INVALID_START && bad.message.find("target vertex") != std::string::npos);
  o.has_target_vertex = false;
  o.has_target_point = true;                         // a target face, and a start face, past the end of the mesh's faces
  o.target_face = Mesh::Face_index(m.number_of_faces() + 10); o.target_u = 1; o.target_v = 1;
  bad = tracer.trace_from_vertex(start, SS::Trace_direction::PLUS_U, o);
  assert(bad.end == SS::Trace_end::INVALID_START && bad.message.find("target face") != std::string::npos);
  bad = tracer.trace_from_point(Mesh::Face_index(m.number_of_faces() + 10), u0, v0, SS::Trace_direction::PLUS_U);
  assert(bad.end == SS::Trace_end::INVALID_START && bad.message.find("no halfedge") != std::string::npos);
  // the motorcycle graph of a square: 4 convex corners, no rays, nothing seeded
  SS::Motorcycle_graph<Mesh> g = SS::build_motorcycle_graph(tracer);
  assert(g.status == SS::SUCCESS && g.border_corners == 4 && g.separatrices.empty() && !g.seeded);
  check_layout(m, uv, g, "grid");                         // one patch: the square itself
  { // its SVG, and that of the same square moved and scaled to UVs of +-1.25 2^1023 (their span overflowed a double: NaN
    // coordinates): finite, the square's corners at the image's corners (5, 5) .. (1005, 1005)
    std::ostringstream svg;
    SS::IO::write_motorcycle_graph_svg(svg, m, uv, g);
    assert(svg.str().find("nan") == std::string::npos && svg.str().find("inf") == std::string::npos);
    Mesh big_m = m;
    UV_map big = uv_of(big_m);
    for(halfedge_descriptor h : big_m.halfedges())
      if(!big_m.is_border(h))
        put(big, h, Point_2(std::ldexp(get(big, h).x() - n / 2., 1022), std::ldexp(get(big, h).y() - n / 2., 1022)));
    std::ostringstream svg_big;
    SS::IO::write_motorcycle_graph_svg(svg_big, big_m, big, SS::Motorcycle_graph<Mesh>());
    const std::string t = svg_big.str();
    assert(t.find("nan") == std::string::npos && t.find("inf") == std::string::npos);
    assert(t.find("5.00,1005.00") != std::string::npos && t.find("1005.00,5.00") != std::string::npos);
  }
  assert(g.layout.patches.size() == 1 && g.layout.patches[0].width == n && g.layout.nodes == 4 && g.layout.arcs == 4);
  std::cout << "trace: grid: OK\n";
}

// A flat n x n torus (each vertex (i, j) once, seams where the grid wraps, transitions: translations by
// n): isolines close. From a vertex along +u the trace runs along n edges and closes at its start
// corner; from the rational point (1/3, 1/7) along +v it closes after crossing 2n faces; both exactly.
// A flat n x n torus: vertex (i, j) once, corner UVs unwrapped (i, j) plus `noise` (uniform, seed 7);
// returns the vertices row by row and the triangle (0,0), (1,0), (1,1) in f_start.
static std::vector<vertex_descriptor> flat_torus(Mesh& m, UV_map& uv, int n, double noise, face_descriptor& f_start)
{
  std::vector<vertex_descriptor> vs;
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) vs.push_back(m.add_vertex(Point_3(i, j, 0)));
  uv = uv_of(m);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> e(-noise, noise);
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      const int I[4] = {i, i + 1, i + 1, i}, J[4] = {j, j, j + 1, j + 1};   // unwrapped corners a, b, c, d
      for(const std::array<int, 3>& t : {std::array<int, 3>{{0, 1, 2}}, std::array<int, 3>{{0, 2, 3}}}) {
        const face_descriptor f = m.add_face(vs[(J[t[0]] % n) * n + I[t[0]] % n], vs[(J[t[1]] % n) * n + I[t[1]] % n],
                                             vs[(J[t[2]] % n) * n + I[t[2]] % n]);
        assert(f != Mesh::null_face());
        for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m))
          for(int c : t)
            if(target(h, m) == vs[(J[c] % n) * n + I[c] % n])
              put(uv, h, Point_2(I[c] + (noise > 0 ? e(rng) : 0.), J[c] + (noise > 0 ? e(rng) : 0.)));
        if(i == 0 && j == 0 && t[2] == 2) f_start = f;
      }
    }
  return vs;
}

static void test_torus_closed_loops()
{
  const int n = 4;
  Mesh m;
  UV_map uv;
  face_descriptor f_start;
  const std::vector<vertex_descriptor> vs = flat_torus(m, uv, n, 0, f_start);
  Tracer tracer(m, uv);
  assert(tracer.status() == SS::SUCCESS && SS::is_exactly_seamless(m, uv));
  halfedge_descriptor corner;
  for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f_start), m)) if(target(h, m) == vs[0]) corner = h;
  Trace t = tracer.trace_from_vertex(corner, SS::Trace_direction::PLUS_U);
  assert(t.end == SS::Trace_end::CLOSED_LOOP && t.segments.size() == std::size_t(n));
  assert(target(t.segments.back().target.halfedge, m) == vs[0]);
  assert(t.has_start_vertex && t.start_vertex == vs[0] && t.has_start_corner && target(t.start_corner, m) == vs[0]);
  assert(face(t.start_corner, m) == t.segments.front().face);
  const CGAL::Gmpq u0(2, 3), v0(1, 7);                    // inside the triangle (0,0), (1,0), (1,1)
  t = tracer.trace_from_point(f_start, u0, v0, SS::Trace_direction::PLUS_V);
  assert(t.end == SS::Trace_end::CLOSED_LOOP && t.faces_crossed == std::size_t(2 * n));
  assert(t.segments.back().face == f_start && t.segments.back().target.u == u0 && t.segments.back().target.v == v0);
  // the motorcycle graph: no cones, no border: four seeded traces; advancing together, +u and -u meet
  // half-way round (as do +v and -v), each after n / 2 edges
  const auto start = std::chrono::steady_clock::now();
  SS::Motorcycle_graph<Mesh> g = SS::build_motorcycle_graph(tracer);
  const double call_ms = ms_since(start);
  // the phases' times: each phase ran, and together they are a part of the call's time
  const SS::Patch_layout& L = g.layout;
  assert(g.trace_ms > 0 && L.subdivision_ms > 0 && L.mesh_ms > 0 && L.measure_ms > 0);
  assert(g.trace_ms + L.subdivision_ms + L.mesh_ms + L.measure_ms <= call_ms);
  assert(g.seeded && g.separatrices.size() == 4 && g.failed == 0);
  for(const Trace& s : g.separatrices)
    assert(s.end == SS::Trace_end::EARLIER_TRACE && s.segments.size() == std::size_t(n / 2));
  check_layout(m, uv, g, "torus, seeded");
  assert(g.layout.patches.size() == 1 && g.layout.nodes == 1 && g.layout.arcs == 2);   // one square, two loops
  std::cout << "trace: torus: closed loops OK\n";
}

// Checks the patch layout of a valid motorcycle graph against properties computed here from the
// traced mesh itself: every patch a disk with 4 right-angle corners whose unfolded UV image is an
// axis-aligned rectangle; the rectangles' areas sum to the UV area of the mesh (exact, from its corner
// UVs); nodes - arcs + patches = V - E + F of the mesh; the refined mesh is a valid polygon mesh with the
// documented property maps, covers every face, keeps the 3D area, and survives a PLY round trip.
static void check_layout(const Mesh& m, UV_map uv, const SS::Motorcycle_graph<Mesh>& g, const std::string& what)
{
  const SS::Patch_layout& L = g.layout;
  if(!L.is_valid())
    std::cerr << what << ": layout " << SS::status_name(L.status) << " " << L.message << " patches " << L.patches.size()
              << " quads " << L.quad_patches << " euler " << L.euler_characteristic << "/" << L.surface_euler_characteristic
              << " unplaced " << L.unplaced_segments << std::endl;
  assert(L.status == SS::SUCCESS && L.unplaced_segments == 0 && !L.patches.empty());
  CGAL::Gmpq uv_area(0), rectangles(0), areas(0);
  bool aligned_border = true;                 // every border edge on an isoline (exact)
  for(face_descriptor f : m.faces()) {
    const halfedge_descriptor h = m.halfedge(f);
    const Point_2 a = get(uv, m.prev(h)), b = get(uv, h), c = get(uv, m.next(h));
    const CGAL::Gmpq au(a.x()), av(a.y()), bu(b.x()), bv(b.y()), cu(c.x()), cv(c.y());
    uv_area += ((bu - au) * (cv - av) - (bv - av) * (cu - au)) / 2;
    for(halfedge_descriptor k : CGAL::halfedges_around_face(h, m))
      if(m.is_border(m.opposite(k)) && get(uv, k).x() != get(uv, m.prev(k)).x() && get(uv, k).y() != get(uv, m.prev(k)).y())
        aligned_border = false;
  }
  std::size_t border_patches = 0;
  for(const SS::Layout_patch& p : L.patches) {
    const bool must_be_quad = aligned_border || !p.on_border;
    if(must_be_quad && !p.is_quad())
      std::cerr << what << ": patch of " << p.polygons << " polygons: euler " << p.euler_characteristic << " loops "
                << p.boundary_loops << " corners " << p.corners << " (" << p.right_angle_corners << " right) unfolds "
                << p.unfolds << " rectangle " << p.is_rectangle << std::endl;
    assert(p.is_disk() && p.unfolds);
    areas += p.area;
    if(!must_be_quad) { ++border_patches; continue; }
    assert(p.corners == 4 && p.right_angle_corners == 4 && p.is_rectangle && p.is_quad());
    assert(CGAL::is_positive(p.width) && CGAL::is_positive(p.height));
    rectangles += p.width * p.height;
  }
  assert(areas == uv_area && L.uv_area == uv_area);
  assert(border_patches > 0 || rectangles == uv_area);     // the rectangles tile the whole UV area, exactly
  const int chi = int(m.number_of_vertices()) - int(m.number_of_edges()) + int(m.number_of_faces());
  assert(L.euler_characteristic == chi && L.surface_euler_characteristic == chi);
  assert(L.quad_patches + border_patches >= L.patches.size() && (border_patches > 0 || L.is_valid()));
  // the message says why a layout is not valid (its patches along a border off the isolines), and nothing when it is
  assert(L.is_valid() ? L.message.empty()
                      : L.message == "not a quad layout: " + std::to_string(L.patches.size() - L.quad_patches) + " of " +
                                     std::to_string(L.patches.size()) + " patches are not quads (disks with 4 right-angle "
                                     "corners and a rectangle as UV image)");
  // the refined mesh
  const SS::Layout_mesh& r = L.mesh;
  assert(CGAL::is_valid_polygon_mesh(r));
  auto is_arc = r.property_map<SS::Layout_mesh::Edge_index, std::uint8_t>("e:is_arc");
  auto patch_id = r.property_map<SS::Layout_mesh::Face_index, std::int32_t>("f:patch_id");
  auto input_face = r.property_map<SS::Layout_mesh::Face_index, std::int32_t>("f:input_face");
  assert(is_arc.second && patch_id.second && input_face.second);
  std::vector<char> covered(m.number_of_faces(), 0);
  for(auto f : r.faces()) {
    assert(get(patch_id.first, f) >= 0 && std::size_t(get(patch_id.first, f)) < L.patches.size());
    covered[std::size_t(get(input_face.first, f))] = 1;
  }
  assert(std::find(covered.begin(), covered.end(), 0) == covered.end());
  std::size_t arc_edges = 0;
  for(auto e : r.edges()) {
    if(!get(is_arc.first, e)) continue;
    ++arc_edges;
    // an arc separates two patches, or a patch from itself only where it closes around (e.g. a torus)
    const bool border = r.is_border(e);
    assert(border || get(patch_id.first, r.face(r.halfedge(e))) >= 0);
  }
  // the layout graph: every arc a chain of arc/border edges from a node to a node, each such edge in one arc
  assert(L.node_vertices.size() == L.nodes && L.arc_chains.size() == L.arcs);
  std::size_t chain_edges = 0, border_edges = 0;
  for(const auto& chain : L.arc_chains) {
    assert(chain.size() >= 2);
    assert(std::find(L.node_vertices.begin(), L.node_vertices.end(), chain.front()) != L.node_vertices.end());
    assert(std::find(L.node_vertices.begin(), L.node_vertices.end(), chain.back()) != L.node_vertices.end());
    for(std::size_t i = 0; i + 1 < chain.size(); ++i) {
      const auto h = CGAL::halfedge(chain[i], chain[i + 1], r);
      assert(h.second && (get(is_arc.first, r.edge(h.first)) || r.is_border(r.edge(h.first))));
      ++chain_edges;
    }
  }
  for(auto e : r.edges()) border_edges += !get(is_arc.first, e) && r.is_border(e) ? 1 : 0;
  std::size_t traced = 0;
  for(const Trace& t : g.separatrices) traced += t.segments.empty() ? 0 : 1;
  assert(traced == 0 || arc_edges >= traced);
  assert(chain_edges == arc_edges + border_edges);
  double refined3 = 0;                                           // convex planar polygons: fans
  for(auto f : r.faces()) {
    std::vector<Point_3> p;
    for(auto v : CGAL::vertices_around_face(r.halfedge(f), r)) p.push_back(r.point(v));
    for(std::size_t i = 1; i + 1 < p.size(); ++i)
      refined3 += std::sqrt(CGAL::cross_product(p[i] - p[0], p[i + 1] - p[0]).squared_length()) / 2;
  }
  const double area3 = CGAL::Polygon_mesh_processing::area(m);
  assert(std::abs(area3 - refined3) <= 1e-9 * area3);             // positions are doubles: a closeness bound
  // PLY and OBJ files, read back with CGAL's readers: the faces, patch ids and arc flags come back
  const std::string base = (fs::temp_directory_path() / "ss_test_trace_layout").string();
  std::string msg;
  assert(SS::IO::write_patch_layout_PLY(base + ".ply", L, msg) == SS::SUCCESS);
  SS::Layout_mesh back;
  std::ifstream ply(base + ".ply");                   // the stream reader keeps the properties
  assert(CGAL::IO::read_PLY(ply, back) && back.number_of_faces() == r.number_of_faces());
  auto back_patch = back.property_map<SS::Layout_mesh::Face_index, std::int32_t>("f:patch_id");
  auto back_arc = back.property_map<SS::Layout_mesh::Edge_index, std::uint8_t>("e:is_arc");
  assert(back_patch.second && back_arc.second);
  for(auto f : r.faces()) assert(get(back_patch.first, f) == get(patch_id.first, f));
  std::size_t back_arcs = 0;
  for(auto e : back.edges()) back_arcs += get(back_arc.first, e) ? 1 : 0;
  assert(back_arcs == arc_edges);
  assert(SS::IO::write_patch_layout_OBJ(base + ".obj", L, msg, false) == SS::SUCCESS);   // CGAL reads no 'l' lines
  std::vector<Point_3> obj_points;
  std::vector<std::vector<std::size_t> > obj_faces;
  assert(CGAL::IO::read_OBJ(base + ".obj", obj_points, obj_faces) && obj_faces.size() == r.number_of_faces());
  assert(SS::IO::write_patch_layout_OBJ(base + ".obj", L, msg) == SS::SUCCESS);
  std::ifstream obj(base + ".obj");
  std::size_t lines = 0, groups = 0;
  for(std::string line; std::getline(obj, line); ) { lines += line.rfind("l ", 0) == 0; groups += line.rfind("g ", 0) == 0; }
  assert(lines == arc_edges && groups == L.patches.size());
  fs::remove(base + ".ply");
  fs::remove(base + ".obj");
  std::printf("trace: %-40s layout: %zu patches, %zu quads (%s); nodes %zu arcs %zu euler %d; %zu polygons, %zu arc edges\n",
              what.c_str(), L.patches.size(), L.quad_patches, aligned_border ? "all" : "unaligned border", L.nodes, L.arcs,
              L.euler_characteristic, std::size_t(r.number_of_faces()), arc_edges);
}

// Checks the properties of the motorcycle graph of an exactly seamless map without fold-overs and
// returns the graph. `what` names the map in the output. `collapsed_faces`: the map has zero-area faces with three
// distinct corners, which the traces cross, and the layout must be refused.
static SS::Motorcycle_graph<Mesh> check_exact_graph(const Mesh& m, UV_map uv, const std::string& what,
                                                    bool collapsed_faces = false)
{
  auto t0 = std::chrono::steady_clock::now();
  Tracer tracer(m, uv);
  assert(tracer.status() == SS::SUCCESS);
  SS::Motorcycle_graph<Mesh> g = SS::build_motorcycle_graph(tracer);
  const double graph_ms = ms_since(t0);
  assert(g.status == SS::SUCCESS);
  // every separatrix ends regularly: cone, border or T-junction (no inconsistency, no length limit)
  for(const Trace& t : g.separatrices) {
    if(t.end != SS::Trace_end::CONE && t.end != SS::Trace_end::BORDER && t.end != SS::Trace_end::EARLIER_TRACE &&
       !(g.seeded && t.end == SS::Trace_end::CLOSED_LOOP))
      std::cerr << what << ": separatrix ended with " << SS::trace_end_name(t.end) << " " << t.message << std::endl;
    assert(t.end == SS::Trace_end::CONE || t.end == SS::Trace_end::BORDER || t.end == SS::Trace_end::EARLIER_TRACE ||
           (g.seeded && t.end == SS::Trace_end::CLOSED_LOOP));
    assert(t.inexact_transfers == 0);
    assert(t.has_start_vertex && t.has_start_corner && target(t.start_corner, m) == t.start_vertex);
  }
  assert(g.failed == 0 && g.cones_with_wrong_ray_count == 0);
  // arcs meet only at their ends: no piece of an isoline is traced twice (compared exactly). Not the crossings of a
  // collapsed face, of zero UV length: the rays that leave its middle corner across its line (two where the line is
  // not an axis: the knight's) all cross it to the point of its long side at that corner (distinct pieces in the limit
  // of a thin positive triangle)
  std::set<std::string> pieces;
  for(const Trace& t : g.separatrices)
    for(const auto& s : t.segments) {
      if(s.source.u == s.target.u && s.source.v == s.target.v) continue;
      std::ostringstream a, b;
      std::string key;
      if(s.source.location == Point::VERTEX && s.target.location == Point::VERTEX) {   // along an edge: by its vertices
        const std::size_t i = std::size_t(target(s.source.halfedge, m)), j = std::size_t(target(s.target.halfedge, m));
        key = "edge " + std::to_string((std::min)(i, j)) + " " + std::to_string((std::max)(i, j));
      } else {
        a << s.source.u << " " << s.source.v;
        b << s.target.u << " " << s.target.v;
        key = "face " + std::to_string(std::size_t(s.face)) + ": " + (std::min)(a.str(), b.str()) + " - " + (std::max)(a.str(), b.str());
      }
      const bool fresh = pieces.insert(key).second;
      if(!fresh) std::cerr << what << ": traced twice: " << key << std::endl;
      assert(fresh);
    }
  // traced back from its end, every separatrix returns exactly to its start
  std::size_t traced_back = 0;
  t0 = std::chrono::steady_clock::now();
  for(const Trace& t : g.separatrices) {
    if(t.segments.empty()) continue;
    const Trace back = trace_back(m, tracer, t);
    assert(back.end == SS::Trace_end::TARGET && !back.segments.empty());
    const Point& start = t.segments.front().source;
    const Point& end = back.segments.back().target;
    if(!same_surface_point(m, start, end))
      std::cerr << what << ": trace back ended " << SS::trace_end_name(back.end) << " " << back.message << std::endl;
    assert(same_surface_point(m, start, end));
    if(back.segments.size() != t.segments.size())
      std::cerr << what << ": " << t.segments.size() << " segments, back " << back.segments.size() << " ("
                << SS::trace_end_name(t.end) << ", back " << SS::trace_end_name(back.end) << ")" << std::endl;
    assert(back.segments.size() == t.segments.size());
    ++traced_back;
  }
  std::printf("trace: %-40s cones %zu corners %zu separatrices %zu (cone %zu, border %zu, T %zu) traced back %zu;"
              " graph %.0f ms, back %.0f ms\n", what.c_str(), g.cones, g.border_corners, g.separatrices.size(),
              g.ends[int(SS::Trace_end::CONE)], g.ends[int(SS::Trace_end::BORDER)],
              g.ends[int(SS::Trace_end::EARLIER_TRACE)], traced_back, graph_ms, ms_since(t0));
  if(!collapsed_faces) {
    check_layout(m, uv, g, what);
    check_independent_of_numbering(m, uv, g, what);
  } else {                                 // zero-area faces: traced through, but no layout (reported)
    assert(g.layout.status != SS::SUCCESS && g.layout.message.find("degenerate") != std::string::npos);
    std::printf("trace: %-40s layout refused: %s\n", what.c_str(), g.layout.message.c_str());
  }
  return g;
}

// The motorcycle graph does not depend on the numbering of the mesh: the map with its vertices and faces shuffled and
// each face's corners rotated (a fixed seed) has as many separatrices ending per reason, the same nodes and arcs, and
// patches of the same exact sizes (sorted pairs of shorter and longer side).
static void check_independent_of_numbering(const Mesh& m, UV_map uv, const SS::Motorcycle_graph<Mesh>& g,
                                           const std::string& what)
{
  Mesh p;
  UV_map puv = uv_of(p);
  const std::vector<halfedge_descriptor> origin = renumbered_copy(m, 7, p);
  for(halfedge_descriptor k : p.halfedges()) if(!p.is_border(k)) put(puv, k, get(uv, origin[std::size_t(k)]));
  const Tracer tracer(p, puv);
  assert(tracer.status() == SS::SUCCESS);
  const SS::Motorcycle_graph<Mesh> h = SS::build_motorcycle_graph(tracer);
  typedef std::vector<std::pair<CGAL::Gmpq, CGAL::Gmpq> > Sizes;
  auto sizes = [](const SS::Patch_layout& L) {
    Sizes out;
    for(const SS::Layout_patch& q : L.patches) out.emplace_back((std::min)(q.width, q.height), (std::max)(q.width, q.height));
    std::sort(out.begin(), out.end());
    return out;
  };
  const bool same = h.ends == g.ends && h.layout.nodes == g.layout.nodes && h.layout.arcs == g.layout.arcs &&
                    sizes(h.layout) == sizes(g.layout);
  if(!same)
    std::cerr << what << ": renumbered: " << h.layout.patches.size() << " patches, " << h.layout.nodes << " nodes, "
              << h.layout.arcs << " arcs; before " << g.layout.patches.size() << ", " << g.layout.nodes << ", "
              << g.layout.arcs << std::endl;
  assert(same);
  std::printf("trace: %-40s renumbered: the same ends, %zu patches (sizes), %zu nodes, %zu arcs\n", what.c_str(),
              g.layout.patches.size(), g.layout.nodes, g.layout.arcs);
}

// the motorcycle graph of a map as it is (inexact in general): it must terminate, and report
// failures with a message; adds its failures and its inexact cut crossings to the counters
static void print_inexact_graph(const Mesh& m, UV_map uv, const std::string& what, std::size_t& failures,
                                std::size_t& inexact_crossings)
{
  Tracer tracer(m, uv);
  if(tracer.status() != SS::SUCCESS) { std::cout << "trace: " << what << ": " << tracer.message() << "\n"; return; }
  auto t0 = std::chrono::steady_clock::now();
  SS::Motorcycle_graph<Mesh> g = SS::build_motorcycle_graph(tracer);
  std::printf("trace: %-40s (input) separatrices %zu failed %zu:", what.c_str(), g.separatrices.size(), g.failed);
  for(int e = 0; e < SS::number_of_trace_ends; ++e)
    if(g.ends[e]) std::printf(" %s %zu", SS::trace_end_name(SS::Trace_end(e)), g.ends[e]);
  if(g.layout.status == SS::SUCCESS)
    std::printf("; layout %zu patches, %zu quads, %zu unplaced", g.layout.patches.size(), g.layout.quad_patches,
                g.layout.unplaced_segments);
  else std::printf("; no layout (%s)", g.layout.message.c_str());
  std::printf("  %.0f ms\n", ms_since(t0));
  for(const Trace& t : g.separatrices) {
    assert(!t.message.empty() || !SS::is_failure(t.end));
    inexact_crossings += t.inexact_transfers;
  }
  failures += g.failed;
}

// CGAL's bear with an Orbifold Tutte square map (3 farthest-point cones); false (and a note) without CGAL's data
static bool bear_orbifold(Mesh& m, UV_map& uv, const std::string& what)
{
  const fs::path p = fs::path(SS_CGAL_DATA_DIR) / "bear.off";
  if(std::string(SS_CGAL_DATA_DIR).empty() || !fs::exists(p) || !CGAL::IO::read_polygon_mesh(p.string(), m)) {
    std::cout << "trace: " << what << ": SKIPPED (no " << p.string() << ")\n";
    return false;
  }
  uv = uv_of(m);
  std::string msg;
  assert(SS::internal::make_orbifold_tutte_uv(m, uv, SS::internal::farthest_point_cones(m, 3), SMP::Square, msg) == SS::SUCCESS);
  return true;
}

static void test_bear_orbifold()
{
  Mesh m;
  UV_map uv;
  if(!bear_orbifold(m, uv, "bear orbifold")) return;
  std::size_t failures = 0, inexact = 0;
  print_inexact_graph(m, uv, "bear orbifold Square", failures, inexact);
  assert(!SS::is_exactly_seamless(m, uv) && inexact > 0);   // the tracer sees the solver error at the cuts
  SS::Snap_report r = SS::snap_seamless_parameterization(m, uv);
  assert(r.status == SS::SUCCESS && r.flips_after == 0);
  SS::Motorcycle_graph<Mesh> g = check_exact_graph(m, uv, "bear orbifold Square, snapped");
  assert(g.cones == 3 && g.separatrices.size() == 4);     // cones of 1, 1 and 2 quarter turns
}

// Cut invariance: the motorcycle graph belongs to the surface map, not to its charts. The bear's Square map, snapped,
// with the faces within 4 and 12 face rings of a cone re-expressed by a quarter turn (the region's border becomes
// cut edges): the same separatrices and ends, the same nodes, arcs and patches with the same exact sizes, and the
// refined mesh with the same 3D points, bit for bit
static void test_cut_invariance()
{
  Mesh input;
  UV_map uv_in;
  if(!bear_orbifold(input, uv_in, "cut invariance")) return;
  assert(SS::snap_seamless_parameterization(input, uv_in).status == SS::SUCCESS);
  struct Summary
  {
    std::size_t separatrices, nodes, arcs;
    std::array<std::size_t, SS::number_of_trace_ends> ends;
    std::vector<std::pair<CGAL::Gmpq, CGAL::Gmpq> > sizes;   // the patches' sides (shorter, longer; width and height
                                                            // are those of the chart a patch unfolds into), sorted
    std::vector<SS::Layout_mesh::Point> points;             // the refined mesh's, sorted
    bool operator==(const Summary& o) const
    {
      return separatrices == o.separatrices && nodes == o.nodes && arcs == o.arcs && ends == o.ends && sizes == o.sizes &&
             points == o.points;
    }
  };
  vertex_descriptor cone;                                   // the region is around a cone: the separatrices start in it
  auto summary = [&cone](const Mesh& m, UV_map uv, const std::string& what) {
    const SS::Motorcycle_graph<Mesh> g = check_exact_graph(m, uv, what);
    cone = g.separatrices.front().start_vertex;             // (the same cone for every map here: asserted below)
    Summary s{g.separatrices.size(), g.layout.nodes, g.layout.arcs, g.ends, {}, {}};
    for(const SS::Layout_patch& p : g.layout.patches) s.sizes.emplace_back((std::min)(p.width, p.height), (std::max)(p.width, p.height));
    for(SS::Layout_mesh::Vertex_index v : g.layout.mesh.vertices()) s.points.push_back(g.layout.mesh.point(v));
    std::sort(s.sizes.begin(), s.sizes.end());
    std::sort(s.points.begin(), s.points.end());
    return s;
  };
  const Summary before = summary(input, uv_in, "bear orbifold Square, snapped");
  for(int rings : {4, 12}) {
    Mesh m = input;
    UV_map uv = uv_of(m);
    const std::size_t new_cuts = recharted(m, uv, cone, rings);
    assert(new_cuts > 0 && SS::is_exactly_seamless(m, uv));
    const vertex_descriptor center = cone;
    const Summary after = summary(m, uv, "bear, " + std::to_string(rings) + " rings re-charted");
    assert(after == before && cone == center);
    std::printf("trace: bear orbifold Square, %d face rings re-charted (%zu new cut edges): the same %zu separatrices, "
                "%zu patches, %zu points of the refined mesh, bit for bit\n", rings, new_cuts, after.separatrices,
                after.sizes.size(), after.points.size());
  }
  // scale covariance: the map times 2^j (exact) has the same separatrices, ends, nodes and arcs, its patches the sizes
  // times 2^j, its refined mesh the same 3D points, bit for bit
  for(int j : {-20, 40}) {
    Mesh m = input;
    UV_map uv = uv_of(m);
    scale_uvs(m, uv, j);
    Summary expected = before;
    const CGAL::Gmpq factor(std::ldexp(1., j));
    for(std::pair<CGAL::Gmpq, CGAL::Gmpq>& s : expected.sizes) { s.first *= factor; s.second *= factor; }
    assert(summary(m, uv, "bear, scaled by 2^" + std::to_string(j)) == expected);
    std::printf("trace: bear orbifold Square, UVs times 2^%d: the same graph, patch sizes times 2^%d, the same 3D points\n", j, j);
  }
}

// Connection constraints realized by traces (Fig. 4 of the paper): on CGAL's bear with an Orbifold Tutte
// square map, every pair of cones that the input puts on a common isoline up to solver error (along the
// shortest edge path, to 1e-6 of the UV diameter) becomes a connection constraint. After snapping with
// them, one of the rays of the first cone ends exactly at the second cone; after plain snapping they miss.
static void test_connections_realized()
{
  Mesh m;
  UV_map uv;
  if(!bear_orbifold(m, uv, "connections")) return;
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for(halfedge_descriptor h : m.halfedges()) {
    if(m.is_border(h)) continue;
    lo[0] = (std::min)(lo[0], get(uv, h).x()); hi[0] = (std::max)(hi[0], get(uv, h).x());
    lo[1] = (std::min)(lo[1], get(uv, h).y()); hi[1] = (std::max)(hi[1], get(uv, h).y());
  }
  const double diameter = std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
  const std::vector<vertex_descriptor> cones = connection_test::find_cones(m, uv);
  std::vector<connection_test::Constraint> cc;
  for(vertex_descriptor a : cones)
    for(vertex_descriptor b : cones)
      for(int comp : {0, 1}) {
        if(a == b) continue;
        connection_test::Constraint c(connection_test::shortest_path(m, a, b), comp);
        const connection_test::Check_result cr = connection_test::unfold_path(m, uv, uv, false, c);
        const double d[2] = {CGAL::to_double(cr.end.x - cr.start.x), CGAL::to_double(cr.end.y - cr.start.y)};
        if(std::abs(d[comp]) > 1e-6 * diameter || std::abs(d[1 - comp]) < 1e-3 * diameter) continue;
        cc.push_back(c);
      }
  assert(!cc.empty());
  Mesh plain = m, connected = m;
  UV_map uv_plain = uv_of(plain), uv_conn = uv_of(connected);
  assert(SS::snap_seamless_parameterization(plain, uv_plain).status == SS::SUCCESS);
  const SS::Snap_report r = SS::snap_seamless_parameterization(connected, uv_conn, SS::parameters::connection_constraints(cc));
  assert(r.status == SS::SUCCESS);
  Tracer t_plain(plain, uv_plain), t_conn(connected, uv_conn);
  std::size_t realized = 0, missed_plain = 0;
  for(std::size_t i = 0; i < cc.size(); ++i) {
    const connection_test::Constraint& c = cc[i];
    assert(connection_test::exact_connection_holds(connected, uv_conn, uv, c).holds);
    const vertex_descriptor a = m.source(c.path.front()), b = m.target(c.path.back());
    SS::Trace_options<Mesh> o;
    o.has_target_vertex = true;
    o.target_vertex = b;
    o.max_faces = 5000;                          // a connecting isoline crosses a few hundred faces; a miss spirals on
    // the rays from a (a cone: only the axis directions inside its sectors start); one must end at b
    auto reaches_b = [&](const Tracer& tracer, std::string& ends) {
      bool hit = false;
      for(halfedge_descriptor corner : CGAL::halfedges_around_target(a, m)) {
        if(m.is_border(corner)) continue;
        for(int d = 0; d < 4; ++d) {
          const Trace t = tracer.trace_from_vertex(corner, SS::Trace_direction(d), o);
          if(t.end == SS::Trace_end::INVALID_START || t.start_corner != corner) continue;   // the ray of another sector
          ends += std::string(" ") + SS::trace_end_name(t.end);
          hit = hit || (t.end == SS::Trace_end::TARGET && t.inexact_transfers == 0);
        }
      }
      return hit;
    };
    std::string ends_conn, ends_plain;
    const bool hit = reaches_b(t_conn, ends_conn);
    if(!hit) std::cerr << "connection " << a << " -> " << b << " (" << c.component << "): rays end" << ends_conn << std::endl;
    assert(hit);
    ++realized;
    missed_plain += reaches_b(t_plain, ends_plain) ? 0 : 1;
  }
  std::cout << "trace: connections: " << cc.size() << " cone pairs on a common isoline (input error <= 1e-6 of the UV"
            << " diameter): realized exactly by a trace after snapping with them " << realized << ", missed after plain snapping "
            << missed_plain << "\n";
  assert(realized == cc.size() && missed_plain > 0);
}

// A cycle constraint closes its isoline: a flat n x n torus whose corner UVs carry noise of 1e-9 is
// snapped (a) plainly: the +u isoline through a vertex spirals (the transition's v-translation is not 0);
// (b) with the cycle constraint "v agrees once around the row j = 0": the same trace closes exactly.
static void test_cycle_closes()
{
  const int n = 4;
  Mesh m;
  UV_map uv;
  face_descriptor f_start;
  const std::vector<vertex_descriptor> vs = flat_torus(m, uv, n, 1e-9, f_start);
  connection_test::Constraint cycle;
  cycle.component = 1;
  for(int i = 0; i < n; ++i) cycle.path.push_back(CGAL::halfedge(vs[i], vs[(i + 1) % n], m).first);
  const halfedge_descriptor corner = m.prev(cycle.path.front());   // (vs[0], the face above the row)
  Mesh plain = m;
  UV_map uv_plain = uv_of(plain);
  assert(SS::snap_seamless_parameterization(plain, uv_plain).status == SS::SUCCESS);
  const std::vector<connection_test::Constraint> cc(1, cycle);
  assert(SS::snap_seamless_parameterization(m, uv, SS::parameters::connection_constraints(cc)).status == SS::SUCCESS);
  const Trace spiral = Tracer(plain, uv_plain).trace_from_vertex(corner, SS::Trace_direction::PLUS_U);
  const Trace loop = Tracer(m, uv).trace_from_vertex(corner, SS::Trace_direction::PLUS_U);
  std::cout << "trace: cycle: plain snap: " << SS::trace_end_name(spiral.end) << " after " << spiral.faces_crossed
            << " faces; with the cycle constraint: " << SS::trace_end_name(loop.end) << " after " << loop.faces_crossed << " faces\n";
  assert(spiral.end != SS::Trace_end::CLOSED_LOOP);
  assert(loop.end == SS::Trace_end::CLOSED_LOOP && loop.inexact_transfers == 0);
  assert(target(loop.segments.back().target.halfedge, m) == vs[0]);
}

// every zero-area UV triangle of the map has three distinct corners (exactly)
static bool zero_area_faces_collinear(const Mesh& m, UV_map uv)
{
  for(face_descriptor f : m.faces()) {
    const halfedge_descriptor h = m.halfedge(f);
    const Point_2 a = get(uv, m.prev(h)), b = get(uv, h), c = get(uv, m.next(h));
    if(CGAL::orientation(a, b, c) == CGAL::COLLINEAR && (a == b || b == c || c == a)) return false;
  }
  return true;
}

// A zero-area face with three distinct corners is crossed: the square [0, 2]^2 with the face (A, C, c) on its
// diagonal, c = (t, t) between A = (0, 0) and C = (2, 2) (test_quad's collapsed face). From (3/2, 1/4) along +v the
// isoline crosses the diagonal at (3/2, 3/2): through the collapsed face into (c, C, D) for t = 1, through the vertex c
// for t = 3/2; from c into the face's own wedge along -v it leaves through the long side: the border at (t, 0).
static void test_collapsed_face()
{
  for(const CGAL::Gmpq& t : {CGAL::Gmpq(1), CGAL::Gmpq(3, 2)}) {
    Mesh m;
    const double td = CGAL::to_double(t);
    const vertex_descriptor A = m.add_vertex(Point_3(0, 0, 0)), B = m.add_vertex(Point_3(2, 0, 0)),
                            C = m.add_vertex(Point_3(2, 2, 0)), D = m.add_vertex(Point_3(0, 2, 0)),
                            c = m.add_vertex(Point_3(td, td, 0.5));
    const face_descriptor below = m.add_face(A, B, C);
    m.add_face(A, C, c);
    m.add_face(c, C, D);
    m.add_face(A, c, D);
    UV_map uv = uv_of(m);
    uv_from_xy(m, uv);
    Tracer tracer(m, uv);
    assert(tracer.status() == SS::SUCCESS);
    const Trace up = tracer.trace_from_point(below, CGAL::Gmpq(3, 2), CGAL::Gmpq(1, 4), SS::Trace_direction::PLUS_V);
    assert(up.end == SS::Trace_end::BORDER && up.inexact_transfers == 0);
    assert(up.segments.back().target.u == CGAL::Gmpq(3, 2) && up.segments.back().target.v == CGAL::Gmpq(2));
    for(const auto& s : up.segments) assert(s.source.u == CGAL::Gmpq(3, 2) && s.target.u == CGAL::Gmpq(3, 2));
    const Trace back = trace_back(m, tracer, up);
    assert(back.end == SS::Trace_end::TARGET && back.segments.size() == up.segments.size());
    assert(back.segments.back().target.u == CGAL::Gmpq(3, 2) && back.segments.back().target.v == CGAL::Gmpq(1, 4));
    const halfedge_descriptor corner = CGAL::halfedge(C, c, m).first;     // c in the collapsed face
    const Trace down = tracer.trace_from_vertex(corner, SS::Trace_direction::MINUS_V);
    assert(down.end == SS::Trace_end::BORDER && down.inexact_transfers == 0);
    assert(down.segments.back().target.u == t && down.segments.back().target.v == CGAL::Gmpq(0));
    // connected in 3D: the crossing of the collapsed face is a segment of zero UV length, from the side or the middle
    // vertex c where the trace enters it to where it leaves it (it was left out, and the polyline jumped there)
    assert(down.segments.front().face == CGAL::face(corner, m) && down.segments.front().source.position[2] == 0.5);
    for(const Trace* trace : {&up, &back, &down})
      for(std::size_t i = 1; i < trace->segments.size(); ++i)
        for(int k = 0; k < 3; ++k)
          assert(std::abs(trace->segments[i].source.position[std::size_t(k)] -
                          trace->segments[i - 1].target.position[std::size_t(k)]) < 1e-12);
  }
  std::cout << "trace: collapsed face: crossed exactly (middle corner on and off the isoline), connected in 3D\n";
}

static void test_shared_data()
{
  std::vector<fs::path> files;
  if(!shared_obj_files_or_skip("trace: shared data", files)) return;
  std::size_t exact_maps = 0, untangled_maps = 0, collapsed_maps = 0, input_failures = 0, inexact_inputs = 0,
              inputs_seen_inexact = 0;
  for(const fs::path& p : files) {
    if(fs::file_size(p) > 1000000) continue;     // the large files are in bench_trace
    Mesh m;
    if(!load_obj(p, m)) continue;
    UV_map uv = uv_of(m);
    std::size_t crossings = 0;
    print_inexact_graph(m, uv, p.filename().string(), input_failures, crossings);
    if(!SS::is_exactly_seamless(m, uv)) { ++inexact_inputs; inputs_seen_inexact += crossings > 0 ? 1 : 0; }
    const Mesh input = m;
    SS::Snap_report r = SS::snap_seamless_parameterization(m, uv);
    if(r.status == SS::SUCCESS && r.flips_before > 0) {
      // fold-overs in the input: the snap keeps them, the untangling removes them (the knight's 3); then the
      // map is locally injective and its layout valid
      m = input;
      uv = uv_of(m);
      r = SS::snap_seamless_parameterization(m, uv, SS::parameters::untangle(true));
      if(r.status == SS::SUCCESS && r.flips_after_repair + r.degenerate_after_repair == 0 && r.winding_defects.empty()) {
        const SS::Motorcycle_graph<Mesh> g = check_exact_graph(m, uv, p.filename().string() + ", untangled");
        assert(!CGAL::is_closed(m) || g.layout.is_valid());
        ++exact_maps;
        ++untangled_maps;
        // integer-grid mode: the knight keeps a forced zero-area face with three distinct (collinear) corners; the
        // separatrices cross it (two start into it at its middle corner), the layout is refused
        Mesh mi = input;
        UV_map uvi = uv_of(mi);
        const SS::Snap_report ri = SS::snap_seamless_parameterization(mi, uvi, SS::parameters::integer_grid_map(true));
        if(ri.status == SS::SUCCESS && ri.flips_after_repair == 0 && ri.degenerate_after_repair > 0 &&
           ri.winding_defects.empty() && zero_area_faces_collinear(mi, uvi)) {
          check_exact_graph(mi, uvi, p.filename().string() + ", IGM, collapsed faces", true);
          ++collapsed_maps;
        }
        continue;
      }
    }
    if(r.status != SS::SUCCESS || r.flips_before > 0) {
      std::cout << "trace: " << p.filename().string() << ": snapped map not checked (" << SS::status_name(r.status)
                << ", " << r.flips_before << " fold-overs in the input)\n";
      continue;
    }
    check_exact_graph(m, uv, p.filename().string() + ", snapped");
    ++exact_maps;
  }
  std::cout << "trace: shared data: " << exact_maps << " snapped maps checked (" << untangled_maps
            << " untangled first), " << collapsed_maps << " integer-grid maps with collapsed faces traced; inexact inputs: "
            << input_failures
            << " failed separatrices; " << inputs_seen_inexact << " of " << inexact_inputs
            << " inexact inputs show inexact cut crossings\n";
  assert(exact_maps >= 3);
  assert(inexact_inputs == 0 || inputs_seen_inexact > 0);
}

// libQEx's maps (over 1 MB, so not in test_shared_data()) snapped to exact integer-grid maps with their collapsed cone
// pairs merged (merge_cone_pairs(true)) and untangled: locally injective, so every separatrix ends regularly and the
// layout is valid (every patch a rectangle). Where traces reach one point at the same time (on integer-grid maps at
// integer points), one goes on at most (else a patch there would have a 270-degree corner).
static void test_merged_libqex_maps()
{
  std::vector<fs::path> files;
  if(!shared_obj_files_or_skip("trace: libQEx maps, cone pairs merged", files)) return;
  std::size_t layouts = 0;
  for(const fs::path& p : files) {
    const std::string name = p.filename().string();
    if(name != "fandisk_param.obj" && name != "duck_miq_8_param.obj" && name != "duck_qc_8_param.obj") continue;
    Mesh m;
    if(!load_obj(p, m)) continue;
    UV_map uv = uv_of(m);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).merge_cone_pairs(true));
    assert(r.status == SS::SUCCESS && r.flips_after_repair + r.degenerate_after_repair == 0 && r.winding_defects.empty());
    const SS::Motorcycle_graph<Mesh> g = check_exact_graph(m, uv, name + ", IGM with cone pairs merged");
    assert(g.layout.is_valid());
    ++layouts;
  }
  std::cout << "trace: libQEx maps, cone pairs merged: " << layouts << " valid layouts\n";
}

int main(int argc, char** argv)
{
  std::setvbuf(stdout, nullptr, _IONBF, 0);
  parse_test_arguments(argc, argv);
  test_grid();
  test_torus_closed_loops();
  test_cycle_closes();
  test_collapsed_face();
  if(!sanitizer_subset()) test_bear_orbifold();
  if(!sanitizer_subset()) test_cut_invariance();
  if(!sanitizer_subset()) test_connections_realized();
  test_shared_data();
  if(!sanitizer_subset()) test_merged_libqex_maps();
  std::cout << "test_trace: all passed\n";
  return 0;
}
