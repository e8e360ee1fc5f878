// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// Mesh types and small helpers shared by the surface tests (test_snap, test_constraints).
// Not part of the package API.

#ifndef CGAL_SEAMLESS_SNAPPING_TEST_MESH_TEST_SUPPORT_H
#define CGAL_SEAMLESS_SNAPPING_TEST_MESH_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Seamless_snapping/IO/OBJ.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iostream>
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
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;

static inline double ms_since(std::chrono::steady_clock::time_point t0)
{ return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count(); }

// the corner UV map "h:uv" of m (created if missing)
static inline UV_map uv_of(Mesh& m)
{
  auto r = m.property_map<halfedge_descriptor, Point_2>("h:uv");
  if(r.second) return r.first;
  return m.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0, 0)).first;
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

// reads an OBJ with corner UVs; files under a "directional" folder are cut meshes and get welded
static inline bool load_obj(const fs::path& p, Mesh& m)
{
  const bool weld = p.string().find("directional") != std::string::npos;
  std::string msg;
  SS::Status s = SS::IO::read_OBJ_with_corner_uvs(p.string(), m, uv_of(m), msg, SS::parameters::weld_vertices(weld));
  if(s != SS::SUCCESS) std::cerr << "cannot read " << p << ": " << msg << std::endl;
  return s == SS::SUCCESS;
}

#endif // CGAL_SEAMLESS_SNAPPING_TEST_MESH_TEST_SUPPORT_H
