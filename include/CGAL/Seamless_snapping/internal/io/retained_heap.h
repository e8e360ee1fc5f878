// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_RETAINED_HEAP_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_RETAINED_HEAP_H

// For the command-line programs and benchmarks only (the library never changes its caller's process):
// a heap that keeps the memory it frees for reuse.
//
// Snapping a large map allocates and frees arrays of several MB phase after phase (the OBJ text's records,
// the mesh, the corner mesh, the sectors, the systems). glibc's defaults give every block above 128 KiB (the
// threshold then adapts, up to 32 MiB) its own mapping and return freed memory at the top of the heap to the
// kernel, so the next phase faults fresh pages in again, each zeroed by the kernel; on a virtual machine whose
// free memory goes back to the host, that zeroing is slow. glibc keeps freed blocks for reuse with the
// tunables glibc.malloc.mmap_threshold / trim_threshold, and arena_max=1 makes the second thread of
// number_of_threads allocate from the same heap instead of an arena of its own, whose freed memory the first
// thread would not reuse (seamless_snap --threads 2 on the bunny below: peak RSS 184 -> 160 MB, the same time).
// glibc reads these tunables only when a process starts. So
// use_retained_heap(argv), first thing in main(), runs the program again (execv of /proc/self/exe, same
// arguments) with them prepended to GLIBC_TUNABLES (the caller's own tunables come after them and win) and
// SEAMLESS_SNAPPING_HEAP=retained set, which also stops it from doing so twice. Setting SEAMLESS_SNAPPING_HEAP
// to anything beforehand keeps the default heap; so does any failure of execv (the program then just goes on).
// Results do not depend on it: the same output bits either way. Without glibc on Linux, and under
// AddressSanitizer (its own allocator), it does nothing.
// Measured (seamless_snap on the 302K-face bunny of ../shared/large, 5 alternating runs each, one session):
// default heap 0.66-0.74 s wall (0.11-0.13 s in the kernel), this heap 0.62-0.66 s (0.08-0.09 s). Transparent
// huge pages for the heap as well (glibc.malloc.hugetlb=1, this program's choice until then: 1.6x faster than
// the default heap in an earlier session) took 0.85-0.93 s (0.30-0.35 s in the kernel) on the same machine:
// zeroing 2 MiB pages that the host has to supply afresh. Users for whom huge pages pay can add that tunable.

#include <cstdlib>
#include <string>

#if defined(__linux__) && defined(__GLIBC__)
#  include <unistd.h>
#  define CGAL_SEAMLESS_SNAPPING_RETAINED_HEAP 1
#endif
#if defined(__SANITIZE_ADDRESS__)
#  undef CGAL_SEAMLESS_SNAPPING_RETAINED_HEAP
#elif defined(__has_feature)
#  if __has_feature(address_sanitizer)
#    undef CGAL_SEAMLESS_SNAPPING_RETAINED_HEAP
#  endif
#endif

namespace CGAL {
namespace Seamless_snapping {
namespace IO {
namespace internal {

constexpr const char* retained_heap_variable = "SEAMLESS_SNAPPING_HEAP";
constexpr const char* retained_heap_tunables =
    "glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=1073741824:glibc.malloc.arena_max=1";

// Returns only if the program goes on with the heap it has (see above).
inline void use_retained_heap(char** argv)
{
#if defined(CGAL_SEAMLESS_SNAPPING_RETAINED_HEAP)
  if(std::getenv(retained_heap_variable) != nullptr) return;
  const char* old = std::getenv("GLIBC_TUNABLES");
  const std::string kept = old == nullptr ? std::string() : std::string(old);
  const std::string tunables = std::string(retained_heap_tunables) + (old == nullptr ? "" : ":" + kept);
  if(::setenv(retained_heap_variable, "retained", 1) != 0) return;
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

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_IO_RETAINED_HEAP_H
