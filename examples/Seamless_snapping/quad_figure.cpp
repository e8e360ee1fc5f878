// quad_figure: draws the figure of the user manual's quad-mesh section as an SVG: CGAL's bear with an
// Orbifold Tutte map (Parallelogram: 4 cones of 180 degrees), the exact integer-grid map it snaps to, and
// the quad mesh extracted from it.
//
//   quad_figure BEAR.off OUT.svg [GRID_SCALE [INPUT_MAP.obj]]
//
// GRID_SCALE (a power of two, default 16) sets the grid: isolines at multiples of 1/GRID_SCALE in UV.
// INPUT_MAP.obj receives the Orbifold Tutte map before snapping (an approximately seamless OBJ with corner
// UVs, the input of the quad-mesh example extract_quad_mesh.cpp and of seamless_quad).
// Panels: (1) the input map in UV: its outline (the mesh cut open along its cut edges is a disk; red), the
// isolines u, v = k / GRID_SCALE (grey), the cones; (2) the exact integer-grid map, likewise, with the quad
// vertices (the integer points, blue) and the cones on them; (3) the quad mesh in 3D (orthographic, painter's
// algorithm), cones in red, each of its rectangle patches (quad_mesh_patches()) in its own colour, the separatrices
// between them dark.
// The orbifold map is seamless up to solver error (about 1e-14 of its size), so panels 1 and 2 look alike:
// what differs is exactness, which the program checks (is_exact_integer_grid_map()) before it draws.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/extract_quad_mesh.h>
#include <CGAL/Seamless_snapping/quad_mesh_patches.h>
#include <CGAL/Seamless_snapping/internal/inputs/orbifold_tutte_input.h>   // farthest_point_cones(), make_orbifold_tutte_uv()
#include <CGAL/Seamless_snapping/is_exact_integer_grid_map.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double>                     K;
typedef K::Point_2                                         Point_2;
typedef K::Point_3                                         Point_3;
typedef CGAL::Surface_mesh<Point_3>                        Mesh;
typedef Mesh::Halfedge_index                               halfedge_descriptor;
typedef Mesh::Property_map<halfedge_descriptor, Point_2>   UV_map;

namespace SS = CGAL::Seamless_snapping;

static int fail(const std::string& why) { std::fprintf(stderr, "quad_figure: %s\n", why.c_str()); return EXIT_FAILURE; }

static std::string fmt(double x) { char b[32]; std::snprintf(b, sizeof b, "%.1f", x); return b; }

struct Frame      // UV -> panel coordinates: the bounding box of all corner UVs fitted into a square, y up
{
  double lo_u, hi_v, scale, x0, y0;
  Point_2 operator()(const Point_2& p) const { return Point_2(x0 + (p.x() - lo_u) * scale, y0 + (hi_v - p.y()) * scale); }
};

// the frame of the square panel with top left corner (x0, y0) and side `size`
static Frame uv_frame(const Mesh& m, UV_map uv, double x0, double y0, double size)
{
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for(halfedge_descriptor h : m.halfedges())
    if(!m.is_border(h)) {
      lo[0] = std::min(lo[0], uv[h].x()); hi[0] = std::max(hi[0], uv[h].x());
      lo[1] = std::min(lo[1], uv[h].y()); hi[1] = std::max(hi[1], uv[h].y());
    }
  const double s = size / std::max(hi[0] - lo[0], hi[1] - lo[1]);
  return Frame{lo[0], hi[1], s, x0 + (size - (hi[0] - lo[0]) * s) / 2, y0 + (size - (hi[1] - lo[1]) * s) / 2};
}

// a cut edge: its two faces disagree on an endpoint's UV
static bool is_cut(const Mesh& m, UV_map uv, Mesh::Edge_index e)
{
  const halfedge_descriptor h = m.halfedge(e), o = m.opposite(h);
  return !m.is_border(e) && (uv[h] != uv[m.prev(o)] || uv[m.prev(h)] != uv[o]);
}

// The outline of the map in UV: the mesh cut open along its cut edges is a disk (an Orbifold Tutte map), whose
// boundary (the cut edges on both sides, and the border) is one polygon in UV.
static std::vector<Point_2> outline(const Mesh& m, UV_map uv)
{
  auto boundary = [&](halfedge_descriptor g) { return m.is_border(m.edge(g)) || is_cut(m, uv, m.edge(g)); };
  halfedge_descriptor h0;
  for(halfedge_descriptor h : m.halfedges()) if(!m.is_border(h) && boundary(h)) { h0 = h; break; }
  std::vector<Point_2> p;
  halfedge_descriptor h = h0;
  do {
    p.push_back(uv[h]);
    halfedge_descriptor g = m.next(h);
    while(!boundary(g)) g = m.next(m.opposite(g));
    h = g;
  } while(h != h0 && p.size() <= m.number_of_halfedges());
  return p;
}

