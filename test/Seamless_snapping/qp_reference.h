// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// The exact rational reference used by the tests (test_projection, test_snap) and the exact-arithmetic
// study (benchmark/bench_exact_study.cpp, paper Sec. 6.1): the L2 optimum
//     x* = argmin ||x - x̄||_2^2  s.t.  C x = b
// by CGAL's QP solver with the exact type CGAL::Gmpzf, returned as CGAL::Gmpq. Not part of the package API.

#ifndef CGAL_SEAMLESS_SNAPPING_TEST_QP_REFERENCE_H
#define CGAL_SEAMLESS_SNAPPING_TEST_QP_REFERENCE_H

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <cstddef>
#include <vector>

namespace SS_test {

// the exact value m 2^e of a Gmpzf
inline CGAL::Gmpq to_gmpq(const CGAL::Gmpzf& z)
{
  CGAL::Gmpq r(z.man());
  const long e = z.exp();
  if(e >= 0) mpq_mul_2exp(r.mpq(), r.mpq(), (unsigned long)e);
  else       mpq_div_2exp(r.mpq(), r.mpq(), (unsigned long)(-e));
  return r;
}
inline CGAL::Gmpq to_gmpq(const CGAL::Quotient<CGAL::Gmpzf>& q) { return to_gmpq(q.numerator()) / to_gmpq(q.denominator()); }

// One nonzero C_ij (|value| < 2^53, so that the QP's double input is exact).
struct Qp_entry { std::size_t row, col; long value; };

// x* for C (m x n, given by its nonzeros) and b; false when the solver does not report an optimum.
// Every input is passed to the solver exactly (doubles); the solution is exact.
inline bool l2_optimum_qp(std::size_t m, std::size_t n, const std::vector<Qp_entry>& C, const std::vector<long>& b,
                          const std::vector<double>& xbar, std::vector<CGAL::Gmpq>& x)
{
  CGAL::Quadratic_program<double> qp(CGAL::EQUAL, false, 0, false, 0);   // equalities, free variables
  for(const Qp_entry& e : C) qp.set_a(int(e.col), int(e.row), double(e.value));   // (variable, row)
  for(std::size_t i = 0; i < m; ++i) qp.set_b(int(i), double(b[i]));
  for(std::size_t j = 0; j < n; ++j) { qp.set_d(int(j), int(j), 2.); qp.set_c(int(j), -2. * xbar[j]); }   // x^T x - 2 x̄^T x
  const CGAL::Quadratic_program_solution<CGAL::Gmpzf> sol = CGAL::solve_quadratic_program(qp, CGAL::Gmpzf());
  if(!sol.is_optimal()) return false;
  x.clear();
  for(auto it = sol.variable_values_begin(); it != sol.variable_values_end(); ++it) x.push_back(to_gmpq(*it));
  return x.size() == n;
}

} // namespace SS_test

#endif // CGAL_SEAMLESS_SNAPPING_TEST_QP_REFERENCE_H
