// seamless_snap: the command-line program of the package.
//
//   seamless_snap IN.obj OUT.obj [--weld | --no-weld] [--keep-layout] [--no-align-boundary] [--unreduced]
//                 [--fail-on-new-flips] [--integer-grid] [--grid-scale S] [--features FILE]
//                 [--sharp-angle DEG] [--pin FILE] [--vt-per-corner] [--vval FILE] [--report FILE.json]
//                 [--untangle | --no-untangle] [--max-untangle-change C] [--merge-cone-pairs]
//                 [--separate-cone-pairs] [--quantize] [--quiet]
//   seamless_snap [options] --outdir DIR IN.obj... [--summary FILE.md]
//
// Reads a triangle mesh with an approximately seamless per-corner UV map (OBJ, f v/vt), snaps the
// UVs to nearby doubles that are exactly seamless (Mandad & Campen 2019), checks the result in
// rational arithmetic and writes OUT atomically. Exit status 0 only when OUT was written and verified.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/IO/cut_mesh.h>
#include <CGAL/Seamless_snapping/IO/OBJ_matrices.h>
#include <CGAL/Seamless_snapping/IO/VVAL.h>
#include <CGAL/Seamless_snapping/matrices.h>
#include <CGAL/Seamless_snapping/version.h>
#include <CGAL/Seamless_snapping/is_exact_integer_grid_map.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/quad_valences.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <CGAL/Seamless_snapping/internal/io/command_line.h>
#include <CGAL/Seamless_snapping/internal/io/json_string.h>
#include <CGAL/Seamless_snapping/internal/io/retained_heap.h>
#include <CGAL/Seamless_snapping/internal/threads.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <charconv>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>
#include <iostream>
#include <sstream>
#include <string>

typedef CGAL::Simple_cartesian<double>                     K;
typedef K::Point_2                                         Point_2;
typedef K::Point_3                                         Point_3;
typedef CGAL::Surface_mesh<Point_3>                        Mesh;
typedef Mesh::Halfedge_index                               halfedge_descriptor;
typedef Mesh::Property_map<halfedge_descriptor, Point_2>   UV_map;

namespace SS = CGAL::Seamless_snapping;
using SS::IO::internal::json_string;
namespace params = CGAL::Seamless_snapping::parameters;

