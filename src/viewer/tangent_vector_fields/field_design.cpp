// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The two designs of the editor: one template over what differs between vector fields and
// n-fields (design_traits.h), so that both get the same edits, all-or-nothing loads, exact
// answers refined on a worker thread (Refining_spline_solver) and fast value edits.

#include "field_design.h"
#include "design_traits.h"

#include <CGAL/Tangent_vector_fields/Reduced_face_vectors.h>
#include <CGAL/Tangent_vector_fields/Refining_spline_solver.h>

#include <map>

namespace tvf_viewer {

namespace {

using namespace design_traits;

// The fur of the page: its lengths and zero-field test relative to the largest magnitude at the
// roots, which a field read face by face (the preview) knows too, so that the preview's strokes
// are those of the field that follows.
TVF::Fur_options fur_options(const Display_settings& display)
{
  TVF::Fur_options fur;
  fur.number_of_strokes = display.strokes;
  fur.length = display.length;
  fur.scale_length_by_magnitude = true;
  fur.magnitude_reference = TVF::Fur_options::Magnitude_reference::roots;
  return fur;
}

// --- the design -------------------------------------------------------------------------------

template <class Kind>
class Spline_design : public Field_design
{
  typedef typename Kind::Constraint Constraint;
  typedef TVF::Basic_refining_spline_solver<typename Kind::Reduced, typename Kind::Full> Refining;
  struct Entry
  {
    TVF::Constraint_id spline = -1; // the refining solver's id
    double weight = 1;
  };

public:
  Spline_design(Kind kind, int order, int basis_size, double omega) : kind_(std::move(kind)), order_(order)
  {
    const int size = std::min(basis_size > 0 ? basis_size : kind_.available(), kind_.available());
    spline_ = make(size, omega);
  }

  int n() const override { return kind_.n(); }
  int order() const override { return order_; }
  int available() const override { return kind_.available(); }
  int basis_size() const override { return spline_->reduced().basis_size(); }
  int kernel_dimension() const override { return kind_.kernel_dimension(); }
  double omega() const override { return spline_->reduced().options().omega; }
  bool full() const override { return full_; }
  std::vector<int> ids() const override
  {
    std::vector<int> out;
    for(const auto& e : entries_) out.push_back(e.first);
    return out;
  }

  int add(const Json& json, double& solve_ms) override
  {
    Entry entry;
    const Constraint constraint = kind_.parse(json, entry.weight);
    const Clock::time_point start = Clock::now();
    entry.spline = spline_->add(constraint); // the reduced solver now, the full pull-back on the worker
    solve_ms = milliseconds_since(start);
    const int id = next_id_++;
    entries_[id] = entry;
    changed(-1);
    return id;
  }

  void change(int id, const Json& json, double& solve_ms) override
  {
    Entry& entry = find(id);
    double weight = 1;
    const Constraint constraint = kind_.parse(json, weight);
    const bool same_rows = spline_->constraint(entry.spline).same_rows_as(constraint);
    const Clock::time_point start = Clock::now();
    spline_->change(entry.spline, constraint); // unchanged if it throws
    solve_ms = milliseconds_since(start);
    entry.weight = weight;
    // Only the values changed: the next field comes from the constraint's cached response.
    changed(same_rows ? id : -1);
  }

  void remove(int id) override
  {
    spline_->remove(find(id).spline);
    entries_.erase(id);
    changed(-1);
  }

  void clear() override
  {
    spline_->clear();
    entries_.clear();
    changed(-1);
  }

  std::vector<int> load(const Json& json) override
  {
    const File<Constraint> file = kind_.parse_file(json);
    const int limit = kind_.model->limits().max_constraints;
    if(static_cast<int>(file.constraints.size()) > limit)
      throw Message_error("too many constraints (" + std::to_string(file.constraints.size()) + "; the limit is " +
                          std::to_string(limit) + ")");
    // All or nothing: a new solver, swapped in once every constraint fitted.
    std::unique_ptr<Refining> spline = make(basis_size(), file.has_omega ? file.omega : omega());
    const std::vector<TVF::Constraint_id> spline_ids = spline->add(file.constraints);
    spline_ = std::move(spline);
    if(full_) spline_->refine_in_background();
    entries_.clear();
    changed(-1);
    std::vector<int> ids;
    for(std::size_t i = 0; i < file.constraints.size(); ++i)
    {
      ids.push_back(next_id_);
      entries_[next_id_++] = Entry{spline_ids[i], file.weights[i]};
    }
    return ids;
  }

  std::string save() const override
  {
    File<Constraint> file;
    file.omega = omega();
    file.has_omega = true;
    for(const auto& e : entries_)
    {
      file.constraints.push_back(spline_->constraint(e.second.spline));
      file.weights.push_back(e.second.weight);
    }
    return kind_.write_file(file, order_);
  }

  void set_omega(double omega) override
  {
    spline_->set_omega(omega); // every pull-back again, on the worker
    changed(-1);
  }

  void set_basis_size(int size) override
  {
    if(size == basis_size()) return;
    try
    {
      spline_->replace_reduced(kind_.reduced(size, omega(), order_)); // all or nothing
    }
    catch(const TVF::Invalid_input& e)
    {
      throw Message_error("the constraints do not fit a basis of " + std::to_string(size) + " elements: " + e.what());
    }
    changed(-1);
  }

  void set_full(bool on) override
  {
    if(on) spline_->refine_in_background();
    else spline_->stop_refining(); // its pull-backs are big (one field per row): keep nothing unused
    full_ = on;
  }

  bool wait_exact(std::chrono::milliseconds timeout) override { return spline_->wait_until_exact(timeout); }
  std::string refinement_error() override { return spline_->refinement_error(); }
  TVF::Spline_answer answer() override { return spline_->answer(); }

