// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Many streamlines of n-direction fields: the hatching (evenly spaced streamlines of every
// family) and fur per branch, checked against the parameter lines of a torus of revolution;
// the generic functions on face maps holding any one of the n vectors.

#include "n_field_streamline_support.h"

#include <CGAL/Tangent_vector_fields/Streamlines.h>
#include <CGAL/Tangent_vector_fields/smoothest_n_field.h>

#include <random>

using namespace nstream_test;

namespace {

// Points along a polyline, every `step`, with the direction of their segment.
struct Sample
{
  P3 point, tangent;
  std::size_t line;
};

void sample(const TVF::Streamline& s, std::size_t line, double step, std::vector<Sample>& out)
{
  for(std::size_t i = 0; i + 1 < s.points.size(); ++i)
  {
    const P3 d = sub(s.points[i + 1], s.points[i]);
    if(norm(d) < 1e-12) continue;
    const int k = 1 + static_cast<int>(norm(d) / step);
    for(int j = 0; j < k; ++j)
    {
      const double u = double(j) / k;
      out.push_back({{s.points[i][0] + u * d[0], s.points[i][1] + u * d[1], s.points[i][2] + u * d[2]}, unit(d), line});
    }
  }
}

} // namespace

TEST(NFieldStreamlines, HatchingOfATorusCrossFieldIsTwoFamiliesEachEvenlySpaced)
{
  // Evenly spaced streamlines of the torus's cross field: parallels and meridians, each
  // family at the separation, crossing each other at right angles; of the line field of
  // the parallels: parallels only.
  const Mesh torus = make_torus(72, 28, torus_R, torus_r);
  for(int n : {4, 2})
  {
    SCOPED_TRACE("n = " + std::to_string(n));
    const auto ops = n_field_operators(torus, n);
    const TVF::Intrinsic_mesh& M = ops->mesh();
    const Eigen::VectorXd x = torus_parallels(M);
    const TVF::Streamline_tracer tracer(*ops, ops->from_vectors(x));
    EXPECT_EQ(tracer.number_of_families(), n / 2);
    TVF::Evenly_spaced_options options;
    options.separation = 0.04;
    const double separation = 0.04 * tracer.bounding_box_diagonal();
    const std::vector<TVF::Streamline> lines = tracer.evenly_spaced(options);
    // Each line's family: the parameter line its segments follow, by length.
    std::vector<int> family(lines.size());
    int count[2] = {0, 0};
    std::vector<Sample> samples[2];
    for(std::size_t l = 0; l < lines.size(); ++l)
    {
      const TVF::Streamline& s = lines[l];
      expect_valid_n_streamline(M, x, n, s);
      EXPECT_GE(s.branch, 0);
      EXPECT_LT(s.branch, n / 2);
      double along[2] = {0, 0};
      for(std::size_t i = 0; i + 1 < s.points.size(); ++i)
      {
        const P3 d = sub(s.points[i + 1], s.points[i]);
        along[std::abs(dot(d, parallel_direction(s.points[i]))) > std::abs(dot(d, meridian_direction(s.points[i])))] +=
            norm(d);
      }
      family[l] = along[1] > along[0];
      EXPECT_LT(std::min(along[0], along[1]), 1e-9) << "line " << l << " changes family";
      ++count[family[l]];
      sample(s, l, 0.2 * separation, samples[family[l]]);
    }
    // About 2 pi r / separation parallels (family 1); for a cross field, at least as many
    // meridians (family 0) as fit on the inner side at the separation.
    EXPECT_GE(count[1], static_cast<int>(0.8 * 2 * M_PI * torus_r / separation));
    if(n == 4)
      EXPECT_GE(count[0], static_cast<int>(2 * M_PI * (torus_R - torus_r) / separation));
    else
      EXPECT_EQ(count[0], 0);
    // Lines of one family keep the separation.
    for(int f = 0; f < 2; ++f)
    {
      double closest = 1e300;
      for(std::size_t i = 0; i < samples[f].size(); ++i)
        for(std::size_t j = i + 1; j < samples[f].size(); ++j)
          if(samples[f][i].line != samples[f][j].line)
            closest = std::min(closest, norm(sub(samples[f][i].point, samples[f][j].point)));
      EXPECT_GT(closest, 0.4 * separation) << "family " << f;
    }
    if(n == 2) continue;
    // The two families cross, at right angles.
    int crossings = 0;
    double worst = 0;
    for(const Sample& a : samples[0])
      for(const Sample& b : samples[1])
        if(norm(sub(a.point, b.point)) < 0.1 * separation)
        {
          ++crossings;
          worst = std::max(worst, std::abs(90 - degrees(std::acos(dot(a.tangent, b.tangent)))));
        }
    EXPECT_GT(crossings, 100);
    EXPECT_LT(worst, 10.0) << "degrees away from a right angle";
    // Each family covers the torus: random points of it are near a line of each.
    std::mt19937 gen(9);
    std::uniform_real_distribution<double> angle(0, 2 * M_PI);
    int far[2] = {0, 0};
    for(int t = 0; t < 500; ++t)
    {
      const double a = angle(gen), b = angle(gen);
      const P3 p = {(torus_R + torus_r * std::cos(b)) * std::cos(a), (torus_R + torus_r * std::cos(b)) * std::sin(a),
                    torus_r * std::sin(b)};
      for(int f = 0; f < 2; ++f)
      {
        double d = 1e300;
        for(const Sample& q : samples[f]) d = std::min(d, norm(sub(q.point, p)));
        far[f] += d > separation;
      }
    }
    EXPECT_LT(far[0], 10);
    EXPECT_LT(far[1], 10);
  }
}

