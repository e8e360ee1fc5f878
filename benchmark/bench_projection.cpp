// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// Timing and size table of CGAL::Seamless_snapping::Exact_constraint_projection.
//
//   bench_projection                     generated systems (seamless-like 2k..1M rows, random 1k..10k rows)
//   bench_projection --quick             only the small sizes
//   bench_projection --no-check          skip the exact Gmpq check of C x = b (default: checked)
//   bench_projection --write-dir DIR     also dump every system (generated, or with --real): DIR/<name>.mtx, _b.txt, _xbar.txt
//   bench_projection --matrix C.mtx [--rhs b.txt] --xbar x.txt [--out x.txt]
//                                        one system from files (Matrix Market coordinate, 1-based,
//                                        integer or real entries with integral values; one number per line)
//   bench_projection --real PATH ...     per-corner seam systems of OBJ files (PATH: a file or a directory, searched recursively for .obj;
//                                        see real_seam_system()); x̄ = the file's UVs. Repeatable.
//   --noise R                            relative noise of x̄ for generated systems (default 1e-9)
//   --time-limit S                       skip the remaining sizes of a family once one took > S seconds (default 120)
//   --repeat R                           run initialize + project R times per system (default 10; 3 from 100k
//                                        rows; fewer once the runs of a system took 10 s)
//   --both-modes                         a second row per system, "<name>/paper", timed with
//                                        Projection_options::minimal_change = false (what the minimal-change mode costs)
//
// One row per system: m, n, nnz, rank, IRREF nnz (fill-in), eliminations (fraction-free row updates), max|coef| of the IRREF, integer type,
// initialize ms, project ms and their total for the fastest of the R runs, the median total,
// max |x - x̄|, and whether every row of C x = b holds exactly (each double converted exactly to
// Gmpq, zero tolerance). Then the size of the change against the smallest exact change
// x* = argmin ||x - x̄||_2 s.t. C x = b (independent reference: exact residual, sparse QR of C^T,
// test/Seamless_snapping/l2_optimum_reference.h; systems up to 5000 rows): L2/opt for the default
// minimal-change mode and for the paper's mode (Projection_options::minimal_change = false), and
// the optimum's max |x* - x̄| in grid quanta. Times on shared virtual machines vary by up to 1.6x from minute to
// minute, so compare rows measured in one run.
//
// Seamless-like systems come in two variable orders. "chain": sectors and rows numbered along the
// cut chains, as a mesh traversal numbers them; "shuffled": rows and columns randomly permuted, the
// worst case for memory locality (every elimination step then touches new cache lines).
//
// Reference point to compare against: a well-known sparse implementation of the same method needs
// about 15 ms for 20 000 rows and 1.7 s for 1 000 000 rows (initialize + project, one core).

#include <CGAL/Seamless_snapping/Exact_constraint_projection.h>
#include <CGAL/Seamless_snapping/IO/OBJ.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>

#include "../test/Seamless_snapping/generators.h"
#include "../test/Seamless_snapping/l2_optimum_reference.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace SS = CGAL::Seamless_snapping;
using SS_test::Linear_system;

