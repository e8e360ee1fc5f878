// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_PATCHES_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_PATCHES_H

// The motorcycle graph of a quad mesh (Eppstein, Goodrich, Kim, Tamstorf, "Motorcycle graphs: canonical quad
// mesh partitioning", SGP 2008) and its patches, on index arrays (quad_mesh_patches() fills them from the
// caller's mesh). Combinatorial only: no coordinate is read.
//
// 1. Motorcycles. Nodes are the interior vertices of valence other than 4 and the border vertices with other
//    than 2 quads; each sends a motorcycle along each of its edges that has a quad on both sides. All move
//    together, one edge per round; a motorcycle marks the edges it runs along and the vertices it reaches, and
//    stops at a vertex marked before the round (a node, a border vertex, or a vertex of a trail laid before: a
//    T-junction). At a regular interior vertex first reached in a round, by one motorcycle or several at once, one
//    goes straight on (the edge opposite the one it came by) and the others stop there: of those that no other
//    meets head-on (two that meet head-on both stop; their trails join), the one whose heading is a quarter turn
//    counter-clockwise from the other's, where two arrive at right angles. The rule reads the orientation only,
//    no index: the partition does not depend on the numbering of the mesh or the order of the motorcycles (but
//    on a part without nodes). A connected part without nodes (a torus, a cylinder whose borders have no corner)
//    gets motorcycles from its first vertex, along each of its edges with two quads.
// 2. Patches: the quads connected across edges that no motorcycle ran along.
// 3. Grids: each patch is given integer coordinates from its quad of smallest index, whose halfedge(f) runs
//    along its bottom side (+i): across the right side of a quad lies (i + 1, j) with its bottom side the
//    halfedge after the shared one, and so on. A patch is a rectangle when every quad gets one cell and one
//    bottom side, consistently from every neighbour in the patch, the cells are those of a w x h rectangle, each
//    once, and exactly the sides on the rectangle's boundary are trail or border edges. On a rectangle the
//    cells are then shifted so that the lower-left one is (0, 0).

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

// A polygon mesh as index arrays: per halfedge next, opposite, target vertex and face (-1: border); per face one
// of its halfedges.
struct Quad_arrays
{
  std::vector<int> next, opp, target, face;
  std::vector<int> face_halfedge;
  int n_vertices = 0;
};

struct Quad_patch_cells
{
  std::vector<int> patch;                 // per face
  std::vector<std::array<int, 2> > cell;  // per face: (i, j) in its patch (rectangles: from (0, 0))
  std::vector<int> bottom;                // per face: its halfedge along the +i side of its cell
  struct Patch { std::size_t quads = 0; int width = 0, height = 0; bool rectangle = false; };
  std::vector<Patch> patches;
  std::size_t motorcycles = 0, nodes = 0;
  std::size_t stops_on_trails = 0;        // motorcycles that ended at a regular vertex of a trail laid before
  std::vector<char> trail;                // per halfedge: on a motorcycle's trail (both halfedges of the edge)
};

// Per vertex: its incoming halfedges (its degree), how many of them are border halfedges, and one of them (-1: isolated).
struct Vertex_fans
{
  std::vector<int> degree, border_in, some_in;
  explicit Vertex_fans(const Quad_arrays& m)
    : degree(std::size_t(m.n_vertices), 0), border_in(std::size_t(m.n_vertices), 0), some_in(std::size_t(m.n_vertices), -1)
  {
    for(std::size_t h = 0; h < m.target.size(); ++h) {
      const std::size_t v = std::size_t(m.target[h]);
      ++degree[v];
      border_in[v] += m.face[h] < 0 ? 1 : 0;
      some_in[v] = int(h);
    }
  }
};

// Empty if the arrays form a manifold quad mesh, else why not.
inline std::string quad_mesh_defect(const Quad_arrays& m, const Vertex_fans& fans)
{
  for(std::size_t f = 0; f < m.face_halfedge.size(); ++f) {
    int n = 0, h = m.face_halfedge[f];
    do { ++n; h = m.next[std::size_t(h)]; } while(h != m.face_halfedge[f] && n <= 4);
    if(n != 4) return "face " + std::to_string(f) + " is not a quad";
  }
  // a manifold vertex: its incoming halfedges are one cycle of opp(next(h)), with at most one border halfedge
  for(int v = 0; v < m.n_vertices; ++v) {
    const int h0 = fans.some_in[std::size_t(v)], degree = fans.degree[std::size_t(v)];
    if(h0 < 0) continue;                                      // isolated: no edge, no motorcycle
    int n = 0, h = h0;
    do { ++n; h = m.opp[std::size_t(m.next[std::size_t(h)])]; } while(h != h0 && n <= degree);
    if(n != degree || fans.border_in[std::size_t(v)] > 1)
      return "vertex " + std::to_string(v) + " is not manifold (its quads form several fans)";
  }
  return std::string();
}

