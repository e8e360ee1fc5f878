// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// Tests of the quad layer: extract_quad_mesh() on exact integer-grid maps, and quad_valences() against it.
//   quad: exact tests on doubles  same_difference() and is_integer_sum() (Dyadic_sum, used by the exact integer-grid
//                               check) agree with Gmpq on 200000 random, near-miss and exact cases
// Every extracted mesh is checked here, independently of the extractor (check_quad_mesh()): a valid
// manifold polygon mesh of quads; closed when the map is; V - E + F and the number of quads equal to the
// map's Euler characteristic and exact UV area (Gmpq, computed here from the corner UVs) when no cell was
// dropped; every quad vertex maps back exactly to its integer UV (a corner UV of its vertex, a point of its
// edge, a point inside its face, compared in Gmpq); its valence is quad_valences()'s for a mesh vertex, 4
// elsewhere inside (3 on a border edge), so that the irregular vertices are exactly the cones; every face of
// the map is covered; the report agrees with the mesh; its patches (quad_mesh_patches(), check_quad_patches())
// are rectangles of quads, every quad a cell of its patch's grid consistent with its neighbours; its quad layout
// (quad_layout(), check_quad_layout()) has a face per patch whose sides between its 4 corners are the patch's width
// and height, arcs whose chains of quad edges run along the patch sides, and the quad mesh's Euler characteristic;
// and, on a map with cones that the quads cover, the motorcycle graph traced on the map itself
// (build_motorcycle_graph(): exact event times, no code shared with the quad layer) has the same layout
// (check_traced_layout()), and so does the one traced on the closed quad mesh itself, triangulated, with its patches as
// charts (check_traced_patch_charts(): every meeting of traces at a vertex).
//   quad: cube                  a generated exact IGM with 8 cones of valence 3, sides 1-3, grid scales 1, 2:
//                               6 n^2 S^2 quads, chi 2; the map scaled by 2^-3 with grid_scale 8 gives the same
//                               mesh bit for bit (scale covariance)
//   quad: torus                 flat tori (no cone): n^2 quads, chi 0, all valence 4; a torus of one cell (its
//                               four corners one point: INVALID_INPUT), cells sharing all sides (2 x 2 cells: not
//                               a polygon mesh, INVALID_INPUT), a non-integer period (not an IGM, INVALID_INPUT)
//   quad: grid                  a planar grid: border on isolines (16 quads, valences 2/3/4), and shifted off
//                               them (the 16 cells cut by the border dropped and counted, 9 quads)
//   quad: collapsed face        a square whose diagonal carries a zero-area face (three distinct collinear corners):
//                               collapsed onto its long side, a 2 x 2 grid whose cells on the diagonal cover it, the
//                               middle corner on the integer point or not; two corners at one UV point: FOLD_OVERS
//   quad: refusals              fold-overs and zero-area triangles (FOLD_OVERS, exactly the faces counted here,
//                               quad_valences() the same), a 90-degree cone (valence 1), a grid scale that is
//                               not a power of two; the output mesh is unchanged on every refusal
//   quad: patches refine        at twice the grid scale every patch is twice as long on both sides (the cubes at scales
//                               1, 2, the bear at 2, 4, 8, the horse at 1, 2)
//   quad: patches refused       quad_mesh_patches() on triangles, on two quads with one vertex in common, on a mesh
//                               with a removed face: INVALID_INPUT, nothing written; the last after collect_garbage(),
//                               a torus with a hole: 4 nodes, rectangles; a quad and a ring of quads (the ring seeded
//                               on its own: two rectangles) (every extracted mesh above and below gets its patches, their
//                               independence of the numbering and its quad layout checked too)
//   quad: branch points         a vertex of 8 quarter turns in one chart: on an integer point a vertex of valence 8
//                               (8 quads around it); inside a cell of a disk wound 2 or 3 times: the cell's 4m-gon
//                               filled with 2m - 1 quads (4(m - 1) vertices of valence 5, the branch point no quad
//                               vertex), refused without fill_branched_cells; on a grid line, or in a cell whose
//                               neighbours the border cuts: refused (INVALID_INPUT)
//   quad: bear orbifold         CGAL's bear, Orbifold Tutte Parallelogram map (4 cones of 180 degrees) snapped
//                               with integer_grid_map(true) at grid scales 2, 4, 8: chi 2, 4 cones of valence 2,
//                               scale covariance; the Square map (cones of 90 degrees): at grid scale 1 refused
//                               (its two cones within two cells), at 8 both split (250 quads, chi 2)
//   quad: cut invariance        the bear's Parallelogram IGM with the faces within 1, 4, 12 rings of a cone
//                               re-expressed by a quarter turn (the cut graph moves): the same quads with the same
//                               3D points, bit for bit
//   quad: shared data           every shared map up to 1 MB (600 kB under --sanitizer-subset) snapped with
//                               integer_grid_map(true): fold-free ones give a checked quad mesh (the horse also
//                               at grid scale 2), the same bit for bit with 8 face rings re-charted; the ones with
//                               fold-overs FOLD_OVERS listing the snap report's flipped and zero-area faces (but
//                               zero-area faces with three distinct corners: the knight's forced one is collapsed),
//                               maps with a cone of 90 degrees (the knight) split (checked quad mesh, three more
//                               irregular vertices than cones less one), refused with split_valence_one_cones(false):
//                               INVALID_INPUT, said to be the map's own cone where no vertex winds twice
//   quad: cone of 90 degrees    a generated quarter plane [0, n]^2 with its sides glued, n = 2, 3, 4, grid scales 1, 2:
//                               the cone's 2 x 2 cells one quad (n^2 S^2 - 3 quads, chi 1, three vertices of valence
//                               3 inside where n S > 2, the cone no quad vertex); refused without the split
//   quad: collapsed cone pairs  libQEx's fandisk and duck_miq_8 (IGM, untangled, fold-free): refused, the message
//                               naming a cone pair the integer translations put onto one point, as the snap report does

#include "mesh_test_support.h"
#include "patch_chart_map.h"

#include <CGAL/Seamless_snapping/Motorcycle_graph.h>
#include <CGAL/Seamless_snapping/extract_quad_mesh.h>
#include <CGAL/Seamless_snapping/internal/inputs/orbifold_tutte_input.h>
#include <CGAL/Seamless_snapping/is_exact_integer_grid_map.h>
#include <CGAL/Seamless_snapping/quad_layout.h>
#include <CGAL/Seamless_snapping/quad_mesh_patches.h>
#include <CGAL/Seamless_snapping/quad_valences.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <cassert>
#include <cstdio>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

typedef Mesh::Face_index face_descriptor;
typedef SS::Quad_vertex_origin<Mesh> Origin;
typedef Mesh::Property_map<vertex_descriptor, Origin> Origin_map;
typedef Mesh::Property_map<face_descriptor, std::vector<face_descriptor> > Covered_map;
typedef CGAL::Gmpq Q;

struct Quad_result
{
  SS::Quad_mesh_report report;
  Mesh q;                        // the quad mesh (the same Surface_mesh type as the input)
  Origin_map origin;
  Covered_map covered;
};

static void extract(const Mesh& m, UV_map uv, double S, Quad_result& r)
{
  r.origin = r.q.add_property_map<vertex_descriptor, Origin>("v:origin").first;
  r.covered = r.q.add_property_map<face_descriptor, std::vector<face_descriptor> >("f:covered").first;
  r.report = SS::extract_quad_mesh(m, uv, r.q, SS::parameters::grid_scale(S),
                                   SS::parameters::vertex_origin_map(r.origin).face_origin_map(r.covered));
}

static int euler(const Mesh& m)
{
  return int(m.number_of_vertices()) - int(m.number_of_edges()) + int(m.number_of_faces());
}

// the exact UV area of m in grid units (UVs times S), from its corner UVs
static Q uv_area(const Mesh& m, UV_map uv, double S)
{
  Q twice(0);
  for(face_descriptor f : m.faces()) {
    const halfedge_descriptor h = m.halfedge(f);
    const Point_2 a = get(uv, m.prev(h)), b = get(uv, h), c = get(uv, m.next(h));
    twice += (Q(b.x()) - Q(a.x())) * (Q(c.y()) - Q(a.y())) - (Q(b.y()) - Q(a.y())) * (Q(c.x()) - Q(a.x()));
  }
  return twice * Q(S) * Q(S) / 2;
}

