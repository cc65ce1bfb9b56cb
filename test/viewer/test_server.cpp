// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The editor's server (`tvf serve`), driven over real sockets: the session honours its
// constraints, and malformed and hostile messages (huge, truncated, NaN, out-of-range
// indices, deep nesting, binary, broken frames, bad HTTP) each get an error while the
// server stays up.  The server runs as its own process, as users run it.

#include "full_spline_truth.h"
#include "server_test_support.h"

#include <gtest/gtest.h>

namespace {

using namespace server_test;

TEST_F(Server_test, hello_sends_mesh_and_field)
{
  Session s(server->address());
  const int nf = s.info.json.get<int>("mesh.faces"), nv = s.info.json.get<int>("mesh.vertices");
  EXPECT_EQ(nf, 320);
  EXPECT_EQ(s.info.json.get<int>("basis.available"), 60);
  EXPECT_EQ(s.mesh.floats.at("positions").size(), 3u * nv);
  EXPECT_EQ(s.mesh.integers.at("triangles").size(), 3u * nf);
  EXPECT_EQ(s.mesh.integers.at("face_edges").size(), 3u * nf);
  EXPECT_EQ(s.mesh.integers.at("boundary_edges").size(), 0u); // a closed sphere
  ASSERT_EQ(s.field.floats.at("vectors").size(), 3u * nf);
  EXPECT_EQ(s.field.json.get<int>("request"), 1);
  for(float x : s.field.floats.at("vectors")) EXPECT_EQ(x, 0.f); // no constraints: the zero field
}

// After an edit of a vector field with fur, the server first sends the preview: the fur of the
// reduced answer traced through the faces it reaches only, then the field as always, whose fur
// (traced on the whole reduced field, the truth here) has the same strokes.
TEST_F(Server_test, preview_strokes_come_before_the_field_and_match_its_fur)
{
  Session s(server->address());
  const int nf = s.info.json.get<int>("mesh.faces");
  const double diagonal = s.info.json.get<double>("mesh.diagonal");
  // Few strokes, so that they reach a fraction of the 320 faces.
  s.client.send("{\"type\":\"set_display\",\"strokes\":20,\"length\":0.1}");
  s.client.expect("field");
  const int f = 17;
  s.client.send("{\"type\":\"add\",\"request\":7,\"constraint\":" + vector_constraint(f, tangent(s.mesh, f)) + "}");
  EXPECT_EQ(s.client.expect("added").json.get<int>("request"), 7);
  const Message preview = s.client.receive();
  ASSERT_EQ(preview.type(), "preview") << "the preview comes before the field";
  const Message field = s.client.receive();
  ASSERT_EQ(field.type(), "field");
  EXPECT_EQ(preview.json.get<int>("request"), 7);
  EXPECT_EQ(field.json.get<int>("request"), 7);
  for(const char* t : {"solve_ms", "lines_ms", "server_ms"})
    EXPECT_GE(preview.json.get<double>(std::string("timings.") + t), 0.0) << t;
  // The error bound of the reduced answer, as the field (reduced too) reports it.
  EXPECT_EQ(preview.json.get<std::string>("report.error_bound"), field.json.get<std::string>("report.error_bound"));
  const int faces_read = preview.json.get<int>("faces_read");
  EXPECT_GT(faces_read, 0);
  EXPECT_LT(faces_read, nf) << "the preview read every face";
  const std::vector<float>& a = preview.floats.at("lines");
  const std::vector<float>& b = field.floats.at("lines");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 0u);
  double largest = 0;
  for(std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, std::abs(double(a[i]) - double(b[i])));
  EXPECT_LE(largest, 1e-6 * diagonal); // float32 transfer of the same strokes

  // No preview without fur: streamlines cover the whole surface, and "none" draws no lines.
  for(const char* lines : {"streamlines", "none"})
  {
    s.client.send(std::string("{\"type\":\"set_display\",\"lines\":\"") + lines + "\"}");
    EXPECT_EQ(s.client.receive().type(), "field") << lines;
  }
}

