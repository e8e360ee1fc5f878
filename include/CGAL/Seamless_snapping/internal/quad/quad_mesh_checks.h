// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_MESH_CHECKS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_MESH_CHECKS_H

// The quad mesh as a polygon mesh, measured and checked against the map it comes from:
// - analyze_quad_soup(): why the cells do not form a polygon mesh (a cell with a corner twice, an edge of
//   more than two cells or twice in one direction), for the refusal's message;
// - measure_quad_mesh(): the counts of Quad_mesh_report (edges, border, boundary loops, non-manifold
//   vertices, Euler characteristic, valences);
// - verify_quad_guarantees(): the guarantees of extract_quad_mesh(), each compared with what the map
//   says, exactly: all quads, manifold, closed if the map is closed; if no cell was dropped, as many quads
//   as the map's exact UV area and the map's Euler characteristic; every quad vertex of the valence the
//   map gives it (quad_valences(): a mesh vertex its integer-direction count, a point of an edge or of a
//   face 4, a point of a border edge 3), so that the irregular vertices are exactly the cones. The repairs
//   (Cell_repairs) change that where they act: a cone of valence 1 split (valence_one_cones.h) is no quad vertex, its
//   2 x 2 cells one quad (3 quads fewer than the UV area), three of their corners with one edge fewer; a branch point
//   filled (branched_cells.h) is no quad vertex, its cell of area m 2m - 1 quads, the rungs' ends with one edge more;
//   a cone of valence 1 whose cell a fill took in is no quad vertex either, its cell no quad (one quad fewer), its
//   corners a and b with two edges and one fewer.

#include <CGAL/Seamless_snapping/Quad_mesh_report.h>
#include <CGAL/Seamless_snapping/internal/quad/quad_cells.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Quad_surface;

// What the map says about its quad mesh (from the checks of the input).
struct Map_facts
{
  int euler_characteristic = 0;
  std::size_t boundary_loops = 0;
  CGAL::Mpzf twice_area = 0;         // twice the UV area in grid units, exact
  std::vector<int> valence;          // per vertex: quad_valences()
  std::vector<char> on_border;       // per vertex: quad_valences()
  std::size_t cones = 0;             // vertices inside the quad mesh (not on_border) of valence other than 4
};

inline void analyze_quad_soup(const std::vector<std::array<int, 4> >& quads, Quad_mesh_report& r, std::string& first)
{
  std::map<std::pair<int, int>, std::array<int, 2> > uses;   // undirected edge -> uses in each direction
  for(std::size_t q = 0; q < quads.size(); ++q) {
    std::array<int, 4> s = quads[q];
    std::sort(s.begin(), s.end());
    if(std::adjacent_find(s.begin(), s.end()) != s.end()) {
      if(r.repeated_vertex_quads++ == 0 && first.empty()) first = "quad " + std::to_string(q) + " has a corner twice";
      continue;
    }
    for(int i = 0; i < 4; ++i) {
      const int a = quads[q][std::size_t(i)], b = quads[q][std::size_t((i + 1) % 4)];
      ++uses[std::make_pair((std::min)(a, b), (std::max)(a, b))][a < b ? 0 : 1];
    }
  }
  for(const auto& e : uses)
    if(e.second[0] > 1 || e.second[1] > 1) {
      if(r.non_manifold_edges++ == 0 && first.empty())
        first = "the edge of quad vertices " + std::to_string(e.first.first) + " and " + std::to_string(e.first.second) +
                " is a side of " + std::to_string(e.second[0] + e.second[1]) + " cells";
    }
}

