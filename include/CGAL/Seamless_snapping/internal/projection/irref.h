// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_IRREF_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_IRREF_H

// Fraction-free transformation of [C | b] into integer reduced row echelon form (IRREF), Sec. 4.1.
//
// The paper gives a dense Gaussian pass (Alg. 1, IREF) followed by a Jordan pass (Alg. 2). We
// compute the same kind of result in one sparse Gauss–Jordan pass: each time a pivot (row k,
// column c) is chosen, column c is eliminated from *every* other row that contains it, active or
// already pivoted, by the fraction-free update
//     row_i <- (p / g) row_i - (a / g) row_k,   g = gcd(p, a),  p = C_kc, a = C_ic,
// after which row_i (with b_i) is divided by the gcd of its entries (Alg. 1–2, "o <- gcd").
// At the end every pivot column has a single nonzero, in its pivot row: that is the IRREF up to
// the order of the rows, which does not matter for evaluation (Eq. 2 only uses free variables).
//
// Pivoting limits fill-in (Markowitz-like): the next row is one that has a +-1 entry, and among
// those one with fewest nonzeros (then rows without a unit entry, fewest nonzeros first); in it,
// the pivot is an entry of smallest |value|, then of the column with fewest nonzeros (counting
// pivoted rows, which the Jordan step also touches), then the smallest column index. All ties are
// broken by indices, so the same canonical input gives the same IRREF. Rows are taken from the
// queue a few steps before they are eliminated, so that what a step reads can be prefetched
// (see Window).

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/Projection_report.h>
#include <CGAL/Seamless_snapping/internal/projection/column_ordering.h>
#include <CGAL/Seamless_snapping/internal/projection/default_init_allocator.h>
#include <CGAL/Seamless_snapping/internal/projection/huge_page_allocator.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_ops.h>
#include <CGAL/Seamless_snapping/internal/projection/integer_system.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <memory>
#include <type_traits>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

// The elimination's per-entry helpers are inlined into its loop on GCC and Clang: left to the
// compiler, find() and eliminate_column() stayed calls once the loop grew (20k-row seamless system:
// 0.24M of 35M instructions of initialize()).
#if defined(__GNUC__)
#  define CGAL_SEAMLESS_SNAPPING_ALWAYS_INLINE __attribute__((always_inline))
#else
#  define CGAL_SEAMLESS_SNAPPING_ALWAYS_INLINE
#endif

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

enum Column_kind : unsigned char { UNCONSTRAINED_COLUMN = 0, FREE_COLUMN = 1, IMPLIED_COLUMN = 2 };

// How pivots are chosen: automatically (the pivot rule on a budget of nonzeros, then the
// fill-reducing order, see Irref_eliminator::run()), the pivot rule alone, or the order from the
// start (the pivot rule alone when no order is available, see column_ordering.h).
enum Pivot_order { AUTOMATIC_PIVOT_ORDER, PIVOT_RULE, FILL_REDUCING_ORDER };

// The result: one row per pivot, x_{pivot_col} = (rhs - sum val * x_col) / pivot (Eq. 2'),
// where every col of a row is a free column. (The arrays sized by extract() and then written in
// full are Default_init_vectors: not zeroed first.)
template <typename Int>
struct Irref
{
  std::size_t n_cols = 0;
  Default_init_vector<std::uint32_t> pivot_col;   // per pivot row
  Default_init_vector<Int> pivot;                 // per pivot row, > 0
  Default_init_vector<Int> rhs;                   // per pivot row: b̂
  Default_init_vector<std::size_t> ptr;           // free terms of pivot row j: [ptr[j], ptr[j+1])
  Default_init_vector<std::uint32_t> col;
  Default_init_vector<Int> val;
  std::vector<unsigned char> kind;        // Column_kind per column
  Default_init_vector<std::uint32_t> free_columns;// the columns of kind FREE_COLUMN, in increasing order
  std::vector<Int> divisor;               // per column: lcm of the pivots of the rows it appears in (Alg. 4); 1 if none;
                                          // empty when every pivot is 1 (read it through divisor_of())
  Int max_abs = Integer_ops<Int>::from_int64(0);  // largest |entry| of the pivots, rhs and val
  bool unit_pivots = true;                // all pivots are 1: every divisor is 1

  const Int& divisor_of(std::size_t c) const { return unit_pivots ? one : divisor[c]; }
  Int one = Integer_ops<Int>::from_int64(1);
  bool homogeneous = true;                // b̂ = 0
  std::size_t dependent_rows = 0;
  std::size_t eliminations = 0;

  std::size_t rank() const { return pivot.size(); }

  void fill_statistics(Irref_statistics& st) const
  {
    typedef Integer_ops<Int> Ops;
    st.rank = rank();
    st.implied_variables = rank();
    st.free_variables = free_columns.size();
    st.dependent_rows = dependent_rows;
    st.irref_nonzeros = rank() + col.size();
    st.eliminations = eliminations;
    st.max_abs_coefficient = Ops::to_string(max_abs);
    st.max_abs_coefficient_double = Ops::to_double(max_abs);
  }
};

