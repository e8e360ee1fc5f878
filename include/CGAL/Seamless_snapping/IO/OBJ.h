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
#include <CGAL/Seamless_snapping/internal/mesh/halfedge_arrays.h>
#include <CGAL/Seamless_snapping/internal/io/line_reader.h>
#include <CGAL/Seamless_snapping/internal/threads.h>

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
#include <condition_variable>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <istream>
#include <mutex>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace IO {
namespace internal {

// ---------------------------------------------------------------------------------------------
// Numbers. std::from_chars / std::to_chars are locale independent and, for double, correctly
// rounded: std::to_chars without a precision writes the shortest decimal that std::from_chars reads
// back to the same double, bit for bit (C++17 [charconv.to.chars]), e.g. 0.1 as "0.1" and not
// "0.10000000000000001". Without them (old standard libraries) we fall back to strtod and to
// snprintf("%.17g"), 17 significant digits, which also round-trip every finite double under the
// "C" numeric locale.
// ---------------------------------------------------------------------------------------------

// A leading '+' (one sign only: "+-1" is no number; it was read as -1), skipped; false where a second sign follows
inline bool skip_plus(const char*& p, const char* end)
{
  if(p == end || *p != '+') return true;
  if(p + 1 != end && (p[1] == '-' || p[1] == '+')) return false;
  ++p;
  return true;
}

// Parses one double at [p, end); on success advances p. Leading '+' is accepted (OBJ writers
// emit it), "nan"/"inf" parse here and are rejected by the caller with a clearer message.
inline bool parse_double(const char*& p, const char* end, double& x, bool& out_of_range)
{
  out_of_range = false;
  if(!skip_plus(p, end)) return false;
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
  if(errno == ERANGE && (std::isinf(x) || x == 0)) { out_of_range = true; return false; }   // as std::from_chars
  p += (e - tok.c_str());
  return true;
#endif
}

// Parses an optional sign and decimal digits; false on overflow or when there are no digits.
inline bool parse_index(const char*& p, const char* end, long long& i)
{
  if(!skip_plus(p, end)) return false;
  std::from_chars_result r = std::from_chars(p, end, i);
  if(r.ec != std::errc()) return false;
  p = r.ptr;
  return true;
}

// Writes x as the shortest decimal that reads back to x bit for bit at p, which must have room for 32
// characters; returns the end. (Shortest rather than 17 digits: the bunny of ../shared/large, 800K
// numbers, 70 -> 50 ms and 15.6 -> 13.8 MB, and the file reads back faster.)
inline char* write_double(char* p, double x)
{
#if defined(__cpp_lib_to_chars)
  return std::to_chars(p, p + 32, x).ptr;
#else
  return p + std::snprintf(p, 32, "%.17g", x);
#endif
}

// Writes the decimal digits of i at p (room for 20 characters); returns the end.
inline char* write_index(char* p, std::uint64_t i)
{
  return std::to_chars(p, p + 20, i).ptr;
}

// Appends x as the shortest decimal that reads back to x bit for bit (write_double()).
inline void append_double(std::string& out, double x)
{
  char buf[32];
  out.append(buf, write_double(buf, x));
}

inline std::uint64_t double_bits(double x)
{
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

inline void skip_spaces(const char*& p, const char* end) { while(p != end && is_space(*p)) ++p; }

// the end of the messages on a file whose line ends are carriage returns alone
inline std::string cr_line_ends_hint()
{
  return "line ends of a carriage return alone (classic Mac OS) are not line breaks here; convert the file to LF or "
         "CRLF line ends";
}

// A token of the file for a message, quoted: at most 60 characters of it, then "..." and its
// length, so that a huge unparsable token does not end up whole in the message; control characters as \xNN (a NUL
// byte went raw to the terminal)
inline std::string quote_token(const char* begin, const char* end)
{
  const std::size_t n = std::size_t(end - begin);
  std::size_t shown = 60;
  if(n > shown)
    while(shown > 56 && (static_cast<unsigned char>(begin[shown]) & 0xC0) == 0x80) --shown;   // not inside a UTF-8 character
  std::string q = "'";
  for(const char* c = begin; c != begin + (std::min)(n, shown); ++c) {
    const unsigned char b = static_cast<unsigned char>(*c);
    if(b >= 0x20 && b != 0x7F) { q += *c; continue; }
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02X", unsigned(b));
    q += hex;
  }
  return n <= shown ? q + "'" : q + "...' (" + std::to_string(n) + " characters)";
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

// What parse_obj_lines() keeps besides the soup: the lines read, and the largest positive index per kind with its
// line (range check once the counts are known: the OBJ format allows a face to refer to vertices given further down).
struct Obj_parse_state
{
  std::size_t lines = 0;
  bool first_line_has_cr = false;   // a carriage return inside the first line (line ends of a carriage return alone)
  bool nul_in_skipped = false;      // a skipped record's type holds a NUL byte (UTF-16: "v\0 \0...", read as no record)
  long long max_v = 0, max_vt = 0;
  std::size_t max_v_line = 0, max_vt_line = 0;
};

// Reads the lines of `is` (at most `limit` bytes) into `soup`. Returns SUCCESS or INVALID_INPUT with
// "<where>:<line>: reason". Lines come from for_each_line() (std::getline's lines, without a std::string each);
// messages are only formatted on failure. `whole` = false: the stream is a later part of a file (parse_obj_file()):
// its first line is not the file's (no byte-order mark), line numbers count from its start, and a relative
// (negative) index, which needs the counts of the parts before, fails.
inline Status parse_obj_lines(std::istream& is, Obj_soup& soup, Obj_parse_state& state, const std::string& where,
                              std::string& message, std::size_t limit = std::size_t(-1), bool whole = true)
{
  Status status = SUCCESS;
  auto fail = [&](std::size_t line, const std::string& why) {
    message = where + ":" + std::to_string(line) + ": " + why;
    status = INVALID_INPUT;
    return false;
  };
  long long& max_v = state.max_v;
  long long& max_vt = state.max_vt;
  std::size_t& max_v_line = state.max_v_line;
  std::size_t& max_vt_line = state.max_vt_line;

  auto read_required_numbers = [&](const char*& p, const char* end, std::size_t lineno, double* out, int required,
                                   const char* what) -> bool {
    for(int k = 0; k < required; ++k) {
      skip_spaces(p, end);
      bool oor = false;
      const char* start = p;
      if(p == end)
        return fail(lineno, std::string("'") + what + "' record needs " + std::to_string(required) + " coordinates, got " + std::to_string(k));
      if(!parse_double(p, end, out[k], oor) || (p != end && !is_space(*p))) {
        const char* tok_end = start; while(tok_end != end && !is_space(*tok_end)) ++tok_end;
        const std::string tok = quote_token(start, tok_end);
        if(oor)   // too large or too small in magnitude (std::from_chars says which only in the value it does not write)
          return fail(lineno, "coordinate " + tok + " is outside the range of double (" +
                              (std::isinf(std::strtod(std::string(start, tok_end).c_str(), nullptr))
                                 ? "its magnitude is above 1.8e308)" : "nonzero, but it would round to 0: below 4.9e-324)"));
        return fail(lineno, "cannot parse coordinate " + tok + " of a '" + what + "' record");
      }
      if(!std::isfinite(out[k]))
        return fail(lineno, std::string("non-finite coordinate (NaN or Inf) in a '") + what + "' record");
    }
    return true;
  };

  // Reads `required` doubles; extra numbers (v: w or r g b; vt: w) are ignored, other text after them is refused (it was
  // ignored: "v 0 1 0 junk" read as a vertex, and a file with CR-only line ends, read as one line, as its first vertex
  // with the rest of the file ignored). False after fail().
  auto read_numbers = [&](const char*& p, const char* end, std::size_t lineno, double* out, int required,
                          const char* what) -> bool {
    if(!read_required_numbers(p, end, lineno, out, required, what)) return false;
    for(;;) {
      skip_spaces(p, end);
      if(p == end) return true;
      const char* start = p;
      double extra;
      bool oor = false;
      if(parse_double(p, end, extra, oor) && (p == end || is_space(*p))) continue;
      const char* tok_end = start; while(tok_end != end && !is_space(*tok_end)) ++tok_end;
      const char* cr = static_cast<const char*>(std::memchr(start, '\r', std::size_t(end - start)));
      if(oor)
        return fail(lineno, "number " + quote_token(start, tok_end) + " after the coordinates of a '" + what +
                            "' record is outside the range of double");
      return fail(lineno, "unexpected text " + quote_token(start, tok_end) + " after the coordinates of a '" + what +
                          "' record (only numbers may follow them: w, or a color)" +
                          (cr != nullptr && cr + 1 != end ? "; the line holds a carriage return in its middle: " +
                                                            cr_line_ends_hint() : ""));
    }
  };

  // One face record after its tag: the corners "v/vt", "v/vt/vn"; only triangles.
  auto read_face = [&](const char*& p, const char* end, std::size_t lineno) -> bool {
    std::array<long long, 3> vi{}, ti{};
    int n = 0;
    for(;;)
    {
      skip_spaces(p, end);
      if(p == end) break;
      const char* tok = p;
      while(p != end && !is_space(*p)) ++p;
      const char* tok_end = p;
      auto token = [&]() { return quote_token(tok, tok_end); };
      if(n == 3) {   // count the rest for the message
        int extra = 1;
        for(;;) { skip_spaces(p, end); if(p == end) break; while(p != end && !is_space(*p)) ++p; ++extra; }
        return fail(lineno, "face with " + std::to_string(3 + extra) +
                            " vertices; only triangles are supported (this reader does not triangulate)");
      }
      const char* q = tok;
      long long a = 0, b = 0;
      if(!parse_index(q, tok_end, a))
        return fail(lineno, "cannot parse vertex index in face corner " + token());
      if(q == tok_end || *q != '/')
        return fail(lineno, "face corner " + token() + " has no texture coordinate (expected v/vt or v/vt/vn)");
      ++q;
      if(q == tok_end || *q == '/')
        return fail(lineno, "face corner " + token() + " has no texture coordinate" + (q != tok_end ? " (v//vn)" : "") +
                            "; per-corner UVs are required");
      if(!parse_index(q, tok_end, b))
        return fail(lineno, "cannot parse texture index in face corner " + token());
      if(q != tok_end) {
        if(*q != '/') return fail(lineno, "malformed face corner " + token());
        ++q;
        long long c = 0;   // normal index: syntax checked, value ignored
        if(q != tok_end && (!parse_index(q, tok_end, c) || q != tok_end))
          return fail(lineno, "malformed normal index in face corner " + token());
      }
      if(a == 0 || b == 0)
        return fail(lineno, "index 0 in face corner " + token() + " (OBJ indices start at 1)");
      // Negative = relative to the elements read so far (-1 = the last one).
      const long long a_in = a, b_in = b;
      if(!whole && (a_in < 0 || b_in < 0)) return fail(lineno, "relative index in a later part of the file");
      if(!resolve_index(a_in, soup.points.size(), a))
        return fail(lineno, "relative vertex index " + std::to_string(a_in) + " out of range: it refers before the first vertex (" +
                            std::to_string(soup.points.size()) + " read so far)");
      if(!resolve_index(b_in, soup.uvs.size(), b))
        return fail(lineno, "relative texture index " + std::to_string(b_in) + " out of range: it refers before the first texture coordinate (" +
                            std::to_string(soup.uvs.size()) + " read so far)");
      if(a_in > max_v) { max_v = a_in; max_v_line = lineno; }
      if(b_in > max_vt) { max_vt = b_in; max_vt_line = lineno; }
      vi[std::size_t(n)] = a; ti[std::size_t(n)] = b;
      ++n;
    }
    if(n < 3)
      return fail(lineno, "face with " + std::to_string(n) + " vertices (at least 3 needed, and only triangles are supported)");
    soup.face_v.push_back({std::size_t(vi[0]), std::size_t(vi[1]), std::size_t(vi[2])});
    soup.face_vt.push_back({std::size_t(ti[0]), std::size_t(ti[1]), std::size_t(ti[2])});
    soup.face_line.push_back(lineno);
    return true;
  };

  bool read_error = false, too_long = false;
  const std::size_t lines = for_each_line(is, [&](const char* p, const char* end, std::size_t lineno) -> bool {
    // a UTF-8 byte-order mark at the start of the file is not part of the first record
    if(whole && lineno == 1 && end - p >= 3 && std::memcmp(p, "\xEF\xBB\xBF", 3) == 0) p += 3;
    if(whole && lineno == 1 && end - p >= 2) state.first_line_has_cr = std::memchr(p, '\r', std::size_t(end - p - 1)) != nullptr;
    // A '#' starts a comment anywhere on the line (also covers "#scale_uv" and friends).
    if(const void* hash = std::memchr(p, '#', std::size_t(end - p)))   // from p: after a byte-order mark too
      end = static_cast<const char*>(hash);
    for(;;) {                                         // (again after a byte-order mark inside the file)
      skip_spaces(p, end);
      if(p == end) return true;
      const char* tag_begin = p;
      while(p != end && !is_space(*p)) ++p;
      const std::size_t tag_len = std::size_t(p - tag_begin);
      if(tag_len == 1 && tag_begin[0] == 'f') return read_face(p, end, lineno);
      if(tag_len == 1 && tag_begin[0] == 'v') {
        std::array<double, 3> x;
        if(!read_numbers(p, end, lineno, x.data(), 3, "v")) return false;
        soup.points.push_back(x);
        return true;
      }
      if(tag_len == 2 && tag_begin[0] == 'v' && tag_begin[1] == 't') {
        std::array<double, 2> x;
        if(!read_numbers(p, end, lineno, x.data(), 2, "vt")) return false;
        soup.uvs.push_back(x);
        return true;
      }
      // a byte-order mark that is not the file's first bytes (files joined, or a mark written twice) is no part of the
      // record after it, which was skipped unseen (and what referred to it failed elsewhere: "vertex index out of range")
      if(tag_len >= 3 && std::memcmp(tag_begin, "\xEF\xBB\xBF", 3) == 0) { p = tag_begin + 3; continue; }
      // vn, vp, g, o, s, usemtl, mtllib, l, p, and non-standard records (c, sm, ...) are skipped.
      ++soup.skipped_records;
      if(std::memchr(tag_begin, '\0', tag_len) != nullptr) state.nul_in_skipped = true;
      return true;
    }
  }, read_error, too_long, limit);
  state.lines = lines;
  if(status != SUCCESS) return status;
  if(read_error) {
    message = where + ": read error after line " + std::to_string(lines);
    return INVALID_INPUT;
  }
  if(too_long) {
    message = where + ":" + std::to_string(lines + 1) + ": a line longer than " + std::to_string(max_line_bytes >> 20) +
              " MiB (not an OBJ text file?); nothing was read";
    return INVALID_INPUT;
  }
  return SUCCESS;
}

// The checks that need the whole file: indices in range, at least one face.
inline Status finish_obj(const Obj_soup& soup, const Obj_parse_state& state, const std::string& where, std::string& message)
{
  Status status = SUCCESS;
  auto fail = [&](std::size_t line, const std::string& why) {
    message = where + ":" + std::to_string(line) + ": " + why;
    status = INVALID_INPUT;
  };
  const long long max_v = state.max_v, max_vt = state.max_vt;
  const std::size_t max_v_line = state.max_v_line, max_vt_line = state.max_vt_line, lineno = state.lines;
  if(max_v > static_cast<long long>(soup.points.size())) {
    fail(max_v_line, "vertex index " + std::to_string(max_v) + " out of range (the file has " +
                     std::to_string(soup.points.size()) + " vertices)");
    return status;
  }
  if(max_vt > static_cast<long long>(soup.uvs.size())) {
    fail(max_vt_line, "texture index " + std::to_string(max_vt) + " out of range (the file has " +
                      std::to_string(soup.uvs.size()) + " texture coordinates)");
    return status;
  }
  if(soup.face_v.empty()) {
    message = where + ": empty mesh: no face in " + std::to_string(lineno) + " lines (" +
              std::to_string(soup.points.size()) + " vertices)" +
              (lineno == 1 && state.first_line_has_cr ? "; its one line holds carriage returns: " + cr_line_ends_hint() : "") +
              (state.nul_in_skipped ? "; its records hold NUL bytes: UTF-16 or another two-byte encoding? (OBJ files are "
                                      "ASCII or UTF-8)" : "");
    return INVALID_INPUT;
  }
  return SUCCESS;
}

// Reads the whole stream into `soup` (parse_obj_lines(), then finish_obj()).
inline Status parse_obj(std::istream& is, Obj_soup& soup, const std::string& where, std::string& message)
{
  Obj_parse_state state;
  const Status s = parse_obj_lines(is, soup, state, where, message);
  return s != SUCCESS ? s : finish_obj(soup, state, where, message);
}

// `b`, the part of a file after `a`'s, appended to `a` (its line numbers shifted by a's lines)
inline void append_part(Obj_soup& a, Obj_parse_state& sa, const Obj_soup& b, const Obj_parse_state& sb)
{
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  a.uvs.insert(a.uvs.end(), b.uvs.begin(), b.uvs.end());
  a.face_v.insert(a.face_v.end(), b.face_v.begin(), b.face_v.end());
  a.face_vt.insert(a.face_vt.end(), b.face_vt.begin(), b.face_vt.end());
  const std::size_t first = a.face_line.size();
  a.face_line.insert(a.face_line.end(), b.face_line.begin(), b.face_line.end());
  for(std::size_t i = first; i < a.face_line.size(); ++i) a.face_line[i] += sa.lines;
  a.skipped_records += b.skipped_records;
  if(sb.max_v > sa.max_v) { sa.max_v = sb.max_v; sa.max_v_line = sb.max_v_line + sa.lines; }   // ties: the first line
  if(sb.max_vt > sa.max_vt) { sa.max_vt = sb.max_vt; sa.max_vt_line = sb.max_vt_line + sa.lines; }
  sa.lines += sb.lines;
  sa.nul_in_skipped = sa.nul_in_skipped || sb.nul_in_skipped;
}

// Reads the file `filename` into `soup`, as parse_obj() reads it: the same soup and the same messages. With two
// threads or more and a file of at least `min_split` bytes, its two halves (cut after the first '\n' from the middle
// on) are parsed at once, on two threads, and joined; where either half fails (bad input, a relative index in the
// second half, a read error), the whole file is parsed again on one thread, for the message parse_obj() gives.
// What is not a regular file (a pipe, a FIFO) is read once, on one thread.
// `in_halves`: set if the result is the two halves'.
// The 30 MB OBJ of ../shared/large, min of 6 in one process: parsing 49 -> 31 ms, the whole reader 128 -> 113 ms.
inline Status parse_obj_file(const std::string& filename, Obj_soup& soup, std::string& message, unsigned threads,
                             std::size_t min_split = std::size_t(1) << 22, bool* in_halves = nullptr)
{
  if(in_halves != nullptr) *in_halves = false;
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(filename, ec);
  if(std::filesystem::is_directory(status)) {          // opens, then reads as "read error"
    message = "cannot read '" + filename + "': it is a directory";
    return INVALID_INPUT;
  }
  std::ifstream is(filename, std::ios::binary);
  if(!is) {
    message = "cannot open '" + filename + "' for reading";
    return INVALID_INPUT;
  }
  // a pipe or a FIFO (/dev/stdin) cannot seek: read on one thread (the failed seekg() left it failed, read as empty)
  if(threads >= 2 && std::filesystem::is_regular_file(status)) {
    is.seekg(0, std::ios::end);
    const std::streamoff size = is.tellg();
    std::ifstream second;             // opened only for a file large enough to be split
    std::streamoff cut = -1;
    if(size > 0 && std::size_t(size) >= min_split) second.open(filename, std::ios::binary);
    if(second.is_open() && second.seekg(size / 2)) {
      std::streamoff at = size / 2;   // the first byte after a '\n' from the middle on
      char c;
      while(second.get(c)) { ++at; if(c == '\n') { cut = at; break; } }
    }
    if(cut > 0 && cut < size) {
      Obj_soup first_soup, second_soup;
      Obj_parse_state first_state, second_state;
      std::string first_message, second_message;
      Status first_status = INVALID_INPUT, second_status = INVALID_INPUT;
      is.clear();
      is.seekg(0);
      Seamless_snapping::internal::run_concurrently(threads, [&] {
        first_status = parse_obj_lines(is, first_soup, first_state, filename, first_message, std::size_t(cut));
      }, [&] {
        second_status = parse_obj_lines(second, second_soup, second_state, filename, second_message, std::size_t(-1), false);
      });
      if(first_status == SUCCESS && second_status == SUCCESS) {
        append_part(first_soup, first_state, second_soup, second_state);
        soup = std::move(first_soup);
        if(in_halves != nullptr) *in_halves = true;
        return finish_obj(soup, first_state, filename, message);
      }
    }
    is.clear();
    is.seekg(0);
  }
  return parse_obj(is, soup, filename, message);
}

// rep[i]: the file vertex that vertex i of `points` becomes: itself, or with `weld` the first vertex of the
// file with bit-identical coordinates (0.0 and -0.0 differ). Returns how many vertices were merged into an earlier one.
// The first occurrences are found with an open-addressing hash table of vertex indices (linear probing,
// at most half full), which compares the coordinates' bits: no node per vertex, as std::unordered_map has.
inline std::size_t weld_representatives(const std::vector<std::array<double, 3> >& points, bool weld,
                                        std::vector<std::size_t>& rep)
{
  const std::size_t nv = points.size();
  rep.resize(nv);
  std::size_t welded = 0;
  if(!weld) {
    for(std::size_t i = 0; i < nv; ++i) rep[i] = i;
    return 0;
  }
  std::size_t slots = 16;
  while(slots < 2 * nv) slots *= 2;
  const std::size_t empty = std::size_t(-1);
  std::vector<std::size_t> table(slots, empty);
  for(std::size_t i = 0; i < nv; ++i) {
    const std::array<double, 3>& x = points[i];
    const std::uint64_t b[3] = {double_bits(x[0]), double_bits(x[1]), double_bits(x[2])};
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for(std::uint64_t c : b) { h ^= c + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2); }
    h ^= h >> 29;
    std::size_t s = std::size_t(h) & (slots - 1);
    for(;; s = (s + 1) & (slots - 1)) {
      const std::size_t j = table[s];
      if(j == empty) { table[s] = i; rep[i] = i; break; }
      const std::array<double, 3>& y = points[j];
      if(double_bits(y[0]) == b[0] && double_bits(y[1]) == b[1] && double_bits(y[2]) == b[2]) { rep[i] = j; ++welded; break; }
    }
  }
  return welded;
}

// How build_mesh() names what it refuses: for a file, the line of a face ("FILE:LINE") and the 1-based numbers of the
// file's vertices; for the matrices (V, F) of the bindings (corner_uv_matrices.h), the rows of F and V (0-based)
struct Soup_naming
{
  std::string where;   // the file's name, or "V, F"
  bool rows = false;   // the matrices
  std::string face(std::size_t line) const { return rows ? "F row " + std::to_string(line) : where + ":" + std::to_string(line); }
  std::string vertex(std::size_t i) const { return rows ? "row " + std::to_string(i) + " of V" : "vertex " + std::to_string(i + 1); }
  std::string edge(std::size_t a, std::size_t b) const
  {
    return rows ? "edge (rows " + std::to_string(a) + ", " + std::to_string(b) + " of V)"
                : "edge (" + std::to_string(a + 1) + ", " + std::to_string(b + 1) + ")";
  }
};

// Soup -> mesh. The faces are first added to Halfedge_arrays (Euler::add_face() step for step, on index
// arrays: internal/mesh/halfedge_arrays.h), which is also the connectivity check; only when every face was accepted and
// every vertex is manifold is `tm` touched, in one pass (add_vertex, add_edge, add_face and the set_*
// functions of MutableFaceGraph), so that a failure leaves `tm` and `uv` untouched, and `tm` gets the
// halfedges, edges and faces, in the same order, that Euler::add_face() face by face would give it.
// With `corners`, (*corners)[f][k] is the halfedge whose target is corner k of soup face f.
template <class TriangleMesh, class VPM, class HalfedgeUVMap>
Status build_mesh(const Obj_soup& soup, bool weld, TriangleMesh& tm, VPM vpm, HalfedgeUVMap uv,
                  const Soup_naming& names, std::string& message,
                  std::vector<std::array<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor, 3> >* corners = nullptr)
{
  typedef boost::graph_traits<TriangleMesh>                  GT;
  typedef typename GT::vertex_descriptor                     vertex_descriptor;
  typedef typename GT::halfedge_descriptor                   halfedge_descriptor;
  typedef typename GT::face_descriptor                       face_descriptor;
  typedef typename boost::property_traits<VPM>::value_type   Point_3;
  typedef typename boost::property_traits<HalfedgeUVMap>::value_type Point_2;

  const std::size_t nv = soup.points.size(), nf = soup.face_v.size();
  // the arrays hold halfedge indices in int (as Surface_mesh does in 32 bits)
  if(nf > std::size_t(300000000)) {
    message = names.where + ": " + std::to_string(nf) + " faces: more than this reader's limit of 300 million";
    return INVALID_INPUT;
  }
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
  std::vector<int> mesh_vertex(nv, -1);   // id[rep[i]] in one lookup
  for(std::size_t i = 0; i < nv; ++i) if(id[rep[i]] != none) mesh_vertex[i] = int(id[rep[i]]);

  auto fail = [&](std::size_t line, const std::string& why) {
    message = names.face(line) + ": " + why;
    return INVALID_INPUT;
  };

  // 3. the connectivity, on index arrays
  Seamless_snapping::internal::Halfedge_arrays a(n_used, nf);
  std::array<int, 3> fv;
  for(std::size_t f = 0; f < nf; ++f) {
    if(f + 2 < nf)
      for(int k = 0; k < 3; ++k) a.prefetch_vertex(mesh_vertex[soup.face_v[f + 2][std::size_t(k)]]);
    for(int k = 0; k < 3; ++k) fv[std::size_t(k)] = mesh_vertex[soup.face_v[f][std::size_t(k)]];
    if(fv[0] == fv[1] || fv[1] == fv[2] || fv[2] == fv[0])
      return fail(soup.face_line[f], std::string("degenerate face: a vertex appears twice") +
                                     (weld ? " (after welding bit-identical vertices)" : ""));
    if(!a.add_face(fv)) {
      for(int k = 0; k < 3; ++k) {
        const int h = a.halfedge(fv[std::size_t(k)], fv[std::size_t((k + 1) % 3)]);
        if(h >= 0 && !a.is_border(h))
          return fail(soup.face_line[f], names.edge(soup.face_v[f][std::size_t(k)], soup.face_v[f][std::size_t((k + 1) % 3)]) +
                      " is already used in the same direction by another face: non-manifold edge or inconsistent "
                      "(non-orientable) orientation");
      }
      return fail(soup.face_line[f], "face cannot be added: non-manifold vertex (a vertex of the face is already "
                                     "surrounded by faces) or non-manifold edge");
    }
  }
  // A vertex where two fans meet is accepted by add_face in two cases (two closed fans, or a "bowtie"): reject it
  const int several_fans = a.first_vertex_with_several_fans();
  if(several_fans >= 0) {
    std::size_t file_index = 0;
    for(std::size_t j = 0; j < nv; ++j) if(rep[j] == j && id[j] == std::size_t(several_fans)) { file_index = j; break; }
    std::size_t f = 0;                                 // the first face at it
    while(f + 1 < nf && mesh_vertex[soup.face_v[f][0]] != several_fans && mesh_vertex[soup.face_v[f][1]] != several_fans &&
          mesh_vertex[soup.face_v[f][2]] != several_fans) ++f;
    message = names.face(soup.face_line[f]) + ": non-manifold " + names.vertex(file_index) +
              " (several fans of faces meet at it, this face in one of them)";
    return INVALID_INPUT;
  }

  // 4. the arrays onto tm: every element in the order Euler::add_face() creates it
  std::vector<vertex_descriptor> vs;
  std::vector<halfedge_descriptor> hs;
  std::vector<face_descriptor> fs;
  Seamless_snapping::internal::copy_to(a, tm, vs, hs, fs);
  for(std::size_t i = 0; i < nv; ++i)
    if(rep[i] == i && id[i] != none) put(vpm, vs[id[i]], Point_3(soup.points[i][0], soup.points[i][1], soup.points[i][2]));
  // corner convention: uv[h] = UV of target(h) in face(h); halfedge k of the triangle (a0, a1, a2)
  // points to a_{k+1}, so corner k is the target of halfedge k + 2 (mod 3), face_halfedge = halfedge 2
  if(corners != nullptr) corners->assign(nf, {});
  for(std::size_t f = 0; f < nf; ++f) {
    int h = a.face_halfedge[f];                       // halfedge 2 of the face: its target is corner 0
    for(int k = 0; k < 3; ++k, h = a.next(h)) {
      const std::array<double, 2>& t = soup.uvs[soup.face_vt[f][std::size_t(k)]];
      put(uv, hs[std::size_t(h)], Point_2(t[0], t[1]));
      if(corners != nullptr) (*corners)[f][std::size_t(k)] = hs[std::size_t(h)];
    }
  }

  message = "read " + std::to_string(soup.face_v.size()) + " faces, " + std::to_string(n_used) + " vertices, " +
            std::to_string(soup.uvs.size()) + " texture coordinates from " + names.where;
  if(weld) message += "; welded " + std::to_string(welded) + " duplicated vertices";
  if(unreferenced != 0) message += "; dropped " + std::to_string(unreferenced) + " vertices used by no face";
  if(soup.skipped_records != 0) message += "; skipped " + std::to_string(soup.skipped_records) + " other records (vn, g, s, ...)";
  return SUCCESS;
}

// ---------------------------------------------------------------------------------------------
// Writing
// ---------------------------------------------------------------------------------------------

// The OBJ text of a mesh with corner UVs, in two steps: prepare() checks the mesh and collects the
// records (nothing is written for an invalid mesh), write() emits the text in blocks of about 1 MiB, so
// that the whole file is never held in memory (for 300K faces it is 30 MB, as much as the mesh).
// Layout: one `v` per vertex (order of vertices(tm)); one `vt` per vertex and bit-identical UV among
// its corners, in the order the faces first use them (with vt_per_corner: one per face corner); one
// `f v/vt v/vt v/vt` per face, corners in the order of halfedges_around_face(halfedge(f)).
class Obj_text
{
  std::vector<std::array<double, 3> > points_;
  std::vector<std::array<double, 2> > vts_;
  std::vector<std::array<std::uint32_t, 6> > faces_;   // v0 vt0 v1 vt1 v2 vt2 (0-based)

public:
  template <class TriangleMesh, class VPM, class HalfedgeUVMap>
  Status prepare(const TriangleMesh& tm, VPM vpm, HalfedgeUVMap uv, bool vt_per_corner, std::string& message)
  {
    typedef boost::graph_traits<TriangleMesh>            GT;
    typedef typename GT::vertex_descriptor               vertex_descriptor;
    typedef typename GT::halfedge_descriptor             halfedge_descriptor;
    typedef typename GT::face_descriptor                 face_descriptor;

    if(faces(tm).first == faces(tm).second) { message = "empty mesh: no face to write"; return INVALID_INPUT; }
    if(num_vertices(tm) >= std::size_t(0xFFFFFFFFu) || 3 * std::size_t(num_faces(tm)) >= std::size_t(0xFFFFFFFFu)) {
      message = "more vertices or face corners than this writer's 32-bit indices hold";
      return INVALID_INPUT;
    }

    auto vid = get(CGAL::dynamic_vertex_property_t<std::uint32_t>(), tm);
    std::uint32_t nv = 0;
    for(vertex_descriptor v : vertices(tm)) put(vid, v, nv++);

    points_.clear();
    points_.reserve(nv);
    for(vertex_descriptor v : vertices(tm)) {
      const auto& p = get(vpm, v);
      std::array<double, 3> x = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
      if(!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) {
        message = "vertex " + std::to_string(get(vid, v) + 1) + " has a non-finite coordinate (NaN or Inf)";
        return INVALID_INPUT;
      }
      points_.push_back(x);
    }

    // One vt per (vertex, bit-identical UV): corners of one vertex with the same UV share it, as
    // inside a chart; a seam (different UV) or another vertex gets its own. With `vt_per_corner`, one
    // vt per face corner (libQEx's layout). The vt of a vertex form a list: first_vt[v], then next_vt[t].
    const std::uint32_t none = 0xFFFFFFFFu;
    std::vector<std::uint32_t> first_vt(vt_per_corner ? 0 : nv, none), next_vt;
    vts_.clear();
    faces_.clear();
    faces_.reserve(num_faces(tm));
    std::size_t fi = 0;
    for(face_descriptor f : faces(tm)) {
      std::array<std::uint32_t, 6> row;
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
        const std::uint32_t v = get(vid, target(h, tm));
        std::uint32_t t_id = none;
        if(!vt_per_corner)
          for(std::uint32_t c = first_vt[v]; c != none; c = next_vt[c])
            if(double_bits(vts_[c][0]) == double_bits(u) && double_bits(vts_[c][1]) == double_bits(w)) { t_id = c; break; }
        if(t_id == none) {
          t_id = std::uint32_t(vts_.size());
          vts_.push_back({u, w});
          if(!vt_per_corner) { next_vt.push_back(first_vt[v]); first_vt[v] = t_id; }
        }
        row[std::size_t(2 * k)] = v; row[std::size_t(2 * k + 1)] = t_id;
        ++k;
      }
      if(k != 3) {
        message = "face " + std::to_string(fi + 1) + " is not a triangle; only triangle meshes are written";
        return INVALID_INPUT;
      }
      faces_.push_back(row);
      ++fi;
    }
    message = "wrote " + std::to_string(faces_.size()) + " faces, " + std::to_string(points_.size()) + " vertices, " +
              std::to_string(vts_.size()) + " texture coordinates";
    return SUCCESS;
  }

  // Emits the text of the prepared mesh: flush(data, size) per block, in order; false as soon as flush() fails.
  // With `threads` >= 2 a second thread formats every other block while this one formats the others and
  // flushes them all in order (the text is the same; if the thread cannot be started, one thread does it all).
  template <class Flush>
  bool write(const Flush& flush, unsigned threads = 1) const
  {
    const std::string header =
      "# OBJ with per-corner texture coordinates (CGAL Seamless_snapping): f v/vt, vt = UV of the corner,\n"
      "# numbers read back to the same doubles, bit for bit. " + std::to_string(points_.size()) + " vertices, " +
      std::to_string(vts_.size()) + " texture coordinates, " + std::to_string(faces_.size()) + " faces\n";
    if(!flush(header.data(), header.size())) return false;
    const std::size_t n_blocks = (number_of_lines() + block_lines - 1) / block_lines;
    if(threads >= 2 && n_blocks >= 4) {
      Block_pipeline pipeline(*this, n_blocks);
      if(pipeline.start()) return pipeline.run(flush);
    }
    std::vector<char> buffer(block_bytes);
    for(std::size_t b = 0; b < n_blocks; ++b)
      if(!flush(buffer.data(), std::size_t(format_block(b, buffer.data()) - buffer.data()))) return false;
    return true;
  }

private:
  // blocks of block_lines lines; a line has at most 1 + 3 (1 + 24) + 1 characters (to_chars: at most 24 per double)
  static constexpr std::size_t block_lines = 8192, block_bytes = block_lines * 80;

  std::size_t number_of_lines() const { return points_.size() + vts_.size() + faces_.size(); }

  // the text of block b (points, then vts, then faces) at p; returns the end
  char* format_block(std::size_t b, char* p) const
  {
    const std::size_t np = points_.size(), nt = vts_.size();
    const std::size_t end = (std::min)((b + 1) * block_lines, number_of_lines());
    std::size_t i = b * block_lines;
    for(; i < end && i < np; ++i) {
      *p++ = 'v';
      for(double c : points_[i]) { *p++ = ' '; p = write_double(p, c); }
      *p++ = '\n';
    }
    for(; i < end && i < np + nt; ++i) {
      *p++ = 'v'; *p++ = 't';
      for(double c : vts_[i - np]) { *p++ = ' '; p = write_double(p, c); }
      *p++ = '\n';
    }
    for(; i < end; ++i) {
      const std::array<std::uint32_t, 6>& r = faces_[i - np - nt];
      *p++ = 'f';
      for(int k = 0; k < 3; ++k) {
        *p++ = ' '; p = write_index(p, std::uint64_t(r[std::size_t(2 * k)]) + 1);
        *p++ = '/'; p = write_index(p, std::uint64_t(r[std::size_t(2 * k + 1)]) + 1);
      }
      *p++ = '\n';
    }
    return p;
  }

  // write() with a second thread: it formats the odd blocks into two slots (one block ahead), the caller's
  // thread the even ones, and flushes every block in order.
  class Block_pipeline
  {
    struct Slot { std::vector<char> text; std::size_t size = 0; bool full = false; };
    const Obj_text& text_;
    const std::size_t n_blocks_;
    Slot slots_[2];                       // the second thread's blocks
    std::vector<char> own_;               // the calling thread's block (allocated before the thread starts)
    bool stop_ = false;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::thread helper_;

    void format_odd_blocks()
    {
      for(std::size_t b = 1; b < n_blocks_; b += 2) {
        Slot& slot = slots_[(b / 2) % 2];
        {
          std::unique_lock<std::mutex> lock(mutex_);
          changed_.wait(lock, [&] { return stop_ || !slot.full; });
          if(stop_) return;
        }
        const std::size_t size = std::size_t(text_.format_block(b, slot.text.data()) - slot.text.data());
        std::lock_guard<std::mutex> lock(mutex_);
        slot.size = size;
        slot.full = true;
        changed_.notify_all();
      }
    }
    void stop()
    {
      { std::lock_guard<std::mutex> lock(mutex_); stop_ = true; }
      changed_.notify_all();
      helper_.join();
    }

  public:
    Block_pipeline(const Obj_text& text, std::size_t n_blocks) : text_(text), n_blocks_(n_blocks)
    {
      for(Slot& s : slots_) s.text.resize(block_bytes);
      own_.resize(block_bytes);
    }
    bool start()
    {
      try { helper_ = std::thread([this] { format_odd_blocks(); }); }
      catch(const std::system_error&) { return false; }
      return true;
    }
    template <class Flush>
    bool run(const Flush& flush)
    {
      bool ok = true;
      try {
        for(std::size_t b = 0; b < n_blocks_ && ok; ++b) {
          if(b % 2 == 0) { ok = flush(own_.data(), std::size_t(text_.format_block(b, own_.data()) - own_.data())); continue; }
          Slot& slot = slots_[(b / 2) % 2];
          {
            std::unique_lock<std::mutex> lock(mutex_);
            changed_.wait(lock, [&] { return slot.full; });
          }
          ok = flush(slot.text.data(), slot.size);
          { std::lock_guard<std::mutex> lock(mutex_); slot.full = false; }
          changed_.notify_all();
        }
      } catch(...) { stop(); throw; }
      stop();
      return ok;
    }
  };
};

// A name for a temporary file next to `filename` (same directory, so std::rename is atomic). Where the name would
// exceed 255 bytes (NAME_MAX of common file systems) with the suffix, a short name is used: a name of 238 to 255
// bytes was refused ("File name too long").
inline std::string temporary_name_next_to(const std::string& filename)
{
  static std::atomic<unsigned> counter(0);
  std::random_device rd;
  const unsigned long long r = (static_cast<unsigned long long>(rd()) << 20) ^
      static_cast<unsigned long long>(std::chrono::steady_clock::now().time_since_epoch().count()) ^ (counter++);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%012llx", r & 0xFFFFFFFFFFFFull);
  const std::filesystem::path p(filename);
  if(p.filename().string().size() + 17 <= 255) return filename + ".tmp-" + buf;
  return (p.parent_path() / (std::string(".tmp-") + buf)).string();
}

// One step along a chain of symbolic links: `p` becomes the target of the link `p` (a relative target read from the
// link's directory); false, `p` unchanged, where `p` is no link or cannot be read
inline bool follow_link(std::filesystem::path& p)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if(!fs::is_symlink(fs::symlink_status(p, ec))) return false;
  const fs::path t = fs::read_symlink(p, ec);
  if(ec) return false;
  p = t.is_absolute() ? t : p.parent_path() / t;
  return true;
}

