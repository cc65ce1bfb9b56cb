// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Singularity indices against fields whose singularities are known analytically.
// Poincare-Hopf holds for any field by the way the indices are computed (each edge's
// turning enters its two end vertices with opposite signs), so it proves nothing about
// where the singularities are or what their indices are: here each vertex's index is
// compared with the answer of the geometry, and Poincare-Hopf stays a sanity line.

#include "n_field_test_support.h"

#include <CGAL/Tangent_vector_fields/N_field_singularities.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <numeric>

using namespace nfield_test;

namespace {

Eigen::Vector3d centroid(const TVF::Intrinsic_mesh& im, int f)
{
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for(int v : im.face_vertices(f)) c += to_eigen(im.position(v)) / 3;
  return c;
}

// The vector field `w(c)` (3D, at face centroids) projected to the faces, in frame coordinates.
template <typename F>
Eigen::VectorXd projected_field(const TVF::Intrinsic_mesh& im, const F& w)
{
  Eigen::VectorXd x(2 * im.number_of_faces());
  for(int f = 0; f < im.number_of_faces(); ++f)
  {
    const Eigen::Vector3d d = w(centroid(im, f));
    const auto ab = im.to_frame(f, {d[0], d[1], d[2]});
    x[2 * f] = ab[0];
    x[2 * f + 1] = ab[1];
  }
  return x;
}

// Rotates every face's vector by `angle(f)` in the face's frame (counter-clockwise about its normal).
template <typename F>
Eigen::VectorXd rotated(const Eigen::VectorXd& x, const F& angle)
{
  Eigen::VectorXd y(x.size());
  for(int f = 0; f < int(x.size() / 2); ++f)
  {
    const double a = angle(f), c = std::cos(a), s = std::sin(a);
    y[2 * f] = c * x[2 * f] - s * x[2 * f + 1];
    y[2 * f + 1] = s * x[2 * f] + c * x[2 * f + 1];
  }
  return y;
}

int nearest_vertex(const TVF::Intrinsic_mesh& im, const Eigen::Vector3d& p)
{
  int best = 0;
  for(int v = 1; v < im.number_of_vertices(); ++v)
    if((to_eigen(im.position(v)) - p).norm() < (to_eigen(im.position(best)) - p).norm()) best = v;
  return best;
}

// Expects the indices `k` of `nops` for the vector field `x` (as an n-field) to be exactly
// `expected` at the listed vertices and 0 everywhere else; Poincare-Hopf as a sanity line.
void expect_indices(const TVF::N_field_operators& nops, const Eigen::VectorXd& x, const std::map<int, int>& expected,
                    int chi, const std::string& what)
{
  SCOPED_TRACE(what + ", n = " + std::to_string(nops.n()));
  const std::vector<int> k = TVF::n_field_indices(nops, nops.from_vectors(x));
  int unexpected = 0;
  for(int v = 0; v < int(k.size()); ++v)
  {
    const auto it = expected.find(v);
    const int want = it == expected.end() ? 0 : it->second;
    if(k[v] != want && ++unexpected <= 5) ADD_FAILURE() << "vertex " << v << ": index " << k[v] << ", expected " << want;
  }
  EXPECT_EQ(unexpected, 0);
  EXPECT_EQ(std::accumulate(k.begin(), k.end(), 0), nops.n() * chi) << "Poincare-Hopf";
}

} // namespace

TEST(NFieldIndices, ConstantVectorProjectedOntoTheSphereIsSingularAtItsTwoPoles)
{
  // w = a - (a.p) p: zero exactly at p = +-a, where it turns once (index +1 each, seen from
  // outside).  As an n-field (each vector repeated n-fold) the index is n/n: k = n at the two
  // poles, 0 elsewhere.  The axis goes through a vertex (the icosphere is centrally symmetric,
  // so through its antipode too).  A discrete field cannot show a turning of pi or more
  // between neighbouring faces: around a pole's 5 or 6 faces the power turns by 2 pi n / 5,
  // so n <= 2.
  const Mesh sphere = make_icosphere(3);
  TVF::Discrete_operators<Mesh> ops(sphere);
  const TVF::Intrinsic_mesh& im = ops.intrinsic_mesh();
  for(int pole : {0, 17, 300})
  {
    const Eigen::Vector3d a = to_eigen(im.position(pole)).normalized();
    const int antipode = nearest_vertex(im, -a);
    ASSERT_LT((to_eigen(im.position(antipode)) + a).norm(), 1e-12);
    const Eigen::VectorXd x = projected_field(im, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(a - a.dot(p) * p / p.squaredNorm()); });
    for(int n : {1, 2})
    {
      const TVF::N_field_operators nops(ops.shared_matrices(), n);
      expect_indices(nops, x, {{pole, n}, {antipode, n}}, 2, "pole " + std::to_string(pole));
    }
  }
}