static const char* usage_text =
  "usage: seamless_snap IN.obj OUT.obj [--weld | --no-weld] [--keep-layout] [--no-align-boundary]\n"
  "                     [--unreduced] [--fail-on-new-flips] [--integer-grid] [--grid-scale S]\n"
  "                     [--features FILE] [--sharp-angle DEG] [--pin FILE] [--vt-per-corner]\n"
  "                     [--vval FILE] [--report FILE.json] [--untangle | --no-untangle]\n"
  "                     [--max-untangle-change C] [--merge-cone-pairs] [--separate-cone-pairs]\n"
  "                     [--quantize] [--threads N] [--quiet]\n"
  "       seamless_snap [options] --outdir DIR IN.obj... [--summary FILE.md]\n";

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
  "  --weld               merge vertices with bit-identical positions before snapping. 'Cut meshes'\n"
  "                       (e.g. libigl/Directional output) duplicate their vertices along the seams;\n"
  "                       read as they are, their seams are mesh borders and nothing gets snapped.\n"
  "                       Such an input is welded automatically (a line says so).\n"
  "  --no-weld            never weld; an input whose seams are then invisible is an error (exit 1)\n"
  "                       instead of 'already exactly seamless'\n"
  "  --keep-layout        write OUT.obj in the input's own layout: the same 'v' and 'vt' lines in the\n"
  "                       same order (only moved UVs change) and the same face indices; not with\n"
  "                       --integer-grid, --grid-scale, --features, --sharp-angle, --pin, --vt-per-corner\n"
  "  --fail-on-new-flips  exit 1 without writing OUT.obj when the snap leaves UV triangles flipped or\n"
  "                       degenerate that were positively oriented in the input\n"
  "  --no-align-boundary  do not make axis-parallel border edges exactly axis-parallel\n"
  "                       (by default, border edges within 1e-3 degrees of the u or v axis are aligned)\n"
  "  --unreduced          project the full sector system instead of the reduced node system\n"
  "                       (Sec. 5.3); much slower, for comparisons\n"
  "  --integer-grid       make it an exact integer-grid map (quad meshing, e.g. libQEx): every seam\n"
  "                       translation becomes the nearest integer vector, so every cone lands on\n"
  "                       an integer point, and aligned border edges lie on integer isolines.\n"
  "                       Refused (nothing written) when a translation is more than 1e-3 from an\n"
  "                       integer (use --grid-scale), when rounded translations contradict each\n"
  "                       other around a vertex, or when a cone's fixed point is not an integer\n"
  "                       point. The result is checked with is_exact_integer_grid_map().\n"
  "  --grid-scale S       the map's integer grid is at multiples of 1/S in UV (S a power of two,\n"
  "                       applied exactly); with --integer-grid, and the grid cell that\n"
  "                       --max-untangle-change and the report's changes in cells are measured in\n"
  "  --features FILE      feature edges to align (made exactly parallel to the u or v axis; with\n"
  "                       --integer-grid on integer isolines): one edge per line, two vertex indices\n"
  "                       separated by blanks, 0-based in the order of the mesh's vertices (the file's\n"
  "                       'v' lines when every vertex is used and --weld merges nothing); '#' starts a\n"
  "                       comment. Each edge must be within 1e-3 degrees of an axis in UV.\n"
  "  --sharp-angle DEG    also align every interior edge whose faces meet at a dihedral angle of more\n"
  "                       than DEG degrees (angle between the face normals)\n"
  "  --pin FILE           vertices whose UVs must not move (pinned_corner_map): one vertex index per\n"
  "                       line, 0-based as for --features, '#' starts a comment; every corner of the\n"
  "                       vertex keeps its UV bit for bit (with --integer-grid too). Refused (nothing\n"
  "                       written) when a pinned UV has bits below the exact snap's grid quantum or\n"
  "                       the pins contradict the constraints (the message names the corner).\n"
  "  --vt-per-corner      write one 'vt' per face corner (the layout libQEx's test meshes use)\n"
  "  --vval FILE          with --integer-grid: also write libQEx's vertex valence file (VVAL: a JSON\n"
  "                       header line, the vertex count, one integer per vertex in the order of\n"
  "                       OUT.obj's 'v' lines): the number of integer-grid directions leaving each\n"
  "                       vertex, counted exactly with sign tests (quad_valences()), which is its\n"
  "                       valence in the quad mesh that seamless_quad extracts. Refused (exit 1,\n"
  "                       nothing written) when the snapped map has fold-overs or zero-area UV\n"
  "                       triangles: no quad mesh has the valences next to them, and libQEx, which\n"
  "                       trusts the file, leaves holes there; run libQEx without a VVAL file, or\n"
  "                       make the map fold-free first. Refused too where a vertex has valence 1 (a\n"
  "                       cone of 90 degrees, or of 450 that the map winds back to 90, e.g. a cone\n"
  "                       pair put onto one integer point: --merge-cone-pairs). Written to its\n"
  "                       temporary file before OUT.obj and renamed after it: a VVAL file that cannot\n"
  "                       be written leaves OUT.obj unwritten.\n"
  "  --untangle           make every UV triangle positively oriented (remove fold-overs) by moving the UVs\n"
  "                       near them inside the space of maps with the same constraints (seam rotations,\n"
  "                       with --integer-grid integer translations and cone positions), then snap exactly;\n"
  "                       the default with --integer-grid. Triangles that the constraints force to be\n"
  "                       degenerate or flipped (e.g. two cones rounded onto one integer point) are\n"
  "                       reported with the proof, as are any left (the JSON report's 'folds')\n"
  "  --no-untangle        keep the input's fold-overs (the default without --integer-grid)\n"
  "  --max-untangle-change C  do not use an untangled map that moves a UV by more than C grid cells\n"
  "                       (then the snapped input is written, with its fold-overs reported)\n"
  "  --merge-cone-pairs   with --integer-grid: a 90 and a -90 degree cone that the rounded translations put\n"
  "                       onto one integer point (no locally injective map has them) become regular points\n"
  "                       of the field: the rotations and translations of the cut edges between them change\n"
  "                       (where that cut runs within one grid cell of the point, S at --grid-scale S > 1),\n"
  "                       as libQEx merges them.\n"
  "                       Other pairs on one point are then joined: one cone takes both indices (two 90 degree\n"
  "                       cones: valence 2, never less), the other becomes regular ('joined_cone_pairs').\n"
  "                       The report lists the pairs ('merged_cone_pairs'); seamless_quad does it by default\n"
  "  --separate-cone-pairs  with --integer-grid: two cones that the rounded translations put onto one integer\n"
  "                       point and that a cut within two grid cells of it (2 S at --grid-scale S > 1) joins\n"
  "                       are moved apart instead (after --merge-cone-pairs, if given), each onto a neighbouring\n"
  "                       integer point nearest its input position: the integer translations along that cut\n"
  "                       change, the field is kept. Where fold-overs are left near a pair, its other ways apart\n"
  "                       are tried (one more snap each, 'separation_trials') and the one with the fewest\n"
  "                       defects near it is kept. The report lists the pairs ('separated_cone_pairs'). A 90\n"
  "                       and a -90 degree cone move as one (merge those)\n"
  "  --quantize           with --integer-grid: a map that is not near an integer-grid map at this grid scale\n"
  "                       (its translations were never made integers, e.g. Directional's rot-seamless output)\n"
  "                       gets integer translations chosen for it instead of being refused: each cone onto\n"
  "                       an integer point next to it (of the four around it, the one that keeps the\n"
  "                       translations nearest the map's; with align edges, one on the isolines of the aligned\n"
  "                       chains through it, up to 2 cells away), the translations from those along the cut graph,\n"
  "                       rounded where it leaves a choice ('quantized' in the report). The map moves by up to\n"
  "                       a few grid cells; choose a --grid-scale whose cells are smaller than the distances\n"
  "                       between the cones\n"
  "  --report FILE.json   write the snap report as JSON to FILE.json (also when snapping fails)\n"
  "  --outdir DIR         several inputs: each IN.obj is snapped (with the same options) into DIR/IN.obj, its\n"
  "                       JSON report into DIR/IN.json (names by file stem: inputs must not share one), then a\n"
  "                       summary table (Markdown: status, faces, cones, nodes, read/snap/write times) is printed;\n"
  "                       exit status 0 only if every input was written and verified. One process, one input\n"
  "                       after the other; for several cores run one process per file (README, 'Many maps')\n"
  "  --summary FILE.md    with --outdir: also write the summary table to FILE.md\n"
  "  --threads N          threads for independent steps of the reading, the snap, the untangling, the\n"
  "                       verification and the output (the same output bits whatever N): 0, the default,\n"
  "                       takes the machine's cores; 1 runs on one thread\n"
  "  --quiet              print nothing but errors\n"
  "  --help               print this help\n"
  "\n"
  "Output: OUT.obj has one 'v' per vertex (after welding, if any), one 'vt' per vertex and\n"
  "distinct UV (or one per face corner, --vt-per-corner), and 'f v/vt' faces (with --keep-layout:\n"
  "the input's layout); each number is the shortest decimal that reads back to the same double.\n"
  "OUT.obj is written atomically (temporary file + rename; a file it replaces keeps its permissions): it\n"
  "is never left half written (a device, a named pipe or an open descriptor, e.g. /dev/stdout, is written\n"
  "directly, where the shell's redirection stands: `>> log` keeps log's lines; a symbolic link is followed,\n"
  "also to a target not created yet). The other files are written the same way. IN.obj may be a pipe\n"
  "(/dev/stdin), read once: a cut mesh (welded after a first read) and --keep-layout read it twice and are\n"
  "refused then (save it to a file). Normals, groups and materials are not carried over.\n"
  "The JSON report has the snap report's fields plus 'input', 'output' and 'version'.\n"
  "\n"
  "Exit status: 0 when OUT.obj was written and verified exactly seamless; 1 when reading,\n"
  "snapping, verifying or writing failed (one line on stderr says why; OUT.obj is then not\n"
  "created or changed); 2 for a command-line error.\n"
  "\n"
  "Environment: on Linux with glibc the program restarts itself once with a heap that keeps freed memory\n"
  "for reuse (GLIBC_TUNABLES, yours kept after it; on a 300K-face map about 10 % faster, the same output);\n"
  "SEAMLESS_SNAPPING_HEAP=default keeps the default heap.\n";

