// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The viewer's server: Boost.Beast, synchronous, one thread per connection (a local tool: a
// handful of pages at most, and a slow solve in one page must not stall the others).

#include "server.h"
#include "access.h"
#include "messages.h"

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <sys/socket.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace tvf_viewer {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace asio = boost::asio;
using tcp = asio::ip::tcp;

struct Server::State
{
  Session_kinds kinds;
  Server_options options;
  std::atomic<int> connections{0};
  asio::io_context io;
  tcp::acceptor acceptor{io};
  std::unique_ptr<Access_policy> access; // made by listen, once the port is known
  std::string address;
};

namespace {

typedef Server::State Server_state;

// Ends a connection that stalls in the middle of a request or a message (a half-open or
// slow client would otherwise hold its thread and its slot for ever): `begin` when bytes of
// one are awaited, `end` when it is complete.  Idle connections between messages (a page
// waiting for its user) are left alone.  The blocked read returns once the socket is shut down.
class Stall_watchdog
{
public:
  Stall_watchdog(tcp::socket& socket, std::chrono::seconds timeout)
    : fd_(socket.native_handle()), timeout_(timeout), thread_([this] { run(); })
  {}
  ~Stall_watchdog()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    changed_.notify_all();
    thread_.join();
  }
  void begin()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if(!waiting_) since_ = std::chrono::steady_clock::now();
    waiting_ = true;
  }
  void end()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    waiting_ = false;
  }

private:
  void run()
  {
    std::unique_lock<std::mutex> lock(mutex_);
    while(!done_)
    {
      changed_.wait_for(lock, std::chrono::milliseconds(200));
      if(waiting_ && std::chrono::steady_clock::now() - since_ > timeout_)
      {
        ::shutdown(fd_, SHUT_RDWR);
        waiting_ = false;
      }
    }
  }

  int fd_;
  std::chrono::seconds timeout_;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool done_ = false, waiting_ = false;
  std::chrono::steady_clock::time_point since_;
  std::thread thread_;
};

std::string content_type(const std::string& path)
{
  const std::string ext = path.substr(path.find_last_of('.') + 1);
  if(ext == "html") return "text/html; charset=utf-8";
  if(ext == "js" || ext == "mjs") return "text/javascript; charset=utf-8";
  if(ext == "css") return "text/css; charset=utf-8";
  if(ext == "json" || ext == "map") return "application/json";
  if(ext == "svg") return "image/svg+xml";
  if(ext == "png") return "image/png";
  if(ext == "ico") return "image/x-icon";
  return "application/octet-stream";
}

// Targets are plain relative paths of the page's files: no "..", no odd characters.
bool safe_target(const std::string& target)
{
  if(target.empty() || target[0] != '/' || target.size() > 256 || target.find("..") != std::string::npos) return false;
  for(char c : target)
    if(!(std::isalnum(static_cast<unsigned char>(c)) || c == '/' || c == '.' || c == '_' || c == '-')) return false;
  return true;
}

const char* missing_page =
    "<!doctype html><title>tvf serve</title><p>The viewer page was not built (npm was not found when the "
    "project was configured), or <code>--web-root</code> does not hold it.  The WebSocket API at <code>/ws</code> "
    "works all the same (doc/viewer/protocol.md).</p>";

http::response<http::string_body> answer(const http::request<http::string_body>& request, const Server_state& server)
{
  auto reply = [&request](http::status status, const std::string& type, std::string body) {
    http::response<http::string_body> res{status, request.version()};
    res.set(http::field::server, "tvf serve");
    res.set(http::field::content_type, type);
    res.set(http::field::cache_control, "no-store");
    res.set("Referrer-Policy", "no-referrer"); // the page's address holds the token
    res.keep_alive(request.keep_alive());
    res.body() = std::move(body);
    res.prepare_payload();
    return res;
  };
  if(request.method() != http::verb::get && request.method() != http::verb::head)
    return reply(http::status::method_not_allowed, "text/plain", "only GET\n");
  std::string target(request.target());
  target = target.substr(0, target.find('?'));
  if(target == "/") target = "/index.html";
  if(!safe_target(target)) return reply(http::status::bad_request, "text/plain", "bad target\n");
  // Without a page directory nothing is served from the disk (an empty root would make
  // the target an absolute path).
  std::ifstream in;
  if(!server.options.web_root.empty() && std::filesystem::is_regular_file(server.options.web_root + target))
    in.open(server.options.web_root + target, std::ios::binary);
  if(!in.is_open())
  {
    if(target == "/index.html") return reply(http::status::ok, "text/html; charset=utf-8", missing_page);
    return reply(http::status::not_found, "text/plain", "not found\n");
  }
  std::ostringstream body;
  body << in.rdbuf();
  auto res = reply(http::status::ok, content_type(target), body.str());
  if(request.method() == http::verb::head) res.body().clear();
  return res;
}

