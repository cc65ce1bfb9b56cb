// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_ELASTIC_DEFORMER_H
#define CGAL_VIBRATION_MODES_ELASTIC_DEFORMER_H

/// \file Elastic_deformer.h
/// Elastic modelling with handles (SPEC 13, "Uses"): the displacement of least linearised
/// elastic energy `u^T H u` that moves every handle by its target, in the span of modes
/// (`Reduced_elastic_deformer`, answers a drag in `O(k x handles)`) or at full resolution
/// (`Full_elastic_deformer`, CHOLMOD).
///
/// A handle is a set of vertices; its constraint is hard: the mass-weighted mean displacement
/// of its vertices equals the target (`group_size` equations per handle; for a handle of one
/// vertex, that vertex's displacement).  With the handles' equations `C u = d` the problem
/// `min u^T H u s.t. C u = d` is solved through `A = H + rho C^T C` (same minimiser on
/// `C u = d`, where `u^T C^T C u = |d|^2` is constant; positive definite exactly when no
/// zero-energy motion leaves the handles in place) and the Schur complement:
/// `u = A^-1 C^T (C A^-1 C^T)^-1 d`.  Everything but the last product with `d` is
/// precomputed when the handles are set.

#include <CGAL/Vibration_modes/Mode_problem.h>
#include <CGAL/Vibration_modes/Modes.h>
#include <CGAL/Vibration_modes/named_function_parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <CGAL/Model_reduction/Sparse_spd_solver.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace Vibration_modes {

/// The handles' equations `C u = d` over the free unknowns of a problem.
struct Handle_constraints
{
  /// `group_size * handles` rows over the free unknowns: row `g * j + c` averages coordinate
  /// `c` of handle `j`'s vertices with their masses as weights.
  Eigen::SparseMatrix<double> C;
  int group_size = 3;
  int number_of_handles() const { return int(C.rows()) / group_size; }
};

/// The equations of `handles` (vertex indices of the problem's mesh).
/// \throws Invalid_input naming the handle for an empty handle, a vertex outside the mesh,
///         or a vertex that is pinned or in no triangle (it cannot move).
Handle_constraints handle_constraints(const Mode_problem& problem, const std::vector<std::vector<int>>& handles);

/// The handles of `mesh` (a range of ranges of vertex descriptors) as the vertex indices the
/// deformers take (those of the vertex index map, the order of `mesh_mode_problem`).
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_index_map} as in CGAL \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \code
/// VM::Reduced_elastic_deformer d(p, modes.vectors, VM::handle_vertex_indices(mesh, std::vector<std::vector<vertex_descriptor>>{{top}, {tail}}));
/// \endcode
template <class TriangleMesh, class HandleRanges, class NamedParameters = parameters::Default_named_parameters>
std::vector<std::vector<int>> handle_vertex_indices(const TriangleMesh& mesh, const HandleRanges& handles,
                                                    const NamedParameters& np = parameters::default_values())
{
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  std::vector<std::vector<int>> indices;
  for(const auto& handle : handles)
  {
    indices.emplace_back();
    for(const auto& v : handle) indices.back().push_back(int(get(vim, v)));
  }
  return indices;
}

/// Precomputed reduced modelling in the span of the kernel of `H` (if `with_kernel`) and `k`
/// modes: `q = G d` with `G` of size `k x (group_size handles)`, so a drag costs `O(k x handles)`.
class Reduced_elastic_deformer
{
public:
  /// \throws Invalid_input as `handle_constraints`, for modes of the wrong height or with
  ///         NaN, when the handles leave a zero-energy motion of the basis free (a free body
  ///         needs three handles not on one line, or pins), or when the basis cannot meet
  ///         that many handle equations (more equations than basis vectors, or dependent ones).
  Reduced_elastic_deformer(const Mode_problem& problem, const Eigen::MatrixXd& modes,
                           const std::vector<std::vector<int>>& handles, bool with_kernel = true);

  int number_of_handles() const { return constraints_.number_of_handles(); }
  /// Basis size: kernel columns + modes.
  Eigen::Index dimension() const { return B_.cols(); }

  /// The basis coordinates for handle targets (`group_size x handles`, column `j` the
  /// displacement of handle `j`): `O(k x handles)`.
  /// \throws Invalid_input for targets of the wrong size or not finite.
  const Eigen::VectorXd& drag(const Eigen::MatrixXd& targets);
  /// The coordinates of the last drag.
  const Eigen::VectorXd& coordinates() const { return q_; }
  /// The displacement of the last drag over all `full_size` unknowns (`O(n k)`).
  Eigen::VectorXd displacement() const;
  /// Its energy `u^T H u`.
  double energy() const { return q_.dot(Hr_ * q_); }

private:
  Mode_problem layout_; // the free unknowns and full size only, for expand()
  Handle_constraints constraints_;
  Eigen::MatrixXd B_, Hr_, G_;
  Eigen::VectorXd q_;
};

/// The same problem at full resolution: factors `H + rho C^T C` once and keeps
/// `A^-1 C^T (C A^-1 C^T)^-1` (`n x group_size handles`).
class Full_elastic_deformer
{
public:
  /// \throws Invalid_input as `handle_constraints` or when the handles leave a zero-energy
  ///         motion free (see `Reduced_elastic_deformer`).
  Full_elastic_deformer(const Mode_problem& problem, const std::vector<std::vector<int>>& handles);
  int number_of_handles() const { return constraints_.number_of_handles(); }
  /// The displacement over all `full_size` unknowns for handle targets as in `Reduced_elastic_deformer::drag`.
  Eigen::VectorXd deform(const Eigen::MatrixXd& targets) const;

private:
  Mode_problem layout_; // the free unknowns and full size only, for expand()
  Handle_constraints constraints_;
  Eigen::MatrixXd G_;
};

} // namespace Vibration_modes
} // namespace CGAL

#endif
