// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef SS_FUZZ_QUAD_PATCHES_BYTES_H
#define SS_FUZZ_QUAD_PATCHES_BYTES_H

// The byte format of fuzz_quad_patches (written by make_fuzz_seeds): byte 0 holds the number of vertices minus 1
// (bits 0-5, 1 to 64 vertices) and, in bit 7, whether collect_garbage() runs at the end; then per face 5 bytes: a flag
// byte (bit 0: a triangle of the next 3 bytes instead of a quad of 4; bit 1: remove it once all are added (the
// first such face, where the mesh allows it; fuzz_quad_patches.cpp), leaving removed elements) and 4 vertex indices (each taken modulo the number of vertices). Faces that
// CGAL::Euler::add_face() refuses (a non-manifold edge, a repeated vertex) are left out.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace SS_fuzz {

struct Quad_soup
{
  int vertices = 1;
  bool collect_garbage = false;
  struct Face { bool triangle = false, removed = false; std::array<int, 4> v{{0, 0, 0, 0}}; };
  std::vector<Face> faces;
};

inline Quad_soup quad_soup_from_bytes(const std::uint8_t* data, std::size_t size)
{
  Quad_soup s;
  if(size == 0) return s;
  s.vertices = 1 + (data[0] & 63);
  s.collect_garbage = (data[0] & 128) != 0;
  for(std::size_t k = 1; k + 5 <= size; k += 5) {
    Quad_soup::Face f;
    f.triangle = (data[k] & 1) != 0;
    f.removed = (data[k] & 2) != 0;
    for(int c = 0; c < 4; ++c) f.v[std::size_t(c)] = int(data[k + 1 + std::size_t(c)]) % s.vertices;
    s.faces.push_back(f);
  }
  return s;
}

inline std::string quad_soup_bytes(int vertices, const std::vector<std::array<int, 4> >& quads, bool collect_garbage = false)
{
  std::string b(1, char((vertices - 1) | (collect_garbage ? 128 : 0)));
  for(const std::array<int, 4>& q : quads) {
    b += char(0);
    for(int v : q) b += char(v);
  }
  return b;
}

} // namespace SS_fuzz

#endif // SS_FUZZ_QUAD_PATCHES_BYTES_H