// True when the other end closed the connection (an orderly shutdown or an error): a peek
// that does not wait reads end-of-file instead of "nothing yet".
bool peer_has_closed(tcp::socket& socket)
{
  char byte = 0;
  const ssize_t got = ::recv(socket.native_handle(), &byte, 1, MSG_PEEK | MSG_DONTWAIT);
  return got == 0 || (got < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR);
}

// The session on an upgraded connection, of the kind its first message asks for.  Messages
// are read in pieces so that one over the size limit can be dropped and answered, instead of
// closing the connection.
void run_websocket(tcp::socket socket, const http::request<http::string_body>& upgrade, const Server_state& server)
{
  Stall_watchdog watchdog(socket, server.options.stall_timeout);
  // Small messages (edits) must leave at once: Nagle's algorithm with delayed ACKs would
  // hold them for up to 40 ms.
  beast::error_code ignored;
  socket.set_option(tcp::no_delay(true), ignored);
  websocket::stream<tcp::socket> ws(std::move(socket));
  ws.read_message_max(std::uint64_t(1) << 32); // our own limit is enforced below, message by message
  // Fields are megabytes: one frame per message (Beast's default cuts writes into 4 kB
  // frames, which took 160 ms for 4 MB instead of 10).
  ws.auto_fragment(false);
  ws.set_option(websocket::stream_base::decorator(
      [](websocket::response_type& res) { res.set(http::field::server, "tvf serve"); }));
  ws.accept(upgrade);
  std::unique_ptr<Session> session; // opened by the first message
  struct Farewell // said on the console when a page goes away with work under way
  {
    std::unique_ptr<Session>& session;
    const Server_state& server;
    ~Farewell()
    {
      const std::string line = session ? session->farewell() : std::string();
      if(!line.empty() && !server.options.quiet) std::printf("%s\n", line.c_str()), std::fflush(stdout);
    }
  } farewell{session, server};
  const Send send = [&ws](const Outgoing& message) {
    ws.binary(message.binary);
    ws.write(asio::buffer(message.data));
  };
  const std::size_t limit = server.options.max_message_bytes;
  beast::flat_buffer buffer;
  for(;;)
  {
    // While the session finishes work unasked (an exact answer), and no message of the page
    // waits, let it send that when ready.  A page that went away ends the session at once:
    // its work stops and what it held is freed, instead of being computed for nobody.
    while(session && session->refining() && ws.next_layer().available() == 0)
    {
      if(peer_has_closed(ws.next_layer())) return;
      session->poll(send, std::chrono::milliseconds(5));
    }
    buffer.clear();
    std::size_t received = 0;
    bool oversized = false;
    do
    {
      received += ws.read_some(buffer, 64 * 1024);
      watchdog.begin(); // a message has begun: its rest must come
      if(received > limit)
      {
        oversized = true;
        buffer.clear(); // drop the rest as it comes: memory stays bounded
      }
    } while(!ws.is_message_done());
    watchdog.end();
    if(oversized) send(oversized_refusal(received, limit));
    else if(!ws.got_text()) send(binary_refusal(received));
    else
    {
      const std::string text = beast::buffers_to_string(buffer.data());
      if(!session)
      {
        Outgoing refusal;
        session = server.kinds.open_for(text, refusal);
        if(!session)
        {
          send(refusal);
          continue;
        }
      }
      session->handle_text(text, send);
    }
  }
}

// Refuses a request the access checks turned down: 403 with the reason, which the console
// also gets (a refusal is worth knowing of: a page the user did not mean to reach us).
void refuse(tcp::socket& socket, const http::request<http::string_body>& request, const std::string& reason,
            const Server_state& server)
{
  if(!server.options.quiet)
  {
    beast::error_code ignored;
    const tcp::endpoint peer = socket.remote_endpoint(ignored);
    std::string target(request.target().substr(0, 64));
    for(char& c : target) c = std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    if(auto at = target.find("token="); at != std::string::npos) target = target.substr(0, at + 6) + "...";
    std::fprintf(stderr, "tvf: refused %s %s from %s: %s\n", std::string(request.method_string()).c_str(),
                 target.c_str(), peer.address().to_string().c_str(), reason.c_str());
  }
  http::response<http::string_body> res{http::status::forbidden, request.version()};
  res.set(http::field::server, "tvf serve");
  res.set(http::field::content_type, "text/plain; charset=utf-8");
  res.body() = "forbidden: " + reason + "\n";
  res.keep_alive(false);
  res.prepare_payload();
  beast::error_code ignored;
  http::write(socket, res, ignored);
}

