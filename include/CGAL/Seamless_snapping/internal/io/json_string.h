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
// 0x20 are escaped (messages name the user's files, which may hold any of them); other bytes are kept
// as they are (UTF-8 stays UTF-8).

#include <cmath>
#include <cstdio>
#include <string>

namespace CGAL {
namespace Seamless_snapping {
namespace IO {
namespace internal {

inline std::string json_string(const std::string& s)
{
  std::string o = "\"";
  for(char c : s) {
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
