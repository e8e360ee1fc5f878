// seamless_quad: the quad mesh of a UV map, from the command line.
//
//   seamless_quad IN.obj OUT.(obj|off|ply) [--weld | --no-weld] [--grid-scale S] [--quantize] [--no-untangle] [--keep-cone-pairs]
//                 [--no-cone-separation] [--no-cone-split] [--no-branch-fill] [--layout FILE.(obj|off|ply)] [--report FILE.json] [--max-grid-cells N] [--threads N] [--quiet]
//
// Reads a triangle mesh with an approximately integer-grid per-corner UV map (OBJ, f v/vt), snaps it to an
// exact integer-grid map (snap_seamless_parameterization() with integer_grid_map(true)), extracts its quad
// mesh (extract_quad_mesh(), which checks the map and verifies the mesh), cuts it into rectangle patches
// (quad_mesh_patches(): in PLY per face patch_id, patch_i, patch_j, patch_corner) and writes OUT atomically;
// with --layout, also the quad layout (quad_layout(): one polygon per patch) into FILE. Exit status 0 only when OUT
// (and FILE) were written.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/IO/cut_mesh.h>
#include <CGAL/Seamless_snapping/extract_quad_mesh.h>
#include <CGAL/Seamless_snapping/is_exact_integer_grid_map.h>
#include <CGAL/Seamless_snapping/quad_layout.h>
#include <CGAL/Seamless_snapping/quad_mesh_patches.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <CGAL/Seamless_snapping/version.h>
#include <CGAL/Seamless_snapping/internal/io/command_line.h>
#include <CGAL/Seamless_snapping/internal/io/json_string.h>
#include <CGAL/Seamless_snapping/internal/io/name_lists.h>
#include <CGAL/Seamless_snapping/internal/io/retained_heap.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/Surface_mesh/IO/PLY.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double>                     K;
typedef K::Point_2                                         Point_2;
typedef K::Point_3                                         Point_3;
typedef CGAL::Surface_mesh<Point_3>                        Mesh;
typedef Mesh::Property_map<Mesh::Halfedge_index, Point_2>  UV_map;

namespace SS = CGAL::Seamless_snapping;
using SS::IO::internal::json_string;
namespace params = CGAL::Seamless_snapping::parameters;

static const char* usage_text =
  "usage: seamless_quad IN.obj OUT.(obj|off|ply) [--weld | --no-weld] [--grid-scale S] [--quantize] [--no-untangle] [--keep-cone-pairs]\n"
  "                     [--no-cone-separation] [--no-cone-split] [--no-branch-fill] [--layout FILE.(obj|off|ply)] [--report FILE.json] [--max-grid-cells N] [--threads N] [--quiet]\n";

