// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_INPUTS_ORBIFOLD_TUTTE_INPUT_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_INPUTS_ORBIFOLD_TUTTE_INPUT_H

// Test and example input: an *approximately* seamless corner UV map of a closed genus-0 surface,
// made with CGAL's Orbifold Tutte embedding (Aigerman & Lipman 2015, CGAL Surface_mesh_parameterization).
// The orbifold solve is a floating-point linear solve, so its seam transitions hold only up to
// solver error (~1e-13..1e-12 relative), which is what the snapping is meant to repair.
//
//   Square        3 cones (90, 90, 180 degrees), seam transitions are +-90 degree rotations
//   Parallelogram 4 cones (180 degrees each),   seam transitions are 180 degree rotations / translations
//   Triangle      3 cones,                      120 degree rotations: NOT quarter-turn seamless
//                                               (the snapping must refuse it; used as a negative test)
//   Diamond       3 cones,                      120 degree rotations as well
//
// Everything here is undocumented helper code (namespace internal); it is not an exactness tool:
// `fit_seam_transitions()` works in double, `exact_max_seam_violation()` evaluates in CGAL::Gmpq.

#include <CGAL/Seamless_snapping/Seam_mesh_uv.h>
#include <CGAL/Seamless_snapping/Status.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Orbifold_Tutte_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/orbifold_enums.h>
#include <CGAL/Surface_mesh_parameterization/orbifold_shortest_path.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Kernel_traits.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <functional>
#include <iterator>
#include <limits>
#include <queue>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

namespace SMP = CGAL::Surface_mesh_parameterization;

/// The name of an orbifold type, and how many cones it needs.
inline const char* orbifold_type_name(SMP::Orbifold_type t)
{
  switch(t) {
    case SMP::Square:        return "Square";
    case SMP::Diamond:       return "Diamond";
    case SMP::Triangle:      return "Triangle";
    case SMP::Parallelogram: return "Parallelogram";
  }
  return "unknown orbifold type";
}

inline std::size_t orbifold_cone_count(SMP::Orbifold_type t) { return t == SMP::Parallelogram ? 4 : 3; }

// SMP::get_error_message() of CGAL 5.5.1 has 9 strings for 10 codes (ERROR_WRONG_PARAMETER gives
// a null pointer); this one is complete.
inline const char* smp_error_name(SMP::Error_code e)
{
  switch(e) {
    case SMP::OK:                               return "OK";
    case SMP::ERROR_EMPTY_MESH:                 return "empty mesh";
    case SMP::ERROR_NON_TRIANGULAR_MESH:        return "mesh is not triangular";
    case SMP::ERROR_NO_TOPOLOGICAL_DISC:        return "mesh is not a topological disc";
    case SMP::ERROR_NO_TOPOLOGICAL_BALL:        return "mesh is not a topological ball";
    case SMP::ERROR_BORDER_TOO_SHORT:           return "border too short";
    case SMP::ERROR_NON_CONVEX_BORDER:          return "non-convex border";
    case SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "cannot solve the linear system";
    case SMP::ERROR_NO_1_TO_1_MAPPING:          return "no one-to-one mapping";
    case SMP::ERROR_WRONG_PARAMETER:            return "wrong parameter (cone count or placement)";
  }
  return "unknown error";
}

// CGAL's orbifold code prints diagnostics to std::cerr, and an empty line for every shortest
// path (compute_shortest_paths_between_two_cones stops Dijkstra by throwing an exception whose
// empty what() it prints). This guard captures them, so that they can go into a message instead.
// Not thread-safe (std::cerr is global): this is test/example input code.
class Scoped_cerr_capture
{
  std::ostringstream m_text;
  std::streambuf* m_old;
public:
  Scoped_cerr_capture() : m_old(std::cerr.rdbuf(m_text.rdbuf())) {}
  ~Scoped_cerr_capture() { std::cerr.rdbuf(m_old); }
  Scoped_cerr_capture(const Scoped_cerr_capture&) = delete;
  Scoped_cerr_capture& operator=(const Scoped_cerr_capture&) = delete;
  /// " (CGAL: <text on one line>)", or "" when nothing but white space was printed
  std::string str() const
  {
    std::string s = m_text.str();
    for(char& c : s) if(c == '\n' || c == '\r') c = ' ';
    const std::size_t b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
    return b == std::string::npos ? std::string() : " (CGAL: " + s.substr(b, e - b + 1) + ")";
  }
};

