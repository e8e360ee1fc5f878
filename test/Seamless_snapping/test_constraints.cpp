// Tests of connection constraints (Eq. 6) and cycle constraints (Eq. 8) in
// snap_seamless_parameterization() (Sec. 5.1, 5.3 "Connections and Cycles").
//
//   connections: random cone pairs on every data mesh   10 connection constraints between random pairs of
//                                                        cones (shortest edge paths), reduced and unreduced:
//                                                        SUCCESS, exactly seamless, and every constraint holds
//                                                        exactly, checked by an independent exact unfolding;
//                                                        snapping the result again changes nothing (unless
//                                                        it has zero-length cut edges, whose k is arbitrary)
//                                                        5 more from vertices inside cut branches to random
//                                                        vertices (endpoints become nodes)
//   connections: orbifold Tutte inputs                   the same on Square orbifold maps of CGAL meshes
//   cycles: torus loops and cone links                   closed paths: the cut loops of the torus (the
//                                                        isocurves close instead of spiralling) and the link
//                                                        of a cone (holonomy), reduced and unreduced
//   connections: invalid paths                           empty, disconnected, foreign halfedge, bad component:
//                                                        INVALID_INPUT naming the constraint, map bit-identical
//   integer grid: torus, cones                           integer_grid_map(true): a flat torus with period
//                                                        3.0000000001 snaps to 3 exactly (also at grid scale 4,
//                                                        bit for bit /4; scale 3 refused); period 3.4 is refused
//                                                        as not near an IGM; a 180-degree cone whose integer
//                                                        translation forces the fixed point (0.5, 0) is INFEASIBLE
//                                                        naming the cone; near (1, 0) it is pinned there exactly
//   integer grid: data                                   libQEx ducks/fandisk, Directional horse/dragon
//                                                        (full-seamless): SUCCESS, is_exact_integer_grid_map()
//                                                        (independent Gmpq check), change < 1e-5, no more flips
//                                                        than the input; no new flips, also on the dragon (a
//                                                        stress case: 239 zero-length seam edges, 549 input
//                                                        fold-overs; its 161 new degenerate triangles are all
//                                                        forced by the constraints)
//   integer grid: orbifold                               CGAL Orbifold Tutte square map (cones on the unit square's
//                                                        corners): an exact IGM after; scaled by 0.3: INVALID_INPUT
//                                                        with advice, map bit-identical
//   quad valences                                       quad_valences() on the results: flat torus all 4, the
//                                                        180-degree cone 2; on the fold-free data every interior
//                                                        valence is 0 mod 4 exactly away from the field cones, and
//                                                        sum(4 - valence) = 4 chi (Gauss-Bonnet) on closed maps;
//                                                        with fold-overs left FOLD_OVERS listing exactly the flipped
//                                                        and zero-area faces; a map that is not exactly seamless is
//                                                        INVALID_INPUT
//   pinned corners: torus, data                          pinned_corner_map, default and integer-grid mode: pinned
//                                                        corners stay bit-identical, the result is exactly seamless
//                                                        (an exact IGM), at scales 2^0, 2^-7, 2^9 bit for bit, also
//                                                        unreduced and with a pin between grid lines; a pin
//                                                        below the grid quantum is RANGE_EXCEEDED, contradicting
//                                                        pins INFEASIBLE, map untouched; fandisk with every
//                                                        integer corner pinned
//   right-hand sides                                     Constraint_rows with b != 0: the exact residual is
//                                                        C x - b, 0 = b != 0 is recorded as a contradiction,
//                                                        project_rows() solves C x = b exactly (scale 2^j too)
//
// The independent exact check (Gmpq unfolding along the face strip) is in connection_test_utils.h.
//
// Bit-for-bit checks, none against stored bits: idempotence (the result snapped again), an empty constraint range
// against none, an exact input returned as it is, grid_scale(4) against the result / 4, pinned and untangled results at
// scales 2^j against scale 1 (scale covariance), pinned corners keeping their input bits, refusals leaving the map untouched;
// each compares outputs computed in this run from the same input bits. The snap uses libm only in decisions far from
// their thresholds and no solver whose rounding depends on the CPU, so they hold on every machine (the orbifold inputs
// made here do differ between CPUs: CTest also runs other_rounding__test_constraints, see test_arguments.h).
//
// Real data: SS_SHARED_DATA_DIR (../shared/data) and SS_CGAL_DATA_DIR (meshes from libcgal-demo);
// parts whose data is missing are skipped with a message.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Seamless_snapping/Connection_constraint.h>
#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/is_exact_integer_grid_map.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/quad_valences.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>
#include <CGAL/Seamless_snapping/internal/inputs/orbifold_tutte_input.h>
#include <CGAL/Seamless_snapping/internal/surface/cone_merging.h>
#include <CGAL/Seamless_snapping/internal/surface/isoline_classes.h>
#include <CGAL/Seamless_snapping/internal/untangling/region_problem.h>
#include <CGAL/Seamless_snapping/internal/untangling/untangler.h>
#include <CGAL/Seamless_snapping/internal/untangling/untangling_energy.h>

#include <CGAL/Gmpq.h>

#include <Eigen/Eigenvalues>

#include "connection_test_utils.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "mesh_test_support.h"
#include <CGAL/Seamless_snapping/diagnose_seamlessness.h>
typedef SS::Connection_constraint<halfedge_descriptor>         Constraint;
using namespace connection_test;




static std::size_t g_checked = 0, g_ambiguous = 0;

// snaps a copy of `input` with the constraints, reduced or not; checks everything; returns the report
static SS::Snap_report snap_and_check(const Mesh& input, const std::vector<Constraint>& cc, bool reduced,
                                      const std::string& name, Mesh* out = nullptr)
{
  Mesh m = input;
  UV_map uv = uv_of(m);
  Mesh m_in = input;
  UV_map uv_in = uv_of(m_in);
  SS::Snap_report r = SS::snap_seamless_parameterization(
      m, uv, SS::parameters::use_reduced_system(reduced, SS::parameters::connection_constraints(std::cref(cc))));
  if(r.status != SS::SUCCESS)
    std::cerr << name << (reduced ? " reduced: " : " unreduced: ") << SS::status_name(r.status) << ": " << r.message << std::endl;
  assert(r.status == SS::SUCCESS);
  assert(SS::is_exactly_seamless(m, uv));
  std::size_t ambiguous = 0;
  for(std::size_t j = 0; j < cc.size(); ++j) {
    const Check_result cr = exact_connection_holds(m, uv, uv_in, cc[j]);
    if(!cr.holds) std::cerr << name << ": constraint " << j << " does not hold exactly" << std::endl;
    assert(cr.holds);
    ++g_checked;
    ambiguous += cr.ambiguous;
  }
  g_ambiguous += ambiguous;
  // idempotent: the result satisfies everything, a second snap changes nothing. Not checked when a
  // connection path crosses a cut edge of UV length 0 in the result: its transition holds for every
  // rotation k, so the rotation fitted on the result may differ from the input's, and with it the
  // connection row. (Every other cut edge keeps its exact rotation: rotation_fit.h.)
  if(ambiguous == 0) {
    // the public checks see the same constraints as the snap: every row holds on the result; on the
    // input, the diagnosis finds the violated rows and agrees with is_exactly_seamless()
    const auto np = SS::parameters::connection_constraints(std::cref(cc));
    // (the rows are those extracted from the result: a cut edge whose two sides the snap made equal is
    // no longer a cut edge there, so their number may differ from the input's; and where the result's
    // seam arcs hold near-degenerate edges, fitting the rotations anew may fail: then both report it)
    const SS::Seamless_diagnosis<Mesh> d = SS::diagnose_seamlessness(m, uv, np);
    if(d.status == SS::SUCCESS) {
      assert(d.exact && d.violated_rows == 0 && d.rows > 0);
      assert(SS::is_exactly_seamless(m, uv, np));
    } else {
      assert(!SS::is_exactly_seamless(m, uv, np));
      std::printf("  NOTE %s: the result's rotations cannot be fitted anew (%s): %s\n", name.c_str(),
                  SS::status_name(d.status), d.message.c_str());
    }
    const SS::Seamless_diagnosis<Mesh> din = SS::diagnose_seamlessness(m_in, uv_in, np);
    if(din.status == SS::SUCCESS) {
      assert(din.rows == r.constraints);
      assert(din.exact == (r.max_input_violation == 0));
      assert(SS::is_exactly_seamless(m_in, uv_in, np) == (SS::is_exactly_seamless(m_in, uv_in) && din.violated_connections == 0));
      if(!din.exact)
        assert(din.row >= 0 && !din.corners.empty() && din.residual_double != 0 && din.residual != "0" &&
               std::fabs(din.residual_double) <= r.max_input_violation * r.uv_diagonal * (1 + 1e-15) + 1e-300 &&
               (din.kind == "connection") == (din.violated_connections > 0 && din.edge == edge_descriptor()));
    }
    if(d.status == SS::SUCCESS) {     // idempotent where the result's rotations can be fitted anew
      Mesh m2 = m;
      UV_map uv2 = uv_of(m2);
      SS::Snap_report r2 = SS::snap_seamless_parameterization(
          m2, uv2, SS::parameters::use_reduced_system(reduced, SS::parameters::connection_constraints(std::cref(cc))));
      if(r2.status != SS::SUCCESS) std::cerr << name << ": second snap: " << r2.message << std::endl;
      assert(r2.status == SS::SUCCESS);
      assert(uv_bits(m2, uv2) == uv_bits(m, uv));       // idempotent: the result, snapped again in this run
    }
  } else {
    std::printf("  NOTE %s: %zu crossings of zero-length cut edges, idempotence not checked\n", name.c_str(), ambiguous);
  }
  if(out != nullptr) *out = m;
  return r;
}

