// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_MESH_HALFEDGE_ARRAYS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_MESH_HALFEDGE_ARRAYS_H

// The halfedge structure that a sequence of CGAL::Euler::add_face() calls builds from a polygon soup,
// built on plain index arrays, then replayed onto a mesh in one pass (copy_to()): the OBJ reader's
// triangles (IO/OBJ.h) and the quad extraction's cells (internal/quad/quad_extraction.h).
//
// add_face() is CGAL::Euler::add_face() (CGAL 5.5, boost/graph/Euler_operations.h) step for step:
// the same tests in the same order (isolated/border vertices, halfedge(u, v) found by walking around v
// from halfedge(v), the "patch re-linking" of existing border halfedges, the cached set_next() calls,
// adjust_incoming_halfedge()), on arrays instead of a generic FaceGraph; a walk is skipped only where what is
// kept per vertex proves that it would find nothing (no border halfedge, no edge to that neighbour). So it accepts
// and refuses the same faces, and the replayed mesh has the same halfedges, edges, faces and vertex/face halfedges, in
// the same order, as a mesh built face by face with Euler::add_face() (and the corner UVs, sectors and
// results of the snap do not change). Why: Euler::add_face() on a Surface_mesh costs about 1800
// instructions per triangle (generic descriptors, three std::vector per call), and the reader used to
// run it twice (on a scratch mesh to validate, then on the caller's mesh); on the arrays it is a few
// hundred, and the caller's mesh is written once, with add_vertex/add_edge/add_face and the set_*
// functions of MutableFaceGraph. The same for the quad mesh of the extraction (Surface_mesh::add_face()
// is Euler::add_face()).
//
// Numbering (as in Surface_mesh): edge e has the halfedges 2e and 2e + 1 = opposite; halfedge 2e points
// from the first to the second vertex of the face side that created the edge. -1 = null.

#include <CGAL/Surface_mesh/Surface_mesh.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

class Halfedge_arrays
{
  // one record per halfedge (the walks around vertices read next, target and face of the same halfedge:
  // one cache line instead of three arrays)
  struct Record { int next, prev, target, face; };
  std::vector<Record> h_;
  // per vertex: its border halfedges, i.e. its edges minus its faces (a face holds one halfedge into each of its
  // vertices). The walks that look for a border halfedge around v stop at once where there is none: around a
  // vertex inside the mesh built so far (on a closed mesh, every vertex once its fan is complete), a whole turn
  std::vector<int> border_in_;
  // per vertex: bit (u mod 64) set for every neighbour u. A clear bit proves that the edge does not exist, so that
  // halfedge(u, v) of a new edge (half of those add_face() asks for on a closed mesh) skips its walk around v, a whole
  // turn through halfedges created at different times, i.e. far apart in memory
  std::vector<std::uint64_t> neighbour_bits_;
  static std::uint64_t bit_of(int u) { return std::uint64_t(1) << (unsigned(u) & 63u); }

public:
  std::vector<int> vertex_halfedge;             // per vertex: halfedge(v), an incoming halfedge, -1 = isolated
  std::vector<int> face_halfedge;               // per face: halfedge(f)

  // `n_faces_hint` faces of `face_degree` sides expected
  explicit Halfedge_arrays(std::size_t n_vertices, std::size_t n_faces_hint = 0, std::size_t face_degree = 3)
    : border_in_(n_vertices, 0), neighbour_bits_(n_vertices, 0), vertex_halfedge(n_vertices, -1)
  {
    face_halfedge.reserve(n_faces_hint);
    // a closed mesh has face_degree halfedges per face; a border adds a few
    h_.reserve(face_degree * n_faces_hint + n_faces_hint / 8 + 16);
  }

  std::size_t number_of_halfedges() const { return h_.size(); }
  std::size_t number_of_faces() const { return face_halfedge.size(); }
  int next(int h) const { return h_[std::size_t(h)].next; }
  int prev(int h) const { return h_[std::size_t(h)].prev; }
  int target(int h) const { return h_[std::size_t(h)].target; }
  int face(int h) const { return h_[std::size_t(h)].face; }           // -1 = border
  static int opposite(int h) { return h ^ 1; }
  bool is_border(int h) const { return face(h) < 0; }
  int source(int h) const { return target(opposite(h)); }
  // the next halfedge around target(h): opposite(next(h)) (Halfedge_around_target_iterator)
  int next_around_target(int h) const { return opposite(next(h)); }

