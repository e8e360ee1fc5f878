// seamless_trace: the isoline-tracing study of Sec. 6.2 (Mandad & Campen 2019) on one file.
//
//   seamless_trace IN.obj [--weld | --no-weld] [--json FILE] [--svg FILE] [--layout-obj FILE] [--layout-ply FILE]
//
// Reads a triangle mesh with a per-corner UV map (OBJ, f v/vt), traces the separatrices of its
// motorcycle graph exactly (rational arithmetic) and prints how each ended: counts per reason,
// and the failures (traces that ended in an inconsistency of the map: Fig. 3). On an exactly
// seamless, locally injective map there are none. Then it cuts the faces along the separatrices
// into the patch layout and prints the patches, how many are quads (disks with 4 right-angle corners
// whose UV image is a rectangle, checked exactly), nodes, arcs and the Euler characteristics; the
// refined mesh (arcs as edges, patch ids) is written with --layout-obj / --layout-ply. A map with
// flipped or degenerate UV triangles gets no layout (the reason is printed; JSON: null).
// Exit status: 0 when the map was read and traced (whatever the failures), 1 when it could not be
// read or traced or a file could not be written, 2 for a command-line error.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/IO/cut_mesh.h>
#include <CGAL/Seamless_snapping/IO/Patch_layout.h>
#include <CGAL/Seamless_snapping/IO/trace_svg.h>
#include <CGAL/Seamless_snapping/Motorcycle_graph.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/internal/io/command_line.h>
#include <CGAL/Seamless_snapping/internal/io/json_string.h>
#include <CGAL/Seamless_snapping/internal/io/retained_heap.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

typedef CGAL::Simple_cartesian<double>                     K;
typedef CGAL::Surface_mesh<K::Point_3>                     Mesh;
typedef Mesh::Property_map<Mesh::Halfedge_index, K::Point_2> UV_map;

namespace SS = CGAL::Seamless_snapping;
using SS::IO::internal::json_string;

// one line on stderr, exit status 1
static int fail(const std::string& why)
{
  std::cerr << "seamless_trace: " << why << std::endl;
  return EXIT_FAILURE;
}

