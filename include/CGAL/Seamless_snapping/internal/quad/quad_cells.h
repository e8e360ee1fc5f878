// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_CELLS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_CELLS_H

// The cells of a fold-free integer-grid map, stitched from the pieces (cell_pieces.h) by exact equality:
//   1. glue: wherever the open segment of an interior edge (side g of face f) runs through the open cell
//      c of a piece (f, c), that piece and the piece (f', T(c)) of the face f' across the edge are one
//      cell, T = R^k u + t the edge's transition (integer t). A union-find carries the transition to the
//      chart of each set's first piece; a cycle that closes with another transition than the identity
//      means a cell that is no disk (a guard: a cycle inside an open cell would need a cone inside it).
//      A border edge through the open cell of a piece cuts the cell: incomplete, dropped and counted.
//      Across a collapsed face (collapsed_faces.h) the piece is glued to the pieces beyond the sides of that
//      face that run through the same open cell (glue_across()), and the cell covers the collapsed face.
//   2. corners: every corner of a piece's cell that lies in the closed UV triangle of its face is an
//      integer point of the surface (integer_points.h); mapped into the chart of the cell's first piece
//      it is one of the four corners of that chart's cell. Each corner of a complete cell must be
//      exactly one surface point.
// A complete cell is then a quad: its four corners counter-clockwise from the lower-left one in the
// chart of its first piece (transitions keep the orientation), and the faces of its pieces.
// A branched cell, one that holds in its open cell the point of a vertex around which the map winds m > 1 times
// (`branch_vertex`: an angle sum of 4m quarter turns off the integer points), is covered m times: its pieces form one
// set whose chart corners are m surface points each. It is no quad; its corner points and faces are kept
// (Quad_cells::branched) for branched_cells.h, which fills the 4m-gon they bound with quads.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/quad/cell_pieces.h>
#include <CGAL/Seamless_snapping/internal/quad/chart_union_find.h>
#include <CGAL/Seamless_snapping/internal/quad/collapsed_faces.h>
#include <CGAL/Seamless_snapping/internal/quad/integer_points.h>
#include <CGAL/Seamless_snapping/internal/surface/index_lists.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>   // vertex_pair_name()

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

struct Quad_cells
{
  std::vector<Integer_point> points;            // the quad vertices
  std::vector<std::array<int, 4> > quads;       // per complete cell: its corners (indices into points), counter-clockwise
  std::vector<std::size_t> faces_first;         // per quad q: the faces of the map it covers, ascending, are
  std::vector<int> faces;                       // faces[faces_first[q] .. faces_first[q + 1] - 1]
  std::size_t incomplete = 0;                   // cells cut by the border, dropped
  int first_incomplete_face = -1;               // a face with a piece of the first of them
  struct Branched
  {
    std::vector<int> corners;                   // its corner points (indices into points), ascending: 4m of them
    std::vector<int> faces;                     // the faces of its pieces, ascending
    int vertex = -1;                            // the vertex it winds around (Corner_mesh numbering)
    bool has_corner(int p) const { return std::binary_search(corners.begin(), corners.end(), p); }
  };
  std::vector<Branched> branched;               // complete branched cells (see the header), not in quads

  // the faces of quad q: faces[faces_first[q] .. faces_first[q + 1] - 1]
  std::vector<int>::const_iterator faces_begin(std::size_t q) const { return faces.cbegin() + std::ptrdiff_t(faces_first[q]); }
  std::vector<int>::const_iterator faces_end(std::size_t q) const { return faces.cbegin() + std::ptrdiff_t(faces_first[q + 1]); }
};

// What extract_quads() changed in the cells beyond the unit cells (branched_cells.h, valence_one_cones.h), for the
// verification (quad_mesh_checks.h)
struct Cell_repairs
{
  std::vector<int> split_cones;        // the mesh vertices (Corner_mesh numbering) of the cones of valence 1 split
  std::vector<int> filled_vertices;    // the vertices whose branched cells were filled
  std::vector<int> absorbed_cones;     // the mesh vertices of the cones of valence 1 whose cell a fill took in
  std::size_t extra_quads = 0;         // quads beyond the UV area that the fills added (m - 1 per cell covered m times)
  std::vector<int> valence_change;     // per quad vertex: its edges beyond (or below) what the map gives its point
};

