// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/Operator_matrices.h>
#include <CGAL/Model_reduction/internal/Lazy_value.h>
#include <CGAL/Model_reduction/internal/compressed_matrix.h>

#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

typedef Operator_matrices::Sparse_matrix Sparse_matrix;
typedef Operator_matrices::Vector Vector;
typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Row_sparse_matrix;

// Fills a compressed column-major matrix from per-face 3x3 blocks.
// `global(f, k)` is the row/column of local index k of face f (-1: dropped);
// `local(f, a, b)` the block entry.  Duplicates are summed.
Sparse_matrix assemble_face_blocks(int n, int nf, const std::function<int(int, int)>& global,
                                   const std::function<void(int, double[3][3])>& local)
{
  std::vector<int> start(n + 1, 0);
  std::vector<std::array<int, 3>> index(nf);
  for(int f = 0; f < nf; ++f)
  {
    for(int k = 0; k < 3; ++k) index[f][k] = global(f, k);
    int present = 0;
    for(int k = 0; k < 3; ++k) present += index[f][k] >= 0;
    for(int k = 0; k < 3; ++k)
      if(index[f][k] >= 0) start[index[f][k] + 1] += present;
  }
  for(int c = 0; c < n; ++c) start[c + 1] += start[c];
  std::vector<std::pair<int, double>> entries(start[n]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for(int f = 0; f < nf; ++f)
  {
    double block[3][3];
    local(f, block);
    for(int b = 0; b < 3; ++b)
    {
      const int col = index[f][b];
      if(col < 0) continue;
      for(int a = 0; a < 3; ++a)
        if(index[f][a] >= 0) entries[fill[col]++] = {index[f][a], block[a][b]};
    }
  }
  // Sort each column by row and merge duplicates.
  std::vector<int> outer(n + 1, 0);
  std::vector<int> inner;
  std::vector<double> values;
  inner.reserve(entries.size() / 2);
  values.reserve(entries.size() / 2);
  for(int c = 0; c < n; ++c)
  {
    std::sort(entries.begin() + start[c], entries.begin() + start[c + 1],
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for(int i = start[c]; i < start[c + 1]; ++i)
    {
      if(static_cast<int>(inner.size()) > outer[c] && inner.back() == entries[i].first)
        values.back() += entries[i].second;
      else
      {
        inner.push_back(entries[i].first);
        values.push_back(entries[i].second);
      }
    }
    outer[c + 1] = static_cast<int>(inner.size());
  }
  return Model_reduction::internal::compressed_matrix(n, n, outer, inner, values);
}

Sparse_matrix diagonal_matrix(const Vector& d)
{
  Sparse_matrix D(d.size(), d.size());
  D.resizeNonZeros(d.size());
  for(Eigen::Index i = 0; i < d.size(); ++i)
  {
    D.outerIndexPtr()[i] = static_cast<int>(i);
    D.innerIndexPtr()[i] = static_cast<int>(i);
    D.valuePtr()[i] = d[i];
  }
  D.outerIndexPtr()[d.size()] = static_cast<int>(d.size());
  return D;
}

// 1/x where x > 0, else 0 (vertices in no face have no mass).
Vector safe_inverse(const Vector& d)
{
  return d.unaryExpr([](double x) { return x > 0 ? 1 / x : 0.; });
}

} // namespace

struct Operator_matrices::Cache
{
  Model_reduction::internal::Lazy_value<Vector> face_areas, vertex_masses, edge_masses, field_masses;
  Model_reduction::internal::Lazy_value<Vector> inverse_vertex_masses, inverse_edge_masses;
  Model_reduction::internal::Lazy_value<Sparse_matrix> G, G_star, G_star_interior, M, M_star, MX, J, W, W_star, S, L, B;
};

Operator_matrices::Operator_matrices(std::shared_ptr<const Intrinsic_mesh> mesh)
  : mesh_(std::move(mesh)), cache_(new Cache)
{}

Operator_matrices::~Operator_matrices() = default;

const Vector& Operator_matrices::face_areas() const
{
  return cache_->face_areas.get([&] {
    Vector a(mesh_->number_of_faces());
    for(int f = 0; f < a.size(); ++f) a[f] = mesh_->face_area(f);
    return a;
  });
}

const Vector& Operator_matrices::vertex_masses() const
{
  return cache_->vertex_masses.get([&] {
    Vector m = Vector::Zero(mesh_->number_of_vertices());
    for(int f = 0; f < mesh_->number_of_faces(); ++f)
      for(int v : mesh_->face_vertices(f)) m[v] += mesh_->face_area(f) / 3;
    return m;
  });
}

const Vector& Operator_matrices::edge_masses() const
{
  return cache_->edge_masses.get([&] {
    Vector m = Vector::Zero(mesh_->number_of_edges());
    for(int f = 0; f < mesh_->number_of_faces(); ++f)
      for(int e : mesh_->face_edges(f)) m[e] += mesh_->face_area(f) / 3;
    return m;
  });
}

const Vector& Operator_matrices::field_masses() const
{
  return cache_->field_masses.get([&] {
    const Vector& a = face_areas();
    Vector m(2 * a.size());
    for(Eigen::Index f = 0; f < a.size(); ++f) m[2 * f] = m[2 * f + 1] = a[f];
    return m;
  });
}

namespace {
// Gradients of the three hat functions of face f in its frame, from the layout
// p0 = (0,0), p1 = (l2,0), p2 = (x,y): grad phi_k = J (p_{k+2} - p_{k+1}) / (2A).
// Computed for the face scaled to a longest edge l2 = 1 (shape area A / l2^2), then
// divided by l2: no product of two lengths, which under- or overflows at extreme scales.
std::array<std::array<double, 2>, 3> hat_gradients(const Intrinsic_mesh& mesh, int f)
{
  const double l2 = mesh.face_edge_length(f, 2);
  const double x = mesh.corner2_layout(f)[0] / l2, y = mesh.corner2_layout(f)[1] / l2;
  const double s = 1 / (2 * mesh.face_shape_area(f) * l2);
  return {{{-y * s, (x - 1) * s}, {y * s, -x * s}, {0., s}}};
}

// 2nf x n matrix with 3 entries per row: rows 2f, 2f+1 hold `scale` times the hat
// gradients of face f in the columns `column(f, k)`.
Sparse_matrix gradient_matrix(const Intrinsic_mesh& mesh, int columns, double scale,
                              const std::function<int(int, int)>& column)
{
  const int nf = mesh.number_of_faces();
  Row_sparse_matrix R(2 * nf, columns);
  R.resizeNonZeros(6 * static_cast<Eigen::Index>(nf));
  for(int f = 0; f < nf; ++f)
  {
    const auto g = hat_gradients(mesh, f);
    std::array<int, 3> order = {0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return column(f, a) < column(f, b); });
    for(int d = 0; d < 2; ++d)
    {
      const int row = 2 * f + d;
      R.outerIndexPtr()[row] = 3 * row;
      for(int i = 0; i < 3; ++i)
      {
        R.innerIndexPtr()[3 * row + i] = column(f, order[i]);
        R.valuePtr()[3 * row + i] = scale * g[order[i]][d];
      }
    }
  }
  R.outerIndexPtr()[2 * nf] = 6 * nf;
  return Sparse_matrix(R);
}

// Local cotan matrix of face f: C_ab = A grad phi_a . grad phi_b.
void cotan_block(const Intrinsic_mesh& mesh, int f, double scale, double block[3][3])
{
  double cot[3];
  for(int k = 0; k < 3; ++k) cot[k] = mesh.cotangent(f, k);
  for(int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    block[a][a] = scale * 0.5 * (cot[b] + cot[c]);
    block[a][b] = block[b][a] = -scale * 0.5 * cot[c];
  }
}
} // namespace