static Q cross(const std::array<Q, 2>& a, const std::array<Q, 2>& b, const std::array<Q, 2>& c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static std::array<Q, 2> exact_uv(UV_map uv, halfedge_descriptor h)
{
  return {{Q(get(uv, h).x()), Q(get(uv, h).y())}};
}

// The quad vertex's origin maps back exactly to its integer UV: P = (u, v) / S in the chart of its face is
// the corner UV of its vertex (VERTEX), a point strictly inside its edge (EDGE), strictly inside its face
// (FACE); its position is the barycentric point, rounded (checked to 1e-12 of the bounding box).
static void check_origin(const Mesh& m, UV_map uv, double S, const Origin& o, const Point_3& position, double diagonal)
{
  assert(m.face(o.halfedge) == o.face && o.face != Mesh::null_face());
  const std::array<Q, 2> P = {{Q(double(o.u)) / Q(S), Q(double(o.v)) / Q(S)}};
  const halfedge_descriptor h = o.halfedge;
  const std::array<Q, 2> a = exact_uv(uv, m.prev(h)), b = exact_uv(uv, h), c = exact_uv(uv, m.next(h));
  std::array<Q, 3> w;                              // barycentric w.r.t. source(h), target(h), target(next(h))
  const Q total = cross(a, b, c);
  w[0] = cross(P, b, c) / total; w[1] = cross(a, P, c) / total; w[2] = Q(1) - w[0] - w[1];
  if(o.location == Origin::VERTEX) {
    assert(b == P && position == m.point(m.target(h)));
    return;
  }
  assert(CGAL::is_zero(w[2]) == (o.location == Origin::EDGE));
  assert(CGAL::is_positive(w[0]) && CGAL::is_positive(w[1]) && (o.location == Origin::EDGE || CGAL::is_positive(w[2])));
  const vertex_descriptor vs[3] = {m.source(h), m.target(h), m.target(m.next(h))};
  double x[3] = {0, 0, 0};
  for(int i = 0; i < 3; ++i)
    for(int k = 0; k < 3; ++k) x[k] += CGAL::to_double(w[std::size_t(i)]) * m.point(vs[i])[k];
  for(int k = 0; k < 3; ++k) assert(std::abs(position[k] - x[k]) <= 1e-12 * diagonal);
}

// Checks r against m (see the header comment); `what` names the map in the output line.
typedef std::vector<std::pair<int, int> > Patch_sizes;   // per patch (shorter side, longer side), sorted
static Patch_sizes check_quad_patches(const Mesh& q, const std::string& what);
static void check_traced_layout(const Mesh& m, UV_map uv, double S, const Mesh& q, const std::string& what);
static void check_traced_patch_charts(const Mesh& q, const std::string& what);

// Returns the sizes of the mesh's patches (check_quad_patches()).
static Patch_sizes check_quad_mesh(const Mesh& m, UV_map uv, double S, const Quad_result& r, const std::string& what)
{
  const SS::Quad_mesh_report& rep = r.report;
  if(rep.status != SS::SUCCESS) std::cerr << what << ": " << SS::status_name(rep.status) << " " << rep.message << std::endl;
  assert(rep.status == SS::SUCCESS);
  const Mesh& q = r.q;
  assert(CGAL::is_valid_polygon_mesh(q) && CGAL::is_quad_mesh(q) && q.number_of_faces() > 0);
  std::vector<halfedge_descriptor> pinched;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(q, std::back_inserter(pinched));
  assert(pinched.empty());
  const bool covers = rep.incomplete_cells == 0;
  assert(rep.covers_map() == covers);
  const Q area = uv_area(m, uv, S);
  assert(rep.uv_area == area);
  // cones of valence 1 split (valence_one_cones.h): each is no quad vertex, its 2 x 2 cells one quad, three corners of
  // valence 3 for it; quad_valences() refuses such a map (no VERTEX gets a valence of 1); branch points filled
  // (branched_cells.h): no quad vertex, its cell of area m 2m - 1 quads, the rungs' ends of valence 5. Where the map
  // was repaired so, the valences are checked by their count only; a cone of valence 1 whose cell was filled with a
  // branched cell (absorbed) is no quad vertex, its cell no quad
  const std::size_t split = rep.split_cones.size() + rep.absorbed_cones.size(), filled = rep.filled_branch_points.size();
  const SS::Quad_valences qv = SS::quad_valences(m, uv);
  long extra = 0;                                               // quads the fills add beyond the area: m - 1 each
  for(std::size_t w : rep.filled_branch_points) extra += qv.status == SS::SUCCESS ? qv.valence[w] / 4 - 1 : 1;
  if(covers) {
    assert(Q(long(q.number_of_faces() + 3 * rep.split_cones.size() + rep.absorbed_cones.size()) - extra) == area);   // the exact UV
    // area (3 fewer per split, m - 1 more per fill, 1 fewer per absorbed cone cell)
    assert(euler(q) == euler(m));
    assert(!CGAL::is_closed(m) || CGAL::is_closed(q));
  } else {
    assert(Q(int(q.number_of_faces())) < area && !CGAL::is_closed(q));
  }
  // origins, valences, cones
  assert(qv.status == SS::SUCCESS || (split > 0 && qv.message.find("(a cone of valence 1)") != std::string::npos));
  std::size_t cones = qv.status == SS::SUCCESS ? 0 : rep.cones, irregular = 0, met_cones = 0;
  if(qv.status == SS::SUCCESS)
    for(vertex_descriptor v : m.vertices()) cones += !m.is_border(v) && qv.valence[std::size_t(v)] != 4 ? 1 : 0;
  CGAL::Bbox_3 box;
  for(vertex_descriptor v : m.vertices()) box += m.point(v).bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  std::map<vertex_descriptor, int> mesh_vertices;
  for(vertex_descriptor v : q.vertices()) {
    const Origin& o = get(r.origin, v);
    check_origin(m, uv, S, o, q.point(v), diagonal);
    const bool border = q.is_border(v);
    const int d = int(q.degree(v));
    irregular += !border && d != 4 ? 1 : 0;
    if(o.location == Origin::VERTEX) assert(++mesh_vertices[m.target(o.halfedge)] == 1);   // one quad vertex per mesh vertex
    if(o.location == Origin::VERTEX)
      for(const std::vector<std::size_t>* l : {&rep.split_cones, &rep.absorbed_cones})
        for(std::size_t c : *l) assert(std::size_t(m.target(o.halfedge)) != c);   // a split or absorbed cone is none
    if(o.location == Origin::VERTEX)
      for(std::size_t w : rep.filled_branch_points) assert(std::size_t(m.target(o.halfedge)) != w);   // nor a branch point
    if((border && !covers) || split + filled > 0) continue;
    const int expected = o.location == Origin::VERTEX ? qv.valence[std::size_t(m.target(o.halfedge))] : (border ? 3 : 4);
    if(d != expected) std::cerr << what << ": quad vertex " << v << " has valence " << d << ", expected " << expected << std::endl;
    assert(d == expected);
    met_cones += !border && o.location == Origin::VERTEX && expected != 4 ? 1 : 0;
  }
  assert(rep.irregular_vertices == irregular && rep.cones == cones);
  if(covers && split + filled == 0) assert(irregular == cones && met_cones == cones);   // the irregular vertices are exactly the cones
  // covered faces
  std::vector<char> covered(m.number_of_faces(), 0);
  for(face_descriptor f : q.faces()) {
    const std::vector<face_descriptor>& c = get(r.covered, f);
    assert(!c.empty() && std::is_sorted(c.begin(), c.end()));
    for(face_descriptor g : c) covered[std::size_t(g)] = 1;
  }
  if(covers) assert(std::find(covered.begin(), covered.end(), 0) == covered.end());
  // the report agrees with the mesh
  std::size_t border_edges = 0;
  for(Mesh::Edge_index e : q.edges()) border_edges += q.is_border(e) ? 1 : 0;
  assert(rep.quads == q.number_of_faces() && rep.quad_vertices == q.number_of_vertices() &&
         rep.quad_edges == q.number_of_edges() && rep.border_edges == border_edges && rep.euler_characteristic == euler(q));
  assert(rep.non_manifold_vertices == 0 && (border_edges > 0 || rep.boundary_loops == 0));
  std::string histogram;
  for(std::size_t d = 0; d < rep.valence_histogram.size(); ++d)
    if(rep.valence_histogram[d] > 0) histogram += " " + std::to_string(d) + ":" + std::to_string(rep.valence_histogram[d]);
  std::printf("quad: %-46s %6zu quads %6zu vertices, chi %d, %zu boundary loops, %zu irregular = cones %zu, valences%s%s;"
              " %.1f ms (check %.1f, cells %.1f, mesh %.1f)\n", what.c_str(), rep.quads, rep.quad_vertices,
              rep.euler_characteristic, rep.boundary_loops, irregular, cones, histogram.c_str(),
              covers ? "" : (", " + std::to_string(rep.incomplete_cells) + " cells dropped").c_str(), rep.total_ms,
              rep.check_ms, rep.cells_ms, rep.mesh_ms);
  const Patch_sizes sizes = check_quad_patches(q, what);
  if(covers && split + filled == 0) check_traced_layout(m, uv, S, q, what);   // the map has the cone or branch point
  if(covers && CGAL::is_closed(q) && cones > 0) check_traced_patch_charts(q, what);
  return sizes;
}

// The motorcycle graph of the map traced exactly on its triangles (build_motorcycle_graph(): separatrices from the cones
// in exact time, the tie rule of quad_mesh_patches()) against the quad mesh's (quad_mesh_patches(), quad_layout()),
// two implementations that share no code: every traced patch a rectangle, of the sizes of the quad mesh's patches in
// grid cells (width and height times the grid scale S, exactly), and the same layout: its nodes and arcs are the quad
// layout's vertices and arcs (SS_test::traced_layout_mismatch()). A map with a zero-area triangle gets no traced layout
// (refused), and one without cones and border corners (a torus) seeded traces from a vertex of its own (not compared).
static void check_traced_layout(const Mesh& m, UV_map uv, double S, const Mesh& q, const std::string& what)
{
  const SS::Isoline_tracer<Mesh, UV_map> tracer(m, uv);
  assert(tracer.status() == SS::SUCCESS);
  const SS::Motorcycle_graph<Mesh> g = SS::build_motorcycle_graph(tracer);
  if(g.seeded) {
    std::printf("quad: %-46s seeded traces: not compared\n", (what + ", traced").c_str());
    return;
  }
  if(g.layout.status != SS::SUCCESS) {
    assert(g.layout.message.find("flipped or degenerate") != std::string::npos);
    std::printf("quad: %-46s traced layout refused (%s)\n", (what + ", traced").c_str(), g.layout.message.c_str());
    return;
  }
  const std::string mismatch = SS_test::traced_layout_mismatch(g, q, S);
  if(!mismatch.empty()) std::cerr << what << ": " << mismatch << std::endl;
  assert(mismatch.empty());
  std::printf("quad: %-46s %6zu patches, the quad mesh's (sizes, %zu nodes, %zu arcs); traced in %.0f ms\n",
              (what + ", traced").c_str(), g.layout.patches.size(), g.layout.nodes, g.layout.arcs, g.trace_ms);
}

// The quad mesh as a map of its own (SS_test::patch_chart_map(): its quads cut in four at their centers, its patches
// as charts), where every trace runs along edges and every meeting of traces is at a vertex or on an edge
// (arrive_at_vertex()'s meetings, three traces at once where two meet head-on and one crosses): its traced motorcycle
// graph is the quad mesh's.
static void check_traced_patch_charts(const Mesh& q, const std::string& what)
{
  std::vector<SS::Quad_patch_location<Mesh> > locations(q.number_of_faces());
  const auto pm = boost::make_iterator_property_map(locations.begin(), get(boost::face_index, q));
  assert(SS::quad_mesh_patches(q, pm).all_rectangles());
  Mesh t;
  UV_map tuv = uv_of(t);
  const bool built = SS_test::patch_chart_map(q, pm, t, tuv);
  assert(built);
  const SS::Isoline_tracer<Mesh, UV_map> tracer(t, tuv);
  assert(tracer.status() == SS::SUCCESS);
  const std::string mismatch = SS_test::traced_layout_mismatch(SS::build_motorcycle_graph(tracer), q, 1);
  if(!mismatch.empty()) std::cerr << what << ": patch charts: " << mismatch << std::endl;
  assert(mismatch.empty());
  std::printf("quad: %-46s the quad mesh's patches, traced on its %zu triangles in its patch charts\n",
              (what + ", patch charts").c_str(), std::size_t(t.number_of_faces()));
}

// quad_mesh_patches() on an extracted mesh, checked here from its output alone: every quad in one patch, the
// patches' sizes and counts; the nodes counted here (interior vertices of valence other than 4, border vertices
// with other than 2 quads); every patch a rectangle (Eppstein et al.: on a mesh with nodes; the tori here get
// seeded trails that close up into one), each cell of its w x h grid once; across a side of a quad, the quad of the
// same patch is the next cell in that direction with its bottom side where the grid walk puts it, unless the side
// lies on the rectangle's boundary (a patch that meets itself across a trail). Returns the patch sizes.
static void check_quad_layout(const Mesh& q, const SS::Quad_patches& patches, const std::string& what);
static void check_patches_independent_of_numbering(const Mesh& q, const std::vector<std::size_t>& patch_of, const std::string& what);

static Patch_sizes check_quad_patches(const Mesh& q, const std::string& what)
{
  std::vector<SS::Quad_patch_location<Mesh> > locations(q.number_of_faces());
  const auto pm = boost::make_iterator_property_map(locations.begin(), get(boost::face_index, q));
  const SS::Quad_patches r = SS::quad_mesh_patches(q, pm);
  assert(r.status == SS::SUCCESS && r.all_rectangles());
  std::size_t nodes = 0;
  for(vertex_descriptor v : q.vertices()) {
    std::size_t quads = 0;
    for(face_descriptor f : CGAL::faces_around_target(q.halfedge(v), q)) quads += f != Mesh::null_face() ? 1 : 0;
    nodes += q.is_border(v) ? (quads != 2 ? 1 : 0) : (q.degree(v) != 4 ? 1 : 0);
  }
  assert(r.nodes == nodes);
  std::vector<std::size_t> count(r.patches.size(), 0);
  std::set<std::array<std::size_t, 3> > cells;
  std::size_t wraps = 0;
  for(face_descriptor f : q.faces()) {
    const SS::Quad_patch_location<Mesh>& l = get(pm, f);
    assert(l.patch < r.patches.size() && q.face(l.bottom) == f);
    const SS::Quad_patch& P = r.patches[l.patch];
    ++count[l.patch];
    assert(0 <= l.i && l.i < P.width && 0 <= l.j && l.j < P.height);
    const std::array<std::size_t, 3> cell = {{l.patch, std::size_t(l.i), std::size_t(l.j)}};
    const bool first_time = cells.insert(cell).second;           // each cell of the patch once
    assert(first_time);
    const int di[4] = {0, 1, 0, -1}, dj[4] = {-1, 0, 1, 0};
    const bool on_boundary[4] = {l.j == 0, l.i == P.width - 1, l.j == P.height - 1, l.i == 0};
    halfedge_descriptor h = l.bottom;
    for(int s = 0; s < 4; ++s, h = q.next(h)) {
      const halfedge_descriptor o = q.opposite(h);
      if(q.is_border(o) || get(pm, q.face(o)).patch != l.patch) { assert(on_boundary[s]); continue; }
      const SS::Quad_patch_location<Mesh>& n = get(pm, q.face(o));
      halfedge_descriptor b = o;                                  // its side (s + 2) mod 4 is o
      for(int t = (s + 2) % 4; t != 0; t = (t + 1) % 4) b = q.next(b);
      if(n.i == l.i + di[s] && n.j == l.j + dj[s]) assert(n.bottom == b);
      else { assert(on_boundary[s]); ++wraps; }
    }
  }
  std::size_t quads = 0;
  for(std::size_t p = 0; p < r.patches.size(); ++p) {
    assert(count[p] == r.patches[p].quads && r.patches[p].quads == std::size_t(r.patches[p].width) * std::size_t(r.patches[p].height));
    quads += r.patches[p].quads;
  }
  assert(quads == q.number_of_faces());
  std::printf("quad: %-46s %6zu patches, all rectangles, %zu nodes, %zu motorcycles, %zu sides across a trail in one patch\n",
              (what + ", patches").c_str(), r.patches.size(), r.nodes, r.motorcycles, wraps);
  check_quad_layout(q, r, what);
  if(r.nodes > 0) {
    std::vector<std::size_t> patch_of;
    for(face_descriptor f : q.faces()) patch_of.push_back(get(pm, f).patch);
    check_patches_independent_of_numbering(q, patch_of, what);
  }
  Patch_sizes sizes;
  for(const SS::Quad_patch& p : r.patches) sizes.push_back(std::make_pair((std::min)(p.width, p.height), (std::max)(p.width, p.height)));
  std::sort(sizes.begin(), sizes.end());
  return sizes;
}

// The patches of a quad mesh with nodes do not depend on its numbering (the tie rule of quad_patches.h reads the
// orientation only): the same mesh with its vertices and faces shuffled and each face's vertex list rotated (three
// fixed seeds) has the same partition of its quads (as sets of faces of q); patch_of: per face of q its patch.
static void check_patches_independent_of_numbering(const Mesh& q, const std::vector<std::size_t>& patch_of, const std::string& what)
{
  auto partition = [](const std::vector<std::size_t>& patch, const std::vector<std::size_t>& face_of) {
    std::map<std::size_t, std::vector<std::size_t> > parts;           // patch -> faces of q
    for(std::size_t f = 0; f < patch.size(); ++f) parts[patch[f]].push_back(face_of[f]);
    std::set<std::vector<std::size_t> > out;
    for(auto& p : parts) { std::sort(p.second.begin(), p.second.end()); out.insert(p.second); }
    return out;
  };
  std::vector<std::size_t> identity(q.number_of_faces());
  for(std::size_t f = 0; f < identity.size(); ++f) identity[f] = f;
  const std::set<std::vector<std::size_t> > expected = partition(patch_of, identity);
  for(unsigned seed : {1u, 2u, 3u}) {
    Mesh p;
    const std::vector<halfedge_descriptor> origin = renumbered_copy(q, seed, p);
    std::vector<std::size_t> face_of;                                   // per face of p: its face of q
    for(face_descriptor f : p.faces()) face_of.push_back(std::size_t(q.face(origin[std::size_t(p.halfedge(f))])));
    std::vector<SS::Quad_patch_location<Mesh> > locations(p.number_of_faces());
    const auto pm = boost::make_iterator_property_map(locations.begin(), get(boost::face_index, p));
    assert(SS::quad_mesh_patches(p, pm).all_rectangles());
    std::vector<std::size_t> patch;
    for(face_descriptor f : p.faces()) patch.push_back(get(pm, f).patch);
    if(partition(patch, face_of) != expected) std::cerr << what << ": another partition with seed " << seed << std::endl;
    assert(partition(patch, face_of) == expected);
  }
}

// quad_layout() on an extracted mesh, checked from its output and the patches: a valid face graph, a polygon mesh
// exactly when the report says so; one face per patch (face k patch k), the Euler characteristic of the quad mesh;
// every layout halfedge's chain of quad edges runs, edge after edge, from the quad vertex of its source to that of its
// target (one quad vertex per layout vertex, each once), in its patch along the patch's side (the quad across is in
// another patch, or is the same patch across the rectangle's boundary) or along the border; the chain of the opposite
// halfedge is the same edges reversed; the arcs cover each trail and border edge once; every face has 4 corners,
// its sides between them as long as its patch's width, height, width, height; the T-junctions counted here.
static void check_quad_layout(const Mesh& q, const SS::Quad_patches& patches, const std::string& what)
{
  typedef SS::Quad_layout_arc<Mesh> Arc;
  Mesh L;
  auto arcs = L.add_property_map<halfedge_descriptor, Arc>("h:arc").first;
  const SS::Quad_layout r = SS::quad_layout(q, L, arcs);
  if(r.status != SS::SUCCESS) std::cerr << what << ": " << r.message << std::endl;
  assert(r.status == SS::SUCCESS && r.patches.patches.size() == patches.patches.size());
  assert(CGAL::is_valid_face_graph(L));
  assert(!r.polygon_mesh || CGAL::is_valid_polygon_mesh(L));
  assert(r.self_adjacent_arcs == 0 || !CGAL::is_valid_polygon_mesh(L));
  assert(L.number_of_faces() == patches.patches.size() && r.vertices == L.number_of_vertices() && r.arcs == L.number_of_edges());
  assert(euler(L) == euler(q) && r.euler_characteristic == euler(q));
  std::vector<SS::Quad_patch_location<Mesh> > locations(q.number_of_faces());
  const auto pm = boost::make_iterator_property_map(locations.begin(), get(boost::face_index, q));
  SS::quad_mesh_patches(q, pm);
  // per quad halfedge: on the border, or on the boundary of its patch's rectangle
  auto on_side = [&](halfedge_descriptor e) {
    if(q.is_border(e)) return true;
    const SS::Quad_patch_location<Mesh>& l = get(pm, q.face(e));
    const SS::Quad_patch& P = patches.patches[l.patch];
    const bool on_boundary[4] = {l.j == 0, l.i == P.width - 1, l.j == P.height - 1, l.i == 0};
    int side = 0;
    for(halfedge_descriptor g = l.bottom; g != e; g = q.next(g)) ++side;
    return on_boundary[side];
  };
  std::map<vertex_descriptor, vertex_descriptor> quad_vertex;    // layout vertex -> quad vertex
  std::set<vertex_descriptor> used;
  std::set<halfedge_descriptor> covered;
  std::size_t t_junctions = 0, border = 0;
  for(halfedge_descriptor h : L.halfedges()) {
    const Arc& a = get(arcs, h);
    const Arc& b = get(arcs, L.opposite(h));
    assert(a.length > 0 && a.length == b.length && a.patch == (L.is_border(h) ? -1 : long(L.face(h))));
    border += a.patch < 0 ? 1 : 0;
    t_junctions += a.patch >= 0 && !a.corner ? 1 : 0;
    halfedge_descriptor e = a.first;
    for(int k = 0; k < a.length; ++k) {
      assert(covered.insert(e).second && on_side(e));              // each quad halfedge in one chain
      assert(a.patch < 0 ? q.is_border(e) : !q.is_border(e) && long(get(pm, q.face(e)).patch) == a.patch);
      if(k + 1 < a.length) e = a.patch < 0 ? q.next(e) : q.next(q.opposite(q.next(e)));
    }
    assert(b.first == q.opposite(e));                              // the opposite chain: the same edges reversed
    auto in = quad_vertex.insert(std::make_pair(L.target(h), q.target(e)));
    assert(in.first->second == q.target(e) && L.point(L.target(h)) == q.point(q.target(e)));
    if(in.second) assert(used.insert(q.target(e)).second);       // one layout vertex per quad vertex
  }
  for(const auto& lq : quad_vertex) assert(SS::layout_quad_vertex(q, L, arcs, lq.first) == lq.second);
  std::size_t sides = 0;
  for(halfedge_descriptor h : q.halfedges()) sides += on_side(h) ? 1 : 0;
  assert(covered.size() == sides && r.border_arcs == border && r.t_junctions == t_junctions);
  std::size_t non_simple = 0;                                      // faces meeting a vertex twice: their repeats
  for(face_descriptor f : L.faces()) {
    const SS::Quad_patch& P = patches.patches[std::size_t(f)];
    std::vector<int> length;
    int run = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(L.halfedge(f), L)) {
      run += get(arcs, h).length;
      if(get(arcs, h).corner) { length.push_back(run); run = 0; }
    }
    assert(length.size() == 4 && run == 0);                        // the face's first halfedge starts at a corner
    std::set<vertex_descriptor> met;
    for(vertex_descriptor v : CGAL::vertices_around_face(L.halfedge(f), L)) non_simple += met.insert(v).second ? 0 : 1;
    assert(length[0] == length[2] && length[1] == length[3] && length[0] == P.width && length[1] == P.height);
  }
  assert((non_simple > 0) == (r.non_simple_faces > 0) && r.non_simple_faces <= non_simple);
  assert(r.polygon_mesh == (r.self_adjacent_arcs == 0 && r.non_simple_faces == 0));
  std::printf("quad: %-46s %6zu faces, %zu vertices, %zu arcs (%zu on the border), %zu T-junctions, %zu self-adjacent arcs, %s\n",
              (what + ", layout").c_str(), std::size_t(L.number_of_faces()), r.vertices, r.arcs, r.border_arcs, r.t_junctions,
              r.self_adjacent_arcs, r.polygon_mesh ? "simple polygons" : "not all faces simple polygons");
}