// The descriptor that `filename` names (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N), else -1: a file the
// caller opened (the shell's `> log` or `>> log`), which is written where it stands, never truncated or replaced (the
// name leads to the regular file log, which a rename replaced: `>> log` lost its earlier lines). Also through symbolic
// links to such a name and with repeated slashes (//dev/stdout); a name that leads to a regular file is that file,
// however it is spelt (a link to the file stdout was redirected to is replaced as the file's own name would be).
inline int descriptor_named(const std::string& filename)
{
  std::error_code ec;                                          // this process's id, where there is a /proc
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self", ec);
  const std::string own_fd = ec ? std::string("/proc/self/fd/") : "/proc/" + self.string() + "/fd/";
  std::filesystem::path name = filename;
  for(int links = 0; links <= 40; ++links) {                   // 40: Linux's limit of links
    std::string q;                                             // repeated slashes as one
    for(char c : name.string()) if(!(c == '/' && !q.empty() && q.back() == '/')) q += c;
    if(q == "/dev/stdout") return 1;
    if(q == "/dev/stderr") return 2;
    for(const std::string& prefix : {std::string("/dev/fd/"), std::string("/proc/self/fd/"), own_fd}) {
      int fd = -1;
      const char* const end = q.data() + q.size();
      if(q.size() > prefix.size() && q.compare(0, prefix.size(), prefix) == 0) {
        const std::from_chars_result r = std::from_chars(q.data() + prefix.size(), end, fd);
        if(r.ec == std::errc() && r.ptr == end && fd >= 0) return fd;
      }
    }
    name = q;
    if(!follow_link(name)) return -1;
  }
  return -1;
}

