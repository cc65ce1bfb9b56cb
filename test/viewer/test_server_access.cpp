// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Who the server lets in (src/viewer/access.h), over real sockets: other web pages in the
// user's browser must not reach the session (a foreign Origin: cross-site WebSocket hijacking;
// a foreign Host: DNS rebinding), and the WebSocket needs the token of the printed address.
// Each refusal is a 403 naming its reason, and a line on the server's console.

#include "server_test_support.h"

namespace {

using namespace server_test;

// A WebSocket upgrade to `target` with the given Host and Origin (none if empty).
std::string upgrade(const std::string& target, const std::string& host, const std::string& origin)
{
  return "GET " + target + " HTTP/1.1\r\nHost: " + host + "\r\n" + (origin.empty() ? "" : "Origin: " + origin + "\r\n") +
         "Upgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
         "Sec-WebSocket-Version: 13\r\n\r\n";
}

// The server's own stdout and stderr are both read, so that refusals can be seen on the console.
class Server_access : public ::testing::Test
{
public:
  static void SetUpTestSuite()
  {
    server = new Server_process({"/bin/sh", "-c",
                                 "exec \"$0\" serve \"$1\" -n 20 --port 0 --allow-host viewer.test "
                                 "--allow-origin https://proxy.test 2>&1",
                                 TVF_TOOL, sphere_path()});
  }
  static void TearDownTestSuite() { delete server; }
  inline static Server_process* server = nullptr;

  static std::string own_host() { return "127.0.0.1:" + std::to_string(server->port()); }
  static std::string token_target() { return "/ws?token=" + server->address().token; }

  // A refused request: 403, the reason in the body, and the same reason on the console.
  static void expect_refused(const std::pair<int, std::string>& answer, const std::string& reason)
  {
    EXPECT_EQ(answer.first, 403) << answer.second;
    EXPECT_EQ(answer.second, "forbidden: " + reason + "\n");
    std::string line;
    EXPECT_TRUE(server->wait_for_line(reason, line, std::chrono::seconds(10))) << "not on the console: " << reason;
    EXPECT_EQ(line.rfind("tvf: refused ", 0), 0u) << line;
    EXPECT_EQ(line.find(server->address().token), std::string::npos) << "the console shows the token: " << line;
  }
};

TEST_F(Server_access, the_printed_address_carries_a_random_token)
{
  const std::string& token = server->address().token;
  EXPECT_EQ(token.size(), 32u); // 128 bits in hex
  EXPECT_EQ(token.find_first_not_of("0123456789abcdef"), std::string::npos) << token;
  // Another run gets another token.
  Server_process other({TVF_TOOL, "serve", sphere_path(), "-n", "20", "--port", "0"});
  EXPECT_NE(other.address().token, token);
}

TEST_F(Server_access, a_foreign_origin_is_refused)
{
  expect_refused(http_exchange(server->port(), upgrade(token_target(), own_host(), "http://evil.example")),
                 "Origin http://evil.example is not allowed (only the page's own; see --allow-origin)");
  // The page's own origin under another port is another origin.
  expect_refused(http_exchange(server->port(), upgrade(token_target(), own_host(), "http://127.0.0.1:1")),
                 "Origin http://127.0.0.1:1 is not allowed (only the page's own; see --allow-origin)");
}

TEST_F(Server_access, a_foreign_host_is_refused_on_the_page_and_on_the_websocket)
{
  const std::string reason = "Host attacker.example:" + std::to_string(server->port()) +
                             " is not allowed (this server answers to 127.0.0.1, localhost, [::1] and its address on "
                             "port " + std::to_string(server->port()) + "; see --allow-host)";
  const std::string host = "attacker.example:" + std::to_string(server->port());
  expect_refused(http_exchange(server->port(), "GET / HTTP/1.1\r\nHost: " + host + "\r\n\r\n"), reason);
  expect_refused(http_exchange(server->port(), "GET /main.js HTTP/1.1\r\nHost: " + host + "\r\n\r\n"), reason);
  // DNS rebinding: the attacker's page is then of the attacker's origin, and its Host too.
  expect_refused(http_exchange(server->port(), upgrade(token_target(), host, "http://" + host)), reason);
  // A local name on another port is not this server either.
  expect_refused(http_exchange(server->port(), "GET / HTTP/1.1\r\nHost: localhost:1\r\n\r\n"),
                 "Host localhost:1 is not allowed (this server answers to 127.0.0.1, localhost, [::1] and its "
                 "address on port " + std::to_string(server->port()) + "; see --allow-host)");
  expect_refused(http_exchange(server->port(), "GET / HTTP/1.0\r\n\r\n"),
                 "a request must name the server in its Host header");
}

TEST_F(Server_access, the_websocket_needs_the_token)
{
  const std::string origin = "http://" + own_host();
  expect_refused(http_exchange(server->port(), upgrade("/ws", own_host(), origin)),
                 "the WebSocket needs the token of the address tvf serve printed (/ws?token=...)");
  std::string wrong = server->address().token;
  wrong[7] = wrong[7] == 'a' ? 'b' : 'a';
  expect_refused(http_exchange(server->port(), upgrade("/ws?token=" + wrong, own_host(), origin)),
                 "wrong token (use the address tvf serve printed)");
  expect_refused(http_exchange(server->port(), upgrade("/ws?token=", own_host(), origin)),
                 "wrong token (use the address tvf serve printed)");
}

TEST_F(Server_access, the_page_and_its_own_origin_with_the_token_are_served)
{
  // The page and its files: without the token, under each local name.
  for(const std::string& host : {own_host(), "localhost:" + std::to_string(server->port()), std::string("localhost"),
                                 "[::1]:" + std::to_string(server->port()), std::string("viewer.test")})
  {
    const auto page = http_exchange(server->port(), "GET / HTTP/1.1\r\nHost: " + host + "\r\nConnection: close\r\n\r\n");
    EXPECT_EQ(page.first, 200) << host << ": " << page.second;
  }
  // The WebSocket with the token and the page's own origin: a session, which says hello.
  Server_test::Session s(server->address());
  EXPECT_EQ(s.info.json.get<std::string>("kind"), "vector_field");
  EXPECT_EQ(s.mesh.integers.at("triangles").size(), 3 * std::size_t(s.info.json.get<int>("mesh.faces")));
  // An origin allowed on the command line, and the origin of an allowed host.
  for(const std::string& origin : {std::string("https://proxy.test"), "http://viewer.test:" + std::to_string(server->port())})
  {
    const auto answer = http_exchange(server->port(), upgrade(token_target(), own_host(), origin));
    EXPECT_EQ(answer.first, 101) << origin << ": " << answer.second;
  }
}

} // namespace
