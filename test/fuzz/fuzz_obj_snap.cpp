// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// libFuzzer target: the bytes are an OBJ file (a first line starting with "#weld" turns on
// weld_vertices), read by read_OBJ_with_corner_uvs() and, when it reads, snapped by
// snap_seamless_parameterization() with the default parameters. It checks
//  - a failed read leaves the (empty) mesh empty;
//  - a successful read gives a mesh with faces;
//  - on SUCCESS of the snap, is_exactly_seamless() holds (exact rational check);
//  - on any other status, every halfedge UV is bit-identical to what was read;
//  - the map as read, snapped with integer_grid_map(true), merge_cone_pairs(true) (as seamless_quad does),
//    separate_cone_pairs(true) and quantize(true) (a map not near an integer-grid map gets integer translations chosen
//    for it): on SUCCESS, is_exact_integer_grid_map() holds and extract_quad_mesh() either gives a valid polygon mesh
//    of quads (as many as the exact UV area when no cell was dropped) or refuses with the output mesh left empty; on
//    any other status the UVs are those read, bit for bit.
// Any violation aborts (a finding). Build: -DSEAMLESS_SNAPPING_FUZZ=ON with clang (README.md, "Sanitizers and fuzzing").
// The bit-for-bit check compares the UVs after a refused snap with those read in the same run: machine independent.

#include "../Seamless_snapping/mesh_test_support.h"

#include <CGAL/Seamless_snapping/extract_quad_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Seamless_snapping/is_exact_integer_grid_map.h>
#include <CGAL/Seamless_snapping/is_exactly_seamless.h>
#include <CGAL/Seamless_snapping/snap_seamless_parameterization.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#define FUZZ_REQUIRE(cond, what) \
  do { if(!(cond)) { std::fprintf(stderr, "fuzz_obj_snap: violated: %s (%s)\n", what, #cond); std::abort(); } } while(0)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  const bool weld = text.compare(0, 5, "#weld") == 0;
  Mesh m;
  UV_map uv = uv_of(m);
  std::istringstream is(text);
  std::string message;
  const SS::Status read = SS::IO::read_OBJ_with_corner_uvs(is, m, uv, message, SS::parameters::weld_vertices(weld));
  if(read != SS::SUCCESS) {
    FUZZ_REQUIRE(m.number_of_vertices() == 0 && m.number_of_faces() == 0 && m.number_of_halfedges() == 0,
                 "a failed read leaves the mesh as it was");
    return 0;
  }
  FUZZ_REQUIRE(m.number_of_faces() > 0, "a mesh that reads has faces");

  Mesh grid = m;                                   // the map as read, for the integer-grid snap below
  const std::vector<std::uint64_t> before = uv_bits(m, uv);
  const SS::Snap_report report = SS::snap_seamless_parameterization(m, uv);
  if(report.status == SS::SUCCESS)
    FUZZ_REQUIRE(SS::is_exactly_seamless(m, uv), "SUCCESS means exactly seamless");
  else
    FUZZ_REQUIRE(uv_bits(m, uv) == before, "the UV map is untouched on failure");

  UV_map guv = uv_of(grid);
  if(SS::snap_seamless_parameterization(grid, guv, SS::parameters::integer_grid_map(true).merge_cone_pairs(true)
                                                              .separate_cone_pairs(true).quantize(true)).status !=
     SS::SUCCESS) {
    FUZZ_REQUIRE(uv_bits(grid, guv) == before, "the UV map is untouched on an integer-grid failure");
    return 0;
  }
  FUZZ_REQUIRE(SS::is_exact_integer_grid_map(grid, guv), "an integer-grid SUCCESS is an exact integer-grid map");
  Mesh quads;
  // a fuzzed map may hold millions of cells (80 triangles with UVs up to 52,000: 22M quads, 7 GB): the bound keeps
  // a run within libFuzzer's memory limit (a map over it is refused, RANGE_EXCEEDED, and must leave quads empty)
  const SS::Quad_mesh_report q = SS::extract_quad_mesh(grid, guv, quads, SS::parameters::max_grid_cells(1 << 20));
  if(q.status == SS::SUCCESS) {
    FUZZ_REQUIRE(CGAL::is_valid_polygon_mesh(quads) && CGAL::is_quad_mesh(quads) && q.quads == quads.number_of_faces(),
                 "a quad mesh of quads");
    FUZZ_REQUIRE(!q.covers_map() || CGAL::Gmpq(double(q.quads)) == q.uv_area, "as many quads as the UV area");
  } else {
    FUZZ_REQUIRE(quads.number_of_vertices() == 0 && quads.number_of_faces() == 0, "nothing written on failure");
  }
  return 0;
}
