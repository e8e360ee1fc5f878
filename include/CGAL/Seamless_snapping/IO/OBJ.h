// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_IO_OBJ_H
#define CGAL_SEAMLESS_SNAPPING_IO_OBJ_H

#include <CGAL/Seamless_snapping/Status.h>
#include <CGAL/Seamless_snapping/internal/parameters.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <istream>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace IO {
namespace internal {

// ---------------------------------------------------------------------------------------------
// Numbers. std::from_chars / std::to_chars are locale independent and, for double, correctly
// rounded (shortest-exact parsing, "%.17g"-like printing), so 17 significant digits round-trip
// every finite double bit for bit. Without them (old standard libraries) we fall back to
// strtod / snprintf, which give the same results under the "C" numeric locale.
// ---------------------------------------------------------------------------------------------

// Parses one double at [p, end); on success advances p. Leading '+' is accepted (OBJ writers
// emit it), "nan"/"inf" parse here and are rejected by the caller with a clearer message.
inline bool parse_double(const char*& p, const char* end, double& x, bool& out_of_range)
{
  out_of_range = false;
  if(p != end && *p == '+') ++p;
#if defined(__cpp_lib_to_chars)
  std::from_chars_result r = std::from_chars(p, end, x);
  if(r.ec == std::errc::result_out_of_range) { out_of_range = true; return false; }
  if(r.ec != std::errc()) return false;
  p = r.ptr;
  return true;
#else
  std::string tok(p, end);            // strtod needs a terminated string
  char* e = nullptr;
  errno = 0;
  x = std::strtod(tok.c_str(), &e);
  if(e == tok.c_str()) return false;
  if(errno == ERANGE && std::isinf(x)) { out_of_range = true; return false; }
  p += (e - tok.c_str());
  return true;
#endif
}

// Parses an optional sign and decimal digits; false on overflow or when there are no digits.
inline bool parse_index(const char*& p, const char* end, long long& i)
{
  if(p != end && *p == '+') ++p;
  std::from_chars_result r = std::from_chars(p, end, i);
  if(r.ec != std::errc()) return false;
  p = r.ptr;
  return true;
}

// Appends x with 17 significant digits (enough for any double to read back bit-identically).
inline void append_double(std::string& out, double x)
{
  char buf[64];
#if defined(__cpp_lib_to_chars)
  std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), x, std::chars_format::general, 17);
  out.append(buf, r.ptr);
#else
  int n = std::snprintf(buf, sizeof(buf), "%.17g", x);
  out.append(buf, buf + n);
#endif
}