typedef Mesh::Property_map<Mesh::Edge_index, bool>       Edge_flags;
typedef Mesh::Property_map<Mesh::Halfedge_index, bool>   Halfedge_flags;

// A file of 0-based vertex indices, `per_line` of them per line ('#' starts a comment, blank lines are
// skipped): `use(indices, where)` per line, where = "file:line: " (it returns false with a message to
// stop). False with a message naming the line for a malformed line or an index out of range, and for a file that
// cannot be read to its end (a directory was read as an empty list).
template <class Use>
static bool read_vertex_index_lines(const std::string& file, const char* what, std::size_t per_line, const Mesh& m,
                                    const Use& use, std::string& message)
{
  std::ifstream is(file);
  if(!is) { message = "cannot open the " + std::string(what) + " file '" + file + "'"; return false; }
  std::string line;
  std::size_t no = 1;
  for(; std::getline(is, line); ++no) {
    line = line.substr(0, line.find('#'));
    std::istringstream ls(line);
    std::vector<std::string> tokens;
    for(std::string token; ls >> token;) tokens.push_back(token);
    if(tokens.empty()) continue;                              // blank or comment line
    const std::string where = file + ":" + std::to_string(no) + ": ";
    if(tokens.size() != per_line) {
      message = where + (per_line == 1 ? "expected one vertex index" : "expected " + std::to_string(per_line) + " vertex indices");
      return false;
    }
    std::vector<long long> idx;
    for(const std::string& token : tokens) {                  // the whole token, a decimal integer in range
      long long i = 0;
      const std::from_chars_result r = std::from_chars(token.data(), token.data() + token.size(), i);
      if(r.ec != std::errc() || r.ptr != token.data() + token.size() || i < 0 || i >= (long long)m.number_of_vertices()) {
        message = where + "'" + token.substr(0, 40) + "' is not a vertex index (0 to " + std::to_string(m.number_of_vertices()) +
                  " - 1: the mesh has " + std::to_string(m.number_of_vertices()) + " vertices)";
        return false;
      }
      idx.push_back(i);
    }
    if(!use(idx, where)) return false;
  }
  if(is.bad()) {                             // a directory (EISDIR), an I/O error: as the OBJ reader says it
    message = "cannot read the " + std::string(what) + " file '" + file + "': read error after line " + std::to_string(no - 1);
    return false;
  }
  return true;
}

// --features FILE: one edge per line, "i j" (0-based vertex indices); a pair that is no edge is refused.
static bool read_feature_edges(const std::string& file, const Mesh& m, Edge_flags features, std::size_t& count,
                               std::string& message)
{
  count = 0;
  return read_vertex_index_lines(file, "feature", 2, m, [&](const std::vector<long long>& i, const std::string& where) {
    const auto h = m.halfedge(Mesh::Vertex_index(Mesh::size_type(i[0])), Mesh::Vertex_index(Mesh::size_type(i[1])));
    if(h == Mesh::null_halfedge()) {
      message = where + "vertices " + std::to_string(i[0]) + " and " + std::to_string(i[1]) + " are not joined by an edge";
      return false;
    }
    put(features, m.edge(h), true);
    ++count;
    return true;
  }, message);
}

// --pin FILE: one vertex per line (0-based index); every corner of the vertex is pinned
static bool read_pinned_vertices(const std::string& file, const Mesh& m, Halfedge_flags pinned, std::size_t& count,
                                 std::string& message)
{
  count = 0;
  return read_vertex_index_lines(file, "pin", 1, m, [&](const std::vector<long long>& i, const std::string&) {
    const Mesh::Vertex_index v = Mesh::Vertex_index(Mesh::size_type(i[0]));
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_target(v, m))
      if(!m.is_border(h)) put(pinned, h, true);
    ++count;
    return true;
  }, message);
}

// --sharp-angle DEG: interior edges whose face normals differ by more than DEG degrees
static std::size_t mark_sharp_edges(const Mesh& m, double degrees, Edge_flags features)
{
  std::size_t n = 0;
  const double cos_limit = std::cos(degrees * CGAL_PI / 180);
  for(Mesh::Edge_index e : m.edges()) {
    if(m.is_border(e)) continue;
    const K::Vector_3 a = CGAL::Polygon_mesh_processing::compute_face_normal(m.face(m.halfedge(e, 0)), m);
    const K::Vector_3 b = CGAL::Polygon_mesh_processing::compute_face_normal(m.face(m.halfedge(e, 1)), m);
    if(a * b < cos_limit && !get(features, e)) { put(features, e, true); ++n; }
  }
  return n;
}

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

static bool read_mesh(const std::string& in, bool weld, unsigned threads, Mesh& mesh, UV_map& uv, std::string& message)
{
  mesh = Mesh();
  uv = mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0, 0)).first;
  return SS::IO::read_OBJ_with_corner_uvs(in, mesh, uv, message, params::weld_vertices(weld).number_of_threads(threads))
         == SS::SUCCESS;
}

