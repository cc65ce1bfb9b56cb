// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the editor's sessions share: the mesh, its Hodge solver and the basis (computed or
// loaded by a background job while the first pages wait), and the mesh message.

#include "editor_messages.h"

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>

#include <cstdint>
#include <vector>

namespace tvf_tool {

// --- the model ----------------------------------------------------------------------------------

Editor_model::Editor_model(std::shared_ptr<const TVF::Operator_matrices> matrices, std::shared_ptr<TVF::Hodge_solver> hodge,
                           std::string name, double diagonal, int initial_basis_size, Editor_limits limits)
  : matrices_(std::move(matrices)), hodge_(std::move(hodge)), name_(std::move(name)), diagonal_(diagonal),
    initial_basis_size_(initial_basis_size), limits_(limits)
{
  status_.stage = "starting";
}

Editor_model::~Editor_model() = default;

void Editor_model::set_progress(const std::string& stage, double fraction)
{
  std::lock_guard<std::mutex> lock(mutex_);
  status_.stage = stage;
  status_.fraction = std::min(1.0, std::max(0.0, fraction));
}

void Editor_model::set_basis(std::shared_ptr<const TVF::Eigenfield_basis> basis)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    basis_ = std::move(basis);
    status_.ready = true;
    status_.stage = "ready";
    status_.fraction = 1;
  }
  changed_.notify_all();
}

void Editor_model::set_failure(const std::string& reason)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    status_.failed = true;
    status_.error = reason;
  }
  changed_.notify_all();
}

Editor_model::Status Editor_model::wait(std::chrono::milliseconds timeout) const
{
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait_for(lock, timeout, [this] { return status_.ready || status_.failed; });
  return status_;
}

std::shared_ptr<const TVF::Eigenfield_basis> Editor_model::basis() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return basis_;
}

const Outgoing& Editor_model::mesh_message() const
{
  std::call_once(mesh_once_, [this] {
    const TVF::Intrinsic_mesh& mesh = matrices_->mesh();
    std::vector<float> positions;
    positions.reserve(3 * mesh.number_of_vertices());
    for(int v = 0; v < mesh.number_of_vertices(); ++v)
      for(int k = 0; k < 3; ++k) positions.push_back(static_cast<float>(mesh.position(v)[k]));
    std::vector<std::uint32_t> triangles, edges, face_edges, boundary;
    for(int f = 0; f < mesh.number_of_faces(); ++f)
      for(int k = 0; k < 3; ++k)
      {
        triangles.push_back(mesh.face_vertices(f)[k]);
        face_edges.push_back(mesh.face_edges(f)[k]);
      }
    for(int e = 0; e < mesh.number_of_edges(); ++e)
    {
      edges.push_back(mesh.edge_vertices(e)[0]);
      edges.push_back(mesh.edge_vertices(e)[1]);
      if(mesh.is_boundary_edge(e)) boundary.push_back(e);
    }
    mesh_message_ = std::make_unique<Outgoing>(binary_message(
        "\"type\":\"mesh\"", {{"positions", true, positions.data(), positions.size()},
                              {"triangles", false, triangles.data(), triangles.size()},
                              {"edges", false, edges.data(), edges.size()},
                              {"face_edges", false, face_edges.data(), face_edges.size()},
                              {"boundary_edges", false, boundary.data(), boundary.size()}}));
  });
  return *mesh_message_;
}

} // namespace tvf_tool
