// Copyright (c) 2026 The Discrete_shells authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISCRETE_SHELLS_SRC_SECOND_ORDER_H
#define CGAL_DISCRETE_SHELLS_SRC_SECOND_ORDER_H

// Forward-mode derivatives of a scalar function of N variables: a value with its gradient
// and (when `with_hessian`) its Hessian, carried through every arithmetic operation.
// The shell's geometric quantities (edge length, triangle area, dihedral angle) are
// written once as templates on their scalar type and differentiated by evaluating them
// on this type: their Hessians (the dihedral angle's above all) are long and easy to get
// wrong by hand, and the tests check the result against finite differences.

#include <Eigen/Core>

#include <cmath>

namespace CGAL {
namespace Discrete_shells {
namespace internal {

template <int N, bool with_hessian>
struct Derivatives
{
  typedef Eigen::Matrix<double, N, 1> Gradient;
  // Without Hessians, an empty matrix: nothing to copy through the operations.
  typedef Eigen::Matrix<double, with_hessian ? N : 0, with_hessian ? N : 0> Hessian;

  double v = 0;
  Gradient g = Gradient::Zero();
  Hessian h = Hessian::Zero();

  Derivatives() = default;
  Derivatives(double value) : v(value) {}

  /// The `i`-th independent variable at `value`.
  static Derivatives variable(int i, double value)
  {
    Derivatives d(value);
    d.g[i] = 1;
    return d;
  }

  // y = f(x) by the chain rule: f' and f'' at x.
  Derivatives chain(double f, double df, double ddf) const
  {
    Derivatives r;
    r.v = f;
    r.g = df * g;
    if constexpr(with_hessian) r.h = df * h + ddf * g * g.transpose();
    return r;
  }
};

template <int N, bool H>
Derivatives<N, H> operator+(const Derivatives<N, H>& a, const Derivatives<N, H>& b)
{
  Derivatives<N, H> r;
  r.v = a.v + b.v;
  r.g = a.g + b.g;
  if constexpr(H) r.h = a.h + b.h;
  return r;
}

template <int N, bool H>
Derivatives<N, H> operator-(const Derivatives<N, H>& a, const Derivatives<N, H>& b)
{
  Derivatives<N, H> r;
  r.v = a.v - b.v;
  r.g = a.g - b.g;
  if constexpr(H) r.h = a.h - b.h;
  return r;
}

template <int N, bool H>
Derivatives<N, H> operator-(const Derivatives<N, H>& a)
{
  return a.chain(-a.v, -1, 0);
}

template <int N, bool H>
Derivatives<N, H> operator*(const Derivatives<N, H>& a, const Derivatives<N, H>& b)
{
  Derivatives<N, H> r;
  r.v = a.v * b.v;
  r.g = a.v * b.g + b.v * a.g;
  if constexpr(H) r.h = a.v * b.h + b.v * a.h + a.g * b.g.transpose() + b.g * a.g.transpose();
  return r;
}

template <int N, bool H>
Derivatives<N, H> operator*(double s, const Derivatives<N, H>& a)
{
  Derivatives<N, H> r;
  r.v = s * a.v;
  r.g = s * a.g;
  if constexpr(H) r.h = s * a.h;
  return r;
}

template <int N, bool H>
Derivatives<N, H> sqrt(const Derivatives<N, H>& a)
{
  const double s = std::sqrt(a.v);
  return a.chain(s, 0.5 / s, -0.25 / (s * a.v));
}

/// atan2(y, x) with the derivatives of both arguments.
template <int N, bool H>
Derivatives<N, H> atan2(const Derivatives<N, H>& y, const Derivatives<N, H>& x)
{
  // d atan2 = (x dy - y dx) / r2, r2 = x^2 + y^2.
  const double r2 = x.v * x.v + y.v * y.v;
  Derivatives<N, H> r;
  r.v = std::atan2(y.v, x.v);
  r.g = (x.v * y.g - y.v * x.g) / r2;
  if constexpr(H)
  {
    // d(x dy - y dx) = dx dy^T + x ddy - dy dx^T - y ddx ; d(1/r2) = -2 (x dx + y dy) / r2^2.
    const typename Derivatives<N, H>::Gradient dr2 = 2 * (x.v * x.g + y.v * y.g);
    const typename Derivatives<N, H>::Gradient num = x.v * y.g - y.v * x.g;
    r.h = (x.v * y.h - y.v * x.h + y.g * x.g.transpose() - x.g * y.g.transpose()) / r2
          - num * dr2.transpose() / (r2 * r2);
  }
  return r;
}

inline double sqrt(double a) { return std::sqrt(a); }
inline double atan2(double y, double x) { return std::atan2(y, x); }

} // namespace internal
} // namespace Discrete_shells
} // namespace CGAL

#endif