// ---------------------------------------------------------------------------------------------
// connections: random cone pairs on every data mesh
// ---------------------------------------------------------------------------------------------
static void test_data_meshes()
{
  std::vector<fs::path> files;
  if(!shared_obj_files_or_skip("connections: random cone pairs on every data mesh", files)) return;
  assert(!files.empty());
  unsigned seed = 2019;
  for(const fs::path& p : files) {
    const std::string name = fs::relative(p, fs::path(SS_SHARED_DATA_DIR)).string();
    Mesh input;
    assert(load_obj(p, input));
    UV_map uv_in = uv_of(input);
    const std::vector<vertex_descriptor> cones = find_cones(input, uv_in);
    if(cones.size() < 2) { std::cout << "connections: " << name << ": fewer than 2 cones, skipped\n"; continue; }
    const std::vector<Constraint> cc = random_cone_connections(input, cones, 10, seed++);
    std::size_t path_edges = 0;
    for(const Constraint& c : cc) path_edges += c.path.size();
    const SS::Snap_report r = snap_and_check(input, cc, true, name);
    std::printf("connections: %-48s cones %4zu paths %5zu edges  node system %4zux%-4zu max|C^| %-3s IRREF %.2f ms"
                "  max change %.3g  total %.1f ms\n",
                name.c_str(), cones.size(), path_edges, r.system_rows, r.system_columns, r.max_abs_coefficient.c_str(),
                r.irref_ms, r.max_change, r.total_ms);
    // the unreduced system (a cross-check of the reduction) is left out of the sanitizer subset: under ASan
    // its multiprecision IRREF takes minutes on these files (horse: 77 s), and the reduced run covers the code
    if(!sanitizer_subset()) {
      const SS::Snap_report ru = snap_and_check(input, cc, false, name);
      std::printf("             %-48s unreduced: system %5zux%-5zu max|C^| %-3s %.1f ms\n", "", ru.system_rows,
                  ru.system_columns, ru.max_abs_coefficient.c_str(), ru.total_ms);
    }
    // endpoints inside cut branches and away from seams (node rule 2 of Sec. 5.3 makes them nodes)
    std::vector<vertex_descriptor> inner;
    for(vertex_descriptor v : input.vertices()) {
      int cut_degree = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_source(v, input)) {
        const halfedge_descriptor o = input.opposite(h);
        if(!input.is_border(input.edge(h)) &&
           (get(uv_in, h) != get(uv_in, input.prev(o)) || get(uv_in, input.prev(h)) != get(uv_in, o))) ++cut_degree;
      }
      if(cut_degree == 2 && !input.is_border(v)) inner.push_back(v);
    }
    if(!inner.empty()) {
      std::mt19937 rng(seed++);
      std::vector<Constraint> cv;
      while(cv.size() < 5) {
        const vertex_descriptor a = inner[rng() % inner.size()];
        const vertex_descriptor b(Mesh::size_type(rng() % input.number_of_vertices()));
        if(a == b) continue;
        cv.emplace_back(shortest_path(input, a, b), int(rng() % 2));
      }
      const SS::Snap_report rv = snap_and_check(input, cv, true, name);
      const double unreduced_change = sanitizer_subset() ? -1. : snap_and_check(input, cv, false, name).max_change;
      std::printf("             %-48s 5 constraints from cut-branch vertices: nodes %zu (with the cone pairs: %zu), max change %.3g / %.3g%s\n",
                  "", rv.nodes, r.nodes, rv.max_change, unreduced_change, sanitizer_subset() ? " (unreduced not run)" : "");
    }
    // sanitizer subset: the first file with cones only: under ASan each snap with random cone connections takes
    // 14-78 s on these files (measured: knight 14 s, lilium 42 s, horse 78 s); the Release run takes them all
    if(sanitizer_subset()) {
      std::cout << "connections: sanitizer subset: the other data files are left out\n";
      break;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// connections: orbifold Tutte inputs
// ---------------------------------------------------------------------------------------------
static void test_orbifolds()
{
  const fs::path dir(SS_CGAL_DATA_DIR);
  if(std::string(SS_CGAL_DATA_DIR).empty() || !fs::is_directory(dir)) {
    std::cout << "connections: orbifold Tutte inputs: SKIPPED (no '" << dir.string() << "')\n";
    return;
  }
  for(const char* name : {"bear.off", "cow.off"}) {
    const fs::path p = dir / name;
    Mesh base;
    if(!fs::exists(p) || !CGAL::IO::read_polygon_mesh(p.string(), base) || base.is_empty()) {
      std::cout << "connections: orbifold: " << name << " SKIPPED (cannot read " << p.string() << ")\n";
      continue;
    }
    for(SMP::Orbifold_type type : {SMP::Square, SMP::Parallelogram}) {
      Mesh m = base;
      UV_map uv = uv_of(m);
      const auto cones = SS::internal::farthest_point_cones(m, SS::internal::orbifold_cone_count(type));
      std::string msg;
      if(SS::internal::make_orbifold_tutte_uv(m, uv, cones, type, msg) != SS::SUCCESS) {
        std::cout << "connections: orbifold: " << name << ": input generation failed, SKIPPED: " << msg << "\n";
        continue;
      }
      // every pair of the orbifold's cones, both components
      std::vector<Constraint> cc;
      for(std::size_t i = 0; i < cones.size(); ++i)
        for(std::size_t j = i + 1; j < cones.size(); ++j)
          cc.emplace_back(shortest_path(m, cones[i], cones[j]), int((i + j) % 2));
      for(int reduced = 1; reduced >= 0; --reduced) {
        const SS::Snap_report r = snap_and_check(m, cc, reduced == 1, name);
        std::printf("connections: orbifold %-9s %-13s %s: %zu constraints, system %zux%zu max|C^| %s, max change %.3g\n",
                    name, SS::internal::orbifold_type_name(type), reduced ? "reduced  " : "unreduced", cc.size(),
                    r.system_rows, r.system_columns, r.max_abs_coefficient.c_str(), r.max_change);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// cycles: torus loops and cone links
// ---------------------------------------------------------------------------------------------

// a closed path along cut edges (exact UV test) that starts with the cut halfedge `first` and
// follows at each vertex the first unused cut edge; empty if `first` is not cut or the walk gets stuck
static std::vector<halfedge_descriptor> cut_loop(const Mesh& m, UV_map uv, halfedge_descriptor first)
{
  auto is_cut = [&](halfedge_descriptor h) {
    const halfedge_descriptor o = m.opposite(h);
    return !m.is_border(m.edge(h)) && (get(uv, h) != get(uv, m.prev(o)) || get(uv, m.prev(h)) != get(uv, o));
  };
  std::vector<halfedge_descriptor> path;
  if(!is_cut(first)) return path;
  std::vector<char> used(m.number_of_edges(), 0);
  const vertex_descriptor v0 = m.source(first);
  halfedge_descriptor next = first;
  for(;;) {
    used[m.edge(next).idx()] = 1;
    path.push_back(next);
    const vertex_descriptor v = m.target(next);
    if(v == v0) return path;
    next = Mesh::null_halfedge();
    for(halfedge_descriptor h : CGAL::halfedges_around_source(v, m))
      if(is_cut(h) && !used[m.edge(h).idx()]) { next = h; break; }
    if(next == Mesh::null_halfedge()) return std::vector<halfedge_descriptor>();
  }
}

// the link of vertex c, counter-clockwise, as a closed path of halfedges
static std::vector<halfedge_descriptor> link_loop(const Mesh& m, vertex_descriptor c)
{
  std::vector<halfedge_descriptor> path;
  for(halfedge_descriptor h : CGAL::halfedges_around_target(c, m)) path.push_back(m.prev(h));   // edge opposite to c
  std::reverse(path.begin(), path.end());
  // make it connected: order by following targets
  std::vector<halfedge_descriptor> ordered(1, path.front());
  while(ordered.size() < path.size()) {
    for(halfedge_descriptor h : path)
      if(m.source(h) == m.target(ordered.back())) { ordered.push_back(h); break; }
  }
  return ordered;
}

static void test_cycles()
{
  const fs::path dir(SS_SHARED_DATA_DIR);
  const fs::path torus = dir / "directional" / "torus-hex-param.obj";
  const fs::path knight = dir / "directional" / "decimated-knight-param.obj";
  if(std::string(SS_SHARED_DATA_DIR).empty() || !fs::exists(torus) || !fs::exists(knight)) {
    std::cout << "cycles: SKIPPED (no '" << torus.string() << "' or '" << knight.string() << "')\n";
    return;
  }
  {
    Mesh input;
    assert(load_obj(torus, input));
    UV_map uv_in = uv_of(input);
    // cut loops through a vertex where cut edges meet (cut-degree > 2): the torus' generators;
    // each constrains the component along which its period is (nearly) zero in the input
    std::vector<Constraint> cc;
    for(vertex_descriptor v : input.vertices()) {
      int cut_degree = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_source(v, input)) {
        const halfedge_descriptor o = input.opposite(h);
        if(get(uv_in, h) != get(uv_in, input.prev(o)) || get(uv_in, input.prev(h)) != get(uv_in, o)) ++cut_degree;
      }
      if(cut_degree <= 2) continue;
      for(halfedge_descriptor first : CGAL::halfedges_around_source(v, input)) {
        const std::vector<halfedge_descriptor> loop = cut_loop(input, uv_in, first);
        if(loop.empty()) continue;
        std::vector<std::size_t> edges, other;
        for(halfedge_descriptor h : loop) edges.push_back(std::size_t(input.edge(h).idx()));
        std::sort(edges.begin(), edges.end());
        bool duplicate = false;
        for(const Constraint& c : cc) {
          other.clear();
          for(halfedge_descriptor h : c.path) other.push_back(std::size_t(input.edge(h).idx()));
          std::sort(other.begin(), other.end());
          duplicate = duplicate || other == edges;
        }
        if(duplicate) continue;
        Constraint c(loop, 0);
        double viol[2];
        input_violation(input, uv_in, c, viol);
        c.component = viol[0] <= viol[1] ? 0 : 1;
        std::printf("cycles: torus cut loop %zu: %zu edges, input period (%.3g, %.3g) in absolute value, constrained component %d\n",
                    cc.size(), loop.size(), viol[0], viol[1], c.component);
        cc.push_back(c);
      }
      if(!cc.empty()) break;
    }
    assert(!cc.empty());
    assert(input.source(cc.front().path.front()) == input.target(cc.front().path.back()));   // closed
    for(int reduced = 1; reduced >= 0; --reduced) {
      const SS::Snap_report r = snap_and_check(input, cc, reduced == 1, "torus");
      std::printf("cycles: torus, %zu cut loops %s: system %zux%zu max|C^| %s, max change %.3g\n", cc.size(),
                  reduced ? "reduced  " : "unreduced", r.system_rows, r.system_columns, r.max_abs_coefficient.c_str(),
                  r.max_change);
    }
  }
  {
    Mesh input;
    assert(load_obj(knight, input));
    UV_map uv_in = uv_of(input);
    const std::vector<vertex_descriptor> cones = find_cones(input, uv_in);
    assert(cones.size() >= 3);
    std::vector<Constraint> cc;
    for(std::size_t i = 0; i < 3; ++i) {
      const std::vector<halfedge_descriptor> loop = link_loop(input, cones[i * cones.size() / 3]);
      assert(input.source(loop.front()) == input.target(loop.back()));
      cc.emplace_back(loop, int(i % 2));
    }
    // and a connection that goes to a cone and back along the same edges: a loop around that cone
    std::vector<halfedge_descriptor> there = shortest_path(input, cones[0], cones[1]);
    std::vector<halfedge_descriptor> back_and_forth = there;
    for(auto it = there.rbegin(); it != there.rend(); ++it) back_and_forth.push_back(input.opposite(*it));
    cc.emplace_back(back_and_forth, 0);
    for(int reduced = 1; reduced >= 0; --reduced) {
      const SS::Snap_report r = snap_and_check(input, cc, reduced == 1, "knight");
      std::printf("cycles: knight, 3 cone links + 1 back-and-forth loop %s: system %zux%zu max|C^| %s, max change %.3g\n",
                  reduced ? "reduced  " : "unreduced", r.system_rows, r.system_columns, r.max_abs_coefficient.c_str(),
                  r.max_change);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// connections: invalid paths
// ---------------------------------------------------------------------------------------------
static void test_invalid()
{
  Mesh m;
  if(!load_shared_or_skip("directional/decimated-knight-param.obj", "connections: invalid paths", m)) return;
  UV_map uv = uv_of(m);
  const std::vector<vertex_descriptor> cones = find_cones(m, uv);
  const std::vector<halfedge_descriptor> good = shortest_path(m, cones[0], cones[1]);
  assert(good.size() >= 3);
  const std::vector<std::uint64_t> before = uv_bits(m, uv);

  std::vector<std::pair<std::string, Constraint> > cases;
  cases.emplace_back("the path is empty", Constraint(std::vector<halfedge_descriptor>(), 0));
  {
    std::vector<halfedge_descriptor> gap = good;
    gap.erase(gap.begin() + 1);
    cases.emplace_back("not connected", Constraint(gap, 1));
  }
  {
    std::vector<halfedge_descriptor> reversed_edge = good;
    reversed_edge[1] = m.opposite(reversed_edge[1]);
    cases.emplace_back("not connected", Constraint(reversed_edge, 0));
  }
  {
    std::vector<halfedge_descriptor> foreign = good;
    foreign.push_back(halfedge_descriptor(Mesh::size_type(10 * m.number_of_halfedges())));
    cases.emplace_back("is not a halfedge of the mesh", Constraint(foreign, 0));
  }
  {
    std::vector<halfedge_descriptor> null = good;
    null.push_back(Mesh::null_halfedge());
    cases.emplace_back("is not a halfedge of the mesh", Constraint(null, 0));
  }
  cases.emplace_back("neither 0 (u) nor 1 (v)", Constraint(good, 2));
  cases.emplace_back("neither 0 (u) nor 1 (v)", Constraint(good, -1));

  for(int reduced = 1; reduced >= 0; --reduced) {
    for(const auto& c : cases) {
      // a valid constraint first, so that the message must name constraint 1
      std::vector<Constraint> cc(1, Constraint(good, 0));
      cc.push_back(c.second);
      SS::Snap_report r = SS::snap_seamless_parameterization(
          m, uv, SS::parameters::use_reduced_system(reduced == 1, SS::parameters::connection_constraints(cc)));
      if(r.status != SS::INVALID_INPUT || r.message.find("connection constraint 1") == std::string::npos ||
         r.message.find(c.first) == std::string::npos)
        std::cerr << "expected INVALID_INPUT with '" << c.first << "', got " << SS::status_name(r.status) << ": " << r.message << "\n";
      assert(r.status == SS::INVALID_INPUT);
      assert(r.message.find("connection constraint 1") != std::string::npos);
      assert(r.message.find(c.first) != std::string::npos);
      assert(uv_bits(m, uv) == before);
      if(reduced) std::cout << "connections: invalid: " << r.message << "\n";
    }
  }
  // an empty range is no constraint at all: the same result as without the parameter
  {
    Mesh a = m, b = m;
    UV_map uva = uv_of(a), uvb = uv_of(b);
    const std::vector<Constraint> none;
    assert(SS::snap_seamless_parameterization(a, uva).status == SS::SUCCESS);
    assert(SS::snap_seamless_parameterization(b, uvb, SS::parameters::connection_constraints(none)).status == SS::SUCCESS);
    assert(uv_bits(a, uva) == uv_bits(b, uvb));         // same input, same run
  }
  // a null halfedge on a Polyhedron_3 (whose halfedge index is read through the handle: a null pointer, a crash): no
  // position, so the path is refused like a foreign halfedge (the conversion alone, not a second snap pipeline to compile)
  {
    typedef CGAL::Polyhedron_3<K, CGAL::Polyhedron_items_with_id_3> Polyhedron;
    typedef boost::graph_traits<Polyhedron>::halfedge_descriptor Poly_halfedge;
    Polyhedron p;
    CGAL::copy_face_graph(m, p);
    std::vector<SS::Connection_constraint<Poly_halfedge> > cc(1);
    cc[0].path = {*halfedges(p).begin(), boost::graph_traits<Polyhedron>::null_halfedge()};
    std::vector<SS::internal::Connection_path> paths;
    SS::internal::connection_paths_from_parameter(p, cc, paths);
    assert(paths.size() == 1 && paths[0].halfedges.size() == 2 && paths[0].halfedges[0] >= 0 && paths[0].halfedges[1] == -1);
  }
  std::cout << "connections: invalid paths: OK\n";
}

// ---------------------------------------------------------------------------------------------
// integer-grid maps (integer_grid_map(true), is_exact_integer_grid_map())
// ---------------------------------------------------------------------------------------------

// a fan of 4 triangles around an interior vertex c, spanning 180 degrees in UV (a cone with k = 2
// across the cut edge c-w0), apex at `apex`; the translation of the cut is (2 apex_u, 2 apex_v)
static void make_half_turn_cone(Mesh& m, UV_map& uv, double apex_u, double apex_v)
{
  const vertex_descriptor c = m.add_vertex(Point_3(0, 0, 1));
  std::vector<vertex_descriptor> w;
  for(int i = 0; i < 4; ++i) w.push_back(m.add_vertex(Point_3(std::cos(CGAL_PI * i / 2), std::sin(CGAL_PI * i / 2), 0)));
  uv = uv_of(m);
  for(int i = 0; i < 4; ++i) {
    const auto f = m.add_face(c, w[i], w[(i + 1) % 4]);
    for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
      int a = -1;   // angle index of the target in the fan: 0 .. 4 (w0 is 0 in the first face, 4 in the last)
      if(m.target(h) == w[i]) a = i;
      else if(m.target(h) == w[(i + 1) % 4]) a = i + 1;
      if(a < 0) { put(uv, h, Point_2(apex_u, apex_v)); continue; }
      const double du[5] = {2, 1.5, 0, -1.5, -2}, dv[5] = {0, 1.5, 2, 1.5, 0};   // counter-clockwise, exact
      put(uv, h, Point_2(apex_u + du[a], apex_v + dv[a]));
    }
  }
}

// is_exact_integer_grid_map() on a map with a zero-length cut edge, whose UV image (a point) fits every rotation: a 2 x 2
// grid of squares in the plane whose right column is in a chart turned by 180 degrees (UV -f + (3, 7), the left column
// f), cut along x = 1 from the border vertex a = (1, 0) through the interior vertex v = (1, 1) to the border. f puts a
// and v onto one half-integer point (0.5, 0.5); the cut edge v-b has rotation 2. The map is an exact integer-grid map
// with rotation 2 on a-v too (v regular); the least rotation that fits a-v, 0, made v a cone of 180 degrees off the
// integer points (the checker refused such a map that the snap had made exactly: the dragon, scaled and quantized)
static void test_zero_length_cut_edge()
{
  Mesh m;
  std::map<std::pair<int, int>, vertex_descriptor> vertex;
  for(int y = 0; y <= 2; ++y)
    for(int x = 0; x <= 2; ++x) vertex[{x, y}] = m.add_vertex(Point_3(x, y, 0));
  UV_map uv = uv_of(m);
  auto f = [](int x, int y) { return x == 1 && y == 0 ? Point_2(0.5, 0.5) : Point_2(x - 0.5, y - 0.5); };
  for(int j = 0; j < 2; ++j)
    for(int i = 0; i < 2; ++i) {
      const int X[4] = {i, i + 1, i + 1, i}, Y[4] = {j, j, j + 1, j + 1};
      for(const std::array<int, 3>& t : {std::array<int, 3>{{0, 1, 2}}, std::array<int, 3>{{0, 2, 3}}}) {
        auto corner = [&](int c) { return vertex[std::make_pair(X[t[std::size_t(c)]], Y[t[std::size_t(c)]])]; };
        const Mesh::Face_index face = m.add_face(corner(0), corner(1), corner(2));
        assert(face != Mesh::null_face());
        for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(face), m)) {
          const Point_3& q = m.point(m.target(h));
          const Point_2 a = f(int(q.x()), int(q.y()));
          put(uv, h, i == 0 ? a : Point_2(3 - a.x(), 7 - a.y()));
        }
      }
    }
  assert(SS::is_exactly_seamless(m, uv) && SS::is_exact_integer_grid_map(m, uv));
  std::cout << "integer grid: a zero-length cut edge takes the rotation that leaves its interior end regular\n";
}

// The integer-grid snap of (m, uv) at grid scale `scale` is refused with `status`, the map untouched, the message naming
// the finer grid scale `named` (`named` / `scale` times this one); at that grid scale the map is an exact integer-grid
// map already and snaps to itself, bit for bit. Returns the refusal's report.
static SS::Snap_report check_finer_grid_scale_named(Mesh& m, UV_map uv, double scale, SS::Status status, double named)
{
  const std::vector<std::uint64_t> bits = uv_bits(m, uv);
  const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).grid_scale(scale));
  if(r.status != status) std::cerr << SS::status_name(r.status) << " " << r.message << std::endl;
  const std::string n = std::to_string(long(named)), times = std::to_string(long(named / scale));
  assert(r.status == status && uv_bits(m, uv) == bits);
  assert(r.message.find("at grid scale " + n + " (" + times + " times this one) every translation, cone and align edge") !=
         std::string::npos);
  const SS::Snap_report rn = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).grid_scale(named));
  assert(rn.status == SS::SUCCESS && uv_bits(m, uv) == bits && SS::is_exact_integer_grid_map(m, uv, SS::parameters::grid_scale(named)));
  return r;
}

static void test_integer_grid_analytic()
{
  // torus: translation 3.0000000001 -> exactly 3; the default mode keeps it (already exactly seamless)
  {
    Mesh m; UV_map uv;
    make_flat_torus(m, uv, 3, 3.0000000001);
    assert(SS::is_exactly_seamless(m, uv) && !SS::is_exact_integer_grid_map(m, uv));
    Mesh d = m; UV_map uvd = uv_of(d);
    const SS::Snap_report rd = SS::snap_seamless_parameterization(d, uvd);
    assert(rd.status == SS::SUCCESS && uv_bits(d, uvd) == uv_bits(m, uv));
    assert(rd.integer_translations_before == rd.integer_translations_after && rd.integer_translations_before < rd.cut_edges);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true));
    if(r.status != SS::SUCCESS) std::cerr << r.message << std::endl;
    assert(r.status == SS::SUCCESS);
    assert(SS::is_exact_integer_grid_map(m, uv) && SS::is_exactly_seamless(m, uv));
    assert(r.integer_translations_after == r.cut_edges && r.cut_edges > 0);
    assert(r.max_change > 0 && r.max_change < 1e-10);
    const SS::Quad_valences qv = SS::quad_valences(m, uv);   // a flat torus: every vertex regular
    assert(qv.status == SS::SUCCESS && qv.valence == std::vector<int>(9, 4) && qv.border.empty());
    // the same map at grid scale 4 (UVs / 4): grid_scale(4) gives the result / 4, bit for bit
    Mesh q; UV_map uvq;
    make_flat_torus(q, uvq, 3, 3.0000000001);
    for(halfedge_descriptor h : q.halfedges()) put(uvq, h, Point_2(get(uvq, h).x() / 4, get(uvq, h).y() / 4));
    const SS::Snap_report r4 = SS::snap_seamless_parameterization(q, uvq, SS::parameters::integer_grid_map(true,
                                                                  SS::parameters::grid_scale(4.)));
    assert(r4.status == SS::SUCCESS && SS::is_exact_integer_grid_map(q, uvq, SS::parameters::grid_scale(4.)));
    assert(!SS::is_exact_integer_grid_map(q, uvq));
    for(halfedge_descriptor h : q.halfedges())          // both snapped in this run from inputs that differ by 2^2 exactly
      assert(get(uvq, h).x() * 4 == get(uv, h).x() && get(uvq, h).y() * 4 == get(uv, h).y());
    // a grid scale that is not a power of two is refused, map untouched
    const std::vector<std::uint64_t> bits = uv_bits(q, uvq);
    const SS::Snap_report r3 = SS::snap_seamless_parameterization(q, uvq, SS::parameters::integer_grid_map(true,
                                                                  SS::parameters::grid_scale(3.)));
    assert(r3.status == SS::INVALID_INPUT && uv_bits(q, uvq) == bits);
    // so are tolerances that are NaN, negative or (but max_untangle_change) infinite: NaN used to pass as "no bound"
    // (max_untangle_change), "align nothing" (alignment_tolerance) or "not quarter-turn seamless" (rotation_tolerance)
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = HUGE_VAL;
    for(const double bad : {nan, -1., inf}) {
      const SS::Snap_report ra = SS::snap_seamless_parameterization(q, uvq, SS::parameters::alignment_tolerance(bad));
      const SS::Snap_report rr = SS::snap_seamless_parameterization(q, uvq, SS::parameters::rotation_tolerance(bad));
      assert(ra.status == SS::INVALID_INPUT && ra.message.find("alignment_tolerance = ") == 0);
      assert(rr.status == SS::INVALID_INPUT && rr.message.find("rotation_tolerance = ") == 0);
      if(bad == inf) continue;
      const SS::Snap_report rm = SS::snap_seamless_parameterization(q, uvq, SS::parameters::integer_grid_map(true).grid_scale(4.)
                                                                                .max_untangle_change(bad));
      assert(rm.status == SS::INVALID_INPUT && rm.message.find("max_untangle_change = ") == 0);
    }
    assert(uv_bits(q, uvq) == bits);
    std::cout << "integer grid: torus translation 3.0000000001 -> 3: OK (" << r.message << ")\n";
  }
  // torus whose period is far from an integer, at every power-of-two grid scale too (3.4 is not dyadic): refused with
  // the reason (a map that was never quantized), map untouched
  {
    Mesh m; UV_map uv;
    make_flat_torus(m, uv, 3, 3.4);
    const std::vector<std::uint64_t> bits = uv_bits(m, uv);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true));
    assert(r.status == SS::INVALID_INPUT && uv_bits(m, uv) == bits);
    assert(r.message.find("not near an integer-grid map") != std::string::npos);
    assert(r.message.find("at any grid scale up to 2^30") != std::string::npos && r.message.find("not quantized") != std::string::npos &&
           r.message.find("quantize(true)") != std::string::npos);
    std::cout << "integer grid: far from integers refused: " << r.message << "\n";
  }
  // torus of period 2.5: refused at grid scale 1, with the grid scale at which every translation is an integer (2)
  // named; at that grid scale it snaps
  {
    Mesh m; UV_map uv;
    make_flat_torus(m, uv, 3, 2.5);
    std::cout << "integer grid: a finer grid scale named: " << check_finer_grid_scale_named(m, uv, 1, SS::INVALID_INPUT, 2).message << "\n";
  }
  // torus of period 2^60 grid units: integer translations beyond what the rows hold exactly: RANGE_EXCEEDED (it was
  // INVALID_INPUT, "farther than 0.001 from integers", for integers), map untouched
  {
    Mesh m; UV_map uv;
    make_flat_torus(m, uv, 3, 0x1p60);
    const std::vector<std::uint64_t> bits = uv_bits(m, uv);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true));
    assert(r.status == SS::RANGE_EXCEEDED && uv_bits(m, uv) == bits);
    assert(r.message.find("2^52 or more") != std::string::npos);
    std::cout << "integer grid: translations of 2^60 refused: " << r.message << "\n";
    // the same torus at 2^1000 (UVs whose products overflow): the same refusal, not a rotation of NaN degrees (the
    // rotation fit works at the scale of a unit UV diagonal)
    Mesh big; UV_map uvb;
    make_flat_torus(big, uvb, 3, 3);
    for(halfedge_descriptor h : big.halfedges())
      if(!big.is_border(h)) put(uvb, h, Point_2(0x1p1000 * get(uvb, h).x(), 0x1p1000 * get(uvb, h).y()));
    const SS::Snap_report rb = SS::snap_seamless_parameterization(big, uvb, SS::parameters::integer_grid_map(true));
    assert(rb.status == SS::RANGE_EXCEEDED && rb.message.find("2^52 or more") != std::string::npos);
    assert(rb.message.find("nan") == std::string::npos);
    // a grid scale of 2^-1074: the corner mesh in grid units (subnormal UVs), a map far within one grid cell, refused
    // as such before its fixed-point grid (below the doubles' range: RANGE_EXCEEDED, whose message said "too large"
    // with numbers inside the limits it named) is reached; that grid's own refusal: test_projection
    Mesh tiny; UV_map uvt;
    make_flat_torus(tiny, uvt, 3, 3);
    const std::vector<std::uint64_t> tiny_bits = uv_bits(tiny, uvt);
    const SS::Snap_report rt = SS::snap_seamless_parameterization(tiny, uvt, SS::parameters::integer_grid_map(true,
                                                                  SS::parameters::grid_scale(0x1p-1074)));
    assert(rt.status == SS::INVALID_INPUT && uv_bits(tiny, uvt) == tiny_bits);
    assert(rt.message.find("spans less than one grid cell") != std::string::npos && rt.message.find("scale the map up") != std::string::npos);
  }
  // the torus scaled by 1e-7 (no cones): within one grid cell its translations are "near" the integer 0, and rounded
  // to it they collapsed the map (SUCCESS with negative triangles the untangling could not remove); refused, untouched
  {
    Mesh m; UV_map uv;
    make_flat_torus(m, uv, 3, 3);
    for(halfedge_descriptor h : m.halfedges())
      if(!m.is_border(h)) put(uv, h, Point_2(1e-7 * get(uv, h).x(), 1e-7 * get(uv, h).y()));
    const std::vector<std::uint64_t> bits = uv_bits(m, uv);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true));
    assert(r.status == SS::INVALID_INPUT && uv_bits(m, uv) == bits);
    assert(r.message.find("spans less than one grid cell") != std::string::npos && r.message.find("would collapse") != std::string::npos);
    std::cout << "integer grid: a torus within one grid cell refused: " << r.message << "\n";
  }
  // half-turn cone: apex (0.5, 0) and translation (1, 0) = integer, but the fixed point is half-integer
  {
    Mesh m; UV_map uv;
    make_half_turn_cone(m, uv, 0.5, 0);
    assert(SS::is_exactly_seamless(m, uv) && !SS::is_exact_integer_grid_map(m, uv));
    const std::vector<std::uint64_t> bits = uv_bits(m, uv);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true));
    if(r.status != SS::INFEASIBLE) std::cerr << SS::status_name(r.status) << " " << r.message << std::endl;
    assert(r.status == SS::INFEASIBLE && uv_bits(m, uv) == bits);
    assert(r.message.find("cone at vertex 0") != std::string::npos && r.message.find("(0.5, 0)") != std::string::npos);
    // the grid scale at which the cone is on an integer point is named (the translations are integers at scale 1)
    check_finer_grid_scale_named(m, uv, 1, SS::INFEASIBLE, 2);
    std::cout << "integer grid: half-integer cone refused: " << r.message << "\n";
  }
  // half-turn cone at (0.25, 0), translation (0.5, 0): the translations are integers at grid scale 2, the cone only at 4,
  // which is the one named
  {
    Mesh m; UV_map uv;
    make_half_turn_cone(m, uv, 0.25, 0);
    const std::string message = check_finer_grid_scale_named(m, uv, 1, SS::INVALID_INPUT, 4).message;
    assert(message.find("not near an integer-grid map") != std::string::npos);
    check_finer_grid_scale_named(m, uv, 2, SS::INFEASIBLE, 4);
    std::cout << "integer grid: a finer grid scale named for a cone: " << message << "\n";
  }
  // a 2 x 2 grid mapped to [0.25, 1.25]^2 (no seam): its border edges are align edges on the isolines 0.25 and 1.25,
  // integers at grid scale 4, which is named; it snaps there (already exact); Snap_report::near_integer_grid_map says so
  {
    Mesh m;
    triangulated_grid(m, 2, true);
    UV_map uv = uv_of(m);
    for(halfedge_descriptor h : m.halfedges())
      if(!m.is_border(h)) put(uv, h, Point_2(m.point(m.target(h)).x() / 2 + 0.25, m.point(m.target(h)).y() / 2 + 0.25));
    const SS::Snap_report r = check_finer_grid_scale_named(m, uv, 1, SS::INVALID_INPUT, 4);
    assert(r.align_edges == 8 && r.message.find("align edge (") != std::string::npos);
    // the default snap does not call it an integer-grid map at grid scale 1 (its align edges are off the integers),
    // but does at grid scale 4, where they lie on the isolines 1 and 5
    for(double S : {1., 4.}) {
      Mesh c = m;
      UV_map cuv = uv_of(c);
      const SS::Snap_report d = SS::snap_seamless_parameterization(c, cuv, SS::parameters::grid_scale(S));
      assert(d.status == SS::SUCCESS && d.align_edges == 8 && d.near_integer_grid_map == (S == 4));
    }
    // its border edges as constrained edges of the checker: on the isolines 0.25 / 1.25 at grid scale 1, 1 / 5 at grid
    // scale 4 (constrained border edges were never checked: true at both)
    auto border = m.add_property_map<Mesh::Edge_index, bool>("e:border", false).first;
    for(Mesh::Edge_index e : m.edges()) put(border, e, m.is_border(e));
    assert(!SS::is_exact_integer_grid_map(m, uv, SS::parameters::edge_is_constrained_map(border)) &&
           SS::is_exact_integer_grid_map(m, uv, SS::parameters::edge_is_constrained_map(border).grid_scale(4.)));
    std::cout << "integer grid: a finer grid scale named for align edges: " << r.message << "\n";
  }
  // the same cone near an integer point (apex (1 + 1e-9, -2e-9)): pinned exactly to (1, 0)
  {
    Mesh m; UV_map uv;
    make_half_turn_cone(m, uv, 1 + 1e-9, -2e-9);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true));
    if(r.status != SS::SUCCESS) std::cerr << SS::status_name(r.status) << " " << r.message << std::endl;
    assert(r.status == SS::SUCCESS && r.pinned_cones == 1 && r.field_cones == 1);
    assert(r.cones_on_integer_points_before == 0 && r.cones_on_integer_points_after == 1);
    assert(SS::is_exact_integer_grid_map(m, uv));
    for(halfedge_descriptor h : m.halfedges())
      if(!m.is_border(h) && m.target(h) == vertex_descriptor(0)) assert(get(uv, h) == Point_2(1, 0));
    const SS::Quad_valences q = SS::quad_valences(m, uv);   // the 180-degree cone: valence 2
    assert(q.status == SS::SUCCESS && q.valence[0] == 2 && q.border.size() == 4);
    std::cout << "integer grid: near-integer cone pinned: OK\n";
  }
}

