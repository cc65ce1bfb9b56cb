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

/// A message being answered (the viewer's shared `Request`), with what the field session adds.
struct Field_session::Request : tvf_viewer::Request
{
  using tvf_viewer::Request::Request;
  // Time the reduced solver spent on the edit itself (a new row's pull-back in the basis),
  // added to the solve time of the field message.
  double reduced_ms = 0;
};

} // namespace tvf_viewer

#endif
