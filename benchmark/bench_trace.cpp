// The isoline-tracing study of Sec. 6.2 (Fig. 3/4 of Mandad & Campen 2019), per model: the motorcycle
// graph's separatrices traced exactly on the input (inexact) map and on its snapped (exact) output,
// with the number that ended at a cone and at a T-junction, the cut crossings where the exit point X did
// not map onto the edge by R^k X + t (the transition is inexact there), the number of failures of each kind
// (Trace_end), the patch layout (patches, quad patches: disks with 4 right-angle corners whose UV image is
// an axis-aligned rectangle, checked exactly; "-" when the map has flipped or degenerate triangles), whether
// the layout is valid (every separatrix ended at a cone, the border or an earlier trace, and every patch is
// a quad) and the time (graph and layout).
//
// usage: bench_trace [--svg DIR] [--max-faces N] <file.obj | directory>...   (directories searched recursively for *.obj;
//        files under a "directional" folder are welded, as Directional writes cut meshes). Without
//        arguments the directory in the environment variable SS_SHARED_DATA_DIR is used.
// --svg DIR: also draws the layout of the input and of the output of each model (UV charts) into DIR.
// Times are wall clock in ms (one run; tracer construction included). Not part of the test run.
// Scale (issue 26): a trace may cross many faces on a large map (a spiralling isoline of the README's bear crosses
// 553060 faces), so on maps with more than 100000 faces each trace is bounded to 20000 faces unless --max-faces
// says otherwise (0: the library's default, 20 times the number of faces plus 100); the table names the bound.
//        [--max-faces N]: the step limit per trace (build_motorcycle_graph()); traces cut there end as length-limit

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/IO/trace_svg.h>
#include <CGAL/Seamless_snapping/Motorcycle_graph.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <CGAL/Seamless_snapping/internal/io/retained_heap.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef Mesh::Property_map<Mesh::Halfedge_index, K::Point_2> UV_map;
namespace SS = CGAL::Seamless_snapping;
namespace fs = std::filesystem;

// failure kinds, in table order
static const SS::Trace_end kinds[] = {SS::Trace_end::OSCILLATION_AT_CUT, SS::Trace_end::MISSED_AT_CUT,
                                      SS::Trace_end::NO_CONTINUATION_AT_VERTEX, SS::Trace_end::SEVERAL_CONTINUATIONS_AT_VERTEX,
                                      SS::Trace_end::FELL_OFF_BORDER, SS::Trace_end::FOLDED_FACE,
                                      SS::Trace_end::DEGENERATE_VERTEX, SS::Trace_end::LENGTH_LIMIT};

static void row(const std::string& name, const char* which, const Mesh& m, UV_map uv, const std::string& svg,
                std::size_t max_faces)
{
  const auto t0 = std::chrono::steady_clock::now();
  SS::Isoline_tracer<Mesh, UV_map> tracer(m, uv);
  if(tracer.status() != SS::SUCCESS) {
    std::printf("| %s | %s | cannot trace: %s |\n", name.c_str(), which, SS::status_name(tracer.status()));
    return;
  }
  const SS::Motorcycle_graph<Mesh> g = SS::build_motorcycle_graph(tracer, max_faces);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::size_t regular = g.ends[int(SS::Trace_end::CONE)] + g.ends[int(SS::Trace_end::BORDER)] +
                        g.ends[int(SS::Trace_end::EARLIER_TRACE)];
  if(g.seeded) regular += g.ends[int(SS::Trace_end::CLOSED_LOOP)];
  std::size_t inexact = 0;
  for(const auto& t : g.separatrices) inexact += t.inexact_transfers;
  std::printf("| %s | %s | %zu | %zu | %zu | %zu | %zu |", name.c_str(), which, g.separatrices.size(),
              g.ends[int(SS::Trace_end::CONE)], g.ends[int(SS::Trace_end::EARLIER_TRACE)], inexact, g.failed);
  for(SS::Trace_end e : kinds) std::printf(" %zu |", g.ends[int(e)]);
  const SS::Patch_layout& L = g.layout;
  if(L.status == SS::SUCCESS) std::printf(" %zu | %zu |", L.patches.size(), L.quad_patches);
  else std::printf(" - | - |");
  std::printf(" %s | %.0f |\n", regular == g.separatrices.size() && L.is_valid() ? "yes" : "no", ms);
  std::fflush(stdout);
  if(!svg.empty()) { std::ofstream os(svg); SS::IO::write_motorcycle_graph_svg(os, m, uv, g); }
}

