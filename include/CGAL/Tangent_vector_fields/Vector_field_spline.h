// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_VECTOR_FIELD_SPLINE_H
#define CGAL_TANGENT_VECTOR_FIELDS_VECTOR_FIELD_SPLINE_H

/// \file Vector_field_spline.h
/// Tangent vector field splines on a triangle mesh (SPEC 7): an editor with
/// constraints given by mesh elements and 3D vectors, reduced (on a `Spectral_basis`,
/// for real-time editing) or at full resolution, and a one-shot function.

#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Spectral_basis.h>
#include <CGAL/Tangent_vector_fields/internal/Answering_spline.h>

#include <CGAL/boost/graph/helpers.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

/// \brief Interactive design of a tangent vector field from constraints.
///
/// Minimises `E_B(x) + omega E_D(x)` subject to the constraints (see `Spline_solver`
/// for the method, the treatment of harmonic fields and the error reporting).
/// Built on a mesh it solves on all `2 nf` unknowns: the exact answer.  Built on a
/// `Spectral_basis` it answers at once in the span of the basis (microseconds per edit),
/// with a guaranteed bound on how far that is from the exact spline
/// (`report().error_bound`), and gives the exact spline on request: `refine()` in this
/// thread or `refine_in_background()` on a worker, sharing the basis' factorisations
/// (see `Refining_spline_solver`).  `answer()` and `field(out, &which)` say which spline a
/// field is.
///
/// Named parameters of both constructors:
/// - `spline_tension` (double, default 0): `omega`, for the mesh scaled to unit area;
/// - `harmonic_eigenvalue` (double, default 0): energy of harmonic fields (see
///   `Spline_options::harmonic_eigenvalue`);
/// - `vertex_index_map`, `edge_index_map`, `face_index_map`: the same maps as used
///   for the basis or operators (default: the mesh's internal ones).
/// With a basis also `number_of_eigenfields` (int, default: all): use only the first
/// `d` elements.  With a mesh, the named parameters of `Discrete_operators`.
///
/// Vectors are projected onto their faces.  Points in faces are 3D points, projected
/// onto the face plane and clamped into the face.
template <class TriangleMesh>
class Vector_field_spline
  : public internal::Spline_answers<Reduced_spline_solver, Full_spline_solver, Spline_solver>
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  /// Reduced: splines in the span of `basis` (which must outlive this object).
  template <class NamedParameters = parameters::Default_named_parameters>
  explicit Vector_field_spline(const Spectral_basis<TriangleMesh>& basis,
                               const NamedParameters& np = parameters::default_values())
    : operators_(basis.operators())
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    set_index_maps(basis.operators().mesh(), np);
    const Spline_options o = options(np);
    std::shared_ptr<const Hodge_solver> hodge = basis.shared_basis()->shared_hodge_solver();
    spline_ = std::make_unique<Answering>(
        std::make_unique<Reduced_spline_solver>(basis.shared_basis(),
                                                choose_parameter(get_parameter(np, internal_np::number_of_eigenfields), 0), o),
        [hodge, o](double omega) {
          Spline_options with = o;
          with.omega = omega;
          return std::make_unique<Full_spline_solver>(hodge, with);
        });
  }

  /// Full resolution on `mesh` (which must outlive this object).
  template <class NamedParameters = parameters::Default_named_parameters>
  explicit Vector_field_spline(const TriangleMesh& mesh, const NamedParameters& np = parameters::default_values())
    : operators_(mesh, np)
  {
    set_index_maps(mesh, np);
    spline_ = std::make_unique<Answering>(
        std::make_unique<Full_spline_solver>(std::make_shared<Hodge_solver>(operators_.shared_matrices()), options(np)));
  }

  /// The field equals `v` (projected) in face `f`.
  template <class Vector_3>
  Constraint_id add_vector(face_descriptor f, const Vector_3& v)
  {
    return add(Field_constraint::vector_in_face(face_index_(f), triple(v)));
  }
  /// The field is parallel to `d` (projected) in face `f`.
  template <class Vector_3>
  Constraint_id add_direction(face_descriptor f, const Vector_3& d)
  {
    return add(Field_constraint::direction_in_face(face_index_(f), triple(d)));
  }
  /// `div_h = value` at vertex `v` (positive: a source).
  Constraint_id add_divergence(vertex_descriptor v, double value)
  {
    return add(Field_constraint::divergence_at_vertex(vertex_index_(v), value));
  }
  /// Divergence at a point of face `f`.
  template <class Point_3>
  Constraint_id add_divergence(face_descriptor f, const Point_3& p, double value)
  {
    const int i = face_index_(f);
    return add(Field_constraint::divergence_at_point(i, barycentric_coordinates(intrinsic(), i, triple(p)), value));
  }
  /// `curl*_h = value` at edge `e` (positive: counter-clockwise about the normals).
  Constraint_id add_curl(edge_descriptor e, double value)
  {
    return add(Field_constraint::curl_at_edge(edge_index_(e), value));
  }
  /// Curl at a point of face `f`.
  template <class Point_3>
  Constraint_id add_curl(face_descriptor f, const Point_3& p, double value)
  {
    const int i = face_index_(f);
    return add(Field_constraint::curl_at_point(i, barycentric_coordinates(intrinsic(), i, triple(p)), value));
  }
  /// The field is parallel to boundary edge `e`.
  Constraint_id add_boundary_alignment(edge_descriptor e)
  {
    return add(Field_constraint::boundary_alignment(intrinsic(), edge_index_(e)));
  }
  /// Adds a constraint given by indices (see `Field_constraint`).
  Constraint_id add(const Field_constraint& c) { return spline_->add(c); }
  /// Adds several (one batch of pull-backs at full resolution); all or nothing.
  std::vector<Constraint_id> add(const std::vector<Field_constraint>& c) { return spline_->add(c); }

  /// New vector of a vector constraint, or new value of a divergence or curl
  /// constraint: one back-substitution at the next solve.
  template <class Vector_3>
  void set_vector(Constraint_id id, const Vector_3& v)
  {
    Field_constraint c = spline_->constraint(id);
    c.vector = triple(v);
    spline_->change(id, c);
  }
  void set_value(Constraint_id id, double value)
  {
    Field_constraint c = spline_->constraint(id);
    c.value = value;
    spline_->change(id, c);
  }
  void remove(Constraint_id id) { spline_->remove(id); }
  void set_tension(double omega) { spline_->set_omega(omega); }

  /// Writes the spline into a face map of 3D vectors: the exact one when it is known (always
  /// at full resolution; on a basis once refined), else the reduced one.  `which` (optional)
  /// receives which one it is.
  template <class FaceVectorMap>
  void field(FaceVectorMap out, Spline_answer* which = nullptr) const
  {
    operators_.from_frame_coordinates(spline_->field(which), out);
  }
