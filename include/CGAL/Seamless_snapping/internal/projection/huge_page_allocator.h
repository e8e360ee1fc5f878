// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_HUGE_PAGE_ALLOCATOR_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_HUGE_PAGE_ALLOCATOR_H

// A standard allocator for the elimination's large arrays (row and column records, occurrence
// pool, arena). On large seamless systems the elimination reads these at random places, and with
// 4 KiB pages nearly every such read also misses the TLB. On Linux, blocks of at least
// `huge_page_threshold` bytes are fresh anonymous mappings aligned to 2 MiB and marked
// MADV_HUGEPAGE, so that the kernel may back them with transparent huge pages when they are first
// touched (where THP is "always" or "madvise"; elsewhere the hint is ignored). Fresh mappings
// matter: heap memory that was already touched keeps its 4 KiB pages. Smaller blocks, and other
// systems, use std::allocator. This is only a hint: the results do not depend on it.

#include <cstddef>
#include <memory>
#include <new>

#if defined(__linux__)
#  include <sys/mman.h>
#  include <cstdint>
#endif

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

template <typename T>
struct Huge_page_allocator
{
  typedef T value_type;
  static constexpr std::size_t huge_page = std::size_t(1) << 21;            // 2 MiB
  static constexpr std::size_t huge_page_threshold = std::size_t(1) << 22;  // 4 MiB

  Huge_page_allocator() noexcept {}
  template <typename U> Huge_page_allocator(const Huge_page_allocator<U>&) noexcept {}

  T* allocate(std::size_t n)
  {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if(is_large(n)) {
      if(n > (std::size_t(-1) - huge_page) / sizeof(T)) throw std::bad_array_new_length();
      const std::size_t bytes = rounded(n);
      void* q = ::mmap(nullptr, bytes + huge_page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if(q == MAP_FAILED) throw std::bad_alloc();
      char* const base = static_cast<char*>(q);
      char* const p = base + (huge_page - std::uintptr_t(base) % huge_page) % huge_page;   // 2 MiB aligned
      if(p != base) ::munmap(base, std::size_t(p - base));                               // unused head
      ::munmap(p + bytes, std::size_t(base + huge_page - p));                            // and tail (never empty)
      ::madvise(p, bytes, MADV_HUGEPAGE);   // a hint: failure is harmless
      return reinterpret_cast<T*>(p);
    }
#endif
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) noexcept
  {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if(is_large(n)) { ::munmap(static_cast<void*>(p), rounded(n)); return; }
#endif
    std::allocator<T>().deallocate(p, n);
  }

  template <typename U> bool operator==(const Huge_page_allocator<U>&) const noexcept { return true; }
  template <typename U> bool operator!=(const Huge_page_allocator<U>&) const noexcept { return false; }

private:
  static bool is_large(std::size_t n) { return n >= huge_page_threshold / sizeof(T); }
  static std::size_t rounded(std::size_t n) { return (n * sizeof(T) + huge_page - 1) / huge_page * huge_page; }
};

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_HUGE_PAGE_ALLOCATOR_H
