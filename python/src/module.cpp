// Python bindings (pybind11, NumPy, SciPy sparse) of the package's matrix entry points:
// snap(V, F, UV, FUV, ...), is_exactly_seamless(V, F, UV, FUV, ...), is_exact_integer_grid_map(V, F, UV, FUV, ...),
// project(C, b, xbar, ...).
// Thin: every check and every computation is the C++ library's; reports cross as JSON text.
#include <CGAL/Seamless_snapping/Exact_constraint_projection.h>
#include <CGAL/Seamless_snapping/matrices.h>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Sparse>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace py = pybind11;
namespace SS = CGAL::Seamless_snapping;

typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> MatrixXdR;
typedef Eigen::Matrix<long long, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> MatrixXlR;

namespace {

py::tuple snap(const MatrixXdR& V, const MatrixXlR& F, const MatrixXdR& UV, const MatrixXlR& FUV, bool weld,
               bool repair_flips, bool align_boundary, bool use_reduced_system, double rotation_tolerance,
               double alignment_tolerance, bool minimal_change, bool integer_grid_map, double grid_scale)
{
  Eigen::MatrixXd UV_out;
  Eigen::MatrixXi FUV_out;
  SS::Snap_report r;
  {
    py::gil_scoped_release release;
    r = SS::snap_seamless_parameterization(V, F, UV, FUV, UV_out, FUV_out,
          SS::parameters::weld_vertices(weld).repair_flips(repair_flips).align_boundary(align_boundary)
                         .use_reduced_system(use_reduced_system).rotation_tolerance(rotation_tolerance)
                         .alignment_tolerance(alignment_tolerance).minimal_change(minimal_change)
                         .integer_grid_map(integer_grid_map).grid_scale(grid_scale));
  }
  if(r.status != SS::SUCCESS) return py::make_tuple(py::none(), py::none(), r.to_json());
  return py::make_tuple(UV_out, FUV_out, r.to_json());
}

bool is_exactly_seamless(const MatrixXdR& V, const MatrixXlR& F, const MatrixXdR& UV, const MatrixXlR& FUV, bool weld)
{
  py::gil_scoped_release release;
  return SS::is_exactly_seamless(V, F, UV, FUV, SS::parameters::weld_vertices(weld));
}

bool is_exact_integer_grid_map(const MatrixXdR& V, const MatrixXlR& F, const MatrixXdR& UV, const MatrixXlR& FUV,
                               bool weld, double grid_scale)
{
  py::gil_scoped_release release;
  return SS::is_exact_integer_grid_map(V, F, UV, FUV, SS::parameters::weld_vertices(weld).grid_scale(grid_scale));
}

std::string projection_report_json(const SS::Projection_report& r, const SS::Irref_statistics& st)
{
  std::ostringstream o;
  o.precision(17);
  auto quoted = [](const std::string& s) {
    std::string q = "\"";
    for(char c : s) { if(c == '"' || c == '\\') q += '\\'; if(c == '\n') { q += "\\n"; continue; } q += c; }
    return q + "\"";
  };
  o << "{\"status\": " << quoted(SS::status_name(r.status)) << ", \"message\": " << quoted(r.message)
    << ", \"delta_exponent\": " << r.delta_exponent << ", \"quantum\": " << r.quantum
    << ", \"max_abs_change\": " << r.max_abs_change << ", \"changed_variables\": " << r.changed_variables
    << ", \"rank\": " << st.rank << ", \"free_variables\": " << st.free_variables
    << ", \"implied_variables\": " << st.implied_variables << ", \"irref_nonzeros\": " << st.irref_nonzeros
    << ", \"integer_type\": " << quoted(st.integer_type()) << ", \"initialize_ms\": " << st.initialize_ms
    << ", \"project_ms\": " << r.project_ms << "}";
  return o.str();
}

// C as COO triplets (rows, cols, integer values), already checked to be integral by the Python side.
py::tuple project(std::size_t n_rows, std::size_t n_cols, const std::vector<long long>& rows,
                  const std::vector<long long>& cols, const std::vector<long long>& vals, const std::vector<long long>& b,
                  const std::vector<double>& xbar, int delta_margin_bits, bool force_multiprecision)
{
  if(rows.size() != cols.size() || rows.size() != vals.size())
    throw std::invalid_argument("C: row, column and value arrays differ in length");
  std::vector<Eigen::Triplet<long> > triplets;
  triplets.reserve(rows.size());
  for(std::size_t k = 0; k < rows.size(); ++k) {
    if(rows[k] < 0 || std::size_t(rows[k]) >= n_rows || cols[k] < 0 || std::size_t(cols[k]) >= n_cols)
      throw std::invalid_argument("C: entry " + std::to_string(k) + " lies outside the matrix");
    triplets.emplace_back(Eigen::Index(rows[k]), Eigen::Index(cols[k]), long(vals[k]));
  }
  SS::Projection_options options;
  options.delta_margin_bits = delta_margin_bits;
  options.force_multiprecision = force_multiprecision;
  SS::Exact_constraint_projection p(options);
  std::vector<double> x;
  SS::Projection_report r;
  {
    py::gil_scoped_release release;
    const std::vector<long> bl(b.begin(), b.end());
    const SS::Status s = p.initialize(n_rows, n_cols, triplets, bl);
    if(s == SS::SUCCESS) r = p.project(xbar, x);
    else { r.status = s; r.message = p.message(); }
  }
  const std::string json = projection_report_json(r, p.statistics());
  if(r.status != SS::SUCCESS) return py::make_tuple(py::none(), json);
  return py::make_tuple(py::array_t<double>(py::ssize_t(x.size()), x.data()), json);
}

} // namespace

PYBIND11_MODULE(_core, m)
{
  m.doc() = "Exact seamless snapping (Mandad & Campen 2019): C++ core of the seamless_snapping package";
  m.def("snap", &snap, py::arg("V"), py::arg("F"), py::arg("UV"), py::arg("FUV"), py::arg("weld"),
        py::arg("repair_flips"), py::arg("align_boundary"), py::arg("use_reduced_system"),
        py::arg("rotation_tolerance"), py::arg("alignment_tolerance"), py::arg("minimal_change"),
        py::arg("integer_grid_map"), py::arg("grid_scale"));
  m.def("is_exactly_seamless", &is_exactly_seamless, py::arg("V"), py::arg("F"), py::arg("UV"), py::arg("FUV"),
        py::arg("weld"));
  m.def("is_exact_integer_grid_map", &is_exact_integer_grid_map, py::arg("V"), py::arg("F"), py::arg("UV"),
        py::arg("FUV"), py::arg("weld"), py::arg("grid_scale"));
  m.def("project", &project, py::arg("n_rows"), py::arg("n_cols"), py::arg("rows"), py::arg("cols"), py::arg("vals"),
        py::arg("b"), py::arg("xbar"), py::arg("delta_margin_bits"), py::arg("force_multiprecision"));
  m.attr("version") = "0.1.0";
}