// Refinement of the patches (sizes from check_quad_mesh()): the quad mesh
// of a closed integer-grid map with cones at grid scale 2 S has the patches of the one at S, each twice as long on both
// sides (its quads are those at S cut in four; the nodes are the same cones, the motorcycles start in the same order
// and run along the same isolines, two rounds for one, and where two meet head-on in the middle of an edge at S, the
// trails at 2 S cover that edge as well): checked where the tests extract one map at several scales (cubes, the bear,
// the horse). Not for maps whose border is off the isolines (more cells fit at 2 S) or without nodes (seeded).
static void check_patches_refine(const Patch_sizes& coarse, const Patch_sizes& fine, const std::string& what)
{
  Patch_sizes doubled;
  for(const std::pair<int, int>& p : coarse) doubled.push_back(std::make_pair(2 * p.first, 2 * p.second));
  if(doubled != fine) std::cerr << what << ": " << coarse.size() << " patches at the coarser scale, " << fine.size() << " at the finer" << std::endl;
  assert(doubled == fine);
  std::printf("quad: %-46s %zu patches, each twice as long on both sides at twice the grid scale\n", what.c_str(), fine.size());
}

// the same quad mesh, bit for bit: positions, faces, origins
static bool same_quad_mesh(const Quad_result& a, const Quad_result& b)
{
  if(a.q.number_of_vertices() != b.q.number_of_vertices() || a.q.number_of_faces() != b.q.number_of_faces()) return false;
  for(vertex_descriptor v : a.q.vertices()) {
    const Origin &oa = get(a.origin, v), &ob = get(b.origin, v);
    if(a.q.point(v) != b.q.point(v) || oa.halfedge != ob.halfedge || oa.u != ob.u || oa.v != ob.v) return false;
  }
  for(face_descriptor f : a.q.faces()) {
    std::vector<vertex_descriptor> va, vb;
    for(vertex_descriptor v : CGAL::vertices_around_face(a.q.halfedge(f), a.q)) va.push_back(v);
    for(vertex_descriptor v : CGAL::vertices_around_face(b.q.halfedge(f), b.q)) vb.push_back(v);
    if(va != vb) return false;
  }
  return true;
}

// a refusal: the status, a message containing `words`, and the output mesh unchanged (one vertex added before)
static SS::Quad_mesh_report check_refused(const Mesh& m, UV_map uv, double S, SS::Status expected, const char* words,
                                          const std::string& what)
{
  Quad_result r;
  r.q.add_vertex(Point_3(1, 2, 3));
  extract(m, uv, S, r);
  if(r.report.status != expected || r.report.message.find(words) == std::string::npos)
    std::cerr << what << ": expected " << SS::status_name(expected) << " with '" << words << "', got "
              << SS::status_name(r.report.status) << ": " << r.report.message << std::endl;
  assert(r.report.status == expected && r.report.message.find(words) != std::string::npos);
  assert(r.q.number_of_vertices() == 1 && r.q.number_of_faces() == 0 && r.q.point(vertex_descriptor(0)) == Point_3(1, 2, 3));
  std::cout << "quad: " << what << ": " << SS::status_name(r.report.status) << ": " << r.report.message << "\n";
  return r.report;
}

// ---------------------------------------------------------------------------------------------
// The surface of the cube [0, n]^3 as an exact integer-grid map: each side a grid of unit squares (two
// triangles each) in its own chart, the coordinates of the side's plane in the order that makes it
// counter-clockwise seen from outside. The transitions are quarter turns plus integer translations; the 8
// corners are cones of 270 degrees (valence 3).
static void make_cube_map(Mesh& m, UV_map& uv, int n)
{
  std::map<std::array<int, 3>, vertex_descriptor> vertex;
  auto V = [&](const std::array<int, 3>& p) {
    auto it = vertex.find(p);
    if(it == vertex.end()) it = vertex.emplace(p, m.add_vertex(Point_3(p[0], p[1], p[2]))).first;
    return it->second;
  };
  uv = uv_of(m);
  // per side: the normal axis, its value, and the two chart axes (a, b) with e_a x e_b = outward normal
  const int sides[6][4] = {{2, n, 0, 1}, {2, 0, 1, 0}, {0, n, 1, 2}, {0, 0, 2, 1}, {1, n, 2, 0}, {1, 0, 0, 2}};
  for(const auto& s : sides)
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) {
        auto point = [&](int a, int b) { std::array<int, 3> p; p[std::size_t(s[0])] = s[1]; p[std::size_t(s[2])] = a; p[std::size_t(s[3])] = b; return p; };
        const int A[4] = {i, i + 1, i + 1, i}, B[4] = {j, j, j + 1, j + 1};
        for(const std::array<int, 3>& t : {std::array<int, 3>{{0, 1, 2}}, std::array<int, 3>{{0, 2, 3}}}) {
          const face_descriptor f = m.add_face(V(point(A[t[0]], B[t[0]])), V(point(A[t[1]], B[t[1]])), V(point(A[t[2]], B[t[2]])));
          assert(f != Mesh::null_face());
          for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m))
            for(int c : t)
              if(m.target(h) == V(point(A[c], B[c]))) put(uv, h, Point_2(A[c], B[c]));
        }
      }
}

static void test_cube()
{
  for(int n = 1; n <= 3; ++n) {
    Mesh m; UV_map uv;
    make_cube_map(m, uv, n);
    assert(CGAL::is_closed(m) && SS::is_exact_integer_grid_map(m, uv));
    Patch_sizes coarser;
    for(double S : {1., 2.}) {
      Quad_result r;
      extract(m, uv, S, r);
      const Patch_sizes sizes = check_quad_mesh(m, uv, S, r, "cube " + std::to_string(n) + ", grid scale " + std::to_string(int(S)));
      if(S == 2) check_patches_refine(coarser, sizes, "cube " + std::to_string(n) + ", patches at scales 1, 2");
      coarser = sizes;
      assert(r.report.quads == std::size_t(6 * n * n * S * S) && r.report.euler_characteristic == 2);
      assert(r.report.cones == 8 && r.report.valence_histogram[3] == 8);
      // scale covariance: UVs times 2^-3 with grid_scale 8 S: the same mesh, bit for bit
      Mesh small = m;
      UV_map uvs = uv_of(small);
      scale_uvs(small, uvs, -3);
      Quad_result rs;
      extract(small, uvs, 8 * S, rs);
      assert(rs.report.status == SS::SUCCESS && same_quad_mesh(r, rs));
    }
  }
}

// quantize(true) on cube maps whose sides are 1.3, 1.45 and 1.7 grid cells long (n x n squares per side, the 8 cones of
// valence 3 off the integers): an exact integer-grid map of a box with integer sides. Where the rounding puts two cones
// on one point (n = 1 at 1.7: two corners joined by one edge; no cone there finds its four candidates taken, so the pair
// comes from what the peeling leaves to the end: the cut graph's root, which takes the point the others give it, and
// the translations rounded on its cycles), the zero-area faces are proven forced and the extraction refuses; otherwise the quad mesh
// has every guarantee, the cones as its only irregular vertices, and its traced layout is the quad mesh's. At n = 1 the
// top side's UV square is a triangle with a cone in the middle of its long side, where the separatrix of that cone
// along an edge meets, at the same time, a trace that reaches the edge there and stops on it: the face subdivision
// inserts the separatrix in two parts (before, 2 of its segments were not placed and the layout had 9 patches, not 12).
// With the cube's 12 n edges as features (align edges), every scale gives a box whose edges lie on integer isolines:
// before, the quantization chose each cone's point without regard to them and each aligned chain took the isoline nearest
// it, so the two cones of one edge could land on two isolines: INFEASIBLE at 3 of the 9 (n, factor) (isoline_classes.h)
static void test_quantized_cube()
{
  for(bool features : {false, true})
    for(int n = 1; n <= 3; ++n)
      for(double factor : {1.3, 1.45, 1.7}) {
        Mesh m; UV_map uv;
        make_cube_map(m, uv, n);
        multiply_uvs(m, uv, factor);
        // the edges between two sides of the cube (their faces in two planes)
        auto feature = m.add_property_map<Mesh::Edge_index, bool>("e:feature", false).first;
        auto plane = [&](halfedge_descriptor h) {
          const Point_3 &a = m.point(m.source(h)), &b = m.point(m.target(h)), &c = m.point(m.target(m.next(h)));
          for(int i = 0; i < 3; ++i) if(a[i] == b[i] && b[i] == c[i]) return std::make_pair(i, a[i]);
          return std::make_pair(-1, 0.);
        };
        std::size_t n_features = 0;
        for(Mesh::Edge_index e : m.edges())
          if(features && plane(m.halfedge(e)) != plane(m.opposite(m.halfedge(e)))) { put(feature, e, true); ++n_features; }
        const std::string what = std::string(features ? "quantized cube with features " : "quantized cube ") +
                                 std::to_string(n) + " x " + std::to_string(factor).substr(0, 4);
        const SS::Snap_report s = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).quantize(true)
                                                                                .edge_is_constrained_map(feature));
        if(s.status != SS::SUCCESS) std::cerr << what << ": " << s.message << std::endl;
        assert(s.status == SS::SUCCESS && s.quantized && s.align_edges == n_features && s.flips_after_repair == 0);
        assert(SS::is_exact_integer_grid_map(m, uv, SS::parameters::edge_is_constrained_map(feature)));
        Quad_result r;
        if(s.degenerate_after_repair > 0) {
          assert(n == 1 && s.degenerate_forced == s.degenerate_after_repair);
          extract(m, uv, 1, r);
          assert(r.report.status == SS::FOLD_OVERS && r.q.number_of_faces() == 0);
          std::printf("quad: %-46s %zu zero-area triangles, forced (two cones on one point): refused\n", what.c_str(),
                      s.degenerate_after_repair);
          continue;
        }
        extract(m, uv, 1, r);
        check_quad_mesh(m, uv, 1, r, what);
        assert(r.report.cones == 8 && r.report.valence_histogram[3] == 8);
      }
}