inline std::uint64_t double_bits(double x)
{
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

inline void skip_spaces(const char*& p, const char* end) { while(p != end && is_space(*p)) ++p; }

// A token of the file for a message, quoted: at most 60 characters of it, then "..." and its
// length, so that a huge unparsable token does not end up whole in the message.
inline std::string quote_token(const char* begin, const char* end)
{
  const std::size_t n = std::size_t(end - begin), shown = 60;
  if(n <= shown) return "'" + std::string(begin, end) + "'";
  return "'" + std::string(begin, begin + shown) + "...' (" + std::to_string(n) + " characters)";
}

// 0-based element index of the OBJ index `i` (1-based, or negative = relative to the `count`
// elements read so far, -1 = the last one). Checked arithmetic: every long long, also -2^63, is
// either mapped into [0, count) (negative indices) or kept for the range check at the end of the
// file (positive ones: the format allows forward references). False for a negative index that
// refers before the first element.
inline bool resolve_index(long long i, std::size_t count, long long& zero_based)
{
  if(i > 0) { zero_based = i - 1; return true; }
  // i < 0: valid iff -i <= count, i.e. -(i + 1) < count (-i itself overflows for i = -2^63)
  if(static_cast<unsigned long long>(-(i + 1)) >= count) return false;
  zero_based = static_cast<long long>(count) + i;
  return true;
}

// ---------------------------------------------------------------------------------------------
// Reading: OBJ text -> triangle soup with per-corner vt indices (no mesh is touched here).
// ---------------------------------------------------------------------------------------------

struct Obj_soup
{
  std::vector<std::array<double, 3> > points;        // "v", file order
  std::vector<std::array<double, 2> > uvs;           // "vt", file order
  std::vector<std::array<std::size_t, 3> > face_v;   // 0-based "v" index of each corner
  std::vector<std::array<std::size_t, 3> > face_vt;  // 0-based "vt" index of each corner
  std::vector<std::size_t> face_line;                // line number of each "f"
  std::size_t skipped_records = 0;                   // lines with a record type we ignore
};

// Reads the whole stream into `soup`. Returns SUCCESS or INVALID_INPUT with "<where>:<line>: reason".
inline Status parse_obj(std::istream& is, Obj_soup& soup, const std::string& where, std::string& message)
{
  auto fail = [&](std::size_t line, const std::string& why) {
    message = where + ":" + std::to_string(line) + ": " + why;
    return INVALID_INPUT;
  };

  // Largest positive index seen per kind, with its line (range check once the counts are known:
  // the OBJ format allows a face to refer to vertices given further down).
  long long max_v = 0, max_vt = 0;
  std::size_t max_v_line = 0, max_vt_line = 0;

  std::string line;
  std::size_t lineno = 0;
  while(std::getline(is, line))
  {
    ++lineno;
    const char* p = line.data();
    const char* end = p + line.size();
    // a UTF-8 byte-order mark at the start of the file is not part of the first record
    if(lineno == 1 && line.size() >= 3 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) p += 3;
    // A '#' starts a comment anywhere on the line (also covers "#scale_uv" and friends).
    if(const void* hash = std::memchr(p, '#', std::size_t(end - p)))   // from p: after a byte-order mark too
      end = static_cast<const char*>(hash);
    skip_spaces(p, end);
    if(p == end) continue;
    const char* tag_begin = p;
    while(p != end && !is_space(*p)) ++p;
    const std::size_t tag_len = std::size_t(p - tag_begin);

    auto is_tag = [&](const char* t) { return tag_len == std::strlen(t) && std::strncmp(tag_begin, t, tag_len) == 0; };

    // Reads `n` doubles (at least `required` of them); extra numbers (v: w or r g b; vt: w) are ignored.
    auto read_numbers = [&](double* out, int required, const char* what) -> Status {
      for(int k = 0; k < required; ++k) {
        skip_spaces(p, end);
        bool oor = false;
        const char* start = p;
        if(p == end)
          return fail(lineno, std::string("'") + what + "' record needs " + std::to_string(required) + " coordinates, got " + std::to_string(k));
        if(!parse_double(p, end, out[k], oor) || (p != end && !is_space(*p))) {
          const char* tok_end = start; while(tok_end != end && !is_space(*tok_end)) ++tok_end;
          const std::string tok = quote_token(start, tok_end);
          if(oor) return fail(lineno, "coordinate " + tok + " is outside the range of double (Inf)");
          return fail(lineno, "cannot parse coordinate " + tok + " of a '" + what + "' record");
        }
        if(!std::isfinite(out[k]))
          return fail(lineno, std::string("non-finite coordinate (NaN or Inf) in a '") + what + "' record");
      }
      return SUCCESS;
    };

    if(is_tag("v"))
    {
      std::array<double, 3> x;
      if(read_numbers(x.data(), 3, "v") != SUCCESS) return INVALID_INPUT;
      soup.points.push_back(x);
    }
    else if(is_tag("vt"))
    {
      std::array<double, 2> x;
      if(read_numbers(x.data(), 2, "vt") != SUCCESS) return INVALID_INPUT;
      soup.uvs.push_back(x);
    }
    else if(is_tag("f"))
    {
      std::array<long long, 3> vi{}, ti{};
      int n = 0;
      for(;;)
      {
        skip_spaces(p, end);
        if(p == end) break;
        const char* tok = p;
        while(p != end && !is_space(*p)) ++p;
        const char* tok_end = p;
        const std::string tok_str = quote_token(tok, tok_end);
        if(n == 3) {   // count the rest for the message
          int extra = 1;
          for(;;) { skip_spaces(p, end); if(p == end) break; while(p != end && !is_space(*p)) ++p; ++extra; }
          return fail(lineno, "face with " + std::to_string(3 + extra) +
                              " vertices; only triangles are supported (this reader does not triangulate)");
        }
        const char* q = tok;
        long long a = 0, b = 0;
        if(!parse_index(q, tok_end, a))
          return fail(lineno, "cannot parse vertex index in face corner " + tok_str);
        if(q == tok_end || *q != '/')
          return fail(lineno, "face corner " + tok_str + " has no texture coordinate (expected v/vt or v/vt/vn)");
        ++q;
        if(q == tok_end || *q == '/')
          return fail(lineno, "face corner " + tok_str + " has no texture coordinate" + (q != tok_end ? " (v//vn)" : "") +
                              "; per-corner UVs are required");
        if(!parse_index(q, tok_end, b))
          return fail(lineno, "cannot parse texture index in face corner " + tok_str);
        if(q != tok_end) {
          if(*q != '/') return fail(lineno, "malformed face corner " + tok_str);
          ++q;
          long long c = 0;   // normal index: syntax checked, value ignored
          if(q != tok_end && (!parse_index(q, tok_end, c) || q != tok_end))
            return fail(lineno, "malformed normal index in face corner " + tok_str);
        }
        if(a == 0 || b == 0)
          return fail(lineno, "index 0 in face corner " + tok_str + " (OBJ indices start at 1)");
        // Negative = relative to the elements read so far (-1 = the last one).
        const long long a_in = a, b_in = b;
        if(!resolve_index(a_in, soup.points.size(), a))
          return fail(lineno, "relative vertex index " + std::to_string(a_in) + " out of range: it refers before the first vertex (" +
                              std::to_string(soup.points.size()) + " read so far)");
        if(!resolve_index(b_in, soup.uvs.size(), b))
          return fail(lineno, "relative texture index " + std::to_string(b_in) + " out of range: it refers before the first texture coordinate (" +
                              std::to_string(soup.uvs.size()) + " read so far)");
        if(a_in > max_v) { max_v = a_in; max_v_line = lineno; }
        if(b_in > max_vt) { max_vt = b_in; max_vt_line = lineno; }
        vi[n] = a; ti[n] = b;
        ++n;
      }
      if(n < 3)
        return fail(lineno, "face with " + std::to_string(n) + " vertices (at least 3 needed, and only triangles are supported)");
      soup.face_v.push_back({std::size_t(vi[0]), std::size_t(vi[1]), std::size_t(vi[2])});
      soup.face_vt.push_back({std::size_t(ti[0]), std::size_t(ti[1]), std::size_t(ti[2])});
      soup.face_line.push_back(lineno);
    }
    else
    {
      // vn, vp, g, o, s, usemtl, mtllib, l, p, and non-standard records (c, sm, ...) are skipped.
      ++soup.skipped_records;
    }
  }
  if(is.bad()) {
    message = where + ": read error after line " + std::to_string(lineno);
    return INVALID_INPUT;
  }
  if(max_v > static_cast<long long>(soup.points.size()))
    return fail(max_v_line, "vertex index " + std::to_string(max_v) + " out of range (the file has " +
                            std::to_string(soup.points.size()) + " vertices)");
  if(max_vt > static_cast<long long>(soup.uvs.size()))
    return fail(max_vt_line, "texture index " + std::to_string(max_vt) + " out of range (the file has " +
                             std::to_string(soup.uvs.size()) + " texture coordinates)");
  if(soup.face_v.empty()) {
    message = where + ": empty mesh: no face in " + std::to_string(lineno) + " lines (" +
              std::to_string(soup.points.size()) + " vertices)";
    return INVALID_INPUT;
  }
  return SUCCESS;
}

struct Bits3_hash
{
  std::size_t operator()(const std::array<std::uint64_t, 3>& a) const
  {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for(std::uint64_t x : a) { h ^= x + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2); }
    return std::size_t(h ^ (h >> 29));
  }
};

