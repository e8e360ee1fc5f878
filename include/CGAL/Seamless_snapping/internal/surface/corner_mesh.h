// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_CORNER_MESH_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_CORNER_MESH_H

// An index-based copy of the halfedge structure of a triangle mesh together with its corner UVs.
//
// Everything after the extraction works on this copy, so that the algorithmic code is written once
// (not once per `FaceGraph` model) and is independent of hash orders or descriptor types.
//
// Indices: halfedges, vertices, edges and faces are numbered 0, 1, ... in the order in which
// `halfedges(tm)`, `vertices(tm)`, `edges(tm)` and `faces(tm)` enumerate them.
// Corner convention (as in the public API): for a non-border halfedge h, (u[h], v[h]) is the UV of
// the corner (target(h), face(h)). Border halfedges have face -1 and no UV.

#include <CGAL/Seamless_snapping/Status.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// x 2^e, bit for bit std::ldexp(x, e) (std::ldexp is a call through libm's error handling, about 60
// instructions, and the corner angles and the scale normalization make millions of them): a product
// with the power of two when that is a normal double, where the product is exact or rounded once like
// std::ldexp (a subnormal result); std::ldexp itself otherwise.
inline double scale_by_power_of_two(double x, int e)
{
  if(e < -1022 || e > 1023) return std::ldexp(x, e);
  const std::uint64_t bits = std::uint64_t(e + 1023) << 52;
  double p;
  std::memcpy(&p, &bits, sizeof p);
  return x * p;
}

// x as text with `precision` significant digits (17: it reads back to the same double)
inline std::string format_double(double x, int precision = 6)
{
  std::ostringstream s; s.precision(precision); s << x; return s.str();
}

// the exponent e of std::frexp(x, &e) (x = f 2^e, 1/2 <= |f| < 1; 0 for 0), read from the bits of a normal x
inline int binary_exponent(double x)
{
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = int((bits >> 52) & 0x7FF);
  if(biased == 0 || biased == 0x7FF) { int e = 0; std::frexp(x, &e); return e; }   // 0, subnormal, Inf, NaN
  return biased - 1022;
}

struct Corner_mesh
{
  int n_vertices = 0, n_edges = 0, n_faces = 0, n_halfedges = 0;
  std::vector<int> next, prev, opp, target, face, edge;  // per halfedge
  std::vector<int> edge_halfedge;                        // per edge: index of halfedge(e, tm)
  std::vector<double> u, v;                              // per halfedge: corner UV (border: unused)
  std::vector<char> vertex_on_border;                    // per vertex
  int uv_exponent = 0;   // u, v are the caller's UVs times 2^-uv_exponent (normalize_uv_scale())

  // a value of the (normalized) corner UVs in the caller's UV units
  double to_uv(double x) const { return scale_by_power_of_two(x, uv_exponent); }

  int source(int h) const { return target[opp[h]]; }
  bool is_border_halfedge(int h) const { return face[h] < 0; }
  bool is_border_edge(int e) const
  {
    const int h = edge_halfedge[e];
    return face[h] < 0 || face[opp[h]] < 0;
  }
  // the UV vector target - source of h, as seen from face(h)
  double du(int h) const { return u[h] - u[prev[h]]; }
  double dv(int h) const { return v[h] - v[prev[h]]; }
};

// The smallest halfedge of every face (a triangle), increasing, by a pass without branches: whether h is the smallest of
// its face is random in halfedge order, and a loop over the halfedges that tests it mispredicts about once per face (the
// 302K-face bunny of ../shared/large: face_orientations() 12 -> 6 ms)
inline std::vector<int> face_first_halfedges(const Corner_mesh& cm)
{
  const std::size_t nf = std::size_t(cm.n_faces);
  std::vector<int> first(nf + 1);                  // + 1: the store after the last face's halfedge
  std::size_t k = 0;
  for(int h = 0; h < cm.n_halfedges; ++h) {
    first[(std::min)(k, nf)] = h;                  // (a mesh of triangles has nf such halfedges: k <= nf)
    k += std::size_t(!cm.is_border_halfedge(h) & (h < cm.next[h]) & (h < cm.prev[h]));
  }
  first.resize((std::min)(k, nf));
  return first;
}

