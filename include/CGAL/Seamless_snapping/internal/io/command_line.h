// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_COMMAND_LINE_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_COMMAND_LINE_H

// The option values of the command-line programs (seamless_snap, seamless_quad, seamless_trace): each parsed whole (nothing may
// follow the number) and checked against its range, so that a bad value is refused with exit status 2 instead of
// being read as a prefix or wrapped.

#include <CGAL/Seamless_snapping/internal/surface/integer_grid_constraints.h>

#include <cstdlib>

namespace CGAL {
namespace Seamless_snapping {
namespace IO {
namespace internal {

// `text` as a whole number (std::strtod: decimal or hexadecimal; "inf" and "nan" read as such, for the caller's
// range check to refuse)
inline bool parse_number(const char* text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text, &end);
  return end != text && *end == '\0';
}

// `text` as a whole decimal count in [0, largest]: digits only (std::strtoull alone would skip white space and
// wrap " -1" around to ULLONG_MAX; an overflow reads as ULLONG_MAX, above any `largest` the programs pass)
inline bool parse_count(const char* text, unsigned long long largest, unsigned long long& n)
{
  if(!(text[0] >= '0' && text[0] <= '9')) return false;
  char* end = nullptr;
  n = std::strtoull(text, &end, 10);
  return *end == '\0' && n <= largest;
}

// `text` as a grid scale: a power of two (Seamless_snapping::internal::grid_scale_exponent(): a non-dyadic scale
// cannot be applied exactly)
inline bool parse_grid_scale(const char* text, double& scale)
{
  int exponent = 0;
  return parse_number(text, scale) && Seamless_snapping::internal::grid_scale_exponent(scale, exponent);
}

// Whether argv[i], an option that takes a file name, is followed by one: not empty (an empty name wrote nothing and
// exited 0) and not an option (`--json --svg` wrote the JSON into a file named "--svg"); ./-x names such a file
inline bool file_name_follows(int argc, char** argv, int i)
{
  return i + 1 < argc && argv[i + 1][0] != '\0' && argv[i + 1][0] != '-';
}

} // namespace internal
} // namespace IO
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_COMMAND_LINE_H
