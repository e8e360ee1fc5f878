// seamless_trace: the isoline-tracing study of Sec. 6.2 (Mandad & Campen 2019) on one file.
//
//   seamless_trace IN.obj [--weld] [--json FILE] [--svg FILE]
//
// Reads a triangle mesh with a per-corner UV map (OBJ, f v/vt), traces the separatrices of its
// motorcycle graph exactly (rational arithmetic) and prints how each ended: counts per reason,
// and the failures (traces that ended in an inconsistency of the map: Fig. 3). On an exactly
// seamless, locally injective map there are none. Exit status: 0 when the map was read and traced
// (whatever the failures), 1 when it could not be read or traced, 2 for a command-line error.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/IO/trace_svg.h>
#include <CGAL/Seamless_snapping/Motorcycle_graph.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double>                     K;
typedef CGAL::Surface_mesh<K::Point_3>                     Mesh;
typedef Mesh::Property_map<Mesh::Halfedge_index, K::Point_2> UV_map;

namespace SS = CGAL::Seamless_snapping;

static std::string json_string(const std::string& s)
{
  std::string out = "\"";
  for(char c : s) {
    if(c == '"' || c == '\\') out += '\\';
    if(static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

int main(int argc, char** argv)
{
  std::string in, json, svg;
  bool weld = false;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--weld") weld = true;
    else if(a == "--json" && i + 1 < argc) json = argv[++i];
    else if(a == "--svg" && i + 1 < argc) svg = argv[++i];
    else if(a == "--help") { std::cout << "usage: seamless_trace IN.obj [--weld] [--json FILE] [--svg FILE]\n"; return 0; }
    else if(in.empty() && a[0] != '-') in = a;
    else { std::cerr << "usage: seamless_trace IN.obj [--weld] [--json FILE] [--svg FILE]\n"; return 2; }
  }
  if(in.empty()) { std::cerr << "usage: seamless_trace IN.obj [--weld] [--json FILE] [--svg FILE]\n"; return 2; }

  Mesh mesh;
  UV_map uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
  std::string message;
  if(SS::IO::read_OBJ_with_corner_uvs(in, mesh, uv, message, SS::parameters::weld_vertices(weld)) != SS::SUCCESS) {
    std::cerr << "seamless_trace: " << message << std::endl;
    return EXIT_FAILURE;
  }
  const auto t0 = std::chrono::steady_clock::now();
  SS::Isoline_tracer<Mesh, UV_map> tracer(mesh, uv);
  if(tracer.status() != SS::SUCCESS) {
    std::cerr << "seamless_trace: " << SS::status_name(tracer.status()) << ": " << tracer.message() << std::endl;
    return EXIT_FAILURE;
  }
  const SS::Motorcycle_graph<Mesh> g = SS::build_motorcycle_graph(tracer);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const bool exact = SS::is_exactly_seamless(mesh, uv);

  std::printf("%s: %zu faces, %s\n", in.c_str(), std::size_t(num_faces(mesh)),
              exact ? "exactly seamless" : "NOT exactly seamless");
  std::printf("cones %zu, border corners %zu%s\n", g.cones, g.border_corners,
              g.seeded ? " (none: four seeded traces, +u, +v, -u, -v)" : "");
  std::printf("separatrices %zu, failed %zu, traced in %.0f ms\n", g.separatrices.size(), g.failed, ms);
  for(int e = 0; e < SS::number_of_trace_ends; ++e)
    if(g.ends[e]) std::printf("  %-32s %zu\n", SS::trace_end_name(SS::Trace_end(e)), g.ends[e]);
  for(std::size_t i = 0; i < g.separatrices.size(); ++i)
    if(SS::is_failure(g.separatrices[i].end))
      std::printf("  failure: separatrix %zu: %s: %s\n", i, SS::trace_end_name(g.separatrices[i].end),
                  g.separatrices[i].message.c_str());
  std::printf("patches: not computed yet (the patch decomposition is not implemented)\n");

  if(!json.empty()) {
    std::ofstream os(json);
    os << "{\n  \"file\": " << json_string(in) << ",\n  \"exactly_seamless\": " << (exact ? "true" : "false")
       << ",\n  \"faces\": " << num_faces(mesh) << ",\n  \"cones\": " << g.cones
       << ",\n  \"border_corners\": " << g.border_corners << ",\n  \"seeded\": " << (g.seeded ? "true" : "false")
       << ",\n  \"separatrices\": " << g.separatrices.size() << ",\n  \"failed\": " << g.failed
       << ",\n  \"patches\": null,\n  \"quad_patches\": null,\n  \"ends\": {";
    bool first = true;
    for(int e = 0; e < SS::number_of_trace_ends; ++e) {
      os << (first ? "" : ", ") << "\"" << SS::trace_end_name(SS::Trace_end(e)) << "\": " << g.ends[e];
      first = false;
    }
    os << "},\n  \"milliseconds\": " << ms << "\n}\n";
    if(!os) { std::cerr << "seamless_trace: cannot write " << json << std::endl; return EXIT_FAILURE; }
  }
  if(!svg.empty()) {
    std::ofstream os(svg);
    SS::IO::write_motorcycle_graph_svg(os, mesh, uv, g);
    if(!os) { std::cerr << "seamless_trace: cannot write " << svg << std::endl; return EXIT_FAILURE; }
  }
  return EXIT_SUCCESS;
}