// Dijkstra over the edge graph with Euclidean edge lengths, from several sources at once.
// Ties are broken by vertex index, so the result does not depend on anything but the mesh.
template <class Point_3>
std::vector<double> edge_graph_distances(const Surface_mesh<Point_3>& sm,
                                         const std::vector<typename Surface_mesh<Point_3>::Vertex_index>& sources)
{
  typedef typename Surface_mesh<Point_3>::Vertex_index   Vertex_index;
  typedef typename Surface_mesh<Point_3>::Halfedge_index Halfedge_index;
  std::vector<double> dist(sm.num_vertices(), std::numeric_limits<double>::infinity());
  typedef std::pair<double, std::size_t> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
  for(Vertex_index s : sources) { dist[s.idx()] = 0; queue.push(Item(0., s.idx())); }
  while(!queue.empty()) {
    const Item top = queue.top(); queue.pop();
    if(top.first > dist[top.second]) continue;
    const Vertex_index v(static_cast<typename Vertex_index::size_type>(top.second));
    if(sm.is_isolated(v)) continue;
    for(Halfedge_index h : CGAL::halfedges_around_source(v, sm)) {
      const Vertex_index w = sm.target(h);
      const double len = std::sqrt(CGAL::to_double(CGAL::squared_distance(sm.point(v), sm.point(w))));
      const double d = top.first + len;
      if(d < dist[w.idx()]) { dist[w.idx()] = d; queue.push(Item(d, w.idx())); }
    }
  }
  return dist;
}

template <class Point_3>
bool order_cones_for_seam(const Surface_mesh<Point_3>& sm, std::vector<typename Surface_mesh<Point_3>::Vertex_index>& cones);

/// `count` cones spread over `sm` by farthest-point sampling of the edge-graph distance:
/// the first cone is the vertex farthest from vertex 0, each next one maximises the distance to
/// the cones chosen so far (ties: smallest index). Deterministic. Returns fewer when the mesh
/// has fewer reachable vertices. The cones are returned in an order whose seam (shortest paths
/// between consecutive cones) is a simple path when such an order exists (`order_cones_for_seam()`).
template <class Point_3>
std::vector<typename Surface_mesh<Point_3>::Vertex_index>
farthest_point_cones(const Surface_mesh<Point_3>& sm, std::size_t count)
{
  typedef typename Surface_mesh<Point_3>::Vertex_index Vertex_index;
  std::vector<Vertex_index> cones;
  if(sm.number_of_vertices() == 0 || count == 0) return cones;
  auto farthest = [&](const std::vector<double>& d) {
    std::size_t best = std::size_t(-1);
    for(Vertex_index v : sm.vertices())
      if(std::isfinite(d[v.idx()]) && d[v.idx()] > 0 && (best == std::size_t(-1) || d[v.idx()] > d[best]))
        best = v.idx();
    return best;
  };
  std::vector<double> d = edge_graph_distances(sm, std::vector<Vertex_index>(1, *sm.vertices().begin()));
  std::size_t first = farthest(d);
  if(first == std::size_t(-1)) return cones;
  cones.push_back(Vertex_index(static_cast<typename Vertex_index::size_type>(first)));
  while(cones.size() < count) {
    d = edge_graph_distances(sm, cones);
    const std::size_t next = farthest(d);
    if(next == std::size_t(-1)) break;
    cones.push_back(Vertex_index(static_cast<typename Vertex_index::size_type>(next)));
  }
  order_cones_for_seam(sm, cones);   // when no order gives a simple seam, keep the sampling order
  return cones;
}

