// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The curve session: check a message, keep the stroke, fit it, answer with the curve.  See
// doc/viewer/protocol.md.

#include "curve_session.h"
#include "messages.h"

#include <CGAL/Model_reduction/errors.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace tvf_viewer {

namespace SA = CGAL::Spline_approximation;


namespace {

const std::map<std::string, SA::Fit_algorithm>& algorithms()
{
  static const std::map<std::string, SA::Fit_algorithm> names = {
      {"greedy", SA::Fit_algorithm::greedy_removal},
      {"penalty", SA::Fit_algorithm::penalty_decomposition},
      {"dp", SA::Fit_algorithm::dynamic_programming},
      {"brute", SA::Fit_algorithm::brute_force}};
  return names;
}

std::string algorithm_key(SA::Fit_algorithm a)
{
  for(const auto& [name, value] : algorithms())
    if(value == a) return name;
  return "greedy";
}

// The fewest points a fit of `settings` takes (the library's own rule, checked here so that
// the page reads it in its own terms).
std::size_t fewest_points(const Curve_settings& settings)
{
  return std::size_t(settings.closed ? std::max(3, settings.degree + 1) : settings.degree + 1);
}

double diagonal_of(const Eigen::MatrixXd& points)
{
  if(points.rows() == 0) return 0;
  return (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
}

// `points`: an array of [x, y] or [x, y, z], all of one dimension.
Eigen::MatrixXd read_points(const Json& node, std::size_t max_points)
{
  if(!node.is_array()) throw Message_error("\"points\" must be an array of points ([x, y] or [x, y, z])");
  if(node.size() > max_points)
    throw Message_error("too many points: " + std::to_string(node.size()) + " (at most " + std::to_string(max_points) +
                        " per stroke)");
  if(node.empty()) throw Message_error("too few points: the stroke is empty");
  const Json& first = node[0];
  const std::size_t dimension = first.is_array() ? first.size() : 0;
  if(dimension != 2 && dimension != 3)
    throw Message_error("point 0 must be an array of 2 or 3 numbers ([x, y] or [x, y, z])");
  Eigen::MatrixXd points(Eigen::Index(node.size()), Eigen::Index(dimension));
  for(std::size_t j = 0; j < node.size(); ++j)
  {
    const Json& p = node[j];
    if(!p.is_array() || p.size() != dimension)
      throw Message_error("point " + std::to_string(j) + " must be an array of " + std::to_string(dimension) +
                          " numbers, as point 0 is");
    for(std::size_t k = 0; k < dimension; ++k)
    {
      // JSON has no NaN: a page's NaN arrives as null (JSON.stringify), and that is refused by name.
      if(p[k].is_null())
        throw Message_error("point " + std::to_string(j) + " has a NaN coordinate (null): every coordinate must be a finite number");
      if(!p[k].is_number()) throw Message_error("point " + std::to_string(j) + " has a coordinate that is not a number");
      const double x = p[k].get<double>();
      if(!std::isfinite(x)) throw Message_error("point " + std::to_string(j) + " has a NaN or infinite coordinate");
      points(Eigen::Index(j), Eigen::Index(k)) = x;
    }
  }
  return points;
}

std::vector<float> row_major_floats(const Eigen::MatrixXd& m)
{
  std::vector<float> out(std::size_t(m.size()));
  for(Eigen::Index i = 0; i < m.rows(); ++i)
    for(Eigen::Index k = 0; k < m.cols(); ++k) out[std::size_t(i * m.cols() + k)] = float(m(i, k));
  return out;
}

} // namespace

Curve_session::Curve_session(Curve_limits limits) : limits_(limits) {}

void Curve_session::handle_text(const std::string& text, const Send& send)
{
  Request r(send);
  try
  {
    read_request(r, text, limits_.max_message_bytes, limits_.max_json_depth);
    // The members each message may have: a misspelt one is refused, by name.
    static const std::vector<const char*> settings = {"degree", "error", "tolerance", "algorithm", "closed"};
    static const std::map<std::string, std::vector<const char*>> members = {
        {"hello", {"kind"}}, {"stroke", {"points"}}, {"fit", {}}, {"clear", {}}, {"ping", {}}};
    const auto allowed = members.find(r.type);
    if(allowed == members.end())
      throw Message_error("unknown message type " + quote(r.type.substr(0, 64)) + " (hello, stroke, fit, clear, ping)");
    std::vector<const char*> keys = allowed->second;
    if(r.type == "stroke" || r.type == "fit") keys.insert(keys.end(), settings.begin(), settings.end());
    keys.push_back("type");
    keys.push_back("request");
    TVF::internal::Json_reader{r.tree, r.type}.allow_only(keys);
    if(r.type == "hello") hello(r);
    else if(r.type == "stroke") take_stroke(r);
    else if(r.type == "fit") refit(r);
    else if(r.type == "clear") clear(r);
    else r.text("\"type\":\"pong\"");
  }
  catch(const Message_error& e)
  {
    r.text("\"type\":\"error\",\"message\":" + quote(e.what()));
  }
  catch(const CGAL::Model_reduction::Invalid_input& e) // the fit's own checks (and bad members)
  {
    r.text("\"type\":\"error\",\"message\":" + quote(e.what()));
  }
  catch(const CGAL::Model_reduction::Numerical_failure& e)
  {
    r.text("\"type\":\"error\",\"message\":" + quote(std::string("the fit failed: ") + e.what()));
  }
  catch(const std::bad_alloc&)
  {
    r.text("\"type\":\"error\",\"message\":\"out of memory\"");
  }
}

std::string Curve_session::info_json() const
{
  std::string algorithm_names;
  for(const auto& entry : algorithms()) algorithm_names += (algorithm_names.empty() ? "\"" : ",\"") + entry.first + "\"";
  return "\"type\":\"info\",\"kind\":\"curve\",\"settings\":{\"degree\":" + std::to_string(settings_.degree) +
         ",\"error\":\"" + (settings_.rms ? "rms" : "max") + "\",\"tolerance\":" +
         (settings_.tolerance ? number(*settings_.tolerance) : std::string("null")) + ",\"algorithm\":\"" +
         algorithm_key(settings_.algorithm) + "\",\"closed\":" + (settings_.closed ? "true" : "false") +
         "},\"algorithms\":[" + algorithm_names + "],\"limits\":{\"max_message_bytes\":" +
         std::to_string(limits_.max_message_bytes) + ",\"max_points\":" + std::to_string(limits_.max_points) + "}";
}

void Curve_session::hello(Request& r)
{
  if(r.tree.contains("kind") && text_member(r.tree, "kind") != "curve")
    throw Message_error("this connection holds a \"curve\" session: open another for " +
                        quote(text_member(r.tree, "kind").substr(0, 64)));
  r.text(info_json());
  answer(r, stroke_, settings_);
}

Curve_settings Curve_session::read_settings(const Request& r) const
{
  Curve_settings s = settings_;
  const Json& t = r.tree;
  if(t.contains("degree")) s.degree = int(integer_member(t, "degree", 1, 3));
  if(t.contains("error"))
  {
    const std::string e = text_member(t, "error");
    if(e != "max" && e != "rms") throw Message_error("\"error\" must be \"max\" or \"rms\", not " + quote(e.substr(0, 64)));
    s.rms = e == "rms";
  }
  if(t.contains("tolerance"))
  {
    const double x = number_member(t, "tolerance");
    if(!(x > 0)) throw Message_error("\"tolerance\" must be > 0 (got " + short_number(x) + ")");
    s.tolerance = x;
  }
  if(t.contains("algorithm"))
  {
    const std::string a = text_member(t, "algorithm");
    const auto it = algorithms().find(a);
    if(it == algorithms().end())
      throw Message_error("unknown \"algorithm\" " + quote(a.substr(0, 64)) + " (greedy, penalty, dp, brute)");
    s.algorithm = it->second;
  }
  if(t.contains("closed"))
  {
    if(!member(t, "closed").is_boolean()) throw Message_error("\"closed\" must be true or false");
    s.closed = t["closed"].get<bool>();
  }
  return s;
}

void Curve_session::take_stroke(Request& r)
{
  const Curve_settings settings = read_settings(r);
  const Eigen::MatrixXd points = read_points(member(r.tree, "points"), limits_.max_points);
  answer(r, points, settings); // throws before anything is kept if the stroke cannot be fitted
  stroke_ = points;
  settings_ = settings;
}

void Curve_session::refit(Request& r)
{
  if(stroke_.rows() == 0) throw Message_error("no stroke to fit: send a \"stroke\" first");
  const Curve_settings settings = read_settings(r);
  answer(r, stroke_, settings);
  settings_ = settings;
}

void Curve_session::clear(Request& r)
{
  stroke_.resize(0, 0);
  answer(r, stroke_, settings_);
}

void Curve_session::answer(Request& r, const Eigen::MatrixXd& points, const Curve_settings& settings)
{
  std::string members = "\"type\":\"curve\"" + r.echo() + ",\"points\":" + std::to_string(points.rows()) +
                        ",\"dimension\":" + std::to_string(points.cols()) + ",\"degree\":" + std::to_string(settings.degree) +
                        ",\"error\":\"" + (settings.rms ? "rms" : "max") + "\",\"algorithm\":\"" +
                        algorithm_key(settings.algorithm) + "\",\"closed\":" + (settings.closed ? "true" : "false");
  if(points.rows() == 0) // no stroke yet (or cleared): an empty picture
  {
    members += ",\"tolerance\":" + (settings.tolerance ? number(*settings.tolerance) : std::string("null")) +
               ",\"knots\":0,\"max_error\":null,\"rms_error\":null,\"within_bound\":null,\"timings\":{\"server_ms\":" +
               short_number(milliseconds_since(r.received)) + "}";
    (*r.send)(binary_message(members, {}));
    return;
  }
  const std::size_t fewest = fewest_points(settings);
  if(std::size_t(points.rows()) < fewest)
    throw Message_error("too few points: " + std::to_string(points.rows()) + " (a" + (settings.closed ? " closed" : "n open") +
                        " curve of degree " + std::to_string(settings.degree) + " needs at least " +
                        std::to_string(fewest) + ")");
  SA::Fit_options options;
  options.degree = settings.degree;
  options.algorithm = settings.algorithm;
  options.closed_curve = settings.closed;
  const double tolerance = settings.tolerance ? *settings.tolerance : 0.005 * diagonal_of(points);
  (settings.rms ? options.rms_error : options.max_error) = tolerance;
  const SA::Spline_fit fit = SA::fit_spline(points, options);

  // The curve sampled evenly in its parameter, with the knots among the samples so that the
  // corners of a degree-1 fit are drawn sharp; closed curves end where they began (t = 1).
  const auto sample_start = Clock::now();
  const Eigen::VectorXd knots = fit.spline.interior_knots();
  const std::size_t even = std::min(limits_.max_curve_samples, std::max<std::size_t>(256, 4 * std::size_t(points.rows())));
  std::vector<double> t(even);
  for(std::size_t i = 0; i < even; ++i) t[i] = double(i) / double(even - 1);
  t.insert(t.end(), knots.data(), knots.data() + knots.size());
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  const Eigen::MatrixXd curve = fit.spline.evaluate(Eigen::Map<const Eigen::VectorXd>(t.data(), Eigen::Index(t.size())));
  const Eigen::MatrixXd knot_points = fit.spline.evaluate(knots);
  const double sample_ms = milliseconds_since(sample_start);

  const std::vector<float> curve_out = row_major_floats(curve), knots_out = row_major_floats(knot_points),
                           control_out = row_major_floats(fit.spline.control_points);
  std::vector<float> knot_parameters(knots.data(), knots.data() + knots.size());
  members += ",\"tolerance\":" + number(tolerance) + ",\"knots\":" + std::to_string(fit.number_of_knots()) +
             ",\"max_error\":" + number(fit.max_error) + ",\"rms_error\":" + number(fit.rms_error) +
             ",\"within_bound\":" + (fit.within_bound ? "true" : "false") + ",\"diagonal\":" + number(diagonal_of(points)) +
             ",\"control_points\":" + std::to_string(fit.spline.control_points.rows()) + ",\"timings\":{\"fit_ms\":" +
             short_number(1000 * fit.seconds) + ",\"sample_ms\":" + short_number(sample_ms) +
             ",\"server_ms\":" + short_number(milliseconds_since(r.received)) + "}";
  (*r.send)(binary_message(members, {{"curve", true, curve_out.data(), curve_out.size()},
                                     {"knot_points", true, knots_out.data(), knots_out.size()},
                                     {"knot_parameters", true, knot_parameters.data(), knot_parameters.size()},
                                     {"control_polygon", true, control_out.data(), control_out.size()}}));
}

} // namespace tvf_viewer
