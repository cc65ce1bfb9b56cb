// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The .tvfc file of `tvf compress` and `tvf decompress`: a field's lowest coefficients in a
// spectral basis with the basis's signature (format in doc/tangent_vector_fields/manual.md).  Apart from the
// subcommands so that the fuzzer (test/fuzz) reads it as the tool does.

#ifndef TVF_TOOL_COEFFICIENT_FILE_H
#define TVF_TOOL_COEFFICIENT_FILE_H

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <iosfwd>
#include <string>

namespace tvf_tool {

struct Coefficient_file
{
  std::uint64_t faces = 0;
  std::array<double, 4> signature{{0, 0, 0, 0}};
  double relative_error = 0;
  Eigen::VectorXd coefficients;
};

/// \throws Tool_error if the file cannot be written.
void write_coefficient_file(const std::string& path, const Coefficient_file& file);

/// Reads at most `bytes` from `in` (the size of the file, so that a hostile count is refused
/// before anything is allocated); `path` names the file in the messages.
/// \throws Tool_error "coefficient file '<path>': <reason>" for anything but a complete, finite file.
Coefficient_file read_coefficient_file(std::istream& in, std::uint64_t bytes, const std::string& path);
/// \throws Tool_error as above, or if the file cannot be opened.
Coefficient_file read_coefficient_file(const std::string& path);

} // namespace tvf_tool

#endif