// Steps 1-3 (see the header). Precondition: quad_mesh_defect(m, fans) is empty.
inline Quad_patch_cells quad_patch_cells(const Quad_arrays& m, const Vertex_fans& fans)
{
  const std::size_t nh = m.next.size(), nf = m.face_halfedge.size(), nv = std::size_t(m.n_vertices);
  Quad_patch_cells out;
  const std::vector<int>& degree = fans.degree;
  const std::vector<int>& some_in = fans.some_in;
  auto on_border = [&](std::size_t v) { return fans.border_in[v] > 0; };
  auto interior_edge = [&](int h) { return m.face[std::size_t(h)] >= 0 && m.face[std::size_t(m.opp[std::size_t(h)])] >= 0; };
  // a border vertex with other than 2 quads (its incoming halfedges but the border one), an interior one of valence other than 4
  auto is_node = [&](std::size_t v) { return some_in[v] >= 0 && (on_border(v) ? degree[v] - fans.border_in[v] != 2 : degree[v] != 4); };

  // 1. motorcycles: the halfedge each runs along next
  std::vector<char> marked(nv, 0);
  out.trail.assign(nh, 0);
  std::vector<int> riding;
  auto launch = [&](std::size_t v) {                          // along every edge with two quads, around v
    marked[v] = 1;
    const int h0 = some_in[v];
    int h = h0;
    do { const int g = m.opp[std::size_t(h)]; if(interior_edge(g)) riding.push_back(g); h = m.opp[std::size_t(m.next[std::size_t(h)])]; } while(h != h0);
  };
  for(std::size_t v = 0; v < nv; ++v) if(is_node(v)) { ++out.nodes; launch(v); }
  for(std::size_t v = 0; v < nv; ++v) if(on_border(v)) marked[v] = 1;
  {                                                           // a connected part without a node: seeded at its first vertex
    std::vector<char> seen(nv, 0);                            // (a part whose nodes launch nothing, e.g. a grid with its 4
    std::vector<std::size_t> stack;                           // corners, is one patch)
    for(std::size_t v0 = 0; v0 < nv; ++v0) {
      if(seen[v0] || some_in[v0] < 0) continue;
      bool has_node = false;
      seen[v0] = 1; stack.assign(1, v0);
      while(!stack.empty()) {
        const std::size_t v = stack.back(); stack.pop_back();
        has_node = has_node || is_node(v);
        int h = some_in[v];
        do {
          const std::size_t u = std::size_t(m.target[std::size_t(m.opp[std::size_t(h)])]);
          if(!seen[u]) { seen[u] = 1; stack.push_back(u); }
          h = m.opp[std::size_t(m.next[std::size_t(h)])];
        } while(h != some_in[v]);
      }
      if(!has_node) launch(v0);
    }
  }
  out.motorcycles = riding.size();
  std::vector<int> group(nv, -1);                             // per vertex reached in this round: its arrivals' group
  std::vector<std::vector<int> > arrivals;
  while(!riding.empty()) {
    arrivals.clear();
    for(int g : riding) {
      out.trail[std::size_t(g)] = out.trail[std::size_t(m.opp[std::size_t(g)])] = 1;
      const std::size_t w = std::size_t(m.target[std::size_t(g)]);
      if(marked[w]) { out.stops_on_trails += is_node(w) || on_border(w) ? 0 : 1; continue; }
      if(group[w] < 0) { group[w] = int(arrivals.size()); arrivals.emplace_back(); }
      arrivals[std::size_t(group[w])].push_back(g);
    }
    // who goes on from a regular interior vertex reached in this round (see the header)
    std::vector<int> still;
    for(const std::vector<int>& a : arrivals) {
      const std::size_t w = std::size_t(m.target[std::size_t(a.front())]);
      marked[w] = 1;
      group[w] = -1;
      std::vector<int> heading(a.size(), 0);                  // quarter turns counter-clockwise from a[0]'s
      for(std::size_t i = 1; i < a.size(); ++i) {
        int h = a.front(), k = 0;                            // opp(next(h)): the next incoming halfedge clockwise
        while(h != a[i] && k < 4) { h = m.opp[std::size_t(m.next[std::size_t(h)])]; ++k; }
        heading[i] = (4 - k) % 4;
      }
      int goes = -1;                                          // of those without one from straight ahead, the one
      for(std::size_t i = 0; i < a.size(); ++i) {             // turned counter-clockwise from the other
        bool met = false;
        for(std::size_t j = 0; j < a.size(); ++j) met = met || heading[j] == (heading[i] + 2) % 4;
        if(!met && (goes < 0 || heading[i] == (heading[std::size_t(goes)] + 1) % 4)) goes = int(i);
      }
      for(std::size_t i = 0; i < a.size(); ++i) {
        if(int(i) == goes) still.push_back(m.next[std::size_t(m.opp[std::size_t(m.next[std::size_t(a[i])])])]);  // straight on
        else ++out.stops_on_trails;
      }
    }
    riding.swap(still);
  }

  // 2. patches (quads across edges off the trails), numbered by their quad of smallest index
  const int none = -1;
  out.patch.assign(nf, none);
  out.cell.assign(nf, std::array<int, 2>{{0, 0}});
  out.bottom.assign(nf, none);
  std::vector<int> queue;
  for(std::size_t f0 = 0; f0 < nf; ++f0) {
    if(out.patch[f0] != none) continue;
    const int p = int(out.patches.size());
    out.patches.emplace_back();
    Quad_patch_cells::Patch& P = out.patches.back();
    // 3. the grid, from f0 with its halfedge(f) as bottom side
    bool consistent = true;
    std::array<int, 2> lo{{0, 0}}, hi{{0, 0}};
    out.patch[f0] = p; out.bottom[f0] = m.face_halfedge[f0];
    queue.assign(1, int(f0));
    for(std::size_t q = 0; q < queue.size(); ++q) {
      const std::size_t f = std::size_t(queue[q]);
      int side = out.bottom[f];
      for(int s = 0; s < 4; ++s, side = m.next[std::size_t(side)]) {   // bottom, right, top, left
        if(out.trail[std::size_t(side)] || !interior_edge(side)) continue;
        const int o = m.opp[std::size_t(side)];
        const std::size_t g = std::size_t(m.face[std::size_t(o)]);
        static const int di[4] = {0, 1, 0, -1}, dj[4] = {-1, 0, 1, 0};
        const std::array<int, 2> c{{out.cell[f][0] + di[s], out.cell[f][1] + dj[s]}};
        // the neighbour's bottom: across our side s lies its side (s + 2) mod 4, which is o
        int b = o;
        for(int t = (s + 2) % 4; t != 0; t = (t + 1) % 4) b = m.next[std::size_t(b)];
        if(out.patch[g] == none) {
          out.patch[g] = p; out.cell[g] = c; out.bottom[g] = b; queue.push_back(int(g));
          for(int k = 0; k < 2; ++k) { lo[std::size_t(k)] = (std::min)(lo[std::size_t(k)], c[std::size_t(k)]); hi[std::size_t(k)] = (std::max)(hi[std::size_t(k)], c[std::size_t(k)]); }
        }
        else if(out.cell[g] != c || out.bottom[g] != b) consistent = false;
      }
    }
    P.quads = queue.size();
    const long w = long(hi[0]) - lo[0] + 1, h = long(hi[1]) - lo[1] + 1;
    P.rectangle = consistent && w * h == long(P.quads);
    if(P.rectangle) {                                          // each cell once, trails exactly on the boundary
      std::vector<char> seen(std::size_t(w * h), 0);
      for(int g : queue) {
        std::array<int, 2>& c = out.cell[std::size_t(g)];
        c[0] -= lo[0]; c[1] -= lo[1];
        char& s = seen[std::size_t(c[1]) * std::size_t(w) + std::size_t(c[0])];
        if(s) P.rectangle = false;
        s = 1;
        int side = out.bottom[std::size_t(g)];
        const bool on_boundary[4] = {c[1] == 0, c[0] == w - 1, c[1] == h - 1, c[0] == 0};
        for(int k = 0; k < 4; ++k, side = m.next[std::size_t(side)])
          if(on_boundary[k] != (out.trail[std::size_t(side)] || !interior_edge(side))) P.rectangle = false;
      }
    }
    if(P.rectangle) { P.width = int(w); P.height = int(h); }
  }
  return out;
}

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_PATCHES_H