// rep[i]: the file vertex that vertex i of `points` becomes: itself, or with `weld` the first vertex of the
// file with bit-identical coordinates (0.0 and -0.0 differ). Returns how many vertices were merged into an earlier one.
inline std::size_t weld_representatives(const std::vector<std::array<double, 3> >& points, bool weld,
                                        std::vector<std::size_t>& rep)
{
  const std::size_t nv = points.size();
  rep.resize(nv);
  std::size_t welded = 0;
  if(weld) {
    std::unordered_map<std::array<std::uint64_t, 3>, std::size_t, Bits3_hash> first;
    first.reserve(nv);
    for(std::size_t i = 0; i < nv; ++i) {
      const std::array<double, 3>& x = points[i];
      auto ins = first.emplace(std::array<std::uint64_t, 3>{double_bits(x[0]), double_bits(x[1]), double_bits(x[2])}, i);
      rep[i] = ins.first->second;
      if(!ins.second) ++welded;
    }
  } else {
    for(std::size_t i = 0; i < nv; ++i) rep[i] = i;
  }
  return welded;
}

// Soup -> mesh. Validates the connectivity on a scratch mesh first, then replays the same
// operations on `tm` (which cannot fail then), so that a failure leaves `tm` and `uv` untouched.
// With `corners`, (*corners)[f][k] is the halfedge whose target is corner k of soup face f.
template <class TriangleMesh, class VPM, class HalfedgeUVMap>
Status build_mesh(const Obj_soup& soup, bool weld, TriangleMesh& tm, VPM vpm, HalfedgeUVMap uv,
                  const std::string& where, std::string& message,
                  std::vector<std::array<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor, 3> >* corners = nullptr)
{
  typedef boost::graph_traits<TriangleMesh>                  GT;
  typedef typename GT::vertex_descriptor                     vertex_descriptor;
  typedef typename GT::halfedge_descriptor                   halfedge_descriptor;
  typedef typename GT::face_descriptor                       face_descriptor;
  typedef typename boost::property_traits<VPM>::value_type   Point_3;
  typedef typename boost::property_traits<HalfedgeUVMap>::value_type Point_2;

  const std::size_t nv = soup.points.size();
  // 1. representative of each file vertex (itself, or the first bit-identical one when welding)
  std::vector<std::size_t> rep;
  const std::size_t welded = weld_representatives(soup.points, weld, rep);

  // 2. mesh vertex ids: representatives used by a face, in file order
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> id(nv, none);
  for(const std::array<std::size_t, 3>& f : soup.face_v)
    for(std::size_t c : f) id[rep[c]] = 0;
  std::size_t n_used = 0;
  for(std::size_t i = 0; i < nv; ++i)
    if(id[i] != none) id[i] = n_used++;
  std::size_t unreferenced = 0;
  for(std::size_t i = 0; i < nv; ++i)
    if(rep[i] == i && id[i] == none) ++unreferenced;

  auto fail = [&](std::size_t line, const std::string& why) {
    message = where + ":" + std::to_string(line) + ": " + why;
    return INVALID_INPUT;
  };

  // 3. connectivity check on a scratch mesh
  {
    TriangleMesh scratch;
    std::vector<vertex_descriptor> vs(n_used);
    for(std::size_t i = 0; i < n_used; ++i) vs[i] = add_vertex(scratch);
    std::array<vertex_descriptor, 3> fv;
    for(std::size_t f = 0; f < soup.face_v.size(); ++f) {
      for(int k = 0; k < 3; ++k) fv[k] = vs[id[rep[soup.face_v[f][k]]]];
      if(fv[0] == fv[1] || fv[1] == fv[2] || fv[2] == fv[0])
        return fail(soup.face_line[f], std::string("degenerate face: a vertex appears twice") +
                                       (weld ? " (after welding bit-identical vertices)" : ""));
      if(CGAL::Euler::add_face(fv, scratch) == GT::null_face()) {
        for(int k = 0; k < 3; ++k) {
          std::pair<halfedge_descriptor, bool> he = halfedge(fv[k], fv[(k + 1) % 3], scratch);
          if(he.second && !is_border(he.first, scratch))
            return fail(soup.face_line[f], "edge (" + std::to_string(soup.face_v[f][k] + 1) + ", " +
                        std::to_string(soup.face_v[f][(k + 1) % 3] + 1) + ") is already used in the same direction by another "
                        "face: non-manifold edge or inconsistent (non-orientable) orientation");
        }
        return fail(soup.face_line[f], "face cannot be added: non-manifold vertex (a vertex of the face is already "
                                       "surrounded by faces) or non-manifold edge");
      }
    }
    // A vertex where two fans meet is accepted by add_face in two cases; reject both here:
    // two closed fans (the cycle around the vertex misses some halfedges pointing to it), and
    // two open fans, a "bowtie" (two border halfedges point to it).
    auto in_degree = get(CGAL::dynamic_vertex_property_t<std::size_t>(), scratch);
    for(std::size_t i = 0; i < n_used; ++i) put(in_degree, vs[i], std::size_t(0));
    for(halfedge_descriptor h : halfedges(scratch)) put(in_degree, target(h, scratch), get(in_degree, target(h, scratch)) + 1);
    for(std::size_t i = 0; i < n_used; ++i) {
      std::size_t around = 0, border_fans = 0;
      for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(vs[i], scratch), scratch)) {
        ++around;
        if(is_border(h, scratch)) ++border_fans;
      }
      if(around != get(in_degree, vs[i]) || border_fans > 1) {
        std::size_t file_index = 0;
        for(std::size_t j = 0; j < nv; ++j) if(rep[j] == j && id[j] == i) { file_index = j; break; }
        message = where + ": non-manifold vertex " + std::to_string(file_index + 1) +
                  " (several fans of faces meet at it)";
        return INVALID_INPUT;
      }
    }
  }

  // 4. replay on tm; every operation succeeded on the scratch mesh, so it succeeds here too
  if(corners != nullptr) corners->assign(soup.face_v.size(), {});
  std::vector<vertex_descriptor> vs(n_used);
  for(std::size_t i = 0; i < nv; ++i)
    if(rep[i] == i && id[i] != none) {
      vs[id[i]] = add_vertex(tm);
      put(vpm, vs[id[i]], Point_3(soup.points[i][0], soup.points[i][1], soup.points[i][2]));
    }
  std::array<vertex_descriptor, 3> fv;
  for(std::size_t f = 0; f < soup.face_v.size(); ++f) {
    for(int k = 0; k < 3; ++k) fv[k] = vs[id[rep[soup.face_v[f][k]]]];
    face_descriptor fd = CGAL::Euler::add_face(fv, tm);
    CGAL_assertion(fd != GT::null_face());
    // corner convention: uv[h] = UV of target(h) in face(h)
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(fd, tm), tm))
      for(int k = 0; k < 3; ++k)
        if(fv[k] == target(h, tm)) {
          const std::array<double, 2>& t = soup.uvs[soup.face_vt[f][k]];
          put(uv, h, Point_2(t[0], t[1]));
          if(corners != nullptr) (*corners)[f][std::size_t(k)] = h;
        }
  }

  message = "read " + std::to_string(soup.face_v.size()) + " faces, " + std::to_string(n_used) + " vertices, " +
            std::to_string(soup.uvs.size()) + " texture coordinates from " + where;
  if(weld) message += "; welded " + std::to_string(welded) + " duplicated vertices";
  if(unreferenced != 0) message += "; dropped " + std::to_string(unreferenced) + " vertices used by no face";
  if(soup.skipped_records != 0) message += "; skipped " + std::to_string(soup.skipped_records) + " other records (vn, g, s, ...)";
  return SUCCESS;
}