private:
  template <class NamedParameters>
  static Spline_options options(const NamedParameters& np)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    Spline_options o;
    o.omega = choose_parameter(get_parameter(np, internal_np::spline_tension), 0.);
    o.harmonic_eigenvalue = choose_parameter(get_parameter(np, internal_np::harmonic_eigenvalue), 0.);
    return o;
  }
  template <class NamedParameters>
  void set_index_maps(const TriangleMesh& mesh, const NamedParameters& np)
  {
    auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
    auto eim = CGAL::get_initialized_edge_index_map(mesh, np);
    auto fim = CGAL::get_initialized_face_index_map(mesh, np);
    vertex_index_ = [vim](vertex_descriptor v) { return static_cast<int>(get(vim, v)); };
    edge_index_ = [eim](edge_descriptor e) { return static_cast<int>(get(eim, e)); };
    face_index_ = [fim](face_descriptor f) { return static_cast<int>(get(fim, f)); };
  }
  template <class T>
  static std::array<double, 3> triple(const T& v)
  {
    return internal::to_array(v);
  }

  const Intrinsic_mesh& intrinsic() const { return operators_.intrinsic_mesh(); }

  typedef internal::Answering_spline<Reduced_spline_solver, Full_spline_solver> Answering;

  Discrete_operators<TriangleMesh> operators_; // shares the basis' mesh data and matrices
  std::function<int(vertex_descriptor)> vertex_index_;
  std::function<int(edge_descriptor)> edge_index_;
  std::function<int(face_descriptor)> face_index_;
};

/// \brief One-shot tangent vector field spline at full resolution: builds only the
/// factorisations of `W` and `W*` (and the harmonic basis if the mesh has harmonic
/// fields), never a spectral basis, and writes the spline into `out`.
///
/// \param constraints index-based constraints (see `Field_constraint`,
///        `read_constraint_file`)
/// \param np `spline_tension` and the named parameters of `Discrete_operators`
/// \returns the report (constraint residual, undetermined harmonic directions, warnings)
/// \throws Infeasible_constraints if the constraints contradict each other
template <class TriangleMesh, class FaceVectorMap, class NamedParameters = parameters::Default_named_parameters>
Spline_report vector_field_spline(const TriangleMesh& mesh, const std::vector<Field_constraint>& constraints,
                                  FaceVectorMap out, const NamedParameters& np = parameters::default_values())
{
  Vector_field_spline<TriangleMesh> spline(mesh, np);
  spline.add(constraints);
  spline.field(out);
  return spline.report();
}

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
