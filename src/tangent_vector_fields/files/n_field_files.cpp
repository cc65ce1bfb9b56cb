// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/n_field_files.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <cmath>
#include <complex>
#include <istream>
#include <limits>
#include <ostream>
#include <set>
#include <sstream>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

std::array<double, 3> to_3d(const Intrinsic_mesh& mesh, int f, double a, double b)
{
  const auto v = mesh.from_frame(f, a, b);
  return {v[0], v[1], v[2]};
}

// Reads one integer token; false at the end of the stream.
bool read_integer(std::istream& in, long long& x)
{
  std::string token;
  if(!(in >> token)) return false;
  std::size_t used = 0;
  try
  {
    x = std::stoll(token, &used);
  }
  catch(const std::exception&)
  {
    used = 0;
  }
  if(used != token.size() || used == 0) throw Invalid_input(".sing file: '" + token + "' is not an integer");
  return true;
}

} // namespace

Raw_field n_field_to_raw_field(const N_field_operators& ops, const Eigen::VectorXd& z)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  if(z.size() != 2 * mesh.number_of_faces())
    throw Invalid_input("n-field raw field: the field has " + std::to_string(z.size()) + " coordinates, the mesh " +
                        std::to_string(mesh.number_of_faces()) + " faces");
  Raw_field raw;
  raw.degree = ops.n();
  std::vector<Eigen::VectorXd> branches;
  for(int j = 0; j < ops.n(); ++j) branches.push_back(ops.to_vectors(z, j));
  raw.vectors.reserve(static_cast<std::size_t>(ops.n()) * mesh.number_of_faces());
  for(int f = 0; f < mesh.number_of_faces(); ++f)
    for(int j = 0; j < ops.n(); ++j) raw.vectors.push_back(to_3d(mesh, f, branches[j][2 * f], branches[j][2 * f + 1]));
  return raw;
}

Eigen::VectorXd n_field_from_raw_field(const N_field_operators& ops, const Raw_field& raw, double tolerance)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  const int n = ops.n();
  if(raw.degree != n)
    throw Invalid_input("raw field: " + std::to_string(raw.degree) + " vectors per face where an n-field with n = " +
                        std::to_string(n) + " has " + std::to_string(n));
  if(raw.number_of_faces() != static_cast<std::size_t>(mesh.number_of_faces()) ||
     raw.vectors.size() != static_cast<std::size_t>(n) * mesh.number_of_faces())
    throw Invalid_input("raw field: " + std::to_string(raw.number_of_faces()) + " faces, the mesh has " +
                        std::to_string(mesh.number_of_faces()));
  Eigen::VectorXd vectors(2 * mesh.number_of_faces());
  for(int f = 0; f < mesh.number_of_faces(); ++f)
  {
    std::vector<std::complex<double>> u(n);
    double largest = 0;
    for(int j = 0; j < n; ++j)
    {
      const auto& v = raw.vectors[static_cast<std::size_t>(f) * n + j];
      for(double x : v)
        if(!std::isfinite(x)) throw Invalid_input("raw field: face " + std::to_string(f) + " has a non-finite coordinate");
      const auto ab = mesh.to_frame(f, v);
      u[j] = {ab[0], ab[1]};
      largest = std::max(largest, std::abs(u[j]));
    }
    vectors[2 * f] = u[0].real();
    vectors[2 * f + 1] = u[0].imag();
    if(largest == 0) continue;
    for(int j = 1; j < n; ++j)
    {
      // Vector j must be vector 0 turned counter-clockwise by 2 pi j / n, of the same length.
      const std::complex<double> expected = u[0] * std::polar(1., 2 * M_PI * j / n);
      if(std::abs(u[j] - expected) > tolerance * largest)
      {
        std::ostringstream s;
        s << "raw field: face " << f << " is not an n-field with n = " << n << ": vector " << j << " is "
          << std::arg(u[j] / expected) * 180 / M_PI << " degrees and a factor " << std::abs(u[j]) / std::abs(expected)
          << " off vector 0 turned by 360 * " << j << " / " << n << " degrees (counter-clockwise)";
        throw Invalid_input(s.str());
      }
    }
  }
  return ops.from_vectors(vectors);
}

