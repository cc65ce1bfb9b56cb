// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Streamlines of n-direction fields, one at a time: one branch followed across edges by
// matching, n = 1 being the vector tracer, the parameter lines of a torus of revolution
// traced by its cross field, invariance to which of the n vectors a face stores, stops at
// the singularities of the smoothest cross field of a sphere, refusals.

#include "n_field_streamline_support.h"

#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/Smoothest_n_field_solver.h>
#include <CGAL/Tangent_vector_fields/Streamlines.h>

#include <random>

using namespace nstream_test;

namespace {

std::vector<std::pair<int, std::array<double, 3>>> random_seeds(int faces, int count, unsigned seed)
{
  std::mt19937 gen(seed);
  std::uniform_int_distribution<int> pick(0, faces - 1);
  std::uniform_real_distribution<double> u(0.05, 1);
  std::vector<std::pair<int, std::array<double, 3>>> seeds;
  for(int i = 0; i < count; ++i) seeds.push_back({pick(gen), {u(gen), u(gen), u(gen)}});
  return seeds;
}

// The part of a streamline after the seed (with the seed), or before it (reversed).
std::vector<P3> part(const TVF::Streamline& s, bool forward)
{
  if(forward) return {s.points.begin() + static_cast<long>(s.seed_index), s.points.end()};
  std::vector<P3> p(s.points.begin(), s.points.begin() + static_cast<long>(s.seed_index) + 1);
  std::reverse(p.begin(), p.end());
  return p;
}

} // namespace

TEST(NFieldStreamlines, OneVectorPerFaceIsTheVectorTracer)
{
  // n = 1 through the n-field entry point is the vector tracer, but for the ends that run
  // into a singular vertex: there the n-field streamline is a prefix of the vector one,
  // plus the last segment to the vertex where the vector tracer stopped in a sink.
  Mesh sphere = make_icosphere(3);
  jitter_vertices(sphere, 0.2, 3);
  Field wind = ambient_field_map(sphere, "wind", 5);
  TVF::Mesh_streamline_tracer<Mesh> vector_tracer(sphere, wind);
  const Eigen::VectorXd x = vector_tracer.adapter().read_field(wind);
  const auto ops = n_field_operators(sphere, 1);
  const TVF::Streamline_tracer one(*ops, x);
  EXPECT_EQ(one.n(), 1);
  EXPECT_EQ(one.singular_vertices().size(), 2u); // the wind's source and sink, index +1 each
  int singular_ends = 0, compared = 0;
  for(const auto& seed : random_seeds(one.mesh().number_of_faces(), 300, 1))
  {
    const TVF::Streamline a = vector_tracer.tracer().trace(seed.first, seed.second);
    const TVF::Streamline b = one.trace(seed.first, seed.second);
    expect_valid_n_streamline(one.mesh(), x, 1, b);
    for(bool forward : {true, false})
    {
      const TVF::Streamline_stop stop_a = forward ? a.forward_stop : a.backward_stop;
      const TVF::Streamline_stop stop_b = forward ? b.forward_stop : b.backward_stop;
      const std::vector<P3> pa = part(a, forward), pb = part(b, forward);
      ++compared;
      if(stop_b != TVF::Streamline_stop::singular_vertex)
      {
        EXPECT_EQ(stop_a, stop_b);
        EXPECT_EQ(pa, pb);
        continue;
      }
      ++singular_ends;
      bool on_singular_vertex = false;
      for(int v : one.singular_vertices()) on_singular_vertex = on_singular_vertex || pb.back() == one.mesh().position(v);
      ASSERT_TRUE(on_singular_vertex);
      ASSERT_LE(pb.size() - 1, pa.size());
      EXPECT_TRUE(std::equal(pb.begin(), pb.end() - 1, pa.begin()));
      if(pa.size() == pb.size() - 1) // the last segment was added: the vector tracer stopped by convergence
        EXPECT_TRUE(stop_a == TVF::Streamline_stop::sink_edge || stop_a == TVF::Streamline_stop::sink_vertex ||
                    stop_a == TVF::Streamline_stop::stalled)
            << TVF::to_string(stop_a);
      else
        EXPECT_EQ(pa[pb.size() - 1], pb.back()) << "the vector streamline passes the vertex";
    }
  }
  EXPECT_GT(singular_ends, 20);
  EXPECT_LT(singular_ends, compared);

  // Without singularities (a torus and its parallels) everything is the same, bit for bit.
  const Mesh torus = make_torus(40, 16);
  const auto torus_ops = n_field_operators(torus, 1);
  const Eigen::VectorXd parallels = torus_parallels(torus_ops->mesh());
  const TVF::Streamline_tracer vectors(torus_ops->operators().shared_mesh(), parallels);
  const TVF::Streamline_tracer lines(*torus_ops, parallels);
  EXPECT_TRUE(lines.singular_vertices().empty());
  for(const auto& seed : random_seeds(torus_ops->mesh().number_of_faces(), 50, 2))
    EXPECT_EQ(vectors.trace(seed.first, seed.second).points, lines.trace(seed.first, seed.second).points);
  TVF::Evenly_spaced_options even;
  even.separation = 0.05;
  const std::vector<TVF::Streamline> ea = vectors.evenly_spaced(even), eb = lines.evenly_spaced(even);
  ASSERT_EQ(ea.size(), eb.size());
  for(std::size_t i = 0; i < ea.size(); ++i) EXPECT_EQ(ea[i].points, eb[i].points);
  TVF::Fur_options fur;
  fur.number_of_strokes = 200;
  const std::vector<TVF::Streamline> fa = vectors.fur(fur), fb = lines.fur(fur);
  ASSERT_EQ(fa.size(), fb.size());
  for(std::size_t i = 0; i < fa.size(); ++i) EXPECT_EQ(fa[i].points, fb[i].points);
}

