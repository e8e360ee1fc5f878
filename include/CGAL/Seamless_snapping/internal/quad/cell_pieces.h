// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_CELL_PIECES_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_CELL_PIECES_H

// The pieces of a fold-free integer-grid map: the intersections of the open UV triangle of a face,
// in its own chart (UVs in grid units), with the open unit cells (i, i+1) x (j, j+1) of that chart,
// those with positive area. Decided exactly, with no construction: the UVs are doubles, the cell
// corners integers, and every decision is a sign of the exact orientation predicate (CGAL's filtered
// predicate on doubles) of a grid point against the line of a side of the face, computed once per
// grid point of the face's bounding box and side:
// - a cell meets the open triangle iff no side has all four corners of the cell on or to its right
//   (separating axis theorem: two convex polygons have disjoint interiors iff a line through an edge
//   of one of them separates them; the cells tested are those of the bounding box, whose overlap with
//   the triangle's box is strict);
// - the open segment of a side runs through the open cell (where two pieces of neighbouring faces are
//   glued, or where the border cuts the cell) iff its u and v ranges overlap the cell's strictly and the
//   cell's corners lie strictly on both sides of its line (the separating axes of a segment and a
//   square are u, v and the segment's normal); a side on a grid line runs through no open cell;
// - a corner of the cell lies in the closed triangle iff it is on or to the left of all three sides;
//   on exactly one side's line: inside that side; on two: at their common corner of the face.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/quad/grid_transform.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Uv_point;

inline Uv_point corner_point(const Corner_mesh& cm, int h) { return Uv_point(cm.u[h], cm.v[h]); }

// Where a corner of a cell lies relative to the closed UV triangle of a face with corners c0, c1, c2
// (its first halfedge and the next two; side s runs from corner c_s to corner c_{s+1}):
enum Corner_place : signed char
{
  OUTSIDE = -1,
  AT_CORNER_0 = 0, AT_CORNER_1, AT_CORNER_2,     // the face's corner c_k
  ON_SIDE_0 = 3, ON_SIDE_1, ON_SIDE_2,           // inside side s
  INSIDE = 6
};