// `filename` with the symbolic links of its last component followed, also a dangling one (whose target is then
// created, as the manual says: links are followed)
inline std::string link_target(const std::string& filename)
{
  std::filesystem::path p(filename);
  for(int i = 0; i < 40 && follow_link(p); ++i) {}              // 40: Linux's limit of links
  return p.string();
}

// write(os), then the stream flushed; false if any of it failed
template <class Write>
bool write_and_flush(std::ostream& os, const Write& write)
{
  bool ok = static_cast<bool>(os) && write(os);
  os.flush();
  return ok && static_cast<bool>(os);
}

// write_and_flush(), then the file closed
template <class Write>
bool write_and_close(std::ofstream& os, const Write& write)
{
  const bool ok = write_and_flush(os, write);
  os.close();
  return ok && !os.fail();
}

// Whether write_atomically() can create `filename`: its directory exists and it is not a directory itself (a check
// before other files are written, so that a failure leaves none of them behind); else false with `message`.
inline bool can_create(const std::string& filename, std::string& message)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(filename);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if(fs::is_directory(fs::status(filename, ec))) message = "cannot write '" + filename + "': it is a directory";
  else if(!fs::is_directory(fs::status(dir, ec))) message = "cannot write '" + filename + "': no directory '" + dir.string() + "'";
  else return true;
  return false;
}

