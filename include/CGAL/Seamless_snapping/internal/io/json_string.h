// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_JSON_STRING_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_JSON_STRING_H

// A string as a JSON string literal (RFC 8259, Sec. 7): the one escaper of the reports' to_json(), the
// command-line programs and the Python module. Quotes, backslashes and every control character below
// 0x20 are escaped (messages name the user's files, which may hold any of them); UTF-8 stays UTF-8, and a
// byte that is not part of a valid UTF-8 sequence (a Latin-1 file name or token) becomes the character of its code,
// U+0080..U+00FF (utf8_text()): the JSON stays valid (such bytes made the reports unreadable).

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

namespace CGAL {
namespace Seamless_snapping {
namespace IO {
namespace internal {

// the length of the valid UTF-8 sequence at p (n bytes left), or 0 (RFC 3629, Sec. 4: no overlong forms, no
// surrogates, nothing above U+10FFFF)
inline std::size_t utf8_sequence_length(const unsigned char* p, std::size_t n)
{
  const unsigned char c = p[0];
  if(c < 0x80) return 1;
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;                    // the range of the second byte
  if(c >= 0xC2 && c <= 0xDF) length = 2;
  else if(c >= 0xE0 && c <= 0xEF) { length = 3; if(c == 0xE0) low = 0xA0; if(c == 0xED) high = 0x9F; }
  else if(c >= 0xF0 && c <= 0xF4) { length = 4; if(c == 0xF0) low = 0x90; if(c == 0xF4) high = 0x8F; }
  else return 0;
  if(n < length || p[1] < low || p[1] > high) return 0;
  for(std::size_t k = 2; k < length; ++k) if(p[k] < 0x80 || p[k] > 0xBF) return 0;
  return length;
}

// `s` as valid UTF-8: its valid sequences kept, every other byte taken as the character of its code (Latin-1)
inline std::string utf8_text(const std::string& s)
{
  std::string o;
  o.reserve(s.size());
  const unsigned char* p = reinterpret_cast<const unsigned char*>(s.data());
  for(std::size_t i = 0; i < s.size();) {
    const std::size_t length = utf8_sequence_length(p + i, s.size() - i);
    if(length > 0) { o.append(s, i, length); i += length; continue; }
    o += static_cast<char>(0xC0 | (p[i] >> 6));
    o += static_cast<char>(0x80 | (p[i] & 0x3F));
    ++i;
  }
  return o;
}

inline std::string json_string(const std::string& s)
{
  std::string o = "\"";
  for(char c : utf8_text(s)) {
    const unsigned char u = static_cast<unsigned char>(c);
    if(c == '"' || c == '\\') { o += '\\'; o += c; }
    else if(c == '\n') o += "\\n";
    else if(c == '\r') o += "\\r";
    else if(c == '\t') o += "\\t";
    else if(u < 0x20) { char b[8]; std::snprintf(b, sizeof b, "\\u%04x", unsigned(u)); o += b; }
    else o += c;
  }
  return o + "\"";
}

// A double as a JSON number (17 significant digits: it reads back to the same double), or null where it is not finite
// (JSON has no NaN or Infinity, RFC 8259, Sec. 6)
inline std::string json_number(double x)
{
  if(!std::isfinite(x)) return "null";
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

} // namespace internal
} // namespace IO
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_JSON_STRING_H
