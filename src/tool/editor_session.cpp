// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The editor's sessions: parse and check a message, apply it to the reduced (and, on
// request, the full) spline solver, answer with the field.  See doc/editor_protocol.md.

#include "editor_messages.h"
#include "tool.h" // field_norm

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/internal/constraint_json.h>


#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace tvf_tool {

namespace {

// The values of a constraint the field is affine in, with the constraint's kind and place
// fixed: a vector's frame components, a divergence's or curl's value.  Empty for a direction
// (its rows depend on it).
std::vector<double> value_parameters(const TVF::Intrinsic_mesh& mesh, const TVF::Field_constraint& c)
{
  switch(c.kind)
  {
  case TVF::Constraint_kind::vector: {
    const auto a = mesh.to_frame(c.face, c.vector);
    return {a[0], a[1]};
  }
  case TVF::Constraint_kind::divergence:
  case TVF::Constraint_kind::curl: return {c.value};
  default: return {};
  }
}

TVF::Field_constraint with_value_parameters(const TVF::Intrinsic_mesh& mesh, TVF::Field_constraint c,
                                            const std::vector<double>& p)
{
  if(c.kind == TVF::Constraint_kind::vector) c.vector = mesh.from_frame(c.face, p[0], p[1]);
  else c.value = p[0];
  return c;
}

TVF::Spline_options spline_options(double omega)
{
  TVF::Spline_options options;
  options.omega = omega;
  return options;
}

} // namespace

// --- the session --------------------------------------------------------------------------------

Editor_session::Editor_session(std::shared_ptr<const Editor_model> model) : model_(std::move(model)) {}

Editor_session::~Editor_session() = default;

void Editor_session::refuse_binary(std::size_t bytes, const Send& send)
{
  send({false, "{\"type\":\"error\",\"message\":" +
                   quote("binary messages are not accepted (" + std::to_string(bytes) + " bytes): send JSON text") +
                   "}"});
}

void Editor_session::refuse_oversized(std::size_t bytes, const Send& send)
{
  send({false, "{\"type\":\"error\",\"message\":" +
                   quote("message of " + std::to_string(bytes) + " bytes or more exceeds the limit of " +
                         std::to_string(model_->limits().max_message_bytes) + " bytes") +
                   "}"});
}

void Editor_session::handle_text(const std::string& text, const Send& send)
{
  Request request;
  request.received = Clock::now();
  request.send = &send;
  try
  {
    if(text.size() > model_->limits().max_message_bytes) return refuse_oversized(text.size(), send);
    // Strict: syntax, duplicate keys and deep nesting are refused while parsing.
    request.tree = TVF::internal::parse_json(text, "not JSON", model_->limits().max_json_depth);
    if(!request.tree.is_object()) throw Message_error("a message must be a JSON object");
    if(request.tree.contains("request"))
    {
      request.id = integer_member(request.tree, "request", 0, (1LL << 53));
      request.has_id = true;
    }
    request.type = text_member(request.tree, "type");
    dispatch(request);
  }
  catch(const Message_error& e)
  {
    request.text("\"type\":\"error\",\"message\":" + quote(e.what()));
  }
  catch(const TVF::Invalid_input& e) // malformed or infeasible constraints, bad sizes
  {
    request.text("\"type\":\"error\",\"message\":" + quote(e.what()));
  }
  catch(const std::bad_alloc&)
  {
    request.text("\"type\":\"error\",\"message\":\"out of memory\"");
  }
}