// The options of a run (one input, or each input of --outdir).
struct Options
{
  bool weld = false, no_weld = false, keep_layout = false, fail_on_new_flips = false;
  bool align_boundary = true, reduced = true, quiet = false;
  bool integer_grid = false, merge_cone_pairs = false, separate_cone_pairs = false, quantize = false;
  int untangle = -1;                 // -1: the default (with --integer-grid)
  double grid_scale = 1, max_untangle_change = HUGE_VAL;
  bool vt_per_corner = false;
  unsigned threads = 0;              // 0: the machine's cores
  std::string features_file, vval_file, pin_file;
  double sharp_angle = -1;
};

// One line of the --outdir summary.
struct Summary_row
{
  std::string input, status = "not run", message;
  std::size_t faces = 0, cones = 0, nodes = 0, flips = 0;
  double read_ms = 0, snap_ms = 0, write_ms = 0, total_ms = 0;
};

typedef std::chrono::steady_clock Clock;
static double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// Snaps `in` into `out` (and the JSON report into `report_file` if not empty): steps 1-4 of the header.
// Returns the exit status; fills `row` when given.
static int snap_file(const Options& options, const std::string& in, const std::string& out, const std::string& report_file,
                     Summary_row* row)
{
  Options o = options;
  bool& weld = o.weld;
  const bool no_weld = o.no_weld, keep_layout = o.keep_layout, fail_on_new_flips = o.fail_on_new_flips;
  const bool align_boundary = o.align_boundary, reduced = o.reduced, quiet = o.quiet, integer_grid = o.integer_grid;
  const int untangle = o.untangle;
  const double grid_scale = o.grid_scale, max_untangle_change = o.max_untangle_change, sharp_angle = o.sharp_angle;
  const bool vt_per_corner = o.vt_per_corner, has_report = !report_file.empty();
  const std::string& features_file = o.features_file;
  const std::string& vval_file = o.vval_file;
  const std::string& pin_file = o.pin_file;
  Summary_row scratch_row;
  Summary_row& R = row != nullptr ? *row : scratch_row;
  R.input = in;
  const Clock::time_point t_start = Clock::now();
  bool report_written = false;
  const SS::Snap_report* snapped = nullptr;   // the snap's report, once it ran
  // "output": OUT, or null where the run failed (nothing written)
  auto write_report = [&](const SS::Snap_report& report, std::string& message, bool failed) {
    report_written = true;
    std::string json = report.to_json();
    json.insert(json.find('{') + 1, "\n  \"input\": " + json_string(in) + ",\n  \"output\": " +
                                    (failed ? std::string("null") : json_string(out)) +
                                    ",\n  \"version\": " + json_string(CGAL_SEAMLESS_SNAPPING_VERSION) + ",");
    return SS::IO::internal::write_text_atomically(report_file, json, message) == SS::SUCCESS;
  };
  // The report says why the run failed: before the snap ran (the input or a file of an option), or after a snap that
  // succeeded (a refused --vval or --fail-on-new-flips, a failed verification or write), where the report already
  // written said SUCCESS: `status` becomes `st` and the message says why, the snap's own message after it
  auto fail = [&](const std::string& why, SS::Status st = SS::INVALID_INPUT) {
    R.status = "FAILED";
    R.message = one_line(why);
    R.total_ms = ms_since(t_start);
    if(has_report && (!report_written || (snapped != nullptr && snapped->status == SS::SUCCESS))) {
      SS::Snap_report failed = snapped != nullptr ? *snapped : SS::Snap_report();
      failed.status = st;
      failed.message = why + (snapped != nullptr ? "; the snap itself: " + snapped->message : std::string());
      std::string message;
      if(!write_report(failed, message, true)) ::fail(message);
    }
    return ::fail(why);
  };

  // 1. read; the corner map: uv[h] = UV of target(h) in face(h). A cut mesh is welded unless --no-weld.
  Mesh mesh;
  UV_map uv;
  std::string message;
  Clock::time_point t = Clock::now();
  const auto read = SS::IO::internal::read_again_checked(in, [&](bool w, std::string& m) {
    return read_mesh(in, w, o.threads, mesh, uv, m);
  });
  const SS::IO::Welding_read wr = SS::IO::read_welding_cut_meshes(mesh, weld, no_weld, message, read);
  if(!wr.ok) return fail("cannot read input: " + message);
  const SS::IO::Cut_mesh_test& cut = wr.cut;
  const bool cut_mesh = cut.is_cut_mesh();
  if(!quiet && !wr.note(weld).empty()) std::cout << wr.note(weld) << "\n";
  weld = wr.welded;
  if(!quiet) std::cout << message << "\n";
  R.read_ms = ms_since(t);

  // feature edges (aligned like border edges; an empty map aligns nothing more)
  Edge_flags features = mesh.add_property_map<Mesh::Edge_index, bool>("e:feature", false).first;
  if(!features_file.empty()) {
    std::size_t n = 0;
    if(!read_feature_edges(features_file, mesh, features, n, message)) return fail(message);
    if(!quiet) std::cout << n << " feature edges read from " << features_file << "\n";
  }
  Halfedge_flags pinned = mesh.add_property_map<Mesh::Halfedge_index, bool>("h:pinned", false).first;
  if(!pin_file.empty()) {
    std::size_t n = 0;
    if(!read_pinned_vertices(pin_file, mesh, pinned, n, message)) return fail(message);
    if(!quiet) std::cout << n << " pinned vertices read from " << pin_file << "\n";
  }
  if(sharp_angle >= 0) {
    const std::size_t n = mark_sharp_edges(mesh, sharp_angle, features);
    if(!quiet) std::cout << n << " sharp edges (dihedral angle > " << sharp_angle << " degrees) to align\n";
  }

  // 2. snap (writes the UVs only on success); with --keep-layout through the matrix entry point,
  //    which keeps the input's v/vt layout
  Eigen::MatrixXd V, UV, UV_out;
  Eigen::MatrixXi F, FUV, FUV_out;
  if(keep_layout && (!SS::IO::internal::can_read_again(in, "--keep-layout", message) ||
                     SS::IO::read_OBJ_matrices(in, V, F, UV, FUV, message) != SS::SUCCESS))
    return fail("cannot read input: " + message);
  const auto np = params::weld_vertices(weld).use_reduced_system(reduced).align_boundary(align_boundary)
                     .integer_grid_map(integer_grid).grid_scale(grid_scale)
                     .untangle(untangle < 0 ? integer_grid : untangle == 1).max_untangle_change(max_untangle_change)
                     .merge_cone_pairs(o.merge_cone_pairs).separate_cone_pairs(o.separate_cone_pairs)
                     .quantize(o.quantize).number_of_threads(o.threads);
  t = Clock::now();
  const SS::Snap_report report = keep_layout ? SS::snap_seamless_parameterization(V, F, UV, FUV, UV_out, FUV_out, np)
                                             : SS::snap_seamless_parameterization(mesh, uv, np.edge_is_constrained_map(features)
                                                                                               .pinned_corner_map(pinned));
  R.snap_ms = ms_since(t);
  R.faces = report.faces; R.cones = report.cones; R.nodes = report.nodes; R.flips = report.flips_after_repair;
  if(!quiet) {
    const bool say = report.status == SS::SUCCESS && !report.message.empty();   // a failure's reason: the stderr line below
    std::printf("snap: %s (%.1f ms)%s%s\n", SS::status_name(report.status), report.total_ms, say ? ": " : "",
                say ? one_line(report.message).c_str() : "");
    std::printf("  %zu faces, %zu cut edges, %zu cones, %zu sectors (%zu constrained), %zu align edges\n",
                report.faces, report.cut_edges, report.cones, report.sectors, report.constrained_sectors, report.align_edges);
    if(report.system_rows > 0)           // built (a refusal may come before)
      std::printf("  %s system: %zu rows x %zu columns, %zu free, %zu implied, max |IRREF entry| %s\n",
                  report.reduced ? "node" : "full", report.system_rows, report.system_columns,
                  report.free_variables, report.implied_variables, report.max_abs_coefficient.c_str());
    if(report.status == SS::SUCCESS) {   // after a refusal nothing was snapped: no change, no counts after it
      std::printf("  relative to the UV diagonal %.6g: input violation %.3g, max change %.3g, mean change %.3g\n",
                  report.uv_diagonal, report.max_input_violation, report.max_change, report.mean_change);
      std::printf("  UV triangles negative / zero-area: input %zu / %zu, after snapping %zu / %zu, after repair %zu / %zu;"
                  " introduced and left %zu / %zu\n", report.flips_before, report.degenerate_before, report.flips_after,
                  report.degenerate_after, report.flips_after_repair, report.degenerate_after_repair,
                  report.flips_unrepaired, report.degenerate_unrepaired);
    }
    if(report.untangled)
      std::printf("  untangling: negative / zero-area %zu / %zu -> %zu / %zu (floating point, %d ring(s), %zu sectors moved, "
                  "max %.3g / RMS %.3g grid cells beyond the snap's %.3g) -> %zu / %zu after its exact snap (%.1f ms: %zu "
                  "optimization(s) with %zu Newton iterations, polish %zu)\n",
                  report.flips_before_untangling, report.degenerate_before_untangling, report.flips_after_untangling,
                  report.degenerate_after_untangling, report.untangle_rings, report.untangle_moved_sectors,
                  report.untangle_max_change * report.grid_scale, report.untangle_rms_change * report.grid_scale,
                  report.snap_max_change * report.grid_scale, report.flips_after, report.degenerate_after, report.untangle_ms,
                  report.untangle_attempts, report.untangle_newton_steps, report.untangle_polish_steps);
    if(!report.folds.empty())
      std::printf("  %zu UV triangles not positive at the end, %zu of them proven forced by the constraints "
                  "(first: face %zu: %s)\n", report.folds.size(), report.folds_forced, report.folds.front().face,
                  report.folds.front().message.c_str());
    if(report.status == SS::SUCCESS)
      std::printf("  integer grid: %zu -> %zu of %zu cut edges with integer translations, %zu -> %zu of %zu cones "
                "on integer points\n", report.integer_translations_before, report.integer_translations_after,
                report.cut_edges, report.cones_on_integer_points_before, report.cones_on_integer_points_after,
                report.field_cones);
  }
  if(!integer_grid && report.near_integer_grid_map && !quiet)
    std::cout << "note: the input looks like an integer-grid map (every seam translation, cone and align edge within 1e-6 "
              << "of integers); use --integer-grid to keep it one exactly (quad extraction, e.g. libQEx)\n";
  if(!integer_grid && report.status == SS::SUCCESS &&
     report.cones_on_integer_points_after < report.cones_on_integer_points_before)
    std::cerr << "seamless_snap: warning: " << report.cones_on_integer_points_before - report.cones_on_integer_points_after
              << " cones that were exactly on integer points moved off them; --integer-grid keeps them\n";
  if(has_report) {
    if(!write_report(report, message, report.status != SS::SUCCESS)) return fail(message);
    if(!quiet) std::cout << "report written to " << report_file << "\n";
  }
  snapped = &report;
  if(report.status != SS::SUCCESS)
    return fail(std::string("snapping failed: ") + SS::status_name(report.status) + ": " + report.message);
  if(report.cut_edges == 0 && cut_mesh && no_weld)   // (welded automatically, a map without cut edges is one chart)
    return fail("no seam is visible: the input looks like a cut mesh (" + std::to_string(cut.twinned) + " of " +
                std::to_string(cut.border_edges) + " border edges lie on another one at bit-identical 3D points) and --no-weld keeps its seams as "
                "borders; nothing was snapped and nothing was written");
  if(fail_on_new_flips && report.flips_unrepaired + report.degenerate_unrepaired > 0)
    return fail("--fail-on-new-flips: " + std::to_string(report.flips_unrepaired) + " flipped and " +
                std::to_string(report.degenerate_unrepaired) + " degenerate UV triangles introduced and not repaired; "
                "nothing was written", SS::FOLD_OVERS);

  // 3. verify independently, in rational arithmetic; 4. write atomically. The VVAL file is written first, to its
  //    temporary file, and renamed only after OUT.obj was: a VVAL file that cannot be written leaves no OUT.obj behind
  //    (a device or pipe such as /dev/stdout, which cannot be replaced, is written at once; a rename of the VVAL file
  //    failing after OUT.obj's, in the same directory, would leave OUT.obj). With two threads or more, the OBJ text is
  //    written to the temporary file while the map is verified, and the file becomes OUT.obj only if it is
  //    (write_atomically(); the 302K-face bunny: verification 28 ms, writing 80-90 ms)
  t = Clock::now();
  SS::Quad_valences valences;
  SS::IO::internal::Atomic_file vval;        // its temporary file is removed unless committed
  if(!vval_file.empty()) {
    valences = SS::quad_valences(mesh, uv);
    if(valences.status != SS::SUCCESS)
      return fail("--vval: " + std::string(SS::status_name(valences.status)) + ": " + valences.message +
                  (valences.status == SS::FOLD_OVERS ? " (libQEx does better without a VVAL file here); nothing was written" : ""),
                  valences.status);
    std::string text;
    if(SS::IO::internal::vval_text(valences.valence, text, message) != SS::SUCCESS ||
       vval.prepare(vval_file, SS::IO::internal::text_writer(text), message) != SS::SUCCESS)
      return fail("--vval: " + message + "; nothing was written");
  }
  bool checked = false, exact = false, grid_exact = true;
  auto verify = [&] {
    checked = true;
    exact = keep_layout ? SS::is_exactly_seamless(V, F, UV_out, FUV_out, params::weld_vertices(weld))
                        : SS::is_exactly_seamless(mesh, uv, params::edge_is_constrained_map(features));
    if(exact && integer_grid && !keep_layout)
      grid_exact = SS::is_exact_integer_grid_map(mesh, uv, params::grid_scale(grid_scale).edge_is_constrained_map(features));
  };
  auto verification_failure = [&] {
    return fail(!exact ? "verification failed: the snapped map is not exactly seamless (internal error; please report)"
                       : "verification failed: the snapped map is not exactly an integer-grid map (internal error; please report)",
                SS::EXACTNESS_CHECK_FAILED);
  };
  auto verified = [&] {
    if(quiet) return;
    std::cout << "verified: every seam transition holds exactly\n";
    if(integer_grid && !keep_layout) std::cout << "verified: integer translations on every cut edge, every cone on an integer point\n";
  };
  const auto write_np = params::vt_per_corner(vt_per_corner).number_of_threads(o.threads);
  SS::Status written = SS::INVALID_INPUT;
  if(keep_layout || SS::internal::resolve_number_of_threads(o.threads) < 2) {
    verify();
    if(!exact || !grid_exact) return verification_failure();
    verified();
    written = keep_layout ? SS::IO::write_OBJ_matrices(out, V, F, UV_out, FUV_out, message)
                          : SS::IO::write_OBJ_with_corner_uvs(out, mesh, uv, message, write_np);
  } else {
    std::string summary;
    SS::Status text_written = SS::INVALID_INPUT;
    written = SS::IO::internal::write_atomically(out, [&](std::ostream& os) {
      SS::internal::run_concurrently(2, verify, [&] { text_written = SS::IO::write_OBJ_with_corner_uvs(os, mesh, uv, summary, write_np); });
      return text_written == SS::SUCCESS && exact && grid_exact;   // else the temporary file is removed
    }, message);
    if(!checked) verify();                                           // the temporary file could not be created
    if(!exact || !grid_exact) return verification_failure();
    verified();
    if(written == SS::SUCCESS) message = summary + " to " + out;
    else if(text_written != SS::SUCCESS && !summary.empty()) message += " (" + summary + ")";
  }
  if(written != SS::SUCCESS) return fail(message);
  if(!quiet) std::cout << message << "\n";
  if(!vval_file.empty()) {
    if(vval.commit(message) != SS::SUCCESS) return fail(message);
    message = SS::IO::internal::vval_written(valences.valence, vval_file);
    if(!quiet) {
      std::vector<char> on_border(valences.valence.size(), 0);
      for(std::size_t v : valences.border) on_border[v] = 1;
      std::size_t cones = 0;
      for(std::size_t v = 0; v < valences.valence.size(); ++v) cones += !on_border[v] && valences.valence[v] != 4 ? 1 : 0;
      std::cout << message << ": " << cones << " interior vertices with a valence other than 4; " << valences.border.size()
                << " border vertices (valence: the grid directions in their fan; libQEx ignores them)\n";
    }
  }
  R.write_ms = ms_since(t);
  R.total_ms = ms_since(t_start);
  R.status = "SUCCESS";
  R.message.clear();
  return EXIT_SUCCESS;
}

