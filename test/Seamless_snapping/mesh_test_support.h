// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// Mesh types and small helpers shared by the surface tests (test_snap, test_constraints, test_quad, test_trace, test_threads).
// Not part of the package API.

#ifndef CGAL_SEAMLESS_SNAPPING_TEST_MESH_TEST_SUPPORT_H
#define CGAL_SEAMLESS_SNAPPING_TEST_MESH_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Surface_mesh_parameterization/orbifold_enums.h>   // the namespace of the alias SMP

#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/internal/timing.h>

#include "test_arguments.h"

#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <cstring>
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#ifndef SS_SHARED_DATA_DIR
#define SS_SHARED_DATA_DIR ""
#endif
#ifndef SS_CGAL_DATA_DIR
#define SS_CGAL_DATA_DIR ""
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel    K;
typedef K::Point_2                                             Point_2;
typedef K::Point_3                                             Point_3;
typedef CGAL::Surface_mesh<Point_3>                            Mesh;
typedef Mesh::Vertex_index                                     vertex_descriptor;
typedef Mesh::Halfedge_index                                   halfedge_descriptor;
typedef Mesh::Edge_index                                       edge_descriptor;
typedef Mesh::Property_map<halfedge_descriptor, Point_2>       UV_map;   // uv[h] = UV of target(h) in face(h)

namespace SS = CGAL::Seamless_snapping;
namespace CGAL { namespace Surface_mesh_parameterization {} }   // declared, for the alias, without its headers
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;

using CGAL::Seamless_snapping::internal::ms_since;

// the corner UV map "h:uv" of m (created if missing)
static inline UV_map uv_of(Mesh& m)
{
  auto r = m.property_map<halfedge_descriptor, Point_2>("h:uv");
  if(r.second) return r.first;
  return m.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0, 0)).first;
}

// every halfedge UV (border ones too) times 2^j, exactly where no bit is lost to underflow or overflow
static inline void scale_uvs(const Mesh& m, UV_map uv, int j)
{
  for(halfedge_descriptor h : m.halfedges())
    put(uv, h, Point_2(std::ldexp(get(uv, h).x(), j), std::ldexp(get(uv, h).y(), j)));
}

// every halfedge UV (border ones too) times `factor`, rounded (a factor that is not a power of two: a map moved off its
// integer grid, e.g. for quantization)
static inline void multiply_uvs(const Mesh& m, UV_map uv, double factor)
{
  for(halfedge_descriptor h : m.halfedges()) put(uv, h, Point_2(get(uv, h).x() * factor, get(uv, h).y() * factor));
}

// all halfedge UVs (also border ones), as raw bits
static inline std::vector<std::uint64_t> uv_bits(const Mesh& m, UV_map uv)
{
  std::vector<std::uint64_t> out;
  out.reserve(2 * m.number_of_halfedges());
  for(halfedge_descriptor h : m.halfedges()) {
    double x = get(uv, h).x(), y = get(uv, h).y();
    std::uint64_t a, b;
    std::memcpy(&a, &x, 8); std::memcpy(&b, &y, 8);
    out.push_back(a); out.push_back(b);
  }
  return out;
}