// Converts an IRREF computed in Gmpz to int64 when every number fits.
inline bool narrow_irref(const Irref<CGAL::Gmpz>& z, Irref<std::int64_t>& r)
{
  typedef Integer_ops<CGAL::Gmpz> Z;
  auto conv = [](const auto& in, auto& out) {
    out.resize(in.size());
    for(std::size_t i = 0; i < in.size(); ++i)
      if(!Z::to_int64(in[i], out[i]) || out[i] == std::numeric_limits<std::int64_t>::min()) return false;   // see Integer_ops::negatable
    return true;
  };
  if(!conv(z.pivot, r.pivot) || !conv(z.rhs, r.rhs) || !conv(z.val, r.val) || !conv(z.divisor, r.divisor)) return false;
  Z::to_int64(z.max_abs, r.max_abs);      // fits: it is one of the converted values
  r.n_cols = z.n_cols; r.pivot_col = z.pivot_col; r.ptr = z.ptr; r.col = z.col; r.kind = z.kind; r.free_columns = z.free_columns;
  r.unit_pivots = z.unit_pivots; r.homogeneous = z.homogeneous;
  r.dependent_rows = z.dependent_rows; r.eliminations = z.eliminations;
  return true;
}

template <typename Int>
class Irref_eliminator
{
  typedef Integer_ops<Int> Ops;
  typedef Sparse_entry<Int> Entry;
  enum Row_state : unsigned char { ACTIVE = 0, PIVOT = 1, ZERO = 2 };
  static constexpr bool FLAT = std::is_trivially_copyable<Entry>::value;   // int64: rows live in an arena

  // Data layout. The elimination is bound by memory latency: on seamless systems a step touches
  // one new row and a few new columns at random places. So the per-row and per-column state are
  // each one small aligned record (one cache line fetch), and a column's first two occurrences are
  // stored in its record, where the scan for the rows that hold it finds them.
  //
  // A row's entries (sorted by column) stay in the input array until the row is first modified;
  // then they move to the arena (int64) or to the row's own vector (Gmpz).
  struct alignas(32) Row
  {
    const Entry* data = nullptr;
    std::uint32_t size = 0;
    std::uint32_t stamp = 0;             // stamp of the last column scan that took this row
    std::uint32_t pivot_col = 0;
    Row_state state = ACTIVE;
    bool in_window = false;              // taken from the queue, step pending (see Window)
    unsigned char key = 0;               // queue key when last pushed
    Int b;
  };
  // Rows holding a column: r0, r1, then a linked list in m_pool. Entries may be stale (the row
  // lost the column by cancellation) or repeated (it got the column back); `count` is exact.
  struct alignas(16) Column
  {
    std::uint32_t count = 0;             // rows (active or pivot) containing the column
    std::uint32_t r0 = NIL, r1 = NIL, more = NIL;
  };
  struct Occurrence { std::uint32_t row, next; };