// ---------------------------------------------------------------------------------------------
// Writing
// ---------------------------------------------------------------------------------------------

// Validates and formats the whole file in memory (a few tens of MB at most for real meshes),
// so that no byte is written for an invalid mesh.
template <class TriangleMesh, class VPM, class HalfedgeUVMap>
Status format_obj(const TriangleMesh& tm, VPM vpm, HalfedgeUVMap uv, bool vt_per_corner, std::string& out,
                  std::string& message)
{
  typedef boost::graph_traits<TriangleMesh>            GT;
  typedef typename GT::vertex_descriptor               vertex_descriptor;
  typedef typename GT::halfedge_descriptor             halfedge_descriptor;
  typedef typename GT::face_descriptor                 face_descriptor;

  if(faces(tm).first == faces(tm).second) { message = "empty mesh: no face to write"; return INVALID_INPUT; }

  auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t nv = 0;
  for(vertex_descriptor v : vertices(tm)) put(vid, v, nv++);

  std::vector<std::array<double, 3> > pts;
  pts.reserve(nv);
  for(vertex_descriptor v : vertices(tm)) {
    const auto& p = get(vpm, v);
    std::array<double, 3> x = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    if(!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) {
      message = "vertex " + std::to_string(get(vid, v) + 1) + " has a non-finite coordinate (NaN or Inf)";
      return INVALID_INPUT;
    }
    pts.push_back(x);
  }

  // One vt per (vertex, bit-identical UV): corners of one vertex with the same UV share it, as
  // inside a chart; a seam (different UV) or another vertex gets its own. With `vt_per_corner`, one
  // vt per face corner (libQEx's layout).
  std::vector<std::vector<std::pair<std::array<std::uint64_t, 2>, std::size_t> > > vt_of_vertex(nv);
  std::vector<std::array<double, 2> > vts;
  std::vector<std::array<std::size_t, 6> > fs;   // v0 vt0 v1 vt1 v2 vt2 (0-based)
  std::size_t fi = 0;
  for(face_descriptor f : faces(tm)) {
    std::array<std::size_t, 6> row;
    int k = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      if(k == 3) {
        message = "face " + std::to_string(fi + 1) + " is not a triangle; only triangle meshes are written";
        return INVALID_INPUT;
      }
      const auto& t = get(uv, h);
      const double u = CGAL::to_double(t.x()), w = CGAL::to_double(t.y());
      if(!std::isfinite(u) || !std::isfinite(w)) {
        message = "non-finite UV (NaN or Inf) at a corner of face " + std::to_string(fi + 1);
        return INVALID_INPUT;
      }
      const std::size_t v = get(vid, target(h, tm));
      const std::array<std::uint64_t, 2> key = {double_bits(u), double_bits(w)};
      std::size_t t_id = std::size_t(-1);
      if(!vt_per_corner)
        for(const auto& e : vt_of_vertex[v]) if(e.first == key) { t_id = e.second; break; }
      if(t_id == std::size_t(-1)) {
        t_id = vts.size();
        vts.push_back({u, w});
        if(!vt_per_corner) vt_of_vertex[v].emplace_back(key, t_id);
      }
      row[2 * k] = v; row[2 * k + 1] = t_id;
      ++k;
    }
    if(k != 3) {
      message = "face " + std::to_string(fi + 1) + " is not a triangle; only triangle meshes are written";
      return INVALID_INPUT;
    }
    fs.push_back(row);
    ++fi;
  }

  out.clear();
  out.reserve(nv * 64 + vts.size() * 44 + fs.size() * 40 + 256);
  out += "# OBJ with per-corner texture coordinates (CGAL Seamless_snapping): f v/vt, vt = UV of the corner,\n";
  out += "# 17 significant digits (bit-exact doubles). " + std::to_string(nv) + " vertices, " +
         std::to_string(vts.size()) + " texture coordinates, " + std::to_string(fs.size()) + " faces\n";
  for(const std::array<double, 3>& p : pts) {
    out += "v ";  append_double(out, p[0]);
    out += ' ';   append_double(out, p[1]);
    out += ' ';   append_double(out, p[2]);
    out += '\n';
  }
  for(const std::array<double, 2>& t : vts) {
    out += "vt "; append_double(out, t[0]);
    out += ' ';   append_double(out, t[1]);
    out += '\n';
  }
  for(const std::array<std::size_t, 6>& r : fs) {
    out += 'f';
    for(int k = 0; k < 3; ++k) {
      out += ' '; out += std::to_string(r[2 * k] + 1);
      out += '/'; out += std::to_string(r[2 * k + 1] + 1);
    }
    out += '\n';
  }
  message = "wrote " + std::to_string(fs.size()) + " faces, " + std::to_string(nv) + " vertices, " +
            std::to_string(vts.size()) + " texture coordinates";
  return SUCCESS;
}

