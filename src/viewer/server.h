// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The viewer's server, shared by every system it shows: HTTP for the page and its files, a
// WebSocket at /ws whose connection holds one session of the kind its `hello` names
// (session_kind.h), and what keeps a local server sound: connection and message limits, a
// watchdog for stalled clients, and the access checks (access.h).  doc/viewer/protocol.md.

#ifndef TVF_VIEWER_SERVER_H
#define TVF_VIEWER_SERVER_H

#include "session_kind.h"

#include <chrono>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace tvf_viewer {

struct Server_options
{
  std::string web_root; ///< the bundled page; empty: none (the WebSocket works all the same)
  int max_connections = 16;
  std::chrono::seconds stall_timeout{20};
  std::size_t max_message_bytes = 1 << 20;
  bool quiet = false; ///< no refusals on the console
  std::vector<std::string> allowed_hosts, allowed_origins; ///< besides the local ones and the page's own
};

class Server
{
public:
  Server(Session_kinds kinds, Server_options options);
  ~Server();

  /// Binds and listens (port 0: any free port); `std::runtime_error` with the reason if it cannot.
  void listen(const std::string& address, int port);
  /// The page's address with this run's token (after `listen`).
  std::string url() const;
  /// Serves until the process ends.
  [[noreturn]] void run();

  struct State; // what the connections' threads share (server.cpp)

private:
  std::unique_ptr<State> state_;
};

} // namespace tvf_viewer

#endif
