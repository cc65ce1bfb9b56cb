// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Smoothest_n_field_solver.h>
#include <CGAL/Model_reduction/Generalized_eigensolver.h>
#include <CGAL/Model_reduction/Sparse_spd_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

typedef Eigen::SparseMatrix<double> Sparse_matrix;

typedef std::complex<double> Complex;
typedef Eigen::SparseMatrix<Complex> Complex_sparse_matrix;
typedef Eigen::MatrixXcd Complex_matrix;

// The lowest eigenvector of A x = lambda D x, A Hermitian positive definite (S_n in complex
// form: each eigenpair (z, i z) of the real form is one complex eigenvector): block Lanczos
// on A^-1 D, blocks of 2, full reorthogonalisation in the D inner product, one Cholesky
// factor.  Its largest Ritz values converge like Chebyshev polynomials (rocker arm and bunny:
// 18 to 20 blocks of 4 real columns, where subspace iteration took 57 steps of 8).  No
// inertia check: a Ritz vector with a true residual below the tolerance is an eigenvector,
// and Lanczos finds the extremal ones first (the tests check it on analytic cases).
// \throws Numerical_failure if A is not positive definite or 100 blocks do not converge.
Eigen::VectorXcd block_lanczos(const Complex_sparse_matrix& A, const Eigen::VectorXd& d, double tolerance)
{
  const Eigen::Index n = d.size();
  const int block = static_cast<int>(std::min<Eigen::Index>(2, n));
  const int max_blocks = static_cast<int>(std::min<Eigen::Index>(100, n / block));
  Model_reduction::Sparse_hermitian_solver solver;
  solver.factor(A, "S_n of the smoothest field");
  // Capacity grows by 16 columns as the Krylov space grows (a preallocated n x 200 block
  // would be 1.1 GB on 346k faces; growing by one column would copy V every time).
  Complex_matrix V_storage(n, 0), H(0, 0);
  int columns = 0;
  auto V = [&]() { return V_storage.leftCols(columns); };
  // Appends the columns of W, D-orthogonalised against V and among themselves.
  auto d_norms = [&](const Complex_matrix& W) {
    return (W.cwiseAbs2().transpose() * d).cwiseSqrt().eval();
  };
  auto append = [&](Complex_matrix W) {
    // Classical Gram-Schmidt, repeated only for columns that lost more than half their
    // length ("twice is enough"): the orthogonalisation is the cost that grows.
    for(int pass = 0; pass < 2 && columns > 0; ++pass)
    {
      const Eigen::VectorXd before = d_norms(W);
      const Complex_matrix DW = d.asDiagonal() * W; // first: V^H D W would copy V scaled
      W -= V() * (V().adjoint() * DW);
      if((d_norms(W).array() > 0.5 * before.array()).all()) break;
    }
    const Eigen::VectorXd entry = d_norms(W);
    for(Eigen::Index j = 0; j < W.cols(); ++j)
    {
      Eigen::VectorXcd w = W.col(j);
      for(int pass = 0; pass < 2; ++pass)
        for(int i = columns - static_cast<int>(j); i < columns; ++i)
          w -= V_storage.col(i).dot(d.cwiseProduct(w)) * V_storage.col(i);
      const double norm = std::sqrt(std::real(w.dot(d.cwiseProduct(w))));
      // Nothing new left of the column (relative to its length): the space is invariant.
      if(!(norm > 1e-10 * entry[j])) throw Numerical_failure("smoothest n-field: the Krylov space closed");
      if(columns == V_storage.cols()) V_storage.conservativeResize(Eigen::NoChange, columns + 16);
      V_storage.col(columns++) = w / norm;
    }
    // H = V^H A V grows by the new columns only.
    const int added = static_cast<int>(W.cols()), first = columns - added;
    const Complex_matrix AW = A * V_storage.middleCols(first, added);
    H.conservativeResize(columns, columns);
    H.block(0, first, columns, added) = V().adjoint() * AW;
    H.block(first, 0, added, first) = H.block(0, first, first, added).adjoint();
  };
  std::mt19937_64 random(1);
  std::normal_distribution<double> normal;
  Complex_matrix start(n, block);
  for(Eigen::Index j = 0; j < start.cols(); ++j)
    for(Eigen::Index i = 0; i < n; ++i) start(i, j) = Complex(normal(random), normal(random));
  append(start);
  for(int k = 1; k < max_blocks; ++k)
  {
    append(solver.solve(Complex_matrix(d.asDiagonal() * V_storage.middleCols(columns - block, block))));
    if(k < 6 || k % 2) continue; // a check costs an n x columns product: every other block
    const Eigen::SelfAdjointEigenSolver<Complex_matrix> ritz(0.5 * (H + H.adjoint()));
    const double lambda = ritz.eigenvalues()[0];
    const Eigen::VectorXcd x = V() * ritz.eigenvectors().col(0);
    const Eigen::VectorXcd r = A * x - lambda * d.cwiseProduct(x);
    // The residual of the symmetric form D^-1/2 A D^-1/2, relative to lambda (x is D-unit).
    const double residual = std::sqrt(r.cwiseAbs2().cwiseQuotient(d).sum()) / lambda;
    if(residual <= tolerance) return x;
  }
  throw Numerical_failure("smoothest n-field: block Lanczos did not converge");
}