TEST(NFieldStreamlines, CrossFieldOfATorusFollowsItsParallelsAndMeridians)
{
  // The cross field of the parallels and meridians of a torus of revolution (irregular
  // triangles, vertices on the torus): each streamline follows one family of parameter
  // lines, branches j and j + 2 give the same line, j and j + 1 the two families.
  const Mesh torus = make_torus(72, 28, torus_R, torus_r);
  const auto ops = n_field_operators(torus, 4);
  const TVF::Intrinsic_mesh& M = ops->mesh();
  const Eigen::VectorXd x = torus_parallels(M);
  const TVF::Streamline_tracer tracer(*ops, ops->from_vectors(x));
  EXPECT_TRUE(tracer.singular_vertices().empty());
  TVF::Streamline_options options;
  options.maximum_length = 4;
  double worst = 0, total = 0, drift = 0;
  int count = 0, families[2] = {0, 0};
  for(const auto& seed : random_seeds(M.number_of_faces(), 25, 3))
  {
    std::vector<TVF::Streamline> lines;
    for(int j = 0; j < 4; ++j)
    {
      options.branch = j;
      lines.push_back(tracer.trace(seed.first, seed.second, options));
      expect_valid_n_streamline(M, x, 4, lines.back());
      EXPECT_EQ(lines.back().branch, j);
    }
    for(int j = 0; j < 4; ++j)
    {
      const TVF::Streamline& s = lines[j];
      // Its family, from the first segment after the seed.
      const P3 first = unit(sub(s.points[s.seed_index + 1], s.points[s.seed_index]));
      const bool parallel = std::abs(dot(first, parallel_direction(s.points[s.seed_index]))) > 0.7;
      ++families[parallel];
      // Along a parallel the height stays, along a meridian the angle around the axis.
      const P3& q = s.points[s.seed_index];
      for(const P3& p : s.points)
        drift = std::max(drift, parallel ? std::abs(p[2] - q[2])
                                         : std::abs(std::remainder(std::atan2(p[1], p[0]) - std::atan2(q[1], q[0]), 2 * M_PI)));
      for(std::size_t i = 0; i + 1 < s.points.size(); ++i)
      {
        const P3 segment = sub(s.points[i + 1], s.points[i]);
        if(norm(segment) < 1e-6) continue;
        P3 mid;
        for(int k = 0; k < 3; ++k) mid[k] = (s.points[i][k] + s.points[i + 1][k]) / 2;
        // The parameter line's direction at the segment's middle, seen in the face's plane.
        P3 expected = parallel ? parallel_direction(mid) : meridian_direction(mid);
        const P3& normal = M.normal(s.faces[i]);
        for(int k = 0; k < 3; ++k) expected[k] -= dot(expected, normal) * normal[k];
        const double angle = degrees(std::acos(std::min(1., std::abs(dot(unit(segment), unit(expected))))));
        worst = std::max(worst, angle);
        total += angle;
        ++count;
      }
      // The opposite branch traces the same line the other way round: its forward part is
      // this one's backward part and the reverse, until one of them stops (only forward parts
      // close loops, at the point nearest to the seed).
      const TVF::Streamline& opposite = lines[(j + 2) % 4];
      if(s.closed && opposite.closed)
        EXPECT_NEAR(s.length(), opposite.length(), 0.01 * s.length());
      std::size_t common = 0;
      for(bool forward : {true, false})
      {
        const std::vector<P3> here = part(s, forward), there = part(opposite, !forward);
        const std::size_t k = std::min(here.size(), there.size());
        for(std::size_t i = 0; i + 1 < k; ++i) EXPECT_LT(norm(sub(here[i], there[i])), 1e-9);
        common = std::max(common, k);
      }
      if(!(s.closed && opposite.closed)) EXPECT_GT(common, 10u);
      // The next branch is the other family.
      const P3 next = unit(sub(lines[(j + 1) % 4].points[lines[(j + 1) % 4].seed_index + 1],
                               lines[(j + 1) % 4].points[lines[(j + 1) % 4].seed_index]));
      EXPECT_LT(std::abs(dot(first, next)), 1e-9);
    }
  }
  EXPECT_EQ(families[0], families[1]);
  EXPECT_LT(worst, 6.0) << "degrees between a segment and its parameter line";
  EXPECT_LT(total / count, 1.5) << "mean degrees between a segment and its parameter line";
  EXPECT_LT(drift, 0.05) << "off its parameter line (height or angle; the grid's steps are 0.09)";
}