static void test_torus()
{
  for(int n : {3, 5}) {
    Mesh m; UV_map uv;
    make_flat_torus(m, uv, n, n);
    Quad_result r;
    extract(m, uv, 1, r);
    check_quad_mesh(m, uv, 1, r, "flat torus " + std::to_string(n));
    assert(r.report.quads == std::size_t(n * n) && r.report.euler_characteristic == 0 && r.report.irregular_vertices == 0);
  }
  Mesh m; UV_map uv;
  make_flat_torus(m, uv, 4, 4);
  check_refused(m, uv, 0.25, SS::INVALID_INPUT, "a corner twice", "torus of 1 x 1 cells");
  const SS::Quad_mesh_report r = check_refused(m, uv, 0.5, SS::INVALID_INPUT, "do not form a polygon mesh", "torus of 2 x 2 cells");
  assert(r.non_manifold_edges > 0);
  Mesh odd; UV_map uvo;
  make_flat_torus(odd, uvo, 3, 3.5);
  check_refused(odd, uvo, 1, SS::INVALID_INPUT, "translation is not an integer vector", "torus of period 3.5");
  // max_grid_cells: the 50 triangles of the 5 x 5 torus each have a box of 1 cell at grid scale 1, of 4 at grid scale 2
  // (100 quads): one cell fewer than the boxes hold is refused, nothing written; as many give the mesh
  Mesh t5; UV_map uv5;
  make_flat_torus(t5, uv5, 5, 5);
  for(const auto& c : {std::make_pair(1., std::size_t(50)), std::make_pair(2., std::size_t(200))}) {
    Mesh q;
    q.add_vertex(Point_3(1, 2, 3));
    SS::Quad_mesh_report r = SS::extract_quad_mesh(t5, uv5, q, SS::parameters::grid_scale(c.first).max_grid_cells(c.second - 1));
    assert(r.status == SS::RANGE_EXCEEDED && r.message.find("more than " + std::to_string(c.second - 1) + " unit cells") != std::string::npos &&
           r.message.find("max_grid_cells") != std::string::npos);
    assert(q.number_of_vertices() == 1 && q.number_of_faces() == 0);
    r = SS::extract_quad_mesh(t5, uv5, q, SS::parameters::grid_scale(c.first).max_grid_cells(c.second));
    assert(r.status == SS::SUCCESS && r.quads == std::size_t(25 * c.first * c.first) && q.number_of_faces() == r.quads);
  }
  static_assert(SS::default_max_grid_cells == std::size_t(1) << 24, "the documented default");
}

// The quad mesh is added to the caller's mesh: appended whole to a Surface_mesh of the extraction's own type
// (a fresh one, or one that already holds elements, a removed face and a property map of the caller: kept, the
// new vertices numbered after the old ones) or face by face to another mesh type; the same mesh every time.
static void test_output_meshes()
{
  typedef CGAL::Simple_cartesian<double>::Point_3 Other_point;
  typedef CGAL::Surface_mesh<Other_point> Other_mesh;
  Mesh m; UV_map uv;
  make_flat_torus(m, uv, 3, 3);
  Mesh fresh;
  const SS::Quad_mesh_report rf = SS::extract_quad_mesh(m, uv, fresh);
  assert(rf.status == SS::SUCCESS && fresh.number_of_faces() == 9);

  Mesh used;                                       // a triangle, a removed one, a property of the caller
  std::vector<vertex_descriptor> tri;
  for(int i = 0; i < 4; ++i) tri.push_back(used.add_vertex(Point_3(i, i * i, 1)));
  used.add_face(tri[0], tri[1], tri[2]);
  used.remove_face(used.add_face(tri[0], tri[2], tri[3]));
  Mesh::Property_map<vertex_descriptor, int> mine = used.add_property_map<vertex_descriptor, int>("v:mine", -1).first;
  for(int i = 0; i < 4; ++i) put(mine, tri[std::size_t(i)], 10 + i);
  Origin_map origin = used.add_property_map<vertex_descriptor, Origin>("v:origin").first;
  const std::size_t nv = used.num_vertices(), nf = used.num_faces();
  const SS::Quad_mesh_report ru = SS::extract_quad_mesh(m, uv, used, CGAL::parameters::default_values(),
                                                          SS::parameters::vertex_origin_map(origin));
  assert(ru.status == SS::SUCCESS && used.number_of_faces() == 1 + 9 && used.num_vertices() == nv + fresh.num_vertices());
  for(int i = 0; i < 4; ++i) assert(get(mine, tri[std::size_t(i)]) == 10 + i && used.point(tri[std::size_t(i)]) == Point_3(i, i * i, 1));

  Other_mesh other;
  const SS::Quad_mesh_report ro = SS::extract_quad_mesh(m, uv, other);
  assert(ro.status == SS::SUCCESS && other.num_vertices() == fresh.num_vertices() && other.num_faces() == fresh.num_faces());
  for(face_descriptor f : fresh.faces()) {
    const face_descriptor g(Mesh::size_type(nf + std::size_t(f)));
    halfedge_descriptor a = fresh.halfedge(f), b = used.halfedge(g);
    Other_mesh::Halfedge_index c = other.halfedge(Other_mesh::Face_index(Mesh::size_type(f)));
    for(int k = 0; k < 4; ++k, a = fresh.next(a), b = used.next(b), c = other.next(c)) {
      const std::size_t v = std::size_t(fresh.target(a));
      assert(std::size_t(used.target(b)) == nv + v && std::size_t(other.target(c)) == v);
      const Point_3& p = fresh.point(fresh.target(a));
      const Other_point& q = other.point(other.target(c));
      assert(used.point(used.target(b)) == p && q.x() == p.x() && q.y() == p.y() && q.z() == p.z());
      assert(get(mine, used.target(b)) == -1 && get(origin, used.target(b)).face != Mesh::null_face());
    }
  }
  std::cout << "quad: output meshes: fresh, appended (after 4 vertices and a removed face), other type: the same mesh\n";
}

static void test_grid()
{
  const int n = 4;
  for(double shift : {0., 0.5}) {
    Mesh m;
    triangulated_grid(m, n, true);
    UV_map uv = uv_of(m);
    for(halfedge_descriptor h : m.halfedges())
      if(!m.is_border(h)) put(uv, h, Point_2(m.point(m.target(h)).x() + shift, m.point(m.target(h)).y() + shift / 2));
    Quad_result r;
    extract(m, uv, 1, r);
    check_quad_mesh(m, uv, 1, r, shift == 0 ? "grid, border on isolines" : "grid, border off isolines");
    assert(r.report.boundary_loops == 1 && r.report.euler_characteristic == 1);
    if(shift == 0) {
      assert(r.report.quads == 16 && r.report.covers_map());
      assert(r.report.valence_histogram[2] == 4 && r.report.valence_histogram[3] == 12 && r.report.valence_histogram[4] == 9);
    } else {
      assert(r.report.quads == 9 && r.report.incomplete_cells == 16 && !r.report.covers_map());
    }
  }
}

// The square [0, 2]^2 with a zero-area face (A, C, c) on its diagonal: A = (0, 0), C = (2, 2) and c = (t, t) between
// them in UV (lifted off the plane in 3D), the face (A, B, C) below the diagonal, (c, C, D) and (A, c, D) above it.
// Collapsed onto its long side A-C, it is covered by the cells that side runs through; the quad mesh is the 2 x 2
// grid: c on the integer point (1, 1) is the quad vertex there (t = 1); elsewhere (t = 1.5, 0.5) the point (1, 1) lies
// on the long side and on a short side, one quad vertex. Two corners at one UV point (t = 0: c onto A) are refused.
static void test_collapsed_faces()
{
  for(double t : {1., 1.5, 0.5, 0.}) {
    Mesh m;
    const vertex_descriptor A = m.add_vertex(Point_3(0, 0, 0)), B = m.add_vertex(Point_3(2, 0, 0)),
                            C = m.add_vertex(Point_3(2, 2, 0)), D = m.add_vertex(Point_3(0, 2, 0)),
                            c = m.add_vertex(Point_3(t, t, 0.5));
    m.add_face(A, B, C);
    const face_descriptor thin = m.add_face(A, C, c);
    m.add_face(c, C, D);
    m.add_face(A, c, D);
    UV_map uv = uv_of(m);
    uv_from_xy(m, uv);
    assert(SS::is_exact_integer_grid_map(m, uv));
    const std::string what = "collapsed face, middle corner at (" + std::to_string(t).substr(0, 3) + ", " +
                             std::to_string(t).substr(0, 3) + ")";
    if(t == 0) {                                 // faces (A, C, c) and (A, c, D) have two corners at (0, 0)
      const SS::Quad_mesh_report r = check_refused(m, uv, 1, SS::FOLD_OVERS, "two corners at one UV point", what);
      assert(r.fold_overs.empty() && r.zero_area_faces.size() == 2);
      assert(SS::quad_valences(m, uv).status == SS::FOLD_OVERS);
      continue;
    }
    Quad_result r;
    extract(m, uv, 1, r);
    check_quad_mesh(m, uv, 1, r, what);
    assert(r.report.quads == 4 && r.report.quad_vertices == 9 && r.report.covers_map());
    assert(r.report.zero_area_faces == std::vector<std::size_t>(1, std::size_t(thin)) && r.report.fold_overs.empty());
    assert(r.report.valence_histogram[2] == 4 && r.report.valence_histogram[3] == 4 && r.report.valence_histogram[4] == 1);
    assert(SS::quad_valences(m, uv).valence[std::size_t(c)] == 4);
    std::size_t covering = 0;                    // the cells the long side runs through: [0, 1]^2 and [1, 2]^2
    for(face_descriptor q : r.q.faces()) {
      const std::vector<face_descriptor>& f = get(r.covered, q);
      covering += std::find(f.begin(), f.end(), thin) != f.end() ? 1 : 0;
    }
    assert(covering == 2);
  }
}

// a fan of 3 triangles around an interior vertex c spanning 90 degrees in UV: a cone of valence 1 at (0, 0),
// the cut edge c-w0 with k = 1 and translation 0
static void make_quarter_turn_cone(Mesh& m, UV_map& uv)
{
  const vertex_descriptor c = m.add_vertex(Point_3(0, 0, 1));
  std::vector<vertex_descriptor> w;
  for(int i = 0; i < 3; ++i) w.push_back(m.add_vertex(Point_3(std::cos(2 * CGAL_PI * i / 3), std::sin(2 * CGAL_PI * i / 3), 0)));
  uv = uv_of(m);
  const Point_2 fan[4] = {Point_2(2, 0), Point_2(2, 1), Point_2(1, 2), Point_2(0, 2)};   // w0, w1, w2, w0 again
  for(int i = 0; i < 3; ++i) {
    const face_descriptor f = m.add_face(c, w[std::size_t(i)], w[std::size_t((i + 1) % 3)]);
    for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m))
      put(uv, h, m.target(h) == c ? Point_2(0, 0) : m.target(h) == w[std::size_t(i)] ? fan[i] : fan[i + 1]);
  }
}

// A fan of 8 triangles around an interior vertex c whose UV angle sum is 8 quarter turns in one chart (no cut edge:
// the map winds twice around c, a branch point), c at `center`, the other vertices at 2 units in the axis directions.
static void make_double_fan(Mesh& m, UV_map& uv, const Point_2& center)
{
  const vertex_descriptor c = m.add_vertex(Point_3(0, 0, 1));
  std::vector<vertex_descriptor> w;
  for(int i = 0; i < 8; ++i) w.push_back(m.add_vertex(Point_3(std::cos(CGAL_PI * i / 4), std::sin(CGAL_PI * i / 4), 0)));
  uv = uv_of(m);
  const double d[4][2] = {{2, 0}, {0, 2}, {-2, 0}, {0, -2}};
  for(int i = 0; i < 8; ++i) {
    const face_descriptor f = m.add_face(c, w[std::size_t(i)], w[std::size_t((i + 1) % 8)]);
    for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
      const int k = m.target(h) == c ? -1 : m.target(h) == w[std::size_t(i)] ? i % 4 : (i + 1) % 4;
      put(uv, h, k < 0 ? center : Point_2(center.x() + d[k][0], center.y() + d[k][1]));
    }
  }
}

