// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The two designs of the editor: one template over what differs between vector fields and
// n-fields (constraint type, solvers, files, display), so that both get the same edits,
// all-or-nothing loads, full-solver bookkeeping and fast value edits.

#include "editor_design.h"
#include "editor_messages.h"
#include "tool.h" // field_norm

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/N_field_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/n_field_constraint_file_io.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>

namespace tvf_tool {

namespace {

typedef TVF::internal::Json Json;

TVF::Spline_options spline_options(double omega)
{
  TVF::Spline_options options;
  options.omega = omega;
  return options;
}

// A constraint file as the designs exchange it.
template <class Constraint>
struct File
{
  std::vector<Constraint> constraints;
  std::vector<double> weights;
  bool has_omega = false;
  double omega = 0;
};

// --- vector fields ----------------------------------------------------------------------------

struct Vector_kind
{
  typedef TVF::Field_constraint Constraint;
  typedef TVF::Reduced_spline_solver Reduced;
  typedef TVF::Full_spline_solver Full;

  std::shared_ptr<const Editor_model> model;
  std::shared_ptr<const TVF::Eigenfield_basis> basis;

  int n() const { return 1; }
  int order() const { return 2; }
  int available() const { return basis->size(); }
  int kernel_dimension() const { return basis->number_of_harmonic(); }
  const TVF::Operator_matrices& matrices() const { return model->matrices(); }

  Constraint parse(const Json& c, double& weight) const
  {
    return TVF::internal::parse_constraint(c, "constraint", matrices(), &weight);
  }
  File<Constraint> parse_file(const Json& root) const
  {
    const TVF::Constraint_file f = TVF::internal::parse_constraint_file(root, matrices());
    return {f.constraints, f.weights, f.has_omega, f.omega};
  }
  std::string write_file(const File<Constraint>& f, int) const
  {
    TVF::Constraint_file file;
    file.omega = f.omega;
    file.has_omega = true;
    file.constraints = f.constraints;
    file.weights = f.weights;
    std::ostringstream out;
    TVF::write_constraint_file(out, file, matrices().mesh());
    return out.str();
  }
  std::unique_ptr<Reduced> reduced(int size, double omega, int) const
  {
    return std::make_unique<Reduced>(basis, size, spline_options(omega));
  }
  std::unique_ptr<Full> full(double omega, int) const { return std::make_unique<Full>(model->hodge(), spline_options(omega)); }
  double norm(const Eigen::VectorXd& x) const { return field_norm(matrices(), x); }

  std::vector<float> vectors(const Eigen::VectorXd& x, double& magnitude_max) const
  {
    return to_3d(matrices().mesh(), x, magnitude_max);
  }
  static std::vector<float> to_3d(const TVF::Intrinsic_mesh& mesh, const Eigen::VectorXd& x, double& magnitude_max)
  {
    const int nf = mesh.number_of_faces();
    std::vector<float> out(3 * static_cast<std::size_t>(nf));
    magnitude_max = 0;
    for(int f = 0; f < nf; ++f)
    {
      const auto v = mesh.from_frame(f, x[2 * f], x[2 * f + 1]);
      for(int k = 0; k < 3; ++k) out[3 * f + k] = static_cast<float>(v[k]);
      magnitude_max = std::max(magnitude_max, std::hypot(x[2 * f], x[2 * f + 1]));
    }
    return out;
  }
  bool has_scalar(const std::string& kind) const { return kind == "divergence" || kind == "curl"; }
  Eigen::VectorXd scalar(const std::string& kind, const Eigen::VectorXd& x) const
  {
    return kind == "divergence" ? matrices().divergence(x) : matrices().curl(x);
  }
  TVF::Streamline_tracer tracer(const Eigen::VectorXd& x) const { return {matrices().shared_mesh(), x}; }
  std::vector<std::pair<int, int>> singularities(const Eigen::VectorXd&) const { return {}; }
};

// --- n-direction fields -----------------------------------------------------------------------

struct N_field_kind
{
  typedef TVF::N_field_constraint Constraint;
  typedef TVF::Reduced_n_field_spline_solver Reduced;
  typedef TVF::Full_n_field_spline_solver Full;

  std::shared_ptr<const Editor_model> model;
  std::shared_ptr<const TVF::N_field_basis> basis;

  const TVF::N_field_operators& operators() const { return basis->operators(); }
  int n() const { return basis->n(); }
  int available() const { return basis->size(); }
  int kernel_dimension() const { return basis->kernel_dimension(); }