// The quads at every point of `cells` (once per corner of each) and the quad with a given side, for the repairs
// (branched_cells.h, valence_one_cones.h); valid while cells.quads is unchanged
struct Quad_incidence
{
  const Quad_cells& cells;
  Index_lists quads_of;

  explicit Quad_incidence(const Quad_cells& c) : cells(c)
  {
    quads_of.build(int(c.points.size()), [&](auto emit) {
      for(std::size_t q = 0; q < c.quads.size(); ++q)
        for(int p : c.quads[q]) emit(p, int(q));
    });
  }

  const std::vector<char>* gone = nullptr;      // quads that quad_with_side() does not see (removed by a repair)

  // the quad other than `not_q` (and not gone) with the side from -> to (in that direction), and in `rank` the place of
  // `from` in it; -1 if none
  int quad_with_side(int from, int to, int not_q, int& rank) const
  {
    for(int q : quads_of[from]) {
      if(q == not_q || (gone != nullptr && (*gone)[std::size_t(q)])) continue;
      for(rank = 0; rank < 4; ++rank)
        if(cells.quads[std::size_t(q)][std::size_t(rank)] == from && cells.quads[std::size_t(q)][std::size_t((rank + 1) % 4)] == to)
          return q;
    }
    return -1;
  }

  bool has_side(int from, int to) const { int rank; return quad_with_side(from, to, -1, rank) >= 0; }
};

// Removes the quads with `quad_gone` set (their faces with them) and the points with `point_gone` set (no remaining quad
// or branched cell may have them as a corner), then appends `added` with the faces `added_faces` each; the others keep
// their order, and the corners of the quads and branched cells and `per_point` (e.g. Cell_repairs::valence_change)
// follow the new numbering of the points. For the repairs that replace cells (valence_one_cones.h, branched_cells.h).
inline void replace_cells(Quad_cells& cells, const std::vector<char>& quad_gone, const std::vector<char>& point_gone,
                          const std::vector<std::array<int, 4> >& added, const std::vector<std::vector<int> >& added_faces,
                          std::vector<int>& per_point)
{
  std::vector<int> new_index(cells.points.size(), -1);
  std::vector<Integer_point> points;
  std::vector<int> per;
  for(std::size_t i = 0; i < cells.points.size(); ++i)
    if(!point_gone[i]) {
      new_index[i] = int(points.size());
      points.push_back(cells.points[i]);
      per.push_back(per_point[i]);
    }
  std::vector<std::array<int, 4> > quads;
  std::vector<std::size_t> faces_first(1, 0);
  std::vector<int> faces;
  auto add = [&](const std::array<int, 4>& q, std::vector<int>::const_iterator b, std::vector<int>::const_iterator e) {
    quads.push_back({{new_index[std::size_t(q[0])], new_index[std::size_t(q[1])], new_index[std::size_t(q[2])],
                      new_index[std::size_t(q[3])]}});
    faces.insert(faces.end(), b, e);
    faces_first.push_back(faces.size());
  };
  for(std::size_t q = 0; q < cells.quads.size(); ++q)
    if(!quad_gone[q])
      add(cells.quads[q], cells.faces_begin(q), cells.faces_end(q));
  for(std::size_t k = 0; k < added.size(); ++k) add(added[k], added_faces[k].cbegin(), added_faces[k].cend());
  for(Quad_cells::Branched& br : cells.branched)
    for(int& c : br.corners) c = new_index[std::size_t(c)];
  cells.points.swap(points);
  cells.quads.swap(quads);
  cells.faces.swap(faces);
  cells.faces_first.swap(faces_first);
  per_point.swap(per);
}

inline std::string cell_name(const Grid_point& c, int f)
{
  return "cell [" + std::to_string(c.u) + ", " + std::to_string(c.u + 1) + "] x [" + std::to_string(c.v) + ", " +
         std::to_string(c.v + 1) + "] of face " + std::to_string(f);
}