// The mesh m renumbered into the empty mesh p: its vertices, then its faces added in a shuffled order and each face's
// corners rotated (std::mt19937 with `seed`: the vertices shuffled, then the faces, then one draw per face). Returns per
// halfedge of p (by index) the halfedge of m with the same target vertex and face, e.g. to copy corner UVs.
static inline std::vector<halfedge_descriptor> renumbered_copy(const Mesh& m, unsigned seed, Mesh& p)
{
  std::mt19937 rng(seed);
  std::vector<vertex_descriptor> vs(m.vertices().begin(), m.vertices().end());
  std::vector<Mesh::Face_index> fs(m.faces().begin(), m.faces().end());
  std::shuffle(vs.begin(), vs.end(), rng);
  std::shuffle(fs.begin(), fs.end(), rng);
  std::vector<vertex_descriptor> to_p(m.num_vertices());
  for(vertex_descriptor v : vs) to_p[std::size_t(v)] = p.add_vertex(m.point(v));
  std::vector<halfedge_descriptor> origin;
  for(Mesh::Face_index f : fs) {
    std::vector<halfedge_descriptor> c(CGAL::halfedges_around_face(m.halfedge(f), m).begin(),
                                       CGAL::halfedges_around_face(m.halfedge(f), m).end());
    std::rotate(c.begin(), c.begin() + long(rng() % c.size()), c.end());
    std::vector<vertex_descriptor> cv;
    for(halfedge_descriptor h : c) cv.push_back(to_p[std::size_t(m.target(h))]);
    const Mesh::Face_index g = p.add_face(cv);
    assert(g != Mesh::null_face());
    origin.resize(p.num_halfedges());
    for(halfedge_descriptor k : CGAL::halfedges_around_face(p.halfedge(g), p))
      for(halfedge_descriptor h : c) if(to_p[std::size_t(m.target(h))] == p.target(k)) origin[std::size_t(k)] = h;
  }
  return origin;
}

// The map of the faces within `rings` face rings of vertex v re-expressed by the grid symmetry p -> R p (R a quarter
// turn counter-clockwise about the origin, an integer point; exact on any double, where a translation would round
// the UVs' low bits): the region's border becomes cut edges, the cut graph moves, the surface map stays the same.
// Returns how many edges became cut edges.
static inline std::size_t recharted(Mesh& m, UV_map uv, vertex_descriptor v, int rings)
{
  std::vector<char> in(m.number_of_faces(), 0), reached(m.number_of_vertices(), 0);
  std::vector<vertex_descriptor> front(1, v);
  reached[v] = 1;
  for(int r = 0; r < rings; ++r) {
    std::vector<vertex_descriptor> next;
    for(vertex_descriptor w : front)
      for(Mesh::Face_index f : CGAL::faces_around_target(m.halfedge(w), m)) {
        if(f == Mesh::null_face() || in[f]) continue;
        in[f] = 1;
        for(vertex_descriptor x : CGAL::vertices_around_face(m.halfedge(f), m))
          if(!reached[x]) { reached[x] = 1; next.push_back(x); }
      }
    front.swap(next);
  }
  auto cut_edges = [&] {
    std::size_t n = 0;
    for(Mesh::Edge_index e : m.edges()) {
      const halfedge_descriptor h = m.halfedge(e), o = m.opposite(h);
      if(!m.is_border(e) && (get(uv, h) != get(uv, m.prev(o)) || get(uv, m.prev(h)) != get(uv, o))) ++n;
    }
    return n;
  };
  const std::size_t before = cut_edges();
  for(Mesh::Face_index f : m.faces())
    if(in[f])
      for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
        const Point_2 p = get(uv, h);
        put(uv, h, Point_2(-p.y(), p.x()));
      }
  return cut_edges() - before;
}

// reads an OBJ with corner UVs; files under a "directional" folder are cut meshes and get welded
static inline bool load_obj(const fs::path& p, Mesh& m)
{
  const bool weld = p.string().find("directional") != std::string::npos;
  std::string msg;
  SS::Status s = SS::IO::read_OBJ_with_corner_uvs(p.string(), m, uv_of(m), msg, SS::parameters::weld_vertices(weld));
  if(s != SS::SUCCESS) std::cerr << "cannot read " << p << ": " << msg << std::endl;
  return s == SS::SUCCESS;
}

// reads the shared data file SS_SHARED_DATA_DIR/relative into m; when the shared data is missing,
// prints "<what>: SKIPPED" and returns false (a file that exists must read, else the test fails)
static inline bool load_shared_or_skip(const char* relative, const char* what, Mesh& m)
{
  const fs::path p = fs::path(SS_SHARED_DATA_DIR) / relative;
  if(std::string(SS_SHARED_DATA_DIR).empty() || !fs::exists(p)) {
    std::cout << what << ": SKIPPED (no '" << p.string() << "')\n";
    return false;
  }
  const bool ok = load_obj(p, m);
  if(!ok) { std::cerr << what << ": cannot read " << p << std::endl; std::abort(); }
  return true;
}