// A disk that the map winds `turns` times around `center` (a branch point of that order, one chart, no cut): rings
// of 16 turns x 16 vertices at radii 0.5 .. 5 around it; in 3D a flat disk whose angle is the UV angle / turns.
static vertex_descriptor make_branched_disk(Mesh& m, UV_map& uv, const Point_2& center, int turns)
{
  const int N = 16, rings = 10;
  const vertex_descriptor w = m.add_vertex(Point_3(0, 0, 0));
  std::vector<std::vector<vertex_descriptor> > ring(rings + 1);
  std::vector<std::vector<Point_2> > at(rings + 1);
  for(int j = 1; j <= rings; ++j)
    for(int k = 0; k < turns * N; ++k) {
      const double r = 0.5 * j, theta = 2 * CGAL_PI * k / N;
      ring[std::size_t(j)].push_back(m.add_vertex(Point_3(r * std::cos(theta / turns), r * std::sin(theta / turns), 0)));
      at[std::size_t(j)].push_back(Point_2(center.x() + r * std::cos(theta), center.y() + r * std::sin(theta)));
    }
  uv = uv_of(m);
  auto triangle = [&](std::array<std::pair<int, int>, 3> c) {   // (ring, index); ring 0 is w
    std::array<vertex_descriptor, 3> v;
    for(int i = 0; i < 3; ++i) v[std::size_t(i)] = c[std::size_t(i)].first == 0 ? w
                                 : ring[std::size_t(c[std::size_t(i)].first)][std::size_t(c[std::size_t(i)].second % (turns * N))];
    const face_descriptor f = m.add_face(v[0], v[1], v[2]);
    assert(f != Mesh::null_face());
    for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m))
      for(int i = 0; i < 3; ++i)
        if(m.target(h) == v[std::size_t(i)])
          put(uv, h, c[std::size_t(i)].first == 0 ? center
                     : at[std::size_t(c[std::size_t(i)].first)][std::size_t(c[std::size_t(i)].second % (turns * N))]);
  };
  for(int k = 0; k < turns * N; ++k) {
    triangle({{{0, 0}, {1, k}, {1, k + 1}}});
    for(int j = 1; j < rings; ++j) {
      triangle({{{j, k}, {j + 1, k}, {j + 1, k + 1}}});
      triangle({{{j, k}, {j + 1, k + 1}, {j, k + 1}}});
    }
  }
  return w;
}

// The square [-k, k]^2 covered twice, branched at (0.5, 0.5) (a vertex wound twice): triangles of half a unit in
// one chart (no cut), the two sheets crossing along the ray from (0.5, 0.5) to (k, 0.5); its border, two turns around
// the square, lies on integer isolines, so every cell is whole. With `hole`, the triangle (0, 0), (0.5, 0), (0, 0.5)
// of one sheet is left out: the branched cell [0, 1]^2 is then cut by that hole's border.
static vertex_descriptor make_branched_square(Mesh& m, UV_map& uv, int k, bool hole)
{
  std::map<std::array<int, 3>, vertex_descriptor> vertex;           // (2u, 2v, sheet); the branch point has sheet 0
  auto at = [&](int i, int j, int sheet) {
    if(i == 1 && j == 1) sheet = 0;
    const std::array<int, 3> key = {{i, j, sheet}};
    auto it = vertex.find(key);
    if(it != vertex.end()) return it->second;
    return vertex[key] = m.add_vertex(Point_3(i / 2., j / 2., i == 1 && j == 1 ? 0.5 : sheet));
  };
  uv = uv_of(m);
  const vertex_descriptor w = at(1, 1, 0);
  for(int sheet = 0; sheet < 2; ++sheet)
    for(int i = -2 * k; i < 2 * k; ++i)
      for(int j = -2 * k; j < 2 * k; ++j) {
        const bool above = j >= 1;                                   // the square lies above the line v = 0.5
        auto corner = [&](int a, int b) {                          // on the ray (v = 0.5, u > 0.5): the sheets cross
          return at(a, b, b == 1 && a > 1 && !above ? 1 - sheet : sheet);
        };
        const std::array<std::pair<int, int>, 3> t[2] = {{{{i, j}, {i + 1, j}, {i, j + 1}}},
                                                         {{{i + 1, j}, {i + 1, j + 1}, {i, j + 1}}}};
        for(int s = 0; s < 2; ++s) {
          if(hole && sheet == 0 && s == 0 && i == 0 && j == 0) continue;
          const face_descriptor f = m.add_face(corner(t[s][0].first, t[s][0].second), corner(t[s][1].first, t[s][1].second),
                                               corner(t[s][2].first, t[s][2].second));
          assert(f != Mesh::null_face());
          for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m))
            for(int c = 0; c < 3; ++c)
              if(m.target(h) == corner(t[s][std::size_t(c)].first, t[s][std::size_t(c)].second))
                put(uv, h, Point_2(t[s][std::size_t(c)].first / 2., t[s][std::size_t(c)].second / 2.));
        }
      }
  return w;
}

static void test_branch_points()
{
  // on an integer point: 8 quads around it, a vertex of valence 8 (the cells along the diagonal border are cut)
  Mesh m; UV_map uv;
  make_double_fan(m, uv, Point_2(0, 0));
  assert(SS::is_exact_integer_grid_map(m, uv) && SS::quad_valences(m, uv).valence[0] == 8);
  Quad_result r;
  extract(m, uv, 1, r);
  check_quad_mesh(m, uv, 1, r, "branch point of 8 quarter turns on (0, 0)");
  assert(r.report.quads == 8 && r.report.valence_histogram[8] == 1 && r.report.incomplete_cells > 0);
  // off the integer points, in a cell whose neighbours the border cuts: its two sheets cannot be filled, refused
  Mesh b; UV_map uvb;
  make_double_fan(b, uvb, Point_2(0.5, 0.25));
  assert(SS::is_exact_integer_grid_map(b, uvb));
  check_refused(b, uvb, 1, SS::INVALID_INPUT, "do not close a loop around the cell", "branch point of 8 quarter turns off the grid");
  // inside a cell of a larger disk wound 2 or 3 times around it: the cell's 4m-gon filled with 2m - 1 quads, its rungs'
  // 4(m - 1) ends of valence 5; on a grid line off the integer points, or without fill_branched_cells: refused
  for(int turns : {2, 3}) {
    Mesh d; UV_map uvd;
    const vertex_descriptor w = make_branched_disk(d, uvd, Point_2(0.5, 0.25), turns);
    assert(SS::is_exact_integer_grid_map(d, uvd) && SS::quad_valences(d, uvd).valence[std::size_t(w)] == 4 * turns);
    Quad_result rd;
    extract(d, uvd, 1, rd);
    check_quad_mesh(d, uvd, 1, rd, "disk wound " + std::to_string(turns) + " times around (0.5, 0.25)");
    assert(rd.report.filled_branch_points == std::vector<std::size_t>(1, std::size_t(w)));
    std::size_t valence_5 = 0;
    for(vertex_descriptor v : rd.q.vertices()) valence_5 += !rd.q.is_border(v) && rd.q.degree(v) == 5 ? 1 : 0;
    assert(valence_5 == std::size_t(4 * (turns - 1)) && rd.report.irregular_vertices == valence_5);
    Quad_result kept;
    kept.report = SS::extract_quad_mesh(d, uvd, kept.q, SS::parameters::fill_branched_cells(false));
    assert(kept.report.status == SS::INVALID_INPUT && kept.report.message.find("branches inside a cell") != std::string::npos &&
           kept.q.number_of_faces() == 0);
    if(turns == 3) continue;
    // a covered map (the square [-2, 2]^2 twice, its border on isolines): the quads are its UV area 32 plus 1, chi 1
    Mesh sq; UV_map uvs;
    const vertex_descriptor ws = make_branched_square(sq, uvs, 2, false);
    assert(SS::is_exact_integer_grid_map(sq, uvs) && SS::quad_valences(sq, uvs).valence[std::size_t(ws)] == 8);
    Quad_result rs;
    extract(sq, uvs, 1, rs);
    check_quad_mesh(sq, uvs, 1, rs, "square covered twice, branched at (0.5, 0.5)");
    assert(rs.report.covers_map() && rs.report.quads == 33 && rs.report.uv_area == Q(32) && rs.report.euler_characteristic == 1);
    assert(rs.report.filled_branch_points == std::vector<std::size_t>(1, std::size_t(ws)) && rs.report.irregular_vertices == 4);
    // its branched cell cut by a hole's border: the branch point would be left out unseen, refused (it was a SUCCESS)
    Mesh sh; UV_map uvh;
    make_branched_square(sh, uvh, 2, true);
    check_refused(sh, uvh, 1, SS::INVALID_INPUT, "the cell at it is cut by the border", "branched cell cut by a hole");
    Mesh e; UV_map uve;
    make_branched_disk(e, uve, Point_2(0.5, 0), turns);
    check_refused(e, uve, 1, SS::INVALID_INPUT, "branches inside a cell", "branch point of 8 quarter turns on a grid line");
  }
}

// The quarter plane [0, n]^2 with its two sides glued ((t, 0) ~ (0, t), the cut edges with a quarter turn and translation
// 0): a cone of 90 degrees (valence 1) at (0, 0), a disk whose border, u = n and v = n, lies on integer isolines.
// Triangles of half a unit (two per square), a fan of 4 around the cone (the square at the cone would be two
// triangles on the same three vertices); 3D points on a paper cone of that angle (r / 4 around the axis).
static vertex_descriptor make_quarter_plane_cone(Mesh& m, UV_map& uv, int n)
{
  std::map<std::pair<int, int>, vertex_descriptor> vertex;          // by (2u, 2v), the v axis glued onto the u axis
  auto at = [&](int i, int j) {
    const std::pair<int, int> key = i == 0 && j > 0 ? std::make_pair(j, 0) : std::make_pair(i, j);
    auto it = vertex.find(key);
    if(it != vertex.end()) return it->second;
    const double r = std::hypot(key.first, key.second) / 2, theta = std::atan2(double(key.second), double(key.first));
    return vertex[key] = m.add_vertex(Point_3(r / 4 * std::cos(4 * theta), r / 4 * std::sin(4 * theta), r * std::sqrt(15.) / 4));
  };
  uv = uv_of(m);
  auto triangle = [&](std::array<std::pair<int, int>, 3> c) {
    const face_descriptor f = m.add_face(at(c[0].first, c[0].second), at(c[1].first, c[1].second), at(c[2].first, c[2].second));
    assert(f != Mesh::null_face());
    halfedge_descriptor h = m.halfedge(f);
    while(m.target(h) != at(c[0].first, c[0].second)) h = m.next(h);
    for(int k = 0; k < 3; ++k, h = m.next(h)) put(uv, h, Point_2(c[std::size_t(k)].first / 2., c[std::size_t(k)].second / 2.));
  };
  const std::pair<int, int> ring[5] = {{2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}};
  for(int k = 0; k < 4; ++k) triangle({{{0, 0}, ring[k], ring[k + 1]}});
  for(int i = 0; i < 2 * n; ++i)
    for(int j = 0; j < 2 * n; ++j) {
      if(i < 2 && j < 2) continue;
      triangle({{{i, j}, {i + 1, j}, {i + 1, j + 1}}});
      triangle({{{i, j}, {i + 1, j + 1}, {i, j + 1}}});
    }
  return at(0, 0);
}

// Two sheets of the quarter plane of make_quarter_plane_cone() (a cone of 90 degrees at (0, 0) in each), crossing along
// the ray from (1.5, 0.5) to (n, 0.5): the map winds twice around the vertex at (1.5, 0.5), a branch point of order 2
// inside the cell [1, 2] x [0, 1], and the cell of each cone, (p, a, b, a) with a = (1, 0), b = (1, 1), shares its side
// u = 1 with that branched cell. A disk (chi = 2 - 1), its border twice around the square; in 3D the cones of the
// two sheets one unit apart. `cones`: the two cone vertices.
static vertex_descriptor make_branched_quarter_planes(Mesh& m, UV_map& uv, int n, std::vector<vertex_descriptor>& cones)
{
  std::map<std::array<int, 3>, vertex_descriptor> vertex;      // (2u, 2v, sheet), the v axis glued onto the u axis
  auto at = [&](int i, int j, int sheet) {
    std::array<int, 3> key = {{i == 0 && j > 0 ? j : i, i == 0 && j > 0 ? 0 : j, sheet}};
    if(key[0] == 3 && key[1] == 1) key[2] = 0;                   // the branch point, one vertex
    auto it = vertex.find(key);
    if(it != vertex.end()) return it->second;
    const double r = std::hypot(key[0], key[1]) / 2, theta = std::atan2(double(key[1]), double(key[0]));
    return vertex[key] = m.add_vertex(Point_3(r / 4 * std::cos(4 * theta), r / 4 * std::sin(4 * theta),
                                              r * std::sqrt(15.) / 4 + key[2]));
  };
  uv = uv_of(m);
  for(int sheet = 0; sheet < 2; ++sheet) {
    auto triangle = [&](std::array<std::pair<int, int>, 3> c, bool above) {
      auto corner = [&](const std::pair<int, int>& x) {          // on the ray the sheets cross
        return at(x.first, x.second, x.second == 1 && x.first > 3 && !above ? 1 - sheet : sheet);
      };
      const face_descriptor f = m.add_face(corner(c[0]), corner(c[1]), corner(c[2]));
      assert(f != Mesh::null_face());
      halfedge_descriptor h = m.halfedge(f);
      while(m.target(h) != corner(c[0])) h = m.next(h);
      for(int k = 0; k < 3; ++k, h = m.next(h)) put(uv, h, Point_2(c[std::size_t(k)].first / 2., c[std::size_t(k)].second / 2.));
    };
    const std::pair<int, int> ring[5] = {{2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}};
    for(int k = 0; k < 4; ++k) triangle({{{0, 0}, ring[k], ring[k + 1]}}, k >= 1);
    for(int i = 0; i < 2 * n; ++i)
      for(int j = 0; j < 2 * n; ++j) {
        if(i < 2 && j < 2) continue;
        triangle({{{i, j}, {i + 1, j}, {i + 1, j + 1}}}, j >= 1);
        triangle({{{i, j}, {i + 1, j + 1}, {i, j + 1}}}, j >= 1);
      }
    cones.push_back(at(0, 0, sheet));
  }
  return at(3, 1, 0);
}

