// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_SPLINE_H
#define CGAL_TANGENT_VECTOR_FIELDS_N_FIELD_SPLINE_H

/// \file N_field_spline.h
/// n-field splines on a triangle mesh (SPEC 10): constraints given by mesh elements and
/// 3D vectors, the field out as 3D vectors; reduced on an n-field spectral basis (real-time
/// edits) or at full resolution (exact); and a one-shot function.

#include <CGAL/Tangent_vector_fields/N_field_spline_solver.h>
#include <CGAL/Tangent_vector_fields/internal/Answering_spline.h>
#include <CGAL/Tangent_vector_fields/smoothest_n_field.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// \brief Design of an n-direction field from constraints: minimises
/// `E_m(z) + omega E_D(z)` (m = 2 by default, the higher-order energy `E_B`; m = 1 with
/// omega = 0 is the classical first-order design) subject to the constraints.
///
/// Named parameters of the constructor:
/// - `number_of_eigenfields` (int, default 0): 0 solves at full resolution (exact); `d > 0`
///   computes the `d` lowest eigenpairs of `L_n` (rounded up to even) and solves in their
///   span (microseconds per edit; `basis()` can be saved with `N_field_basis::save`);
/// - `spline_tension` (double, default 0): `omega`, for the mesh scaled to unit area;
/// - `n_field_boundary` (`N_field_boundary`, default `free`);
/// - `alignment_field_map`: a readable face map of `Vector_3`, any one of the n vectors of a
///   guide field per face (its length weights it), e.g. from `curvature_direction_field`;
///   the energy gains `s |z - guide|^2` (see `N_field_alignment`);
/// - `alignment_weight` (double, default 1): `s`, for the mesh scaled to unit area;
/// - `progress_callback`, `eigensolver_tolerance`: for the basis;
/// - the named parameters of `Discrete_operators`.
/// The energy order `m` and prescribed singularities built into the connection (see
/// `N_field_operators`) are constructor arguments.
template <class TriangleMesh>
class N_field_spline
  : public internal::Spline_answers<Reduced_n_field_spline_solver, Full_n_field_spline_solver, N_field_spline_solver>
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  /// \param singularities prescribed singularities `(vertex, k)`, index `k / n`, built into the
  ///        connection (see `N_field_operators`): the smooth fields have exactly them.
  template <class NamedParameters = parameters::Default_named_parameters>
  N_field_spline(const TriangleMesh& mesh, int n, const NamedParameters& np = parameters::default_values(),
                 const std::vector<std::pair<vertex_descriptor, int>>& singularities = {}, int order = 2)
    : adapter_(std::make_shared<internal::Mesh_adapter<TriangleMesh>>(mesh, np))
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
    auto fim = CGAL::get_initialized_face_index_map(mesh, np);
    vertex_index_ = [vim](vertex_descriptor v) { return static_cast<int>(get(vim, v)); };
    face_index_ = [fim](face_descriptor f) { return static_cast<int>(get(fim, f)); };
    N_field_options options;
    options.boundary = choose_parameter(get_parameter(np, internal_np::n_field_boundary), N_field_boundary::free);
    for(const auto& [v, k] : singularities) options.singularities.push_back({vertex_index_(v), k});
    operators_ = std::make_shared<const N_field_operators>(
        std::make_shared<const Operator_matrices>(adapter_->intrinsic_mesh()), n, options);
    Spline_options spline_options;
    spline_options.omega = choose_parameter(get_parameter(np, internal_np::spline_tension), 0.);
    const int d = choose_parameter(get_parameter(np, internal_np::number_of_eigenfields), 0);
    if(d > 0)
    {
      Basis_options basis_options;
      basis_options.tolerance = choose_parameter(get_parameter(np, internal_np::eigensolver_tolerance), 1e-10);
      basis_options.progress = choose_parameter(get_parameter(np, internal_np::progress_callback),
                                                std::function<void(const Spectral_progress&)>());
      basis_ = std::make_shared<const N_field_basis>(operators_, d, basis_options);
      make_reduced(basis_->size(), spline_options, order, alignment(np));
    }
    else
      spline_ = std::make_unique<Answering>(
          std::make_unique<Full_n_field_spline_solver>(operators_, spline_options, order, alignment(np)));
  }

  /// Reduced on a basis computed before (e.g. `N_field_basis::load`ed for this mesh, with
  /// the same index maps): real-time edits without the eigenproblem.  `d`: elements used (0: all).
  template <class NamedParameters = parameters::Default_named_parameters>
  N_field_spline(const TriangleMesh& mesh, std::shared_ptr<const N_field_basis> basis, int d = 0,
                 const NamedParameters& np = parameters::default_values(), int order = 2)
    : adapter_(std::make_shared<internal::Mesh_adapter<TriangleMesh>>(mesh, np)), basis_(std::move(basis))
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    if(!basis_) throw Invalid_input("n-field spline: no basis given");
    auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
    auto fim = CGAL::get_initialized_face_index_map(mesh, np);
    vertex_index_ = [vim](vertex_descriptor v) { return static_cast<int>(get(vim, v)); };
    face_index_ = [fim](face_descriptor f) { return static_cast<int>(get(fim, f)); };
    if(basis_->operators().mesh().number_of_faces() != adapter_->intrinsic_mesh()->number_of_faces())
      throw Invalid_input("n-field spline: the basis belongs to a mesh with another number of faces");
    operators_ = basis_->shared_operators();
    Spline_options spline_options;
    spline_options.omega = choose_parameter(get_parameter(np, internal_np::spline_tension), 0.);
    make_reduced(d, spline_options, order, alignment(np));
  }

  /// The n-field's vectors in face `f` are `v` (projected) and its turns by `2 pi j / n`.
  template <class Vector_3>
  Constraint_id add_vector(face_descriptor f, const Vector_3& v)
  {
    return add(N_field_constraint::vector_in_face(face_index_(f), triple(v)));
  }
  /// The n-field's power in face `f` is a real multiple of that of `d` (see
  /// `N_field_constraint::direction_in_face` for what that allows when n > 1).
  template <class Vector_3>
  Constraint_id add_direction(face_descriptor f, const Vector_3& d)
  {
    return add(N_field_constraint::direction_in_face(face_index_(f), triple(d)));
  }
  /// Index `k / n` at vertex `v` by one-ring relations (editable in real time on a basis;
  /// see `N_field_constraint::singularity_at_vertex` for what they do not prevent).
  Constraint_id add_singularity(vertex_descriptor v, int k)
  {
    return add(N_field_constraint::singularity_at_vertex(vertex_index_(v), k));
  }
  Constraint_id add(const N_field_constraint& c) { return spline_->add(c); }
  /// Adds several (one batch of pull-backs at full resolution); all or nothing.
  std::vector<Constraint_id> add(const std::vector<N_field_constraint>& c) { return spline_->add(c); }

  /// New vector of a vector constraint: a value edit (no new rows).
  template <class Vector_3>
  void set_vector(Constraint_id id, const Vector_3& v)
  {
    N_field_constraint c = spline_->constraint(id);
    c.vector = triple(v);
    spline_->change(id, c);
  }
  void remove(Constraint_id id) { spline_->remove(id); }

  /// Writes the field into a face map: per face the first of its n vectors, of length the
  /// field's magnitude (`unit`: length 1; faces where the field vanishes get 0).  The exact
  /// spline when it is known (always at full resolution; on a basis once refined), else the
  /// reduced one; `which` (optional) receives which one it is.
  template <class FaceVectorMap>
  void field(FaceVectorMap out, bool unit = false, Spline_answer* which = nullptr) const
  {
    const Eigen::VectorXd z = spline_->field(which);
    adapter_->write_field(operators_->to_vectors(unit ? operators_->normalized(z) : z), out);
  }
  /// Writes the index `k` (index `k / n`) of every vertex into a vertex map; returns the
  /// singular vertices.
  template <class VertexIntMap>
  std::vector<std::pair<vertex_descriptor, int>> singularities(VertexIntMap index) const
  {
    const std::vector<int> k = n_field_indices(*operators_, spline_->field());
    std::vector<std::pair<vertex_descriptor, int>> singular;
    for(std::size_t v = 0; v < k.size(); ++v)
    {
      put(index, adapter_->vertices()[v], k[v]);
      if(k[v] != 0) singular.emplace_back(adapter_->vertices()[v], k[v]);
    }
    return singular;
  }

  const N_field_operators& operators() const { return *operators_; }
  /// The basis of a reduced spline (null at full resolution).
  std::shared_ptr<const N_field_basis> basis() const { return basis_; }