const Sparse_matrix& Operator_matrices::G() const
{
  return cache_->G.get([&] {
    return gradient_matrix(*mesh_, mesh_->number_of_vertices(), 1.,
                           [this](int f, int k) { return mesh_->face_vertices(f)[k]; });
  });
}

// psi_e = 1 - 2 phi_k for the edge e opposite corner k, so grad psi_e = -2 grad phi_k.
const Sparse_matrix& Operator_matrices::G_star() const
{
  return cache_->G_star.get([&] {
    return gradient_matrix(*mesh_, mesh_->number_of_edges(), -2.,
                           [this](int f, int k) { return mesh_->face_edges(f)[k]; });
  });
}

const Sparse_matrix& Operator_matrices::G_star_interior() const
{
  return cache_->G_star_interior.get([&] {
    // Number interior edges first and boundary edges after them, then cut those off.
    const int ne = mesh_->number_of_edges(), ni = mesh_->number_of_interior_edges();
    std::vector<int> column(ne);
    int next_boundary = ni;
    for(int e = 0; e < ne; ++e)
      column[e] = mesh_->is_boundary_edge(e) ? next_boundary++ : mesh_->interior_edge_index(e);
    const Sparse_matrix full =
        gradient_matrix(*mesh_, ne, -2., [&](int f, int k) { return column[mesh_->face_edges(f)[k]]; });
    return Sparse_matrix(full.leftCols(ni));
  });
}

const Sparse_matrix& Operator_matrices::M() const
{
  return cache_->M.get([&] { return diagonal_matrix(vertex_masses()); });
}

