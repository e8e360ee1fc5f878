// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// number_of_threads under ThreadSanitizer (built only in the sanitizer build directory, with -fsanitize=thread:
// test/Seamless_snapping/CMakeLists.txt; a data race aborts the test): every step that runs on two threads (the cones
// and the sectors, the node system and the minimal-change start point, the two halves of the untangling's independent
// parts (duck_miq_8), the separation trials two at a time (the full-seamless dragon), the proofs and the windings of
// the explain stage, the OBJ writer's blocks, the OBJ reader's two halves of a file, the core's implied rows in two
// halves on a generated 30000-row system) on maps of ../shared/data, in the default mode and as an untangled
// integer-grid map, and the results of two threads against those of one, bit for bit. Without ../shared: a generated
// map.

#include "generators.h"
#include "mesh_test_support.h"

#include <CGAL/Seamless_snapping/Exact_constraint_projection.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>

#include <fstream>
#include <sstream>

namespace {

int failures = 0;
#define CHECK(cond, what) do { if(!(cond)) { ++failures; std::cerr << "FAILED: " << what << std::endl; } } while(0)

// the OBJ text of (m, uv) written with `threads` threads
std::string obj_text(const Mesh& m, UV_map uv, unsigned threads)
{
  std::ostringstream os;
  std::string message;
  const SS::Status s = SS::IO::write_OBJ_with_corner_uvs(os, m, uv, message, SS::parameters::number_of_threads(threads));
  return s == SS::SUCCESS ? os.str() : std::string();
}

void check_map(const std::string& name, const Mesh& input)
{
  for(int igm = 0; igm < 2; ++igm) {
    Mesh one = input, two = input;
    UV_map uv1 = uv_of(one), uv2 = uv_of(two);
    const auto np = SS::parameters::integer_grid_map(igm == 1).untangle(igm == 1);
    const SS::Snap_report r1 = SS::snap_seamless_parameterization(one, uv1, np.number_of_threads(1));
    const SS::Snap_report r2 = SS::snap_seamless_parameterization(two, uv2, np.number_of_threads(2));
    const std::string mode = igm == 1 ? "integer-grid map, untangled" : "default";
    CHECK(r1.status == r2.status && r1.message == r2.message, name << " (" << mode << "): the same status and message");
    CHECK(uv_bits(one, uv1) == uv_bits(two, uv2), name << " (" << mode << "): the same UVs, bit for bit");
    CHECK(r1.nodes == r2.nodes && r1.folds.size() == r2.folds.size() && r1.winding_defects.size() == r2.winding_defects.size(),
          name << " (" << mode << "): the same report");
    const std::string text = obj_text(two, uv2, 2);
    CHECK(!text.empty() && text == obj_text(two, uv2, 1), name << " (" << mode << "): the OBJ text of two threads is that of one");
    std::cout << "threads: " << name << " (" << mode << "): " << SS::status_name(r2.status) << ", " << r2.faces << " faces, "
              << text.size() << " bytes of OBJ text" << std::endl;
  }
}

// the separation trials (two trial snaps at once: solve_with_separation_trials()) on Directional's full-seamless dragon,
// the only shared map with trials, in integer-grid mode with its cone pairs merged and separated (seamless_quad's
// options): the same map, bit for bit, and the same trials
void check_separation_trials(const Mesh& input)
{
  Mesh one = input, two = input;
  UV_map uv1 = uv_of(one), uv2 = uv_of(two);
  const auto np = SS::parameters::integer_grid_map(true).untangle(true).merge_cone_pairs(true).separate_cone_pairs(true);
  const SS::Snap_report r1 = SS::snap_seamless_parameterization(one, uv1, np.number_of_threads(1));
  const SS::Snap_report r2 = SS::snap_seamless_parameterization(two, uv2, np.number_of_threads(2));
  CHECK(r1.status == SS::SUCCESS && r2.status == SS::SUCCESS && r1.message == r2.message, "dragon: both snapped, one message");
  CHECK(r1.separation_trials > 1 && r1.separation_trials == r2.separation_trials &&
        r1.separated_cone_pairs == r2.separated_cone_pairs, "dragon: the same separation trials");
  CHECK(uv_bits(one, uv1) == uv_bits(two, uv2), "dragon (separation trials): the same UVs, bit for bit");
  std::cout << "threads: dragon (full-seamless), cone pairs separated: " << r2.separation_trials << " trial snaps, "
            << r2.separated_cone_pairs.size() << " pairs" << std::endl;
}

// the core's implied rows in two halves (Projection_options::number_of_threads) on a generated system large enough
void check_projection()
{
  SS_test::Seamless_options so; so.target_rows = 30000; so.seed = 4242;
  const SS_test::Linear_system s = SS_test::seamless_system(so);
  const std::vector<double> xbar = SS_test::noisy_input(s, 1e-7, 3);
  std::vector<double> x[2];
  SS::Projection_report r[2];
  for(unsigned t = 1; t <= 2; ++t) {
    SS::Projection_options o;
    o.number_of_threads = t;
    o.minimal_change = false;                     // (its least squares would take most of the time under TSan)
    SS::Exact_constraint_projection p(o);
    CHECK(p.initialize(s.m, s.n, s.triplets, s.b) == SS::SUCCESS, "projection: initialize");
    r[t - 1] = p.project(xbar, x[t - 1]);
  }
  CHECK(r[0].status == SS::SUCCESS && r[1].status == SS::SUCCESS && r[0].message == r[1].message &&
        x[0].size() == x[1].size() && std::memcmp(x[0].data(), x[1].data(), x[0].size() * sizeof(double)) == 0,
        "projection: two threads = one");
  std::cout << "threads: the projection of a " << s.m << "-row system, implied rows in two halves" << std::endl;
}

} // namespace

