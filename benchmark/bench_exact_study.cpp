// The exact-arithmetic comparison study of Mandad & Campen 2019, Sec. 6.1, on the node systems
// (Sec. 5.3) of real parametrizations: one row per model, three ways to make C x = 0 hold.
//
//  1. CGAL's QP solver with an exact type (Gmpzf): the L2 optimum x* = argmin ||x - x̄|| s.t. C x = 0,
//     run in a child process with a limit on its CPU time (RLIMIT_CPU; '>limit' beyond it, and a
//     wall-clock cap of 3x the limit on a busy machine). Printed: time, the largest
//     numerator and denominator of x* in bits, and how many rows x* violates once its values are
//     rounded to doubles (CGAL::to_double), checked exactly.
//  2. naive floating-point evaluation of Eq. 2: free variables keep x̄, every implied variable is
//     (b̂_j - sum_i Ĉ_ji x_i) / p_j evaluated in double arithmetic from the same IRREF. Printed: rows
//     violated (exact check) and the largest exact violation.
//  3. ours: Exact_constraint_projection (initialize + project) on the same system. Printed: time
//     (the least of 3 runs),
//     whether every row holds exactly (checked again here), and the distance to x*:
//     ||x - x̄||_2 / ||x* - x̄||_2 and ||x - x*||_inf (relative to the UV bounding-box diagonal).
//
// The node system is built by the package's own stages (internal/surface/snap_pipeline.h:
// extract_seams, build_constraints, reduce_stage) with default options, as the snap does.
//
// usage: bench_exact_study [--qp-seconds S] [--qp-max-columns N] <file.obj | directory>...
//        (directories are searched recursively for *.obj; files under a "directional" folder are
//        welded, as Directional writes cut meshes). Without files: $SS_SHARED_DATA_DIR.
// Defaults: S = 20 s of CPU time per QP, N = 100000 (larger node systems print 'skipped'). Times in ms:
// ours is the CPU time of this process (least of 3 runs); the QP's is the CPU time of its child process
// (it includes building the program and the conversion of x* to Gmpq) when that is at least 100 ms,
// else the wall-clock time of the solve (the kernel's accounting is too coarse below), so that a shared
// machine does not inflate them.
// Not part of the test run.

#include <CGAL/Seamless_snapping/Exact_constraint_projection.h>
#include <CGAL/Seamless_snapping/internal/surface/snap_pipeline.h>

#include "obj_inputs.h"
#include "../test/Seamless_snapping/mesh_test_support.h"
#include "../test/Seamless_snapping/qp_reference.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace I = CGAL::Seamless_snapping::internal;