TEST_F(Server_test, field_honours_constraints_and_edits)
{
  Session s(server->address());
  const int f = 17;
  const std::array<double, 3> v = tangent(s.mesh, f);
  s.client.send("{\"type\":\"add\",\"request\":5,\"constraint\":" + vector_constraint(f, v) + "}");
  const Message added = s.client.expect("added");
  const int id = added.json.get<int>("id");
  EXPECT_EQ(added.json.get<int>("request"), 5);
  Message field = s.client.expect("field");
  EXPECT_EQ(field.json.get<int>("request"), 5);
  // float32 transfer: 1e-6 relative to a unit vector.
  EXPECT_LT(distance(face_vector(field, f), v), 1e-6);
  EXPECT_LT(field.json.get<double>("report.residual"), 1e-9);
  for(const char* t : {"solve_ms", "reconstruct_ms", "lines_ms", "server_ms"})
    EXPECT_GE(field.json.get<double>(std::string("timings.") + t), 0.0) << t;
  EXPECT_GT(field.floats.at("lines").size(), 0u); // fur by default

  // A changed value (the fast path) moves the field at the face with it.
  const std::array<double, 3> w = {{-2 * v[0], -2 * v[1], -2 * v[2]}};
  s.client.send("{\"type\":\"change\",\"id\":" + std::to_string(id) + ",\"constraint\":" + vector_constraint(f, w) + "}");
  field = s.client.expect("field");
  EXPECT_LT(distance(face_vector(field, f), w), 2e-6);

  // Display: divergence as a scalar per vertex, no lines.
  s.client.send("{\"type\":\"set_display\",\"scalar\":\"divergence\",\"lines\":\"none\"}");
  field = s.client.expect("field");
  EXPECT_EQ(field.floats.at("scalar").size(), s.mesh.floats.at("positions").size() / 3);
  EXPECT_EQ(field.floats.count("lines"), 0u);

  // A source: the divergence at the point is met (vertex values interpolate linearly).
  s.client.send("{\"type\":\"add\",\"constraint\":{\"type\":\"divergence\",\"face\":100,\"barycentric\":[0.2,0.3,0.5],"
                "\"vertices\":[" +
                std::to_string(s.mesh.integers.at("triangles")[300]) + "," +
                std::to_string(s.mesh.integers.at("triangles")[301]) + "," +
                std::to_string(s.mesh.integers.at("triangles")[302]) + "],\"value\":3}}");
  s.client.expect("added");
  field = s.client.expect("field");
  const auto& t = s.mesh.integers.at("triangles");
  const auto& div = field.floats.at("scalar");
  EXPECT_NEAR(0.2 * div[t[300]] + 0.3 * div[t[301]] + 0.5 * div[t[302]], 3.0, 1e-4);

  // Exact answers: the one-shot full spline of the same constraints, solved here through the
  // library; the distance of the reduced answer (the field just sent) to it is the one reported.
  const Message reduced = field;
  const Truth truth = full_spline({TVF::Field_constraint::vector_in_face(f, w),
                                   TVF::Field_constraint::divergence_at_point(100, {{0.2, 0.3, 0.5}}, 3)},
                                  0);
  ASSERT_EQ(library_sphere_triangles(), t); // the server numbers faces and vertices as the library does
  s.client.send("{\"type\":\"set_solver\",\"solver\":\"full\"}");
  field = s.client.expect("field");
  EXPECT_EQ(field.json.get<std::string>("solver"), "full");
  if(!field.json.get<bool>("answer.exact")) field = s.client.expect("field"); // the refined one
  EXPECT_TRUE(field.json.get<bool>("answer.exact"));
  EXPECT_LT(largest_gap(field, truth), 1e-6); // float32 on the wire: 6e-8 relative
  EXPECT_GT(largest_gap(reduced, truth), 1e-3); // the reduced answer is not the exact one
  EXPECT_NEAR(field.json.get<double>("difference"), mass_distance(reduced, truth), 1e-6);
  EXPECT_GT(field.json.get<double>("largest_angle_deg"), 0.0);

  // Save: the command line's constraint file, which load takes back.
  s.client.send("{\"type\":\"save\"}");
  Message saved = s.client.expect("constraints");
  EXPECT_EQ(saved.json.get_child("file.constraints").size(), 2u);
  const std::string file = object_member_text(saved.text, "file");
  s.client.send("{\"type\":\"clear\"}");
  field = s.client.expect("field");
  EXPECT_EQ(field.json.get_child("ids").size(), 0u);
  s.client.send("{\"type\":\"set_solver\",\"solver\":\"reduced\"}");
  s.client.expect("field");
  s.client.send("{\"type\":\"load\",\"file\":" + file + "}");
  EXPECT_EQ(s.client.expect("loaded").json.get_child("ids").size(), 2u);
  field = s.client.expect("field");
  EXPECT_LT(distance(face_vector(field, f), w), 2e-6);

  // Removing the vector constraint leaves the source only: the face vector changes.
  s.client.send("{\"type\":\"remove\",\"id\":" + std::to_string(field.json.get_child("ids").front().second.get_value<int>()) + "}");
  field = s.client.expect("field");
  EXPECT_GT(distance(face_vector(field, f), w), 0.1);
}