void Editor_session::dispatch(Request& r)
{
  static const std::map<std::string, void (Editor_session::*)(Request&)> handlers = {
      {"hello", &Editor_session::hello},
      {"add", &Editor_session::add},
      {"change", &Editor_session::change},
      {"remove", &Editor_session::remove},
      {"clear", &Editor_session::clear},
      {"load", &Editor_session::load},
      {"save", &Editor_session::save},
      {"set_omega", &Editor_session::set_omega},
      {"set_basis_size", &Editor_session::set_basis_size},
      {"set_solver", &Editor_session::set_solver},
      {"set_display", &Editor_session::set_display}};
  // The members each message may have besides "type" and "request": a misspelt one is refused.
  static const std::map<std::string, std::vector<const char*>> members = {
      {"hello", {}}, {"add", {"constraint"}}, {"change", {"id", "constraint"}}, {"remove", {"id"}}, {"clear", {}},
      {"load", {"file"}}, {"save", {}}, {"set_omega", {"omega"}}, {"set_basis_size", {"size"}},
      {"set_solver", {"solver"}}, {"set_display", {"lines", "strokes", "length", "separation", "scalar"}}, {"ping", {}}};
  const auto allowed = members.find(r.type);
  if(allowed != members.end())
  {
    std::vector<const char*> keys = allowed->second;
    keys.push_back("type");
    keys.push_back("request");
    TVF::internal::Json_reader{r.tree, r.type}.allow_only(keys);
  }
  if(r.type == "ping") return r.text("\"type\":\"pong\"");
  const auto it = handlers.find(r.type);
  if(it == handlers.end())
    throw Message_error("unknown message type " + quote(r.type.substr(0, 64)) +
                        " (hello, add, change, remove, clear, load, save, set_omega, set_basis_size, "
                        "set_solver, set_display, ping)");
  (this->*it->second)(r);
}

void Editor_session::require_ready(const Request&) const
{
  if(!reduced_) throw Message_error("say hello first (the session starts when the basis is ready)");
}

std::string Editor_session::info_json() const
{
  const TVF::Intrinsic_mesh& mesh = model_->matrices().mesh();
  const TVF::Mesh_topology& topology = mesh.topology();
  const Editor_limits& limits = model_->limits();
  return "\"type\":\"info\",\"mesh\":{\"name\":" + quote(model_->name()) +
         ",\"vertices\":" + std::to_string(mesh.number_of_vertices()) +
         ",\"faces\":" + std::to_string(mesh.number_of_faces()) + ",\"edges\":" + std::to_string(mesh.number_of_edges()) +
         ",\"genus\":" + std::to_string(topology.total_genus()) +
         ",\"boundary_loops\":" + std::to_string(topology.number_of_boundary_loops()) +
         ",\"components\":" + std::to_string(topology.number_of_components()) +
         ",\"area\":" + number(model_->matrices().face_areas().sum()) + ",\"diagonal\":" + number(model_->diagonal()) +
         ",\"mean_edge_length\":" + number(mesh.mean_edge_length()) + "},\"basis\":{\"available\":" +
         std::to_string(reduced_->basis().size()) + ",\"size\":" + std::to_string(reduced_->basis_size()) +
         ",\"harmonic\":" + std::to_string(reduced_->basis().number_of_harmonic()) + "},\"omega\":" + number(omega_) +
         ",\"solver\":\"" + (use_full_ ? "full" : "reduced") + "\",\"display\":{\"lines\":" + quote(display_.lines) +
         ",\"strokes\":" + std::to_string(display_.strokes) + ",\"length\":" + number(display_.length) +
         ",\"separation\":" + number(display_.separation) + ",\"scalar\":" + quote(display_.scalar) +
         "},\"limits\":{\"max_message_bytes\":" + std::to_string(limits.max_message_bytes) +
         ",\"max_constraints\":" + std::to_string(limits.max_constraints) +
         ",\"max_strokes\":" + std::to_string(limits.max_strokes) + "}";
}

