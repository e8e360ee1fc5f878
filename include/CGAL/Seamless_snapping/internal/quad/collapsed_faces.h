// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_COLLAPSED_FACES_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_COLLAPSED_FACES_H

// Zero-area UV triangles with three distinct corners (Fold_overs::collinear) in a map without fold-overs,
// e.g. a triangle whose three corners are cones that the integer-grid constraints put onto collinear
// integer points (the snap report proves such faces forced). The middle corner lies inside the segment
// of the other two, the long side. The face is the limit of a thin positively oriented triangle: its
// neighbours are positively oriented, so the face across the long side lies on one side of that line and
// the faces across the two short sides on the other (each keeps its third corner to the left of its own
// side, and the short sides run against the long one). Collapsed onto its long side, the face is a seam
// with the long side's neighbour on one side and the short sides' neighbours on the other, and the map is
// locally injective there. The quad extraction follows that:
// - the face has no cell pieces of its own; a piece whose side on the face runs through its open cell is
//   glued to the pieces across those sides of the face that run through the same open cell, through
//   neighbouring collapsed faces too (quad_cells.h: glue_across());
// - the integer points of the long side have several names (a point of the long side and of a short side,
//   or of the long side and the middle vertex): aliases of one point (add_collapsed_aliases());
// - its middle corner turns by 180 degrees in the quad valences (surface/quad_valences.h).
// The quad mesh is then verified as for any map (quad_mesh_checks.h).

#include <CGAL/Seamless_snapping/internal/quad/cell_pieces.h>
#include <CGAL/Seamless_snapping/internal/quad/grid_transform.h>
#include <CGAL/Seamless_snapping/internal/quad/integer_points.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

struct Collapsed_faces
{
  std::vector<int> faces;              // the collapsed faces, ascending
  std::vector<char> is_collapsed;      // per face

  Collapsed_faces(int n_faces, const std::vector<int>& collinear)
    : faces(collinear), is_collapsed(std::size_t(n_faces), 0)
  {
    for(int f : faces) is_collapsed[std::size_t(f)] = 1;
  }
};