private:
  template <class NamedParameters>
  N_field_alignment alignment(const NamedParameters& np) const
  {
    N_field_alignment a;
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::alignment_field_map_t>::value)
    {
      a.guide = operators_->from_vectors(adapter_->read_field(parameters::get_parameter(np, internal_np::alignment_field_map)));
      a.weight = parameters::choose_parameter(parameters::get_parameter(np, internal_np::alignment_weight), 1.);
    }
    return a;
  }

  template <class T>
  static std::array<double, 3> triple(const T& v)
  {
    return internal::to_array(v);
  }

  typedef internal::Answering_spline<Reduced_n_field_spline_solver, Full_n_field_spline_solver> Answering;

  // Reduced on `basis_`, refined by a full solver of the same energy made when first needed.
  void make_reduced(int d, const Spline_options& options, int order, const N_field_alignment& alignment)
  {
    std::shared_ptr<const N_field_operators> operators = operators_;
    spline_ = std::make_unique<Answering>(
        std::make_unique<Reduced_n_field_spline_solver>(basis_, d, options, order, alignment),
        [operators, options, order, alignment](double omega) {
          Spline_options with = options;
          with.omega = omega;
          return std::make_unique<Full_n_field_spline_solver>(operators, with, order, alignment);
        });
  }

  std::shared_ptr<internal::Mesh_adapter<TriangleMesh>> adapter_;
  std::shared_ptr<const N_field_operators> operators_;
  std::shared_ptr<const N_field_basis> basis_;
  std::function<int(vertex_descriptor)> vertex_index_;
  std::function<int(face_descriptor)> face_index_;
};

/// \brief One-shot n-field spline at full resolution, written into `out` (first vector per
/// face, with the field's magnitude).
/// \param constraints index-based constraints (see `N_field_constraint`)
/// \param np `spline_tension`, `n_field_boundary`, `alignment_field_map`, `alignment_weight` and
///        the named parameters of `Discrete_operators`
/// \returns the report; \throws Infeasible_constraints if the constraints contradict each other
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
Spline_report n_field_spline(const TriangleMesh& mesh, int n, const std::vector<N_field_constraint>& constraints,
                             FaceVectorMap out, const NamedParameters& np = parameters::default_values())
{
  N_field_spline<TriangleMesh> spline(mesh, n, np);
  spline.add(constraints);
  spline.field(out);
  return spline.report();
}

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
