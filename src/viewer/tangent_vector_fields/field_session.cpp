// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The field sessions: parse and check a message, apply it to the reduced (and, on request,
// the full) spline solver, answer with the field.  See doc/viewer/protocol.md.

#include "field_request.h"

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/internal/constraint_json.h>

#include <algorithm>
#include <string>
#include <vector>

namespace tvf_viewer {

namespace {

std::string ids_json(const std::vector<int>& ids)
{
  return json_array(ids, [](int i) { return std::to_string(i); });
}

} // namespace

// --- the session --------------------------------------------------------------------------------

Field_session::Field_session(std::shared_ptr<const Field_model> model, std::string kind, int start_n)
  : model_(std::move(model)), kind_(std::move(kind)), start_n_(start_n)
{}

Field_session::~Field_session() = default;

std::string Field_session::farewell()
{
  int pending = 0;
  try
  {
    pending = refining() ? pending_pull_backs() : 0;
  }
  catch(const std::exception&) // a refusal of the full solver: nothing to say here
  {
  }
  if(pending == 0) return std::string();
  return "a page closed while its exact answer was being computed: refinement stopped with " +
         std::to_string(pending) + " of " + std::to_string(constraints()) + " constraints not pulled back";
}

void Field_session::handle_text(const std::string& text, const Send& send)
{
  Request request(send);
  try
  {
    read_request(request, text, model_->limits().max_message_bytes, model_->limits().max_json_depth);
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

void Field_session::dispatch(Request& r)
{
  static const std::map<std::string, void (Field_session::*)(Request&)> handlers = {
      {"hello", &Field_session::hello},
      {"set_n", &Field_session::set_n},
      {"add", &Field_session::add},
      {"change", &Field_session::change},
      {"remove", &Field_session::remove},
      {"clear", &Field_session::clear},
      {"load", &Field_session::load},
      {"save", &Field_session::save},
      {"set_omega", &Field_session::set_omega},
      {"set_basis_size", &Field_session::set_basis_size},
      {"set_solver", &Field_session::set_solver},
      {"set_display", &Field_session::set_display}};
  // The members each message may have besides "type" and "request": a misspelt one is refused.
  static const std::map<std::string, std::vector<const char*>> members = {
      {"hello", {"kind"}}, {"set_n", {"n", "order"}}, {"add", {"constraint"}}, {"change", {"id", "constraint"}}, {"remove", {"id"}}, {"clear", {}},
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
                        " (hello, set_n, add, change, remove, clear, load, save, set_omega, set_basis_size, "
                        "set_solver, set_display, ping)");
  (this->*it->second)(r);
}

void Field_session::require_ready(const Request&) const
{
  if(!design_) throw Message_error("say hello first (the session starts when the basis is ready)");
}

std::string Field_session::info_json() const
{
  const TVF::Intrinsic_mesh& mesh = model_->matrices().mesh();
  const TVF::Mesh_topology& topology = mesh.topology();
  const Field_limits& limits = model_->limits();
  return "\"type\":\"info\",\"kind\":" + quote(kind_) + ",\"mesh\":{\"name\":" + quote(model_->name()) +
         ",\"vertices\":" + std::to_string(mesh.number_of_vertices()) +
         ",\"faces\":" + std::to_string(mesh.number_of_faces()) + ",\"edges\":" + std::to_string(mesh.number_of_edges()) +
         ",\"genus\":" + std::to_string(topology.total_genus()) +
         ",\"boundary_loops\":" + std::to_string(topology.number_of_boundary_loops()) +
         ",\"components\":" + std::to_string(topology.number_of_components()) +
         ",\"area\":" + number(model_->matrices().face_areas().sum()) + ",\"diagonal\":" + number(model_->diagonal()) +
         ",\"mean_edge_length\":" + number(mesh.mean_edge_length()) + "},\"n\":" + std::to_string(design_->n()) +
         ",\"order\":" + std::to_string(design_->order()) + ",\"basis\":{\"available\":" +
         std::to_string(design_->available()) + ",\"size\":" + std::to_string(design_->basis_size()) +
         ",\"harmonic\":" + std::to_string(design_->kernel_dimension()) + "},\"omega\":" + number(design_->omega()) +
         ",\"solver\":\"" + (design_->full() ? "full" : "reduced") + "\",\"display\":{\"lines\":" + quote(display_.lines) +
         ",\"strokes\":" + std::to_string(display_.strokes) + ",\"length\":" + number(display_.length) +
         ",\"separation\":" + number(display_.separation) + ",\"scalar\":" + quote(display_.scalar) +
         "},\"limits\":{\"max_message_bytes\":" + std::to_string(limits.max_message_bytes) +
         ",\"max_constraints\":" + std::to_string(limits.max_constraints) +
         ",\"max_strokes\":" + std::to_string(limits.max_strokes) + ",\"max_n\":" + std::to_string(limits.max_n) + "}";
}

// Waits for the basis of n-fields of `n`, with its progress to the page.
void Field_session::wait_n_field(Request& r, int n)
{
  for(;;)
  {
    const Field_model::Status status = model_->wait_n_field(n, std::chrono::milliseconds(250));
    if(status.ready) return;
    if(status.failed) throw Message_error("the basis of n = " + std::to_string(n) + " fields could not be made: " + status.error);
    r.text("\"type\":\"status\",\"stage\":" + quote(status.stage) + ",\"fraction\":" + short_number(status.fraction));
  }
}

void Field_session::hello(Request& r)
{
  // The server chose this session by the first hello's kind; a later one cannot change it.
  if(r.tree.contains("kind") && text_member(r.tree, "kind") != kind_)
    throw Message_error("this connection holds a " + quote(kind_) + " session: open another for " +
                        quote(text_member(r.tree, "kind").substr(0, 64)));
  for(;;)
  {
    const Field_model::Status status = model_->wait(std::chrono::milliseconds(250));
    if(status.ready) break;
    if(status.failed) throw Message_error("the basis could not be made: " + status.error);
    r.text("\"type\":\"status\",\"stage\":" + quote(status.stage) + ",\"fraction\":" + short_number(status.fraction));
  }
  if(!design_)
  {
    const int size = model_->initial_basis_size();
    if(start_n_ > 1) wait_n_field(r, start_n_);
    design_ = start_n_ > 1 ? make_n_field_design(model_, start_n_, 2, size - size % 2, 0)
                           : make_vector_design(model_, size, 0);
    if(!design_->has_scalar(display_.scalar)) display_.scalar = "none";
  }
  r.text(info_json());
  (*r.send)(model_->mesh_message());
  send_field(r);
}

void Field_session::set_n(Request& r)
{
  require_ready(r);
  const int n = static_cast<int>(integer_member(r.tree, "n", 1, model_->limits().max_n));
  const int order = r.tree.contains("order") ? static_cast<int>(integer_member(r.tree, "order", 1, 3)) : 2;
  if(n == 1 && order != 2) throw Message_error("vector fields have the energy of order 2 (E_B): \"order\" is for n > 1");
  if(n != 1) wait_n_field(r, n);
  // A new design: the constraints of another n do not carry over.  The solver and tension
  // do; the basis size is the one sessions start with (`tvf serve -d`, within what the new
  // basis has).
  const bool full = design_->full();
  const int size = model_->initial_basis_size();
  std::unique_ptr<Field_design> design =
      n == 1 ? make_vector_design(model_, size, design_->omega())
             : make_n_field_design(model_, n, order, size - size % 2, design_->omega());
  if(full) design->set_full(true);
  design_ = std::move(design);
  if(!design_->has_scalar(display_.scalar)) display_.scalar = "none";
  r.text(info_json());
  send_field(r);
}

void Field_session::add(Request& r)
{
  require_ready(r);
  if(static_cast<int>(design_->ids().size()) >= model_->limits().max_constraints)
    throw Message_error("too many constraints (the limit is " + std::to_string(model_->limits().max_constraints) + ")");
  const int id = design_->add(member(r.tree, "constraint"), r.reduced_ms);
  r.text("\"type\":\"added\",\"id\":" + std::to_string(id));
  send_field(r);
}

void Field_session::change(Request& r)
{
  require_ready(r);
  const int id = static_cast<int>(integer_member(r.tree, "id", 0, 1 << 30));
  design_->change(id, member(r.tree, "constraint"), r.reduced_ms);
  send_field(r);
}

void Field_session::remove(Request& r)
{
  require_ready(r);
  design_->remove(static_cast<int>(integer_member(r.tree, "id", 0, 1 << 30)));
  send_field(r);
}

void Field_session::clear(Request& r)
{
  require_ready(r);
  design_->clear();
  send_field(r);
}

void Field_session::load(Request& r)
{
  require_ready(r);
  const std::vector<int> ids = design_->load(member(r.tree, "file"));
  r.text("\"type\":\"loaded\",\"ids\":" + ids_json(ids) + ",\"omega\":" + number(design_->omega()));
  send_field(r);
}

void Field_session::save(Request& r)
{
  require_ready(r);
  r.text("\"type\":\"constraints\",\"ids\":" + ids_json(design_->ids()) + ",\"file\":" + design_->save());
}

void Field_session::set_omega(Request& r)
{
  require_ready(r);
  const double omega = number_member(r.tree, "omega");
  if(omega < 0 || omega > 1e12) throw Message_error("\"omega\" must lie in [0, 1e12]");
  design_->set_omega(omega);
  send_field(r);
}

void Field_session::set_basis_size(Request& r)
{
  require_ready(r);
  const int size = static_cast<int>(integer_member(r.tree, "size", 1, design_->available()));
  if(design_->n() > 1 && size % 2 != 0)
    throw Message_error("\"size\" must be even for n-fields (the basis comes in pairs z, i z)");
  design_->set_basis_size(size);
  send_field(r);
}

void Field_session::set_solver(Request& r)
{
  require_ready(r);
  const std::string solver = text_member(r.tree, "solver");
  if(solver != "reduced" && solver != "full") throw Message_error("\"solver\" must be \"reduced\" or \"full\"");
  design_->set_full(solver == "full");
  send_field(r);
}

} // namespace tvf_viewer