// Why a request may not be answered, or empty: a foreign Host on every request (DNS
// rebinding), a foreign Origin, and for the WebSocket the token.
std::string access_refusal(const http::request<http::string_body>& request, const std::string& path, bool upgrade,
                           const Server_state& server)
{
  const auto header = [&request](http::field f) {
    const auto it = request.find(f);
    return it == request.end() ? std::string() : std::string(it->value());
  };
  std::string reason = server.access->check_host(header(http::field::host));
  if(reason.empty()) reason = server.access->check_origin(header(http::field::origin));
  if(reason.empty() && upgrade && path == "/ws") reason = server.access->check_token(std::string(request.target()));
  return reason;
}

void serve_connection(tcp::socket socket, Server_state& server)
{
  struct Count // connections are counted so that a flood of them is refused, not served
  {
    std::atomic<int>& n;
    ~Count()
    {
      --n;
#ifdef __GLIBC__
      // A session's fields and pull-backs were allocated in its thread's arena, which
      // glibc keeps for the next thread: give the free pages back, so that the memory of
      // a closed session returns to the system (measured: bench/bench_server_load.mjs).
      malloc_trim(0);
#endif
    }
  } count{server.connections};
  beast::flat_buffer buffer;
  try
  {
    for(;;)
    {
      // The request must arrive whole within the stall timeout (then the socket is shut down).
      std::unique_ptr<Stall_watchdog> watchdog = std::make_unique<Stall_watchdog>(socket, server.options.stall_timeout);
      watchdog->begin();
      http::request_parser<http::string_body> parser;
      parser.header_limit(16 * 1024);
      parser.body_limit(64 * 1024);
      beast::error_code error;
      http::read(socket, buffer, parser, error);
      watchdog.reset();
      if(error == http::error::end_of_stream || error == asio::error::eof || error == asio::error::connection_reset)
        return;
      if(error)
      {
        http::response<http::string_body> res{http::status::bad_request, 11};
        res.set(http::field::content_type, "text/plain");
        res.body() = "bad request: " + error.message() + "\n";
        res.keep_alive(false);
        res.prepare_payload();
        http::write(socket, res, error);
        return;
      }
      const http::request<http::string_body>& request = parser.get();
      const std::string path(request.target().substr(0, request.target().find('?')));
      const bool upgrade = websocket::is_upgrade(request);
      if(const std::string reason = access_refusal(request, path, upgrade, server); !reason.empty())
        return refuse(socket, request, reason, server);
      if(upgrade)
      {
        if(path != "/ws")
        {
          http::response<http::string_body> res{http::status::not_found, request.version()};
          res.keep_alive(false);
          res.prepare_payload();
          http::write(socket, res);
          return;
        }
        return run_websocket(std::move(socket), request, server);
      }
      http::response<http::string_body> res = answer(request, server);
      const bool keep_alive = res.keep_alive();
      http::write(socket, res);
      if(!keep_alive) return;
    }
  }
  catch(const std::exception&)
  {
    // The page went away (or sent garbage the transport refused): only this connection ends.
  }
}

} // namespace

Server::Server(Session_kinds kinds, Server_options options) : state_(std::make_unique<State>())
{
  state_->kinds = std::move(kinds);
  state_->options = std::move(options);
}

Server::~Server() = default;

void Server::listen(const std::string& address_text, int port)
{
  beast::error_code error;
  const asio::ip::address address = asio::ip::make_address(address_text, error);
  if(error) throw std::runtime_error("'" + address_text + "' is not an IP address");
  try
  {
    const tcp::endpoint endpoint(address, static_cast<unsigned short>(port));
    state_->acceptor.open(endpoint.protocol());
    state_->acceptor.set_option(asio::socket_base::reuse_address(true));
    state_->acceptor.bind(endpoint);
    state_->acceptor.listen();
  }
  catch(const boost::system::system_error& e)
  {
    throw std::runtime_error("cannot listen on " + address_text + ":" + std::to_string(port) + ": " +
                             e.code().message());
  }
  const tcp::endpoint bound = state_->acceptor.local_endpoint();
  state_->address = bound.address().to_string();
  state_->access = std::make_unique<Access_policy>(state_->address, int(bound.port()), state_->options.allowed_hosts,
                                                   state_->options.allowed_origins, random_token());
}

std::string Server::url() const
{
  const tcp::endpoint bound = state_->acceptor.local_endpoint();
  return "http://" + url_host(state_->address) + ":" + std::to_string(bound.port()) + "/?token=" +
         state_->access->token();
}

void Server::run()
{
  std::signal(SIGPIPE, SIG_IGN); // a page that vanishes mid-write ends its session, not the server
  State& server = *state_;
  for(;;)
  {
    beast::error_code error;
    tcp::socket socket(server.io);
    server.acceptor.accept(socket, error);
    if(error) continue;
    if(server.connections.load() >= server.options.max_connections)
    {
      socket.close(error); // refused: too many pages at once
      continue;
    }
    ++server.connections;
    std::thread([s = std::move(socket), &server]() mutable { serve_connection(std::move(s), server); }).detach();
  }
}

} // namespace tvf_viewer
