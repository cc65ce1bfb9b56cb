// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the server suites share: `tvf serve` as a process, a WebSocket client that decodes the
// binary messages, and a fixture with one server on CGAL's sphere for the whole suite.

#ifndef TVF_TEST_EDITOR_SERVER_TEST_SUPPORT_H
#define TVF_TEST_EDITOR_SERVER_TEST_SUPPORT_H

#include <gtest/gtest.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read_until.hpp>
#include <boost/asio/streambuf.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <map>
#include <poll.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <utility>
#include <unistd.h>
#include <vector>


namespace server_test {


namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace asio = boost::asio;
using tcp = asio::ip::tcp;
typedef boost::property_tree::ptree Tree;

// --- the server process ---------------------------------------------------------------------------

/// Where a server listens, and the token its printed address carries.
struct Address
{
  int port = 0;
  std::string token;
};

class Server_process
{
public:
  Server_process(const std::vector<std::string>& args)
  {
    int out[2];
    if(pipe(out) != 0) throw std::runtime_error("pipe");
    pid_ = fork();
    if(pid_ == 0)
    {
      dup2(out[1], STDOUT_FILENO);
      close(out[0]);
      std::vector<char*> argv;
      for(const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
    close(out[1]);
    out_ = out[0]; // kept open so the server's later prints do not hit a closed pipe
    std::string line;
    char token[65] = "";
    if(!wait_for_line("listening on http://127.0.0.1:", line, std::chrono::seconds(60)) ||
       std::sscanf(line.c_str(), "listening on http://127.0.0.1:%d/?token=%64[0-9a-f]", &address_.port, token) != 2)
      throw std::runtime_error("the server did not start");
    address_.token = token;
  }
  ~Server_process()
  {
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
    close(out_);
  }
  int port() const { return address_.port; }
  const Address& address() const { return address_; }
  bool running() const { return waitpid(pid_, nullptr, WNOHANG) == 0; }

  /// Reads the server's output until a line containing `text` (into `line`), or until the
  /// timeout passes or the server closes its output (false).
  bool wait_for_line(const std::string& text, std::string& line, std::chrono::seconds timeout)
  {
    const auto end = std::chrono::steady_clock::now() + timeout;
    for(;;)
    {
      for(std::size_t eol; (eol = output_.find('\n')) != std::string::npos;)
      {
        line = output_.substr(0, eol);
        output_.erase(0, eol + 1);
        if(line.find(text) != std::string::npos) return true;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
      pollfd p = {out_, POLLIN, 0};
      if(left.count() <= 0 || ::poll(&p, 1, int(left.count())) <= 0) return false;
      char chunk[4096];
      const ssize_t got = ::read(out_, chunk, sizeof chunk);
      if(got <= 0) return false;
      output_.append(chunk, std::size_t(got));
    }
  }

private:
  pid_t pid_ = -1;
  Address address_;
  int out_ = -1;
  std::string output_; // read, not yet taken as lines
};

// --- a WebSocket client ---------------------------------------------------------------------------

struct Message
{
  bool binary = false;
  Tree json; // text message, or the header of a binary one
  std::string text; // the JSON text itself (numbers as the server wrote them)
  std::map<std::string, std::vector<float>> floats;
  std::map<std::string, std::vector<std::uint32_t>> integers;
  std::string type() const { return json.get<std::string>("type", ""); }
};

// The text of the object member `key` of a JSON text (as sent: its numbers stay numbers,
// which a property tree would turn into strings).
inline std::string object_member_text(const std::string& text, const std::string& key)
{
  const std::size_t start = text.find('{', text.find("\"" + key + "\":"));
  int depth = 0;
  bool in_string = false;
  for(std::size_t i = start; i < text.size(); ++i)
  {
    const char c = text[i];
    if(in_string) in_string = !(c == '"' && text[i - 1] != '\\');
    else if(c == '"') in_string = true;
    else if(c == '{') ++depth;
    else if(c == '}' && --depth == 0) return text.substr(start, i + 1 - start);
  }
  return std::string();
}

inline Message decode(bool binary, const std::string& data)
{
  Message m;
  m.binary = binary;
  m.text = binary ? std::string() : data;
  std::string header = data;
  std::size_t offset = 0;
  if(binary)
  {
    std::uint32_t n = 0;
    std::memcpy(&n, data.data(), 4);
    header = data.substr(4, n);
    offset = (4 + n + 3) / 4 * 4;
  }
  std::istringstream in(header);
  boost::property_tree::read_json(in, m.json);
  if(binary)
    for(const auto& a : m.json.get_child("arrays"))
    {
      const std::string name = a.second.get<std::string>("name");
      const std::size_t length = a.second.get<std::size_t>("length");
      if(offset + 4 * length > data.size()) throw std::runtime_error("array past the end of the message");
      if(a.second.get<std::string>("type") == "float32")
      {
        std::vector<float>& v = m.floats[name];
        v.resize(length);
        std::memcpy(v.data(), data.data() + offset, 4 * length);
      }
      else
      {
        std::vector<std::uint32_t>& v = m.integers[name];
        v.resize(length);
        std::memcpy(v.data(), data.data() + offset, 4 * length);
      }
      offset += 4 * length;
    }
  return m;
}

class Client
{
public:
  /// Upgrades to the WebSocket at /ws with the server's token, as a page of the server's own
  /// origin does.
  explicit Client(const Address& address) : ws_(io_)
  {
    tcp::resolver resolver(io_);
    asio::connect(ws_.next_layer(), resolver.resolve("127.0.0.1", std::to_string(address.port)));
    ws_.read_message_max(std::uint64_t(1) << 30);
    const std::string host = "127.0.0.1:" + std::to_string(address.port);
    ws_.set_option(websocket::stream_base::decorator(
        [host](websocket::request_type& req) { req.set(http::field::origin, "http://" + host); }));
    ws_.handshake(host, "/ws?token=" + address.token);
  }
  void send(const std::string& text)
  {
    ws_.text(true);
    ws_.write(asio::buffer(text));
  }
  void send_binary(const std::string& data)
  {
    ws_.binary(true);
    ws_.write(asio::buffer(data));
  }
  Message receive()
  {
    beast::flat_buffer buffer;
    ws_.read(buffer);
    return decode(ws_.got_binary(), beast::buffers_to_string(buffer.data()));
  }
  // The next message of `type`, skipping progress and status messages (and the preview strokes
  // sent before a field, unless asked for).
  Message expect(const std::string& type)
  {
    for(;;)
    {
      Message m = receive();
      if(m.type() == "progress" || m.type() == "status") continue;
      if(m.type() == "preview" && type != "preview") continue;
      EXPECT_EQ(m.type(), type) << (m.type() == "error" ? m.json.get<std::string>("message") : "");
      return m;
    }
  }
  std::string expect_error()
  {
    Message m = expect("error");
    return m.json.get<std::string>("message", "");
  }
  websocket::stream<tcp::socket>& stream() { return ws_; }

private:
  asio::io_context io_;
  websocket::stream<tcp::socket> ws_;
};

inline std::array<double, 3> face_vector(const Message& field, int f)
{
  const std::vector<float>& v = field.floats.at("vectors");
  return {{v[3 * f], v[3 * f + 1], v[3 * f + 2]}};
}

inline double distance(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// A unit vector along the first edge of face f of the mesh message (tangent to the face).
inline std::array<double, 3> tangent(const Message& mesh, int f)
{
  const auto& p = mesh.floats.at("positions");
  const auto& t = mesh.integers.at("triangles");
  std::array<double, 3> e;
  for(int k = 0; k < 3; ++k) e[k] = p[3 * t[3 * f + 1] + k] - p[3 * t[3 * f] + k];
  const double n = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  for(double& x : e) x /= n;
  return e;
}

inline std::string vector_constraint(int face, const std::array<double, 3>& v)
{
  std::ostringstream s;
  s.precision(17);
  s << "{\"type\":\"vector\",\"face\":" << face << ",\"vector\":[" << v[0] << "," << v[1] << "," << v[2] << "]}";
  return s.str();
}

/// A raw HTTP request to the server: the status code and the body of its answer.
inline std::pair<int, std::string> http_exchange(int port, const std::string& request)
{
  asio::io_context io;
  tcp::socket socket(io);
  socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
  asio::write(socket, asio::buffer(request));
  beast::flat_buffer buffer;
  http::response<http::string_body> response;
  http::read(socket, buffer, response);
  return {int(response.result_int()), response.body()};
}

inline std::string sphere_path() { return std::string(TVF_CGAL_DATA_DIR) + "/meshes/sphere.off"; }

class Server_test : public ::testing::Test
{
public:
  static void SetUpTestSuite()
  {
    server = new Server_process({TVF_TOOL, "serve", sphere_path(), "-n", "60", "--port", "0", "--stall-timeout", "2"});
  }
  static void TearDownTestSuite() { delete server; }
  inline static Server_process* server = nullptr;

  // A session after hello: the info, mesh and first field.
  struct Session
  {
    Client client;
    Message info, mesh, field;
    explicit Session(const Address& address) : client(address)
    {
      client.send("{\"type\":\"hello\",\"request\":1}");
      info = client.expect("info");
      mesh = client.expect("mesh");
      field = client.expect("field");
    }
  };
};


} // namespace server_test

#endif