// Descriptors of the mesh in the numbering of `Corner_mesh`, to write results back.
template <class TriangleMesh>
struct Corner_mesh_descriptors
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<typename GT::halfedge_descriptor> halfedges;
  std::vector<typename GT::edge_descriptor> edges;
  std::vector<typename GT::vertex_descriptor> vertices;
};

// Copies the connectivity and the corner UVs of `tm`. Checks what the rest of the pipeline relies
// on: at least one face, triangles only, finite UVs. Returns INVALID_INPUT with a message otherwise.
template <class TriangleMesh, class HalfedgeUVMap>
Status build_corner_mesh(const TriangleMesh& tm, HalfedgeUVMap uvmap, Corner_mesh& cm,
                         Corner_mesh_descriptors<TriangleMesh>& d, std::string& message)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  cm = Corner_mesh();
  d.halfedges.clear(); d.edges.clear(); d.vertices.clear();
  if(faces(tm).empty()) {
    message = "the mesh has no faces";
    return INVALID_INPUT;
  }

  // positions in the enumeration, looked up through CGAL's (initialized) index maps
  auto vim = CGAL::get_initialized_vertex_index_map(tm);
  auto him = CGAL::get_initialized_halfedge_index_map(tm);
  auto fim = CGAL::get_initialized_face_index_map(tm);
  d.vertices.reserve(num_vertices(tm));
  d.halfedges.reserve(num_halfedges(tm));
  d.edges.reserve(num_edges(tm));
  std::size_t max_v = 0, max_h = 0, max_f = 0;
  for(vertex_descriptor v : vertices(tm)) { max_v = (std::max)(max_v, std::size_t(get(vim, v)) + 1); d.vertices.push_back(v); }
  for(halfedge_descriptor h : halfedges(tm)) { max_h = (std::max)(max_h, std::size_t(get(him, h)) + 1); d.halfedges.push_back(h); }
  for(face_descriptor f : faces(tm)) max_f = (std::max)(max_f, std::size_t(get(fim, f)) + 1);
  // position of an element from its index; when the indices are the positions (a mesh without removed
  // elements, e.g. a Surface_mesh after reading) the lookup tables are skipped: they are random accesses
  std::vector<int> vpos, hpos, fpos;
  bool v_identity = max_v == d.vertices.size(), h_identity = max_h == d.halfedges.size();
  for(std::size_t i = 0; v_identity && i < d.vertices.size(); ++i) v_identity = std::size_t(get(vim, d.vertices[i])) == i;
  for(std::size_t i = 0; h_identity && i < d.halfedges.size(); ++i) h_identity = std::size_t(get(him, d.halfedges[i])) == i;
  if(!v_identity) {
    vpos.assign(max_v, -1);
    for(std::size_t i = 0; i < d.vertices.size(); ++i) vpos[get(vim, d.vertices[i])] = int(i);
  }
  if(!h_identity) {
    hpos.assign(max_h, -1);
    for(std::size_t i = 0; i < d.halfedges.size(); ++i) hpos[get(him, d.halfedges[i])] = int(i);
  }
  int nf = 0;
  bool f_identity = true;
  for(face_descriptor f : faces(tm)) { f_identity = f_identity && std::size_t(get(fim, f)) == std::size_t(nf); ++nf; }
  if(!f_identity) {
    fpos.assign(max_f, -1);
    nf = 0;
    for(face_descriptor f : faces(tm)) fpos[get(fim, f)] = nf++;
  }
  auto vertex_position = [&](vertex_descriptor v) { return v_identity ? int(get(vim, v)) : vpos[get(vim, v)]; };
  auto halfedge_position = [&](halfedge_descriptor h) { return h_identity ? int(get(him, h)) : hpos[get(him, h)]; };
  auto face_position = [&](face_descriptor f) { return f_identity ? int(get(fim, f)) : fpos[get(fim, f)]; };

  // one pass over the halfedges: connectivity, corner UVs; then whether every face is a triangle
  const int nh = int(d.halfedges.size());
  cm.n_vertices = int(d.vertices.size());
  cm.n_faces = nf;
  cm.n_halfedges = nh;
  cm.next.resize(nh); cm.prev.resize(nh); cm.opp.resize(nh); cm.target.resize(nh);
  cm.face.resize(nh); cm.edge.assign(nh, -1);
  cm.u.assign(nh, 0.); cm.v.assign(nh, 0.);
  cm.vertex_on_border.assign(cm.n_vertices, 0);
  std::vector<unsigned char> degree(std::size_t(nf), 0);   // halfedges per face, counted up to 255
  int first_bad_uv = -1;
  for(int i = 0; i < nh; ++i) {
    const halfedge_descriptor h = d.halfedges[i];
    cm.next[i] = halfedge_position(next(h, tm));
    cm.prev[i] = halfedge_position(prev(h, tm));
    cm.opp[i] = halfedge_position(opposite(h, tm));
    cm.target[i] = vertex_position(target(h, tm));
    const face_descriptor f = face(h, tm);
    cm.face[i] = (f == GT::null_face()) ? -1 : face_position(f);
    if(cm.face[i] < 0) {
      cm.vertex_on_border[cm.target[i]] = 1;
      continue;
    }
    unsigned char& dg = degree[std::size_t(cm.face[i])];
    if(dg < 255) ++dg;
    const auto p = get(uvmap, h);
    const double pu = CGAL::to_double(p.x()), pv = CGAL::to_double(p.y());
    if(!std::isfinite(pu) || !std::isfinite(pv)) { if(first_bad_uv < 0) first_bad_uv = i; continue; }
    cm.u[i] = pu; cm.v[i] = pv;
  }
  bool triangles = true;
  for(unsigned char dg : degree) triangles = triangles && dg == 3;
  if(!triangles) {   // the first face of faces(tm) that is not a triangle
    nf = 0;
    for(face_descriptor f : faces(tm)) {
      ++nf;
      std::size_t n = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) { (void)h; ++n; }
      if(n != 3) {
        message = "face " + std::to_string(nf - 1) + " is not a triangle";
        return INVALID_INPUT;
      }
    }
  }
  if(first_bad_uv >= 0) {
    message = "the UV of corner (vertex " + std::to_string(cm.target[first_bad_uv]) + ", face " + std::to_string(cm.face[first_bad_uv]) +
              ") is not finite (NaN or infinity)";
    return INVALID_INPUT;
  }
  for(edge_descriptor e : edges(tm)) {
    const int h = halfedge_position(halfedge(e, tm));
    const int id = int(d.edges.size());
    d.edges.push_back(e);
    cm.edge_halfedge.push_back(h);
    cm.edge[h] = id;
    cm.edge[cm.opp[h]] = id;
  }
  cm.n_edges = int(d.edges.size());
  return SUCCESS;
}

