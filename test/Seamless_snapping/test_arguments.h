// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// The command line of the tests (--sanitizer-subset). Not part of the package API.

#ifndef CGAL_SEAMLESS_SNAPPING_TEST_TEST_ARGUMENTS_H
#define CGAL_SEAMLESS_SNAPPING_TEST_TEST_ARGUMENTS_H

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>

// The sanitizer build (SEAMLESS_SNAPPING_SANITIZE) runs test_io, test_snap and test_constraints
// with the argument --sanitizer-subset: the loops over the shared data take only its files up to
// 600 kB (shared_data_file_in_subset()), and main() leaves out the slowest groups (ASan + UBSan make
// the code several times slower).
static inline bool& sanitizer_subset()
{
  static bool on = false;
  return on;
}

// reads the command line of a test: nothing, or --sanitizer-subset; exits on anything else
static inline void parse_test_arguments(int argc, char** argv)
{
  for(int i = 1; i < argc; ++i) {
    if(std::strcmp(argv[i], "--sanitizer-subset") == 0) sanitizer_subset() = true;
    else { std::cerr << "usage: " << argv[0] << " [--sanitizer-subset]" << std::endl; std::exit(EXIT_FAILURE); }
  }
  if(sanitizer_subset()) std::cout << "sanitizer subset: shared data files up to 600 kB, slowest groups left out\n";
}

// whether a shared data file of `bytes` bytes is used (all of them, except under --sanitizer-subset)
static inline bool shared_data_file_in_subset(std::uintmax_t bytes)
{
  return !sanitizer_subset() || bytes <= 600 * 1000;
}

#endif // CGAL_SEAMLESS_SNAPPING_TEST_TEST_ARGUMENTS_H