  Constraint parse(const Json& c, double& weight) const
  {
    weight = 1;
    return TVF::internal::parse_n_field_constraint(c, "constraint", operators());
  }
  File<Constraint> parse_file(const Json& root) const
  {
    const TVF::N_field_constraint_file f =
        TVF::internal::parse_n_field_constraint_file(root, model->shared_matrices());
    if(f.n != n())
      throw Message_error("the file is for n = " + std::to_string(f.n) + ", the session designs n = " +
                          std::to_string(n()) + " (set_n first)");
    if(!f.singularities.empty())
      throw Message_error("the file prescribes singularities in the connection (\"singularities\"), which needs a "
                          "basis of its own: place singularity constraints instead, or use tvf design");
    File<Constraint> out;
    out.constraints = f.constraints;
    out.weights.assign(f.constraints.size(), 1.0);
    out.has_omega = root.contains("omega");
    out.omega = f.omega;
    return out;
  }
  std::string write_file(const File<Constraint>& f, int order) const
  {
    TVF::N_field_constraint_file file;
    file.n = n();
    file.omega = f.omega;
    file.order = order;
    file.constraints = f.constraints;
    std::ostringstream out;
    TVF::write_n_field_constraint_file(out, file, model->matrices().mesh());
    return out.str();
  }
  std::unique_ptr<Reduced> reduced(int size, double omega, int order) const
  {
    return std::make_unique<Reduced>(basis, size, spline_options(omega), order);
  }
  std::unique_ptr<Full> full(double omega, int order) const
  {
    return std::make_unique<Full>(basis->shared_operators(), spline_options(omega), order);
  }
  double norm(const Eigen::VectorXd& z) const { return std::sqrt(z.dot(operators().masses().cwiseProduct(z))); }

  std::vector<float> vectors(const Eigen::VectorXd& z, double& magnitude_max) const
  {
    return Vector_kind::to_3d(model->matrices().mesh(), operators().to_vectors(z), magnitude_max);
  }
  bool has_scalar(const std::string& kind) const { return kind == "energy"; }
  Eigen::VectorXd scalar(const std::string&, const Eigen::VectorXd& z) const { return operators().energy_density(z); }
  TVF::Streamline_tracer tracer(const Eigen::VectorXd& z) const { return {operators(), z}; }
  std::vector<std::pair<int, int>> singularities(const Eigen::VectorXd& z) const
  {
    std::vector<std::pair<int, int>> out;
    for(const TVF::N_field_singularity& s : TVF::n_field_singularities(operators(), z)) out.push_back({s.vertex, s.index});
    return out;
  }
};

// --- the design -------------------------------------------------------------------------------

template <class Kind>
class Spline_design : public Editor_design
{
  typedef typename Kind::Constraint Constraint;
  struct Entry
  {
    Constraint constraint;
    double weight = 1;
    TVF::Constraint_id reduced = -1, full = -1;
  };

public:
  Spline_design(Kind kind, int order, int basis_size, double omega) : kind_(std::move(kind)), order_(order), omega_(omega)
  {
    const int size = std::min(basis_size > 0 ? basis_size : kind_.available(), kind_.available());
    reduced_ = kind_.reduced(size, omega_, order_);
  }

  int n() const override { return kind_.n(); }
  int order() const override { return order_; }
  int available() const override { return kind_.available(); }
  int basis_size() const override { return reduced_->basis_size(); }
  int kernel_dimension() const override { return kind_.kernel_dimension(); }
  double omega() const override { return omega_; }
  bool full() const override { return full_ != nullptr; }
  std::vector<int> ids() const override
  {
    std::vector<int> out;
    for(const auto& e : entries_) out.push_back(e.first);
    return out;
  }

  int add(const Json& json, const Design_progress& progress, Edit_time& time) override
  {
    Entry entry;
    entry.constraint = kind_.parse(json, entry.weight);
    Clock::time_point start = Clock::now();
    entry.reduced = reduced_->add(entry.constraint);
    time.reduced_ms = milliseconds_since(start);
    if(full_)
    {
      try
      {
        std::lock_guard<std::mutex> lock(model().full_solver_mutex());
        progress("full solution: pulling back the new constraint", 0);
        start = Clock::now();
        entry.full = full_->add(entry.constraint);
        time.full_ms = milliseconds_since(start);
      }
      catch(...)
      {
        reduced_->remove(entry.reduced);
        throw;
      }
    }
    const int id = next_id_++;
    entries_[id] = entry;
    edited_ = -1;
    return id;
  }

