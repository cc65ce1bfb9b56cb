// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_DISCRETE_OPERATORS_H
#define CGAL_TANGENT_VECTOR_FIELDS_DISCRETE_OPERATORS_H

/// \file Discrete_operators.h
/// The operators of SPEC section 2 acting on property maps of a `TriangleMesh`.

#include <CGAL/Tangent_vector_fields/Operator_matrices.h>
#include <CGAL/Tangent_vector_fields/internal/Mesh_adapter.h>
#include <CGAL/Tangent_vector_fields/named_function_parameters.h>

#include <memory>

namespace CGAL {
namespace Tangent_vector_fields {

/// \brief Discrete operators on piecewise-constant tangent fields of a triangle mesh.
///
/// Fields are face property maps with 3D vector values (`Vector_3` of the mesh's
/// kernel); an input vector is projected orthogonally onto its face plane.  Scalar
/// functions are vertex maps (conforming `S_h`, piecewise linear) or edge maps
/// (Crouzeix-Raviart `S*_h`, values at edge midpoints).  The matrices behind the
/// operators are assembled on first use and cached (`matrices()`).
///
/// The mesh must outlive this object and must not change while it is used.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` with triangle faces.
///
/// Named parameters of the constructor:
/// - `vertex_point_map`: points of the vertices; default `get(CGAL::vertex_point, mesh)`.
/// - `vertex_index_map`, `edge_index_map`, `face_index_map`: indices 0..n-1;
///   default: the mesh's internal index maps.
/// - `use_intrinsic_mollification` (bool, default false): make degenerate faces
///   usable by adding a constant to every edge length (SPEC 9).
/// - `mollification_epsilon` (double, default 1e-6): the margin mollification
///   guarantees, relative to the mean edge length.
/// - `degeneracy_tolerance` (double, default 1e-10): faces whose smallest triangle
///   inequality margin is at most this times their longest edge are refused.
///
/// \throws Invalid_mesh for meshes the package cannot process (see `Mesh_defect`).
template <class TriangleMesh>
class Discrete_operators
{
public:
  typedef internal::Mesh_adapter<TriangleMesh> Adapter;
  typedef typename Adapter::vertex_descriptor vertex_descriptor;
  typedef typename Adapter::edge_descriptor edge_descriptor;
  typedef typename Adapter::face_descriptor face_descriptor;

  template <class NamedParameters = parameters::Default_named_parameters>
  explicit Discrete_operators(const TriangleMesh& mesh,
                              const NamedParameters& np = parameters::default_values())
    : adapter_(std::make_shared<Adapter>(mesh, np)),
      matrices_(std::make_shared<Operator_matrices>(adapter_->intrinsic_mesh()))
  {}

  const TriangleMesh& mesh() const { return adapter_->mesh(); }
  const Intrinsic_mesh& intrinsic_mesh() const { return matrices_->mesh(); }
  const Mesh_topology& topology() const { return intrinsic_mesh().topology(); }
  const Operator_matrices& matrices() const { return *matrices_; }
  std::shared_ptr<const Operator_matrices> shared_matrices() const { return matrices_; }
  const Adapter& adapter() const { return *adapter_; }

  /// Frame coordinates (`2nf`, order of the face index map) of a face field.
  template <class FaceVectorMap>
  Eigen::VectorXd to_frame_coordinates(const FaceVectorMap& field) const { return adapter_->read_field(field); }
  /// Writes frame coordinates into a face field as 3D vectors.
  template <class FaceVectorMap>
  void from_frame_coordinates(const Eigen::VectorXd& x, FaceVectorMap field) const
  {
    adapter_->write_field(x, field);
  }

