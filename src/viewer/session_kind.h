// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The seam between the viewer's server (server.h: HTTP, WebSocket, limits, access checks) and
// the systems it shows.  A system plugs in as one or more session kinds; every WebSocket
// connection holds one session of the kind its `hello` names (doc/viewer/protocol.md).  The
// server knows nothing of fields: it hands each complete text message to the session and
// sends what comes back.

#ifndef TVF_VIEWER_SESSION_KIND_H
#define TVF_VIEWER_SESSION_KIND_H

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tvf_viewer {

/// A message to the page: JSON text, or a binary message (header and arrays).
struct Outgoing
{
  bool binary = false;
  std::string data;
};
typedef std::function<void(const Outgoing&)> Send;

/// One page's session.  Called from the connection's thread only.
class Session
{
public:
  virtual ~Session() = default;
  /// Answers a complete text message (no larger than the server's message limit); bad messages
  /// get an `error` answer.  Throws only if `send` throws (the connection dropped).
  virtual void handle_text(const std::string& text, const Send& send) = 0;
  /// Work the session finishes unasked (an exact answer after a reduced one): while this is
  /// true and no message of the page waits, the server calls `poll`.
  virtual bool refining() { return false; }
  virtual void poll(const Send&, std::chrono::milliseconds) {}
  /// A line for the console when the page goes away (empty: nothing to say).
  virtual std::string farewell() { return std::string(); }
};

/// A kind of session: a name the page's `hello` gives, and a way to open a session.
class Session_kind
{
public:
  virtual ~Session_kind() = default;
  virtual std::string name() const = 0;
  virtual std::unique_ptr<Session> open() const = 0;
};

/// The kinds a server offers; the first is the one a `hello` without `kind` gets.
class Session_kinds
{
public:
  void add(std::shared_ptr<const Session_kind> kind) { kinds_.push_back(std::move(kind)); }
  const std::vector<std::shared_ptr<const Session_kind>>& all() const { return kinds_; }

  /// The session for a connection's first message: of the kind its `hello` names, else of the
  /// first kind (which then answers the message, whatever it is, as its own).  Null, with the
  /// `error` message to send in `refusal`, if the `hello` names a kind not offered.
  std::unique_ptr<Session> open_for(const std::string& first_message, Outgoing& refusal) const;

private:
  std::vector<std::shared_ptr<const Session_kind>> kinds_;
};

} // namespace tvf_viewer

#endif
