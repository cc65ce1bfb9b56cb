// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "fuzz_support.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <unistd.h>
#include <vector>

// UBSan's options unless UBSAN_OPTIONS says otherwise: every report ends the run (libFuzzer
// then keeps the input), except those ubsan.supp silences in a library's headers.
extern "C" const char* __ubsan_default_options()
{
  return "halt_on_error=1:print_stacktrace=1:suppressions=" TVF_UBSAN_SUPPRESSIONS;
}

namespace tvf_fuzz {

std::shared_ptr<const TVF::Operator_matrices> torus_operators()
{
  static const std::shared_ptr<const TVF::Operator_matrices> operators = [] {
    const int around = 8, tube = 5;
    const double pi = std::acos(-1.0);
    std::vector<TVF::Intrinsic_mesh::Point> points;
    for(int i = 0; i < around; ++i)
      for(int j = 0; j < tube; ++j)
      {
        const double u = 2 * pi * i / around, v = 2 * pi * j / tube, r = 2 + 0.7 * std::cos(v);
        points.push_back({{r * std::cos(u), r * std::sin(u), 0.7 * std::sin(v)}});
      }
    const auto vertex = [&](int i, int j) { return (i % around) * tube + (j % tube); };
    std::vector<std::array<int, 3>> faces;
    for(int i = 0; i < around; ++i)
      for(int j = 0; j < tube; ++j)
      {
        faces.push_back({{vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)}});
        faces.push_back({{vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)}});
      }
    auto mesh = std::make_shared<const TVF::Intrinsic_mesh>(std::move(points), faces);
    return std::make_shared<const TVF::Operator_matrices>(mesh);
  }();
  return operators;
}

std::shared_ptr<TVF::Hodge_solver> torus_hodge()
{
  static const std::shared_ptr<TVF::Hodge_solver> hodge = std::make_shared<TVF::Hodge_solver>(torus_operators());
  return hodge;
}

std::shared_ptr<const TVF::Eigenfield_basis> torus_basis()
{
  static const std::shared_ptr<const TVF::Eigenfield_basis> basis =
      std::make_shared<const TVF::Eigenfield_basis>(torus_hodge(), TVF::Basis_request::lowest(16));
  return basis;
}

std::shared_ptr<const TVF::N_field_operators> torus_n_field_operators(int n)
{
  static std::mutex mutex;
  static std::map<int, std::shared_ptr<const TVF::N_field_operators>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto& operators = cache[n];
  if(!operators) operators = std::make_shared<const TVF::N_field_operators>(torus_operators(), n);
  return operators;
}

std::shared_ptr<const TVF::N_field_basis> torus_n_field_basis()
{
  static const std::shared_ptr<const TVF::N_field_basis> basis =
      std::make_shared<const TVF::N_field_basis>(torus_n_field_operators(4), 16);
  return basis;
}

const tvf_tool::Tool_mesh& torus_tool_mesh()
{
  static const std::unique_ptr<tvf_tool::Tool_mesh> mesh = [] {
    tvf_tool::set_quiet(true);
    const TVF::Intrinsic_mesh& m = torus_operators()->mesh();
    std::string off = "OFF\n" + std::to_string(m.number_of_vertices()) + " " + std::to_string(m.number_of_faces()) + " 0\n";
    char line[128];
    for(int v = 0; v < m.number_of_vertices(); ++v)
    {
      std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", m.position(v)[0], m.position(v)[1], m.position(v)[2]);
      off += line;
    }
    for(int f = 0; f < m.number_of_faces(); ++f)
    {
      const auto& c = m.face_vertices(f);
      off += "3 " + std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]) + "\n";
    }
    const std::string path =
        input_file(reinterpret_cast<const std::uint8_t*>(off.data()), off.size(), "torus", "off");
    return std::make_unique<tvf_tool::Tool_mesh>(path, false);
  }();
  return *mesh;
}

std::string input_file(const std::uint8_t* data, std::size_t size, const std::string& name,
                       const std::string& extension)
{
  static const std::string folder = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/tvf-fuzz-XXXXXX";
    if(!mkdtemp(&pattern[0])) fail("cannot make a temporary folder");
    return pattern;
  }();
  const std::string path = folder + "/" + name + "." + extension;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if(!out) fail("cannot write " + path);
  return path;
}

void fail(const std::string& what)
{
  std::fprintf(stderr, "tvf fuzz: %s\n", what.c_str());
  std::abort();
}

} // namespace tvf_fuzz
