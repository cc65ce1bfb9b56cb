// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The editor's server under load: sessions editing at once (half of them with exact answers
// on a worker thread each) while other connections misbehave -- frames cut off, oversized
// messages dropped mid-way, upgrades closed at once, sessions closed while their exact answer
// is being computed.  Every honest session must get correct fields throughout, and the
// connections that went away must give back their slots (the server serves at most 16 at once).

#include "server_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>
#include <thread>

namespace {

using namespace server_test;

// A connection of type `C` to the server; a refusal is retried for up to 10 s.  The server
// serves at most 16 at once, and a connection that went away keeps its slot until the
// server's thread of it ends -- a session dropped during an exact answer until the answer is
// done, which on a loaded machine outlasts the next few connections.  Null (with a test
// failure) if it was still refused after that.
template <class C>
std::unique_ptr<C> connect_retrying(const Address& port, const std::string& what)
{
  for(int attempt = 0;; ++attempt)
  {
    try
    {
      return std::make_unique<C>(port);
    }
    catch(const std::exception& e)
    {
      if(attempt == 100)
      {
        ADD_FAILURE() << what << " was refused for 10 s: " << e.what();
        return nullptr;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
}

// A session that edits one vector constraint `edits` times (moves and value edits) and checks
// every field it gets at the constrained face: what went wrong first, or "" if nothing did.
std::string edit_session(const Address& port, int first_face, bool exact, int edits)
{
  int k = -1;
  try
  {
    Server_test::Session s(port);
    if(exact)
    {
      s.client.send("{\"type\":\"set_solver\",\"solver\":\"full\"}");
      while(!s.client.expect("field").json.get<bool>("answer.exact")) // the exact one follows
        ;
    }
    int id = -1;
    for(k = 0; k < edits; ++k)
    {
      const int face = (first_face + 37 * (k / 3)) % 320; // a move every third edit
      std::array<double, 3> v = tangent(s.mesh, face);
      for(double& x : v) x *= 0.5 + 0.1 * (k % 3);
      if(id < 0)
      {
        s.client.send("{\"type\":\"add\",\"constraint\":" + vector_constraint(face, v) + "}");
        id = s.client.expect("added").json.get<int>("id");
      }
      else
        s.client.send("{\"type\":\"change\",\"id\":" + std::to_string(id) + ",\"constraint\":" + vector_constraint(face, v) + "}");
      Message field = s.client.expect("field");
      // With exact answers on, the exact field may follow: take it too (it meets the constraint as well).
      if(exact && !field.json.get<bool>("answer.exact")) field = s.client.expect("field");
      if(field.type() != "field") return "edit " + std::to_string(k) + ": a " + field.type() + " message instead of a field";
      const double off = distance(face_vector(field, face), v);
      if(off > 1e-5) return "edit " + std::to_string(k) + ": the field is " + std::to_string(off) + " off the constraint";
    }
    return "";
  }
  catch(const std::exception& e)
  {
    return "edit " + std::to_string(k) + ": " + e.what();
  }
}

// Joins the threads however the test body ends (a joinable thread left behind aborts the run).
struct Joined_threads
{
  std::vector<std::thread> threads;
  ~Joined_threads()
  {
    for(std::thread& t : threads)
      if(t.joinable()) t.join();
  }
};

TEST_F(Server_test, sessions_keep_working_while_other_connections_misbehave)
{
  const Address port = server->address();
  std::string outcomes[6];
  Joined_threads sessions;
  for(int i = 0; i < 6; ++i)
    sessions.threads.emplace_back([&, i] { outcomes[i] = edit_session(port, 11 * i + 3, i % 2 == 1, 15); });

  // Meanwhile: misbehaving connections, each of which must end only itself.
  for(int i = 0; i < 12; ++i)
  {
    // a frame header announcing 1000 bytes, a few of them, then the socket closes
    if(auto cut = connect_retrying<Client>(port, "a connection to cut off"))
    {
      const unsigned char frame[] = {0x81, 0xFE, 0x03, 0xE8, 1, 2, 3, 4, '{', '"'};
      asio::write(cut->stream().next_layer(), asio::buffer(frame, sizeof frame));
      cut->stream().next_layer().close();
    }
    // an upgrade, closed at once
    if(auto closed = connect_retrying<Client>(port, "a connection to close")) closed->stream().next_layer().close();
    // a session closed while its exact answer is being computed
    if(auto dropped = connect_retrying<Session>(port, "a session to drop"))
    {
      dropped->client.send("{\"type\":\"set_solver\",\"solver\":\"full\"}");
      dropped->client.send("{\"type\":\"add\",\"constraint\":" + vector_constraint(5 + i, tangent(dropped->mesh, 5 + i)) + "}");
      dropped->client.stream().next_layer().close();
    }
  }
  // an oversized message (2 MiB), answered with an error while the others go on
  if(auto big = connect_retrying<Session>(port, "the session of the oversized message"))
  {
    big->client.send(std::string(2 << 20, ' '));
    EXPECT_NE(big->client.expect_error().find("exceeds the limit"), std::string::npos);
  }
  for(std::thread& t : sessions.threads) t.join();
  for(int i = 0; i < 6; ++i) EXPECT_EQ(outcomes[i], "") << "editing session " << i << (i % 2 ? " (exact answers)" : "");

  // Every connection that went away gave back its slot: 16 sessions (the limit) at once.
  std::vector<std::unique_ptr<Session>> full_house;
  for(int i = 0; i < 16; ++i)
  {
    full_house.push_back(connect_retrying<Session>(port, "session " + std::to_string(i) + " of 16"));
    ASSERT_TRUE(full_house.back());
  }
  for(auto& s : full_house)
  {
    s->client.send("{\"type\":\"ping\",\"request\":3}");
    EXPECT_EQ(s->client.expect("pong").json.get<int>("request"), 3);
  }
  full_house.clear();
  EXPECT_TRUE(server->running());
  // The 16 slots come back as the server's threads see their connections close, a moment
  // after the close here (on a loaded machine, after the next connection arrives).
  const auto after = connect_retrying<Session>(port, "a session after the 16");
  ASSERT_TRUE(after);
  EXPECT_EQ(after->info.json.get<int>("mesh.faces"), 320);
}

TEST_F(Server_test, stalled_clients_are_disconnected)
{
  // A client that begins a request or a message and stalls is cut off after the stall
  // timeout (2 s for this server); an idle session between messages is not.
  const Address port = server->address();
  Session idle(port);
  const auto start = std::chrono::steady_clock::now();
  Client stalled(port); // a frame announcing 1000 bytes, 2 of them sent, the socket kept open
  const unsigned char frame[] = {0x81, 0xFE, 0x03, 0xE8, 1, 2, 3, 4, '{', '"'};
  asio::write(stalled.stream().next_layer(), asio::buffer(frame, sizeof frame));
  asio::io_context io;
  tcp::socket silent(io); // a TCP connection that never sends its HTTP request
  silent.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port.port));
  beast::flat_buffer buffer;
  beast::error_code error;
  stalled.stream().read(buffer, error);
  EXPECT_TRUE(error) << "the stalled message's connection stays open";
  char byte;
  silent.read_some(asio::buffer(&byte, 1), error);
  EXPECT_TRUE(error) << "the silent connection stays open";
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GT(seconds, 1.5);
  EXPECT_LT(seconds, 10.0);
  idle.client.send("{\"type\":\"ping\",\"request\":2}"); // idle for those seconds: still served
  EXPECT_EQ(idle.client.expect("pong").json.get<int>("request"), 2);
}

TEST(Server_refinement, a_page_that_goes_away_while_refining_stops_the_refinement)
{
  // A constraint file of 30 vectors loaded at once on a mesh of 20k faces: the reduced
  // answer comes at once, the 30 pull-backs (milliseconds each) after it.  The page closes
  // as soon as it has the reduced field; the server must notice at once and stop, not
  // compute the rest for nobody.  It says so on its console, with the count of constraints
  // left without their pull-back (none would be left had it gone on until the exact field).
  Server_process server({TVF_TOOL, "serve", std::string(TVF_CGAL_DATA_DIR) + "/meshes/camel.off", "-n", "300",
                         "--port", "0"});
  std::string line;
  ASSERT_TRUE(server.wait_for_line("basis ready", line, std::chrono::seconds(120)));
  const int constraints = 30;
  {
    Server_test::Session s(server.address());
    const int faces = s.info.json.get<int>("mesh.faces");
    s.client.send("{\"type\":\"set_display\",\"lines\":\"none\"}");
    s.client.expect("field");
    s.client.send("{\"type\":\"set_solver\",\"solver\":\"full\"}"); // the full solver is made
    while(!s.client.expect("field").json.get<bool>("answer.exact"))
      ;
    std::string file = "{\"constraints\":[";
    for(int k = 0; k < constraints; ++k)
    {
      const int face = int((k * 7919LL) % faces);
      file += (k ? "," : "") + vector_constraint(face, tangent(s.mesh, face));
    }
    s.client.send("{\"type\":\"load\",\"file\":" + file + "],\"omega\":0}}");
    EXPECT_EQ(s.client.expect("loaded").json.get_child("ids").size(), std::size_t(constraints));
    const Message field = s.client.expect("field");
    ASSERT_FALSE(field.json.get<bool>("answer.exact"));
    s.client.stream().next_layer().close();
  }
  ASSERT_TRUE(server.wait_for_line("a page closed while its exact answer was being computed", line,
                                   std::chrono::seconds(30)));
  int pending = -1, total = -1;
  ASSERT_EQ(std::sscanf(line.c_str(), "%*[^0-9]%d of %d", &pending, &total), 2) << line;
  EXPECT_EQ(total, constraints) << line;
  EXPECT_GT(pending, 0) << line;
}

} // namespace