void Editor_session::hello(Request& r)
{
  for(;;)
  {
    const Editor_model::Status status = model_->wait(std::chrono::milliseconds(250));
    if(status.ready) break;
    if(status.failed) throw Message_error("the basis could not be made: " + status.error);
    r.text("\"type\":\"status\",\"stage\":" + quote(status.stage) + ",\"fraction\":" + short_number(status.fraction));
  }
  if(!reduced_)
  {
    const auto basis = model_->basis();
    const int size = std::min(model_->initial_basis_size() > 0 ? model_->initial_basis_size() : basis->size(), basis->size());
    reduced_ = std::make_unique<TVF::Reduced_spline_solver>(basis, size, spline_options(omega_));
  }
  r.text(info_json());
  (*r.send)(model_->mesh_message());
  send_field(r);
}

void Editor_session::add(Request& r)
{
  require_ready(r);
  if(static_cast<int>(entries_.size()) >= model_->limits().max_constraints)
    throw Message_error("too many constraints (the limit is " + std::to_string(model_->limits().max_constraints) + ")");
  Entry entry;
  entry.constraint = TVF::internal::parse_constraint(member(r.tree, "constraint"), "constraint", model_->matrices(),
                                                     &entry.weight);
  Clock::time_point start = Clock::now();
  entry.reduced = reduced_->add(entry.constraint);
  r.reduced_ms = milliseconds_since(start);
  if(use_full_)
  {
    try
    {
      std::lock_guard<std::mutex> lock(model_->full_solver_mutex());
      r.progress("full solution: pulling back the new constraint", 0);
      start = Clock::now();
      entry.full = full_->add(entry.constraint);
      r.full_ms = milliseconds_since(start);
    }
    catch(...)
    {
      reduced_->remove(entry.reduced);
      throw;
    }
  }
  const int id = next_id_++;
  entries_[id] = entry;
  ++structure_;
  r.text("\"type\":\"added\",\"id\":" + std::to_string(id));
  send_field(r);
}

void Editor_session::change(Request& r)
{
  require_ready(r);
  const int id = static_cast<int>(integer_member(r.tree, "id", 0, 1 << 30));
  const auto it = entries_.find(id);
  if(it == entries_.end()) throw Message_error("no constraint with id " + std::to_string(id));
  Entry& entry = it->second;
  double weight = 1;
  const TVF::Field_constraint constraint =
      TVF::internal::parse_constraint(member(r.tree, "constraint"), "constraint", model_->matrices(), &weight);
  const TVF::Field_constraint old = entry.constraint;
  Clock::time_point start = Clock::now();
  reduced_->change(entry.reduced, constraint); // unchanged if it throws
  r.reduced_ms = milliseconds_since(start);
  if(use_full_)
  {
    try
    {
      std::lock_guard<std::mutex> lock(model_->full_solver_mutex());
      if(!old.same_rows_as(constraint)) r.progress("full solution: pulling back the moved constraint", 0);
      start = Clock::now();
      full_->change(entry.full, constraint);
      r.full_ms = milliseconds_since(start);
    }
    catch(...)
    {
      reduced_->change(entry.reduced, old);
      throw;
    }
  }
  const bool same_rows = old.same_rows_as(constraint);
  entry.constraint = constraint;
  entry.weight = weight;
  if(!same_rows) ++structure_;
  else
  {
    start = Clock::now();
    has_edited_field_ = value_edit_field(id, constraint, edited_field_);
    edited_field_ms_ = milliseconds_since(start);
  }
  send_field(r);
}