// Scale normalization (scale covariance): multiplies every corner UV by 2^-E, E = uv_exponent, the
// binary exponent of the largest |UV coordinate| (so that it lies in [1/2, 1) afterwards). A power
// of 2 changes no significant bit, so a map scaled by 2^j is normalized to the very same doubles as
// the map itself, and everything computed from the normalized UVs (cut edges, cones, rotation fit,
// alignment, F_delta, flip repair) is identical; results are scaled back by 2^E with to_uv(). This
// also keeps products, angle tests and the grid away from the underflow and overflow limits of
// double for maps of any size. Refused (INVALID_INPUT): a UV that would lose bits (a subnormal one, or one more
// than 2^1074 times smaller than the largest one: a map spanning more than the double range).
// With `forced_exponent`, E = *forced_exponent instead (integer-grid maps: E = -s for the grid scale
// 2^s, so that the corner mesh holds the UVs in grid units and integers stay integers; pinned
// corners: E at most the lowest bit of every pinned value, pinned_corners.h); a UV that would
// overflow or lose bits is then RANGE_EXCEEDED.
// The binary exponent E of the largest |UV coordinate| (0 if all are 0): the default E above.
inline int natural_uv_exponent(const Corner_mesh& cm)
{
  int e = 0;
  double max_abs = 0;
  for(int h = 0; h < cm.n_halfedges; ++h)
    if(!cm.is_border_halfedge(h)) max_abs = (std::max)({max_abs, std::fabs(cm.u[h]), std::fabs(cm.v[h])});
  if(max_abs > 0) e = binary_exponent(max_abs);
  return e;
}

