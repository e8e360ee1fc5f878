// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_PINNED_CORNERS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_PINNED_CORNERS_H

// Pinned corners (named parameter pinned_corner_map, default and integer-grid mode): the UV of a
// pinned corner is kept bit-identical. The two variables of its sector become constants: rows
//   x_{2s+c} = p_c,   c = 0, 1,   p = the pinned corner's input UV,
// with right-hand sides b != 0 (Constraint_rows::rhs, the core's Eq. 2'), appended to the full
// system after the connection and integer-grid rows and reduced with them (Sec. 5.3). The vertex of
// a pinned sector is a forced node, so a pinned variable is a node variable (its row needs no
// substitution of Eq. 9) and flip repair never moves it: group moves only displace inner sectors of
// branches and sectors in no row, node moves keep every row of the node system, x = p among them,
// and every move is checked against the rows of the full system.
//
// Units: b must be an integer in corner-mesh units, so the corner mesh is scaled by 2^-E with E at
// most the lowest set bit of every nonzero pinned coordinate (pin_unit_exponent). E moves with the
// scale 2^j of the input, so the corner mesh, and with it the result, is covariant.
// Grid: every snapped value is a multiple of the quantum 2^(K-52) of F_delta (Sec. 4.3, K from the
// largest constrained |UV|), so a pinned value with set bits below the quantum cannot be kept: it is
// refused (RANGE_EXCEEDED, naming the corner and the quantum in the caller's units) before the
// projection, and again if the projection has to enlarge the grid.
// All corners of a sector have the same UV (compute_seam_topology refuses anything else), so the
// pinned value of a sector does not depend on which of its corners is pinned. Pins that contradict the constraints (e.g. two pairs of pinned corners across one
// cut branch with different translations, or a cone pinned off its integer point in the
// integer-grid mode) make the system inconsistent: INFEASIBLE, with the pinned corners named.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/projection/fixed_point_grid.h>
#include <CGAL/Seamless_snapping/internal/surface/connection_constraints.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// The pinned sectors, increasing, with one pinned corner each (for messages) and its UV in
// corner-mesh units (integers, see above).
struct Pinned_sectors
{
  std::vector<int> sector;
  std::vector<int> corner;
  std::vector<double> value;     // 2 per pinned sector
  bool empty() const { return sector.empty(); }
};

// the corner whose UV the halfedge h holds: h itself, or for a border halfedge the corner
// (target(h), face(prev(opposite(h)))) (the Seam_mesh convention, as write_stage keeps it)
inline int pinned_corner_of(const Corner_mesh& cm, int h)
{
  return cm.is_border_halfedge(h) ? cm.prev[cm.opp[h]] : h;
}

// q with x = m 2^q, m odd (x finite and nonzero)
inline int lowest_bit_exponent(double x)
{
  int e;
  const double f = std::frexp(std::fabs(x), &e);           // |x| = f 2^e, f in [1/2, 1)
  long long m = static_cast<long long>(std::ldexp(f, 53));  // an integer < 2^53, exactly
  int q = e - 53;
  while((m & 1) == 0) { m >>= 1; ++q; }
  return q;
}

// E: the smallest lowest-bit exponent over the nonzero coordinates of the pinned corners (caller's
// units, before normalize_uv_scale); false if every pinned coordinate is zero (or none is pinned)
inline bool pin_unit_exponent(const Corner_mesh& cm, const std::vector<int>& pinned, int& E)
{
  bool found = false;
  for(int h : pinned) {
    const int c = pinned_corner_of(cm, h);
    for(double a : {cm.u[c], cm.v[c]}) {
      if(a == 0) continue;
      const int q = lowest_bit_exponent(a);
      E = found ? (std::min)(E, q) : q;
      found = true;
    }
  }
  return found;
}

inline std::string pinned_corner_name(const Corner_mesh& cm, int corner)
{
  return row_origin_name(cm, pinned_row_origin(corner));
}

inline std::string uv_name(const Corner_mesh& cm, int corner)
{
  return "(" + format_double(cm.to_uv(cm.u[corner]), 17) + ", " + format_double(cm.to_uv(cm.v[corner]), 17) + ")";
}

// The pinned sectors of the corners `pinned` (halfedges in the pipeline's numbering), one corner each.
inline void collect_pinned_sectors(const Corner_mesh& cm, const Seam_topology& st, const std::vector<int>& pinned,
                                   Pinned_sectors& pins)
{
  pins = Pinned_sectors();
  std::vector<int> corner_of_sector(st.n_sectors, -1);
  for(int h : pinned) {
    const int c = pinned_corner_of(cm, h);
    if(corner_of_sector[st.sector_of[c]] < 0) corner_of_sector[st.sector_of[c]] = c;
  }
  for(int s = 0; s < st.n_sectors; ++s) {
    const int c = corner_of_sector[s];
    if(c < 0) continue;
    pins.sector.push_back(s);
    pins.corner.push_back(c);
    pins.value.push_back(cm.u[c]);
    pins.value.push_back(cm.v[c]);
  }
}