// Whether the input `filename` can be read a second time, for `why` (the command-line programs read a cut mesh as it
// is, then welded; --keep-layout reads it again as matrices): a regular file can; a pipe, a FIFO or a terminal
// (/dev/stdin of `cat a.obj | ...`) gives its text once (read again, it read as empty or waited for a writer): false
// with `message`.
inline bool can_read_again(const std::string& filename, const std::string& why, std::string& message)
{
  std::error_code ec;
  if(std::filesystem::is_regular_file(std::filesystem::status(filename, ec))) return true;
  message = "'" + filename + "' is not a regular file (a pipe?) and can be read once only, but " + why +
            " reads it a second time; save it to a file first";
  return false;
}

// The reader `read(weld, message)` that read_welding_cut_meshes() calls for the input `filename`, refused from its second
// call on (the welded read after the read as it is) where the input can be read once only (can_read_again(): the three
// command-line programs)
template <class Read>
struct Read_again_checked
{
  const std::string& filename;
  Read read;
  mutable int calls = 0;

  bool operator()(bool weld, std::string& message) const
  {
    if(calls++ > 0 && !can_read_again(filename, "welding the cut mesh", message)) return false;
    return read(weld, message);
  }
};

template <class Read>
Read_again_checked<Read> read_again_checked(const std::string& filename, const Read& read) { return {filename, read}; }

