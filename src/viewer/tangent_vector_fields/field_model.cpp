// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the editor's sessions share: the mesh, its Hodge solver and the basis (computed or
// loaded by a background job while the first pages wait), and the mesh message.

#include "field_request.h"

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/N_field_operators.h>
#include <CGAL/Tangent_vector_fields/Reduced_face_vectors.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>

#include <thread>

#include <algorithm>
#include <cstdint>
#include <future>
#include <vector>

#include <unistd.h> // sysconf: the machine's memory

namespace tvf_viewer {

// --- the model ----------------------------------------------------------------------------------

Field_model::Field_model(std::shared_ptr<const TVF::Operator_matrices> matrices, std::shared_ptr<TVF::Hodge_solver> hodge,
                           std::string name, double diagonal, int initial_basis_size, Field_limits limits)
  : matrices_(std::move(matrices)), hodge_(std::move(hodge)), name_(std::move(name)), diagonal_(diagonal),
    initial_basis_size_(initial_basis_size), limits_(limits)
{
  status_.stage = "starting";
}

Field_model::~Field_model() = default;

void Field_model::set_progress(const std::string& stage, double fraction)
{
  std::lock_guard<std::mutex> lock(mutex_);
  status_.stage = stage;
  status_.fraction = std::min(1.0, std::max(0.0, fraction));
}

void Field_model::set_basis(std::shared_ptr<const TVF::Eigenfield_basis> basis)
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

void Field_model::set_failure(const std::string& reason)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    status_.failed = true;
    status_.error = reason;
  }
  changed_.notify_all();
}

Field_model::Status Field_model::wait(std::chrono::milliseconds timeout) const
{
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait_for(lock, timeout, [this] { return status_.ready || status_.failed; });
  return status_;
}

std::shared_ptr<const TVF::Eigenfield_basis> Field_model::basis() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return basis_;
}

void Field_model::set_n_field_basis_source(N_field_basis_source source)
{
  std::lock_guard<std::mutex> lock(mutex_);
  n_field_source_ = std::move(source);
}

namespace {

// The operators' lazy caches are filled before the basis is announced, so that the first
// edit of the first page does not wait for them: everything the solvers, the tracer and the
// index use.
void warm_up(const TVF::N_field_operators& ops)
{
  ops.transport_angles();
  ops.connection_angles();
  ops.edge_weights();
  ops.vertex_curvatures();
  ops.boundary_vertices();
  ops.S();
  ops.kernel();
  if(ops.mesh().number_of_vertices() > 0) ops.vertex_fan(0);
}

} // namespace

Field_model::Status Field_model::wait_n_field(int n, std::chrono::milliseconds timeout) const
{
  std::unique_lock<std::mutex> lock(mutex_);
  auto it = n_fields_.find(n);
  if(it == n_fields_.end())
  {
    // The first page to ask for this n starts the job; the others wait for the same one.
    it = n_fields_.emplace(n, N_field_space()).first;
    it->second.status.stage = "starting";
    std::shared_ptr<const Field_model> self = shared_from_this();
    N_field_basis_source source = n_field_source_;
    std::thread([self, n, source] {
      auto progress = [&self, n](const std::string& stage, double fraction) {
        std::lock_guard<std::mutex> lock(self->mutex_);
        Status& s = self->n_fields_[n].status;
        s.stage = stage;
        s.fraction = std::min(1.0, std::max(0.0, fraction));
      };
      std::shared_ptr<const TVF::N_field_basis> basis;
      std::string error;
      try
      {
        auto ops = std::make_shared<const TVF::N_field_operators>(self->shared_matrices(), n);
        if(source) basis = source(ops, progress);
        else
        {
          TVF::Basis_options options;
          options.progress = [&progress](const TVF::Spectral_progress& p) {
            progress("computing the basis of n-fields: " + p.stage, p.fraction);
          };
          const int count = std::max(2, self->initial_basis_size() > 0 ? self->initial_basis_size() : 100);
          basis = std::make_shared<const TVF::N_field_basis>(ops, count, options);
        }
        warm_up(basis->operators());
      }
      catch(const std::exception& e)
      {
        error = e.what();
      }
      {
        std::lock_guard<std::mutex> lock(self->mutex_);
        N_field_space& space = self->n_fields_[n];
        if(basis)
        {
          space.basis = basis;
          space.status.ready = true;
          space.status.stage = "ready";
          space.status.fraction = 1;
        }
        else
        {
          space.status.failed = true;
          space.status.error = error;
        }
      }
      self->changed_.notify_all();
    }).detach();
  }
  changed_.wait_for(lock, timeout, [this, n] {
    const Status& s = n_fields_.at(n).status;
    return s.ready || s.failed;
  });
  return n_fields_.at(n).status;
}

std::shared_ptr<const TVF::N_field_basis> Field_model::n_field_basis(int n) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = n_fields_.find(n);
  return it == n_fields_.end() ? nullptr : it->second.basis;
}

const Outgoing& Field_model::mesh_message() const
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

std::shared_ptr<const TVF::Streamline_surface> Field_model::streamline_surface() const
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if(surface_) return surface_;
  }
  auto surface = std::make_shared<const TVF::Streamline_surface>(matrices_->shared_mesh());
  std::lock_guard<std::mutex> lock(mutex_);
  if(!surface_) surface_ = std::move(surface);
  return surface_;
}

std::shared_ptr<const TVF::Eigenfield_rows> Field_model::eigenfield_rows(int d) const
{
  const std::shared_ptr<const TVF::Eigenfield_basis> b = basis();
  if(!b) return nullptr;
  std::lock_guard<std::mutex> lock(rows_mutex_);
  Rows_slot& slot = rows_[d];
  if(std::shared_ptr<const TVF::Eigenfield_rows> rows = slot.rows.lock()) return rows;
  auto make = [b, d] { return std::make_shared<const TVF::Eigenfield_rows>(b, d); };
  const double bytes = 8.0 * matrices_->mesh().number_of_faces() * std::max(d, 0); // 2 nf d float32
  // The rows double the basis' memory (2.8 GB for the armadillo's 346k faces at d = 1000): past a
  // quarter of the machine's memory there is no preview, only the field.
  static const double memory = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if(memory > 0 && bytes > memory / 4) return nullptr;
  if(!slot.job.valid())
  {
    if(bytes < 64e6)
    {
      std::shared_ptr<const TVF::Eigenfield_rows> rows = make();
      slot.rows = rows;
      return rows;
    }
    slot.job = std::async(std::launch::async, make).share();
  }
  if(slot.job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return nullptr;
  const std::shared_future<std::shared_ptr<const TVF::Eigenfield_rows>> job = slot.job;
  slot.job = {};
  std::shared_ptr<const TVF::Eigenfield_rows> rows = job.get(); // rethrows what the job threw
  slot.rows = rows;
  return rows;
}

} // namespace tvf_viewer
