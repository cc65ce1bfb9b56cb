// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The field sessions' WebSocket messages, without sockets: every line of the input is a text
// message to one session on the torus (what the server hands to `handle_text`), after
// a hello and a display without lines.
// Every answer must be a JSON object with a "type", or a well-formed binary message.

#include "fuzz_support.h"

#include "field_session.h"
#include "messages.h"

#include <cstring>

namespace {

std::shared_ptr<const tvf_viewer::Field_model> torus_model()
{
  static const std::shared_ptr<tvf_viewer::Field_model> model = [] {
    tvf_viewer::Field_limits limits;
    limits.max_constraints = 50;
    limits.max_strokes = 2000; // streamlines on 80 faces: small caps keep executions fast
    limits.max_n = 6;
    auto m = std::make_shared<tvf_viewer::Field_model>(tvf_fuzz::torus_operators(), tvf_fuzz::torus_hodge(), "torus",
                                                      5.4, 16, limits);
    m->set_n_field_basis_source(
        [](std::shared_ptr<const CGAL::Tangent_vector_fields::N_field_operators> operators,
           const std::function<void(const std::string&, double)>&) {
          return std::make_shared<const CGAL::Tangent_vector_fields::N_field_basis>(operators, 16);
        });
    m->set_basis(tvf_fuzz::torus_basis());
    return m;
  }();
  return model;
}

void check_answer(const tvf_viewer::Outgoing& out)
{
  if(!out.binary)
  {
    tvf_viewer::Json answer;
    try
    {
      answer = CGAL::Tangent_vector_fields::internal::parse_json(out.data, "answer");
    }
    catch(const std::exception& e)
    {
      tvf_fuzz::fail("an answer is not JSON (" + std::string(e.what()) + "): " + out.data.substr(0, 500));
    }
    if(!answer.is_object() || !answer.contains("type") || !answer["type"].is_string())
      tvf_fuzz::fail("an answer has no type: " + out.data.substr(0, 500));
    return;
  }
  std::uint32_t header = 0;
  if(out.data.size() < 4) tvf_fuzz::fail("a binary answer without a header");
  std::memcpy(&header, out.data.data(), 4);
  if(4 + std::size_t(header) > out.data.size()) tvf_fuzz::fail("a binary answer's header overruns it");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text = tvf_fuzz::input_text(data, size);
  tvf_viewer::Field_session session(torus_model());
  const tvf_viewer::Send send = check_answer;
  // A started session without lines: the default display (4000 fur strokes, 45 ms a field at
  // -O1 with ASan) would make the fuzzer 20 times slower; inputs ask for lines themselves.
  session.handle_text("{\"type\":\"hello\"}", send);
  session.handle_text("{\"type\":\"set_display\",\"lines\":\"none\"}", send);
  std::size_t start = 0;
  for(int message = 0; message < 16 && start <= text.size(); ++message)
  {
    std::size_t end = text.find('\n', start);
    if(end == std::string::npos) end = text.size();
    session.handle_text(text.substr(start, end - start), send);
    // An exact answer on its way is waited for here, as the server polls between messages.
    if(session.refining()) session.poll(send, std::chrono::milliseconds(2000));
    start = end + 1;
  }
  return 0;
}