// Which cone cells a branched fill takes in (internal/quad/branched_cells.h), on cells built by hand: a branched cell of
// 8 corners with a quad on every side but one, across which lies the cell (p, a, b, a) of a cone of valence 1 with a
// quad across its other side a - b: taken in (3 quads for the area 3, p no point, a and b the rungs' ends); the same
// cone cell with quads across both of its sides a - b (its a and b corners of the branched cell, which does not touch
// it): left alone, the branched cell filled on its own
static void test_cone_cell_absorption_rules()
{
  namespace Q4 = SS::internal::quad;
  for(int adjacent = 0; adjacent < 2; ++adjacent) {
    Q4::Quad_cells c;
    std::vector<int> valence;                       // per vertex; every point is a vertex of its own
    c.faces_first.assign(1, 0);
    auto point = [&](int v) {
      SS::internal::quad::Integer_point p;
      p.kind = SS::internal::quad::AT_VERTEX;
      p.element = int(valence.size());
      valence.push_back(v);
      c.points.push_back(p);
      return int(c.points.size()) - 1;
    };
    auto quad = [&](int a, int b, int d, int e) {
      c.quads.push_back({{a, b, d, e}});
      c.faces.push_back(int(c.quads.size()));
      c.faces_first.push_back(c.faces.size());
    };
    std::vector<int> L;
    for(int i = 0; i < 8; ++i) L.push_back(point(4));
    Q4::Quad_cells::Branched br;
    br.corners = L;                                  // ascending
    br.faces.assign(1, 1000);
    br.vertex = point(8);
    c.branched.push_back(br);
    for(int i = adjacent ? 1 : 0; i < 8; ++i) quad(L[std::size_t((i + 1) % 8)], L[std::size_t(i)], point(4), point(4));
    const int a = adjacent ? L[1] : L[0], b = adjacent ? L[0] : L[4], p = point(1);
    quad(p, a, b, a);
    quad(a, b, point(4), point(4));
    if(!adjacent) quad(b, a, point(4), point(4));
    const std::size_t quads = c.quads.size(), points = c.points.size();
    Q4::Cell_repairs r;
    int failed = -1;
    std::string message;
    assert(Q4::fill_branched_cells(c, valence, r, failed, message) == SS::SUCCESS && r.filled_vertices.size() == 1);
    if(adjacent) {
      assert(r.absorbed_cones == std::vector<int>(1, p) && c.quads.size() == quads - 1 + 3 && c.points.size() == points - 1);
      std::vector<int> rung_ends;                    // the corners of the added quads: a rung's ends are in two of them
      for(std::size_t q = quads - 1; q < c.quads.size(); ++q)
        for(int x : c.quads[q]) rung_ends.push_back(x);
      assert(std::count(rung_ends.begin(), rung_ends.end(), a) == 2 && std::count(rung_ends.begin(), rung_ends.end(), b) == 2);
    } else {
      assert(r.absorbed_cones.empty() && c.quads.size() == quads + 3 && c.points.size() == points);
    }
  }
}

// A cone of 90 degrees: its 2 x 2 cells made one quad (split_valence_one_cones, the default), or refused without that
static void test_valence_one_cones()
{
  for(int n : {2, 3, 4})
    for(double S : {1., 2.}) {
      Mesh m; UV_map uv;
      const vertex_descriptor cone = make_quarter_plane_cone(m, uv, n);
      assert(SS::is_exact_integer_grid_map(m, uv, SS::parameters::grid_scale(S)) && CGAL::is_valid_polygon_mesh(m));
      const std::string what = "cone of 90 degrees, [0, " + std::to_string(n) + "]^2, grid scale " + std::to_string(int(S));
      Quad_result r;
      extract(m, uv, S, r);
      check_quad_mesh(m, uv, S, r, what);
      const std::size_t side = std::size_t(n * S);
      assert(r.report.split_cones == std::vector<std::size_t>(1, std::size_t(cone)) && r.report.cones == 1);
      assert(r.report.quads == side * side - 3 && r.report.quad_vertices == (side + 1) * (side + 1) - side - 3);
      assert(r.report.euler_characteristic == 1 && r.report.boundary_loops == 1);
      // the three corners of the merged quad next to the glued sides: valence 3 inside, 2 on the border (n S = 2)
      std::size_t valence_3_inside = 0;
      for(vertex_descriptor v : r.q.vertices()) valence_3_inside += !r.q.is_border(v) && r.q.degree(v) == 3 ? 1 : 0;
      assert(valence_3_inside == (side > 2 ? 3 : 0) && r.report.irregular_vertices == valence_3_inside);
      const std::vector<std::uint64_t> bits = uv_bits(m, uv);
      Quad_result kept;
      kept.q.add_vertex(Point_3(1, 2, 3));
      kept.report = SS::extract_quad_mesh(m, uv, kept.q, SS::parameters::grid_scale(S).split_valence_one_cones(false));
      assert(kept.report.status == SS::INVALID_INPUT && kept.report.message.find("(a cone of valence 1)") != std::string::npos);
      assert(kept.q.number_of_vertices() == 1 && kept.q.number_of_faces() == 0 && uv_bits(m, uv) == bits);
    }
  // next to a branched cell (two sheets crossing, make_branched_quarter_planes()): each cone's cell is filled with it,
  // the disk of the three bounded by the 8 corners of the branched cell: 3 quads for the area 4; at grid scale 2 the
  // branch point is an integer point (a quad vertex of valence 8) and the cones are split
  for(int n : {3, 4}) {
    Mesh m; UV_map uv;
    std::vector<vertex_descriptor> cones;
    const vertex_descriptor w = make_branched_quarter_planes(m, uv, n, cones);
    assert(SS::is_exact_integer_grid_map(m, uv) && CGAL::is_valid_polygon_mesh(m));
    assert(SS::quad_valences(m, uv).status == SS::INVALID_INPUT);   // it has no valence for a cone of 90 degrees
    const std::string what = "two sheets of the quarter plane [0, " + std::to_string(n) + "]^2 wound around (1.5, 0.5)";
    Quad_result r;
    extract(m, uv, 1, r);
    check_quad_mesh(m, uv, 1, r, what);
    std::vector<std::size_t> absorbed = r.report.absorbed_cones;
    std::sort(absorbed.begin(), absorbed.end());
    assert(absorbed == std::vector<std::size_t>({std::size_t((std::min)(cones[0], cones[1])), std::size_t((std::max)(cones[0], cones[1]))}));
    assert(r.report.filled_branch_points == std::vector<std::size_t>(1, std::size_t(w)) && r.report.split_cones.empty());
    assert(r.report.covers_map() && r.report.uv_area == Q(2 * n * n) && r.report.quads == std::size_t(2 * n * n - 1));
    assert(r.report.euler_characteristic == 1 && r.report.boundary_loops == 1 && r.report.cones == 3);
    // the rungs end at the absorbed cells' corners a (valence 2 + 1) and b (3 + 1): the two cones' index 3/4 each and the
    // branch point's -1 carried by two inside vertices of valence 3 (before the rotation was chosen so: 8 irregular)
    assert(r.report.irregular_vertices == 2);
    Quad_result fine;
    extract(m, uv, 2, fine);
    check_quad_mesh(m, uv, 2, fine, what + ", grid scale 2");
    assert(fine.report.split_cones.size() == 2 && fine.report.absorbed_cones.empty() && fine.report.filled_branch_points.empty());
    Quad_result kept;
    kept.report = SS::extract_quad_mesh(m, uv, kept.q, SS::parameters::fill_branched_cells(false));
    assert(kept.report.status == SS::INVALID_INPUT && kept.q.number_of_faces() == 0);
  }
}

// quad_mesh_patches() refuses what is not a manifold quad mesh (INVALID_INPUT naming the face or vertex) and then
// writes nothing
static void test_patch_refusals()
{
  Mesh t;
  triangulated_grid(t, 2, true);
  Mesh pinched;                                      // two quads with one vertex in common: two fans there
  std::vector<vertex_descriptor> v;
  for(int k = 0; k < 7; ++k) v.push_back(pinched.add_vertex(Point_3(k, k % 2, 0)));
  pinched.add_face(v[0], v[1], v[2], v[3]);
  pinched.add_face(v[0], v[4], v[5], v[6]);
  for(const Mesh* m : {&t, &pinched}) {
    SS::Quad_patch_location<Mesh> untouched;
    untouched.patch = 12345;
    std::vector<SS::Quad_patch_location<Mesh> > locations(m->number_of_faces(), untouched);
    const SS::Quad_patches r = SS::quad_mesh_patches(*m, boost::make_iterator_property_map(locations.begin(), get(boost::face_index, *m)));
    const char* words = m == &t ? "face 0 is not a quad" : "vertex 0 is not manifold";
    assert(r.status == SS::INVALID_INPUT && r.message.find(words) != std::string::npos && r.patches.empty());
    for(const SS::Quad_patch_location<Mesh>& l : locations) assert(l.patch == 12345);
    std::printf("quad: patches refused: %s\n", r.message.c_str());
  }
  // a quad mesh with a removed face (Surface_mesh keeps its index until collect_garbage()): refused, naming the cure;
  // after collect_garbage() a torus of 5 x 5 quads with a hole, whose 4 corners send motorcycles: rectangles
  Mesh m; UV_map uv;
  make_flat_torus(m, uv, 5, 5);
  Quad_result q;
  extract(m, uv, 1, q);
  assert(q.report.status == SS::SUCCESS && q.q.number_of_faces() == 25);
  CGAL::Euler::remove_face(q.q.halfedge(face_descriptor(12)), q.q);
  std::vector<SS::Quad_patch_location<Mesh> > locations(q.q.num_faces());
  const auto pm = boost::make_iterator_property_map(locations.begin(), get(boost::face_index, q.q));
  SS::Quad_patches r = SS::quad_mesh_patches(q.q, pm);
  assert(r.status == SS::INVALID_INPUT && r.message.find("collect_garbage()") != std::string::npos);
  q.q.collect_garbage();
  r = SS::quad_mesh_patches(q.q, pm);
  assert(r.status == SS::SUCCESS && r.all_rectangles() && r.nodes == 4);
  check_quad_patches(q.q, "torus 5 x 5 with a hole");

  // two parts: one quad (its 4 corners are nodes that launch nothing) and a ring of 4 quads (no node: seeded at its first
  // vertex, one motorcycle across it). The first version seeded vertex 0 only, and only where no node launched a
  // motorcycle: here a corner of the quad, which launches nothing, and the ring stayed an annulus (as in the regression
  // input of fuzz_quad_patches); every patch a rectangle now, and the layout: 2 faces
  Mesh two;
  std::vector<vertex_descriptor> w;
  for(int k = 0; k < 12; ++k) w.push_back(two.add_vertex(Point_3(k % 4, k / 4, k % 3)));
  two.add_face(w[0], w[1], w[2], w[3]);
  for(int k = 0; k < 4; ++k) two.add_face(w[std::size_t(4 + k)], w[std::size_t(4 + (k + 1) % 4)], w[std::size_t(8 + (k + 1) % 4)], w[std::size_t(8 + k)]);
  std::vector<SS::Quad_patch_location<Mesh> > parts(two.number_of_faces());
  r = SS::quad_mesh_patches(two, boost::make_iterator_property_map(parts.begin(), get(boost::face_index, two)));
  assert(r.status == SS::SUCCESS && r.all_rectangles() && r.patches.size() == 2 && r.nodes == 4 && r.motorcycles == 1);
  check_quad_patches(two, "a quad and a ring of 4 quads");
}

static void test_refusals()
{
  // fold-overs and zero-area triangles: the grid with vertex (1, 1) moved to (3, 1) in UV, (1, 2) onto (1, 3);
  // an IGM (no cut edge)
  Mesh m;
  const std::vector<vertex_descriptor> vs = triangulated_grid(m, 3, true);
  UV_map uv = uv_of(m);
  for(halfedge_descriptor h : m.halfedges())
    if(!m.is_border(h))
      put(uv, h, m.target(h) == vs[5] ? Point_2(3, 1) : m.target(h) == vs[9] ? Point_2(1, 3)
                                      : Point_2(m.point(m.target(h)).x(), m.point(m.target(h)).y()));
  std::vector<std::size_t> negative, zero;
  for(face_descriptor f : m.faces()) {
    const halfedge_descriptor h = m.halfedge(f);
    const int s = CGAL::sign(cross(exact_uv(uv, m.prev(h)), exact_uv(uv, h), exact_uv(uv, m.next(h))));
    if(s < 0) negative.push_back(std::size_t(f));
    if(s == 0) zero.push_back(std::size_t(f));
  }
  assert(!negative.empty() && !zero.empty() && SS::is_exact_integer_grid_map(m, uv));
  const SS::Quad_mesh_report r = check_refused(m, uv, 1, SS::FOLD_OVERS, "fold-over", "grid with fold-overs");
  assert(r.fold_overs == negative && r.zero_area_faces == zero && r.advice.find("untangle the map first") == 0 &&
         r.message.size() > r.advice.size() && r.message.compare(r.message.size() - r.advice.size(), r.advice.size(), r.advice) == 0);
  // a closed surface mapped without cuts (a projection: an exact integer-grid map, trivially, with no seam) folds in
  // every map: said so instead of the advice to untangle (closed_uncut_parts.h)
  {
    Mesh t; UV_map uvt;
    make_flat_torus(t, uvt, 8, 8);
    uv_from_xy(t, uvt);
    assert(SS::is_exact_integer_grid_map(t, uvt));
    const SS::Quad_mesh_report rt = check_refused(t, uvt, 1, SS::FOLD_OVERS, "closed parts of the surface without cut edges",
                                                  "torus projected onto a plane");
    assert(rt.message.find("untangle the map first") == std::string::npos && rt.advice.empty());
  }
  const SS::Quad_valences qv = SS::quad_valences(m, uv);
  assert(qv.status == SS::FOLD_OVERS && qv.fold_overs == negative && qv.zero_area_faces == zero && qv.valence.empty());
  // a grid scale that is not a power of two
  check_refused(m, uv, 3, SS::INVALID_INPUT, "not a power of two", "grid scale 3");
  // a cone of 90 degrees
  Mesh c; UV_map uvc;
  make_quarter_turn_cone(c, uvc);
  {
    const SS::Quad_valences qc = SS::quad_valences(c, uvc);   // the same refusal: a VVAL file never gets a valence of 1
    assert(SS::is_exact_integer_grid_map(c, uvc) && qc.status == SS::INVALID_INPUT && qc.valence.empty() &&
           qc.message.find("vertex 0 has a UV angle sum of 1 quarter turn") == 0);
  }
  check_refused(c, uvc, 1, SS::INVALID_INPUT, "valence 1", "cone of 90 degrees");
  // no whole cell, so no quad mesh (it used to be an empty mesh with SUCCESS, or an internal error): one grid square
  // at half size (its one cell cut by the border), and a grid whose UVs lie on one line (every face collapsed onto
  // its long side: UV area 0)
  for(int which = 0; which < 2; ++which) {
    Mesh g;
    triangulated_grid(g, which == 0 ? 1 : 3, true);
    UV_map uvg = uv_of(g);
    for(halfedge_descriptor h : g.halfedges()) {
      if(g.is_border(h)) continue;
      const Point_3& p = g.point(g.target(h));
      put(uvg, h, which == 0 ? Point_2(0.5 * p.x(), 0.5 * p.y()) : Point_2(p.x() + 2 * p.y(), 0));
    }
    assert(SS::is_exact_integer_grid_map(g, uvg));
    check_refused(g, uvg, 1, SS::INVALID_INPUT, which == 0 ? "no whole cell of the integer grid (UV area 0.25 grid cells, 1 cells cut"
                                                           : "no whole cell of the integer grid (UV area 0 grid cells)",
                  which == 0 ? "half a cell" : "a map of zero area");
  }
}

