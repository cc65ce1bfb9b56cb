// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "access.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <stdexcept>

namespace tvf_viewer {

namespace {

std::string lower(std::string s)
{
  for(char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A header value as it may appear in a refusal and on the console: printable, and short.
std::string shown(const std::string& value)
{
  std::string out;
  for(char c : value.substr(0, 100)) out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return value.size() > 100 ? out + "..." : out;
}

bool contains(const std::vector<std::string>& list, const std::string& s)
{
  return std::find(list.begin(), list.end(), s) != list.end();
}

} // namespace

std::string url_host(const std::string& address)
{
  return address.find(':') != std::string::npos ? "[" + address + "]" : address;
}

Access_policy::Access_policy(const std::string& bound_address, int port, const std::vector<std::string>& hosts,
                             const std::vector<std::string>& origins, std::string token)
  : port_(port), token_(std::move(token))
{
  hosts_ = {"127.0.0.1", "localhost", "[::1]", lower(url_host(bound_address))};
  for(const std::string& h : hosts) hosts_.push_back(lower(h));
  for(const std::string& h : hosts_)
  {
    origins_.push_back("http://" + h + ":" + std::to_string(port));
    if(port == 80) origins_.push_back("http://" + h);
  }
  for(const std::string& o : origins) origins_.push_back(lower(o));
}

std::string Access_policy::check_host(const std::string& host_header) const
{
  if(host_header.empty()) return "a request must name the server in its Host header";
  // name, or name:port; IPv6 addresses are in brackets.
  std::string host = lower(host_header), port;
  const std::size_t colon = host.rfind(':');
  if(colon != std::string::npos && host.find(']', colon) == std::string::npos)
  {
    port = host.substr(colon + 1);
    host.erase(colon);
  }
  if(!contains(hosts_, host) || (!port.empty() && port != std::to_string(port_)))
    return "Host " + shown(host_header) + " is not allowed (this server answers to 127.0.0.1, localhost, [::1] and " +
           "its address on port " + std::to_string(port_) + "; see --allow-host)";
  return std::string();
}

std::string Access_policy::check_origin(const std::string& origin_header) const
{
  if(origin_header.empty() || contains(origins_, lower(origin_header))) return std::string();
  return "Origin " + shown(origin_header) + " is not allowed (only the page's own; see --allow-origin)";
}

std::string Access_policy::check_token(const std::string& target) const
{
  const std::size_t query = target.find('?');
  std::string given;
  bool found = false;
  for(std::size_t start = query; start != std::string::npos && !found;)
  {
    const std::size_t end = target.find('&', start + 1);
    const std::string parameter = target.substr(start + 1, end == std::string::npos ? end : end - start - 1);
    if(parameter.compare(0, 6, "token=") == 0) given = parameter.substr(6), found = true;
    start = end;
  }
  if(!found) return "the WebSocket needs the token of the address tvf serve printed (/ws?token=...)";
  if(!equal_in_constant_time(given, token_)) return "wrong token (use the address tvf serve printed)";
  return std::string();
}

std::string random_token()
{
  unsigned char bytes[16];
  std::ifstream random("/dev/urandom", std::ios::binary);
  if(!random.read(reinterpret_cast<char*>(bytes), sizeof bytes))
    throw std::runtime_error("cannot read /dev/urandom for the access token");
  static const char digits[] = "0123456789abcdef";
  std::string token;
  for(unsigned char b : bytes) token += {digits[b >> 4], digits[b & 15]};
  return token;
}

bool equal_in_constant_time(const std::string& a, const std::string& b)
{
  // The length of the token is no secret (32 hex digits); its digits are.
  if(a.size() != b.size()) return false;
  volatile unsigned char difference = 0;
  for(std::size_t i = 0; i < a.size(); ++i) difference = difference | static_cast<unsigned char>(a[i] ^ b[i]);
  return difference == 0;
}

} // namespace tvf_viewer
