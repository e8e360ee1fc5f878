// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// libFuzzer target: Exact_constraint_projection on a small integer system C x = b with input x̄,
// decoded from the bytes (format: projection_bytes.h). It checks
//  - on SUCCESS: x has n finite entries, every row of C x = b holds in rational arithmetic
//    (CGAL::Gmpq, from the triplets as given, duplicates summed exactly), columns in no row are
//    copied bit for bit, and for b = 0 the projection of 2^j x̄ is 2^j x bit for bit (scale covariance,
//    when 2^j x̄ stays far from the subnormal and overflow ranges);
//  - on failure: x is untouched, and a failed initialize() is the status project() reports.
// Any violation aborts (a finding). Build: -DSEAMLESS_SNAPPING_FUZZ=ON with clang (README.md, "Sanitizers and fuzzing").
// The bit-for-bit checks compare outputs of one run from the same input bits (copies, untouched x, 2^j scaling):
// machine independent, no stored bits.

#include "projection_bytes.h"

#include <CGAL/Seamless_snapping/Exact_constraint_projection.h>

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace SS = CGAL::Seamless_snapping;

#define FUZZ_REQUIRE(cond, what) \
  do { if(!(cond)) { std::fprintf(stderr, "fuzz_projection: violated: %s (%s)\n", what, #cond); std::abort(); } } while(0)

static bool bit_identical(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

static bool all_rows_hold(const SS_fuzz::Fuzz_system& s, const std::vector<double>& x)
{
  std::vector<CGAL::Gmpq> lhs(s.m, CGAL::Gmpq(0));
  for(const auto& t : s.triplets)
    lhs[std::size_t(t.row())] += CGAL::Gmpq(CGAL::Gmpz(long(t.value()))) * CGAL::Gmpq(x[std::size_t(t.col())]);
  for(std::size_t i = 0; i < s.m; ++i)
    if(lhs[i] != CGAL::Gmpq(CGAL::Gmpz(long(s.b[i])))) return false;
  return true;
}

// true when every x̄_i is 0 or has |x̄_i| in [2^-800, 2^800], also after scaling by 2^j
static bool scale_check_applies(const std::vector<double>& xbar, int j)
{
  for(double v : xbar) {
    if(v == 0) continue;
    if(!std::isfinite(v)) return false;
    const int e = std::ilogb(v);
    if(e < -800 || e > 800 || e + j < -800 || e + j > 800) return false;
  }
  return true;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const SS_fuzz::Fuzz_system s = SS_fuzz::decode_system(data, size);
  SS::Projection_options options;
  options.force_multiprecision = s.force_multiprecision;
  options.delta_margin_bits = s.delta_margin_bits;
  SS::Exact_constraint_projection projection(options);
  const SS::Status init = projection.initialize(s.m, s.n, s.triplets, s.b);

  const std::vector<double> before{ 42., -0.5 };        // what x holds before project()
  std::vector<double> x = before;
  const SS::Projection_report report = projection.project(s.xbar, x);
  if(report.status != SS::SUCCESS) {
    FUZZ_REQUIRE(bit_identical(x, before), "x untouched on failure");
    FUZZ_REQUIRE(init == SS::SUCCESS || report.status == init, "a failed initialize() is reported by project()");
    return 0;
  }
  FUZZ_REQUIRE(init == SS::SUCCESS, "no SUCCESS after a failed initialize()");
  FUZZ_REQUIRE(x.size() == s.n, "x has n entries");
  for(double v : x) FUZZ_REQUIRE(std::isfinite(v), "finite x");
  FUZZ_REQUIRE(all_rows_hold(s, x), "every row of C x = b holds exactly (Gmpq)");
  std::vector<char> constrained(s.n, 0);
  {                                                         // a column whose duplicates cancel is in no row
    std::vector<std::vector<std::pair<std::size_t, CGAL::Gmpz>>> per_row(s.m);
    for(const auto& t : s.triplets) {
      auto& row = per_row[std::size_t(t.row())];
      bool found = false;
      for(auto& e : row) if(e.first == std::size_t(t.col())) { e.second += CGAL::Gmpz(long(t.value())); found = true; }
      if(!found) row.emplace_back(std::size_t(t.col()), CGAL::Gmpz(long(t.value())));
    }
    for(const auto& row : per_row)
      for(const auto& e : row) if(e.second != 0) constrained[e.first] = 1;
  }
  for(std::size_t j = 0; j < s.n; ++j)
    if(!constrained[j]) FUZZ_REQUIRE(std::memcmp(&x[j], &s.xbar[j], sizeof(double)) == 0, "columns in no row are copied");

  bool homogeneous = true;
  for(std::int64_t v : s.b) homogeneous = homogeneous && v == 0;
  if(homogeneous && s.scale_exponent != 0 && scale_check_applies(s.xbar, s.scale_exponent)) {
    std::vector<double> scaled(s.n), xs;
    for(std::size_t j = 0; j < s.n; ++j) scaled[j] = std::ldexp(s.xbar[j], s.scale_exponent);
    const SS::Projection_report rs = projection.project(scaled, xs);
    FUZZ_REQUIRE(rs.status == SS::SUCCESS, "2^j x̄ projects too (b = 0)");
    for(std::size_t j = 0; j < s.n; ++j) {
      const double expected = std::ldexp(x[j], s.scale_exponent);
      FUZZ_REQUIRE(std::memcmp(&xs[j], &expected, sizeof(double)) == 0, "projection of 2^j x̄ is 2^j x (b = 0)");
    }
  }
  return 0;
}
