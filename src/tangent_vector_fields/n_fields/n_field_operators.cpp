// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/N_field_operators.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Model_reduction/internal/Lazy_value.h>
#include <CGAL/Tangent_vector_fields/internal/n_field_geometry.h>
#include <CGAL/Tangent_vector_fields/internal/singularity_connection.h>

#include <cmath>
#include <complex>
#include <queue>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

namespace internal {

std::array<double, 2> corner_layout(const Intrinsic_mesh& mesh, int f, int k)
{
  if(k == 0) return {0., 0.};
  if(k == 1) return {mesh.face_edge_length(f, 2), 0.};
  return mesh.corner2_layout(f);
}

int local_corner(const Intrinsic_mesh& mesh, int f, int v)
{
  const auto& c = mesh.face_vertices(f);
  return c[0] == v ? 0 : c[1] == v ? 1 : c[2] == v ? 2 : -1;
}

double edge_angle(const Intrinsic_mesh& mesh, int f, int from, int to)
{
  const auto p = corner_layout(mesh, f, local_corner(mesh, f, from));
  const auto q = corner_layout(mesh, f, local_corner(mesh, f, to));
  return std::atan2(q[1] - p[1], q[0] - p[0]);
}

double corner_angle(const Intrinsic_mesh& mesh, int f, int k)
{
  const auto p2 = mesh.corner2_layout(f);
  const double l2 = mesh.face_edge_length(f, 2);
  const double a0 = std::atan2(p2[1], p2[0]);
  const double a1 = std::atan2(p2[1], l2 - p2[0]);
  return k == 0 ? a0 : k == 1 ? a1 : M_PI - a0 - a1;
}

double wrap_angle(double a)
{
  a = std::fmod(a + M_PI, 2 * M_PI);
  if(a < 0) a += 2 * M_PI;
  return a - M_PI;
}

} // namespace internal

struct N_field_operators::Cache
{
  Model_reduction::internal::Lazy_value<Vector> transport, connection, weights, curvatures;
  Model_reduction::internal::Lazy_value<Sparse_matrix> S;
  Model_reduction::internal::Lazy_value<Eigen::SparseMatrix<std::complex<double>>> complex_S;
  Model_reduction::internal::Lazy_value<Matrix> kernel;
  Model_reduction::internal::Lazy_value<std::vector<int>> vertex_corner;
  Model_reduction::internal::Lazy_value<std::vector<char>> boundary_vertices; // 3 f + k of one corner of each vertex, -1: none
};

N_field_operators::N_field_operators(std::shared_ptr<const Operator_matrices> operators, int n,
                                     const N_field_options& options)
  : operators_(std::move(operators)), n_(n), options_(options), cache_(std::make_unique<Cache>())
{
  if(!operators_) throw Invalid_input("n-field operators: no operators given");
  if(n < 1) throw Invalid_input("n-field operators: n must be at least 1 (got " + std::to_string(n) + ")");
  // Indices are integers k summing to n chi and angles are n times a face angle: beyond this
  // the sums leave the range of int and n theta keeps no digit of theta's precision.
  if(n > max_n)
    throw Invalid_input("n-field operators: n must be at most " + std::to_string(max_n) + " (got " + std::to_string(n) +
                        ")");
  const Intrinsic_mesh& m = mesh();
  std::vector<char> prescribed(m.number_of_vertices(), 0);
  const int components = m.topology().number_of_components();
  std::vector<long long> index_sum(components, 0);
  for(const auto& [v, k] : options_.singularities)
  {
    const std::string what = "n-field operators: the singularity of index " + std::to_string(k) + "/" +
                             std::to_string(n) + " at vertex " + std::to_string(v);
    if(v < 0 || v >= m.number_of_vertices()) throw Invalid_input(what + ": no such vertex");
    if(prescribed[v]) throw Invalid_input(what + ": the vertex is prescribed twice");
    prescribed[v] = 1;
    if(m.is_isolated_vertex(v)) throw Invalid_input(what + ": the vertex is in no face");
    if(boundary_vertices()[v]) throw Invalid_input(what + ": the vertex is on the boundary");
    index_sum[m.vertex_component(v)] += k;
  }
  if(options_.singularities.empty()) return;
  // On a closed component the indices sum to n chi (Poincare-Hopf).  Free vertices take up
  // the difference; when every vertex of the component is prescribed none can, and the
  // connection would silently miss the holonomy of one of them.
  std::vector<char> has_free(components, 0);
  for(int v = 0; v < m.number_of_vertices(); ++v)
    if(!m.is_isolated_vertex(v) && !prescribed[v]) has_free[m.vertex_component(v)] = 1;
  for(int c = 0; c < components; ++c)
  {
    const Component_topology& t = m.topology().components[c];
    const long long expected = static_cast<long long>(n) * t.euler_characteristic();
    if(t.is_closed() && !has_free[c] && index_sum[c] != expected)
      throw Invalid_input("n-field operators: every vertex of component " + std::to_string(c) +
                          " has a prescribed singularity, and their indices sum to " + std::to_string(index_sum[c]) +
                          "/" + std::to_string(n) + ", not n chi = " + std::to_string(expected) + "/" +
                          std::to_string(n) + " (Poincare-Hopf)");
  }
}

