// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace CGAL {
namespace Tangent_vector_fields {


struct Full_spline_solver::Screened
{
  // Unknowns: vertices in some face, all interior edges.
  std::vector<int> vertices;
  Sparse_spd_solver vertex_solver, edge_solver;
};

Full_spline_solver::Full_spline_solver(std::shared_ptr<const Hodge_solver> hodge, const Spline_options& options)
  : Spline_solver(std::shared_ptr<const Operator_matrices>(hodge, &hodge->operators()), hodge->harmonic_dimension(),
                  options),
    hodge_(std::move(hodge))
{}

Full_spline_solver::~Full_spline_solver() = default;

void Full_spline_solver::energy_changed()
{
  screened_.reset();
  factored_ = false;
}

void Full_spline_solver::factor() const
{
  const auto start = std::chrono::steady_clock::now();
  const Operator_matrices& ops = *operators_;
  // W and W* (pinned) are factored by the Hodge solver on first use; solving an
  // empty block makes sure they exist, so that their cost is counted here.
  hodge_->solve_vertex_laplacian(Eigen::MatrixXd::Zero(ops.mesh().number_of_vertices(), 1));
  hodge_->solve_edge_laplacian(Eigen::MatrixXd::Zero(ops.mesh().number_of_interior_edges(), 1));
  if(omega_ > 0)
  {
    screened_ = std::make_unique<Screened>();
    const Intrinsic_mesh& mesh = ops.mesh();
    std::vector<int> index(mesh.number_of_vertices(), -1);
    for(int v = 0; v < mesh.number_of_vertices(); ++v)
      if(!mesh.is_isolated_vertex(v))
      {
        index[v] = static_cast<int>(screened_->vertices.size());
        screened_->vertices.push_back(v);
      }
    const int n = static_cast<int>(screened_->vertices.size());
    std::vector<Eigen::Triplet<double>> t;
    const Eigen::SparseMatrix<double>& W = ops.W();
    for(int k = 0; k < W.outerSize(); ++k)
      for(Eigen::SparseMatrix<double>::InnerIterator it(W, k); it; ++it)
        if(index[it.row()] >= 0 && index[it.col()] >= 0) t.emplace_back(index[it.row()], index[it.col()], it.value());
    const double u2 = length_unit_ * length_unit_;
    for(int i = 0; i < n; ++i) t.emplace_back(i, i, omega_ * (ops.vertex_masses()[screened_->vertices[i]] / u2));
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    screened_->vertex_solver.factor(A, "W + omega M (full spline)");
    const Eigen::VectorXd edge_masses = ops.all_to_interior_edges(ops.edge_masses()) / u2;
    Eigen::SparseMatrix<double> A_star = ops.W_star();
    for(int i = 0; i < A_star.rows(); ++i) A_star.coeffRef(i, i) += omega_ * edge_masses[i];
    screened_->edge_solver.factor(A_star, "W* + omega M* (full spline)");
  }
  factored_ = true;
  statistics_.factor_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Eigen::MatrixXd Full_spline_solver::apply_energy(const Eigen::MatrixXd& X) const
{
  const Operator_matrices& ops = *operators_;
  // In the length unit: S is scale-free, MX / u^2 near 1.
  const Eigen::MatrixXd SX = ops.S() * X;
  const double u2 = length_unit_ * length_unit_;
  Eigen::MatrixXd result = ops.S() * ((ops.field_masses() / u2).cwiseInverse().asDiagonal() * SX);
  if(omega_ > 0) result += omega_ * SX;
  return result;
}

void Full_spline_solver::pull_back(std::vector<Row>& rows) const
{
  if(rows.empty()) return;
  if(!factored_) factor();
  const auto start = std::chrono::steady_clock::now();
  const Operator_matrices& ops = *operators_;
  const int m = static_cast<int>(rows.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(space_dimension(), m);
  for(int j = 0; j < m; ++j)
    for(const auto& e : rows[j].row.entries) B(e.first, j) += e.second;

  // The mesh measured in the length unit u: G and G* times u, masses over u^2 (exact,
  // u is a power of two), so that f, q, p stay near the size of the rows instead of
  // growing like size^1, size^3, size^5.
  const double u = length_unit_;
  const Eigen::VectorXd M = ops.vertex_masses() / (u * u);
  const Eigen::VectorXd M_star = ops.all_to_interior_edges(ops.edge_masses()) / (u * u);
  // Exact part: f from W f = G^T MX u = G^T r^T, then W q = M f, (W + omega M) p = M q.
  const Eigen::MatrixXd GtB = (ops.G().transpose() * B) * u;
  const Eigen::MatrixXd f = hodge_->solve_vertex_laplacian(GtB);
  const Eigen::MatrixXd q = hodge_->solve_vertex_laplacian(M.asDiagonal() * f);
  Eigen::MatrixXd p;
  if(omega_ > 0)
  {
    const std::vector<int>& vs = screened_->vertices;
    Eigen::MatrixXd rhs(vs.size(), m);
    for(std::size_t i = 0; i < vs.size(); ++i) rhs.row(i) = M[vs[i]] * q.row(vs[i]);
    const Eigen::MatrixXd x = screened_->vertex_solver.solve(rhs);
    p = Eigen::MatrixXd::Zero(M.size(), m);
    for(std::size_t i = 0; i < vs.size(); ++i) p.row(vs[i]) = x.row(i);
  }
  else
    p = hodge_->solve_vertex_laplacian(M.asDiagonal() * q);
  Eigen::MatrixXd Y = (ops.G() * p) * u;
  // Solver precision: residuals of the second-order systems just solved, over the
  // whole block (a column may have a zero right-hand side: curl rows have no exact part).
  auto relative = [](const Eigen::MatrixXd& r, const Eigen::MatrixXd& b) {
    return b.norm() > 0 ? r.norm() / b.norm() : r.norm();
  };
  {
    const Eigen::MatrixXd& b1 = GtB;
    const Eigen::MatrixXd b2 = M.asDiagonal() * f, b3 = M.asDiagonal() * q;
    const Eigen::MatrixXd Wp = ops.W() * p + omega_ * (M.asDiagonal() * p);
    statistics_.residual = std::max({statistics_.residual, relative(ops.W() * f - b1, b1),
                                     relative(ops.W() * q - b2, b2), relative(Wp - b3, b3)});
  }
  // Coexact part: g from W* g = -G*^T J MX u = -G*^T J r^T, then the same two steps.
  Eigen::MatrixXd JB(B.rows(), m);
  for(int j = 0; j < m; ++j) JB.col(j) = ops.rotate(B.col(j));
  const Eigen::MatrixXd GstB = -(ops.G_star_interior().transpose() * JB) * u;
  const Eigen::MatrixXd g = hodge_->solve_edge_laplacian(GstB);
  const Eigen::MatrixXd q_star = hodge_->solve_edge_laplacian(M_star.asDiagonal() * g);
  const Eigen::MatrixXd p_star = omega_ > 0 ? screened_->edge_solver.solve(Eigen::MatrixXd(M_star.asDiagonal() * q_star))
                                            : hodge_->solve_edge_laplacian(M_star.asDiagonal() * q_star);
  {
    const Eigen::MatrixXd& b1 = GstB;
    const Eigen::MatrixXd b2 = M_star.asDiagonal() * g, b3 = M_star.asDiagonal() * q_star;
    const Eigen::MatrixXd Wp = ops.W_star() * p_star + omega_ * (M_star.asDiagonal() * p_star);
    statistics_.residual = std::max({statistics_.residual, relative(ops.W_star() * g - b1, b1),
                                     relative(ops.W_star() * q_star - b2, b2), relative(Wp - b3, b3)});
  }
  const Eigen::MatrixXd Gp = (ops.G_star_interior() * p_star) * u;
  for(int j = 0; j < m; ++j) Y.col(j) += ops.rotate(Gp.col(j));

  // Harmonic parts of the rows, in the basis orthonormal for MX / u^2 (u times the Hodge solver's).
  const int nh = harmonic_dimension();
  const Eigen::MatrixXd H =
      nh > 0 ? Eigen::MatrixXd((hodge_->harmonic_basis().transpose() * B) * u) : Eigen::MatrixXd(0, m);
  for(int j = 0; j < m; ++j)
  {
    rows[j].y = Y.col(j);
    rows[j].harmonic = H.col(j);
  }
  statistics_.pull_back_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double Full_spline_solver::energy(const Eigen::VectorXd& x) const
{
  if(x.squaredNorm() == 0) return 0;
  double harmonic = 0;
  if(harmonic_penalty_ > 0 && harmonic_dimension() > 0)
  {
    const double u = length_unit_;
    harmonic =
        (hodge_->harmonic_basis().transpose() * (operators_->field_masses() / (u * u)).cwiseProduct(x) * u).squaredNorm();
  }
  return x.dot(apply_energy(x).col(0)) + harmonic_penalty_ * harmonic;
}

void Full_spline_solver::add_harmonic(const Eigen::VectorXd& z, Eigen::VectorXd& x) const
{
  x += hodge_->harmonic_basis() * (z * length_unit_);
}

} // namespace Tangent_vector_fields
} // namespace CGAL