bool Editor_session::value_edit_field(int id, const TVF::Field_constraint& constraint, Eigen::VectorXd& field)
{
  const TVF::Intrinsic_mesh& mesh = model_->matrices().mesh();
  const std::vector<double> p = value_parameters(mesh, constraint);
  if(p.empty()) return false;
  Value_responses& cache = responses_;
  if(cache.id != id || cache.structure != structure_)
  {
    // One pass over the basis for the field and its responses: the coefficients are exact
    // differences of solves (the solution is linear in the values), the reconstruction of
    // several columns costs about as much as one (it reads the eigenfunctions once).
    const TVF::Constraint_id rid = entries_.at(id).reduced;
    const Eigen::Index d = reduced_->basis_size(), n = static_cast<Eigen::Index>(p.size());
    Eigen::MatrixXd a(d, 1 + n);
    a.col(0) = reduced_->coefficients();
    for(Eigen::Index k = 0; k < n; ++k)
    {
      std::vector<double> q = p;
      q[k] += 1;
      reduced_->change(rid, with_value_parameters(mesh, constraint, q));
      a.col(1 + k) = reduced_->coefficients() - a.col(0);
    }
    reduced_->change(rid, constraint);
    const Eigen::MatrixXd x = model_->basis()->decompress({a, 0, 0, {}});
    cache.id = id;
    cache.structure = structure_;
    cache.parameters = p;
    cache.field = x.col(0);
    cache.responses = x.rightCols(n);
    field = cache.field;
    return true;
  }
  Eigen::VectorXd change(p.size());
  for(std::size_t k = 0; k < p.size(); ++k) change[k] = p[k] - cache.parameters[k];
  field = cache.field + cache.responses * change;
  return true;
}

void Editor_session::remove(Request& r)
{
  require_ready(r);
  ++structure_;
  const int id = static_cast<int>(integer_member(r.tree, "id", 0, 1 << 30));
  const auto it = entries_.find(id);
  if(it == entries_.end()) throw Message_error("no constraint with id " + std::to_string(id));
  reduced_->remove(it->second.reduced);
  if(use_full_)
  {
    std::lock_guard<std::mutex> lock(model_->full_solver_mutex());
    full_->remove(it->second.full);
  }
  entries_.erase(it);
  send_field(r);
}

void Editor_session::clear(Request& r)
{
  require_ready(r);
  ++structure_;
  reduced_->clear();
  if(use_full_)
  {
    std::lock_guard<std::mutex> lock(model_->full_solver_mutex());
    full_->clear();
  }
  entries_.clear();
  send_field(r);
}

void Editor_session::load(Request& r)
{
  require_ready(r);
  const TVF::Constraint_file file = TVF::internal::parse_constraint_file(member(r.tree, "file"), model_->matrices());
  if(static_cast<int>(file.constraints.size()) > model_->limits().max_constraints)
    throw Message_error("too many constraints (" + std::to_string(file.constraints.size()) + "; the limit is " +
                        std::to_string(model_->limits().max_constraints) + ")");
  const double omega = file.has_omega ? file.omega : omega_;
  // All or nothing: new solvers, swapped in once every constraint fitted.
  auto reduced =
      std::make_unique<TVF::Reduced_spline_solver>(model_->basis(), reduced_->basis_size(), spline_options(omega));
  const std::vector<TVF::Constraint_id> reduced_ids = reduced->add(file.constraints);
  std::unique_ptr<TVF::Full_spline_solver> full;
  std::vector<TVF::Constraint_id> full_ids;
  if(use_full_)
  {
    std::lock_guard<std::mutex> lock(model_->full_solver_mutex());
    full = std::make_unique<TVF::Full_spline_solver>(model_->hodge(), spline_options(omega));
    r.progress("full solution: pulling back " + std::to_string(file.constraints.size()) + " constraints", 0);
    full_ids = full->add(file.constraints);
  }
  reduced_ = std::move(reduced);
  full_ = std::move(full);
  omega_ = omega;
  ++structure_;
  entries_.clear();
  std::vector<int> ids;
  for(std::size_t i = 0; i < file.constraints.size(); ++i)
  {
    Entry entry;
    entry.constraint = file.constraints[i];
    entry.weight = file.weights[i];
    entry.reduced = reduced_ids[i];
    if(use_full_) entry.full = full_ids[i];
    ids.push_back(next_id_);
    entries_[next_id_++] = entry;
  }
  r.text("\"type\":\"loaded\",\"ids\":" + json_array(ids, [](int i) { return std::to_string(i); }) +
         ",\"omega\":" + number(omega_));
  send_field(r);
}

