// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// Writes the seed corpora of the fuzz targets, all generated (no data files are read):
//   make_fuzz_seeds DIR   ->  DIR/obj_snap/*.obj, DIR/projection/*.bin, DIR/quad_patches/*.bin
// obj_snap: Orbifold Tutte maps (Square: 3 cones, Parallelogram: 4 cones) of a Loop-subdivided
// icosahedron, as written (seamless up to solver error), with UV noise, scaled by 2^30, as a cut
// mesh to be welded ("#weld" first line), and a few small hand-made files.
// projection: small seamless-like and random systems of test/Seamless_snapping/generators.h with
// noisy inputs, in the byte format of projection_bytes.h, and a few hand-made edge cases.
// quad_patches: quad meshes in the byte format of quad_patches_bytes.h: grids of 2 x 2 and 3 x 3 quads, a cube, a
// 3 x 3 torus, the torus with its garbage collected after nothing was removed.
// Deterministic: the same files on every run.

#include "projection_bytes.h"
#include "quad_patches_bytes.h"

#include "../Seamless_snapping/generators.h"
#include "../Seamless_snapping/mesh_test_support.h"

#include <CGAL/Seamless_snapping/internal/inputs/orbifold_tutte_input.h>

#include <CGAL/boost/graph/generators.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

static int files = 0;

static void write_file(const fs::path& p, const std::string& bytes)
{
  std::ofstream os(p, std::ios::binary);
  os << bytes;
  if(!os) { std::cerr << "make_fuzz_seeds: cannot write " << p << std::endl; std::exit(EXIT_FAILURE); }
  ++files;
}

static std::string obj_text(const Mesh& m, UV_map uv)
{
  std::ostringstream os;
  std::string message;
  if(SS::IO::write_OBJ_with_corner_uvs(os, m, uv, message) != SS::SUCCESS) {
    std::cerr << "make_fuzz_seeds: " << message << std::endl;
    std::exit(EXIT_FAILURE);
  }
  return os.str();
}

// the same surface as a cut mesh: one `v` per (vertex, distinct corner UV), as libigl writes them
static std::string cut_mesh_text(const Mesh& m, UV_map uv)
{
  std::ostringstream os;
  os.precision(17);
  os << "#weld: a cut mesh, welded by the reader\n";
  std::map<std::pair<std::uint32_t, std::pair<double, double>>, int> index;
  std::ostringstream faces;
  for(auto f : m.faces()) {
    faces << "f";
    for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
      const Point_2 t = get(uv, h);
      const auto key = std::make_pair(std::uint32_t(m.target(h)), std::make_pair(t.x(), t.y()));
      auto it = index.find(key);
      if(it == index.end()) {
        it = index.emplace(key, int(index.size()) + 1).first;
        const Point_3& p = m.point(m.target(h));
        os << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << "\nvt " << t.x() << ' ' << t.y() << '\n';
      }
      faces << ' ' << it->second << '/' << it->second;
    }
    faces << '\n';
  }
  return os.str() + faces.str();
}