N_field_operators::~N_field_operators() = default;

const N_field_operators::Vector& N_field_operators::transport_angles() const
{
  return cache_->transport.get([&] {
    const Intrinsic_mesh& mesh = this->mesh();
    Vector t(mesh.number_of_interior_edges());
    for(int i = 0; i < t.size(); ++i)
    {
      const int e = mesh.interior_edges()[i];
      const auto& v = mesh.edge_vertices(e);
      const auto& ff = mesh.edge_faces(e);
      t[i] = internal::edge_angle(mesh, ff[0], v[0], v[1]) - internal::edge_angle(mesh, ff[1], v[0], v[1]);
    }
    return t;
  });
}

const N_field_operators::Vector& N_field_operators::connection_angles() const
{
  return cache_->connection.get([&] {
    Vector t = transport_angles();
    if(!options_.singularities.empty()) t += internal::singularity_connection(*this);
    return t;
  });
}

const N_field_operators::Vector& N_field_operators::edge_weights() const
{
  return cache_->weights.get([&] {
    const Intrinsic_mesh& mesh = this->mesh();
    Vector w(mesh.number_of_interior_edges());
    for(int i = 0; i < w.size(); ++i)
    {
      const int e = mesh.interior_edges()[i];
      const auto& ff = mesh.edge_faces(e);
      const double l = mesh.edge_length(e);
      w[i] = 3 * l * l / (mesh.face_area(ff[0]) + mesh.face_area(ff[1]));
    }
    return w;
  });
}

const std::vector<char>& N_field_operators::boundary_vertices() const
{
  return cache_->boundary_vertices.get([&] {
    const Intrinsic_mesh& mesh = this->mesh();
    std::vector<char> on_boundary(mesh.number_of_vertices(), 0);
    for(int e = 0; e < mesh.number_of_edges(); ++e)
      if(mesh.is_boundary_edge(e))
        for(int v : mesh.edge_vertices(e)) on_boundary[v] = 1;
    return on_boundary;
  });
}

const N_field_operators::Vector& N_field_operators::vertex_curvatures() const
{
  return cache_->curvatures.get([&] {
    const Intrinsic_mesh& mesh = this->mesh();
    Vector angle_sum = Vector::Zero(mesh.number_of_vertices());
    const std::vector<char>& on_boundary = boundary_vertices();
    for(int f = 0; f < mesh.number_of_faces(); ++f)
      for(int k = 0; k < 3; ++k) angle_sum[mesh.face_vertices(f)[k]] += internal::corner_angle(mesh, f, k);
    Vector K(mesh.number_of_vertices());
    for(int v = 0; v < K.size(); ++v)
      K[v] = mesh.is_isolated_vertex(v) ? 0. : (on_boundary[v] ? M_PI : 2 * M_PI) - angle_sum[v];
    return K;
  });
}