/// reads the cones of a CGAL selection file (`*.selection.txt`, as written by the CGAL Polyhedron
/// demo and used by CGAL's `orbifold.cpp`): the first line holds the 0-based indices of the selected
/// vertices (in the order of `vertices(sm)`); further lines (faces, edges) are ignored.
/// Checks that there are 3 or 4 distinct, valid indices.
template <class Point_3>
Status read_cone_selection_file(const std::string& filename, const Surface_mesh<Point_3>& sm,
                                std::vector<typename Surface_mesh<Point_3>::Vertex_index>& cones,
                                std::string& message)
{
  typedef typename Surface_mesh<Point_3>::Vertex_index Vertex_index;
  std::ifstream in(filename);
  if(!in) { message = "cannot open cone file '" + filename + "'"; return INVALID_INPUT; }
  std::string line;
  std::getline(in, line);
  std::istringstream ls(line);
  std::vector<Vertex_index> by_position(sm.vertices().begin(), sm.vertices().end());
  std::vector<Vertex_index> out;
  std::string tok;
  while(ls >> tok) {
    long long i = -1;
    std::size_t used = 0;
    try { i = std::stoll(tok, &used); } catch(...) { used = 0; }
    if(used != tok.size() || i < 0 || i >= static_cast<long long>(by_position.size())) {
      message = filename + ":1: cone '" + tok + "' is not a vertex index in [0, " +
                std::to_string(by_position.size()) + ")";
      return INVALID_INPUT;
    }
    const Vertex_index v = by_position[std::size_t(i)];
    if(std::find(out.begin(), out.end(), v) != out.end()) {
      message = filename + ":1: cone " + tok + " is given twice";
      return INVALID_INPUT;
    }
    out.push_back(v);
  }
  if(out.size() < 3 || out.size() > 4) {
    message = filename + ":1: " + std::to_string(out.size()) + " cones; orbifold Tutte embeddings need 3 or 4";
    return INVALID_INPUT;
  }
  cones.swap(out);
  message = "read " + std::to_string(cones.size()) + " cones from " + filename;
  return SUCCESS;
}

// Concatenates the edge paths between consecutive cones into `seam` and checks that it is one
// simple path from cones.front() to cones.back() through the other cones (CGAL's orbifold
// parameterizer requires this: paths must not cross, touch or share edges).
template <class Point_3>
bool seam_is_simple_path(const Surface_mesh<Point_3>& sm,
                         const std::vector<typename Surface_mesh<Point_3>::Vertex_index>& cones,
                         const std::vector<std::vector<typename Surface_mesh<Point_3>::Edge_index> >& paths,
                         std::vector<typename Surface_mesh<Point_3>::Edge_index>& seam, std::string& message)
{
  typedef typename Surface_mesh<Point_3>::Edge_index SM_edge;
  seam.clear();
  for(const auto& p : paths) seam.insert(seam.end(), p.begin(), p.end());
  std::vector<SM_edge> sorted(seam);
  std::sort(sorted.begin(), sorted.end());
  if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
    message = "the shortest paths between consecutive cones share an edge; reorder or choose other cones";
    return false;
  }
  std::unordered_map<std::size_t, int> degree;
  for(SM_edge e : seam) { ++degree[sm.source(sm.halfedge(e)).idx()]; ++degree[sm.target(sm.halfedge(e)).idx()]; }
  for(const auto& d : degree) {
    const bool end_cone = (d.first == cones.front().idx() || d.first == cones.back().idx());
    if(d.second != (end_cone ? 1 : 2)) {
      message = "the shortest paths between consecutive cones cross or touch at vertex " + std::to_string(d.first) +
                "; reorder or choose other cones";
      return false;
    }
  }
  if(degree.size() != seam.size() + 1) {
    message = "the seam between the cones is not a simple path; reorder or choose other cones";
    return false;
  }
  return true;
}