// The fields an edit brings: the first answer, and if it is reduced, the exact one that follows
// (a `refined` field echoing the edit's request).  Returns the exact one; `reduced` receives
// the reduced one if it came (else stays empty).
Message until_exact(Client& client, int request, Message* reduced = nullptr)
{
  Message field = client.expect("field");
  EXPECT_EQ(field.json.get<int>("request"), request);
  EXPECT_FALSE(field.json.get<bool>("refined", false));
  if(field.json.get<bool>("answer.exact")) return field;
  if(reduced) *reduced = field;
  Message exact = client.expect("field");
  EXPECT_TRUE(exact.json.get<bool>("refined", false));
  EXPECT_TRUE(exact.json.get<bool>("answer.exact"));
  EXPECT_EQ(exact.json.get<int>("answer.pending"), 0);
  EXPECT_EQ(exact.json.get<int>("request"), request);
  return exact;
}

TEST_F(Server_test, exact_answers_follow_reduced_ones)
{
  // With exact answers on, an edit is answered at once (reduced if a pull-back is pending)
  // and the exact field follows unasked; value edits of pulled-back constraints are exact at
  // once; a move makes the answer reduced again until its new pull-back is in; the exact
  // field meets the constraints in the solver's precision (1e-9) and to float32 on the wire,
  // and is the one-shot full spline of its constraints (solved here through the library).
  Session s(server->address());
  s.client.send("{\"type\":\"set_solver\",\"solver\":\"full\",\"request\":1}");
  until_exact(s.client, 1); // no constraint yet: exact once the full solver is made
  const int f = 40, g = 200;
  const std::array<double, 3> v = tangent(s.mesh, f);
  s.client.send("{\"type\":\"add\",\"request\":2,\"constraint\":" + vector_constraint(f, v) + "}");
  const int id = s.client.expect("added").json.get<int>("id");
  Message reduced;
  Message exact = until_exact(s.client, 2, &reduced);
  EXPECT_LT(distance(face_vector(exact, f), v), 1e-6);
  EXPECT_LT(exact.json.get<double>("report.residual"), 1e-9);
  const Truth truth_v = full_spline({TVF::Field_constraint::vector_in_face(f, v)}, 0);
  EXPECT_LT(largest_gap(exact, truth_v), 1e-6); // float32 on the wire: 6e-8 relative
  // The exact answer's error bound is 0; the reduced one's is positive (60 of 640 dimensions).
  EXPECT_EQ(exact.json.get<double>("report.error_bound"), 0.);
  if(reduced.binary) EXPECT_GT(reduced.json.get<double>("report.error_bound"), 0.);
  if(reduced.binary) // the reduced answer came first: the reported difference is its distance
    EXPECT_NEAR(exact.json.get<double>("difference"), mass_distance(reduced, truth_v), 1e-6);
  else // the exact answer came sooner: no reduced one of this state, no difference
    EXPECT_EQ(exact.json.count("difference"), 0u);
  // A value edit: exact at once, no second field.
  const std::array<double, 3> w = {{0.5 * v[0], 0.5 * v[1], 0.5 * v[2]}};
  s.client.send("{\"type\":\"change\",\"request\":3,\"id\":" + std::to_string(id) + ",\"constraint\":" +
                vector_constraint(f, w) + "}");
  Message field = s.client.expect("field");
  EXPECT_TRUE(field.json.get<bool>("answer.exact"));
  EXPECT_LT(distance(face_vector(field, f), w), 1e-6);
  EXPECT_LT(largest_gap(field, full_spline({TVF::Field_constraint::vector_in_face(f, w)}, 0)), 1e-6);
  const double difference = field.json.get<double>("difference"); // the reduced answer is cheap here too
  EXPECT_GT(difference, 1e-3); // 60 eigenfields of 640 dimensions do not give the exact spline
  s.client.send("{\"type\":\"ping\",\"request\":4}");
  EXPECT_EQ(s.client.expect("pong").json.get<int>("request"), 4); // nothing else came
  // Another value edit: with omega = 0 both answers are linear in the one value, so their
  // relative difference stays as it was.
  const std::array<double, 3> w2 = {{-2 * v[0], -2 * v[1], -2 * v[2]}};
  s.client.send("{\"type\":\"change\",\"request\":4,\"id\":" + std::to_string(id) + ",\"constraint\":" +
                vector_constraint(f, w2) + "}");
  field = s.client.expect("field");
  EXPECT_TRUE(field.json.get<bool>("answer.exact"));
  EXPECT_LT(largest_gap(field, full_spline({TVF::Field_constraint::vector_in_face(f, w2)}, 0)), 1e-6);
  EXPECT_NEAR(field.json.get<double>("difference"), difference, 1e-9 * difference);
  // A move, then another before its pull-back can be in: each answer is of its own state, and
  // the exact field that ends it meets the last one.
  const std::array<double, 3> u = tangent(s.mesh, g);
  s.client.send("{\"type\":\"change\",\"request\":5,\"id\":" + std::to_string(id) + ",\"constraint\":" +
                vector_constraint(g, u) + "}");
  s.client.send("{\"type\":\"change\",\"request\":6,\"id\":" + std::to_string(id) + ",\"constraint\":" +
                vector_constraint(f, v) + "}");
  std::vector<Message> fields;
  for(;;)
  {
    fields.push_back(s.client.expect("field"));
    const Message& m = fields.back();
    if(m.json.get<int>("request") == 6 && m.json.get<bool>("answer.exact")) break;
  }
  for(const Message& m : fields)
  {
    const bool last_state = m.json.get<int>("request") == 6;
    // Every field shows its own state: the constraint of that request is met.
    EXPECT_LT(distance(face_vector(m, last_state ? f : g), last_state ? v : u), 1e-6)
        << "request " << m.json.get<int>("request") << (m.json.get<bool>("answer.exact") ? " exact" : " reduced");
  }
  EXPECT_LT(distance(face_vector(fields.back(), f), v), 1e-6);
  EXPECT_LT(largest_gap(fields.back(), truth_v), 1e-6);
  // Exact answers off: reduced at once, nothing follows.
  s.client.send("{\"type\":\"set_solver\",\"solver\":\"reduced\",\"request\":7}");
  field = s.client.expect("field");
  EXPECT_FALSE(field.json.get<bool>("answer.exact"));
  s.client.send("{\"type\":\"ping\",\"request\":8}");
  EXPECT_EQ(s.client.expect("pong").json.get<int>("request"), 8);
}

