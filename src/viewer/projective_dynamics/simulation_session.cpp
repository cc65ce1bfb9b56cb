// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The simulation session: check a message, act on the simulation, answer with its state;
// while playing, step and send the surface's positions.  See doc/viewer/protocol.md.

#include "simulation_session.h"

#include <CGAL/Projective_dynamics/errors.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <thread>
#include <vector>

namespace tvf_viewer {

// Stiffness accepted: this many times the default, up or down (beyond, the factorisation of
// a stiff body or the sag of a soft one leave what a person can watch).
static const double stiffness_span = 1e4;
// Positions farther than this many diagonals from the floor's centre have blown up.
static const double blow_up_distance = 100;
static const double longest_time_step = 0.1;


namespace {

// A finite number; a page's NaN arrives as null (JSON.stringify) and is refused by name.
double finite_member(const Json& tree, const char* key)
{
  if(member(tree, key).is_null()) throw Message_error(std::string("\"") + key + "\" is NaN (null): it must be a finite number");
  return number_member(tree, key);
}

Eigen::RowVector3d vector_member(const Json& tree, const char* key)
{
  const Json& node = member(tree, key);
  const std::string name = std::string("\"") + key + "\"";
  if(!node.is_array() || node.size() != 3) throw Message_error(name + " must be an array of 3 numbers [x, y, z]");
  Eigen::RowVector3d v;
  for(std::size_t k = 0; k < 3; ++k)
  {
    if(node[k].is_null()) throw Message_error(name + " has a NaN coordinate (null): every coordinate must be a finite number");
    if(!node[k].is_number()) throw Message_error(name + " has a coordinate that is not a number");
    v[Eigen::Index(k)] = node[k].get<double>();
    if(!std::isfinite(v[Eigen::Index(k)])) throw Message_error(name + " has a coordinate that is not finite");
  }
  return v;
}

bool boolean_member(const Json& tree, const char* key)
{
  if(!member(tree, key).is_boolean()) throw Message_error(std::string("\"") + key + "\" must be true or false");
  return tree[key].get<bool>();
}

std::string vertex_json(const std::optional<int>& v) { return v ? std::to_string(*v) : std::string("null"); }

} // namespace

Simulation_session::Simulation_session(std::shared_ptr<const Simulation_surface> surface, Simulation_limits limits)
  : surface_(std::move(surface)), limits_(limits)
{}

void Simulation_session::handle_text(const std::string& text, const Send& send)
{
  Request r(send);
  try
  {
    read_request(r, text, limits_.max_message_bytes, limits_.max_json_depth);
    // The members each message may have: a misspelt one is refused, by name.
    static const std::map<std::string, std::vector<const char*>> members = {
        {"hello", {"kind", "mode", "simulator", "playing"}},
        {"play", {}}, {"pause", {}}, {"reset", {}}, {"drop", {}}, {"release", {}}, {"ping", {}},
        {"step", {"count"}}, {"grab", {"vertex", "point", "target"}}, {"move", {"target"}},
        {"poke", {"vertex", "point", "velocity"}}, {"stiffness", {"value"}}, {"time_step", {"value"}}};
    const auto allowed = members.find(r.type);
    if(allowed == members.end())
      throw Message_error("unknown message type " + quote(r.type.substr(0, 64)) +
                          " (hello, play, pause, step, reset, drop, grab, move, release, poke, stiffness, time_step, ping)");
    std::vector<const char*> keys = allowed->second;
    keys.push_back("type");
    keys.push_back("request");
    TVF::internal::Json_reader{r.tree, r.type}.allow_only(keys);
    if(r.type == "ping") return r.text("\"type\":\"pong\"");
    if(r.type == "hello") return hello(r);
    if(!body_) throw Message_error("no simulation yet: send \"hello\" first");
    Stepper& stepper = body_->stepper();
    if(r.type == "play")
    {
      playing_ = true;
      paced_ = false;
      next_due_ = Clock::now();
    }
    else if(r.type == "pause") playing_ = false;
    else if(r.type == "step")
    {
      const long long count = integer_member(r.tree, "count", 1, limits_.max_steps);
      for(long long i = 0; i < count; ++i)
        if(!step_and_send(send, -1, std::string())) break;
    }
    else if(r.type == "reset")
    {
      restart(body_->rest());
      send_frame(send, -1, -1, std::string());
    }
    else if(r.type == "drop")
    {
      // The shape as it is now, lifted (or lowered) to where the start shape was above the floor.
      PD::Positions q = stepper.positions();
      q.col(2).array() += body_->drawn(body_->rest()).col(2).minCoeff() - drawn_.col(2).minCoeff();
      restart(q);
      send_frame(send, -1, -1, std::string());
    }
    else if(r.type == "grab") grab(r);
    else if(r.type == "move")
    {
      const Eigen::RowVector3d target = vector_member(r.tree, "target");
      if(!grabbed_) throw Message_error("nothing is grabbed: send \"grab\" first");
      stepper.move_grabbed(target + grab_offset_);
    }
    else if(r.type == "release")
    {
      if(grabbed_) stepper.release_grabbed();
      grabbed_.reset();
    }
    else if(r.type == "poke") poke(r);
    else if(r.type == "stiffness")
    {
      const double k = finite_member(r.tree, "value");
      const double lowest = body_->default_stiffness() / stiffness_span, highest = body_->default_stiffness() * stiffness_span;
      if(!(k > 0)) throw Message_error("the stiffness must be > 0 (got " + short_number(k) + ")");
      if(k < lowest || k > highest)
        throw Message_error("the stiffness " + short_number(k) + " is outside [" + short_number(lowest) + ", " +
                            short_number(highest) + "] (the default times 1e-4 to 1e4)");
      body_->set_stiffness(k); // refactors only the small matrix on the next step
    }
    else if(r.type == "time_step")
    {
      const double h = finite_member(r.tree, "value");
      if(!(h > 0) || h > longest_time_step)
        throw Message_error("the time step must lie in (0, " + short_number(longest_time_step) + "] seconds (got " +
                            short_number(h) + ")");
      stepper.set_time_step(h);
      time_step_ = h;
    }
    r.text(state_json());
  }
  catch(const Message_error& e)
  {
    r.text("\"type\":\"error\",\"message\":" + quote(e.what()));
  }
  catch(const std::invalid_argument& e) // Invalid_input and Invalid_mesh of the library's checks
  {
    r.text("\"type\":\"error\",\"message\":" + quote(e.what()));
  }
  catch(const CGAL::Projective_dynamics::Numerical_failure& e)
  {
    r.text("\"type\":\"error\",\"message\":" + quote(std::string("the simulation failed: ") + e.what()));
  }
  catch(const std::bad_alloc&)
  {
    r.text("\"type\":\"error\",\"message\":\"out of memory\"");
  }
}

void Simulation_session::hello(Request& r)
{
  const Json& t = r.tree;
  if(t.contains("kind") && text_member(t, "kind") != "simulation")
    throw Message_error("this connection holds a \"simulation\" session: open another for " +
                        quote(text_member(t, "kind").substr(0, 64)));
  Body_request request;
  if(t.contains("mode"))
  {
    const std::string mode = text_member(t, "mode");
    if(mode != "shell" && mode != "solid")
      throw Message_error("\"mode\" must be \"shell\" or \"solid\", not " + quote(mode.substr(0, 64)));
    request.solid = mode == "solid";
  }
  if(t.contains("simulator"))
  {
    const std::string s = text_member(t, "simulator");
    if(s != "reduced" && s != "full")
      throw Message_error("\"simulator\" must be \"reduced\" or \"full\", not " + quote(s.substr(0, 64)));
    request.reduced = s == "reduced";
  }
  const bool playing = t.contains("playing") ? boolean_member(t, "playing") : true;
  // Built before anything is replaced: a refused hello leaves the session as it was.
  auto body = std::make_unique<Simulation_body>(*surface_, request);
  body_ = std::move(body);
  steps_ = 0;
  time_ = 0;
  time_step_ = body_->default_time_step();
  grabbed_.reset();
  drawn_ = body_->drawn(body_->stepper().positions());

  const double k = body_->default_stiffness();
  r.text("\"type\":\"info\",\"kind\":\"simulation\",\"mesh\":{\"name\":" + quote(surface_->name) +
         ",\"vertices\":" + std::to_string(surface_->points.size()) + ",\"faces\":" +
         std::to_string(surface_->triangles.size()) + ",\"closed\":" + (surface_->closed ? "true" : "false") +
         "},\"body\":{" + body_->description_json() + "},\"floor\":" + number(body_->floor_height()) +
         ",\"diagonal\":" + number(body_->diagonal()) + ",\"stiffness\":{\"value\":" + number(k) + ",\"default\":" +
         number(k) + ",\"min\":" + number(k / stiffness_span) + ",\"max\":" + number(k * stiffness_span) +
         "},\"time_step\":" + number(time_step_) + ",\"frame_hz\":" + short_number(limits_.frame_hz) +
         ",\"limits\":{\"max_steps\":" + std::to_string(limits_.max_steps) + ",\"max_message_bytes\":" +
         std::to_string(limits_.max_message_bytes) + "}");
  // The mesh once (the page draws it), then the first frame, which answers the hello.
  std::vector<float> positions;
  std::vector<std::uint32_t> triangles;
  for(const PD::Point& p : surface_->points) positions.insert(positions.end(), {float(p[0]), float(p[1]), float(p[2])});
  for(const PD::Triangle& f : surface_->triangles)
    triangles.insert(triangles.end(), {std::uint32_t(f[0]), std::uint32_t(f[1]), std::uint32_t(f[2])});
  (*r.send)(binary_message("\"type\":\"mesh\"", {{"positions", true, positions.data(), positions.size()},
                                                 {"triangles", false, triangles.data(), triangles.size()}}));
  send_frame(*r.send, -1, -1, r.echo());
  playing_ = playing;
  paced_ = false;
  next_due_ = Clock::now();
}

int Simulation_session::vertex_of(const Json& tree) const
{
  const bool has_vertex = tree.contains("vertex"), has_point = tree.contains("point");
  if(has_vertex == has_point) throw Message_error("give either \"vertex\" or \"point\" (the nearest surface vertex)");
  const long long n = (long long)surface_->points.size();
  if(has_vertex)
  {
    const Json& node = member(tree, "vertex");
    const double v = node.is_number() ? node.get<double>() : -1;
    if(!node.is_number() || v != std::floor(v) || v < 0 || v >= double(n))
      throw Message_error("unknown vertex " + (node.is_number() ? short_number(v) : std::string(node.dump()).substr(0, 32)) +
                          ": the surface has " + std::to_string(n) + " vertices (0 to " + std::to_string(n - 1) + ")");
    return int(v);
  }
  const Eigen::RowVector3d p = vector_member(tree, "point");
  Eigen::Index nearest = 0;
  (drawn_.rowwise() - p).rowwise().squaredNorm().minCoeff(&nearest);
  return int(nearest);
}

void Simulation_session::grab(Request& r)
{
  const int v = vertex_of(r.tree);
  const Eigen::RowVector3d target = r.tree.contains("target") ? vector_member(r.tree, "target")
                                                              : Eigen::RowVector3d(drawn_.row(v));
  Stepper& stepper = body_->stepper();
  const PD::Positions q = stepper.positions();
  const int s = body_->simulated_vertex(v, q);
  grab_offset_ = q.row(s) - drawn_.row(v);
  stepper.grab(s, target + grab_offset_);
  grabbed_ = v;
}

void Simulation_session::poke(Request& r)
{
  const int v = vertex_of(r.tree);
  const Eigen::RowVector3d dv = vector_member(r.tree, "velocity");
  const double fastest = 100 * body_->diagonal();
  if(dv.norm() > fastest)
    throw Message_error("the poke's velocity " + short_number(dv.norm()) + " is above " + short_number(fastest) +
                        " (100 diagonals per second)");
  // Spread over a tenth of the diagonal around the vertex, fading out: a fingertip, not a needle.
  Stepper& stepper = body_->stepper();
  const PD::Positions q = stepper.positions();
  PD::Positions velocity = stepper.velocities();
  const double radius = 0.1 * body_->diagonal();
  for(Eigen::Index i = 0; i < q.rows(); ++i)
  {
    const double d = (q.row(i) - drawn_.row(v)).norm();
    if(d < radius) velocity.row(i) += (1 - d / radius) * (1 - d / radius) * dv;
  }
  stepper.set_state(q, velocity);
}

void Simulation_session::restart(const PD::Positions& q)
{
  Stepper& stepper = body_->stepper();
  if(grabbed_) stepper.release_grabbed();
  grabbed_.reset();
  stepper.set_state(q, PD::Positions::Zero(q.rows(), 3));
  drawn_ = body_->drawn(stepper.positions());
}

bool Simulation_session::step_and_send(const Send& send, double interval_ms, const std::string& echo)
{
  Stepper& stepper = body_->stepper();
  const PD::Positions q0 = stepper.positions(), v0 = stepper.velocities();
  std::string failure;
  try
  {
    stepper.step();
  }
  catch(const CGAL::Projective_dynamics::Numerical_failure& e)
  {
    failure = e.what();
  }
  PD::Positions q = failure.empty() ? stepper.positions() : q0;
  if(failure.empty())
  {
    const Eigen::RowVector3d centre = 0.5 * (body_->rest().colwise().minCoeff() + body_->rest().colwise().maxCoeff());
    const double far = blow_up_distance * body_->diagonal();
    if(!q.allFinite()) failure = "positions are no longer finite";
    else if((q.rowwise() - centre).rowwise().norm().maxCoeff() > far)
      failure = "a vertex went farther than " + short_number(blow_up_distance) + " diagonals away";
  }
  if(!failure.empty())
  {
    try
    {
      stepper.set_state(q0, v0);
    }
    catch(const std::exception&) // the state before was finite; nothing better to do
    {}
    playing_ = false;
    send(Outgoing{false, "{\"type\":\"error\",\"blown_up\":true,\"message\":" +
                             quote("the simulation blew up at step " + std::to_string(steps_ + 1) + " (" + failure +
                                   "): paused at the step before; send \"reset\" to start again") +
                             "}"});
    return false;
  }
  ++steps_;
  time_ += time_step_;
  drawn_ = body_->drawn(q);
  send_frame(send, 1000 * stepper.last_step_seconds(), interval_ms, echo);
  return true;
}

void Simulation_session::send_frame(const Send& send, double simulation_ms, double interval_ms, const std::string& echo)
{
  std::vector<float> positions(std::size_t(3 * drawn_.rows()));
  for(Eigen::Index v = 0; v < drawn_.rows(); ++v)
    for(Eigen::Index k = 0; k < 3; ++k) positions[std::size_t(3 * v + k)] = float(drawn_(v, k));
  const double period_ms = 1000 / limits_.frame_hz;
  send(binary_message("\"type\":\"frame\"" + echo + ",\"step\":" + std::to_string(steps_) + ",\"time\":" + number(time_) +
                          ",\"lowest\":" + number(drawn_.col(2).minCoeff()) + ",\"grabbed\":" + vertex_json(grabbed_) +
                          ",\"timings\":{\"simulation_ms\":" +
                          (simulation_ms < 0 ? std::string("null") : short_number(simulation_ms)) +
                          ",\"interval_ms\":" + (interval_ms < 0 ? std::string("null") : short_number(interval_ms)) +
                          "},\"late\":" + (interval_ms > 1.25 * period_ms ? "true" : "false"),
                      {{"positions", true, positions.data(), positions.size()}}));
}

void Simulation_session::poll(const Send& send, std::chrono::milliseconds budget)
{
  if(!playing_ || !body_) return;
  const auto now = Clock::now();
  if(now < next_due_)
  {
    // Sleep a little, not until the frame is due: a message of the page may arrive meanwhile.
    std::this_thread::sleep_for(std::min<Clock::duration>(next_due_ - now, std::max<Clock::duration>(budget, std::chrono::milliseconds(1))));
    return;
  }
  const double interval_ms = paced_ ? std::chrono::duration<double, std::milli>(now - last_frame_).count() : -1;
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1 / limits_.frame_hz));
  // Behind (a step slower than the period): the next step at once, never a burst to catch up.
  next_due_ = std::max(next_due_ + period, now);
  last_frame_ = now;
  paced_ = true;
  step_and_send(send, interval_ms, std::string());
}

std::string Simulation_session::state_json() const
{
  return "\"type\":\"state\",\"playing\":" + std::string(playing_ ? "true" : "false") + ",\"step\":" +
         std::to_string(steps_) + ",\"time\":" + number(time_) + ",\"stiffness\":" + number(body_->stiffness()) +
         ",\"time_step\":" + number(time_step_) + ",\"grabbed\":" + vertex_json(grabbed_);
}

} // namespace tvf_viewer