// The lowest eigenvector of S_n on the faces of one component (unit-area masses), as a real
// `2 |faces|` vector.
Eigen::VectorXd lowest_on_component(const N_field_operators& ops, const std::vector<int>& faces,
                                    const Smoothest_n_field_options& options)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  const bool whole = static_cast<int>(faces.size()) == mesh.number_of_faces();
  const Eigen::Index m = static_cast<Eigen::Index>(faces.size());
  Eigen::VectorXd d(m);
  double area = 0;
  for(int f : faces) area += mesh.face_area(f);
  for(Eigen::Index i = 0; i < m; ++i) d[i] = mesh.face_area(faces[i]) / area;
  Complex_sparse_matrix A;
  if(whole)
    A = ops.complex_S();
  else
  {
    std::vector<int> position(mesh.number_of_faces(), -1);
    for(Eigen::Index i = 0; i < m; ++i) position[faces[i]] = static_cast<int>(i);
    std::vector<Eigen::Triplet<Complex>> entries;
    const Complex_sparse_matrix& S = ops.complex_S();
    for(int f : faces)
      for(Complex_sparse_matrix::InnerIterator it(S, f); it; ++it)
        entries.emplace_back(position[it.row()], position[f], it.value());
    A.resize(m, m);
    A.setFromTriplets(entries.begin(), entries.end());
  }
  Eigen::VectorXd x(2 * m);
  try
  {
    const Eigen::VectorXcd z = block_lanczos(A, d, options.tolerance);
    for(Eigen::Index i = 0; i < m; ++i)
    {
      x[2 * i] = z[i].real();
      x[2 * i + 1] = z[i].imag();
    }
    return x;
  }
  catch(const Numerical_failure&)
  {
    // S_n nearly singular (a holonomy close to trivial) or slow convergence: the slicing
    // eigensolver on the real form copes with both.
  }
  Eigen::VectorXd d2(2 * m);
  for(Eigen::Index i = 0; i < m; ++i) d2[2 * i] = d2[2 * i + 1] = d[i];
  Sparse_matrix R(2 * m, 2 * m);
  {
    std::vector<Eigen::Triplet<double>> entries;
    for(Eigen::Index g = 0; g < A.outerSize(); ++g)
      for(Complex_sparse_matrix::InnerIterator it(A, g); it; ++it)
      {
        const double a = it.value().real(), b = it.value().imag();
        const Eigen::Index f = it.row();
        entries.emplace_back(2 * f, 2 * g, a);
        entries.emplace_back(2 * f + 1, 2 * g, b);
        entries.emplace_back(2 * f, 2 * g + 1, -b);
        entries.emplace_back(2 * f + 1, 2 * g + 1, a);
      }
    R.setFromTriplets(entries.begin(), entries.end());
  }
  Model_reduction::Eigensolver_options eigen_options;
  eigen_options.tolerance = options.tolerance;
  // The lowest eigenvalue comes twice (z and i z): ask for the pair.
  const Model_reduction::Eigenpairs pairs = Model_reduction::lowest_eigenpairs(R, d2, std::min<int>(2, static_cast<int>(d2.size())), Eigen::MatrixXd(),
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

  // A NaN tolerance is never met: block Lanczos would run out of blocks and blame itself.
  if(!(options.tolerance > 0 && options.tolerance < 1))
    throw Invalid_input("smoothest n-field: the tolerance must lie in (0, 1) (got " + std::to_string(options.tolerance) +
                        ")");
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
    Model_reduction::Sparse_spd_solver solver;
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