  // halfedge(u, v, g) of Surface_mesh: the halfedge u -> v, found by walking around v from halfedge(v); -1 if none
  int halfedge(int u, int v) const
  {
    const int hh = vertex_halfedge[std::size_t(v)];
    if(hh < 0 || (neighbour_bits_[std::size_t(v)] & bit_of(u)) == 0) return -1;
    int h = hh;
    do {
      if(source(h) == u) return h;
      h = next_around_target(h);
    } while(h != hh);
    return -1;
  }

  // is_border(v, g): the first border halfedge around v from halfedge(v), -1 if none (or v isolated)
  int border_halfedge_of(int v) const
  {
    const int hh = vertex_halfedge[std::size_t(v)];
    if(hh < 0 || border_in_[std::size_t(v)] == 0) return -1;
    int h = hh;
    do {
      if(is_border(h)) return h;
      h = next_around_target(h);
    } while(h != hh);
    return -1;
  }

  // The vertex test of a polygon mesh, after the faces are added: every halfedge into v lies on the one cycle
  // around v, at most one of them border; else two fans of faces meet at v (two closed fans, whose cycles miss
  // each other's halfedges, or two open ones, a "bowtie"), which add_face() accepts. The first vertex (in index
  // order) that fails, -1 if none. The turns around `turns` vertices at a time advance together, one step each
  // in turn: each step waits for a record that may lie anywhere in memory, and independent waits overlap (the
  // 302K-face bunny: 8 ms less than one turn after the other, of 22).
  int first_vertex_with_several_fans() const
  {
    const int nv = int(vertex_halfedge.size());
    std::vector<int> in_degree(std::size_t(nv), 0);
    for(const Record& r : h_) ++in_degree[std::size_t(r.target)];
    constexpr int turns = 8;
    for(int v0 = 0; v0 < nv; v0 += turns) {
      const int k = (std::min)(turns, nv - v0);
      int h[turns], around[turns], border[turns], walking = 0;
      for(int i = 0; i < k; ++i) {
        h[i] = vertex_halfedge[std::size_t(v0 + i)];
        around[i] = border[i] = 0;
        walking += h[i] >= 0 ? 1 : 0;
      }
      while(walking > 0)
        for(int i = 0; i < k; ++i) {
          if(h[i] < 0) continue;                            // isolated, or its turn is complete
          ++around[i];
          border[i] += is_border(h[i]) ? 1 : 0;
          h[i] = next_around_target(h[i]);
          if(h[i] == vertex_halfedge[std::size_t(v0 + i)]) { h[i] = -1; --walking; }
        }
      for(int i = 0; i < k; ++i)
        if(vertex_halfedge[std::size_t(v0 + i)] >= 0 && (around[i] != in_degree[std::size_t(v0 + i)] || border[i] > 1))
          return v0 + i;
    }
    return -1;
  }

  // a hint for an add_face() soon to come with vertex v: its first walk reads the record of halfedge(v)
  void prefetch_vertex(int v) const
  {
    const int hh = vertex_halfedge[std::size_t(v)];
    if(hh >= 0) __builtin_prefetch(&h_[std::size_t(hh)]);
  }

