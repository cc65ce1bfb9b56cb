// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "messages.h"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace tvf_viewer {

double milliseconds_since(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// --- JSON out -----------------------------------------------------------------------------------

namespace {

// The length of the well-formed UTF-8 sequence at `text[i]` (RFC 3629: no overlong forms, no
// surrogates, at most U+10FFFF), or 0.
std::size_t utf8_sequence_length(const std::string& text, std::size_t i)
{
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = byte(i);
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xbf; // the range of the second byte
  if(c >= 0xc2 && c <= 0xdf) length = 2;
  else if(c >= 0xe0 && c <= 0xef) length = 3, low = c == 0xe0 ? 0xa0 : 0x80, high = c == 0xed ? 0x9f : 0xbf;
  else if(c >= 0xf0 && c <= 0xf4) length = 4, low = c == 0xf0 ? 0x90 : 0x80, high = c == 0xf4 ? 0x8f : 0xbf;
  else return 0;
  if(i + length > text.size() || byte(i + 1) < low || byte(i + 1) > high) return 0;
  for(std::size_t k = 2; k < length; ++k)
    if(byte(i + k) < 0x80 || byte(i + k) > 0xbf) return 0;
  return length;
}

} // namespace

std::string quote(const std::string& text)
{
  std::string q = "\"";
  for(std::size_t i = 0; i < text.size(); ++i)
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if(c == '"' || c == '\\') q += '\\', q += char(c);
    else if(c == '\n') q += "\\n";
    else if(c < 0x20)
    {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
      q += buffer;
    }
    else if(c < 0x80) q += char(c);
    else if(const std::size_t length = utf8_sequence_length(text, i))
    {
      q.append(text, i, length);
      i += length - 1;
    }
    else
      q += "\\ufffd"; // a byte of no UTF-8 character (e.g. a page's bad message quoted in an error): JSON needs UTF-8
  }
  return q + "\"";
}

std::string number(double x)
{
  if(!std::isfinite(x)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string short_number(double x) // timings and sizes: 6 digits are plenty
{
  if(!std::isfinite(x)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

// --- binary messages ----------------------------------------------------------------------------

/// `uint32 n`, `n` bytes of JSON header, zero padding to 4 bytes, then the arrays.
Outgoing binary_message(const std::string& members, const std::vector<Array_out>& arrays)
{
  std::string header = "{" + members + ",\"arrays\":[";
  for(std::size_t i = 0; i < arrays.size(); ++i)
    header += (i ? "," : "") + std::string("{\"name\":") + quote(arrays[i].name) + ",\"type\":\"" +
              (arrays[i].is_float ? "float32" : "uint32") + "\",\"length\":" + std::to_string(arrays[i].length) + "}";
  header += "]}";
  Outgoing out;
  out.binary = true;
  const std::size_t padded = (4 + header.size() + 3) / 4 * 4;
  std::size_t size = padded;
  for(const Array_out& a : arrays) size += 4 * a.length;
  out.data.reserve(size);
  const std::uint32_t n = static_cast<std::uint32_t>(header.size());
  const unsigned char length_bytes[4] = {static_cast<unsigned char>(n), static_cast<unsigned char>(n >> 8),
                                         static_cast<unsigned char>(n >> 16), static_cast<unsigned char>(n >> 24)};
  out.data.append(reinterpret_cast<const char*>(length_bytes), 4);
  out.data += header;
  out.data.append(padded - out.data.size(), '\0');
  static_assert(sizeof(float) == 4, "float32 arrays");
  for(const Array_out& a : arrays) out.data.append(static_cast<const char*>(a.data), 4 * a.length); // x86: little-endian
  return out;
}

// --- JSON in ------------------------------------------------------------------------------------

const Json& member(const Json& tree, const char* key)
{
  const auto it = tree.find(key);
  if(it == tree.end()) throw Message_error(std::string("missing \"") + key + "\"");
  return *it;
}

double number_member(const Json& tree, const char* key)
{
  const Json& node = member(tree, key);
  if(!node.is_number()) throw Message_error(std::string("\"") + key + "\" must be a number");
  const double x = node.get<double>();
  if(!std::isfinite(x)) throw Message_error(std::string("\"") + key + "\" is not finite");
  return x;
}

long long integer_member(const Json& tree, const char* key, long long lowest, long long highest)
{
  const double x = number_member(tree, key);
  if(x != std::floor(x) || x < double(lowest) || x > double(highest))
    throw Message_error(std::string("\"") + key + "\" must be an integer in [" + std::to_string(lowest) + ", " +
                        std::to_string(highest) + "]");
  return static_cast<long long>(x);
}

std::string text_member(const Json& tree, const char* key)
{
  const Json& node = member(tree, key);
  if(!node.is_string()) throw Message_error(std::string("\"") + key + "\" must be a string");
  return node.get<std::string>();
}

namespace {

std::string oversized_reason(std::size_t bytes, std::size_t limit)
{
  return "message of " + std::to_string(bytes) + " bytes or more exceeds the limit of " + std::to_string(limit) +
         " bytes";
}

} // namespace

void read_request(Request& r, const std::string& text, std::size_t max_bytes, int max_depth)
{
  if(text.size() > max_bytes) throw Message_error(oversized_reason(text.size(), max_bytes));
  r.tree = TVF::internal::parse_json(text, "not JSON", max_depth);
  if(!r.tree.is_object()) throw Message_error("a message must be a JSON object");
  if(r.tree.contains("request"))
  {
    r.id = integer_member(r.tree, "request", 0, (1LL << 53));
    r.has_id = true;
  }
  r.type = text_member(r.tree, "type");
}

Outgoing binary_refusal(std::size_t bytes)
{
  return {false, "{\"type\":\"error\",\"message\":" +
                     quote("binary messages are not accepted (" + std::to_string(bytes) + " bytes): send JSON text") +
                     "}"};
}

Outgoing oversized_refusal(std::size_t bytes, std::size_t limit)
{
  return {false, "{\"type\":\"error\",\"message\":" + quote(oversized_reason(bytes, limit)) + "}"};
}

} // namespace tvf_viewer
