// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `curve` session of `tvf serve` (stroke fitting, Chapter 6) over a real socket: a stroke
// that is exactly a polyline gets its knots at the corners it was made from, a looser
// tolerance never needs more knots, and every bad message is refused with its reason while the
// session keeps its stroke.

#include "server_test_support.h"

#include <gtest/gtest.h>

#include <sstream>

namespace {

using namespace server_test;

class Curve_server_test : public Server_test
{
};

// The corners of the test polyline: two ends and three interior corners (the truth).
const std::vector<std::array<double, 2>> curve_test_corners = {{0, 0}, {100, 0}, {100, 60}, {40, 90}, {-20, 50}};

// The polyline through `corners`, sampled every `step` or closer, corners included.
std::vector<std::array<double, 2>> curve_test_polyline(const std::vector<std::array<double, 2>>& corners, double step)
{
  std::vector<std::array<double, 2>> out;
  for(std::size_t i = 0; i + 1 < corners.size(); ++i)
  {
    const auto& a = corners[i];
    const auto& b = corners[i + 1];
    const int pieces = int(std::ceil(std::hypot(b[0] - a[0], b[1] - a[1]) / step));
    for(int k = 0; k < pieces; ++k)
    {
      const double s = double(k) / pieces;
      out.push_back({a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])});
    }
  }
  out.push_back(corners.back());
  return out;
}

std::string curve_test_points_json(const std::vector<std::array<double, 2>>& points)
{
  std::ostringstream s;
  s.precision(17);
  s << "[";
  for(std::size_t i = 0; i < points.size(); ++i) s << (i ? "," : "") << "[" << points[i][0] << "," << points[i][1] << "]";
  s << "]";
  return s.str();
}

