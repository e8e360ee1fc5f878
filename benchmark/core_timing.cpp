// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// initialize() + project() of Exact_constraint_projection in the paper's mode, timed on one system,
// through the public API only, so that compare_core_revisions.sh can build it against the headers of
// another revision too (one that has no Projection_options::minimal_change is in the paper's mode anyway).
//
//   core_timing seamless ROWS SEED SHUFFLE [REPEAT]    a generated seamless-like system (generators.h)
//   core_timing random ROWS SEED [REPEAT]              random rows (4-8 entries in [-3, 3], n = 3m)
//   core_timing mtx C.mtx XBAR.txt [REPEAT]            a system from files (b = 0), e.g. bench_projection --write-dir
// Environment: PROJECT_ONLY=1 initializes once and times project() alone.
// Prints one line: the fastest initialize, project and total of REPEAT runs (default 10), the median
// total, the IRREF's nonzeros and a hash of x (the same x gives the same hash).

#include <CGAL/Seamless_snapping/Exact_constraint_projection.h>

#include "../test/Seamless_snapping/generators.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace SS = CGAL::Seamless_snapping;

template <typename Options> auto paper_mode(Options& o, int) -> decltype(o.minimal_change = false, void()) { o.minimal_change = false; }
template <typename Options> void paper_mode(Options&, long) {}     // a revision before the minimal-change mode

int main(int argc, char** argv)
{
  const std::string kind = argc > 1 ? argv[1] : "";
  SS_test::Linear_system s;
  std::vector<double> xbar;
  int repeat = 10;
  if((kind == "seamless" && argc >= 5) || (kind == "random" && argc >= 4)) {
    const std::size_t rows = std::size_t(std::atol(argv[2]));
    const std::uint64_t seed = std::uint64_t(std::atol(argv[3]));
    if(kind == "seamless") {
      SS_test::Seamless_options o; o.target_rows = rows; o.seed = seed; o.shuffle = std::atoi(argv[4]) != 0;
      s = SS_test::seamless_system(o);
      if(argc > 5) repeat = std::atoi(argv[5]);
    } else {
      SS_test::Random_options o; o.rows = rows; o.columns_per_row = 3.; o.seed = seed;
      s = SS_test::random_system(o);
      if(argc > 4) repeat = std::atoi(argv[4]);
    }
    xbar = SS_test::noisy_input(s, 1e-9, (seed + 1) * 31);
  } else if(kind == "mtx" && argc >= 4) {
    std::string error;
    if(!SS_test::read_matrix_market(argv[2], s, error) || !SS_test::read_vector(argv[3], xbar, error)) {
      std::fprintf(stderr, "error: %s\n", error.c_str());
      return EXIT_FAILURE;
    }
    s.b.assign(s.m, 0);
    if(argc > 4) repeat = std::atoi(argv[4]);
  } else {
    std::fprintf(stderr, "usage: %s seamless ROWS SEED SHUFFLE [REPEAT] | random ROWS SEED [REPEAT] | mtx C.mtx XBAR.txt [REPEAT]\n", argv[0]);
    return EXIT_FAILURE;
  }
  repeat = std::max(1, repeat);
  SS::Projection_options options;
  paper_mode(options, 0);
  const bool project_only = std::getenv("PROJECT_ONLY") != nullptr;
  SS::Exact_constraint_projection once(options);
  if(project_only) once.initialize(s.m, s.n, s.triplets, s.b);
  std::vector<double> init_ms, project_ms, total_ms, x;
  std::size_t irref_nonzeros = 0;
  for(int r = 0; r < repeat; ++r) {
    SS::Exact_constraint_projection fresh(options);
    SS::Exact_constraint_projection& p = project_only ? once : fresh;
    const auto t0 = std::chrono::steady_clock::now();
    if(!project_only) p.initialize(s.m, s.n, s.triplets, s.b);
    const auto t1 = std::chrono::steady_clock::now();
    const SS::Projection_report report = p.project(xbar, x);
    const auto t2 = std::chrono::steady_clock::now();
    if(report.status != SS::SUCCESS) x.clear();        // still timed: a failure has its cost too
    irref_nonzeros = p.statistics().irref_nonzeros;
    init_ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    project_ms.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
    total_ms.push_back(init_ms.back() + project_ms.back());
  }
  std::uint64_t hash = 1469598103934665603ull;                     // FNV-1a over the bits of x
  for(const double v : x) { std::uint64_t b; std::memcpy(&b, &v, 8); hash = (hash ^ b) * 1099511628211ull; }
  const double best_total = *std::min_element(total_ms.begin(), total_ms.end());
  std::sort(total_ms.begin(), total_ms.end());
  std::printf("init_min %.3f proj_min %.3f total_min %.3f total_med %.3f irref_nnz %zu hash %016llx\n",
              *std::min_element(init_ms.begin(), init_ms.end()), *std::min_element(project_ms.begin(), project_ms.end()),
              best_total, total_ms[total_ms.size() / 2], irref_nonzeros, (unsigned long long)hash);
  return EXIT_SUCCESS;
}