void write_singularity_file(std::ostream& out, const Singularity_file& file)
{
  if(file.n < 1) throw Invalid_input(".sing file: N must be at least 1, got " + std::to_string(file.n));
  out << file.n << " " << file.singularities.size() << "\n";
  for(const auto& [v, k] : file.singularities) out << v << " " << k << "\n";
  if(!out) throw Invalid_input(".sing file: writing failed");
}

Singularity_file read_singularity_file(std::istream& in)
{
  Singularity_file file;
  long long n = 0, count = 0;
  if(!read_integer(in, n) || !read_integer(in, count)) throw Invalid_input(".sing file: no header 'N count'");
  if(n < 1 || n > std::numeric_limits<int>::max()) throw Invalid_input(".sing file: N must be at least 1, got " + std::to_string(n));
  if(count < 0) throw Invalid_input(".sing file: negative count " + std::to_string(count));
  file.n = static_cast<int>(n);
  std::set<long long> seen;
  for(long long i = 0; i < count; ++i)
  {
    long long v = 0, k = 0;
    if(!read_integer(in, v) || !read_integer(in, k))
      throw Invalid_input(".sing file: " + std::to_string(count) + " singularities announced, " + std::to_string(i) +
                          " found");
    if(v < 0 || v > std::numeric_limits<int>::max()) throw Invalid_input(".sing file: bad vertex " + std::to_string(v));
    if(std::abs(k) > std::numeric_limits<int>::max()) throw Invalid_input(".sing file: index out of range at vertex " + std::to_string(v));
    if(!seen.insert(v).second) throw Invalid_input(".sing file: vertex " + std::to_string(v) + " listed twice");
    file.singularities.emplace_back(static_cast<int>(v), static_cast<int>(k));
  }
  std::string extra;
  if(in >> extra) throw Invalid_input(".sing file: unexpected '" + extra + "' after the " + std::to_string(count) + " singularities");
  return file;
}

Singularity_file n_field_singularity_file(const N_field_operators& ops, const Eigen::VectorXd& z)
{
  Singularity_file file;
  file.n = ops.n();
  for(const N_field_singularity& s : n_field_singularities(ops, z)) file.singularities.emplace_back(s.vertex, s.index);
  return file;
}

Vtk_polydata n_field_polydata(const N_field_operators& ops, const Eigen::VectorXd& z, const std::string& name)
{
  const Intrinsic_mesh& mesh = ops.mesh();
  const Raw_field raw = n_field_to_raw_field(ops, z);
  std::vector<std::array<double, 3>> points;
  for(int v = 0; v < mesh.number_of_vertices(); ++v) points.push_back(mesh.position(v));
  std::vector<std::array<int, 3>> triangles;
  for(int f = 0; f < mesh.number_of_faces(); ++f) triangles.push_back(mesh.face_vertices(f));
  std::vector<std::pair<std::string, std::vector<std::array<double, 3>>>> fields(ops.n());
  for(int j = 0; j < ops.n(); ++j)
  {
    fields[j].first = name + "_" + std::to_string(j);
    for(int f = 0; f < mesh.number_of_faces(); ++f)
      fields[j].second.push_back(raw.vectors[static_cast<std::size_t>(f) * ops.n() + j]);
  }
  Vtk_polydata data = face_fields_polydata(points, triangles, fields);
  Vtk_polydata::Array index;
  index.name = name + "_index";
  for(int k : n_field_indices(ops, z)) index.values.push_back(static_cast<double>(k) / ops.n());
  data.point_data.push_back(std::move(index));
  return data;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
