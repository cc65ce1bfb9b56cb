// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The editor's field message: the session's display settings and what the display needs
// (the field as 3D vectors, a scalar, streamlines or fur), computed only when asked for.

#include "editor_messages.h"
#include "tool.h" // field_norm

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tvf_tool {

void Editor_session::set_display(Request& r)
{
  require_ready(r);
  Display display = display_;
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
    if(display.scalar != "divergence" && display.scalar != "curl" && display.scalar != "none")
      throw Message_error("\"scalar\" must be \"divergence\", \"curl\" or \"none\"");
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

void Editor_session::send_field(Request& r)
{
  const TVF::Intrinsic_mesh& mesh = model_->matrices().mesh();
  const int nf = mesh.number_of_faces();

  Clock::time_point start = Clock::now();
  reduced_->coefficients(); // the solve (the small system)
  const double solve_ms = r.reduced_ms + milliseconds_since(start);
  Eigen::VectorXd x;
  double reconstruct_ms = 0;
  if(has_edited_field_)
  {
    x.swap(edited_field_);
    reconstruct_ms = edited_field_ms_;
    has_edited_field_ = false;
  }
  else
  {
    start = Clock::now();
    x = reduced_->field();
    reconstruct_ms = milliseconds_since(start);
  }
  const TVF::Spline_report* report = &reduced_->report();

  std::string full_timing, full_difference;
  if(use_full_)
  {
    std::lock_guard<std::mutex> lock(model_->full_solver_mutex());
    start = Clock::now();
    Eigen::VectorXd x_full = full_->field();
    const double full_ms = r.full_ms + milliseconds_since(start);
    const double difference = field_norm(model_->matrices(), x - x_full);
    const double norm = field_norm(model_->matrices(), x_full);
    full_timing = ",\"full_ms\":" + short_number(full_ms);
    full_difference = ",\"difference\":" + number(norm > 0 ? difference / norm : difference);
    x.swap(x_full);
    report = &full_->report();
  }

  // 3D vectors (float32): what the page draws and the test checks.
  start = Clock::now();
  std::vector<float> vectors(3 * static_cast<std::size_t>(nf));
  double magnitude_max = 0;
  for(int f = 0; f < nf; ++f)
  {
    const auto v = mesh.from_frame(f, x[2 * f], x[2 * f + 1]);
    for(int k = 0; k < 3; ++k) vectors[3 * f + k] = static_cast<float>(v[k]);
    magnitude_max = std::max(magnitude_max, std::hypot(x[2 * f], x[2 * f + 1]));
  }
  reconstruct_ms += milliseconds_since(start);

  std::vector<Array_out> arrays = {{"vectors", true, vectors.data(), vectors.size()}};
  std::vector<float> scalar;
  double scalar_ms = 0, scalar_min = 0, scalar_max = 0;
  if(display_.scalar != "none")
  {
    start = Clock::now();
    const Eigen::VectorXd s =
        display_.scalar == "divergence" ? model_->matrices().divergence(x) : model_->matrices().curl(x);
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
    const TVF::Streamline_tracer tracer(model_->matrices().shared_mesh(), x);
    std::vector<TVF::Streamline> traced;
    if(display_.lines == "fur")
    {
      TVF::Fur_options fur;
      fur.number_of_strokes = display_.strokes;
      fur.length = display_.length;
      fur.scale_length_by_magnitude = true;
      traced = tracer.fur(fur);
    }
    else
    {
      TVF::Evenly_spaced_options even;
      even.separation = display_.separation;
      traced = tracer.evenly_spaced(even);
    }
    for(const TVF::Streamline& s : traced)
      for(std::size_t i = 0; i + 1 < s.points.size(); ++i)
        for(const auto& p : {s.points[i], s.points[i + 1]})
          for(int k = 0; k < 3; ++k) lines.push_back(static_cast<float>(p[k]));
    arrays.push_back({"lines", true, lines.data(), lines.size()});
    lines_ms = milliseconds_since(start);
  }

  std::vector<int> ids;
  for(const auto& e : entries_) ids.push_back(e.first);
  const std::string warnings = json_array(report->warnings, [](const std::string& w) { return quote(w); });
  std::string members = "\"type\":\"field\"" + r.echo() + ",\"solver\":\"" + (use_full_ ? "full" : "reduced") +
                        "\",\"basis_size\":" + std::to_string(reduced_->basis_size()) + ",\"omega\":" + number(omega_) +
                        ",\"ids\":" + json_array(ids, [](int i) { return std::to_string(i); }) +
                        ",\"report\":{\"residual\":" + number(report->constraint_residual) +
                        ",\"undetermined_harmonic\":" + std::to_string(report->undetermined_harmonic) +
                        ",\"warnings\":" + warnings + "},\"magnitude_max\":" + number(magnitude_max) +
                        ",\"scalar_range\":[" + number(scalar_min) + "," + number(scalar_max) + "]" +
                        ",\"timings\":{\"solve_ms\":" + short_number(solve_ms) +
                        ",\"reconstruct_ms\":" + short_number(reconstruct_ms) + ",\"lines_ms\":" + short_number(lines_ms) +
                        ",\"scalar_ms\":" + short_number(scalar_ms) + full_timing;
  // server_ms is measured last, just before the message is handed to the transport.
  members += ",\"server_ms\":" + short_number(milliseconds_since(r.received)) + "}" + full_difference;
  (*r.send)(binary_message(members, arrays));
}

} // namespace tvf_tool