int main()
{
  check_projection();
  std::vector<fs::path> files;
  if(shared_obj_files_or_skip("threads: shared maps", files)) {
    for(const char* name : {"libqex/fandisk_param.obj", "directional/horsers-param-full-seamless.obj", "libqex/duck_miq_8_param.obj"}) {
      Mesh m;
      if(load_shared_or_skip(name, "threads", m)) check_map(name, m);
    }
    Mesh dragon;
    if(load_shared_or_skip("directional/dragon-param-full-seamless.obj", "threads", dragon)) check_separation_trials(dragon);
    const fs::path file = fs::path(SS_SHARED_DATA_DIR) / "libqex/fandisk_param.obj";   // the reader: its two halves
    SS::IO::internal::Obj_soup one, two;
    std::string m1, m2;
    std::ifstream is(file, std::ios::binary);
    bool halves = false;
    CHECK(SS::IO::internal::parse_obj(is, one, file.string(), m1) == SS::SUCCESS &&
          SS::IO::internal::parse_obj_file(file.string(), two, m2, 2, 0, &halves) == SS::SUCCESS && halves &&
          one.points == two.points && one.uvs == two.uvs && one.face_v == two.face_v && one.face_vt == two.face_vt,
          "fandisk read in two halves on two threads as on one");
    std::cout << "threads: fandisk read in two halves: " << two.face_v.size() << " faces" << std::endl;
  } else {
    // a generated map: a flat 120 x 120 torus (28,800 faces, enough for the OBJ writer's second thread) with its two
    // seams, the UVs moved by up to 1e-9 (a function of the UV, so that the corners of one chart stay equal)
    Mesh m;
    UV_map uv;
    make_flat_torus(m, uv, 120, 120.);
    for(halfedge_descriptor h : m.halfedges())
      if(!m.is_border(h)) {
        const Point_2 t = get(uv, h);
        put(uv, h, Point_2(t.x() + 1e-9 * std::sin(7 * t.y() + 3 * t.x()), t.y() + 1e-9 * std::cos(5 * t.x() + 2 * t.y())));
      }
    check_map("generated torus", m);
  }
  std::cout << "test_threads: " << (failures == 0 ? "OK" : "FAILED") << " (" << failures << " failures)" << std::endl;
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