const N_field_operators::Sparse_matrix& N_field_operators::S() const
{
  return cache_->S.get([&] {
    const Intrinsic_mesh& mesh = this->mesh();
    const Vector& t = connection_angles();
    const Vector& w = edge_weights();
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(16 * static_cast<std::size_t>(t.size()) + 2 * mesh.number_of_faces());
    Vector diagonal = Vector::Zero(mesh.number_of_faces());
    for(int i = 0; i < t.size(); ++i)
    {
      const auto& ff = mesh.edge_faces(mesh.interior_edges()[i]);
      const int f = ff[0], g = ff[1];
      const double c = std::cos(n_ * t[i]), s = std::sin(n_ * t[i]);
      diagonal[f] += w[i];
      diagonal[g] += w[i];
      // S[f,g] = -w R(n t), S[g,f] = -w R(n t)^T.
      const double R[2][2] = {{c, -s}, {s, c}};
      for(int a = 0; a < 2; ++a)
        for(int b = 0; b < 2; ++b)
        {
          entries.emplace_back(2 * f + a, 2 * g + b, -w[i] * R[a][b]);
          entries.emplace_back(2 * g + b, 2 * f + a, -w[i] * R[a][b]);
        }
    }
    add_boundary_diagonal(diagonal);
    for(int f = 0; f < mesh.number_of_faces(); ++f)
      for(int a = 0; a < 2; ++a) entries.emplace_back(2 * f + a, 2 * f + a, diagonal[f]);
    Sparse_matrix S(2 * mesh.number_of_faces(), 2 * mesh.number_of_faces());
    S.setFromTriplets(entries.begin(), entries.end());
    return S;
  });
}

double N_field_operators::transport_angle(int e, int from) const
{
  const double t = transport_angles()[mesh().interior_edge_index(e)];
  // transport_angles() carries from the edge's second face into its first.
  return mesh().edge_faces(e)[1] == from ? t : -t;
}

N_field_operators::Vertex_fan N_field_operators::vertex_fan(int v) const
{
  const Intrinsic_mesh& mesh = this->mesh();
  const std::vector<int>& vertex_corner = cache_->vertex_corner.get([&] {
    std::vector<int> corner(mesh.number_of_vertices(), -1);
    for(int f = 0; f < mesh.number_of_faces(); ++f)
      for(int k = 0; k < 3; ++k) corner[mesh.face_vertices(f)[k]] = 3 * f + k;
    return corner;
  });
  Vertex_fan fan;
  int c = vertex_corner[v];
  if(c < 0) return fan;
  // Counter-clockwise around v, face f (v at corner k) is followed across local edge k+1 and
  // preceded across local edge k+2.  Around a boundary vertex, first walk back to the start.
  auto step = [&](int corner, int local_edge) {
    const int f = corner / 3, e = mesh.face_edges(f)[(corner % 3 + local_edge) % 3];
    if(mesh.is_boundary_edge(e)) return -1;
    const auto& ff = mesh.edge_faces(e);
    const int g = ff[0] == f ? ff[1] : ff[0];
    return 3 * g + internal::local_corner(mesh, g, v);
  };
  const int start = c;
  for(int back = step(c, 2); back >= 0 && back != start; back = step(c, 2)) c = back;
  fan.on_boundary = step(c, 2) < 0;
  const int first = c;
  do
  {
    fan.faces.push_back(c / 3);
    const int e = mesh.face_edges(c / 3)[(c % 3 + 1) % 3];
    const int next = step(c, 1);
    if(next < 0) break;
    fan.edges.push_back(e);
    c = next;
  } while(c != first);
  return fan;
}

const Eigen::SparseMatrix<std::complex<double>>& N_field_operators::complex_S() const
{
  return cache_->complex_S.get([&] {
    // Assembled directly (not from the real form): the smoothest field needs only this one.
    const Intrinsic_mesh& mesh = this->mesh();
    const Vector& t = connection_angles();
    const Vector& w = edge_weights();
    std::vector<Eigen::Triplet<std::complex<double>>> entries;
    entries.reserve(2 * static_cast<std::size_t>(t.size()) + mesh.number_of_faces());
    Vector diagonal = Vector::Zero(mesh.number_of_faces());
    for(int i = 0; i < t.size(); ++i)
    {
      const auto& ff = mesh.edge_faces(mesh.interior_edges()[i]);
      diagonal[ff[0]] += w[i];
      diagonal[ff[1]] += w[i];
      const std::complex<double> rho = std::polar(w[i], n_ * t[i]); // w_e rho_fg^n
      entries.emplace_back(ff[0], ff[1], -rho);
      entries.emplace_back(ff[1], ff[0], -std::conj(rho));
    }
    add_boundary_diagonal(diagonal);
    for(int f = 0; f < mesh.number_of_faces(); ++f) entries.emplace_back(f, f, diagonal[f]);
    Eigen::SparseMatrix<std::complex<double>> C(mesh.number_of_faces(), mesh.number_of_faces());
    C.setFromTriplets(entries.begin(), entries.end());
    return C;
  });
}