const Sparse_matrix& Operator_matrices::M_star() const
{
  return cache_->M_star.get([&] { return diagonal_matrix(edge_masses()); });
}

const Sparse_matrix& Operator_matrices::MX() const
{
  return cache_->MX.get([&] { return diagonal_matrix(field_masses()); });
}

const Sparse_matrix& Operator_matrices::J() const
{
  return cache_->J.get([&] {
    const int n = 2 * mesh_->number_of_faces();
    Sparse_matrix J(n, n);
    J.resizeNonZeros(n);
    for(int c = 0; c < n; ++c)
    {
      // column 2f has +1 in row 2f+1; column 2f+1 has -1 in row 2f
      J.outerIndexPtr()[c] = c;
      J.innerIndexPtr()[c] = (c % 2 == 0) ? c + 1 : c - 1;
      J.valuePtr()[c] = (c % 2 == 0) ? 1. : -1.;
    }
    J.outerIndexPtr()[n] = n;
    return J;
  });
}

const Sparse_matrix& Operator_matrices::W() const
{
  return cache_->W.get([&] {
    return assemble_face_blocks(
        mesh_->number_of_vertices(), mesh_->number_of_faces(),
        [this](int f, int k) { return mesh_->face_vertices(f)[k]; },
        [this](int f, double block[3][3]) { cotan_block(*mesh_, f, 1., block); });
  });
}

const Sparse_matrix& Operator_matrices::W_star() const
{
  // grad psi_e = -2 grad phi_k: the Crouzeix-Raviart block is 4 times the cotan block.
  return cache_->W_star.get([&] {
    return assemble_face_blocks(
        mesh_->number_of_interior_edges(), mesh_->number_of_faces(),
        [this](int f, int k) { return mesh_->interior_edge_index(mesh_->face_edges(f)[k]); },
        [this](int f, double block[3][3]) { cotan_block(*mesh_, f, 4., block); });
  });
}

namespace {
const Vector& cached_inverse(const Model_reduction::internal::Lazy_value<Vector>& slot, const Vector& d)
{
  return slot.get([&] { return Vector(safe_inverse(d)); });
}
} // namespace

// S = sum_v a_v a_v^T / M_v + sum_e c_e c_e^T / M*_e (interior e), with a_v the
// column of MX G for vertex v and c_e that of MX J G* for edge e.  Assembled column
// block by column block (two columns per face) from the faces around each vertex:
// an order of magnitude faster than the general sparse products.
const Sparse_matrix& Operator_matrices::S() const
{
  return cache_->S.get([&] {
    const Intrinsic_mesh& m = *mesh_;
    const int nf = m.number_of_faces(), nv = m.number_of_vertices();
    const Vector& inverse_mass = cached_inverse(cache_->inverse_vertex_masses, vertex_masses());
    const Vector& inverse_edge_mass = cached_inverse(cache_->inverse_edge_masses, edge_masses());

    // Faces around each vertex (CSR), with the local corner of the vertex.
    std::vector<int> first(nv + 1, 0);
    for(int f = 0; f < nf; ++f)
      for(int v : m.face_vertices(f)) ++first[v + 1];
    for(int v = 0; v < nv; ++v) first[v + 1] += first[v];
    std::vector<std::pair<int, int>> corners(first[nv]);
    {
      std::vector<int> fill(first.begin(), first.end() - 1);
      for(int f = 0; f < nf; ++f)
        for(int k = 0; k < 3; ++k) corners[fill[m.face_vertices(f)[k]]++] = {f, k};
    }
    // a_v restricted to face f (corner k): area * grad phi_k; c_e on face f
    // (e opposite corner k): area * J (-2 grad phi_k).
    std::vector<std::array<std::array<double, 2>, 3>> a(nf), c(nf);
    for(int f = 0; f < nf; ++f)
    {
      const auto g = hat_gradients(m, f);
      const double area = m.face_area(f);
      for(int k = 0; k < 3; ++k)
      {
        a[f][k] = {area * g[k][0], area * g[k][1]};
        c[f][k] = {2 * area * g[k][1], -2 * area * g[k][0]};
      }
    }

    struct Block
    {
      int face;
      double v[2][2]; // v[row][col]: rows of face `face`, columns of the current face
    };
    std::vector<Block> blocks;
    std::vector<int> outer(2 * nf + 1, 0);
    std::vector<int> inner;
    std::vector<double> values;
    inner.reserve(static_cast<std::size_t>(nf) * 52);
    values.reserve(static_cast<std::size_t>(nf) * 52);
    std::vector<double> second_column;
    for(int g = 0; g < nf; ++g)
    {
      blocks.clear();
      for(int kg = 0; kg < 3; ++kg)
      {
        const int v = m.face_vertices(g)[kg];
        const double w = inverse_mass[v];
        const auto& ag = a[g][kg];
        for(int i = first[v]; i < first[v + 1]; ++i)
        {
          const auto [f, kf] = corners[i];
          const auto& af = a[f][kf];
          blocks.push_back({f, {{w * af[0] * ag[0], w * af[0] * ag[1]}, {w * af[1] * ag[0], w * af[1] * ag[1]}}});
        }
        const int e = m.face_edges(g)[kg];
        if(m.is_boundary_edge(e)) continue;
        const double we = inverse_edge_mass[e];
        const auto& cg = c[g][kg];
        for(int f : m.edge_faces(e))
        {
          int kf = 0;
          while(m.face_edges(f)[kf] != e) ++kf;
          const auto& cf = c[f][kf];
          blocks.push_back({f, {{we * cf[0] * cg[0], we * cf[0] * cg[1]}, {we * cf[1] * cg[0], we * cf[1] * cg[1]}}});
        }
      }
      std::sort(blocks.begin(), blocks.end(), [](const Block& x, const Block& y) { return x.face < y.face; });
      // Column 2g goes straight to the output, column 2g+1 is buffered.
      second_column.clear();
      for(std::size_t i = 0; i < blocks.size();)
      {
        Block sum = blocks[i];
        for(++i; i < blocks.size() && blocks[i].face == sum.face; ++i)
          for(int r = 0; r < 2; ++r)
            for(int q = 0; q < 2; ++q) sum.v[r][q] += blocks[i].v[r][q];
        for(int r = 0; r < 2; ++r)
        {
          inner.push_back(2 * sum.face + r);
          values.push_back(sum.v[r][0]);
          second_column.push_back(sum.v[r][1]);
        }
      }
      const std::size_t count = second_column.size();
      outer[2 * g + 1] = static_cast<int>(inner.size());
      for(std::size_t i = 0; i < count; ++i)
      {
        inner.push_back(inner[inner.size() - count]);
        values.push_back(second_column[i]);
      }
      outer[2 * g + 2] = static_cast<int>(inner.size());
    }
    return Model_reduction::internal::compressed_matrix(2 * nf, 2 * nf, outer, inner, values);
  });
}

