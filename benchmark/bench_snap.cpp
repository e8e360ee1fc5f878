// Timing of snap_seamless_parameterization() per model, one row per model like Table 1 of
// Mandad & Campen 2019: sizes, phase times of the reduced pipeline (Sec. 5.3.1), the time ratio of
// the unreduced (full sector system) to the reduced pipeline, input violation, change, flips.
//
// usage: bench_snap [--repeat N] [--connections] [--subdivide L] [--change] [--integer-grid] [--untangle] [--large]
//                   [--threads N] [--max-reference-faces F] <file.obj | directory>...
//        (directories are searched recursively for *.obj; files under a "directional" folder are read
//        with weld_vertices(true), as Directional writes cut meshes). Without arguments the directory
//        in the environment variable SS_SHARED_DATA_DIR is used.
// Times are wall clock in ms, the minimum over N runs (default 3). Lengths are relative to the UV
// bounding-box diagonal. Not part of the test run.
//
// Scale (issue 26): everything runs on ../shared/large (300K faces, 2530 cones) within a few minutes. The parts
// that do not scale are bounded and say so in their output: the L2 reference of --change (a sparse QR of C^T,
// test/Seamless_snapping/l2_optimum_reference.h; it did not finish in 15 minutes on the 300K-face bunny and grew
// to 4.9 GB) is skipped above --max-reference-faces F faces (default 100000), with a line naming the model.
//
// --large: instead, the table of issue 26 per model: faces, cones, nodes, the OBJ read time, the snap's phases
// (report times), the snap time per face, the OBJ write time, snap / read, and the peak RSS of the read, the snap
// and the write (each phase's own peak: the kernel's high-water mark is reset before it through
// /proc/self/clear_refs where Linux allows it, else the peak so far is printed with a '+'). Wall clock in ms, the
// minimum over N runs (default 3); CPU columns: the process's CPU time of the same phase (the machine may be shared).
// --threads N: the read, the snap and the write with number_of_threads(N) (default 1; the CPU columns then add up the
// threads); with --untangle, both snaps of each row.
//
// After the timing table (or alone with --change): the size of the change against the smallest exact
// change u* = argmin ||u - ubar||_2 s.t. C u = 0 over the same sector system (Eq. 4 per cut edge,
// alignment rows), computed independently of the package (exact residual, sparse QR of C^T:
// test/Seamless_snapping/l2_optimum_reference.h), for the paper's mode (minimal_change(false)) and the
// default minimal-change mode; targets of issue 10 per model and the median.
//
// --connections: instead, the stress study of Table 3 / Fig. 2: per model, 0, 10, 20, 50 and 100 random
// connection constraints (Eq. 6) between pairs of cones (shortest edge paths, random component; seed
// fixed per model and count, so the table is reproducible) are added; per count: the size of the node
// system, the maximum |entry| of its IRREF C^ (Table 3), the IRREF time (Fig. 2, minimum over N runs),
// and whether the result is exact: SUCCESS (whose final check evaluates every row, connection rows
// included, in exact arithmetic), is_exactly_seamless(), and every connection re-checked by an
// independent exact (Gmpq) unfolding along its path (test/Seamless_snapping/connection_test_utils.h).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/is_exact_integer_grid_map.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <CGAL/Seamless_snapping/internal/io/retained_heap.h>

#include "obj_inputs.h"
#include "../test/Seamless_snapping/connection_test_utils.h"
#include "../test/Seamless_snapping/l2_optimum_reference.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <ctime>
#include <fstream>
#include <functional>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef Mesh::Property_map<Mesh::Halfedge_index, K::Point_2> UV_map;   // uv[h] = UV of target(h) in face(h)
namespace SS = CGAL::Seamless_snapping;
namespace fs = std::filesystem;

// --subdivide L: instead, the scaling check: each model is refined L times by 1-to-4 midpoint
// subdivision (corner UVs of a new corner = midpoint of its face's corner UVs, so every seam stays
// approximately seamless and the cones stay), and the snap time (reduced pipeline, no IO) is printed
// per level with the time per 1000 faces: linear growth keeps that column flat.

// --integer-grid: instead, integer_grid_map(true) per model: cut edges with integer translations and
// cones of the field on integer points, before -> after (exact counts), verified by
// is_exact_integer_grid_map(); max change relative to the UV diagonal, flips input -> after repair
// (and how many of those the snap introduced), ms (minimum over N runs). Models that are not near an
// integer-grid map are listed with the status and reason (e.g. "not near an integer-grid map").

// Reads a model; files under a "directional" folder are cut meshes (Directional) and get welded.
// On failure, prints a "cannot read" table row, counts it in `failures` and returns false.
static bool read_model(const fs::path& p, Mesh& m, UV_map& uv, int& failures, unsigned threads = 1)
{
  uv = m.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
  const bool weld = p.string().find("directional") != std::string::npos;
  std::string msg;
  if(SS::IO::read_OBJ_with_corner_uvs(p.string(), m, uv, msg, SS::parameters::weld_vertices(weld).number_of_threads(threads))
     == SS::SUCCESS) return true;
  std::printf("%-36s cannot read: %s\n", p.filename().string().c_str(), msg.c_str());
  ++failures;
  return false;
}

