// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Model_reduction/internal/compressed_matrix.h>

#include <Eigen/Dense>

#include <mutex>
#include <optional>
#include <random>
#include <sstream>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

typedef Eigen::SparseMatrix<double> Sparse_matrix;

// Rows and columns of A kept by `unknown` (>= 0: new index, increasing), others dropped.
Sparse_matrix principal_submatrix(const Sparse_matrix& A, const std::vector<int>& unknown, int m)
{
  std::vector<int> outer(m + 1, 0), inner;
  std::vector<double> values;
  inner.reserve(A.nonZeros());
  values.reserve(A.nonZeros());
  for(int c = 0; c < A.outerSize(); ++c)
  {
    if(unknown[c] < 0) continue;
    for(Sparse_matrix::InnerIterator it(A, c); it; ++it)
      if(unknown[it.row()] >= 0)
      {
        inner.push_back(unknown[it.row()]);
        values.push_back(it.value());
      }
    outer[unknown[c] + 1] = static_cast<int>(inner.size());
  }
  return Model_reduction::internal::compressed_matrix(m, m, outer, inner, values);
}

// A linear system on a subset of the unknowns (the others are pinned to zero).
struct Pinned_system
{
  std::vector<int> unknown; // element -> unknown index, -1 when pinned or unused
  int size = 0;
  Model_reduction::Sparse_spd_solver solver;

  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const
  {
    Eigen::MatrixXd reduced(size, rhs.cols());
    for(std::size_t i = 0; i < unknown.size(); ++i)
      if(unknown[i] >= 0) reduced.row(unknown[i]) = rhs.row(i);
    const Eigen::MatrixXd x = solver.solve(reduced);
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(rhs.rows(), rhs.cols());
    for(std::size_t i = 0; i < unknown.size(); ++i)
      if(unknown[i] >= 0) full.row(i) = x.row(unknown[i]);
    return full;
  }
};

// Subtracts from each column its mass-weighted mean over every group (group -1 is left alone).
void remove_group_means(Eigen::MatrixXd& X, const std::vector<int>& group, int number_of_groups,
                        const Eigen::VectorXd& mass)
{
  Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(number_of_groups, X.cols());
  Eigen::VectorXd weights = Eigen::VectorXd::Zero(number_of_groups);
  // Relative masses: area times value would overflow on a huge mesh (~size^3).
  const double unit = mass.size() > 0 && mass.maxCoeff() > 0 ? mass.maxCoeff() : 1.;
  for(std::size_t i = 0; i < group.size(); ++i)
    if(group[i] >= 0)
    {
      sums.row(group[i]) += (mass[i] / unit) * X.row(i);
      weights[group[i]] += mass[i] / unit;
    }
  for(std::size_t i = 0; i < group.size(); ++i)
    if(group[i] >= 0 && weights[group[i]] > 0) X.row(i) -= sums.row(group[i]) / weights[group[i]];
}

} // namespace

struct Hodge_solver::Impl
{
  // One lock per factorisation: CHOLMOD's workspace is not thread-safe, and the vertex and
  // edge systems may be solved at the same time from two threads.
  std::mutex vertex_mutex, edge_mutex, harmonic_mutex;
  std::optional<Pinned_system> vertex_system; // W on vertices
  std::optional<Pinned_system> edge_system;   // W* on interior edges
  std::optional<Eigen::MatrixXd> harmonic_basis;
  Eigen::VectorXd rank_spectrum;
};

Hodge_solver::Hodge_solver(std::shared_ptr<const Operator_matrices> operators)
  : ops_(std::move(operators)), impl_(new Impl)
{}

Hodge_solver::~Hodge_solver() = default;

int Hodge_solver::harmonic_dimension() const { return ops_->mesh().topology().harmonic_dimension(); }

bool Hodge_solver::has_potential_factorization() const { return impl_->vertex_system.has_value(); }
bool Hodge_solver::has_copotential_factorization() const { return impl_->edge_system.has_value(); }

Eigen::MatrixXd Hodge_solver::solve_vertex_laplacian(const Eigen::MatrixXd& b) const
{
  const Intrinsic_mesh& mesh = ops_->mesh();
  const int nv = mesh.number_of_vertices();
  std::unique_lock<std::mutex> lock(impl_->vertex_mutex);
  if(!impl_->vertex_system)
  {
    // Pin the first vertex of every component; drop vertices in no face.
    Pinned_system system;
    system.unknown.assign(nv, -1);
    std::vector<char> pinned(mesh.topology().number_of_components(), 0);
    for(int v = 0; v < nv; ++v)
    {
      const int c = mesh.vertex_component(v);
      if(c < 0) continue;
      if(!pinned[c])
        pinned[c] = 1;
      else
        system.unknown[v] = system.size++;
    }
    system.solver.factor(principal_submatrix(ops_->W(), system.unknown, system.size), "the cotan matrix W");
    impl_->vertex_system = std::move(system);
  }
  Eigen::MatrixXd f = impl_->vertex_system->solve(b);
  lock.unlock();
  std::vector<int> component(nv);
  for(int v = 0; v < nv; ++v) component[v] = mesh.vertex_component(v);
  remove_group_means(f, component, mesh.topology().number_of_components(), ops_->vertex_masses());
  return f;
}

