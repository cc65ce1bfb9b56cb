// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Who may use the viewer's server.  A local server is reachable from every web page the user
// opens: a foreign page could open the WebSocket (cross-site WebSocket hijacking: it would read
// the mesh and drive the session), or reach the server under a name of its own (DNS rebinding).
// So every request must name this machine in its Host, a browser's Origin must be the page's
// own, and the WebSocket needs the token of this run, which only the printed address carries.

#ifndef TVF_VIEWER_ACCESS_H
#define TVF_VIEWER_ACCESS_H

#include <string>
#include <vector>

namespace tvf_viewer {

class Access_policy
{
public:
  /// `hosts`: names the Host header may give besides the local ones (127.0.0.1, localhost,
  /// [::1]) and `bound_address`; `origins`: origins allowed besides those of the allowed hosts
  /// on `port` (the page's own).  `token`: what the WebSocket must carry.
  Access_policy(const std::string& bound_address, int port, const std::vector<std::string>& hosts,
                const std::vector<std::string>& origins, std::string token);

  /// Each returns why a request is refused, or an empty string.  A request without Origin
  /// (not a browser's cross-site request) passes that check; the Host header is required.
  std::string check_host(const std::string& host_header) const;
  std::string check_origin(const std::string& origin_header) const;
  /// The `token` parameter of the target's query.
  std::string check_token(const std::string& target) const;

  const std::string& token() const { return token_; }

private:
  std::vector<std::string> hosts_, origins_; // lower case
  int port_;
  std::string token_;
};

/// 128 bits from the system's random source (/dev/urandom), as 32 hex digits.
std::string random_token();

/// Compares without stopping at the first difference, so that the time taken does not tell
/// how much of a guessed token is right.
bool equal_in_constant_time(const std::string& a, const std::string& b);

/// `address` as a URL's host: IPv6 addresses in brackets.
std::string url_host(const std::string& address);

} // namespace tvf_viewer

#endif
