// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_EXTRACT_QUAD_MESH_IMPL_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_EXTRACT_QUAD_MESH_IMPL_H

// extract_quad_mesh() between the caller's types and the index-based extraction (quad_extraction.h):
// reads the triangle mesh into a corner mesh, runs the extraction, and only when it succeeded (the quad
// mesh built and verified) adds the same vertices and faces, in the same order, to the caller's mesh,
// with the positions and the origin maps.

#include <CGAL/Seamless_snapping/Quad_mesh_report.h>
#include <CGAL/Seamless_snapping/internal/quad/quad_extraction.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/integer_grid_constraints.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <chrono>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

template <class TriangleMesh> struct Quad_vertex_origin;

namespace internal {
namespace quad {

// The verified quad mesh x.mesh added to qm: its vertices and faces, in order, into `qv` and `qf`.
template <class QuadMesh>
void add_vertices_and_faces(const Quad_extraction& x, QuadMesh& qm,
                            std::vector<typename boost::graph_traits<QuadMesh>::vertex_descriptor>& qv,
                            std::vector<typename boost::graph_traits<QuadMesh>::face_descriptor>& qf)
{
  typedef boost::graph_traits<QuadMesh> QT;
  for(std::size_t i = 0; i < x.cells.points.size(); ++i) qv.push_back(add_vertex(qm));
  for(const std::array<int, 4>& c : x.cells.quads) {
    const std::array<typename QT::vertex_descriptor, 4> corners = {{qv[std::size_t(c[0])], qv[std::size_t(c[1])],
                                                                    qv[std::size_t(c[2])], qv[std::size_t(c[3])]}};
    qf.push_back(CGAL::Euler::add_face(corners, qm));
    CGAL_assertion(qf.back() != QT::null_face());     // the faces of the verified mesh, in the same order
  }
}

// The same for a mesh of the verified mesh's own type: appended whole (Surface_mesh::join(), which keeps the
// caller's property maps and numbers the new elements after the old ones, removed ones included).
inline void add_vertices_and_faces(const Quad_extraction& x, Quad_surface& qm, std::vector<Quad_surface::Vertex_index>& qv,
                                   std::vector<Quad_surface::Face_index>& qf)
{
  const Quad_surface::size_type nv = qm.num_vertices(), nf = qm.num_faces();
  qm.join(x.mesh);
  for(std::size_t i = 0; i < x.mesh.num_vertices(); ++i) qv.push_back(Quad_surface::Vertex_index(nv + Quad_surface::size_type(i)));
  for(std::size_t q = 0; q < x.mesh.num_faces(); ++q) qf.push_back(Quad_surface::Face_index(nf + Quad_surface::size_type(q)));
}

// `covered`: fill face_origin_map (false when the caller gave none)
template <class TriangleMesh, class QuadMesh, class VPM_out, class Origin_map, class Face_origin_map>
void add_quad_mesh(const TriangleMesh& tm, const Corner_mesh_descriptors<TriangleMesh>& desc, const Quad_extraction& x,
                   QuadMesh& qm, VPM_out vpm_out, Origin_map origin_map, Face_origin_map face_origin_map, bool covered_faces)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef boost::graph_traits<QuadMesh> QT;
  typedef typename boost::property_traits<VPM_out>::value_type Out_point;
  typedef Quad_vertex_origin<TriangleMesh> Origin;
  std::vector<typename GT::face_descriptor> face_of(std::size_t(x.cm.n_faces));
  for(std::size_t h = 0; h < desc.halfedges.size(); ++h)
    if(!x.cm.is_border_halfedge(int(h))) face_of[std::size_t(x.cm.face[h])] = face(desc.halfedges[h], tm);
  std::vector<typename QT::vertex_descriptor> qv;
  std::vector<typename QT::face_descriptor> qf;
  add_vertices_and_faces(x, qm, qv, qf);
  for(std::size_t i = 0; i < x.cells.points.size(); ++i) {
    const Integer_point& p = x.cells.points[i];
    const typename QT::vertex_descriptor v = qv[i];
    put(vpm_out, v, Out_point(x.positions[i][0], x.positions[i][1], x.positions[i][2]));
    Origin o;
    o.location = p.kind == AT_VERTEX ? Origin::VERTEX : p.kind == ON_EDGE ? Origin::EDGE : Origin::FACE;
    o.halfedge = desc.halfedges[std::size_t(p.halfedge)];
    o.face = face(o.halfedge, tm);
    o.u = p.uv.u;
    o.v = p.uv.v;
    put(origin_map, v, o);
  }
  for(std::size_t q = 0; q < x.cells.quads.size(); ++q) {
    const typename QT::face_descriptor f = qf[q];
    if(!covered_faces) continue;
    std::vector<typename GT::face_descriptor> covered;
    covered.reserve(std::size_t(x.cells.faces_end(q) - x.cells.faces_begin(q)));
    for(auto g = x.cells.faces_begin(q); g != x.cells.faces_end(q); ++g) covered.push_back(face_of[std::size_t(*g)]);
    put(face_origin_map, f, covered);
  }
}

template <class TriangleMesh, class HalfedgeUVMap, class VPM_in, class QuadMesh, class VPM_out, class Origin_map,
          class Face_origin_map>
Quad_mesh_report extract_quad_mesh_impl(const TriangleMesh& tm, HalfedgeUVMap uv, VPM_in vpm_in, double grid_scale,
                                        const Quad_options& opt, QuadMesh& qm, VPM_out vpm_out, Origin_map origin_map,
                                        Face_origin_map face_origin_map, bool covered_faces)
{
  const auto t0 = std::chrono::steady_clock::now();
  Quad_mesh_report report;
  Quad_extraction x;
  Corner_mesh_descriptors<TriangleMesh> desc;
  report.status = build_corner_mesh(tm, uv, x.cm, desc, report.message);
  int scale_exponent = 0;
  if(report.status == SUCCESS && !grid_scale_exponent(grid_scale, scale_exponent)) {
    report.status = INVALID_INPUT;
    report.message = "the grid scale " + format_double(grid_scale, 17) + " is not a power of two";
  }
  if(report.status == SUCCESS) {
    std::vector<typename boost::property_traits<VPM_in>::value_type> points;
    for(const auto& v : desc.vertices) points.push_back(get(vpm_in, v));
    report.status = extract_quads(scale_exponent, opt, points, x, report);
  }
  if(report.status != SUCCESS) { report.total_ms = ms_since(t0); return report; }

  add_quad_mesh(tm, desc, x, qm, vpm_out, origin_map, face_origin_map, covered_faces);
  report.message = std::to_string(report.quads) + " quads, " + std::to_string(report.quad_vertices) + " vertices (" +
                   std::to_string(report.irregular_vertices) + " irregular, " + std::to_string(report.cones) +
                   " cones in the map), Euler characteristic " + std::to_string(report.euler_characteristic) + ", " +
                   std::to_string(report.boundary_loops) + " boundary loops; " +
                   (report.incomplete_cells == 0 ? std::string("the quads cover the map (as many as its UV area") +
                                                   (report.split_cones.empty() && report.filled_branch_points.empty()
                                                        ? ")" : " less 3 per split cone, plus m - 1 per filled branch "
                                                                "point, less 1 per cone cell filled with one)")
                                                 : std::to_string(report.incomplete_cells) + " cells cut by the border "
                                                   "(not on integer isolines) were dropped") +
                   (report.split_cones.empty() ? std::string() : "; " + std::to_string(report.split_cones.size()) +
                    " cone(s) of valence 1 (90 degrees) split: the 2 x 2 cells at each made one quad, three of whose "
                    "corners have valence 3 for it") +
                   (report.filled_branch_points.empty() ? std::string() : "; " +
                    std::to_string(report.filled_branch_points.size()) + " branch point(s) off the integer points (the "
                    "map winds m > 1 times around a vertex inside a cell) filled: the 4m-gon of the cell's m sheets "
                    "made 2m - 1 quads (m - 1 more than its UV area each)") +
                   (report.absorbed_cones.empty() ? std::string() : "; " + std::to_string(report.absorbed_cones.size()) +
                    " cone(s) of valence 1 next to a branched cell filled with it (one quad fewer each)");
  report.total_ms = ms_since(t0);
  return report;
}

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_EXTRACT_QUAD_MESH_IMPL_H