  static constexpr std::uint32_t NNZ_BUCKETS = 64;   // rows with more nonzeros share the last bucket
  static constexpr std::uint32_t NIL = std::uint32_t(-1);

public:
  Status run(const Integer_system& sys, Irref<Int>& out, std::string& message, Pivot_order order)
  {
    // With a fill-reducing column order available, the pivot rule alone goes first, on a budget of
    // nonzeros (those of the input plus one per 16 rows): within it (seamless-like systems numbered
    // by sectors, whose IRREF has fewer nonzeros than the input) it is the faster one and the order
    // would only cost; past it (per-corner seam systems, where the pivot rule alone fills in 8-16x)
    // the elimination starts over with the pivots taken in the order (see column_ordering.h). The
    // budget is small because the pass is thrown away past it: on the generated seamless systems
    // the pivot rule never holds more nonzeros than the input (peak = input, 500-20k rows), on the
    // dragon's per-corner system it passes n/16 after 1424 of the 4370 row updates it took to pass
    // n (dragon full-seamless initialize 6.4 -> 4.9 ms with the front order's earlier exit); such
    // chain-like systems now skip the trial (below). The
    // order ignores the values: if an entry then grows beyond 2^20 or a pivot beyond 2 (random
    // systems; large pivots make the divisibility of Alg. 4 costly), the pivot rule alone, which
    // takes small pivots, redoes the elimination.
    const std::size_t unlimited = std::numeric_limits<std::size_t>::max();
    const bool ordered = has_fill_reducing_column_order() && order != PIVOT_RULE;
    bool over_budget = true;
    Status st = SUCCESS;
    // The pivot rule reads the caller's int64 rows as they are where numbering the columns would
    // shorten the per-column arrays by less than half (the generated seamless systems: no copy of
    // the input, and none of its page faults); the orders need the numbered columns.
    const Csr_rows<Int>* as_given = sys.fits_int64 ? same_type(sys.rows64) : nullptr;
    use_rows(sys, as_given != nullptr && 2 * sys.constrained_columns() >= sys.n_cols ? as_given : nullptr);
    m_prefetch = m_in->e.size() > PREFETCH_NONZEROS;
    // Where nearly every column lies in exactly two rows, the rows form long chains (the sides of
    // cuts): there the pivot rule alone fills in and its trial would be thrown away, so it is left out
    // (columns in two rows: every per-corner seam system of ../shared/data 95-100%, the generated
    // seamless systems 70-72%; dragon full-seamless initialize -8%, same IRREF).
    const bool chains = 10 * sys.n_columns_in_two_rows >= 9 * sys.constrained_columns();
    if(order != FILL_REDUCING_ORDER && !(ordered && chains)) {
      st = eliminate<false>(out, message, ordered ? sys.nonzeros() + sys.n_rows / 16 : unlimited, over_budget);
      if(!over_budget) { if(st == SUCCESS) extract(sys, out); return st; }
    }
    const std::size_t spent = out.eliminations;
    out = Irref<Int>();
    out.eliminations = spent;                          // every row update performed, both passes
    use_rows(sys, nullptr);
    fill_reducing_column_order(*m_in, m_original.size(), m_position, m_latest_first);   // none: the pivot rule alone
    st = m_position.empty() ? eliminate<false>(out, message, unlimited, over_budget)
                            : eliminate<true>(out, message, unlimited, over_budget);
    if(over_budget) {                                  // the order ignores values: on coefficient growth, the pivot rule alone
      const std::size_t spent_too = out.eliminations;
      out = Irref<Int>();
      out.eliminations = spent_too;
      m_position.clear();
      m_latest_first = false;
      st = eliminate<false>(out, message, unlimited, over_budget);
    }
    if(st == SUCCESS) extract(sys, out);
    return st;
  }

private:
  // One elimination pass over the loaded input: ORDERED takes the pivots in the fill-reducing order
  // (m_position) and stops (SUCCESS with over_budget set) once an entry grows beyond GROWTH_LIMIT or a
  // pivot beyond 2; otherwise the pivot rule chooses them. Either pass stops so when the rows hold more
  // than `budget` nonzeros. Two instantiations, so that the pivot rule's loop tests nothing of the
  // order (the generated 20k-row seamless systems: the IRREF 1-2% faster).
  template <bool ORDERED>
  Status eliminate(Irref<Int>& out, std::string& message, std::size_t budget, bool& over_budget)
  {
    load<ORDERED>();
    Window window;
    fill<ORDERED>(window);
    over_budget = false;
    while(window.size > 0) {
      if(m_nonzeros > budget || (ORDERED && m_too_large)) { over_budget = true; return SUCCESS; }
      const Pending next = window.take();
      const std::uint32_t k = next.row;
      Row& row = m_rows[k];
      row.in_window = false;
      // Back to the queue if its key changed meanwhile or a row with a smaller key was queued (see Window).
      const bool changed = row.state == ACTIVE && (row.key != next.key || m_cursor < row.key);
      if(changed) push<ORDERED>(k);
      fill<ORDERED>(window);
      if(m_prefetch && window.size > 1) prefetch_target_records<ORDERED>(window.at(1));
      if(m_prefetch && window.size > 0) prefetch_target_entries<ORDERED>(window.at(0));
      if(row.state != ACTIVE || changed) continue;
      if(row.size == 0) {
        if(!Ops::is_zero(row.b)) {
          message = "row " + std::to_string(k) + " is a linear combination of other rows with an inconsistent right-hand side "
                    "(it reduces to 0 = " + Ops::to_string(row.b) + "): the system has no solution";
          return INFEASIBLE;
        }
        row.state = ZERO;
        ++out.dependent_rows;
        continue;
      }
      const Entry& pivot = row.data[choose_pivot<ORDERED>(row)];
      const std::uint32_t c = pivot.col;
      const Int p = pivot.val;
      if(ORDERED && Ops::less(Ops::from_int64(2), Ops::abs(p))) { over_budget = true; return SUCCESS; }
      eliminate_column<ORDERED>(k, c, p, out.eliminations);
      m_rows[k].state = PIVOT;
      m_rows[k].pivot_col = c;
    }
    return SUCCESS;
  }

  template <bool ORDERED>
  void load()
  {
    const Csr_rows<Int>& in = *m_in;
    const auto& ptr = in.ptr;
    const std::size_t n_rows = ptr.size() - 1;
    m_rows.assign(n_rows, Row());
    if(!FLAT) m_own.assign(n_rows, std::vector<Entry>());
    m_cols.assign(m_n_cols, Column());
    m_pool.clear();
    m_pool.reserve(in.e.size());                       // no reallocation in practice (pages are touched only when used)
    m_arena_block = std::max<std::size_t>(std::size_t(1) << 16, in.e.size() / 4);
    m_arena.clear(); m_arena_used = 0; m_arena_capacity = 0;
    m_nonzeros = in.e.size();
    m_too_large = false;
    m_stamp = 0;
    // Rows are read backwards and pushed at once: the queue's buckets are stacks, so lower indices come out first.
    m_ordered.clear();
    m_buckets.assign(2 * NNZ_BUCKETS, std::vector<std::uint32_t>());
    m_buckets[std::min<std::uint32_t>(4, NNZ_BUCKETS - 1)].reserve(n_rows);   // seamless rows: 4 unit entries
    m_cursor = 0;
    for(std::size_t i = n_rows; i-- > 0; ) {
      Row& row = m_rows[i];
      row.data = in.e.data() + ptr[i];
      row.size = std::uint32_t(ptr[i + 1] - ptr[i]);
      row.b = in.b[i];
      for(std::uint32_t q = row.size; q-- > 0; ) {
        if(ptr[i] + q >= prefetch_distance) __builtin_prefetch(&m_cols[in.e[ptr[i] + q - prefetch_distance].col], 1);
        add_occurrence(row.data[q].col, std::uint32_t(i));
      }
      push<ORDERED>(std::uint32_t(i));
    }
  }

