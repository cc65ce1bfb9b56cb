// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The viewer's messages (doc/viewer/protocol.md): JSON text out, the binary messages with
// arrays, and the checked members of the page's JSON in.  Shared by the server and every
// session kind.

#ifndef TVF_VIEWER_MESSAGES_H
#define TVF_VIEWER_MESSAGES_H

#include "session_kind.h"

#include <CGAL/Tangent_vector_fields/internal/constraint_json.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

namespace tvf_viewer {

namespace TVF = CGAL::Tangent_vector_fields;

typedef TVF::internal::Json Json;
typedef std::chrono::steady_clock Clock;

/// A message the session refuses; its text goes to the page.
class Message_error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

double milliseconds_since(Clock::time_point start);

/// A JSON string literal of `text`; bytes that are not UTF-8 become U+FFFD (JSON text is UTF-8).
std::string quote(const std::string& text);
/// All 17 digits (`null` if not finite).
std::string number(double x);
/// 6 digits: timings and sizes.
std::string short_number(double x);

template <class Range, class Format>
std::string json_array(const Range& values, Format format)
{
  std::string s = "[";
  for(const auto& v : values) s += (s.size() > 1 ? "," : "") + format(v);
  return s + "]";
}

/// One array of a binary message.
struct Array_out
{
  std::string name;
  bool is_float; // float32, else uint32
  const void* data;
  std::size_t length; // entries
};

/// `uint32 n`, `n` bytes of JSON header, zero padding to 4 bytes, then the arrays.
Outgoing binary_message(const std::string& members, const std::vector<Array_out>& arrays);

// Members of the page's messages; `Message_error` names the key.
const Json& member(const Json& tree, const char* key);
double number_member(const Json& tree, const char* key);
long long integer_member(const Json& tree, const char* key, long long lowest, long long highest);
std::string text_member(const Json& tree, const char* key);

/// A page's message being answered: its JSON, its type, its request id (echoed in every
/// answer), when it arrived, and the way back.  Session kinds share it.
struct Request
{
  Request() = default;
  /// A message arriving now, answered through `send`.
  explicit Request(const Send& to) : received(Clock::now()), send(&to) {}

  Json tree;
  std::string type;
  bool has_id = false;
  long long id = 0;
  Clock::time_point received;
  const Send* send = nullptr;

  std::string echo() const { return has_id ? ",\"request\":" + std::to_string(id) : std::string(); }
  /// Sends `{members, "request": id}`.
  void text(const std::string& members) const { (*send)(Outgoing{false, "{" + members + echo() + "}"}); }
};

/// Reads a message's JSON (strict: more than `max_bytes`, syntax, duplicate keys and nesting
/// deeper than `max_depth` refused), its request id and type into `r`; `Message_error` names
/// what is wrong.
void read_request(Request& r, const std::string& text, std::size_t max_bytes, int max_depth);

/// The `error` messages of the transport: a binary message (the page sends JSON text) and a
/// message over `limit` bytes.
Outgoing binary_refusal(std::size_t bytes);
Outgoing oversized_refusal(std::size_t bytes, std::size_t limit);

} // namespace tvf_viewer

#endif