static const char* help_text =
  "Makes the quad mesh of an integer-grid map: snaps the per-corner UV map of IN.obj to an exact\n"
  "integer-grid map (every seam translation an integer vector, every cone on an integer point; the\n"
  "package's snap with integer_grid_map(true), which first removes the map's fold-overs inside the\n"
  "space of maps with the same exact constraints: untangle(true), and merges the +-90 degree cone pairs\n"
  "that the map's integer translations put onto one integer point: merge_cone_pairs(true), and moves\n"
  "the other cone pairs on one integer point that a cut joins apart: separate_cone_pairs(true)), then\n"
  "extracts its quad mesh: the vertices are the integer points of the map, the edges the unit segments\n"
  "of its integer isolines, the faces its unit cells, all decided exactly. The result is verified\n"
  "before it is written: every face a quad, manifold, closed if the input is, Euler characteristic and\n"
  "number of quads (= the exact UV area) those of the map, irregular vertices exactly the cones. A cone\n"
  "of 90 degrees (valence 1, e.g. in Directional's maps) has no cell of its own: its 2 x 2 cells are made\n"
  "one quad, whose three corners next to the cone have valence 3 for it (split_valence_one_cones(true);\n"
  "the quad mesh report's \"split_cones\" lists them, 3 quads fewer than the UV area each). A vertex\n"
  "around which the map winds m > 1 times inside a cell (a branch point the untangling left) covers\n"
  "that cell m times: the 4m-gon is filled with 2m - 1 quads, 4(m - 1) of whose corners have valence 5\n"
  "(fill_branched_cells(true); \"filled_branch_points\", m - 1 quads more than the UV area each); the cell\n"
  "of a 90 degree cone next to that cell is filled with it (\"absorbed_cones\", one quad fewer each).\n"
  "\n"
  "Refused (exit 1, nothing written), with the reason: a map that is not near an integer-grid map\n"
  "(scale it with --grid-scale, or --quantize it), a map left with fold-overs or zero-area UV triangles\n"
  "with two corners at one point (listed, with the reason the constraints force them in the snap\n"
  "report's \"folds\"; a zero-area triangle with three distinct collinear corners is collapsed onto its\n"
  "long side), a cone of 90 degrees whose 2 x 2 cells are not four whole cells around two regular\n"
  "points (or any, with --no-cone-split), a branch point next to another one or a cone (but the cell of\n"
  "a 90 degree cone, which is filled with it), a grid too coarse for the surface (cells that wrap\n"
  "around or share more than a side: use a larger --grid-scale).\n"
  "\n"
  "Options:\n"
  "  --weld               merge vertices with bit-identical positions first (cut meshes, e.g.\n"
  "                       libigl/Directional output, whose seams are otherwise borders). Such an input\n"
  "                       is welded automatically (a line says so)\n"
  "  --no-weld            never weld; a cut mesh is then refused (exit 1: its seams would be borders)\n"
  "  --grid-scale S       the integer grid is at multiples of 1/S in UV (S a power of two); larger S,\n"
  "                       finer quads (S^2 times as many)\n"
  "  --quantize           a map that is not near an integer-grid map at this grid scale (its translations\n"
  "                       were never made integers, e.g. Directional's rot-seamless output) gets integer\n"
  "                       translations chosen for it: each cone onto an integer point next to it (of the four\n"
  "                       around it, the one that keeps the translations nearest the map's), the translations\n"
  "                       from those along the cut graph, rounded where it leaves a choice (quantize(true));\n"
  "                       the map then moves by up to a few grid cells and is untangled. Refused (exit 1) where\n"
  "                       the choice contradicts itself around a vertex; the grid's cells must be smaller than\n"
  "                       the distances between the cones (a larger --grid-scale)\n"
  "  --no-untangle        snap the map as it is, without removing its fold-overs (then refused if it\n"
  "                       has any)\n"
  "  --keep-cone-pairs    keep every cone of the map's field: a valence-3 and a valence-5 cone that the\n"
  "                       map's integer translations put onto one integer point are not merged into\n"
  "                       regular vertices (the map then folds around them and is refused; libQEx\n"
  "                       merges such pairs too), and other pairs on one point are not joined into one\n"
  "                       cone. The snap report lists the merged pairs\n"
  "  --no-cone-separation two cones on one integer point that a cut within two cells (2 S at --grid-scale S)\n"
  "                       joins are left there (the map then has a zero-area triangle there and is\n"
  "                       refused) instead of moved apart, each onto a neighbouring integer point\n"
  "                       (separate_cone_pairs; the snap report's \"separated_cone_pairs\"). Only\n"
  "                       Directional's full-seamless dragon of the shared maps has such pairs left after\n"
  "                       the merge\n"
  "  --no-cone-split      refuse a cone of 90 degrees instead of making its 2 x 2 cells one quad (every\n"
  "                       quad then a unit cell of the grid)\n"
  "  --no-branch-fill     refuse a map that winds more than once around a point inside a cell instead of\n"
  "                       filling that cell's sheets with quads\n"
  "  --layout FILE        also write the quad layout (quad_layout()): one polygon per patch, its vertices the\n"
  "                       quad vertices at patch corners (cones, border corners, T-junctions where a trace ends\n"
  "                       on another), its edges the arcs between them (the 'coarse mesh' of the patches);\n"
  "                       by extension .obj, .off or .ply (ASCII, per vertex quad_vertex: its index in OUT,\n"
  "                       per face patch_width, patch_height: the patch's size in quads). A patch may touch\n"
  "                       itself across an arc or a vertex (a line says how often): its polygon then lists\n"
  "                       that vertex twice\n"
  "  --report FILE.json   write {\"snap\": ..., \"quad_mesh\": ..., \"patches\": ..., \"layout\": ...} (the\n"
  "                       reports; \"layout\" null without --layout) as JSON, also on failure\n"
  "  --max-grid-cells N   refuse (exit 1) a map whose faces' UV bounding boxes hold more than N unit cells\n"
  "                       of the integer grid in all (default 16777216 = 2^24): the work and the memory\n"
  "                       grow with them, about 290 bytes per quad\n"
  "  --threads N          threads for independent steps of the reading and the snap (its untangling\n"
  "                       included; the same quad mesh whatever N): 0, the default, takes the machine's\n"
  "                       cores; 1 runs on one thread\n"
  "  --quiet              print nothing but errors\n"
  "  --help               print this help\n"
  "\n"
  "Output, by the extension of OUT: .obj and .off (positions with 17 significant digits, quads), or\n"
  ".ply (ASCII, with per vertex input_kind (0 at a mesh vertex, 1 on an edge, 2 inside a face),\n"
  "input_face (the input face, 0-based in the order of the mesh's faces, in whose UV chart grid_u, grid_v\n"
  "are given), grid_u, grid_v (the integer UV in grid units), and per face input_face (the first input\n"
  "face it covers), input_faces (how many it covers), patch_id, patch_i, patch_j (the quad's patch and its cell\n"
  "(i, j) in the patch's grid, see below) and patch_corner (the rank, 0-3, of the face's vertex at the cell's\n"
  "corner (i, j); the next vertex is (i + 1, j))). Written atomically (temporary file + rename; a device, a\n"
  "named pipe or /dev/stdout directly, not truncated).\n"
  "Patches: the quads are partitioned by the motorcycle graph of the quad mesh (quad_mesh_patches(): traces\n"
  "from every irregular vertex and border corner along the quad edges, each stopping at an earlier one) into\n"
  "rectangles of width x height quads, each quad a cell (i, j) of its patch's grid; a line counts them.\n"
  "Cells cut by a border that is not on an integer isoline are left out and counted (a line says so).\n"
  "\n"
  "Exit status: 0 when OUT (and the --layout file) was written; 1 when reading, snapping, extracting or\n"
  "writing failed (one line on stderr says why; OUT and the layout file are then not created or changed:\n"
  "the layout goes to its temporary file first, renamed only after OUT was); 2 for a command-line error.\n";