  Design_field field() override
  {
    Design_field out;
    // The solve and its report first (timed as the solve), then the field from the same
    // solver (timed as the reconstruction); should the worker's pull-backs come in between,
    // the report is taken again from the solver that answered.
    Clock::time_point start = Clock::now();
    const bool exact_before = spline_->answer().exact;
    out.report = spline_->report();
    out.solve_ms = milliseconds_since(start);
    TVF::Spline_answer answer;
    start = Clock::now();
    const TVF::Constraint_id edited = edited_ >= 0 ? entries_.at(edited_).spline : -1;
    // After an add or a move: the exact field at once where the worker has it sooner than the
    // reduced one would take.
    // With the preview's strokes on screen the reduced field is no longer the first thing the
    // user sees: an exact field expected within this time is worth waiting for instead.
    const double worth_waiting = preview_shown_ ? 0.5 : 0;
    preview_shown_ = false;
    out.x = edited >= 0 ? spline_->field_after_value_edit(edited, &answer) : spline_->soonest_field(&answer, worth_waiting);
    (answer.exact ? out.full_ms : out.reconstruct_ms) = milliseconds_since(start);
    if(answer.exact != exact_before) out.report = spline_->report();
    out.exact = answer.exact;
    out.pending = answer.pending;
    // The two answers of one constraint set, once both are known: the reduced one is sent
    // first after an edit (unless the exact one comes sooner); after a value edit in exact mode
    // it is cheap (its own cached response).
    if(!answer.exact)
    {
      reduced_ = out.x;
      reduced_state_ = state_;
    }
    else if(reduced_state_ != state_ && edited >= 0)
    {
      reduced_ = spline_->reduced_field_after_value_edit(edited);
      reduced_state_ = state_;
    }
    if(answer.exact && reduced_state_ == state_ && reduced_.size() == out.x.size())
    {
      const double norm = kind_.norm(out.x), difference = kind_.norm(reduced_ - out.x);
      out.difference = norm > 0 ? difference / norm : difference;
      out.largest_angle = kind_.angle(reduced_, out.x);
    }
    edited_ = -1;
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
    if(display.lines == "fur") return tracer.fur(fur_options(display));
    TVF::Evenly_spaced_options even;
    even.separation = display.separation;
    return tracer.evenly_spaced(even);
  }
  std::vector<std::pair<int, int>> singularities(const Eigen::VectorXd& x) const override
  {
    return kind_.singularities(x);
  }

  bool preview(const Display_settings& display, Design_preview& out) override
  {
    if constexpr(!Kind::has_preview) return false;
    else
    {
      if(display.lines != "fur") return false;
      const int d = basis_size();
      if(!preview_source_ || preview_size_ != d)
      {
        preview_source_.reset(); // its rows may go before the new ones are made
        preview_size_ = d;
        try
        {
          preview_source_ = kind_.face_vectors(d); // null while they are being made
        }
        catch(const std::exception&) // no memory for the rows: no preview, the field as before
        {
          return false;
        }
      }
      if(!preview_source_) return false;
      Clock::time_point start = Clock::now();
      const typename Kind::Reduced& reduced = spline_->reduced();
      const Eigen::VectorXd a = reduced.coefficients();
      out.report = reduced.report();
      out.solve_ms = milliseconds_since(start);
      start = Clock::now();
      preview_source_->set_coefficients(a);
      const TVF::Streamline_tracer tracer(*kind_.surface(), preview_source_, 1);
      out.strokes = tracer.fur(fur_options(display));
      out.faces_read = preview_source_->faces_asked();
      out.lines_ms = milliseconds_since(start);
      preview_shown_ = true;
      return true;
    }
  }

private:
  std::unique_ptr<Refining> make(int size, double omega) const
  {
    return std::make_unique<Refining>(kind_.reduced(size, omega, order_), kind_.full_factory(order_));
  }
  void changed(int value_edit)
  {
    edited_ = value_edit;
    ++state_;
  }
  Entry& find(int id)
  {
    const auto it = entries_.find(id);
    if(it == entries_.end()) throw Message_error("no constraint with id " + std::to_string(id));
    return it->second;
  }

  Kind kind_;
  int order_;
  std::unique_ptr<Refining> spline_;
  bool full_ = false;
  std::map<int, Entry> entries_; // by session id
  int next_id_ = 0;
  int edited_ = -1;    // the constraint whose values the last change edited (-1: none)
  long state_ = 0;     // counts edits: the reduced and exact answers of one state are compared
  long reduced_state_ = -1;
  Eigen::VectorXd reduced_; // the last reduced answer, of `reduced_state_`
  std::shared_ptr<TVF::Reduced_face_vectors> preview_source_; // vector fields: the reduced field face by face
  int preview_size_ = 0;
  bool preview_shown_ = false; // a preview answered the edit the next field answers
};

} // namespace

std::unique_ptr<Field_design> make_vector_design(std::shared_ptr<const Field_model> model, int basis_size, double omega)
{
  Vector_kind kind{model, model->basis()};
  return std::make_unique<Spline_design<Vector_kind>>(std::move(kind), 2, basis_size, omega);
}

std::unique_ptr<Field_design> make_n_field_design(std::shared_ptr<const Field_model> model, int n, int order,
                                                   int basis_size, double omega)
{
  N_field_kind kind{model, model->n_field_basis(n)};
  if(!kind.basis) throw Message_error("the basis of n = " + std::to_string(n) + " fields is not ready");
  return std::make_unique<Spline_design<N_field_kind>>(std::move(kind), order, basis_size, omega);
}

} // namespace tvf_viewer