  void change(int id, const Json& json, const Design_progress& progress, Edit_time& time) override
  {
    Entry& entry = find(id);
    double weight = 1;
    const Constraint constraint = kind_.parse(json, weight);
    const Constraint old = entry.constraint;
    Clock::time_point start = Clock::now();
    reduced_->change(entry.reduced, constraint); // unchanged if it throws
    time.reduced_ms = milliseconds_since(start);
    if(full_)
    {
      try
      {
        std::lock_guard<std::mutex> lock(model().full_solver_mutex());
        if(!old.same_rows_as(constraint)) progress("full solution: pulling back the moved constraint", 0);
        start = Clock::now();
        full_->change(entry.full, constraint);
        time.full_ms = milliseconds_since(start);
      }
      catch(...)
      {
        reduced_->change(entry.reduced, old);
        throw;
      }
    }
    entry.constraint = constraint;
    entry.weight = weight;
    // Only the values changed: the next field comes from the constraint's cached response.
    edited_ = old.same_rows_as(constraint) ? id : -1;
  }

  void remove(int id) override
  {
    Entry& entry = find(id);
    reduced_->remove(entry.reduced);
    if(full_)
    {
      std::lock_guard<std::mutex> lock(model().full_solver_mutex());
      full_->remove(entry.full);
    }
    entries_.erase(id);
    edited_ = -1;
  }

  void clear() override
  {
    reduced_->clear();
    if(full_)
    {
      std::lock_guard<std::mutex> lock(model().full_solver_mutex());
      full_->clear();
    }
    entries_.clear();
    edited_ = -1;
  }

  std::vector<int> load(const Json& json, const Design_progress& progress) override
  {
    const File<Constraint> file = kind_.parse_file(json);
    const int limit = model().limits().max_constraints;
    if(static_cast<int>(file.constraints.size()) > limit)
      throw Message_error("too many constraints (" + std::to_string(file.constraints.size()) + "; the limit is " +
                          std::to_string(limit) + ")");
    const double omega = file.has_omega ? file.omega : omega_;
    // All or nothing: new solvers, swapped in once every constraint fitted.
    auto reduced = kind_.reduced(reduced_->basis_size(), omega, order_);
    const std::vector<TVF::Constraint_id> reduced_ids = reduced->add(file.constraints);
    std::unique_ptr<typename Kind::Full> full;
    std::vector<TVF::Constraint_id> full_ids;
    if(full_)
    {
      std::lock_guard<std::mutex> lock(model().full_solver_mutex());
      full = kind_.full(omega, order_);
      progress("full solution: pulling back " + std::to_string(file.constraints.size()) + " constraints", 0);
      full_ids = full->add(file.constraints);
    }
    reduced_ = std::move(reduced);
    full_ = std::move(full);
    omega_ = omega;
    entries_.clear();
    edited_ = -1;
    std::vector<int> ids;
    for(std::size_t i = 0; i < file.constraints.size(); ++i)
    {
      Entry entry;
      entry.constraint = file.constraints[i];
      entry.weight = file.weights[i];
      entry.reduced = reduced_ids[i];
      if(full_) entry.full = full_ids[i];
      ids.push_back(next_id_);
      entries_[next_id_++] = entry;
    }
    return ids;
  }

  std::string save() const override
  {
    File<Constraint> file;
    file.omega = omega_;
    file.has_omega = true;
    for(const auto& e : entries_)
    {
      file.constraints.push_back(e.second.constraint);
      file.weights.push_back(e.second.weight);
    }
    return kind_.write_file(file, order_);
  }

  void set_omega(double omega, const Design_progress& progress) override
  {
    reduced_->set_omega(omega);
    if(full_)
    {
      std::lock_guard<std::mutex> lock(model().full_solver_mutex());
      progress("full solution: new tension, pulling back every constraint", 0);
      try
      {
        full_->set_omega(omega);
      }
      catch(...)
      {
        reduced_->set_omega(omega_);
        throw;
      }
    }
    omega_ = omega;
    edited_ = -1;
  }

  void set_basis_size(int size) override
  {
    if(size == reduced_->basis_size()) return;
    auto reduced = kind_.reduced(size, omega_, order_);
    std::vector<Constraint> constraints;
    for(const auto& e : entries_) constraints.push_back(e.second.constraint);
    std::vector<TVF::Constraint_id> ids;
    try
    {
      ids = reduced->add(constraints); // all or nothing
    }
    catch(const TVF::Invalid_input& e)
    {
      throw Message_error("the constraints do not fit a basis of " + std::to_string(size) + " elements: " + e.what());
    }
    reduced_ = std::move(reduced);
    std::size_t i = 0;
    for(auto& e : entries_) e.second.reduced = ids[i++];
    edited_ = -1;
  }