// A file written as write_atomically() writes it, in two steps, so that a program writing several files can replace
// them together: prepare() writes the content into a temporary file next to the file, commit() renames it over the
// file; a temporary file not committed is removed (destructor). A regular file keeps its permission bits, and a
// symbolic link is followed (also a dangling one: its target is created). What is not a regular file (a device such
// as /dev/null, a named pipe) would be replaced by a regular file by a rename (as root: /dev/null itself), so
// prepare() writes it directly, not atomically, without truncating it; a name of an open descriptor (descriptor_named():
// /dev/stdout, ...) too, through std::cout and std::cerr for 1 and 2. A directory is refused.
class Atomic_file
{
public:
  Atomic_file() = default;
  Atomic_file(const Atomic_file&) = delete;
  Atomic_file& operator=(const Atomic_file&) = delete;
  ~Atomic_file() { if(!tmp_.empty()) std::remove(tmp_.c_str()); }

  // `write(os)` writes the content to the stream and returns false if it could not; on failure nothing is left behind
  template <class Write>
  Status prepare(const std::string& filename, const Write& write, std::string& message)
  {
    namespace fs = std::filesystem;
    filename_ = filename;
    std::error_code ec;
    const int fd = descriptor_named(filename);
    if(fd == 1 || fd == 2) {
      std::ostream& os = fd == 1 ? std::cout : std::cerr;
      const std::streamsize precision = os.precision();
      const std::ios::fmtflags flags = os.flags();
      const bool ok = write_and_flush(os, write);
      os.precision(precision);                  // the writers may set them (stream_precision())
      os.flags(flags);
      if(ok) return SUCCESS;
      message = "cannot write '" + filename + "'";
      return INVALID_INPUT;
    }
    const fs::file_status target = fs::status(filename, ec);     // follows symbolic links
    if(!ec && fs::is_directory(target)) {
      message = "cannot write '" + filename + "': it is a directory";
      return INVALID_INPUT;
    }
    if(ec && ec != std::errc::no_such_file_or_directory) {        // a loop of links (another link of it was replaced)
      message = "cannot write '" + filename + "': " + ec.message();
      return INVALID_INPUT;
    }
    if(fd >= 0 || (!ec && fs::exists(target) && !fs::is_regular_file(target))) {
      std::ofstream os(filename, std::ios::binary | std::ios::app);
      if(write_and_close(os, write)) return SUCCESS;
      message = "cannot write '" + filename + "' (" + std::strerror(errno) + ")";
      return INVALID_INPUT;
    }
    path_ = link_target(filename);
    const std::string tmp = temporary_name_next_to(path_);
    std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
    if(!os) {
      message = "cannot write '" + filename + "': cannot create the temporary file '" + tmp + "' (" +
                std::strerror(errno) + ")";
      return INVALID_INPUT;
    }
    tmp_ = tmp;
    if(fs::is_regular_file(target)) {          // a 0600 file became 0644
      fs::permissions(tmp_, target.permissions(), ec);
    }
    if(!write_and_close(os, write)) {
      message = "cannot write '" + filename + "': writing the temporary file '" + tmp + "' failed (disk full?)";
      return INVALID_INPUT;
    }
    return SUCCESS;
  }

