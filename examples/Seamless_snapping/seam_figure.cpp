// seam_figure: draws the seam region of a UV map before and after snapping, as an SVG (the figure
// of the user manual; cf. Fig. 1 of Mandad & Campen 2019).
//
//   seam_figure IN.obj OUT.svg [--factor F]
//
// IN.obj is an approximately seamless per-corner UV map (e.g. bear_orbifold.obj written by
// orbifold_to_exact). The program snaps it, picks the cut edge whose transition is violated most in
// the input (evaluated exactly), and draws the faces around that edge from both sides of the cut:
// the faces of the other side are brought into the chart of the first by the edge's transition
// (rotation by k quarter turns, translation fixed at the edge midpoint). The remaining gap along the
// cut edge is magnified by F (default: a power of ten that makes it about a tenth of the edge
// length), which the caption states. After snapping the gap is exactly zero (checked in CGAL::Gmpq).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Gmpq.h>

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/internal/inputs/orbifold_tutte_input.h>   // fit_seam_transitions()
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>                     K;
typedef K::Point_2                                         Point_2;
typedef K::Point_3                                         Point_3;
typedef CGAL::Surface_mesh<Point_3>                        Mesh;
typedef Mesh::Halfedge_index                               halfedge_descriptor;
typedef Mesh::Face_index                                   face_descriptor;
typedef Mesh::Property_map<halfedge_descriptor, Point_2>   UV_map;

namespace SS = CGAL::Seamless_snapping;

static int fail(const std::string& why) { std::cerr << "seam_figure: " << why << std::endl; return EXIT_FAILURE; }

// R^k (x, y), R(x, y) = (-y, x): k quarter turns counter-clockwise
template <class T>
static std::array<T, 2> rotate(int k, const std::array<T, 2>& p)
{
  std::array<T, 2> r = p;
  for(int i = 0; i < ((k % 4) + 4) % 4; ++i) r = {-r[1], r[0]};
  return r;
}

// The transition violation of the cut edge h (o = opposite(h), a = source(h), b = target(h)),
// exactly: R^k (A_i - B_i) - (A_j - B_j), with A_i, B_i the UVs of a, b in face(h), A_j, B_j in face(o).
static std::array<CGAL::Gmpq, 2> violation(const Mesh& m, UV_map uv, halfedge_descriptor h, int k)
{
  const halfedge_descriptor o = m.opposite(h);
  const Point_2 Ai = uv[m.prev(h)], Bi = uv[h], Aj = uv[o], Bj = uv[m.prev(o)];
  typedef CGAL::Gmpq Q;
  const std::array<Q, 2> di = {Q(Ai.x()) - Q(Bi.x()), Q(Ai.y()) - Q(Bi.y())};
  const std::array<Q, 2> dj = {Q(Aj.x()) - Q(Bj.x()), Q(Aj.y()) - Q(Bj.y())};
  const std::array<Q, 2> r = rotate(k, di);
  return {r[0] - dj[0], r[1] - dj[1]};
}

