// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_BRANCHED_CELLS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_BRANCHED_CELLS_H

// A vertex around which a fold-free map winds m > 1 times (an angle sum of 4m quarter turns, e.g. a regular vertex
// wound twice where the untangling could not unwind it) is a branch point of order m. On an integer point it is a quad
// vertex of valence 4m. Off the integer points, the cell holding its point is covered m times (quad_cells.h: a
// branched cell): its preimage is a disk bounded by the cell's four sides m times, a 4m-gon whose corners are the m
// surface points of each corner of the cell, and which holds no integer point. No unit cell is a face there.
// fill_branched_cells() finds that 4m-gon as the loop of sides that the quads around it leave open (each side of a
// quad on one side and none on the other, between corners of the cell), and fills it with 2m - 1 quads, a ladder of
// rungs between its corners: for the loop L[0..n-1], the quads (L[i], L[i+1], L[n-2-i], L[n-1-i]), i < n/2 - 1, rotated
// so that no rung is an edge the mesh has already. The fill keeps the disk's border, so V - E + F is kept; its two
// ends of each rung gain one edge (the branch point's index -(m-1) carried by 4(m-1) vertices of index -1/4, valence
// 5 where they had 4), and the quads are m - 1 more than the cell's UV area m. The cell of a cone of valence 1 next to
// the branched cell (a quad (p, a, b, a), valence_one_cones.h, whose side a - b it shares) is taken into the fill: the
// two are one disk bounded by the same 4m points. Refused where the loop is not that (a neighbouring cell dropped or
// branched too, a corner point twice).

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/quad/quad_cells.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

// The cell of a cone of valence 1 next to a branched cell: a quad (p, a, b, a) with the cone p at one corner
// (valence_one_cones.h) whose corners a and b are corners of the branched cell `br` and which has a quad across one of
// its two sides a - b and none across the other (where the branched cell is: it has no quad). The union of the two is
// a disk bounded by the same 4m points (the cone cell's other side a - b takes the place of the one they share), so
// the fill takes it in: `p` and the rotation of the quad are returned; -1 if `q` is no such cell (e.g. with a cone at
// a, whose a and b are corners of a branched cell that does not touch it: quads across both sides).
inline int absorbable_cone_cell(const Quad_cells& cells, const Quad_incidence& incidence, const Quad_cells::Branched& br,
                                int q, const std::vector<int>& valence, int& rotation)
{
  const std::array<int, 4>& Q = cells.quads[std::size_t(q)];
  for(rotation = 0; rotation < 4; ++rotation) {
    const int p = Q[std::size_t(rotation)], a = Q[std::size_t((rotation + 1) % 4)], b = Q[std::size_t((rotation + 2) % 4)];
    if(a != Q[std::size_t((rotation + 3) % 4)] || a == b || !br.has_corner(a) || !br.has_corner(b) || br.has_corner(p))
      continue;
    const Integer_point& cone = cells.points[std::size_t(p)];
    if(cone.kind != AT_VERTEX || valence[std::size_t(cone.element)] != 1 || incidence.quads_of[p].size() != 1) continue;
    int r = 0;
    if((incidence.quad_with_side(b, a, q, r) < 0) != (incidence.quad_with_side(a, b, q, r) < 0)) return p;
  }
  return -1;
}