// quad_valences() of a snapped integer-grid map. With fold-overs or zero-area triangles left: refused
// (FOLD_OVERS), listing exactly the faces the snap report counts. Fold-free: every interior valence is
// 0 mod 4 exactly away from the field cones, and on a closed map Gauss-Bonnet holds exactly:
// sum over the interior vertices of (4 - valence) = 4 chi.
static void check_quad_valences(const Mesh& m, UV_map uv, const SS::Snap_report& r, const char* what)
{
  const SS::Quad_valences q = SS::quad_valences(m, uv);
  if(r.flips_after_repair + r.degenerate_after_repair > 0) {
    assert(q.status == SS::FOLD_OVERS && q.valence.empty());
    assert(q.fold_overs.size() == r.flips_after_repair && q.zero_area_faces.size() == r.degenerate_after_repair);
    std::printf("quad valences: %-44s FOLD_OVERS: %s\n", what, q.message.c_str());
    return;
  }
  assert(q.status == SS::SUCCESS && q.valence.size() == m.number_of_vertices());
  std::vector<char> border(q.valence.size(), 0);
  for(std::size_t v : q.border) border[v] = 1;
  std::size_t off_class = 0;
  long sum = 0;
  for(std::size_t v = 0; v < q.valence.size(); ++v) {
    if(border[v]) continue;
    sum += 4 - q.valence[v];
    off_class += ((q.valence[v] % 4) + 4) % 4 != 0 ? 1 : 0;
  }
  const long chi = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
  std::printf("quad valences: %-44s %zu border; %zu not = 0 mod 4 (field cones %zu); sum(4 - valence) %ld, 4 chi = %ld\n",
              what, q.border.size(), off_class, r.field_cones, sum, 4 * chi);
  assert(off_class == r.field_cones);
  if(q.border.empty()) assert(sum == 4 * chi);
}