/// reorders `cones` so that the shortest edge paths between consecutive cones form one simple
/// path (what `make_orbifold_tutte_uv()` needs), preferring the shortest total seam. Tries every
/// order (3 for 3 cones, 12 for 4; a path and its reverse are the same seam); deterministic.
/// Returns false (and leaves `cones` as it is) when no order works.
template <class Point_3>
bool order_cones_for_seam(const Surface_mesh<Point_3>& sm, std::vector<typename Surface_mesh<Point_3>::Vertex_index>& cones)
{
  typedef typename Surface_mesh<Point_3>::Vertex_index Vertex_index;
  typedef typename Surface_mesh<Point_3>::Edge_index   SM_edge;
  const std::size_t n = cones.size();
  if(n < 2) return false;
  std::vector<std::vector<std::vector<SM_edge> > > path(n, std::vector<std::vector<SM_edge> >(n));
  std::vector<std::vector<double> > length(n, std::vector<double>(n, 0));
  Scoped_cerr_capture quiet;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j) {
      SMP::compute_shortest_paths_between_two_cones(sm, cones[i], cones[j], std::back_inserter(path[i][j]));
      path[j][i] = path[i][j];
      for(SM_edge e : path[i][j])
        length[i][j] += std::sqrt(CGAL::to_double(CGAL::squared_distance(sm.point(sm.source(sm.halfedge(e))),
                                                                         sm.point(sm.target(sm.halfedge(e))))));
      length[j][i] = length[i][j];
    }
  std::vector<std::size_t> order(n), best;
  for(std::size_t i = 0; i < n; ++i) order[i] = i;
  double best_length = std::numeric_limits<double>::infinity();
  do {
    if(order.front() > order.back()) continue;             // the reverse order gives the same seam
    std::vector<Vertex_index> c(n);
    std::vector<std::vector<SM_edge> > p;
    double total = 0;
    for(std::size_t i = 0; i < n; ++i) c[i] = cones[order[i]];
    for(std::size_t i = 0; i + 1 < n; ++i) { p.push_back(path[order[i]][order[i + 1]]); total += length[order[i]][order[i + 1]]; }
    std::vector<SM_edge> seam;
    std::string why;
    if(total < best_length && seam_is_simple_path(sm, c, p, seam, why)) { best_length = total; best = order; }
  } while(std::next_permutation(order.begin(), order.end()));
  if(best.empty()) return false;
  std::vector<Vertex_index> c(n);
  for(std::size_t i = 0; i < n; ++i) c[i] = cones[best[i]];
  cones.swap(c);
  return true;
}