// Panel of a UV map: its outline, filled, with the isolines u, v = k / S clipped to it, the cones, and optionally
// the integer points.
static void uv_panel(std::ostringstream& svg, const std::string& id, const Mesh& m, UV_map uv, double S, const Frame& F,
                     const std::vector<Point_2>& cones, const std::vector<Point_2>& dots)
{
  std::ostringstream poly, lines;
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for(const Point_2& p : outline(m, uv)) {
    const Point_2 q = F(p);
    poly << fmt(q.x()) << "," << fmt(q.y()) << " ";
    lo[0] = std::min(lo[0], p.x()); hi[0] = std::max(hi[0], p.x()); lo[1] = std::min(lo[1], p.y()); hi[1] = std::max(hi[1], p.y());
  }
  for(int c = 0; c < 2; ++c)
    for(double k = std::ceil(lo[c] * S); k <= hi[c] * S; ++k) {
      const Point_2 a = F(c == 0 ? Point_2(k / S, lo[1]) : Point_2(lo[0], k / S));
      const Point_2 b = F(c == 0 ? Point_2(k / S, hi[1]) : Point_2(hi[0], k / S));
      lines << "M" << fmt(a.x()) << " " << fmt(a.y()) << "L" << fmt(b.x()) << " " << fmt(b.y());
    }
  svg << "<clipPath id=\"" << id << "\"><polygon points=\"" << poly.str() << "\"/></clipPath>\n"
      << "<polygon points=\"" << poly.str() << "\" fill=\"#eef2f7\" stroke=\"#d62728\" stroke-width=\"1.2\"/>\n"
      << "<path d=\"" << lines.str() << "\" stroke=\"#777\" stroke-width=\"0.5\" fill=\"none\" clip-path=\"url(#" << id << ")\"/>\n";
  for(const Point_2& p : dots) {
    const Point_2 q = F(p);
    svg << "<circle cx=\"" << fmt(q.x()) << "\" cy=\"" << fmt(q.y()) << "\" r=\"1.3\" fill=\"#1f77b4\"/>\n";
  }
  for(const Point_2& p : cones) {
    const Point_2 q = F(p);
    svg << "<circle cx=\"" << fmt(q.x()) << "\" cy=\"" << fmt(q.y()) << "\" r=\"3.5\" fill=\"none\" stroke=\"black\" stroke-width=\"1.5\"/>\n";
  }
}

// the UVs of the corners of the cones (interior vertices whose UV angle sum is not a full turn)
static std::vector<Point_2> cone_corners(const Mesh& m, UV_map uv)
{
  std::vector<Point_2> c;
  for(Mesh::Vertex_index v : m.vertices()) {
    if(m.is_border(v)) continue;
    double sum = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, m)) {
      const Point_2 p = uv[h], a = uv[m.next(h)], b = uv[m.prev(h)];
      sum += std::atan2((a.x() - p.x()) * (b.y() - p.y()) - (a.y() - p.y()) * (b.x() - p.x()),
                        (a.x() - p.x()) * (b.x() - p.x()) + (a.y() - p.y()) * (b.y() - p.y()));
    }
    if(std::abs(sum - 2 * CGAL_PI) > 0.5)
      for(halfedge_descriptor h : CGAL::halfedges_around_target(v, m)) c.push_back(uv[h]);
  }
  return c;
}

