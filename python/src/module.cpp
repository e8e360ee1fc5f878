// Python bindings (pybind11, NumPy, SciPy sparse) of the package's matrix entry points:
// snap(V, F, UV, FUV, ...), is_exactly_seamless(V, F, UV, FUV, ...), is_exact_integer_grid_map(V, F, UV, FUV, ...),
// project(C, b, xbar, ...), motorcycle_graph(V, F, UV, FUV, ...), trace_isoline(V, F, UV, FUV, face, corner, direction, ...),
// read_obj(filename, weld, threads), write_obj(filename, V, F, UV, FUV) (IO/OBJ_matrices.h), extract_quad_mesh(V, F, UV, FUV, ...),
// quad_mesh_patches(QF), quad_layout(QF), quad_valences(V, F, UV, FUV, weld), write_vval(filename, valences) (IO/VVAL.h),
// diagnose_seamlessness(V, F, UV, FUV, ...).
// Thin: every check and every computation is the C++ library's; reports cross as JSON text. Arguments refused
// before any computation raise InputError (a ValueError), registered here for the Python side too.
#include <CGAL/Seamless_snapping/Exact_constraint_projection.h>
#include <CGAL/Seamless_snapping/IO/OBJ_matrices.h>
#include <CGAL/Seamless_snapping/IO/VVAL.h>
#include <CGAL/Seamless_snapping/IO/cut_mesh.h>
#include <CGAL/Seamless_snapping/Motorcycle_graph.h>
#include <CGAL/Seamless_snapping/diagnose_seamlessness.h>
#include <CGAL/Seamless_snapping/extract_quad_mesh.h>
#include <CGAL/Seamless_snapping/quad_layout.h>
#include <CGAL/Seamless_snapping/quad_mesh_patches.h>
#include <CGAL/Seamless_snapping/quad_valences.h>
#include <CGAL/Seamless_snapping/matrices.h>
#include <CGAL/Seamless_snapping/trace_isoline.h>
#include <CGAL/Seamless_snapping/internal/io/json_string.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cctype>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <set>
#include <string>
#include <vector>

namespace py = pybind11;
namespace SS = CGAL::Seamless_snapping;

typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> MatrixXdR;
typedef Eigen::Matrix<long long, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> MatrixXlR;

namespace {

// an argument refused before anything is computed; Python: seamless_snapping.InputError (a ValueError)
struct Input_error : std::invalid_argument
{
  // valid UTF-8 (Python decodes the message as UTF-8: a Latin-1 byte of a file left it empty)
  explicit Input_error(const std::string& what) : std::invalid_argument(SS::IO::internal::utf8_text(what)) {}
};

// (V, F, UV, FUV, message) of the OBJ file in its own layout (rows of V welded with `weld`); InputError with the
// reader's message ("<file>:<line>: <reason>") when it cannot be read
py::tuple read_obj(const std::string& filename, bool weld, unsigned threads)
{
  Eigen::MatrixXd V, UV;
  Eigen::MatrixXi F, FUV;
  std::string message;
  SS::Status s;
  {
    py::gil_scoped_release release;
    s = SS::IO::read_OBJ_matrices(filename, V, F, UV, FUV, message, SS::parameters::weld_vertices(weld).number_of_threads(threads));
  }
  if(s != SS::SUCCESS) throw Input_error(message);
  return py::make_tuple(V, F, UV, FUV, message);
}

// writes the matrices as an OBJ file (atomically); InputError with the writer's message when nothing was written
std::string write_obj(const std::string& filename, const MatrixXdR& V, const MatrixXlR& F, const MatrixXdR& UV,
                      const MatrixXlR& FUV)
{
  std::string message;
  SS::Status s;
  {
    py::gil_scoped_release release;
    s = SS::IO::write_OBJ_matrices(filename, V, F, UV, FUV, message);
  }
  if(s != SS::SUCCESS) throw Input_error(message);
  return message;
}

py::tuple snap(const MatrixXdR& V, const MatrixXlR& F, const MatrixXdR& UV, const MatrixXlR& FUV, bool weld,
               bool repair_flips, bool align_boundary, bool use_reduced_system, double rotation_tolerance,
               double alignment_tolerance, bool minimal_change, bool integer_grid_map, double grid_scale, bool untangle,
               double max_untangle_change, bool merge_cone_pairs, bool separate_cone_pairs, bool quantize, unsigned threads)
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
                         .integer_grid_map(integer_grid_map).grid_scale(grid_scale).untangle(untangle)
                         .max_untangle_change(max_untangle_change).merge_cone_pairs(merge_cone_pairs)
                         .separate_cone_pairs(separate_cone_pairs).quantize(quantize).number_of_threads(threads));
  }
  if(r.status != SS::SUCCESS) return py::make_tuple(py::none(), py::none(), r.to_json());
  return py::make_tuple(UV_out, FUV_out, r.to_json());
}

