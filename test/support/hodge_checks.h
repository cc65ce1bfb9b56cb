// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Checks of a Hodge decomposition through the operators, independently of how the
// solver found the parts.  The sum of the parts holds by construction (one part is the
// remainder) and mutual orthogonality holds for any orthogonal projection, including
// zero: neither proves the parts right.  What does, with V = im G + J im G*_int + H:
//  - the exact part has no nonconforming curl on interior edges and is orthogonal to the
//    harmonic basis (curl-free and orthogonal to H is im G),
//  - the coexact part has no conforming divergence at any vertex and is orthogonal to H
//    (divergence-free and orthogonal to H is J im G*_int),
//  - the harmonic part has neither and lies in the span of H,
//  - the parts add up to the input and none is zero for a generic (white-noise) input.
// Divergences and curls are measured integrated (G^T MX v, G*^T J MX v, without the
// inverse masses that a needle's vertex would blow up) and relative to the input's own.

#ifndef TVF_TEST_HODGE_CHECKS_H
#define TVF_TEST_HODGE_CHECKS_H

#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/Operator_matrices.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace tvf_test {

struct Hodge_check
{
  double sum = 0, orthogonality = 0;                      // relative to |v|, |v|^2
  double exact_curl = 0, exact_in_h = 0;                  // relative to |curl v|, |v|
  double coexact_divergence = 0, coexact_in_h = 0;        // relative to |div v|, |v|
  double harmonic_divergence = 0, harmonic_curl = 0, harmonic_outside_h = 0;
  double exact_share = 0, coexact_share = 0, harmonic_share = 0; // |part| / |v|
  int harmonic_dimension = 0, field_size = 0;
  bool finite = true, input_has_divergence = false, input_has_curl = false;

  double worst() const
  {
    if(!finite) return HUGE_VAL;
    return std::max({sum, orthogonality, exact_curl, exact_in_h, coexact_divergence, coexact_in_h,
                     harmonic_divergence, harmonic_curl, harmonic_outside_h});
  }
  std::string report() const
  {
    std::ostringstream s;
    s << "sum " << sum << ", orthogonality " << orthogonality << ", exact: curl " << exact_curl << " H-component "
      << exact_in_h << ", coexact: divergence " << coexact_divergence << " H-component " << coexact_in_h
      << ", harmonic: divergence " << harmonic_divergence << " curl " << harmonic_curl << " outside H "
      << harmonic_outside_h << "; shares " << exact_share << " " << coexact_share << " " << harmonic_share
      << " (dim H " << harmonic_dimension << ")";
    return s.str();
  }
};

inline Hodge_check check_hodge_parts(const CGAL::Tangent_vector_fields::Hodge_solver& solver, const Eigen::VectorXd& v)
{
  namespace TVF = CGAL::Tangent_vector_fields;
  const TVF::Operator_matrices& A = solver.operators();
  const TVF::Hodge_parts p = solver.decompose(v, TVF::hodge_exact | TVF::hodge_coexact | TVF::hodge_harmonic);
  Hodge_check c;
  c.field_size = int(v.size());
  c.finite = p.exact.allFinite() && p.coexact.allFinite() && p.harmonic.allFinite();
  if(!c.finite) return c;
  const Eigen::VectorXd& mx = A.field_masses();
  auto dot = [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return a.dot(mx.cwiseProduct(b)); };
  auto norm = [&](const Eigen::VectorXd& a) { return std::sqrt(dot(a, a)); };
  // Integrated conforming divergence (vertices) and nonconforming curl (interior edges).
  auto divergence = [&](const Eigen::VectorXd& a) -> double { return (A.G().transpose() * mx.cwiseProduct(a)).norm(); };
  auto curl = [&](const Eigen::VectorXd& a) -> double {
    return (A.G_star_interior().transpose() * A.rotate(mx.cwiseProduct(a))).norm();
  };
  // A mesh without interior edges has no curl at all: 0/0 counts as no defect.
  const double tiny = std::numeric_limits<double>::min();
  const double n = norm(v), div_v = std::max(divergence(v), tiny), curl_v = std::max(curl(v), tiny);
  c.input_has_divergence = div_v > tiny;
  c.input_has_curl = curl_v > tiny;
  c.sum = norm(p.exact + p.coexact + p.harmonic - v) / n;
  c.orthogonality = std::max({std::abs(dot(p.exact, p.coexact)), std::abs(dot(p.exact, p.harmonic)),
                              std::abs(dot(p.coexact, p.harmonic))}) / (n * n);
  c.exact_curl = curl(p.exact) / curl_v;
  c.coexact_divergence = divergence(p.coexact) / div_v;
  c.harmonic_divergence = divergence(p.harmonic) / div_v;
  c.harmonic_curl = curl(p.harmonic) / curl_v;
  // Components along the harmonic basis (its own orthogonality is not assumed).
  const Eigen::MatrixXd& H = solver.harmonic_basis();
  c.harmonic_dimension = int(H.cols());
  if(H.cols() == 0)
    c.harmonic_outside_h = norm(p.harmonic) / n;
  else
  {
    const Eigen::MatrixXd MH = mx.asDiagonal() * H;
    const Eigen::LDLT<Eigen::MatrixXd> gram(H.transpose() * MH);
    auto h_component = [&](const Eigen::VectorXd& a) -> Eigen::VectorXd { return H * gram.solve(MH.transpose() * a); };
    c.exact_in_h = norm(h_component(p.exact)) / n;
    c.coexact_in_h = norm(h_component(p.coexact)) / n;
    c.harmonic_outside_h = norm(p.harmonic - h_component(p.harmonic)) / n;
  }
  c.exact_share = norm(p.exact) / n;
  c.coexact_share = norm(p.coexact) / n;
  c.harmonic_share = norm(p.harmonic) / n;
  return c;
}

// Expects every defect of the decomposition of the white-noise field `v` below
// `tolerance` and every part nonzero.  For white noise in 2nf dimensions a part in a
// k-dimensional subspace has a norm of about sqrt(k / 2nf) |v|: the exact and coexact
// parts (k ~ nf/2 or more) well above 5 %, the harmonic part asked to reach a hundredth
// of its expected size.
inline void expect_sound_hodge_parts(const CGAL::Tangent_vector_fields::Hodge_solver& solver, const Eigen::VectorXd& v,
                                     double tolerance)
{
  const Hodge_check c = check_hodge_parts(solver, v);
  ASSERT_TRUE(c.finite) << "non-finite parts";
  EXPECT_LT(c.worst(), tolerance) << c.report();
  // The input's divergence is all in the exact part, its curl all in the coexact part.
  EXPECT_TRUE(c.input_has_divergence && c.input_has_curl) << "not a generic field: " << c.report();
  EXPECT_GT(c.exact_share, 0.05) << c.report();
  EXPECT_GT(c.coexact_share, 0.05) << c.report();
  if(c.harmonic_dimension > 0)
    EXPECT_GT(c.harmonic_share, 0.01 * std::sqrt(double(c.harmonic_dimension) / c.field_size)) << c.report();
}

} // namespace tvf_test

#endif // TVF_TEST_HODGE_CHECKS_H