/// fills `corner_uv` (for every halfedge `h` of `sm`: the UV of (`target(h)`, `face(h)`)) with an
/// Orbifold Tutte embedding of the closed genus-0 triangle mesh `sm`, cut along the shortest
/// edge paths between consecutive cones (CGAL's `compute_shortest_paths_between_cones`).
///
/// `cones` are given in seam order: the first and the last are the ends of the seam. Their number
/// must be 3 (Square, Diamond, Triangle) or 4 (Parallelogram).
/// \return `SUCCESS`, or `INVALID_INPUT` (not a closed connected genus-0 triangle mesh, wrong cones,
///         crossing seam paths, orbifold solve failed); `corner_uv` is only written on success.
/// The mesh must not contain removed elements (garbage); its connectivity is not modified
/// (three temporary property maps are added and removed again).
template <class Point_3, class CornerUVMap>
Status make_orbifold_tutte_uv(Surface_mesh<Point_3>& sm, CornerUVMap corner_uv,
                              const std::vector<typename Surface_mesh<Point_3>::Vertex_index>& cones,
                              SMP::Orbifold_type type, std::string& message,
                              SMP::Weight_type weights = SMP::Mean_value)
{
  typedef Surface_mesh<Point_3>                                  SM;
  typedef typename SM::Vertex_index                              SM_vertex;
  typedef typename SM::Halfedge_index                            SM_halfedge;
  typedef typename SM::Edge_index                                SM_edge;
  typedef typename SM::template Property_map<SM_edge, bool>      Seam_edge_pmap;
  typedef typename SM::template Property_map<SM_vertex, bool>    Seam_vertex_pmap;
  typedef CGAL::Seam_mesh<SM, Seam_edge_pmap, Seam_vertex_pmap>  Seam_mesh;
  typedef boost::graph_traits<Seam_mesh>                         SGT;
  typedef typename SGT::vertex_descriptor                        seam_vertex;
  typedef typename SGT::halfedge_descriptor                      seam_halfedge;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::Point_2 Orbifold_point_2;
  typedef typename boost::property_traits<CornerUVMap>::value_type UV;

  // --- preconditions, as statuses
  if(sm.has_garbage()) { message = "the mesh has removed elements; call collect_garbage() first"; return INVALID_INPUT; }
  if(sm.number_of_faces() == 0) { message = "empty mesh"; return INVALID_INPUT; }
  if(!CGAL::is_triangle_mesh(sm)) { message = "the mesh is not a triangle mesh"; return INVALID_INPUT; }
  if(!CGAL::is_closed(sm)) { message = "the mesh has a border; orbifold Tutte embeddings need a closed surface"; return INVALID_INPUT; }
  {
    const long long chi = static_cast<long long>(sm.number_of_vertices()) - static_cast<long long>(sm.number_of_edges()) +
                          static_cast<long long>(sm.number_of_faces());
    // connected?
    std::vector<char> seen(sm.num_vertices(), 0);
    std::vector<SM_vertex> stack(1, *sm.vertices().begin());
    seen[stack.back().idx()] = 1;
    std::size_t reached = 1;
    while(!stack.empty()) {
      SM_vertex v = stack.back(); stack.pop_back();
      if(sm.is_isolated(v)) continue;
      for(SM_halfedge h : CGAL::halfedges_around_source(v, sm))
        if(!seen[sm.target(h).idx()]) { seen[sm.target(h).idx()] = 1; ++reached; stack.push_back(sm.target(h)); }
    }
    if(reached != sm.number_of_vertices()) {
      message = "the mesh is not connected (or has isolated vertices)"; return INVALID_INPUT;
    }
    if(chi != 2) {
      message = "the mesh is not a topological sphere (Euler characteristic " + std::to_string(chi) + ", genus " +
                std::to_string((2 - chi) / 2) + ")";
      return INVALID_INPUT;
    }
  }
  if(cones.size() != orbifold_cone_count(type)) {
    message = std::string("orbifold type ") + orbifold_type_name(type) + " needs " +
              std::to_string(orbifold_cone_count(type)) + " cones, got " + std::to_string(cones.size());
    return INVALID_INPUT;
  }
  for(std::size_t i = 0; i < cones.size(); ++i) {
    if(!sm.is_valid(cones[i]) || sm.is_removed(cones[i])) { message = "cone " + std::to_string(i) + " is not a vertex of the mesh"; return INVALID_INPUT; }
    for(std::size_t j = 0; j < i; ++j)
      if(cones[i] == cones[j]) { message = "cone vertex " + std::to_string(cones[i].idx()) + " is given twice"; return INVALID_INPUT; }
  }

  Scoped_cerr_capture cerr_capture;   // from here on, CGAL's prints go into the message

  // --- seam: shortest edge paths between consecutive cones; must be one simple path
  std::vector<SM_edge> seam_edges;
  {
    std::vector<std::vector<SM_edge> > paths;
    for(std::size_t i = 0; i + 1 < cones.size(); ++i) {
      paths.emplace_back();
      SMP::compute_shortest_paths_between_two_cones(sm, cones[i], cones[i + 1], std::back_inserter(paths.back()));
    }
    if(!seam_is_simple_path(sm, cones, paths, seam_edges, message)) return INVALID_INPUT;
  }

  // --- temporary properties (removed on every path out of this block)
  struct Scratch {
    SM& m; Seam_edge_pmap se; Seam_vertex_pmap sv;
    typename SM::template Property_map<SM_halfedge, Orbifold_point_2> uv;
    explicit Scratch(SM& mesh) : m(mesh) {
      se = m.template add_property_map<SM_edge, bool>("e:ss_orbifold_seam", false).first;
      sv = m.template add_property_map<SM_vertex, bool>("v:ss_orbifold_seam", false).first;
      uv = m.template add_property_map<SM_halfedge, Orbifold_point_2>("h:ss_orbifold_uv", Orbifold_point_2(0, 0)).first;
    }
    ~Scratch() { m.remove_property_map(se); m.remove_property_map(sv); m.remove_property_map(uv); }
  } scratch(sm);

  Seam_mesh mesh(sm, scratch.se, scratch.sv);
  for(SM_edge e : seam_edges) mesh.add_seam(sm.source(sm.halfedge(e)), sm.target(sm.halfedge(e)));

  std::unordered_map<seam_vertex, int> index;
  int counter = 0;
  for(seam_vertex v : vertices(mesh)) index[v] = counter++;
  boost::associative_property_map<std::unordered_map<seam_vertex, int> > vimap(index);


  std::unordered_map<seam_vertex, SMP::Cone_type> cmap;
  if(!SMP::locate_cones(mesh, cones.begin(), cones.end(), cmap)) {
    message = "CGAL could not place the cones on the seam mesh" + cerr_capture.str(); return INVALID_INPUT;
  }
  seam_halfedge bhd;
  for(seam_halfedge h : halfedges(mesh)) if(is_border(h, mesh)) { bhd = h; break; }

  SMP::Orbifold_Tutte_parameterizer_3<Seam_mesh> parameterizer(type, weights);
  const SMP::Error_code err = parameterizer.parameterize(mesh, bhd, cmap, scratch.uv, vimap);
  if(err != SMP::OK) {
    message = std::string("Orbifold_Tutte_parameterizer_3 failed: ") + smp_error_name(err) + cerr_capture.str();
    return INVALID_INPUT;
  }

  // --- seam-mesh vertex UVs -> corner map (the public conversion of Seam_mesh_uv.h, in place:
  // the orbifold solve stored each seam-mesh vertex's UV on its canonical halfedge only)
  Seamless_snapping::seam_mesh_uv_to_corner_uv(mesh, scratch.uv, scratch.uv);
  std::vector<std::pair<SM_halfedge, UV> > staged;
  staged.reserve(sm.number_of_halfedges());
  for(SM_halfedge h : sm.halfedges()) {
    if(sm.is_border(h)) continue;
    const Orbifold_point_2 p = get(scratch.uv, h);
    const double u = CGAL::to_double(p.x()), v = CGAL::to_double(p.y());
    if(!std::isfinite(u) || !std::isfinite(v)) {
      message = "the orbifold solve produced a non-finite UV"; return INVALID_INPUT;
    }
    staged.emplace_back(h, UV(u, v));
  }
  for(const auto& s : staged) put(corner_uv, s.first, s.second);
  message = std::string("orbifold Tutte ") + orbifold_type_name(type) + " (" +
            (weights == SMP::Mean_value ? "mean value" : "cotangent") + " weights): " +
            std::to_string(seam_edges.size()) + " seam edges, " + std::to_string(num_vertices(mesh)) + " seam-mesh vertices";
  return SUCCESS;
}

