// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Energies of fields given by their coefficients in an eigenfield basis, in total and per band.

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

// Coefficients beyond the basis have no eigenvalue: dropping them would hide a mix-up of bases.
void check_coefficients(const Eigen::VectorXd& a, int size)
{
  if(a.size() > size)
    throw Invalid_input(std::to_string(a.size()) + " coefficients for a basis of " + std::to_string(size) + " elements");
  if(!a.allFinite()) throw Invalid_input("the coefficients have non-finite entries");
}

} // namespace

double Eigenfield_basis::dirichlet_energy(const Vector& a) const
{
  check_coefficients(a, size());
  const Eigen::Index n = a.size();
  return (values_.head(n).array() * a.head(n).array().square()).sum();
}

double Eigenfield_basis::biharmonic_energy(const Vector& a) const
{
  check_coefficients(a, size());
  const Eigen::Index n = a.size();
  return (values_.head(n).array().square() * a.head(n).array().square()).sum();
}

Eigenfield_basis::Matrix Eigenfield_basis::band_energies(const Vector& a, const std::vector<double>& edges) const
{
  check_coefficients(a, size());
  for(std::size_t i = 0; i < edges.size(); ++i)
    if(std::isnan(edges[i]) || (i > 0 && !(edges[i] >= edges[i - 1])))
      throw Invalid_input("band energies: the band edges must be ascending numbers");
  const int bands = edges.size() < 2 ? 0 : static_cast<int>(edges.size()) - 1;
  Matrix energy = Matrix::Zero(bands, 3);
  for(Eigen::Index k = 0; k < std::min<Eigen::Index>(a.size(), size()); ++k)
    for(int b = 0; b < bands; ++b)
      if(values_[k] >= edges[b] && values_[k] < edges[b + 1])
      {
        energy(b, static_cast<int>(order_[k].type)) += a[k] * a[k];
        break;
      }
  return energy;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