std::string curve_test_number(double x)
{
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

// A client with a curve session, after its hello (info, then the empty curve).
struct Curve_test_session
{
  Client client;
  Message info;
  explicit Curve_test_session(const Address& address) : client(address)
  {
    client.send("{\"type\":\"hello\",\"kind\":\"curve\",\"request\":1}");
    info = client.expect("info");
    const Message empty = client.expect("curve");
    EXPECT_EQ(empty.json.get<int>("points"), 0);
    EXPECT_EQ(empty.json.get<int>("knots"), 0);
  }
};

TEST_F(Curve_server_test, curve_is_offered_but_not_the_default)
{
  Session fields(server->address()); // a hello without kind
  EXPECT_EQ(fields.info.json.get<std::string>("kind"), "vector_field");
  Curve_test_session s(server->address());
  EXPECT_EQ(s.info.json.get<std::string>("kind"), "curve");
  EXPECT_EQ(s.info.json.get<std::string>("settings.algorithm"), "greedy");
  EXPECT_EQ(s.info.json.get<int>("limits.max_points"), 10000);
  Client other(server->address());
  other.send("{\"type\":\"hello\",\"kind\":\"curves\"}");
  EXPECT_NE(other.expect_error().find("vector_field, n_field, curve"), std::string::npos);
}

TEST_F(Curve_server_test, knots_of_a_polyline_stroke_are_its_corners)
{
  Curve_test_session s(server->address());
  const auto stroke = curve_test_polyline(curve_test_corners, 3.0);
  s.client.send("{\"type\":\"stroke\",\"request\":2,\"degree\":1,\"error\":\"max\",\"tolerance\":1e-6,\"points\":" +
                curve_test_points_json(stroke) + "}");
  const Message fit = s.client.expect("curve");
  EXPECT_EQ(fit.json.get<int>("request"), 2);
  EXPECT_EQ(fit.json.get<std::size_t>("points"), stroke.size());
  EXPECT_EQ(fit.json.get<std::string>("algorithm"), "greedy");
  EXPECT_TRUE(fit.json.get<bool>("within_bound"));
  EXPECT_LE(fit.json.get<double>("max_error"), 1e-6);
  EXPECT_GE(fit.json.get<double>("timings.fit_ms"), 0.0);
  ASSERT_EQ(fit.json.get<int>("knots"), 3);
  const std::vector<float>& knots = fit.floats.at("knot_points");
  ASSERT_EQ(knots.size(), 6u);
  for(int i = 0; i < 3; ++i)
  {
    const auto& corner = curve_test_corners[std::size_t(i) + 1];
    EXPECT_NEAR(knots[2 * i], corner[0], 1e-3) << "knot " << i;
    EXPECT_NEAR(knots[2 * i + 1], corner[1], 1e-3) << "knot " << i;
  }
  // Degree 1 with 3 knots: 5 control points, the corners themselves.
  const std::vector<float>& control = fit.floats.at("control_polygon");
  ASSERT_EQ(control.size(), 10u);
  for(std::size_t i = 0; i < 5; ++i)
    EXPECT_NEAR(std::hypot(control[2 * i] - curve_test_corners[i][0], control[2 * i + 1] - curve_test_corners[i][1]), 0, 1e-3);
  // The drawn curve starts and ends at the stroke's ends and passes through every corner.
  const std::vector<float>& curve = fit.floats.at("curve");
  ASSERT_GE(curve.size(), 2u * 256);
  EXPECT_NEAR(curve[0], 0, 1e-4);
  EXPECT_NEAR(curve[curve.size() - 2], -20, 1e-3);
  for(const auto& corner : curve_test_corners)
  {
    double nearest = 1e9;
    for(std::size_t j = 0; j < curve.size(); j += 2) nearest = std::min(nearest, std::hypot(curve[j] - corner[0], curve[j + 1] - corner[1]));
    EXPECT_LT(nearest, 1e-3);
  }
}

// A smooth stroke: a wavy spiral, 600 points.
std::vector<std::array<double, 2>> curve_test_spiral()
{
  std::vector<std::array<double, 2>> out;
  for(int j = 0; j < 600; ++j)
  {
    const double s = j / 599.0, r = 20 + 60 * s + 3 * std::sin(40 * s);
    out.push_back({r * std::cos(9 * s), r * std::sin(9 * s)});
  }
  return out;
}

TEST_F(Curve_server_test, looser_tolerances_never_need_more_knots)
{
  for(const auto& stroke : {curve_test_polyline(curve_test_corners, 2.0), curve_test_spiral()})
  {
    Curve_test_session s(server->address());
    s.client.send("{\"type\":\"stroke\",\"degree\":1,\"tolerance\":1e-6,\"points\":" + curve_test_points_json(stroke) + "}");
    s.client.expect("curve");
    for(const char* error : {"max", "rms"})
      for(int degree = 1; degree <= 3; ++degree)
      {
        int previous = 1 << 30;
        for(double tolerance : {1e-6, 1e-3, 0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 40.0, 80.0, 200.0})
        {
          // Settings only: the session re-fits the stroke it kept.
          s.client.send(std::string("{\"type\":\"fit\",\"error\":\"") + error + "\",\"degree\":" + std::to_string(degree) +
                        ",\"tolerance\":" + curve_test_number(tolerance) + "}");
          const Message fit = s.client.expect("curve");
          ASSERT_EQ(fit.json.get<std::size_t>("points"), stroke.size());
          const int knots = fit.json.get<int>("knots");
          EXPECT_LE(knots, previous) << error << " degree " << degree << " tolerance " << tolerance;
          EXPECT_TRUE(fit.json.get<bool>("within_bound")) << error << " degree " << degree << " tolerance " << tolerance;
          EXPECT_LE(fit.json.get<double>(std::string(error) + "_error"), tolerance * (1 + 1e-9));
          previous = knots;
        }
        EXPECT_EQ(previous, 0) << "a tolerance larger than the stroke needs no knot";
      }
  }
}

TEST_F(Curve_server_test, bad_messages_are_refused_with_their_reason)
{
  Curve_test_session s(server->address());
  s.client.send("{\"type\":\"fit\",\"tolerance\":1}");
  EXPECT_NE(s.client.expect_error().find("no stroke to fit"), std::string::npos);
  const auto stroke = curve_test_polyline(curve_test_corners, 3.0);
  const std::string points = curve_test_points_json(stroke);
  s.client.send("{\"type\":\"stroke\",\"degree\":1,\"tolerance\":1e-6,\"points\":" + points + "}");
  ASSERT_EQ(s.client.expect("curve").json.get<int>("knots"), 3);

  const std::vector<std::pair<std::string, std::string>> refusals = {
      {"{\"type\":\"stroke\",\"points\":[[1,2]],\"degree\":3}", "too few points: 1 (an open curve of degree 3 needs at least 4)"},
      {"{\"type\":\"stroke\",\"points\":[]}", "too few points: the stroke is empty"},
      {"{\"type\":\"stroke\",\"points\":[[0,0],[1,1],[2,0]],\"closed\":true,\"degree\":3}",
       "too few points: 3 (a closed curve of degree 3 needs at least 4)"},
      {"{\"type\":\"stroke\",\"points\":[[0,0],[1,null],[2,0],[3,1]]}", "point 1 has a NaN coordinate (null)"},
      {"{\"type\":\"stroke\",\"points\":[[0,0],[1,\"NaN\"],[2,0],[3,1]]}", "point 1 has a coordinate that is not a number"},
      {"{\"type\":\"stroke\",\"points\":[[0,0],[1,1,1],[2,0],[3,1]]}", "point 1 must be an array of 2 numbers"},
      {"{\"type\":\"fit\",\"tolerance\":0}", "\"tolerance\" must be > 0 (got 0)"},
      {"{\"type\":\"fit\",\"tolerance\":-2.5}", "\"tolerance\" must be > 0 (got -2.5)"},
      {"{\"type\":\"fit\",\"tolerence\":1}", "unknown key \"tolerence\""},
      {"{\"type\":\"stroke\",\"points\":[[0,0],[1,0]],\"colour\":\"red\"}", "unknown key \"colour\""},
      {"{\"type\":\"fit\",\"degree\":4}", "\"degree\" must be an integer in [1, 3]"},
      {"{\"type\":\"fit\",\"error\":\"mean\"}", "\"error\" must be \"max\" or \"rms\""},
      {"{\"type\":\"fit\",\"algorithm\":\"fastest\"}", "unknown \"algorithm\" \"fastest\""},
      {"{\"type\":\"fit\",\"closed\":\"yes\"}", "\"closed\" must be true or false"},
      {"{\"type\":\"fit\",\"algorithm\":\"dp\",\"degree\":3}", "dynamic programming optimum is known for degree 1 only"},
      {"{\"type\":\"stroke\",\"points\":[[0,0],[1,1],[1,1],[2,0]],\"degree\":1}", "samples 1 and 2 coincide"},
      {"{\"type\":\"draw\"}", "unknown message type \"draw\""},
      {"{\"type\":\"hello\",\"kind\":\"n_field\"}", "holds a \"curve\" session"},
      {"[1,2]", "a message must be a JSON object"},
  };
  for(const auto& [message, reason] : refusals)
  {
    s.client.send(message);
    const std::string error = s.client.expect_error();
    EXPECT_NE(error.find(reason), std::string::npos) << message << " -> " << error;
  }
  // Over the stated limit of points.
  std::string many = "{\"type\":\"stroke\",\"points\":[";
  for(int i = 0; i <= 10000; ++i) many += (i ? ",[" : "[") + std::to_string(i) + ",0]";
  s.client.send(many + "]}");
  EXPECT_NE(s.client.expect_error().find("too many points: 10001 (at most 10000 per stroke)"), std::string::npos);

  // Nothing refused changed the session: its stroke and settings fit as before.
  s.client.send("{\"type\":\"fit\",\"request\":9}");
  const Message fit = s.client.expect("curve");
  EXPECT_EQ(fit.json.get<int>("request"), 9);
  EXPECT_EQ(fit.json.get<std::size_t>("points"), stroke.size());
  EXPECT_EQ(fit.json.get<int>("degree"), 1);
  EXPECT_EQ(fit.json.get<int>("knots"), 3);
  s.client.send("{\"type\":\"ping\",\"request\":10}");
  EXPECT_EQ(s.client.expect("pong").json.get<int>("request"), 10);
}

// A 3D stroke: a polyline on the edges of a cube, its two interior corners the knots.
TEST_F(Curve_server_test, a_3d_stroke_has_its_knots_at_its_corners)
{
  Curve_test_session s(server->address());
  const std::vector<std::array<double, 3>> corners = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {10, 10, 10}};
  std::ostringstream points;
  points.precision(17);
  points << "[";
  for(std::size_t i = 0; i + 1 < corners.size(); ++i)
    for(int k = 0; k < 10; ++k)
    {
      const double u = k / 10.0;
      points << (i + k ? "," : "") << "[" << corners[i][0] + u * (corners[i + 1][0] - corners[i][0]) << ","
             << corners[i][1] + u * (corners[i + 1][1] - corners[i][1]) << ","
             << corners[i][2] + u * (corners[i + 1][2] - corners[i][2]) << "]";
    }
  points << ",[10,10,10]]";
  s.client.send("{\"type\":\"stroke\",\"degree\":1,\"tolerance\":1e-9,\"points\":" + points.str() + "}");
  const Message fit = s.client.expect("curve");
  EXPECT_EQ(fit.json.get<int>("dimension"), 3);
  ASSERT_EQ(fit.json.get<int>("knots"), 2);
  const std::vector<float>& knots = fit.floats.at("knot_points");
  ASSERT_EQ(knots.size(), 6u);
  for(int i = 0; i < 2; ++i)
    for(int k = 0; k < 3; ++k) EXPECT_NEAR(knots[std::size_t(3 * i + k)], corners[std::size_t(i) + 1][std::size_t(k)], 1e-4);
  EXPECT_EQ(fit.floats.at("curve").size() % 3, 0u);
}

