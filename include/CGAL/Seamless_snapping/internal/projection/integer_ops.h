// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_INTEGER_OPS_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_INTEGER_OPS_H

// Integer arithmetic used by the fraction-free elimination (Sec. 4.1), in two flavours with one
// interface: `std::int64_t` with overflow detection (an overflow throws `Integer_overflow`, and the
// caller redoes the whole elimination in `CGAL::Gmpz`), and `CGAL::Gmpz`, which never overflows.

#include <CGAL/Gmpz.h>

#include <cstdint>
#include <limits>
#include <utility>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

struct Integer_overflow {};

template <typename Int> struct Integer_ops;

template <>
struct Integer_ops<std::int64_t>
{
  typedef std::int64_t Int;
  static const char* name() { return "int64"; }
  static Int mul(Int a, Int b) { Int r; if(__builtin_mul_overflow(a, b, &r)) throw Integer_overflow(); return r; }
  static Int sub(Int a, Int b) { Int r; if(__builtin_sub_overflow(a, b, &r)) throw Integer_overflow(); return r; }
  static Int add(Int a, Int b) { Int r; if(__builtin_add_overflow(a, b, &r)) throw Integer_overflow(); return r; }
  static Int neg(Int a)        { if(a == std::numeric_limits<Int>::min()) throw Integer_overflow(); return -a; }
  static Int abs(Int a)        { return a < 0 ? neg(a) : a; }
  static bool is_zero(Int a)   { return a == 0; }
  static bool is_unit(Int a)   { return a == 1 || a == -1; }
  static int  sign(Int a)      { return (a > 0) - (a < 0); }
  static Int gcd(Int a, Int b)  // non-negative gcd; gcd(0,0) = 0
  {
    std::uint64_t x = a < 0 ? std::uint64_t(0) - std::uint64_t(a) : std::uint64_t(a);
    std::uint64_t y = b < 0 ? std::uint64_t(0) - std::uint64_t(b) : std::uint64_t(b);
    if(x == 0 || y == 0) x |= y;
    else if(x == 1 || y == 1) x = 1;                       // the common case in seamless systems
    else {                                                 // binary gcd (Stein): no divisions
      const int shift = __builtin_ctzll(x | y);
      x >>= __builtin_ctzll(x);
      do {
        y >>= __builtin_ctzll(y);
        if(x > y) std::swap(x, y);
        y -= x;
      } while(y != 0);
      x <<= shift;
    }
    if(x > std::uint64_t(std::numeric_limits<Int>::max())) throw Integer_overflow();
    return Int(x);
  }
  static Int exact_div(Int a, Int b) { return a / b; }   // b != 0, b | a, b != -1 or a != min (gcd > 0)
  static bool divides(Int d, Int a) { return d != 0 && a % d == 0; }
  static Int lcm(Int a, Int b) { a = abs(a); b = abs(b); if(a == 0 || b == 0) return 0; return mul(a / gcd(a, b), b); }
  static bool to_int64(Int a, std::int64_t& out) { out = a; return true; }
  static double to_double(Int a) { return double(a); }
  static std::string to_string(Int a) { return std::to_string(a); }
  static bool less(Int a, Int b) { return a < b; }
  static Int from_int64(std::int64_t v) { return v; }
  // Results of the elimination must be negatable (IRREF values are negated when evaluated).
  static const Int& negatable(const Int& a) { if(a == std::numeric_limits<Int>::min()) throw Integer_overflow(); return a; }
};

// Note on CGAL::Gmpz: copies share one representation and the non-const mpz() does not copy on
// write, so every mpz_* function here writes into a freshly constructed Gmpz, never into a copy.
template <>
struct Integer_ops<CGAL::Gmpz>
{
  typedef CGAL::Gmpz Int;
  static const char* name() { return "Gmpz"; }
  static Int mul(const Int& a, const Int& b) { return a * b; }
  static Int sub(const Int& a, const Int& b) { return a - b; }
  static Int add(const Int& a, const Int& b) { return a + b; }
  static Int neg(const Int& a)               { return -a; }
  static Int abs(const Int& a)               { return a.sign() == CGAL::NEGATIVE ? Int(-a) : a; }
  static bool is_zero(const Int& a)          { return a.sign() == CGAL::ZERO; }
  static bool is_unit(const Int& a)          { return a == 1 || a == -1; }
  static int  sign(const Int& a)             { return int(a.sign()); }
  static Int gcd(const Int& a, const Int& b)
  {
    Int r; mpz_gcd(r.mpz(), a.mpz(), b.mpz()); return r;
  }
  static Int exact_div(const Int& a, const Int& b) { Int r; mpz_divexact(r.mpz(), a.mpz(), b.mpz()); return r; }
  static bool divides(const Int& d, const Int& a) { return !is_zero(d) && mpz_divisible_p(a.mpz(), d.mpz()) != 0; }
  static Int lcm(const Int& a, const Int& b) { Int r; mpz_lcm(r.mpz(), a.mpz(), b.mpz()); return r; }
  // a mod b in [0, |b|)
  static Int mod_floor(const Int& a, const Int& b) { Int r; mpz_fdiv_r(r.mpz(), a.mpz(), b.mpz()); return r; }
  static bool to_int64(const Int& a, std::int64_t& out)
  {
    if(!mpz_fits_slong_p(a.mpz())) return false;
    static_assert(sizeof(long) == 8, "64-bit long expected");
    out = mpz_get_si(a.mpz()); return true;
  }
  static double to_double(const Int& a) { return a.to_double(); }
  static std::string to_string(const Int& a)
  {
    std::string s(mpz_sizeinbase(a.mpz(), 10) + 2, '\0');
    mpz_get_str(&s[0], 10, a.mpz());
    s.resize(std::char_traits<char>::length(s.c_str()));
    return s;
  }
  static bool less(const Int& a, const Int& b) { return a < b; }
  static Int from_int64(std::int64_t v) { Int r; mpz_set_si(r.mpz(), long(v)); return r; }
  static const Int& negatable(const Int& a) { return a; }
};

// Converts an integer of the caller's type (built-in integral type or CGAL::Gmpz) to int64.
template <typename T>
typename std::enable_if<std::is_integral<T>::value, bool>::type
to_int64(const T& v, std::int64_t& out)
{
  if(std::is_unsigned<T>::value && std::uint64_t(v) > std::uint64_t(std::numeric_limits<std::int64_t>::max()))
    return false;
  out = std::int64_t(v);
  return true;
}
inline bool to_int64(const CGAL::Gmpz& v, std::int64_t& out) { return Integer_ops<CGAL::Gmpz>::to_int64(v, out); }

template <typename T>
typename std::enable_if<std::is_integral<T>::value, CGAL::Gmpz>::type
to_gmpz(const T& v)
{
  CGAL::Gmpz r;
  if(std::is_signed<T>::value) mpz_set_si(r.mpz(), long(v)); else mpz_set_ui(r.mpz(), (unsigned long)(v));
  return r;
}
inline CGAL::Gmpz to_gmpz(const CGAL::Gmpz& v) { return v; }

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_PROJECTION_INTEGER_OPS_H