// The corners of a cell, counter-clockwise from its lower-left corner: offsets from it.
constexpr std::int64_t cell_corner_offset[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

// The pieces of all faces, face by face; within a face ordered by cell (row by row).
struct Cell_pieces
{
  struct Glue { std::size_t piece; int halfedge; };   // the side of halfedge runs through the piece's open cell

  std::vector<std::size_t> first;                   // per face f: its pieces are first[f] .. first[f + 1] - 1
  std::vector<Grid_point> cell;                     // per piece: the lower-left corner of its cell, chart of its face
  std::vector<int> face;                            // per piece
  std::vector<std::array<Corner_place, 4> > corner; // per piece: where the cell's corners lie (cell_corner_offset order)
  std::vector<char> cut;                            // per piece: a border side runs through its open cell
  std::vector<Glue> glue;                           // interior sides through open cells, once per edge (halfedge < opposite)

  std::size_t size() const { return cell.size(); }
  // the piece of face f in cell c, or -1
  long find(int f, const Grid_point& c) const
  {
    const auto b = cell.begin() + std::ptrdiff_t(first[std::size_t(f)]), e = cell.begin() + std::ptrdiff_t(first[std::size_t(f) + 1]);
    const auto it = std::lower_bound(b, e, c);
    return it != e && *it == c ? long(it - cell.begin()) : -1;
  }
};

// The UV bounding box of the triangle t: [u0, u1] x [v0, v1].
inline void uv_box(const Uv_point t[3], double& u0, double& u1, double& v0, double& v1)
{
  u0 = (std::min)({t[0].x(), t[1].x(), t[2].x()}); u1 = (std::max)({t[0].x(), t[1].x(), t[2].x()});
  v0 = (std::min)({t[0].y(), t[1].y(), t[2].y()}); v1 = (std::max)({t[0].y(), t[1].y(), t[2].y()});
}

// The cells of the bounding box of the triangle t that overlap it strictly: i in [i0, i1], j in [j0, j1].
inline void candidate_cells(const Uv_point t[3], std::int64_t& i0, std::int64_t& i1, std::int64_t& j0, std::int64_t& j1)
{
  double u0, u1, v0, v1;
  uv_box(t, u0, u1, v0, v1);
  i0 = std::int64_t(std::floor(u0)); i1 = std::int64_t(std::ceil(u1)) - 1;
  j0 = std::int64_t(std::floor(v0)); j1 = std::int64_t(std::ceil(v1)) - 1;
}

// The grid points of the bounding box of the triangle t (closed): i in [i0, i1], j in [j0, j1] (empty: i1 < i0 or j1 < j0).
inline void box_grid_points(const Uv_point t[3], std::int64_t& i0, std::int64_t& i1, std::int64_t& j0, std::int64_t& j1)
{
  double u0, u1, v0, v1;
  uv_box(t, u0, u1, v0, v1);
  i0 = std::int64_t(std::ceil(u0)); i1 = std::int64_t(std::floor(u1));
  j0 = std::int64_t(std::ceil(v0)); j1 = std::int64_t(std::floor(v1));
}

// The u and v ranges of the open segment pq overlap those of the open cell strictly (the segment runs through the
// open cell if, in addition, the cell has corners strictly on both sides of its line).
inline bool ranges_overlap_open_cell(const Uv_point& p, const Uv_point& q, const Grid_point& cell)
{
  return (std::max)(p.x(), q.x()) > double(cell.u) && (std::min)(p.x(), q.x()) < double(cell.u + 1) &&
         (std::max)(p.y(), q.y()) > double(cell.v) && (std::min)(p.y(), q.y()) < double(cell.v + 1);
}

// The sign of the orientation of (a, b, q) for many grid points q and one side (a, b), exactly: the
// determinant (b - a) x (q - a) in double with Shewchuk's first error bound for this formula (orient2d's
// errboundA, valid without underflow), the exact predicate where the bound does not decide.
class Side_orientation
{
public:
  Side_orientation(const Uv_point& a, const Uv_point& b) : a_(a), b_(b), dx_(b.x() - a.x()), dy_(b.y() - a.y()) {}
  signed char operator()(double qx, double qy) const
  {
    const double l = dx_ * (qy - a_.y()), r = dy_ * (qx - a_.x()), det = l - r;
    const double bound = 3.3306690738754716e-16 * (std::fabs(l) + std::fabs(r));   // (3 + 16 eps) eps, eps = 2^-53
    if(std::fabs(det) > bound && bound > 0x1p-900) return static_cast<signed char>((det > 0) - (det < 0));   // no branch on the sign
    return static_cast<signed char>(CGAL::orientation(a_, b_, Uv_point(qx, qy)));
  }
private:
  Uv_point a_, b_;
  double dx_, dy_;
};

// Where a grid point lies relative to the closed triangle, from its side masks (bit s of `left`: strictly left
// of side s; of `right`: strictly right): outside if right of a side; on no side's line: inside; on one: inside
// that side; on two (s and s+1): at the corner c_{s+1} between them.
inline Corner_place corner_place(unsigned left, unsigned right)
{
  if(right != 0) return OUTSIDE;
  switch(~left & 7u) {                            // the sides whose line holds the point
    case 0: return INSIDE;
    case 1: return ON_SIDE_0;
    case 2: return ON_SIDE_1;
    case 4: return ON_SIDE_2;
    case 3: return AT_CORNER_1;                   // sides 0 and 1 meet at c_1
    case 6: return AT_CORNER_2;
    case 5: return AT_CORNER_0;                   // sides 2 and 0 meet at c_0
    default: return AT_CORNER_2;                  // on all three lines: no such point of a positive triangle
  }
}

// The pieces of face f (first halfedge h0), appended to `out`; `mask` is scratch space; `collapsed`: per face, a
// collapsed face (collapsed_faces.h: no pieces of its own; every side through a cell glued towards it).
inline void add_face_pieces(const Corner_mesh& cm, int f, int h0, const std::vector<char>& collapsed, Cell_pieces& out,
                            std::vector<unsigned char>& mask)
{
  const int c[3] = {h0, cm.next[h0], cm.next[cm.next[h0]]};
  const Uv_point t[3] = {corner_point(cm, c[0]), corner_point(cm, c[1]), corner_point(cm, c[2])};
  std::int64_t i0, i1, j0, j1;
  candidate_cells(t, i0, i1, j0, j1);
  const std::size_t ni = std::size_t(i1 - i0 + 2), nj = std::size_t(j1 - j0 + 2), n = ni * nj;   // grid points
  // per grid point: bits 0-2 strictly left of side s, bits 3-5 strictly right of it
  mask.assign(n, 0);
  for(int s = 0; s < 3; ++s) {
    const Side_orientation side(t[s], t[(s + 1) % 3]);
    for(std::size_t b = 0; b < nj; ++b)
      for(std::size_t a = 0; a < ni; ++a) {
        const signed char o = side(double(i0 + std::int64_t(a)), double(j0 + std::int64_t(b)));
        mask[b * ni + a] |= static_cast<unsigned char>((unsigned(o > 0) << s) | (unsigned(o < 0) << (s + 3)));
      }
  }
  for(std::size_t b = 0; b + 1 < nj; ++b)
    for(std::size_t a = 0; a + 1 < ni; ++a) {
      std::size_t g[4];                           // the cell's corners in the grid, counter-clockwise
      for(int k = 0; k < 4; ++k) g[k] = (b + std::size_t(cell_corner_offset[k][1])) * ni + a + std::size_t(cell_corner_offset[k][0]);
      const unsigned any = unsigned(mask[g[0]] | mask[g[1]] | mask[g[2]] | mask[g[3]]);
      const unsigned left = any & 7u, right = any >> 3;   // sides with a corner strictly left / right of them
      if(left != 7u) continue;                    // all four corners on or right of a side: separated
      const std::size_t x = out.cell.size();
      const Grid_point cell{i0 + std::int64_t(a), j0 + std::int64_t(b)};
      out.cell.push_back(cell);
      out.face.push_back(f);
      std::array<Corner_place, 4> place;
      for(int k = 0; k < 4; ++k) place[std::size_t(k)] = corner_place(mask[g[k]] & 7u, unsigned(mask[g[k]]) >> 3);
      out.corner.push_back(place);
      char cut = 0;
      for(int s = 0; s < 3; ++s) {                // side s: from t[s] to t[s+1], the halfedge c[s+1]
        if(!(right & (1u << s)) || !ranges_overlap_open_cell(t[s], t[(s + 1) % 3], cell)) continue;
        const int h = c[(s + 1) % 3], o = cm.opp[h];
        if(cm.is_border_halfedge(o)) cut = 1;
        else if(h < o || collapsed[std::size_t(cm.face[o])]) out.glue.push_back(Cell_pieces::Glue{x, h});
      }
      out.cut.push_back(cut);
    }
}

inline Status out_of_memory(std::size_t candidates, Cell_pieces& out, std::string& message)
{
  out = Cell_pieces();
  message = "the faces' UV bounding boxes hold " + std::to_string(candidates) + " unit cells of the integer grid, more " +
            "than this machine's memory can hold (about 290 bytes per quad); use a smaller grid_scale, or a smaller " +
            "max_grid_cells to be told so before any memory is taken";
  return RANGE_EXCEEDED;
}

// Collects the pieces of every face but the collapsed ones. Preconditions: the map is fold-free (its zero-area
// faces collapsed), its UVs are in grid units with |u|, |v| < 2^30. RANGE_EXCEEDED (nothing collected) when the
// bounding boxes of the faces hold more than `max_candidates` cells in all (grid points for the collapsed faces).
inline Status collect_cell_pieces(const Corner_mesh& cm, const std::vector<int>& face_halfedge,
                                  const std::vector<char>& collapsed, std::size_t max_candidates, Cell_pieces& out,
                                  std::string& message)
{
  out = Cell_pieces();
  std::size_t candidates = 0;
  for(int f = 0; f < cm.n_faces; ++f) {
    const int h0 = face_halfedge[std::size_t(f)];
    const Uv_point t[3] = {corner_point(cm, h0), corner_point(cm, cm.next[h0]), corner_point(cm, cm.prev[h0])};
    std::int64_t i0, i1, j0, j1;
    std::size_t n;                                // at most 2^62 (|u|, |v| < 2^30)
    if(collapsed[std::size_t(f)]) {               // the grid points of the box, which add_collapsed_aliases() visits
      box_grid_points(t, i0, i1, j0, j1);
      n = std::size_t((std::max)(i1 - i0 + 1, std::int64_t(0))) * std::size_t((std::max)(j1 - j0 + 1, std::int64_t(0)));
    } else {
      candidate_cells(t, i0, i1, j0, j1);
      n = std::size_t(i1 - i0 + 1) * std::size_t(j1 - j0 + 1);
    }
    // (compared before the sum: with max_candidates near 2^64 the sum wrapped around to 0 and passed)
    if(n > max_candidates - candidates || (candidates += n) > max_candidates) {
      message = "the faces' UV bounding boxes hold more than " + std::to_string(max_candidates) + " unit cells of the " +
                "integer grid (max_grid_cells; reached at face " + std::to_string(f) + "): the quad mesh would be too " +
                "large; use a smaller grid_scale, or a larger max_grid_cells (about 290 bytes of memory per quad)";
      return RANGE_EXCEEDED;
    }
  }
  try {                                         // a max_grid_cells beyond the memory (e.g. 2^62 cells)
    out.first.reserve(std::size_t(cm.n_faces) + 1);
    out.cell.reserve(candidates); out.face.reserve(candidates); out.corner.reserve(candidates); out.cut.reserve(candidates);
    out.glue.reserve(candidates);
    std::vector<unsigned char> mask;
    for(int f = 0; f < cm.n_faces; ++f) {
      out.first.push_back(out.cell.size());
      if(!collapsed[std::size_t(f)]) add_face_pieces(cm, f, face_halfedge[std::size_t(f)], collapsed, out, mask);
    }
    out.first.push_back(out.cell.size());
  } catch(const std::bad_alloc&) {
    return out_of_memory(candidates, out, message);
  } catch(const std::length_error&) {
    return out_of_memory(candidates, out, message);
  }
  return SUCCESS;
}

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_CELL_PIECES_H
