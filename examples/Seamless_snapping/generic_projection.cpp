// Mesh-free use of the exact core: project an approximate solution of an integer system C x = b
// to doubles that satisfy every equation exactly (Mandad & Campen 2019, Sec. 4).
//
// Usage: generic_projection            (a small generated seamless-like system)
#include <CGAL/Seamless_snapping/Exact_constraint_projection.h>

#include <CGAL/Gmpq.h>

#include <Eigen/Sparse>

#include <cstdlib>
#include <iostream>
#include <random>
#include <vector>

namespace SS = CGAL::Seamless_snapping;

int main()
{
  // A chain of 1000 "transition" rows  x_i - x_{i+1} - (y_i - y_{i+1}) = 0  and one b != 0 row
  // 2 x_0 + 2 y_0 = 1, with x̄ an exact solution plus noise of 1e-9.
  const int L = 1000;
  const int n = 2 * (L + 1);                         // x_0..x_L, y_0..y_L
  std::vector<Eigen::Triplet<long> > t;
  std::vector<long> b;
  for(int i = 0; i < L; ++i) {
    t.emplace_back(i, i, 1);          t.emplace_back(i, i + 1, -1);
    t.emplace_back(i, L + 1 + i, -1); t.emplace_back(i, L + 2 + i, 1);
    b.push_back(0);
  }
  t.emplace_back(L, 0, 2); t.emplace_back(L, L + 1, 2); b.push_back(1);
  Eigen::SparseMatrix<long> C(L + 1, n);
  C.setFromTriplets(t.begin(), t.end());

  std::mt19937 gen(1);
  std::uniform_real_distribution<double> u(0, 1), noise(-1e-9, 1e-9);
  std::vector<double> xbar(n);
  for(int i = 0; i <= L; ++i) { double y = u(gen); xbar[L + 1 + i] = y; xbar[i] = y + 0.5 - 2 * xbar[L + 1]; }
  xbar[0] = 0.5 - xbar[L + 1];
  for(double& v : xbar) v += noise(gen);

  SS::Exact_constraint_projection projection;        // initialize once per system ...
  if(projection.initialize(C, b) != SS::SUCCESS) {
    std::cerr << "initialize failed: " << SS::status_name(projection.status()) << ": " << projection.message() << "\n";
    return EXIT_FAILURE;
  }
  std::vector<double> x;                             // ... project as often as needed
  SS::Projection_report report = projection.project(xbar, x);
  if(report.status != SS::SUCCESS) {
    std::cerr << "project failed: " << SS::status_name(report.status) << ": " << report.message << "\n";
    return EXIT_FAILURE;
  }
  const SS::Irref_statistics& st = projection.statistics();
  std::cout << "rows " << st.rows << ", rank " << st.rank << ", free " << st.free_variables << ", implied "
            << st.implied_variables << ", IRREF nonzeros " << st.irref_nonzeros << " (" << st.integer_type() << ")\n"
            << "max |x - xbar| = " << report.max_abs_change << ", grid quantum 2^" << report.delta_exponent - 52 << "\n";

  // Exactness is checked exactly: every double converted to a rational, zero tolerance.
  int violated = 0;
  std::vector<CGAL::Gmpq> r(C.rows(), CGAL::Gmpq(0));
  for(int k = 0; k < C.outerSize(); ++k)
    for(Eigen::SparseMatrix<long>::InnerIterator it(C, k); it; ++it)
      r[it.row()] += CGAL::Gmpq(double(it.value())) * CGAL::Gmpq(x[it.col()]);
  for(int i = 0; i < C.rows(); ++i) if(r[i] != CGAL::Gmpq(double(b[i]))) ++violated;
  std::cout << "rows violated in exact rational arithmetic: " << violated << " of " << C.rows() << "\n";
  return violated == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