Eigen::MatrixXd Hodge_solver::solve_edge_laplacian(const Eigen::MatrixXd& b) const
{
  const Intrinsic_mesh& mesh = ops_->mesh();
  const int ni = mesh.number_of_interior_edges();
  const auto& components = mesh.topology().components;
  std::unique_lock<std::mutex> lock(impl_->edge_mutex);
  if(!impl_->edge_system)
  {
    // Pin the first interior edge of every closed component; with boundary the
    // zero boundary values already fix the constant.
    Pinned_system system;
    system.unknown.assign(ni, -1);
    std::vector<char> pinned(components.size(), 0);
    for(int i = 0; i < ni; ++i)
    {
      const int c = mesh.edge_component(mesh.interior_edges()[i]);
      if(components[c].is_closed() && !pinned[c])
        pinned[c] = 1;
      else
        system.unknown[i] = system.size++;
    }
    system.solver.factor(principal_submatrix(ops_->W_star(), system.unknown, system.size),
                         "the Crouzeix-Raviart matrix W*");
    impl_->edge_system = std::move(system);
  }
  Eigen::MatrixXd g = impl_->edge_system->solve(b);
  lock.unlock();
  std::vector<int> closed_component(ni, -1);
  Eigen::VectorXd mass(ni);
  for(int i = 0; i < ni; ++i)
  {
    const int e = mesh.interior_edges()[i];
    const int c = mesh.edge_component(e);
    closed_component[i] = components[c].is_closed() ? c : -1;
    mass[i] = ops_->edge_masses()[e];
  }
  remove_group_means(g, closed_component, static_cast<int>(components.size()), mass);
  return g;
}

// The right-hand sides G^T MX v are formed with the areas in units of the mesh's
// length unit (a power of two: exact), so that areas times values (~size^2) cannot
// overflow before G^T brings them back to ~size.
namespace {
Eigen::VectorXd unit_field_masses(const Operator_matrices& ops)
{
  const double u = ops.mesh().length_unit();
  return ops.field_masses() / u / u;
}
} // namespace

Eigen::MatrixXd Hodge_solver::potentials(const Eigen::MatrixXd& fields) const
{
  const double u = ops_->mesh().length_unit();
  return solve_vertex_laplacian((ops_->G().transpose() * (unit_field_masses(*ops_).asDiagonal() * fields)) * u * u);
}

Eigen::MatrixXd Hodge_solver::copotentials(const Eigen::MatrixXd& fields) const
{
  const Intrinsic_mesh& mesh = ops_->mesh();
  // rhs = -G*^T J MX v, one column per field.
  Eigen::MatrixXd rotated(fields.rows(), fields.cols());
  for(Eigen::Index j = 0; j < fields.cols(); ++j)
    rotated.col(j) = ops_->rotate(unit_field_masses(*ops_).cwiseProduct(fields.col(j)));
  const double u = mesh.length_unit();
  const Eigen::MatrixXd g = solve_edge_laplacian(-(ops_->G_star_interior().transpose() * rotated) * u * u);
  Eigen::MatrixXd all = Eigen::MatrixXd::Zero(mesh.number_of_edges(), fields.cols());
  for(int i = 0; i < mesh.number_of_interior_edges(); ++i) all.row(mesh.interior_edges()[i]) = g.row(i);
  return all;
}

Hodge_parts Hodge_solver::decompose(const Eigen::VectorXd& field, unsigned outputs) const
{
  if(field.size() != 2 * static_cast<Eigen::Index>(ops_->mesh().number_of_faces()))
    throw Invalid_input("the field has " + std::to_string(field.size()) + " coordinates, expected " +
                        std::to_string(2 * ops_->mesh().number_of_faces()) + " (2 per face)");
  if(!field.allFinite()) throw Invalid_input("the field has NaN or infinite entries");

  const bool need_f = outputs & (hodge_exact | hodge_harmonic | hodge_potential);
  const bool need_g = outputs & (hodge_coexact | hodge_harmonic | hodge_copotential);
  Hodge_parts parts;
  Eigen::VectorXd f, g, exact, coexact;
  if(need_f)
  {
    f = potentials(field);
    exact = ops_->G() * f;
  }
  if(need_g)
  {
    g = copotentials(field);
    coexact = ops_->rotate(ops_->G_star() * g);
  }
  // Finite input, finite operators: a non-finite part means an overflow (a field near
  // the largest double); say so instead of handing back NaNs.
  if(!f.allFinite() || !g.allFinite() || !exact.allFinite() || !coexact.allFinite())
  {
    std::ostringstream msg;
    msg << "the Hodge decomposition overflowed (non-finite potentials): the field's coordinates, up to "
        << field.cwiseAbs().maxCoeff() << ", are too large for double precision";
    throw Numerical_failure(msg.str());
  }
  if(outputs & hodge_harmonic) parts.harmonic = field - exact - coexact;
  if(outputs & hodge_exact) parts.exact = std::move(exact);
  if(outputs & hodge_coexact) parts.coexact = std::move(coexact);
  if(outputs & hodge_potential) parts.potential = std::move(f);
  if(outputs & hodge_copotential) parts.copotential = std::move(g);
  return parts;
}