TEST(NFieldIndices, ParallelsAndMeridiansOfATorusHaveNoSingularity)
{
  // A torus of revolution about z: the field along the parallels, (-y, x, 0), and the one
  // along the meridians (its cross product with the normal) never vanish: index 0 at every
  // vertex, for every n (the field is smooth, so the power turns little from face to face).
  const Mesh torus = make_torus(30, 14);
  TVF::Discrete_operators<Mesh> ops(torus);
  const TVF::Intrinsic_mesh& im = ops.intrinsic_mesh();
  const Eigen::VectorXd parallels = projected_field(im, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(-p[1], p[0], 0); });
  const Eigen::VectorXd meridians = TVF::Operator_matrices::rotate(parallels);
  for(int n : {1, 2, 4, 6})
  {
    const TVF::N_field_operators nops(ops.shared_matrices(), n);
    expect_indices(nops, parallels, {}, 0, "parallels");
    expect_indices(nops, meridians, {}, 0, "meridians");
    // A field turning k times along the parallel direction (angle k theta / n, theta the
    // longitude) is still regular: the turning is spread over the whole loop.
    const Eigen::VectorXd turning = rotated(parallels, [&](int f) {
      const Eigen::Vector3d c = centroid(im, f);
      return 3 * std::atan2(c[1], c[0]) / n;
    });
    expect_indices(nops, turning, {}, 0, "turning along the parallels");
  }
}

TEST(NFieldIndices, AFieldRotatedByAKnownAngleAroundAVertexOfTheSphere)
{
  // The field of the poles above (singular at +-a with k = n) rotated in each face by
  // k phi / n, phi the longitude about an axis q through an equatorial vertex: the n-field
  // then also turns k times around q (index k/n) and -k times around -q (seen from outside,
  // the longitude about q runs the other way there).  |k| <= 2 keeps the turning between
  // neighbouring faces below pi around 6 faces; the poles stay at k = n for n = 1, 2.
  const Mesh sphere = make_icosphere(3);
  TVF::Discrete_operators<Mesh> ops(sphere);
  const TVF::Intrinsic_mesh& im = ops.intrinsic_mesh();
  const int pole = 0;
  const Eigen::Vector3d a = to_eigen(im.position(pole)).normalized();
  // The vertex closest to the equator of a (generic: not on a symmetry axis of the pole field).
  int q = -1;
  for(int v = 0; v < im.number_of_vertices(); ++v)
    if(q < 0 || std::abs(to_eigen(im.position(v)).normalized().dot(a)) < std::abs(to_eigen(im.position(q)).normalized().dot(a)))
      q = v;
  const Eigen::Vector3d b = to_eigen(im.position(q)).normalized();
  ASSERT_LT(std::abs(a.dot(b)), 0.1);
  const Eigen::Vector3d u = b.unitOrthogonal(), w = b.cross(u);
  const int antipole = nearest_vertex(im, -a), antiq = nearest_vertex(im, -b);
  const Eigen::VectorXd x = projected_field(im, [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(a - a.dot(p) * p / p.squaredNorm()); });
  for(int n : {1, 2})
    for(int k : {-2, -1, 1, 2})
    {
      const TVF::N_field_operators nops(ops.shared_matrices(), n);
      const Eigen::VectorXd y = rotated(x, [&](int f) {
        const Eigen::Vector3d c = centroid(im, f);
        return k * std::atan2(c.dot(w), c.dot(u)) / n;
      });
      expect_indices(nops, y, {{pole, n}, {antipole, n}, {q, k}, {antiq, -k}}, 2, "k = " + std::to_string(k));
    }
}