TEST(NFieldStreamlines, FurHasAStrokeAlongEachVectorOfItsRoot)
{
  const Mesh torus = make_torus(40, 16, torus_R, torus_r);
  for(int n : {4, 2, 3})
  {
    SCOPED_TRACE("n = " + std::to_string(n));
    const auto ops = n_field_operators(torus, n);
    const Eigen::VectorXd x = torus_parallels(ops->mesh());
    const TVF::Streamline_tracer tracer(*ops, ops->from_vectors(x));
    TVF::Fur_options fur;
    fur.number_of_strokes = 100;
    fur.length = 0.05;
    fur.length_unit = TVF::Length_unit::absolute;
    const std::vector<TVF::Streamline> strokes = tracer.fur(fur);
    ASSERT_EQ(strokes.size(), static_cast<std::size_t>(100 * n));
    for(std::size_t r = 0; r < 100; ++r)
    {
      // The n strokes of a root: from the same point, 2 pi / n apart, of the full length.
      const TVF::Streamline& s0 = strokes[n * r];
      const P3 d0 = unit(sub(s0.points[1], s0.points[0]));
      for(int j = 0; j < n; ++j)
      {
        const TVF::Streamline& s = strokes[n * r + j];
        expect_valid_n_streamline(ops->mesh(), x, n, s);
        EXPECT_EQ(s.branch, j);
        EXPECT_EQ(s.points.front(), s0.points.front());
        EXPECT_NEAR(dot(unit(sub(s.points[1], s.points[0])), d0), std::cos(2 * M_PI * j / n), 1e-9);
        EXPECT_NEAR(s.length(), 0.05, 1e-12);
      }
    }
    // One chosen branch: the same roots, the same strokes.
    fur.branch = n - 1;
    const std::vector<TVF::Streamline> one = tracer.fur(fur);
    ASSERT_EQ(one.size(), 100u);
    for(std::size_t r = 0; r < 100; ++r) EXPECT_EQ(one[r].points, strokes[n * r + n - 1].points);
  }
}


