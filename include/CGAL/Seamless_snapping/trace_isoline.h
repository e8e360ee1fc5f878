// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_TRACE_ISOLINE_H
#define CGAL_SEAMLESS_SNAPPING_TRACE_ISOLINE_H

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/Trace_end.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/tracing/isoline_tracer.h>

#include <CGAL/Gmpq.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * The four isoline directions in the UV chart of a face: `PLUS_U` = (1, 0), `PLUS_V` = (0, 1),
 * `MINUS_U`, `MINUS_V`; the value is the number of counter-clockwise quarter turns from (1, 0).
 */
enum class Trace_direction { PLUS_U = 0, PLUS_V = 1, MINUS_U = 2, MINUS_V = 3 };

/*!
 * \ingroup PkgSeamlessSnappingRef
 * A point of an isoline trace, exact in the UV chart of `face`.
 */
template <class TriangleMesh>
struct Trace_point
{
  typedef boost::graph_traits<TriangleMesh> GT;
  enum Location { VERTEX, EDGE, FACE };
  Location location = FACE;                        ///< where the point is on the surface
  typename GT::face_descriptor face;               ///< the face of the segment the point belongs to
  typename GT::halfedge_descriptor halfedge;       ///< `VERTEX`: the halfedge of `face` whose target is the vertex; `EDGE`: the halfedge of `face` on the edge
  /// exact UV in the chart of `face` (the corner UVs of `face`, as rationals)
  CGAL::Gmpq u = internal::tracing::zero_rational(), v = internal::tracing::zero_rational();
  /// exact, w.r.t. the targets of `halfedge(face)`, its next, and its next's next
  std::array<CGAL::Gmpq, 3> barycentric = {{internal::tracing::zero_rational(), internal::tracing::zero_rational(),
                                             internal::tracing::zero_rational()}};
  std::array<double, 3> position = {{0, 0, 0}};    ///< the 3D point, barycentric coordinates rounded to double
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 * A straight piece of a trace inside one face: from `source` to `target` along `direction` in the chart of `face`.
 */
template <class TriangleMesh>
struct Trace_segment
{
  typename boost::graph_traits<TriangleMesh>::face_descriptor face;
  Trace_direction direction = Trace_direction::PLUS_U;
  Trace_point<TriangleMesh> source, target;
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 * The result of tracing one isoline: the polyline as segments (consecutive segments meet in the same
 * surface point, each given in the chart of its own face; the crossing of a zero-area triangle with three distinct
 * corners is a segment of zero UV length between two different surface points) and how it ended.
 */
template <class TriangleMesh>
struct Isoline_trace
{
  Trace_end end = Trace_end::INVALID_START;       ///< the reason the trace stopped
  std::string message;                            ///< where (vertex, edge, face), for inconsistencies in particular
  std::vector<Trace_segment<TriangleMesh> > segments;
  std::size_t faces_crossed = 0;
  double length = 0;                              ///< parametric (UV) length, rounded to double
  int hit_trace = -1;                             ///< `EARLIER_TRACE`: index of the trace that was reached
  std::size_t inexact_transfers = 0;              ///< cut crossings where `R^k X + t` was not the exit point on the edge (0 on exact maps)
  bool has_start_vertex = false;                  ///< `start_vertex` is set (the start was a vertex)
  typename boost::graph_traits<TriangleMesh>::vertex_descriptor start_vertex;   ///< the vertex the trace started from
  bool has_start_corner = false;                  ///< `start_corner` is set (the start sector was found)
  typename boost::graph_traits<TriangleMesh>::halfedge_descriptor start_corner; ///< the corner (`target` = start vertex) in whose chart the trace started
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 * Options of a trace: a step limit and an optional target (a vertex, or an exact point of a face).
 */
template <class TriangleMesh>
struct Trace_options
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::size_t max_faces = 0;                      ///< 0: 20 times the number of faces, plus 100
  bool has_target_vertex = false;
  typename GT::vertex_descriptor target_vertex;
  bool has_target_point = false;
  typename GT::face_descriptor target_face;       ///< the target point, in the chart of `target_face` (a point of its
                                                  ///< closed UV triangle on an edge or at a corner is met from the
                                                  ///< faces around it too)
  CGAL::Gmpq target_u, target_v;
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * Traces isolines (Sec. 6.2 of Mandad & Campen 2019) of a per-corner UV map, exactly: every position is a
 * rational (`CGAL::Gmpq`) in the chart of a face, every decision an exact sign. A trace follows an axis
 * direction face by face; across a cut edge it continues in the neighbouring chart through the
 * transition `R^k u + t` (`k` fitted per seam arc, `t` computed exactly from the corner UVs); through a vertex
 * it leaves by the unique sector that continues it straight on (exact direction classification). It stops at
 * a cone, the border, the target, a closed loop (back at its start point and direction, exactly) or the face
 * limit, and reports an inconsistency of the map (see `Trace_end`) instead of looping.
 *
 * The map is read once, at construction; traces do not modify anything.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`, triangles only, with an internal
 *         `vertex_point` map whose points have `x()`, `y()`, `z()`
 * \tparam HalfedgeUVMap a model of `ReadablePropertyMap` with `halfedge_descriptor` as key type and a 2D point
 *         type with `double` coordinates: `get(uv, h)` is the UV of the corner (`target(h)`, `face(h)`)
 *
 * Preconditions for regular ends only: the map is exactly seamless (see `is_exactly_seamless()`, e.g. the output of
 * `snap_seamless_parameterization()`) and locally injective. On other maps the tracer still terminates, with the
 * failure ends of `Trace_end`.
 */
template <class TriangleMesh, class HalfedgeUVMap>
class Isoline_tracer
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef Isoline_trace<TriangleMesh> Trace;

  /// reads the map; `rotation_tolerance` (degrees) as in `snap_seamless_parameterization()`.
  Isoline_tracer(const TriangleMesh& tm, HalfedgeUVMap uv, double rotation_tolerance = 1) : tm_(tm)
  {
    status_ = internal::build_corner_mesh(tm, uv, map_.cm, desc_, message_);
    if(status_ == SUCCESS) status_ = internal::tracing::build_tracing_map(map_, rotation_tolerance, message_);
    if(status_ != SUCCESS) return;
    auto him = CGAL::get_initialized_halfedge_index_map(tm);
    std::size_t max_h = 0;
    for(halfedge_descriptor h : halfedges(tm)) max_h = (std::max)(max_h, std::size_t(get(him, h)) + 1);
    hpos_.assign(max_h, -1);
    for(std::size_t i = 0; i < desc_.halfedges.size(); ++i) hpos_[get(him, desc_.halfedges[i])] = int(i);
    for(std::size_t i = 0; i < desc_.vertices.size(); ++i) vpos_[desc_.vertices[i]] = int(i);
    auto fim = CGAL::get_initialized_face_index_map(tm);
    std::size_t max_f = 0;
    for(face_descriptor f : faces(tm)) max_f = (std::max)(max_f, std::size_t(get(fim, f)) + 1);
    face_of_mesh_.assign(max_f, 0);
    for(face_descriptor f : faces(tm)) face_of_mesh_[get(fim, f)] = 1;
  }

  /// `SUCCESS`, or why the map cannot be traced (`INVALID_INPUT`, `NOT_QUARTER_TURN_SEAMLESS`), with `message()`.
  Status status() const { return status_; }
  const std::string& message() const { return message_; }

  /// traces from the vertex `target(corner)`, along `d` in the chart of `face(corner)` (the sector of that corner). At a
  /// cone the rays around the vertex depend on the way around it: the ray is the one that the chart of `face(corner)`
  /// shows (within the faces around the vertex that share that chart, up to the cut edges), else the one reached turning
  /// counter-clockwise from the corner, else none (`Trace_end::INVALID_START`). At a cone of 3 quarter turns one of the
  /// four directions from a corner so gives another one's ray again, or none.
  Trace trace_from_vertex(halfedge_descriptor corner, Trace_direction d,
                          const Trace_options<TriangleMesh>& options = Trace_options<TriangleMesh>()) const
  {
    internal::tracing::Trace_run r;
    const int start = index_or_none(corner);
    const std::string problem = start_problem(start, d, options);
    if(!problem.empty()) return failed_start(problem);
    if(is_border(corner, tm_)) return failed_start("border halfedge");
    internal::tracing::Trace_target target;
    internal::tracing::Isoline_stepper stepper = make_stepper(options, target);
    stepper.start_at_vertex(r, start, int(d));
    stepper.run_to_end(r);
    return convert(r);
  }

  /// traces from the point (u, v) of the closed UV triangle of `f` (exact, in its chart), along `d` in that chart.
  Trace trace_from_point(face_descriptor f, const CGAL::Gmpq& u, const CGAL::Gmpq& v, Trace_direction d,
                         const Trace_options<TriangleMesh>& options = Trace_options<TriangleMesh>()) const
  {
    internal::tracing::Trace_run r;
    const int start = status_ == SUCCESS && is_face_of_mesh(f) ? index_or_none(halfedge(f, tm_)) : -1;
    const std::string problem = start_problem(start, d, options);
    if(!problem.empty()) return failed_start(problem);
    internal::tracing::Trace_target target;
    internal::tracing::Isoline_stepper stepper = make_stepper(options, target);
    stepper.start_at_point(r, start, internal::tracing::Exact_uv{u, v}, int(d));
    stepper.run_to_end(r);
    return convert(r);
  }

  /// the internal map (corner mesh, cut edges, cones, rotations); for the layout code of this package.
  const internal::tracing::Tracing_map& tracing_map() const { return map_; }

  /// the 3D positions of the vertices in the numbering of `tracing_map()`; for the layout code of this package.
  std::vector<std::array<double, 3> > vertex_positions() const
  {
    std::vector<std::array<double, 3> > p;
    for(vertex_descriptor v : desc_.vertices) {
      const auto q = get(CGAL::vertex_point, tm_, v);
      p.push_back({{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}});
    }
    return p;
  }

  /// converts an internal trace run into the public result.
  Trace convert(const internal::tracing::Trace_run& r) const
  {
    Trace t;
    t.end = r.end;
    t.message = r.detail;
    t.faces_crossed = r.steps;
    t.length = r.length;
    t.hit_trace = r.hit_trace;
    t.inexact_transfers = r.inexact_transfers;
    if(r.start_vertex >= 0) { t.has_start_vertex = true; t.start_vertex = desc_.vertices[std::size_t(r.start_vertex)]; }
    if(r.start_corner >= 0) { t.has_start_corner = true; t.start_corner = desc_.halfedges[std::size_t(r.start_corner)]; }
    t.segments.reserve(r.segments.size());
    for(const internal::tracing::Raw_segment& s : r.segments) {
      Trace_segment<TriangleMesh> seg;
      seg.face = face(desc_.halfedges[map_.face_halfedge[s.face]], tm_);
      seg.direction = Trace_direction(s.m);
      seg.source = point(s.face, s.from);
      seg.target = point(s.face, s.to);
      t.segments.push_back(seg);
    }
    return t;
  }

private:
  const TriangleMesh& tm_;
  internal::tracing::Tracing_map map_;
  internal::Corner_mesh_descriptors<TriangleMesh> desc_;
  Status status_ = INVALID_INPUT;
  std::string message_;
  std::vector<int> hpos_;
  std::map<vertex_descriptor, int> vpos_;
  std::vector<char> face_of_mesh_;          // per face index: a face of the mesh when the tracer read it

  int index(halfedge_descriptor h) const
  {
    return hpos_[get(CGAL::get_initialized_halfedge_index_map(tm_), h)];
  }

  // whether f is a face of the mesh as the tracer read it (not one removed since, nor an index past its end, where
  // halfedge(f) would read outside the mesh)
  bool is_face_of_mesh(face_descriptor f) const
  {
    const std::size_t i = std::size_t(get(CGAL::get_initialized_face_index_map(tm_), f));
    return i < face_of_mesh_.size() && face_of_mesh_[i];
  }

  // the index of h, or -1 where h is no halfedge of the mesh as the tracer read it (e.g. one of a removed face)
  int index_or_none(halfedge_descriptor h) const
  {
    const std::size_t i = std::size_t(get(CGAL::get_initialized_halfedge_index_map(tm_), h));
    return i < hpos_.size() ? hpos_[i] : -1;
  }

  // why a trace cannot start from the halfedge of index `start` (index_or_none()) along d with options o; empty if it can
  std::string start_problem(int start, Trace_direction d, const Trace_options<TriangleMesh>& o) const
  {
    if(status_ != SUCCESS) return "invalid tracer";
    if(start < 0) return "the start is no halfedge (or face) of the mesh the tracer read (an element removed since?)";
    if(int(d) < 0 || int(d) > 3) return "direction " + std::to_string(int(d)) + " is none of PLUS_U, PLUS_V, MINUS_U, MINUS_V";
    if(o.has_target_vertex && vpos_.find(o.target_vertex) == vpos_.end())
      return "the target vertex is no vertex of the mesh the tracer read";
    if(o.has_target_point && (!is_face_of_mesh(o.target_face) || index_or_none(halfedge(o.target_face, tm_)) < 0))
      return "the target face is no face of the mesh the tracer read";
    return std::string();
  }

  Trace failed_start(const std::string& why) const
  {
    Trace t; t.end = Trace_end::INVALID_START; t.message = why; return t;
  }

  internal::tracing::Isoline_stepper make_stepper(const Trace_options<TriangleMesh>& o,
                                                  internal::tracing::Trace_target& target) const
  {
    internal::tracing::Isoline_stepper stepper(map_);
    if(o.max_faces > 0) stepper.max_steps = o.max_faces;
    if(o.has_target_vertex) target.vertex = vpos_.find(o.target_vertex)->second;   // start_problem() found it
    if(o.has_target_point)
      internal::tracing::set_target_point(map_, index_or_none(halfedge(o.target_face, tm_)),
                                          internal::tracing::Exact_uv{o.target_u, o.target_v}, target);
    if(o.has_target_vertex || o.has_target_point) stepper.target = &target;
    return stepper;
  }

  // The barycentric coordinates (w.r.t. the corners c) of a point at a corner or inside a side of its face, read off
  // its place: 1 at the corner; 1 - t and t at the side's ends, t its parameter along the side. False (b unset) where
  // the point lies inside the face or its place is not confirmed exactly (then barycentric() decides).
  bool place_weights(const internal::tracing::Raw_point& p, const int c[3], internal::tracing::FT b[3]) const
  {
    using namespace internal::tracing;
    const internal::Corner_mesh& cm = map_.cm;
    if(p.kind == IN_FACE || (p.h != c[0] && p.h != c[1] && p.h != c[2])) return false;
    if(p.kind == AT_VERTEX) {
      if(corner_uv(map_, p.h) != p.uv) return false;
      for(int i = 0; i < 3; ++i) b[i] = c[i] == p.h ? one_rational() : zero_rational();
      return true;
    }
    const Exact_uv& A = corner_uv(map_, cm.prev[p.h]);   // the side from corner prev(h) to h
    const Exact_uv& B = corner_uv(map_, p.h);
    // t is taken along the coordinate in which A and B differ (lerp_parameter()), so that coordinate of A + t (B - A)
    // is the point's: the point lies on the side iff the other one is too
    const FT t = lerp_parameter(A, B, p.uv);
    if(A.u != B.u ? !lerp_scalar_equals(A.v, B.v, t, p.uv.v) : p.uv.u != A.u) return false;
    for(int i = 0; i < 3; ++i) b[i] = c[i] == p.h ? t : c[i] == cm.prev[p.h] ? one_minus(t) : zero_rational();
    return true;
  }

  Trace_point<TriangleMesh> point(int f, const internal::tracing::Raw_point& p) const
  {
    using internal::tracing::Exact_uv;
    Trace_point<TriangleMesh> out;
    const int h0 = map_.face_halfedge[f];
    out.face = face(desc_.halfedges[h0], tm_);
    out.location = p.kind == internal::tracing::AT_VERTEX ? Trace_point<TriangleMesh>::VERTEX
                 : p.kind == internal::tracing::ON_EDGE ? Trace_point<TriangleMesh>::EDGE : Trace_point<TriangleMesh>::FACE;
    if(p.h >= 0) out.halfedge = desc_.halfedges[p.h];
    out.u = p.uv.u; out.v = p.uv.v;
    // barycentric coordinates w.r.t. the targets of halfedge(f), next, next-next
    const halfedge_descriptor hf = halfedge(out.face, tm_);
    const int c[3] = {index(hf), index(next(hf, tm_)), index(next(next(hf, tm_), tm_))};
    internal::tracing::FT b[3] = {internal::tracing::zero_rational(), internal::tracing::zero_rational(),
                                  internal::tracing::zero_rational()};
    // a zero-area face has no barycentric coordinates of its own; the ends of the segment crossing it (a corner or a
    // point of a side) still have theirs, read off their place
    const bool placed = place_weights(p, c, b);
    if(placed || internal::tracing::face_orientation(map_.cm, c[0]) != 0) {
      if(!placed) {
        Exact_uv cuv[3];
        for(int i = 0; i < 3; ++i) cuv[i] = internal::tracing::corner_uv(map_, c[i]);
        internal::tracing::barycentric(cuv, p.uv, b);
      }
      for(int i = 0; i < 3; ++i) {
        out.barycentric[i] = b[i];
        const auto q = get(CGAL::vertex_point, tm_, desc_.vertices[map_.cm.target[c[i]]]);
        const double w = CGAL::to_double(b[i]);
        out.position[0] += w * CGAL::to_double(q.x());
        out.position[1] += w * CGAL::to_double(q.y());
        out.position[2] += w * CGAL::to_double(q.z());
      }
    }
    return out;
  }
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 * traces one isoline from the vertex `target(corner)` along `d` in the chart of `face(corner)`; see `Isoline_tracer`.
 * Reads the whole map on every call: use one `Isoline_tracer` for several traces.
 * If the map cannot be read, the result has `Trace_end::INVALID_START` and the reason in its message.
 */
template <class TriangleMesh, class HalfedgeUVMap>
Isoline_trace<TriangleMesh>
trace_isoline(const TriangleMesh& tm, HalfedgeUVMap uv, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor corner,
              Trace_direction d, const Trace_options<TriangleMesh>& options = Trace_options<TriangleMesh>())
{
  Isoline_tracer<TriangleMesh, HalfedgeUVMap> tracer(tm, uv);
  if(tracer.status() != SUCCESS) {
    Isoline_trace<TriangleMesh> t;
    t.message = std::string(status_name(tracer.status())) + ": " + tracer.message();
    return t;
  }
  return tracer.trace_from_vertex(corner, d, options);
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_TRACE_ISOLINE_H