namespace {

// CPU time of this process, ms
double cpu_ms()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

// The node system of one model, over its used columns.
struct Node_system
{
  I::Constraint_rows rows;               // over the used columns 0..n-1
  std::size_t n = 0;
  std::vector<double> xbar;              // x̄ of the used columns
  double diagonal = 1;                   // UV bounding-box diagonal
};

bool node_system_of(Mesh& m, Node_system& ns, std::string& message)
{
  I::Snap_options opt;
  I::Snap_state<Mesh> S;
  SS::Snap_report report;
  auto none = [](auto) { return 0; };
  SS::Status s = I::extract_seams(m, uv_of(m), none, false, none, false, none, false, opt, S, report, message);
  if(s == SS::SUCCESS) s = I::build_constraints(opt, S, report, message);
  if(s == SS::SUCCESS) s = I::reduce_stage(S, report, message);
  if(s != SS::SUCCESS) return false;
  std::vector<int> vars, column_of;
  I::used_variables(S.rs.node_rows, 2 * std::size_t(S.st.n_sectors), vars, column_of);
  ns.rows = S.rs.node_rows;
  for(int& c : ns.rows.col) c = column_of[c];
  ns.n = vars.size();
  ns.xbar.resize(vars.size());
  for(std::size_t j = 0; j < vars.size(); ++j) ns.xbar[j] = S.st.ubar[vars[j]];
  ns.diagonal = S.st.uv_diagonal > 0 ? S.st.uv_diagonal : 1.;
  return true;
}

// rows violated by x (exact), and the largest exact violation rounded to double
std::size_t violated_rows(const I::Constraint_rows& rows, const std::vector<double>& x, double& worst)
{
  std::size_t bad = 0;
  worst = 0;
  for(std::size_t i = 0; i < rows.size(); ++i) {
    const CGAL::Mpzf r = I::exact_row_residual(rows, i, x);
    if(r.is_zero()) continue;
    ++bad;
    worst = std::max(worst, std::fabs(r.to_double()));
  }
  return bad;
}

// Eq. 2 in plain double arithmetic on the IRREF of [C | b]
void naive_evaluation(const Node_system& ns, std::vector<double>& x, bool& ok)
{
  const std::vector<long>& b = ns.rows.rhs;
  I::Integer_system sys;
  std::string msg;
  ok = I::build_integer_system(ns.rows.size(), ns.n, b, [&](auto&& add) {
         for(std::size_t i = 0; i < ns.rows.size(); ++i)
           for(std::size_t k = ns.rows.start[i]; k < ns.rows.start[i + 1]; ++k) add(i, std::size_t(ns.rows.col[k]), long(ns.rows.coef[k]));
       }, sys, msg) == SS::SUCCESS;
  I::Irref<CGAL::Gmpz> ir;
  ok = ok && I::compute_irref(sys, ir, msg) == SS::SUCCESS;
  x = ns.xbar;
  if(!ok) return;
  for(std::size_t j = 0; j < ir.rank(); ++j) {
    double r = CGAL::to_double(ir.rhs[j]);
    for(std::size_t q = ir.ptr[j]; q < ir.ptr[j + 1]; ++q) r -= CGAL::to_double(ir.val[q]) * ns.xbar[ir.col[q]];
    x[ir.pivot_col[j]] = r / CGAL::to_double(ir.pivot[j]);
  }
}

// What the QP child reports through its pipe.
struct Qp_result
{
  double ms = 0;
  long num_bits = 0, den_bits = 0;       // largest numerator / denominator of x*, in bits
  long violated_rounded = 0;             // rows violated by x* rounded to doubles
  double ratio = 0;                      // ||x_ours - x̄|| / ||x* - x̄||
  double dist_inf = 0;                   // ||x_ours - x*||_inf (rounded)
  int optimal = 0;
};

Qp_result solve_qp(const Node_system& ns, const std::vector<double>& ours)
{
  Qp_result r;
  std::vector<SS_test::Qp_entry> C;
  for(std::size_t i = 0; i < ns.rows.size(); ++i)
    for(std::size_t k = ns.rows.start[i]; k < ns.rows.start[i + 1]; ++k)
      C.push_back({ i, std::size_t(ns.rows.col[k]), long(ns.rows.coef[k]) });
  std::vector<CGAL::Gmpq> xs;
  const std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  r.optimal = SS_test::l2_optimum_qp(ns.rows.size(), ns.n, C, ns.rows.rhs, ns.xbar, xs);
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();   // wall clock
  if(!r.optimal) return r;
  std::vector<double> rounded(ns.n);
  CGAL::Gmpq d_opt(0), d_ours(0), dist(0);
  for(std::size_t j = 0; j < ns.n; ++j) {
    r.num_bits = std::max(r.num_bits, long(mpz_sizeinbase(mpq_numref(xs[j].mpq()), 2)));
    r.den_bits = std::max(r.den_bits, long(mpz_sizeinbase(mpq_denref(xs[j].mpq()), 2)));
    rounded[j] = CGAL::to_double(xs[j]);
    const CGAL::Gmpq xb(ns.xbar[j]), xo(ours[j]);
    d_opt += (xs[j] - xb) * (xs[j] - xb);
    d_ours += (xo - xb) * (xo - xb);
    const CGAL::Gmpq e = CGAL::abs(xo - xs[j]);
    if(dist < e) dist = e;
  }
  double worst;
  r.violated_rounded = long(violated_rows(ns.rows, rounded, worst));
  r.ratio = CGAL::is_zero(d_opt) ? (CGAL::is_zero(d_ours) ? 1. : HUGE_VAL) : std::sqrt(CGAL::to_double(d_ours / d_opt));
  r.dist_inf = CGAL::to_double(dist);
  return r;
}

// solve_qp() in a child process killed after `seconds`; false on timeout or failure
bool solve_qp_limited(const Node_system& ns, const std::vector<double>& ours, int seconds, Qp_result& out, std::string& why)
{
  int fd[2];
  if(pipe(fd) != 0) { why = "pipe failed"; return false; }
  std::fflush(stdout);
  const pid_t pid = fork();
  if(pid < 0) { why = "fork failed"; close(fd[0]); close(fd[1]); return false; }
  if(pid == 0) {
    close(fd[0]);
    const rlimit cpu = { rlim_t(seconds), rlim_t(seconds) + 1 };
    setrlimit(RLIMIT_CPU, &cpu);              // SIGXCPU ends the child at the CPU-time limit
    alarm(unsigned(3 * seconds));             // SIGALRM at 3x the limit in wall-clock time
    const Qp_result r = solve_qp(ns, ours);
    const bool written = write(fd[1], &r, sizeof r) == ssize_t(sizeof r);
    close(fd[1]);
    _exit(written ? 0 : 1);
  }
  close(fd[1]);
  Qp_result r;
  const ssize_t got = read(fd[0], &r, sizeof r);   // blocks until the child writes or ends
  close(fd[0]);
  int status = 0;
  rusage usage;
  wait4(pid, &status, 0, &usage);
  if(WIFSIGNALED(status) && (WTERMSIG(status) == SIGXCPU || WTERMSIG(status) == SIGKILL || WTERMSIG(status) == SIGALRM)) {
    why = "timeout";
    return false;
  }
  if(got != ssize_t(sizeof r) || !r.optimal) { why = "failed"; return false; }
  // the child's CPU time (kernel accounting) when it is long enough to be precise, else its wall-clock time
  const double child_cpu_ms = 1e3 * (double(usage.ru_utime.tv_sec) + double(usage.ru_stime.tv_sec))
                            + 1e-3 * (double(usage.ru_utime.tv_usec) + double(usage.ru_stime.tv_usec));
  if(child_cpu_ms >= 100.) r.ms = child_cpu_ms;
  out = r;
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  int qp_seconds = 20;
  std::size_t qp_max_columns = 100000;
  std::vector<fs::path> inputs;
  for(int i = 1; i < argc; ++i) {
    if(std::strcmp(argv[i], "--qp-seconds") == 0 && i + 1 < argc) { qp_seconds = std::max(1, std::atoi(argv[++i])); continue; }
    if(std::strcmp(argv[i], "--qp-max-columns") == 0 && i + 1 < argc) { qp_max_columns = std::size_t(std::atol(argv[++i])); continue; }
    inputs.emplace_back(argv[i]);
  }
  std::vector<fs::path> files;
  if(!collect_obj_files(inputs, std::string("usage: ") + argv[0] + " [--qp-seconds S] [--qp-max-columns N] <file.obj | directory>...  (or set SS_SHARED_DATA_DIR)", files)) return EXIT_FAILURE;

  std::printf("QP: CGAL::solve_quadratic_program with Gmpzf, limit %d s of CPU time per model. Times: ms (CPU; QP < 100 ms: wall clock).\n"
              "Distances |x - x*| relative to the UV diagonal; max viol.: largest exact |C_i x| of the naive Eq. 2.\n", qp_seconds);
  std::printf("%-36s %6s %6s | %10s %8s %8s %7s | %8s %9s | %8s %5s %8s %9s | %9s\n", "model", "rows", "cols",
              "QP ms", "num bits", "den bits", "viol.", "naive v.", "max viol", "ours ms", "exact", "d/d_opt", "|x-x*|inf", "QP/ours");
  int failures = 0;
  for(const fs::path& p : files) {
    Mesh m;
    std::string msg;
    Node_system ns;
    if(!load_obj(p, m) || !node_system_of(m, ns, msg)) {
      std::printf("%-36s cannot build the node system: %s\n", p.filename().string().c_str(), msg.c_str());
      ++failures;
      continue;
    }
    // ours: the public core on the node system, best of 3
    std::vector<Eigen::Triplet<long> > triplets;
    for(std::size_t i = 0; i < ns.rows.size(); ++i)
      for(std::size_t k = ns.rows.start[i]; k < ns.rows.start[i + 1]; ++k) triplets.emplace_back(int(i), ns.rows.col[k], long(ns.rows.coef[k]));
    const std::vector<long>& b = ns.rows.rhs;
    std::vector<double> ours;
    double ours_ms = HUGE_VAL;
    SS::Status status = SS::SUCCESS;
    for(int rep = 0; rep < 3 && status == SS::SUCCESS; ++rep) {
      SS::Exact_constraint_projection projection;
      const double t0 = cpu_ms();
      status = projection.initialize(ns.rows.size(), ns.n, triplets, b);
      if(status == SS::SUCCESS) status = projection.project(ns.xbar, ours).status;
      ours_ms = std::min(ours_ms, cpu_ms() - t0);
    }
    double worst_ours;
    const bool exact = status == SS::SUCCESS && violated_rows(ns.rows, ours, worst_ours) == 0;
    if(!exact) { ++failures; if(status != SS::SUCCESS) ours = ns.xbar; }

    // naive Eq. 2
    std::vector<double> naive;
    bool naive_ok;
    naive_evaluation(ns, naive, naive_ok);
    double naive_worst = 0;
    const std::size_t naive_bad = naive_ok ? violated_rows(ns.rows, naive, naive_worst) : 0;

    // the exact QP
    Qp_result qp;
    std::string why = "skipped";
    const bool qp_done = ns.n <= qp_max_columns && solve_qp_limited(ns, ours, qp_seconds, qp, why);
    char qp_cols[4][32], ratio_col[32], cmp_col[32];
    if(qp_done) {
      std::snprintf(qp_cols[0], 32, "%.3g", qp.ms);
      std::snprintf(qp_cols[1], 32, "%ld", qp.num_bits);
      std::snprintf(qp_cols[2], 32, "%ld", qp.den_bits);
      std::snprintf(qp_cols[3], 32, "%ld", qp.violated_rounded);
      std::snprintf(ratio_col, 32, "%.3g", qp.ratio);
      std::snprintf(cmp_col, 32, "%.3g", qp.dist_inf / ns.diagonal);
    } else {
      std::snprintf(qp_cols[0], 32, "%s", why == "timeout" ? (">" + std::to_string(qp_seconds * 1000)).c_str() : why.c_str());
      for(int c = 1; c < 4; ++c) std::snprintf(qp_cols[c], 32, "-");
      std::snprintf(ratio_col, 32, "-");
      std::snprintf(cmp_col, 32, "-");
    }
    char speed[32];
    if(qp_done) std::snprintf(speed, 32, "%.3g", qp.ms / ours_ms);
    else if(why == "timeout") std::snprintf(speed, 32, ">%.3g", qp_seconds * 1000. / ours_ms);
    else std::snprintf(speed, 32, "-");
    std::printf("%-36s %6zu %6zu | %10s %8s %8s %7s | %8zu %9.2g | %8.3g %5s %8s %9s | %9s\n",
                p.filename().string().c_str(), ns.rows.size(), ns.n, qp_cols[0], qp_cols[1], qp_cols[2], qp_cols[3],
                naive_bad, naive_worst, ours_ms, exact ? "yes" : "NO", ratio_col, cmp_col, speed);
    std::fflush(stdout);
  }
  if(failures) std::printf("%d model(s) failed\n", failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