// --outdir: the summary table (Markdown), to `os`
static void write_summary(std::ostream& os, const std::vector<Summary_row>& rows)
{
  os << "| input | status | faces | cones | nodes | negative UV triangles | read ms | snap ms | verify+write ms | total ms | message |\n"
     << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  char b[512];
  std::size_t ok = 0;
  double total = 0;
  auto cell = [](const std::string& text) {         // a '|' in a file name or message would end the cell
    std::string c;
    for(char x : text) { if(x == '|') c += '\\'; c += x; }
    return c;
  };
  for(const Summary_row& r : rows) {
    std::snprintf(b, sizeof b, " | %s | %zu | %zu | %zu | %zu | %.1f | %.1f | %.1f | %.1f | ", r.status.c_str(),
                  r.faces, r.cones, r.nodes, r.flips, r.read_ms, r.snap_ms, r.write_ms, r.total_ms);
    os << "| " << cell(r.input) << b << cell(r.message.substr(0, 200)) << " |\n";
    ok += r.status == "SUCCESS" ? 1 : 0;
    total += r.total_ms;
  }
  std::snprintf(b, sizeof b, "\n%zu of %zu inputs snapped exactly; %.1f s in all\n", ok, rows.size(), total / 1000);
  os << b;
}

int main(int argc, char** argv)
{
  CGAL::Seamless_snapping::IO::internal::use_retained_heap(argv);   // large maps: see the header
  std::string in, out, report_file, outdir, summary_file;
  std::vector<std::string> inputs;
  Options o;
  bool& weld = o.weld; bool& no_weld = o.no_weld; bool& keep_layout = o.keep_layout;
  bool& fail_on_new_flips = o.fail_on_new_flips; bool& align_boundary = o.align_boundary; bool& reduced = o.reduced;
  bool& quiet = o.quiet; bool& integer_grid = o.integer_grid; int& untangle = o.untangle; double& grid_scale = o.grid_scale;
  double& max_untangle_change = o.max_untangle_change; bool& vt_per_corner = o.vt_per_corner;
  std::string& features_file = o.features_file; std::string& vval_file = o.vval_file; std::string& pin_file = o.pin_file;
  double& sharp_angle = o.sharp_angle;
  bool has_report = false;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--help" || a == "-h") { std::cout << usage_text << "\n" << help_text; return EXIT_SUCCESS; }
    else if(a == "--weld") weld = true;
    else if(a == "--no-weld") no_weld = true;
    else if(a == "--keep-layout") keep_layout = true;
    else if(a == "--fail-on-new-flips") fail_on_new_flips = true;
    else if(a == "--no-align-boundary") align_boundary = false;
    else if(a == "--unreduced") reduced = false;
    else if(a == "--quiet") quiet = true;
    else if(a == "--integer-grid") integer_grid = true;
    else if(a == "--untangle") untangle = untangle == 0 ? 2 : 1;
    else if(a == "--no-untangle") untangle = untangle == 1 ? 2 : 0;
    else if(a == "--merge-cone-pairs") o.merge_cone_pairs = true;
    else if(a == "--separate-cone-pairs") o.separate_cone_pairs = true;
    else if(a == "--quantize") o.quantize = true;
    else if(a == "--max-untangle-change") {
      if(i + 1 >= argc || !SS::IO::internal::parse_number(argv[i + 1], max_untangle_change) || !(max_untangle_change >= 0)) {
        std::cerr << "seamless_snap: --max-untangle-change needs a number of grid cells >= 0\n" << usage_text; return 2;
      }
      ++i;
    }
    else if(a == "--vt-per-corner") vt_per_corner = true;
    else if(a == "--threads") {
      unsigned long long n = 0;
      if(i + 1 >= argc || !SS::IO::internal::parse_count(argv[i + 1], 1024, n)) {
        std::cerr << "seamless_snap: --threads needs a number of threads in [0, 1024]\n" << usage_text; return 2;
      }
      o.threads = unsigned(n);
      ++i;
    }
    else if(a == "--pin") {
      if(!SS::IO::internal::file_name_follows(argc, argv, i)) { std::cerr << "seamless_snap: --pin needs a file name\n" << usage_text; return 2; }
      pin_file = argv[++i];
    }
    else if(a == "--vval") {
      if(!SS::IO::internal::file_name_follows(argc, argv, i)) { std::cerr << "seamless_snap: --vval needs a file name\n" << usage_text; return 2; }
      vval_file = argv[++i];
    }
    else if(a == "--features") {
      if(!SS::IO::internal::file_name_follows(argc, argv, i)) { std::cerr << "seamless_snap: --features needs a file name\n" << usage_text; return 2; }
      features_file = argv[++i];
    }
    else if(a == "--sharp-angle") {
      if(i + 1 >= argc || !SS::IO::internal::parse_number(argv[i + 1], sharp_angle) || !(sharp_angle >= 0 && sharp_angle <= 180)) {
        std::cerr << "seamless_snap: --sharp-angle needs an angle in degrees in [0, 180]\n" << usage_text; return 2;
      }
      ++i;
    }
    else if(a == "--grid-scale") {
      if(i + 1 >= argc || !SS::IO::internal::parse_grid_scale(argv[i + 1], grid_scale)) {
        std::cerr << "seamless_snap: --grid-scale needs a power of two (1, 2, 4, 0.5, ...)\n" << usage_text; return 2;
      }
      ++i;
    }
    else if(a == "--outdir") {
      if(!SS::IO::internal::file_name_follows(argc, argv, i)) { std::cerr << "seamless_snap: --outdir needs a directory\n" << usage_text; return 2; }
      outdir = argv[++i];
    }
    else if(a == "--summary") {
      if(!SS::IO::internal::file_name_follows(argc, argv, i)) { std::cerr << "seamless_snap: --summary needs a file name\n" << usage_text; return 2; }
      summary_file = argv[++i];
    }
    else if(a == "--report") {
      if(!SS::IO::internal::file_name_follows(argc, argv, i)) { std::cerr << "seamless_snap: --report needs a file name\n" << usage_text; return 2; }
      report_file = argv[++i]; has_report = true;
    }
    else if(a.size() > 1 && a[0] == '-') { std::cerr << "seamless_snap: unknown option '" << a << "'\n" << usage_text; return 2; }
    else inputs.push_back(a);
  }
  if(!outdir.empty()) {   // several inputs, one summary
    if(inputs.empty()) { std::cerr << "seamless_snap: --outdir needs at least one input\n" << usage_text; return 2; }
    if(has_report || !vval_file.empty()) {
      std::cerr << "seamless_snap: with --outdir every input gets OUTDIR/NAME.json; --report and --vval name one file\n" << usage_text;
      return 2;
    }
  } else {
    if(!summary_file.empty()) { std::cerr << "seamless_snap: --summary needs --outdir\n" << usage_text; return 2; }
    if(inputs.size() > 2) { std::cerr << "seamless_snap: unexpected argument '" << inputs[2] << "' (several inputs: --outdir)\n" << usage_text; return 2; }
    if(inputs.size() == 2) { in = inputs[0]; out = inputs[1]; }
  }
  if(outdir.empty() && (in.empty() || out.empty())) { std::cerr << usage_text << "(--help for details)\n"; return 2; }
  if(keep_layout && (integer_grid || grid_scale != 1 || !features_file.empty() || sharp_angle >= 0 || vt_per_corner ||
                     !pin_file.empty())) {
    std::cerr << "seamless_snap: --keep-layout does not combine with --integer-grid, --grid-scale, --features, "
                 "--sharp-angle, --pin or --vt-per-corner (not supported yet)\n" << usage_text;
    return 2;
  }
  if(!vval_file.empty() && !integer_grid) {
    std::cerr << "seamless_snap: --vval needs --integer-grid (valences are those of an integer-grid map)\n" << usage_text;
    return 2;
  }
  if(weld && no_weld) { std::cerr << "seamless_snap: --weld and --no-weld exclude each other\n" << usage_text; return 2; }
  const std::string same = SS::IO::internal::same_output_file({{"OUT", out}, {"--report", report_file}, {"--vval", vval_file},
                                                               {"--summary", summary_file}});
  if(!same.empty()) { std::cerr << "seamless_snap: " << same << "\n" << usage_text; return 2; }
  // a report or VVAL file naming the input replaced the map (OUT = IN snaps the file in place: allowed)
  const std::string over_input = SS::IO::internal::same_output_file({{"IN", in}, {"--report", report_file},
                                                                     {"--vval", vval_file}});
  if(!over_input.empty()) { std::cerr << "seamless_snap: " << over_input << "\n" << usage_text; return 2; }
  if(untangle == 2) { std::cerr << "seamless_snap: --untangle and --no-untangle exclude each other\n" << usage_text; return 2; }
  if(o.merge_cone_pairs && !integer_grid) {
    std::cerr << "seamless_snap: --merge-cone-pairs needs --integer-grid (cones are merged on integer points)\n" << usage_text;
    return 2;
  }
  if(o.quantize && !integer_grid) {
    std::cerr << "seamless_snap: --quantize needs --integer-grid (it chooses integer translations)\n" << usage_text;
    return 2;
  }
  if(o.separate_cone_pairs && !integer_grid) {
    std::cerr << "seamless_snap: --separate-cone-pairs needs --integer-grid (cones are moved between integer points)\n" << usage_text;
    return 2;
  }

  if(outdir.empty()) return snap_file(o, in, out, has_report ? report_file : std::string(), nullptr);
  // --outdir: each input to OUTDIR/NAME.obj with its report OUTDIR/NAME.json, then the summary table
  auto result_stem = [&](const std::string& input) {   // OUTDIR/NAME, NAME the input's file stem
    return (std::filesystem::path(outdir) / std::filesystem::path(input).stem()).string();
  };
  std::vector<std::pair<std::string, std::string> > written{{"--summary", summary_file}};
  for(const std::string& input : inputs) {            // two inputs of one name, or --summary on a report, would overwrite
    written.emplace_back("the result of '" + input + "'", result_stem(input) + ".obj");
    written.emplace_back("the report of '" + input + "'", result_stem(input) + ".json");
  }
  const std::string clash = SS::IO::internal::same_output_file(written);
  if(!clash.empty()) {
    std::cerr << "seamless_snap: --outdir: " << clash << " (each input's results are OUTDIR/NAME.obj and OUTDIR/NAME.json, "
              << "NAME its file name without extension); nothing was written\n";
    return 2;
  }
  // the summary or a report naming an input replaced that map (exit 0); a result over its own input is a snap in place.
  // The inputs first: same_output_file() names the later of two as the one that would replace the earlier
  std::vector<std::pair<std::string, std::string> > over_inputs;
  for(const std::string& input : inputs) over_inputs.emplace_back("the input '" + input + "'", input);
  over_inputs.emplace_back("--summary", summary_file);
  for(const std::string& input : inputs) over_inputs.emplace_back("the report of '" + input + "'", result_stem(input) + ".json");
  const std::string over_an_input = SS::IO::internal::same_output_file(over_inputs);
  if(!over_an_input.empty()) { std::cerr << "seamless_snap: --outdir: " << over_an_input << "; nothing was written\n"; return 2; }
  // a --summary that cannot be written: refused before any input is snapped (its directory may be OUTDIR, made below)
  std::string why;
  const std::filesystem::path summary_dir = std::filesystem::path(summary_file).parent_path();
  const bool in_outdir = !summary_file.empty() && SS::IO::internal::comparable_path(summary_dir.empty() ? std::string(".")
                                                    : summary_dir.string()) == SS::IO::internal::comparable_path(outdir);
  if(!summary_file.empty() && !in_outdir && !SS::IO::internal::can_create(summary_file, why))
    return fail("--summary: " + why + "; nothing was written");
  std::error_code ec;
  std::filesystem::create_directories(outdir, ec);
  if(!std::filesystem::is_directory(outdir)) return fail("cannot create the output directory '" + outdir + "'");
  std::vector<Summary_row> rows(inputs.size());
  int status = EXIT_SUCCESS;
  for(std::size_t i = 0; i < inputs.size(); ++i) {
    const std::string obj = result_stem(inputs[i]) + ".obj", json = result_stem(inputs[i]) + ".json";
    if(!quiet) std::cout << "== " << inputs[i] << " -> " << obj << "\n";
    if(snap_file(o, inputs[i], obj, json, &rows[i]) != EXIT_SUCCESS) status = EXIT_FAILURE;
  }
  if(!quiet) {                                        // --quiet: nothing but errors (the table is in --summary)
    std::cout << "\n";
    write_summary(std::cout, rows);
  }
  if(!summary_file.empty()) {
    std::ostringstream table;
    write_summary(table, rows);
    std::string message;
    if(SS::IO::internal::write_text_atomically(summary_file, table.str(), message) != SS::SUCCESS) return fail(message);
  }
  return status;
}