/// Per cut edge: the closest quarter turn and how far the transition is from it (double arithmetic).
template <class TriangleMesh>
struct Seam_transition_fit
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  std::vector<halfedge_descriptor> cut_halfedges;   ///< one halfedge `h` per cut edge (both sides non-border)
  std::vector<int> k;                               ///< quarter turns (ccw) from face(h)'s frame to face(opposite(h))'s
  std::array<std::size_t, 4> k_histogram = {{0, 0, 0, 0}};
  double uv_diagonal = 0;                           ///< of the bounding box of all corner UVs
  double max_relative_residual = 0;                 ///< max |R^k d - d'| / uv_diagonal
  double max_angle_deviation_deg = 0;               ///< max angle between R^k d and d' (non-degenerate edges)
};

/// finds the cut edges of the corner map `uv` (interior edges whose two faces disagree on an endpoint
/// UV, bit for bit) and fits the rotation of each transition: edge vector d = uv[h] - uv[prev(h)] in
/// face(h), d' = uv[prev(o)] - uv[o] in face(o), o = opposite(h); k maximises <R^k d, d'>.
template <class TriangleMesh, class CornerUVMap>
Seam_transition_fit<TriangleMesh> fit_seam_transitions(const TriangleMesh& tm, CornerUVMap uv)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor     edge_descriptor;
  Seam_transition_fit<TriangleMesh> fit;
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for(halfedge_descriptor h : halfedges(tm)) {
    if(is_border(h, tm)) continue;
    const double p[2] = {CGAL::to_double(get(uv, h).x()), CGAL::to_double(get(uv, h).y())};
    for(int c = 0; c < 2; ++c) { lo[c] = (std::min)(lo[c], p[c]); hi[c] = (std::max)(hi[c], p[c]); }
  }
  fit.uv_diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]));
  for(edge_descriptor e : edges(tm)) {
    const halfedge_descriptor h = halfedge(e, tm), o = opposite(h, tm);
    if(is_border(h, tm) || is_border(o, tm)) continue;
    if(get(uv, h) == get(uv, prev(o, tm)) && get(uv, prev(h, tm)) == get(uv, o)) continue;
    const double d[2]  = {CGAL::to_double(get(uv, h).x()) - CGAL::to_double(get(uv, prev(h, tm)).x()),
                          CGAL::to_double(get(uv, h).y()) - CGAL::to_double(get(uv, prev(h, tm)).y())};
    const double d2[2] = {CGAL::to_double(get(uv, prev(o, tm)).x()) - CGAL::to_double(get(uv, o).x()),
                          CGAL::to_double(get(uv, prev(o, tm)).y()) - CGAL::to_double(get(uv, o).y())};
    int best = 0; double best_dot = -std::numeric_limits<double>::infinity();
    double r[2] = {d[0], d[1]};
    double best_r[2] = {d[0], d[1]};
    for(int k = 0; k < 4; ++k) {
      const double dot = r[0] * d2[0] + r[1] * d2[1];
      if(dot > best_dot) { best_dot = dot; best = k; best_r[0] = r[0]; best_r[1] = r[1]; }
      const double t = r[0]; r[0] = -r[1]; r[1] = t;            // rotate by +90 degrees
    }
    fit.cut_halfedges.push_back(h);
    fit.k.push_back(best);
    ++fit.k_histogram[std::size_t(best)];
    const double res = std::hypot(best_r[0] - d2[0], best_r[1] - d2[1]);
    if(fit.uv_diagonal > 0) fit.max_relative_residual = (std::max)(fit.max_relative_residual, res / fit.uv_diagonal);
    const double n1 = std::hypot(d[0], d[1]), n2 = std::hypot(d2[0], d2[1]);
    if(n1 > 1e-9 * fit.uv_diagonal && n2 > 1e-9 * fit.uv_diagonal) {
      const double cross = best_r[0] * d2[1] - best_r[1] * d2[0];
      const double ang = std::abs(std::atan2(cross, best_r[0] * d2[0] + best_r[1] * d2[1])) * 180.0 / CGAL_PI;
      fit.max_angle_deviation_deg = (std::max)(fit.max_angle_deviation_deg, ang);
    }
  }
  return fit;
}

