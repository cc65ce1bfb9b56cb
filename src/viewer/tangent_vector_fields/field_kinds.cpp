// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "field_kinds.h"
#include "field_session.h"

namespace tvf_viewer {

namespace {

class Field_kind : public Session_kind
{
public:
  Field_kind(std::shared_ptr<const Field_model> model, std::string name, int start_n)
    : model_(std::move(model)), name_(std::move(name)), start_n_(start_n)
  {}
  std::string name() const override { return name_; }
  std::unique_ptr<Session> open() const override { return std::make_unique<Field_session>(model_, name_, start_n_); }

private:
  std::shared_ptr<const Field_model> model_;
  std::string name_;
  int start_n_;
};

} // namespace

void add_field_kinds(Session_kinds& kinds, std::shared_ptr<const Field_model> model)
{
  kinds.add(std::make_shared<Field_kind>(model, "vector_field", 1));
  kinds.add(std::make_shared<Field_kind>(model, "n_field", 4));
}

} // namespace tvf_viewer
