// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_REGION_PROBLEM_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_REGION_PROBLEM_H

// The optimization problem of the untangling on a set of regions (vertex sets), in the reduced
// variables w of the constraint space (region_space.h): x = x0 + N w. For every face with a corner in a
// region (and not excluded), J = J0 + B N_f w_f is affine in the few w it depends on; the problem holds
// J0 and B N_f per face, and the pattern of the lower triangle of N^T H N once, so that a Newton step
// only writes numbers into a fixed sparse matrix (one symbolic factorization per independent part of it,
// independent_parts.h).
//
//   distortion(w, eps) = sum_f area(ref_f) f_eps(J_f)                          (untangling_energy.h)
//   proximity(w)       = sum_l (x_l(w) - target_l)^2 / h^2,  l over the regions' variables
//
// h: the square root of the mean reference area (a length of the map). proximity measures the change
// from a target map (the exact snap of the input) for the minimal-change polish (untangler.h).

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/surface/corner_mesh.h>
#include <CGAL/Seamless_snapping/internal/surface/index_lists.h>
#include <CGAL/Seamless_snapping/internal/surface/seam_topology.h>
#include <CGAL/Seamless_snapping/internal/surface/transition_constraints.h>
#include <CGAL/Seamless_snapping/internal/untangling/reference_shapes.h>
#include <CGAL/Seamless_snapping/internal/untangling/region_space.h>
#include <CGAL/Seamless_snapping/internal/untangling/untangling_energy.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