  // CGAL::Euler::add_face(vertices, g) for a face of N >= 3 vertices: false (and nothing changed) where
  // add_face() returns null_face()
  template <std::size_t N>
  bool add_face(const std::array<int, N>& vertices)
  {
    static_assert(N >= 3, "a face has at least three vertices");
    const int n = int(N);
    const int* v = vertices.data();
    for(int i = 0; i < n; ++i)                                       // "check that every vertex is unique"
      for(int j = i + 1; j < n; ++j)
        if(v[i] == v[j]) return false;
    int he[N];
    bool is_new[N];
    for(int i = 0, ii = 1; i < n; ++i, ++ii, ii %= n) {
      if(vertex_halfedge[std::size_t(v[i])] >= 0 && border_halfedge_of(v[i]) < 0) return false;
      he[i] = halfedge(v[i], v[ii]);
      is_new[i] = he[i] < 0;
      if(!is_new[i] && !is_border(he[i])) return false;
    }

    // the cache of set_next() calls (applied at the end, in order)
    std::array<std::pair<int, int>, 6 * N> cache;        // at most 3 re-links and 3 links per side
    int cached = 0;
    auto set_next_later = [&](int h, int nh) { cache[std::size_t(cached++)] = std::make_pair(h, nh); };

    // re-link patches if necessary
    for(int i = 0, ii = 1; i < n; ++i, ++ii, ii %= n) {
      if(is_new[i] || is_new[ii]) continue;
      const int inner_prev = he[i], inner_next = he[ii];
      if(next(inner_prev) == inner_next) continue;
      // search a free gap between border_prev and border_next
      const int outer_prev = opposite(inner_next);
      int border_prev = outer_prev;
      do {
        border_prev = opposite(next(border_prev));
      } while(!is_border(border_prev) || border_prev == inner_prev);
      const int border_next = next(border_prev);
      if(border_next == inner_next) return false;
      const int patch_start = next(inner_prev), patch_end = prev(inner_next);
      set_next_later(border_prev, patch_start);
      set_next_later(patch_end, border_next);
      set_next_later(inner_prev, inner_next);
    }

    // create missing edges (u -> v is the even halfedge of the new edge)
    for(int i = 0, ii = 1; i < n; ++i, ++ii, ii %= n) {
      if(!is_new[i]) continue;
      he[i] = int(h_.size());
      h_.push_back(Record{-1, -1, v[ii], -1});
      h_.push_back(Record{-1, -1, v[i], -1});
      neighbour_bits_[std::size_t(v[i])] |= bit_of(v[ii]);
      neighbour_bits_[std::size_t(v[ii])] |= bit_of(v[i]);
    }
    // create the face
    const int f = int(face_halfedge.size());
    face_halfedge.push_back(he[n - 1]);

    // setup halfedges
    for(int i = 0, ii = 1; i < n; ++i, ++ii, ii %= n) {
      const int w = v[ii];
      const int inner_prev = he[i], inner_next = he[ii];
      const int id = (is_new[i] ? 1 : 0) | (is_new[ii] ? 2 : 0);
      if(id != 0) {
        const int outer_prev = opposite(inner_next), outer_next = opposite(inner_prev);
        switch(id) {
          case 1: {   // prev is new, next is old
            const int border_prev = prev(inner_next);
            set_next_later(border_prev, outer_next);
            vertex_halfedge[std::size_t(w)] = border_prev;
            break;
          }
          case 2: {   // next is new, prev is old
            const int border_next = next(inner_prev);
            set_next_later(outer_prev, border_next);
            vertex_halfedge[std::size_t(w)] = outer_prev;
            break;
          }
          default: {  // both are new: try to pick a border halfedge with w as target
            int hv = vertex_halfedge[std::size_t(w)];
            if(hv >= 0 && !is_border(hv)) {
              const int border = border_halfedge_of(w);   // walks from halfedge(w) = hv
              hv = border >= 0 ? border : -1;
            }
            if(hv < 0) {
              vertex_halfedge[std::size_t(w)] = outer_prev;
              set_next_later(outer_prev, outer_next);
            } else {
              const int border_prev = hv, border_next = next(border_prev);
              set_next_later(border_prev, outer_next);
              set_next_later(outer_prev, border_next);
            }
            break;
          }
        }
        set_next_later(inner_prev, inner_next);   // inner link
      }
      h_[std::size_t(inner_prev)].face = f;
    }

    for(int c = 0; c < cached; ++c) {
      h_[std::size_t(cache[std::size_t(c)].first)].next = cache[std::size_t(c)].second;
      h_[std::size_t(cache[std::size_t(c)].second)].prev = cache[std::size_t(c)].first;
    }
    for(int i = 0, ii = 1; i < n; ++i, ++ii, ii %= n) {
      if(is_new[i]) { ++border_in_[std::size_t(v[i])]; ++border_in_[std::size_t(v[ii])]; }
      --border_in_[std::size_t(v[i])];
    }
    for(int i = 0; i < n; ++i) adjust_incoming_halfedge(v[i]);
    return true;
  }

private:
  // CGAL::internal::adjust_incoming_halfedge(): halfedge(v) becomes a border halfedge into v if there is one
  void adjust_incoming_halfedge(int v)
  {
    int h = vertex_halfedge[std::size_t(v)];
    if(h < 0) return;
    if(target(h) != v) {
      h = opposite(h);
      vertex_halfedge[std::size_t(v)] = h;
    }
    if(border_in_[std::size_t(v)] == 0) return;   // no border halfedge into v: the walk below would find none
    const int hh = h;
    do {
      if(is_border(h)) { vertex_halfedge[std::size_t(v)] = h; return; }
      h = next_around_target(h);
    } while(h != hh);
  }
};

