// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "coefficient_file.h"

#include "tool.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

namespace tvf_tool {

namespace {

const char coefficient_magic[8] = {'T', 'V', 'F', 'C', 'O', 'E', 'F', 'S'};
const char coefficient_end[8] = {'T', 'V', 'F', 'C', 'E', 'N', 'D', '\0'};
const std::uint32_t coefficient_version = 1;
const std::uint32_t byte_order_mark = 0x01020304u;

template <class T>
void put_binary(std::ostream& out, const T& value)
{
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <class T>
bool get_binary(std::istream& in, T& value)
{
  return static_cast<bool>(in.read(reinterpret_cast<char*>(&value), sizeof(T)));
}

} // namespace

void write_coefficient_file(const std::string& path, const Coefficient_file& file)
{
  std::ofstream out(path, std::ios::binary);
  if(!out) throw Tool_error("cannot open '" + path + "' for writing: " + std::strerror(errno));
  out.write(coefficient_magic, 8);
  put_binary(out, coefficient_version);
  put_binary(out, byte_order_mark);
  put_binary(out, file.faces);
  put_binary(out, static_cast<std::uint32_t>(file.coefficients.size()));
  put_binary(out, std::uint32_t(1)); // fields
  for(double s : file.signature) put_binary(out, s);
  put_binary(out, file.relative_error);
  out.write(reinterpret_cast<const char*>(file.coefficients.data()),
            static_cast<std::streamsize>(sizeof(double) * file.coefficients.size()));
  out.write(coefficient_end, 8);
  if(!out) throw Tool_error("writing '" + path + "' failed");
}

Coefficient_file read_coefficient_file(std::istream& in, std::uint64_t bytes, const std::string& path)
{
  const std::string what = "coefficient file '" + path + "': ";
  char magic[8];
  std::uint32_t version = 0, bom = 0, k = 0, fields = 0;
  Coefficient_file file;
  if(!in.read(magic, 8) || std::memcmp(magic, coefficient_magic, 8) != 0)
    throw Tool_error(what + "not a .tvfc file (no TVFCOEFS header)");
  if(!get_binary(in, version) || version != coefficient_version)
    throw Tool_error(what + "format version " + std::to_string(version) + ", this tool reads version 1");
  if(!get_binary(in, bom) || bom != byte_order_mark) throw Tool_error(what + "written with another byte order");
  if(!get_binary(in, file.faces) || !get_binary(in, k) || !get_binary(in, fields) || fields != 1)
    throw Tool_error(what + "bad header");
  if(k == 0) throw Tool_error(what + "no coefficients");
  // The header, the coefficients and the end marker: checked against the size before the
  // coefficients are allocated, so that a corrupt count cannot ask for gigabytes.
  const std::uint64_t header_bytes = 8 + 4 * 4 + 8 * 6; // magic; version, mark, count, fields; faces, signature, error
  if(bytes < header_bytes + 8 || (bytes - header_bytes - 8) / 8 < k)
    throw Tool_error(what + "truncated (" + std::to_string(k) + " coefficients announced, " + std::to_string(bytes) +
                     " bytes)");
  for(double& s : file.signature)
    if(!get_binary(in, s)) throw Tool_error(what + "truncated");
  if(!get_binary(in, file.relative_error)) throw Tool_error(what + "truncated");
  for(double s : file.signature)
    if(!std::isfinite(s)) throw Tool_error(what + "non-finite basis signature");
  // At most 1 (a projection), up to the roundoff of a field orthogonal to the kept elements.
  if(!(file.relative_error >= 0 && file.relative_error <= 1 + 1e-9))
    throw Tool_error(what + "the relative error at compression is not in [0, 1]");
  file.coefficients.resize(k);
  char end[8];
  if(!in.read(reinterpret_cast<char*>(file.coefficients.data()), static_cast<std::streamsize>(sizeof(double) * k)) ||
     !in.read(end, 8) || std::memcmp(end, coefficient_end, 8) != 0)
    throw Tool_error(what + "truncated or corrupt");
  if(!file.coefficients.allFinite()) throw Tool_error(what + "non-finite coefficients");
  return file;
}

Coefficient_file read_coefficient_file(const std::string& path)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if(!in) throw Tool_error("cannot open coefficient file '" + path + "': " + std::strerror(errno));
  const std::uint64_t bytes = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  return read_coefficient_file(in, bytes, path);
}

} // namespace tvf_tool