  // the prepared file renamed over `filename` (nothing to do where it was written directly)
  Status commit(std::string& message)
  {
    if(tmp_.empty()) return SUCCESS;
    if(std::rename(tmp_.c_str(), path_.c_str()) != 0) {
      message = "cannot write '" + filename_ + "': renaming the temporary file failed (" + std::strerror(errno) + ")";
      return INVALID_INPUT;
    }
    tmp_.clear();
    return SUCCESS;
  }

private:
  std::string filename_, path_, tmp_;   // the caller's name, the file renamed over, the temporary file (until renamed)
};

// Writes a file through a temporary file next to it and std::rename (atomic on POSIX): `write(os)`
// writes the content to the stream and returns false if it could not; on failure nothing is left
// behind and `filename` is untouched. Atomic_file::prepare() says which files are written directly.
template <class Write>
Status write_atomically(const std::string& filename, const Write& write, std::string& message)
{
  Atomic_file file;
  if(file.prepare(filename, write, message) != SUCCESS) return INVALID_INPUT;
  return file.commit(message);
}

// A path as the command-line programs compare files: made absolute, then as std::filesystem::weakly_canonical() gives
// it (./a and a are one file, also where a does not exist yet)
inline std::string comparable_path(const std::string& path)
{
  // absolute first: weakly_canonical() leaves a relative path whose first component does not exist as it is, so
  // "x" and "./x" differed where x was not written yet
  std::error_code ec;
  std::filesystem::path p = std::filesystem::absolute(path, ec);
  if(ec) p = path;
  const std::filesystem::path c = std::filesystem::weakly_canonical(p, ec);
  return (ec ? p.lexically_normal() : c).string();
}