// Where glue_across() went: the collapsed faces it crossed and the border sides it met, per piece.
struct Collapsed_crossings
{
  std::vector<std::pair<std::size_t, int> > faces;    // (piece, collapsed face whose sides run through its open cell)
  std::vector<std::size_t> cut;                       // pieces whose open cell a border side of a collapsed face cuts
};

// Unites piece x with the piece of face f in the cell that T (the chart of x's face to f's) maps x's cell to,
// reached across edge g.
inline Status glue_to(const Corner_mesh& cm, const Cell_pieces& pieces, std::size_t x, int f, const Grid_transform& T,
                      int g, Chart_union_find& uf, std::string& message)
{
  const Grid_point& c = pieces.cell[x];
  const long y = pieces.find(f, T.apply_to_cell(c));
  if(y < 0) {
    message = "internal error: the " + cell_name(c, pieces.face[x]) + " has no piece in face " + std::to_string(f) +
              " across edge " + vertex_pair_name(cm, g);
    return EXACTNESS_CHECK_FAILED;
  }
  if(!uf.unite(int(x), int(y), T)) {
    message = "the " + cell_name(c, pieces.face[x]) + " closes around the surface (its pieces are joined through a "
              "non-trivial transition, last across edge " + vertex_pair_name(cm, g) + "): it is not a disk, so the "
              "cells are no quads; the integer grid is too coarse for the surface (use a larger grid_scale)";
    return INVALID_INPUT;
  }
  return SUCCESS;
}

// The same where the face across g is collapsed: x is glued to the pieces beyond those sides of that face that run
// through the same open cell (on the line of g: they do iff their u and v ranges overlap the cell's), and so on
// through neighbouring collapsed faces, each crossed once.
inline Status glue_across(const Corner_mesh& cm, const std::vector<Grid_transform>& transition, const Cell_pieces& pieces,
                          const Collapsed_faces& collapsed, std::size_t x, int g, Chart_union_find& uf,
                          Collapsed_crossings& crossings, std::string& message)
{
  struct Step { int h; Grid_transform T; };           // into face(h) across h; T: the chart of x's face to face(h)'s
  std::vector<Step> todo(1, Step{cm.opp[g], transition[std::size_t(g)]});
  const std::size_t crossed_before = crossings.faces.size();
  while(!todo.empty()) {
    const Step step = todo.back();
    todo.pop_back();
    const int f = cm.face[step.h];
    if(!collapsed.is_collapsed[std::size_t(f)]) {
      const Status s = glue_to(cm, pieces, x, f, step.T, g, uf, message);
      if(s != SUCCESS) return s;
      continue;
    }
    const auto first = crossings.faces.begin() + std::ptrdiff_t(crossed_before);
    if(std::find(first, crossings.faces.end(), std::make_pair(x, f)) != crossings.faces.end()) continue;
    crossings.faces.emplace_back(x, f);
    const Grid_point c = step.T.apply_to_cell(pieces.cell[x]);
    for(int h : {cm.next[step.h], cm.prev[step.h]}) {  // the other two sides of f: from corner prev(h) to corner h
      if(!ranges_overlap_open_cell(corner_point(cm, cm.prev[h]), corner_point(cm, h), c)) continue;
      if(cm.is_border_halfedge(cm.opp[h])) crossings.cut.push_back(x);
      else todo.push_back(Step{cm.opp[h], compose(transition[std::size_t(h)], step.T)});
    }
  }
  return SUCCESS;
}

// Stage 1: glues the pieces into cells.
inline Status glue_pieces(const Corner_mesh& cm, const std::vector<Grid_transform>& transition, const Cell_pieces& pieces,
                          const Collapsed_faces& collapsed, Chart_union_find& uf, Collapsed_crossings& crossings,
                          std::string& message)
{
  for(const Cell_pieces::Glue& glue : pieces.glue) {
    const int g = glue.halfedge, f = cm.face[cm.opp[g]];
    const Status s = collapsed.is_collapsed[std::size_t(f)]
                         ? glue_across(cm, transition, pieces, collapsed, glue.piece, g, uf, crossings, message)
                         : glue_to(cm, pieces, glue.piece, f, transition[std::size_t(g)], g, uf, message);
    if(s != SUCCESS) return s;
  }
  return SUCCESS;
}