TEST_F(Curve_server_test, closed_strokes_and_clear)
{
  Curve_test_session s(server->address());
  // A square drawn once around, its start not repeated: degree 1, four corners as knots on the circle.
  const auto stroke = curve_test_polyline({{0, 0}, {50, 0}, {50, 50}, {0, 50}, {0, 1}}, 2.0);
  s.client.send("{\"type\":\"stroke\",\"degree\":1,\"closed\":true,\"tolerance\":0.6,\"points\":" +
                curve_test_points_json(stroke) + "}");
  Message fit = s.client.expect("curve");
  EXPECT_TRUE(fit.json.get<bool>("closed"));
  EXPECT_TRUE(fit.json.get<bool>("within_bound"));
  EXPECT_GE(fit.json.get<int>("knots"), 4);
  const std::vector<float>& curve = fit.floats.at("curve");
  EXPECT_NEAR(std::hypot(curve[0] - curve[curve.size() - 2], curve[1] - curve.back()), 0, 1e-3) << "the curve closes";
  s.client.send("{\"type\":\"clear\"}");
  fit = s.client.expect("curve");
  EXPECT_EQ(fit.json.get<int>("points"), 0);
  s.client.send("{\"type\":\"fit\"}");
  EXPECT_NE(s.client.expect_error().find("no stroke to fit"), std::string::npos);
}

} // namespace
