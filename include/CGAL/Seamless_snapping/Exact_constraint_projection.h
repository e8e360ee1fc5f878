// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_EXACT_CONSTRAINT_PROJECTION_H
#define CGAL_SEAMLESS_SNAPPING_EXACT_CONSTRAINT_PROJECTION_H

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/Projection_report.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_system.h>
#include <CGAL/Seamless_snapping/internal/projection/irref.h>
#include <CGAL/Seamless_snapping/internal/projection/evaluation.h>
#include <CGAL/Seamless_snapping/internal/projection/exact_input_check.h>
#include <CGAL/Seamless_snapping/internal/projection/least_squares_projection.h>
#include <CGAL/Seamless_snapping/internal/timing.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 *
 * Projects a vector of doubles x̄ onto the solution space of an integer linear system `C x = b`
 * such that the result `x` consists of IEEE doubles and satisfies every equation *exactly* in real
 * arithmetic (Mandad & Campen 2019, Sec. 4, Alg. 1–5, with the addendum's Eq. 2' for `b != 0`).
 *
 * Like a factorization, the work is split by what changes:
 * - `initialize(C, b)` once per system: fraction-free Gauss–Jordan elimination of `[C | b]` into
 *   integer reduced row echelon form (IRREF, Sec. 4.1, Alg. 1–2) with sparse pivoting, the
 *   free/implied split, and the divisor (lcm of pivots) of every free variable (Alg. 4).
 *   Integers are 64-bit with overflow detection; on any overflow the elimination is redone in
 *   `CGAL::Gmpz`, so the IRREF is exact either way.
 *   In the minimal-change mode (`Projection_options::minimal_change`, the default) also the sparse
 *   LDL^T factorization of `C C^T` for the floating-point projection.
 * - `project(x̄, x)` per input vector: if x̄ already satisfies every row exactly, x = x̄ bit-identical.
 *   Otherwise, in the minimal-change mode, x̄ is first replaced by its L2-closest point on `C x = b`
 *   computed in floating point (beyond Sec. 4.2: the correction is spread over all variables); then
 *   the fixed-point grid `F_delta` from `max |x̄|` (Sec. 4.3),
 *   free variables rounded to multiples of their divisors (Alg. 3–4; for `b != 0` shifted by a
 *   particular solution of the per-row divisibility congruences, addendum Eq. 2'), implied variables
 *   by the safe dot product (Alg. 5), and a final exact integer check of every row of the
 *   *original* `C` before `x` is written.
 * - Wide-range systems (b = 0): when the result on the common grid changes x̄ by much more than x̄
 *   violates `C x = b` (`Projection_report::large_change`, e.g. a doubling chain whose smallest
 *   values lie below the grid quantum and round to 0), or the common grid has no room (`RANGE_EXCEEDED`),
 *   `project()` also evaluates with one quantum per IRREF row (the result is then an exact double
 *   solution near x̄ of the kind Addendum A allows, when one exists) and keeps it if it passes the same
 *   exact check of every row and changes x̄ less (`Projection_report::per_row_grids`).
 *
 * Shapes and units: `C` is m × n with integer entries (one row per constraint); `b` has m integer
 * entries; x̄ and `x` have n doubles, in the units of the caller (UV units for parametrizations).
 * A variable that appears in no row is copied unchanged from x̄ to `x`.
 *
 * State: `status()`, `message()` and `statistics()` are valid after `initialize()`. Calling
 * `project()` before `initialize()` is a precondition violation; after a failed `initialize()`,
 * `project()` returns that failure and writes nothing.
 *
 * `x` is exact and near x̄. In the minimal-change mode `||x - x̄||_2` is within grid rounding of the
 * smallest change under the same constraints (measured by `bench_projection`); with
 * `minimal_change = false` it is the paper's point (Sec. 4.2): free variables keep (rounded) input
 * values and implied variables absorb the whole change, often several times the smallest one.
 *
 * \warning For `b != 0` a system may have no solution in doubles (e.g. `3 x = 1`: no dyadic solution): `INFEASIBLE`
 * is then reported, whatever x̄ (also where x̄ alone would ask for a grid that `b` does not fit), never a wrong answer;
 * where dyadic solutions exist but only on a grid finer than the fixed-point range allows
 * (e.g. `2^62 (x0 + x1 + x2) = 2^63 - 1`), `RANGE_EXCEEDED`.
 */
class Exact_constraint_projection
{
public:
  /// \name Construction
  /// @{
  explicit Exact_constraint_projection(const Projection_options& options = Projection_options())
    : m_options(options)
  {}
  /// @}

  /// \name Initialization (per system)
  /// @{

  /*!
   * computes the IRREF of `[C | b]`.
   * \tparam Scalar a built-in integral type or `CGAL::Gmpz`
   * \param C m × n sparse integer matrix (explicit zeros are ignored)
   * \param b random-access range of m integers (`int`, `long`, `std::int64_t`, `CGAL::Gmpz`, ...)
   * \return `SUCCESS`, `INVALID_INPUT` (size mismatch) or `INFEASIBLE` (a row reduces to `0 = b̂_j != 0`)
   */
  template <typename Scalar, int Options, typename StorageIndex, typename BRange>
  Status initialize(const Eigen::SparseMatrix<Scalar, Options, StorageIndex>& C, const BRange& b)
  {
    typedef Eigen::SparseMatrix<Scalar, Options, StorageIndex> M;
    return initialize_impl(std::size_t(C.rows()), std::size_t(C.cols()), b,
      [&](auto&& add) {
        for(Eigen::Index k = 0; k < C.outerSize(); ++k)
          for(typename M::InnerIterator it(C, k); it; ++it)
            add(std::size_t(it.row()), std::size_t(it.col()), it.value());
      });
  }

  /*!
   * computes the IRREF of `[C | b]`, with `C` given as triplets. Duplicate (row, column) pairs
   * are summed, as `Eigen::SparseMatrix::setFromTriplets()` does.
   * \tparam TripletRange a range of objects `t` with `t.row()`, `t.col()` and `t.value()`
   *         (e.g. `Eigen::Triplet<long>`); the value type is integral or `CGAL::Gmpz`
   * \param n_rows m, the number of rows of `C`
   * \param n_cols n, the number of columns of `C`
   * \param triplets the nonzero entries of `C`, with `0 <= row() < m` and `0 <= col() < n`
   * \param b random-access range of m integers, as for the other overload
   */
  template <typename TripletRange, typename BRange>
  Status initialize(std::size_t n_rows, std::size_t n_cols, const TripletRange& triplets, const BRange& b)
  {
    return initialize_impl(n_rows, n_cols, b,
      [&](auto&& add) {
        for(const auto& t : triplets)
          add(std::size_t(t.row()), std::size_t(t.col()), t.value());
      });
  }
  /// @}

  /// \name Projection (per input vector)
  /// @{

  /*!
   * projects x̄ onto `{x | C x = b}` exactly, with `x` in doubles.
   * \tparam XRange random-access range of n `double` (`std::vector<double>`, `Eigen::VectorXd`, ...)
   * \param xbar n input values (NaN/Inf give `INVALID_INPUT`)
   * \param x output; resized to n and written only when the returned status is `SUCCESS`
   * \return a report whose status is one of `SUCCESS`, `INVALID_INPUT`, `INFEASIBLE`,
   *   `RANGE_EXCEEDED`, `SAFE_DOT_FAILED`, `EXACTNESS_CHECK_FAILED`, or the failure of `initialize()`
   * \pre `initialize()` was called
   */
  template <typename XRange>
  Projection_report project(const XRange& xbar, std::vector<double>& x) const
  {
    CGAL_precondition_msg(m_initialized, "Exact_constraint_projection::project() called before initialize()");
    auto t0 = std::chrono::steady_clock::now();
    Projection_report report;
    if(!m_initialized) { report.status = INVALID_INPUT; report.message = "project() called before initialize()"; return report; }
    if(m_status != SUCCESS) { report.status = m_status; report.message = m_message; return report; }
    const std::size_t n = m_statistics.columns;
    if(std::size_t(xbar.size()) != n) {
      report.status = INVALID_INPUT;
      report.message = "x has " + std::to_string(std::size_t(xbar.size())) + " entries, C has " + std::to_string(n) + " columns";
      return report;
    }
    std::vector<double> copy;
    const std::vector<double>& xb = as_doubles(xbar, copy);
    for(std::size_t i = 0; i < n; ++i)
      if(!std::isfinite(xb[i])) { report.status = INVALID_INPUT; report.message = "x̄[" + std::to_string(i) + "] is not finite"; return report; }
    if(input_is_exact(xb)) {                                   // nothing to do: x̄ comes back bit-identical
      report.status = SUCCESS;
      if(m_options.delta_exponent) {
        const internal::Fixed_point_grid grid(*m_options.delta_exponent);
        report.delta_exponent = grid.K; report.delta = grid.delta; report.quantum = grid.quantum;
      }
      report.message = "x̄ satisfies all " + std::to_string(m_statistics.rows) + " rows exactly; returned unchanged";
      x = xb;                                                  // (x may be x̄ itself)
      report.project_ms = internal::ms_since(t0);
      return report;
    }
    std::vector<double> start, result;
    if(m_least_squares) {                                // minimal-change mode: snap the L2-closest point
      const auto t1 = std::chrono::steady_clock::now();
      m_least_squares->project(m_b_double, xb, start);
      report.least_squares_ms = internal::ms_since(t1);
      if(std::all_of(start.begin(), start.end(), [](double v) { return std::isfinite(v); })) evaluate(start, result, report);
      else { report.status = INVALID_INPUT; report.message = "the floating-point projection is not finite"; }
      report.minimal_change = report.status == SUCCESS;
    }
    if(!report.minimal_change) {
      const double ls_ms = report.least_squares_ms;
      const std::string note = m_least_squares ? " (snapping the floating-point projection failed: " + report.message + ")"
                                                       : std::string();
      report = Projection_report();
      report.least_squares_ms = ls_ms;
      evaluate(xb, result, report);
      if(report.status == SUCCESS) report.message += note;
    }
    if(report.status == SUCCESS) {
      if(report.minimal_change) {                        // the evaluation measured from the projected point: now from x̄
        internal::measure_change(xb, result, report);
        report.input_violation = internal::scaled_input_violation(m_system, xb);
        report.large_change = report.max_abs_change > Projection_report::large_change_factor * report.input_violation;
        report.message = "all " + std::to_string(m_statistics.rows) + " rows hold exactly; " + std::to_string(report.changed_variables)
                       + " of " + std::to_string(n) + " variables changed, by at most " + std::to_string(report.max_abs_change)
                       + " (floating-point projection snapped)";
      }
      x.swap(result);
    }
    report.project_ms = internal::ms_since(t0);
    return report;
  }

  /// the same, with the output in an `Eigen::VectorXd` (resized to n and written only on `SUCCESS`).
  template <typename XRange>
  Projection_report project(const XRange& xbar, Eigen::VectorXd& x) const
  {
    std::vector<double> result;
    const Projection_report report = project(xbar, result);
    if(report.status == SUCCESS) x = Eigen::Map<const Eigen::VectorXd>(result.data(), Eigen::Index(result.size()));
    return report;
  }
  /// @}

  /// \name Access (valid after `initialize()`)
  /// @{
  Status status() const { return m_status; }                        ///< outcome of `initialize()`
  const std::string& message() const { return m_message; }          ///< details of `status()`
  const Irref_statistics& statistics() const { return m_statistics; }///< sizes, rank, fill-in, integer type
  std::size_t number_of_variables() const { return m_statistics.columns; } ///< n
  std::size_t number_of_constraints() const { return m_statistics.rows; }  ///< m
  /// @}

private:
  internal::Pivot_order pivot_order() const
  {
    return m_options.fill_reducing_order ? internal::AUTOMATIC_PIVOT_ORDER : internal::PIVOT_RULE;
  }

  // x̄ as a vector of doubles: the caller's own where it is one (1M-row system: no copy of 16 MB), else a copy
  static const std::vector<double>& as_doubles(const std::vector<double>& xbar, std::vector<double>&) { return xbar; }
  template <typename XRange>
  static const std::vector<double>& as_doubles(const XRange& xbar, std::vector<double>& copy)
  {
    copy.resize(std::size_t(xbar.size()));
    for(std::size_t i = 0; i < copy.size(); ++i) copy[i] = double(xbar[i]);
    return copy;
  }

  // x̄ satisfies every row exactly (and, with a given grid, its constrained values lie on that grid,
  // as a caller sharing the grid relies on)
  bool input_is_exact(const std::vector<double>& xb) const
  {
    if(m_options.delta_exponent) {
      const internal::Fixed_point_grid grid(*m_options.delta_exponent);
      for(std::size_t i = 0; i < xb.size(); ++i)
        if(m_system.column_used(i) && !grid.contains(xb[i])) return false;
    }
    return internal::satisfies_exactly(m_system, xb);
  }

  void evaluate(const std::vector<double>& xb, std::vector<double>& result, Projection_report& report) const
  {
    if(m_irref64) internal::evaluate(*m_irref64, m_system, xb, m_options, result, report);
    else          internal::evaluate(*m_irrefz, m_system, xb, m_options, result, report);
  }

  // The floating-point copy of the canonical rows and the factorization of C C^T (minimal-change
  // mode). A failed factorization only turns the mode off (x̄ itself is then snapped).
  void initialize_least_squares()
  {
    const internal::Integer_system& sys = m_system;
    std::vector<Eigen::Triplet<double> > entries;
    entries.reserve(sys.nonzeros());
    m_b_double.assign(sys.n_rows, 0.);
    for(std::size_t i = 0; i < sys.n_rows; ++i) {
      if(sys.fits_int64) {
        m_b_double[i] = double(sys.rows64.b[i]);
        for(std::size_t q = sys.rows64.ptr[i]; q < sys.rows64.ptr[i + 1]; ++q)
          entries.emplace_back(int(i), int(sys.rows64.e[q].col), double(sys.rows64.e[q].val));
      } else {
        m_b_double[i] = CGAL::to_double(sys.rowsz.b[i]);
        for(std::size_t q = sys.rowsz.ptr[i]; q < sys.rowsz.ptr[i + 1]; ++q)
          entries.emplace_back(int(i), int(sys.rowsz.e[q].col), CGAL::to_double(sys.rowsz.e[q].val));
      }
    }
    internal::Least_squares_projection::Matrix C(Eigen::Index(sys.n_rows), Eigen::Index(sys.n_cols));
    C.setFromTriplets(entries.begin(), entries.end());
    std::string ignored;
    m_least_squares.reset(new internal::Least_squares_projection());
    if(m_least_squares->initialize(C, std::vector<double>(), ignored) != SUCCESS) m_least_squares.reset();
  }

  template <typename BRange, typename Visit>
  Status initialize_impl(std::size_t n_rows, std::size_t n_cols, const BRange& b, Visit visit)
  {
    auto t0 = std::chrono::steady_clock::now();
    m_initialized = true;
    m_irref64.reset(); m_irrefz.reset();
    m_least_squares.reset();
    m_statistics = Irref_statistics();
    m_statistics.rows = n_rows; m_statistics.columns = n_cols;
    m_message.clear();
    m_status = internal::build_integer_system(n_rows, n_cols, b, visit, m_system, m_message);
    if(m_status == SUCCESS) {
      m_statistics.input_nonzeros = m_system.nonzeros();
      m_statistics.constrained_columns = m_system.constrained_columns();
      bool need_gmp = m_options.force_multiprecision || !m_system.fits_int64;
      if(!need_gmp) {
        try {
          m_irref64.reset(new internal::Irref<std::int64_t>());
          m_status = internal::compute_irref(m_system, *m_irref64, m_message, pivot_order());
        } catch(const internal::Integer_overflow&) {
          m_irref64.reset();
          need_gmp = true;
        }
      }
      if(need_gmp) {
        m_irrefz.reset(new internal::Irref<CGAL::Gmpz>());
        m_status = internal::compute_irref(m_system, *m_irrefz, m_message, pivot_order());
        // When the result fits in 64 bits (e.g. forced Gmpz on a small system) evaluation is faster in int64.
        std::unique_ptr<internal::Irref<std::int64_t>> narrow(new internal::Irref<std::int64_t>());
        if(m_status == SUCCESS && !m_options.force_multiprecision && internal::narrow_irref(*m_irrefz, *narrow)) {
          m_irref64 = std::move(narrow);
          m_irrefz.reset();
        }
        m_statistics.multiprecision = true;
      }
      if(m_status == SUCCESS) {
        if(m_irref64) m_irref64->fill_statistics(m_statistics);
        else          m_irrefz->fill_statistics(m_statistics);
        if(m_options.minimal_change) initialize_least_squares();
      } else {
        m_irref64.reset(); m_irrefz.reset();
      }
    }
    m_statistics.initialize_ms = internal::ms_since(t0);
    return m_status;
  }

  Projection_options m_options;
  bool m_initialized = false;
  Status m_status = INVALID_INPUT;
  std::string m_message = "not initialized";
  Irref_statistics m_statistics;
  internal::Integer_system m_system;                      // the original rows, for the final exact check
  std::unique_ptr<internal::Irref<std::int64_t>> m_irref64; // exactly one of the two is set after a successful initialize()
  std::unique_ptr<internal::Irref<CGAL::Gmpz>> m_irrefz;
  std::unique_ptr<internal::Least_squares_projection> m_least_squares;   // set only in the minimal-change mode
  std::vector<double> m_b_double;
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 * one-shot projection: `initialize(C, b)` then `project(xbar, x)`.
 * \return the projection report; its status is the failure of `initialize()` if that failed
 */
template <typename Scalar, int Options, typename StorageIndex, typename BRange, typename XRange>
Projection_report project_exactly(const Eigen::SparseMatrix<Scalar, Options, StorageIndex>& C, const BRange& b,
                                  const XRange& xbar, std::vector<double>& x,
                                  const Projection_options& options = Projection_options())
{
  Exact_constraint_projection p(options);
  if(p.initialize(C, b) != SUCCESS) {
    Projection_report r; r.status = p.status(); r.message = p.message(); return r;
  }
  return p.project(xbar, x);
}

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_EXACT_CONSTRAINT_PROJECTION_H
