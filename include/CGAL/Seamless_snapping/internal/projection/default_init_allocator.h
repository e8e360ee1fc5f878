// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_DEFAULT_INIT_ALLOCATOR_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_DEFAULT_INIT_ALLOCATOR_H

// A std::allocator whose construction without arguments default-initializes instead of
// value-initializing: `resize(n)` and `vector(n)` then leave elements of trivial types (integers,
// doubles, the sparse entries and records of the projection) unwritten, instead of a pass that
// zeroes them before they are written in full. For the large arrays that are sized and then
// filled: the IRREF's rows (extract()) and the canonical rows (build_rows()). (The evaluation's
// records are a plain array: see evaluate_on_grid().) Values of class type (CGAL::Gmpz) are
// default-constructed as before.

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

template <typename T>
struct Default_init_allocator : std::allocator<T>
{
  template <typename U> struct rebind { typedef Default_init_allocator<U> other; };
  Default_init_allocator() noexcept {}
  template <typename U> Default_init_allocator(const Default_init_allocator<U>&) noexcept {}

  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value) { ::new(static_cast<void*>(p)) U; }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) { ::new(static_cast<void*>(p)) U(std::forward<Args>(args)...); }
};

template <typename T> using Default_init_vector = std::vector<T, Default_init_allocator<T> >;

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_DEFAULT_INIT_ALLOCATOR_H
