// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_ISOLINE_CLASSES_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_ISOLINE_CLASSES_H

// The sector coordinates that the integer-grid rows of align edges and cut edges tie together (beyond the paper). With
// integer translations t, every such row reads x_a = s x_b + c (s = +-1, c an integer): an align edge x_a = x_b (its two
// ends, one component), a cut edge x_j = (R x_i)_c + t_c at each of its two ends (Eq. 4 with the translation fixed, R
// a quarter turn). The rows split the coordinates into classes, each with a root r and x = s x_r + c for its members
// (a union-find with those relations on its links); a row closing a cycle of a class either holds for every value
// (x_r = x_r + 0), fixes the class (x_r = -x_r + c: around a cone, x_r = c / 2, which must be an integer: a cone at an
// integer point) or contradicts it (x_r = x_r + c, c != 0, or two different fixed values, or c odd): then no map has
// these translations and these align edges, whatever the isolines. The quantization (integer_grid_quantization.h)
// tries each cone's candidate points against the classes so far (checkpoint() / rollback()), and
// add_integer_grid_rows() takes each aligned chain's isoline from its class: one value for the chains that the cut
// edges join across the charts and for the cones on them.

#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>

#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

class Isoline_classes
{
public:
  struct Relation { std::size_t root; int sign; long offset; };   // x = sign x_root + offset

  explicit Isoline_classes(std::size_t n)
    : parent_(n), sign_(n, 1), offset_(n, 0), fixed_(n, 0), value_(n, 0)
  {
    std::iota(parent_.begin(), parent_.end(), std::size_t(0));
  }

  std::size_t size() const { return parent_.size(); }

  // whether some row contradicts the others (or an offset left 2^62: range_exceeded())
  bool conflict() const { return conflict_; }
  bool range_exceeded() const { return range_exceeded_; }
  // the first row that contradicted the others: its two coordinates
  std::size_t conflict_a() const { return conflict_a_; }
  std::size_t conflict_b() const { return conflict_b_; }

  Relation find(std::size_t a)
  {
    path_.clear();
    std::size_t r = a;
    while(parent_[r] != r) { path_.push_back(r); r = parent_[r]; }
    for(std::size_t i = path_.size(); i-- > 0;) {              // from the root down: parent_[x] is compressed already
      const std::size_t x = path_[i], p = parent_[x];
      if(p == r) continue;
      const __int128 o = __int128(sign_[x]) * offset_[p] + offset_[x];
      if(!fits(o)) { fail(a, a, true); return {r, 1, 0}; }      // (offsets stay near the UVs' size: not reached)
      save(x);
      offset_[x] = long(o);
      sign_[x] *= sign_[p];
      parent_[x] = r;
    }
    return {r, a == r ? 1 : sign_[a], a == r ? 0 : offset_[a]};
  }

  // whether the class of the root r has one value, in `value`
  bool fixed(std::size_t r, long& value) const { value = value_[r]; return fixed_[r] != 0; }

  // the row x_a = s x_b + c
  void relate(std::size_t a, int s, std::size_t b, long c)
  {
    const Relation A = find(a), B = find(b);
    // x_ra = A.sign (x_a - A.offset) = S x_rb + O
    const int S = A.sign * s * B.sign;
    const __int128 O = __int128(A.sign) * (__int128(s) * B.offset + c - A.offset);
    if(!fits(O)) { fail(a, b, true); return; }
    if(A.root != B.root) {
      save(A.root);
      parent_[A.root] = B.root; sign_[A.root] = S; offset_[A.root] = long(O);
      if(fixed_[A.root]) fix(B.root, __int128(S) * (value_[A.root] - O), a, b);   // x_rb = S (x_ra - O)
    } else if(S == 1) {
      if(O != 0) fail(a, b, false);
    } else if(O % 2 != 0) {
      fail(a, b, false);                                         // x_r = -x_r + O: O / 2, not an integer
    } else {
      fix(A.root, O / 2, a, b);
    }
  }

  // Starts recording the changes (one level): rollback() undoes everything done since.
  void checkpoint() { log_.clear(); recording_ = true; saved_conflict_ = conflict_; saved_range_ = range_exceeded_; }
  void rollback()
  {
    for(std::size_t i = log_.size(); i-- > 0;) {
      const Entry& e = log_[i];
      parent_[e.index] = e.parent; sign_[e.index] = e.sign; offset_[e.index] = e.offset;
      fixed_[e.index] = e.fixed; value_[e.index] = e.value;
    }
    log_.clear();
    recording_ = false;
    conflict_ = saved_conflict_;
    range_exceeded_ = saved_range_;
  }

private:
  struct Entry { std::size_t index, parent; int sign; long offset; char fixed; long value; };

  static bool fits(__int128 v) { return v > -(__int128(1) << 62) && v < (__int128(1) << 62); }

  void save(std::size_t x)
  {
    if(recording_) log_.push_back({x, parent_[x], sign_[x], offset_[x], fixed_[x], value_[x]});
  }

  void fail(std::size_t a, std::size_t b, bool range)
  {
    if(!conflict_) { conflict_a_ = a; conflict_b_ = b; }
    conflict_ = true;
    range_exceeded_ = range_exceeded_ || range;
  }

  void fix(std::size_t r, __int128 v, std::size_t a, std::size_t b)
  {
    if(!fits(v)) { fail(a, b, true); return; }
    if(fixed_[r]) { if(value_[r] != long(v)) fail(a, b, false); return; }
    save(r);
    fixed_[r] = 1;
    value_[r] = long(v);
  }

  std::vector<std::size_t> parent_;
  std::vector<int> sign_;
  std::vector<long> offset_;
  std::vector<char> fixed_;
  std::vector<long> value_;
  std::vector<std::size_t> path_;
  std::vector<Entry> log_;
  bool recording_ = false, conflict_ = false, range_exceeded_ = false, saved_conflict_ = false, saved_range_ = false;
  std::size_t conflict_a_ = 0, conflict_b_ = 0;
};

inline void relate_align_edges(const Corner_mesh& cm, const Seam_topology& st, const Align_edges& al, Isoline_classes& classes)
{
  for(int e : al.edges) {
    std::size_t a, b;
    align_edge_ends(cm, st, al, e, a, b);
    classes.relate(a, 1, b, 0);
  }
}

// the rows of the cut edge of halfedge h, whose translation t[2h], t[2h + 1] is known: at both ends of the edge, the
// sector across it is the rotation of the sector on h's side plus the translation
inline void relate_cut_edge(const Corner_mesh& cm, const Seam_topology& st, const Cut_rotations& rot,
                            const std::vector<long>& t, int h, Isoline_classes& classes)
{
  const Quarter_turn R(rot.k[h]);
  const Cut_edge_ends s = cut_edge_ends(cm, st, h);
  for(int m = 0; m < 2; ++m)
    for(int c = 0; c < 2; ++c)
      classes.relate(2 * std::size_t(s.j[m]) + std::size_t(c), R.sign[c], 2 * std::size_t(s.i[m]) + std::size_t(R.col[c]),
                     t[2 * std::size_t(h) + std::size_t(c)]);
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_SURFACE_ISOLINE_CLASSES_H
