// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_BASIS_FILE_H
#define CGAL_TANGENT_VECTOR_FIELDS_INTERNAL_BASIS_FILE_H

// What the binary basis files (vector-field `.tvfb`, n-field `.tvfn`) share: the mesh
// fingerprint and geometry signature that tie a file to its mesh, and a bounded reader
// that refuses truncated or oversized content with `Invalid_input`.

#include <CGAL/Tangent_vector_fields/Intrinsic_mesh.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <fstream>
#include <istream>
#include <ostream>
#include <string>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

/// Hash of the connectivity (counts, face vertices and edges): equal only for the same mesh.
std::uint64_t mesh_fingerprint(const Intrinsic_mesh& mesh);

/// Total area and four pseudo-randomly weighted sums of the edge lengths: equal to ~1e-12
/// relative only for the same intrinsic geometry.
std::array<double, 5> geometry_signature(const Intrinsic_mesh& mesh);

/// Byte-order mark written after the version.
constexpr std::uint32_t byte_order_mark = 0x01020304u;

template <class T>
void write_value(std::ostream& out, const T& value)
{
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

/// Rows, columns (int64), then the column-major doubles.
void write_matrix(std::ostream& out, const Eigen::MatrixXd& M);

/// Writes the fingerprint and the geometry signature of `mesh`.
void write_mesh_identity(std::ostream& out, const Intrinsic_mesh& mesh);

/// The header every basis file starts with: magic, version, byte-order mark, mesh identity.
void write_basis_header(std::ostream& out, const char (&magic)[8], std::uint32_t version, const Intrinsic_mesh& mesh);

/// Opens `path` for `Binary_reader`; `bytes` receives its size.
/// \throws Invalid_input "cannot open the <what> file '<path>'"
std::ifstream open_basis_file(const std::string& path, const std::string& what, std::uint64_t& bytes);

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
  /// Checks the fingerprint and the geometry signature written by `write_mesh_identity`.
  void expect_mesh_identity(const Intrinsic_mesh& mesh);
  /// Checks a header written by `write_basis_header` ("not a <what> file", version, byte order, mesh).
  void expect_basis_header(const char (&magic)[8], std::uint32_t version, const Intrinsic_mesh& mesh);
  /// The same for a file of any version from `oldest` to `newest`; returns the version found.
  std::uint32_t expect_basis_header(const char (&magic)[8], std::uint32_t oldest, std::uint32_t newest,
                                    const Intrinsic_mesh& mesh);
  [[noreturn]] void fail(const std::string& why) const;

private:
  void read(void* data, std::size_t bytes);
  template <class Matrix>
  Matrix any_matrix(Eigen::Index rows, Eigen::Index cols, const char* what);
  std::istream& in_;
  std::string path_, what_;
  std::uint64_t left_;
};

} // namespace internal
} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