const Eigen::MatrixXd& Hodge_solver::harmonic_basis(std::uint64_t seed) const
{
  // Made once; the lock keeps a second thread from reading it half made (the solves below
  // take their own locks).
  std::lock_guard<std::mutex> lock(impl_->harmonic_mutex);
  if(impl_->harmonic_basis) return *impl_->harmonic_basis;
  const int dim = harmonic_dimension();
  const Eigen::Index n = 2 * static_cast<Eigen::Index>(ops_->mesh().number_of_faces());
  if(dim == 0)
  {
    impl_->rank_spectrum = Eigen::VectorXd(0);
    impl_->harmonic_basis = Eigen::MatrixXd(n, 0);
    return *impl_->harmonic_basis;
  }
  // Harmonic parts of dim + 2 random fields (SPEC 4).
  const int m = dim + 2;
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd R(n, m);
  for(Eigen::Index j = 0; j < m; ++j)
    for(Eigen::Index i = 0; i < n; ++i) R(i, j) = normal(generator);
  const Eigen::MatrixXd P = potentials(R);
  const Eigen::MatrixXd Q = copotentials(R);
  Eigen::MatrixXd H = R - ops_->G() * P;
  const Eigen::MatrixXd GQ = ops_->G_star() * Q;
  for(Eigen::Index j = 0; j < m; ++j) H.col(j) -= ops_->rotate(GQ.col(j));

  // Rank from the singular values of sqrt(MX) H (QR, then SVD of the small R; the
  // Gram matrix would square them and hide everything below 1e-8).  The projections
  // span the harmonic space, so `dim` singular values are O(1) relative to the largest
  // and two are at the level of the solver's roundoff; the cut 1e-6 lies far from both.
  // In the length unit (exact): the singular values stay near 1 at any scale.
  const double u = ops_->mesh().length_unit();
  const Eigen::VectorXd sqrt_mass = unit_field_masses(*ops_).cwiseSqrt();
  const Eigen::MatrixXd Y = sqrt_mass.asDiagonal() * H;
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(Y);
  const Eigen::MatrixXd R_factor = qr.matrixQR().topRows(m).triangularView<Eigen::Upper>();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(R_factor, Eigen::ComputeFullV);
  const Eigen::VectorXd& singular = svd.singularValues();
  const double top = singular[0];
  Eigen::VectorXd sigma = top > 0 ? Eigen::VectorXd(singular / top) : Eigen::VectorXd::Zero(m);
  impl_->rank_spectrum = sigma;
  const double cut = 1e-6;
  int rank = 0;
  while(rank < m && sigma[rank] > cut) ++rank;
  if(rank != dim)
  {
    std::ostringstream msg;
    msg << "the harmonic space has numerical dimension " << rank << " but the topology ("
        << ops_->mesh().topology().summary() << ") predicts " << dim << "; relative singular values near the cut:";
    for(int i = std::max(0, dim - 2); i < m; ++i) msg << ' ' << sigma[i];
    throw Numerical_failure(msg.str());
  }
  Eigen::MatrixXd basis = H * svd.matrixV().leftCols(dim);
  for(int j = 0; j < dim; ++j) basis.col(j) /= singular[j];
  // A second pass (Cholesky of the new Gram matrix) brings orthonormality to roundoff.
  const Eigen::MatrixXd K2 = basis.transpose() * unit_field_masses(*ops_).asDiagonal() * basis;
  Eigen::LLT<Eigen::MatrixXd> llt(K2);
  basis = llt.matrixU().solve<Eigen::OnTheRight>(basis) / u; // orthonormal in MX, not MX / u^2
  impl_->harmonic_basis = std::move(basis);
  return *impl_->harmonic_basis;
}

const Eigen::VectorXd& Hodge_solver::harmonic_rank_spectrum() const { return impl_->rank_spectrum; }

} // namespace Tangent_vector_fields
} // namespace CGAL