inline Status normalize_uv_scale(Corner_mesh& cm, std::string& message, const int* forced_exponent = nullptr)
{
  const int e = forced_exponent != nullptr ? *forced_exponent : natural_uv_exponent(cm);
  if(e == 0) { cm.uv_exponent = 0; return SUCCESS; }   // nothing to scale
  // when every scaled nonzero |UV| stays a normal double, the scaling is one exact product each
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for(int h = 0; h < cm.n_halfedges; ++h)
    if(!cm.is_border_halfedge(h))
      for(double x : {std::fabs(cm.u[h]), std::fabs(cm.v[h])}) { hi = (std::max)(hi, x); if(x > 0) lo = (std::min)(lo, x); }
  if(e > -1000 && e < 1000 && std::ldexp(hi, -e) < 0x1p1020 && (lo == std::numeric_limits<double>::infinity() ||
                                                                std::ldexp(lo, -e) >= 0x1p-1020)) {
    const double f = std::ldexp(1., -e);
    for(int h = 0; h < cm.n_halfedges; ++h)
      if(!cm.is_border_halfedge(h)) { cm.u[h] *= f; cm.v[h] *= f; }
    cm.uv_exponent = e;
    return SUCCESS;
  }
  for(int h = 0; h < cm.n_halfedges; ++h) {
    if(cm.is_border_halfedge(h)) continue;
    const double n[2] = {scale_by_power_of_two(cm.u[h], -e), scale_by_power_of_two(cm.v[h], -e)};
    if(scale_by_power_of_two(n[0], e) != cm.u[h] || scale_by_power_of_two(n[1], e) != cm.v[h]) {
      if(forced_exponent != nullptr) {
        message = "the UV of corner (vertex " + std::to_string(cm.target[h]) + ", face " + std::to_string(cm.face[h]) +
                  ") scaled by 2^" + std::to_string(-e) + " (the unit set by the grid scale and the pinned corners) " +
                  "is not exact in doubles (overflow or underflow)";
        return RANGE_EXCEEDED;
      }
      const double x = scale_by_power_of_two(n[0], e) != cm.u[h] ? cm.u[h] : cm.v[h];
      message = "the UV of corner (vertex " + std::to_string(cm.target[h]) + ", face " + std::to_string(cm.face[h]) +
                ") has the coordinate " + format_double(x, 17) + ", which loses bits when the map is scaled by 2^" +
                std::to_string(-e) + " (to its largest coordinate, below 2^" + std::to_string(e) + "): " +
                (std::fabs(x) < std::numeric_limits<double>::min() ? "a subnormal double, below the precision of the map's other coordinates; "
                                                                   : "the map spans more than the range of double; ") +
                "round such tiny values to 0";
      return INVALID_INPUT;
    }
    cm.u[h] = n[0]; cm.v[h] = n[1];
  }
  cm.uv_exponent = e;
  return SUCCESS;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_CORNER_MESH_H