TEST(NFieldStreamlines, TurningAFacesVectorByAFractionOfATurnChangesNothing)
{
  // The same n-field with each face's vector turned by a random multiple of 2 pi / n: the
  // streamlines (from the same seed, along the same vector) are the same, because each face
  // takes the vector closest to the one carried across the edge, whichever one is stored.
  Mesh sphere = make_icosphere(3);
  jitter_vertices(sphere, 0.15, 4);
  for(int n : {2, 3, 4})
  {
    SCOPED_TRACE("n = " + std::to_string(n));
    const auto ops = n_field_operators(sphere, n);
    const TVF::Intrinsic_mesh& M = ops->mesh();
    const Eigen::VectorXd z = TVF::smoothest_n_field(*ops);
    const TVF::Streamline_tracer reference(*ops, z);
    ASSERT_EQ(static_cast<int>(reference.singular_vertices().size()), 2 * n);
    const Eigen::VectorXd first = ops->to_vectors(z);
    Eigen::VectorXd turned_field(first.size());
    std::vector<int> turns(M.number_of_faces());
    std::mt19937 gen(5);
    for(int f = 0; f < M.number_of_faces(); ++f)
    {
      turns[f] = std::uniform_int_distribution<int>(0, n - 1)(gen);
      const auto ab = turned(first[2 * f], first[2 * f + 1], 2 * M_PI * turns[f] / n);
      turned_field[2 * f] = ab[0];
      turned_field[2 * f + 1] = ab[1];
    }
    const TVF::Streamline_tracer other(ops->operators().shared_mesh(), turned_field, n, reference.singular_vertices());
    int crossings = 0;
    for(const auto& seed : random_seeds(M.number_of_faces(), 40, 6))
      for(int j = 0; j < n; ++j)
      {
        TVF::Streamline_options options;
        options.branch = j;
        const TVF::Streamline a = reference.trace(seed.first, seed.second, options);
        options.branch = ((j - turns[seed.first]) % n + n) % n;
        const TVF::Streamline b = other.trace(seed.first, seed.second, options);
        expect_valid_n_streamline(M, turned_field, n, b);
        EXPECT_EQ(a.faces, b.faces);
        EXPECT_EQ(a.forward_stop, b.forward_stop);
        EXPECT_EQ(a.backward_stop, b.backward_stop);
        ASSERT_EQ(a.points.size(), b.points.size());
        for(std::size_t i = 0; i < a.points.size(); ++i) EXPECT_LT(norm(sub(a.points[i], b.points[i])), 1e-9);
        crossings += static_cast<int>(a.points.size());
      }
    EXPECT_GT(crossings, 1000);
  }
}

