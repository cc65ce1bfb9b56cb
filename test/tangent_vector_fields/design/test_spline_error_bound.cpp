// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The reduced splines' a-posteriori error bound (Spline_report::error_bound): against the
// error measured from the exact spline, on meshes of every topology the suite has, at many
// basis sizes and tensions.  The truth is independent of the bound's derivation: the exact
// spline comes from the full-resolution solver (sparse factorisations), and the energy norm of
// the difference from the complete eigenbasis (dense), E(v) = sum_k D_k (u_k^T MX v)^2.

#include "design_test_support.h"

#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/N_field_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;
using namespace design_test;

namespace {

// Two meshes side by side as one (two components).
Mesh side_by_side(const Mesh& a, Mesh b)
{
  transform(b, 1.0, {1, 0, 0, 0, 1, 0, 0, 0, 1}, Vector_3(3, 0, 0));
  std::vector<Point_3> points;
  std::vector<std::array<int, 3>> triangles;
  for(const Mesh* m : {&a, static_cast<const Mesh*>(&b)})
  {
    const int offset = static_cast<int>(points.size());
    for(auto v : m->vertices()) points.push_back(m->point(v));
    for(auto f : m->faces())
    {
      std::array<int, 3> t;
      int k = 0;
      for(auto v : CGAL::vertices_around_face(m->halfedge(f), *m)) t[k++] = offset + static_cast<int>(v);
      triangles.push_back(t);
    }
  }
  return make_mesh(points, triangles);
}

// E_B + omega E_D of fields (columns) through the complete eigenbasis of the mesh as given.
Eigen::VectorXd spectral_energies(const TVF::Eigenfield_basis& complete, double omega_effective, const Eigen::MatrixXd& v)
{
  const Eigen::MatrixXd a = complete.compress(v, complete.size()).coefficients;
  Eigen::VectorXd e = Eigen::VectorXd::Zero(v.cols());
  for(int k = 0; k < complete.size(); ++k)
  {
    const double lambda = complete.eigenvalue(k);
    e += (lambda * lambda + omega_effective * lambda) * a.row(k).transpose().cwiseAbs2();
  }
  return e;
}

struct Bound_case
{
  double bound = 0, measured = 0;
};

} // namespace

// On a sphere, a torus (harmonic fields), an annulus (boundary), a curved patch and two
// components: the bound is never below the measured energy-norm error, for basis sizes from
// a few fields to nearly all, with and without tension, for two constraint sets; and it is not
// vacuous: within a factor the test states of the measured error.
TEST(SplineErrorBound, BoundsTheMeasuredErrorOnEveryTopology)
{
  const std::vector<std::pair<std::string, Mesh>> meshes = {
      {"sphere", make_icosphere(2)},
      {"torus", make_torus(14, 8)},
      {"annulus", make_disk(8, 0.35)},
      {"curved patch", make_curved_disk(8)},
      {"two components", side_by_side(make_icosphere(1), make_torus(10, 6))}};
  std::vector<double> ratios;
  for(const auto& [name, mesh] : meshes)
  {
    const Design_setup s = setup(mesh, 0); // the complete basis: the truth, and the solver's basis cut at d
    const double area = s.ops->face_areas().sum();
    for(double omega : {0., 2.})
      for(unsigned seed : {1u, 2u})
      {
        const std::vector<TVF::Field_constraint> constraints = mixed_constraints(s.ops->mesh(), 2 + 3 * seed, seed);
        TVF::Spline_options options;
        options.omega = omega;
        TVF::Full_spline_solver full(s.hodge, options);
        full.add(constraints);
        const Eigen::VectorXd exact = full.field();
        EXPECT_EQ(full.report().error_bound, 0.) << "the full solver is exact";
        for(int d : {24, 48, 96, 192, 2 * s.nf - 8})
        {
          TVF::Reduced_spline_solver reduced(s.basis, d, options);
          try
          {
            reduced.add(constraints);
          }
          catch(const TVF::Infeasible_constraints&)
          {
            continue; // too few fields for these constraints: no answer to bound
          }
          const Eigen::VectorXd x = reduced.field();
          Eigen::MatrixXd v(x.size(), 2);
          v << x - exact, exact;
          const Eigen::VectorXd e = spectral_energies(*s.basis, omega / area, v);
          const double measured = std::sqrt(e[0] / e[1]);
          const double bound = reduced.report().error_bound;
          // Rounding: the bound is a difference of two energies of the small system (1e-12 of
          // them), the measurement a difference of two fields (1e-8 of the field's norm).
          EXPECT_GE(bound, measured * (1 - 1e-6) - 1e-7) << name << ", omega " << omega << ", d " << d;
          if(measured > 1e-6) ratios.push_back(bound / measured);
          std::printf("%-15s omega %g seed %u d %4d: measured %.3e bound %.3e\n", name.c_str(), omega, seed, d, measured,
                      bound);
        }
      }
  }
  ASSERT_GT(ratios.size(), 40u);
  std::sort(ratios.begin(), ratios.end());
  std::printf("bound / measured: min %.3g median %.3g max %.3g over %zu cases\n", ratios.front(),
              ratios[ratios.size() / 2], ratios.back(), ratios.size());
  // Measured when written: median 2.2, largest 11 (a few fields and constraints in one place).
  // A bound some 25 times the error would not tell a user whether to trust the answer.
  EXPECT_LT(ratios[ratios.size() / 2], 4.);
  EXPECT_LT(ratios.back(), 25.);
}

// The bound is kept between reports and grown as rows are appended (rebuilt when rows are
// dropped): after every kind of edit it equals the bound of a fresh solver of the same
// constraints, and value edits change it as they change the spline.
TEST(SplineErrorBound, KeptThroughEditsAsAFreshSolverComputesIt)
{
  const Design_setup s = setup(make_torus(14, 8), 60);
  const std::vector<TVF::Field_constraint> constraints = mixed_constraints(s.ops->mesh(), 4, 3);
  TVF::Spline_options options;
  options.omega = 1;
  TVF::Reduced_spline_solver edited(s.basis, 0, options);
  std::vector<TVF::Constraint_id> ids;
  auto fresh_bound = [&](const std::vector<TVF::Field_constraint>& set) {
    TVF::Reduced_spline_solver fresh(s.basis, 0, options);
    fresh.add(set);
    return fresh.report().error_bound;
  };
  std::vector<TVF::Field_constraint> set;
  for(const TVF::Field_constraint& c : constraints)
  {
    ids.push_back(edited.add(c));
    set.push_back(c);
    // Rounding: the same small systems built in another order of appends, 1e-9 relative.
    EXPECT_NEAR(edited.report().error_bound, fresh_bound(set), 1e-9 * fresh_bound(set)) << set.size() << " constraints";
  }
  edited.remove(ids[1]);
  set.erase(set.begin() + 1);
  EXPECT_NEAR(edited.report().error_bound, fresh_bound(set), 1e-9 * fresh_bound(set)) << "after a removal";
  // A value edit (same rows, other values): the kept system serves it.
  TVF::Field_constraint moved = set.front();
  moved.vector = {{2 * moved.vector[0], -moved.vector[1], 0.5 * moved.vector[2]}};
  edited.change(ids[0], moved);
  set.front() = moved;
  EXPECT_NEAR(edited.report().error_bound, fresh_bound(set), 1e-9 * fresh_bound(set)) << "after a value edit";
  edited.set_omega(3);
  options.omega = 3;
  EXPECT_NEAR(edited.report().error_bound, fresh_bound(set), 1e-9 * fresh_bound(set)) << "after a new tension";
}
