// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// The command line of the tests (--sanitizer-subset) and the floating-point environment they report and, for
// CTest's other_rounding__* runs, change. Not part of the package API.

#ifndef CGAL_SEAMLESS_SNAPPING_TEST_TEST_ARGUMENTS_H
#define CGAL_SEAMLESS_SNAPPING_TEST_TEST_ARGUMENTS_H

#include <Eigen/Core>

#include <cmath>
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

// The tests compute floating-point inputs at run time whose last bits depend on the machine, not only on the code:
//  - CGAL's Orbifold Tutte maps (Eigen::SparseLU): its supernodal kernels call Eigen's dense matrix product, which
//    splits the inner dimension of a sum into blocks sized from the L1 data cache that CPUID reports (Eigen 3.4,
//    double: at most 504 terms for 32 KiB, 720 for 48 KiB), so long sums are rounded in another order on another CPU.
//    On CGAL's bear every UV differs in its last bits between 32 KiB (AMD Zen 2-4, older Intel) and 48 KiB (Intel
//    since Ice Lake); neither is wrong.
//  - glibc's libm picks FMA/AVX2 variants of sin, cos, tan, atan, atan2, exp, log, pow, ... at run time when the CPU
//    has FMA and AVX2; they round up to 1 result in 1000 (glibc 2.36: sin, exp, pow; atan2 1 in 4000) to the other
//    neighbour of the exact value (sqrt, hypot and cbrt have no such variant). The package uses atan2 and hypot only for decisions far from their thresholds
//    (quarter turns of angle sums and transitions, the alignment tolerance).
// So no test compares such a result with stored bits, and CTest runs the tests that compute them a second time,
// as other_rounding__<test> (test/Seamless_snapping/CMakeLists.txt), the way another machine rounds them:
// SS_TEST_OTHER_ROUNDING=1 sets Eigen's blocking for the other L1 size (48 KiB, or 32 KiB on a CPU with 48 KiB), and
// GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA (glibc >= 2.33 names; glibc 2.26-2.32 called them AVX2_Usable and
// FMA_Usable, and ignores names it does not know, silently) selects libm's variants without FMA on a CPU that has it.

// a hash of the bits of sin, exp and atan2 on 8192 fixed arguments: differs between libm's FMA and SSE2 variants
static inline std::uint64_t libm_fingerprint()
{
  std::uint64_t s = 88172645463325252ull, h = 1469598103934665603ull;
  auto next = [&]() { s ^= s << 13; s ^= s >> 7; s ^= s << 17; return -10 + 20 * double(s >> 11) / 9007199254740992.0; };
  for(int i = 0; i < 8192; ++i) {
    const double a = next(), b = next();
    for(double r : {std::sin(a), std::exp(a), std::atan2(a, b)}) {
      std::uint64_t bits;
      std::memcpy(&bits, &r, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
  }
  return h;
}

// applies SS_TEST_OTHER_ROUNDING=1 (see above) and prints the floating-point environment of the run
static inline void set_up_floating_point()
{
  const std::ptrdiff_t l1 = Eigen::l1CacheSize();
  const char* other = std::getenv("SS_TEST_OTHER_ROUNDING");
  const bool switched = other != nullptr && std::strcmp(other, "1") == 0;
  if(switched) Eigen::setCpuCacheSizes(l1 == 48 * 1024 ? 32 * 1024 : 48 * 1024, Eigen::l2CacheSize(), Eigen::l3CacheSize());
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::cout << "floating point: " << (switched ? "OTHER ROUNDING: " : "") << "Eigen's product blocking for an L1 data cache of "
            << Eigen::l1CacheSize() / 1024 << " KiB (this CPU: " << l1 / 1024 << " KiB), GLIBC_TUNABLES="
            << (tunables != nullptr ? tunables : "(unset)") << ", libm fingerprint " << std::hex << libm_fingerprint()
            << std::dec << "\n";
}

// reads the command line of a test: nothing, or --sanitizer-subset; exits on anything else. Then
// set_up_floating_point().
static inline void parse_test_arguments(int argc, char** argv)
{
  for(int i = 1; i < argc; ++i) {
    if(std::strcmp(argv[i], "--sanitizer-subset") == 0) sanitizer_subset() = true;
    else { std::cerr << "usage: " << argv[0] << " [--sanitizer-subset]" << std::endl; std::exit(EXIT_FAILURE); }
  }
  if(sanitizer_subset()) std::cout << "sanitizer subset: shared data files up to 600 kB, slowest groups left out\n";
  set_up_floating_point();
}

// whether a shared data file of `bytes` bytes is used (all of them, except under --sanitizer-subset)
static inline bool shared_data_file_in_subset(std::uintmax_t bytes)
{
  return !sanitizer_subset() || bytes <= 600 * 1000;
}

#endif // CGAL_SEAMLESS_SNAPPING_TEST_TEST_ARGUMENTS_H