/// max over the cut edges of `fit` of |R^k d - d'| (each component, evaluated exactly in CGAL::Gmpq from
/// the doubles of `uv`), divided by `fit.uv_diagonal` and rounded to double. Exactly 0 iff every
/// transition of `fit` holds exactly with its rotation k.
template <class TriangleMesh, class CornerUVMap>
double exact_max_seam_violation(const TriangleMesh& tm, CornerUVMap uv, const Seam_transition_fit<TriangleMesh>& fit)
{
  CGAL::Gmpq worst(0);
  for(std::size_t i = 0; i < fit.cut_halfedges.size(); ++i) {
    const auto h = fit.cut_halfedges[i];
    const auto o = opposite(h, tm);
    auto q = [&](double x) { return CGAL::Gmpq(x); };
    CGAL::Gmpq d[2]  = {q(CGAL::to_double(get(uv, h).x())) - q(CGAL::to_double(get(uv, prev(h, tm)).x())),
                        q(CGAL::to_double(get(uv, h).y())) - q(CGAL::to_double(get(uv, prev(h, tm)).y()))};
    const CGAL::Gmpq d2[2] = {q(CGAL::to_double(get(uv, prev(o, tm)).x())) - q(CGAL::to_double(get(uv, o).x())),
                              q(CGAL::to_double(get(uv, prev(o, tm)).y())) - q(CGAL::to_double(get(uv, o).y()))};
    for(int k = 0; k < fit.k[i]; ++k) { CGAL::Gmpq t = d[0]; d[0] = -d[1]; d[1] = t; }
    for(int c = 0; c < 2; ++c) {
      CGAL::Gmpq diff = d[c] - d2[c];
      if(diff < 0) diff = -diff;
      if(diff > worst) worst = diff;
    }
  }
  if(fit.uv_diagonal <= 0) return CGAL::to_double(worst);
  return CGAL::to_double(worst / CGAL::Gmpq(fit.uv_diagonal));
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_INPUTS_ORBIFOLD_TUTTE_INPUT_H
