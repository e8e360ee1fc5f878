// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_VERTEX_PASSAGE_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_VERTEX_PASSAGE_H

// The rays leaving a vertex along the axis directions, found by exact direction classification
// around the vertex (Sec. 6.2, Fig. 3b).
//
// Fan: the corners of vertex v in counter-clockwise order. The corner h (target(h) = v) spans the
// wedge from e_a = UV(target(next(h))) - UV(v) to e_b = UV(source(h)) - UV(v); its ccw successor is
// prev(opposite(h)) (across the edge of h), its cw predecessor opposite(next(h)).
// A reference direction m0, given in the chart of a start corner, is carried around the fan through the
// transitions (m += k across each crossed edge). The direction code (chart_geometry.h) of e_a and e_b
// relative to the carried direction is lifted to integers along the fan: within a wedge (a
// non-folded triangle corner, angle < 180 degrees) by ((code_b - code_a) mod 8), across an edge by
// the jump of the code of the shared edge between the two charts (0 on an exactly seamless map).
// Lifted values count eighths of the codes' circle: 2 = one quarter turn, 8 = a full turn.
// A ray at lifted value T lies in the wedge with L_a < T <= L_b (half-open: a ray along an edge is
// counted once; the sides of the middle corner of a zero-area triangle count as turned inwards, vertex_fan()).
// Passing a regular vertex, the trace arrives with the back ray at 4 and leaves at 8 = straight on:
// exactly one wedge on an exactly seamless map, none or several on an inexact one.

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/tracing/chart_geometry.h>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace tracing {

struct Fan_wedge
{
  int corner;     // halfedge with target v
  int m;          // the reference direction, carried into the chart of face(corner)
  int La, Lb;     // lifted codes of e_a and e_b
};

struct Vertex_fan
{
  std::vector<Fan_wedge> wedges;   // ccw; the first one is the start corner unless the fan is open
  bool closed = true;              // false: v is on the border (the fan runs from border to border)
  int start = 0;                   // index of the start corner in `wedges`
  bool degenerate = false;         // an edge of zero UV length at v (no direction)
};

inline int code_of_edge(const Corner_mesh& cm, int m, int corner, int other)
{
  auto sign_of_difference = [](double a, double b) { return int(a > b) - int(a < b); };   // of a - b, exactly
  return direction_code_of_signs(m, sign_of_difference(cm.u[other], cm.u[corner]),
                                 sign_of_difference(cm.v[other], cm.v[corner]));
}

// The fan of target(h0) with the reference direction m0 in the chart of face(h0); lifted so that
// L_a of the start corner equals its code in [0, 8).
inline Vertex_fan vertex_fan(const Corner_mesh& cm, const Cut_rotations& rot, int h0, int m0)
{
  Vertex_fan fan;
  // walk cw to the first corner of an open fan (m carried backwards: the edge of next(h) maps the
  // frame of face(h) to face(opposite(next(h))) by k(next(h)))
  int first = h0, m_first = direction_mod4(m0);
  int guard = 0;
  for(;;) {
    const int o = cm.opp[cm.next[first]];
    if(cm.face[o] < 0) { fan.closed = false; break; }
    m_first = direction_mod4(m_first + rot.k[cm.next[first]]);
    first = o;
    if(first == h0 || ++guard > cm.n_halfedges) break;
  }
  if(fan.closed) { first = h0; m_first = direction_mod4(m0); }

  int h = first, m = m_first, L = 0, prev_code_b = 0;
  for(bool at_first = true;; at_first = false) {
    const int ca = code_of_edge(cm, m, h, cm.next[h]), cb = code_of_edge(cm, m, h, cm.prev[h]);
    if(ca < 0 || cb < 0) { fan.degenerate = true; return fan; }
    const int La = at_first ? ca : L + (((ca - prev_code_b) % 8 + 12) % 8 - 4);
    const int Lb = La + ((cb - ca) % 8 + 8) % 8;
    if(h == h0) fan.start = int(fan.wedges.size());
    fan.wedges.push_back(Fan_wedge{h, m, La, Lb});
    L = Lb; prev_code_b = cb;
    const int o = cm.opp[h];
    if(cm.face[o] < 0) break;                         // reached the border
    m = direction_mod4(m + rot.k[h]);
    h = cm.prev[o];
    if(h == first || int(fan.wedges.size()) > cm.n_halfedges) break;
  }
  // The middle corner of a zero-area triangle with three distinct corners spans exactly a half turn. The triangle is
  // the limit of a thin positive one (as the quad extraction collapses it), whose sides at that corner turn towards
  // its inside: a side along an axis counts as just inside the wedge, in the wedge and in its neighbour across that
  // side alike. So a ray along the triangle's line leaves the middle corner by the positive face beyond the side at
  // either end (the half-open rule would give the ray at e_b to the zero-area face, which a trace cannot run along),
  // and only the ray across the line enters the face.
  const int n = int(fan.wedges.size()), La_start = fan.wedges[fan.start].La;
  std::vector<int> straight;
  for(int i = 0; i < n; ++i)
    if(fan.wedges[i].Lb - fan.wedges[i].La == 4 && face_orientation(cm, fan.wedges[i].corner) == 0) straight.push_back(i);
  for(int i : straight) {
    Fan_wedge& w = fan.wedges[i];
    const int before = i > 0 ? i - 1 : fan.closed ? n - 1 : -1, after = i + 1 < n ? i + 1 : fan.closed ? 0 : -1;
    if(w.La % 2 == 0) { ++w.La; if(before >= 0) ++fan.wedges[before].Lb; }
    if(w.Lb % 2 == 0) { --w.Lb; if(after >= 0) --fan.wedges[after].La; }
  }
  // shift so that L_a(start) is its code in [0, 8) (turned inwards as above)
  const Fan_wedge& s = fan.wedges[fan.start];
  const int code = code_of_edge(cm, s.m, s.corner, cm.next[s.corner]) + s.La - La_start;
  const int shift = (code + 8) % 8 - s.La;
  for(Fan_wedge& w : fan.wedges) { w.La += shift; w.Lb += shift; }
  return fan;
}

// the wedges containing the ray at lifted value T (L_a < T <= L_b, or L_a <= T for the first
// wedge of an open fan)
inline void wedges_containing(const Vertex_fan& fan, int T, std::vector<int>& out)
{
  for(std::size_t i = 0; i < fan.wedges.size(); ++i) {
    const Fan_wedge& w = fan.wedges[i];
    const bool lower = (!fan.closed && i == 0) ? w.La <= T : w.La < T;
    if(lower && T <= w.Lb) out.push_back(int(i));
  }
}

// A wedge of the closed fan `fan` (its wedges listed from its start corner) whose closed angle holds the ray of direction
// m0, the reference direction of the start corner, in the start corner's own chart: among the wedges that share that
// chart (reached from the start corner without crossing a cut edge, `is_cut` per edge), the first turn of the chart each
// way (lifted 8 counter-clockwise, 0 clockwise); on an edge between two of them, the one where it is e_b; -1 if none, or
// if both ways find it (the chart overlaps itself around v: a cone of more than a full turn inside one chart). The ray found
// counter-clockwise (lifted 8) from the start is this one where it lies counter-clockwise of the start in its chart; at a
// cone it may lie clockwise of the start instead, and the way around counter-clockwise then reaches another ray or none.
inline int chart_wedge_of_start_ray(const Vertex_fan& fan, const Corner_mesh& cm, const std::vector<char>& is_cut)
{
  const int n = int(fan.wedges.size());
  if(!fan.closed || n == 0 || fan.start != 0) return -1;
  auto crosses_cut = [&](int i) { return is_cut[std::size_t(cm.edge[fan.wedges[std::size_t(i)].corner])] != 0; };   // wedge i to i + 1
  auto holds = [&](int i, int T) { return fan.wedges[std::size_t(i)].La <= T && T <= fan.wedges[std::size_t(i)].Lb; };
  const int total = fan.wedges[std::size_t(n - 1)].Lb - fan.wedges[0].La;   // the angle around v, lifted
  int ccw = 1;                                                               // wedges 0 .. ccw - 1: the chart, ccw
  while(ccw < n && !crosses_cut(ccw - 1)) ++ccw;
  std::vector<int> found;                                                    // the ray on a shared edge: two wedges
  for(int i = 0; i < ccw; ++i) if(holds(i, 8)) found.push_back(i);           // lifted 8 counter-clockwise
  for(int j = n - 1; j >= ccw && !crosses_cut(j); --j)                       // lifted 0 clockwise: total counter-clockwise
    if(holds(j, total)) found.push_back(j);
  std::sort(found.begin(), found.end());                                      // (the clockwise ones were descending)
  const bool one_ray = found.size() == 1 ||
                       (found.size() == 2 && (found[1] == found[0] + 1 || (found[0] == 0 && found[1] == n - 1)));
  return !found.empty() && one_ray ? found[0] : -1;
}

// The direction, in the chart of wedge w, of the ray at lifted value T (T even, inside w):
// the carried reference direction turned by (T mod 8) / 2 quarter turns.
inline int ray_direction(const Fan_wedge& w, int T) { return direction_mod4(w.m + (((T % 8) + 8) % 8) / 2); }

} // namespace tracing
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_TRACING_VERTEX_PASSAGE_H