TEST(NFieldStreamlines, GenericFunctionsTraceTheVectorsOfAFaceMap)
{
  // A face map holding any one of the n vectors per face, as smoothest_n_field writes it
  // and then turned by random multiples of 2 pi / 4: branch j of a face is its map vector
  // turned by 2 pi j / 4; streamlines stop at the singularities n_field_singularities
  // reports; the free functions agree with the tracer class.
  Mesh sphere = make_icosphere(3);
  auto field = sphere.add_property_map<Face_index, Vector_3>("f:cross", Vector_3(0, 0, 0)).first;
  const auto singular = TVF::smoothest_n_field(sphere, 4, field);
  ASSERT_EQ(singular.size(), 8u);
  std::mt19937 gen(3);
  for(Face_index f : sphere.faces())
  {
    // A quarter turn about the face's normal: n x v.
    const auto h = sphere.halfedge(f);
    const Vector_3 normal = CGAL::unit_normal(sphere.point(sphere.source(h)), sphere.point(sphere.target(h)),
                                              sphere.point(sphere.target(sphere.next(h))));
    for(int k = std::uniform_int_distribution<int>(0, 3)(gen); k > 0; --k) field[f] = CGAL::cross_product(normal, field[f]);
  }
  TVF::Mesh_streamline_tracer<Mesh> tracer(sphere, 4, field);
  EXPECT_EQ(tracer.tracer().n(), 4);
  std::vector<int> expected;
  for(const auto& s : singular) expected.push_back(static_cast<int>(std::size_t(s.first)));
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(tracer.tracer().singular_vertices(), expected);

  TVF::Streamline_options options;
  options.maximum_length = 1;
  std::mt19937 pick(4);
  for(int i = 0; i < 30; ++i)
  {
    const Face_index f(std::uniform_int_distribution<int>(0, static_cast<int>(sphere.number_of_faces()) - 1)(pick));
    const auto h = sphere.halfedge(f);
    const Point_3 seed = CGAL::centroid(sphere.point(sphere.source(h)), sphere.point(sphere.target(h)),
                                        sphere.point(sphere.target(sphere.next(h))));
    const Vector_3 normal = CGAL::unit_normal(sphere.point(sphere.source(h)), sphere.point(sphere.target(h)),
                                              sphere.point(sphere.target(sphere.next(h))));
    Vector_3 expected_direction = field[f] / std::sqrt(field[f].squared_length());
    for(int j = 0; j < 4; ++j)
    {
      options.branch = j;
      const TVF::Streamline s = tracer.trace(f, seed, options);
      EXPECT_EQ(s.points, TVF::trace_n_field_streamline(sphere, 4, field, f, seed, options).points);
      const P3 first = unit(sub(s.points[s.seed_index + 1], s.points[s.seed_index]));
      EXPECT_NEAR(dot(first, {expected_direction.x(), expected_direction.y(), expected_direction.z()}), 1, 1e-9);
      expected_direction = CGAL::cross_product(normal, expected_direction);
    }
  }
  TVF::Evenly_spaced_options even;
  even.separation = 0.05;
  const std::vector<TVF::Streamline> lines = tracer.evenly_spaced(even);
  const std::vector<TVF::Streamline> again = TVF::evenly_spaced_n_field_streamlines(sphere, 4, field, even);
  ASSERT_EQ(lines.size(), again.size());
  for(std::size_t i = 0; i < lines.size(); ++i) EXPECT_EQ(lines[i].points, again[i].points);
  TVF::Fur_options fur;
  fur.number_of_strokes = 50;
  fur.branch = 1;
  const std::vector<TVF::Streamline> strokes = tracer.fur(fur), more = TVF::n_field_fur_strokes(sphere, 4, field, fur);
  ASSERT_EQ(strokes.size(), more.size());
  for(std::size_t i = 0; i < strokes.size(); ++i) EXPECT_EQ(strokes[i].points, more[i].points);

  expect_invalid([&] { TVF::Mesh_streamline_tracer<Mesh>(sphere, 0, field); }, "n must be at least 1 (got 0)");
  field[*sphere.faces().begin()] = Vector_3(std::nan(""), 0, 0);
  expect_invalid([&] { TVF::evenly_spaced_n_field_streamlines(sphere, 4, field); }, "non-finite");
}