// The command-line programs' output files, each with the option that names it: where two of them name one file (the
// later write would replace the earlier, and the program would still report both written), a message naming the two,
// else empty. Paths are compared as comparable_path() gives them.
inline std::string same_output_file(const std::vector<std::pair<std::string, std::string> >& outputs)
{
  std::vector<std::string> canonical;
  for(const std::pair<std::string, std::string>& o : outputs) canonical.push_back(comparable_path(o.second));
  for(std::size_t i = 0; i < outputs.size(); ++i)
    for(std::size_t j = 0; j < i; ++j)
      if(!outputs[i].second.empty() && !outputs[j].second.empty() && canonical[i] == canonical[j])
        return outputs[j].first + " and " + outputs[i].first + " name one file, '" + outputs[i].second +
               "': the second would replace the first";
  return std::string();
}

// The `write` of write_atomically() and Atomic_file::prepare() that writes `text` (which must outlive it)
inline auto text_writer(const std::string& text)
{
  return [&text](std::ostream& os) {
    os.write(text.data(), static_cast<std::streamsize>(text.size()));
    return static_cast<bool>(os);
  };
}

// Writes `text` to `filename` atomically (write_atomically()).
inline Status write_text_atomically(const std::string& filename, const std::string& text, std::string& message)
{
  return write_atomically(filename, text_writer(text), message);
}