// CGAL's bear with an Orbifold Tutte map of the given type (farthest-point cones); false without CGAL's data
static bool bear_orbifold(Mesh& m, UV_map& uv, SMP::Orbifold_type type)
{
  const fs::path p = fs::path(SS_CGAL_DATA_DIR) / "bear.off";
  if(std::string(SS_CGAL_DATA_DIR).empty() || !fs::exists(p) || !CGAL::IO::read_polygon_mesh(p.string(), m)) {
    std::cout << "quad: bear orbifold: SKIPPED (no " << p.string() << ")\n";
    return false;
  }
  uv = uv_of(m);
  std::string msg;
  const std::size_t cones = SS::internal::orbifold_cone_count(type);
  assert(SS::internal::make_orbifold_tutte_uv(m, uv, SS::internal::farthest_point_cones(m, cones), type, msg) == SS::SUCCESS);
  return true;
}

static void test_bear_orbifold()
{
  Mesh input; UV_map uv_in;
  if(!bear_orbifold(input, uv_in, SMP::Parallelogram)) return;
  Patch_sizes coarser;
  for(double S : {2., 4., 8.}) {
    Mesh m = input;
    UV_map uv = uv_of(m);
    const SS::Snap_report s = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).grid_scale(S));
    assert(s.status == SS::SUCCESS && s.flips_after_repair == 0 && s.degenerate_after_repair == 0);
    Quad_result r;
    extract(m, uv, S, r);
    const Patch_sizes sizes = check_quad_mesh(m, uv, S, r, "bear orbifold Parallelogram, scale " + std::to_string(int(S)));
    if(S > 2) check_patches_refine(coarser, sizes, "bear orbifold, patches at scales " + std::to_string(int(S / 2)) + ", " + std::to_string(int(S)));
    coarser = sizes;
    assert(r.report.euler_characteristic == 2 && r.report.cones == 4 && r.report.valence_histogram[2] == 4);
    if(S == 8) {                                    // the map scaled by 2^-5, grid_scale 2^8: the same mesh
      Mesh small = m;
      UV_map uvs = uv_of(small);
      scale_uvs(small, uvs, -5);
      Quad_result rs;
      extract(small, uvs, S * 32, rs);
      assert(rs.report.status == SS::SUCCESS && same_quad_mesh(r, rs));
    }
  }
  {   // at grid scale 2^-3 the map spans less than one grid cell: its 4 cones would fall onto one integer point
    Mesh m = input;
    UV_map uv = uv_of(m);
    const std::vector<std::uint64_t> bits = uv_bits(m, uv);
    const SS::Snap_report s = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).grid_scale(0.125));
    assert(s.status == SS::INVALID_INPUT && uv_bits(m, uv) == bits);
    assert(s.message.find("spans less than one grid cell") != std::string::npos && s.message.find("has 4 cones") != std::string::npos);
    std::cout << "quad: bear orbifold Parallelogram at grid scale 1/8 refused: " << s.message << "\n";
  }
  // the Square map (two cones of 90 degrees): at grid scale 1 the 2 x 2 cells around a cone are not 7 points of the
  // surface (refused); at 8 each is made one quad
  Mesh square; UV_map uv_square;
  bear_orbifold(square, uv_square, SMP::Square);
  for(double S : {1., 8.}) {
    Mesh m = square;
    UV_map uv = uv_of(m);
    assert(SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).grid_scale(S)).status == SS::SUCCESS);
    if(S == 1) { check_refused(m, uv, S, SS::INVALID_INPUT, "cannot be replaced with its 2 x 2 cells", "bear orbifold Square"); continue; }
    Quad_result r;
    extract(m, uv, S, r);
    check_quad_mesh(m, uv, S, r, "bear orbifold Square, scale 8, its 2 cones of 90 degrees split");
    assert(r.report.split_cones.size() == 2 && r.report.euler_characteristic == 2);
  }
}

// the quads of a mesh as cycles of 3D points, each from its smallest point (orientation kept), sorted
static std::vector<std::vector<Point_3> > quad_point_cycles(const Mesh& q)
{
  std::vector<std::vector<Point_3> > out;
  for(face_descriptor f : q.faces()) {
    std::vector<Point_3> c;
    for(vertex_descriptor v : CGAL::vertices_around_face(q.halfedge(f), q)) c.push_back(q.point(v));
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Cut invariance: the quad mesh belongs to the surface map, not to its charts. Re-expressing a region around a cone
// by a grid symmetry (its border becomes cut edges) gives the same quads with the same 3D points, bit for bit (every
// position is rounded once from exact differences, which a quarter turn keeps)
static void test_cut_invariance()
{
  Mesh input; UV_map uv_in;
  if(!bear_orbifold(input, uv_in, SMP::Parallelogram)) return;
  const double S = 32;                            // a few thousand quads, vertices inside faces, on edges, at vertices
  assert(SS::snap_seamless_parameterization(input, uv_in, SS::parameters::integer_grid_map(true).grid_scale(S)).status == SS::SUCCESS);
  Quad_result a;
  extract(input, uv_in, S, a);
  assert(a.report.status == SS::SUCCESS);
  const std::vector<std::vector<Point_3> > quads = quad_point_cycles(a.q);
  for(int rings : {1, 4, 12}) {
    Mesh m = input;
    UV_map uv = uv_of(m);
    const std::size_t new_cuts = recharted(m, uv, SS::internal::farthest_point_cones(m, 4).front(), rings);   // around a cone
    assert(new_cuts > 0 && SS::is_exact_integer_grid_map(m, uv, SS::parameters::grid_scale(S)));
    Quad_result b;
    extract(m, uv, S, b);
    check_quad_mesh(m, uv, S, b, "bear orbifold re-charted, " + std::to_string(rings) + " rings");
    assert(b.report.status == SS::SUCCESS && b.report.valence_histogram == a.report.valence_histogram);
    assert(quad_point_cycles(b.q) == quads);
    std::cout << "quad: bear orbifold, " << rings << " face rings re-charted (" << new_cuts << " new cut edges): the same "
              << quads.size() << " quads, bit for bit\n";
  }
}

static void test_shared_data()
{
  std::vector<fs::path> files;
  if(!shared_obj_files_or_skip("quad: shared data", files)) return;
  std::size_t extracted = 0, folded = 0, quarter_cones = 0, recharted_maps = 0;
  for(const fs::path& p : files) {
    if(fs::file_size(p) > 1000000) continue;     // the large files are in bench_quad
    Mesh m;
    if(!load_obj(p, m)) continue;
    UV_map uv = uv_of(m);
    const SS::Snap_report s = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true));
    const std::string name = p.filename().string();
    if(s.status != SS::SUCCESS) {
      std::cout << "quad: " << name << ": not snapped to an integer-grid map (" << SS::status_name(s.status) << ")\n";
      // a map that was never quantized (retinal_miq, an MIQ map before its integer rounding): quantize(true) at grid
      // scale 8, whose cells are smaller than the distances between its cones, gives an exact fold-free integer-grid
      // map and its quad mesh, with every guarantee
      if(s.status != SS::INVALID_INPUT || s.message.find("not quantized") == std::string::npos) continue;
      const SS::Snap_report q = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).quantize(true)
                                                                              .grid_scale(8.));
      std::cout << "quad: " << name << ": quantized at grid scale 8: " << SS::status_name(q.status) << ", "
                << q.flips_after_repair << " / " << q.degenerate_after_repair << " negative / zero-area triangles\n";
      if(name != "retinal_miq.obj") continue;
      assert(q.status == SS::SUCCESS && q.quantized && q.flips_after_repair == 0 && q.degenerate_after_repair == 0);
      Quad_result r;
      extract(m, uv, 8, r);
      check_quad_mesh(m, uv, 8, r, name + ", quantized, grid scale 8");
      assert(r.report.irregular_vertices == q.field_cones);
      ++extracted;
      continue;
    }
    std::size_t coincident = 0;                  // zero-area faces with two corners at one UV point
    for(face_descriptor f : m.faces()) {
      const halfedge_descriptor h = m.halfedge(f);
      const std::array<Q, 2> a = exact_uv(uv, m.prev(h)), b = exact_uv(uv, h), c = exact_uv(uv, m.next(h));
      coincident += CGAL::is_zero(cross(a, b, c)) && (a == b || b == c || c == a) ? 1 : 0;
    }
    if(s.flips_after_repair > 0 || coincident > 0) {
      const SS::Quad_mesh_report r = check_refused(m, uv, 1, SS::FOLD_OVERS, "untangle", name);
      assert(r.fold_overs.size() == s.flips_after_repair && r.zero_area_faces.size() == s.degenerate_after_repair);
      ++folded;
      continue;
    }
    const SS::Quad_valences qv = SS::quad_valences(m, uv);
    // a cone of 90 degrees (Directional's knight has one): quad_valences() refuses it, naming the vertex
    const bool quarter_cone = qv.status == SS::INVALID_INPUT && qv.message.find("(a cone of valence 1)") != std::string::npos;
    const bool winds_twice = quarter_cone && qv.message.find("quarter turns: most likely a cone of 5") != std::string::npos;
    assert(qv.status == SS::SUCCESS || quarter_cone);
    if(quarter_cone) {
      // by default its 2 x 2 cells become one quad (the knight's cone: 3 corners of valence 3 for it) ...
      Quad_result r;
      extract(m, uv, 1, r);
      check_quad_mesh(m, uv, 1, r, name + ", its cone of 90 degrees split");
      assert(!r.report.split_cones.empty() && r.report.irregular_vertices == r.report.cones + 2 * r.report.split_cones.size());
      // ... and without split_valence_one_cones, refused: with no vertex winding twice anywhere, the cone is most
      // likely the map's own (the knight's field has it): said so, and no cone pair is blamed
      Quad_result kept;
      kept.report = SS::extract_quad_mesh(m, uv, kept.q, SS::parameters::split_valence_one_cones(false));
      assert(kept.report.status == SS::INVALID_INPUT && kept.q.number_of_faces() == 0);
      assert(winds_twice || (kept.report.message.find("singularity of index 3/4") != std::string::npos &&
                             kept.report.message.find("onto one integer point") == std::string::npos));
      ++quarter_cones;
      continue;
    }
    Patch_sizes coarser;
    for(double S : {1., 2.}) {
      if(S == 2 && name.find("horse") == std::string::npos) continue;
      Quad_result r;                             // an IGM at grid scale 1 is one at 2 as well
      extract(m, uv, S, r);
      const Patch_sizes sizes = check_quad_mesh(m, uv, S, r, name + ", grid scale " + std::to_string(int(S)));
      if(S == 2) check_patches_refine(coarser, sizes, name + ", patches at scales 1, 2");
      coarser = sizes;
      ++extracted;
      if(S == 1) {                               // cut invariance (test_cut_invariance()), on real maps
        Mesh m2 = m;
        UV_map uv2 = uv_of(m2);
        assert(recharted(m2, uv2, *m2.vertices().begin(), 8) > 0);
        Quad_result r2;
        extract(m2, uv2, S, r2);
        assert(r2.report.status == r.report.status && quad_point_cycles(r2.q) == quad_point_cycles(r.q));
        ++recharted_maps;
      }
    }
  }
  std::cout << "quad: shared data: " << extracted << " quad meshes checked (" << recharted_maps << " of them the same, bit for "
            << "bit, with 8 face rings re-charted), " << folded << " maps with fold-overs refused, " << quarter_cones
            << " with a cone of 90 degrees split (refused without split_valence_one_cones)\n";
  assert(extracted >= 3);
}

// libQEx's stored quad mesh of a map of ../shared/data/libqex (../shared/reference/libqex_quads/<name>_quad.obj):
// its vertex and face counts and its irregular vertices (valence other than 4); false if it is not there
static bool libqex_reference(const fs::path& map_file, std::size_t& V, std::size_t& F, std::size_t& irregular)
{
  std::string name = map_file.filename().string();
  name = name.substr(0, name.size() - std::string("_param.obj").size());
  fs::path data(SS_SHARED_DATA_DIR);
  if(!data.has_filename()) data = data.parent_path();                  // ".../data/"
  const fs::path ref = data.parent_path() / "reference" / "libqex_quads" / (name + "_quad.obj");
  Mesh q;
  if(!fs::is_regular_file(ref) || !CGAL::IO::read_OBJ(ref.string(), q)) return false;
  V = q.number_of_vertices(); F = q.number_of_faces(); irregular = 0;
  for(vertex_descriptor v : q.vertices()) irregular += q.degree(v) != 4 ? 1 : 0;
  return true;
}

