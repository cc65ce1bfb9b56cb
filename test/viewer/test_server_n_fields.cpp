// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The editor's server designing n-direction fields: a session switches to n = 4, places
// vectors and singularities, and the field it sends has the constrained vectors and exactly
// the constrained index at each singularity, measured here from the 3D vectors and the mesh
// alone (not through the package's index); save and load round trips, the display of
// n-fields, and hostile n-field messages.

#include "full_spline_truth.h"
#include "server_test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace server_test;

typedef std::array<double, 3> Vec;

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec scaled(const Vec& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
Vec unit(const Vec& a) { return scaled(a, 1 / std::sqrt(dot(a, a))); }
// `u` turned by `angle` about the unit axis `k` (Rodrigues).
Vec turned(const Vec& u, const Vec& k, double angle)
{
  const Vec kxu = cross(k, u);
  const double c = std::cos(angle), s = std::sin(angle), d = dot(k, u) * (1 - c);
  return {u[0] * c + kxu[0] * s + k[0] * d, u[1] * c + kxu[1] * s + k[1] * d, u[2] * c + kxu[2] * s + k[2] * d};
}

struct Geometry
{
  const std::vector<float>& p;
  const std::vector<std::uint32_t>& t;
  Vec point(int v) const { return {p[3 * v], p[3 * v + 1], p[3 * v + 2]}; }
  Vec normal(int f) const
  {
    const Vec a = point(t[3 * f]);
    return unit(cross(sub(point(t[3 * f + 1]), a), sub(point(t[3 * f + 2]), a)));
  }
};

// The index k (the field turns by 2 pi k / n around v) of the n-field whose vector in each face
// is `field`'s (any one of its n), from the 3D geometry alone: around the one-ring, counter-
// clockwise, each face's vector is carried into the next face by the rotation about their
// common edge (unfolding), the turn to the next face's vector is taken modulo 2 pi / n (the
// smallest), and the angle defect is added: 2 pi k / n = sum of turns + K_v.  Not an integer
// if the field is not an n-field with a well-defined index there.
double index_from_vectors(const Message& mesh, const Message& field, int v, int n)
{
  const Geometry g{mesh.floats.at("positions"), mesh.integers.at("triangles")};
  // Each face of the ring as (v, p, q), counter-clockwise; the next face starts with (v, q).
  std::map<int, std::pair<int, int>> by_first; // p -> (face, q)
  for(std::size_t f = 0; 3 * f < g.t.size(); ++f)
    for(int k = 0; k < 3; ++k)
      if(int(g.t[3 * f + k]) == v) by_first[g.t[3 * f + (k + 1) % 3]] = {int(f), int(g.t[3 * f + (k + 2) % 3])};
  const Vec& x = g.point(v);
  double defect = 2 * M_PI, turns = 0;
  for(const auto& [p, fq] : by_first)
  {
    const auto [f, q] = fq;
    const Vec a = unit(sub(g.point(p), x)), b = unit(sub(g.point(q), x));
    defect -= std::acos(std::max(-1.0, std::min(1.0, dot(a, b))));
    const int h = by_first.at(q).first; // the next face, across the edge v -> q
    const Vec nf = g.normal(f), nh = g.normal(h);
    const double dihedral = std::atan2(dot(cross(nf, nh), b), dot(nf, nh));
    const Vec carried = turned(face_vector(field, f), b, dihedral);
    const Vec next = face_vector(field, h);
    const double turn = std::atan2(dot(cross(carried, next), nh), dot(carried, next));
    turns += std::remainder(n * turn, 2 * M_PI) / n;
  }
  return n * (turns + defect) / (2 * M_PI);
}

// The face of the mesh message with corner v.
int face_at(const Message& mesh, int v)
{
  const auto& t = mesh.integers.at("triangles");
  for(std::size_t i = 0; i < t.size(); ++i)
    if(int(t[i]) == v) return int(i / 3);
  return -1;
}

std::string singularity(int vertex, int k, int face, const Vec& v)
{
  std::ostringstream s;
  s.precision(17);
  s << "{\"type\":\"singularity\",\"vertex\":" << vertex << ",\"index\":" << k << ",\"face\":" << face << ",\"vector\":["
    << v[0] << "," << v[1] << "," << v[2] << "]}";
  return s.str();
}

// The index k the server reports at v (0 if v is not listed).
int reported_index(const Message& field, int v)
{
  const auto& vertices = field.integers.at("singular_vertices");
  for(std::size_t i = 0; i < vertices.size(); ++i)
    if(int(vertices[i]) == v) return int(field.floats.at("singular_indices")[i]);
  return 0;
}

TEST_F(Server_test, n_field_session_meets_vectors_and_singularities)
{
  Session s(server->address());
  const int nf = s.info.json.get<int>("mesh.faces");
  s.client.send("{\"type\":\"set_n\",\"n\":4,\"request\":2}");
  const Message info = s.client.expect("info");
  EXPECT_EQ(info.json.get<int>("n"), 4);
  EXPECT_EQ(info.json.get<int>("order"), 2);
  EXPECT_EQ(info.json.get<int>("basis.available"), 60);
  EXPECT_EQ(info.json.get<int>("basis.harmonic"), 0); // no parallel cross field on a sphere
  Message field = s.client.expect("field");
  EXPECT_EQ(field.json.get<int>("n"), 4);
  EXPECT_EQ(field.json.get<int>("request"), 2);
  EXPECT_EQ(field.floats.at("vectors").size(), 3u * nf);

  // A vector: the field there is one of its 4 turns about the face's normal.
  const int f = 17;
  const Vec t = tangent(s.mesh, f);
  s.client.send("{\"type\":\"add\",\"constraint\":" + vector_constraint(f, scaled(t, 0.5)) + "}");
  s.client.expect("added");
  field = s.client.expect("field");
  const Geometry g{s.mesh.floats.at("positions"), s.mesh.integers.at("triangles")};
  double closest = 1e9;
  for(int j = 0; j < 4; ++j) closest = std::min(closest, distance(face_vector(field, f), turned(scaled(t, 0.5), g.normal(f), j * M_PI / 2)));
  EXPECT_LT(closest, 1e-5); // float32

  // A singularity of index +1/4, anchored in a face of its ring: exactly that index there.
  const int v = 40, anchor = face_at(s.mesh, v);
  s.client.send("{\"type\":\"add\",\"constraint\":" + singularity(v, 1, anchor, scaled(tangent(s.mesh, anchor), 0.5)) +
                ",\"request\":5}");
  const int id = s.client.expect("added").json.get<int>("id");
  field = s.client.expect("field");
  EXPECT_NEAR(index_from_vectors(s.mesh, field, v, 4), 1, 1e-3);
  EXPECT_EQ(reported_index(field, v), 1);
  // Every singularity the server reports is one the geometry confirms, and Poincare-Hopf holds.
  int sum = 0;
  const auto& vertices = field.integers.at("singular_vertices");
  for(std::size_t i = 0; i < vertices.size(); ++i)
  {
    const int k = int(field.floats.at("singular_indices")[i]);
    sum += k;
    EXPECT_NEAR(index_from_vectors(s.mesh, field, vertices[i], 4), k, 1e-3) << "vertex " << vertices[i];
  }
  EXPECT_EQ(sum, 4 * 2); // n chi

  // Moved to another vertex: the index goes with it.
  const int w = 100, anchor_w = face_at(s.mesh, w);
  s.client.send("{\"type\":\"change\",\"id\":" + std::to_string(id) + ",\"constraint\":" +
                singularity(w, -1, anchor_w, scaled(tangent(s.mesh, anchor_w), 0.5)) + "}");
  field = s.client.expect("field");
  EXPECT_NEAR(index_from_vectors(s.mesh, field, w, 4), -1, 1e-3);
  EXPECT_EQ(reported_index(field, w), -1);

  // A value edit (the anchor's vector dragged) keeps the index and equals a fresh session
  // loading the saved constraints.
  s.client.send("{\"type\":\"change\",\"id\":" + std::to_string(id) + ",\"constraint\":" +
                singularity(w, -1, anchor_w, scaled(tangent(s.mesh, anchor_w), 2.0)) + "}");
  field = s.client.expect("field");
  EXPECT_NEAR(index_from_vectors(s.mesh, field, w, 4), -1, 1e-3);
  s.client.send("{\"type\":\"save\"}");
  const Message saved = s.client.expect("constraints");
  EXPECT_EQ(saved.json.get<int>("file.n"), 4);
  Session fresh(server->address());
  fresh.client.send("{\"type\":\"set_n\",\"n\":4}");
  fresh.client.expect("info");
  fresh.client.expect("field");
  fresh.client.send("{\"type\":\"load\",\"file\":" + object_member_text(saved.text, "file") + "}");
  fresh.client.expect("loaded");
  const Message loaded = fresh.client.expect("field");
  double largest = 0, difference = 0;
  for(int i = 0; i < 3 * nf; ++i)
  {
    largest = std::max(largest, std::fabs(double(field.floats.at("vectors")[i])));
    difference = std::max(difference, std::fabs(double(field.floats.at("vectors")[i]) - loaded.floats.at("vectors")[i]));
  }
  EXPECT_GT(largest, 0.1);
  EXPECT_LT(difference, 1e-5 * largest);

  // The display of n-fields: energy density per face, hatching, glyph strokes.
  s.client.send("{\"type\":\"set_display\",\"scalar\":\"energy\",\"lines\":\"streamlines\"}");
  field = s.client.expect("field");
  EXPECT_EQ(field.json.get<std::string>("scalar_on"), "faces");
  ASSERT_EQ(field.floats.at("scalar").size(), std::size_t(nf));
  for(float e : field.floats.at("scalar")) EXPECT_GE(e, 0.f);
  EXPECT_GT(field.floats.at("lines").size(), 0u);

  // Back to vector fields: the constraints of n = 4 are gone, the vector design works.
  s.client.send("{\"type\":\"set_n\",\"n\":1}");
  EXPECT_EQ(s.client.expect("info").json.get<int>("n"), 1);
  field = s.client.expect("field");
  EXPECT_EQ(field.json.get_child("ids").size(), 0u);
  EXPECT_EQ(field.integers.count("singular_vertices"), 0u);
  s.client.send("{\"type\":\"add\",\"constraint\":" + vector_constraint(f, t) + "}");
  s.client.expect("added");
  EXPECT_LT(distance(face_vector(s.client.expect("field"), f), t), 1e-5);
}

// The fields that follow an edit in exact mode, up to the exact one (which it returns).
Message exact_field(Client& client)
{
  for(;;)
  {
    Message field = client.expect("field");
    if(field.json.get<bool>("answer.exact", false)) return field;
  }
}

TEST_F(Server_test, n_field_exact_answers_are_full_n_field_splines)
{
  // Exact mode with n = 4: every exact field is the one-shot full n-field spline of the same
  // constraints (Full_n_field_spline_solver, solved here through the library): after a vector,
  // an anchored singularity, a value edit, a move, a new omega and another order.
  Session s(server->address());
  ASSERT_EQ(library_sphere_triangles(), s.mesh.integers.at("triangles")); // numbered alike
  s.client.send("{\"type\":\"set_n\",\"n\":4}");
  s.client.expect("info");
  s.client.expect("field");
  s.client.send("{\"type\":\"set_solver\",\"solver\":\"full\"}");
  EXPECT_EQ(exact_field(s.client).json.get<std::string>("solver"), "full");
  const int f = 17, v = 40, anchor = face_at(s.mesh, v), w = 100, anchor_w = face_at(s.mesh, w);
  const Vec a = scaled(tangent(s.mesh, f), 0.5), b = scaled(tangent(s.mesh, anchor), 0.5),
            c = scaled(tangent(s.mesh, anchor_w), 2.0);
  typedef TVF::N_field_constraint C;
  const C vector = C::vector_in_face(f, a), at_v = C::singularity_at_vertex(v, 1, anchor, b);
  // float32 on the wire: 6e-8 relative.
  s.client.send("{\"type\":\"add\",\"constraint\":" + vector_constraint(f, a) + "}");
  s.client.expect("added");
  Message field = exact_field(s.client);
  EXPECT_LT(largest_gap(field, full_n_field_spline(4, 2, {vector}, 0)), 1e-6);

  s.client.send("{\"type\":\"add\",\"constraint\":" + singularity(v, 1, anchor, b) + "}");
  const int id = s.client.expect("added").json.get<int>("id");
  field = exact_field(s.client);
  const Truth truth = full_n_field_spline(4, 2, {vector, at_v}, 0);
  EXPECT_LT(largest_gap(field, truth), 1e-6);
  if(field.json.count("difference")) // the reduced answer came first (unless the exact one was sooner)
    EXPECT_GT(field.json.get<double>("difference"), 1e-3); // and was another field

  // A value edit (the anchor's vector), then a move to another vertex with index -1/4.
  s.client.send("{\"type\":\"change\",\"id\":" + std::to_string(id) + ",\"constraint\":" +
                singularity(v, 1, anchor, scaled(b, -3)) + "}");
  field = exact_field(s.client);
  EXPECT_LT(largest_gap(field, full_n_field_spline(4, 2, {vector, C::singularity_at_vertex(v, 1, anchor, scaled(b, -3))}, 0)),
            1e-6);
  s.client.send("{\"type\":\"change\",\"id\":" + std::to_string(id) + ",\"constraint\":" +
                singularity(w, -1, anchor_w, c) + "}");
  field = exact_field(s.client);
  const C at_w = C::singularity_at_vertex(w, -1, anchor_w, c);
  EXPECT_LT(largest_gap(field, full_n_field_spline(4, 2, {vector, at_w}, 0)), 1e-6);

  // Omega > 0, then the energy of order 1 (set_n starts a new design: constraints loaded again).
  s.client.send("{\"type\":\"set_omega\",\"omega\":0.5}");
  field = exact_field(s.client);
  EXPECT_LT(largest_gap(field, full_n_field_spline(4, 2, {vector, at_w}, 0.5)), 1e-6);
  s.client.send("{\"type\":\"save\"}");
  const std::string file = object_member_text(s.client.expect("constraints").text, "file");
  s.client.send("{\"type\":\"set_n\",\"n\":4,\"order\":1}");
  EXPECT_EQ(s.client.expect("info").json.get<int>("order"), 1);
  exact_field(s.client);
  s.client.send("{\"type\":\"load\",\"file\":" + file + "}");
  s.client.expect("loaded");
  field = exact_field(s.client);
  EXPECT_EQ(field.json.get<std::string>("solver"), "full");
  EXPECT_LT(largest_gap(field, full_n_field_spline(4, 1, {vector, at_w}, 0.5)), 1e-6);
}

TEST_F(Server_test, hostile_n_field_messages_get_errors)
{
  Session s(server->address());
  const int nv = s.info.json.get<int>("mesh.vertices");
  // Before set_n: n-field constraints are not vector-field constraints.
  s.client.send("{\"type\":\"add\",\"constraint\":{\"type\":\"singularity\",\"vertex\":3,\"index\":1}}");
  EXPECT_NE(s.client.expect_error().find("unknown type \"singularity\""), std::string::npos);
  const std::vector<std::pair<std::string, std::string>> before = {
      {"{\"type\":\"set_n\",\"n\":0}", "\"n\""},
      {"{\"type\":\"set_n\",\"n\":13}", "\"n\""},
      {"{\"type\":\"set_n\",\"n\":\"4\"}", "must be a number"},
      {"{\"type\":\"set_n\",\"n\":2.5}", "integer"},
      {"{\"type\":\"set_n\"}", "missing \"n\""},
      {"{\"type\":\"set_n\",\"n\":4,\"order\":0}", "\"order\""},
      {"{\"type\":\"set_n\",\"n\":1,\"order\":1}", "order 2"},
      {"{\"type\":\"set_n\",\"n\":4,\"colour\":1}", "unknown key \"colour\""},
  };
  for(const auto& c : before)
  {
    s.client.send(c.first);
    const std::string message = s.client.expect_error();
    EXPECT_NE(message.find(c.second), std::string::npos) << c.first << " -> " << message;
  }
  s.client.send("{\"type\":\"set_n\",\"n\":2}");
  s.client.expect("info");
  s.client.expect("field");
  const int anchor = face_at(s.mesh, 7);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"singularity\",\"vertex\":" + std::to_string(nv) + ",\"index\":1}}",
       "no such vertex"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"singularity\",\"vertex\":7,\"index\":1000}}", "cannot show a turning"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"singularity\",\"vertex\":7,\"index\":1,\"face\":" +
           std::to_string(face_at(s.mesh, 100)) + ",\"vector\":[1,0,0]}}",
       "not around the vertex"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"singularity\",\"vertex\":7,\"index\":1,\"face\":" +
           std::to_string(anchor) + "}}",
       "missing \"vector\""},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"singularity\",\"vertex\":7,\"index\":\"1\"}}", "must be a number"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"divergence\",\"vertex\":7,\"value\":1}}", "unknown type"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"vector\",\"face\":1,\"vector\":[1e300,1e300,0]}}",
       "beyond what the page shows"},
      {"{\"type\":\"load\",\"file\":{\"n\":4,\"constraints\":[]}}", "n = 4"},
      {"{\"type\":\"load\",\"file\":{\"n\":2,\"singularities\":[{\"vertex\":7,\"index\":1}],\"constraints\":[]}}",
       "prescribes singularities"},
      {"{\"type\":\"load\",\"file\":{\"constraints\":[]}}", "missing \"n\""},
      {"{\"type\":\"set_basis_size\",\"size\":31}", "even"},
      {"{\"type\":\"set_display\",\"scalar\":\"divergence\"}", "\"energy\" or \"none\""},
  };
  for(const auto& c : cases)
  {
    s.client.send(c.first);
    const Message m = s.client.receive();
    if(c.first.find("1e300") != std::string::npos && m.type() != "error")
    {
      // A huge vector is a vector: if accepted, its field must be finite.
      EXPECT_EQ(m.type(), "added");
      const Message field = s.client.expect("field");
      for(float x : field.floats.at("vectors")) EXPECT_TRUE(std::isfinite(x));
      s.client.send("{\"type\":\"clear\"}");
      s.client.expect("field");
      continue;
    }
    ASSERT_EQ(m.type(), "error") << c.first;
    const std::string message = m.json.get<std::string>("message");
    EXPECT_NE(message.find(c.second), std::string::npos) << c.first.substr(0, 100) << " -> " << message;
  }
  // Nothing was added by all that.
  s.client.send("{\"type\":\"save\"}");
  EXPECT_EQ(s.client.expect("constraints").json.get_child("file.constraints").size(), 0u);
  EXPECT_TRUE(server->running());
}

} // namespace