int main(int argc, char** argv)
{
  CGAL::Seamless_snapping::IO::internal::use_retained_heap(argv);   // large maps: see the header
  const char* usage = "usage: seamless_trace IN.obj [--weld | --no-weld] [--json FILE] [--svg FILE] [--layout-obj FILE] [--layout-ply FILE]\n";
  const char* help =
    "\n"
    "Traces the motorcycle graph of the per-corner UV map of IN.obj exactly (rational arithmetic): the\n"
    "separatrices (the n axis rays of every cone of n quarter turns, the axis rays inside the fan of\n"
    "every border corner; four seeded traces +u, +v, -u, -v where there is neither), together at unit\n"
    "speed (time = parametric length, exact), each until it meets a cone, the border or the trail of a\n"
    "trace that passed there earlier (a T-junction); two that meet head-on both stop, and of two that\n"
    "cross at the same time the one heading a quarter turn counter-clockwise from the other goes on\n"
    "(on an integer-grid map: the patches of seamless_quad's quad mesh). Prints how each ended, counted per reason, and every failure: a trace that ended in an\n"
    "inconsistency of the map (a seam that does not match, a flipped or degenerate UV triangle; Fig. 3 of\n"
    "Mandad and Campen 2019). On an exactly seamless, locally injective map there are none: snap the map\n"
    "first (seamless_snap, --untangle for fold-overs). Then cuts the faces along the separatrices into\n"
    "the patch layout and prints the patches, how many are quads (disks with 4 right-angle corners whose\n"
    "UV image is a rectangle, checked exactly), the nodes, arcs and Euler characteristics. A map with\n"
    "flipped or degenerate UV triangles gets no layout (the reason is printed; JSON: null).\n"
    "\n"
    "Options:\n"
    "  --weld               merge vertices with bit-identical positions first (cut meshes, e.g.\n"
    "                       libigl/Directional output, whose seams are otherwise borders). Such an input\n"
    "                       is welded automatically (a line says so)\n"
    "  --no-weld            never weld\n"
    "  --json FILE          the counts as one JSON object (ends per reason, patches, times)\n"
    "  --svg FILE           the UV triangles (flipped ones red) and the separatrices in their charts\n"
    "                       (failed ones orange), the patches filled (SVG)\n"
    "  --layout-obj FILE    the refined mesh: the faces cut along the arcs, one OBJ group per patch, the\n"
    "                       arcs as 'l' lines, a 'vt' per corner\n"
    "  --layout-ply FILE    the same as PLY, with the properties patch_id (per face) and is_arc (per edge)\n"
    "  --help               print this help\n"
    "Every file is written atomically (temporary file + rename; a device, a named pipe or /dev/stdout\n"
    "directly, not truncated). IN.obj may be a pipe, read once (a cut mesh, read twice, is refused then).\n"
    "\n"
    "Exit status: 0 when the map was read and traced (whatever the failures: they are what the study\n"
    "counts), 1 when it could not be read or traced or a file could not be written, 2 for a command-line\n"
    "error.\n";
  std::string in, json, svg, layout_obj, layout_ply;
  bool weld = false, no_weld = false;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--weld") weld = true;
    else if(a == "--no-weld") no_weld = true;
    else if(a == "--json" || a == "--svg" || a == "--layout-obj" || a == "--layout-ply") {
      if(!SS::IO::internal::file_name_follows(argc, argv, i)) {
        std::cerr << "seamless_trace: " << a << " needs a file name\n" << usage; return 2;
      }
      (a == "--json" ? json : a == "--svg" ? svg : a == "--layout-obj" ? layout_obj : layout_ply) = argv[++i];
    }
    else if(a == "--help") { std::cout << usage << help; return 0; }
    else if(in.empty() && !a.empty() && a[0] != '-') in = a;
    else {
      std::cerr << "seamless_trace: " << (!a.empty() && a[0] == '-' ? "unknown option '" + a + "'"
                                                                     : in.empty() ? std::string("no input file")
                                                                     : "one input only ('" + a + "' after '" + in + "')")
                << "\n" << usage;
      return 2;
    }
  }
  if(in.empty() || (weld && no_weld)) {
    std::cerr << "seamless_trace: " << (in.empty() ? "no input file" : "--weld and --no-weld exclude each other") << "\n" << usage;
    return 2;
  }
  // (IN too: an output naming the input replaced the map)
  const std::string same = SS::IO::internal::same_output_file({{"IN", in}, {"--json", json}, {"--svg", svg},
                                                               {"--layout-obj", layout_obj}, {"--layout-ply", layout_ply}});
  if(!same.empty()) { std::cerr << "seamless_trace: " << same << "\n" << usage; return 2; }

  // a cut mesh (vertices duplicated along the seams, as libigl/Directional write them) is welded unless --no-weld
  Mesh mesh;
  UV_map uv;
  std::string message;
  const auto read = SS::IO::internal::read_again_checked(in, [&](bool w, std::string& m) {
    mesh = Mesh();
    uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
    return SS::IO::read_OBJ_with_corner_uvs(in, mesh, uv, m, SS::parameters::weld_vertices(w)) == SS::SUCCESS;
  });
  const SS::IO::Welding_read wr = SS::IO::read_welding_cut_meshes(mesh, weld, no_weld, message, read);
  if(!wr.note(weld).empty()) std::cout << wr.note(weld) << "\n";
  if(!wr.ok) return fail(message);
  const auto t0 = std::chrono::steady_clock::now();
  SS::Isoline_tracer<Mesh, UV_map> tracer(mesh, uv);
  if(tracer.status() != SS::SUCCESS)
    return fail(std::string(SS::status_name(tracer.status())) + ": " + tracer.message());
  const SS::Motorcycle_graph<Mesh> g = SS::build_motorcycle_graph(tracer);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const bool exact = SS::is_exactly_seamless(mesh, uv);

  std::printf("%s: %zu faces, %s\n", in.c_str(), std::size_t(num_faces(mesh)),
              exact ? "exactly seamless" : "NOT exactly seamless");
  std::printf("cones %zu, border corners %zu%s\n", g.cones, g.border_corners,
              g.seeded ? " (none: four seeded traces, +u, +v, -u, -v)" : "");
  std::printf("separatrices %zu, failed %zu, traced in %.0f ms (separatrices %.0f, subdivision %.0f, refined mesh %.0f, "
              "patches %.0f)\n", g.separatrices.size(), g.failed, ms, g.trace_ms, g.layout.subdivision_ms, g.layout.mesh_ms,
              g.layout.measure_ms);
  for(int e = 0; e < SS::number_of_trace_ends; ++e)
    if(g.ends[e]) std::printf("  %-32s %zu\n", SS::trace_end_name(SS::Trace_end(e)), g.ends[e]);
  std::size_t inexact = 0;                      // cut crossings where the transition missed the point on the edge
  for(const auto& s : g.separatrices) inexact += s.inexact_transfers;
  if(inexact > 0)
    std::printf("  inexact cut crossings            %zu (the transition R^k u + t of a cut edge did not give the point on "
                "the other side: the seams are not exact; seamless_snap makes them so)\n", inexact);
  for(std::size_t i = 0; i < g.separatrices.size(); ++i)
    if(SS::is_failure(g.separatrices[i].end))
      std::printf("  failure: separatrix %zu: %s: %s\n", i, SS::trace_end_name(g.separatrices[i].end),
                  g.separatrices[i].message.c_str());
  const SS::Patch_layout& L = g.layout;
  if(L.status == SS::SUCCESS) {
    std::printf("patches %zu, quad patches %zu%s; nodes %zu, arcs %zu, Euler characteristic %d (surface %d)%s\n",
                L.patches.size(), L.quad_patches, L.is_valid() ? " (a valid quad layout)" : "", L.nodes, L.arcs,
                L.euler_characteristic, L.surface_euler_characteristic,
                L.unplaced_segments ? (", " + std::to_string(L.unplaced_segments) + " segments not placed").c_str() : "");
    if(!L.is_valid()) std::printf("  %s\n", L.message.c_str());   // why not
  }
  else std::printf("patches: none (%s)\n", L.message.c_str());

  if(!json.empty()) {
    std::ostringstream os;
    os << "{\n  \"file\": " << json_string(in) << ",\n  \"exactly_seamless\": " << (exact ? "true" : "false")
       << ",\n  \"faces\": " << num_faces(mesh) << ",\n  \"cones\": " << g.cones
       << ",\n  \"border_corners\": " << g.border_corners << ",\n  \"seeded\": " << (g.seeded ? "true" : "false")
       << ",\n  \"separatrices\": " << g.separatrices.size() << ",\n  \"failed\": " << g.failed
       << ",\n  \"inexact_transfers\": " << inexact
       << ",\n  \"valid_layout\": " << (L.is_valid() ? "true" : "false")
       << ",\n  \"layout_message\": " << json_string(L.message);
    // the layout's numbers, null where no layout was built (they were 0, the surface's Euler characteristic too)
    auto count = [&](long n) { return L.status == SS::SUCCESS ? std::to_string(n) : std::string("null"); };
    os << ",\n  \"patches\": " << count(long(L.patches.size())) << ",\n  \"quad_patches\": " << count(long(L.quad_patches))
       << ",\n  \"nodes\": " << count(long(L.nodes)) << ",\n  \"arcs\": " << count(long(L.arcs))
       << ",\n  \"euler_characteristic\": " << count(L.euler_characteristic)
       << ",\n  \"surface_euler_characteristic\": " << count(L.surface_euler_characteristic) << ",\n  \"ends\": {";
    bool first = true;
    for(int e = 0; e < SS::number_of_trace_ends; ++e) {
      os << (first ? "" : ", ") << "\"" << SS::trace_end_name(SS::Trace_end(e)) << "\": " << g.ends[e];
      first = false;
    }
    os << "},\n  \"milliseconds\": " << ms << ",\n  \"trace_ms\": " << g.trace_ms << ",\n  \"subdivision_ms\": "
       << L.subdivision_ms << ",\n  \"mesh_ms\": " << L.mesh_ms << ",\n  \"measure_ms\": " << L.measure_ms << "\n}\n";
    if(SS::IO::internal::write_text_atomically(json, os.str(), message) != SS::SUCCESS) return fail(message);
  }
  // the SVG first: it shows what keeps a layout from being built (its flipped triangles in red)
  if(!svg.empty()) {
    std::ostringstream os;
    SS::IO::write_motorcycle_graph_svg(os, mesh, uv, g);
    if(SS::IO::internal::write_text_atomically(svg, os.str(), message) != SS::SUCCESS) return fail(message);
  }
  for(const std::string* file : {&layout_obj, &layout_ply}) {
    if(file->empty()) continue;
    const SS::Status s = file == &layout_obj ? SS::IO::write_patch_layout_OBJ(*file, L, message)
                                             : SS::IO::write_patch_layout_PLY(*file, L, message);
    if(s != SS::SUCCESS) return fail(message);
    std::printf("%s\n", message.c_str());
  }
  return EXIT_SUCCESS;
}