// the blocks of Obj_text::write() into a stream
struct Stream_flush
{
  std::ostream& os;
  bool operator()(const char* data, std::size_t size) const
  {
    os.write(data, static_cast<std::streamsize>(size));
    return static_cast<bool>(os);
  }
};

// the mesh of a parsed file (build_mesh()) with the vertex_point_map and weld_vertices of `np`
template <class TriangleMesh, class HalfedgeUVMap, class NamedParameters>
Status mesh_of_soup(const Obj_soup& soup, const std::string& where, TriangleMesh& tm, HalfedgeUVMap uv,
                    std::string& message, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::type VPM;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                             get_property_map(CGAL::vertex_point, tm));
  const bool weld = choose_parameter(get_parameter(np, snap_np::weld_vertices), false);
  return build_mesh(soup, weld, tm, vpm, uv, Soup_naming{where, false}, message);
}

template <class TriangleMesh, class HalfedgeUVMap, class NamedParameters>
Status prepare_obj_text(const TriangleMesh& tm, HalfedgeUVMap uv, Obj_text& text, std::string& message,
                        const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                             get_const_property_map(CGAL::vertex_point, tm));
  return text.prepare(tm, vpm, uv, choose_parameter(get_parameter(np, snap_np::vt_per_corner), false), message);
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
 * coordinates, and numbers outside the range of `double` (above 1.8e308 in magnitude, or nonzero and below
 * 4.9e-324, which would read as 0; subnormal numbers are read as they are); a degenerate face (a vertex
 * twice, also after welding); a non-manifold edge or vertex,
 * or an orientation that is inconsistent between neighbouring faces (non-orientable input),
 * as detected by `CGAL::Euler::add_face()`; a file without faces; a line longer than 64 MiB (not a text file, e.g.
 * `/dev/zero`: reading stops there, the memory stays bounded); a file that cannot be opened.
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
 *   \cgalParamNBegin{number_of_threads}
 *     \cgalParamDescription{with 2 or more, a file of 4 MiB or more is parsed in two halves at once, on two threads
 *                           (the same mesh, UVs and messages as on one thread); `0` takes the machine's cores}
 *     \cgalParamType{unsigned integer}
 *     \cgalParamDefault{`1`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::number_of_threads()`}
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
  internal::Obj_soup soup;
  if(internal::parse_obj_file(filename, soup, message, Seamless_snapping::internal::number_of_threads_parameter(np)) != SUCCESS)
    return INVALID_INPUT;
  return internal::mesh_of_soup(soup, filename, tm, uv, message, np);
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
  internal::Obj_soup soup;
  if(internal::parse_obj(is, soup, "stream", message) != SUCCESS) return INVALID_INPUT;
  return internal::mesh_of_soup(soup, "stream", tm, uv, message, np);
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 * writes the triangle mesh `tm` with the per-corner texture coordinates `uv` to the OBJ file
 * `filename`, atomically: the text goes to a temporary file in the same directory, which is
 * then renamed to `filename` (`std::rename()`, atomic on POSIX file systems). On any failure no
 * file is created or changed, and no temporary file is left behind. A symbolic link is followed (its
 * target is replaced); a `filename` that is not a regular file (a device such as `/dev/stdout`, a named
 * pipe) is written directly, not atomically, and stays what it is.
 *
 * The file has one `v` per vertex (in the order of `vertices(tm)`), one `vt` per vertex and
 * distinct (bit-identical) UV among the corners of that vertex (so `vt` are shared inside charts
 * and differ across seams), and one `f v/vt v/vt v/vt` per face, the corners in the order of
 * `halfedges_around_face(halfedge(f, tm), tm)`. Each number is the shortest decimal that reads back
 * to the same double (`std::to_chars`, locale independent), so reading the file back with
 * `read_OBJ_with_corner_uvs()` gives bit-identical positions and UVs. Only the corner UVs (non-border halfedges) are written.
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
 *   \cgalParamNBegin{number_of_threads}
 *     \cgalParamDescription{with 2 or more, a second thread formats every other block of lines while the calling thread
 *                           formats the others and writes them all in order (the same text); `0` takes the machine's cores}
 *     \cgalParamType{unsigned integer}
 *     \cgalParamDefault{`1`}
 *     \cgalParamExtra{pass it with `CGAL::Seamless_snapping::parameters::number_of_threads()`}
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
  internal::Obj_text text;
  if(internal::prepare_obj_text(tm, uv, text, message, np) != SUCCESS) {
    message = "not writing '" + filename + "': " + message;
    return INVALID_INPUT;
  }
  const std::string summary = message;
  const unsigned threads = Seamless_snapping::internal::number_of_threads_parameter(np);
  if(internal::write_atomically(filename, [&](std::ostream& os) { return text.write(internal::Stream_flush{os}, threads); },
                                message) != SUCCESS)
    return INVALID_INPUT;
  message = summary + " to " + filename;
  return SUCCESS;
}

/*!
 * \ingroup PkgSeamlessSnappingRef
 * same as the file overload, writing to the stream `os`. The mesh is checked before the first byte is
 * written, so an invalid mesh writes nothing; a stream error in the middle (returned as `INVALID_INPUT`)
 * may leave a partial text in `os`.
 */
template <class TriangleMesh, class HalfedgeUVMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Status write_OBJ_with_corner_uvs(std::ostream& os, const TriangleMesh& tm, HalfedgeUVMap uv,
                                 std::string& message,
                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::Obj_text text;
  if(internal::prepare_obj_text(tm, uv, text, message, np) != SUCCESS) return INVALID_INPUT;
  const bool ok = text.write(internal::Stream_flush{os}, Seamless_snapping::internal::number_of_threads_parameter(np));
  os.flush();
  if(!ok || !os) {
    message = "stream: write failed";
    return INVALID_INPUT;
  }
  return SUCCESS;
}

} // namespace IO
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_IO_OBJ_H