bool is_exactly_seamless(const MatrixXdR& V, const MatrixXlR& F, const MatrixXdR& UV, const MatrixXlR& FUV, bool weld)
{
  py::gil_scoped_release release;
  return SS::is_exactly_seamless(V, F, UV, FUV, SS::parameters::weld_vertices(weld));
}

// (IO::cut_mesh_test() of the mesh of (V, F) as it is, whether to weld it as the command-line programs decide,
// IO::read_welding_cut_meshes(): a cut mesh, or a mesh refused as it is but not welded)
py::tuple cut_mesh_test(const MatrixXdR& V, const MatrixXlR& F)
{
  py::gil_scoped_release release;
  const MatrixXdR UV = MatrixXdR::Zero(1, 2);                 // the UVs play no part: one row for every corner
  const MatrixXlR FUV = MatrixXlR::Zero(F.rows(), 3);
  SS::internal::Matrix_mesh_with_uv m;
  std::string message;
  bool cut = false, weld = false;
  if(SS::internal::mesh_from_matrices(V, F, UV, FUV, false, m, message) == SS::SUCCESS)
    weld = cut = SS::IO::cut_mesh_test(m.mesh).is_cut_mesh();
  else
    weld = SS::internal::mesh_from_matrices(V, F, UV, FUV, true, m, message) == SS::SUCCESS;
  py::gil_scoped_acquire acquire;
  return py::make_tuple(cut, weld);
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
  auto quoted = [](const std::string& s) { return SS::IO::internal::json_string(s); };
  o << "{\"status\": " << quoted(SS::status_name(r.status)) << ", \"message\": " << quoted(r.message)
    << ", \"delta_exponent\": " << r.delta_exponent << ", \"quantum\": " << r.quantum
    << ", \"max_abs_change\": " << r.max_abs_change << ", \"changed_variables\": " << r.changed_variables
    << ", \"input_violation\": " << SS::IO::internal::json_number(r.input_violation)
    << ", \"large_change\": " << (r.large_change ? "true" : "false")
    << ", \"per_row_grids\": " << (r.per_row_grids ? "true" : "false")
    << ", \"minimal_change\": " << (r.minimal_change ? "true" : "false")
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
    throw Input_error("C: row, column and value arrays differ in length");
  std::vector<Eigen::Triplet<long> > triplets;
  triplets.reserve(rows.size());
  for(std::size_t k = 0; k < rows.size(); ++k) {
    if(rows[k] < 0 || std::size_t(rows[k]) >= n_rows || cols[k] < 0 || std::size_t(cols[k]) >= n_cols)
      throw Input_error("C: entry " + std::to_string(k) + " lies outside the matrix");
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

// ---- tracing: the mesh of the matrices (the package's matrix-to-mesh conversion), traces as dicts ----

typedef SS::internal::Matrix_mesh Mesh;
typedef SS::Isoline_tracer<Mesh, SS::internal::Matrix_uv_map> Tracer;
typedef SS::Isoline_trace<Mesh> Trace;

// mesh vertex -> a row of V, mesh face -> its row of F, corner (halfedge) -> the row of V that F has there (welded, a
// vertex has several rows; a trace's start is named by the row of its start corner) (through the corners of the conversion)
struct Row_maps
{
  std::vector<long long> vertex_row, face_row, corner_row;
  Row_maps(const SS::internal::Matrix_mesh_with_uv& m, const MatrixXlR& F)
    : vertex_row(m.mesh.number_of_vertices(), -1), face_row(m.mesh.number_of_faces(), -1),
      corner_row(m.mesh.number_of_halfedges(), -1)
  {
    for(std::size_t f = 0; f < m.corner.size(); ++f)
      for(int k = 0; k < 3; ++k) {
        const Mesh::Halfedge_index h = m.corner[f][std::size_t(k)];
        const std::size_t v = std::size_t(m.mesh.target(h));
        if(std::size_t(h) < corner_row.size()) corner_row[std::size_t(h)] = F(Eigen::Index(f), k);
        if(v < vertex_row.size() && vertex_row[v] < 0) vertex_row[v] = F(Eigen::Index(f), k);
        const std::size_t fi = std::size_t(m.mesh.face(h));
        if(fi < face_row.size()) face_row[fi] = (long long)(f);
      }
  }
};

std::string rational(const CGAL::Gmpq& q)
{
  std::ostringstream o;
  o << q.numerator() << "/" << q.denominator();
  return o.str();
}

// `exact_uv`: with "uv_exact", the polyline's points as exact "p/q" strings
py::dict trace_dict(const Trace& t, const Mesh& mesh, const Row_maps& rows, bool exact_uv = true)
{
  py::dict d;
  d["end"] = SS::trace_end_name(t.end);
  d["failure"] = SS::is_failure(t.end);
  d["message"] = t.message;
  d["start"] = t.has_start_corner && std::size_t(t.start_corner) < rows.corner_row.size()
                   && rows.corner_row[std::size_t(t.start_corner)] >= 0 ? rows.corner_row[std::size_t(t.start_corner)]
               : t.has_start_vertex ? rows.vertex_row[std::size_t(t.start_vertex)] : -1LL;
  long long start_face = -1, start_corner = -1;
  if(t.has_start_corner) {
    start_face = rows.face_row[std::size_t(mesh.face(t.start_corner))];
    Mesh::Halfedge_index h = mesh.halfedge(mesh.face(t.start_corner));
    for(int k = 0; k < 3; ++k, h = mesh.next(h))
      if(h == t.start_corner) start_corner = k;
  }
  d["start_face"] = start_face;
  d["hit_trace"] = t.hit_trace;
  d["faces_crossed"] = t.faces_crossed;
  d["length"] = t.length;
  d["inexact_transfers"] = t.inexact_transfers;
  const py::ssize_t n = py::ssize_t(t.segments.size());
  py::array_t<long long> faces(n), dirs(n);
  py::array_t<double> uv({n, py::ssize_t(2), py::ssize_t(2)});
  py::array_t<double> points({n == 0 ? py::ssize_t(0) : n + 1, py::ssize_t(3)});
  auto fa = faces.mutable_unchecked<1>();
  auto da = dirs.mutable_unchecked<1>();
  auto ua = uv.mutable_unchecked<3>();
  auto pa = points.mutable_unchecked<2>();
  py::list exact;
  for(py::ssize_t i = 0; i < n; ++i) {
    const SS::Trace_segment<Mesh>& s = t.segments[std::size_t(i)];
    fa(i) = rows.face_row[std::size_t(s.face)];
    da(i) = int(s.direction);
    const SS::Trace_point<Mesh>* ends[2] = {&s.source, &s.target};
    for(int e = 0; e < 2; ++e) {
      ua(i, e, 0) = CGAL::to_double(ends[e]->u);
      ua(i, e, 1) = CGAL::to_double(ends[e]->v);
    }
    if(exact_uv) {
      py::list seg;
      for(const SS::Trace_point<Mesh>* p : ends) seg.append(py::make_tuple(rational(p->u), rational(p->v)));
      exact.append(seg);
    }
    if(i == 0) for(int c = 0; c < 3; ++c) pa(0, c) = s.source.position[std::size_t(c)];
    for(int c = 0; c < 3; ++c) pa(i + 1, c) = s.target.position[std::size_t(c)];
  }
  d["faces"] = faces;
  d["directions"] = dirs;
  d["uv"] = uv;
  if(exact_uv) d["uv_exact"] = exact;
  d["points"] = points;
  return d;
}

// the status of a map that could not be traced, as the graph's dict
py::dict failed_dict(SS::Status s, const std::string& message)
{
  py::dict d;
  d["status"] = SS::status_name(s);
  d["message"] = message;
  return d;
}

// the mesh of V, F, UV, FUV (GIL released while it is built); false with `failure` set when it cannot be built
bool mesh_or_failure(const MatrixXdR& V, const MatrixXlR& F, const MatrixXdR& UV, const MatrixXlR& FUV, bool weld,
                     SS::internal::Matrix_mesh_with_uv& m, py::dict& failure)
{
  std::string message;
  SS::Status s;
  {
    py::gil_scoped_release release;
    s = SS::internal::mesh_from_matrices(V, F, UV, FUV, weld, m, message);
  }
  if(s == SS::SUCCESS) return true;
  failure = failed_dict(s, message);
  return false;
}

py::dict motorcycle_graph(const MatrixXdR& V, const MatrixXlR& F, const MatrixXdR& UV, const MatrixXlR& FUV, bool weld,
                          std::size_t max_faces, double rotation_tolerance, bool exact_uv)
{
  SS::internal::Matrix_mesh_with_uv m;
  py::dict failure;
  if(!mesh_or_failure(V, F, UV, FUV, weld, m, failure)) return failure;
  std::unique_ptr<Tracer> tracer;
  SS::Motorcycle_graph<Mesh> g;
  {
    py::gil_scoped_release release;
    tracer.reset(new Tracer(m.mesh, m.uv, rotation_tolerance));
    g = SS::build_motorcycle_graph(*tracer, max_faces);
  }
  py::dict d = failed_dict(g.status, g.message);
  if(g.status != SS::SUCCESS) return d;
  const Row_maps rows(m, F);
  static const char* kinds[3] = {"cone", "border_corner", "seed"};
  py::list seps;
  std::size_t inexact = 0;
  for(std::size_t i = 0; i < g.separatrices.size(); ++i) {
    py::dict t = trace_dict(g.separatrices[i], m.mesh, rows, exact_uv);
    const int k = i < g.source_kind.size() ? g.source_kind[i] : -1;
    t["source"] = (k >= 0 && k < 3) ? kinds[k] : "unknown";
    inexact += g.separatrices[i].inexact_transfers;
    seps.append(t);
  }
  py::dict ends;
  for(int e = 0; e < SS::number_of_trace_ends; ++e) ends[SS::trace_end_name(SS::Trace_end(e))] = g.ends[std::size_t(e)];
  py::dict counts;
  counts["separatrices"] = g.separatrices.size();
  counts["failed"] = g.failed;
  counts["cones"] = g.cones;
  counts["border_corners"] = g.border_corners;
  counts["cones_with_wrong_ray_count"] = g.cones_with_wrong_ray_count;
  counts["inexact_transfers"] = inexact;
  d["counts"] = counts;
  d["ends"] = ends;
  d["seeded"] = g.seeded;
  d["separatrices"] = seps;
  py::dict layout;                       // the patch layout's counts (the refined mesh stays in C++)
  const SS::Patch_layout& L = g.layout;
  layout["status"] = SS::status_name(L.status);
  layout["message"] = L.message;
  layout["patches"] = L.patches.size();
  layout["quad_patches"] = L.quad_patches;
  layout["nodes"] = L.nodes;
  layout["arcs"] = L.arcs;
  layout["euler_characteristic"] = L.euler_characteristic;
  layout["surface_euler_characteristic"] = L.surface_euler_characteristic;
  layout["valid"] = L.is_valid();
  layout["subdivision_ms"] = L.subdivision_ms;
  layout["mesh_ms"] = L.mesh_ms;
  layout["measure_ms"] = L.measure_ms;
  d["layout"] = layout;
  d["trace_ms"] = g.trace_ms;
  return d;
}

py::dict trace_isoline(const MatrixXdR& V, const MatrixXlR& F, const MatrixXdR& UV, const MatrixXlR& FUV, long long face,
                       int corner, int direction, bool weld, std::size_t max_faces, double rotation_tolerance)
{
  if(face < 0 || face >= (long long)(F.rows()))
    throw Input_error("face " + std::to_string(face) + " is not a row of F (" +
                      (F.rows() == 0 ? std::string("F has none") : "0.." + std::to_string(F.rows() - 1)) + ")");
  if(corner < 0 || corner > 2) throw Input_error("corner " + std::to_string(corner) + " is not 0, 1 or 2");
  if(direction < 0 || direction > 3)
    throw Input_error("direction " + std::to_string(direction) + " is not 0 (+u), 1 (+v), 2 (-u) or 3 (-v)");
  SS::internal::Matrix_mesh_with_uv m;
  py::dict failure;
  if(!mesh_or_failure(V, F, UV, FUV, weld, m, failure)) return failure;
  std::unique_ptr<Tracer> tracer;
  Trace t;
  {
    py::gil_scoped_release release;
    tracer.reset(new Tracer(m.mesh, m.uv, rotation_tolerance));
    if(tracer->status() == SS::SUCCESS) {
      SS::Trace_options<Mesh> o;
      o.max_faces = max_faces;
      t = tracer->trace_from_vertex(m.corner[std::size_t(face)][std::size_t(corner)], SS::Trace_direction(direction), o);
    }
  }
  if(tracer->status() != SS::SUCCESS) return failed_dict(tracer->status(), tracer->message());
  const Row_maps rows(m, F);
  py::dict d = trace_dict(t, m.mesh, rows);
  d["status"] = "SUCCESS";
  return d;
}

// A message of quad_mesh_patches() / quad_layout() on the mesh that quad_mesh_from_rows() built, with the vertex it names
// ("vertex N is not manifold ...") in QF's numbering (`row_of`: per mesh vertex its index in QF; the faces are QF's rows)
std::string in_qf_numbering(const std::string& message, const std::vector<long long>* row_of)
{
  const std::string key = "vertex ";
  const std::size_t at = message.find(key), begin = at + key.size();
  if(row_of == nullptr || at == std::string::npos) return message;
  std::size_t end = begin;
  while(end < message.size() && std::isdigit(static_cast<unsigned char>(message[end]))) ++end;
  if(end == begin || end - begin > 9) return message;
  const std::size_t v = std::size_t(std::stoul(message.substr(begin, end - begin)));
  return v < row_of->size() ? message.substr(0, begin) + std::to_string((*row_of)[v]) + message.substr(end) : message;
}

// the patches of the quad mesh q (quad_mesh_patches()) into `out`: per quad its patch, its cell (i, j) and the rank in its
// row of QF of the vertex at the cell's corner (i, j) (QF lists the targets of halfedge(f), next(), ...), and the report
void add_patches(Mesh& q, py::dict& out, const std::vector<long long>* row_of = nullptr)
{
  auto patch = q.add_property_map<Mesh::Face_index, SS::Quad_patch_location<Mesh> >("f:patch").first;
  SS::Quad_patches patches = SS::quad_mesh_patches(q, patch);
  patches.message = in_qf_numbering(patches.message, row_of);
  const py::ssize_t nf = py::ssize_t(q.number_of_faces());
  py::array_t<long long> patch_id(nf), cell({nf, py::ssize_t(2)}), corner(nf);
  auto pa = patch_id.mutable_unchecked<1>();
  auto ce = cell.mutable_unchecked<2>();
  auto co = corner.mutable_unchecked<1>();
  for(Mesh::Face_index f : q.faces()) {
    const SS::Quad_patch_location<Mesh>& l = patch[f];
    const py::ssize_t i = py::ssize_t(f);
    pa(i) = patches.status == SS::SUCCESS ? (long long)(l.patch) : -1;
    ce(i, 0) = l.i;
    ce(i, 1) = l.j;
    co(i) = patches.status == SS::SUCCESS ? SS::patch_corner_rank(q, f, l) : 0;
  }
  q.remove_property_map(patch);
  out["QF_patch"] = patch_id;
  out["QF_patch_cell"] = cell;
  out["QF_patch_corner"] = corner;
  out["patches"] = patches.to_json();
}

// The quad mesh of an exact integer-grid map: (QV, QF, report JSON, the origins as arrays); QV, QF are None on failure.
py::tuple extract_quad_mesh(const MatrixXdR& V, const MatrixXlR& F, const MatrixXdR& UV, const MatrixXlR& FUV, bool weld,
                            double grid_scale, std::size_t max_grid_cells, bool split_valence_one_cones,
                            bool fill_branched_cells)
{
  SS::internal::Matrix_mesh_with_uv m;
  SS::Quad_mesh_report r;
  py::dict origins;
  {
    py::gil_scoped_release release;
    r.status = SS::internal::mesh_from_matrices(V, F, UV, FUV, weld, m, r.message);
  }
  if(r.status != SS::SUCCESS) return py::make_tuple(py::none(), py::none(), r.to_json(), origins);
  Mesh q;
  auto origin = q.add_property_map<Mesh::Vertex_index, SS::Quad_vertex_origin<Mesh> >("v:origin").first;
  auto covered = q.add_property_map<Mesh::Face_index, std::vector<Mesh::Face_index> >("f:covered").first;
  {
    py::gil_scoped_release release;
    r = SS::extract_quad_mesh(m.mesh, m.uv, q, SS::parameters::grid_scale(grid_scale).max_grid_cells(max_grid_cells)
                                                .split_valence_one_cones(split_valence_one_cones)
                                                .fill_branched_cells(fill_branched_cells),
                              SS::parameters::vertex_origin_map(origin).face_origin_map(covered));
  }
  if(r.status != SS::SUCCESS) return py::make_tuple(py::none(), py::none(), r.to_json(), origins);
  const Row_maps rows(m, F);
  const py::ssize_t nv = py::ssize_t(q.number_of_vertices()), nf = py::ssize_t(q.number_of_faces());
  py::array_t<double> QV({nv, py::ssize_t(3)});
  py::array_t<long long> QF({nf, py::ssize_t(4)}), location(nv), face(nv), vertex(nv), uv({nv, py::ssize_t(2)});
  auto qv = QV.mutable_unchecked<2>();
  auto qf = QF.mutable_unchecked<2>();
  auto lo = location.mutable_unchecked<1>();
  auto fa = face.mutable_unchecked<1>();
  auto va = vertex.mutable_unchecked<1>();
  auto ua = uv.mutable_unchecked<2>();
  for(Mesh::Vertex_index v : q.vertices()) {
    const py::ssize_t i = py::ssize_t(v);
    for(int c = 0; c < 3; ++c) qv(i, c) = q.point(v)[c];
    const SS::Quad_vertex_origin<Mesh>& o = origin[v];
    lo(i) = int(o.location);
    fa(i) = rows.face_row[std::size_t(o.face)];
    va(i) = o.location == SS::Quad_vertex_origin<Mesh>::VERTEX ? rows.vertex_row[std::size_t(m.mesh.target(o.halfedge))] : -1;
    ua(i, 0) = o.u;
    ua(i, 1) = o.v;
  }
  py::list faces;
  for(Mesh::Face_index f : q.faces()) {
    int k = 0;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(q.halfedge(f), q)) qf(py::ssize_t(f), k++) = (long long)(v);
    std::vector<long long> c;
    for(Mesh::Face_index g : covered[f]) c.push_back(rows.face_row[std::size_t(g)]);
    faces.append(py::array_t<long long>(py::ssize_t(c.size()), c.data()));
  }
  origins["QV_location"] = location;
  origins["QV_face"] = face;
  origins["QV_vertex"] = vertex;
  origins["QV_uv"] = uv;
  origins["QF_faces"] = faces;
  auto vertex_rows = [&](const std::vector<std::size_t>& vs) {   // rows of V (the report's numbers are the built mesh's)
    std::vector<long long> out;
    for(std::size_t v : vs) out.push_back(rows.vertex_row[v]);
    return py::array_t<long long>(py::ssize_t(out.size()), out.data());
  };
  origins["split_cones"] = vertex_rows(r.split_cones);
  origins["filled_branch_points"] = vertex_rows(r.filled_branch_points);
  origins["absorbed_cones"] = vertex_rows(r.absorbed_cones);
  add_patches(q, origins);
  return py::make_tuple(QV, QF, r.to_json(), origins);
}

// ---- diagnose_seamlessness(): the rows the snap would enforce, checked exactly on the map as it is ----

// "status", "message", "exact", "rows", "violated_rows", "violated_connections", and where a row is violated the
// worst one: "row", "kind", "edge" (its two rows of V, or None for a connection row), "corners" ([row of F, corner
// 0-2] per sector of the row), "residual" (exact, "p/q" in UV units) and "residual_double"
py::dict diagnose_seamlessness(const MatrixXdR& V, const MatrixXlR& F, const MatrixXdR& UV, const MatrixXlR& FUV, bool weld,
                               bool align_boundary, double rotation_tolerance, double alignment_tolerance,
                               bool integer_grid_map, double grid_scale)
{
  SS::internal::Matrix_mesh_with_uv m;
  SS::Seamless_diagnosis<Mesh> r;
  {
    py::gil_scoped_release release;
    r.status = SS::internal::mesh_from_matrices(V, F, UV, FUV, weld, m, r.message);
    if(r.status == SS::SUCCESS)
      r = SS::diagnose_seamlessness(m.mesh, m.uv, SS::parameters::align_boundary(align_boundary)
                                                    .rotation_tolerance(rotation_tolerance).alignment_tolerance(alignment_tolerance)
                                                    .integer_grid_map(integer_grid_map).grid_scale(grid_scale));
  }
  py::dict d = failed_dict(r.status, r.message);
  if(r.status == SS::SUCCESS) d["exact"] = r.exact;               // the rows were evaluated
  else d["exact"] = py::none();
  d["rows"] = r.rows;
  d["violated_rows"] = r.violated_rows;
  d["violated_connections"] = r.violated_connections;
  if(r.status != SS::SUCCESS || r.exact) return d;
  const Row_maps rows(m, F);
  d["row"] = r.row;
  d["kind"] = r.kind;
  if(r.kind == "connection") d["edge"] = py::none();
  else d["edge"] = py::make_tuple(rows.vertex_row[std::size_t(m.mesh.source(m.mesh.halfedge(r.edge)))],
                                  rows.vertex_row[std::size_t(m.mesh.target(m.mesh.halfedge(r.edge)))]);
  py::list corners;
  for(Mesh::Halfedge_index h : r.corners)
    for(std::size_t f = 0; f < m.corner.size(); ++f)
      for(int k = 0; k < 3; ++k)
        if(m.corner[f][std::size_t(k)] == h) corners.append(py::make_tuple((long long)(f), k));
  d["corners"] = corners;
  d["residual"] = r.residual;
  d["residual_double"] = r.residual_double;
  return d;
}

// ---- quad valences (quad_valences()) per row of V, and their VVAL file ----

// "status", "message", the rows of F of the fold-overs and zero-area triangles that prevent the valences, and on
// success per row of V "valence" (that of its vertex; 0 for a row no face uses) and "border" (its vertex on the border)
py::dict quad_valences(const MatrixXdR& V, const MatrixXlR& F, const MatrixXdR& UV, const MatrixXlR& FUV, bool weld)
{
  SS::internal::Matrix_mesh_with_uv m;
  SS::Quad_valences q;
  {
    py::gil_scoped_release release;
    q.status = SS::internal::mesh_from_matrices(V, F, UV, FUV, weld, m, q.message);
    if(q.status == SS::SUCCESS) q = SS::quad_valences(m.mesh, m.uv);
  }
  py::dict d = failed_dict(q.status, q.message);
  const Row_maps rows(m, F);
  auto face_rows = [&](const std::vector<std::size_t>& faces) {      // face ranks of the mesh -> rows of F
    py::array_t<long long> a(py::ssize_t(faces.size()));
    auto r = a.mutable_unchecked<1>();
    for(std::size_t i = 0; i < faces.size(); ++i) r(py::ssize_t(i)) = rows.face_row[faces[i]];
    return a;
  };
  d["fold_overs"] = face_rows(q.fold_overs);
  d["zero_area_faces"] = face_rows(q.zero_area_faces);
  if(q.status != SS::SUCCESS) return d;
  std::vector<char> on_border(q.valence.size(), 0);
  for(std::size_t v : q.border) on_border[v] = 1;
  py::array_t<long long> valence(py::ssize_t(V.rows()));
  py::array_t<bool> border(py::ssize_t(V.rows()));
  auto va = valence.mutable_unchecked<1>();
  auto bo = border.mutable_unchecked<1>();
  for(py::ssize_t i = 0; i < py::ssize_t(V.rows()); ++i) { va(i) = 0; bo(i) = false; }
  for(std::size_t f = 0; f < m.corner.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      const std::size_t v = std::size_t(m.mesh.target(m.corner[f][std::size_t(k)]));
      const py::ssize_t row = py::ssize_t(F(Eigen::Index(f), k));
      va(row) = q.valence[v];
      bo(row) = on_border[v] != 0;
    }
  d["valence"] = valence;
  d["border"] = border;
  return d;
}

// writes one valence per entry (IO::write_VVAL(), atomically); InputError when nothing was written (a valence
// below 0 or beyond an int, a file that cannot be written)
std::string write_vval(const std::string& filename, const py::array_t<long long, py::array::c_style | py::array::forcecast>& valences)
{
  if(valences.ndim() != 1) throw Input_error("the valences must be a 1-D array, one per vertex; it has " +
                                             std::to_string(valences.ndim()) + " dimensions");
  const auto a = valences.unchecked<1>();
  std::vector<int> v(std::size_t(a.shape(0)));
  for(py::ssize_t i = 0; i < a.shape(0); ++i) {
    if(a(i) < 0 || a(i) > std::numeric_limits<int>::max())
      throw Input_error("vertex " + std::to_string(i) + " has the valence " + std::to_string(a(i)) + ": the VVAL format "
                        "holds integers from 0 to " + std::to_string(std::numeric_limits<int>::max()) + "; nothing was written");
    v[std::size_t(i)] = int(a(i));
  }
  std::string message;
  if(SS::IO::write_VVAL(filename, v, message) != SS::SUCCESS) throw Input_error(message);
  return message;
}

// The quad mesh of the rows of QF (#QF x 4 vertex indices, counter-clockwise), built face by face with Euler::add_face(),
// on the indices that QF uses only (a row of large indices must not allocate that many vertices; rows of QV that no quad
// uses are no vertices of the mesh): returns per vertex of q its index in QF. A row that cannot be added (a repeated vertex,
// an index out of range, an edge in two quads in one direction or in a third quad) is named (InputError)
std::vector<long long> quad_mesh_from_rows(const MatrixXlR& QF, Mesh& q)
{
  if(QF.cols() != 4) throw Input_error("QF must have 4 columns (quads), not " + std::to_string(QF.cols()));
  std::vector<long long> used;
  used.reserve(std::size_t(QF.size()));
  for(Eigen::Index r = 0; r < QF.rows(); ++r)
    for(Eigen::Index c = 0; c < QF.cols(); ++c) {
      if(QF(r, c) < 0 || QF(r, c) >= (1LL << 31)) throw Input_error("QF[" + std::to_string(r) + ", " + std::to_string(c) + "] is not a vertex index");
      used.push_back((long long)QF(r, c));
    }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  for(std::size_t v = 0; v < used.size(); ++v) q.add_vertex(Mesh::Point(0, 0, 0));
  for(Eigen::Index r = 0; r < QF.rows(); ++r) {
    std::array<Mesh::Vertex_index, 4> c;
    for(int k = 0; k < 4; ++k)
      c[std::size_t(k)] = Mesh::Vertex_index(Mesh::size_type(std::lower_bound(used.begin(), used.end(), (long long)QF(r, k)) - used.begin()));
    if(std::set<Mesh::Vertex_index>(c.begin(), c.end()).size() != 4 || CGAL::Euler::add_face(c, q) == Mesh::null_face())
      throw Input_error("QF row " + std::to_string(r) + " cannot be added to a manifold quad mesh (a repeated vertex, "
                        "or an edge already in two quads or in one in the same direction)");
  }
  return used;
}

// quad_mesh_patches() on the quads of QF: the patches of extract_quad_mesh()'s report
py::dict quad_mesh_patches(const MatrixXlR& QF)
{
  Mesh q;
  const std::vector<long long> row_of = quad_mesh_from_rows(QF, q);
  py::dict out;
  add_patches(q, out, &row_of);
  return out;
}

// quad_layout() on the quads of QF: the report (JSON), "LV" (per layout vertex its row of QV), and per patch its polygon
// "LF" (layout vertices counter-clockwise from the patch's corner (0, 0)), "LF_corner" (vertex k a corner of the patch's
// rectangle) and "LF_length" (quad edges from vertex k to k + 1)
py::dict quad_layout(const MatrixXlR& QF)
{
  Mesh q, L;
  const std::vector<long long> row_of = quad_mesh_from_rows(QF, q);
  auto arcs = L.add_property_map<Mesh::Halfedge_index, SS::Quad_layout_arc<Mesh> >("h:arc").first;
  SS::Quad_layout r = SS::quad_layout(q, L, arcs);
  r.message = in_qf_numbering(r.message, &row_of);
  r.patches.message = in_qf_numbering(r.patches.message, &row_of);
  py::dict out;
  out["layout"] = r.to_json();
  out["patches"] = r.patches.to_json();
  if(r.status != SS::SUCCESS) return out;
  py::array_t<long long> LV(py::ssize_t(L.number_of_vertices()));
  auto lv = LV.mutable_unchecked<1>();
  for(Mesh::Vertex_index v : L.vertices()) lv(py::ssize_t(v)) = row_of[std::size_t(SS::layout_quad_vertex(q, L, arcs, v))];
  py::list faces, corners, lengths;
  for(Mesh::Face_index f : L.faces()) {
    std::vector<long long> vs, ls;
    std::vector<bool> cs;
    bool corner = true;                                     // L.halfedge(f) starts at the corner (0, 0)
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(L.halfedge(f), L)) {
      vs.push_back((long long)(L.source(h)));
      cs.push_back(corner);
      ls.push_back(arcs[h].length);
      corner = arcs[h].corner;
    }
    py::array_t<bool> c(py::ssize_t(cs.size()));
    for(std::size_t k = 0; k < cs.size(); ++k) c.mutable_at(py::ssize_t(k)) = cs[k];
    faces.append(py::array_t<long long>(py::ssize_t(vs.size()), vs.data()));
    corners.append(c);
    lengths.append(py::array_t<long long>(py::ssize_t(ls.size()), ls.data()));
  }
  out["LV"] = LV;
  out["LF"] = faces;
  out["LF_corner"] = corners;
  out["LF_length"] = lengths;
  return out;
}

} // namespace

