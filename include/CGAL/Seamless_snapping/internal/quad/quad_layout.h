// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_LAYOUT_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_LAYOUT_H

// The quad layout of a quad mesh whose patches are rectangles (quad_patches.h): the coarse polygon mesh with one
// face per patch, on index arrays (quad_layout() in the public header builds the caller's graph from them).
//
// 1. Layout vertices: the quad vertices at a corner of some patch's rectangle (nodes, border corners, and the
//    T-junctions: a trail that ends on another is a corner of the patches on its side and lies on a side of the
//    patch across), and the middle vertex of a chain that would make an arc from a vertex to itself (step 2).
// 2. Each patch's boundary, counter-clockwise from its cell (0, 0): the quad halfedges along its bottom, right,
//    top and left sides (w, h, w, h of them), cut at every layout vertex into runs; one layout halfedge per run,
//    its length the run's number of quad edges. Along a side, the next quad halfedge after e is
//    next(opp(next(e))) (across the inner edge of the rectangle), and a side ends with a turn, next(e).
// 3. The halfedge opposite a run is the run that starts with opp() of its last quad halfedge: a run of the patch
//    across (cut at the same layout vertices, so the same edges reversed), or a border run made here. A border
//    run's next one starts with next() of its last quad halfedge, the border halfedge from the layout vertex where
//    it ends.
// A patch may lie on both sides of an arc (a band cut open once) and meet a vertex more than once (a torus without
// nodes: its vertex where the two loops cross, each loop split once, one face): the layout is then a valid face graph
// but not a polygon mesh.

#include <CGAL/Seamless_snapping/internal/quad/quad_patches.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

// A face graph as index arrays: layout halfedges 2a and 2a + 1 are the two sides of arc a.
struct Quad_layout_arrays
{
  std::vector<int> vertex;          // per layout vertex: its quad vertex (increasing)
  std::vector<int> first;           // per layout halfedge: the first quad halfedge of its run (border runs: border halfedges)
  std::vector<int> length;          // per layout halfedge: quad edges in its run
  std::vector<int> next, target, face;   // face: the patch, -1 on the border
  std::vector<char> corner;         // per layout halfedge of a patch: its target is a corner of the patch's rectangle
  std::vector<int> face_halfedge;   // per patch: its run from the rectangle's corner (0, 0)
  std::size_t t_junctions = 0;      // (patch, vertex) incidences on a side of the rectangle, not at a corner
  std::size_t self_adjacent_arcs = 0;   // arcs with one patch on both sides
  std::size_t loop_splits = 0;          // layout vertices that split a loop (no corner of a patch)
};