namespace {

struct Settings
{
  bool quick = false, check = true, both_modes = false;
  double noise = 1e-9;
  double time_limit_s = 120;
  int repeat = 0;                      // 0: 10 below 100k rows, else 3
  std::string write_dir, matrix, rhs, xbar, out;
  std::vector<std::string> real;
};

void print_header()
{
  std::printf("%-36s %8s %8s %9s %8s %10s %6s %9s %-5s %9s %10s %9s %9s %10s %9s %-6s %8s %8s %9s %s\n",
              "system", "m", "n", "nnz", "rank", "irref_nnz", "fill", "elim", "int", "init_ms", "project_ms", "total_ms",
              "median_ms", "max|x-x̄|", "max|coef|", "exact", "L2/opt", "paper", "opt(q)", "status");
}

std::string short_coefficient(const std::string& c)
{
  if(c.size() <= 9) return c;
  return c.substr(0, 1) + "." + c.substr(1, 2) + "e" + std::to_string(c.size() - 1);   // huge Gmpz entries, 3 digits
}

// returns the best total time (initialize + project) in ms
double bench(const Linear_system& s, const std::vector<double>& xbar, const Settings& set, std::vector<double>* x_out = nullptr,
             bool minimal_change = true)
{
  SS::Projection_options options;
  options.minimal_change = minimal_change;
  const int runs = set.repeat > 0 ? set.repeat : (s.m < 100000 ? 10 : 3);
  SS::Irref_statistics st;
  SS::Projection_report r;
  std::vector<double> x, totals;
  double best = -1, spent = 0;
  for(int run = 0; run < runs; ++run) {
    SS::Exact_constraint_projection p(options);
    SS::Projection_report rr;
    std::vector<double> xr;
    const SS::Status init = p.initialize(s.m, s.n, s.triplets, s.b);
    if(init == SS::SUCCESS) rr = p.project(xbar, xr);
    else { rr.status = init; rr.message = p.message(); }
    const double t = p.statistics().initialize_ms + (init == SS::SUCCESS ? rr.project_ms : 0.);
    totals.push_back(t);
    if(best < 0 || t < best) { best = t; st = p.statistics(); r = rr; x.swap(xr); }
    spent += t;
    if(spent > 10000.) break;                               // slow systems: fewer runs
  }
  std::sort(totals.begin(), totals.end());
  const double median = totals[totals.size() / 2];
  const char* exact = "-";
  if(r.status == SS::SUCCESS) {
    if(set.check) exact = SS_test::exactly_satisfied(s, x) ? "yes" : "NO";
    else exact = "skip";
  }
  const double total = best;
  // the change against the L2 optimum, for this mode and the paper's
  char l2[3][16] = {"-", "-", "-"};
  if(r.status == SS::SUCCESS && s.m <= 5000 && minimal_change) {     // the sparse QR reference is slow beyond (20k rows: minutes)
    std::vector<l2_reference::Row> rows(s.m);
    for(const auto& t : s.triplets) { rows[std::size_t(t.row())].col.push_back(int(t.col())); rows[std::size_t(t.row())].coef.push_back(long(t.value())); }
    for(std::size_t i = 0; i < s.m; ++i) rows[i].b = s.b[i];
    const l2_reference::Optimum opt = l2_reference::l2_optimum(rows, xbar);
    SS::Projection_options paper_options; paper_options.minimal_change = false;
    SS::Exact_constraint_projection paper(paper_options);
    std::vector<double> xp;
    const bool paper_ok = paper.initialize(s.m, s.n, s.triplets, s.b) == SS::SUCCESS && paper.project(xbar, xp).status == SS::SUCCESS;
    if(opt.ok) {
      std::snprintf(l2[0], 16, "%.4f", l2_reference::compare(opt, xbar, x, r.quantum).ratio_l2);
      if(paper_ok) std::snprintf(l2[1], 16, "%.3f", l2_reference::compare(opt, xbar, xp, r.quantum).ratio_l2);
      if(r.quantum > 0) std::snprintf(l2[2], 16, "%.3g", opt.max / r.quantum);
    }
  }
  const double fill = s.triplets.empty() ? 0. : double(st.irref_nonzeros) / double(s.triplets.size());
  std::printf("%-36s %8zu %8zu %9zu %8zu %10zu %6.2f %9zu %-5s %9.1f %10.1f %9.1f %9.1f %10.3g %9s %-6s %8s %8s %9s %s%s%s\n",
              (minimal_change ? s.name : s.name + "/paper").c_str(), s.m, s.n, s.triplets.size(), st.rank, st.irref_nonzeros, fill, st.eliminations, st.integer_type(),
              st.initialize_ms, r.status == SS::SUCCESS ? r.project_ms : 0., total, median, r.status == SS::SUCCESS ? r.max_abs_change : 0.,
              short_coefficient(st.max_abs_coefficient).c_str(), exact, l2[0], l2[1], l2[2], SS::status_name(r.status),
              r.status == SS::SUCCESS ? "" : ": ", r.status == SS::SUCCESS ? "" : r.message.c_str());
  std::fflush(stdout);
  if(x_out != nullptr && r.status == SS::SUCCESS) x_out->swap(x);
  if(minimal_change && set.both_modes) bench(s, xbar, set, nullptr, false);
  return total;
}

void dump(const Linear_system& s, const std::vector<double>& xbar, const Settings& set)
{
  if(set.write_dir.empty()) return;
  const std::string base = set.write_dir + "/" + s.name;
  if(!SS_test::write_matrix_market(base + ".mtx", s) || !SS_test::write_vector(base + "_b.txt", s.b) ||
     !SS_test::write_vector(base + "_xbar.txt", xbar))
    std::fprintf(stderr, "warning: could not write %s.*\n", base.c_str());
}

int run_files(const Settings& set)
{
  Linear_system s;
  std::string error;
  if(!SS_test::read_matrix_market(set.matrix, s, error)) { std::fprintf(stderr, "error: %s\n", error.c_str()); return EXIT_FAILURE; }
  if(!set.rhs.empty()) {
    if(!SS_test::read_vector(set.rhs, s.b, error)) { std::fprintf(stderr, "error: %s\n", error.c_str()); return EXIT_FAILURE; }
    if(s.b.size() != s.m) { std::fprintf(stderr, "error: %s has %zu entries, the matrix %zu rows\n", set.rhs.c_str(), s.b.size(), s.m); return EXIT_FAILURE; }
  }
  std::vector<double> xbar;
  if(set.xbar.empty()) { std::fprintf(stderr, "error: --matrix needs --xbar\n"); return EXIT_FAILURE; }
  if(!SS_test::read_vector(set.xbar, xbar, error)) { std::fprintf(stderr, "error: %s\n", error.c_str()); return EXIT_FAILURE; }
  if(xbar.size() != s.n) { std::fprintf(stderr, "error: %s has %zu entries, the matrix %zu columns\n", set.xbar.c_str(), xbar.size(), s.n); return EXIT_FAILURE; }
  print_header();
  std::vector<double> x;
  bench(s, xbar, set, &x);
  if(!set.out.empty()) {
    if(x.empty() && s.n != 0) { std::fprintf(stderr, "error: no solution, %s not written\n", set.out.c_str()); return EXIT_FAILURE; }
    if(!SS_test::write_vector(set.out, x)) { std::fprintf(stderr, "error: cannot write %s\n", set.out.c_str()); return EXIT_FAILURE; }
  }
  return x.size() == s.n ? EXIT_SUCCESS : EXIT_FAILURE;
}

// The per-corner seam system of an OBJ file, as a generic solver sees it: one variable pair (u, v)
// per `vt` of the file (columns 2t, 2t+1), and for each cut edge the two rows of Eq. 4,
//   R^k (f_i(a) - f_i(b)) - (f_j(a) - f_j(b)) = 0,
// with k the quarter turn that best maps the edge's UV vector in face i to the one in face j
// (fitted per edge). A cut edge is an edge whose two faces use different vt at one of its ends, so
// files with one vt per face corner (libQEx) have a cut edge at every edge, most of them with
// identical UVs on both sides. Positions are welded when bit-identical (Directional's cut meshes
// duplicate vertices along the seams: without it no seam is visible; elsewhere nothing changes),
// vt are kept as in the file. x̄ = the file's UVs, b = 0.
bool real_seam_system(const std::string& file, Linear_system& s, std::vector<double>& xbar, std::string& error)
{
  namespace IOi = SS::IO::internal;
  IOi::Obj_soup soup;
  std::ifstream is(file, std::ios::binary);
  if(!is || IOi::parse_obj(is, soup, file, error) != SS::SUCCESS) { if(error.empty()) error = "cannot read " + file; return false; }
  std::vector<std::size_t> rep(soup.points.size());
  std::map<std::array<std::uint64_t, 3>, std::size_t> first;           // bit-identical positions
  for(std::size_t i = 0; i < soup.points.size(); ++i) {
    const std::array<double, 3>& p = soup.points[i];
    rep[i] = first.emplace(std::array<std::uint64_t, 3>{IOi::double_bits(p[0]), IOi::double_bits(p[1]), IOi::double_bits(p[2])}, i).first->second;
  }
  s = Linear_system();
  s.name = std::filesystem::path(file).stem().string();
  s.n = 2 * soup.uvs.size();
  xbar.resize(s.n);
  for(std::size_t t = 0; t < soup.uvs.size(); ++t) { xbar[2 * t] = soup.uvs[t][0]; xbar[2 * t + 1] = soup.uvs[t][1]; }
  std::unordered_map<std::uint64_t, std::size_t> open;                 // (a, b) -> face * 3 + corner of a -> b
  for(std::size_t f = 0; f < soup.face_v.size(); ++f)
    for(std::size_t c = 0; c < 3; ++c) {
      const std::uint64_t a = rep[soup.face_v[f][c]], b = rep[soup.face_v[f][(c + 1) % 3]];
      const auto other = open.find((b << 32) | a);
      if(other == open.end()) { open.emplace((a << 32) | b, 3 * f + c); continue; }
      const std::size_t g = other->second / 3, d = other->second % 3;   // face g runs b -> a
      const std::size_t a1 = soup.face_vt[f][c], b1 = soup.face_vt[f][(c + 1) % 3];
      const std::size_t b2 = soup.face_vt[g][d], a2 = soup.face_vt[g][(d + 1) % 3];
      open.erase(other);
      if(a1 == a2 && b1 == b2) continue;                                 // not a cut edge
      const double d1[2] = { soup.uvs[a1][0] - soup.uvs[b1][0], soup.uvs[a1][1] - soup.uvs[b1][1] };
      const double d2[2] = { soup.uvs[a2][0] - soup.uvs[b2][0], soup.uvs[a2][1] - soup.uvs[b2][1] };
      int k = 0;
      double best = -1;
      for(int r = 0; r < 4; ++r) {
        double x, y;
        CGAL::Seamless_snapping::internal::rotate_quarter_turns(r, d1[0], d1[1], x, y);
        const double dot = x * d2[0] + y * d2[1];
        if(r == 0 || dot > best) { best = dot; k = r; }
      }
      const CGAL::Seamless_snapping::internal::Quarter_turn q(k);
      for(int comp = 0; comp < 2; ++comp) {
        const long row = long(s.m++);
        s.triplets.emplace_back(row, long(2 * a1 + q.col[comp]), long(q.sign[comp]));
        s.triplets.emplace_back(row, long(2 * b1 + q.col[comp]), long(-q.sign[comp]));
        s.triplets.emplace_back(row, long(2 * a2 + comp), -1L);
        s.triplets.emplace_back(row, long(2 * b2 + comp), 1L);
      }
    }
  s.b.assign(s.m, 0);
  SS_test::canonicalize(s);
  return true;
}

int run_real(const Settings& set)
{
  std::vector<std::string> files;
  for(const std::string& p : set.real) {
    if(std::filesystem::is_directory(p)) {
      std::vector<std::string> in_dir;
      for(const auto& e : std::filesystem::recursive_directory_iterator(p))
        if(e.path().extension() == ".obj") in_dir.push_back(e.path().string());
      std::sort(in_dir.begin(), in_dir.end());
      files.insert(files.end(), in_dir.begin(), in_dir.end());
    } else files.push_back(p);
  }
  std::printf("per-corner seam systems (one variable pair per vt, Eq. 4 rows per cut edge, x̄ = the file's UVs)\n");
  print_header();
  int status = EXIT_SUCCESS;
  for(const std::string& f : files) {
    Linear_system s;
    std::vector<double> xbar;
    std::string error;
    if(!real_seam_system(f, s, xbar, error)) { std::fprintf(stderr, "error: %s\n", error.c_str()); status = EXIT_FAILURE; continue; }
    dump(s, xbar, set);
    bench(s, xbar, set);
  }
  return status;
}

void usage(const char* prog)
{
  std::fprintf(stderr, "usage: %s [--quick] [--no-check] [--noise R] [--time-limit S] [--repeat R] [--write-dir DIR]\n"
                       "       %s --matrix C.mtx [--rhs b.txt] --xbar x.txt [--out x.txt] [--no-check]\n"
                       "       %s --real FILE_OR_DIR [--real ...] [--repeat R] [--no-check] [--both-modes] [--write-dir DIR]\n", prog, prog, prog);
}

} // namespace