// every near-IGM file of the shared data: SUCCESS, exact IGM (checked independently), small change, no new flips
// (the snap alone: untangle(false))
// quantize(true): maps that are not near an integer-grid map get integer translations chosen for them (each cone onto
// one of the four integer points around it, the rest along the cut graph) and snap to exact integer-grid maps; maps that are
// near one are rounded as without it, bit for bit
// A cut graph with cycles (Directional's full-seamless dragon cuts its sphere into several charts), its UVs scaled by 1.5
// so that they are near no integer-grid map, quantized at grid scale 1 with pairs merged and without untangling: the
// edges that close the cycles are the free choices. Before, a free choice could fall on an edge that no cycle holds and
// cut a part off its root: INFEASIBLE, the translations around vertex 4211 composing to (1, 1). The result also has
// zero-length cut edges at half-integer points, which is_exact_integer_grid_map() must read with the rotations that
// leave their interior ends regular (test_zero_length_cut_edge())
// The classes of the integer-grid rows (isoline_classes.h): x = +-x' + c along the links, a cycle that fixes a class
// (x = -x + c: c / 2) or contradicts it (x = x + c, c != 0; an odd c; two fixed values), and rollback() undoing every
// change of a tentative row, path compression included
static void test_isoline_classes()
{
  using CGAL::Seamless_snapping::internal::Isoline_classes;
  auto value = [](Isoline_classes& c, std::size_t a, long& x) {   // the value of a where its class is fixed
    const Isoline_classes::Relation r = c.find(a);
    long root;
    if(!c.fixed(r.root, root)) return false;
    x = r.sign * root + r.offset;
    return true;
  };
  Isoline_classes c(6);
  c.relate(1, -1, 0, 5);                   // x1 = -x0 + 5
  c.relate(2, 1, 1, -2);                   // x2 = x1 - 2 = -x0 + 3
  c.relate(3, 1, 2, 0);                    // x3 = x2
  long x;
  assert(!c.conflict() && !value(c, 3, x));
  c.relate(0, 1, 3, 7);                    // x0 = x3 + 7 = -x0 + 10: x0 = 5, x3 = -2
  assert(!c.conflict() && value(c, 0, x) && x == 5 && value(c, 3, x) && x == -2 && value(c, 1, x) && x == 0);
  c.checkpoint();                          // a tentative row that contradicts the class: x3 = 4
  c.relate(4, 1, 3, 6);                    // x4 = x3 + 6 = 4 (joins 4 to the fixed class)
  c.relate(4, 1, 5, 0);
  c.relate(5, -1, 3, 1);                   // x5 = -x3 + 1 = 3, but x5 = x4 = 4
  assert(c.conflict());
  c.rollback();                            // as before the checkpoint: 4 and 5 alone, no conflict
  assert(!c.conflict() && !value(c, 4, x) && !value(c, 5, x) && value(c, 2, x) && x == -2);
  c.relate(4, 1, 4, 0);                    // x4 = x4: holds for every value
  assert(!c.conflict() && !value(c, 4, x));
  c.relate(4, -1, 5, 3);
  c.relate(5, -1, 4, 3);                   // the same row the other way round
  assert(!c.conflict() && !value(c, 4, x));
  c.relate(5, 1, 4, 0);                    // x4 = -x4 + 3: 3 / 2, not an integer
  assert(c.conflict() && !c.range_exceeded());
  Isoline_classes d(2);
  d.relate(0, 1, 1, 1);
  d.relate(1, 1, 0, 1);                    // x0 = x0 + 2
  assert(d.conflict() && d.conflict_a() == 1 && d.conflict_b() == 0);
  std::cout << "isoline classes: relations, fixed cycles, contradictions, rollback\n";
}

static void test_quantized_cut_cycles()
{
  Mesh m;
  if(!load_shared_or_skip("directional/dragon-param-full-seamless.obj", "quantization: a cut graph with cycles", m)) return;
  UV_map uv = uv_of(m);
  multiply_uvs(m, uv, 1.5);
  const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).quantize(true)
                                                                          .merge_cone_pairs(true).untangle(false));
  if(r.status != SS::SUCCESS) std::cerr << r.message << std::endl;
  assert(r.status == SS::SUCCESS && r.quantized && SS::is_exact_integer_grid_map(m, uv));
  std::cout << "quantization: the full-seamless dragon x 1.5 (cut graph with cycles): exact integer-grid map, "
            << r.field_cones << " cones\n";
}

static void test_quantization()
{
  const auto quantized = SS::parameters::integer_grid_map(true).quantize(true);
  // a torus of period 3.4 (no cone: its cut graph is two cycles, each with one free translation, rounded to 3)
  {
    Mesh m; UV_map uv;
    make_flat_torus(m, uv, 3, 3.4);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, quantized);
    if(r.status != SS::SUCCESS) std::cerr << r.message << std::endl;
    assert(r.status == SS::SUCCESS && r.quantized && !r.near_integer_grid_map);
    assert(SS::is_exact_integer_grid_map(m, uv) && r.integer_translations_after == r.cut_edges);
    assert((r.total_max_change * r.grid_scale) > 0 && (r.total_max_change * r.grid_scale) <= 0.4);
    std::cout << "quantization: torus of period 3.4: exact integer-grid map, max change " << (r.total_max_change * r.grid_scale) << " cells\n";
  }
  // a half-turn cone at (0.25, 0), its translation (0.5, 0): neither on the integers; quantized, the cone moves onto the
  // nearest integer point (0, 0) and the translation becomes 2 (0, 0) - its own half turn of it, an integer vector
  {
    Mesh m; UV_map uv;
    make_half_turn_cone(m, uv, 0.25, 0);
    const std::vector<std::uint64_t> bits = uv_bits(m, uv);
    const SS::Snap_report refused = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true));
    assert(refused.status == SS::INVALID_INPUT && !refused.quantized && uv_bits(m, uv) == bits);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, quantized);
    if(r.status != SS::SUCCESS) std::cerr << r.message << std::endl;
    assert(r.status == SS::SUCCESS && r.quantized && r.pinned_cones == 1 && SS::is_exact_integer_grid_map(m, uv));
    const vertex_descriptor apex(0);
    for(halfedge_descriptor h : CGAL::halfedges_around_target(m.halfedge(apex), m))
      if(!m.is_border(h)) assert(get(uv, h) == Point_2(0, 0));
  }
  // a map near an integer-grid map: quantize(true) rounds it, the same bits as without
  {
    Mesh a; UV_map uva;
    make_flat_torus(a, uva, 3, 3.0000000001);
    Mesh b = a; UV_map uvb = uv_of(b);
    const SS::Snap_report ra = SS::snap_seamless_parameterization(a, uva, quantized);
    const SS::Snap_report rb = SS::snap_seamless_parameterization(b, uvb, SS::parameters::integer_grid_map(true));
    assert(ra.status == SS::SUCCESS && rb.status == SS::SUCCESS && !ra.quantized && uv_bits(a, uva) == uv_bits(b, uvb));
  }
  // without integer_grid_map it would do nothing: refused, as the command line and the Python module refuse it (it was
  // the default snap, SUCCESS), map untouched; so are merge_cone_pairs and separate_cone_pairs
  {
    Mesh m; UV_map uv;
    make_flat_torus(m, uv, 3, 3.4);
    const std::vector<std::uint64_t> bits = uv_bits(m, uv);
    for(int which = 0; which < 3; ++which) {
      const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::quantize(which == 0)
                                                                   .merge_cone_pairs(which == 1).separate_cone_pairs(which == 2));
      assert(r.status == SS::INVALID_INPUT && uv_bits(m, uv) == bits && r.message.find("needs integer_grid_map(true)") != std::string::npos);
    }
  }
  // real maps before their integer rounding (../shared/data): an MIQ map of the retina, whose translations are integers
  // at no grid scale; quantized at grid scale 8 it snaps to an exact, fold-free integer-grid map (its quad mesh: test_quad)
  Mesh m;
  if(!load_shared_or_skip("progressive_embedding/retinal_miq.obj", "quantization: retinal_miq", m)) return;
  UV_map uv = uv_of(m);
  const std::vector<std::uint64_t> bits = uv_bits(m, uv);
  const SS::Snap_report refused = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).grid_scale(8.));
  assert(refused.status == SS::INVALID_INPUT && refused.message.find("not quantized") != std::string::npos && uv_bits(m, uv) == bits);
  const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, quantized.grid_scale(8.));
  if(r.status != SS::SUCCESS) std::cerr << r.message << std::endl;
  assert(r.status == SS::SUCCESS && r.quantized && SS::is_exact_integer_grid_map(m, uv, SS::parameters::grid_scale(8.)));
  assert(r.flips_after_repair == 0 && r.degenerate_after_repair == 0 && r.pinned_cones == r.field_cones);
  std::cout << "quantization: retinal_miq at grid scale 8: exact integer-grid map, " << r.field_cones << " cones, max / RMS change "
            << (r.total_max_change * r.grid_scale) << " / " << (r.total_rms_change * r.grid_scale) << " cells\n";
  test_quantized_cut_cycles();
}

static void test_integer_grid_data()
{
  const char* files[] = {"libqex/duck_miq_8_param.obj", "libqex/duck_qc_8_param.obj", "libqex/fandisk_param.obj",
                         "directional/horsers-param-full-seamless.obj", "directional/dragon-param-full-seamless.obj"};
  for(const char* f : files) {
    Mesh m;
    const fs::path path = fs::path(SS_SHARED_DATA_DIR) / f;
    if(sanitizer_subset() && fs::exists(path) && fs::file_size(path) > 600 * 1000) continue;   // see mesh_test_support.h
    if(!load_shared_or_skip(f, "integer grid: data", m)) continue;
    UV_map uv = uv_of(m);
    // the snap alone (the untangling, on by default with integer_grid_map, is tested in test_untangling_data())
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).untangle(false));
    if(r.status != SS::SUCCESS) std::cerr << f << ": " << SS::status_name(r.status) << " " << r.message << std::endl;
    std::printf("integer grid: %-44s translations %4zu -> %4zu of %4zu, cones on integers %3zu -> %3zu of %3zu"
                " (not field cones %zu), change %.3g, flips %zu -> %zu (new %zu), %.0f ms\n",
                f, r.integer_translations_before, r.integer_translations_after, r.cut_edges,
                r.cones_on_integer_points_before, r.cones_on_integer_points_after, r.field_cones, r.not_field_cones.size(),
                r.max_change, r.flips_before, r.flips_after_repair, r.flips_unrepaired, r.total_ms);
    assert(r.status == SS::SUCCESS);
    assert(SS::is_exact_integer_grid_map(m, uv) && SS::is_exactly_seamless(m, uv));
    assert(r.integer_translations_after == r.cut_edges && r.cones_on_integer_points_after == r.field_cones);
    assert(r.max_change < 1e-5);
    assert(r.flips_after_repair <= r.flips_before);
    assert(r.flips_unrepaired == 0 && r.degenerate_unrepaired == r.degenerate_forced);
    check_quad_valences(m, uv, r, f);
    // the package reads its own exact output again: snapped once more (either mode), it is found exact and
    // nothing is written, bit for bit (the dragon's cone pairs on one integer point hide cones of the field
    // from the UV angle sums, and its seam arcs run through them: rotation_fit.h)
    for(bool igm : {false, true}) {
      Mesh m2 = m;
      UV_map uv2 = uv_of(m2);
      const SS::Snap_report r2 = SS::snap_seamless_parameterization(m2, uv2, SS::parameters::integer_grid_map(igm).untangle(false));
      if(r2.status != SS::SUCCESS || r2.max_input_violation != 0)
        std::cerr << f << ": snapped again: violation " << r2.max_input_violation << ", " << SS::status_name(r2.status) << " "
                  << r2.message << std::endl;
      assert(r2.status == SS::SUCCESS && r2.max_input_violation == 0 && uv_bits(m2, uv2) == uv_bits(m, uv));
    }
  }
}