static std::string one_line(std::string s)
{
  for(char& c : s) if(c == '\n' || c == '\r') c = ' ';
  return s;
}

static int fail(const std::string& why)
{
  std::cerr << "seamless_quad: " << one_line(why) << std::endl;
  return EXIT_FAILURE;
}

static std::string extension_of(const std::string& file)
{
  const std::size_t dot = file.rfind('.');
  std::string e = dot == std::string::npos ? "" : file.substr(dot + 1);
  for(char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

int main(int argc, char** argv)
{
  CGAL::Seamless_snapping::IO::internal::use_retained_heap(argv);   // large maps: see the header
  std::string in, out, report_file, layout_file;
  bool weld = false, no_weld = false, quiet = false, untangle = true, merge = true, quantize = false, split_cones = true,
       fill_branches = true, separate = true;
  double grid_scale = 1;
  std::size_t max_grid_cells = SS::default_max_grid_cells;
  unsigned threads = 0;                 // 0: the machine's cores
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--help" || a == "-h") { std::cout << usage_text << "\n" << help_text; return EXIT_SUCCESS; }
    else if(a == "--weld") weld = true;
    else if(a == "--no-weld") no_weld = true;
    else if(a == "--quiet") quiet = true;
    else if(a == "--no-untangle") untangle = false;
    else if(a == "--keep-cone-pairs") merge = false;
    else if(a == "--no-cone-separation") separate = false;
    else if(a == "--no-cone-split") split_cones = false;
    else if(a == "--no-branch-fill") fill_branches = false;
    else if(a == "--quantize") quantize = true;
    else if(a == "--grid-scale") {
      if(i + 1 >= argc || !SS::IO::internal::parse_grid_scale(argv[i + 1], grid_scale)) {
        std::cerr << "seamless_quad: --grid-scale needs a power of two (1, 2, 4, 0.5, ...)\n" << usage_text; return 2;
      }
      ++i;
    }
    else if(a == "--max-grid-cells") {
      unsigned long long n = 0;
      if(i + 1 >= argc || !SS::IO::internal::parse_count(argv[i + 1], ULLONG_MAX - 1, n)) {
        std::cerr << "seamless_quad: --max-grid-cells needs a number of cells\n" << usage_text; return 2;
      }
      max_grid_cells = std::size_t(n);
      ++i;
    }
    else if(a == "--threads") {
      unsigned long long n = 0;
      if(i + 1 >= argc || !SS::IO::internal::parse_count(argv[i + 1], 1024, n)) {
        std::cerr << "seamless_quad: --threads needs a number of threads in [0, 1024]\n" << usage_text; return 2;
      }
      threads = unsigned(n);
      ++i;
    }
    else if(a == "--layout") {
      if(!SS::IO::internal::file_name_follows(argc, argv, i)) { std::cerr << "seamless_quad: --layout needs a file name\n" << usage_text; return 2; }
      layout_file = argv[++i];
    }
    else if(a == "--report") {
      if(!SS::IO::internal::file_name_follows(argc, argv, i)) { std::cerr << "seamless_quad: --report needs a file name\n" << usage_text; return 2; }
      report_file = argv[++i];
    }
    else if(a.size() > 1 && a[0] == '-') { std::cerr << "seamless_quad: unknown option '" << a << "'\n" << usage_text; return 2; }
    else if(in.empty()) in = a;
    else if(out.empty()) out = a;
    else { std::cerr << "seamless_quad: unexpected argument '" << a << "'\n" << usage_text; return 2; }
  }
  if(in.empty() || out.empty()) { std::cerr << usage_text << "(--help for details)\n"; return 2; }
  if(weld && no_weld) { std::cerr << "seamless_quad: --weld and --no-weld exclude each other\n" << usage_text; return 2; }
  // (IN too: `seamless_quad IN IN` replaced the map with its quad mesh)
  const std::string same = SS::IO::internal::same_output_file({{"IN", in}, {"OUT", out}, {"--report", report_file},
                                                               {"--layout", layout_file}});
  if(!same.empty()) { std::cerr << "seamless_quad: " << same << "\n" << usage_text; return 2; }
  const std::string format = extension_of(out);
  if(format != "obj" && format != "off" && format != "ply") {
    std::cerr << "seamless_quad: OUT must end in .obj, .off or .ply\n" << usage_text; return 2;
  }
  const std::string layout_format = extension_of(layout_file);
  if(!layout_file.empty() && layout_format != "obj" && layout_format != "off" && layout_format != "ply") {
    std::cerr << "seamless_quad: the --layout file must end in .obj, .off or .ply\n" << usage_text; return 2;
  }

  // 1. read; the corner map: uv[h] = UV of target(h) in face(h). A cut mesh is welded unless --no-weld.
  Mesh mesh;
  UV_map uv;
  std::string message;
  auto read = SS::IO::internal::read_again_checked(in, [&](bool w, std::string& m) {
    mesh = Mesh();
    uv = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv", Point_2(0, 0)).first;
    return SS::IO::read_OBJ_with_corner_uvs(in, mesh, uv, m, params::weld_vertices(w).number_of_threads(threads))
           == SS::SUCCESS;
  });
  // the JSON report (--report): the snap report and the quad mesh's, its patches' and its layout's (JSON texts)
  // `error`: why the run failed (then "output" is null: nothing was written), or empty
  auto write_report = [&](const SS::Snap_report& snap, const std::string& quad_mesh, const std::string& patches,
                          const std::string& layout, const std::string& error = std::string()) {
    const std::string json = "{\n  \"input\": " + json_string(in) + ",\n  \"output\": " +
                             (error.empty() ? json_string(out) : std::string("null")) +
                             (error.empty() ? std::string() : ",\n  \"error\": " + json_string(error)) +
                             ",\n  \"version\": " + json_string(CGAL_SEAMLESS_SNAPPING_VERSION) + ",\n  \"snap\": " +
                             snap.to_json() + ",\n  \"quad_mesh\": " + quad_mesh + ",\n  \"patches\": " + patches +
                             ",\n  \"layout\": " + layout + "}\n";
    return SS::IO::internal::write_text_atomically(report_file, json, message) == SS::SUCCESS;
  };
  // a refusal before the snap (the input cannot be read): the report says why, as the help promises
  auto refuse_input = [&](const std::string& why) {
    if(!report_file.empty()) {
      SS::Snap_report refused;
      refused.status = SS::INVALID_INPUT;
      refused.message = why;
      const std::string saved = message;
      if(!write_report(refused, "null", "null", "null", why)) fail(message);   // "output": null, "error": why
      message = saved;
    }
    return fail(why);
  };
  const SS::IO::Welding_read wr = SS::IO::read_welding_cut_meshes(mesh, weld, no_weld, message, read);
  if(!wr.ok) return refuse_input("cannot read input: " + message);
  const SS::IO::Cut_mesh_test& cut = wr.cut;
  if(cut.is_cut_mesh() && no_weld)
    return refuse_input("the input looks like a cut mesh (" + std::to_string(cut.twinned) + " of " +
                std::to_string(cut.border_edges) + " border edges lie on another one at bit-identical 3D points) and "
                "--no-weld keeps its seams as borders, which no quad mesh of the map has; nothing was written");
  if(!quiet && !wr.note(weld).empty()) std::cout << wr.note(weld) << "\n";
  weld = wr.welded;
  if(!quiet) std::cout << message << "\n";

  // 2. snap to an exact integer-grid map (the UVs are written only on success)
  const SS::Snap_report snap = SS::snap_seamless_parameterization(mesh, uv, params::integer_grid_map(true).untangle(untangle)
                                                                               .merge_cone_pairs(merge).separate_cone_pairs(separate)
                                                                               .grid_scale(grid_scale)
                                                                               .quantize(quantize)
                                                                               .number_of_threads(threads));
  if(!quiet && snap.status == SS::SUCCESS)
    std::printf("snap: %s (%.1f ms): %zu faces, %zu cut edges, %zu cones; UV triangles flipped / zero-area after "
                "snapping: %zu / %zu\n", SS::status_name(snap.status), snap.total_ms, snap.faces, snap.cut_edges,
                snap.field_cones, snap.flips_after_repair, snap.degenerate_after_repair);
  else if(!quiet)                                       // nothing was snapped: no counts after it (the reason follows)
    std::printf("snap: %s (%.1f ms): %zu faces, %zu cut edges, %zu cones\n", SS::status_name(snap.status), snap.total_ms,
                snap.faces, snap.cut_edges, snap.field_cones);
  const auto pairs = [](const std::vector<std::pair<std::size_t, std::size_t> >& p) {
    return SS::internal::first_ten(p, SS::internal::pair_name("+"));
  };
  if(!quiet && !snap.merged_cone_pairs.empty())
    std::printf("merged %zu cone pair(s) that the map's integer translations put onto one integer point (vertices%s): "
                "regular vertices of the quad mesh now (%zu pair(s) whose indices do not cancel: one vertex with both), "
                "the rotations of %zu cut edges changed (%zu of them new); --keep-cone-pairs keeps them\n",
                snap.merged_cone_pairs.size(), pairs(snap.merged_cone_pairs).c_str(), snap.joined_cone_pairs,
                snap.merged_cut_edges, snap.added_cut_edges);
  if(!quiet && !snap.separated_cone_pairs.empty())
    std::printf("moved %zu cone pair(s) apart that the map's integer translations put onto one integer point (vertices%s): "
                "each onto a neighbouring integer point, %zu trial snap(s); --no-cone-separation leaves them\n",
                snap.separated_cone_pairs.size(), pairs(snap.separated_cone_pairs).c_str(), snap.separation_trials);

  // 3. extract (the quad mesh is written into `quads` only on success)
  Mesh quads;
  auto origin = quads.add_property_map<Mesh::Vertex_index, SS::Quad_vertex_origin<Mesh> >("v:origin").first;
  auto covered = quads.add_property_map<Mesh::Face_index, std::vector<Mesh::Face_index> >("f:covered").first;
  SS::Quad_mesh_report q;
  if(snap.status == SS::SUCCESS && SS::is_exact_integer_grid_map(mesh, uv, params::grid_scale(grid_scale)))
    q = SS::extract_quad_mesh(mesh, uv, quads, params::grid_scale(grid_scale).max_grid_cells(max_grid_cells)
                                                .split_valence_one_cones(split_cones).fill_branched_cells(fill_branches),
                              params::vertex_origin_map(origin).face_origin_map(covered));
  else if(snap.status == SS::SUCCESS)
    return fail("verification failed: the snapped map is not exactly an integer-grid map (internal error; please report)");
  // its patches (the motorcycle graph of the quads: rectangles of quads)
  auto patch = quads.add_property_map<Mesh::Face_index, SS::Quad_patch_location<Mesh> >("f:patch").first;
  SS::Quad_patches patches;
  if(q.status == SS::SUCCESS) patches = SS::quad_mesh_patches(quads, patch);
  // with --layout, the quad layout (one polygon per patch)
  Mesh layout;
  auto arcs = layout.add_property_map<Mesh::Halfedge_index, SS::Quad_layout_arc<Mesh> >("h:arc").first;
  SS::Quad_layout lay;
  if(q.status == SS::SUCCESS && !layout_file.empty()) lay = SS::quad_layout(quads, layout, arcs);
  // the extraction's advice to untangle is for callers that did not: seamless_quad did, so its report does not repeat it
  const std::string advice = "; " + q.advice;
  const bool untangled_already = q.status == SS::FOLD_OVERS && untangle && !q.advice.empty() &&
                                 q.message.size() >= advice.size() &&
                                 q.message.compare(q.message.size() - advice.size(), advice.size(), advice) == 0;
  if(untangled_already) {
    q.message.resize(q.message.size() - advice.size());
    q.advice = "seamless_quad untangled the map already; the snap report's \"folds\" and \"winding_defects\" say what "
               "is left and what the constraints force";
  }
  const std::string quad_json = snap.status == SS::SUCCESS ? q.to_json() : std::string("null");
  const std::string patches_json = q.status == SS::SUCCESS ? patches.to_json() : std::string("null");
  const std::string layout_json = q.status == SS::SUCCESS && !layout_file.empty() ? lay.to_json() : std::string("null");
  if(!report_file.empty() && !write_report(snap, quad_json, patches_json, layout_json)) return fail(message);
  // a failure from here on: the report written above gets "error" and no "output"
  auto fail = [&](const std::string& why) {
    if(!report_file.empty() && !write_report(snap, quad_json, patches_json, layout_json, why)) ::fail(message);
    return ::fail(why);
  };
  if(snap.status != SS::SUCCESS)
    return fail(std::string("snapping failed: ") + SS::status_name(snap.status) + ": " + snap.message);
  if(q.status != SS::SUCCESS) {
    // what the snap proved about the faces and vertices that block the extraction (the snap report has them all)
    std::string why = q.message, proven;
    if(untangled_already) {
      proven = (snap.uv_mirrored ? "; the map or a component of it is mirrored, so seamless_quad did not untangle it "
                                   "there (" + std::string(SS::mirrored_map_advice()) + "); it untangled the rest"
                                 : std::string("; seamless_quad untangled the map already")) +
               ": " + std::to_string(snap.flips_after_repair) + " negative and " +
               std::to_string(snap.degenerate_after_repair) + " zero-area triangles are left";
    }
    const auto forced = std::find_if(snap.folds.begin(), snap.folds.end(), [](const SS::Fold_explanation& f) { return f.forced(); });
    if(q.status == SS::FOLD_OVERS && forced != snap.folds.end())
      proven += "; the snap proved " + std::to_string(snap.folds_forced) + " of them forced by the constraints, so no "
               "untangling removes them, e.g. face " + std::to_string(forced->face) + ": " + forced->message;
    if(!snap.winding_defects.empty()) {
      const auto forced_windings = std::count_if(snap.winding_defects.begin(), snap.winding_defects.end(),
                                                 [](const SS::Winding_defect& w) { return w.forced; });
      proven += "; the map also winds wrongly around " + std::to_string(snap.winding_defects.size()) + " vertices" +
                (forced_windings == 0 ? std::string()
                                      : " (" + std::to_string(forced_windings) + " of them corners of the forced faces)");
    }
    if(!proven.empty()) proven += " (--report FILE.json lists them all: \"folds\", \"winding_defects\")";
    return fail(std::string("quad extraction failed: ") + SS::status_name(q.status) + ": " + why + proven);
  }
  if(!quiet) {
    std::printf("quad mesh: %s (%.1f ms): %s\n", SS::status_name(q.status), q.total_ms, q.message.c_str());
    const std::string split = (q.split_cones.empty() ? std::string()
                               : ", " + std::to_string(q.split_cones.size()) + " of valence 1 split, into 3 of valence 3 each") +
                              (q.filled_branch_points.empty() ? std::string()
                               : ", " + std::to_string(q.filled_branch_points.size()) + " branch points filled") +
                              (q.absorbed_cones.empty() ? std::string()
                               : ", " + std::to_string(q.absorbed_cones.size()) + " of valence 1 filled with a branched cell");
    std::printf("verified: all quads, manifold, %s, Euler characteristic %d (map %d), %zu irregular vertices (%zu cones%s)%s\n",
                q.boundary_loops == 0 ? "closed" : (std::to_string(q.boundary_loops) + " boundary loops").c_str(),
                q.euler_characteristic, q.input_euler_characteristic, q.irregular_vertices, q.cones, split.c_str(),
                !q.covers_map() ? "" : q.split_cones.empty() && q.filled_branch_points.empty()
                                       ? ", as many quads as the exact UV area"
                                       : ", as many quads as the exact UV area, less 3 per split cone, plus m - 1 per filled branch "
                                         "point, less 1 per cone cell filled with one");
    std::printf("patches: %s\n", patches.message.c_str());
    if(!layout_file.empty()) std::printf("layout: %s\n", lay.message.c_str());
  }
  if(!layout_file.empty() && lay.status != SS::SUCCESS) return fail(lay.message + "; nothing was written");
  if(q.incomplete_cells > 0)
    std::cerr << "seamless_quad: note: " << q.incomplete_cells << " cells cut by the border (not on integer isolines) "
              << "were left out\n";

  // 4. write atomically
  std::ostringstream os;
  os.precision(17);
  bool written = false;
  if(format == "ply") {
    auto kind = quads.add_property_map<Mesh::Vertex_index, std::int32_t>("v:input_kind").first;
    auto face = quads.add_property_map<Mesh::Vertex_index, std::int32_t>("v:input_face").first;
    auto gu = quads.add_property_map<Mesh::Vertex_index, std::int32_t>("v:grid_u").first;
    auto gv = quads.add_property_map<Mesh::Vertex_index, std::int32_t>("v:grid_v").first;
    auto first = quads.add_property_map<Mesh::Face_index, std::int32_t>("f:input_face").first;
    auto count = quads.add_property_map<Mesh::Face_index, std::int32_t>("f:input_faces").first;
    auto patch_id = quads.add_property_map<Mesh::Face_index, std::int32_t>("f:patch_id").first;
    auto patch_i = quads.add_property_map<Mesh::Face_index, std::int32_t>("f:patch_i").first;
    auto patch_j = quads.add_property_map<Mesh::Face_index, std::int32_t>("f:patch_j").first;
    auto patch_corner = quads.add_property_map<Mesh::Face_index, std::int32_t>("f:patch_corner").first;
    for(Mesh::Vertex_index v : quads.vertices()) {
      const SS::Quad_vertex_origin<Mesh>& o = origin[v];
      kind[v] = std::int32_t(o.location);
      face[v] = std::int32_t(o.face);
      gu[v] = std::int32_t(o.u);
      gv[v] = std::int32_t(o.v);
    }
    for(Mesh::Face_index f : quads.faces()) {
      first[f] = std::int32_t(covered[f].front()); count[f] = std::int32_t(covered[f].size());
      const SS::Quad_patch_location<Mesh>& l = patch[f];
      patch_id[f] = std::int32_t(l.patch); patch_i[f] = l.i; patch_j[f] = l.j;
      patch_corner[f] = SS::patch_corner_rank(quads, f, l);   // in the order PLY lists the face's vertices
    }
    quads.remove_property_map(origin);
    quads.remove_property_map(covered);
    quads.remove_property_map(patch);
    written = CGAL::IO::write_PLY(os, quads, "quad mesh of " + in, CGAL::parameters::use_binary_mode(false));
  }
  else if(format == "off") written = CGAL::IO::write_OFF(os, quads, CGAL::parameters::stream_precision(17));
  else written = CGAL::IO::write_OBJ(os, quads, CGAL::parameters::stream_precision(17));
  if(!written) return fail("cannot format the quad mesh as " + format);
  std::ostringstream ls;                                // the layout, formatted before anything is written
  if(!layout_file.empty()) {
    ls.precision(17);
    if(layout_format == "ply") {
      auto quad_vertex = layout.add_property_map<Mesh::Vertex_index, std::int32_t>("v:quad_vertex").first;
      auto width = layout.add_property_map<Mesh::Face_index, std::int32_t>("f:patch_width").first;
      auto height = layout.add_property_map<Mesh::Face_index, std::int32_t>("f:patch_height").first;
      for(Mesh::Vertex_index v : layout.vertices()) quad_vertex[v] = std::int32_t(SS::layout_quad_vertex(quads, layout, arcs, v));
      for(Mesh::Face_index f : layout.faces()) {
        width[f] = std::int32_t(lay.patches.patches[std::size_t(f)].width);
        height[f] = std::int32_t(lay.patches.patches[std::size_t(f)].height);
      }
      layout.remove_property_map(arcs);
      written = CGAL::IO::write_PLY(ls, layout, "quad layout of " + in, CGAL::parameters::use_binary_mode(false));
    }
    else if(layout_format == "off") written = CGAL::IO::write_OFF(ls, layout, CGAL::parameters::stream_precision(17));
    else written = CGAL::IO::write_OBJ(ls, layout, CGAL::parameters::stream_precision(17));
    if(!written) return fail("cannot format the quad layout as " + layout_format);
  }
  // the layout to its temporary file first, renamed only after OUT was: a layout that cannot be written leaves no OUT
  // behind (the report, which says "output": null then, was wrong; a device or pipe named by --layout is written at once)
  const std::string layout_text = ls.str();
  SS::IO::internal::Atomic_file layout_out;
  if(!layout_file.empty() &&
     layout_out.prepare(layout_file, SS::IO::internal::text_writer(layout_text), message) != SS::SUCCESS)
    return fail(message + "; nothing was written");
  if(SS::IO::internal::write_text_atomically(out, os.str(), message) != SS::SUCCESS) return fail(message);
  if(layout_out.commit(message) != SS::SUCCESS) return fail(message);
  if(!quiet) std::cout << std::to_string(q.quads) << " quads written to " << out << "\n";
  if(!quiet && !layout_file.empty()) std::cout << lay.patches.patches.size() << " layout faces written to " << layout_file << "\n";
  return EXIT_SUCCESS;
}