// Appends the rows x_{2s+c} = p_c (origin: pinned_row_origin(corner)). RANGE_EXCEEDED if a pinned
// value is no integer of at most 62 bits in corner-mesh units (a corner mesh whose unit was not set
// by pin_unit_exponent); nothing is appended then.
inline Status add_pinned_rows(const Corner_mesh& cm, const Pinned_sectors& pins, Constraint_rows& rows, std::string& message)
{
  for(std::size_t i = 0; i < pins.sector.size(); ++i)
    for(int c = 0; c < 2; ++c) {
      const double p = pins.value[2 * i + c];
      if(p != std::nearbyint(p)) {
        message = pinned_corner_name(cm, pins.corner[i]) + ": its UV " + uv_name(cm, pins.corner[i]) +
                  " is not an integer of the corner mesh's unit 2^" + std::to_string(cm.uv_exponent) + ": internal error";
        return RANGE_EXCEEDED;
      }
      if(!(std::fabs(p) < 0x1p62)) {   // the unit is the lowest set bit of the pins: they span 62 bits or more
        double largest = 0;            // the map's largest |UV| sets the quantum of F_delta (Sec. 4.3)
        for(int h = 0; h < cm.n_halfedges; ++h)
          if(!cm.is_border_halfedge(h)) largest = (std::max)({largest, std::fabs(cm.u[h]), std::fabs(cm.v[h])});
        const int k = Fixed_point_grid::exponent_of(cm.to_uv(largest)) + 1 - 52;
        message = pinned_corner_name(cm, pins.corner[i]) + ": its UV " + uv_name(cm, pins.corner[i]) + " is 2^62 or " +
                  "more units of 2^" + std::to_string(cm.uv_exponent) + ", the lowest set bit of the pinned UVs: they " +
                  "span more bits than any snapped map keeps (every snapped value is a multiple of the quantum of the " +
                  "fixed-point grid F_delta, Sec. 4.3, 52 bits below the map's largest |UV|); round the pinned UVs to " +
                  "multiples of 2^" + std::to_string(k) + " or coarser; nothing was written";
        return RANGE_EXCEEDED;
      }
    }
  for(std::size_t i = 0; i < pins.sector.size(); ++i)
    for(int c = 0; c < 2; ++c)
      rows.add({ {2 * pins.sector[i] + c, 1} }, pinned_row_origin(pins.corner[i]), long(pins.value[2 * i + c]));
  return SUCCESS;
}

// The pinned corner whose UV sets the corner mesh's unit (pin_unit_exponent(): a coordinate with its lowest set bit
// at the unit, an odd number of units), or -1 if none does (no pin, or the unit set by the map).
inline int finest_pinned_corner(const Pinned_sectors& pins)
{
  for(std::size_t i = 0; i < pins.sector.size(); ++i)
    for(int c = 0; c < 2; ++c)
      if(std::fabs(std::fmod(pins.value[2 * i + std::size_t(c)], 2.)) == 1) return pins.corner[i];
  return -1;
}

// the vertices of the pinned sectors become nodes of the reduction (Sec. 5.3)
inline void mark_pinned_nodes(const Corner_mesh& cm, const Seam_topology& st, const Pinned_sectors& pins,
                              std::vector<char>& forced_nodes)
{
  forced_nodes.resize(std::size_t(cm.n_vertices), 0);
  for(int s : pins.sector) forced_nodes[std::size_t(st.sector_vertex(cm, s))] = 1;
}

// RANGE_EXCEEDED if a pinned value is not a multiple of the quantum 2^(K-52) of `grid` (corner-mesh
// units): it has bits that no snapped value can have.
inline Status check_pins_on_grid(const Corner_mesh& cm, const Pinned_sectors& pins, const Fixed_point_grid& grid,
                                 std::string& message)
{
  if(grid.K <= 52) return SUCCESS;                 // the quantum divides every integer
  for(std::size_t i = 0; i < pins.sector.size(); ++i)
    for(int c = 0; c < 2; ++c) {
      const double p = pins.value[2 * i + c];
      if(std::fmod(p, grid.quantum) == 0) continue;   // exact (fmod is exact)
      message = pinned_corner_name(cm, pins.corner[i]) + ": its UV " + uv_name(cm, pins.corner[i]) + " has set bits " +
                "below 2^" + std::to_string(grid.K - 52 + cm.uv_exponent) + ", the quantum of the fixed-point grid " +
                "F_delta (Sec. 4.3) of this map: every snapped value is a multiple of it, so this UV cannot be kept " +
                "bit-identical; round the pinned UV to a multiple of 2^" + std::to_string(grid.K - 52 + cm.uv_exponent) +
                " (or pin a corner whose UV is one); nothing was written";
      return RANGE_EXCEEDED;
    }
  return SUCCESS;
}

// appended to an INFEASIBLE message when corners are pinned: which ones, and what to do
inline std::string pinned_infeasible_hint(const Corner_mesh& cm, const Pinned_sectors& pins)
{
  if(pins.empty()) return std::string();
  std::string hint = "; " + std::to_string(pins.sector.size()) + " sector(s) are pinned (";
  for(std::size_t i = 0; i < pins.sector.size() && i < 5; ++i)
    hint += (i > 0 ? ", " : "") + pinned_corner_name(cm, pins.corner[i]) + " at " + uv_name(cm, pins.corner[i]);
  hint += pins.sector.size() > 5 ? ", ...)" : ")";
  return hint + ": pinned UVs that contradict the constraints (two pinned corners across a cut branch whose " +
         "translation differs from that of other pinned corners of the branch, a cone pinned off its integer point in " +
         "the integer-grid mode, a pinned corner off an aligned isoline) have no exact solution; unpin some of them, or " +
         "make their UVs consistent";
}

// restores the pinned values bit for bit (-0.0 included) in the result x, where they are equal
inline void restore_pinned_values(const Pinned_sectors& pins, std::vector<double>& x)
{
  for(std::size_t i = 0; i < pins.sector.size(); ++i)
    for(int c = 0; c < 2; ++c) {
      double& xi = x[2 * std::size_t(pins.sector[i]) + c];
      if(xi == pins.value[2 * i + c]) xi = pins.value[2 * i + c];
    }
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_PINNED_CORNERS_H