PYBIND11_MODULE(_core, m)
{
  m.doc() = "Exact seamless snapping (Mandad & Campen 2019): C++ core of the seamless_snapping package";
  py::register_exception<Input_error>(m, "InputError", PyExc_ValueError);
  m.def("read_obj", &read_obj, py::arg("filename"), py::arg("weld"), py::arg("threads"));
  m.def("write_obj", &write_obj, py::arg("filename"), py::arg("V"), py::arg("F"), py::arg("UV"), py::arg("FUV"));
  m.def("snap", &snap, py::arg("V"), py::arg("F"), py::arg("UV"), py::arg("FUV"), py::arg("weld"),
        py::arg("repair_flips"), py::arg("align_boundary"), py::arg("use_reduced_system"),
        py::arg("rotation_tolerance"), py::arg("alignment_tolerance"), py::arg("minimal_change"),
        py::arg("integer_grid_map"), py::arg("grid_scale"), py::arg("untangle"), py::arg("max_untangle_change"),
        py::arg("merge_cone_pairs"), py::arg("separate_cone_pairs"), py::arg("quantize"), py::arg("threads"));
  m.def("cut_mesh_test", &cut_mesh_test, py::arg("V"), py::arg("F"));
  m.def("is_exactly_seamless", &is_exactly_seamless, py::arg("V"), py::arg("F"), py::arg("UV"), py::arg("FUV"),
        py::arg("weld"));
  m.def("is_exact_integer_grid_map", &is_exact_integer_grid_map, py::arg("V"), py::arg("F"), py::arg("UV"),
        py::arg("FUV"), py::arg("weld"), py::arg("grid_scale"));
  m.def("project", &project, py::arg("n_rows"), py::arg("n_cols"), py::arg("rows"), py::arg("cols"), py::arg("vals"),
        py::arg("b"), py::arg("xbar"), py::arg("delta_margin_bits"), py::arg("force_multiprecision"));
  m.def("motorcycle_graph", &motorcycle_graph, py::arg("V"), py::arg("F"), py::arg("UV"), py::arg("FUV"),
        py::arg("weld"), py::arg("max_faces"), py::arg("rotation_tolerance"), py::arg("exact_uv"));
  m.def("trace_isoline", &trace_isoline, py::arg("V"), py::arg("F"), py::arg("UV"), py::arg("FUV"), py::arg("face"),
        py::arg("corner"), py::arg("direction"), py::arg("weld"), py::arg("max_faces"), py::arg("rotation_tolerance"));
  m.def("quad_mesh_patches", &quad_mesh_patches, py::arg("QF"));
  m.def("quad_layout", &quad_layout, py::arg("QF"));
  m.def("extract_quad_mesh", &extract_quad_mesh, py::arg("V"), py::arg("F"), py::arg("UV"), py::arg("FUV"), py::arg("weld"),
        py::arg("grid_scale"), py::arg("max_grid_cells"), py::arg("split_valence_one_cones"),
        py::arg("fill_branched_cells"));
  m.def("diagnose_seamlessness", &diagnose_seamlessness, py::arg("V"), py::arg("F"), py::arg("UV"), py::arg("FUV"),
        py::arg("weld"), py::arg("align_boundary"), py::arg("rotation_tolerance"), py::arg("alignment_tolerance"),
        py::arg("integer_grid_map"), py::arg("grid_scale"));
  m.def("quad_valences", &quad_valences, py::arg("V"), py::arg("F"), py::arg("UV"), py::arg("FUV"), py::arg("weld"));
  m.def("write_vval", &write_vval, py::arg("filename"), py::arg("valences"));
  m.attr("default_max_grid_cells") = SS::default_max_grid_cells;
  m.attr("version") = "0.1.0";
}
