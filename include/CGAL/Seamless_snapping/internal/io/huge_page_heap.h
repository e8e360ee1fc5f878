// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_HUGE_PAGE_HEAP_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_HUGE_PAGE_HEAP_H

// For the command-line programs and benchmarks only (the library never changes its caller's process):
// the heap of a program that snaps a large map in transparent huge pages.
//
// Reading a map, building its mesh, corner mesh, sectors and reduced system touches a few hundred MB at
// random places; with 4 KiB pages nearly every such access also misses the TLB, and the kernel spends a
// quarter of the run zeroing and mapping fresh pages (seamless_snap on a 302K-face map: 0.42 s of 1.72 s in
// the kernel, 58,000 page faults; with huge pages 0.25 s, about 1,000). glibc can put its heap in transparent huge pages (glibc.malloc.hugetlb=1, glibc >= 2.35, where
// THP is "always" or "madvise"), and keep freed blocks for reuse instead of unmapping and faulting them in
// again (glibc.malloc.mmap_threshold / trim_threshold), but it reads these tunables only when a process
// starts. So use_huge_page_heap(argv), first thing in main(), runs the program again (execv of
// /proc/self/exe, same arguments) with them prepended to GLIBC_TUNABLES (the caller's own tunables come
// after them and win) and SEAMLESS_SNAPPING_HEAP=huge-pages set, which also stops it from doing so twice.
// Setting SEAMLESS_SNAPPING_HEAP to anything beforehand keeps the default heap; so does any failure of
// execv (the program then just goes on). Results do not depend on it: the same output bits either way.
// Without glibc on Linux, and under AddressSanitizer (its own allocator), it does nothing.

#include <cstdlib>
#include <string>

#if defined(__linux__) && defined(__GLIBC__)
#  include <unistd.h>
#  define CGAL_SEAMLESS_SNAPPING_HUGE_PAGE_HEAP 1
#endif
#if defined(__SANITIZE_ADDRESS__)
#  undef CGAL_SEAMLESS_SNAPPING_HUGE_PAGE_HEAP
#elif defined(__has_feature)
#  if __has_feature(address_sanitizer)
#    undef CGAL_SEAMLESS_SNAPPING_HUGE_PAGE_HEAP
#  endif
#endif

namespace CGAL {
namespace Seamless_snapping {
namespace IO {
namespace internal {

constexpr const char* huge_page_heap_variable = "SEAMLESS_SNAPPING_HEAP";
constexpr const char* huge_page_heap_tunables =
    "glibc.malloc.hugetlb=1:glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=1073741824";

// Returns only if the program goes on with the heap it has (see above).
inline void use_huge_page_heap(char** argv)
{
#if defined(CGAL_SEAMLESS_SNAPPING_HUGE_PAGE_HEAP)
  if(std::getenv(huge_page_heap_variable) != nullptr) return;
  const char* old = std::getenv("GLIBC_TUNABLES");
  const std::string kept = old == nullptr ? std::string() : std::string(old);
  const std::string tunables = std::string(huge_page_heap_tunables) + (old == nullptr ? "" : ":" + kept);
  if(::setenv(huge_page_heap_variable, "huge-pages", 1) != 0) return;
  if(::setenv("GLIBC_TUNABLES", tunables.c_str(), 1) == 0) ::execv("/proc/self/exe", argv);
  // execv failed: the environment as it was, except the variable that says this was tried
  if(old == nullptr) ::unsetenv("GLIBC_TUNABLES");
  else ::setenv("GLIBC_TUNABLES", kept.c_str(), 1);
#else
  (void)argv;
#endif
}

} // namespace internal
} // namespace IO
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_HUGE_PAGE_HEAP_H