void N_field_operators::add_boundary_diagonal(Vector& diagonal) const
{
  if(options_.boundary != N_field_boundary::zero) return;
  const Intrinsic_mesh& mesh = this->mesh();
  for(int e = 0; e < mesh.number_of_edges(); ++e)
    if(mesh.is_boundary_edge(e))
    {
      const int f = mesh.edge_faces(e)[0];
      const double l = mesh.edge_length(e);
      diagonal[f] += 3 * l * l / mesh.face_area(f);
    }
}

N_field_operators::Vector N_field_operators::laplacian(const Vector& z) const
{
  return (S() * z).cwiseQuotient(masses());
}

double N_field_operators::dirichlet_energy(const Vector& z) const { return z.dot(S() * z); }

N_field_operators::Vector N_field_operators::energy_density(const Vector& z) const
{
  const Intrinsic_mesh& mesh = this->mesh();
  if(z.size() != 2 * mesh.number_of_faces())
    throw Invalid_input("n-field energy density: the field has " + std::to_string(z.size()) + " coordinates, not " +
                        std::to_string(2 * mesh.number_of_faces()));
  const Vector& t = connection_angles();
  const Vector& w = edge_weights();
  Vector twice_energy = Vector::Zero(mesh.number_of_faces()); // each edge term, half to each face, doubled
  for(int i = 0; i < t.size(); ++i)
  {
    const auto& ff = mesh.edge_faces(mesh.interior_edges()[i]);
    // |z_f - rho^n z_g|^2 with rho^n z_g = R(n t) z_g, the connection of S_n.
    const std::complex<double> zf(z[2 * ff[0]], z[2 * ff[0] + 1]), zg(z[2 * ff[1]], z[2 * ff[1] + 1]);
    const double term = w[i] * std::norm(zf - std::polar(1., n_ * t[i]) * zg);
    twice_energy[ff[0]] += term;
    twice_energy[ff[1]] += term;
  }
  Vector boundary = Vector::Zero(mesh.number_of_faces());
  add_boundary_diagonal(boundary); // the zero boundary condition: w_e |z_f|^2
  Vector density(mesh.number_of_faces());
  for(int f = 0; f < mesh.number_of_faces(); ++f)
    density[f] = (twice_energy[f] / 2 + boundary[f] * (z[2 * f] * z[2 * f] + z[2 * f + 1] * z[2 * f + 1])) / mesh.face_area(f);
  return density;
}

double N_field_operators::m_harmonic_energy(const Vector& z, int m) const
{
  if(m < 1) throw Invalid_input("m-harmonic energy: m must be at least 1 (got " + std::to_string(m) + ")");
  Vector u = z;
  for(int k = 1; k < m; ++k) u = laplacian(u);
  return z.dot(S() * u);
}

