// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// Test-system generators shared by test_projection.cpp and benchmark/bench_projection.cpp, plus
// the exact (Gmpq, zero tolerance) check of `C x = b` and the Matrix Market / text-vector I/O.
// Not part of the package API.

#ifndef CGAL_SEAMLESS_SNAPPING_TEST_GENERATORS_H
#define CGAL_SEAMLESS_SNAPPING_TEST_GENERATORS_H

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cassert>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace SS_test {

typedef Eigen::Triplet<long> Triplet;
typedef Eigen::SparseMatrix<long, Eigen::RowMajor> Row_matrix;

/// An integer system `C x = b` (m x n) with a known exact solution (when `has_solution`).
struct Linear_system
{
  std::string name;
  std::size_t m = 0, n = 0;
  std::vector<Triplet> triplets;  // canonical: sorted by (row, col), no duplicates, no zeros
  std::vector<long> b;            // m entries
  std::vector<double> solution;   // n entries, C solution = b exactly (checked by the caller in Gmpq)
  bool has_solution = false;
  std::size_t redundant_rows = 0; // rows added as combinations of others: rank <= m - redundant_rows
  std::vector<char> constrained;  // n flags: column has a nonzero entry

  Row_matrix matrix() const
  {
    Row_matrix C{Eigen::Index(m), Eigen::Index(n)};
    C.setFromTriplets(triplets.begin(), triplets.end());
    return C;
  }
};

// ---------------------------------------------------------------------------------------------
// Portable random numbers (only the raw mt19937_64 stream is used, so the systems are the same
// with every standard library).
class Rng
{
public:
  explicit Rng(std::uint64_t seed) : m_gen(seed) {}
  std::uint64_t bits() { return m_gen(); }
  long integer(long lo, long hi) { return lo + long(m_gen() % std::uint64_t(hi - lo + 1)); } // [lo, hi]
  double uniform() { return double(m_gen() >> 11) * 0x1p-53; }                                // [0, 1)
  double symmetric() { return 2. * uniform() - 1.; }                                          // [-1, 1)
  std::size_t index(std::size_t n) { return std::size_t(m_gen() % n); }
  template <typename T> void shuffle(std::vector<T>& v)
  {
    for(std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[index(i)]);
  }
private:
  std::mt19937_64 m_gen;
};

/// sorts, sums duplicates, drops zeros, sets `constrained`.
inline void canonicalize(Linear_system& s)
{
  std::sort(s.triplets.begin(), s.triplets.end(), [](const Triplet& a, const Triplet& c) {
    return a.row() != c.row() ? a.row() < c.row() : a.col() < c.col(); });
  std::vector<Triplet> out;
  out.reserve(s.triplets.size());
  for(const Triplet& t : s.triplets) {
    if(!out.empty() && out.back().row() == t.row() && out.back().col() == t.col())
      out.back() = Triplet(t.row(), t.col(), out.back().value() + t.value());
    else
      out.push_back(t);
  }
  s.triplets.clear();
  for(const Triplet& t : out) if(t.value() != 0) s.triplets.push_back(t);
  s.constrained.assign(s.n, 0);
  for(const Triplet& t : s.triplets) s.constrained[std::size_t(t.col())] = 1;
}

// rotation by k quarter turns counter-clockwise: r_1 (u, v) = (-v, u)
inline void rotate(int k, double u, double v, double& ru, double& rv)
{
  switch(k & 3) {
    case 0: ru = u;  rv = v;  break;
    case 1: ru = -v; rv = u;  break;
    case 2: ru = -u; rv = -v; break;
    default: ru = v; rv = -u; break;
  }
}
// the same on coefficient vectors: row_u/row_v of r_k applied to (a_u, a_v), as (column, coefficient) lists
struct Uv_rows { std::vector<std::pair<long, long>> u, v; };

/*!
 * Seamless-like system (Sec. 5.1): variables are (u, v) pairs per sector (variable 2s = u, 2s+1 = v
 * before the optional column shuffle). A cut chain of length L runs between two node vertices and
 * separates a '+' side (chart A) from a '-' side (chart B); its rotation is k = rho_B - rho_A mod 4.
 * Per cut edge (i, i+1) there are two rows (u and v component), 4 entries in {-1, 0, 1} each:
 *     r_k (p_i - p_{i+1}) - (q_i - q_{i+1}) = 0,
 * p = '+' sector, q = '-' sector. The end sectors of the chains are node sectors (node vertex, chart),
 * shared by every chain that touches that vertex with that chart on one side, so the system couples.
 * Redundant rows (sum or difference of two rows) make it rank-deficient.
 *
 * Exact solution: every sector value is r_{rho_c}(P_v + T_c) with P_v a vertex position on a
 * 2^-20 grid in [-1, 1]^2 and T_c an integer chart translation in [-8, 8]^2; all values are exact
 * doubles, and the transition constraints hold exactly because both sides come from one position.
 */
struct Seamless_options
{
  std::size_t target_rows = 2000;
  int min_chain_length = 1, max_chain_length = 12;
  int charts = 6;
  double redundant_fraction = 0.05;    // share of rows that are sums/differences of other rows
  std::size_t untouched_sectors = 4;   // sectors in no row (their values must be copied unchanged)
  bool shuffle = true;                 // random row and column order
  std::uint64_t seed = 1;
};

inline Linear_system seamless_system(const Seamless_options& o)
{
  Rng rng(o.seed);
  Linear_system s;
  std::vector<int> rho(std::size_t(o.charts));
  std::vector<double> tu(rho.size()), tv(rho.size());
  for(std::size_t c = 0; c < rho.size(); ++c) {
    rho[c] = int(rng.integer(0, 3)); tu[c] = double(rng.integer(-8, 8)); tv[c] = double(rng.integer(-8, 8));
  }
  const double mean_rows_per_chain = double(o.min_chain_length + o.max_chain_length); // 2 rows per edge
  const std::size_t base_rows = std::size_t(double(o.target_rows) * (1. - o.redundant_fraction));
  const std::size_t chains = std::max<std::size_t>(1, std::size_t(double(base_rows) / mean_rows_per_chain + 0.5));
  const std::size_t node_vertices = std::max<std::size_t>(3, (2 * chains) / 3);   // cut graph of degree ~3

  auto position = [&]() { return double(rng.integer(-(1L << 20), 1L << 20)) * 0x1p-20; };
  std::vector<double> pu(node_vertices), pv(node_vertices);
  for(std::size_t i = 0; i < node_vertices; ++i) { pu[i] = position(); pv[i] = position(); }

  std::vector<double> value;   // 2 per sector
  auto new_sector = [&](double u, double v, int c) {
    double ru, rv; rotate(rho[std::size_t(c)], u + tu[std::size_t(c)], v + tv[std::size_t(c)], ru, rv);
    value.push_back(ru); value.push_back(rv);
    return long(value.size() / 2 - 1);
  };
  std::map<std::pair<std::size_t, int>, long> node_sector;
  auto get_node_sector = [&](std::size_t vtx, int c) {
    auto it = node_sector.find(std::make_pair(vtx, c));
    if(it != node_sector.end()) return it->second;
    long sct = new_sector(pu[vtx], pv[vtx], c);
    node_sector[std::make_pair(vtx, c)] = sct;
    return sct;
  };

  std::vector<std::map<long, long>> rows;
  for(std::size_t ch = 0; ch < chains; ++ch) {
    std::size_t v0 = rng.index(node_vertices), v1 = rng.index(node_vertices - 1);
    if(v1 >= v0) ++v1;
    int A = int(rng.index(rho.size())), B = int(rng.index(rho.size()));
    if(A == B && rng.uniform() < 0.8) B = (B + 1) % o.charts;
    const int L = int(rng.integer(o.min_chain_length, o.max_chain_length));
    const int k = ((rho[std::size_t(B)] - rho[std::size_t(A)]) % 4 + 4) % 4;
    std::vector<long> p(std::size_t(L) + 1), q(std::size_t(L) + 1);
    p[0] = get_node_sector(v0, A); q[0] = get_node_sector(v0, B);
    p[std::size_t(L)] = get_node_sector(v1, A); q[std::size_t(L)] = get_node_sector(v1, B);
    for(int i = 1; i < L; ++i) {
      double u = position(), v = position();
      p[std::size_t(i)] = new_sector(u, v, A); q[std::size_t(i)] = new_sector(u, v, B);
    }
    for(int i = 0; i < L; ++i) {
      const long a = p[std::size_t(i)], a1 = p[std::size_t(i) + 1], c = q[std::size_t(i)], c1 = q[std::size_t(i) + 1];
      // r_k applied to the coefficient pattern of (p_i - p_{i+1}):
      //  component u of r_k(w) is  w_u (k=0), -w_v (k=1), -w_u (k=2), w_v (k=3)
      //  component v of r_k(w) is  w_v (k=0),  w_u (k=1), -w_v (k=2), -w_u (k=3)
      const int su_comp = (k == 0 || k == 2) ? 0 : 1, su_sign = (k == 0 || k == 3) ? 1 : -1;
      const int sv_comp = 1 - su_comp,                sv_sign = (k == 0 || k == 1) ? 1 : -1;
      std::map<long, long> ru, rv;
      ru[2 * a + su_comp] += su_sign; ru[2 * a1 + su_comp] -= su_sign; ru[2 * c] -= 1; ru[2 * c1] += 1;
      rv[2 * a + sv_comp] += sv_sign; rv[2 * a1 + sv_comp] -= sv_sign; rv[2 * c + 1] -= 1; rv[2 * c1 + 1] += 1;
      for(auto* r : { &ru, &rv }) {
        for(auto it = r->begin(); it != r->end();) { if(it->second == 0) it = r->erase(it); else ++it; }
        if(!r->empty()) rows.push_back(*r);
      }
    }
  }
  const std::size_t independent = rows.size();
  const std::size_t redundant = std::size_t(double(independent) * o.redundant_fraction / (1. - o.redundant_fraction));
  for(std::size_t d = 0; d < redundant && independent > 1; ++d) {
    const std::size_t r1 = rng.index(independent), r2 = rng.index(independent);
    const long sign = (rng.bits() & 1) ? 1 : -1;
    std::map<long, long> r = rows[r1];
    for(const auto& e : rows[r2]) r[e.first] += sign * e.second;
    for(auto it = r.begin(); it != r.end();) { if(it->second == 0) it = r.erase(it); else ++it; }
    if(!r.empty()) { rows.push_back(r); ++s.redundant_rows; }
  }
  for(std::size_t i = 0; i < o.untouched_sectors; ++i) new_sector(position(), position(), int(rng.index(rho.size())));

  s.m = rows.size();
  s.n = value.size();
  std::vector<long> col_perm(s.n), row_perm(s.m);
  for(std::size_t j = 0; j < s.n; ++j) col_perm[j] = long(j);
  for(std::size_t i = 0; i < s.m; ++i) row_perm[i] = long(i);
  if(o.shuffle) { rng.shuffle(col_perm); rng.shuffle(row_perm); }
  for(std::size_t i = 0; i < s.m; ++i)
    for(const auto& e : rows[i]) s.triplets.emplace_back(row_perm[i], col_perm[std::size_t(e.first)], e.second);
  s.b.assign(s.m, 0);
  s.solution.assign(s.n, 0.);
  for(std::size_t j = 0; j < s.n; ++j) s.solution[std::size_t(col_perm[j])] = value[j];
  s.has_solution = true;
  canonicalize(s);
  std::ostringstream name; name << "seamless_m" << s.m << "_s" << o.seed;
  s.name = name.str();
  return s;
}

/*!
 * Unstructured random system: each row has `min_nnz`..`max_nnz` distinct random columns with
 * coefficients in [-max_coefficient, max_coefficient] \ {0}.
 * - inhomogeneous (default): `b = C x*` with x* integer in [-100, 100], so the system has an
 *   integer (hence grid) solution;
 * - homogeneous: `b = 0` and x* has entries in {-2, -1, 1, 2}; each row is drawn until its last
 *   coefficient, chosen to make the row vanish at x*, lies in the coefficient range (rejection).
 * Columns not hit by any row stay unconstrained.
 */
struct Random_options
{
  std::size_t rows = 100;
  double columns_per_row = 2.;   // n = columns_per_row * rows
  int min_nnz = 4, max_nnz = 8;
  int max_coefficient = 3;
  bool homogeneous = false;
  std::size_t redundant_rows = 0;// extra rows (with b) that are sums/differences of two rows
  std::uint64_t seed = 1;
};

inline Linear_system random_system(const Random_options& o)
{
  Rng rng(o.seed);
  Linear_system s;
  s.m = o.rows;
  s.n = std::max<std::size_t>(std::size_t(o.max_nnz), std::size_t(double(o.rows) * o.columns_per_row));
  s.solution.assign(s.n, 0.);
  for(double& x : s.solution) {
    if(o.homogeneous) { x = double(rng.integer(1, 2)); if(rng.bits() & 1) x = -x; }
    else x = double(rng.integer(-100, 100));
  }
  auto coefficient = [&]() { long a = rng.integer(1, o.max_coefficient); return (rng.bits() & 1) ? a : -a; };
  for(std::size_t i = 0; i < s.m; ++i) {
    const int nnz = int(rng.integer(o.min_nnz, o.max_nnz));
    for(;;) {
      std::vector<long> cols;
      while(int(cols.size()) < nnz) {
        long c = long(rng.index(s.n));
        if(std::find(cols.begin(), cols.end(), c) == cols.end()) cols.push_back(c);
      }
      std::vector<long> a(cols.size());
      for(long& v : a) v = coefficient();
      if(o.homogeneous) {                       // last coefficient: a_last x*_last = -sum of the others
        long r = 0;
        for(std::size_t k = 0; k + 1 < cols.size(); ++k) r += a[k] * long(s.solution[std::size_t(cols[k])]);
        const long xl = long(s.solution[std::size_t(cols.back())]);
        if(r % xl != 0 || r == 0 || std::abs(r / xl) > o.max_coefficient) continue;
        a.back() = -r / xl;
      }
      for(std::size_t k = 0; k < cols.size(); ++k) s.triplets.emplace_back(long(i), cols[k], a[k]);
      break;
    }
  }
  for(std::size_t d = 0; d < o.redundant_rows && o.rows > 1; ++d) {
    const long r1 = long(rng.index(o.rows)), r2 = long(rng.index(o.rows)), sign = (rng.bits() & 1) ? 1 : -1;
    const long r = long(s.m++);
    const std::size_t end = s.triplets.size();
    for(std::size_t k = 0; k < end; ++k) {
      const Triplet t = s.triplets[k];
      if(t.row() == r1) s.triplets.emplace_back(r, t.col(), t.value());
      if(t.row() == r2) s.triplets.emplace_back(r, t.col(), sign * t.value());
    }
  }
  s.redundant_rows = o.redundant_rows;
  canonicalize(s);
  s.b.assign(s.m, 0);
  for(const Triplet& t : s.triplets) s.b[std::size_t(t.row())] += t.value() * long(s.solution[std::size_t(t.col())]);
  s.has_solution = true;
  std::ostringstream name; name << (o.homogeneous ? "random_hom_m" : "random_m") << s.m << "_n" << s.n << "_s" << o.seed;
  s.name = name.str();
  return s;
}

/// x̄ = solution + noise, noise uniform in relative_noise * max|solution| * [-1, 1) on constrained
/// columns; unconstrained columns get the solution value plus the same noise (they must come back
/// unchanged anyway).
inline std::vector<double> noisy_input(const Linear_system& s, double relative_noise, std::uint64_t seed)
{
  assert(s.solution.size() == s.n);                               // a system grown by hand must resize it
  Rng rng(seed);
  double scale = 0;
  for(double v : s.solution) scale = std::max(scale, std::abs(v));
  if(scale == 0) scale = 1;
  std::vector<double> xbar(s.n);
  for(std::size_t j = 0; j < s.n; ++j) xbar[j] = s.solution[j] + relative_noise * scale * rng.symmetric();
  return xbar;
}

// ---------------------------------------------------------------------------------------------
// Exact check: every row of the ORIGINAL C, each double converted exactly to Gmpq, zero tolerance.

/// returns the number of rows i with (C x)_i != b_i in exact rational arithmetic (every double
/// converted exactly to Gmpq, zero tolerance), or -1 on a size mismatch.
template <typename Scalar, int Options, typename StorageIndex, typename BRange>
long count_violated_rows(const Eigen::SparseMatrix<Scalar, Options, StorageIndex>& C, const BRange& b,
                         const std::vector<double>& x)
{
  typedef Eigen::SparseMatrix<Scalar, Options, StorageIndex> M;
  if(std::size_t(C.cols()) != x.size() || std::size_t(C.rows()) != std::size_t(b.size())) return -1;
  for(double v : x) if(!std::isfinite(v)) return long(C.rows()) + 1;   // not a real number at all
  std::vector<CGAL::Gmpq> xq(x.size());
  for(std::size_t j = 0; j < x.size(); ++j) xq[j] = CGAL::Gmpq(x[j]);  // exact: every double is a dyadic rational
  std::vector<CGAL::Gmpq> residual(std::size_t(C.rows()));
  for(Eigen::Index k = 0; k < C.outerSize(); ++k)
    for(typename M::InnerIterator it(C, k); it; ++it)       // explicit zeros and duplicates are harmless here
      residual[std::size_t(it.row())] += CGAL::Gmpq(CGAL::Gmpz(it.value())) * xq[std::size_t(it.col())];
  long bad = 0;
  for(std::size_t i = 0; i < residual.size(); ++i)
    if(residual[i] != CGAL::Gmpq(CGAL::Gmpz(b[i]))) ++bad;
  return bad;
}

/// true iff every ORIGINAL row of C x = b holds exactly in rational arithmetic.
template <typename Scalar, int Options, typename StorageIndex, typename BRange>
bool exactly_satisfied(const Eigen::SparseMatrix<Scalar, Options, StorageIndex>& C, const BRange& b,
                       const std::vector<double>& x)
{
  return count_violated_rows(C, b, x) == 0;
}
inline bool exactly_satisfied(const Linear_system& s, const std::vector<double>& x)
{
  return exactly_satisfied(s.matrix(), s.b, x);
}

/// rank of C over GF(p), p = 2^61 - 1 (a lower bound of the rational rank, equal to it unless p
/// divides every maximal nonzero minor: an independent cross-check of the core's rank). Forward
/// elimination row by row, pivot = leading column; fill-in is fine for the sparse test systems.
inline std::size_t rank_mod_p(const Linear_system& s)
{
  typedef unsigned __int128 U128;
  const std::uint64_t P = (std::uint64_t(1) << 61) - 1;
  auto mulmod = [&](std::uint64_t a, std::uint64_t c) { return std::uint64_t((U128(a) * c) % P); };
  auto powmod = [&](std::uint64_t a, std::uint64_t e) { std::uint64_t r = 1; while(e) { if(e & 1) r = mulmod(r, a); a = mulmod(a, a); e >>= 1; } return r; };
  auto to_mod = [&](long v) { return v >= 0 ? std::uint64_t(v) % P : (P - std::uint64_t(-v) % P) % P; };
  typedef std::vector<std::pair<long, std::uint64_t>> Row;   // sorted by column, nonzero values
  std::vector<Row> rows(s.m);
  for(const Triplet& t : s.triplets) rows[std::size_t(t.row())].emplace_back(t.col(), to_mod(t.value()));
  std::map<long, Row> pivots;                                   // leading column -> normalized row (leading 1)
  for(Row& r : rows) {
    std::sort(r.begin(), r.end());
    while(!r.empty()) {
      auto it = pivots.find(r.front().first);
      if(it == pivots.end()) {
        const std::uint64_t inv = powmod(r.front().second, P - 2);
        for(auto& e : r) e.second = mulmod(e.second, inv);
        pivots.emplace(r.front().first, r);
        break;
      }
      const std::uint64_t f = r.front().second;                 // r -= f * pivot row
      Row out; out.reserve(r.size() + it->second.size());
      std::size_t a = 0, c = 0;
      const Row& q = it->second;
      while(a < r.size() || c < q.size()) {
        if(c == q.size() || (a < r.size() && r[a].first < q[c].first)) { out.push_back(r[a++]); continue; }
        std::uint64_t sub = mulmod(f, q[c].second);
        if(a < r.size() && r[a].first == q[c].first) {
          std::uint64_t v = (r[a].second + P - sub) % P;
          if(v != 0) out.emplace_back(r[a].first, v);
          ++a; ++c;
        } else { out.emplace_back(q[c].first, (P - sub) % P); ++c; }
      }
      r.swap(out);
    }
  }
  return pivots.size();
}

/// sum of (x_j - xbar_j)^2, exact
inline CGAL::Gmpq exact_squared_distance(const std::vector<double>& x, const std::vector<double>& xbar)
{
  CGAL::Gmpq d(0);
  for(std::size_t j = 0; j < x.size(); ++j) { CGAL::Gmpq e = CGAL::Gmpq(x[j]) - CGAL::Gmpq(xbar[j]); d += e * e; }
  return d;
}

inline double max_abs_difference(const std::vector<double>& x, const std::vector<double>& xbar)
{
  double d = 0;
  for(std::size_t j = 0; j < x.size(); ++j) d = std::max(d, std::abs(x[j] - xbar[j]));
  return d;
}

// ---------------------------------------------------------------------------------------------
// Files: Matrix Market coordinate (1-based; integer, or real with integral values), one number per line.

inline bool parse_integral(const std::string& tok, long& out)
{
  char* end = nullptr;
  errno = 0;
  long long v = std::strtoll(tok.c_str(), &end, 10);
  if(errno == 0 && end != tok.c_str() && *end == '\0') { out = long(v); return true; }
  double d = std::strtod(tok.c_str(), &end);
  if(end == tok.c_str() || *end != '\0' || !std::isfinite(d) || d != std::floor(d) || std::abs(d) > 0x1p53) return false;
  out = long(d);
  return true;
}

/// reads a Matrix Market coordinate file (general or symmetric; integer or real with integral values).
inline bool read_matrix_market(const std::string& file, Linear_system& s, std::string& error)
{
  std::ifstream in(file);
  if(!in) { error = "cannot open " + file; return false; }
  std::string line;
  if(!std::getline(in, line) || line.compare(0, 14, "%%MatrixMarket") != 0) { error = file + ": no %%MatrixMarket header"; return false; }
  std::string header = line;
  std::transform(header.begin(), header.end(), header.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if(header.find("coordinate") == std::string::npos) { error = file + ": only the coordinate format is supported"; return false; }
  if(header.find("complex") != std::string::npos || header.find("pattern") != std::string::npos) {
    error = file + ": complex and pattern matrices are not supported"; return false; }
  const bool symmetric = header.find("symmetric") != std::string::npos;
  if(header.find("hermitian") != std::string::npos || header.find("skew") != std::string::npos) {
    error = file + ": only general and symmetric matrices are supported"; return false; }
  while(std::getline(in, line) && (line.empty() || line[0] == '%')) {}
  std::istringstream hs(line);
  long m = 0, n = 0, nnz = 0;
  if(!(hs >> m >> n >> nnz) || m < 0 || n < 0 || nnz < 0) { error = file + ": bad size line"; return false; }
  s = Linear_system();
  s.name = file; s.m = std::size_t(m); s.n = std::size_t(n);
  s.triplets.reserve(std::size_t(nnz));
  for(long k = 0; k < nnz; ++k) {
    if(!std::getline(in, line)) { error = file + ": fewer entries than announced"; return false; }
    if(line.empty() || line[0] == '%') { --k; continue; }
    std::istringstream ls(line);
    long i = 0, j = 0; std::string tok; long v = 0;
    if(!(ls >> i >> j >> tok) || !parse_integral(tok, v) || i < 1 || j < 1 || i > m || j > n) {
      error = file + ": bad entry line " + std::to_string(k + 1) + ": '" + line + "'"; return false; }
    s.triplets.emplace_back(i - 1, j - 1, v);
    if(symmetric && i != j) s.triplets.emplace_back(j - 1, i - 1, v);
  }
  canonicalize(s);
  s.b.assign(s.m, 0);
  return true;
}

inline bool write_matrix_market(const std::string& file, const Linear_system& s)
{
  std::ofstream out(file);
  out << "%%MatrixMarket matrix coordinate integer general\n% " << s.name << "\n"
      << s.m << ' ' << s.n << ' ' << s.triplets.size() << '\n';
  for(const Triplet& t : s.triplets) out << t.row() + 1 << ' ' << t.col() + 1 << ' ' << t.value() << '\n';
  return bool(out);
}

template <typename T>
bool read_vector(const std::string& file, std::vector<T>& v, std::string& error)
{
  std::ifstream in(file);
  if(!in) { error = "cannot open " + file; return false; }
  v.clear();
  std::string tok;
  while(in >> tok) {
    if(std::is_integral<T>::value) {
      long x; if(!parse_integral(tok, x)) { error = file + ": not an integer: " + tok; return false; }
      v.push_back(T(x));
    } else {
      char* end = nullptr;
      double x = std::strtod(tok.c_str(), &end);   // correctly rounded; "nan"/"inf" are passed on (the core rejects them)
      if(end == tok.c_str() || *end != '\0') { error = file + ": not a number: " + tok; return false; }
      v.push_back(T(x));
    }
  }
  return true;
}

template <typename T>
bool write_vector(const std::string& file, const std::vector<T>& v)
{
  std::ofstream out(file);
  out << std::setprecision(17);   // max_digits10: the round trip is bit-exact
  for(const T& x : v) out << x << '\n';
  return bool(out);
}

} // namespace SS_test

#endif // CGAL_SEAMLESS_SNAPPING_TEST_GENERATORS_H
