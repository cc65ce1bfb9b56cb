// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_MODEL_REDUCTION_INTERNAL_BINARY_FILE_H
#define CGAL_MODEL_REDUCTION_INTERNAL_BINARY_FILE_H

// What the binary result files of every package share (a precomputation saved so that it is
// not repeated): a header of magic, version, byte-order mark and the identity of the mesh the
// result belongs to, and a bounded reader that refuses truncated, oversized or foreign content
// with `Invalid_input`.

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <functional>
#include <istream>
#include <ostream>
#include <string>

namespace CGAL {
namespace Model_reduction {
namespace internal {

/// What ties a file to its mesh: a hash of the connectivity, and sums of the geometry (say the
/// total area and weighted sums of the edge lengths) that agree to ~1e-12 relative only for the
/// same geometry.  Each package computes it from its own mesh representation.
struct Mesh_identity
{
  std::uint64_t connectivity = 0;
  std::array<double, 5> geometry{};
};

/// FNV-1a, for `Mesh_identity::connectivity`.
struct Hasher
{
  std::uint64_t h = 1469598103934665603ull;
  void add(const void* data, std::size_t bytes)
  {
    const unsigned char* c = static_cast<const unsigned char*>(data);
    for(std::size_t i = 0; i < bytes; ++i)
    {
      h ^= c[i];
      h *= 1099511628211ull;
    }
  }
  template <class T>
  void add(const T& value)
  {
    add(&value, sizeof(T));
  }
};

/// Byte-order mark written after the version.
constexpr std::uint32_t byte_order_mark = 0x01020304u;

template <class T>
void write_value(std::ostream& out, const T& value)
{
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

/// Rows, columns (int64), then the column-major doubles.
void write_matrix(std::ostream& out, const Eigen::MatrixXd& M);

/// The header every result file starts with: magic, version, byte-order mark, mesh identity.
void write_header(std::ostream& out, const char (&magic)[8], std::uint32_t version, const Mesh_identity& mesh);

/// Opens `path` for `Binary_reader`; `bytes` receives its size.
/// \throws Invalid_input "cannot open the <what> file '<path>'"
std::ifstream open_binary_file(const std::string& path, const std::string& what, std::uint64_t& bytes);

/// Reads at most `bytes` from `in`; every failure throws `Invalid_input` with
/// "cannot load the <what> from '<path>': <reason>".
class Binary_reader
{
public:
  Binary_reader(std::istream& in, const std::string& path, std::uint64_t bytes, const std::string& what)
    : in_(in), path_(path), what_(what), left_(bytes)
  {}
  template <class T>
  T value()
  {
    T v;
    read(&v, sizeof(T));
    return v;
  }
  /// A matrix written by `write_matrix`; `rows`/`cols` < 0: any.
  Eigen::MatrixXd matrix(Eigen::Index rows, Eigen::Index cols, const char* what);
  /// The same with float entries.
  Eigen::MatrixXf float_matrix(Eigen::Index rows, Eigen::Index cols, const char* what);
  /// Checks 8 magic bytes.
  void expect_magic(const char (&magic)[8], const std::string& why_not);
  /// Checks a header written by `write_header` ("not a <what> file", version, byte order, mesh).
  void expect_header(const char (&magic)[8], std::uint32_t version, const Mesh_identity& mesh);
  /// The same accepting any version in [oldest, newest]; returns the file's.
  std::uint32_t expect_header(const char (&magic)[8], std::uint32_t oldest, std::uint32_t newest,
                              const Mesh_identity& mesh);
  /// The same with the identity the file's version holds (a format that changed how it
  /// identifies meshes still reads its older files).
  std::uint32_t expect_header(const char (&magic)[8], std::uint32_t oldest, std::uint32_t newest,
                              const std::function<Mesh_identity(std::uint32_t version)>& mesh_of_version);
  [[noreturn]] void fail(const std::string& why) const;

private:
  template <class Matrix>
  Matrix any_matrix(Eigen::Index rows, Eigen::Index cols, const char* what);
  void read(void* data, std::size_t bytes);

  std::istream& in_;
  std::string path_, what_;
  std::uint64_t left_;
};

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL

#endif