class Region_problem
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;

  struct Face
  {
    int face;
    int region;                // index of the region it touches (-1: none of its corners is in one)
    double area;               // of its reference triangle
    Eigen::Vector4d J0;
    std::size_t first;         // its n w (increasing) are face_w[first, first + n), dJ / dw_f (4 x n, column-major)
    std::size_t n;             // is face_BM[4 first, 4 (first + n)) and the index of (w[a], w[b]), b <= a, in the
    std::size_t slots;         // values of H is face_slot[slots + a (a + 1) / 2 + b]
  };

  std::vector<int> vars;             // the regions' variables (2s + c), increasing
  std::vector<int> var_region;       // per variable: its region
  Region_space space;
  std::vector<Face> faces;
  std::vector<int> face_w;           // the faces' w, BM and H slots, in one array each (see Face)
  std::vector<double> face_BM;
  std::vector<int> face_slot;
  std::vector<int> proximity_slot;   // per (l, a, b) with w_index[b] <= w_index[a], in the loop order of derivatives():
                                     // the index of (w_index[a], w_index[b]) in the values of H
  Matrix H;                          // lower triangle of N^T H N (+ the proximity's N^T N), pattern only
  std::vector<double> offset;        // per variable l: x0_l - target_l (proximity); empty without a target
  double h2 = 1;                     // h^2

  // Builds the problem of `regions` (vertex sets) at x; faces with `excluded` set are left out.
  Status build(const Corner_mesh& cm, const Seam_topology& st, const Constraint_rows& rows, const Variable_rows& incidence,
               const Face_corners& fc, const std::vector<Reference_triangle>& refs, const std::vector<char>& excluded,
               const std::vector<std::vector<int> >& regions, const std::vector<double>& x,
               const std::vector<double>* target, std::string& message)
  {
    // regions whose variables share a constraint row (e.g. the two ends of a cut edge) move together:
    // they are one region from here on (its smallest index). Marker arrays over the mesh instead of sorted lists and
    // binary searches, and only the rows of the regions' variables: the 302K-face bunny's polish problem (50K faces)
    // built in about 60 ms instead of 88, the same problem
    std::vector<int> region_of(std::size_t(cm.n_vertices), -1);
    for(std::size_t i = 0; i < regions.size(); ++i)
      for(int v : regions[i]) region_of[std::size_t(v)] = int(i);
    std::vector<char> is_touched(fc.halfedge.size(), 0);
    for(const std::vector<int>& region : regions)
      for(int v : region)
        for(int f : fc.vertex_faces[v]) is_touched[std::size_t(f)] = 1;
    std::vector<int> touched;                                  // the faces with a corner in a region, increasing
    for(std::size_t f = 0; f < is_touched.size(); ++f) if(is_touched[f]) touched.push_back(int(f));
    std::vector<int> var_local(2 * std::size_t(st.n_sectors), -1);   // per variable: its region, then its index in vars
    for(int f : touched)
      for(int h : fc.halfedge[std::size_t(f)])
        for(int c = 0; c < 2; ++c) var_local[2 * std::size_t(st.sector_of[h]) + std::size_t(c)] = region_of[std::size_t(cm.target[h])];
    vars.clear(); var_region.clear();
    for(std::size_t var = 0; var < var_local.size(); ++var) if(var_local[var] >= 0) vars.push_back(int(var));
    {
      Union_find uf(int(regions.size()));
      for(int var : vars)
        for(std::size_t q = incidence.start[std::size_t(var)]; q < incidence.start[std::size_t(var) + 1]; ++q) {
          const std::size_t i = std::size_t(incidence.row[q]);
          for(std::size_t k = rows.start[i]; k < rows.start[i + 1]; ++k) {
            const int r = var_local[std::size_t(rows.col[k])];
            if(r >= 0) uf.unite(var_local[std::size_t(var)], r);
          }
        }
      for(int& r : region_of) if(r >= 0) r = uf.find(r);
      for(std::size_t l = 0; l < vars.size(); ++l) {
        var_region.push_back(uf.find(var_local[std::size_t(vars[l])]));
        var_local[std::size_t(vars[l])] = int(l);
      }
    }
    // The basis N: the pivot rule of the IRREF for the untangling, the fill-reducing order where there is one
    // (AUTOMATIC_PIVOT_ORDER, column_ordering.h) for the polish (with a target). Newton's method does not depend
    // on the basis, but rounding does: the eps continuation of the untangling follows it (with the order,
    // duck_qc_8 in default mode ends with 4 wound vertices instead of 2 and a max change of 1.05 instead of 0.73
    // cells), the polish does not (the same max / RMS change to 6 digits on the shared maps), and there the
    // sparser basis makes the knight's polish 2x faster (89K -> 25K Hessian terms of the faces, 11K -> 6K
    // nonzeros of N^T H N)
    const Pivot_order order = target != nullptr ? AUTOMATIC_PIVOT_ORDER : PIVOT_RULE;
    Status s = build_region_space(rows, incidence, vars, order, space, message);
    if(s != SUCCESS) return s;

    auto local = [&](int var) -> long { return var_local[std::size_t(var)]; };
    faces.clear();
    face_w.clear();
    face_BM.clear();
    double area_sum = 0;
    std::vector<std::pair<int, std::pair<int, double> > > terms;   // (coordinate 2m + c, (w, coefficient))
    for(int f : touched) {
      if(excluded[std::size_t(f)]) continue;
      Face e;
      e.face = f;
      e.region = -1;
      const Reference_triangle& r = refs[std::size_t(f)];
      e.area = r.area;
      area_sum += r.area;
      double p[3][2];
      terms.clear();
      for(int m = 0; m < 3; ++m) {
        const int sec = st.sector_of[fc.halfedge[std::size_t(f)][m]];
        if(region_of[std::size_t(cm.target[fc.halfedge[std::size_t(f)][m]])] >= 0)
          e.region = region_of[std::size_t(cm.target[fc.halfedge[std::size_t(f)][m]])];
        for(int c = 0; c < 2; ++c) {
          p[m][c] = x[2 * std::size_t(sec) + std::size_t(c)];
          const long l = local(2 * sec + c);
          if(l < 0) continue;
          for(std::size_t q = space.ptr[std::size_t(l)]; q < space.ptr[std::size_t(l) + 1]; ++q)
            terms.push_back({2 * m + c, {space.w_index[q], space.coef[q]}});
        }
      }
      e.first = face_w.size();
      for(const auto& t : terms) face_w.push_back(t.second.first);
      std::sort(face_w.begin() + long(e.first), face_w.end());
      face_w.erase(std::unique(face_w.begin() + long(e.first), face_w.end()), face_w.end());
      e.n = face_w.size() - e.first;
      e.J0 = r.jacobian(p);
      face_BM.resize(4 * face_w.size(), 0.);
      const int* ws = face_w.data() + e.first;
      double* bm = face_BM.data() + 4 * e.first;
      for(const auto& t : terms) {   // dJ/dx (untangling_energy.h) times the entry of N
        const std::size_t j = std::size_t(std::lower_bound(ws, ws + e.n, t.second.first) - ws);
        const int m = t.first / 2, c = t.first % 2;
        bm[4 * j + std::size_t(2 * c)] += r.q[m][0] * t.second.second;
        bm[4 * j + std::size_t(2 * c + 1)] += r.q[m][1] * t.second.second;
      }
      faces.push_back(e);
    }
    h2 = faces.empty() ? 1. : area_sum / double(faces.size());
    offset.clear();
    if(target != nullptr) {
      offset.resize(vars.size());
      for(std::size_t l = 0; l < vars.size(); ++l) offset[l] = x[std::size_t(vars[l])] - (*target)[std::size_t(vars[l])];
    }
    set_pattern();
    proximity_slot.clear();
    for(std::size_t l = 0; l < offset.size(); ++l)
      for(std::size_t a = space.ptr[l]; a < space.ptr[l + 1]; ++a)
        for(std::size_t b = space.ptr[l]; b < space.ptr[l + 1]; ++b)
          if(space.w_index[b] <= space.w_index[a]) proximity_slot.push_back(slot(space.w_index[a], space.w_index[b]));
    return SUCCESS;
  }

  std::size_t dimension() const { return space.dimension; }

  Eigen::Vector4d jacobian(const Face& e, const std::vector<double>& w) const
  {
    Eigen::Vector4d j = e.J0;
    const int* ws = face_w.data() + e.first;
    const double* bm = face_BM.data() + 4 * e.first;
    for(std::size_t a = 0; a < e.n; ++a) {
      const double wa = w[std::size_t(ws[a])];
      for(int r = 0; r < 4; ++r) j[r] += bm[4 * a + std::size_t(r)] * wa;
    }
    return j;
  }

  // the displacement of variable l at w
  double displacement(std::size_t l, const std::vector<double>& w) const
  {
    double d = 0;
    for(std::size_t q = space.ptr[l]; q < space.ptr[l + 1]; ++q) d += space.coef[q] * w[std::size_t(space.w_index[q])];
    return d;
  }

  // The energy per group g of faces and variables (group_of_face[i] of faces[i], group_of_var[l] of variable l;
  // -1: left out): E[g] += sum_f area f_eps[g](J_f) (+ weight_proximity * proximity) over its faces and variables,
  // D[g] min= their smallest det J, and with `non_positive`, (*non_positive)[g] += its faces with det J <= 0.
  // eps: one per group, or one for all
  void group_values(const std::vector<double>& w, const std::vector<double>& eps, double weight_proximity,
                    const std::vector<int>& group_of_face, const std::vector<int>& group_of_var, std::vector<double>& E,
                    std::vector<double>& D, std::vector<std::size_t>* non_positive = nullptr) const
  {
    for(std::size_t i = 0; i < faces.size(); ++i) {
      const int g = group_of_face[i];
      if(g < 0) continue;
      const Eigen::Vector4d j = jacobian(faces[i], w);
      const double det = untangling_determinant(j);
      D[std::size_t(g)] = (std::min)(D[std::size_t(g)], det);
      if(non_positive != nullptr) (*non_positive)[std::size_t(g)] += !(det > 0);
      E[std::size_t(g)] += faces[i].area * untangling_energy(j, eps[eps.size() == 1 ? 0 : std::size_t(g)]);
    }
    if(weight_proximity > 0)
      for(std::size_t l = 0; l < offset.size(); ++l) {
        const int g = group_of_var[l];
        if(g < 0) continue;
        const double r = offset[l] + displacement(l, w);
        E[std::size_t(g)] += weight_proximity * r * r / h2;
      }
  }

  // The independent parts of the problem: groups of w that no face and no variable's displacement couple (the
  // energy is a sum over them). Returns their number; per w, face and variable its group (-1: a face or a
  // variable with no w, a constant term)
  int components(std::vector<int>& group_of_w, std::vector<int>& group_of_face, std::vector<int>& group_of_var) const
  {
    Union_find uf(int(space.dimension));
    for(const Face& e : faces)
      for(std::size_t a = 1; a < e.n; ++a) uf.unite(face_w[e.first], face_w[e.first + a]);
    for(std::size_t l = 0; l < vars.size(); ++l)
      for(std::size_t q = space.ptr[l] + 1; q < space.ptr[l + 1]; ++q) uf.unite(space.w_index[space.ptr[l]], space.w_index[q]);
    std::vector<int> id(space.dimension, -1);
    int n = 0;
    group_of_w.resize(space.dimension);
    for(std::size_t i = 0; i < space.dimension; ++i) {
      int& r = id[std::size_t(uf.find(int(i)))];
      if(r < 0) r = n++;
      group_of_w[i] = r;
    }
    group_of_face.resize(faces.size());
    for(std::size_t i = 0; i < faces.size(); ++i) group_of_face[i] = faces[i].n > 0 ? group_of_w[std::size_t(face_w[faces[i].first])] : -1;
    group_of_var.resize(vars.size());
    for(std::size_t l = 0; l < vars.size(); ++l)
      group_of_var[l] = space.ptr[l] < space.ptr[l + 1] ? group_of_w[std::size_t(space.w_index[space.ptr[l]])] : -1;
    return n;
  }

  // the gradient g and, with `hessian`, the PSD Hessian (added to the values of H, which the caller sets to 0 in the
  // columns of the groups first) of the energy of the groups that are not -1 (group_values()); the other entries of g
  // are 0, those of H untouched
  void derivatives(const std::vector<double>& w, const std::vector<double>& eps, double weight_proximity,
                   const std::vector<int>& group_of_face, const std::vector<int>& group_of_var, Eigen::VectorXd& g,
                   bool hessian)
  {
    g.setZero();
    double* values = H.valuePtr();
    std::vector<double> HB;
    for(std::size_t i = 0; i < faces.size(); ++i) {
      const Face& e = faces[i];
      const int group = group_of_face[i];
      if(group < 0) continue;
      Eigen::Vector4d gj;
      Eigen::Matrix4d hj;
      untangling_energy(jacobian(e, w), eps[eps.size() == 1 ? 0 : std::size_t(group)], gj, hessian ? &hj : nullptr);
      const std::size_t n = e.n;
      const int* ws = face_w.data() + e.first;
      const double* BM = face_BM.data() + 4 * e.first;
      for(std::size_t a = 0; a < n; ++a) {
        const double* bm = BM + 4 * a;
        g[ws[a]] += e.area * (bm[0] * gj[0] + bm[1] * gj[1] + bm[2] * gj[2] + bm[3] * gj[3]);
      }
      if(!hessian) continue;
      HB.resize(4 * n);                                   // hj BM, column by column
      for(std::size_t a = 0; a < n; ++a) {
        const double* bm = BM + 4 * a;
        for(int r = 0; r < 4; ++r)
          HB[4 * a + std::size_t(r)] = hj(r, 0) * bm[0] + hj(r, 1) * bm[1] + hj(r, 2) * bm[2] + hj(r, 3) * bm[3];
      }
      const int* slots = face_slot.data() + e.slots;
      for(std::size_t a = 0; a < n; ++a)
        for(std::size_t b = 0; b <= a; ++b) {
          const double* ba = BM + 4 * a;
          const double* hb = &HB[4 * b];
          values[*slots++] += e.area * (ba[0] * hb[0] + ba[1] * hb[1] + ba[2] * hb[2] + ba[3] * hb[3]);
        }
    }
    if(weight_proximity > 0) {
      const int* slots = proximity_slot.data();
      for(std::size_t l = 0; l < offset.size(); ++l) {
        if(group_of_var[l] < 0) {                            // its slots, skipped
          if(hessian)
            for(std::size_t a = space.ptr[l]; a < space.ptr[l + 1]; ++a)
              for(std::size_t b = space.ptr[l]; b < space.ptr[l + 1]; ++b) slots += space.w_index[b] <= space.w_index[a] ? 1 : 0;
          continue;
        }
        const double c = 2 * weight_proximity / h2, r = offset[l] + displacement(l, w);
        for(std::size_t a = space.ptr[l]; a < space.ptr[l + 1]; ++a) {
          g[space.w_index[a]] += c * r * space.coef[a];
          if(hessian)
            for(std::size_t b = space.ptr[l]; b < space.ptr[l + 1]; ++b)
              if(space.w_index[b] <= space.w_index[a]) values[*slots++] += c * space.coef[a] * space.coef[b];
        }
      }
    }
  }

  // per group g of faces (group_of_face as in group_values()), t[g] min= the largest t such that every face of g with
  // det J > floor at w keeps det J > floor on [w, w + t d] (det J is quadratic in t)
  void group_positive_steps(const std::vector<double>& w, const Eigen::VectorXd& d, double floor,
                            const std::vector<int>& group_of_face, std::vector<double>& t) const
  {
    for(std::size_t i = 0; i < faces.size(); ++i) {
      const int g = group_of_face[i];
      if(g < 0) continue;
      const Face& e = faces[i];
      const Eigen::Vector4d j = jacobian(e, w);
      const double c = untangling_determinant(j) - floor;
      if(!(c > 0)) continue;
      Eigen::Vector4d k = Eigen::Vector4d::Zero();
      const int* ws = face_w.data() + e.first;
      const double* bm = face_BM.data() + 4 * e.first;
      for(std::size_t a = 0; a < e.n; ++a)
        for(int r = 0; r < 4; ++r) k[r] += bm[4 * a + std::size_t(r)] * d[ws[a]];
      const double qa = untangling_determinant(k), qb = j[0] * k[3] + k[0] * j[3] - j[1] * k[2] - k[1] * j[2];
      double root = HUGE_VAL;                             // the smallest positive root of qa t^2 + qb t + c
      if(qa == 0) { if(qb < 0) root = -c / qb; }
      else {
        const double disc = qb * qb - 4 * qa * c;
        if(disc >= 0) {
          const double q = -0.5 * (qb + (qb >= 0 ? std::sqrt(disc) : -std::sqrt(disc)));
          for(double r : {q / qa, q != 0 ? c / q : HUGE_VAL}) if(r > 0) root = (std::min)(root, r);
        }
      }
      t[std::size_t(g)] = (std::min)(t[std::size_t(g)], root);
    }
  }

  // per region: the faces that are not positive at w and the smallest det J
  void region_state(const std::vector<double>& w, std::size_t n_regions, std::vector<std::size_t>& bad,
                    std::vector<double>& det_min) const
  {
    bad.assign(n_regions, 0);
    det_min.assign(n_regions, HUGE_VAL);
    for(const Face& e : faces) {
      if(e.region < 0) continue;
      const double D = untangling_determinant(jacobian(e, w));
      bad[std::size_t(e.region)] += !(D > 0);
      det_min[std::size_t(e.region)] = (std::min)(det_min[std::size_t(e.region)], D);
    }
  }