int main(int argc, char** argv)
{
  CGAL::Seamless_snapping::IO::internal::use_retained_heap(argv);   // large maps: see the header
  std::vector<fs::path> inputs, files;
  std::string svg_dir;
  long long max_faces_option = -1;   // -1: bounded on large maps only
  for(int i = 1; i < argc; ++i) {
    if(std::strcmp(argv[i], "--svg") == 0 && i + 1 < argc) { svg_dir = argv[++i]; continue; }
    if(std::strcmp(argv[i], "--max-faces") == 0 && i + 1 < argc) { max_faces_option = std::atoll(argv[++i]); continue; }
    inputs.emplace_back(argv[i]);
  }
  if(inputs.empty()) {
    const char* env = std::getenv("SS_SHARED_DATA_DIR");
    if(!env) { std::fprintf(stderr, "usage: %s [--svg DIR] [--max-faces N] <file.obj | directory>...  (or set SS_SHARED_DATA_DIR)\n", argv[0]); return 2; }
    inputs.emplace_back(env);
  }
  for(const fs::path& p : inputs) {
    if(fs::is_directory(p)) {
      for(const auto& e : fs::recursive_directory_iterator(p))
        if(e.is_regular_file() && e.path().extension() == ".obj") files.push_back(e.path());
    } else files.push_back(p);
  }
  std::sort(files.begin(), files.end());
  std::printf("| model | map | separatrices | to cone | T-junction | inexact cut crossings | failed |");
  for(SS::Trace_end e : kinds) std::printf(" %s |", SS::trace_end_name(e));
  std::printf(" patches | quad patches | valid layout | ms |\n|---|---|---|---|---|---|---|");
  for(std::size_t i = 0; i < sizeof(kinds) / sizeof(kinds[0]); ++i) std::printf("---|");
  std::printf("---|---|---|---|\n");
  for(const fs::path& p : files) {
    Mesh m;
    UV_map uv = m.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
    const bool weld = p.string().find("directional") != std::string::npos;
    std::string msg;
    const std::string name = p.stem().string();
    if(SS::IO::read_OBJ_with_corner_uvs(p.string(), m, uv, msg, SS::parameters::weld_vertices(weld)) != SS::SUCCESS) {
      std::printf("| %s | cannot read: %s |\n", name.c_str(), msg.c_str());
      continue;
    }
    std::size_t max_faces = max_faces_option >= 0 ? std::size_t(max_faces_option) : 0;
    if(max_faces_option < 0 && m.number_of_faces() > 100000) {
      max_faces = 20000;
      std::printf("| %s | (%zu faces: each trace bounded to %zu faces; --max-faces 0 for the library's bound) |\n",
                  name.c_str(), std::size_t(m.number_of_faces()), max_faces);
    }
    row(name, "input", m, uv, svg_dir.empty() ? "" : svg_dir + "/" + name + "_input.svg", max_faces);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv);
    if(r.status != SS::SUCCESS) {
      std::printf("| %s | snapped | snap failed: %s |\n", name.c_str(), SS::status_name(r.status));
      continue;
    }
    char which[64];
    std::snprintf(which, sizeof which, "snapped (%zu folds)", r.flips_before);
    row(name, which, m, uv, svg_dir.empty() ? "" : svg_dir + "/" + name + "_snapped.svg", max_faces);
  }
  return 0;
}