// One level of 1-to-4 midpoint subdivision of a triangle mesh with a corner UV map.
static void subdivide(const Mesh& in, UV_map uv_in, Mesh& out, UV_map& uv_out)
{
  out.clear();
  uv_out = out.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
  std::vector<Mesh::Vertex_index> vmap(in.number_of_vertices());
  for(Mesh::Vertex_index v : in.vertices()) vmap[v] = out.add_vertex(in.point(v));
  std::vector<Mesh::Vertex_index> emap(in.number_of_edges());
  for(Mesh::Edge_index e : in.edges()) {
    const Mesh::Halfedge_index h = in.halfedge(e);
    emap[e] = out.add_vertex(CGAL::midpoint(in.point(in.source(h)), in.point(in.target(h))));
  }
  for(Mesh::Face_index f : in.faces()) {
    const Mesh::Halfedge_index h0 = in.halfedge(f), h1 = in.next(h0), h2 = in.next(h1);
    const Mesh::Vertex_index a = vmap[in.target(h0)], b = vmap[in.target(h1)], c = vmap[in.target(h2)];
    const Mesh::Vertex_index mab = emap[in.edge(h1)], mbc = emap[in.edge(h2)], mca = emap[in.edge(h0)];
    const K::Point_2 ua = get(uv_in, h0), ub = get(uv_in, h1), uc = get(uv_in, h2);
    const K::Point_2 uab = CGAL::midpoint(ua, ub), ubc = CGAL::midpoint(ub, uc), uca = CGAL::midpoint(uc, ua);
    const std::array<std::array<std::pair<Mesh::Vertex_index, K::Point_2>, 3>, 4> tris = {{
      {{ {a, ua}, {mab, uab}, {mca, uca} }}, {{ {mab, uab}, {b, ub}, {mbc, ubc} }},
      {{ {mca, uca}, {mbc, ubc}, {c, uc} }}, {{ {mab, uab}, {mbc, ubc}, {mca, uca} }} }};
    for(const auto& t : tris) {
      const Mesh::Face_index nf = out.add_face(t[0].first, t[1].first, t[2].first);
      for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(out.halfedge(nf), out))
        for(const auto& corner : t) if(out.target(h) == corner.first) put(uv_out, h, corner.second);
    }
  }
}