private:
  // H's pattern: the lower triangle of the union of the cliques of the w that appear together in a face or, with a
  // target, in the displacement of a variable (its proximity term), and the diagonal; the rows of each column are
  // collected with a marker array (no list of duplicates to sort). And the faces' slots: once a column's rows are
  // numbered, every face with that w reads there the slots of its pairs (no search: the dragon's polish problem with
  // the pivot rule's basis has 1.4M face slots, about 45 ms of binary searches per build)
  void set_pattern()
  {
    const bool proximity = !offset.empty();
    const int n_groups = int(faces.size() + (proximity ? vars.size() : 0));
    auto members = [&](int g, auto&& visit) {
      if(g < int(faces.size())) {
        const Face& e = faces[std::size_t(g)];
        for(std::size_t a = e.first; a < e.first + e.n; ++a) visit(face_w[a]);
        return;
      }
      const std::size_t l = std::size_t(g) - faces.size();
      for(std::size_t q = space.ptr[l]; q < space.ptr[l + 1]; ++q) visit(space.w_index[q]);
    };
    Index_lists groups_of;                                     // w -> the groups it appears in
    groups_of.build(int(space.dimension), [&](auto emit) {
      for(int g = 0; g < n_groups; ++g) members(g, [&](int a) { emit(a, g); });
    });
    std::size_t n_slots = 0;
    for(Face& e : faces) { e.slots = n_slots; n_slots += e.n * (e.n + 1) / 2; }
    face_slot.resize(n_slots);
    std::vector<int> outer(1, 0), inner, mark(space.dimension, -1), column, position(space.dimension, 0);
    for(int b = 0; b < int(space.dimension); ++b) {
      column.assign(1, b);
      mark[std::size_t(b)] = b;
      for(int g : groups_of[b])
        members(g, [&](int a) { if(a > b && mark[std::size_t(a)] != b) { mark[std::size_t(a)] = b; column.push_back(a); } });
      std::sort(column.begin(), column.end());
      for(std::size_t i = 0; i < column.size(); ++i) position[std::size_t(column[i])] = int(inner.size() + i);
      inner.insert(inner.end(), column.begin(), column.end());
      outer.push_back(int(inner.size()));
      for(int g : groups_of[b]) {                              // the slots (w[a], w[j] = b), a >= j, of the faces with b
        if(g >= int(faces.size())) continue;
        const Face& e = faces[std::size_t(g)];
        const int* ws = face_w.data() + e.first;
        const std::size_t j = std::size_t(std::lower_bound(ws, ws + e.n, b) - ws);
        for(std::size_t a = j; a < e.n; ++a) face_slot[e.slots + a * (a + 1) / 2 + j] = position[std::size_t(ws[a])];
      }
    }
    const std::vector<double> zeros(inner.size(), 0.);
    H = Eigen::Map<const Matrix>(Eigen::Index(space.dimension), Eigen::Index(space.dimension), Eigen::Index(inner.size()),
                                 outer.data(), inner.data(), zeros.data());
  }

  int slot(int a, int b) const   // index of (a, b), a >= b, in H's values
  {
    const int* first = H.innerIndexPtr() + H.outerIndexPtr()[b];
    const int* last = H.innerIndexPtr() + H.outerIndexPtr()[b + 1];
    return int(std::lower_bound(first, last, a) - H.innerIndexPtr());
  }
};

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_REGION_PROBLEM_H