// CGAL's Orbifold Tutte Square map puts its cones on the corners of the unit square, with integer
// translations: it is near an integer-grid map and snaps to an exact one. The same map scaled by 0.3
// is not near one: refused with advice, map untouched.
static void test_integer_grid_orbifold()
{
  Mesh m;
  if(!load_shared_or_skip("cgal-orbifold-generated/bear_orbifold_square_mvc.obj", "integer grid: orbifold", m)) return;
  const Mesh m0 = m;
  UV_map uv = uv_of(m);
  const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true));
  assert(r.status == SS::SUCCESS && SS::is_exact_integer_grid_map(m, uv));   // exact: Gmpq, zero tolerance
  assert(r.max_change < 1e-10);   // a separate property: the snap moved the map little (relative to its UV diagonal)
  // scaled by 1.3 its cones and translations are off the integers; by 0.3 it spans less than one grid cell, so that
  // its 3 cones would all fall onto one integer point (refused before the translations are looked at)
  for(const std::pair<double, const char*>& c : {std::make_pair(1.3, "not near an integer-grid map"),
                                                 std::make_pair(0.3, "spans less than one grid cell")}) {
    Mesh scaled = m0;
    UV_map uvs = uv_of(scaled);
    for(halfedge_descriptor h : scaled.halfedges()) put(uvs, h, Point_2(c.first * get(uvs, h).x(), c.first * get(uvs, h).y()));
    const std::vector<std::uint64_t> bits = uv_bits(scaled, uvs);
    const SS::Snap_report rs = SS::snap_seamless_parameterization(scaled, uvs, SS::parameters::integer_grid_map(true));
    assert(rs.status == SS::INVALID_INPUT && uv_bits(scaled, uvs) == bits);
    assert(rs.message.find(c.second) != std::string::npos);
    std::cout << "integer grid: orbifold Tutte square map scaled by " << c.first << " refused: " << rs.message << "\n";
  }
  std::cout << "integer grid: orbifold Tutte square map: " << r.integer_translations_before << " -> " << r.integer_translations_after
            << " of " << r.cut_edges << " integer translations\n";
}

// ---------------------------------------------------------------------------------------------
// pinned corners (pinned_corner_map), default and integer-grid mode
// ---------------------------------------------------------------------------------------------

typedef Mesh::Property_map<halfedge_descriptor, bool> Pin_map;

static Pin_map pins_of(Mesh& m)
{
  Pin_map pin = m.add_property_map<halfedge_descriptor, bool>("h:pinned_test", false).first;
  for(halfedge_descriptor h : m.halfedges()) put(pin, h, false);
  return pin;
}

// pins every non-border corner whose UV is `p`; returns how many
static std::size_t pin_uv(const Mesh& m, UV_map uv, Pin_map pin, const Point_2& p)
{
  std::size_t n = 0;
  for(halfedge_descriptor h : m.halfedges())
    if(!m.is_border(h) && get(uv, h) == p) { put(pin, h, true); ++n; }
  return n;
}

// true iff every pinned corner of (m, uv) has the bits of the same corner of (m0, uv0)
static bool pinned_bit_identical(const Mesh& m, UV_map uv, Pin_map pin, const std::vector<std::uint64_t>& bits0)
{
  const std::vector<std::uint64_t> bits = uv_bits(m, uv);
  std::size_t i = 0;
  for(halfedge_descriptor h : m.halfedges()) {   // uv_bits: 2 words per halfedge, in this order
    if(get(pin, h) && (bits[2 * i] != bits0[2 * i] || bits[2 * i + 1] != bits0[2 * i + 1])) return false;
    ++i;
  }
  return true;
}

// the flat 3 x 3 torus with period 3 + 2^-51 in u, and the corners of vertex (1, 0) whose UV is (1, 0)
// moved by 2^-40 in u: not exactly seamless (the translation of the j = 0 seam differs at vertex (1, 0))
static void make_perturbed_torus(Mesh& m, UV_map& uv, double scale)
{
  make_flat_torus(m, uv, 3, 3 + std::ldexp(1., -51));
  for(halfedge_descriptor h : m.halfedges())
    if(!m.is_border(h) && get(uv, h) == Point_2(1, 0)) put(uv, h, Point_2(1 + std::ldexp(1., -40), 0));
  multiply_uvs(m, uv, scale);
}

static void test_pinned_corners_analytic()
{
  for(bool igm : {false, true}) {
    const char* mode = igm ? "integer grid" : "default";
    std::vector<std::uint64_t> reference;    // the result at scale 1, for the covariance check
    for(int j : {0, -7, 9}) {
      const double scale = std::ldexp(1., j);
      Mesh m; UV_map uv;
      make_perturbed_torus(m, uv, scale);
      assert(!SS::is_exactly_seamless(m, uv) && SS::quad_valences(m, uv).status == SS::INVALID_INPUT);
      Pin_map pin = pins_of(m);
      // vertex (1, 0) on the side j = 3 of the seam j = 0 (its other side is the perturbed one), vertex (2, 0)
      // on the side j = 0, and the free vertex (1, 1)
      assert(pin_uv(m, uv, pin, Point_2(scale, 3 * scale)) > 0 && pin_uv(m, uv, pin, Point_2(2 * scale, 0)) > 0);
      assert(pin_uv(m, uv, pin, Point_2(scale, scale)) == 6);
      const std::vector<std::uint64_t> bits0 = uv_bits(m, uv);
      const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv,
          SS::parameters::pinned_corner_map(pin).integer_grid_map(igm).grid_scale(igm ? 1 / scale : 1.));
      if(r.status != SS::SUCCESS) std::cerr << mode << ": " << SS::status_name(r.status) << " " << r.message << std::endl;
      assert(r.status == SS::SUCCESS && r.pinned_sectors == 3);
      assert(uv_bits(m, uv) != bits0 && pinned_bit_identical(m, uv, pin, bits0));
      assert(SS::is_exactly_seamless(m, uv));
      if(igm) assert(SS::is_exact_integer_grid_map(m, uv, SS::parameters::grid_scale(1 / scale)));
      // the full sector system (use_reduced_system(false)) keeps the pins as well
      if(j == 0) {
        Mesh u; UV_map uvu;
        make_perturbed_torus(u, uvu, 1);
        Pin_map pu = pins_of(u);
        pin_uv(u, uvu, pu, Point_2(1, 3)); pin_uv(u, uvu, pu, Point_2(2, 0)); pin_uv(u, uvu, pu, Point_2(1, 1));
        const std::vector<std::uint64_t> bu = uv_bits(u, uvu);
        const SS::Snap_report ru = SS::snap_seamless_parameterization(u, uvu,
            SS::parameters::pinned_corner_map(pu).integer_grid_map(igm).use_reduced_system(false));
        assert(ru.status == SS::SUCCESS && ru.pinned_sectors == 3 && pinned_bit_identical(u, uvu, pu, bu));
        assert(SS::is_exactly_seamless(u, uvu) && (!igm || SS::is_exact_integer_grid_map(u, uvu)));
      }
      // the same pins without the flag: the result differs only where the pins hold it (sanity of the test:
      // the pinned sectors do move without pins)
      if(j == 0) {
        Mesh f; UV_map uvf;
        make_perturbed_torus(f, uvf, 1);
        Pin_map pf = pins_of(f);
        pin_uv(f, uvf, pf, Point_2(1, 3)); pin_uv(f, uvf, pf, Point_2(2, 0)); pin_uv(f, uvf, pf, Point_2(1, 1));
        const std::vector<std::uint64_t> b0 = uv_bits(f, uvf);
        const SS::Snap_report rf = SS::snap_seamless_parameterization(f, uvf, SS::parameters::integer_grid_map(igm));
        assert(rf.status == SS::SUCCESS && !pinned_bit_identical(f, uvf, pf, b0));
      }
      // covariance: the result at scale 2^j is the result at scale 1 times 2^j, bit for bit (a relation between
      // two snaps of this run; the pinned UVs are exact binary fractions)
      std::vector<std::uint64_t> unscaled;
      for(halfedge_descriptor h : m.halfedges()) {
        const double a = get(uv, h).x() / scale, b = get(uv, h).y() / scale;
        std::uint64_t wa, wb;
        std::memcpy(&wa, &a, 8); std::memcpy(&wb, &b, 8);
        unscaled.push_back(wa); unscaled.push_back(wb);
      }
      if(j == 0) reference = unscaled;
      else assert(unscaled == reference);
      if(j == 0) std::cout << "pinned corners: " << mode << " torus: OK, scales 2^0, 2^-7, 2^9 bit for bit (" << r.message << ")\n";
    }
    // a pinned UV between grid lines: the free vertex (1, 1) moved to (1.25, 1.5) and pinned. With integer_grid_map
    // the corner mesh unit becomes 2^-2 grid units and the integer right-hand sides are scaled by 4
    {
      Mesh m; UV_map uv;
      make_perturbed_torus(m, uv, 1);
      for(halfedge_descriptor h : m.halfedges())
        if(!m.is_border(h) && get(uv, h) == Point_2(1, 1)) put(uv, h, Point_2(1.25, 1.5));
      Pin_map pin = pins_of(m);
      assert(pin_uv(m, uv, pin, Point_2(1.25, 1.5)) == 6 && pin_uv(m, uv, pin, Point_2(1, 3)) > 0);
      const std::vector<std::uint64_t> bits0 = uv_bits(m, uv);
      const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv,
          SS::parameters::pinned_corner_map(pin).integer_grid_map(igm));
      if(r.status != SS::SUCCESS) std::cerr << SS::status_name(r.status) << " " << r.message << std::endl;
      assert(r.status == SS::SUCCESS && r.pinned_sectors == 2 && pinned_bit_identical(m, uv, pin, bits0));
      assert(SS::is_exactly_seamless(m, uv) && (!igm || SS::is_exact_integer_grid_map(m, uv)));
    }
    // a pin with bits below the grid quantum: the corner at u = 3 + 2^-51 (quantum 2^-49): RANGE_EXCEEDED, untouched
    {
      Mesh m; UV_map uv;
      make_perturbed_torus(m, uv, 1);
      Pin_map pin = pins_of(m);
      assert(pin_uv(m, uv, pin, Point_2(3 + std::ldexp(1., -51), 1)) > 0);
      const std::vector<std::uint64_t> bits0 = uv_bits(m, uv);
      const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv,
          SS::parameters::pinned_corner_map(pin).integer_grid_map(igm));
      if(r.status != SS::RANGE_EXCEEDED) std::cerr << SS::status_name(r.status) << " " << r.message << std::endl;
      assert(r.status == SS::RANGE_EXCEEDED && uv_bits(m, uv) == bits0);
      assert(r.message.find("pinned corner (vertex") != std::string::npos && r.message.find("round the pinned UV") != std::string::npos);
      std::cout << "pinned corners: " << mode << ": off-grid pin refused: " << r.message << "\n";
    }
    // pinned UVs whose bits span more than 62 (the free vertex (1, 1) moved to (1, 2^-70) and pinned): the corner
    // mesh's unit 2^-70 cannot hold 1; refused with what to do (it said "internal error")
    {
      Mesh m; UV_map uv;
      make_perturbed_torus(m, uv, 1);
      const Point_2 fine(1, std::ldexp(1., -70));
      for(halfedge_descriptor h : m.halfedges())
        if(!m.is_border(h) && get(uv, h) == Point_2(1, 1)) put(uv, h, fine);
      Pin_map pin = pins_of(m);
      assert(pin_uv(m, uv, pin, fine) == 6);
      const std::vector<std::uint64_t> bits0 = uv_bits(m, uv);
      const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv,
          SS::parameters::pinned_corner_map(pin).integer_grid_map(igm));
      if(r.status != SS::RANGE_EXCEEDED) std::cerr << SS::status_name(r.status) << " " << r.message << std::endl;
      assert(r.status == SS::RANGE_EXCEEDED && uv_bits(m, uv) == bits0);
      std::cout << "pinned corners: " << mode << ": pins spanning 62 bits refused: " << r.message << std::endl;
      assert(r.message.find(igm ? "pin UVs with fewer bits" : "round the pinned UVs to multiples of 2^") != std::string::npos &&
             r.message.find("internal error") == std::string::npos);
      assert(r.message.find("pinned corner (vertex") != std::string::npos);   // integer-grid mode named none
    }
    // contradicting pins: both sides of vertices (1, 0) and (2, 0) of one seam branch, whose translations differ
    // by 2^-40: INFEASIBLE naming the pinned corners, untouched
    {
      Mesh m; UV_map uv;
      make_perturbed_torus(m, uv, 1);
      Pin_map pin = pins_of(m);
      pin_uv(m, uv, pin, Point_2(1 + std::ldexp(1., -40), 0)); pin_uv(m, uv, pin, Point_2(1, 3));
      pin_uv(m, uv, pin, Point_2(2, 0)); pin_uv(m, uv, pin, Point_2(2, 3));
      const std::vector<std::uint64_t> bits0 = uv_bits(m, uv);
      const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv,
          SS::parameters::pinned_corner_map(pin).integer_grid_map(igm));
      if(r.status != SS::INFEASIBLE) std::cerr << SS::status_name(r.status) << " " << r.message << std::endl;
      assert(r.status == SS::INFEASIBLE && uv_bits(m, uv) == bits0);
      assert(r.message.find("pinned corner (vertex") != std::string::npos);
      std::cout << "pinned corners: " << mode << ": contradicting pins refused: " << r.message << "\n";
    }
  }
}