int main(int argc, char** argv)
{
  if(argc < 3) return fail("usage: quad_figure BEAR.off OUT.svg [GRID_SCALE [INPUT_MAP.obj]]");
  const double S = argc > 3 ? std::atof(argv[3]) : 16;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh)) return fail(std::string("cannot read mesh ") + argv[1]);

  // 1. the input map: Orbifold Tutte, Parallelogram (cones of 180 degrees: valence 2 in the quad mesh);
  //    corner map: uv[h] = UV of target(h) as seen from face(h)
  UV_map input = mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0, 0)).first;
  std::string msg;
  if(SS::internal::make_orbifold_tutte_uv(mesh, input, SS::internal::farthest_point_cones(mesh, 4),
                                          SS::internal::SMP::Parallelogram, msg) != SS::SUCCESS)
    return fail(msg);
  if(argc > 4 && SS::IO::write_OBJ_with_corner_uvs(argv[4], mesh, input, msg) != SS::SUCCESS) return fail(msg);

  // 2. the exact integer-grid map
  UV_map igm = mesh.add_property_map<halfedge_descriptor, Point_2>("h:igm", Point_2(0, 0)).first;
  for(halfedge_descriptor h : mesh.halfedges()) igm[h] = input[h];
  const SS::Snap_report r = SS::snap_seamless_parameterization(mesh, igm, SS::parameters::integer_grid_map(true).grid_scale(S));
  if(r.status != SS::SUCCESS) return fail(std::string("snap: ") + SS::status_name(r.status) + ": " + r.message);
  if(!SS::is_exact_integer_grid_map(mesh, igm, SS::parameters::grid_scale(S))) return fail("not an exact integer-grid map");

  // 3. the quad mesh
  Mesh quads;
  const SS::Quad_mesh_report q = SS::extract_quad_mesh(mesh, igm, quads, SS::parameters::grid_scale(S));
  if(q.status != SS::SUCCESS) return fail(std::string("quad mesh: ") + SS::status_name(q.status) + ": " + q.message);
  auto patch = quads.add_property_map<Mesh::Face_index, SS::Quad_patch_location<Mesh> >("f:patch").first;
  const SS::Quad_patches patches = SS::quad_mesh_patches(quads, patch);
  if(!patches.all_rectangles()) return fail("patches: " + patches.message);

  // --- SVG: three panels
  const double P = 300, margin = 20, top = 40;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 3 * P + 4 * margin << "\" height=\"" << top + P + 97
      << "\" font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const char* titles[3] = {"input map (Orbifold Tutte)", "exact integer-grid map", "quad mesh"};
  for(int k = 0; k < 3; ++k)
    svg << "<text x=\"" << margin + k * (P + margin) << "\" y=\"" << top - 12 << "\" font-weight=\"bold\">" << titles[k] << "</text>\n";
  uv_panel(svg, "input", mesh, input, S, uv_frame(mesh, input, margin, top, P), cone_corners(mesh, input), {});
  std::vector<Point_2> all_points;                    // the integer points of every face, in its chart (a drawing)
  for(Mesh::Face_index f : mesh.faces()) {
    const halfedge_descriptor h = mesh.halfedge(f);
    const Point_2 t[3] = {igm[mesh.prev(h)], igm[h], igm[mesh.next(h)]};
    for(double i = std::ceil(std::min({t[0].x(), t[1].x(), t[2].x()}) * S); i <= std::max({t[0].x(), t[1].x(), t[2].x()}) * S; ++i)
      for(double j = std::ceil(std::min({t[0].y(), t[1].y(), t[2].y()}) * S); j <= std::max({t[0].y(), t[1].y(), t[2].y()}) * S; ++j) {
        const Point_2 p(i / S, j / S);
        if(CGAL::orientation(t[0], t[1], p) >= 0 && CGAL::orientation(t[1], t[2], p) >= 0 && CGAL::orientation(t[2], t[0], p) >= 0)
          all_points.push_back(p);
      }
  }
  std::sort(all_points.begin(), all_points.end());
  all_points.erase(std::unique(all_points.begin(), all_points.end()), all_points.end());
  uv_panel(svg, "igm", mesh, igm, S, uv_frame(mesh, igm, 2 * margin + P, top, P), cone_corners(mesh, igm), all_points);

  // the quad mesh: rotated (30 degrees about y, -20 about x), orthographic, back faces culled, far to near
  const double ay = 30 * CGAL_PI / 180, ax = -20 * CGAL_PI / 180;
  auto view = [&](const Point_3& p) {
    const double x = std::cos(ay) * p.x() + std::sin(ay) * p.z(), z = -std::sin(ay) * p.x() + std::cos(ay) * p.z();
    return Point_3(x, std::cos(ax) * p.y() - std::sin(ax) * z, std::sin(ax) * p.y() + std::cos(ax) * z);
  };
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for(Mesh::Vertex_index v : quads.vertices()) {
    const Point_3 p = view(quads.point(v));
    lo[0] = std::min(lo[0], p.x()); hi[0] = std::max(hi[0], p.x()); lo[1] = std::min(lo[1], p.y()); hi[1] = std::max(hi[1], p.y());
  }
  const double s3 = P / std::max(hi[0] - lo[0], hi[1] - lo[1]);
  const double x3 = 3 * margin + 2 * P + (P - (hi[0] - lo[0]) * s3) / 2, y3 = top + P - (P - (hi[1] - lo[1]) * s3) / 2;
  auto screen = [&](const Point_3& p) { return Point_2(x3 + (p.x() - lo[0]) * s3, y3 - (p.y() - lo[1]) * s3); };
  std::vector<std::pair<double, Mesh::Face_index> > order;
  for(Mesh::Face_index f : quads.faces()) {
    double depth = 0;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(quads.halfedge(f), quads)) depth += view(quads.point(v)).z();
    order.push_back(std::make_pair(depth, f));
  }
  std::sort(order.begin(), order.end(), [](const std::pair<double, Mesh::Face_index>& a, const std::pair<double, Mesh::Face_index>& b) {
    return a.first < b.first || (a.first == b.first && a.second < b.second); });
  for(const auto& df : order) {
    std::vector<Point_3> c;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(quads.halfedge(df.second), quads)) c.push_back(view(quads.point(v)));
    const K::Vector_3 n = CGAL::cross_product(c[2] - c[0], c[3] - c[1]);
    const double len = std::sqrt(n.squared_length());
    if(len == 0 || n.z() <= 0) continue;              // facing away (the viewer looks along -z)
    const double shade = (110 + 130 * n.z() / len) / 240;
    static const int palette[6][3] = {{150, 190, 240}, {245, 180, 110}, {150, 215, 150}, {215, 160, 215}, {235, 215, 120}, {140, 210, 210}};
    const int* base = palette[get(patch, df.second).patch % 6];
    svg << "<polygon points=\"";
    for(const Point_3& p : c) svg << fmt(screen(p).x()) << "," << fmt(screen(p).y()) << " ";
    svg << "\" fill=\"rgb(" << int(base[0] * shade) << "," << int(base[1] * shade) << "," << int(base[2] * shade)
        << ")\" stroke=\"#223\" stroke-width=\"0.6\"/>\n";
    halfedge_descriptor h = quads.halfedge(df.second);             // its sides on separatrices (other patch across)
    for(int k = 0; k < 4; ++k, h = quads.next(h)) {
      const halfedge_descriptor o = quads.opposite(h);
      if(quads.is_border(o) || get(patch, quads.face(o)).patch == get(patch, df.second).patch) continue;
      const Point_2 a = screen(view(quads.point(quads.source(h)))), b = screen(view(quads.point(quads.target(h))));
      svg << "<line x1=\"" << fmt(a.x()) << "\" y1=\"" << fmt(a.y()) << "\" x2=\"" << fmt(b.x()) << "\" y2=\"" << fmt(b.y())
          << "\" stroke=\"#112\" stroke-width=\"2\"/>\n";
    }
  }
  for(Mesh::Vertex_index v : quads.vertices())
    if(quads.degree(v) != 4) {
      const Point_2 p = screen(view(quads.point(v)));
      svg << "<circle cx=\"" << fmt(p.x()) << "\" cy=\"" << fmt(p.y()) << "\" r=\"3.5\" fill=\"#d62728\"/>\n";
    }
  const std::string caption[4] = {
    "CGAL's bear (" + std::to_string(mesh.number_of_faces()) + " triangles), Orbifold Tutte Parallelogram map: 4 cones of 180 degrees "
    "(circles), red: the cut edges, grey: the isolines",
    "u, v = k / " + std::to_string(int(S)) + ". Middle: snapped to an exact integer-grid map; blue: its integer points, the quad vertices.",
    "Right: its " + std::to_string(q.quads) + " quads (= the exact UV area), " + std::to_string(q.quad_vertices) +
    " vertices, closed, manifold, Euler characteristic " + std::to_string(q.euler_characteristic) + "; red: the cones, valence 2;",
    "colours: its " + std::to_string(patches.patches.size()) + " rectangle patches (quad_mesh_patches()), dark: the separatrices between them."};
  for(int l = 0; l < 4; ++l)
    svg << "<text x=\"" << margin << "\" y=\"" << top + P + 25 + 17 * l << "\">" << caption[l] << "</text>\n";
  svg << "</svg>\n";
  if(SS::IO::internal::write_text_atomically(argv[2], svg.str(), msg) != SS::SUCCESS) return fail(msg);
  std::printf("snap: %s; quad mesh: %s; wrote %s\n", SS::status_name(r.status), q.message.c_str(), argv[2]);
  return EXIT_SUCCESS;
}
