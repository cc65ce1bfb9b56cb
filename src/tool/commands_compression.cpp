// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Subcommands compress and decompress: a field's lowest coefficients in a spectral basis,
// stored in a .tvfc file with the basis's signature (so that a file is decompressed only with
// the basis it was made with).  No Surface_mesh here (see tool_mesh.cpp).

#include "coefficient_file.h"
#include "tool.h"

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace tvf_tool {

namespace {

std::uint64_t splitmix(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// A number in [-1, 1] that depends only on (a, b).
double hashed_unit(std::uint64_t a, std::uint64_t b)
{
  return static_cast<double>(splitmix(splitmix(a) ^ (b * 0x2545f4914f6cdd1dull)) >> 11) * 0x1.0p-52 - 1;
}

// Four weighted sums of the coefficients of a fixed pseudo-random field in the first
// `k` elements: they identify the basis up to roundoff (a different basis, another
// order or a flipped sign changes them), so a .tvfc file is decoded only with the
// basis it was made with.
std::array<double, 4> basis_signature(const TVF::Eigenfield_basis& b, int k, double* scale)
{
  const int nf = b.operators().mesh().number_of_faces();
  Eigen::VectorXd probe(2 * nf);
  for(int i = 0; i < 2 * nf; ++i) probe[i] = hashed_unit(1, static_cast<std::uint64_t>(i));
  const Eigen::VectorXd a = b.coefficients(probe).head(k);
  std::array<double, 4> s{{0, 0, 0, 0}};
  for(int m = 0; m < 4; ++m)
    for(int j = 0; j < k; ++j) s[m] += hashed_unit(2 + m, static_cast<std::uint64_t>(j)) * a[j];
  if(scale) *scale = a.norm();
  return s;
}

} // namespace

int compress_command(const Arguments& args)
{
  Command_line command("tvf compress <mesh> --basis FILE (--field FILE | --field-ply NAME) (-k K | --max-error E) "
                       "-o FILE.tvfc",
                       "Keeps the K lowest coefficients of a field in a spectral basis and writes them to a small\n"
                       "binary .tvfc file (format in doc/tangent_vector_fields/manual.md); prints the ratio and the relative L2 error.");
  command.positional("mesh", "the mesh file");
  add_basis_option(command, true);
  add_field_options(command);
  command.group("compression").add_options()
    ("keep,k", po::value<int>()->value_name("K"), "how many coefficients to keep (at most the basis size)")
    ("max-error", po::value<double>()->value_name("E"),
     "instead: the fewest coefficients whose relative L2 error is at most E");
  command.group("output").add_options()("output,o", po::value<std::string>()->value_name("FILE"),
                                        "the coefficient file (.tvfc)");
  if(!command.parse(args)) return 0; // --help
  command.require("basis");
  command.exactly_one({"keep", "max-error"});
  command.require("output");
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const Eigen::VectorXd v = read_input_field(command, mesh);
  const auto basis = load_basis(mesh, command.get<std::string>("basis"));
  const TVF::Eigenfield_basis& b = *basis;
  const double nv = field_norm(mesh.matrices(), v);
  if(!(nv > 0)) throw Tool_error("the field is zero: nothing to compress");

  int k = 0;
  const Eigen::VectorXd a = b.coefficients(v);
  if(command.has("keep"))
  {
    k = command.get<int>("keep");
    if(k <= 0 || k > b.size())
      throw Tool_error("-k must lie in [1, " + std::to_string(b.size()) + "] (the basis size), not " + std::to_string(k));
  }
  else
  {
    const double target = command.get<double>("max-error");
    if(!(target > 0 && target < 1)) throw Usage_error("'--max-error' must lie in (0, 1)");
    // |v - v_k|^2 = |v|^2 - sum_{j<k} a_j^2 (orthonormal basis).
    double kept = 0;
    for(k = 0; k < b.size(); ++k)
    {
      if(std::sqrt(std::max(0., 1 - kept / (nv * nv))) <= target) break;
      kept += a[k] * a[k];
    }
    if(std::sqrt(std::max(0., 1 - kept / (nv * nv))) > target)
      throw Tool_error("even all " + std::to_string(b.size()) + " coefficients leave a relative error of " +
                       std::to_string(std::sqrt(std::max(0., 1 - kept / (nv * nv)))) + ": use a larger basis");
    k = std::max(k, 1);
  }
  const TVF::Compressed_fields compressed = b.compress(v, k);
  Coefficient_file file;
  file.faces = static_cast<std::uint64_t>(mesh.number_of_faces());
  file.signature = basis_signature(b, k, nullptr);
  file.relative_error = compressed.relative_errors[0];
  file.coefficients = compressed.coefficients.col(0);
  const std::string output = command.get<std::string>("output");
  write_coefficient_file(output, file);
  const std::size_t bytes = 80 + 8 * static_cast<std::size_t>(k);
  say("compressed %d frame coordinates to %d coefficients: ratio %.1f, %.3g bits per face\n", 2 * mesh.number_of_faces(),
      k, compressed.ratio, compressed.bits_per_face);
  say("  relative L2 error %.3g; %s: %zu bytes\n", file.relative_error, output.c_str(), bytes);
  return 0;
}

int decompress_command(const Arguments& args)
{
  Command_line command("tvf decompress <mesh> --basis FILE --coefficients FILE.tvfc -o FILE",
                       "Rebuilds a field from the coefficients written by 'tvf compress', with the same basis.");
  command.positional("mesh", "the mesh file");
  add_basis_option(command, true);
  command.group("input").add_options()("coefficients,c", po::value<std::string>()->value_name("FILE"),
                                       "the coefficient file (.tvfc)");
  add_output_options(command, "the field", "decompressed");
  if(!command.parse(args)) return 0; // --help
  command.require("basis");
  command.require("coefficients");
  command.require("output");
  const Tool_mesh mesh(command.positional_value(), command.mollify());
  const std::string path = command.get<std::string>("coefficients");
  const Coefficient_file file = read_coefficient_file(path);
  if(file.faces != static_cast<std::uint64_t>(mesh.number_of_faces()))
    throw Tool_error("coefficient file '" + path + "' is for a mesh of " + std::to_string(file.faces) + " faces, '" +
                     mesh.path() + "' has " + std::to_string(mesh.number_of_faces()));
  const auto basis = load_basis(mesh, command.get<std::string>("basis"));
  const int k = static_cast<int>(file.coefficients.size());
  if(k > basis->size())
    throw Tool_error("coefficient file '" + path + "' has " + std::to_string(k) + " coefficients, the basis only " +
                     std::to_string(basis->size()) + " elements");
  double scale = 0;
  const std::array<double, 4> signature = basis_signature(*basis, k, &scale);
  for(int m = 0; m < 4; ++m)
    if(!(std::abs(signature[m] - file.signature[m]) <= 1e-6 * scale))
      throw Tool_error("coefficient file '" + path + "' was made with another basis (its first " + std::to_string(k) +
                       " elements differ from those of '" + command.get<std::string>("basis") + "')");
  TVF::Compressed_fields compressed;
  compressed.coefficients = file.coefficients;
  const Eigen::VectorXd x = basis->decompress(compressed).col(0);
  say("decompressed %d coefficients (relative L2 error at compression: %.3g)\n", k, file.relative_error);
  write_outputs(command, mesh, x);
  return 0;
}

} // namespace tvf_tool
