// Uses the installed package: projects x̄ onto a 2-row integer system C x = b and checks, in exact
// rational arithmetic (CGAL::Gmpq, zero tolerance), that the doubles it returns satisfy C x = b.
#include <CGAL/Seamless_snapping/Exact_constraint_projection.h>

#include <CGAL/Gmpq.h>

#include <Eigen/Sparse>

#include <cstdlib>
#include <iostream>
#include <vector>

namespace SS = CGAL::Seamless_snapping;

int main()
{
  //  x0 - x1 + x2      = 0
  //       2 x1    - x3 = 1
  std::vector<Eigen::Triplet<long> > t = {{0, 0, 1}, {0, 1, -1}, {0, 2, 1}, {1, 1, 2}, {1, 3, -1}};
  Eigen::SparseMatrix<long> C(2, 4);
  C.setFromTriplets(t.begin(), t.end());
  const std::vector<long> b = {0, 1};
  const std::vector<double> xbar = {0.1, 0.3 + 1e-12, 0.2, -0.4 - 3e-13};   // a solution plus solver noise

  SS::Exact_constraint_projection projection;
  if(projection.initialize(C, b) != SS::SUCCESS) {
    std::cerr << "initialize: " << SS::status_name(projection.status()) << ": " << projection.message() << "\n";
    return EXIT_FAILURE;
  }
  std::vector<double> x;
  const SS::Projection_report report = projection.project(xbar, x);
  if(report.status != SS::SUCCESS) {
    std::cerr << "project: " << SS::status_name(report.status) << ": " << report.message << "\n";
    return EXIT_FAILURE;
  }
  for(int i = 0; i < C.rows(); ++i) {
    CGAL::Gmpq r(0);
    for(int k = 0; k < C.outerSize(); ++k)
      for(Eigen::SparseMatrix<long>::InnerIterator it(C, k); it; ++it)
        if(it.row() == i) r += CGAL::Gmpq(double(it.value())) * CGAL::Gmpq(x[std::size_t(it.col())]);
    if(r != CGAL::Gmpq(double(b[std::size_t(i)]))) { std::cerr << "row " << i << " is violated\n"; return EXIT_FAILURE; }
  }
  std::cout << "consumer: C x = b holds exactly (2 rows, max |x - xbar| = " << report.max_abs_change << ")\n";
  return EXIT_SUCCESS;
}
