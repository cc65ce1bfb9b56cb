// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The editor's field message: the session's display settings and what the display needs
// (the field as 3D vectors, a scalar, streamlines or fur), computed only when asked for.

#include "field_request.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tvf_viewer {

void Field_session::set_display(Request& r)
{
  require_ready(r);
  Display_settings display = display_;
  const Json& t = r.tree;
  if(t.contains("lines"))
  {
    display.lines = text_member(t, "lines");
    if(display.lines != "fur" && display.lines != "streamlines" && display.lines != "none")
      throw Message_error("\"lines\" must be \"fur\", \"streamlines\" or \"none\"");
  }
  if(t.contains("scalar"))
  {
    display.scalar = text_member(t, "scalar");
    if(display.scalar != "none" && !design_->has_scalar(display.scalar))
      throw Message_error(design_->n() == 1 ? "\"scalar\" must be \"divergence\", \"curl\" or \"none\" for a vector field"
                                            : "\"scalar\" must be \"energy\" or \"none\" for an n-field");
  }
  if(t.contains("strokes")) display.strokes = static_cast<int>(integer_member(t, "strokes", 1, model_->limits().max_strokes));
  if(t.contains("length"))
  {
    display.length = number_member(t, "length");
    if(!(display.length > 0 && display.length <= 0.5)) throw Message_error("\"length\" must lie in (0, 0.5]");
  }
  if(t.contains("separation"))
  {
    display.separation = number_member(t, "separation");
    if(!(display.separation >= 0.002 && display.separation <= 0.5))
      throw Message_error("\"separation\" must lie in [0.002, 0.5]");
  }
  display_ = display;
  send_field(r);
}

bool Field_session::refining() { return design_ && design_->full() && awaiting_exact_; }

int Field_session::constraints() const { return design_ ? static_cast<int>(design_->ids().size()) : 0; }

int Field_session::pending_pull_backs() { return design_ && design_->full() ? design_->answer().pending : 0; }

void Field_session::poll(const Send& send, std::chrono::milliseconds timeout)
{
  if(!refining()) return;
  const bool exact = design_->wait_exact(timeout);
  Request r;
  r.send = &send;
  r.has_id = last_edit_.has_id;
  r.id = last_edit_.id;
  r.received = last_edit_.received; // server_ms: from the edit to its exact field
  if(exact) return send_field(r, true);
  const std::string error = design_->refinement_error();
  if(!error.empty())
  {
    awaiting_exact_ = false; // said once; the next edit tries again
    r.text("\"type\":\"refinement_failed\",\"message\":" +
           quote("no exact answer: " + error + "; the field stays the reduced one"));
  }
}

namespace {

// Float32, 6 per segment: its two 3D end points.
std::vector<float> segments(const std::vector<TVF::Streamline>& strokes)
{
  std::vector<float> out;
  for(const TVF::Streamline& s : strokes)
    for(std::size_t i = 0; i + 1 < s.points.size(); ++i)
      for(const auto& p : {s.points[i], s.points[i + 1]})
        for(int k = 0; k < 3; ++k) out.push_back(static_cast<float>(p[k]));
  return out;
}

} // namespace

void Field_session::send_preview(Request& r)
{
  Design_preview preview;
  if(!design_->preview(display_, preview)) return;
  const Clock::time_point start = Clock::now();
  const std::vector<float> lines = segments(preview.strokes);
  const double lines_ms = preview.lines_ms + milliseconds_since(start);
  std::string members = "\"type\":\"preview\"" + r.echo() + ",\"n\":" + std::to_string(design_->n()) +
                        ",\"basis_size\":" + std::to_string(design_->basis_size()) +
                        ",\"report\":{\"error_bound\":" + number(preview.report.error_bound) +
                        "},\"faces_read\":" + std::to_string(preview.faces_read) +
                        ",\"timings\":{\"solve_ms\":" + short_number(r.reduced_ms + preview.solve_ms) +
                        ",\"lines_ms\":" + short_number(lines_ms);
  members += ",\"server_ms\":" + short_number(milliseconds_since(r.received)) + "}";
  (*r.send)(binary_message(members, {{"lines", true, lines.data(), lines.size()}}));
}