  // The columns numbered 0..nc-1 in index order, over the columns that occur in a row only (a
  // per-corner system: 7.8k of the dragon's 29k): every per-column array of the elimination and of
  // the orders is then that short. The numbering keeps the order of the columns, so ties by column
  // index go as with the original indices; extract() maps them back.
  void number_columns(const Integer_system& sys)
  {
    m_number.resize(sys.n_cols);
    m_original.resize(sys.n_cols);
    std::uint32_t nc = 0;
    for(std::size_t c = 0; c < sys.n_cols; ++c) {         // no branch: which columns occur follows no pattern
      m_number[c] = nc;
      m_original[nc] = std::uint32_t(c);
      nc += std::uint32_t(sys.column_used(c));
    }
    m_original.resize(nc);
  }
  // The rows the elimination reads: `as_given` (the caller's, columns of the system), or if null the
  // input in Int with the numbered columns (made once).
  void use_rows(const Integer_system& sys, const Csr_rows<Int>* as_given)
  {
    m_in = as_given;
    m_n_cols = sys.n_cols;
    if(m_in != nullptr) return;
    if(m_input.ptr.empty()) {
      number_columns(sys);
      if(sys.fits_int64) number_rows(sys.rows64);
      else               number_rows(sys.rowsz);
    }
    m_in = &m_input;
    m_n_cols = m_original.size();
  }
  bool numbered() const { return m_in == &m_input; }
  std::uint32_t original(std::uint32_t c) const { return numbered() ? m_original[c] : c; }
  template <typename From>
  void number_rows(const Csr_rows<From>& in)
  {
    m_input.ptr = in.ptr;
    m_input.e.resize(in.e.size());
    m_input.b.resize(in.b.size());
    for(std::size_t q = 0; q < in.e.size(); ++q) m_input.e[q] = Entry{m_number[in.e[q].col], convert(in.e[q].val)};
    for(std::size_t i = 0; i < in.b.size(); ++i) m_input.b[i] = convert(in.b[i]);
  }
  static const Csr_rows<Int>* same_type(const Csr_rows<Int>& rows) { return &rows; }
  template <typename From> static const Csr_rows<Int>* same_type(const Csr_rows<From>&) { return nullptr; }
  static Int convert(const Int& v) { return v; }
  template <typename From> static Int convert(const From& v)
  {
    Int r;
    if(!convert_integer(v, r)) throw Integer_overflow();   // a Gmpz system into int64
    return r;
  }

  void add_occurrence(std::uint32_t c, std::uint32_t i)
  {
    Column& col = m_cols[c];
    ++col.count;
    if(col.r0 == NIL) col.r0 = i;
    else if(col.r1 == NIL) col.r1 = i;
    else { m_pool.push_back(Occurrence{i, col.more}); col.more = std::uint32_t(m_pool.size() - 1); }
  }

  // Look-ahead (a software pipeline over the pivot steps). A row is taken from the queue LOOKAHEAD
  // steps before it is eliminated; meanwhile what its step will read is prefetched in stages, each
  // a step after the previous one has been requested: the records of its columns (which
  // choose_pivot() reads), the records of the other rows holding its likely pivot column, then
  // those rows' entries. On shuffled systems these are three dependent cache misses per step.
  // The prefetches are hints only: when the step comes, its row, pivot and targets are read afresh,
  // and the row goes back to the queue instead if its key changed meanwhile or a row with a smaller
  // key was queued (the fill-reducing order matters on unstructured systems). So the result is that
  // of the serial elimination in this deterministic order: the queue's, LOOKAHEAD steps early.
  // While a row is in the window, its other queue entries are skipped.
  // The prefetches pay off only when the elimination's data do not fit in the cache: below
  // PREFETCH_NONZEROS input nonzeros (some 1 MB of rows, columns and entries) they only cost and are
  // left out (measured, initialize with / without: dragon full-seamless, 15.5k nonzeros, 4.1-4.2 /
  // 3.8 ms; generated seamless systems of 21k nonzeros 2.5 / 2.2-2.4 ms, of 86k 11-14 / 16.5 ms).
  // The window stays, so the result is the same either way.
  static constexpr std::size_t PREFETCH_NONZEROS = std::size_t(1) << 15;
  static constexpr std::size_t LOOKAHEAD = 3;
  struct Pending
  {
    std::uint32_t row;
    std::uint32_t col;                   // likely pivot column (NIL: not looked at yet)
    unsigned char key;                   // the row's queue key when it was taken
  };
  struct Window                         // a ring buffer of up to LOOKAHEAD rows, in pop order
  {
    static constexpr std::size_t MASK = 3;  // 4 slots: indices wrap without a division
    static_assert(LOOKAHEAD <= MASK + 1, "window too small");
    Pending slot[MASK + 1];
    std::size_t head = 0, size = 0;
    Pending& at(std::size_t j) { return slot[(head + j) & MASK]; }
    Pending take() { const Pending p = slot[head]; head = (head + 1) & MASK; --size; return p; }
  };
  template <bool ORDERED>
  void fill(Window& window)
  {
    std::uint32_t i;
    while(window.size < LOOKAHEAD && pop<ORDERED>(i)) {
      Row& row = m_rows[i];
      if(row.in_window) continue;        // a second queue entry of a row already taken
      row.in_window = true;
      window.at(window.size++) = Pending{i, NIL, row.key};
      if(m_prefetch) for(std::uint32_t q = 0; q < row.size; ++q) __builtin_prefetch(&m_cols[row.data[q].col], 1);
    }
  }
  // The pivot its step would choose now (the step chooses again: counts change meanwhile).
  template <bool ORDERED>
  bool look_ahead_pivot(Pending& p) const
  {
    const Row& row = m_rows[p.row];
    if(row.state != ACTIVE || row.size == 0) return false;
    if(p.col == NIL) p.col = row.data[choose_pivot<ORDERED>(row)].col;
    return true;
  }
  template <bool ORDERED>
  void prefetch_target_records(Pending& p) const
  {
    if(!look_ahead_pivot<ORDERED>(p)) return;
    const Column& col = m_cols[p.col];
    if(col.r0 != p.row && col.r0 != NIL) __builtin_prefetch(&m_rows[col.r0], 1);
    if(col.r1 != p.row && col.r1 != NIL) __builtin_prefetch(&m_rows[col.r1], 1);
    if(col.more != NIL) __builtin_prefetch(&m_pool[col.more]);
  }
  template <bool ORDERED>
  void prefetch_target_entries(Pending& p) const
  {
    if(!look_ahead_pivot<ORDERED>(p)) return;
    const Column& col = m_cols[p.col];
    for(const std::uint32_t r : { col.r0, col.r1 }) {
      if(r == p.row || r == NIL) continue;
      const char* entries = reinterpret_cast<const char*>(m_rows[r].data);
      __builtin_prefetch(entries); __builtin_prefetch(entries + 64);
    }
    if(col.more != NIL) __builtin_prefetch(&m_rows[m_pool[col.more].row], 1);
  }

