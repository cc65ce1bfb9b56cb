// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `tvf serve`: the field editor's server.  Boost.Beast, synchronous, one thread per
// connection (a local tool: a handful of pages at most, and a slow full-resolution solve
// in one page must not stall the others).  HTTP serves the bundled page; the WebSocket
// at /ws carries the editing session (editor_session.h, doc/editor_protocol.md).

#include "editor_session.h"
#include "tool.h"

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>


#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>
#include <sys/socket.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <mutex>
#include <condition_variable>

#ifndef TVF_EDITOR_DIST_DIR
#define TVF_EDITOR_DIST_DIR ""
#endif

namespace tvf_tool {

namespace {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace asio = boost::asio;
using tcp = asio::ip::tcp;

struct Server
{
  std::shared_ptr<const Editor_model> model;
  std::string web_root;
  int max_connections = 16;
  std::atomic<int> connections{0};
  std::chrono::seconds stall_timeout{20};
  bool quiet = false;
};

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
  const std::string ext = extension(path);
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
    "<!doctype html><title>tvf serve</title><p>The editor page was not built (npm was not found when the "
    "project was configured), or <code>--web-root</code> does not hold it.  The WebSocket API at <code>/ws</code> "
    "works all the same (doc/editor_protocol.md).</p>";

http::response<http::string_body> answer(const http::request<http::string_body>& request, const Server& server)
{
  auto reply = [&request](http::status status, const std::string& type, std::string body) {
    http::response<http::string_body> res{status, request.version()};
    res.set(http::field::server, "tvf serve");
    res.set(http::field::content_type, type);
    res.set(http::field::cache_control, "no-store");
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
  if(!server.web_root.empty() && std::filesystem::is_regular_file(server.web_root + target))
    in.open(server.web_root + target, std::ios::binary);
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

// The editing session on an upgraded connection.  Messages are read in pieces so that one
// over the size limit can be dropped and answered, instead of closing the connection.
void run_websocket(tcp::socket socket, const http::request<http::string_body>& upgrade, const Server& server)
{
  Stall_watchdog watchdog(socket, server.stall_timeout);
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
  Editor_session session(server.model);
  struct Farewell // said on the console when a page goes away before its exact answer came
  {
    Editor_session& session;
    const Server& server;
    ~Farewell()
    {
      int pending = 0;
      try
      {
        pending = session.refining() ? session.pending_pull_backs() : 0;
      }
      catch(const std::exception&) // a refusal of the full solver: nothing to say here
      {
      }
      if(pending > 0 && !server.quiet)
        std::printf("a page closed while its exact answer was being computed: refinement stopped with %d of %d "
                    "constraints not pulled back\n",
                    pending, session.constraints()),
            std::fflush(stdout);
    }
  } farewell{session, server};
  const Send send = [&ws](const Outgoing& message) {
    ws.binary(message.binary);
    ws.write(asio::buffer(message.data));
  };
  const std::size_t limit = server.model->limits().max_message_bytes;
  beast::flat_buffer buffer;
  for(;;)
  {
    // While an exact answer is being computed, and no message of the page waits, send it
    // when ready (the page sees the reduced field at once and the exact one moments later).
    // A page that went away ends the session at once: its refinement stops and what it
    // held is freed, instead of pull-backs being computed for nobody.
    while(session.refining() && ws.next_layer().available() == 0)
    {
      if(peer_has_closed(ws.next_layer())) return;
      session.poll(send, std::chrono::milliseconds(5));
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
    if(oversized) session.refuse_oversized(received, send);
    else if(!ws.got_text()) session.refuse_binary(received, send);
    else session.handle_text(beast::buffers_to_string(buffer.data()), send);
  }
}

void serve_connection(tcp::socket socket, Server& server)
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
      std::unique_ptr<Stall_watchdog> watchdog = std::make_unique<Stall_watchdog>(socket, server.stall_timeout);
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
      if(websocket::is_upgrade(request))
      {
        if(request.target() != "/ws")
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

int serve_command(const Arguments& args)
{
  Command_line command(
      "tvf serve <mesh> [--basis FILE.tvfb] [-n N] [-d D] [--port P] [--bind ADDRESS]",
      "Starts the interactive field editor: a local web server that serves the editor page and answers\n"
      "constraint edits with the new field (tangent vector field splines in a spectral basis: the\n"
      "reduced solver, and the full-resolution one on request).  Open the address it prints in a browser.\n"
      "The basis is loaded from --basis if that file exists, else computed (the N lowest eigenfields,\n"
      "with progress on the page) and saved there, so the precomputation is done once.  The page also\n"
      "designs n-direction fields (line fields, cross fields, ...): the basis of n-fields (N elements) is\n"
      "made when a page first asks for its n, loaded from or saved to FILE.n<n>.tvfn beside --basis.\n"
      "Stop with Ctrl-C.");
  command.positional("mesh", "the mesh file");
  command.group("basis").add_options()
    ("basis", po::value<std::string>()->value_name("FILE"), "the basis: loaded if the file exists, else computed and saved")
    ("eigenfields,n", po::value<int>()->default_value(300)->value_name("N"), "eigenfields to compute if there is no basis file")
    ("size,d", po::value<int>()->value_name("D"), "basis size a new session starts with (default: all)");
  command.group("server").add_options()
    ("port", po::value<int>()->default_value(8080)->value_name("P"), "TCP port (0: any free port)")
    ("bind", po::value<std::string>()->default_value("127.0.0.1")->value_name("ADDRESS"),
     "address to listen on (the default serves this machine only)")
    ("web-root", po::value<std::string>()->value_name("DIR"), "directory of the page (default: the one built with tvf)")
    ("max-connections", po::value<int>()->default_value(16)->value_name("N"), "connections served at once")
    ("stall-timeout", po::value<int>()->default_value(20)->value_name("S"),
     "seconds a request or message may take to arrive once begun; a client that stalls longer is disconnected");
  if(!command.parse(args)) return 0; // --help
  const int port = command.get<int>("port");
  if(port < 0 || port > 65535) throw Usage_error("'--port' must lie in [0, 65535]");
  const int eigenfields = command.get<int>("eigenfields");
  if(eigenfields <= 0) throw Usage_error("'--eigenfields' must be positive");
  const int size = command.has("size") ? command.get<int>("size") : 0;
  if(command.has("size") && size <= 0) throw Usage_error("'--size' must be positive");
  const int max_connections = command.get<int>("max-connections");
  if(max_connections <= 0) throw Usage_error("'--max-connections' must be positive");
  const int stall_timeout = command.get<int>("stall-timeout");
  if(stall_timeout <= 0) throw Usage_error("'--stall-timeout' must be positive");
  std::string basis_path = command.has("basis") ? command.get<std::string>("basis") : std::string();
  if(!basis_path.empty() && extension(basis_path) != "tvfb")
    throw Usage_error("the basis file '" + basis_path + "' should end in .tvfb");
  beast::error_code error;
  const asio::ip::address address = asio::ip::make_address(command.get<std::string>("bind"), error);
  if(error) throw Usage_error("'--bind': '" + command.get<std::string>("bind") + "' is not an IP address");

  const Tool_mesh mesh(command.positional_value(), command.mollify());
  if(!basis_path.empty() && !std::ifstream(basis_path) && eigenfields > 2 * mesh.number_of_faces())
    throw Tool_error("the mesh has only " + std::to_string(2 * mesh.number_of_faces()) + " eigenfields");
  auto hodge = std::make_shared<TVF::Hodge_solver>(mesh.shared_matrices());
  std::string name = mesh.path();
  name = name.substr(name.find_last_of('/') + 1);
  auto model = std::make_shared<Editor_model>(mesh.shared_matrices(), hodge, name, mesh.bounding_box_diagonal(), size,
                                              Editor_limits());

  // n-field bases: beside the basis file (FILE.n4.tvfn), loaded if there, else computed and saved.
  model->set_n_field_basis_source([basis_path, eigenfields](std::shared_ptr<const TVF::N_field_operators> ops,
                                                            const std::function<void(const std::string&, double)>& progress) {
    const std::string path = basis_path.empty() ? std::string()
                                                : basis_path.substr(0, basis_path.size() - 5) + ".n" +
                                                      std::to_string(ops->n()) + ".tvfn";
    if(!path.empty() && std::ifstream(path))
    {
      progress("loading the basis of n-fields " + path, 0);
      return std::make_shared<const TVF::N_field_basis>(TVF::N_field_basis::load(ops, path));
    }
    TVF::Basis_options options;
    options.progress = [&progress](const TVF::Spectral_progress& p) {
      progress("computing the basis of n-fields: " + p.stage, p.fraction);
    };
    const int count = std::min(eigenfields + eigenfields % 2, 2 * ops->mesh().number_of_faces());
    auto basis = std::make_shared<const TVF::N_field_basis>(ops, count, options);
    if(!path.empty())
    {
      progress("saving the basis of n-fields to " + path, 1);
      basis->save(path);
    }
    return basis;
  });

  Server server;
  server.model = model;
  server.web_root = command.has("web-root") ? command.get<std::string>("web-root") : std::string(TVF_EDITOR_DIST_DIR);
  server.max_connections = max_connections;
  server.stall_timeout = std::chrono::seconds(stall_timeout);
  server.quiet = command.quiet();
  if(!std::ifstream(server.web_root + "/index.html"))
    std::fprintf(stderr, "tvf: warning: no editor page in '%s' (built with npm; see --web-root)\n",
                 server.web_root.c_str());

  std::signal(SIGPIPE, SIG_IGN); // a page that vanishes mid-write ends its session, not the server
  asio::io_context io;
  tcp::acceptor acceptor(io);
  try
  {
    const tcp::endpoint endpoint(address, static_cast<unsigned short>(port));
    acceptor.open(endpoint.protocol());
    acceptor.set_option(asio::socket_base::reuse_address(true));
    acceptor.bind(endpoint);
    acceptor.listen();
  }
  catch(const boost::system::system_error& e)
  {
    throw Tool_error("cannot listen on " + command.get<std::string>("bind") + ":" + std::to_string(port) + ": " +
                     e.code().message());
  }

  // The basis: loaded or computed in the background, so that the page can show progress.
  const bool quiet = command.quiet();
  std::thread([model, hodge, basis_path, eigenfields, quiet] {
    try
    {
      std::shared_ptr<const TVF::Eigenfield_basis> basis;
      if(!basis_path.empty() && std::ifstream(basis_path))
      {
        model->set_progress("loading the basis " + basis_path, 0);
        basis = std::make_shared<const TVF::Eigenfield_basis>(TVF::Eigenfield_basis::load(hodge, basis_path));
      }
      else
      {
        TVF::Basis_options options;
        options.progress = [&model](const TVF::Spectral_progress& p) {
          model->set_progress("computing the basis: " + p.stage, p.fraction);
        };
        basis = std::make_shared<const TVF::Eigenfield_basis>(hodge, TVF::Basis_request::lowest(eigenfields), options);
        if(!basis_path.empty())
        {
          model->set_progress("saving the basis to " + basis_path, 1);
          basis->save(basis_path);
        }
      }
      model->set_basis(basis);
      if(!quiet) std::printf("basis ready: %d eigenfields\n", basis->size()), std::fflush(stdout);
    }
    catch(const std::exception& e)
    {
      model->set_failure(one_line(e.what()));
      std::fprintf(stderr, "tvf: error: the basis: %s\n", one_line(e.what()).c_str());
    }
  }).detach();

  const tcp::endpoint bound = acceptor.local_endpoint();
  // Always printed (also with --quiet): scripts and tests read the port from it.
  std::printf("listening on http://%s:%d/\n", bound.address().to_string().c_str(), int(bound.port()));
  std::fflush(stdout);
  for(;;)
  {
    tcp::socket socket(io);
    acceptor.accept(socket, error);
    if(error) continue;
    if(server.connections.load() >= server.max_connections)
    {
      socket.close(error); // refused: too many pages at once
      continue;
    }
    ++server.connections;
    std::thread([s = std::move(socket), &server]() mutable { serve_connection(std::move(s), server); }).detach();
  }
}

} // namespace tvf_tool