// A name for a temporary file next to `filename` (same directory, so std::rename is atomic).
inline std::string temporary_name_next_to(const std::string& filename)
{
  static std::atomic<unsigned> counter(0);
  std::random_device rd;
  const unsigned long long r = (static_cast<unsigned long long>(rd()) << 20) ^
      static_cast<unsigned long long>(std::chrono::steady_clock::now().time_since_epoch().count()) ^ (counter++);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%012llx", r & 0xFFFFFFFFFFFFull);
  return filename + ".tmp-" + buf;
}

// Writes `text` to `filename` through a temporary file next to it and std::rename (atomic on POSIX):
// on failure nothing is left behind and `filename` is untouched.
inline Status write_text_atomically(const std::string& filename, const std::string& text, std::string& message)
{
  const std::string tmp = temporary_name_next_to(filename);
  {
    std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
    if(!os) {
      message = "cannot write '" + filename + "': cannot create the temporary file '" + tmp + "' (" +
                std::strerror(errno) + ")";
      return INVALID_INPUT;
    }
    os.write(text.data(), static_cast<std::streamsize>(text.size()));
    os.flush();
    const bool ok = static_cast<bool>(os);
    os.close();
    if(!ok || os.fail()) {
      std::remove(tmp.c_str());
      message = "cannot write '" + filename + "': writing the temporary file '" + tmp + "' failed (disk full?)";
      return INVALID_INPUT;
    }
  }
  if(std::rename(tmp.c_str(), filename.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    message = "cannot write '" + filename + "': renaming the temporary file failed (" + why + ")";
    return INVALID_INPUT;
  }
  return SUCCESS;
}

template <class TriangleMesh, class HalfedgeUVMap, class NamedParameters>
Status read_obj_impl(std::istream& is, const std::string& where, TriangleMesh& tm, HalfedgeUVMap uv,
                     std::string& message, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::type VPM;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                             get_property_map(CGAL::vertex_point, tm));
  const bool weld = choose_parameter(get_parameter(np, snap_np::weld_vertices), false);

  Obj_soup soup;
  if(parse_obj(is, soup, where, message) != SUCCESS) return INVALID_INPUT;
  return build_mesh(soup, weld, tm, vpm, uv, where, message);
}