TEST(NFieldStreamlines, StopAtTheSingularitiesOfTheSmoothestCrossFieldOfASphere)
{
  // The smoothest cross field of a sphere has 8 singularities of index +1/4.  A streamline
  // aimed at one (seeded in a face of its one-ring, on the ray from the vertex along one of
  // the face's vectors) ends exactly on it with the singular stop; from anywhere, a singular
  // stop is on a singular vertex, and no streamline stops in a sink next to a singularity
  // (but at the length limit, which the last segment into the singularity must keep too).
  const Mesh sphere = make_icosphere(3);
  const auto ops = n_field_operators(sphere, 4);
  const TVF::Intrinsic_mesh& M = ops->mesh();
  const Eigen::VectorXd z = TVF::smoothest_n_field(*ops);
  const TVF::Streamline_tracer tracer(*ops, z);
  const std::vector<int> indices = TVF::n_field_indices(*ops, z);
  ASSERT_EQ(tracer.singular_vertices().size(), 8u);
  for(int v : tracer.singular_vertices()) EXPECT_EQ(indices[v], 1);
  const Eigen::VectorXd first = ops->to_vectors(z);
  std::vector<char> next_to_singularity(M.number_of_faces(), 0);
  for(int f = 0; f < M.number_of_faces(); ++f)
    for(int v : M.face_vertices(f)) next_to_singularity[f] |= indices[v] != 0;

  TVF::Streamline_options forward;
  forward.backward = false;
  forward.maximum_length = 3;
  for(int v : tracer.singular_vertices())
  {
    int aimed = 0;
    for(int f = 0; f < M.number_of_faces(); ++f)
    {
      const auto& t = M.face_vertices(f);
      const int m = t[0] == v ? 0 : t[1] == v ? 1 : t[2] == v ? 2 : -1;
      if(m < 0) continue;
      const P3 ea = sub(M.position(t[(m + 1) % 3]), M.position(v)), eb = sub(M.position(t[(m + 2) % 3]), M.position(v));
      for(int j = 0; j < 4; ++j)
      {
        // w = -(vector j) = alpha ea + beta eb: the ray from v against vector j, inside the
        // face if alpha, beta > 0; the seed half-way along it.
        const auto ab = turned(first[2 * f], first[2 * f + 1], 2 * M_PI * j / 4);
        const P3 w = M.from_frame(f, -ab[0], -ab[1]);
        const double d = dot(cross(ea, eb), M.normal(f));
        const double alpha = dot(cross(w, eb), M.normal(f)) / d, beta = dot(cross(ea, w), M.normal(f)) / d;
        if(!(alpha > 0.05 && beta > 0.05)) continue;
        const double lambda = 0.5 / (alpha + beta);
        std::array<double, 3> seed;
        seed[m] = 0.5;
        seed[(m + 1) % 3] = lambda * alpha;
        seed[(m + 2) % 3] = lambda * beta;
        forward.branch = j;
        const TVF::Streamline s = tracer.trace(f, seed, forward);
        expect_valid_n_streamline(M, first, 4, s);
        EXPECT_EQ(s.forward_stop, TVF::Streamline_stop::singular_vertex) << TVF::to_string(s.forward_stop);
        EXPECT_EQ(s.points.back(), M.position(v));
        EXPECT_EQ(s.number_of_segments(), 1u);
        ++aimed;
      }
    }
    EXPECT_GE(aimed, 2) << "vertex " << v;
  }
  // From random seeds everywhere.
  double longest_edge = 0;
  for(int e = 0; e < M.number_of_edges(); ++e) longest_edge = std::max(longest_edge, M.edge_length(e));
  int singular_stops = 0, limited = 0;
  for(const auto& seed : random_seeds(M.number_of_faces(), 200, 7))
    for(int j = 0; j < 4; ++j)
    {
      forward.branch = j;
      const TVF::Streamline s = tracer.trace(seed.first, seed.second, forward);
      expect_valid_n_streamline(M, first, 4, s);
      if(s.forward_stop == TVF::Streamline_stop::singular_vertex)
      {
        ++singular_stops;
        bool on_singular_corner = false;
        for(int v : M.face_vertices(s.faces.back()))
          on_singular_corner = on_singular_corner || (indices[v] != 0 && s.points.back() == M.position(v));
        EXPECT_TRUE(on_singular_corner);
      }
      else if(s.forward_stop == TVF::Streamline_stop::sink_edge || s.forward_stop == TVF::Streamline_stop::sink_vertex ||
              s.forward_stop == TVF::Streamline_stop::stalled)
      {
        // Unless the last segment into the singularity would pass the length limit.
        const bool at_the_limit = s.length() > forward.maximum_length - longest_edge;
        EXPECT_TRUE(!next_to_singularity[s.faces.back()] || at_the_limit) << TVF::to_string(s.forward_stop);
        limited += next_to_singularity[s.faces.back()];
      }
    }
  EXPECT_GT(singular_stops, 0);
  // Every such stop is explained by the length limit (checked above); that the limit falls
  // within an edge of a singularity is rare: 1 or 2 of the 800 traces, depending on the last
  // bits of the field (the solver's order of operations).
  EXPECT_LE(limited, 4);
}

