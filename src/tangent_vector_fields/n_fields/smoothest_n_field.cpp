// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Smoothest_n_field_solver.h>
#include <CGAL/Model_reduction/Generalized_eigensolver.h>
#include <CGAL/Model_reduction/Sparse_spd_solver.h>
#include <CGAL/Model_reduction/internal/One_blas_thread.h>
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
// form: each eigenpair (z, i z) of the real form is one complex eigenvector): Lanczos on the
// shift-inverted operator A^-1 D, self-adjoint in the D inner product, one simplicial Cholesky
// factor and one single-column solve per step.  The lowest eigenvalue can sit within 2% of the
// next (armadillo, 346k faces: 951.8 and 972.9), so the run is long (about 40 steps) and
// what costs is keeping the Krylov vectors orthogonal: each new vector loses its components
// along the last two by the three-term recurrence first (O(n)), so that one pass against all
// of them (two reads of V) is enough; a second pass is made only when that pass removed more
// than half of what was left (Daniel-Gragg-Kaufman-Stewart).  The tridiagonal T = V^H D A^-1 D V
// comes from the same coefficients.  A single vector suffices: any vector of a multiple
// lowest eigenspace is a smoothest field.  Partial reorthogonalisation (Simon's recurrence for
// the loss of orthogonality, a full pass only past sqrt(eps)) was tried: with a semi-orthogonal
// basis the true residual stalled at 1e-9 to 1e-5 (rocker arm, bunny), short of the default
// 1e-10, even after inverse-iteration steps on the Ritz vector.
//
// Convergence: for the Ritz pair (x = V y, 1 / theta) of T, A x - D x / theta =
// -(beta y_k / theta) A v_{k+1}, so its relative residual in the D^-1 norm is
// beta |y_k| |A v_{k+1}|_{D^-1}: one sparse product per check.  A pair whose estimate meets the
// tolerance is checked with its true residual (Rayleigh quotient, explicit product), which
// alone decides.  No inertia check: Lanczos finds the extremal eigenvalues first (the tests
// check it on analytic cases).
// \throws Numerical_failure if A is not positive definite, the Krylov space closes, or 150
//         steps do not converge.
Eigen::VectorXcd lowest_by_lanczos(const Complex_sparse_matrix& A, const Eigen::VectorXd& d, double tolerance)
{
  const Eigen::Index n = d.size();
  const int max_steps = static_cast<int>(std::min<Eigen::Index>(150, n));
  // One BLAS thread: the products here are matrix-vector, where OpenBLAS's threads only wake
  // and yield.
  Model_reduction::internal::One_blas_thread one_blas_thread;
  Model_reduction::Sparse_hermitian_solver solver(Model_reduction::Spd_factorization::simplicial);
  solver.factor(A, "S_n of the smoothest field");
  const Eigen::VectorXd d_inverse = d.cwiseInverse();
  auto d_norm = [&](const Eigen::VectorXcd& w) { return std::sqrt(w.cwiseAbs2().dot(d)); };

  // V grows by doubling its capacity: a preallocated n x 150 block would be 830 MB on 346k faces.
  Complex_matrix V_storage(n, 8);
  Complex_matrix T = Complex_matrix::Zero(max_steps + 1, max_steps + 1);
  std::mt19937_64 random(1);
  std::normal_distribution<double> normal;
  Eigen::VectorXcd w(n);
  for(Eigen::Index i = 0; i < n; ++i) w[i] = Complex(normal(random), normal(random));
  V_storage.col(0) = w / d_norm(w);
  int columns = 1;
  for(int k = 0; k < max_steps; ++k)
  {
    w = solver.solve(Eigen::VectorXcd(d.cwiseProduct(V_storage.col(k))));
    const double entry = d_norm(w);
    Eigen::VectorXcd coefficients = Eigen::VectorXcd::Zero(columns);
    // The recurrence: the last two vectors, each subtracted in turn.
    for(int i = std::max(0, k - 1); i <= k; ++i)
    {
      const Complex c = V_storage.col(i).dot(d.cwiseProduct(w));
      w -= c * V_storage.col(i);
      coefficients[i] += c;
    }
    // Full reorthogonalisation, repeated while a pass removes more than half of what is left.
    for(int pass = 0; pass < 3; ++pass)
    {
      const double before = d_norm(w);
      const Eigen::VectorXcd c = V_storage.leftCols(columns).adjoint() * d.cwiseProduct(w);
      w.noalias() -= V_storage.leftCols(columns) * c;
      coefficients += c;
      if(d_norm(w) > 0.5 * before) break;
    }
    const double beta = d_norm(w);
    T.col(k).head(columns) = coefficients;
    T(k + 1, k) = beta;
    // Nothing new left of the vector (relative to its length): the space is invariant.
    if(!(beta > 1e-10 * entry)) throw Numerical_failure("smoothest n-field: the Krylov space closed");
    if(columns == V_storage.cols()) V_storage.conservativeResize(Eigen::NoChange, 2 * columns);
    V_storage.col(columns++) = w / beta;

    // The Ritz pair of the largest theta in the space of the first k + 1 vectors, every other
    // step (its estimate costs a product with A).
    if(k < 8 || k % 2) continue;
    const Eigen::Index m = k + 1;
    const Complex_matrix Tk = T.topLeftCorner(m, m);
    const Eigen::SelfAdjointEigenSolver<Complex_matrix> ritz(0.5 * (Tk + Tk.adjoint()));
    const Eigen::VectorXcd y = ritz.eigenvectors().col(m - 1);
    const Eigen::VectorXcd next = A * V_storage.col(k + 1);
    const double estimate = beta * std::abs(y[m - 1]) * std::sqrt(next.cwiseAbs2().dot(d_inverse));
    if(!(estimate <= tolerance)) continue;
    Eigen::VectorXcd x = V_storage.leftCols(m) * y;
    x /= d_norm(x);
    const Eigen::VectorXcd Ax = A * x;
    const double lambda = std::real(x.dot(Ax));
    // The residual of the symmetric form D^-1/2 A D^-1/2, relative to lambda (x is D-unit).
    const double residual = std::sqrt((Ax - lambda * d.cwiseProduct(x)).cwiseAbs2().dot(d_inverse)) / lambda;
    if(residual <= tolerance) return x;
  }
  throw Numerical_failure("smoothest n-field: Lanczos did not converge in " + std::to_string(max_steps) + " steps");
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
  Eigen::VectorXcd z;
  try
  {
    z = lowest_by_lanczos(A, d, options.tolerance);
  }
  catch(const Numerical_failure&)
  {
    // S_n nearly singular (a holonomy close to trivial) or slow convergence: the slicing
    // eigensolver copes with both (its complex Hermitian path: each eigenvalue once).
    Model_reduction::Eigensolver_options eigen_options;
    eigen_options.tolerance = options.tolerance;
    z = Model_reduction::lowest_eigenpairs(A, d, 1, Eigen::MatrixXcd(), eigen_options).vectors.col(0);
  }
  // The real layout: face i at rows 2i (real part) and 2i + 1 (imaginary part).
  Eigen::VectorXd x(2 * m);
  for(Eigen::Index i = 0; i < m; ++i)
  {
    x[2 * i] = z[i].real();
    x[2 * i + 1] = z[i].imag();
  }
  return x;
}

} // namespace

Eigen::VectorXd smoothest_n_field(const N_field_operators& ops, const Smoothest_n_field_options& options)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  const int nf = mesh.number_of_faces();
  const Eigen::VectorXd& mass = ops.masses();
  double area = 0;
  for(int f = 0; f < nf; ++f) area += mesh.face_area(f);

  // A NaN tolerance is never met: Lanczos would run out of steps and blame itself.
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