// a shared file (libQEx fandisk, near an IGM): every corner with integer UVs pinned, in both modes; and a
// corner whose UV has bits below any grid quantum of this map (lowest bit < 2^-53, while the constrained UVs
// reach |u| > 1, so the quantum is at least 2^-51) is refused
static void test_pinned_corners_data()
{
  Mesh m0;
  if(!load_shared_or_skip("libqex/fandisk_param.obj", "pinned corners: data", m0)) return;
  for(bool igm : {false, true}) {
    Mesh m = m0;
    UV_map uv = uv_of(m);
    Pin_map pin = pins_of(m);
    std::size_t n = 0;
    halfedge_descriptor fine;
    bool has_fine = false;
    for(halfedge_descriptor h : m.halfedges()) {
      if(m.is_border(h)) continue;
      const Point_2 p = get(uv, h);
      if(p.x() == std::nearbyint(p.x()) && p.y() == std::nearbyint(p.y())) { put(pin, h, true); ++n; }
      else if(!has_fine && std::fmod(p.x(), std::ldexp(1., -53)) != 0) { fine = h; has_fine = true; }
    }
    const std::vector<std::uint64_t> bits0 = uv_bits(m, uv);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv,
        SS::parameters::pinned_corner_map(pin).integer_grid_map(igm));
    if(r.status != SS::SUCCESS) std::cerr << SS::status_name(r.status) << " " << r.message << std::endl;
    assert(r.status == SS::SUCCESS && n > 0 && r.pinned_sectors > 0);
    assert(pinned_bit_identical(m, uv, pin, bits0) && uv_bits(m, uv) != bits0);
    assert(SS::is_exactly_seamless(m, uv));
    if(igm) assert(SS::is_exact_integer_grid_map(m, uv));
    // default mode: every field cone on an integer point stays there (without pins, 7 of 30 move off)
    assert(r.cones_on_integer_points_after >= r.cones_on_integer_points_before);
    std::printf("pinned corners: fandisk %s: %zu corners with integer UVs pinned (%zu sectors), cones on integers %zu -> %zu "
                "of %zu, change %.3g, %.0f ms\n", igm ? "integer grid" : "default", n, r.pinned_sectors,
                r.cones_on_integer_points_before, r.cones_on_integer_points_after, r.field_cones, r.max_change, r.total_ms);
    assert(has_fine);
    Mesh q = m0;
    UV_map uvq = uv_of(q);
    Pin_map pq = pins_of(q);
    put(pq, fine, true);
    const std::vector<std::uint64_t> bq = uv_bits(q, uvq);
    const SS::Snap_report rq = SS::snap_seamless_parameterization(q, uvq,
        SS::parameters::pinned_corner_map(pq).integer_grid_map(igm));
    if(rq.status != SS::RANGE_EXCEEDED) std::cerr << SS::status_name(rq.status) << " " << rq.message << std::endl;
    assert(rq.status == SS::RANGE_EXCEEDED && uv_bits(q, uvq) == bq);
  }
}

// ---------------------------------------------------------------------------------------------
// untangling (untangle(true), the default with integer_grid_map): fold-overs removed inside the constraint space
// ---------------------------------------------------------------------------------------------

// the UV triangles of the map that are negative / zero (exact orientation test); `touched`, if given: per vertex,
// 1 if one of them has a corner there
static std::pair<std::size_t, std::size_t> non_positive(const Mesh& m, UV_map uv, std::vector<char>* touched = nullptr)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  std::size_t negative = 0, zero = 0;
  if(touched != nullptr) touched->assign(m.number_of_vertices(), 0);
  for(Mesh::Face_index f : m.faces()) {
    const halfedge_descriptor h = m.halfedge(f);
    const CGAL::Orientation o = CGAL::orientation(P(get(uv, h).x(), get(uv, h).y()), P(get(uv, m.next(h)).x(), get(uv, m.next(h)).y()),
                                                  P(get(uv, m.prev(h)).x(), get(uv, m.prev(h)).y()));
    negative += o == CGAL::NEGATIVE ? 1 : 0;
    zero += o == CGAL::ZERO ? 1 : 0;
    if(touched != nullptr && o != CGAL::POSITIVE)
      for(halfedge_descriptor g : CGAL::halfedges_around_face(h, m)) (*touched)[std::size_t(m.target(g))] = 1;
  }
  return {negative, zero};
}

// what every snap with untangle(true) must give: SUCCESS, exactly seamless (an exact IGM in that mode), the
// report's final counts equal to an independent exact count, and every non-positive triangle listed with a
// reason (never a SUCCESS that hides a fold-over)
static void check_untangled(const Mesh& m, UV_map uv, const SS::Snap_report& r, bool igm, const char* what)
{
  if(r.status != SS::SUCCESS) std::cerr << what << ": " << SS::status_name(r.status) << " " << r.message << std::endl;
  assert(r.status == SS::SUCCESS && r.untangle);
  assert(igm ? SS::is_exact_integer_grid_map(m, uv) : SS::is_exactly_seamless(m, uv));
  std::vector<char> touched;
  const std::pair<std::size_t, std::size_t> np = non_positive(m, uv, &touched);
  assert(np.first == r.flips_after_repair && np.second == r.degenerate_after_repair);
  assert(r.folds.size() == np.first + np.second);
  // the seam rotations around a vertex fix its angle sum modulo 4 quarter turns: a defect's target valence is in
  // that class wherever the angle sum is exact (no non-positive triangle there), at merged and joined cones too
  for(const SS::Winding_defect& w : r.winding_defects)
    assert(touched[w.vertex] || ((w.angle_sum - w.valence) % 4 + 4) % 4 == 0);
  std::size_t forced = 0;
  std::vector<char> forced_corner(m.number_of_vertices(), 0);
  for(const SS::Fold_explanation& e : r.folds) {
    forced += e.forced() ? 1 : 0;
    assert(!e.message.empty() && e.vertices.size() == 3);
    if(e.forced()) for(std::size_t v : e.vertices) forced_corner[v] = 1;
  }
  assert(forced == r.folds_forced);
  assert(r.untangle_polish_ms >= 0 && r.untangle_polish_ms <= r.untangle_ms);   // a part of the untangling's time
  // the work counts: none where the untangling did not run; where it moved the map, some optimization took a step
  if(!r.untangled) assert(r.untangle_attempts == 0 && r.untangle_newton_steps == 0 && r.untangle_polish_steps == 0);
  if(r.untangle_moved_sectors > 0) assert(r.untangle_attempts > 0 && r.untangle_newton_steps > 0);
  assert(r.untangle_polish_steps <= std::size_t(SS::internal::Untangle_options().polish_iterations));
  // a defect is forced iff its vertex is a corner of a forced face, and then its message names such a face
  for(const SS::Winding_defect& w : r.winding_defects) {
    assert(w.forced == bool(forced_corner[w.vertex]));
    if(!w.forced) continue;
    const std::string named = "it is a corner of face ";
    const std::size_t at = w.message.find(named);
    assert(at != std::string::npos);
    const std::size_t f = std::stoul(w.message.substr(at + named.size()));
    assert(std::any_of(r.folds.begin(), r.folds.end(), [&](const SS::Fold_explanation& e) {
      return e.face == f && e.forced() && std::count(e.vertices.begin(), e.vertices.end(), w.vertex) == 1;
    }));
  }
  std::printf("untangling: %-48s %s: negative / zero %zu / %zu -> %zu / %zu after untangling -> %zu / %zu (forced %zu), "
              "winding defects %zu, rings %d, %zu sectors moved, max %.3g / RMS %.3g grid cells (snap alone %.3g), "
              "%.0f ms of %.0f ms\n", what, igm ? "integer grid" : "default", r.flips_before_untangling,
              r.degenerate_before_untangling, r.flips_after_untangling, r.degenerate_after_untangling, np.first, np.second,
              forced, r.winding_defects.size(), r.untangle_rings, r.untangle_moved_sectors,
              r.untangle_max_change * r.grid_scale, r.untangle_rms_change * r.grid_scale, r.snap_max_change * r.grid_scale,
              r.untangle_ms, r.total_ms);
}

// corner UVs (target(h), face(h)) of vertex v: all set to p
static void move_vertex_uv(Mesh& m, UV_map uv, vertex_descriptor v, const Point_2& p)
{
  for(halfedge_descriptor h : m.halfedges())
    if(!m.is_border(h) && m.target(h) == v) put(uv, h, p);
}

// The untangling energy's derivatives (untangling_energy.h): the gradient against central differences of the
// energy, and the PSD-projected Hessian, written from its eigensystem in closed form, against Eigen's symmetric
// eigensolver applied to central differences of the gradient (eigenvalues clamped at 0), on random Jacobians
// (positive, inverted, near-singular) and on the special ones (j+ = 0 or j- = 0, the zero matrix)
static void test_untangling_energy()
{
  namespace SI = CGAL::Seamless_snapping::internal;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-2, 2);
  std::vector<Eigen::Vector4d> js = {Eigen::Vector4d(1, 0, 0, 1), Eigen::Vector4d(1, 0, 0, -1), Eigen::Vector4d(0, 1, -1, 0),
                                     Eigen::Vector4d(0, 1, 1, 0), Eigen::Vector4d(0, 0, 0, 0), Eigen::Vector4d(2, 0, 0, 0.5),
                                     Eigen::Vector4d(0.5, 0.2, 0.2, 0.08)};
  for(int i = 0; i < 2000; ++i) js.emplace_back(U(rng), U(rng), U(rng), U(rng));
  double worst_grad = 0, worst_hess = 0;
  for(double eps : {1., 0.1, 0.01})
    for(const Eigen::Vector4d& j : js) {
      Eigen::Vector4d grad;
      Eigen::Matrix4d hess;
      const double f = SI::untangling_energy(j, eps, grad, &hess);
      assert(f == SI::untangling_energy(j, eps));
      Eigen::Vector4d grad_only;
      assert(SI::untangling_energy(j, eps, grad_only, nullptr) == f && grad_only == grad);
      const double h = 1e-6 * (std::max)(1., j.norm());
      Eigen::Vector4d grad_fd;
      Eigen::Matrix4d hess_fd;
      for(int c = 0; c < 4; ++c) {
        Eigen::Vector4d a = j, b = j, ga, gb;
        a[c] += h; b[c] -= h;
        grad_fd[c] = (SI::untangling_energy(a, eps) - SI::untangling_energy(b, eps)) / (2 * h);
        SI::untangling_energy(a, eps, ga, nullptr);
        SI::untangling_energy(b, eps, gb, nullptr);
        hess_fd.col(c) = (ga - gb) / (2 * h);
      }
      hess_fd = 0.5 * (hess_fd + hess_fd.transpose()).eval();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> es(hess_fd);
      const Eigen::Matrix4d projected = es.eigenvectors() * es.eigenvalues().cwiseMax(0.).asDiagonal() * es.eigenvectors().transpose();
      const double scale_g = (std::max)(1., grad.norm()), scale_h = (std::max)(1., hess_fd.norm());
      worst_grad = (std::max)(worst_grad, (grad - grad_fd).norm() / scale_g);
      worst_hess = (std::max)(worst_hess, (hess - projected).norm() / scale_h);
      assert((grad - grad_fd).norm() <= 1e-5 * scale_g);
      assert((hess - projected).norm() <= 1e-5 * scale_h);
      assert(hess.isApprox(hess.transpose(), 0.) && Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(hess).eigenvalues().minCoeff() >= -1e-12 * scale_h);
    }
  std::cout << "untangling energy: gradient and projected Hessian of " << 3 * js.size()
            << " Jacobians agree with central differences (largest relative differences " << worst_grad << ", " << worst_hess << ")\n";
}

// the polish's flip-free step bound over all faces of p (Region_problem::group_positive_steps() with one group)
static double positive_step(const CGAL::Seamless_snapping::internal::Region_problem& p, const std::vector<double>& w,
                            const Eigen::VectorXd& d, double floor)
{
  std::vector<double> t(1, HUGE_VAL);
  p.group_positive_steps(w, d, floor, std::vector<int>(p.faces.size(), 0), t);
  return t[0];
}

// The flip-free step bound of the polish (Region_problem::group_positive_steps()): along d, det J of every face that starts
// above the floor reaches the floor (not 0) at the returned step and stays above it before; a face already at or
// below the floor gives no bound. Two faces, J affine in two reduced variables w.
static void test_untangling_step_bound()
{
  namespace SI = CGAL::Seamless_snapping::internal;
  SI::Region_problem p;
  p.face_w = {0, 1, 0, 1};
  p.face_BM = {-1, 0, 0, 0,  0, 0, 0, -1,     // face 0: J = (1 - w0, 0, 0, 1 - w1), det = (1 - w0)(1 - w1)
               0, 1, 0, 0,   0, 0, 1, 0};     // face 1: J = (1, w0, w1, 1), det = 1 - w0 w1
  for(std::size_t f = 0; f < 2; ++f) {
    SI::Region_problem::Face e;
    e.face = int(f); e.region = 0; e.area = 1; e.J0 = Eigen::Vector4d(1, 0, 0, 1);
    e.first = 2 * f; e.n = 2; e.slots = 0;
    p.faces.push_back(e);
  }
  const std::vector<double> w = {0., 0.};
  Eigen::VectorXd d(2);
  d << 1., 1.;                                // det of face 0: (1 - t)^2, of face 1: 1 - t^2
  for(double floor : {0., 1e-6, 0.25, 0.81}) {
    const double t = positive_step(p, w, d, floor);
    const double expected = 1 - std::sqrt(floor);   // face 0 reaches the floor first
    assert(std::fabs(t - expected) <= 1e-12);
    for(const SI::Region_problem::Face& e : p.faces) {
      const std::vector<double> at = {t * d[0], t * d[1]}, before = {0.999 * t * d[0], 0.999 * t * d[1]};
      assert(SI::untangling_determinant(p.jacobian(e, at)) >= floor - 1e-12);
      assert(SI::untangling_determinant(p.jacobian(e, before)) > floor);
    }
  }
  assert(positive_step(p, w, d, 1.) == HUGE_VAL);   // both faces start at det 1: no face above the floor
  d << -1., -1.;                              // face 0 grows, face 1 shrinks: 1 - t^2 reaches 0.19 at t = 0.9
  assert(std::fabs(positive_step(p, w, d, 0.19) - 0.9) <= 1e-12);
  std::cout << "untangling: the polish's step bound keeps det J above its floor (0, 1e-6, 0.25, 0.81)\n";
}