// Fills every branched cell of `cells` (see the header); the quads are appended, with the faces of the cell each,
// `repairs` gets the vertices, the extra quads and the rung ends' valence changes (valence_change sized to the points).
// A cone of valence 1 whose cell is next to a branched cell (absorbable_cone_cell()) is taken into the fill: its cell
// and point go, its corners a and b lose two edges and one (its index 3/4 goes to them: 1/2 and 1/4), and the fill's
// 2m - 1 quads cover the area m + k with k such cells (Cell_repairs::absorbed_cones); of the ladder's rotations, the
// one whose rungs end at the most of those a and b (where a rung ends at a, valence 3, at b 4).
// `valence`: per vertex its angle sum in quarter turns (quad_valences()). On INVALID_INPUT (the first cell whose loop
// is not a 4m-gon of its corners; `failed_vertex` its branch point, named in `message`) `cells` is unchanged.
inline Status fill_branched_cells(Quad_cells& cells, const std::vector<int>& valence, Cell_repairs& repairs,
                                  int& failed_vertex, std::string& message)
{
  repairs.valence_change.assign(cells.points.size(), 0);
  if(cells.branched.empty()) return SUCCESS;
  Quad_incidence incidence(cells);                        // of the unit cells
  std::vector<char> quad_gone(cells.quads.size(), 0), point_gone(cells.points.size(), 0);
  incidence.gone = &quad_gone;
  std::vector<std::array<int, 4> > added;
  std::vector<std::vector<int> > added_faces;
  std::vector<int> change(cells.points.size(), 0), absorbed;
  std::size_t extra = 0;
  // the cone cells each cell takes in, its loop and its ladder, into `added`
  auto fill = [&](const Quad_cells::Branched& br) {
    const int turns = valence[std::size_t(br.vertex)];
    auto refuse = [&](const std::string& why) {
      failed_vertex = br.vertex;
      message = "vertex " + std::to_string(br.vertex) + " has a UV angle sum of " + std::to_string(turns) +
                " quarter turns off the integer points (the map winds " + std::to_string(turns / 4) + " times around "
                "it, inside a cell), and the cell's preimage cannot be filled with quads: " + why +
                "; a larger grid_scale makes the cells smaller";
      return INVALID_INPUT;
    };
    const std::vector<int>& K = br.corners;
    const std::size_t n = K.size();
    if(n != std::size_t(turns))
      return refuse("its cell has " + std::to_string(n) + " corner points, not 4 per turn (another branch point or a "
                    "cone in it or next to it)");
    std::vector<int> faces = br.faces, lost;             // lost: the corners a and b of the cone cells taken in
    for(int k : K)
      for(int q : incidence.quads_of[k]) {
        int r = 0;
        const int p = quad_gone[std::size_t(q)] ? -1 : absorbable_cone_cell(cells, incidence, br, q, valence, r);
        if(p < 0) continue;
        const std::array<int, 4>& Q = cells.quads[std::size_t(q)];
        quad_gone[std::size_t(q)] = 1;
        point_gone[std::size_t(p)] = 1;
        change[std::size_t(Q[std::size_t((r + 1) % 4)])] -= 2;
        change[std::size_t(Q[std::size_t((r + 2) % 4)])] -= 1;
        lost.push_back(Q[std::size_t((r + 1) % 4)]);
        lost.push_back(Q[std::size_t((r + 2) % 4)]);
        absorbed.push_back(cells.points[std::size_t(p)].element);
        faces.insert(faces.end(), cells.faces_begin(std::size_t(q)), cells.faces_end(std::size_t(q)));
      }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    auto rank = [&](int p) { return std::size_t(std::lower_bound(K.begin(), K.end(), p) - K.begin()); };
    // the loop: the sides between the cell's corners with a quad on one side only, reversed (the hole's direction)
    std::vector<int> next(n, -1);
    for(std::size_t i = 0; i < n; ++i)
      for(int q : incidence.quads_of[K[i]]) {
        if(quad_gone[std::size_t(q)]) continue;
        for(int k = 0; k < 4; ++k) {
          const int a = cells.quads[std::size_t(q)][std::size_t(k)], b = cells.quads[std::size_t(q)][std::size_t((k + 1) % 4)];
          if(a != K[i] || !br.has_corner(b) || incidence.has_side(b, a)) continue;
          if(next[rank(b)] >= 0 && next[rank(b)] != a) return refuse("a corner point has two open sides");
          next[rank(b)] = a;                              // the hole runs b -> a
        }
      }
    std::vector<int> loop(1, K[0]);
    while(loop.size() <= n) {
      const int a = next[rank(loop.back())];
      if(a < 0) return refuse("the quads around it do not close a loop around the cell (a neighbouring cell is missing)");
      if(a == loop.front()) break;
      loop.push_back(a);
    }
    if(loop.size() != n) return refuse("the open sides around it form a loop of " + std::to_string(loop.size()) +
                                       " of its " + std::to_string(n) + " corner points");
    // a rotation whose rungs are no edges yet; of those, the first whose rungs end at the most corners that lost
    // edges to a cone cell taken in (valence 2 or 3 otherwise)
    auto lost_edges = [&](int x) { return std::find(lost.begin(), lost.end(), x) != lost.end() ? 1 : 0; };
    std::size_t start = n;
    int best = -1;
    for(std::size_t s = 0; s < n; ++s) {
      bool free = true;
      int score = 0;
      for(std::size_t i = 0; i + 2 < n / 2 && free; ++i) {
        const int a = loop[(s + i + 1) % n], b = loop[(s + n - 2 - i) % n];
        free = !incidence.has_side(a, b) && !incidence.has_side(b, a);
        score += lost_edges(a) + lost_edges(b);
      }
      if(free && score > best) { start = s; best = score; }
    }
    if(start == n) return refuse("every ladder of quads across it would repeat an edge of the mesh");
    auto L = [&](std::size_t i) { return loop[(start + i) % n]; };
    for(std::size_t i = 0; i + 1 < n / 2; ++i) {
      added.push_back({{L(i), L(i + 1), L(n - 2 - i), L(n - 1 - i)}});
      added_faces.push_back(faces);
      if(i + 2 < n / 2) { ++change[std::size_t(L(i + 1))]; ++change[std::size_t(L(n - 2 - i))]; }
    }
    extra += n / 4 - 1;
    return SUCCESS;
  };
  for(const Quad_cells::Branched& br : cells.branched) {
    const Status s = fill(br);
    if(s != SUCCESS) return s;
  }
  for(const Quad_cells::Branched& br : cells.branched) repairs.filled_vertices.push_back(br.vertex);
  repairs.absorbed_cones.insert(repairs.absorbed_cones.end(), absorbed.begin(), absorbed.end());
  repairs.extra_quads = extra;
  cells.branched.clear();
  replace_cells(cells, quad_gone, point_gone, added, added_faces, change);
  repairs.valence_change.swap(change);
  return SUCCESS;
}

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_BRANCHED_CELLS_H