const N_field_operators::Matrix& N_field_operators::kernel() const
{
  return cache_->kernel.get([&] {
    const Intrinsic_mesh& mesh = this->mesh();
    const int nf = mesh.number_of_faces();
    const int components = mesh.topology().number_of_components();
    Matrix K(2 * nf, 0);
    if(options_.boundary == N_field_boundary::free)
    {
      // Carry z = 1 from a root face along a spanning tree of each component, then
      // check that every edge of the component agrees with the carried field.
      const Vector& t = connection_angles();
      std::vector<std::vector<std::pair<int, int>>> neighbours(nf); // (face, interior edge)
      for(int i = 0; i < t.size(); ++i)
      {
        const auto& ff = mesh.edge_faces(mesh.interior_edges()[i]);
        neighbours[ff[0]].push_back({ff[1], i});
        neighbours[ff[1]].push_back({ff[0], i});
      }
      std::vector<double> phase(nf, 0.);
      std::vector<char> reached(nf, 0);
      std::vector<char> parallel(components, 1);
      for(int root = 0; root < nf; ++root)
      {
        if(reached[root]) continue;
        reached[root] = 1;
        std::queue<int> queue;
        queue.push(root);
        while(!queue.empty())
        {
          const int f = queue.front();
          queue.pop();
          for(const auto& [g, i] : neighbours[f])
          {
            if(reached[g]) continue;
            reached[g] = 1;
            // z_first = rho^n z_second, rho = e^{i t} carries second into first.
            const bool f_first = mesh.edge_faces(mesh.interior_edges()[i])[0] == f;
            phase[g] = internal::wrap_angle(phase[f] + (f_first ? -n_ * t[i] : n_ * t[i]));
            queue.push(g);
          }
        }
      }
      for(int i = 0; i < t.size(); ++i)
      {
        const auto& ff = mesh.edge_faces(mesh.interior_edges()[i]);
        const double mismatch = internal::wrap_angle(phase[ff[0]] - phase[ff[1]] - n_ * t[i]);
        if(!(std::abs(mismatch) <= options_.holonomy_tolerance)) parallel[mesh.face_component(ff[0])] = 0;
      }
      std::vector<int> column(components, -1);
      int count = 0;
      for(int c = 0; c < components; ++c)
        if(parallel[c]) column[c] = count++;
      K = Matrix::Zero(2 * nf, 2 * count);
      Vector area = Vector::Zero(components);
      for(int f = 0; f < nf; ++f) area[mesh.face_component(f)] += mesh.face_area(f);
      for(int f = 0; f < nf; ++f)
      {
        const int c = mesh.face_component(f);
        if(column[c] < 0) continue;
        const double s = 1 / std::sqrt(area[c]);
        const double x = s * std::cos(phase[f]), y = s * std::sin(phase[f]);
        K(2 * f, 2 * column[c]) = x;
        K(2 * f + 1, 2 * column[c]) = y;
        K(2 * f, 2 * column[c] + 1) = -y; // J p
        K(2 * f + 1, 2 * column[c] + 1) = x;
      }
    }
    return K;
  });
}

N_field_operators::Vector N_field_operators::from_vectors(const Vector& vectors) const
{
  if(vectors.size() != 2 * mesh().number_of_faces())
    throw Invalid_input("n-field: " + std::to_string(vectors.size()) + " frame coordinates for a mesh of " +
                        std::to_string(mesh().number_of_faces()) + " faces");
  // hypot(NaN, b) > 0 is false: a NaN vector would silently become the zero n-field.
  if(!vectors.allFinite()) throw Invalid_input("n-field: the vectors have non-finite entries");
  const Eigen::Index nf = vectors.size() / 2;
  Vector z(vectors.size());
  for(Eigen::Index f = 0; f < nf; ++f)
  {
    const double a = vectors[2 * f], b = vectors[2 * f + 1];
    const double r = std::hypot(a, b);
    const std::complex<double> w = r > 0 ? std::polar(r, n_ * std::atan2(b, a)) : std::complex<double>(0, 0);
    z[2 * f] = w.real();
    z[2 * f + 1] = w.imag();
  }
  return z;
}

N_field_operators::Vector N_field_operators::to_vectors(const Vector& z) const { return to_vectors(z, 0); }

N_field_operators::Vector N_field_operators::to_vectors(const Vector& z, int j) const
{
  if(j < 0 || j >= n_)
    throw Invalid_input("n-field: vector " + std::to_string(j) + " asked of a field of " + std::to_string(n_));
  const Eigen::Index nf = z.size() / 2;
  Vector u(z.size());
  for(Eigen::Index f = 0; f < nf; ++f)
  {
    const double r = std::hypot(z[2 * f], z[2 * f + 1]);
    const double theta = std::atan2(z[2 * f + 1], z[2 * f]) / n_ + 2 * M_PI * j / n_;
    u[2 * f] = r * std::cos(theta);
    u[2 * f + 1] = r * std::sin(theta);
  }
  return u;
}

N_field_operators::Vector N_field_operators::normalized(const Vector& z) const
{
  Vector u(z.size());
  for(Eigen::Index f = 0; f < z.size() / 2; ++f)
  {
    const double r = std::hypot(z[2 * f], z[2 * f + 1]);
    u[2 * f] = r > 0 ? z[2 * f] / r : 0.;
    u[2 * f + 1] = r > 0 ? z[2 * f + 1] / r : 0.;
  }
  return u;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