// Every .obj file below the shared data directory, sorted (under --sanitizer-subset only those up to
// 600 kB); false (after a SKIPPED line naming `what`) when there is no shared data directory.
static inline bool shared_obj_files_or_skip(const char* what, std::vector<fs::path>& files)
{
  const fs::path dir(SS_SHARED_DATA_DIR);
  if(std::string(SS_SHARED_DATA_DIR).empty() || !fs::is_directory(dir)) {
    std::cout << what << ": SKIPPED (no shared data directory '" << dir.string() << "')\n";
    return false;
  }
  files.clear();
  for(const auto& entry : fs::recursive_directory_iterator(dir))
    if(entry.is_regular_file() && entry.path().extension() == ".obj" &&
       shared_data_file_in_subset(entry.file_size())) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return true;
}

// every corner's UV: the x and y of its vertex (a projection onto the plane z = 0: one UV per vertex, no cut edge)
static inline void uv_from_xy(const Mesh& m, UV_map uv)
{
  for(halfedge_descriptor h : m.halfedges())
    if(!m.is_border(h)) put(uv, h, Point_2(m.point(m.target(h)).x(), m.point(m.target(h)).y()));
}

// an n x n grid of unit squares in the plane z = 0, two triangles per square: split along the
// diagonal (i, j)-(i+1, j+1) when `main_diagonal`, else along (i+1, j)-(i, j+1). Returns the
// vertices, vertex (i, j) at index j (n + 1) + i.
static inline std::vector<vertex_descriptor> triangulated_grid(Mesh& m, int n, bool main_diagonal)
{
  std::vector<vertex_descriptor> vs;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) vs.push_back(m.add_vertex(Point_3(i, j, 0)));
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      const vertex_descriptor a = vs[j * (n + 1) + i], b = vs[j * (n + 1) + i + 1],
                              c = vs[(j + 1) * (n + 1) + i + 1], d = vs[(j + 1) * (n + 1) + i];
      if(main_diagonal) { m.add_face(a, b, c); m.add_face(a, c, d); }
      else              { m.add_face(a, b, d); m.add_face(b, c, d); }
    }
  return vs;
}

// a flat n x n torus of unit squares (vertex (i, j), i, j mod n), corner UVs (i, j) unwrapped in each
// face: the seams of the cut i = 0 and j = 0 translate by (period_u, 0) and (0, n)
static inline void make_flat_torus(Mesh& m, UV_map& uv, int n, double period_u)
{
  std::vector<vertex_descriptor> vs;
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      const double a = 2 * CGAL_PI * i / n, b = 2 * CGAL_PI * j / n;
      vs.push_back(m.add_vertex(Point_3((2 + std::cos(b)) * std::cos(a), (2 + std::cos(b)) * std::sin(a), std::sin(b))));
    }
  uv = uv_of(m);
  auto V = [&](int i, int j) { return vs[(j % n) * n + (i % n)]; };
  auto add = [&](int i0, int j0, int i1, int j1, int i2, int j2) {
    const int I[3] = {i0, i1, i2}, J[3] = {j0, j1, j2};
    const auto f = m.add_face(V(i0, j0), V(i1, j1), V(i2, j2));
    assert(f != Mesh::null_face());
    for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m))
      for(int c = 0; c < 3; ++c)
        if(m.target(h) == V(I[c], J[c]))
          put(uv, h, Point_2(I[c] == n ? period_u : double(I[c]), double(J[c])));
  };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) { add(i, j, i + 1, j, i + 1, j + 1); add(i, j, i + 1, j + 1, i, j + 1); }
}

#endif // CGAL_SEAMLESS_SNAPPING_TEST_MESH_TEST_SUPPORT_H
