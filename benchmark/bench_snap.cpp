// Timing of snap_seamless_parameterization() per model, one row per model like Table 1 of
// Mandad & Campen 2019: sizes, phase times of the reduced pipeline (Sec. 5.3.1), the time ratio of
// the unreduced (full sector system) to the reduced pipeline, input violation, change, flips.
//
// usage: bench_snap [--repeat N] <file.obj | directory>...
//        (directories are searched recursively for *.obj; files under a "directional" folder are read
//        with weld_vertices(true), as Directional writes cut meshes). Without arguments the directory
//        in the environment variable SS_SHARED_DATA_DIR is used.
// Times are wall clock in ms, the minimum over N runs (default 3). Lengths are relative to the UV
// bounding-box diagonal. Not part of the test run.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef Mesh::Property_map<Mesh::Halfedge_index, K::Point_2> UV_map;   // uv[h] = UV of target(h) in face(h)
namespace SS = CGAL::Seamless_snapping;
namespace fs = std::filesystem;

int main(int argc, char** argv)
{
  int repeat = 3;
  std::vector<fs::path> inputs;
  for(int i = 1; i < argc; ++i) {
    if(std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) { repeat = (std::max)(1, std::atoi(argv[++i])); continue; }
    inputs.emplace_back(argv[i]);
  }
  if(inputs.empty()) {
    const char* env = std::getenv("SS_SHARED_DATA_DIR");
    if(env == nullptr) {
      std::cerr << "usage: " << argv[0] << " [--repeat N] <file.obj | directory>...  (or set SS_SHARED_DATA_DIR)\n";
      return EXIT_FAILURE;
    }
    inputs.emplace_back(env);
  }
  std::vector<fs::path> files;
  for(const fs::path& p : inputs) {
    if(fs::is_directory(p)) {
      for(const auto& e : fs::recursive_directory_iterator(p))
        if(e.is_regular_file() && e.path().extension() == ".obj") files.push_back(e.path());
    } else {
      files.push_back(p);
    }
  }
  std::sort(files.begin(), files.end());

  std::printf("%-36s %7s %6s %6s %6s | %8s %8s %8s %8s %8s %8s | %9s %6s %9s %6s | %9s %9s %9s | %7s | %9s\n",
              "model", "#F", "#cut", "#nodes", "#branch", "extract", "reduce", "IRREF", "evaluate", "propag.", "total",
              "unreduced", "ratio", "unr.proj", "ratio", "max Cx/d", "avg du/d", "max du/d", "flips", "read OBJ");
  int failures = 0;
  for(const fs::path& p : files) {
    const bool weld = p.string().find("directional") != std::string::npos;
    Mesh input;
    UV_map uv_in = input.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
    std::string msg;
    auto t0 = std::chrono::steady_clock::now();
    SS::Status s = SS::IO::read_OBJ_with_corner_uvs(p.string(), input, uv_in, msg, SS::parameters::weld_vertices(weld));
    const double read_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if(s != SS::SUCCESS) { std::printf("%-36s cannot read: %s\n", p.filename().string().c_str(), msg.c_str()); ++failures; continue; }

    SS::Snap_report best, best_full;
    bool first = true;
    for(int r = 0; r < repeat; ++r) {
      Mesh m = input;
      UV_map uv = m.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
      SS::Snap_report rep = SS::snap_seamless_parameterization(m, uv);
      Mesh mf = input;
      UV_map uvf = mf.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
      SS::Snap_report full = SS::snap_seamless_parameterization(mf, uvf, SS::parameters::use_reduced_system(false));
      if(rep.status != SS::SUCCESS || full.status != SS::SUCCESS) {
        std::printf("%-36s FAILED: reduced %s (%s), unreduced %s (%s)\n", p.filename().string().c_str(),
                    SS::status_name(rep.status), rep.message.c_str(), SS::status_name(full.status), full.message.c_str());
        ++failures;
        first = true;
        break;
      }
      if(first || rep.total_ms < best.total_ms) best = rep;
      if(first || full.total_ms < best_full.total_ms) best_full = full;
      first = false;
    }
    if(first) continue;
    const double proj = best.reduce_ms + best.irref_ms + best.evaluate_ms + best.propagate_ms;
    const double proj_full = best_full.irref_ms + best_full.evaluate_ms;
    std::printf("%-36s %7zu %6zu %6zu %6zu | %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f | %9.2f %6.2f %9.2f %6.2f | %9.2e %9.2e %9.2e | %3zu->%-3zu | %9.1f\n",
                p.filename().string().c_str(), best.faces, best.cut_edges, best.nodes, best.cut_branches + best.align_branches,
                best.extract_ms, best.reduce_ms, best.irref_ms, best.evaluate_ms, best.propagate_ms, best.total_ms,
                best_full.total_ms, best.total_ms > 0 ? best_full.total_ms / best.total_ms : 0.,
                proj_full, proj > 0 ? proj_full / proj : 0.,
                best.max_input_violation, best.mean_change, best.max_change, best.flips_before, best.flips_after, read_ms);
  }
  std::printf("\ncolumns: phase times of the reduced pipeline (extract = corner mesh, seams, sectors, rotations, full rows,\n"
              "input violation, flips; reduce = nodes/branches/node system; IRREF and evaluate = Exact_constraint_projection\n"
              "initialize()/project() on the node system; propag. = non-node sectors; total includes the exact verification\n"
              "and the write). unreduced = total ms with use_reduced_system(false); ratio = unreduced / reduced.\n"
              "unr.proj = IRREF + evaluate ms of the full system; its ratio is to reduce + IRREF + evaluate + propag. of the\n"
              "reduced pipeline (the part Sec. 5.3 speeds up).\n");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
