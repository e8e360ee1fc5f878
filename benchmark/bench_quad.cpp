// Quad mesh extraction on every model (a table, not a test): the map is snapped to an exact integer-grid
// map (snap_seamless_parameterization() with integer_grid_map(true): with the untangling step of the
// package, when it has one, as its default; merge_cone_pairs(true), as seamless_quad, unless --keep-cone-pairs; and
// separate_cone_pairs(true), as seamless_quad, unless --no-cone-separation), then extract_quad_mesh() makes the quad
// mesh. Per model:
// faces; the snap's status and time; the extraction's status and time; the quad mesh: quads, vertices,
// irregular vertices against the cones of the map, holes (boundary loops of the quad mesh of a closed
// map; for a map with a border: the loops beyond the map's own), non-manifold vertices and edges, Euler
// characteristic, whether every face is a quad and whether the quads cover the map (as many as its exact UV
// area); and where libQEx's stored output exists (the reference directory, <name>_quad.obj for
// <name>_param.obj, see ../shared/reference/README.md): its V, F, valences, closed and manifold, measured
// here from the OBJ file. A second table gives the valence histograms, a third the patches of each quad mesh
// (quad_mesh_patches(): its motorcycle graph along the quad edges): patches, how many are rectangles, nodes,
// motorcycles, separatrix edges, the largest patch (width x height), the time, the quad layout (quad_layout(): its
// vertices, arcs, T-junctions, arcs with one patch on both sides, whether it is a polygon mesh, its time with the
// patches it recomputes), the layout of the map's motorcycle graph traced exactly on its triangles
// (build_motorcycle_graph(), as seamless_trace: patches / nodes / arcs, its time, and whether it is the quad layout:
// as many patches, its nodes and arcs the quad layout's vertices and arcs but those that split loops), and the
// patches of libQEx's stored mesh.
//
// --quantize: quantize(true) too, so that maps whose translations are not integers (Directional's rot-seamless dragon,
// retinal_miq) get integer translations chosen at the grid scale given, as `seamless_quad --quantize` (on the maps that
// are integer-grid maps already the rounding keeps their translations: the same rows).
//
// usage: bench_quad [--repeat N] [--grid-scale S] [--quantize] [--reference DIR] [--keep-cone-pairs] [--no-cone-separation] <file.obj | directory>...
//        (directories are searched recursively for *.obj; files under a "directional" folder are welded,
//        as Directional writes cut meshes). Without arguments the directory in the environment variable
//        SS_SHARED_DATA_DIR is used, and the reference directory is SS_SHARED_DATA_DIR/../reference/libqex_quads.
// Times are wall clock in ms, the minimum over N runs (default 5); the extraction's also per stage (Quad_mesh_report::
// check_ms, cells_ms, mesh_ms; each its own minimum); "extract / snap" is the ratio of the two minima, measured in the
// same run (the snap's includes its untangling). Not part of the test run.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/Motorcycle_graph.h>
#include <CGAL/Seamless_snapping/extract_quad_mesh.h>
#include <CGAL/Seamless_snapping/quad_layout.h>
#include <CGAL/Seamless_snapping/quad_mesh_patches.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <CGAL/Seamless_snapping/internal/io/retained_heap.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include "obj_inputs.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef Mesh::Property_map<Mesh::Halfedge_index, K::Point_2> UV_map;
namespace SS = CGAL::Seamless_snapping;
namespace fs = std::filesystem;

static std::string histogram(const std::vector<std::size_t>& h)
{
  std::string s;
  for(std::size_t d = 0; d < h.size(); ++d)
    if(h[d] > 0) s += (s.empty() ? "" : " ") + std::to_string(d) + ":" + std::to_string(h[d]);
  return s;
}

// libQEx's stored quad mesh, measured from its OBJ file (a polygon soup)
struct Reference
{
  bool found = false;
  std::size_t V = 0, F = 0, non_quads = 0, border_edges = 0, non_manifold_edges = 0;
  bool polygon_mesh = false;      // a manifold, consistently oriented polygon mesh (CGAL's test)
  std::vector<std::size_t> valences;
  std::string patches = "-";      // its patches (quad_mesh_patches()), where it is a polygon mesh of quads
};