  void set_full(bool on, const Design_progress& progress) override
  {
    if(!on)
    {
      full_.reset(); // its pull-backs are big (one field per row); keep nothing we do not show
      return;
    }
    if(full_) return;
    std::lock_guard<std::mutex> lock(model().full_solver_mutex());
    progress("full solution: factoring", 0);
    auto full = kind_.full(omega_, order_);
    // In chunks, so that the page sees progress (a batch of pull-backs shares the solves' set-up).
    std::vector<Entry*> order;
    for(auto& e : entries_) order.push_back(&e.second);
    const std::size_t chunk = std::max<std::size_t>(1, order.size() / 10);
    std::vector<TVF::Constraint_id> ids;
    for(std::size_t start = 0; start < order.size(); start += chunk)
    {
      const std::size_t end = std::min(order.size(), start + chunk);
      std::vector<Constraint> constraints;
      for(std::size_t i = start; i < end; ++i) constraints.push_back(order[i]->constraint);
      const std::vector<TVF::Constraint_id> more = full->add(constraints);
      ids.insert(ids.end(), more.begin(), more.end());
      progress("full solution: pulled back " + std::to_string(end) + " of " + std::to_string(order.size()) +
                   " constraints",
               double(end) / order.size());
    }
    for(std::size_t i = 0; i < order.size(); ++i) order[i]->full = ids[i];
    full_ = std::move(full);
  }

  Design_field field() override
  {
    Design_field out;
    Clock::time_point start = Clock::now();
    out.report = reduced_->report(); // the solve (the small system) and its report
    out.solve_ms = milliseconds_since(start);
    start = Clock::now();
    out.x = edited_ >= 0 ? reduced_->field_after_value_edit(entries_.at(edited_).reduced) : reduced_->field();
    out.reconstruct_ms = milliseconds_since(start);
    edited_ = -1;
    if(full_)
    {
      std::lock_guard<std::mutex> lock(model().full_solver_mutex());
      start = Clock::now();
      Eigen::VectorXd x_full = full_->field();
      out.full_ms = milliseconds_since(start);
      const double norm = kind_.norm(x_full), difference = kind_.norm(out.x - x_full);
      out.difference = norm > 0 ? difference / norm : difference;
      out.x.swap(x_full);
      out.report = full_->report();
      out.full = true;
    }
    return out;
  }

  std::vector<float> vectors(const Eigen::VectorXd& x, double& magnitude_max) const override
  {
    return kind_.vectors(x, magnitude_max);
  }
  bool has_scalar(const std::string& kind) const override { return kind_.has_scalar(kind); }
  Eigen::VectorXd scalar(const std::string& kind, const Eigen::VectorXd& x) const override
  {
    if(!kind_.has_scalar(kind)) throw Message_error("no scalar \"" + kind + "\" for this field");
    return kind_.scalar(kind, x);
  }
  std::vector<TVF::Streamline> lines(const Eigen::VectorXd& x, const Display_settings& display) const override
  {
    const TVF::Streamline_tracer tracer = kind_.tracer(x);
    if(display.lines == "fur")
    {
      TVF::Fur_options fur;
      fur.number_of_strokes = display.strokes;
      fur.length = display.length;
      fur.scale_length_by_magnitude = true;
      return tracer.fur(fur);
    }
    TVF::Evenly_spaced_options even;
    even.separation = display.separation;
    return tracer.evenly_spaced(even);
  }
  std::vector<std::pair<int, int>> singularities(const Eigen::VectorXd& x) const override
  {
    return kind_.singularities(x);
  }

private:
  const Editor_model& model() const { return *kind_.model; }
  Entry& find(int id)
  {
    const auto it = entries_.find(id);
    if(it == entries_.end()) throw Message_error("no constraint with id " + std::to_string(id));
    return it->second;
  }

  Kind kind_;
  int order_;
  double omega_;
  std::unique_ptr<typename Kind::Reduced> reduced_;
  std::unique_ptr<typename Kind::Full> full_; // null: the full solver is off
  std::map<int, Entry> entries_;              // by session id
  int next_id_ = 0;
  int edited_ = -1; // the constraint whose values the last change edited (-1: none)
};

} // namespace

std::unique_ptr<Editor_design> make_vector_design(std::shared_ptr<const Editor_model> model, int basis_size, double omega)
{
  Vector_kind kind{model, model->basis()};
  return std::make_unique<Spline_design<Vector_kind>>(std::move(kind), 2, basis_size, omega);
}

std::unique_ptr<Editor_design> make_n_field_design(std::shared_ptr<const Editor_model> model, int n, int order,
                                                   int basis_size, double omega)
{
  N_field_kind kind{model, model->n_field_basis(n)};
  if(!kind.basis) throw Message_error("the basis of n = " + std::to_string(n) + " fields is not ready");
  return std::make_unique<Spline_design<N_field_kind>>(std::move(kind), order, basis_size, omega);
}

} // namespace tvf_tool