  static unsigned char key(const Row& row)
  {
    bool unit = false;
    for(std::uint32_t q = 0; q < row.size; ++q) if(Ops::is_unit(row.data[q].val)) { unit = true; break; }
    return (unsigned char)((unit ? 0 : NNZ_BUCKETS) + std::min(row.size, NNZ_BUCKETS - 1));
  }
  // The front order's queue: rows whose first column in the order comes latest go first (a heap
  // keyed by NIL - position; entries whose row changed meanwhile are stale and skipped by pop()).
  // Each row still takes its first column as the pivot, so the pivots are mostly those of any other
  // row order (on the systems measured, the same IRREF as with the nonzero-count queue), but the
  // rows eliminated early then hold the columns of the end of the order, whose pivots meet few
  // other rows: with the front order 215k -> 99k row updates on duck_miq_8 (init 1075 -> 521 ms);
  // in order of position the front of rows keeps growing (duck > 300 s). With COLAMD's order it
  // saves updates too (duck 226k -> 169k, dragon-full 12.1k -> 9.8k) but no time (dragon: +20%,
  // the heap), so the nonzero-count queue stays there, and with the static degree order (the heap
  // not tried there).
  std::uint32_t ordered_key(const Row& row) const
  {
    std::uint32_t first = NIL;
    for(std::uint32_t q = 0; q < row.size; ++q) first = std::min(first, m_position[row.data[q].col]);
    return NIL - first;
  }
  template <bool ORDERED>
  void push(std::uint32_t i)
  {
    if(ORDERED && m_latest_first) {
      m_rows[i].key = 0;                     // the window's key check does not apply (see pop())
      m_ordered.push_back(std::make_pair(ordered_key(m_rows[i]), i));
      std::push_heap(m_ordered.begin(), m_ordered.end(), std::greater<std::pair<std::uint32_t, std::uint32_t> >());
      return;
    }
    const unsigned char k = key(m_rows[i]);
    m_rows[i].key = k;
    m_buckets[k].push_back(i);
    if(k < m_cursor) m_cursor = k;
  }
  template <bool ORDERED>
  bool pop(std::uint32_t& out)
  {
    if(ORDERED && m_latest_first) {
      while(!m_ordered.empty()) {
        std::pop_heap(m_ordered.begin(), m_ordered.end(), std::greater<std::pair<std::uint32_t, std::uint32_t> >());
        const std::pair<std::uint32_t, std::uint32_t> top = m_ordered.back();
        m_ordered.pop_back();
        const Row& row = m_rows[top.second];
        if(row.state == ACTIVE && ordered_key(row) == top.first) { out = top.second; return true; }   // else stale
      }
      return false;
    }
    while(m_cursor < m_buckets.size()) {
      std::vector<std::uint32_t>& bucket = m_buckets[m_cursor];
      while(!bucket.empty()) {
        const std::uint32_t i = bucket.back();
        bucket.pop_back();
        if(m_rows[i].state == ACTIVE && m_rows[i].key == m_cursor) { out = i; return true; }  // else stale
      }
      ++m_cursor;
    }
    return false;
  }

