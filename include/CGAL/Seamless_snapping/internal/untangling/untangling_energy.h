// Copyright (c) 2026  The Seamless Snapping authors.
// All rights reserved.
//
// This file is part of the Seamless Snapping package for CGAL; it is not part of CGAL itself.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Seamless Snapping authors

#ifndef CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_UNTANGLING_ENERGY_H
#define CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_UNTANGLING_ENERGY_H

// The per-triangle untangling energy of Garanzha, Kaporin, Kudryavtseva, Protais, Ray, Sokolov,
// "Foldover-free maps in 50 lines of code" (ACM TOG 40(4), 2021), written from the paper:
//
//   f_eps(J) = ((1 - theta) |J|_F^2 + theta (1 + det(J)^2)) / chi(det J, eps),
//   chi(D, eps) = (D + sqrt(eps^2 + D^2)) / 2,
//
// J the 2x2 Jacobian of the affine map from the triangle's reference shape to its UV triangle.
// chi > 0 for every D when eps > 0, so f is finite on inverted triangles too; as eps -> 0, chi -> max(D, 0)
// and f becomes a barrier that is infinite on non-positive triangles. The first term is a measure of
// conformal distortion (|J|^2 / det J >= 2, equality for similarities), the second of area distortion
// ((1 + D^2) / D >= 2, equality for D = 1): a triangle that keeps its reference shape is at the minimum.
// theta = 1/128 as in the paper's 2D experiments.
//
// Derivatives in j = (J00, J01, J10, J11) = (a, b, c, d), D = ad - bc:
//   grad f = g grad N + N g' grad D,   g = 1 / chi
//   hess f = g hess N + g' (grad N grad D^T + grad D grad N^T) + N g'' grad D grad D^T + N g' hess D
// with N = (1 - theta)|j|^2 + theta (1 + D^2), chi' = chi / s, s = sqrt(eps^2 + D^2), g' = -1 / (chi s),
// g'' = 2 / s^3. The 4x4 Hessian is projected onto the positive semidefinite
// cone (eigenvalues clamped at 0) for Newton's method, from its eigensystem in closed form (below).

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Seamless_snapping {
namespace internal {

constexpr double untangling_theta = 1. / 128;

// chi(D, eps), without cancellation for D < 0
inline double untangling_chi(double D, double eps)
{
  const double s = std::sqrt(eps * eps + D * D);
  return D >= 0 ? 0.5 * (D + s) : 0.5 * eps * eps / (s - D);
}

// The reference shape of a triangle: the inverse of its edge matrix [r1 - r0, r2 - r0] (columns)
// folded into the map from corner coordinates to J, and its area (the weight of the triangle).
// With Q (3 x 2) the rows q_m: J_i. = sum_m p_m,i q_m (p_m the UV of corner m, i = u, v).
struct Reference_triangle
{
  double q[3][2] = {{0, 0}, {0, 0}, {0, 0}};
  double area = 0;

  // from a positively oriented reference triangle (r0, r1, r2); false if it is degenerate
  bool set(const double r0[2], const double r1[2], const double r2[2])
  {
    const double e00 = r1[0] - r0[0], e10 = r1[1] - r0[1], e01 = r2[0] - r0[0], e11 = r2[1] - r0[1];
    const double det = e00 * e11 - e01 * e10;
    if(!(det > 0) || !std::isfinite(det)) return false;
    // inverse of E = [[e00, e01], [e10, e11]]
    const double i00 = e11 / det, i01 = -e01 / det, i10 = -e10 / det, i11 = e00 / det;
    q[1][0] = i00; q[1][1] = i01;
    q[2][0] = i10; q[2][1] = i11;
    q[0][0] = -(i00 + i10); q[0][1] = -(i01 + i11);
    area = 0.5 * det;
    return true;
  }

  // J of the UV triangle p (p[m][i]) as (a, b, c, d)
  Eigen::Vector4d jacobian(const double p[3][2]) const
  {
    Eigen::Vector4d j = Eigen::Vector4d::Zero();
    for(int m = 0; m < 3; ++m) {
      j[0] += p[m][0] * q[m][0]; j[1] += p[m][0] * q[m][1];
      j[2] += p[m][1] * q[m][0]; j[3] += p[m][1] * q[m][1];
    }
    return j;
  }

  // dj / dx, x = (u0, v0, u1, v1, u2, v2)
  Eigen::Matrix<double, 4, 6> jacobian_derivative() const
  {
    Eigen::Matrix<double, 4, 6> B = Eigen::Matrix<double, 4, 6>::Zero();
    for(int m = 0; m < 3; ++m) {
      B(0, 2 * m) = q[m][0]; B(1, 2 * m) = q[m][1];
      B(2, 2 * m + 1) = q[m][0]; B(3, 2 * m + 1) = q[m][1];
    }
    return B;
  }
};

inline double untangling_determinant(const Eigen::Vector4d& j) { return j[0] * j[3] - j[1] * j[2]; }

// f_eps(J)
inline double untangling_energy(const Eigen::Vector4d& j, double eps)
{
  const double D = untangling_determinant(j);
  const double N = (1 - untangling_theta) * j.squaredNorm() + untangling_theta * (1 + D * D);
  return N / untangling_chi(D, eps);
}

// f_eps(J), its gradient in j and, unless hess is null, its Hessian in j projected onto the PSD cone (eigenvalues
// clamped at 0), from the Hessian's eigensystem in closed form. With hD j = gD and hN, gN from the header,
//   hess f = c0 I + c1 hD + k gD gD^T + m (j gD^T + gD j^T),
//   c0 = 2 g (1 - theta), c1 = 2 g theta D + N g', k = 2 g theta + N g'' + 4 theta D g', m = 2 (1 - theta) g'.
// hD (the Hessian of det) has the eigenvalue +1 on V+ = {(a, b, -b, a)} (similarities) and -1 on
// V- = {(a, b, b, -a)} (anti-similarities); j = j+ + j- splits along them and gD = j+ - j-. So the unit vector
// w+ of V+ orthogonal to j+ is an eigenvector (eigenvalue c0 + c1), so is w- in V- orthogonal to j-
// (c0 - c1), and on the unit vectors u+ = j+ / |j+|, u- = j- / |j-| the Hessian is the 2x2 block
//   [[c0 + c1 + (k + 2m) |j+|^2, -k |j+| |j-|], [-k |j+| |j-|, c0 - c1 + (k - 2m) |j-|^2]],
// whose eigenpairs are written with square roots only (no libm function whose last bit may differ between
// machines). This is the structure of the Hessians of isotropic 2D energies (Smith, Goes, Kim, "Analytic
// eigensystems for isotropic distortion energies", ACM TOG 2019), derived here for f_eps directly.
inline double untangling_energy(const Eigen::Vector4d& j, double eps, Eigen::Vector4d& grad, Eigen::Matrix4d* hess)
{
  const double theta = untangling_theta;
  const double D = untangling_determinant(j);
  const Eigen::Vector4d gD(j[3], -j[2], -j[1], j[0]);
  const double N = (1 - theta) * j.squaredNorm() + theta * (1 + D * D);
  const Eigen::Vector4d gN = 2 * (1 - theta) * j + 2 * theta * D * gD;
  const double s = std::sqrt(eps * eps + D * D);
  const double chi = untangling_chi(D, eps);
  const double g = 1 / chi, g1 = -1 / (chi * s), g2 = 2 / (s * s * s);
  grad = g * gN + N * g1 * gD;
  if(hess == nullptr) return N / chi;                     // as untangling_energy(j, eps), bit for bit
  const double c0 = 2 * g * (1 - theta), c1 = 2 * g * theta * D + N * g1;
  const double k = 2 * g * theta + N * g2 + 4 * theta * D * g1, m = 2 * (1 - theta) * g1;
  // j+ = p1 e1 + p2 e2, j- = q1 e3 + q2 e4 in the orthonormal bases e1 = (1, 0, 0, 1) / sqrt2,
  // e2 = (0, 1, -1, 0) / sqrt2 of V+ and e3 = (1, 0, 0, -1) / sqrt2, e4 = (0, 1, 1, 0) / sqrt2 of V-
  const double r = std::sqrt(0.5);
  const double p1 = r * (j[0] + j[3]), p2 = r * (j[1] - j[2]), q1 = r * (j[0] - j[3]), q2 = r * (j[1] + j[2]);
  const double np = std::sqrt(p1 * p1 + p2 * p2), nm = std::sqrt(q1 * q1 + q2 * q2);
  const double a1 = np > 0 ? p1 / np : 1, a2 = np > 0 ? p2 / np : 0;   // u+ in (e1, e2); any unit vector if j+ = 0
  const double b1 = nm > 0 ? q1 / nm : 1, b2 = nm > 0 ? q2 / nm : 0;   // u- in (e3, e4)
  const Eigen::Vector4d up(r * a1, r * a2, -r * a2, r * a1), wp(-r * a2, r * a1, -r * a1, -r * a2);
  const Eigen::Vector4d um(r * b1, r * b2, r * b2, -r * b1), wm(-r * b2, r * b1, r * b1, r * b2);
  // the 2x2 block [[A, B], [B, C]] on (u+, u-): eigenvalues mean +- rad, the first eigenvector without cancellation
  const double A = c0 + c1 + (k + 2 * m) * np * np, C = c0 - c1 + (k - 2 * m) * nm * nm, B = -k * np * nm;
  const double mean = 0.5 * (A + C), dif = 0.5 * (A - C), rad = std::sqrt(dif * dif + B * B);
  double v1 = 1, v2 = 0;
  if(rad > 0) {
    const double x = dif >= 0 ? dif + rad : B, y = dif >= 0 ? B : rad - dif, n = std::sqrt(x * x + y * y);
    v1 = x / n; v2 = y / n;
  }
  const Eigen::Vector4d z1 = v1 * up + v2 * um, z2 = v1 * um - v2 * up;
  hess->setZero();
  const double lambda[4] = {c0 + c1, c0 - c1, mean + rad, mean - rad};
  const Eigen::Vector4d* vector[4] = {&wp, &wm, &z1, &z2};
  for(int i = 0; i < 4; ++i) {
    if(!(lambda[i] > 0)) continue;
    const Eigen::Vector4d& v = *vector[i];
    for(int a = 0; a < 4; ++a)
      for(int b = 0; b < 4; ++b) (*hess)(a, b) += lambda[i] * (v[a] * v[b]);   // exactly symmetric
  }
  return N / chi;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_UNTANGLING_ENERGY_H