// Names every integer point of the long side of each collapsed face (UVs in grid units) by one name: a mesh vertex
// where the point is one (the smallest), else its point on the edge of smallest index that is a side of a face not
// collapsed (if any); every other name of the point becomes an alias of it in `index`. Points shared by neighbouring
// collapsed faces are one point for all of them. Visits the grid points of each collapsed face's UV bounding box
// (counted in collect_cell_pieces()'s bound).
inline void add_collapsed_aliases(const Corner_mesh& cm, const std::vector<int>& face_halfedge,
                                  const Collapsed_faces& collapsed, const std::vector<Grid_transform>& transition,
                                  Integer_point_index& index)
{
  typedef std::tuple<int, int, std::int64_t, std::int64_t> Name_key;          // kind, element, u, v (edges only)
  std::map<Name_key, int> number;
  std::vector<Integer_point> names;
  std::vector<int> parent;
  auto find = [&](int x) { while(parent[std::size_t(x)] != x) x = parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])]; return x; };
  auto add = [&](const Integer_point& p) {
    const Name_key k(int(p.kind), p.element, p.kind == AT_VERTEX ? 0 : p.uv.u, p.kind == AT_VERTEX ? 0 : p.uv.v);
    const auto it = number.emplace(k, int(names.size()));
    if(it.second) { names.push_back(p); parent.push_back(int(parent.size())); }
    return it.first->second;
  };
  for(int f : collapsed.faces) {
    const int h0 = face_halfedge[std::size_t(f)];
    const int c[3] = {h0, cm.next[h0], cm.next[cm.next[h0]]};
    const Uv_point t[3] = {corner_point(cm, c[0]), corner_point(cm, c[1]), corner_point(cm, c[2])};
    // the integer points of the closed long side: of its bounding box, those on its line
    std::int64_t i0, i1, j0, j1;
    box_grid_points(t, i0, i1, j0, j1);
    const Uv_point& a = (std::min)({t[0], t[1], t[2]});   // lexicographic: the ends of the long side
    const Uv_point& b = (std::max)({t[0], t[1], t[2]});
    for(std::int64_t j = j0; j <= j1; ++j)
      for(std::int64_t i = i0; i <= i1; ++i) {
        const Uv_point q{double(i), double(j)};
        if(CGAL::orientation(a, b, q) != CGAL::COLLINEAR) continue;
        int first = -1;
        for(int s = 0; s < 3; ++s) {               // side s: from t[s] to t[s+1]; its closed segment
          const Uv_point& p0 = t[s];
          const Uv_point& p1 = t[(s + 1) % 3];
          if(q < (std::min)(p0, p1) || (std::max)(p0, p1) < q) continue;
          const Corner_place place = q == p0 ? Corner_place(AT_CORNER_0 + s) : q == p1 ? Corner_place(AT_CORNER_0 + (s + 1) % 3)
                                             : Corner_place(ON_SIDE_0 + s);
          const int x = find(add(locate_integer_point(cm, h0, Grid_point{i, j}, place, transition)));
          if(first < 0) first = x;
          else if(x != first) parent[std::size_t((std::max)(x, first))] = (std::min)(x, first);
          first = (std::min)(x, first);
        }
      }
  }
  // per group the smallest name by (kind, edge with a collapsed face on both sides, element): a vertex before a
  // point on an edge, an edge between two collapsed faces last
  std::vector<int> best(names.size(), -1);
  auto rank = [&](int x) {
    const Integer_point& p = names[std::size_t(x)];
    const int o = cm.opp[p.halfedge];
    const bool inside = p.kind == ON_EDGE && collapsed.is_collapsed[std::size_t(cm.face[p.halfedge])] &&
                        (cm.is_border_halfedge(o) || collapsed.is_collapsed[std::size_t(cm.face[o])]);
    return std::make_tuple(int(p.kind), inside, p.element);
  };
  auto before = [&](int x, int y) { return rank(x) < rank(y); };
  for(int x = 0; x < int(names.size()); ++x) {
    int& b = best[std::size_t(find(x))];
    if(b < 0 || before(x, b)) b = x;
  }
  for(int x = 0; x < int(names.size()); ++x) {
    const int b = best[std::size_t(find(x))];
    if(b != x) index.alias(names[std::size_t(x)], names[std::size_t(b)]);
  }
}

// The integer points named in the chart of a collapsed face (a vertex by its corner there, a point on an edge in the
// chart of the collapsed face of the edge) named in the chart of a face that is not collapsed: the quad mesh's
// origins (Quad_vertex_origin) then have barycentric coordinates. Points on edges between two collapsed faces stay.
inline void name_outside_collapsed_faces(const Corner_mesh& cm, const std::vector<Grid_transform>& transition,
                                         const Collapsed_faces& collapsed, std::vector<Integer_point>& points)
{
  auto outside = [&](int h) { return !cm.is_border_halfedge(h) && !collapsed.is_collapsed[std::size_t(cm.face[h])]; };
  for(Integer_point& p : points) {
    if(p.kind == IN_FACE || outside(p.halfedge)) continue;
    if(p.kind == ON_EDGE) {
      const int o = cm.opp[p.halfedge];
      if(!outside(o)) continue;
      p.uv = transition[std::size_t(p.halfedge)].apply(p.uv);
      p.halfedge = o;
      continue;
    }
    int h = p.halfedge;                            // the corners around the vertex, until one outside
    do h = cm.opp[cm.next[h]]; while(h != p.halfedge && !outside(h) && !cm.is_border_halfedge(h));
    if(!outside(h)) {                              // the other way round from the border
      h = p.halfedge;
      do h = cm.prev[cm.opp[h]]; while(h != p.halfedge && !outside(h) && !cm.is_border_halfedge(h));
    }
    if(!outside(h)) continue;
    p.halfedge = h;
    p.uv = Grid_point{std::int64_t(cm.u[h]), std::int64_t(cm.v[h])};
  }
}

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_COLLAPSED_FACES_H
