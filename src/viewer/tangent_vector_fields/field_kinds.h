// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Chapters 1 and 2 in the viewer: two session kinds over one shared model (the mesh and its
// bases).  "vector_field" starts designing tangent vector fields, "n_field" cross fields
// (n = 4); both are field sessions, so `set_n` moves either between the two designs.

#ifndef TVF_VIEWER_FIELD_KINDS_H
#define TVF_VIEWER_FIELD_KINDS_H

#include "session_kind.h"

#include <memory>

namespace tvf_viewer {

class Field_model;

/// Adds "vector_field" (first: the default of a `hello` without `kind`) and "n_field".
void add_field_kinds(Session_kinds& kinds, std::shared_ptr<const Field_model> model);

} // namespace tvf_viewer

#endif
