// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Model_reduction/internal/binary_file.h>
#include <CGAL/Model_reduction/errors.h>

#include <cmath>
#include <cstring>

namespace CGAL {
namespace Model_reduction {
namespace internal {

void write_matrix(std::ostream& out, const Eigen::MatrixXd& M)
{
  write_value<std::int64_t>(out, M.rows());
  write_value<std::int64_t>(out, M.cols());
  out.write(reinterpret_cast<const char*>(M.data()), static_cast<std::streamsize>(sizeof(double) * M.size()));
}

void write_header(std::ostream& out, const char (&magic)[8], std::uint32_t version, const Mesh_identity& mesh)
{
  out.write(magic, sizeof(magic));
  write_value(out, version);
  write_value(out, byte_order_mark);
  write_value(out, mesh.connectivity);
  for(double s : mesh.geometry) write_value(out, s);
}

std::ifstream open_binary_file(const std::string& path, const std::string& what, std::uint64_t& bytes)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if(!in) throw Invalid_input("cannot open the " + what + " file '" + path + "'");
  bytes = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  return in;
}

void Binary_reader::expect_header(const char (&magic)[8], std::uint32_t version, const Mesh_identity& mesh)
{
  expect_header(magic, version, version, mesh);
}

std::uint32_t Binary_reader::expect_header(const char (&magic)[8], std::uint32_t oldest, std::uint32_t newest,
                                           const Mesh_identity& mesh)
{
  return expect_header(magic, oldest, newest, [&](std::uint32_t) { return mesh; });
}

std::uint32_t Binary_reader::expect_header(const char (&magic)[8], std::uint32_t oldest, std::uint32_t newest,
                                           const std::function<Mesh_identity(std::uint32_t)>& mesh_of_version)
{
  expect_magic(magic, "not a " + what_ + " file");
  const std::uint32_t found = value<std::uint32_t>();
  if(found < oldest || found > newest)
    fail("file format version " + std::to_string(found) + ", this library reads version " +
         (oldest == newest ? std::to_string(newest) : std::to_string(oldest) + " to " + std::to_string(newest)));
  if(value<std::uint32_t>() != byte_order_mark) fail("written on a machine of another byte order");
  const Mesh_identity mesh = mesh_of_version(found);
  if(value<std::uint64_t>() != mesh.connectivity) fail("it belongs to a mesh with other connectivity");
  for(double s : mesh.geometry)
  {
    const double stored = value<double>();
    if(!(std::abs(stored - s) <= 1e-9 * std::abs(s))) fail("it belongs to a mesh with other edge lengths");
  }
  return found;
}

Eigen::MatrixXd Binary_reader::matrix(Eigen::Index rows, Eigen::Index cols, const char* what)
{
  return any_matrix<Eigen::MatrixXd>(rows, cols, what);
}

Eigen::MatrixXf Binary_reader::float_matrix(Eigen::Index rows, Eigen::Index cols, const char* what)
{
  return any_matrix<Eigen::MatrixXf>(rows, cols, what);
}

template <class Matrix>
Matrix Binary_reader::any_matrix(Eigen::Index rows, Eigen::Index cols, const char* what)
{
  typedef typename Matrix::Scalar Scalar;
  const std::int64_t r = value<std::int64_t>(), c = value<std::int64_t>();
  if((rows >= 0 && r != rows) || (cols >= 0 && c != cols) || r < 0 || c < 0)
    fail(std::string("the ") + what + " have the wrong size");
  // Checked by division: r * c * 8 may overflow for hostile sizes.
  if(r > 0 && static_cast<std::uint64_t>(c) > left_ / sizeof(Scalar) / static_cast<std::uint64_t>(r))
    fail("the file is truncated");
  Matrix M(r, c);
  read(M.data(), sizeof(Scalar) * M.size());
  return M;
}

void Binary_reader::expect_magic(const char (&magic)[8], const std::string& why_not)
{
  char found[8];
  for(char& c : found) c = value<char>();
  if(std::memcmp(found, magic, sizeof(found)) != 0) fail(why_not);
}

void Binary_reader::fail(const std::string& why) const
{
  throw Invalid_input("cannot load the " + what_ + " from '" + path_ + "': " + why);
}

void Binary_reader::read(void* data, std::size_t bytes)
{
  if(bytes > left_) fail("the file is truncated");
  in_.read(static_cast<char*>(data), static_cast<std::streamsize>(bytes));
  if(!in_) fail("read error");
  left_ -= bytes;
}

} // namespace internal
} // namespace Model_reduction
} // namespace CGAL
