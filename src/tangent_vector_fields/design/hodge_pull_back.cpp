// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/internal/Hodge_pull_back.h>

#include <algorithm>
#include <chrono>
#include <future>
#include <mutex>
#include <thread>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

// The screened Laplacians `W + a M` (vertices in some face) and `W* + a M*`, with
// `a = omega` (splines) or `1 / omega` (soft design: `M + omega W = omega (W + M / omega)`).
struct Hodge_pull_back::Screened
{
  std::vector<int> vertices;
  Model_reduction::Sparse_spd_solver vertex_solver, edge_solver;
  double shift = 0;     // a
  double rhs_scale = 1; // 1, or 1 / omega
};

// G and G* (interior edges) by rows: the entries of a constraint row's faces.
struct Hodge_pull_back::Transposes
{
  Eigen::SparseMatrix<double, Eigen::RowMajor> G, G_star;
};

const Hodge_pull_back::Transposes& Hodge_pull_back::transposes() const
{
  std::call_once(transposes_made_, [this] {
    transposes_ = std::make_unique<Transposes>();
    transposes_->G = hodge_->operators().G();
    transposes_->G_star = hodge_->operators().G_star_interior();
  });
  return *transposes_;
}

Hodge_pull_back::Hodge_pull_back(std::shared_ptr<const Hodge_solver> hodge, Design_energy energy, double omega,
                                 double length_unit)
  : hodge_(std::move(hodge)), energy_(energy), omega_(omega), u_(length_unit)
{}

Hodge_pull_back::~Hodge_pull_back() = default;

