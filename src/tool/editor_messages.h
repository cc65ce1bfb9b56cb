// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The editor's messages (doc/editor_protocol.md): JSON text out, the binary messages with
// arrays, and the checked members of the page's JSON in.  Shared by the session and the model.

#ifndef TVF_TOOL_EDITOR_MESSAGES_H
#define TVF_TOOL_EDITOR_MESSAGES_H

#include "editor_session.h"

#include <CGAL/Tangent_vector_fields/Spline_solver.h>
#include <CGAL/Tangent_vector_fields/internal/constraint_json.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

namespace tvf_tool {

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

/// A message being answered: its JSON, its request id (echoed), the way back.
struct Editor_session::Request
{
  Json tree;
  std::string type;
  bool has_id = false;
  long long id = 0;
  Clock::time_point received;
  const Send* send = nullptr;
  // Time the reduced solver spent on the edit itself (a new row's pull-back in the basis),
  // added to the solve time of the field message.
  double reduced_ms = 0;

  std::string echo() const { return has_id ? ",\"request\":" + std::to_string(id) : std::string(); }
  void text(const std::string& members) const
  {
    Outgoing out;
    out.data = "{" + members + echo() + "}";
    (*send)(out);
  }
};


} // namespace tvf_tool

#endif