  /// Face frames: `e1` (along an edge), `e2 = n x e1`, and the unit normal `n`, into three face maps.
  template <class FaceVectorMap>
  void face_frames(FaceVectorMap e1, FaceVectorMap e2, FaceVectorMap normal) const
  {
    typedef typename boost::property_traits<FaceVectorMap>::value_type Vector_3;
    const auto& faces = adapter_->faces();
    for(std::size_t f = 0; f < faces.size(); ++f)
    {
      const int i = static_cast<int>(f);
      const auto& a = intrinsic_mesh().frame_e1(i);
      const auto& b = intrinsic_mesh().frame_e2(i);
      const auto& n = intrinsic_mesh().normal(i);
      put(e1, faces[f], Vector_3(a[0], a[1], a[2]));
      put(e2, faces[f], Vector_3(b[0], b[1], b[2]));
      put(normal, faces[f], Vector_3(n[0], n[1], n[2]));
    }
  }

  /// Face areas (intrinsic, after mollification).
  template <class FaceScalarMap>
  void face_areas(FaceScalarMap areas) const { Adapter::write_values(adapter_->faces(), matrices_->face_areas(), areas); }
  /// Vertex masses (diagonal of `M`).
  template <class VertexScalarMap>
  void vertex_masses(VertexScalarMap masses) const
  {
    Adapter::write_values(adapter_->vertices(), matrices_->vertex_masses(), masses);
  }
  /// Edge masses (diagonal of `M*`).
  template <class EdgeScalarMap>
  void edge_masses(EdgeScalarMap masses) const
  {
    Adapter::write_values(adapter_->edges(), matrices_->edge_masses(), masses);
  }

  /// Gradient (`G`) of a piecewise-linear vertex function.
  template <class VertexScalarMap, class FaceVectorMap>
  void gradient(const VertexScalarMap& function, FaceVectorMap gradient_field) const
  {
    from_frame_coordinates(matrices_->G() * Adapter::read_values(adapter_->vertices(), function), gradient_field);
  }
  /// Gradient (`G*`) of a Crouzeix-Raviart edge function (values at edge midpoints).
  template <class EdgeScalarMap, class FaceVectorMap>
  void nonconforming_gradient(const EdgeScalarMap& function, FaceVectorMap gradient_field) const
  {
    from_frame_coordinates(matrices_->G_star() * Adapter::read_values(adapter_->edges(), function), gradient_field);
  }
  /// Conforming divergence `div_h` (vertex values).
  template <class FaceVectorMap, class VertexScalarMap>
  void divergence(const FaceVectorMap& field, VertexScalarMap result) const
  {
    Adapter::write_values(adapter_->vertices(), matrices_->divergence(to_frame_coordinates(field)), result);
  }
  /// Conforming curl `curl_h` (vertex values).
  template <class FaceVectorMap, class VertexScalarMap>
  void curl(const FaceVectorMap& field, VertexScalarMap result) const
  {
    Adapter::write_values(adapter_->vertices(), matrices_->curl(to_frame_coordinates(field)), result);
  }
  /// Nonconforming divergence `div*_h` (edge values).
  template <class FaceVectorMap, class EdgeScalarMap>
  void nonconforming_divergence(const FaceVectorMap& field, EdgeScalarMap result) const
  {
    Adapter::write_values(adapter_->edges(), matrices_->nonconforming_divergence(to_frame_coordinates(field)), result);
  }
  /// Nonconforming curl `curl*_h` (edge values).
  template <class FaceVectorMap, class EdgeScalarMap>
  void nonconforming_curl(const FaceVectorMap& field, EdgeScalarMap result) const
  {
    Adapter::write_values(adapter_->edges(), matrices_->nonconforming_curl(to_frame_coordinates(field)), result);
  }
  /// Rotation `J` by +pi/2 about the face normals.
  template <class FaceVectorMap, class OutputFaceVectorMap>
  void rotate(const FaceVectorMap& field, OutputFaceVectorMap rotated) const
  {
    from_frame_coordinates(matrices_->rotate(to_frame_coordinates(field)), rotated);
  }

private:
  std::shared_ptr<Adapter> adapter_;
  std::shared_ptr<Operator_matrices> matrices_;
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