TEST_F(Server_test, fast_value_edits_equal_fresh_solves)
{
  // Value edits use the field's cached response to the edited constraint; a fresh session
  // solving the same constraints from scratch must give the same field.
  Session a(server->address());
  const int f = 40, g = 200;
  const std::array<double, 3> v = tangent(a.mesh, f), u = tangent(a.mesh, g);
  a.client.send("{\"type\":\"set_display\",\"lines\":\"none\"}");
  a.client.expect("field");
  a.client.send("{\"type\":\"add\",\"constraint\":" + vector_constraint(f, v) + "}");
  const int vid = a.client.expect("added").json.get<int>("id");
  a.client.expect("field");
  a.client.send("{\"type\":\"add\",\"constraint\":" + vector_constraint(g, u) + "}");
  const int uid = a.client.expect("added").json.get<int>("id");
  a.client.expect("field");
  a.client.send("{\"type\":\"add\",\"constraint\":{\"type\":\"curl\",\"edge\":77,\"value\":2}}");
  const int cid = a.client.expect("added").json.get<int>("id");
  a.client.expect("field");
  Message field;
  // Runs of edits of one constraint (the cached responses at work), and switches between
  // constraints (the responses rebuilt).
  const std::string schedule = "vvvuuccvv";
  for(std::size_t k = 0; k < schedule.size(); ++k)
  {
    const double s = 0.3 + 0.4 * k;
    const char which = schedule[k];
    if(which == 'c')
      a.client.send("{\"type\":\"change\",\"id\":" + std::to_string(cid) +
                    ",\"constraint\":{\"type\":\"curl\",\"edge\":77,\"value\":" + std::to_string(-s) + "}}");
    else
    {
      const std::array<double, 3>& w = which == 'u' ? u : v;
      a.client.send("{\"type\":\"change\",\"id\":" + std::to_string(which == 'u' ? uid : vid) + ",\"constraint\":" +
                    vector_constraint(which == 'u' ? g : f, {{s * w[0], -s * w[1], s * w[2]}}) + "}");
    }
    field = a.client.expect("field");
  }
  a.client.send("{\"type\":\"save\"}");
  const std::string file = object_member_text(a.client.expect("constraints").text, "file");

  Session b(server->address());
  b.client.send("{\"type\":\"load\",\"file\":" + file + "}");
  b.client.expect("loaded");
  const Message fresh = b.client.expect("field");
  const std::vector<float>& x = field.floats.at("vectors");
  const std::vector<float>& y = fresh.floats.at("vectors");
  ASSERT_EQ(x.size(), y.size());
  double largest = 0, difference = 0;
  for(std::size_t i = 0; i < x.size(); ++i)
  {
    largest = std::max(largest, std::fabs(double(y[i])));
    difference = std::max(difference, std::fabs(double(x[i]) - double(y[i])));
  }
  EXPECT_GT(largest, 0.1);
  EXPECT_LT(difference, 1e-5 * largest); // float32 output; the two paths agree to ~1e-12 in double
}