static void obj_seeds(const fs::path& dir)
{
  Mesh sphere;
  CGAL::make_icosahedron(sphere, Point_3(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(sphere, CGAL::parameters::number_of_iterations(1));
  for(SMP::Orbifold_type type : { SMP::Square, SMP::Parallelogram }) {
    Mesh m = sphere;
    UV_map uv = uv_of(m);
    std::string message;
    const auto cones = SS::internal::farthest_point_cones(m, SS::internal::orbifold_cone_count(type));
    if(SS::internal::make_orbifold_tutte_uv(m, uv, cones, type, message) != SS::SUCCESS) {
      std::cerr << "make_fuzz_seeds: orbifold map failed: " << message << std::endl;
      std::exit(EXIT_FAILURE);
    }
    const std::string name = SS::internal::orbifold_type_name(type);
    write_file(dir / (name + ".obj"), obj_text(m, uv));
    write_file(dir / (name + "_cut.obj"), cut_mesh_text(m, uv));
    SS_test::Rng rng(type == SMP::Square ? 1 : 2);
    Mesh noisy = m;
    UV_map nuv = uv_of(noisy);
    for(halfedge_descriptor h : noisy.halfedges())
      put(nuv, h, Point_2(get(nuv, h).x() + 1e-7 * rng.symmetric(), get(nuv, h).y() + 1e-7 * rng.symmetric()));
    write_file(dir / (name + "_noise.obj"), obj_text(noisy, nuv));
    Mesh scaled = m;
    UV_map suv = uv_of(scaled);
    for(halfedge_descriptor h : scaled.halfedges())
      put(suv, h, Point_2(std::ldexp(get(suv, h).x(), 30), std::ldexp(get(suv, h).y(), 30)));
    write_file(dir / (name + "_scaled.obj"), obj_text(scaled, suv));
  }
  write_file(dir / "triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
  // two triangles whose shared edge is a cut with a quarter-turn transition (plus a small error)
  write_file(dir / "quarter_turn.obj",
             "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
             "vt 0 0\nvt 1 0\nvt 1 1\nvt 5 5\nvt 4 5.000001\nvt 4 4\n"
             "f 1/1 2/2 3/3\nf 1/4 3/6 4/5\n");
  write_file(dir / "relative_indices.obj",
             "# relative indices, normals, groups\nmtllib x.mtl\no quad\nv 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\n"
             "vn 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\ns off\nf -4/-4/1 -3/-3/1 -2/-2/1\nf -4/-4/1 -2/-2/1 -1/-1/1\n");
}

static void system_seed(const fs::path& p, const SS_test::Linear_system& s, const std::vector<double>& xbar, int flags)
{
  std::vector<std::vector<std::pair<std::size_t, std::int64_t>>> rows(s.m);
  for(const auto& t : s.triplets) rows[std::size_t(t.row())].emplace_back(std::size_t(t.col()), std::int64_t(t.value()));
  std::vector<std::int64_t> b(s.b.begin(), s.b.end());
  const std::vector<std::uint8_t> bytes = SS_fuzz::encode_system(s.n, rows, b, xbar, flags);
  write_file(p, std::string(bytes.begin(), bytes.end()));
}

static SS_test::Linear_system small_system(std::size_t n, const std::vector<std::vector<std::pair<long, long>>>& rows,
                                           const std::vector<long>& b)
{
  SS_test::Linear_system s;
  s.m = rows.size();
  s.n = n;
  for(std::size_t i = 0; i < rows.size(); ++i)
    for(const auto& e : rows[i]) s.triplets.emplace_back(Eigen::Index(i), Eigen::Index(e.first), e.second);
  s.b = b;
  return s;
}

static void projection_seeds(const fs::path& dir)
{
  const int scale_flags = (16 + 7) << 3;                 // scale check with j = 7
  int k = 0;
  for(std::uint64_t seed = 1; seed <= 40 && k < 8; ++seed) {
    SS_test::Seamless_options o;
    o.target_rows = 24;
    o.max_chain_length = 3;
    o.charts = 3;
    o.untouched_sectors = 1;
    o.seed = seed;
    const SS_test::Linear_system s = SS_test::seamless_system(o);
    if(s.m > 32 || s.n > 48) continue;
    system_seed(dir / ("seamless_" + std::to_string(seed) + ".bin"), s, SS_test::noisy_input(s, 1e-9, seed),
                (k % 2) | (k % 3 == 0 ? scale_flags : 0));
    ++k;
  }
  for(std::uint64_t seed = 1; seed <= 6; ++seed) {
    SS_test::Random_options o;
    o.rows = 6 + 4 * seed;
    o.columns_per_row = 1.5;
    o.min_nnz = 2;
    o.max_nnz = 5;
    o.max_coefficient = int(3 * seed);
    o.homogeneous = seed % 2 == 0;
    o.redundant_rows = seed % 3;
    o.seed = seed;
    const SS_test::Linear_system s = SS_test::random_system(o);
    if(s.m > 32 || s.n > 48) continue;
    system_seed(dir / ("random_" + std::to_string(seed) + ".bin"), s, SS_test::noisy_input(s, 1e-6, seed),
                o.homogeneous ? scale_flags : 2);
  }
  const long big = 1L << 40;
  system_seed(dir / "infeasible_3x_1.bin", small_system(1, { { { 0, 3 } } }, { 1 }), { 0.3 }, 0);
  system_seed(dir / "offset_2_30.bin", small_system(2, { { { 0, 1 }, { 1, -1 } } }, { 1L << 30 }), { 1e-9, 0 }, 0);
  system_seed(dir / "large_coefficients.bin",
              small_system(4, { { { 0, big + 1 }, { 1, -big }, { 2, 3 } }, { { 1, big - 1 }, { 2, big }, { 3, -7 } },
                                { { 0, 5 }, { 3, big } } }, { 0, 0, 0 }),
              { 0.25, -1.5, 2., 1e-3 }, scale_flags);
  system_seed(dir / "unconstrained_and_duplicate.bin",
              small_system(3, { { { 0, 1 }, { 0, 1 }, { 1, -2 } } }, { 0 }), { 1., 0.5, 123.456 }, 0);
}

static void quad_patches_seeds(const fs::path& dir)
{
  auto grid = [](int n) {
    std::vector<std::array<int, 4> > q;
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) q.push_back({{j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i}});
    return q;
  };
  std::vector<std::array<int, 4> > torus;
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 3; ++i) torus.push_back({{3 * j + i, 3 * j + (i + 1) % 3, 3 * ((j + 1) % 3) + (i + 1) % 3, 3 * ((j + 1) % 3) + i}});
  const std::vector<std::array<int, 4> > cube = {{{0, 3, 2, 1}}, {{4, 5, 6, 7}}, {{0, 1, 5, 4}}, {{1, 2, 6, 5}}, {{2, 3, 7, 6}}, {{3, 0, 4, 7}}};
  write_file(dir / "grid_2.bin", SS_fuzz::quad_soup_bytes(9, grid(2)));
  write_file(dir / "grid_3.bin", SS_fuzz::quad_soup_bytes(16, grid(3)));
  write_file(dir / "cube.bin", SS_fuzz::quad_soup_bytes(8, cube));
  write_file(dir / "torus_3.bin", SS_fuzz::quad_soup_bytes(9, torus));
  write_file(dir / "torus_3_garbage.bin", SS_fuzz::quad_soup_bytes(9, torus, true));
}

int main(int argc, char** argv)
{
  if(argc != 2) { std::cerr << "usage: make_fuzz_seeds DIR" << std::endl; return EXIT_FAILURE; }
  const fs::path dir(argv[1]);
  fs::create_directories(dir / "obj_snap");
  fs::create_directories(dir / "projection");
  fs::create_directories(dir / "quad_patches");
  obj_seeds(dir / "obj_snap");
  projection_seeds(dir / "projection");
  quad_patches_seeds(dir / "quad_patches");
  std::cout << "make_fuzz_seeds: " << files << " seed files in " << dir.string() << std::endl;
  return EXIT_SUCCESS;
}
