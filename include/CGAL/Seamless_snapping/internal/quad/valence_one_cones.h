// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_VALENCE_ONE_CONES_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_VALENCE_ONE_CONES_H

// A cone of 90 degrees (quad valence 1, a singularity of index 3/4 of the field, e.g. in Directional's maps) has no
// quad mesh of unit cells: its cell F is a quad whose two sides at the cone p are one edge, so its corner a next to p
// comes twice, F = (p, a, b, a), and F shares two edges with b's other cells. Around p the grid is a quarter plane with
// its two sides glued: in the chart where p = (0, 0) and the sides are the u and v axes, a = (1, 0) ~ (0, 1),
// c = (2, 0) ~ (0, 2), b = (1, 1), d = (2, 1), e = (1, 2), g = (2, 2), and the four cells of [0, 2]^2 are
//   F = (p, a, b, a),  A = (a, c, d, b),  B = (a, b, e, c),  C = (b, d, g, e),
// a disk whose border is the loop c, d, g, e (its sides on the axes are glued). split_valence_one_cones() replaces
// them by the one quad (c, d, g, e): p, a and b and their six edges go, the border of the disk stays, so the mesh
// around it is untouched, V - E + F is kept (-3 + 6 - 3), and c, d and e lose one edge each: the cone's index 3/4 is
// carried by three vertices of index 1/4 (valence 3 where they had 4). The quads are then no longer the unit cells
// there (three cells fewer than the UV area), which the verification accounts for (quad_mesh_checks.h).
// The replacement needs exactly that neighbourhood: a and b of valence 4 with no other cells, and c, d, e, g four
// other points (any of them may be a cone or on the border); else (a cone at a or b, a dropped cell among the four,
// cells that meet themselves or another split's) the cone is refused, with the reason.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/quad/quad_cells.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {
namespace quad {

// q rotated so that its corner i comes first
inline std::array<int, 4> starting_at(const std::array<int, 4>& q, int i)
{
  return {{q[std::size_t(i)], q[std::size_t((i + 1) % 4)], q[std::size_t((i + 2) % 4)], q[std::size_t((i + 3) % 4)]}};
}

// Splits the cells at the quad vertices `cones` (points of valence-1 cones, see the header) in `cells`; the
// points and quads that go are removed, the others keep their order (and their entries of repairs.valence_change,
// sized to the points on entry, to which c, d and e add -1). Returns INVALID_INPUT, naming the first cone whose
// neighbourhood is not the 2 x 2 cells, with `cells` and `repairs` unchanged.
inline Status split_valence_one_cones(Quad_cells& cells, const std::vector<int>& cones, Cell_repairs& repairs,
                                      std::string& message)
{
  if(cones.empty()) return SUCCESS;
  const Quad_incidence incidence(cells);
  const Index_lists& quads_of = incidence.quads_of;
  // the quad other than `not_q` with the directed side from -> to, rotated to start at `from`; {-1} if none
  auto with_side = [&](int from, int to, int not_q, int& found) {
    int rank = 0;
    found = incidence.quad_with_side(from, to, not_q, rank);
    return found < 0 ? std::array<int, 4>{{-1, -1, -1, -1}} : starting_at(cells.quads[std::size_t(found)], rank);
  };
  std::vector<char> quad_gone(cells.quads.size(), 0), point_gone(cells.points.size(), 0);
  std::vector<std::array<int, 4> > merged;                // per split: (c, d, g, e)
  std::vector<std::array<int, 4> > merged_from;           // per split: F, A, B, C
  for(int p : cones) {
    const Integer_point& cone = cells.points[std::size_t(p)];
    auto refuse = [&](const std::string& why) {
      message = "vertex " + std::to_string(cone.element) + " is a cone of valence 1 (an angle sum of 1 quarter turn): "
                "its cell would be a quad whose two sides at the cone are one edge, a corner twice, and it cannot be "
                "replaced with its 2 x 2 cells by one quad: " + why + "; a larger grid_scale makes the cells smaller";
      return INVALID_INPUT;
    };
    const auto fq = quads_of[p];
    if(fq.size() != 1) return refuse("it is a corner of " + std::to_string(fq.size()) + " cells, not of 1");
    const int f = *fq.begin();
    int i = 0;
    while(cells.quads[std::size_t(f)][std::size_t(i)] != p) ++i;
    const std::array<int, 4> F = starting_at(cells.quads[std::size_t(f)], i);
    const int a = F[1], b = F[2];
    if(F[3] != a) return refuse("its cell does not have the corner next to it twice");
    int ia, ib, ic;
    const std::array<int, 4> A = with_side(b, a, f, ia), B = with_side(a, b, f, ib);
    if(ia < 0 || ib < 0) return refuse("a cell next to it is missing (the border or a dropped cell)");
    const std::array<int, 4> Ar = starting_at(A, 1), Br = B;   // A = (a, c, d, b), B = (a, b, e, c)
    const int c = Ar[1], d = Ar[2], e = Br[2];
    if(Br[3] != c) return refuse("the cells next to it do not meet at one point");
    const std::array<int, 4> C = with_side(b, d, -1, ic);      // C = (b, d, g, e)
    if(ic < 0 || C[3] != e) return refuse("the cell across from it is missing or does not close the 2 x 2 cells");
    const int g = C[2];
    if(quads_of[a].size() != 4 || quads_of[b].size() != 4)
      return refuse("the integer points next to it are corners of other cells too (a cone there)");
    std::array<int, 7> all = {{p, a, b, c, d, e, g}};
    std::sort(all.begin(), all.end());
    if(std::adjacent_find(all.begin(), all.end()) != all.end())
      return refuse("the 2 x 2 cells around it do not have 7 distinct corners");
    for(int q : {f, ia, ib, ic})
      if(quad_gone[std::size_t(q)]) return refuse("its 2 x 2 cells overlap those of another cone of valence 1");
    for(int q : {f, ia, ib, ic}) quad_gone[std::size_t(q)] = 1;
    for(int q : {p, a, b}) point_gone[std::size_t(q)] = 1;
    merged.push_back({{c, d, g, e}});
    merged_from.push_back({{f, ia, ib, ic}});
  }
  std::vector<std::vector<int> > covered(merged.size());
  for(std::size_t s = 0; s < merged.size(); ++s) {
    for(int q : merged_from[s])
      covered[s].insert(covered[s].end(), cells.faces_begin(std::size_t(q)), cells.faces_end(std::size_t(q)));
    std::sort(covered[s].begin(), covered[s].end());
    covered[s].erase(std::unique(covered[s].begin(), covered[s].end()), covered[s].end());
    for(int k : {0, 1, 3}) --repairs.valence_change[std::size_t(merged[s][std::size_t(k)])];   // c, d, e
  }
  for(int p : cones) repairs.split_cones.push_back(cells.points[std::size_t(p)].element);
  replace_cells(cells, quad_gone, point_gone, merged, covered, repairs.valence_change);
  return SUCCESS;
}

} // namespace quad
} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_QUAD_VALENCE_ONE_CONES_H