// The independent parts of an untangling problem (Region_problem::components(), independent_parts.h): two faces
// that share no reduced variable are two parts, each with its own flip-free step bound and energy; a face over
// variables of both joins them into one part. The per-part values sum to the whole problem's.
static void test_untangling_parts()
{
  namespace SI = CGAL::Seamless_snapping::internal;
  SI::Region_problem p;
  p.space.dimension = 4;
  p.face_w = {0, 1, 2, 3};
  p.face_BM = {-1, 0, 0, 0,  0, 0, 0, -1,     // face 0: J = (1 - w0, 0, 0, 1 - w1), det = (1 - w0)(1 - w1)
               0, 1, 0, 0,   0, 0, 1, 0};     // face 1: J = (1, w2, w3, 1), det = 1 - w2 w3
  for(std::size_t f = 0; f < 2; ++f) {
    SI::Region_problem::Face e;
    e.face = int(f); e.region = int(f); e.area = 1; e.J0 = Eigen::Vector4d(1, 0, 0, 1);
    e.first = 2 * f; e.n = 2; e.slots = 0;
    p.faces.push_back(e);
  }
  std::vector<int> of_w, of_face, of_var;
  assert(p.components(of_w, of_face, of_var) == 2);
  assert((of_w == std::vector<int>{0, 0, 1, 1}) && (of_face == std::vector<int>{0, 1}) && of_var.empty());
  const std::vector<double> w = {0.2, 0.2, 0., 0.};
  Eigen::VectorXd d(4);
  d << 1., 1., 1., 1.;
  std::vector<double> t(2, HUGE_VAL);
  const double floor = 0.36;
  p.group_positive_steps(w, d, floor, of_face, t);
  // face 0: (0.8 - t)^2 = 0.36 first at t = 0.2; face 1: 1 - t^2 = 0.36 at t = 0.8
  assert(std::fabs(t[0] - 0.2) <= 1e-12 && std::fabs(t[1] - 0.8) <= 1e-12);
  assert(positive_step(p, w, d, floor) == (std::min)(t[0], t[1]));
  std::vector<double> E(2, 0.), D(2, HUGE_VAL), E1(1, 0.), D1(1, HUGE_VAL);
  std::vector<std::size_t> bad(2, 0);
  const std::vector<double> eps(1, 1e-3);
  p.group_values(w, eps, 0, of_face, of_var, E, D, &bad);
  p.group_values(w, eps, 0, std::vector<int>(2, 0), of_var, E1, D1);
  assert(std::fabs(D[0] - 0.64) <= 1e-15 && D[1] == 1 && D1[0] == (std::min)(D[0], D[1]));
  assert(std::fabs(E[0] + E[1] - E1[0]) <= 1e-12 * E1[0] && bad[0] == 0 && bad[1] == 0);
  p.face_w[2] = 0; p.face_w[3] = 2;          // face 1 now over w0 and w2: both faces one part, w3 (in no face) another
  assert(p.components(of_w, of_face, of_var) == 2 && of_w[0] == of_w[2] && of_w[1] == of_w[0] && of_w[3] != of_w[0]);
  assert(of_face[0] == of_face[1]);
  std::cout << "untangling: independent parts found, each with its own step bound (0.2, 0.8) and energy\n";
}

// A closed surface whose map has no cut edge (one UV per vertex: here the projection onto the plane z = 0, as some
// exporters make) folds in every map: the snap says so for its folds and wound vertices (Snap_report::closed_uncut_faces),
// proves none per face, and the untangling leaves it alone (the map is bit for bit the input's). The same projection
// on a disk (a border) is an ordinary map whose fold the untangling removes.
static void test_closed_uncut_parts()
{
  const int n = 8;
  Mesh m0; UV_map uv0;
  make_flat_torus(m0, uv0, n, n);
  uv_from_xy(m0, uv0);
  const std::pair<std::size_t, std::size_t> np = non_positive(m0, uv0);
  assert(np.first + np.second > 0);                    // as the theorem says
  for(const bool untangle : {false, true}) {
    Mesh m = m0; UV_map uv = uv_of(m);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::untangle(untangle));
    assert(r.status == SS::SUCCESS && r.closed_uncut_faces == m.number_of_faces() && !r.untangled);
    assert(uv_bits(m, uv) == uv_bits(m0, uv0));
    assert(r.folds.size() == np.first + np.second && r.folds_forced == 0);
    for(const SS::Fold_explanation& e : r.folds) assert(e.message.find("closed part of the surface (" + std::to_string(n * n * 2) + " faces") != std::string::npos);
    for(const SS::Winding_defect& w : r.winding_defects) assert(w.message.find("closed part of the surface") != std::string::npos);
    assert(r.message.find("closed parts of the surface without cut edges") != std::string::npos);
  }
  // a disk (grid of 6 x 6 squares) mapped by the same kind of projection, with a vertex dragged across a neighbour
  Mesh d; UV_map uvd = uv_of(d);
  const std::vector<vertex_descriptor> vs = triangulated_grid(d, 6, true);
  uv_from_xy(d, uvd);
  move_vertex_uv(d, uvd, vs[3 * 7 + 3], Point_2(4.4, 3.3));
  assert(non_positive(d, uvd).first > 0);
  const SS::Snap_report rd = SS::snap_seamless_parameterization(d, uvd, SS::parameters::untangle(true));
  check_untangled(d, uvd, rd, false, "grid with a dragged vertex");
  assert(rd.untangled && rd.closed_uncut_faces == 0 && rd.folds.empty());
  std::cout << "untangling: a closed surface without cuts (" << np.first + np.second << " folds) explained, not untangled; a disk untangled\n";
}

static void test_untangling_analytic()
{
  // an exact flat 8 x 8 torus (an IGM) with vertex (3, 3) dragged across its neighbour (4, 3): its triangles fold
  // over. Without untangling they stay, listed; with it (the default of integer_grid_map) every triangle is positive,
  // the map an exact IGM, and only vertices near the fold move (bit for bit elsewhere)
  const int n = 8;
  Mesh m0; UV_map uv0;
  make_flat_torus(m0, uv0, n, n);
  const vertex_descriptor dragged(3 * n + 3);
  move_vertex_uv(m0, uv0, dragged, Point_2(4.6, 3.3));
  assert(non_positive(m0, uv0).first > 0 && SS::is_exact_integer_grid_map(m0, uv0));
  {
    Mesh m = m0; UV_map uv = uv_of(m);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true).untangle(false));
    assert(r.status == SS::SUCCESS && !r.untangle && !r.untangled && r.flips_after_repair > 0);
    assert(r.folds.size() == r.flips_after_repair + r.degenerate_after_repair && r.folds_forced == 0);
    assert(r.message.find("remain") != std::string::npos);
  }
  // the same torus mirrored (u -> -u: every triangle negative, the cut's transitions mirrored too): the untangling does
  // not run (it would turn the whole map over), the report says why, every triangle stays listed
  {
    Mesh m; UV_map uv;
    make_flat_torus(m, uv, n, n);
    for(halfedge_descriptor h : m.halfedges())
      if(!m.is_border(h)) put(uv, h, Point_2(-get(uv, h).x(), get(uv, h).y()));
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true));
    assert(r.status == SS::SUCCESS && r.untangle && !r.untangled && r.uv_mirrored && SS::is_exact_integer_grid_map(m, uv));
    assert(r.flips_after_repair == r.faces && r.folds.size() == r.faces && r.message.find("mirrored") != std::string::npos);
    assert(r.folds[0].message.find("mirrored") != std::string::npos);
    std::cout << "untangling: a mirrored torus: not untangled, reported as mirrored\n";
  }
  Mesh m = m0; UV_map uv = uv_of(m);
  const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(true));
  check_untangled(m, uv, r, true, "torus with a dragged vertex");
  assert(!r.uv_mirrored);
  assert(r.untangled && r.flips_before_untangling > 0 && r.flips_after_repair == 0 && r.degenerate_after_repair == 0);
  assert(r.folds.empty() && r.winding_defects.empty() && r.closed_uncut_faces == 0);   // a closed surface, but with cuts
  for(halfedge_descriptor h : m.halfedges()) {
    if(m.is_border(h) || get(uv, h) == get(uv0, h)) continue;
    const int v = int(m.target(h)), i = v % n, j = v / n;
    assert(std::abs(i - 3) <= 5 && std::abs(j - 3) <= 5);   // k <= 2 rings, polish 2 rings, one more for the seams
  }
  // the same input twice: the same bits (deterministic)
  Mesh m2 = m0; UV_map uv2 = uv_of(m2);
  SS::snap_seamless_parameterization(m2, uv2, SS::parameters::integer_grid_map(true));
  assert(uv_bits(m2, uv2) == uv_bits(m, uv));
  // a bound on the change: the untangled map is not used, the fold-overs stay and are listed
  Mesh m3 = m0; UV_map uv3 = uv_of(m3);
  const SS::Snap_report r3 = SS::snap_seamless_parameterization(m3, uv3,
                                 SS::parameters::integer_grid_map(true).max_untangle_change(1e-3));
  assert(r3.status == SS::SUCCESS && r3.untangle_refused && r3.flips_after_repair > 0 && !r3.folds.empty());
  assert(r3.message.find("max_untangle_change") != std::string::npos);
  // scale covariance: the input times 2^j untangles and snaps to the result at scale 1 times 2^j, bit for bit, in both
  // modes (integer grid at grid scale 2^-j): the untangling's energies are relative to the input's own triangles, its
  // proximity term to the map's scale, so every step commutes with powers of two (a relation, both snapped in this run)
  for(bool igm : {true, false}) {
    Mesh a = m0; UV_map uva = uv_of(a);
    const SS::Snap_report ra = SS::snap_seamless_parameterization(a, uva, SS::parameters::integer_grid_map(igm).untangle(true));
    assert(ra.status == SS::SUCCESS && ra.untangled && ra.flips_after_repair == 0);
    for(int j : {-9, 13}) {
      Mesh b = m0; UV_map uvb = uv_of(b);
      scale_uvs(b, uvb, j);
      const SS::Snap_report rb = SS::snap_seamless_parameterization(b, uvb, SS::parameters::integer_grid_map(igm)
                                                                       .grid_scale(std::ldexp(1., -j)).untangle(true));
      assert(rb.status == SS::SUCCESS && rb.untangled && rb.untangle_moved_sectors == ra.untangle_moved_sectors);
      for(halfedge_descriptor h : b.halfedges())
        assert(b.is_border(h) || (get(uvb, h).x() == std::ldexp(get(uva, h).x(), j) &&
                                  get(uvb, h).y() == std::ldexp(get(uva, h).y(), j)));
    }
  }

  // a triangle whose three corners are pinned onto one line: degenerate in every map with these pins (proven:
  // RIGID_TRIANGLE); the triangles its moved corner folds are untangled around it
  Mesh p; UV_map uvp;
  make_flat_torus(p, uvp, n, n);
  move_vertex_uv(p, uvp, vertex_descriptor(3 * n + 4), Point_2(3.5, 3.5));   // (4, 3) onto the diagonal (3, 3)-(4, 4)
  Pin_map pin = pins_of(p);
  for(int v : {3 * n + 3, 3 * n + 4, 4 * n + 4})
    for(halfedge_descriptor h : p.halfedges()) if(!p.is_border(h) && int(p.target(h)) == v) put(pin, h, true);
  const SS::Snap_report rp = SS::snap_seamless_parameterization(p, uvp,
                                 SS::parameters::integer_grid_map(true).pinned_corner_map(pin));
  check_untangled(p, uvp, rp, true, "torus with three pinned collinear corners");
  assert(rp.flips_after_repair == 0 && rp.degenerate_after_repair == 1 && rp.folds_forced == 1);
  assert(rp.folds.front().reason == SS::FOLD_RIGID_TRIANGLE && !rp.folds.front().negative);
  std::cout << "untangling: analytic cases OK (" << rp.folds.front().message << ")\n";
  test_closed_uncut_parts();
}

// merge_cone_pairs(true) on the dragon (full-seamless), after the cancelling pairs, joins pairs whose indices do not
// cancel (one cone takes both, never below valence 2; its partner becomes regular): against the integer-grid map of
// the caller's field, a tenth of the triangles are left not positive, every zero-area one proven forced, and the
// result is an exact integer-grid map with the field cones counted as the pairs say
// The valences a join gives (cone_merging.h): 4 - the index in quarter turns, from the rotation sums K (the angle sum
// is K quarter turns modulo 4: K = 1 is a -90 degree cone, valence 5); a half-turn cone (K = 2) counts as 2 or 6,
// whichever makes a quad mesh vertex; three +90 degree cones on one point never do (valence 1)
static void test_cone_valences()
{
  namespace SI = CGAL::Seamless_snapping::internal;
  //                 vertex: 0  1  2  3  4  5  6
  const std::vector<int> K = {1, 3, 2, 2, 3, 3, 1};
  const std::vector<int> angle_sums = {5, 3, -2, 6, 3, 3, 5};   // the input's (vertex 2 folded: meaningless)
  SI::Cone_valences c(K, angle_sums);
  assert(c.valence[0] == 5 && c.valence[1] == 3 && c.valence[2] == 2 && c.valence[3] == 6);
  assert(c.joined(0, 1, true) == 4 && c.joined(0, 6, false) == 6 && c.joined(1, 4, false) == 2);
  assert(c.joined(0, 2, false) == 3);   // -90 and a half turn: 5 + 2 - 4, as given
  assert(c.joined(1, 2, false) == 5);   // +90 and a half turn: valence 1 as given, so the half turn counts as 6
  assert(c.joined(2, 3, true) == 4);    // two half turns cancel: 2 + 6
  c.join(4, 5, c.joined(4, 5, false));  // two +90 degree cones: valence 2 at 5, 4 regular
  assert(c.valence[5] == 2 && c.valence[4] == 4 && c.joined(1, 5, false) == 0);   // a third one: valence 1
  c.join(1, 2, c.joined(1, 2, false));  // the half turn took valence 6 and the +90 degree cone: 5, no longer either
  assert(c.valence[2] == 5 && c.either[2] == 0 && c.joined(2, 6, false) == 6);
  SI::Cone_valences d({1, 1, 1, 1}, {5, 5, 5, 5});   // four -90 degree cones on one point: two valence-6 points, then 8
  d.join(0, 1, d.joined(0, 1, false));
  d.join(2, 3, d.joined(2, 3, false));
  assert(d.valence[1] == 6 && d.valence[3] == 6 && d.joined(1, 3, true) == 8 && d.joined(1, 3, false) == 0);
  std::printf("cone merging: joined valences as the rotation sums give them (half turns 2 or 6)\n");
}

// Target_valences (vertex_windings.h): a cone whose index the input does not fix accepts every member of its
// class of at least 2 (a half turn: 2, 6, 10; never 1 for a -90 degree cone); the others only their valence
static void test_target_valences()
{
  namespace SI = CGAL::Seamless_snapping::internal;
  const SI::Target_valences t{{2, 2, 5, 4, 0}, {1, 0, 1, 0, 0}};
  assert(!t.wound(0, 2) && !t.wound(0, 6) && !t.wound(0, 10) && t.wound(0, -2) && t.wound(0, 4) && t.wound(0, 3));
  assert(!t.wound(1, 2) && t.wound(1, 6));                               // fixed by the input
  assert(!t.wound(2, 5) && !t.wound(2, 9) && t.wound(2, 1) && t.wound(2, 3));   // valence 1: no quad vertex
  assert(!t.wound(3, 4) && t.wound(3, 8) && !t.wound(4, 7));              // a branch point; no target
  std::printf("untangling: target valences accept the other members of an unfixed cone's class from 2 on\n");
}