TEST(NFieldStreamlines, BadInputIsRefusedWithAReason)
{
  const Mesh sphere = make_icosphere(1);
  const auto ops = n_field_operators(sphere, 4);
  const auto mesh = ops->operators().shared_mesh();
  const int nf = mesh->number_of_faces();
  const Eigen::VectorXd z = Eigen::VectorXd::Ones(2 * nf);
  expect_invalid([&] { TVF::Streamline_tracer(mesh, Eigen::VectorXd::Ones(3), 4); }, "the field has 3 frame coordinates");
  expect_invalid([&] { TVF::Streamline_tracer(mesh, z, 0); }, "n must be at least 1 (got 0)");
  Eigen::VectorXd nan = z;
  nan[7] = std::nan("");
  expect_invalid([&] { TVF::Streamline_tracer(mesh, nan, 4); }, "non-finite");
  expect_invalid([&] { TVF::Streamline_tracer(*ops, nan); }, "n-field streamlines: the field has non-finite entries");
  expect_invalid([&] { TVF::Streamline_tracer(*ops, Eigen::VectorXd::Ones(2 * nf + 2)); },
                 "n-field streamlines: the field has " + std::to_string(2 * nf + 2) + " entries");
  expect_invalid([&] { TVF::Streamline_tracer(mesh, z, 4, {0, mesh->number_of_vertices()}); },
                 "singular vertex " + std::to_string(mesh->number_of_vertices()) + " does not exist");
  const TVF::Streamline_tracer tracer(*ops, z);
  TVF::Streamline_options options;
  for(int branch : {-1, 4})
  {
    options.branch = branch;
    expect_invalid([&] { tracer.trace(0, {1, 1, 1}, options); },
                   "branch " + std::to_string(branch) + " asked of a field of 4 vector(s) per face");
  }
  TVF::Fur_options fur;
  fur.number_of_strokes = 10;
  for(int branch : {-2, 4})
  {
    fur.branch = branch;
    expect_invalid([&] { tracer.fur(fur); },
                   "fur: branch " + std::to_string(branch) + " asked of a field of 4 vector(s) per face (-1: all)");
  }
  TVF::Evenly_spaced_options even;
  even.tracing.branch = 1;
  expect_invalid([&] { tracer.evenly_spaced(even); }, "tracing.branch must be 0");
}

