// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The truth the server's exact answers are checked against: one-shot full spline solves
// (Full_spline_solver, Full_n_field_spline_solver) of the served sphere, read and solved here
// through the library, in double.  Its own translation unit: the only one of the server's
// tests with Surface_mesh.

#ifndef TVF_TEST_VIEWER_FULL_SPLINE_TRUTH_H
#define TVF_TEST_VIEWER_FULL_SPLINE_TRUTH_H

#include "server_test_support.h"

#include <CGAL/Tangent_vector_fields/Field_constraint.h>
#include <CGAL/Tangent_vector_fields/N_field_constraint.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace server_test {

namespace TVF = CGAL::Tangent_vector_fields;

/// A field per face as 3D vectors (n-fields: all n vectors of each face, `vectors[j][f]`),
/// with the face areas (the norms are the mass matrix's).
struct Truth
{
  std::vector<std::vector<std::array<double, 3>>> vectors;
  std::vector<double> areas;
};

/// The triangles of the served sphere as the library numbers them (to check that the
/// server numbers faces and vertices alike).
std::vector<std::uint32_t> library_sphere_triangles();
/// The one-shot full vector field spline (energy E_B) of `constraints` with `omega`.
Truth full_spline(const std::vector<TVF::Field_constraint>& constraints, double omega);
/// The one-shot full n-field spline of order `order`.
Truth full_n_field_spline(int n, int order, const std::vector<TVF::N_field_constraint>& constraints, double omega);

/// The largest distance, over the faces, of the server's vector to the truth's (for n-fields
/// the nearest of its n vectors), relative to the truth's largest vector.
inline double largest_gap(const Message& field, const Truth& truth)
{
  double largest = 0, gap = 0;
  for(std::size_t f = 0; f < truth.areas.size(); ++f)
  {
    double nearest = HUGE_VAL;
    for(const auto& family : truth.vectors)
    {
      largest = std::max(largest, distance(family[f], {{0, 0, 0}}));
      nearest = std::min(nearest, distance(face_vector(field, int(f)), family[f]));
    }
    gap = std::max(gap, nearest);
  }
  return gap / largest;
}

/// |server - truth| / |truth| in the mass matrix's norm (vector fields): what the server
/// reports as "difference" when `field` is its reduced answer and the truth the exact one.
inline double mass_distance(const Message& field, const Truth& truth)
{
  double d2 = 0, t2 = 0;
  for(std::size_t f = 0; f < truth.areas.size(); ++f)
  {
    const double d = distance(face_vector(field, int(f)), truth.vectors[0][f]);
    const double t = distance(truth.vectors[0][f], {{0, 0, 0}});
    d2 += truth.areas[f] * d * d;
    t2 += truth.areas[f] * t * t;
  }
  return std::sqrt(d2 / t2);
}

} // namespace server_test

#endif