// Steps 1-3. Precondition: every patch of c is a rectangle. Empty message on success.
inline std::string quad_layout(const Quad_arrays& m, const Quad_patch_cells& c, Quad_layout_arrays& out)
{
  out = Quad_layout_arrays();
  const std::size_t nh = m.next.size(), np = c.patches.size();
  auto along = [&](int e) { return m.next[std::size_t(m.opp[std::size_t(m.next[std::size_t(e)])])]; };
  // the boundary of each patch (step 2), with the side ends marked
  std::vector<int> corner_bottom(np, -1);
  for(std::size_t f = 0; f < c.patch.size(); ++f)
    if(c.cell[f][0] == 0 && c.cell[f][1] == 0) corner_bottom[std::size_t(c.patch[f])] = c.bottom[f];
  std::vector<std::size_t> start(np + 1, 0);
  std::vector<int> boundary;
  std::vector<char> side_end;
  std::vector<int> layout_vertex(std::size_t(m.n_vertices), -1);
  for(std::size_t p = 0; p < np; ++p) {
    start[p] = boundary.size();
    if(!c.patches[p].rectangle || corner_bottom[p] < 0) return "patch " + std::to_string(p) + " is not a rectangle";
    int e = corner_bottom[p];
    for(int s = 0; s < 4; ++s, e = m.next[std::size_t(e)]) {
      const int n = s % 2 == 0 ? c.patches[p].width : c.patches[p].height;
      for(int k = 0; k < n; ++k, e = k < n ? along(e) : e) {
        boundary.push_back(e);
        side_end.push_back(k == n - 1 ? 1 : 0);
      }
      layout_vertex[std::size_t(m.target[std::size_t(e)])] = 0;          // a corner (step 1)
    }
  }
  start[np] = boundary.size();
  // an arc from a vertex to itself (a trail that comes back to its node, the loops of a torus without nodes) is split
  // at the middle quad vertex of its chain: CGAL's halfedge graphs have no loop edge (is_valid_halfedge_graph())
  for(bool split = true; split;) {
    split = false;
    for(std::size_t p = 0; p < np; ++p)
      for(std::size_t k = start[p], b = start[p]; k < start[p + 1]; ++k) {
        if(layout_vertex[std::size_t(m.target[std::size_t(boundary[k])])] < 0) continue;
        if(m.target[std::size_t(boundary[k])] == m.target[std::size_t(m.opp[std::size_t(boundary[b])])]) {
          if(k == b) return "a quad edge from a vertex to itself";
          int& middle = layout_vertex[std::size_t(m.target[std::size_t(boundary[b + (k - b) / 2])])];
          out.loop_splits += middle < 0 ? 1 : 0;
          middle = 0;
          split = true;
        }
        b = k + 1;
      }
  }
  for(int v = 0; v < m.n_vertices; ++v)
    if(layout_vertex[std::size_t(v)] == 0) { layout_vertex[std::size_t(v)] = int(out.vertex.size()); out.vertex.push_back(v); }
  // the runs of the patches (step 2); halfedge 2a of arc a is the one made first
  std::vector<int> run_of(nh, -1), last;
  auto add_run = [&](int first_q, int last_q, int length, int face, char corner) {
    const int l = int(out.first.size());
    out.first.push_back(first_q); out.length.push_back(length); out.face.push_back(face); out.corner.push_back(corner);
    out.target.push_back(layout_vertex[std::size_t(m.target[std::size_t(last_q)])]);
    out.next.push_back(-1);
    last.push_back(last_q);
    run_of[std::size_t(first_q)] = l;
    return l;
  };
  std::vector<int> runs;                                               // per patch, in order
  for(std::size_t p = 0; p < np; ++p) {
    runs.clear();
    for(std::size_t k = start[p], b = start[p]; k < start[p + 1]; ++k) {
      const std::size_t t = std::size_t(m.target[std::size_t(boundary[k])]);
      if(layout_vertex[t] < 0) continue;
      const int first_q = boundary[b];
      int l = run_of[std::size_t(first_q)];                            // made as the opposite of an earlier run
      if(l < 0) {
        l = add_run(first_q, boundary[k], int(k - b + 1), int(p), side_end[k]);
        add_run(m.opp[std::size_t(boundary[k])], m.opp[std::size_t(first_q)], int(k - b + 1), -1, 0);   // its opposite, for now
      }
      else if(out.face[std::size_t(l)] != -1 || out.length[std::size_t(l)] != int(k - b + 1) || last[std::size_t(l)] != boundary[k])
        return "the runs of patch " + std::to_string(p) + " do not match those across its sides";
      else { out.face[std::size_t(l)] = int(p); out.corner[std::size_t(l)] = side_end[k]; }
      runs.push_back(l);
      b = k + 1;
    }
    for(std::size_t r = 0; r < runs.size(); ++r) out.next[std::size_t(runs[r])] = runs[(r + 1) % runs.size()];
    out.face_halfedge.push_back(runs.front());
    for(int l : runs) out.t_junctions += out.corner[std::size_t(l)] ? 0 : 1;
  }
  // border runs (step 3): those still without a patch
  for(std::size_t l = 0; l < out.first.size(); ++l) {
    if(out.face[l] >= 0) continue;
    if(m.face[std::size_t(out.first[l])] >= 0) return "a run of the patches has no run across it";
    const int n = run_of[std::size_t(m.next[std::size_t(last[l])])];
    if(n < 0 || out.face[std::size_t(n)] >= 0) return "the border is not cut where the patches are";
    out.next[l] = n;
  }
  for(std::size_t a = 0; 2 * a < out.first.size(); ++a)
    out.self_adjacent_arcs += out.face[2 * a] >= 0 && out.face[2 * a] == out.face[2 * a + 1] ? 1 : 0;
  return std::string();
}

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_LAYOUT_H