const Sparse_matrix& Operator_matrices::L() const
{
  return cache_->L.get([&] { return Sparse_matrix(safe_inverse(field_masses()).asDiagonal() * S()); });
}

const Sparse_matrix& Operator_matrices::B() const
{
  return cache_->B.get([&] {
    const Sparse_matrix& s = S();
    return Sparse_matrix(s * (safe_inverse(field_masses()).asDiagonal() * s));
  });
}

Vector Operator_matrices::rotate(const Vector& v)
{
  Vector r(v.size());
  for(Eigen::Index f = 0; 2 * f < v.size(); ++f)
  {
    r[2 * f] = -v[2 * f + 1];
    r[2 * f + 1] = v[2 * f];
  }
  return r;
}

Vector Operator_matrices::divergence(const Vector& v) const
{
  const Vector& im = cached_inverse(cache_->inverse_vertex_masses, vertex_masses());
  return -im.cwiseProduct(G().transpose() * field_masses().cwiseProduct(v));
}

Vector Operator_matrices::curl(const Vector& v) const
{
  const Vector& im = cached_inverse(cache_->inverse_vertex_masses, vertex_masses());
  return im.cwiseProduct(G().transpose() * rotate(field_masses().cwiseProduct(v)));
}

Vector Operator_matrices::nonconforming_divergence(const Vector& v) const
{
  const Vector& im = cached_inverse(cache_->inverse_edge_masses, edge_masses());
  return -im.cwiseProduct(G_star().transpose() * field_masses().cwiseProduct(v));
}

Vector Operator_matrices::nonconforming_curl(const Vector& v) const
{
  const Vector& im = cached_inverse(cache_->inverse_edge_masses, edge_masses());
  return im.cwiseProduct(G_star().transpose() * rotate(field_masses().cwiseProduct(v)));
}

Vector Operator_matrices::interior_to_all_edges(const Vector& interior_values) const
{
  Vector all = Vector::Zero(mesh_->number_of_edges());
  for(int i = 0; i < interior_values.size(); ++i) all[mesh_->interior_edges()[i]] = interior_values[i];
  return all;
}

Vector Operator_matrices::all_to_interior_edges(const Vector& edge_values) const
{
  Vector interior(mesh_->number_of_interior_edges());
  for(int i = 0; i < interior.size(); ++i) interior[i] = edge_values[mesh_->interior_edges()[i]];
  return interior;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