// The new elements of g that copy_to() fills: nv vertices, nh / 2 edges and nf faces, created with add_vertex(),
// add_edge() and add_face() in this order (each also appends to every property array of g)
template <class FaceGraph>
void add_elements(FaceGraph& g, std::size_t nv, std::size_t nh, std::size_t nf,
                  std::vector<typename boost::graph_traits<FaceGraph>::vertex_descriptor>& vs,
                  std::vector<typename boost::graph_traits<FaceGraph>::halfedge_descriptor>& hs,
                  std::vector<typename boost::graph_traits<FaceGraph>::face_descriptor>& fs)
{
  typedef boost::graph_traits<FaceGraph> GT;
  reserve(g, static_cast<typename GT::vertices_size_type>(vertices(g).size() + nv),
          static_cast<typename GT::edges_size_type>(edges(g).size() + nh / 2),
          static_cast<typename GT::faces_size_type>(faces(g).size() + nf));
  vs.resize(nv);
  for(std::size_t i = 0; i < nv; ++i) vs[i] = add_vertex(g);
  hs.resize(nh);
  for(std::size_t h = 0; h < nh; h += 2) {
    hs[h] = halfedge(add_edge(g), g);
    hs[h + 1] = opposite(hs[h], g);
  }
  fs.resize(nf);
  for(std::size_t f = 0; f < nf; ++f) fs[f] = add_face(g);
}

// The same on a Surface_mesh without removed elements, where add_vertex(), add_edge() and add_face() append at the
// end (no free list to recycle): each property array grows once (Surface_mesh::resize(), as Surface_mesh::join()
// does) instead of by one element per call. The 302K-face bunny of ../shared/large: copy_to() 32 -> 23 ms (3 CLI runs).
template <class Point>
void add_elements(CGAL::Surface_mesh<Point>& g, std::size_t nv, std::size_t nh, std::size_t nf,
                  std::vector<typename CGAL::Surface_mesh<Point>::Vertex_index>& vs,
                  std::vector<typename CGAL::Surface_mesh<Point>::Halfedge_index>& hs,
                  std::vector<typename CGAL::Surface_mesh<Point>::Face_index>& fs)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::size_type size_type;
  if(g.has_garbage()) {
    add_elements<Mesh>(g, nv, nh, nf, vs, hs, fs);
    return;
  }
  const size_type v0 = g.num_vertices(), e0 = g.num_edges(), f0 = g.num_faces();
  g.resize(v0 + size_type(nv), e0 + size_type(nh / 2), f0 + size_type(nf));
  vs.resize(nv);
  for(std::size_t i = 0; i < nv; ++i) vs[i] = typename Mesh::Vertex_index(v0 + size_type(i));
  hs.resize(nh);
  for(std::size_t h = 0; h < nh; ++h) hs[h] = typename Mesh::Halfedge_index(2 * e0 + size_type(h));
  fs.resize(nf);
  for(std::size_t f = 0; f < nf; ++f) fs[f] = typename Mesh::Face_index(f0 + size_type(f));
}

// The structure of `a` onto the MutableFaceGraph g, in one pass: its vertices, then its edges, then its faces, each
// in the order of the arrays (the order in which Euler::add_face() face by face would create them in g), with their
// next, target, face and halfedge. `vs`, `hs`, `fs`: the new elements of g, by index in the arrays.
template <class FaceGraph>
void copy_to(const Halfedge_arrays& a, FaceGraph& g, std::vector<typename boost::graph_traits<FaceGraph>::vertex_descriptor>& vs,
             std::vector<typename boost::graph_traits<FaceGraph>::halfedge_descriptor>& hs,
             std::vector<typename boost::graph_traits<FaceGraph>::face_descriptor>& fs)
{
  typedef boost::graph_traits<FaceGraph> GT;
  const std::size_t nv = a.vertex_halfedge.size(), nh = a.number_of_halfedges(), nf = a.number_of_faces();
  add_elements(g, nv, nh, nf, vs, hs, fs);
  for(std::size_t f = 0; f < nf; ++f) set_halfedge(fs[f], hs[std::size_t(a.face_halfedge[f])], g);
  for(std::size_t h = 0; h < nh; ++h) {
    const int i = int(h);
    set_target(hs[h], vs[std::size_t(a.target(i))], g);
    set_next(hs[h], hs[std::size_t(a.next(i))], g);
    set_face(hs[h], a.is_border(i) ? GT::null_face() : fs[std::size_t(a.face(i))], g);
  }
  for(std::size_t i = 0; i < nv; ++i)
    if(a.vertex_halfedge[i] >= 0) set_halfedge(vs[i], hs[std::size_t(a.vertex_halfedge[i])], g);
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_MESH_HALFEDGE_ARRAYS_H
