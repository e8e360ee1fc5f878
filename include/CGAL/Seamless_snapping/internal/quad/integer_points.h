// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_INTEGER_POINTS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_INTEGER_POINTS_H

// The integer points of an integer-grid map, one per point of the surface. An integer point p of the
// closed UV triangle of a face (in its chart, grid units), located exactly (cell_pieces.h), is named
// canonically, so that the same surface point seen from different faces and charts gets the same name:
//   AT_VERTEX  p is the UV of a corner of the face: the mesh vertex;
//   ON_EDGE    p lies inside a side: the edge and p in the chart of the edge's canonical face, the face of
//              its edge_halfedge (the other one on the border), reached through the edge's transition;
//   IN_FACE    otherwise: the face and p in its chart.
// Integer_point_index numbers the distinct names in the order they are first seen; names that denote one
// point of a collapsed face (collapsed_faces.h) are aliases of one of them.

#include <CGAL/Seamless_snapping/internal/quad/cell_pieces.h>
#include <CGAL/Seamless_snapping/internal/quad/grid_transform.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

enum Integer_point_kind { AT_VERTEX = 0, ON_EDGE = 1, IN_FACE = 2 };

struct Integer_point
{
  Integer_point_kind kind = IN_FACE;
  int element = -1;     // the vertex, edge or face (Corner_mesh numbering)
  int halfedge = -1;    // a halfedge of the face whose chart holds `uv`: AT_VERTEX a corner of the vertex (its
                        // target), ON_EDGE the side of the canonical face, IN_FACE the face's first halfedge
  Grid_point uv;        // in the chart of face(halfedge), grid units
};

// names the integer point p of the closed UV triangle of the face of h0 (its first halfedge), at
// `place` in it (cell_pieces.h)
inline Integer_point locate_integer_point(const Corner_mesh& cm, int h0, const Grid_point& p, Corner_place place,
                                          const std::vector<Grid_transform>& transition)
{
  const int c[3] = {h0, cm.next[h0], cm.next[cm.next[h0]]};
  Integer_point r;
  r.uv = p;
  if(place <= AT_CORNER_2) {
    r.kind = AT_VERTEX; r.halfedge = c[place]; r.element = cm.target[r.halfedge];
  } else if(place <= ON_SIDE_2) {                  // side s runs from corner c_s to c_{s+1}: the halfedge c_{s+1}
    const int g = c[(place - ON_SIDE_0 + 1) % 3];
    r.kind = ON_EDGE;
    r.element = cm.edge[g];
    const int g0 = cm.edge_halfedge[std::size_t(r.element)];
    r.halfedge = cm.is_border_halfedge(g0) ? cm.opp[g0] : g0;
    if(r.halfedge != g) r.uv = transition[std::size_t(g)].apply(p);
  } else {
    r.kind = IN_FACE; r.element = cm.face[h0]; r.halfedge = h0;
  }
  return r;
}

// Numbers the names: a mesh vertex by an array over the vertices, a point in a face by an array over the grid
// points of that face's bounding box (its lookups come together: the pieces are ordered by face, see
// stitch_cells()), a point on an edge by a hash table. The same array remembers, for the face begun last, the
// number of each of its points (id_in_face()).
class Integer_point_index
{
public:
  explicit Integer_point_index(int n_vertices) : vertex_id_(std::size_t(n_vertices), -1) {}
  const std::vector<Integer_point>& points() const { return points_; }
  void reserve(std::size_t n) { ids_.reserve(n / 4); points_.reserve(n); }

  // the points in face f are looked up next; their uv within [u0, u1] x [v0, v1]
  void begin_face(int f, std::int64_t u0, std::int64_t u1, std::int64_t v0, std::int64_t v1)
  {
    face_ = f; u0_ = u0; v0_ = v0; width_ = std::size_t(u1 - u0 + 1);
    face_id_.assign(width_ * std::size_t(v1 - v0 + 1), -1);
  }

  // the number of the integer point p of the face begun last (within its box), named by locate() the first time p is
  // asked for in that face: a point is named once per face, not once per cell around it
  template <class Locate>
  int id_in_face(const Grid_point& p, Locate locate)
  {
    const std::size_t i = std::size_t(p.v - v0_) * width_ + std::size_t(p.u - u0_);
    if(face_id_[i] < 0) { const int k = id(locate()); face_id_[i] = k; }
    return face_id_[i];
  }

  // `name` (at a vertex or on an edge) is the point `same` (at a vertex or on an edge, not itself an alias)
  void alias(const Integer_point& name, const Integer_point& same) { aliases_[alias_key(name)] = same; }

  // the number of the point (a new one if its name was not seen yet)
  int id(const Integer_point& name)
  {
    const Integer_point* aliased = nullptr;
    if(!aliases_.empty() && name.kind != IN_FACE) {
      const auto it = aliases_.find(alias_key(name));
      if(it != aliases_.end()) aliased = &it->second;
    }
    const Integer_point& p = aliased ? *aliased : name;
    int* slot;
    if(p.kind == AT_VERTEX) slot = &vertex_id_[std::size_t(p.element)];
    else if(p.kind == IN_FACE) {
      CGAL_precondition(p.element == face_);
      slot = &face_id_[std::size_t(p.uv.v - v0_) * width_ + std::size_t(p.uv.u - u0_)];
    } else {
      const Key k{p.element, p.uv.u, p.uv.v};
      slot = &ids_.try_emplace(k, -1).first->second;     // no node allocated for a name seen before
    }
    if(*slot < 0) { *slot = int(points_.size()); points_.push_back(p); }
    return *slot;
  }

private:
  struct Key                                     // a point on an edge
  {
    int element;
    std::int64_t u, v;
    bool operator==(const Key& o) const { return element == o.element && u == o.u && v == o.v; }
  };
  struct Key_hash
  {
    std::size_t operator()(const Key& k) const
    {
      std::uint64_t h = std::uint64_t(k.element) * 0x9E3779B97F4A7C15ull;
      h ^= std::uint64_t(k.u) + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
      h ^= std::uint64_t(k.v) + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
      return std::size_t(h);
    }
  };
  // a point on an edge by its name, a vertex by -1 - its index
  static Key alias_key(const Integer_point& p)
  {
    return p.kind == AT_VERTEX ? Key{-1 - p.element, 0, 0} : Key{p.element, p.uv.u, p.uv.v};
  }
  std::unordered_map<Key, int, Key_hash> ids_;
  std::unordered_map<Key, Integer_point, Key_hash> aliases_;
  std::vector<int> vertex_id_, face_id_;
  int face_ = -1;
  std::int64_t u0_ = 0, v0_ = 0;
  std::size_t width_ = 0;
  std::vector<Integer_point> points_;
};

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_INTEGER_POINTS_H