inline void measure_quad_mesh(const Quad_surface& m, Quad_mesh_report& r)
{
  r.quads = m.number_of_faces();
  r.quad_vertices = m.number_of_vertices();
  r.quad_edges = m.number_of_edges();
  r.euler_characteristic = int(r.quad_vertices) - int(r.quad_edges) + int(r.quads);
  r.border_edges = 0;
  for(Quad_surface::Edge_index e : m.edges()) r.border_edges += m.is_border(e) ? 1 : 0;
  std::vector<char> walked(m.number_of_halfedges(), 0);
  r.boundary_loops = 0;
  for(Quad_surface::Halfedge_index h : m.halfedges()) {
    if(!m.is_border(h) || walked[std::size_t(h)]) continue;
    ++r.boundary_loops;
    for(Quad_surface::Halfedge_index g = h; !walked[std::size_t(g)]; g = m.next(g)) walked[std::size_t(g)] = 1;
  }
  std::vector<Quad_surface::Halfedge_index> umbrellas;          // one per umbrella of each non-manifold vertex
  CGAL::Polygon_mesh_processing::non_manifold_vertices(m, std::back_inserter(umbrellas));
  std::vector<Quad_surface::Vertex_index> pinched;
  for(Quad_surface::Halfedge_index h : umbrellas) pinched.push_back(m.target(h));
  std::sort(pinched.begin(), pinched.end());
  r.non_manifold_vertices = std::size_t(std::unique(pinched.begin(), pinched.end()) - pinched.begin());
  r.irregular_vertices = 0;
  r.valence_histogram.clear();
  for(Quad_surface::Vertex_index v : m.vertices()) {
    const std::size_t d = m.degree(v);
    if(r.valence_histogram.size() <= d) r.valence_histogram.resize(d + 1, 0);
    ++r.valence_histogram[d];
    if(!m.is_border(v) && d != 4) ++r.irregular_vertices;
  }
}

// Precondition: the vertices of m are cells.points in order, and r holds measure_quad_mesh(m).
inline bool verify_quad_guarantees(const Quad_surface& m, const Quad_cells& cells, const Map_facts& map,
                                   const Cell_repairs& repairs, const Quad_mesh_report& r, std::string& message)
{
  auto fail = [&](const std::string& what) { message = "internal error: the quad mesh " + what; return false; };
  for(Quad_surface::Face_index f : m.faces())
    if(m.degree(f) != 4) return fail("has a face of " + std::to_string(m.degree(f)) + " sides");
  if(r.non_manifold_vertices > 0) return fail("has " + std::to_string(r.non_manifold_vertices) + " non-manifold vertices");
  if(map.boundary_loops == 0 && r.border_edges > 0)
    return fail("of a closed map has " + std::to_string(r.border_edges) + " border edges");
  const bool covers = cells.incomplete == 0;
  const std::size_t split = repairs.split_cones.size(), filled = repairs.filled_vertices.size(),
                    absorbed = repairs.absorbed_cones.size();
  if(covers && CGAL::Mpzf(double(2 * (r.quads + 3 * split + absorbed - repairs.extra_quads))) != map.twice_area)
    return fail("has " + std::to_string(r.quads) + " quads" + (split + filled > 0 ? " (" + std::to_string(split) +
                " cones of valence 1 split, 3 cells fewer each; " + std::to_string(repairs.extra_quads) + " quads more "
                "in branched cells, " + std::to_string(absorbed) + " cone cells taken into them)" : std::string()) +
                ", but the UV area of the map is " +
                std::to_string(CGAL::to_double(map.twice_area) / 2) + " grid units");
  if(covers && r.euler_characteristic != map.euler_characteristic)
    return fail("has the Euler characteristic " + std::to_string(r.euler_characteristic) + ", the map " +
                std::to_string(map.euler_characteristic));
  std::size_t irregular = 0, cones_met = 0;
  for(Quad_surface::Vertex_index v : m.vertices()) {
    const Integer_point& p = cells.points[std::size_t(v)];
    const bool border = m.is_border(v);
    if(border && !covers) continue;                  // next to dropped cells: fewer edges
    const int expected = (p.kind == AT_VERTEX ? map.valence[std::size_t(p.element)] : (border ? 3 : 4)) +
                         repairs.valence_change[std::size_t(v)];
    if(int(m.degree(v)) != expected)
      return fail("has a vertex of valence " + std::to_string(m.degree(v)) + " where the map has " +
                  std::to_string(expected) + " integer directions (" +
                  (p.kind == AT_VERTEX ? "mesh vertex " : p.kind == ON_EDGE ? "on edge " : "in face ") +
                  std::to_string(p.element) + ")");
    irregular += !border && expected != 4 ? 1 : 0;
    cones_met += !border && p.kind == AT_VERTEX && map.valence[std::size_t(p.element)] != 4 ? 1 : 0;
  }
  if(covers && (cones_met + split + absorbed + filled != map.cones || r.irregular_vertices != irregular))
    return fail("has " + std::to_string(r.irregular_vertices) + " irregular vertices for the " + std::to_string(map.cones) +
                " cones of the map" + (split + filled > 0 ? " (" + std::to_string(split) + " of them of valence 1, split, " +
                std::to_string(filled) + " branch points filled, " + std::to_string(absorbed) + " cone cells filled with "
                "them)" : std::string()));
  return true;
}

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_QUAD_MESH_CHECKS_H