template <class TriangleMesh, class HalfedgeUVMap, class NamedParameters>
Status format_obj_np(const TriangleMesh& tm, HalfedgeUVMap uv, std::string& out, std::string& message,
                     const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                             get_const_property_map(CGAL::vertex_point, tm));
  return format_obj(tm, vpm, uv, choose_parameter(get_parameter(np, snap_np::vt_per_corner), false), out, message);
}

} // namespace internal

/*!
 * \ingroup PkgSeamlessSnappingRef
 * reads a triangle mesh with per-corner texture coordinates (UVs) from the OBJ file `filename`
 * and appends it to `tm` (like `CGAL::IO::read_OBJ()`, `tm` is not cleared; it is normally empty).
 *
 * The corner UV map is filled with the convention of the package: for every face `f` of the
 * file and every halfedge `h` of `f`, `get(uv, h)` is the `vt` of the corner (`target(h)`, `f`).
 * Only non-border halfedges are written; border halfedges keep whatever value `uv` gives them
 * (if the map is also to be used by a `CGAL::Seam_mesh`, copy `get(uv, prev(opposite(h)))` onto
 * each border halfedge `h`, see `CGAL_CONVENTIONS`).
 *
 * What is read:
 * - `v x y z` (extra numbers such as `w` or vertex colours are ignored), `vt u v` (a third
 *   coordinate is ignored), and `f a/ta b/tb c/tc` or `f a/ta/na b/tb/nb c/tc/nc` (normal indices
 *   are ignored). Indices start at 1; negative indices are relative (`-1` = the last element read
 *   so far); positive indices may refer to elements given further down.
 * - Any `vt` layout: shared inside charts, one `vt` per face corner, or one per vertex of a cut
 *   mesh. Seams are where the UV *values* of the two faces of an edge differ, not where indices do.
 * - Comments (`#` to the end of the line) and every other record (`vn`, `vp`, `g`, `o`, `s`,
 *   `usemtl`, `mtllib`, `l`, `p` and non-standard ones such as `c` or `sm`) are skipped.
 * - Vertices used by no face are dropped; the others keep their file order.
 * - Lines are read one by one: line continuations (a `\` at the end of a line) are not supported.
 * - With `weld_vertices(true)`, vertices with bit-identical coordinates become one vertex (the
 *   first in the file): this turns the "cut meshes" written by libigl/Directional, whose
 *   vertices are duplicated along the seams, back into the closed surface. Coordinates that are
 *   equal but not bit-identical (`0.0` and `-0.0`) are not merged.
 *
 * What is rejected, with `INVALID_INPUT` and a message `"<filename>:<line>: <reason>"`:
 * a face without texture coordinates (`f a b c`, `f a//na`); a face that is not a triangle
 * (this reader does not triangulate); an index that is 0 or out of range; NaN, Inf or unparsable
 * coordinates; a degenerate face (a vertex twice, also after welding); a non-manifold edge or vertex,
 * or an orientation that is inconsistent between neighbouring faces (non-orientable input),
 * as detected by `CGAL::Euler::add_face()`; a file without faces; a file that cannot be opened.
 *
 * \tparam TriangleMesh a model of `MutableFaceGraph` (e.g. `CGAL::Surface_mesh`), default constructible
 * \tparam HalfedgeUVMap a model of `WritablePropertyMap` with
 *         `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and a 2D point type
 *         constructible from two `double` as value type
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param filename the OBJ file
 * \param tm the mesh the file is appended to
 * \param uv the corner UV map of `tm`
 * \param message on success a one-line summary (counts, number of welded vertices), otherwise the reason
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of `tm`}
 *     \cgalParamType{a class model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
 *                    as key type and a 3D point type constructible from three `double` as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{weld_vertices}
 *     \cgalParamDescription{merge vertices whose coordinates are bit-identical}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{`false`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::weld_vertices()`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return `SUCCESS`, or `INVALID_INPUT`; on failure `tm` and `uv` are left exactly as they were
 *         (the connectivity is checked on a scratch mesh before `tm` is touched).
 *
 * \sa `write_OBJ_with_corner_uvs()`
 */