void Field_session::send_field(Request& r, bool refined)
{
  if(!refined)
  {
    // The edit a later exact field belongs to.
    last_edit_.has_id = r.has_id;
    last_edit_.id = r.id;
    last_edit_.received = r.received;
  }
  if(!refined) send_preview(r);
  Design_field field = design_->field();
  awaiting_exact_ = !field.exact; // with exact answers on, `poll` sends the exact one when ready
  const double solve_ms = r.reduced_ms + field.solve_ms;
  double reconstruct_ms = field.reconstruct_ms;
  const Eigen::VectorXd& x = field.x;

  // 3D vectors (float32): what the page draws and the test checks.
  Clock::time_point start = Clock::now();
  double magnitude_max = 0;
  const std::vector<float> vectors = design_->vectors(x, magnitude_max);
  reconstruct_ms += milliseconds_since(start);

  std::vector<Array_out> arrays = {{"vectors", true, vectors.data(), vectors.size()}};
  std::vector<float> scalar;
  double scalar_ms = 0, scalar_min = 0, scalar_max = 0;
  if(display_.scalar != "none")
  {
    start = Clock::now();
    const Eigen::VectorXd s = design_->scalar(display_.scalar, x);
    scalar.assign(s.data(), s.data() + s.size());
    scalar_min = s.size() ? s.minCoeff() : 0;
    scalar_max = s.size() ? s.maxCoeff() : 0;
    arrays.push_back({"scalar", true, scalar.data(), scalar.size()});
    scalar_ms = milliseconds_since(start);
  }
  std::vector<float> lines;
  double lines_ms = 0;
  if(display_.lines != "none")
  {
    start = Clock::now();
    lines = segments(design_->lines(x, display_));
    arrays.push_back({"lines", true, lines.data(), lines.size()});
    lines_ms = milliseconds_since(start);
  }
  // n-fields: the singular vertices and their indices k (the index is k / n), every field.
  std::vector<std::uint32_t> singular_vertices;
  std::vector<float> singular_indices;
  double singularities_ms = 0;
  if(design_->n() > 1)
  {
    start = Clock::now();
    for(const auto& [v, k] : design_->singularities(x))
    {
      singular_vertices.push_back(static_cast<std::uint32_t>(v));
      singular_indices.push_back(static_cast<float>(k));
    }
    arrays.push_back({"singular_vertices", false, singular_vertices.data(), singular_vertices.size()});
    arrays.push_back({"singular_indices", true, singular_indices.data(), singular_indices.size()});
    singularities_ms = milliseconds_since(start);
  }

  const TVF::Spline_report& report = field.report;
  const std::string warnings = json_array(report.warnings, [](const std::string& w) { return quote(w); });
  std::string members = "\"type\":\"field\"" + r.echo() + ",\"n\":" + std::to_string(design_->n()) +
                        (refined ? ",\"refined\":true" : "") + ",\"solver\":\"" + (design_->full() ? "full" : "reduced") +
                        "\",\"answer\":{\"exact\":" + (field.exact ? "true" : "false") +
                        ",\"pending\":" + std::to_string(field.pending) + "}" +
                        ",\"basis_size\":" + std::to_string(design_->basis_size()) +
                        ",\"omega\":" + number(design_->omega()) + ",\"ids\":" +
                        json_array(design_->ids(), [](int i) { return std::to_string(i); }) +
                        ",\"report\":{\"residual\":" + number(report.constraint_residual) +
                        ",\"undetermined_harmonic\":" + std::to_string(report.undetermined_harmonic) +
                        ",\"error_bound\":" + number(report.error_bound) +
                        ",\"warnings\":" + warnings + "},\"magnitude_max\":" + number(magnitude_max) +
                        ",\"scalar_range\":[" + number(scalar_min) + "," + number(scalar_max) + "]" +
                        ",\"scalar_on\":\"" + (design_->n() == 1 ? "vertices" : "faces") + "\"" +
                        ",\"timings\":{\"solve_ms\":" + short_number(solve_ms) +
                        ",\"reconstruct_ms\":" + short_number(reconstruct_ms) + ",\"lines_ms\":" + short_number(lines_ms) +
                        ",\"scalar_ms\":" + short_number(scalar_ms) +
                        (design_->n() > 1 ? ",\"singularities_ms\":" + short_number(singularities_ms) : std::string()) +
                        (field.exact ? ",\"full_ms\":" + short_number(field.full_ms) : std::string());
  // server_ms is measured last, just before the message is handed to the transport.
  members += ",\"server_ms\":" + short_number(milliseconds_since(r.received)) + "}";
  if(field.difference >= 0)
    members += ",\"difference\":" + number(field.difference) +
               ",\"largest_angle_deg\":" + number(field.largest_angle * 180 / 3.14159265358979323846);
  (*r.send)(binary_message(members, arrays));
}

} // namespace tvf_viewer
