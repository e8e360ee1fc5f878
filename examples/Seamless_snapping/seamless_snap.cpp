// seamless_snap: the command-line program of the package.
//
//   seamless_snap IN.obj OUT.obj [--weld] [--no-align-boundary] [--unreduced] [--report FILE.json] [--quiet]
//
// Reads a triangle mesh with an approximately seamless per-corner UV map (OBJ, f v/vt), snaps the
// UVs to nearby doubles that are exactly seamless (Mandad & Campen 2019), checks the result in
// rational arithmetic and writes OUT atomically. Exit status 0 only when OUT was written and verified.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <unordered_map>

typedef CGAL::Simple_cartesian<double>                     K;
typedef K::Point_2                                         Point_2;
typedef K::Point_3                                         Point_3;
typedef CGAL::Surface_mesh<Point_3>                        Mesh;
typedef Mesh::Halfedge_index                               halfedge_descriptor;
typedef Mesh::Property_map<halfedge_descriptor, Point_2>   UV_map;

namespace SS = CGAL::Seamless_snapping;
namespace params = CGAL::Seamless_snapping::parameters;

static const char* usage_text =
  "usage: seamless_snap IN.obj OUT.obj [--weld] [--no-align-boundary] [--unreduced]\n"
  "                     [--report FILE.json] [--quiet]\n";

static const char* help_text =
  "Makes an approximately seamless UV map exactly seamless (Mandad & Campen 2019, \"Exact\n"
  "Constraint Satisfaction for Truly Seamless Parametrization\").\n"
  "\n"
  "IN.obj is a triangle mesh with per-corner texture coordinates (every face 'f v/vt' or\n"
  "'f v/vt/vn'). Across every seam the UVs of the two sides must be related, up to solver\n"
  "error, by a rotation by a multiple of 90 degrees plus a translation. The snapped UVs are\n"
  "doubles for which every seam transition holds exactly, in real arithmetic; the result is\n"
  "checked in rational arithmetic before OUT.obj is written.\n"
  "\n"
  "Options:\n"
  "  --weld               merge vertices with bit-identical positions before snapping. Needed for\n"
  "                       'cut meshes' (e.g. libigl/Directional output), whose vertices are\n"
  "                       duplicated along the seams: without it the seams are mesh borders and\n"
  "                       nothing gets snapped. A hint is printed when the input looks like one.\n"
  "  --no-align-boundary  do not make axis-parallel border edges exactly axis-parallel\n"
  "                       (by default, border edges within 1e-3 degrees of the u or v axis are aligned)\n"
  "  --unreduced          project the full sector system instead of the reduced node system\n"
  "                       (Sec. 5.3); much slower, for comparisons\n"
  "  --report FILE.json   write the snap report as JSON to FILE.json (also when snapping fails)\n"
  "  --quiet              print nothing but errors\n"
  "  --help               print this help\n"
  "\n"
  "Output: OUT.obj has one 'v' per vertex (after welding, if asked), one 'vt' per vertex and\n"
  "distinct UV, and 'f v/vt' faces; numbers have 17 significant digits, so the doubles are\n"
  "exact. OUT.obj is written atomically (temporary file + rename): it is never left half written.\n"
  "Normals, groups and materials of IN.obj are not carried over.\n"
  "\n"
  "Exit status: 0 when OUT.obj was written and verified exactly seamless; 1 when reading,\n"
  "snapping, verifying or writing failed (one line on stderr says why; OUT.obj is then not\n"
  "created or changed); 2 for a command-line error.\n";

static std::string one_line(std::string s)
{
  for(char& c : s) if(c == '\n' || c == '\r') c = ' ';
  return s;
}

static int fail(const std::string& why)
{
  std::cerr << "seamless_snap: " << one_line(why) << std::endl;
  return EXIT_FAILURE;
}

// Border edges whose two endpoints both have a bit-identical copy elsewhere in the mesh: many of
// them mean a cut mesh read without --weld.
static std::size_t border_edges_with_duplicated_ends(const Mesh& m, std::size_t& border_edges)
{
  std::unordered_map<std::string, std::size_t> count;
  auto key = [&](Mesh::Vertex_index v) {
    const Point_3& p = m.point(v);
    double xyz[3] = {p.x(), p.y(), p.z()};
    return std::string(reinterpret_cast<const char*>(xyz), sizeof xyz);
  };
  for(Mesh::Vertex_index v : m.vertices()) ++count[key(v)];
  std::size_t n = 0;
  border_edges = 0;
  for(Mesh::Edge_index e : m.edges()) {
    if(!m.is_border(e)) continue;
    ++border_edges;
    const halfedge_descriptor h = m.halfedge(e);
    if(count[key(m.source(h))] > 1 && count[key(m.target(h))] > 1) ++n;
  }
  return n;
}

