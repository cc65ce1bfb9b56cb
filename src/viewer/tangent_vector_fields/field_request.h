// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A message of the field session being answered, shared by the files of the session.

#ifndef TVF_VIEWER_FIELD_REQUEST_H
#define TVF_VIEWER_FIELD_REQUEST_H

#include "field_session.h"
#include "messages.h"

#include <string>

namespace tvf_viewer {

/// A message being answered: its JSON, its request id (echoed), the way back.
struct Field_session::Request
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

} // namespace tvf_viewer

#endif
