// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

// The byte format of the fuzz target fuzz_projection: a small integer system C x = b and an input
// x̄, decoded from any byte string (missing bytes read as 0), and its encoder for the seed corpus
// (make_fuzz_seeds). Not part of the package API.
//
//   byte 0: m - 1 (mod 32)          byte 1: n - 1 (mod 48)
//   byte 2: flags: bit 0 force_multiprecision, bits 1-2 delta_margin_bits - 1,
//                  bits 3-7 the exponent j - 16 of the scale check (2^j x̄, only for b = 0)
//   per row i < m: a count c (mod n + 1), then c times (column (mod n), integer); then b_i (integer)
//   per column j < n: x̄_j (double)
//   integer: a tag byte t; t < 200: t - 100; t < 250: a 2-byte signed value times 2^(8 (t - 200) mod 48);
//            t >= 250: 8 raw bytes (any int64, INT64_MIN included)
//   double:  a tag byte t; t < 100: (t - 50) / 8; t < 200: 8 raw bytes (NaN, Inf, subnormals included);
//            t >= 200: a 4-byte signed mantissa times 2^e, e = (signed byte) / 2
// Columns may repeat within a row: the triplets then hold duplicates, which initialize() sums.

#ifndef CGAL_SEAMLESS_SNAPPING_TEST_FUZZ_PROJECTION_BYTES_H
#define CGAL_SEAMLESS_SNAPPING_TEST_FUZZ_PROJECTION_BYTES_H

#include <Eigen/Sparse>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace SS_fuzz {

struct Fuzz_system
{
  std::size_t m = 0, n = 0;
  std::vector<Eigen::Triplet<std::int64_t>> triplets;   // as decoded: duplicates and zeros possible
  std::vector<std::int64_t> b;
  std::vector<double> xbar;
  bool force_multiprecision = false;
  int delta_margin_bits = 1;
  int scale_exponent = 0;                                // j of the scale check, in [-16, 15]
};

class Byte_reader
{
public:
  Byte_reader(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}
  std::uint8_t byte() { return m_pos < m_size ? m_data[m_pos++] : 0; }
  std::uint64_t raw(int bytes)
  {
    std::uint64_t v = 0;
    for(int k = 0; k < bytes; ++k) v |= std::uint64_t(byte()) << (8 * k);
    return v;
  }
  std::int64_t integer()
  {
    const int t = byte();
    if(t < 200) return t - 100;
    if(t < 250) {
      const std::int64_t v = std::int16_t(std::uint16_t(raw(2)));
      return v * (std::int64_t(1) << ((8 * (t - 200)) % 48));        // |v| <= 2^15, shift <= 40: fits
    }
    const std::uint64_t u = raw(8);
    std::int64_t v;
    std::memcpy(&v, &u, 8);
    return v;
  }
  double real()
  {
    const int t = byte();
    if(t < 100) return (t - 50) / 8.;
    if(t < 200) {
      const std::uint64_t u = raw(8);
      double v;
      std::memcpy(&v, &u, 8);
      return v;
    }
    const std::int32_t mantissa = std::int32_t(std::uint32_t(raw(4)));
    const int e = std::int8_t(byte()) / 2;
    return std::ldexp(double(mantissa), e);
  }
private:
  const std::uint8_t* m_data;
  std::size_t m_size, m_pos = 0;
};

inline Fuzz_system decode_system(const std::uint8_t* data, std::size_t size)
{
  Byte_reader in(data, size);
  Fuzz_system s;
  s.m = 1 + in.byte() % 32;
  s.n = 1 + in.byte() % 48;
  const int flags = in.byte();
  s.force_multiprecision = (flags & 1) != 0;
  s.delta_margin_bits = 1 + ((flags >> 1) & 3);
  s.scale_exponent = (flags >> 3) - 16;
  s.b.resize(s.m);
  for(std::size_t i = 0; i < s.m; ++i) {
    const std::size_t count = in.byte() % (s.n + 1);
    for(std::size_t k = 0; k < count; ++k) {
      const std::size_t col = in.byte() % s.n;
      s.triplets.emplace_back(Eigen::Index(i), Eigen::Index(col), in.integer());
    }
    s.b[i] = in.integer();
  }
  s.xbar.resize(s.n);
  for(double& x : s.xbar) x = in.real();
  return s;
}

// ---- encoder (seed corpus): the exact inverse of decode_system() for m <= 32, n <= 48
inline void put_raw(std::vector<std::uint8_t>& out, std::uint64_t v, int bytes)
{
  for(int k = 0; k < bytes; ++k) out.push_back(std::uint8_t(v >> (8 * k)));
}
inline void put_integer(std::vector<std::uint8_t>& out, std::int64_t v)
{
  if(v >= -100 && v < 100) { out.push_back(std::uint8_t(v + 100)); return; }
  std::uint64_t u;
  std::memcpy(&u, &v, 8);
  out.push_back(255);
  put_raw(out, u, 8);
}
inline void put_real(std::vector<std::uint8_t>& out, double x)
{
  if(x * 8 == std::floor(x * 8) && x >= -50 / 8. && x < 50 / 8.) { out.push_back(std::uint8_t(int(x * 8) + 50)); return; }
  std::uint64_t u;
  std::memcpy(&u, &x, 8);
  out.push_back(150);
  put_raw(out, u, 8);
}

/// the bytes of the system with rows `rows[i]` = (column, coefficient) lists; flags as in decode_system()
inline std::vector<std::uint8_t>
encode_system(std::size_t n, const std::vector<std::vector<std::pair<std::size_t, std::int64_t>>>& rows,
              const std::vector<std::int64_t>& b, const std::vector<double>& xbar, int flags)
{
  std::vector<std::uint8_t> out;
  out.push_back(std::uint8_t(rows.size() - 1));
  out.push_back(std::uint8_t(n - 1));
  out.push_back(std::uint8_t(flags));
  for(std::size_t i = 0; i < rows.size(); ++i) {
    out.push_back(std::uint8_t(rows[i].size()));
    for(const auto& e : rows[i]) {
      out.push_back(std::uint8_t(e.first));
      put_integer(out, e.second);
    }
    put_integer(out, b[i]);
  }
  for(double x : xbar) put_real(out, x);
  return out;
}

} // namespace SS_fuzz

#endif // CGAL_SEAMLESS_SNAPPING_TEST_FUZZ_PROJECTION_BYTES_H