int main(int argc, char** argv)
{
  Settings set;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) { usage(argv[0]); std::exit(EXIT_FAILURE); }
      return argv[++i];
    };
    if(a == "--quick") set.quick = true;
    else if(a == "--no-check") set.check = false;
    else if(a == "--noise") set.noise = std::atof(value().c_str());
    else if(a == "--time-limit") set.time_limit_s = std::atof(value().c_str());
    else if(a == "--repeat") set.repeat = std::max(1, std::atoi(value().c_str()));
    else if(a == "--write-dir") set.write_dir = value();
    else if(a == "--matrix") set.matrix = value();
    else if(a == "--rhs") set.rhs = value();
    else if(a == "--xbar") set.xbar = value();
    else if(a == "--out") set.out = value();
    else if(a == "--real") set.real.push_back(value());
    else if(a == "--both-modes") set.both_modes = true;
    else if(a == "-h" || a == "--help") { usage(argv[0]); return EXIT_SUCCESS; }
    else { std::fprintf(stderr, "unknown option %s\n", a.c_str()); usage(argv[0]); return EXIT_FAILURE; }
  }
  if(!set.matrix.empty()) return run_files(set);
  if(!set.real.empty()) return run_real(set);

  std::printf("Exact_constraint_projection benchmark (x̄ = exact solution + %.0e relative noise; exact = every row checked in Gmpq)\n",
              set.noise);
  std::printf("reference: a well-known sparse implementation needs ~15 ms (20 000 rows) and ~1.7 s (1 000 000 rows), initialize + project\n");
  std::printf("times: fastest of the repeated runs (median in median_ms); chain = numbered along the cut chains, shuffled = random order\n");
  print_header();
  std::vector<std::size_t> seamless_rows = { 2000, 20000, 100000, 1000000 };
  std::vector<std::size_t> random_rows = { 1000, 2000, 5000, 10000 };
  if(set.quick) { seamless_rows = { 2000, 20000 }; random_rows = { 1000 }; }

  std::uint64_t seed = 1;
  std::string versus;                                       // speed-ups against the reference point
  for(std::size_t rows : seamless_rows) {
    double ms = 0;
    for(const bool shuffle : { false, true }) {
      SS_test::Seamless_options o; o.target_rows = rows; o.seed = seed; o.shuffle = shuffle;
      Linear_system s = SS_test::seamless_system(o);
      s.name += shuffle ? "_shuffled" : "_chain";
      const std::vector<double> xbar = SS_test::noisy_input(s, set.noise, (seed + 1) * 31);
      dump(s, xbar, set);
      const double t = bench(s, xbar, set);
      ms = std::max(ms, t);
      const double reference_ms = rows == 20000 ? 15. : (rows == 1000000 ? 1700. : 0.);
      if(reference_ms > 0 && t > 0) {
        char line[128];
        std::snprintf(line, sizeof(line), "  %zu rows, %s order: %.1f ms, %.2fx faster than the reference (%.0f ms)\n",
                      rows, shuffle ? "shuffled" : "chain", t, reference_ms / t, reference_ms);
        versus += line;
      }
    }
    ++seed;
    if(ms > 1000. * set.time_limit_s) { std::printf("(larger seamless sizes skipped: %.1f s > --time-limit)\n", ms / 1000.); break; }
  }
  if(!versus.empty()) std::printf("seamless-like systems against the reference point (fastest run):\n%s", versus.c_str());
  // Unstructured random rows (4-8 entries in [-3, 3], n = 3m, b = C x* with x* integer): there is no
  // sparsity structure to exploit, so fill-in and coefficient growth are what they are.
  for(std::size_t rows : random_rows) {
    SS_test::Random_options o; o.rows = rows; o.columns_per_row = 3.; o.seed = seed++;
    const Linear_system s = SS_test::random_system(o);
    const std::vector<double> xbar = SS_test::noisy_input(s, set.noise, seed * 31);
    dump(s, xbar, set);
    const double ms = bench(s, xbar, set);
    if(ms > 1000. * set.time_limit_s) { std::printf("(larger random sizes skipped: %.1f s > --time-limit)\n", ms / 1000.); break; }
  }
  return EXIT_SUCCESS;
}