// Directional's rot-seamless dragon (../shared/data; 24,984 faces, 870 cones, never quantized) quantized at grid scale 4
// with the cone pairs merged (seamless_quad's options): the cells are about as large as the distances between its cones,
// and only the quantizer's rules (no cone onto the point of a cone near it unless the pair merges, no triangle of three
// cones non-positive) leave the untangling a map it can make fold-free: an exact integer-grid map whose quad mesh has
// every guarantee (before those rules: 1 negative and 3 zero-area triangles left, refused)
static void test_quantized_dragon()
{
  Mesh m;
  if(!load_shared_or_skip("directional/dragon-param-rot-seamless.obj", "quad: quantized dragon", m)) return;
  UV_map uv = uv_of(m);
  const SS::Snap_report s = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).quantize(true)
                                                                        .merge_cone_pairs(true).grid_scale(4.));
  if(s.status != SS::SUCCESS) std::cerr << s.message << std::endl;
  assert(s.status == SS::SUCCESS && s.quantized && SS::is_exact_integer_grid_map(m, uv, SS::parameters::grid_scale(4.)));
  std::printf("quad: dragon (rot-seamless), quantized at grid scale 4: %zu / %zu negative / zero-area triangles, %zu pairs "
              "merged, max change %.2f cells\n", s.flips_after_repair, s.degenerate_after_repair, s.merged_cone_pairs.size(),
              s.total_max_change * s.grid_scale);
  assert(s.flips_after_repair == 0 && s.degenerate_after_repair == 0);
  Quad_result r;
  extract(m, uv, 4, r);
  check_quad_mesh(m, uv, 4, r, "dragon (rot-seamless), quantized at 4");
  assert(r.report.irregular_vertices == s.field_cones);
  // at grid scale 2 a cone finds each of its four neighbouring integer points on the point of a cone near it or making a
  // face of three cones negative: the integer points beyond them are tried next (before: it took the first, and two
  // zero-area triangles were left, proven forced by coincident corners; now none is left)
  Mesh m2;
  if(!load_shared_or_skip("directional/dragon-param-rot-seamless.obj", "quad: quantized dragon", m2)) return;
  UV_map uv2 = uv_of(m2);
  const SS::Snap_report s2 = SS::snap_seamless_parameterization(m2, uv2, SS::parameters::integer_grid_map(true)
                                                                           .quantize(true).merge_cone_pairs(true).grid_scale(2.));
  assert(s2.status == SS::SUCCESS && s2.quantized);
  assert(s2.degenerate_after_repair == 0);
  for(const SS::Fold_explanation& f : s2.folds) assert(f.reason != SS::FOLD_COINCIDENT_CORNERS);
  std::printf("quad: dragon (rot-seamless), quantized at grid scale 2: %zu / %zu negative / zero-area triangles\n",
              s2.flips_after_repair, s2.degenerate_after_repair);
}

// Directional's full-seamless dragon (../shared/data; 24,984 faces) snapped to an integer-grid map at grid scale 1 with
// its cone pairs merged and the others on one integer point separated, untangled: no fold-over and no zero-area
// triangle left, but 12 vertices around which the map winds twice inside a cell. Each branched cell is filled; the one
// at vertex 5676 shares a side with the cell of a cone of 90 degrees (a quad (p, a, b, a)), which is filled with it
// (before: refused, "a neighbouring cell is missing"). The quad mesh has every guarantee: closed, manifold, all quads,
// chi 2 (libQEx leaves holes and non-manifold edges on this map)
static void test_full_seamless_dragon()
{
  Mesh m;
  if(!load_shared_or_skip("directional/dragon-param-full-seamless.obj", "quad: full-seamless dragon", m)) return;
  UV_map uv = uv_of(m);
  const SS::Snap_report s = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).untangle(true)
                                                                        .merge_cone_pairs(true).separate_cone_pairs(true));
  if(s.status != SS::SUCCESS) std::cerr << s.message << std::endl;
  assert(s.status == SS::SUCCESS && SS::is_exact_integer_grid_map(m, uv));
  assert(s.flips_after_repair == 0 && s.degenerate_after_repair == 0);
  Quad_result r;
  extract(m, uv, 1, r);
  check_quad_mesh(m, uv, 1, r, "dragon (full-seamless), cone pairs merged and separated");
  assert(r.report.covers_map() && r.report.euler_characteristic == 2 && r.report.boundary_loops == 0);
  assert(!r.report.filled_branch_points.empty() && !r.report.absorbed_cones.empty());
  std::printf("quad: dragon (full-seamless): %zu quads, %zu irregular vertices, %zu cones of 90 degrees split, %zu branch "
              "points filled, %zu cone cells filled with them\n", r.report.quads, r.report.irregular_vertices,
              r.report.split_cones.size(), r.report.filled_branch_points.size(), r.report.absorbed_cones.size());
}

// A real genus-1 map that was never made integral: Directional's hex torus with its UVs times 1.1 (no cone, no border:
// the quantization rounds the translations of the cut edges that close the cut graph's cycles and takes the others from
// the vertices' conditions), quantized at grid scale 1: an exact fold-free IGM whose quad mesh has every guarantee,
// Euler characteristic 0 and no irregular vertex
static void test_quantized_torus()
{
  Mesh m;
  if(!load_shared_or_skip("directional/torus-hex-param.obj", "quad: quantized hex torus", m)) return;
  UV_map uv = uv_of(m);
  multiply_uvs(m, uv, 1.1);
  const SS::Snap_report s = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).quantize(true));
  if(s.status != SS::SUCCESS) std::cerr << s.message << std::endl;
  assert(s.status == SS::SUCCESS && s.quantized && SS::is_exact_integer_grid_map(m, uv) && s.field_cones == 0);
  assert(s.flips_after_repair == 0 && s.degenerate_after_repair == 0 && s.winding_defects.empty());
  Quad_result r;
  extract(m, uv, 1, r);
  check_quad_mesh(m, uv, 1, r, "hex torus x 1.1, quantized");
  assert(r.report.euler_characteristic == 0 && r.report.irregular_vertices == 0);
  std::printf("quad: hex torus x 1.1 (genus 1), quantized at grid scale 1: %zu quads, max change %.2f cells\n",
              r.report.quads, s.total_max_change * s.grid_scale);
}

// libQEx's maps (over 1 MB, so not in test_shared_data()): their integer translations put cone pairs onto one
// integer point, and the untangled IGM winds wrongly around them (fandisk, duck_miq_8: fold-free; duck_qc_8: 2
// fold-overs left). The extraction refuses the fold-free ones (nothing written) and names a collapsed pair that the
// snap report's winding defects name too; quad_valences() refuses them as well (no valence 1 in a VVAL file).
// With merge_cone_pairs(true) the named pair is merged (its cones regular points of the field, the map still an
// exact IGM with two cones fewer), and the quad mesh is extracted with every guarantee: as many vertices and
// quads as libQEx's stored mesh within 10 %, no more irregular vertices than it.
static void test_collapsed_cone_pairs()
{
  std::vector<fs::path> files;
  if(!shared_obj_files_or_skip("quad: collapsed cone pairs", files)) return;
  std::size_t refused = 0, merged = 0;
  for(const fs::path& p : files) {
    const std::string name = p.filename().string();
    if(name != "fandisk_param.obj" && name != "duck_miq_8_param.obj" && name != "duck_qc_8_param.obj") continue;
    Mesh m;
    if(!load_obj(p, m)) continue;
    const Mesh input = m;
    UV_map uv = uv_of(m);
    const SS::Snap_report s = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true));
    assert(s.status == SS::SUCCESS && !s.winding_defects.empty() && s.merged_cone_pairs.empty());
    std::string pair;                          // "a and b": the pair the refusal names first, the nearest (fandisk, duck_miq_8)
    std::vector<std::string> pairs;            // every pair it names
    if(s.flips_after_repair + s.degenerate_after_repair == 0) {
      const SS::Quad_mesh_report r = check_refused(m, uv, 1, SS::INVALID_INPUT, "onto one integer point (vertices ", name);
      const std::size_t at = r.message.find("(vertices ") + 10;
      for(std::size_t b = at, e; ; b = e + 2) {
        e = r.message.find_first_of(",;)", b);
        pairs.push_back(r.message.substr(b, e - b));
        if(r.message[e] != ',') break;
      }
      assert(pairs.size() <= 3);               // the nearest three at most, the others counted
      pair = pairs.front();
      bool named = false;
      for(const SS::Winding_defect& d : s.winding_defects)
        named = named || d.message.find("the cones at vertices " + pair + " nearby") != std::string::npos;
      assert(named);
      // quad_valences() (the VVAL file) refuses it too: it gave the wound cone valence 1 and its partner 8
      const SS::Quad_valences qv = SS::quad_valences(m, uv);
      assert(qv.status == SS::INVALID_INPUT && qv.valence.empty() && qv.message.find("quarter turns: most likely a cone of 5") != std::string::npos);
      ++refused;
    }

    Mesh mm = input;
    UV_map uvm = uv_of(mm);
    const SS::Snap_report sm = SS::snap_seamless_parameterization(mm, uvm, SS::parameters::integer_grid_map(true).merge_cone_pairs(true));
    assert(sm.status == SS::SUCCESS && sm.flips_after_repair + sm.degenerate_after_repair == 0 && sm.winding_defects.empty());
    bool pair_merged = pairs.empty();          // one of the named pairs (pairs sharing a cone: one of them merges)
    for(const std::pair<std::size_t, std::size_t>& c : sm.merged_cone_pairs)
      pair_merged = pair_merged || std::find(pairs.begin(), pairs.end(), std::to_string((std::min)(c.first, c.second)) + " and " +
                                                                       std::to_string((std::max)(c.first, c.second))) != pairs.end();
    assert(pair_merged && sm.merged_cut_edges >= sm.merged_cone_pairs.size() + sm.added_cut_edges);
    assert(sm.cut_edges == s.cut_edges + sm.added_cut_edges);
    assert(sm.field_cones + 2 * sm.merged_cone_pairs.size() == s.field_cones);
    assert(sm.cones_on_integer_points_after == sm.field_cones && sm.integer_translations_after == sm.cut_edges);
    assert(SS::is_exact_integer_grid_map(mm, uvm));
    Quad_result q;
    extract(mm, uvm, 1, q);
    check_quad_mesh(mm, uvm, 1, q, name + ", cone pairs merged");
    assert(q.report.irregular_vertices == sm.field_cones);
    std::size_t V, F, irregular;
    if(libqex_reference(p, V, F, irregular)) {
      const double dv = std::fabs(double(q.q.number_of_vertices()) / double(V) - 1), df = std::fabs(double(q.q.number_of_faces()) / double(F) - 1);
      std::cout << "quad: " << name << ": " << sm.merged_cone_pairs.size() << " cone pairs merged, " << q.q.number_of_vertices()
                << " vertices, " << q.q.number_of_faces() << " quads, " << q.report.irregular_vertices << " irregular (libQEx: " << V
                << ", " << F << ", " << irregular << ")\n";
      assert(dv <= 0.1 && df <= 0.1 && q.report.irregular_vertices <= irregular);
    }
    ++merged;
  }
  std::cout << "quad: collapsed cone pairs: " << refused << " maps refused with the pair named, " << merged
            << " extracted with the pairs merged\n";
}

// The exact tests on doubles that the extractor's input check uses (exact_uv_check.h, integer_grid_constraints.h):
// same_difference (x - y == z - w, by Dyadic_sum) and is_integer_sum ((a + b) 2^s an integer) against Gmpq, on
// random doubles of every magnitude, on near misses (one ulp off) and on exact hits.
static void test_exact_double_tests()
{
  std::mt19937_64 rng(11);
  auto any_double = [&]() {
    const double m = std::uniform_real_distribution<double>(-1, 1)(rng);
    return std::ldexp(m, int(rng() % 2090) - 1070);   // finite: below 2^1020
  };
  auto grid_double = [&]() { return double(std::int64_t(rng() % 2001) - 1000) * std::ldexp(1., -int(rng() % 60)); };
  std::size_t equal = 0, integral = 0;
  for(int i = 0; i < 200000; ++i) {
    const bool grid = i % 2 == 0;
    double x = grid ? grid_double() : any_double(), y = grid ? grid_double() : any_double();
    double z = grid ? grid_double() : any_double(), w = grid ? grid_double() : any_double();
    if(i % 4 == 1) { z = x + std::ldexp(1., int(rng() % 8)); w = y + std::ldexp(1., int(rng() % 8)); }   // often equal
    if(i % 8 == 3) w = std::nextafter(w, 1e300);                                                   // a near miss
    const bool same = Q(x) - Q(y) == Q(z) - Q(w);
    assert(SS::internal::same_difference(x, y, z, w) == same);
    equal += same ? 1 : 0;
    const int e = int(rng() % 80) - 40;
    const Q scaled = (Q(x) + Q(y)) * (e >= 0 ? Q(CGAL::Gmpz(1) << e) : Q(CGAL::Gmpz(1), CGAL::Gmpz(1) << -e));
    assert(SS::internal::is_integer_sum(x, y, e) == SS::internal::is_integer(scaled));
    integral += SS::internal::is_integer(scaled) ? 1 : 0;
  }
  std::cout << "quad: exact tests on doubles: 200000 cases agree with Gmpq (" << equal << " equal differences, " << integral
            << " integer sums)\n";
  assert(equal > 10000 && integral > 10000);
}

int main(int argc, char** argv)
{
  std::setvbuf(stdout, nullptr, _IONBF, 0);
  parse_test_arguments(argc, argv);
  test_exact_double_tests();
  test_cube();
  test_quantized_cube();
  test_torus();
  test_output_meshes();
  test_grid();
  test_collapsed_faces();
  test_refusals();
  test_patch_refusals();
  test_branch_points();
  test_valence_one_cones();
  test_cone_cell_absorption_rules();
  if(!sanitizer_subset()) test_bear_orbifold();
  if(!sanitizer_subset()) test_cut_invariance();
  test_shared_data();
  if(!sanitizer_subset()) test_collapsed_cone_pairs();
  if(!sanitizer_subset()) test_quantized_dragon();
  if(!sanitizer_subset()) test_full_seamless_dragon();
  test_quantized_torus();
  std::cout << "test_quad: all passed\n";
  return 0;
}