static void test_joined_cone_pairs()
{
  const char* f = "directional/dragon-param-full-seamless.obj";
  Mesh m0;
  if(sanitizer_subset()) return;                                   // 2 x 2-3 s of untangling, 10 s of separation trials
  if(!load_shared_or_skip(f, "untangling: joined cone pairs", m0)) return;
  Mesh m1 = m0, m2 = m0;
  UV_map uv0 = uv_of(m0), uv1 = uv_of(m1), uv2 = uv_of(m2);
  const SS::Snap_report r0 = SS::snap_seamless_parameterization(m0, uv0, SS::parameters::integer_grid_map(true));
  const SS::Snap_report r1 = SS::snap_seamless_parameterization(m1, uv1, SS::parameters::integer_grid_map(true).merge_cone_pairs(true));
  std::printf("untangling: %s, integer grid: %zu negative, %zu zero-area left; pairs merged (%zu, %zu of them joined): "
              "%zu negative, %zu zero-area (%zu forced)\n", f, r0.flips_after_repair, r0.degenerate_after_repair,
              r1.merged_cone_pairs.size(), r1.joined_cone_pairs, r1.flips_after_repair, r1.degenerate_after_repair,
              r1.folds_forced);
  check_untangled(m1, uv1, r1, true, f);
  assert(r0.status == SS::SUCCESS);
  // some vertices left wound are corners of the faces proven zero-area: proven not locally injective in every solution
  const std::size_t forced_windings = std::size_t(std::count_if(r1.winding_defects.begin(), r1.winding_defects.end(),
                                                                [](const SS::Winding_defect& w) { return w.forced; }));
  assert(r1.folds_forced > 0 && forced_windings > 0 && forced_windings < r1.winding_defects.size());
  assert(r1.message.find(std::to_string(forced_windings) + " of them proven forced") != std::string::npos);
  assert(SS::is_exact_integer_grid_map(m1, uv1) && r1.cones_on_integer_points_after == r1.field_cones);
  assert(r1.joined_cone_pairs > 0 && r1.joined_cone_pairs < r1.merged_cone_pairs.size());
  assert(r1.field_cones + 2 * r1.merged_cone_pairs.size() - r1.joined_cone_pairs == r0.field_cones);
  assert(r1.degenerate_after_repair == r1.folds_forced);
  assert(10 * (r1.flips_after_repair + r1.degenerate_after_repair) < r0.flips_after_repair + r0.degenerate_after_repair);
  assert(r1.message.find(std::to_string(r1.joined_cone_pairs) + " of them into one cone with both indices") != std::string::npos);
  // the pairs left on one point after merging (three +90 degree cones there: no join makes a quad vertex) separated,
  // their shifts chosen by trials: no fold-over is left (with the first shift in the fixed order: 6 negative
  // triangles), and fewer zero-area triangles than with merging alone
  const SS::Snap_report r2 = SS::snap_seamless_parameterization(m2, uv2, SS::parameters::integer_grid_map(true)
                                                                   .merge_cone_pairs(true).separate_cone_pairs(true));
  std::printf("untangling: %s, pairs merged and separated (%zu, %zu separation trials): %zu negative, %zu zero-area "
              "(%zu forced), %zu wound\n", f, r2.separated_cone_pairs.size(), r2.separation_trials, r2.flips_after_repair,
              r2.degenerate_after_repair, r2.folds_forced, r2.winding_defects.size());
  check_untangled(m2, uv2, r2, true, f);
  assert(SS::is_exact_integer_grid_map(m2, uv2) && r2.cones_on_integer_points_after == r2.field_cones);
  assert(!r2.separated_cone_pairs.empty() && r2.separation_trials > 0);
  assert(r2.separation_ms > 0 && r2.separation_ms <= r2.total_ms);   // the trials' time, a part of the whole
  assert(r2.flips_after_repair == 0 && r2.degenerate_after_repair == r2.folds_forced);
  assert(r2.degenerate_after_repair < r1.degenerate_after_repair);
}

// the shared maps with fold-overs, both modes: no negative triangle is left, every zero-area one is proven forced,
// in integer-grid mode every vertex left not locally injective lies next to a cone pair collapsed onto one integer
// point. duck_qc_8 in integer-grid mode keeps 2 negative triangles and 14 wound vertices, each next to such a pair; its
// report names the pairs (at the wound vertices and at the two triangles) and merge_cone_pairs(true), with which it
// is fold-free.
static void test_untangling_data()
{
  struct Case { const char* file; bool igm; double grid_scale; bool merge; bool separate; };
  const Case cases[] = {{"directional/decimated-knight-param.obj", true, 1, false, false}, {"libqex/fandisk_param.obj", true, 1, false, false},
                        {"libqex/duck_miq_8_param.obj", true, 8, false, false}, {"directional/decimated-knight-param.obj", false, 1, false, false},
                        {"libqex/fandisk_param.obj", false, 1, false, false}, {"libqex/duck_miq_8_param.obj", false, 1, false, false},
                        {"libqex/duck_qc_8_param.obj", false, 1, false, false}, {"libqex/duck_qc_8_param.obj", true, 1, false, false},
                        {"libqex/duck_qc_8_param.obj", true, 1, true, false}, {"libqex/duck_qc_8_param.obj", true, 1, false, true}};
  std::vector<std::pair<std::size_t, std::size_t> > duck_qc_collapsed;   // without separating
  std::size_t duck_qc_field_cones = 0;
  for(const Case& c : cases) {
    Mesh m;
    const fs::path path = fs::path(SS_SHARED_DATA_DIR) / c.file;
    if(sanitizer_subset() && fs::exists(path) && fs::file_size(path) > 600 * 1000) continue;   // see mesh_test_support.h
    if(!load_shared_or_skip(c.file, "untangling: data", m)) continue;
    UV_map uv = uv_of(m);
    const SS::Snap_report r = SS::snap_seamless_parameterization(m, uv, SS::parameters::integer_grid_map(c.igm)
                                                                    .grid_scale(c.grid_scale).untangle(true)
                                                                    .merge_cone_pairs(c.merge)
                                                                    .separate_cone_pairs(c.separate));
    check_untangled(m, uv, r, c.igm, c.file);
    assert(c.separate || r.separated_cone_pairs.empty());
    assert(r.flips_before > 0 && r.untangled);
    assert(r.degenerate_after_repair == r.folds_forced);
    if(std::strcmp(c.file, "libqex/duck_qc_8_param.obj") == 0 && c.igm && !c.merge && !c.separate) {
      // what is left is reported with the pairs next to it (every winding: the search of merging and separating finds
      // them; a chart composition along a breadth-first face tree named 12 of the 14), and what merges them
      std::size_t near_pairs = 0;
      for(const SS::Winding_defect& w : r.winding_defects) near_pairs += w.message.find("cone pair") != std::string::npos ? 1 : 0;
      assert(r.flips_after_repair > 0 && !r.winding_defects.empty() && near_pairs == r.winding_defects.size());
      assert(r.message.find("with cancelling indices (merge_cone_pairs(true)") != std::string::npos);
      // the same pairs as fields: each named by a winding defect, the count of cancelling ones as in the message
      assert(!r.collapsed_cone_pairs.empty() && r.cancelling_collapsed_cone_pairs > 0 &&
             r.cancelling_collapsed_cone_pairs <= r.collapsed_cone_pairs.size());
      assert(r.message.find(std::to_string(r.collapsed_cone_pairs.size()) + " cone pair(s) rounded onto one integer point") != std::string::npos);
      assert(r.message.find(", " + std::to_string(r.cancelling_collapsed_cone_pairs) + " with cancelling indices") != std::string::npos);
      for(std::size_t i = 0; i < r.collapsed_cone_pairs.size(); ++i) {
        const std::pair<std::size_t, std::size_t>& p = r.collapsed_cone_pairs[i];
        assert(p.first < p.second && (i == 0 || r.collapsed_cone_pairs[i - 1] < p));
        const std::string named = "the cones at vertices " + std::to_string(p.first) + " and " + std::to_string(p.second);
        bool found = false;
        for(const SS::Winding_defect& w : r.winding_defects) found = found || w.message.find(named) != std::string::npos;
        for(const SS::Fold_explanation& f : r.folds) found = found || f.message.find(named) != std::string::npos;
        assert(found);
      }
      // each negative triangle left is not proven forced, says how far the untangling's regions grew around it, and
      // names the collapsed pair next to it (its likely cause)
      const std::string tried = "the untangling did not make it positive (its regions grew to " +
                                std::to_string(r.untangle_rings) + " face rings around the fold-overs";
      for(const SS::Fold_explanation& f : r.folds)
        assert(!f.forced() && f.negative && f.message.find(tried) != std::string::npos &&
               f.message.find("a cone pair the integer translations collapse") != std::string::npos);
      const std::string json = r.to_json();
      assert(json.find("\"collapsed_cone_pairs\": [[" + std::to_string(r.collapsed_cone_pairs.front().first) + ", ") != std::string::npos);
      duck_qc_collapsed = r.collapsed_cone_pairs;
      duck_qc_field_cones = r.field_cones;
      continue;
    }
    if(c.separate) {
      // the pairs that a cut near their point joins are moved apart, the field kept: every cone still on an integer
      // point (check_untangled: an exact IGM), no negative triangle left, and the separated pairs are no longer
      // collapsed (each was before, next to a defect); the windings left are each next to a pair still collapsed
      assert(!r.separated_cone_pairs.empty() && r.separated_cut_edges >= r.separated_cone_pairs.size());
      for(const SS::Winding_defect& w : r.winding_defects) assert(w.message.find("cone pair") != std::string::npos);
      assert(r.field_cones == duck_qc_field_cones && r.cones_on_integer_points_after == r.field_cones);
      assert(r.flips_after_repair == 0 && r.degenerate_after_repair == 0);
      assert(r.collapsed_cone_pairs.size() < duck_qc_collapsed.size());
      for(const std::pair<std::size_t, std::size_t>& p : r.separated_cone_pairs) {
        assert(p.first < p.second);
        assert(std::find(duck_qc_collapsed.begin(), duck_qc_collapsed.end(), p) != duck_qc_collapsed.end());
        assert(std::find(r.collapsed_cone_pairs.begin(), r.collapsed_cone_pairs.end(), p) == r.collapsed_cone_pairs.end());
        assert(r.message.find(std::to_string(p.first) + "|" + std::to_string(p.second)) != std::string::npos);
      }
      continue;
    }
    if(c.igm) for(const SS::Winding_defect& w : r.winding_defects) assert(w.message.find("cone pair") != std::string::npos);
    assert(r.flips_after_repair == 0);
    if(c.merge) assert(!r.merged_cone_pairs.empty() && r.message.find("merge_cone_pairs(true)") == std::string::npos);
    if(r.winding_defects.empty()) assert(r.collapsed_cone_pairs.empty() && r.cancelling_collapsed_cone_pairs == 0);
    // default mode: no forced triangle; locally injective everywhere but on duck_qc_8 (a few vertices left wound)
    if(!c.igm) assert(r.degenerate_after_repair == 0);
    if(!c.igm && std::strcmp(c.file, "libqex/duck_qc_8_param.obj") != 0) assert(r.winding_defects.empty());
    if(std::strcmp(c.file, "directional/decimated-knight-param.obj") == 0 && c.igm) {
      // three cones rounded onto collinear integer points: one zero-area triangle, proven
      assert(r.folds.size() == 1 && r.folds.front().reason == SS::FOLD_RIGID_TRIANGLE);
    }
  }
}

// Constraint_rows with integer right-hand sides, through the exact check and project_rows()
static void test_right_hand_sides()
{
  namespace SI = CGAL::Seamless_snapping::internal;
  for(int j : {0, 10, 30}) {             // the same system scaled by 2^j (b stays integer)
    const double scale = std::ldexp(1., j);
    SI::Constraint_rows rows;
    const long b0 = 3L << j, b1 = 2L << j;
    assert(rows.add({{0, 1}, {2, -1}}, 0, b0));   // x0 - x2 = 3 s
    assert(rows.add({{2, 1}}, 1, b1));            // x2 = 2 s
    assert(!rows.add({{1, 1}, {1, -1}}, 7, 4));   // 0 = 4: not stored, recorded
    assert(!rows.add({{1, 1}, {1, -1}}, 8));      // 0 = 0: not stored, not recorded
    assert(rows.size() == 2 && rows.contradictions == std::vector<int>(1, 7));
    std::vector<double> x = {5 * scale, 0.25, 2 * scale};
    assert(SI::first_violated_row(rows, x) == -1 && SI::max_abs_residual(rows, x) == 0);
    x[2] = 2.5 * scale;
    assert(SI::first_violated_row(rows, x) == 0);
    std::vector<double> y = {4.9 * scale, 0.25, 2.1 * scale};
    SS::Snap_report report;
    std::string message;
    const SI::Fixed_point_grid grid = SI::Fixed_point_grid::from_max_abs(5 * scale, 1);
    assert(SI::project_rows(rows, grid, false, y, report, message) == SS::SUCCESS);
    assert(y[0] == 5 * scale && y[2] == 2 * scale && y[1] == 0.25);   // C y = b exactly; x1 is in no row
  }
  std::cout << "right-hand sides: OK\n";
}

int main(int argc, char** argv)
{
  parse_test_arguments(argc, argv);
  test_right_hand_sides();
  test_integer_grid_analytic();
  test_zero_length_cut_edge();
  test_pinned_corners_analytic();
  test_pinned_corners_data();
  if(!sanitizer_subset()) test_integer_grid_orbifold();
  test_integer_grid_data();
  test_isoline_classes();
  test_quantization();
  test_untangling_energy();
  test_untangling_step_bound();
  test_untangling_parts();
  test_untangling_analytic();
  test_untangling_data();
  test_cone_valences();
  test_target_valences();
  test_joined_cone_pairs();
  test_invalid();
  test_cycles();
  test_data_meshes();
  if(!sanitizer_subset()) test_orbifolds();
  std::cout << "exact constraint checks: " << g_checked << " (" << g_ambiguous
            << " crossings of zero-length cut edges, rotation taken from the input)\n";
  std::cout << "test_constraints: all tests passed" << std::endl;
  return EXIT_SUCCESS;
}
