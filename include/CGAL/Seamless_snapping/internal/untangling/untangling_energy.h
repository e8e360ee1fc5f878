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
// cone (eigenvalues clamped at 0) for Newton's method.

#include <Eigen/Dense>

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

// f_eps(J), its gradient in j and its Hessian in j projected onto the PSD cone
inline double untangling_energy(const Eigen::Vector4d& j, double eps, Eigen::Vector4d& grad, Eigen::Matrix4d& hess)
{
  const double theta = untangling_theta;
  const double D = untangling_determinant(j);
  const Eigen::Vector4d gD(j[3], -j[2], -j[1], j[0]);
  Eigen::Matrix4d hD = Eigen::Matrix4d::Zero();
  hD(0, 3) = hD(3, 0) = 1;
  hD(1, 2) = hD(2, 1) = -1;
  const double N = (1 - theta) * j.squaredNorm() + theta * (1 + D * D);
  const Eigen::Vector4d gN = 2 * (1 - theta) * j + 2 * theta * D * gD;
  const Eigen::Matrix4d hN = 2 * (1 - theta) * Eigen::Matrix4d::Identity() + 2 * theta * (gD * gD.transpose() + D * hD);
  const double s = std::sqrt(eps * eps + D * D);
  const double chi = untangling_chi(D, eps);
  const double g = 1 / chi, g1 = -1 / (chi * s), g2 = 2 / (s * s * s);
  grad = g * gN + N * g1 * gD;
  hess = g * hN + g1 * (gN * gD.transpose() + gD * gN.transpose()) + N * g2 * gD * gD.transpose() + N * g1 * hD;
  if(Eigen::LLT<Eigen::Matrix4d>(hess).info() == Eigen::Success) return N * g;   // positive definite already
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> es(hess);
  const Eigen::Vector4d lambda = es.eigenvalues().cwiseMax(0.);
  hess = es.eigenvectors() * lambda.asDiagonal() * es.eigenvectors().transpose();
  return N * g;
}

} // namespace internal
} // namespace Seamless_snapping
} // namespace CGAL

#endif // CGAL_SEAMLESS_SNAPPING_INTERNAL_UNTANGLING_UNTANGLING_ENERGY_H