static Reference read_reference(const fs::path& file)
{
  Reference r;
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!fs::exists(file) || !CGAL::IO::read_OBJ(file.string(), points, polygons)) return r;
  r.found = true;
  r.V = points.size();
  r.F = polygons.size();
  std::map<std::pair<std::size_t, std::size_t>, int> uses;
  for(const auto& p : polygons) {
    r.non_quads += p.size() != 4 ? 1 : 0;
    for(std::size_t i = 0; i < p.size(); ++i) {
      const std::size_t a = p[i], b = p[(i + 1) % p.size()];
      ++uses[std::make_pair((std::min)(a, b), (std::max)(a, b))];
    }
  }
  std::vector<std::size_t> degree(points.size(), 0);
  for(const auto& e : uses) {
    r.border_edges += e.second == 1 ? 1 : 0;
    r.non_manifold_edges += e.second > 2 ? 1 : 0;
    ++degree[e.first.first];
    ++degree[e.first.second];
  }
  for(std::size_t d : degree) {
    if(r.valences.size() <= d) r.valences.resize(d + 1, 0);
    ++r.valences[d];
  }
  r.polygon_mesh = CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons);
  if(r.polygon_mesh && r.non_quads == 0) {
    Mesh m;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, m);
    Mesh layout;
    auto arcs = layout.add_property_map<Mesh::Halfedge_index, SS::Quad_layout_arc<Mesh> >("h:arc").first;
    const SS::Quad_layout lay = SS::quad_layout(m, layout, arcs);   // its patches too (lay.patches)
    const SS::Quad_patches& pt = lay.patches;
    r.patches = pt.status == SS::SUCCESS ? std::to_string(pt.patches.size()) + " (" + std::to_string(pt.rectangles) +
                                           " rectangles, " + std::to_string(pt.nodes) + " nodes; layout " +
                                           (lay.status == SS::SUCCESS ? std::to_string(lay.vertices) + " / " + std::to_string(lay.arcs) +
                                                                        " / " + std::to_string(lay.t_junctions) + " / " +
                                                                        std::to_string(lay.self_adjacent_arcs)
                                                                      : std::string(SS::status_name(lay.status))) + ")"
                                         : SS::status_name(pt.status);
  }
  return r;
}

