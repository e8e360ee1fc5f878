// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_PROJECTION_REPORT_H
#define CGAL_SEAMLESS_SNAPPING_PROJECTION_REPORT_H

#include <CGAL/Seamless_snapping/Status.h>

#include <cstddef>
#include <optional>
#include <string>

namespace CGAL {
namespace Seamless_snapping {

/*!
 * \ingroup PkgSeamlessSnappingRef
 * Options of `Exact_constraint_projection`.
 */
struct Projection_options
{
  /// Extra bits of headroom in the fixed-point range: `delta = 2^K` with
  /// `K = max_i e(|v_i|) + delta_margin_bits`, where `e(v)` is the binary exponent with
  /// `|v| < 2^e(v)` and `v` runs over the constrained entries of x̄ and, for `b != 0`, the values `b̂_j / p_j` of the IRREF (implied values when the free variables are 0).
  /// The paper's choice (Sec. 4.3, "+1 adds a margin") is `1`: an implied value may then deviate
  /// from its input by up to `max |x̄|` before `RANGE_EXCEEDED` (Sec. 7).
  int delta_margin_bits = 1;
  /// Skips the 64-bit elimination and eliminates in `CGAL::Gmpz` from the start.
  bool force_multiprecision = false;
  /// When set, `K` (with `delta = 2^K`) is taken from here instead of from x̄, so that several
  /// projections (e.g. the node system and the propagation of Sec. 5.3) share one grid `F_delta`.
  /// Whether given or taken from x̄, `K` must lie in [-1022, 1023] (delta a normal double, the quantum
  /// `2^(K-52)` at least the smallest subnormal): otherwise `project()` returns `RANGE_EXCEEDED`.
  /// Within this range the projection with `minimal_change = false` is scale covariant: for `b = 0`, x̄ scaled by
  /// `2^j` gives `x` scaled by `2^j`, bit for bit; with `minimal_change` (the default) too while the nonzero |x̄_i| stay
  /// within about `2^-800 .. 2^800` (the floating-point least-squares step over- or underflows near the ends of the
  /// double range: at `K = 1016` or `-998` the results differ, found by a sweep; `fuzz_projection` checks that range).
  /// An input that already satisfies every row exactly is then returned unchanged only if its
  /// constrained values lie on that grid.
  std::optional<int> delta_exponent;
  /// Minimal-change mode (default): x̄ is first projected onto `C x = b` in floating point (the
  /// L2-closest point, by a sparse LDL^T factorization of `C C^T` with iterative refinement,
  /// computed in `initialize()`), and that point is snapped exactly (Sec. 4.3). The change
  /// `||x - x̄||_2` is then close to the smallest possible one; what is left is grid rounding
  /// (a few quanta `2^(K-52)` per variable). `false` gives the paper's asymmetric choice (Sec. 4.2):
  /// free variables keep their rounded inputs and the implied variables absorb the whole correction.
  /// If snapping the projected point fails (e.g. `RANGE_EXCEEDED`), x̄ itself is snapped.
  /// \warning The factorization makes `initialize()` much slower on large systems (measured: a 20k-row
  /// seamless system 150-220 ms instead of 5 ms; the factor of `C C^T` has 480k nonzeros there, and
  /// CHOLMOD's orderings and supernodal factorization were no faster). Set `false` for large systems
  /// where speed matters more than the size of the change.
  bool minimal_change = true;
  /// Pivot order of the IRREF (Sec. 4.1). `true` (default): the pivot rule (unit pivots first, then the
  /// column with the fewest nonzeros) runs on a budget of nonzeros (those of `C` plus one per 16 rows);
  /// past it, or at once where at least 90% of the columns lie in exactly two rows (long chains of
  /// rows: the sides of cuts, as in per-corner seam systems, where the pivot rule alone always fills
  /// in), the elimination runs with the pivots taken in a fill-reducing column order
  /// chosen by the shape of the row graph (a breadth-first front order on closed surface-like row
  /// graphs, a static minimum degree order on seams, SuiteSparse COLAMD's in between), when the build
  /// has COLAMD (CMake option `SEAMLESS_SNAPPING_USE_COLAMD`, on by default). On per-corner seam
  /// systems (one variable pair per texture corner) this fills in 2-8 times less (Directional's dragon:
  /// 23.5k IRREF nonzeros instead of 134k; libQEx's duck: 1.35M instead of 3.74M; manual, "Pivot order
  /// and fill-in"). `false`: the pivot rule alone.
  /// Both give exact solutions, with other free variables, so the results differ slightly.
  bool fill_reducing_order = true;
  /// With 2 or more, `project()` evaluates the implied variables (Alg. 3 with the safe dot product, Alg. 5) in two
  /// halves of the IRREF rows at once, on two threads: each row depends on the free variables only, so the result,
  /// status and message are those of one thread, bit for bit. `0` takes the machine's cores.
  unsigned number_of_threads = 1;
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 * What `Exact_constraint_projection::initialize()` found (valid after `initialize()`).
 */
struct Irref_statistics
{
  std::size_t rows = 0;                 ///< m, rows of C as given
  std::size_t columns = 0;              ///< n, number of variables
  std::size_t input_nonzeros = 0;       ///< nonzero entries of C (explicit zeros and cancelled duplicates removed)
  std::size_t rank = 0;                 ///< rows with a pivot in the IRREF
  std::size_t dependent_rows = 0;       ///< rows that became zero (linearly dependent, b consistent)
  std::size_t constrained_columns = 0;  ///< columns with a nonzero entry in C
  std::size_t free_variables = 0;       ///< constrained columns without a pivot
  std::size_t implied_variables = 0;    ///< pivot columns (= rank)
  std::size_t irref_nonzeros = 0;       ///< nonzeros of the IRREF matrix Ĉ (fill-in = irref_nonzeros vs input_nonzeros)
  std::size_t eliminations = 0;         ///< fraction-free row updates performed
  std::string max_abs_coefficient = "0";///< largest |entry| of Ĉ and b̂, exact decimal
  double max_abs_coefficient_double = 0;///< the same, rounded to double
  bool multiprecision = false;          ///< true when the elimination ran in `CGAL::Gmpz` (overflow of int64 or forced)
  double initialize_ms = 0;             ///< wall-clock time of `initialize()` (the factorization of `C C^T` included)
  /// the integer type the IRREF was computed in: "int64" or "Gmpz"
  const char* integer_type() const { return multiprecision ? "Gmpz" : "int64"; }
};

/*!
 * \ingroup PkgSeamlessSnappingRef
 * What one call of `Exact_constraint_projection::project()` did.
 */
struct Projection_report
{
  Status status = INVALID_INPUT;   ///< `SUCCESS` iff `C x = b` holds exactly and `x` was written
  std::string message;             ///< why it failed (names row/column), or a one-line summary
  int delta_exponent = 0;          ///< K, with `delta = 2^K` (Sec. 4.3); where K from `delta_margin_bits` falls outside the doubles, one past their range (-1023 or 1024; `RANGE_EXCEEDED`)
  double delta = 0;                ///< the fixed-point range is (-delta, delta)
  double quantum = 0;              ///< spacing s = 2^(K-52) of the grid F_delta; every constrained output is a multiple of s
                                   ///< (`K`, `delta` and `quantum` are 0 when x̄ already satisfied every row exactly
                                   ///< and was returned bit-identical)
  double max_abs_change = 0;       ///< max_i |x_i - x̄_i| (rounded to double)
  std::size_t changed_variables = 0; ///< number of i with x_i != x̄_i
  /// max_i |C_i x̄ - b_i| / ||C_i||_2 over the rows of `C`: how far x̄ is from the solution space,
  /// evaluated in double arithmetic (a diagnostic, not a proof; 0 for an exactly feasible x̄ up to rounding)
  double input_violation = 0;
  /// true when the change is huge relative to how far x̄ was from satisfying `C x = b`:
  /// `max_abs_change > large_change_factor * input_violation` (with a zero violation, any change).
  /// The result is still exact; it is just not a small correction of x̄ (e.g. values far below the
  /// grid quantum of Sec. 4.3 were rounded to 0). See `large_change_factor`.
  bool large_change = false;
  /// the factor of `large_change`: 2^20
  static constexpr double large_change_factor = 1048576.;
  /// true when x comes from the evaluation with one quantum per IRREF row (b = 0 only), which is
  /// tried when the common grid F_delta gives a `large_change` or `RANGE_EXCEEDED` and is kept only
  /// if it is exact and changes x̄ less. Then `quantum` is the finest quantum used (every constrained
  /// output is a multiple of it) and `delta_exponent`/`delta` describe the common grid tried first.
  bool per_row_grids = false;
  double project_ms = 0;           ///< wall-clock time of `project()`
  double least_squares_ms = 0;     ///< part of it spent on the floating-point projection (`Projection_options::minimal_change`)
  bool minimal_change = false;     ///< true iff the floating-point projection of x̄ was snapped (not x̄ itself)
};

} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_PROJECTION_REPORT_H