void Editor_session::save(Request& r)
{
  require_ready(r);
  TVF::Constraint_file file;
  file.omega = omega_;
  file.has_omega = true;
  std::vector<int> ids;
  for(const auto& e : entries_)
  {
    ids.push_back(e.first);
    file.constraints.push_back(e.second.constraint);
    file.weights.push_back(e.second.weight);
  }
  std::ostringstream out;
  TVF::write_constraint_file(out, file, model_->matrices().mesh());
  r.text("\"type\":\"constraints\",\"ids\":" + json_array(ids, [](int i) { return std::to_string(i); }) +
         ",\"file\":" + out.str());
}

void Editor_session::set_omega(Request& r)
{
  require_ready(r);
  const double omega = number_member(r.tree, "omega");
  if(omega < 0 || omega > 1e12) throw Message_error("\"omega\" must lie in [0, 1e12]");
  reduced_->set_omega(omega);
  ++structure_;
  if(use_full_)
  {
    std::lock_guard<std::mutex> lock(model_->full_solver_mutex());
    r.progress("full solution: new tension, pulling back every constraint", 0);
    full_->set_omega(omega);
  }
  omega_ = omega;
  send_field(r);
}

void Editor_session::set_basis_size(Request& r)
{
  require_ready(r);
  const int available = reduced_->basis().size();
  const int size = static_cast<int>(integer_member(r.tree, "size", 1, available));
  if(size != reduced_->basis_size())
  {
    auto reduced = std::make_unique<TVF::Reduced_spline_solver>(model_->basis(), size, spline_options(omega_));
    std::vector<TVF::Field_constraint> constraints;
    for(const auto& e : entries_) constraints.push_back(e.second.constraint);
    std::vector<TVF::Constraint_id> ids;
    try
    {
      ids = reduced->add(constraints); // all or nothing
    }
    catch(const TVF::Invalid_input& e)
    {
      throw Message_error("the constraints do not fit a basis of " + std::to_string(size) + " fields: " + e.what());
    }
    reduced_ = std::move(reduced);
    ++structure_;
    std::size_t i = 0;
    for(auto& e : entries_) e.second.reduced = ids[i++];
  }
  send_field(r);
}

void Editor_session::sync_full(Request& r)
{
  std::lock_guard<std::mutex> lock(model_->full_solver_mutex());
  r.progress("full solution: factoring", 0);
  auto full = std::make_unique<TVF::Full_spline_solver>(model_->hodge(), spline_options(omega_));
  // In chunks, so that the page sees progress (a batch of pull-backs shares the solves' set-up).
  std::vector<std::map<int, Entry>::iterator> order;
  for(auto it = entries_.begin(); it != entries_.end(); ++it) order.push_back(it);
  const std::size_t chunk = std::max<std::size_t>(1, order.size() / 10);
  for(std::size_t start = 0; start < order.size(); start += chunk)
  {
    const std::size_t end = std::min(order.size(), start + chunk);
    std::vector<TVF::Field_constraint> constraints;
    for(std::size_t i = start; i < end; ++i) constraints.push_back(order[i]->second.constraint);
    const std::vector<TVF::Constraint_id> ids = full->add(constraints);
    for(std::size_t i = start; i < end; ++i) order[i]->second.full = ids[i - start];
    r.progress("full solution: pulled back " + std::to_string(end) + " of " + std::to_string(order.size()) +
                   " constraints",
               double(end) / order.size());
  }
  full_ = std::move(full);
}

void Editor_session::set_solver(Request& r)
{
  require_ready(r);
  const std::string solver = text_member(r.tree, "solver");
  if(solver != "reduced" && solver != "full") throw Message_error("\"solver\" must be \"reduced\" or \"full\"");
  if(solver == "full" && !use_full_)
  {
    sync_full(r);
    use_full_ = true;
  }
  else if(solver == "reduced")
  {
    use_full_ = false;
    full_.reset(); // its pull-backs are big (one field per row); keep nothing we do not show
  }
  send_field(r);
}

} // namespace tvf_tool