int main(int argc, char** argv)
{
  CGAL::Seamless_snapping::IO::internal::use_retained_heap(argv);   // large maps: see the header
  std::vector<fs::path> inputs, files;
  int repeat = 5;
  double grid_scale = 1;
  bool merge_cone_pairs = true, separate_cone_pairs = true, quantize = false;
  std::string reference_dir;
  for(int i = 1; i < argc; ++i) {
    if(std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) repeat = (std::max)(1, std::atoi(argv[++i]));
    else if(std::strcmp(argv[i], "--grid-scale") == 0 && i + 1 < argc) grid_scale = std::atof(argv[++i]);
    else if(std::strcmp(argv[i], "--reference") == 0 && i + 1 < argc) reference_dir = argv[++i];
    else if(std::strcmp(argv[i], "--keep-cone-pairs") == 0) merge_cone_pairs = false;
    else if(std::strcmp(argv[i], "--no-cone-separation") == 0) separate_cone_pairs = false;
    else if(std::strcmp(argv[i], "--quantize") == 0) quantize = true;
    else inputs.emplace_back(argv[i]);
  }
  if(reference_dir.empty() && std::getenv("SS_SHARED_DATA_DIR") != nullptr)
    reference_dir = (fs::path(std::getenv("SS_SHARED_DATA_DIR")) / ".." / "reference" / "libqex_quads").string();
  if(!collect_obj_files(inputs, std::string("usage: ") + argv[0] + " [--repeat N] [--grid-scale S] [--quantize] [--reference DIR] [--keep-cone-pairs] [--no-cone-separation] "
                                "<file.obj | directory>...  (or set SS_SHARED_DATA_DIR)", files))
    return 2;

  std::printf("grid scale %g%s; times: minimum of %d runs, ms\n\n", grid_scale, quantize ? ", quantized" : "", repeat);
  std::printf("| model | faces | snap | snap ms | extraction | extract ms (check / cells / mesh) | extract / snap | quads | vertices |"
              " irregular / cones | holes | non-manifold v / e | chi (map) | all quads | covers map | libQEx V / F |"
              " libQEx closed, manifold |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> histograms, patch_rows;
  for(const fs::path& p : files) {
    const std::string name = p.stem().string();
    const bool weld = p.string().find("directional") != std::string::npos;
    Mesh input;
    UV_map uv_in = input.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
    std::string msg;
    if(SS::IO::read_OBJ_with_corner_uvs(p.string(), input, uv_in, msg, SS::parameters::weld_vertices(weld)) != SS::SUCCESS) {
      std::printf("| %s | cannot read: %s |\n", name.c_str(), msg.c_str());
      continue;
    }
    // snap (minimum time over the runs, each on a fresh copy of the input)
    Mesh m;
    SS::Snap_report snap;
    double snap_ms = 1e300;
    for(int k = 0; k < repeat; ++k) {
      m = input;
      UV_map uv = m.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
      snap = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).grid_scale(grid_scale)
                                                       .merge_cone_pairs(merge_cone_pairs)
                                                       .separate_cone_pairs(separate_cone_pairs).quantize(quantize));
      snap_ms = (std::min)(snap_ms, snap.total_ms);
    }
    UV_map uv = m.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
    std::printf("| %s | %zu | %s | %.1f |", name.c_str(), std::size_t(input.number_of_faces()), SS::status_name(snap.status), snap_ms);
    if(snap.status != SS::SUCCESS) { std::printf(" - | | | | | | | | | | | | |\n"); continue; }
    // extract
    SS::Quad_mesh_report q;
    double extract_ms = 1e300, check_ms = 1e300, cells_ms = 1e300, mesh_ms = 1e300;
    Mesh quads;
    for(int k = 0; k < repeat; ++k) {
      quads = Mesh();
      q = SS::extract_quad_mesh(m, uv, quads, SS::parameters::grid_scale(grid_scale));
      extract_ms = (std::min)(extract_ms, q.total_ms);
      check_ms = (std::min)(check_ms, q.check_ms);
      cells_ms = (std::min)(cells_ms, q.cells_ms);
      mesh_ms = (std::min)(mesh_ms, q.mesh_ms);
    }
    const fs::path ref_file = fs::path(reference_dir) / (name.substr(0, name.rfind("_param")) + "_quad.obj");
    const Reference ref = reference_dir.empty() || name.rfind("_param") == std::string::npos ? Reference() : read_reference(ref_file);
    char ref_cells[2][96] = {"-", "-"};
    if(ref.found) {
      std::snprintf(ref_cells[0], sizeof ref_cells[0], "%zu / %zu", ref.V, ref.F);
      std::snprintf(ref_cells[1], sizeof ref_cells[1], "%s, %s%s", ref.border_edges == 0 ? "closed" : "open",
                    ref.polygon_mesh && ref.non_manifold_edges == 0 ? "manifold" : "non-manifold",
                    ref.non_quads == 0 ? "" : ", not all quads");
      histograms.push_back("| " + name + " | libQEx (stored) | " + histogram(ref.valences) + " |");
    }
    if(q.status != SS::SUCCESS) {
      std::string why = SS::status_name(q.status);
      if(q.status == SS::FOLD_OVERS)
        why += " (" + std::to_string(q.fold_overs.size()) + " fold-overs, " + std::to_string(q.zero_area_faces.size()) + " zero-area)";
      std::printf(" %s | %.1f | | | | | | | | | | %s | %s |\n", why.c_str(), q.total_ms, ref_cells[0], ref_cells[1]);
      continue;
    }
    const std::size_t holes = q.boundary_loops - (std::min)(q.boundary_loops, q.input_boundary_loops);
    std::printf(" SUCCESS | %.1f (%.1f / %.1f / %.1f) | %.2f | %zu | %zu | %zu / %zu | %zu | %zu / %zu | %d (%d) | %s | %s | %s | %s |\n",
                extract_ms, check_ms, cells_ms, mesh_ms, extract_ms / snap_ms, q.quads,
                q.quad_vertices, q.irregular_vertices, q.cones, holes, q.non_manifold_vertices, q.non_manifold_edges,
                q.euler_characteristic, q.input_euler_characteristic, CGAL::is_quad_mesh(quads) ? "yes" : "no",
                q.covers_map() ? "yes" : ("no: " + std::to_string(q.incomplete_cells) + " cells cut by the border").c_str(),
                ref_cells[0], ref_cells[1]);
    histograms.push_back("| " + name + " | extracted | " + histogram(q.valence_histogram) + " |");
    auto patch = quads.add_property_map<Mesh::Face_index, SS::Quad_patch_location<Mesh> >("f:patch").first;
    const SS::Quad_patches pt = SS::quad_mesh_patches(quads, patch);
    std::size_t largest = 0;
    for(std::size_t k = 1; k < pt.patches.size(); ++k) if(pt.patches[k].quads > pt.patches[largest].quads) largest = k;
    Mesh layout;
    auto arcs = layout.add_property_map<Mesh::Halfedge_index, SS::Quad_layout_arc<Mesh> >("h:arc").first;
    const SS::Quad_layout lay = SS::quad_layout(quads, layout, arcs);
    const SS::Isoline_tracer<Mesh, UV_map> tracer(m, uv);
    const SS::Motorcycle_graph<Mesh> g = SS::build_motorcycle_graph(tracer);
    const SS::Patch_layout& L = g.layout;
    char traced[160] = "-";
    if(L.status == SS::SUCCESS)
      std::snprintf(traced, sizeof traced, "%zu / %zu / %zu | %.0f | %s", L.patches.size(), L.nodes, L.arcs,
                    g.trace_ms + L.subdivision_ms + L.mesh_ms + L.measure_ms,
                    L.patches.size() == pt.patches.size() && L.nodes + lay.loop_splits == lay.vertices &&
                    L.arcs + lay.loop_splits == lay.arcs ? "yes" : "no");
    else std::snprintf(traced, sizeof traced, "- | | %s", L.message.c_str());
    char row[768];
    std::snprintf(row, sizeof row, "| %s | %s | %zu | %zu | %zu | %zu | %zu | %d x %d | %.2f | %zu / %zu / %zu / %zu (%s) | %.2f | %s | %s |",
                  name.c_str(), SS::status_name(pt.status),
                  pt.patches.size(), pt.rectangles, pt.nodes, pt.motorcycles, pt.separatrix_edges,
                  pt.patches.empty() ? 0 : pt.patches[largest].width, pt.patches.empty() ? 0 : pt.patches[largest].height, pt.total_ms,
                  lay.vertices, lay.arcs, lay.t_junctions, lay.self_adjacent_arcs, lay.polygon_mesh ? "yes" : "no", lay.total_ms,
                  traced, ref.found ? ref.patches.c_str() : "-");
    patch_rows.push_back(row);
    std::fflush(stdout);
  }
  std::printf("\n| model | mesh | valences (valence:vertices) |\n|---|---|---|\n");
  for(const std::string& h : histograms) std::printf("%s\n", h.c_str());
  std::printf("\n| model | patches status | patches | rectangles | nodes | motorcycles | separatrix edges | largest patch | ms |"
              " layout: vertices / arcs / T-junctions / self-adjacent arcs (polygon mesh) | layout ms |"
              " traced on the map: patches / nodes / arcs | traced ms | = quad layout | libQEx's mesh: patches (its layout) |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const std::string& r : patch_rows) std::printf("%s\n", r.c_str());
  return 0;
}