TEST_F(Server_test, hostile_messages_get_errors_and_the_server_stays_up)
{
  Session s(server->address());
  const int nf = s.info.json.get<int>("mesh.faces");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {std::string(2 << 20, ' '), "exceeds the limit"},                     // huge (2 MiB)
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"vector\",\"face\":1,", "not JSON"}, // truncated
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"vector\",\"face\":1,\"vector\":[NaN,0,0]}}", "not JSON"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"vector\",\"face\":1,\"vector\":[1e999,0,0]}}", "overflow"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"vector\",\"face\":1,\"vector\":[1,0,0],\"weigth\":2}}",
       "unknown key \"weigth\" for a vector constraint"},
      {"{\"type\":\"set_omega\",\"omgea\":1}", "unknown key \"omgea\""},
      {"{\"type\":\"set_omega\",\"omega\":1,\"omega\":2}", "the key \"omega\" appears twice"},
      {"{\"type\":\"set_omega\",\"omega\":\"1\"}", "must be a number"},
      {"{\"type\":\"load\",\"file\":{\"constraints\":[],\"omega\":0,\"extra\":1}}", "unknown key \"extra\""},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"vector\",\"face\":" + std::to_string(nf) + ",\"vector\":[1,0,0]}}",
       "out of range"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"vector\",\"face\":-1,\"vector\":[1,0,0]}}", "index"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"divergence\",\"vertex\":99999999,\"value\":1}}", "range"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"curl\",\"edge\":4000000000,\"value\":1}}", "index"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"vector\",\"face\":3,\"vector\":[1,0]}}", "3 numbers"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"vector\",\"face\":3,\"vector\":[1e300,1e300,0]}}",
       "beyond what the page shows"},
      {"{\"type\":\"add\",\"constraint\":{\"type\":\"warp\",\"face\":3}}", "unknown type"},
      {"{\"type\":\"add\",\"constraint\":5}", "not a JSON object"},
      {"{\"type\":\"add\"}", "missing \"constraint\""},
      {"{\"type\":\"change\",\"id\":12345,\"constraint\":{\"type\":\"vector\",\"face\":1,\"vector\":[1,0,0]}}",
       "no constraint with id"},
      {"{\"type\":\"remove\",\"id\":\"abc\"}", "must be a number"},
      {"{\"type\":\"remove\",\"id\":1.5}", "integer"},
      {"{\"type\":\"set_omega\",\"omega\":-1}", "omega"},
      {"{\"type\":\"set_basis_size\",\"size\":100000}", "size"},
      {"{\"type\":\"set_display\",\"strokes\":1e9}", "strokes"},
      {"{\"type\":\"set_display\",\"lines\":{\"a\":1}}", "must be a string"},
      {"{\"type\":\"set_solver\",\"solver\":\"quantum\"}", "solver"},
      {"{\"type\":\"load\",\"file\":{\"constraints\":[{\"type\":\"vector\",\"face\":1,\"vector\":[1,0,0]},"
       "{\"type\":\"vector\",\"face\":1,\"vector\":[0,1,0]}]}}",
       "depends on the constraints already set"}, // two different vectors in one face: infeasible
      {"{\"type\":\"frobnicate\"}", "unknown message type"},
      {"{\"request\":3}", "missing \"type\""},
      {"[1,2,3]", "JSON object"},
      {"42", "JSON object"},
      {"", "not JSON"},
      {std::string(100000, '[') + std::string(100000, ']'), "nested deeper"},
      {"{\"type\":\"hello\",\"request\":-4}", "request"},
  };
  for(const auto& c : cases)
  {
    s.client.send(c.first);
    const std::string message = s.client.expect_error();
    EXPECT_NE(message.find(c.second), std::string::npos) << c.first.substr(0, 80) << " -> " << message;
    s.client.send("{\"type\":\"ping\",\"request\":9}");
    EXPECT_EQ(s.client.expect("pong").json.get<int>("request"), 9);
  }
  s.client.send_binary(std::string(1000, '\x01'));
  EXPECT_NE(s.client.expect_error().find("binary"), std::string::npos);

  // The session is unchanged by all that: no constraints were added.
  s.client.send("{\"type\":\"save\"}");
  EXPECT_EQ(s.client.expect("constraints").json.get_child("file.constraints").size(), 0u);

  // Transport-level abuse ends only its own connection.
  {
    Client broken(server->address()); // invalid UTF-8 in a text message: Beast closes the connection
    broken.send(std::string("{\"type\":\"\xff\xfe\"}"));
    beast::flat_buffer buffer;
    beast::error_code error;
    broken.stream().read(buffer, error);
    EXPECT_TRUE(error);
  }
  {
    Client truncated(server->address()); // a frame header announcing 1000 bytes, then the socket closes
    const unsigned char frame[] = {0x81, 0xFE, 0x03, 0xE8, 1, 2, 3, 4, 'a', 'b'};
    asio::write(truncated.stream().next_layer(), asio::buffer(frame, sizeof frame));
    truncated.stream().next_layer().close();
  }
  for(const std::string& raw : std::vector<std::string>{"GARBAGE\r\n\r\n", "GET /../etc/passwd HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n",
                                "GET / HTTP/1.1\r\nX-Big: " + std::string(100000, 'a') + "\r\n\r\n",
                                "POST / HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 5\r\n\r\nhello"})
  {
    asio::io_context io;
    tcp::socket socket(io);
    socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), server->port()));
    beast::error_code error;
    asio::write(socket, asio::buffer(raw), error);
    asio::streambuf reply;
    asio::read_until(socket, reply, "\r\n", error);
    std::istream in(&reply);
    std::string status;
    std::getline(in, status);
    EXPECT_TRUE(status.find(" 400 ") != std::string::npos || status.find(" 405 ") != std::string::npos)
        << raw.substr(0, 40) << " -> " << status;
  }

  EXPECT_TRUE(server->running());
  Session again(server->address()); // a new session still works
  EXPECT_EQ(again.info.json.get<int>("mesh.faces"), nf);
  s.client.send("{\"type\":\"ping\"}");
  s.client.expect("pong");
}

} // namespace