double Hodge_pull_back::factor() const
{
  if(factored_) return 0;
  const auto start = std::chrono::steady_clock::now();
  const Operator_matrices& ops = hodge_->operators();
  // W and W* (pinned) are factored by the Hodge solver on first use; solving an
  // empty block makes sure they exist, so that their cost is counted here.
  hodge_->solve_vertex_laplacian(Eigen::MatrixXd::Zero(ops.mesh().number_of_vertices(), 1));
  hodge_->solve_edge_laplacian(Eigen::MatrixXd::Zero(ops.mesh().number_of_interior_edges(), 1));
  if(omega_ > 0)
  {
    screened_ = std::make_unique<Screened>();
    Screened& s = *screened_;
    s.shift = energy_ == Design_energy::biharmonic ? omega_ : 1 / omega_;
    s.rhs_scale = energy_ == Design_energy::biharmonic ? 1 : 1 / omega_;
    const Intrinsic_mesh& mesh = ops.mesh();
    std::vector<int> index(mesh.number_of_vertices(), -1);
    for(int v = 0; v < mesh.number_of_vertices(); ++v)
      if(!mesh.is_isolated_vertex(v))
      {
        index[v] = static_cast<int>(s.vertices.size());
        s.vertices.push_back(v);
      }
    const int n = static_cast<int>(s.vertices.size());
    std::vector<Eigen::Triplet<double>> t;
    const Eigen::SparseMatrix<double>& W = ops.W();
    for(int k = 0; k < W.outerSize(); ++k)
      for(Eigen::SparseMatrix<double>::InnerIterator it(W, k); it; ++it)
        if(index[it.row()] >= 0 && index[it.col()] >= 0) t.emplace_back(index[it.row()], index[it.col()], it.value());
    const double u2 = u_ * u_;
    for(int i = 0; i < n; ++i) t.emplace_back(i, i, s.shift * (ops.vertex_masses()[s.vertices[i]] / u2));
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    s.vertex_solver.factor(A, "W + a M (field design)");
    const Eigen::VectorXd edge_masses = ops.all_to_interior_edges(ops.edge_masses()) / u2;
    Eigen::SparseMatrix<double> A_star = ops.W_star();
    for(int i = 0; i < A_star.rows(); ++i) A_star.coeffRef(i, i) += s.shift * edge_masses[i];
    s.edge_solver.factor(A_star, "W* + a M* (field design)");
  }
  factored_ = true;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <class Solve, class Screened_solve>
Eigen::MatrixXd Hodge_pull_back::chain(const Eigen::MatrixXd& rhs, const Eigen::SparseMatrix<double>& laplacian,
                                       const Eigen::VectorXd& masses, const Solve& solve,
                                       const Screened_solve& screened, double* residual) const
{
  auto relative = [](const Eigen::MatrixXd& r, const Eigen::MatrixXd& b) {
    return b.norm() > 0 ? r.norm() / b.norm() : r.norm();
  };
  // A part without right-hand side (a divergence row has no coexact part) costs no solve,
  // except where the solver's precision is being measured.
  if(!residual && rhs.isZero(0)) return Eigen::MatrixXd::Zero(rhs.rows(), rhs.cols());
  const Eigen::MatrixXd f = solve(rhs);
  const Eigen::MatrixXd b2 = masses.asDiagonal() * f;
  const Eigen::MatrixXd q = solve(b2);
  // Solver precision: residuals of the second-order systems, over the whole block
  // (a column may have a zero right-hand side: curl rows have no exact part).
  if(residual) *residual = std::max({*residual, relative(laplacian * f - rhs, rhs), relative(laplacian * q - b2, b2)});
  if(energy_ == Design_energy::dirichlet && omega_ == 0) return q;
  Eigen::MatrixXd b3 = masses.asDiagonal() * q;
  if(omega_ > 0)
  {
    b3 *= screened_->rhs_scale;
    const Eigen::MatrixXd p = screened(b3);
    if(residual)
      *residual = std::max(*residual, relative(laplacian * p + screened_->shift * (masses.asDiagonal() * p) - b3, b3));
    return p;
  }
  const Eigen::MatrixXd p = solve(b3);
  if(residual) *residual = std::max(*residual, relative(laplacian * p - b3, b3));
  return p;
}

Eigen::MatrixXd Hodge_pull_back::apply(const Eigen::SparseMatrix<double>& R, Eigen::MatrixXd& harmonic, double& residual) const
{
  factor();
  const Operator_matrices& ops = hodge_->operators();
  const Eigen::Index m = R.cols();
  const double u = u_;
  const Eigen::VectorXd M = ops.vertex_masses() / (u * u);
  const Eigen::VectorXd M_star = ops.all_to_interior_edges(ops.edge_masses()) / (u * u);
  // Exact part: f from W f = G^T MX (MX^-1 r^T) = G^T r^T.
  auto vertex_solve = [&](const Eigen::MatrixXd& b) { return hodge_->solve_vertex_laplacian(b); };
  auto vertex_screened = [&](const Eigen::MatrixXd& b) {
    const std::vector<int>& vs = screened_->vertices;
    Eigen::MatrixXd rhs(vs.size(), b.cols());
    for(std::size_t i = 0; i < vs.size(); ++i) rhs.row(i) = b.row(vs[i]);
    const Eigen::MatrixXd x = screened_->vertex_solver.solve(rhs);
    Eigen::MatrixXd p = Eigen::MatrixXd::Zero(b.rows(), b.cols());
    for(std::size_t i = 0; i < vs.size(); ++i) p.row(vs[i]) = x.row(i);
    return p;
  };
  // The rows touch a few faces each: G^T r and G*^T J r from the rows of G and G* that
  // the rows' faces own (a pass over all of G costs 25 ms at 346k faces).
  const Transposes& t = transposes();
  Eigen::MatrixXd GtR = Eigen::MatrixXd::Zero(t.G.cols(), m), GstR = Eigen::MatrixXd::Zero(t.G_star.cols(), m);
  typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Rows;
  for(Eigen::Index j = 0; j < m; ++j)
    for(Eigen::SparseMatrix<double>::InnerIterator it(R, j); it; ++it)
    {
      const Eigen::Index i = it.row();
      for(Rows::InnerIterator g(t.G, i); g; ++g) GtR(g.col(), j) += g.value() * it.value() * u;
      // Coexact part: g from W* g = -G*^T J r^T, with J (a, b) = (-b, a) in each face's frame:
      // (J r)_i is -r_{i+1} for even i, r_{i-1} for odd i.
      const Eigen::Index rotated = i % 2 == 0 ? i + 1 : i - 1;
      const double sign = i % 2 == 0 ? 1 : -1;
      for(Rows::InnerIterator g(t.G_star, rotated); g; ++g) GstR(g.col(), j) -= sign * g.value() * it.value() * u;
    }
  // A part that is rounding noise (a curl row has no exact part, a divergence row no
  // coexact one) is zero: solving for it would only measure the noise.
  for(Eigen::Index j = 0; j < m; ++j)
  {
    const double exact = GtR.col(j).norm(), coexact = GstR.col(j).norm();
    if(exact < 1e-13 * coexact) GtR.col(j).setZero();
    if(coexact < 1e-13 * exact) GstR.col(j).setZero();
  }
  // The residuals (three sparse products per part) are measured on the first block after a
  // factorisation: they tell the solver's precision, which later blocks share.
  const bool measure = !residual_measured_.exchange(true);
  double exact_residual = 0, coexact_residual = 0;
  auto exact_fields = [&] { // G p
    const Eigen::MatrixXd p = chain(GtR, ops.W(), M, vertex_solve, vertex_screened, measure ? &exact_residual : nullptr);
    return Eigen::MatrixXd((ops.G() * p) * u);
  };
  auto edge_solve = [&](const Eigen::MatrixXd& b) { return hodge_->solve_edge_laplacian(b); };
  auto edge_screened = [&](const Eigen::MatrixXd& b) { return screened_->edge_solver.solve(b); };
  auto coexact_fields = [&] { // J G* p*
    const Eigen::MatrixXd p_star =
        chain(GstR, ops.W_star(), M_star, edge_solve, edge_screened, measure ? &coexact_residual : nullptr);
    Eigen::MatrixXd Gp = (ops.G_star_interior() * p_star) * u;
    for(Eigen::Index j = 0; j < Gp.cols(); ++j) Gp.col(j) = ops.rotate(Eigen::VectorXd(Gp.col(j)));
    return Gp;
  };
  // The two chains share nothing (each its own factorisations and lock): on a large mesh the
  // exact one runs on a second thread while this one does the coexact one (346k faces, two
  // rows: 110 ms and 295 ms one after the other, 190 ms side by side).  A thread costs more
  // than both chains on a small mesh.
  const bool side_by_side = ops.mesh().number_of_faces() >= 10000 && std::thread::hardware_concurrency() > 1;
  std::future<Eigen::MatrixXd> exact_part;
  if(side_by_side) exact_part = std::async(std::launch::async, exact_fields);
  Eigen::MatrixXd Y = coexact_fields();
  Y += side_by_side ? exact_part.get() : exact_fields();
  residual = std::max({residual, exact_residual, coexact_residual});
  const int nh = hodge_->harmonic_dimension();
  harmonic = nh > 0 ? Eigen::MatrixXd((R.transpose() * hodge_->harmonic_basis()).transpose() * u) : Eigen::MatrixXd(0, m);
  return Y;
}

Eigen::MatrixXd Hodge_pull_back::apply_energy(const Eigen::MatrixXd& X) const
{
  const Operator_matrices& ops = hodge_->operators();
  // In the length unit: S is scale-free, MX / u^2 near 1.
  const Eigen::MatrixXd SX = ops.S() * X;
  const Eigen::MatrixXd BX = ops.S() * ((ops.field_masses() / (u_ * u_)).cwiseInverse().asDiagonal() * SX);
  if(energy_ == Design_energy::biharmonic) return omega_ > 0 ? Eigen::MatrixXd(BX + omega_ * SX) : BX;
  return omega_ > 0 ? Eigen::MatrixXd(SX + omega_ * BX) : SX;
}

Eigen::VectorXd Hodge_pull_back::harmonic_field(const Eigen::VectorXd& z) const
{
  return hodge_->harmonic_basis() * (z * u_);
}

double Hodge_pull_back::harmonic_squared_norm(const Eigen::VectorXd& x) const
{
  if(hodge_->harmonic_dimension() == 0) return 0;
  const Eigen::VectorXd& masses = hodge_->operators().field_masses();
  return (hodge_->harmonic_basis().transpose() * (masses / (u_ * u_)).cwiseProduct(x) * u_).squaredNorm();
}

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL
