// Helpers shared by test_constraints.cpp and benchmark/bench_snap.cpp (--connections): cones, shortest
// edge paths, random connection constraints between cones, and an independent exact check of a
// connection or cycle constraint on a corner UV map of a CGAL::Surface_mesh.
//
// The check unfolds the UVs along the path's face strip (the convention of Connection_constraint:
// left side, right side only around a border) in rational arithmetic (CGAL::Gmpq): crossing from
// face A into face B across an edge (w, z), the rotation k is the one with
// R^k (z_A - w_A) = z_B - w_B exactly, and the unfolding keeps w fixed. The end vertex, unfolded into
// the frame of the first face, must have the same `component` coordinate as the start vertex.

#ifndef SEAMLESS_SNAPPING_TEST_CONNECTION_TEST_UTILS_H
#define SEAMLESS_SNAPPING_TEST_CONNECTION_TEST_UTILS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <CGAL/Seamless_snapping/Connection_constraint.h>
#include <CGAL/Seamless_snapping/internal/surface/rotation_fit.h>

#include <CGAL/Gmpq.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <deque>
#include <random>
#include <vector>

namespace connection_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel    K;
typedef K::Point_2                                             Point_2;
typedef CGAL::Surface_mesh<K::Point_3>                         Mesh;
typedef Mesh::Vertex_index                                     vertex_descriptor;
typedef Mesh::Halfedge_index                                   halfedge_descriptor;
typedef Mesh::Property_map<halfedge_descriptor, Point_2>       UV_map;   // uv[h] = UV of target(h) in face(h)
typedef CGAL::Seamless_snapping::Connection_constraint<halfedge_descriptor> Constraint;
namespace SS = CGAL::Seamless_snapping;

// interior vertices whose UV angle sum, rounded to quarter turns, is not 360 degrees
inline std::vector<vertex_descriptor> find_cones(const Mesh& m, UV_map uv)
{
  std::vector<double> sum(m.number_of_vertices(), 0.);
  for(halfedge_descriptor h : m.halfedges()) {
    if(m.is_border(h)) continue;
    const Point_2 p = get(uv, h), a = get(uv, m.next(h)), b = get(uv, m.prev(h));
    const double ax = a.x() - p.x(), ay = a.y() - p.y(), bx = b.x() - p.x(), by = b.y() - p.y();
    sum[m.target(h).idx()] += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  }
  std::vector<vertex_descriptor> cones;
  for(vertex_descriptor v : m.vertices())
    if(!m.is_border(v) && std::lround(sum[v.idx()] / (std::acos(-1.) / 2)) != 4) cones.push_back(v);
  return cones;
}

// a shortest edge path from a to b (breadth-first search; deterministic)
inline std::vector<halfedge_descriptor> shortest_path(const Mesh& m, vertex_descriptor a, vertex_descriptor b)
{
  std::vector<halfedge_descriptor> parent(m.number_of_vertices(), Mesh::null_halfedge());
  std::vector<char> seen(m.number_of_vertices(), 0);
  std::deque<vertex_descriptor> queue(1, a);
  seen[a.idx()] = 1;
  while(!queue.empty() && !seen[b.idx()]) {
    const vertex_descriptor v = queue.front();
    queue.pop_front();
    for(halfedge_descriptor h : CGAL::halfedges_around_source(v, m)) {
      const vertex_descriptor w = m.target(h);
      if(seen[w.idx()]) continue;
      seen[w.idx()] = 1;
      parent[w.idx()] = h;
      queue.push_back(w);
    }
  }
  std::vector<halfedge_descriptor> path;
  if(!seen[b.idx()]) return path;
  for(vertex_descriptor v = b; v != a; v = m.source(parent[v.idx()])) path.push_back(parent[v.idx()]);
  std::reverse(path.begin(), path.end());
  return path;
}

// `count` connection constraints between random pairs of distinct cones, deterministic in `seed`
inline std::vector<Constraint> random_cone_connections(const Mesh& m, const std::vector<vertex_descriptor>& cones,
                                                       std::size_t count, unsigned seed)
{
  std::vector<Constraint> out;
  if(cones.size() < 2) return out;
  std::mt19937 rng(seed);
  while(out.size() < count) {
    const vertex_descriptor a = cones[rng() % cones.size()], b = cones[rng() % cones.size()];
    const int component = int(rng() % 2);
    if(a == b) continue;
    out.emplace_back(shortest_path(m, a, b), component);
    assert(!out.back().path.empty());
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// independent exact check (Gmpq)
// ---------------------------------------------------------------------------------------------
struct Q2 { CGAL::Gmpq x, y; };
inline Q2 q2(const Point_2& p) { return Q2{CGAL::Gmpq(p.x()), CGAL::Gmpq(p.y())}; }
inline Q2 rot(int k, const Q2& p)
{
  switch(((k % 4) + 4) % 4) {
    case 0: return p;
    case 1: return Q2{-p.y, p.x};
    case 2: return Q2{-p.x, -p.y};
    default: return Q2{p.y, -p.x};
  }
}
inline Q2 sub(const Q2& a, const Q2& b) { return Q2{a.x - b.x, a.y - b.y}; }
inline Q2 add(const Q2& a, const Q2& b) { return Q2{a.x + b.x, a.y + b.y}; }
inline bool eq(const Q2& a, const Q2& b) { return a.x == b.x && a.y == b.y; }

struct Check_result { bool holds = true; std::size_t ambiguous = 0; Q2 start, end; };

// best-fitting quarter turn: argmax_k dot(R^k a, b)
inline int fit_k(const Point_2& wa, const Point_2& za, const Point_2& wb, const Point_2& zb)
{
  const double ax = za.x() - wa.x(), ay = za.y() - wa.y(), bx = zb.x() - wb.x(), by = zb.y() - wb.y();
  double best = -1e300;
  int k = 0;
  for(int kk = 0; kk < 4; ++kk) {
    double rx, ry;
    SS::internal::rotate_quarter_turns(kk, ax, ay, rx, ry);
    if(rx * bx + ry * by > best) { best = rx * bx + ry * by; k = kk; }
  }
  return k;
}

// Unfolding G(p) = R^q p + t maps the frame of the current face to the frame of the first face.
// Crossing from corner g (face A) to corner g2 (face B) around w = target(g) = target(g2) over the
// edge (w, z): the k with R^k (z_A - w_A) = z_B - w_B exactly (`exact_k`); if both vectors are zero,
// or if !exact_k, the best-fitting k of `uv_fit` (zero vectors are counted as ambiguous).
inline void cross(const Mesh& m, UV_map uv, UV_map uv_fit, bool exact_k, halfedge_descriptor g, halfedge_descriptor g2,
                  halfedge_descriptor edge_in_a, int& q, Q2& t, Check_result& cr)
{
  const vertex_descriptor w = m.target(g);
  auto uv_at = [&](UV_map map, halfedge_descriptor corner_face_h, vertex_descriptor v) {
    for(halfedge_descriptor c : CGAL::halfedges_around_face(corner_face_h, m))
      if(m.target(c) == v) return get(map, c);
    assert(false);
    return Point_2();
  };
  const vertex_descriptor z = m.target(edge_in_a) == w ? m.source(edge_in_a) : m.target(edge_in_a);
  const Q2 wa = q2(get(uv, g)), wb = q2(get(uv, g2));
  const Q2 da = sub(q2(uv_at(uv, g, z)), wa), db = sub(q2(uv_at(uv, g2, z)), wb);
  int k = -1;
  const bool zero = da.x == 0 && da.y == 0 && db.x == 0 && db.y == 0;
  if(exact_k && !zero) {
    for(int kk = 0; kk < 4 && k < 0; ++kk) if(eq(rot(kk, da), db)) k = kk;
    if(k < 0) { cr.holds = false; return; }    // not a rigid transition: not seamless
  } else {
    if(zero) ++cr.ambiguous;
    k = fit_k(get(uv_fit, g), uv_at(uv_fit, g, z), get(uv_fit, g2), uv_at(uv_fit, g2, z));
  }
  // G_B(p) = R^(q-k) p + t_B with G_B(w_B) = G_A(w_A)
  const Q2 ga = add(rot(q, wa), t);
  q -= k;
  t = sub(ga, rot(q, wb));
}

// start = UV of a in the first face; end = UV of b in the last face, unfolded into the first frame
inline Check_result unfold_path(const Mesh& m, UV_map uv, UV_map uv_fit, bool exact_k, const Constraint& c)
{
  Check_result cr;
  int q = 0;
  Q2 t{CGAL::Gmpq(0), CGAL::Gmpq(0)};
  cr.start = cr.end = t;
  halfedge_descriptor d_prev;
  for(std::size_t i = 0; i < c.path.size(); ++i) {
    const halfedge_descriptor h = c.path[i];
    const halfedge_descriptor ci = m.is_border(h) ? m.opposite(h) : m.prev(h);
    const halfedge_descriptor di = m.is_border(h) ? m.prev(m.opposite(h)) : h;
    if(i == 0) {
      cr.start = q2(get(uv, ci));
    } else {
      // around target(d_prev): clockwise (left side) unless that meets the border
      bool ok = true;
      for(halfedge_descriptor g = d_prev; g != ci;) {
        const halfedge_descriptor g2 = m.opposite(m.next(g));
        if(m.is_border(g2)) { ok = false; break; }
        g = g2;
      }
      int steps = 0;
      for(halfedge_descriptor g = d_prev; g != ci; ++steps) {
        assert(steps < 1000);
        const halfedge_descriptor g2 = ok ? m.opposite(m.next(g)) : m.prev(m.opposite(g));
        assert(!m.is_border(g2));
        cross(m, uv, uv_fit, exact_k, g, g2, ok ? m.next(g) : g, q, t, cr);
        if(!cr.holds) return cr;
        g = g2;
      }
    }
    cr.end = add(rot(q, q2(get(uv, di))), t);
    d_prev = di;
  }
  return cr;
}

inline Check_result exact_connection_holds(const Mesh& m, UV_map uv, UV_map uv_in, const Constraint& c)
{
  Check_result cr = unfold_path(m, uv, uv_in, true, c);
  if(cr.holds) cr.holds = c.component == 0 ? cr.start.x == cr.end.x : cr.start.y == cr.end.y;
  return cr;
}

// |end - start| per component on an approximate map (rotations fitted)
inline void input_violation(const Mesh& m, UV_map uv, const Constraint& c, double v[2])
{
  const Check_result cr = unfold_path(m, uv, uv, false, c);
  v[0] = std::fabs(CGAL::to_double(cr.end.x - cr.start.x));
  v[1] = std::fabs(CGAL::to_double(cr.end.y - cr.start.y));
}

} // namespace connection_test

#endif // SEAMLESS_SNAPPING_TEST_CONNECTION_TEST_UTILS_H