  // The pivot of a (nonempty) row: the index of its entry in the row.
  template <bool ORDERED>
  std::uint32_t choose_pivot(const Row& row) const
  {
    if(ORDERED) {                                            // the column that comes first in the fill-reducing order
      std::uint32_t best = 0;
      for(std::uint32_t q = 1; q < row.size; ++q) if(m_position[row.data[q].col] < m_position[row.data[best].col]) best = q;
      return best;
    }
    // fewest nonzeros, then index; the entry's index in the low bits (columns, and so entries, are in increasing order)
    auto entry_key = [&](std::uint32_t q) { return (std::uint64_t(m_cols[row.data[q].col].count) << 32) | row.data[q].col; };
    std::uint64_t best_key = entry_key(0);
    std::uint32_t best = 0;
    bool units = Ops::is_unit(row.data[0].val);
    for(std::uint32_t q = 1; q < row.size; ++q) {           // all values +-1 (seamless rows): only the keys count
      const std::uint64_t k = entry_key(q);
      best = k < best_key ? q : best;
      best_key = std::min(best_key, k);
      units = units & Ops::is_unit(row.data[q].val);
    }
    if(units) return best;
    auto column_key = [&](std::uint32_t c) { return (std::uint64_t(m_cols[c].count) << 32) | c; };
    best = 0;                                                // else smallest |value| first
    best_key = column_key(row.data[0].col);
    for(std::uint32_t q = 1; q < row.size; ++q) {
      const Int& v = row.data[q].val;
      const Int& vb = row.data[best].val;
      const std::uint64_t k = column_key(row.data[q].col);
      if(!(Ops::is_unit(v) && Ops::is_unit(vb))) {           // compare |v| only when not both units
        const Int a = Ops::abs(v), ab = Ops::abs(vb);
        if(Ops::less(a, ab)) { best = q; best_key = k; continue; }
        if(Ops::less(ab, a)) continue;
      }
      if(k < best_key) { best = q; best_key = k; }
    }
    return best;
  }

  CGAL_SEAMLESS_SNAPPING_ALWAYS_INLINE static const Int* find(const Row& row, std::uint32_t c)
  {
    if(row.size <= 16) {                                    // short rows: a linear scan beats bisection
      for(const Entry* e = row.data; e != row.data + row.size; ++e) if(e->col >= c) return e->col == c ? &e->val : nullptr;
      return nullptr;
    }
    const Entry* e = std::lower_bound(row.data, row.data + row.size, c,
                                      [](const Entry& x, std::uint32_t cc) { return x.col < cc; });
    return (e != row.data + row.size && e->col == c) ? &e->val : nullptr;
  }

  // Eliminates column c from every row but k, whose entry there is p (fraction-free, then divided by the row gcd).
  template <bool ORDERED>
  CGAL_SEAMLESS_SNAPPING_ALWAYS_INLINE void eliminate_column(std::uint32_t k, std::uint32_t c, const Int& p, std::size_t& eliminations)
  {
    Column& col = m_cols[c];
    m_targets.clear();
    // The count is exact, so the scan of the (possibly stale, possibly repeated) occurrences stops
    // as soon as all count - 1 other rows are found; a stamp per row removes repeats.
    const std::size_t wanted = col.count - 1;
    if(wanted > 0) {
      const std::uint32_t stamp = ++m_stamp;
      m_rows[k].stamp = stamp;
      auto consider = [&](std::uint32_t i) {
        Row& r = m_rows[i];
        if(r.stamp == stamp || r.state == ZERO) return;
        if(const Int* a = find(r, c)) { r.stamp = stamp; m_targets.push_back(Target{i, a}); }
      };
      if(col.r0 != NIL) consider(col.r0);
      if(col.r1 != NIL && m_targets.size() < wanted) consider(col.r1);
      for(std::uint32_t f = col.more; f != NIL && m_targets.size() < wanted; f = m_pool[f].next) consider(m_pool[f].row);
      CGAL_assertion(m_targets.size() == wanted);
      auto by_row = [](const Target& x, const Target& y) { return x.row < y.row; };   // a deterministic order
      if(m_targets.size() == 2) { if(by_row(m_targets[1], m_targets[0])) std::swap(m_targets[0], m_targets[1]); }
      else if(m_targets.size() > 2) std::sort(m_targets.begin(), m_targets.end(), by_row);
    }
    const Row& pr = m_rows[k];
    for(const Target& t : m_targets) {                     // (a row's entries move only when it is combined)
      const std::uint32_t i = t.row;
      Row& row = m_rows[i];
      const Int a = *t.value;
      Int fi, fk;
      if(Ops::is_unit(p) || Ops::is_unit(a)) { fi = p; fk = a; }   // gcd 1: the common case, no division
      else { const Int g = Ops::gcd(p, a); fi = Ops::exact_div(p, g); fk = Ops::exact_div(a, g); }
      combine<ORDERED>(row, i, fi, pr, fk);
      ++eliminations;
      if(row.state == ACTIVE) push<ORDERED>(i);
    }
    // Only row k holds column c now (pivot columns never spread again: every later pivot row is free of c).
    col.count = 1; col.r0 = k; col.r1 = NIL; col.more = NIL;   // m_cols is never resized: `col` is still valid
  }

