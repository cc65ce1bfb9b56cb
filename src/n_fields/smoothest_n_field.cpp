// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Smoothest_n_field_solver.h>
#include <CGAL/Tangent_vector_fields/Generalized_eigensolver.h>
#include <CGAL/Tangent_vector_fields/Sparse_spd_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

typedef Eigen::SparseMatrix<double> Sparse_matrix;

// The lowest eigenvector of S_n on the faces of one component (unit-area masses).
Eigen::VectorXd lowest_on_component(const N_field_operators& ops, const std::vector<int>& faces,
                                    const Smoothest_n_field_options& options)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  const bool whole = static_cast<int>(faces.size()) == mesh.number_of_faces();
  Sparse_matrix A;
  Eigen::VectorXd d(2 * faces.size());
  double area = 0;
  for(int f : faces) area += mesh.face_area(f);
  for(std::size_t i = 0; i < faces.size(); ++i) d[2 * i] = d[2 * i + 1] = mesh.face_area(faces[i]) / area;
  if(whole)
    A = ops.S();
  else
  {
    std::vector<int> position(mesh.number_of_faces(), -1);
    for(std::size_t i = 0; i < faces.size(); ++i) position[faces[i]] = static_cast<int>(i);
    std::vector<Eigen::Triplet<double>> entries;
    const Sparse_matrix& S = ops.S();
    for(int f : faces)
      for(int a = 0; a < 2; ++a)
        for(Sparse_matrix::InnerIterator it(S, 2 * f + a); it; ++it)
          entries.emplace_back(2 * position[it.row() / 2] + it.row() % 2, 2 * position[f] + a, it.value());
    A.resize(d.size(), d.size());
    A.setFromTriplets(entries.begin(), entries.end());
  }
  Eigensolver_options eigen_options;
  eigen_options.tolerance = options.tolerance;
  // The lowest eigenvalue comes twice (z and i z): ask for the pair.
  const Eigenpairs pairs = lowest_eigenpairs(A, d, std::min<int>(2, static_cast<int>(d.size())), Eigen::MatrixXd(),
                                             eigen_options);
  return pairs.vectors.col(0);
}

} // namespace

Eigen::VectorXd smoothest_n_field(const N_field_operators& ops, const Smoothest_n_field_options& options)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  const int nf = mesh.number_of_faces();
  const Eigen::VectorXd& mass = ops.masses();
  double area = 0;
  for(int f = 0; f < nf; ++f) area += mesh.face_area(f);

  if(options.alignment.size() > 0)
  {
    if(options.alignment.size() != 2 * nf)
      throw Invalid_input("smoothest n-field: the alignment field has " + std::to_string(options.alignment.size()) +
                          " values, the mesh needs " + std::to_string(2 * nf));
    if(!options.alignment.allFinite()) throw Invalid_input("smoothest n-field: the alignment field is not finite");
    if(!(options.alignment_weight > 0) || !std::isfinite(options.alignment_weight))
      throw Invalid_input("smoothest n-field: the alignment weight must be positive and finite");
    // min E_D(z) + s |z - g|^2_MX, s for the mesh as given: (S_n + s MX) z = s MX g.
    const double s = options.alignment_weight / area;
    Sparse_matrix A = ops.S();
    A.diagonal() += s * mass;
    Sparse_spd_solver solver;
    solver.factor(A, "S_n + s MX of the aligned smoothest field");
    return solver.solve(Eigen::VectorXd(s * mass.cwiseProduct(options.alignment)));
  }

  // Per component: a parallel field where the holonomy allows one, else the lowest eigenvector.
  Eigen::VectorXd z = Eigen::VectorXd::Zero(2 * nf);
  const Eigen::MatrixXd& kernel = ops.kernel();
  std::vector<std::vector<int>> faces(mesh.topology().number_of_components());
  for(int f = 0; f < nf; ++f) faces[mesh.face_component(f)].push_back(f);
  std::vector<char> done(faces.size(), 0);
  for(Eigen::Index j = 0; j < kernel.cols(); j += 2)
  {
    // A kernel pair lives on one component: take its first column there.
    for(int f = 0; f < nf; ++f)
      if(kernel(2 * f, j) != 0 || kernel(2 * f + 1, j) != 0)
      {
        const int c = mesh.face_component(f);
        for(int g : faces[c]) z.segment<2>(2 * g) = kernel.col(j).segment<2>(2 * g);
        done[c] = 1;
        break;
      }
  }
  for(std::size_t c = 0; c < faces.size(); ++c)
  {
    if(done[c]) continue;
    const Eigen::VectorXd x = lowest_on_component(ops, faces[c], options);
    for(std::size_t i = 0; i < faces[c].size(); ++i) z.segment<2>(2 * faces[c][i]) = x.segment<2>(2 * i);
  }
  return z;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
