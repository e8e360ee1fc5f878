// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_TRACE_END_H
#define CGAL_SEAMLESS_SNAPPING_TRACE_END_H

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * How an isoline trace ended (Sec. 6.2 of Mandad & Campen 2019). The first six are regular ends;
 * the others are inconsistencies of the map (Fig. 3), which cannot occur on an exactly seamless,
 * locally injective map, and are reported instead of looping or asserting.
 */
enum class Trace_end
{
  CONE,                          ///< reached a cone (an interior vertex whose UV angle sum is not 4 quarter turns)
  BORDER,                        ///< reached the border of the mesh
  TARGET,                        ///< reached the given target exactly
  CLOSED_LOOP,                   ///< came back to its start point, in its start direction, exactly
  EARLIER_TRACE,                 ///< reached an earlier trace (a T-junction of the motorcycle graph)
  LENGTH_LIMIT,                  ///< crossed the given maximal number of faces
  OSCILLATION_AT_CUT,            ///< behind a cut edge the direction points back onto the edge (Fig. 3a)
  MISSED_AT_CUT,                 ///< behind a cut edge the isoline misses the edge (inexact transition)
  NO_CONTINUATION_AT_VERTEX,     ///< no outgoing sector continues the isoline at a regular vertex (Fig. 3b)
  SEVERAL_CONTINUATIONS_AT_VERTEX,///< more than one sector continues it (Fig. 3b)
  FELL_OFF_BORDER,               ///< a trace running along the border left the mesh (Fig. 3c)
  FOLDED_FACE,                   ///< entered a face whose UV triangle is flipped or degenerate (not locally injective); a zero-area triangle with three distinct (collinear) corners is crossed instead, as the limit of a thin positive one (a segment of zero UV length), unless the trace runs along its line (a ray along its line from a vertex of it leaves by a positive face beside it)
  DEGENERATE_VERTEX,             ///< passed a vertex with a zero-length UV edge (no direction)
  INVALID_START                  ///< the start location is not on the surface, or no sector contains the start direction; or the start, the direction or the target of `Trace_options` is none of the mesh the tracer read (`message` says which)
};

/// `true` for the ends that report an inconsistency of the map (not a regular end).
inline bool is_failure(Trace_end e) { return e >= Trace_end::OSCILLATION_AT_CUT; }

/// a short, distinct name of `e`.
inline const char* trace_end_name(Trace_end e)
{
  switch(e) {
    case Trace_end::CONE:                            return "cone";
    case Trace_end::BORDER:                          return "border";
    case Trace_end::TARGET:                          return "target";
    case Trace_end::CLOSED_LOOP:                     return "closed_loop";
    case Trace_end::EARLIER_TRACE:                   return "earlier_trace";
    case Trace_end::LENGTH_LIMIT:                    return "length_limit";
    case Trace_end::OSCILLATION_AT_CUT:              return "oscillation_at_cut";
    case Trace_end::MISSED_AT_CUT:                   return "missed_at_cut";
    case Trace_end::NO_CONTINUATION_AT_VERTEX:       return "no_continuation_at_vertex";
    case Trace_end::SEVERAL_CONTINUATIONS_AT_VERTEX: return "several_continuations_at_vertex";
    case Trace_end::FELL_OFF_BORDER:                 return "fell_off_border";
    case Trace_end::FOLDED_FACE:                     return "folded_face";
    case Trace_end::DEGENERATE_VERTEX:               return "degenerate_vertex";
    case Trace_end::INVALID_START:                   return "invalid_start";
  }
  return "unknown";
}

/// number of values of `Trace_end`
constexpr int number_of_trace_ends = int(Trace_end::INVALID_START) + 1;

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_TRACE_END_H