  // row <- fi * row - fk * pr, then divided by the gcd of its entries and b; int64 entries are
  // written straight into the arena, Gmpz entries appended to the merge buffer (no default-constructed
  // values), which then becomes the row's own vector.
  template <bool ORDERED>
  void combine(Row& row, std::uint32_t i, const Int& fi, const Row& pr, const Int& fk)
  {
    Entry* w = nullptr;
    if(FLAT) w = arena_reserve(std::size_t(row.size) + pr.size);
    else { m_merged.clear(); m_merged.reserve(std::size_t(row.size) + pr.size); }
    Entry* const first = w;
    bool large = false;                                      // ordered pass: an entry beyond GROWTH_LIMIT
    auto emit = [&](std::uint32_t col, const Int& v) {
      if(ORDERED) large |= beyond_growth_limit(v);
      if(FLAT) *w++ = Entry{col, v}; else m_merged.push_back(Entry{col, v});
    };
    const bool fi_one = Ops::is_unit(fi) && Ops::sign(fi) > 0;
    const Entry *a = row.data, *ae = row.data + row.size;
    const Entry *b = pr.data, *be = pr.data + pr.size;
    while(a != ae || b != be) {
      if(b == be || (a != ae && a->col < b->col)) {
        emit(a->col, fi_one ? a->val : Ops::mul(fi, a->val)); ++a;
      } else if(a == ae || b->col < a->col) {
        emit(b->col, Ops::neg(Ops::mul(fk, b->val)));
        add_occurrence(b->col, i);
        ++b;
      } else {
        Int v = Ops::sub(fi_one ? a->val : Ops::mul(fi, a->val), Ops::mul(fk, b->val));
        if(Ops::is_zero(v)) --m_cols[a->col].count;
        else emit(a->col, v);
        ++a; ++b;
      }
    }
    Entry* const dst = FLAT ? first : m_merged.data();
    const std::size_t size = FLAT ? std::size_t(w - first) : m_merged.size();
    m_too_large |= large;
    row.b = Ops::sub(fi_one ? row.b : Ops::mul(fi, row.b), Ops::mul(fk, pr.b));
    Int g = Ops::abs(row.b);
    for(std::size_t q = 0; q < size && !Ops::is_unit(g); ++q) g = Ops::gcd(g, dst[q].val);
    if(!Ops::is_zero(g) && !Ops::is_unit(g)) {
      for(std::size_t q = 0; q < size; ++q) dst[q].val = Ops::exact_div(dst[q].val, g);
      row.b = Ops::exact_div(row.b, g);
    }
    m_nonzeros += size;
    m_nonzeros -= row.size;
    if(FLAT) m_arena_used += size;
    else m_own[i].swap(m_merged);
    row.data = FLAT ? dst : m_own[i].data();
    row.size = std::uint32_t(size);
  }

  // |v| > GROWTH_LIMIT, tested as every entry is written; in int64 without a branch or an overflow
  // check, |v| > L being v + L > 2 L in unsigned arithmetic (dragon full-seamless: a second pass over
  // the entries with Ops::abs() took 4% of initialize).
  static bool beyond_growth_limit(std::int64_t v)
  {
    const std::uint64_t L = std::uint64_t(GROWTH_LIMIT);
    return std::uint64_t(v) + L > 2 * L;
  }
  static bool beyond_growth_limit(const CGAL::Gmpz& v) { return mpz_cmpabs_ui(v.mpz(), (unsigned long)GROWTH_LIMIT) > 0; }

  // Room for `size` entries at the end of the arena: large blocks with stable addresses, no
  // allocation per row; superseded versions of rows are simply left behind.
  Entry* arena_reserve(std::size_t size)
  {
    if(m_arena.empty() || m_arena_used + size > m_arena_capacity) {
      m_arena_capacity = std::max(m_arena_block, size);
      std::unique_ptr<Entry[], Arena_deleter> block(Huge_page_allocator<Entry>().allocate(m_arena_capacity), Arena_deleter{m_arena_capacity});
      m_arena.push_back(std::move(block));             // owned before the vector may grow (and throw)
      m_arena_used = 0;
    }
    return m_arena.back().get() + m_arena_used;
  }

