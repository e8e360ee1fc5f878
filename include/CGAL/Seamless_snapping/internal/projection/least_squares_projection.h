// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_LEAST_SQUARES_PROJECTION_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_LEAST_SQUARES_PROJECTION_H

// The (weighted) L2-closest point of {x | C x = b}, in floating point: the start point of the
// minimal-change mode. Sec. 4.2 of the paper fixes the free variables at their (rounded) inputs, so
// the implied variables absorb the whole correction; projecting x̄ first and snapping the projection
// spreads the correction over all variables, and the exact snap then only moves it by grid quanta.
//
//   y = argmin sum_i w_i (y_i - x̄_i)^2  s.t.  C y = b
//     = x̄ + W^-1 C^T lambda,   (C W^-1 C^T) lambda = b - C x̄          (Lagrange conditions)
//
// C W^-1 C^T is symmetric positive semidefinite; it is singular when rows of C are dependent (a
// closed loop of transitions, a redundant alignment). It is factored once (sparse LDL^T, Eigen's
// SimplicialLDLT with AMD ordering) with a tiny shift eps I, eps = 1e-10 max_j (C W^-1 C^T)_jj, and
// the shift is removed by iterative refinement: y <- y + W^-1 C^T (A + eps I)^-1 (b - C y), until the
// residual stops shrinking. Each step reduces the residual on the range of C by eps / (sigma^2 + eps);
// a component of the residual in the left null space of C (rounding only, as b is consistent)
// is multiplied by C^T and vanishes. Everything is relative (eps to A, weights to each other), so
// y scales with x̄ and b: no dependence on the scale 2^j of the input.
//
// The result is a floating-point approximation, never claimed exact: the exact projection snaps it
// afterwards (Exact_constraint_projection, surface pipeline), and its final check decides.

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/timing.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

class Least_squares_projection
{
public:
  typedef Eigen::SparseMatrix<double, Eigen::RowMajor, int> Matrix;

  // Factors C W^-1 C^T + eps I. `weights`: empty (all 1) or one positive finite weight per column
  // of C; a larger weight makes that variable move less. Returns INVALID_INPUT (with a message) for
  // a bad weight or a failed factorization (non-finite entries); the shifted matrix is positive
  // definite, so dependent rows are no failure.
  Status initialize(const Matrix& C, const std::vector<double>& weights, std::string& message)
  {
    const auto t0 = std::chrono::steady_clock::now();
    m_ready = false;
    m_C = C;
    m_inverse_weight.assign(std::size_t(C.cols()), 1.);
    if(!weights.empty()) {
      if(weights.size() != std::size_t(C.cols())) {
        message = "weights: " + std::to_string(weights.size()) + " values for " + std::to_string(C.cols()) + " variables";
        return INVALID_INPUT;
      }
      for(std::size_t i = 0; i < weights.size(); ++i) {
        if(!(std::isfinite(weights[i]) && weights[i] > 0)) {
          message = "weight of variable " + std::to_string(i) + " is not a positive finite number";
          return INVALID_INPUT;
        }
        m_inverse_weight[i] = 1. / weights[i];
      }
    }
    m_CWt = (m_C * Eigen::Map<const Eigen::VectorXd>(m_inverse_weight.data(), Eigen::Index(m_inverse_weight.size())).asDiagonal()).transpose();
    Eigen::SparseMatrix<double, Eigen::ColMajor, int> A = m_C * m_CWt;
    double max_diagonal = 0;
    for(Eigen::Index j = 0; j < A.rows(); ++j) max_diagonal = (std::max)(max_diagonal, A.coeff(j, j));
    if(!std::isfinite(max_diagonal)) { message = "C W^-1 C^T is not finite"; return INVALID_INPUT; }
    const double eps = max_diagonal > 0 ? 1e-10 * max_diagonal : 1.;
    Eigen::SparseMatrix<double, Eigen::ColMajor, int> shift(A.rows(), A.cols());
    shift.setIdentity();
    A += eps * shift;
    m_solver.compute(A);
    if(m_solver.info() != Eigen::Success) {
      message = "the sparse LDL^T factorization of C W^-1 C^T failed";
      return INVALID_INPUT;
    }
    m_ready = true;
    m_factor_ms = ms_since(t0);
    return SUCCESS;
  }

  bool ready() const { return m_ready; }
  double factor_ms() const { return m_factor_ms; }

  // y: the weighted L2-closest point of {C y = b} to x̄ (floating point). Variables in no row keep
  // x̄ bit-identical (-0.0 included). Returns the number of refinement steps taken.
  int project(const std::vector<double>& b, const std::vector<double>& xbar, std::vector<double>& y) const
  {
    CGAL_precondition(m_ready);
    const Eigen::Index m = m_C.rows(), n = m_C.cols();
    Eigen::Map<const Eigen::VectorXd> bb(b.data(), m), xb(xbar.data(), n);
    Eigen::VectorXd cur = xb, best = xb;
    Eigen::VectorXd r(m);
    residual(bb, cur, r);
    double best_norm = r.lpNorm<Eigen::Infinity>(), previous = best_norm;
    int steps = 0;
    for(int it = 0; it < max_steps && best_norm > 0; ++it) {
      const Eigen::VectorXd lambda = m_solver.solve(r);
      cur += m_CWt * lambda;
      residual(bb, cur, r);
      const double norm = r.lpNorm<Eigen::Infinity>();
      ++steps;
      if(!(norm < best_norm)) break;                 // stagnation (rounding level) or divergence
      best = cur;
      best_norm = norm;
      if(norm > 0.5 * previous && it > 0) break;     // no longer converging fast: at the rounding level
      previous = norm;
    }
    y.assign(best.data(), best.data() + n);
    for(Eigen::Index i = 0; i < n; ++i)
      if(m_CWt.outerIndexPtr()[i + 1] == m_CWt.outerIndexPtr()[i]) y[std::size_t(i)] = xbar[std::size_t(i)];
    return steps;
  }

private:
  // r = b - C x with the accuracy of twice the working precision (Dot2 of Ogita, Rump and Oishi:
  // error-free products by fma, error-free sums by TwoSum). The residual of a nearly feasible x is a
  // sum of nearly cancelling terms; in plain double it would be off by about ulp(max |x|), a grid
  // quantum, and so would the correction.
  void residual(const Eigen::Map<const Eigen::VectorXd>& b, const Eigen::VectorXd& x, Eigen::VectorXd& r) const
  {
    for(Eigen::Index i = 0; i < m_C.rows(); ++i) {
      double s = b[i], c = 0;
      for(Matrix::InnerIterator it(m_C, i); it; ++it) {
        const double p = -it.value() * x[it.col()];
        const double pe = std::fma(-it.value(), x[it.col()], -p);        // p + pe = -C_ij x_j exactly
        const double t = s + p, z = t - s;
        c += ((s - (t - z)) + (p - z)) + pe;                               // TwoSum error + product error
        s = t;
      }
      r[i] = s + c;
    }
  }

  static constexpr int max_steps = 20;
  bool m_ready = false;
  double m_factor_ms = 0;
  Matrix m_C;
  Matrix m_CWt;                                               // W^-1 C^T (row i: variable i)
  std::vector<double> m_inverse_weight;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double, Eigen::ColMajor, int> > m_solver;
};

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_LEAST_SQUARES_PROJECTION_H
