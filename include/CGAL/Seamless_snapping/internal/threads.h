// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_THREADS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_THREADS_H

// Two independent steps on two threads (the named parameter number_of_threads, default 1: the caller's
// thread only). The steps must share nothing that either writes: then the results are those of running
// them one after the other, bit for bit, whatever the number of threads. Plain std::thread (C++11; glibc
// 2.34 and later need no -pthread, older systems link Threads::Threads, which the package's CMake target
// does).

#include <CGAL/Seamless_snapping/internal/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <exception>
#include <system_error>
#include <thread>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

// the number_of_threads parameter: 0 means the machine's cores (std::thread::hardware_concurrency(), 1 if unknown)
inline unsigned resolve_number_of_threads(unsigned requested)
{
  if(requested != 0) return requested;
  const unsigned cores = std::thread::hardware_concurrency();
  return cores == 0 ? 1u : cores;
}

// the number_of_threads named parameter of `np`, resolved (`default_threads` where it is not given)
template <class NamedParameters>
unsigned number_of_threads_parameter(const NamedParameters& np, unsigned default_threads = 1)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return resolve_number_of_threads(choose_parameter(get_parameter(np, snap_np::number_of_threads), default_threads));
}

// a() on the calling thread and b() on a second thread when `threads` >= 2, else (or when no thread can be
// started) a() then b() on the calling thread; returns when both are done. An exception of a() or b() is
// rethrown after both are done (a()'s first).
template <class A, class B>
void run_concurrently(unsigned threads, A&& a, B&& b)
{
  if(threads < 2) { a(); b(); return; }
  std::exception_ptr thrown_b;
  std::thread second;
  try {
    second = std::thread([&b, &thrown_b] {
      try { b(); } catch(...) { thrown_b = std::current_exception(); }
    });
  } catch(const std::system_error&) {
    a(); b(); return;
  }
  std::exception_ptr thrown_a;
  try { a(); } catch(...) { thrown_a = std::current_exception(); }
  second.join();
  if(thrown_a) std::rethrow_exception(thrown_a);
  if(thrown_b) std::rethrow_exception(thrown_b);
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_THREADS_H
