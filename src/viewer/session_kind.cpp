// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "session_kind.h"
#include "messages.h"

namespace tvf_viewer {

std::unique_ptr<Session> Session_kinds::open_for(const std::string& first_message, Outgoing& refusal) const
{
  if(kinds_.empty()) throw std::logic_error("a viewer server needs a session kind");
  // Only a well-formed hello with a string `kind` chooses; anything else goes to the first
  // kind's session, which answers it (an error, a pong, or its own hello).
  Json tree;
  try
  {
    tree = TVF::internal::parse_json(first_message, "not JSON", 32);
  }
  catch(const std::exception&)
  {
    return kinds_.front()->open();
  }
  if(!tree.is_object() || !tree.contains("kind") || !tree["kind"].is_string() || tree.value("type", Json()) != "hello")
    return kinds_.front()->open();
  const std::string name = tree["kind"].get<std::string>();
  std::string names;
  for(const auto& kind : kinds_)
  {
    if(kind->name() == name) return kind->open();
    names += (names.empty() ? "" : ", ") + kind->name();
  }
  const auto request = tree.find("request");
  const std::string echo = request != tree.end() && request->is_number_unsigned()
                               ? ",\"request\":" + std::to_string(request->get<unsigned long long>())
                               : std::string();
  refusal = {false, "{\"type\":\"error\",\"message\":" +
                        quote("unknown session kind " + quote(name.substr(0, 64)) + " (this server offers " + names + ")") +
                        echo + "}"};
  return nullptr;
}

} // namespace tvf_viewer