// `branch_vertex`: per vertex, 1 where the map winds around it more than once off the integer points (the cells
// holding its point are branched, see the header); empty: none
inline Status stitch_cells(const Corner_mesh& cm, const std::vector<int>& face_halfedge,
                           const std::vector<Grid_transform>& transition, const Cell_pieces& pieces,
                           const Collapsed_faces& collapsed, const std::vector<char>& branch_vertex, Quad_cells& out,
                           std::string& message)
{
  out = Quad_cells();
  Chart_union_find uf(int(pieces.size()));
  Collapsed_crossings crossings;
  const Status s = glue_pieces(cm, transition, pieces, collapsed, uf, crossings, message);
  if(s != SUCCESS) return s;

  // cells, numbered by their first piece (the representative); incomplete ones marked
  std::vector<int> cell_of(pieces.size(), -1), root_of(pieces.size(), -1);
  std::vector<Grid_transform> to_root(pieces.size());
  std::vector<int> roots;
  for(std::size_t x = 0; x < pieces.size(); ++x) {
    const int r = uf.find(int(x), to_root[x]);
    root_of[x] = r;
    if(cell_of[std::size_t(r)] < 0) { cell_of[std::size_t(r)] = int(roots.size()); roots.push_back(r); }
    cell_of[x] = cell_of[std::size_t(r)];
  }
  std::vector<char> complete(roots.size(), 1);
  auto drop = [&](std::size_t x) {
    if(!complete[std::size_t(cell_of[x])]) return;
    complete[std::size_t(cell_of[x])] = 0;
    ++out.incomplete;
    if(out.first_incomplete_face < 0) out.first_incomplete_face = pieces.face[x];
  };
  for(std::size_t x = 0; x < pieces.size(); ++x)
    if(pieces.cut[x]) drop(x);
  for(std::size_t x : crossings.cut) drop(x);
  // branched cells: a piece whose face has a branch vertex strictly inside the piece's open cell
  std::vector<int> branched_by(roots.size(), -1);
  if(!branch_vertex.empty())
    for(std::size_t x = 0; x < pieces.size(); ++x)
      for(int h = face_halfedge[std::size_t(pieces.face[x])], k = 0; k < 3; ++k, h = cm.next[h]) {
        const Grid_point& c = pieces.cell[x];
        if(branch_vertex[std::size_t(cm.target[h])] && double(c.u) < cm.u[h] && cm.u[h] < double(c.u + 1) &&
           double(c.v) < cm.v[h] && cm.v[h] < double(c.v + 1))
          branched_by[std::size_t(cell_of[x])] = cm.target[h];
      }
  std::vector<std::vector<int> > branched_corners(roots.size());

  // corners
  Integer_point_index index(cm.n_vertices);
  index.reserve(roots.size() + roots.size() / 8 + 16);   // about one point per cell on a closed surface
  add_collapsed_aliases(cm, face_halfedge, collapsed, transition, index);
  std::vector<int> corner(4 * roots.size(), -1);
  out.faces_first.assign(1, 0);
  for(int f = 0; f < cm.n_faces; ++f) {
    const std::size_t b = pieces.first[std::size_t(f)], e = pieces.first[std::size_t(f) + 1];
    if(b == e) continue;
    std::int64_t u0 = pieces.cell[b].u, u1 = u0, v0 = pieces.cell[b].v, v1 = v0;   // the corners of its pieces' cells
    for(std::size_t x = b; x < e; ++x) {
      u0 = (std::min)(u0, pieces.cell[x].u); u1 = (std::max)(u1, pieces.cell[x].u);
      v0 = (std::min)(v0, pieces.cell[x].v); v1 = (std::max)(v1, pieces.cell[x].v);
    }
    index.begin_face(f, u0, u1 + 1, v0, v1 + 1);
    for(std::size_t x = b; x < e; ++x) {
      const std::size_t cell = std::size_t(cell_of[x]);
      if(!complete[cell]) continue;
      const Grid_point& c = pieces.cell[x];
      const Grid_point& root_cell = pieces.cell[std::size_t(root_of[x])];
      if(to_root[x].apply_to_cell(c) != root_cell) {
        message = "internal error: the " + cell_name(c, f) + " is joined to a piece of another cell";
        return EXACTNESS_CHECK_FAILED;
      }
      for(int k = 0; k < 4; ++k) {
        const Corner_place place = pieces.corner[x][std::size_t(k)];
        if(place == OUTSIDE) continue;
        const Grid_point p{c.u + cell_corner_offset[k][0], c.v + cell_corner_offset[k][1]};
        const Grid_point q = to_root[x].apply(p);
        int i = 0;
        while(i < 3 && !(q.u - root_cell.u == cell_corner_offset[i][0] && q.v - root_cell.v == cell_corner_offset[i][1])) ++i;
        CGAL_assertion(q.u - root_cell.u == cell_corner_offset[i][0] && q.v - root_cell.v == cell_corner_offset[i][1]);
        const int id = index.id_in_face(p, [&] { return locate_integer_point(cm, face_halfedge[std::size_t(f)], p, place, transition); });
        if(branched_by[cell] >= 0) { branched_corners[cell].push_back(id); continue; }
        int& slot = corner[4 * cell + std::size_t(i)];
        if(slot >= 0 && slot != id) {
          message = "the " + cell_name(c, f) + " has two surface points at one corner (" + std::to_string(p.u) + ", " +
                    std::to_string(p.v) + "): it is not a disk; the integer grid is too coarse for the surface (use a "
                    "larger grid_scale)";
          return INVALID_INPUT;
        }
        slot = id;
      }
    }
  }
  // the faces per cell: pieces are ordered by face, so each cell's list comes out ascending; the collapsed faces
  // crossed are added and sorted in
  std::vector<std::size_t> count(roots.size() + 1, 0);
  for(std::size_t x = 0; x < pieces.size(); ++x) ++count[std::size_t(cell_of[x]) + 1];
  for(const std::pair<std::size_t, int>& c : crossings.faces) ++count[std::size_t(cell_of[c.first]) + 1];
  for(std::size_t k = 0; k < roots.size(); ++k) count[k + 1] += count[k];
  std::vector<int> faces_of_cell(count.back());       // the pieces' faces, grouped by cell
  std::vector<std::size_t> fill(count.begin(), count.end() - 1);
  for(std::size_t x = 0; x < pieces.size(); ++x) faces_of_cell[fill[std::size_t(cell_of[x])]++] = pieces.face[x];
  for(const std::pair<std::size_t, int>& c : crossings.faces) faces_of_cell[fill[std::size_t(cell_of[c.first])]++] = c.second;
  for(std::size_t cell = 0; cell < roots.size(); ++cell) {
    if(!complete[cell]) continue;
    const auto b = faces_of_cell.begin() + std::ptrdiff_t(count[cell]), e = faces_of_cell.begin() + std::ptrdiff_t(count[cell + 1]);
    if(!crossings.faces.empty() || branched_by[cell] >= 0) std::sort(b, e);
    if(branched_by[cell] >= 0) {
      Quad_cells::Branched br;
      br.corners.swap(branched_corners[cell]);
      std::sort(br.corners.begin(), br.corners.end());
      br.corners.erase(std::unique(br.corners.begin(), br.corners.end()), br.corners.end());
      br.faces.assign(b, std::unique(b, e));
      br.vertex = branched_by[cell];
      out.branched.push_back(std::move(br));
      continue;
    }
    std::array<int, 4> q;
    for(int i = 0; i < 4; ++i) {
      q[std::size_t(i)] = corner[4 * cell + std::size_t(i)];
      if(q[std::size_t(i)] < 0) {
        const std::size_t r = std::size_t(roots[cell]);
        message = "internal error: corner " + std::to_string(i) + " of the " + cell_name(pieces.cell[r], pieces.face[r]) +
                  " lies in no face";
        return EXACTNESS_CHECK_FAILED;
      }
    }
    out.quads.push_back(q);
    out.faces.insert(out.faces.end(), b, std::unique(b, e));
    out.faces_first.push_back(out.faces.size());
  }
  out.points = index.points();
  if(!collapsed.faces.empty()) name_outside_collapsed_faces(cm, transition, collapsed, out.points);
  return SUCCESS;
}

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_CELLS_H