// One side of the cut near edge (a, b): the faces having a corner at a with the UV `ua` or a corner at
// b with the UV `ub` (corners of one sector share their UV, so this is the fan of that sector).
static std::vector<face_descriptor> side_faces(const Mesh& m, UV_map uv, Mesh::Vertex_index a, Point_2 ua,
                                               Mesh::Vertex_index b, Point_2 ub)
{
  std::vector<face_descriptor> faces;
  for(Mesh::Vertex_index v : {a, b})
    for(halfedge_descriptor g : CGAL::halfedges_around_target(v, m))
      if(!m.is_border(g) && uv[g] == (v == a ? ua : ub)) faces.push_back(m.face(g));
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

struct Panel_geometry
{
  std::vector<std::array<Point_2, 3> > near_side, far_side;   // far side already in the near side's chart
  std::array<Point_2, 2> near_edge, far_edge;                 // the cut edge (a, b) on both sides
};

// The faces around the cut edge h from both sides, in the chart of face(h). The far side is mapped by
// the inverse transition u -> R^-k (u - t), with t chosen so that the edge midpoints coincide; the
// resulting gap along the edge, e_a = -e_b = -1/2 R^-k (violation), is then magnified by `factor`:
// a far-side point p moves by (factor - 1) * ((1 - s) e_a + s e_b), s = its position along the edge.
static Panel_geometry panel(const Mesh& m, UV_map uv, halfedge_descriptor h, int k, double factor)
{
  const halfedge_descriptor o = m.opposite(h);
  const Mesh::Vertex_index a = m.source(h), b = m.target(h);
  const Point_2 Ai = uv[m.prev(h)], Bi = uv[h], Aj = uv[o], Bj = uv[m.prev(o)];
  const std::array<CGAL::Gmpq, 2> viol = violation(m, uv, h, k);
  const std::array<double, 2> half = {CGAL::to_double(viol[0]) / 2, CGAL::to_double(viol[1]) / 2};
  const std::array<double, 2> ea = rotate(-k, std::array<double, 2>{-half[0], -half[1]});   // gap at a
  const std::array<double, 2> eb = {-ea[0], -ea[1]};                                          // gap at b
  // t = mid_j - R^k mid_i, applied inversely: q = R^-k (p - mid_j) + mid_i
  const std::array<double, 2> mid_i = {(Ai.x() + Bi.x()) / 2, (Ai.y() + Bi.y()) / 2};
  const std::array<double, 2> mid_j = {(Aj.x() + Bj.x()) / 2, (Aj.y() + Bj.y()) / 2};
  const double ex = Bi.x() - Ai.x(), ey = Bi.y() - Ai.y(), len2 = ex * ex + ey * ey;
  auto to_near_chart = [&](const Point_2& p) {
    const std::array<double, 2> q = rotate(-k, std::array<double, 2>{p.x() - mid_j[0], p.y() - mid_j[1]});
    const double x = q[0] + mid_i[0], y = q[1] + mid_i[1];
    double s = len2 > 0 ? ((x - Ai.x()) * ex + (y - Ai.y()) * ey) / len2 : 0.5;
    s = (std::min)(1.0, (std::max)(0.0, s));
    return Point_2(x + (factor - 1) * ((1 - s) * ea[0] + s * eb[0]), y + (factor - 1) * ((1 - s) * ea[1] + s * eb[1]));
  };
  Panel_geometry g;
  for(face_descriptor f : side_faces(m, uv, a, Ai, b, Bi)) {
    std::array<Point_2, 3> t; int i = 0;
    for(halfedge_descriptor c : CGAL::halfedges_around_face(m.halfedge(f), m)) t[std::size_t(i++)] = uv[c];
    g.near_side.push_back(t);
  }
  for(face_descriptor f : side_faces(m, uv, a, Aj, b, Bj)) {
    std::array<Point_2, 3> t; int i = 0;
    for(halfedge_descriptor c : CGAL::halfedges_around_face(m.halfedge(f), m)) t[std::size_t(i++)] = to_near_chart(uv[c]);
    g.far_side.push_back(t);
  }
  g.near_edge = {Ai, Bi};
  g.far_edge = {to_near_chart(Aj), to_near_chart(Bj)};
  return g;
}

static std::string fmt(const char* f, double x) { char buf[64]; std::snprintf(buf, sizeof buf, f, x); return buf; }

int main(int argc, char** argv)
{
  std::string in, out;
  double factor = 0;                                  // 0: automatic
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if(arg == "--factor" && i + 1 < argc) factor = std::atof(argv[++i]);
    else if(in.empty()) in = arg;
    else if(out.empty()) out = arg;
    else return fail("usage: seam_figure IN.obj OUT.svg [--factor F]");
  }
  if(out.empty()) return fail("usage: seam_figure IN.obj OUT.svg [--factor F]");

  // corner map: uv[h] = UV of target(h) as seen from face(h)
  Mesh mesh;
  UV_map input = mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0, 0)).first;
  std::string msg;
  if(SS::IO::read_OBJ_with_corner_uvs(in, mesh, input, msg) != SS::SUCCESS) return fail(msg);
  UV_map snapped = mesh.add_property_map<halfedge_descriptor, Point_2>("h:snapped", Point_2(0, 0)).first;
  for(halfedge_descriptor h : mesh.halfedges()) snapped[h] = input[h];

  const SS::Snap_report r = SS::snap_seamless_parameterization(mesh, snapped);
  if(r.status != SS::SUCCESS) return fail(std::string("snap: ") + SS::status_name(r.status) + ": " + r.message);
  if(!SS::is_exactly_seamless(mesh, snapped)) return fail("the snapped map is not exactly seamless");

  // the cut edge whose transition is violated most (exact squared norm)
  const auto fit = SS::internal::fit_seam_transitions(mesh, input);
  if(fit.cut_halfedges.empty()) return fail("the input has no cut edge");
  std::size_t worst = 0;
  CGAL::Gmpq worst_norm2(-1);
  for(std::size_t i = 0; i < fit.cut_halfedges.size(); ++i) {
    const auto v = violation(mesh, input, fit.cut_halfedges[i], fit.k[i]);
    const CGAL::Gmpq n2 = v[0] * v[0] + v[1] * v[1];
    if(n2 > worst_norm2) { worst_norm2 = n2; worst = i; }
  }
  const halfedge_descriptor h = fit.cut_halfedges[worst];
  const int k = fit.k[worst];
  const double gap = std::sqrt(CGAL::to_double(worst_norm2));
  const auto after = violation(mesh, snapped, h, k);
  if(after[0] != 0 || after[1] != 0) return fail("the transition of the chosen edge does not hold exactly after snapping");

  const Point_2 A = input[mesh.prev(h)], B = input[h];
  const double edge_length = std::sqrt(CGAL::squared_distance(A, B));
  if(factor <= 0 && gap == 0) factor = 1;            // already exactly seamless: nothing to magnify
  if(factor <= 0) {                                  // the largest 1, 2, 5 x 10^n with a magnified gap <= 0.3 edge
    const double target = 0.3 * edge_length / gap;
    const double p = std::pow(10.0, std::floor(std::log10(target)));
    factor = target >= 5 * p ? 5 * p : target >= 2 * p ? 2 * p : p;
  }
  // "2 x 10^10" (or the number itself when it is small)
  std::string factor_text;
  {
    const int e = int(std::floor(std::log10(factor) + 1e-9));
    const double m = factor / std::pow(10.0, e);
    factor_text = e < 3 ? fmt("%g", factor) : (std::abs(m - 1) < 1e-9 ? "" : fmt("%g", m) + " x ") + "10^" + std::to_string(e);
  }

  const Panel_geometry before_panel = panel(mesh, input, h, k, factor);
  const Panel_geometry after_panel = panel(mesh, snapped, h, k, factor);

  // --- SVG: two panels with one common view box (that of both sides before snapping)
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for(const auto& t : before_panel.near_side)
    for(const Point_2& p : t) { lo[0] = std::min(lo[0], p.x()); lo[1] = std::min(lo[1], p.y());
                                hi[0] = std::max(hi[0], p.x()); hi[1] = std::max(hi[1], p.y()); }
  for(const auto& t : before_panel.far_side)
    for(const Point_2& p : t) { lo[0] = std::min(lo[0], p.x()); lo[1] = std::min(lo[1], p.y());
                                hi[0] = std::max(hi[0], p.x()); hi[1] = std::max(hi[1], p.y()); }
  const double W = 420, H = 380, margin = 20, top = 40;
  const double scale = std::min((W - 2 * margin) / (hi[0] - lo[0]), (H - 2 * margin) / (hi[1] - lo[1]));
  const double pad_x = (W - 2 * margin - (hi[0] - lo[0]) * scale) / 2, pad_y = (H - 2 * margin - (hi[1] - lo[1]) * scale) / 2;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 2 * W + 3 * margin << "\" height=\"" << top + H + 90
      << "\" font-family=\"sans-serif\" font-size=\"13\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  auto draw_panel = [&](const Panel_geometry& g, double x0, const char* colour, const char* title) {
    auto X = [&](const Point_2& p) { return x0 + margin + pad_x + (p.x() - lo[0]) * scale; };
    auto Y = [&](const Point_2& p) { return top + H - margin - pad_y - (p.y() - lo[1]) * scale; };   // y up
    auto poly = [&](const std::array<Point_2, 3>& t, const char* fill, const char* stroke, double opacity) {
      svg << "<polygon points=\"";
      for(const Point_2& p : t) svg << fmt("%.2f", X(p)) << "," << fmt("%.2f", Y(p)) << " ";
      svg << "\" fill=\"" << fill << "\" fill-opacity=\"" << opacity << "\" stroke=\"" << stroke << "\" stroke-width=\"0.8\"/>\n";
    };
    svg << "<text x=\"" << x0 + margin << "\" y=\"" << top - 12 << "\" font-weight=\"bold\">" << title << "</text>\n";
    svg << "<rect x=\"" << x0 << "\" y=\"" << top << "\" width=\"" << W << "\" height=\"" << H
        << "\" fill=\"none\" stroke=\"#999\"/>\n";
    for(const auto& t : g.near_side) poly(t, "#d0d0d0", "#404040", 1.0);
    for(const auto& t : g.far_side) poly(t, colour, colour, 0.25);
    auto line = [&](const std::array<Point_2, 2>& e, const char* stroke, double width) {
      svg << "<line x1=\"" << fmt("%.2f", X(e[0])) << "\" y1=\"" << fmt("%.2f", Y(e[0])) << "\" x2=\"" << fmt("%.2f", X(e[1]))
          << "\" y2=\"" << fmt("%.2f", Y(e[1])) << "\" stroke=\"" << stroke << "\" stroke-width=\"" << width << "\"/>\n";
    };
    line(g.near_edge, "#000000", 2.5);
    line(g.far_edge, colour, 2.5);
  };
  draw_panel(before_panel, margin, "#d62728", "before snapping (input)");
  draw_panel(after_panel, W + 2 * margin, "#2ca02c", "after snapping (exactly seamless)");
  std::string factor_svg = factor_text;
  const std::size_t x_pos = factor_svg.find(" x ");
  if(x_pos != std::string::npos) factor_svg.replace(x_pos, 3, " &#215; ");
  const char* caption[] = {
    "Grey: the faces on one side of the cut edge (black) with the largest transition violation; coloured: the faces",
    "on the other side, brought into the same chart by the transition of the edge (rotation by k quarter turns,",
    "translation fixed at the edge midpoint). Violation: ",
    "After snapping the two sides meet exactly (checked in rational arithmetic), at any magnification."};
  const std::string third = std::string(caption[2]) + fmt("%.2g", gap / fit.uv_diagonal) + " of the UV bounding-box diagonal, k = " +
                            std::to_string(k) + "; the gap is magnified " + factor_svg + " times.";
  const std::string lines[] = {caption[0], caption[1], third, caption[3]};
  for(int l = 0; l < 4; ++l)
    svg << "<text x=\"" << margin << "\" y=\"" << top + H + 22 + 17 * l << "\">" << lines[l] << "</text>\n";
  svg << "</svg>\n";

  // through a temporary file next to it, as the package's writers do (it had its own copy of that)
  if(SS::IO::internal::write_text_atomically(out, svg.str(), msg) != SS::SUCCESS) return fail(msg);

  std::printf("%zu cut edges; the worst transition violation is %.3g (relative to the UV diagonal), k = %d, "
              "edge length %.3g; after snapping it is exactly 0\n", fit.cut_halfedges.size(), gap / fit.uv_diagonal, k,
              edge_length / fit.uv_diagonal);
  std::printf("%zu + %zu faces drawn, gap magnified %s times; wrote %s\n", before_panel.near_side.size(),
              before_panel.far_side.size(), factor_text.c_str(), out.c_str());
  return EXIT_SUCCESS;
}