int main(int argc, char** argv)
{
  std::string in, out, report_file;
  bool weld = false, align_boundary = true, reduced = true, quiet = false, has_report = false;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--help" || a == "-h") { std::cout << usage_text << "\n" << help_text; return EXIT_SUCCESS; }
    else if(a == "--weld") weld = true;
    else if(a == "--no-align-boundary") align_boundary = false;
    else if(a == "--unreduced") reduced = false;
    else if(a == "--quiet") quiet = true;
    else if(a == "--report") {
      if(i + 1 >= argc) { std::cerr << "seamless_snap: --report needs a file name\n" << usage_text; return 2; }
      report_file = argv[++i]; has_report = true;
    }
    else if(a.size() > 1 && a[0] == '-') { std::cerr << "seamless_snap: unknown option '" << a << "'\n" << usage_text; return 2; }
    else if(in.empty()) in = a;
    else if(out.empty()) out = a;
    else { std::cerr << "seamless_snap: unexpected argument '" << a << "'\n" << usage_text; return 2; }
  }
  if(in.empty() || out.empty()) { std::cerr << usage_text << "(--help for details)\n"; return 2; }

  // 1. read; the corner map: uv[h] = UV of target(h) in face(h)
  Mesh mesh;
  UV_map uv = mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0, 0)).first;
  std::string message;
  if(SS::IO::read_OBJ_with_corner_uvs(in, mesh, uv, message, params::weld_vertices(weld)) != SS::SUCCESS)
    return fail("cannot read input: " + message);
  if(!quiet) std::cout << message << "\n";
  if(!weld) {
    std::size_t border = 0;
    const std::size_t dup = border_edges_with_duplicated_ends(mesh, border);
    if(dup >= 3 && 2 * dup >= border)
      std::cerr << "seamless_snap: hint: " << dup << " of " << border << " border edges join vertices that have "
                << "bit-identical copies: this looks like a cut mesh (vertices duplicated along the seams); "
                << "its seams are treated as borders and left alone. Use --weld to snap them.\n";
  }

  // 2. snap (writes uv only on success)
  const SS::Snap_report report = SS::snap_seamless_parameterization(
      mesh, uv, params::use_reduced_system(reduced, params::align_boundary(align_boundary)));
  if(!quiet) {
    std::printf("snap: %s (%.1f ms)%s%s\n", SS::status_name(report.status), report.total_ms,
                report.message.empty() ? "" : ": ", one_line(report.message).c_str());
    std::printf("  %zu faces, %zu cut edges, %zu cones, %zu sectors (%zu constrained), %zu align edges\n",
                report.faces, report.cut_edges, report.cones, report.sectors, report.constrained_sectors, report.align_edges);
    std::printf("  %s system: %zu rows x %zu columns, %zu free, %zu implied, max |IRREF entry| %s\n",
                report.reduced ? "node" : "full", report.system_rows, report.system_columns,
                report.free_variables, report.implied_variables, report.max_abs_coefficient.c_str());
    std::printf("  relative to the UV diagonal %.6g: input violation %.3g, max change %.3g, mean change %.3g\n",
                report.uv_diagonal, report.max_input_violation, report.max_change, report.mean_change);
    std::printf("  UV fold-overs: %zu before, %zu after\n", report.flips_before, report.flips_after);
  }
  if(has_report) {
    const std::string tmp = report_file + ".tmp";
    bool ok = false;
    {
      std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
      if(os) { os << report.to_json(); os.flush(); ok = bool(os); }
    }
    if(!ok || std::rename(tmp.c_str(), report_file.c_str()) != 0) {
      std::remove(tmp.c_str());
      return fail("cannot write the report '" + report_file + "'");
    }
    if(!quiet) std::cout << "report written to " << report_file << "\n";
  }
  if(report.status != SS::SUCCESS)
    return fail(std::string("snapping failed: ") + SS::status_name(report.status) + ": " + report.message);

  // 3. verify independently, in rational arithmetic
  if(!SS::is_exactly_seamless(mesh, uv))
    return fail("verification failed: the snapped map is not exactly seamless (internal error; please report)");
  if(!quiet) std::cout << "verified: every seam transition holds exactly\n";

  // 4. write atomically
  if(SS::IO::write_OBJ_with_corner_uvs(out, mesh, uv, message) != SS::SUCCESS)
    return fail(message);
  if(!quiet) std::cout << message << "\n";
  return EXIT_SUCCESS;
}