template <class TriangleMesh, class HalfedgeUVMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Status read_OBJ_with_corner_uvs(const std::string& filename, TriangleMesh& tm, HalfedgeUVMap uv,
                                std::string& message,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  std::ifstream is(filename, std::ios::binary);
  if(!is) {
    message = "cannot open '" + filename + "' for reading";
    return INVALID_INPUT;
  }
  return internal::read_obj_impl(is, filename, tm, uv, message, np);
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 * same as the file overload, reading from the stream `is`; messages name lines `"stream:<line>"`.
 */
template <class TriangleMesh, class HalfedgeUVMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Status read_OBJ_with_corner_uvs(std::istream& is, TriangleMesh& tm, HalfedgeUVMap uv, std::string& message,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  if(!is) {
    message = "stream: not readable";
    return INVALID_INPUT;
  }
  return internal::read_obj_impl(is, std::string("stream"), tm, uv, message, np);
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 * writes the triangle mesh `tm` with the per-corner texture coordinates `uv` to the OBJ file
 * `filename`, atomically: the text goes to a temporary file in the same directory, which is
 * then renamed to `filename` (`std::rename()`, atomic on POSIX file systems). On any failure no
 * file is created or changed, and no temporary file is left behind.
 *
 * The file has one `v` per vertex (in the order of `vertices(tm)`), one `vt` per vertex and
 * distinct (bit-identical) UV among the corners of that vertex (so `vt` are shared inside charts
 * and differ across seams), and one `f v/vt v/vt v/vt` per face, the corners in the order of
 * `halfedges_around_face(halfedge(f, tm), tm)`. Numbers have 17 significant digits (locale
 * independent), so reading the file back with `read_OBJ_with_corner_uvs()` gives bit-identical
 * positions and UVs. Only the corner UVs (non-border halfedges) are written.
 *
 * \tparam TriangleMesh a model of `FaceListGraph`
 * \tparam HalfedgeUVMap a model of `ReadablePropertyMap` with
 *         `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and a 2D point type as value type
 *         (coordinates are converted with `CGAL::to_double()`, exact for `double`)
 * \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
 *
 * \param filename the file to write
 * \param tm the mesh, triangles only
 * \param uv its corner UV map: `get(uv, h)` is the UV of (`target(h)`, `face(h)`)
 * \param message on success a one-line summary, otherwise the reason
 * \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
 *
 * \cgalNamedParamsBegin
 *   \cgalParamNBegin{vertex_point_map}
 *     \cgalParamDescription{a property map associating points to the vertices of `tm`}
 *     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
 *                    as key type and a 3D point type as value type}
 *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
 *   \cgalParamNEnd
 *   \cgalParamNBegin{vt_per_corner}
 *     \cgalParamDescription{write one `vt` per face corner (`3 * #faces` of them, the layout of libQEx's test meshes)
 *                           instead of one per vertex and distinct UV}
 *     \cgalParamType{Boolean}
 *     \cgalParamDefault{`false`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::vt_per_corner()`}
 *   \cgalParamNEnd
 * \cgalNamedParamsEnd
 *
 * \return `SUCCESS`, or `INVALID_INPUT` (the message says why) for a mesh without faces, a face that is
 *         not a triangle, a NaN/Inf coordinate or UV, or an I/O failure (directory not writable, disk full, rename failed).
 */
template <class TriangleMesh, class HalfedgeUVMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Status write_OBJ_with_corner_uvs(const std::string& filename, const TriangleMesh& tm, HalfedgeUVMap uv,
                                 std::string& message,
                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  std::string text;
  if(internal::format_obj_np(tm, uv, text, message, np) != SUCCESS) {
    message = "not writing '" + filename + "': " + message;
    return INVALID_INPUT;
  }
  const std::string summary = message;
  if(internal::write_text_atomically(filename, text, message) != SUCCESS) return INVALID_INPUT;
  message = summary + " to " + filename;
  return SUCCESS;
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 * same as the file overload, writing to the stream `os`. The mesh is checked and the whole text
 * formatted before the first byte is written, so an invalid mesh writes nothing; a stream error
 * in the middle (returned as `INVALID_INPUT`) may leave a partial text in `os`.
 */
template <class TriangleMesh, class HalfedgeUVMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Status write_OBJ_with_corner_uvs(std::ostream& os, const TriangleMesh& tm, HalfedgeUVMap uv,
                                 std::string& message,
                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  std::string text;
  if(internal::format_obj_np(tm, uv, text, message, np) != SUCCESS) return INVALID_INPUT;
  os.write(text.data(), static_cast<std::streamsize>(text.size()));
  os.flush();
  if(!os) {
    message = "stream: write failed";
    return INVALID_INPUT;
  }
  return SUCCESS;
}

} // namespace IO
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_IO_OBJ_H