  // The pivot rows in row order (the order of IRREF rows does not matter, Eq. 2' uses free variables only).
  void extract(const Integer_system& sys, Irref<Int>& out)
  {
    out.n_cols = sys.n_cols;                        // columns are the system's from here on (original())
    // the columns that occur in a row are free unless they are pivots; with numbered columns only those
    // are visited (dragon full-seamless: 7.8k of 29k columns), else all, without a branch per column
    const std::size_t occurring = numbered() ? m_original.size() : sys.n_cols;
    out.kind.assign(sys.n_cols, (unsigned char)UNCONSTRAINED_COLUMN);
    if(numbered()) for(const std::uint32_t c : m_original) out.kind[c] = FREE_COLUMN;
    else for(std::size_t c = 0; c < sys.n_cols; ++c) out.kind[c] = (unsigned char)(sys.column_used(c) ? FREE_COLUMN : UNCONSTRAINED_COLUMN);
    std::size_t rank = 0, total = 0;
    for(const Row& row : m_rows) if(row.state == PIVOT) { ++rank; total += row.size - 1; out.kind[original(row.pivot_col)] = IMPLIED_COLUMN; }
    // in increasing order; every column visited is written, the free ones kept: room for the free
    // columns (the constrained ones but the pivots) + 1, all of it written (no untouched pages)
    out.free_columns.resize(sys.constrained_columns() - rank + 1);
    std::size_t f = 0;
    for(std::size_t k = 0; k < occurring; ++k) {
      const std::uint32_t c = original(std::uint32_t(k));
      out.free_columns[f] = c;
      f += std::size_t(out.kind[c] == FREE_COLUMN);
    }
    CGAL_assertion(f + 1 == out.free_columns.size());
    out.free_columns.pop_back();
    out.ptr.resize(rank + 1); out.ptr[0] = 0;
    out.col.resize(total + 1); out.val.resize(total + 1);   // + 1: see the entry loop
    out.pivot_col.resize(rank); out.pivot.resize(rank); out.rhs.resize(rank);
    Int lo = Ops::from_int64(0), hi = lo;           // range of the values written: max_abs at the end
    auto note = [&](const Int& v) { if(Ops::less(hi, v)) hi = v; if(Ops::less(v, lo)) lo = v; return v; };
    std::size_t j = 0, t = 0;                       // next IRREF row, next entry
    for(std::size_t k = 0; k < m_rows.size(); ++k) {
      if(k + prefetch_distance / 4 < m_rows.size()) __builtin_prefetch(m_rows[k + prefetch_distance / 4].data);   // rows, not entries
      Row& row = m_rows[k];
      if(row.state != PIVOT) continue;
      const Int* pv = find(row, row.pivot_col);
      const bool flip = Ops::sign(*pv) < 0;           // normalize: pivot > 0
      const Int p = flip ? Ops::neg(*pv) : *pv;
      out.pivot_col[j] = original(row.pivot_col);
      out.rhs[j] = note(Ops::negatable(flip ? Ops::neg(row.b) : row.b));
      if(!Ops::is_zero(out.rhs[j])) out.homogeneous = false;
      const std::size_t first = t;
      for(std::uint32_t q = 0; q < row.size; ++q) {  // every entry is written; the pivot's is then overwritten
        const Entry& x = row.data[q];                 // (the last row's lands in the extra slot): no branch on its place
        out.col[t] = original(x.col);
        out.val[t] = note(Ops::negatable(flip ? Ops::neg(x.val) : x.val));
        t += std::size_t(x.col != row.pivot_col);
      }
      for(std::size_t q = first; q < t; ++q) CGAL_assertion(out.kind[out.col[q]] == FREE_COLUMN);
      if(!Ops::is_unit(p)) {
        if(out.unit_pivots) out.divisor.assign(sys.n_cols, Ops::from_int64(1));   // at the first pivot other than 1
        out.unit_pivots = false;
        for(std::size_t q = first; q < t; ++q) out.divisor[out.col[q]] = Ops::lcm(out.divisor[out.col[q]], p);   // Alg. 4
      }
      out.pivot[j] = note(p);
      out.ptr[++j] = t;
      if(!FLAT) std::vector<Entry>().swap(m_own[k]);  // release memory as we go
    }
    out.col.pop_back(); out.val.pop_back();
    out.max_abs = Ops::less(hi, Ops::neg(lo)) ? Ops::neg(lo) : hi;   // every value is negatable
  }

  template <typename T> using Big_vector = std::vector<T, Huge_page_allocator<T> >;   // large, randomly accessed
  struct Arena_deleter
  {
    std::size_t n;
    void operator()(Entry* p) const { Huge_page_allocator<Entry>().deallocate(p, n); }   // entries are trivial (int64 only)
  };

  std::size_t m_n_cols = 0;                            // columns of the rows read (m_in, see use_rows())
  bool m_prefetch = true;                              // see Window
  Big_vector<Row> m_rows;
  std::vector<std::vector<Entry> > m_own;              // Gmpz only: the entries of modified rows
  Big_vector<Column> m_cols;
  Big_vector<Occurrence> m_pool;                       // column occurrences beyond r0, r1
  const Csr_rows<Int>* m_in = nullptr;                // the rows read: the caller's or m_input (see use_rows())
  Csr_rows<Int> m_input;                               // the input in Int, columns numbered (see number_columns())
  std::vector<std::uint32_t> m_number;                 // per column of the system: its number (numbered rows only)
  std::vector<std::uint32_t> m_original;               // per column number: the system's column (those that occur in a row)
  std::vector<std::vector<std::uint32_t> > m_buckets;
  std::size_t m_cursor = 0;
  struct Target { std::uint32_t row; const Int* value; };   // a row holding the pivot column, and its entry there
  std::vector<Target> m_targets;
  std::uint32_t m_stamp = 0;
  std::vector<Entry> m_merged;                         // Gmpz only: merge buffer
  std::vector<std::unique_ptr<Entry[], Arena_deleter> > m_arena;   // int64 only: see arena_reserve()
  std::size_t m_arena_used = 0, m_arena_capacity = 0;
  std::size_t m_arena_block = std::size_t(1) << 16;    // entries per block: a quarter of the input, at least 2^16
  std::size_t m_nonzeros = 0;                          // in the rows (active, pivot and zero)
  std::vector<std::uint32_t> m_position;               // fill-reducing column order, if any (column_ordering.h)
  bool m_latest_first = false;                         // the order is the front order: rows in m_ordered
  std::vector<std::pair<std::uint32_t, std::uint32_t> > m_ordered;   // the front order's queue: (ordered_key, row)
  bool m_too_large = false;                            // ordered pass: an entry exceeds GROWTH_LIMIT (it then stops)
  static constexpr std::int64_t GROWTH_LIMIT = std::int64_t(1) << 20;   // see beyond_growth_limit()
};

// Computes the IRREF of the canonical system in Int. With Int = int64 an overflow throws
// Integer_overflow (the caller then redoes it in Gmpz).
// `order` is for tests and benchmarks: both rules give an exact IRREF of the same system.
template <typename Int>
Status compute_irref(const Integer_system& sys, Irref<Int>& out, std::string& message, Pivot_order order = AUTOMATIC_PIVOT_ORDER)
{
  out = Irref<Int>();
  Irref_eliminator<Int> e;
  return e.run(sys, out, message, order);
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_IRREF_H