static int scaling_study(const std::vector<fs::path>& files, int levels, int repeat)
{
  std::printf("%-36s %5s %9s %9s %10s %9s  %s\n", "model", "level", "#F", "snap ms", "ms/1000F", "#cut", "status");
  int failures = 0;
  for(const fs::path& p : files) {
    Mesh m;
    UV_map uv;
    if(!read_model(p, m, uv, failures)) continue;
    for(int level = 0; level <= levels; ++level) {
      if(level > 0) { Mesh next; UV_map uv_next; subdivide(m, uv, next, uv_next); m = std::move(next); uv = m.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first; }
      double best = 0; SS::Snap_report rep;
      for(int r = 0; r < repeat; ++r) {
        Mesh c = m;
        UV_map cuv = c.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
        rep = SS::snap_seamless_parameterization(c, cuv);
        if(r == 0 || rep.total_ms < best) best = rep.total_ms;
      }
      if(rep.status != SS::SUCCESS) ++failures;
      std::printf("%-36s %5d %9zu %9.2f %10.3f %9zu  %s\n", p.filename().string().c_str(), level, rep.faces, best,
                  1000. * best / double(rep.faces), rep.cut_edges, SS::status_name(rep.status));
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// Table 3 / Fig. 2 of the paper: random connection constraints between cones, per model
static int connection_study(const std::vector<fs::path>& files, int repeat)
{
  namespace CT = connection_test;
  const std::size_t counts[] = {0, 10, 20, 50, 100};
  std::printf("%-36s %7s %6s | %5s %7s %9s %10s %9s %6s %10s\n", "model", "#F", "#cones", "#conn", "#nodes",
              "node sys", "max|C^|", "IRREF ms", "exact", "max du/d");
  int failures = 0;
  for(const fs::path& p : files) {
    Mesh input;
    UV_map uv_in;
    if(!read_model(p, input, uv_in, failures)) continue;
    const std::vector<CT::vertex_descriptor> cones = CT::find_cones(input, uv_in);
    if(cones.size() < 2) {
      std::printf("%-36s %7zu %6zu | fewer than 2 cones, skipped\n", p.filename().string().c_str(),
                  std::size_t(input.number_of_faces()), cones.size());
      continue;
    }
    for(std::size_t n : counts) {
      const std::vector<CT::Constraint> cc = CT::random_cone_connections(input, cones, n, unsigned(1000 + n));
      SS::Snap_report best;
      bool exact = true;
      for(int r = 0; r < repeat; ++r) {
        Mesh m = input;
        UV_map uv = m.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
        SS::Snap_report rep = SS::snap_seamless_parameterization(m, uv, SS::parameters::connection_constraints(std::cref(cc)));
        if(r == 0) {
          exact = rep.status == SS::SUCCESS && SS::is_exactly_seamless(m, uv);
          for(std::size_t j = 0; exact && j < cc.size(); ++j) exact = CT::exact_connection_holds(m, uv, uv_in, cc[j]).holds;
          if(rep.status != SS::SUCCESS)
            std::printf("%-36s %zu connections: %s: %s\n", p.filename().string().c_str(), n, SS::status_name(rep.status),
                        rep.message.c_str());
        }
        if(r == 0 || rep.irref_ms < best.irref_ms) best = rep;
      }
      if(!exact) ++failures;
      char sys[32];
      std::snprintf(sys, sizeof(sys), "%zux%zu", best.system_rows, best.system_columns);
      std::printf("%-36s %7zu %6zu | %5zu %7zu %9s %10s %9.3f %6s %10.3g\n", p.filename().string().c_str(),
                  std::size_t(input.number_of_faces()), cones.size(), n, best.nodes, sys, best.max_abs_coefficient.c_str(),
                  best.irref_ms, exact ? "yes" : "NO", best.max_change);
    }
  }
  std::printf("\ncolumns: #conn = random connection constraints between pairs of cones (Table 3); node sys = rows x\n"
              "columns of the reduced system C; max|C^| = largest |entry| of its IRREF; IRREF ms = initialize() of\n"
              "Exact_constraint_projection (minimum over the runs; Fig. 2 plots it against #nodes); exact = SUCCESS,\n"
              "is_exactly_seamless() and every connection re-checked by an independent Gmpq unfolding; max du/d = largest\n"
              "change relative to the UV diagonal (the constraints are not in the input, so it is as large as their violation).\n");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// The change of both modes against the L2 optimum, per model (see the header).
static std::size_t max_reference_faces = 100000;   // --max-reference-faces: the L2 reference does not scale beyond

static int change_study(const std::vector<fs::path>& files)
{
  namespace LR = l2_reference;
  std::printf("%-36s %9s %9s | %8s %8s %7s %5s | %8s %8s %7s %5s %8s | %6s\n", "model", "opt quanta", "opt max",
              "L2 paper", "max", "excess", "flips", "L2 ours", "max", "excess", "flips", "LS ms", "target");
  int failures = 0;
  std::vector<double> ratios;
  for(const fs::path& p : files) {
    Mesh input;
    UV_map uv_in;
    if(!read_model(p, input, uv_in, failures)) continue;
    if(std::size_t(input.number_of_faces()) > max_reference_faces) {
      std::printf("%-36s skipped: %zu faces, more than --max-reference-faces %zu (the sparse QR of the L2 reference "
                  "does not scale: it did not finish in 15 min on the 300K-face bunny)\n", p.filename().string().c_str(),
                  std::size_t(input.number_of_faces()), max_reference_faces);
      continue;
    }
    const LR::Sector_system<Mesh> sys = LR::sector_system(input, uv_in);
    const LR::Optimum opt = sys.ok ? LR::l2_optimum(sys.rows, sys.ubar) : LR::Optimum();
    if(!opt.ok) { std::printf("%-36s no reference (sector system or QR failed)\n", p.filename().string().c_str()); ++failures; continue; }
    LR::Comparison cmp[2];
    SS::Snap_report rep[2];
    for(int mode = 0; mode < 2; ++mode) {
      Mesh m = input;
      UV_map uv = m.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
      rep[mode] = SS::snap_seamless_parameterization(m, uv, SS::parameters::minimal_change(mode == 1));
      cmp[mode] = LR::compare(opt, sys.ubar, LR::sector_values(sys, uv), sys.quantum);
    }
    if(rep[0].status != SS::SUCCESS || rep[1].status != SS::SUCCESS) {
      std::printf("%-36s FAILED: paper %s, ours %s (%s)\n", p.filename().string().c_str(), SS::status_name(rep[0].status),
                  SS::status_name(rep[1].status), rep[1].message.c_str());
      ++failures;
      continue;
    }
    const bool ok = LR::meets_target(opt, cmp[1], sys.quantum);
    if(opt.l2 > 0) ratios.push_back(cmp[1].ratio_l2);
    std::printf("%-36s %9.3g %9.2e | %8.3f %8.3f %7.1f %5zu | %8.4f %8.4f %7.1f %5zu %8.2f | %6s\n",
                p.filename().string().c_str(), opt.max / sys.quantum, opt.max,
                cmp[0].ratio_l2, cmp[0].ratio_max, cmp[0].excess_quanta, rep[0].flips_unrepaired,
                cmp[1].ratio_l2, cmp[1].ratio_max, cmp[1].excess_quanta, rep[1].flips_unrepaired,
                rep[1].least_squares_ms, opt.l2 == 0 ? (cmp[1].l2 == 0 ? "exact" : "MOVED") : ok ? "ok" : "MISSED");
    if(!ok) ++failures;
  }
  double median = 0;
  if(!ratios.empty()) {
    std::sort(ratios.begin(), ratios.end());
    const std::size_t h = ratios.size() / 2;
    median = ratios.size() % 2 ? ratios[h] : 0.5 * (ratios[h - 1] + ratios[h]);
  }
  std::printf("median L2 ratio (ours) over %zu models with a nonzero optimum: %.4f (target <= 1.1)\n", ratios.size(), median);
  std::printf("\ncolumns: opt quanta = ||u* - ubar||_inf in grid quanta 2^(K-52); opt max = the same in UV units; L2 =\n"
              "||u - ubar||_2 / ||u* - ubar||_2; max = ||u - ubar||_inf / ||u* - ubar||_inf; excess = (||u - ubar||_inf -\n"
              "||u* - ubar||_inf) in quanta; flips = triangles flipped by snapping and left unrepaired; LS ms = the\n"
              "floating-point projection of the full system (minimal-change mode); target: L2 <= 1.05 where the optimum\n"
              "spans >= 100 quanta, else excess <= 8 quanta.\n");
  if(ratios.size() > 0 && median > 1.1) ++failures;
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

static int integer_grid_study(const std::vector<fs::path>& files, int repeat)
{
  std::printf("%-44s %7s | %18s | %16s | %9s | %15s | %8s | %s\n", "model (integer_grid_map)", "#F",
              "int. translations", "cones on integers", "max du/d", "flips (new)", "ms", "exact IGM");
  int failures = 0;
  for(const fs::path& p : files) {
    Mesh input;
    UV_map uv_in;
    if(!read_model(p, input, uv_in, failures)) continue;
    SS::Snap_report best;
    Mesh out;
    for(int r = 0; r < repeat; ++r) {
      Mesh m = input;
      UV_map uv = m.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
      const SS::Snap_report rep = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).untangle(false));
      if(r == 0 || rep.total_ms < best.total_ms) { best = rep; out = m; }
    }
    const std::string name = fs::relative(p, p.parent_path().parent_path()).string();
    if(best.status != SS::SUCCESS) {
      std::printf("%-44s %7zu | %s: %.150s\n", name.c_str(), best.faces, SS::status_name(best.status), best.message.c_str());
      continue;
    }
    UV_map uv = out.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
    const bool exact = SS::is_exact_integer_grid_map(out, uv);
    if(!exact) ++failures;
    std::printf("%-44s %7zu | %4zu -> %4zu /%4zu | %3zu -> %3zu /%4zu | %9.2e | %4zu -> %4zu (%2zu) | %8.1f | %s\n",
                name.c_str(), best.faces, best.integer_translations_before, best.integer_translations_after, best.cut_edges,
                best.cones_on_integer_points_before, best.cones_on_integer_points_after, best.field_cones, best.max_change,
                best.flips_before, best.flips_after_repair, best.flips_unrepaired, best.total_ms, exact ? "yes" : "NO");
  }
  std::printf("\ncolumns: cut edges whose translation is exactly an integer vector, and cones of the field (rotation sum\n"
              "not 0 mod 4) exactly on integer points, input -> result / total; max du/d = max change relative to the UV\n"
              "diagonal; flips = UV fold-overs input -> after repair (new = introduced by snapping, left after repair);\n"
              "exact IGM = is_exact_integer_grid_map() (Gmpq) on the result.\n");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// --untangle: instead, the untangling (untangle(true)) per model, in the default mode and in integer-grid mode, and
// in integer-grid mode with merge_cone_pairs(true) (row "IGM+m", printed where pairs were merged), with
// separate_cone_pairs(true) (row "IGM+s", printed where pairs were separated) and with both (row "IGM+ms", likewise):
// UV triangles negative / zero in the input, after the snap alone, after untangling (floating point), at the end
// (after its exact snap and the repair); of those at the end, how many are proven forced; vertices left not locally
// injective (of them, next to a cone pair the rounding collapsed); rings, moved sectors, the change in grid cells
// (max / RMS beyond the snap, and the snap alone's max); the times of the snap alone (untangle(false)) and of
// untangling + snap (of it, the polish), and their ratio; the untangling's work (optimizations / their Newton iterations /
// the polish's Newton iterations); exact = is_exactly_seamless / is_exact_integer_grid_map (Gmpq) on the result.
static int untangle_study(const std::vector<fs::path>& files, int repeat, unsigned threads)
{
  std::printf("number_of_threads(%u)\n", threads);
  std::printf("%-34s %5s %7s | %9s %9s %9s %9s %6s | %7s | %5s %6s %17s %9s | %9s %9s %7s %6s %12s | %s\n", "model", "mode",
              "#F", "input", "snap", "untangled", "end", "forced", "wound", "rings", "moved", "max/RMS cells", "snap max",
              "snap ms", "unt.+snap", "polish", "ratio", "opt/Newt/pol", "exact");
  int failures = 0;
  for(const fs::path& p : files) {
    Mesh input;
    UV_map uv_in;
    if(!read_model(p, input, uv_in, failures)) continue;
    for(int mode = 0; mode < 5; ++mode) {
      const bool igm = mode > 0, merge = mode == 2 || mode == 4, separate = mode >= 3;
      const char* const mode_names[5] = {"def", "IGM", "IGM+m", "IGM+s", "IGM+ms"};
      const char* mode_name = mode_names[mode];
      SS::Snap_report alone, best;
      Mesh out;
      for(int r = 0; r < repeat; ++r) {
        Mesh m0 = input;
        UV_map uv0 = m0.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
        const SS::Snap_report a = SS::snap_seamless_parameterization(m0, uv0, SS::parameters::integer_grid_map(igm).untangle(false)
                                                                               .merge_cone_pairs(merge).separate_cone_pairs(separate)
                                                                               .number_of_threads(threads));
        Mesh m = input;
        UV_map uv = m.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
        const SS::Snap_report b = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(igm).untangle(true)
                                                                             .merge_cone_pairs(merge).separate_cone_pairs(separate)
                                                                             .number_of_threads(threads));
        if(r == 0 || a.total_ms < alone.total_ms) alone = a;
        if(r == 0 || b.total_ms < best.total_ms) { best = b; out = m; }
      }
      const std::string name = p.filename().string();
      if(mode == 2 && best.merged_cone_pairs.empty()) continue;      // the IGM row again
      if(separate && best.separated_cone_pairs.empty()) continue;   // the IGM or IGM+m row again
      if(best.status != SS::SUCCESS) {
        std::printf("%-34s %5s %7zu | %s: %.120s\n", name.c_str(), mode_name, best.faces, SS::status_name(best.status),
                    best.message.c_str());
        continue;
      }
      UV_map uv = out.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
      const bool exact = igm ? SS::is_exact_integer_grid_map(out, uv) : SS::is_exactly_seamless(out, uv);
      if(!exact) ++failures;
      std::size_t at_pairs = 0;
      for(const SS::Winding_defect& w : best.winding_defects) at_pairs += w.message.find("cone pair") != std::string::npos ? 1 : 0;
      auto counts = [](std::size_t n, std::size_t z) { return std::to_string(n) + "/" + std::to_string(z); };
      const std::string change = best.untangled ? (std::to_string(best.untangle_max_change * best.grid_scale).substr(0, 6) + " / " +
                                                   std::to_string(best.untangle_rms_change * best.grid_scale).substr(0, 6)) : "-";
      const std::string work = std::to_string(best.untangle_attempts) + "/" + std::to_string(best.untangle_newton_steps) + "/" +
                               std::to_string(best.untangle_polish_steps);
      std::printf("%-34s %5s %7zu | %9s %9s %9s %9s %6zu | %3zu (%zu) | %5d %6zu %17s %9.2e | %9.1f %9.1f %7.1f %6.2f %12s | %s%s\n",
                  name.c_str(), mode_name, best.faces, counts(best.flips_before, best.degenerate_before).c_str(),
                  counts(alone.flips_after_repair, alone.degenerate_after_repair).c_str(),
                  counts(best.flips_after_untangling, best.degenerate_after_untangling).c_str(),
                  counts(best.flips_after_repair, best.degenerate_after_repair).c_str(), best.folds_forced,
                  best.winding_defects.size(), at_pairs, best.untangle_rings, best.untangle_moved_sectors, change.c_str(),
                  alone.snap_max_change * alone.grid_scale, alone.total_ms, best.total_ms, best.untangle_polish_ms,
                  alone.total_ms > 0 ? best.total_ms / alone.total_ms : 0., work.c_str(), exact ? "yes" : "NO",
                  best.separation_trials > 0 ? (", " + std::to_string(best.separation_trials) + " trials in " +
                                                std::to_string(long(best.separation_ms + 0.5)) + " ms").c_str() : "");
    }
  }
  std::printf("\ncolumns: negative/zero-area UV triangles (exact test): input, after the snap alone (untangle(false), with its\n"
              "repair), after untangling (the floating-point map), at the end (after its exact snap and the repair); forced =\n"
              "those at the end proven non-positive in every exact solution (Snap_report::folds); wound = vertices left whose\n"
              "UV angle sum is not their valence (Snap_report::winding_defects), in brackets those next to a cone pair the\n"
              "integer rounding collapsed onto one point; rings = largest k of the regions; max/RMS cells = the change beyond\n"
              "the snap (grid cells: UV units at grid scale 1); snap max = the snap alone's max change; times in ms (min over\n"
              "--repeat runs); polish = the untangling's minimal-change polish, part of unt.+snap; ratio = (untangling +\n"
              "snap) / snap alone; opt/Newt/pol = the untangling's optimizations (one per ring size tried), their Newton\n"
              "iterations and the polish's (Snap_report::untangle_attempts, untangle_newton_steps, untangle_polish_steps: each\n"
              "iteration factors the regions' sparse Hessians or reuses the last factorization, where the time goes);\n"
              "IGM+m: integer-grid mode with merge_cone_pairs(true)\n"
              "(the collapsed cone pairs made regular points of the field), where it merged pairs; IGM+s: with\n"
              "separate_cone_pairs(true) (the collapsed pairs moved apart, the field kept), where it separated pairs, with the\n"
              "extra snaps that chose the shifts (trials, with their time: Snap_report::separation_ms, a part of unt.+snap); IGM+ms: both.\n");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// --large: the scale table of issue 26 (see the header)
static double cpu_ms()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

// the peak RSS of the process in MB (VmHWM); reset_peak_rss() lowers it to the current RSS, where Linux allows it
static double peak_rss_mb()
{
  std::ifstream is("/proc/self/status");
  for(std::string line; std::getline(is, line);)
    if(line.compare(0, 6, "VmHWM:") == 0) return std::atof(line.c_str() + 6) / 1024.;
  return 0;
}
static bool reset_peak_rss()
{
  std::ofstream os("/proc/self/clear_refs");
  os << "5";
  os.flush();
  return bool(os);
}

static int large_study(const std::vector<fs::path>& files, int repeat, unsigned threads)
{
  std::printf("number_of_threads(%u)\n", threads);
  std::printf("%-34s %7s %6s %6s | %8s %8s | %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s | %6s %8s | %8s %8s | %6s | %7s %7s %7s\n",
              "model", "#F", "#cones", "#nodes", "read", "cpu", "extract", "reduce", "LS", "IRREF", "evaluate", "repair",
              "explain", "verify", "snap", "cpu", "us/F", "extr/F", "write", "cpu", "s/r", "MB read", "MB snap", "MB write");
  int failures = 0;
  bool peaks_reset = true;
  const fs::path out = fs::temp_directory_path() / ("bench_snap_large_" + std::to_string(::getpid()) + ".obj");
  for(const fs::path& p : files) {
    double read = 0, read_cpu = 0, snap_cpu = 0, write = 0, write_cpu = 0, mb_read = 0, mb_snap = 0, mb_write = 0;
    SS::Snap_report best;
    bool ok = true;
    for(int r = 0; r < repeat && ok; ++r) {
      int fails = 0;
      peaks_reset = reset_peak_rss() && peaks_reset;
      double c0 = cpu_ms();
      auto t0 = std::chrono::steady_clock::now();
      Mesh m;
      UV_map uv;
      if(!read_model(p, m, uv, fails, threads)) { ++failures; ok = false; break; }
      const double t_read = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      const double c_read = cpu_ms() - c0;
      const double m_read = peak_rss_mb();
      peaks_reset = reset_peak_rss() && peaks_reset;
      c0 = cpu_ms();
      const SS::Snap_report rep = SS::snap_seamless_parameterization(m, uv, SS::parameters::number_of_threads(threads));
      const double c_snap = cpu_ms() - c0;
      const double m_snap = peak_rss_mb();
      if(rep.status != SS::SUCCESS) {
        std::printf("%-34s snap FAILED: %s: %s\n", p.filename().string().c_str(), SS::status_name(rep.status), rep.message.c_str());
        ++failures; ok = false; break;
      }
      peaks_reset = reset_peak_rss() && peaks_reset;
      c0 = cpu_ms();
      t0 = std::chrono::steady_clock::now();
      std::string msg;
      if(SS::IO::write_OBJ_with_corner_uvs(out.string(), m, uv, msg, SS::parameters::number_of_threads(threads)) != SS::SUCCESS) {
        std::printf("%-34s write FAILED: %s\n", p.filename().string().c_str(), msg.c_str());
        ++failures; ok = false; break;
      }
      const double t_write = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      const double c_write = cpu_ms() - c0;
      const double m_write = peak_rss_mb();
      fs::remove(out);
      if(r == 0 || t_read < read) { read = t_read; read_cpu = c_read; }
      if(r == 0 || rep.total_ms < best.total_ms) { best = rep; snap_cpu = c_snap; }
      if(r == 0 || t_write < write) { write = t_write; write_cpu = c_write; }
      mb_read = (std::max)(mb_read, m_read); mb_snap = (std::max)(mb_snap, m_snap); mb_write = (std::max)(mb_write, m_write);
    }
    if(!ok) continue;
    const double per_face = 1000. * best.total_ms / double(best.faces);
    const char* plus = peaks_reset ? " " : "+";
    std::printf("%-34s %7zu %6zu %6zu | %8.1f %8.1f | %8.1f %8.1f %8.1f %8.1f %8.1f %8.1f %8.1f %8.1f %8.1f %8.1f | %6.2f %8.3f | %8.1f %8.1f | %6.2f | %6.0f%s %6.0f%s %6.0f%s\n",
                p.filename().string().c_str(), best.faces, best.cones, best.nodes, read, read_cpu, best.extract_ms,
                best.reduce_ms, best.least_squares_ms, best.irref_ms, best.evaluate_ms, best.repair_ms, best.explain_ms, best.verify_ms,
                best.total_ms, snap_cpu, per_face, 1000. * best.extract_ms / double(best.faces), write, write_cpu,
                read > 0 ? best.total_ms / read : 0., mb_read, plus, mb_snap, plus, mb_write, plus);
    std::fflush(stdout);
  }
  std::printf("\ncolumns: read / write = read_OBJ_with_corner_uvs (welding files under \"directional\") / write_OBJ_with_corner_uvs,\n"
              "wall ms, minimum over the runs, with the process CPU ms of that run (cpu); extract .. snap = the Snap_report's\n"
              "phase times of the fastest snap (explain = the faces left not positive with their proofs and the vertex\n"
              "windings; snap = total_ms, which also holds the steps not listed: propagation, untangling, the write into\n"
              "the map), cpu = its CPU ms; us/F = snap us per face, extr/F = extract us\n"
              "per face; s/r = snap / read (wall); MB = peak RSS of the process during the read, the snap, the write\n"
              "(each phase's own peak%s).\n", peaks_reset ? "" : "; '+': the peak could not be reset, so it is the peak so far");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

int main(int argc, char** argv)
{
  CGAL::Seamless_snapping::IO::internal::use_retained_heap(argv);   // large maps: see the header
  int repeat = 3;
  bool connections = false, change_only = false, integer_grid = false, untangle = false, large = false;
  unsigned threads = 1;                      // --large, --untangle: number_of_threads
  int subdivide_levels = -1;
  std::vector<fs::path> inputs;
  for(int i = 1; i < argc; ++i) {
    if(std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) { repeat = (std::max)(1, std::atoi(argv[++i])); continue; }
    if(std::strcmp(argv[i], "--connections") == 0) { connections = true; continue; }
    if(std::strcmp(argv[i], "--change") == 0) { change_only = true; continue; }
    if(std::strcmp(argv[i], "--integer-grid") == 0) { integer_grid = true; continue; }
    if(std::strcmp(argv[i], "--untangle") == 0) { untangle = true; continue; }
    if(std::strcmp(argv[i], "--subdivide") == 0 && i + 1 < argc) { subdivide_levels = (std::max)(0, std::atoi(argv[++i])); continue; }
    if(std::strcmp(argv[i], "--large") == 0) { large = true; continue; }
    if(std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) { threads = unsigned((std::max)(0, std::atoi(argv[++i]))); continue; }
    if(std::strcmp(argv[i], "--max-reference-faces") == 0 && i + 1 < argc) {
      max_reference_faces = std::size_t(std::strtoull(argv[++i], nullptr, 10));
      continue;
    }
    inputs.emplace_back(argv[i]);
  }
  std::vector<fs::path> files;
  if(!collect_obj_files(inputs, std::string("usage: ") + argv[0] + " [--repeat N] [--threads N] [--large] [--connections | --change | --integer-grid | --untangle | --subdivide L] <file.obj | directory>...  (or set SS_SHARED_DATA_DIR)", files)) return EXIT_FAILURE;
  if(large) return large_study(files, repeat, threads);
  if(connections) return connection_study(files, repeat);
  if(integer_grid) return integer_grid_study(files, repeat);
  if(untangle) return untangle_study(files, repeat, threads);
  if(subdivide_levels >= 0) return scaling_study(files, subdivide_levels, repeat);
  if(change_only) return change_study(files);

  // The table: one column per entry (header, width, value of the row); a new column is one line here.
  struct Row
  {
    std::string name;
    double read_ms = 0;
    SS::Snap_report best, best_full;
  };
  struct Column
  {
    const char* header;
    int width;
    std::function<std::string(const Row&)> value;
    bool separator_before;
  };
  auto num = [](const char* f, double x) { char b[64]; std::snprintf(b, sizeof b, f, x); return std::string(b); };
  auto count = [](std::size_t n) { return std::to_string(n); };
  auto triple = [](std::size_t a, std::size_t b, std::size_t c) {
    return std::to_string(a) + "/" + std::to_string(b) + "/" + std::to_string(c);
  };
  auto pair = [](std::size_t a, std::size_t b) { return std::to_string(a) + "+" + std::to_string(b); };
  auto proj = [](const SS::Snap_report& r) { return r.reduce_ms + r.irref_ms + r.evaluate_ms + r.propagate_ms; };
  const std::vector<Column> columns = {
    {"#F", 7, [&](const Row& r) { return count(r.best.faces); }, false},
    {"#cut", 6, [&](const Row& r) { return count(r.best.cut_edges); }, false},
    {"#nodes", 6, [&](const Row& r) { return count(r.best.nodes); }, false},
    {"#branch", 6, [&](const Row& r) { return count(r.best.cut_branches + r.best.align_branches); }, false},
    {"extract", 8, [&](const Row& r) { return num("%.2f", r.best.extract_ms); }, true},
    {"reduce", 8, [&](const Row& r) { return num("%.2f", r.best.reduce_ms); }, false},
    {"IRREF", 8, [&](const Row& r) { return num("%.2f", r.best.irref_ms); }, false},
    {"evaluate", 8, [&](const Row& r) { return num("%.2f", r.best.evaluate_ms); }, false},
    {"propag.", 8, [&](const Row& r) { return num("%.2f", r.best.propagate_ms); }, false},
    {"total", 8, [&](const Row& r) { return num("%.2f", r.best.total_ms); }, false},
    {"unreduced", 9, [&](const Row& r) { return num("%.2f", r.best_full.total_ms); }, true},
    {"ratio", 6, [&](const Row& r) { return num("%.2f", r.best.total_ms > 0 ? r.best_full.total_ms / r.best.total_ms : 0.); }, false},
    {"unr.proj", 9, [&](const Row& r) { return num("%.2f", r.best_full.irref_ms + r.best_full.evaluate_ms); }, false},
    {"ratio", 6, [&](const Row& r) {
       return num("%.2f", proj(r.best) > 0 ? (r.best_full.irref_ms + r.best_full.evaluate_ms) / proj(r.best) : 0.); }, false},
    {"max Cx/d", 9, [&](const Row& r) { return num("%9.2e", r.best.max_input_violation); }, true},
    {"avg du/d", 9, [&](const Row& r) { return num("%9.2e", r.best.mean_change); }, false},
    {"max du/d", 9, [&](const Row& r) { return num("%9.2e", r.best.max_change); }, false},
    {"neg in/sn/rep", 13, [&](const Row& r) { return triple(r.best.flips_before, r.best.flips_after, r.best.flips_after_repair); }, true},
    {"deg in/sn/rep", 13, [&](const Row& r) {
       return triple(r.best.degenerate_before, r.best.degenerate_after, r.best.degenerate_after_repair); }, false},
    {"intro n+d", 9, [&](const Row& r) { return pair(r.best.flips_introduced, r.best.degenerate_introduced); }, true},
    {"left n+d", 9, [&](const Row& r) { return pair(r.best.flips_unrepaired, r.best.degenerate_unrepaired); }, false},
    {"repair", 8, [&](const Row& r) { return num("%.2f", r.best.repair_ms); }, false},
    {"read OBJ", 9, [&](const Row& r) { return num("%.1f", r.read_ms); }, true},
  };
  auto print_line = [&](const std::string& first, const std::function<std::string(const Column&)>& cell) {
    std::string line = first;
    line.resize((std::max)(line.size(), std::size_t(36)), ' ');
    for(const Column& c : columns) {
      line += c.separator_before ? " | " : " ";
      std::string v = cell(c);
      if(int(v.size()) < c.width) v.insert(0, std::size_t(c.width) - v.size(), ' ');
      line += v;
    }
    std::printf("%s\n", line.c_str());
  };
  print_line("model", [](const Column& c) { return std::string(c.header); });
  int failures = 0;
  for(const fs::path& p : files) {
    Mesh input;
    UV_map uv_in;
    auto t0 = std::chrono::steady_clock::now();
    const bool read = read_model(p, input, uv_in, failures);
    Row row;
    row.name = p.filename().string();
    row.read_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if(!read) continue;

    bool first = true;
    for(int r = 0; r < repeat; ++r) {
      Mesh m = input;
      UV_map uv = m.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
      SS::Snap_report rep = SS::snap_seamless_parameterization(m, uv);
      Mesh mf = input;
      UV_map uvf = mf.property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
      SS::Snap_report full = SS::snap_seamless_parameterization(mf, uvf, SS::parameters::use_reduced_system(false));
      if(rep.status != SS::SUCCESS || full.status != SS::SUCCESS) {
        std::printf("%-36s FAILED: reduced %s (%s), unreduced %s (%s)\n", row.name.c_str(),
                    SS::status_name(rep.status), rep.message.c_str(), SS::status_name(full.status), full.message.c_str());
        ++failures;
        first = true;
        break;
      }
      if(first || rep.total_ms < row.best.total_ms) row.best = rep;
      if(first || full.total_ms < row.best_full.total_ms) row.best_full = full;
      first = false;
    }
    if(first) continue;
    print_line(row.name, [&](const Column& c) { return c.value(row); });
    if(row.best.flips_unrepaired + row.best.degenerate_unrepaired > 0) {
      std::printf("    %s\n", row.best.message.c_str());
      ++failures;
    }
  }
  std::printf("\ncolumns: phase times of the reduced pipeline (extract = corner mesh, seams, sectors, rotations, full rows,\n"
              "input violation, flips; reduce = nodes/branches/node system; IRREF and evaluate = Exact_constraint_projection\n"
              "initialize()/project() on the node system; propag. = non-node sectors; total includes the exact verification\n"
              "and the write). unreduced = total ms with use_reduced_system(false); ratio = unreduced / reduced.\n"
              "unr.proj = IRREF + evaluate ms of the full system; its ratio is to reduce + IRREF + evaluate + propag. of the\n"
              "reduced pipeline (the part Sec. 5.3 speeds up).\n"
              "neg / deg in/sn/rep = UV triangles with negative / zero area (exact test) in the input, after snapping, after\n"
              "the flip repair; intro n+d = negative + degenerate triangles that were positive in the input, after snapping;\n"
              "left n+d = the same after the repair (must be 0+0: otherwise the reason is printed and the exit code is 1);\n"
              "repair = flip repair ms.\n\n");
  const int change = change_study(files);
  return failures == 0 && change == EXIT_SUCCESS ? EXIT_SUCCESS : EXIT_FAILURE;
}
