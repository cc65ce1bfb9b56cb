// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// n-direction fields (SPEC 10), design: splines reduced and full (constraints met,
// stationarity, convergence in d, rotation, invariance), prescribed singularities by one-ring
// relations and by the modified connection, refusals, constraint files.  The basis itself:
// test_n_field_basis.cpp.

#include "n_field_test_support.h"
#include "scratch_path.h"

#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/N_field_spline.h>
#include <CGAL/Tangent_vector_fields/N_field_spline_solver.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/n_field_constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/smoothest_n_field.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <fstream>
#include <numeric>
#include <set>
#include <sstream>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;
using namespace nfield_test;

TEST(NFieldSpline, ReducedConvergesToTheFullSplineWhichMeetsItsConstraints)
{
  Mesh torus = make_torus(24, 16);
  jitter_vertices(torus, 0.05, 19);
  const auto ops = n_field_operators(torus, 4);
  const auto constraints = random_vector_constraints(ops->mesh(), 6, 23);
  TVF::Full_n_field_spline_solver full(ops);
  full.add(constraints);
  const Eigen::VectorXd exact = full.field();
  for(const auto& c : constraints) EXPECT_LT(closest_vector_distance(*ops, exact, c.face, c.vector), 1e-9);
  // Stationarity, from S_n alone: S MX^-1 S z vanishes on every unconstrained face.
  const Eigen::VectorXd gradient = ops->S() * ops->laplacian(exact);
  std::vector<char> constrained(ops->mesh().number_of_faces(), 0);
  for(const auto& c : constraints) constrained[c.face] = 1;
  double free_part = 0;
  for(int f = 0; f < ops->mesh().number_of_faces(); ++f)
    if(!constrained[f]) free_part = std::max(free_part, gradient.segment<2>(2 * f).norm());
  EXPECT_LT(free_part, 1e-8 * gradient.cwiseAbs().maxCoeff());

  const auto basis = std::make_shared<const TVF::N_field_basis>(ops, 300);
  double previous_error = std::numeric_limits<double>::infinity(), previous_energy = previous_error;
  for(int d : {30, 100, 300})
  {
    TVF::Reduced_n_field_spline_solver reduced(basis, d);
    reduced.add(constraints);
    const Eigen::VectorXd z = reduced.field();
    for(const auto& c : constraints) EXPECT_LT(closest_vector_distance(*ops, z, c.face, c.vector), 1e-9) << "d = " << d;
    const double error = relative_difference(z, exact, ops->masses());
    const double energy = ops->m_harmonic_energy(z, 2);
    EXPECT_LT(error, previous_error) << "d = " << d;
    EXPECT_LT(energy, previous_energy) << "d = " << d;
    EXPECT_GE(energy, ops->m_harmonic_energy(exact, 2) * (1 - 1e-9)) << "d = " << d;
    previous_error = error;
    previous_energy = energy;
  }
  EXPECT_LT(previous_error, 0.1);
}

TEST(NFieldSpline, TurningTheConstraintsTurnsTheField)
{
  // Every constraint vector turned by alpha about its face's normal: the n-field's power
  // turns by n alpha everywhere, exactly (reduced: the basis is closed under i).
  Mesh torus = make_torus(16, 10);
  jitter_vertices(torus, 0.05, 29);
  const auto ops = n_field_operators(torus, 3);
  const auto constraints = random_vector_constraints(ops->mesh(), 4, 31);
  const double alpha = 0.4;
  std::vector<TVF::N_field_constraint> turned = constraints;
  for(auto& c : turned)
  {
    const auto ab = ops->mesh().to_frame(c.face, c.vector);
    c.vector = ops->mesh().from_frame(c.face, std::cos(alpha) * ab[0] - std::sin(alpha) * ab[1],
                                      std::sin(alpha) * ab[0] + std::cos(alpha) * ab[1]);
  }
  const auto basis = std::make_shared<const TVF::N_field_basis>(ops, 40);
  auto turn = [&](const Eigen::VectorXd& z) {
    Eigen::VectorXd r(z.size());
    const std::complex<double> w = std::polar(1., 3 * alpha);
    for(Eigen::Index f = 0; f < z.size() / 2; ++f)
    {
      const std::complex<double> x = w * std::complex<double>(z[2 * f], z[2 * f + 1]);
      r[2 * f] = x.real();
      r[2 * f + 1] = x.imag();
    }
    return r;
  };
  TVF::Full_n_field_spline_solver full(ops), full_turned(ops);
  full.add(constraints);
  full_turned.add(turned);
  EXPECT_LT(relative_difference(full_turned.field(), turn(full.field()), ops->masses()), 1e-9);
  TVF::Reduced_n_field_spline_solver reduced(basis, 40), reduced_turned(basis, 40);
  reduced.add(constraints);
  reduced_turned.add(turned);
  EXPECT_LT(relative_difference(reduced_turned.field(), turn(reduced.field()), ops->masses()), 1e-9);
}

TEST(NFieldSpline, OneRingSingularityConstraintsGiveExactlyTheirIndex)
{
  // One-ring relations (N_field_constraint::singularity_at_vertex) fix the index at their
  // vertex exactly, anchored or not.  They do not keep opposite singularities off the
  // neighbouring vertices: measured over 20 random pairs (+1/4, -1/4) on this torus, some
  // neighbour was singular in 15 (unanchored), 2 (anchored, m = 1) and 8 (anchored, m = 2)
  // pairs; the modified connection (next test) is the formulation that does.
  Mesh torus = make_torus(24, 16);
  jitter_vertices(torus, 0.05, 37);
  const auto ops = n_field_operators(torus, 4);
  const TVF::Intrinsic_mesh& mesh = ops->mesh();
  const int plus = 0, minus = mesh.number_of_vertices() / 2;
  const auto vector = random_vector_constraints(mesh, 1, 41);
  auto anchored = [&](int v, int k) {
    const int f = ops->vertex_fan(v).faces[0];
    return TVF::N_field_constraint::singularity_at_vertex(v, k, f, mesh.from_frame(f, 1, 0));
  };
  for(bool anchor : {false, true})
    for(int order : {1, 2})
    {
      std::vector<TVF::N_field_constraint> constraints = vector;
      constraints.push_back(anchor ? anchored(plus, 1) : TVF::N_field_constraint::singularity_at_vertex(plus, 1));
      constraints.push_back(anchor ? anchored(minus, -1) : TVF::N_field_constraint::singularity_at_vertex(minus, -1));
      TVF::Full_n_field_spline_solver full(ops, TVF::Spline_options(), order);
      full.add(constraints);
      const std::vector<int> k = TVF::n_field_indices(*ops, full.field());
      EXPECT_EQ(k[plus], 1) << "m = " << order << (anchor ? ", anchored" : "");
      EXPECT_EQ(k[minus], -1) << "m = " << order << (anchor ? ", anchored" : "");
      EXPECT_EQ(std::accumulate(k.begin(), k.end(), 0), 0);
    }
}

TEST(NFieldSingularities, ModifiedConnectionPrescribesExactlyTheGivenSingularities)
{
  // Sphere, n = 4: eight +1/4 at the vertices nearest the corners of a cube sum to n chi;
  // the other vertices keep their angle defect less its mean, nearly 0 on a sphere, so the
  // smoothest field is singular exactly there.  Then the same with vectors constrained (full
  // spline, m = 1 and 2), and on a flat disk with a +1/4 and a -1/4 (the boundary takes the
  // rest): the connection is then flat elsewhere, and its smoothest field parallel.
  const Mesh sphere = make_icosphere(3);
  TVF::Discrete_operators<Mesh> sphere_ops(sphere);
  const TVF::Intrinsic_mesh& mesh = sphere_ops.intrinsic_mesh();
  TVF::N_field_options options;
  for(int corner = 0; corner < 8; ++corner)
  {
    const Eigen::Vector3d d(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
    int best = 0;
    for(int v = 1; v < mesh.number_of_vertices(); ++v)
      if(to_eigen(mesh.position(v)).dot(d) > to_eigen(mesh.position(best)).dot(d)) best = v;
    options.singularities.push_back({best, 1});
  }
  const auto ops = std::make_shared<const TVF::N_field_operators>(sphere_ops.shared_matrices(), 4, options);
  auto expect_exactly = [&](const TVF::N_field_operators& o, const Eigen::VectorXd& z, const std::string& what) {
    std::vector<TVF::N_field_singularity> expected;
    for(const auto& [v, k] : o.options().singularities) expected.push_back({v, k, false});
    std::sort(expected.begin(), expected.end(), [](const auto& a, const auto& b) { return a.vertex < b.vertex; });
    std::vector<TVF::N_field_singularity> found;
    for(const auto& s : TVF::n_field_singularities(o, z))
      if(!s.on_boundary) found.push_back(s);
    ASSERT_EQ(found.size(), expected.size()) << what;
    for(std::size_t i = 0; i < found.size(); ++i)
    {
      EXPECT_EQ(found[i].vertex, expected[i].vertex) << what;
      EXPECT_EQ(found[i].index, expected[i].index) << what;
    }
  };
  const Eigen::VectorXd smoothest = TVF::smoothest_n_field(*ops);
  expect_exactly(*ops, smoothest, "smoothest");
  for(int order : {1, 2})
  {
    TVF::Full_n_field_spline_solver full(ops, TVF::Spline_options(), order);
    full.add(random_vector_constraints(mesh, 3, 43));
    expect_exactly(*ops, full.field(), "spline m = " + std::to_string(order));
  }

  const Mesh disk = make_disk(8);
  TVF::Discrete_operators<Mesh> disk_ops(disk);
  TVF::N_field_options disk_options;
  // Vertex 0 is the centre; a vertex on the fourth ring is far from it and from the boundary.
  const int ring4 = 1 + 6 + 12 + 18 + 3;
  disk_options.singularities = {{0, 1}, {ring4, -1}};
  const auto disk_n = std::make_shared<const TVF::N_field_operators>(disk_ops.shared_matrices(), 4, disk_options);
  EXPECT_EQ(disk_n->kernel().cols(), 2);
  expect_exactly(*disk_n, TVF::smoothest_n_field(*disk_n), "flat disk");

  // Refusals name the vertex and the reason.
  TVF::N_field_options bad;
  bad.singularities = {{0, 1}, {0, 2}};
  try
  {
    TVF::N_field_operators(disk_ops.shared_matrices(), 4, bad);
    ADD_FAILURE() << "a vertex prescribed twice was accepted";
  }
  catch(const TVF::Invalid_input& e)
  {
    EXPECT_NE(std::string(e.what()).find("prescribed twice"), std::string::npos) << e.what();
  }
}

TEST(NFieldSpline, BadConstraintsAreRefusedWithTheirReason)
{
  const Mesh disk = make_curved_disk(5, 0.3);
  const auto ops = n_field_operators(disk, 4);
  TVF::Full_n_field_spline_solver full(ops);
  auto reason = [&](const TVF::N_field_constraint& c) {
    try
    {
      full.add(c);
    }
    catch(const TVF::Invalid_input& e)
    {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  int boundary_vertex = -1;
  for(int e = 0; e < ops->mesh().number_of_edges() && boundary_vertex < 0; ++e)
    if(ops->mesh().is_boundary_edge(e)) boundary_vertex = ops->mesh().edge_vertices(e)[0];
  EXPECT_NE(reason(TVF::N_field_constraint::singularity_at_vertex(boundary_vertex, 1)).find("on the boundary"),
            std::string::npos);
  EXPECT_NE(reason(TVF::N_field_constraint::singularity_at_vertex(ops->mesh().number_of_vertices(), 1)).find("no such vertex"),
            std::string::npos);
  EXPECT_NE(reason(TVF::N_field_constraint::direction_in_face(0, {0, 0, 0})).find("direction is zero"), std::string::npos);
  const auto normal = ops->mesh().normal(0);
  EXPECT_NE(reason(TVF::N_field_constraint::vector_in_face(0, normal)).find("normal to its face"), std::string::npos);
  EXPECT_NE(reason(TVF::N_field_constraint::vector_in_face(0, {NAN, 0, 0})).find("not finite"), std::string::npos);
  // A vector twice with another value: contradictory, refused with the residual.
  const auto v = ops->mesh().from_frame(3, 1, 0);
  full.add(TVF::N_field_constraint::vector_in_face(3, v));
  try
  {
    full.add(TVF::N_field_constraint::vector_in_face(3, ops->mesh().from_frame(3, 0, 2)));
    ADD_FAILURE() << "a contradictory constraint was accepted";
  }
  catch(const TVF::Infeasible_constraints& e)
  {
    EXPECT_NE(std::string(e.what()).find("depends on the constraints already set"), std::string::npos) << e.what();
    EXPECT_GT(e.residual(), 0.5);
  }
  EXPECT_EQ(full.number_of_constraints(), 1);
  const auto basis = std::make_shared<const TVF::N_field_basis>(ops, 10);
  try
  {
    TVF::Reduced_n_field_spline_solver odd(basis, 9);
    ADD_FAILURE() << "an odd basis size was accepted";
  }
  catch(const TVF::Invalid_input& e)
  {
    EXPECT_NE(std::string(e.what()).find("must be even"), std::string::npos) << e.what();
  }
}

TEST(NFieldSpline, InvariantToScaleAndRigidMotion)
{
  // The same constraints (vectors moved with the mesh) on the mesh scaled by 1e-8 and 1e8 and
  // moved: the same field (frame coordinates are intrinsic), full and reduced.
  Mesh reference = make_torus(16, 10);
  jitter_vertices(reference, 0.05, 47);
  const auto ops0 = n_field_operators(reference, 2);
  const auto constraints = random_vector_constraints(ops0->mesh(), 5, 53);
  TVF::Full_n_field_spline_solver full0(ops0);
  full0.add(constraints);
  const auto basis0 = std::make_shared<const TVF::N_field_basis>(ops0, 60);
  TVF::Reduced_n_field_spline_solver reduced0(basis0, 60);
  reduced0.add(constraints);
  const auto R = rotation_matrix(Vector_3(1, -2, 0.5), 1.1);
  for(double s : {1e-8, 1e8})
  {
    Mesh mesh = reference;
    transform(mesh, s, R, Vector_3(-2 * s, 7 * s, 3 * s));
    const auto ops = n_field_operators(mesh, 2);
    std::vector<TVF::N_field_constraint> moved = constraints;
    for(auto& c : moved)
    {
      const auto& v = c.vector;
      c.vector = {s * (R[0] * v[0] + R[1] * v[1] + R[2] * v[2]), s * (R[3] * v[0] + R[4] * v[1] + R[5] * v[2]),
                  s * (R[6] * v[0] + R[7] * v[1] + R[8] * v[2])};
    }
    TVF::Full_n_field_spline_solver full(ops);
    full.add(moved);
    EXPECT_LT((full.field() / s - full0.field()).norm(), 1e-8 * full0.field().norm()) << "scale " << s;
    const auto basis = std::make_shared<const TVF::N_field_basis>(ops, 60);
    TVF::Reduced_n_field_spline_solver reduced(basis, 60);
    reduced.add(moved);
    EXPECT_LT((reduced.field() / s - reduced0.field()).norm(), 1e-6 * reduced0.field().norm()) << "scale " << s;
  }
}

TEST(NFieldSpline, GenericInterfaceFullAndReduced)
{
  Mesh sphere = make_icosphere(3);
  auto out = sphere.add_property_map<Face_index, Vector_3>("f:lines", Vector_3(0, 0, 0)).first;
  auto index = sphere.add_property_map<Vertex_index, int>("v:k", 0).first;
  const Face_index f(7), g(300);
  auto edge_of = [&](Face_index h) {
    const auto e = sphere.halfedge(h);
    return sphere.point(sphere.target(e)) - sphere.point(sphere.source(e));
  };
  TVF::N_field_spline<Mesh> exact(sphere, 2);
  exact.add_vector(f, edge_of(f));
  const TVF::Constraint_id id = exact.add_vector(g, edge_of(g));
  exact.field(out);
  // A line field: the constrained face carries the vector or its opposite.
  const Vector_3 e = edge_of(f), u = out[f];
  EXPECT_LT(std::min((u - e).squared_length(), (u + e).squared_length()), 1e-18 * e.squared_length());
  int sum = 0;
  for(const auto& s : exact.singularities(index)) sum += s.second;
  EXPECT_EQ(sum, 4); // n chi
  exact.set_vector(id, -edge_of(g)); // the same line: the same field
  auto again = sphere.add_property_map<Face_index, Vector_3>("f:again", Vector_3(0, 0, 0)).first;
  exact.field(again);
  for(Face_index h : sphere.faces()) EXPECT_LT((again[h] - out[h]).squared_length(), 1e-20);

  TVF::N_field_spline<Mesh> reduced(sphere, 2, TVF::parameters::number_of_eigenfields(81));
  ASSERT_TRUE(reduced.basis());
  EXPECT_EQ(reduced.basis()->size(), 82);
  reduced.add_vector(f, edge_of(f));
  auto unit = sphere.add_property_map<Face_index, Vector_3>("f:unit", Vector_3(0, 0, 0)).first;
  reduced.field(unit, true);
  EXPECT_NEAR(unit[f].squared_length(), 1., 1e-12);
}

TEST(NFieldConstraintFile, RoundTripAndRefusalsWithTheirReason)
{
  const Mesh disk = make_curved_disk(5, 0.3);
  TVF::Discrete_operators<Mesh> ops(disk);
  const TVF::Intrinsic_mesh& mesh = ops.intrinsic_mesh();
  int interior = -1, boundary = -1;
  std::vector<char> on_boundary(mesh.number_of_vertices(), 0);
  for(int e = 0; e < mesh.number_of_edges(); ++e)
    if(mesh.is_boundary_edge(e))
      for(int v : mesh.edge_vertices(e)) on_boundary[v] = 1;
  for(int v = 0; v < mesh.number_of_vertices(); ++v) (on_boundary[v] ? boundary : interior) = v;
  const auto nops = std::make_shared<const TVF::N_field_operators>(ops.shared_matrices(), 4);
  TVF::N_field_constraint_file file;
  file.n = 4;
  file.omega = 0.25;
  file.order = 1;
  file.singularities = {{interior, -1}};
  file.constraints = random_vector_constraints(mesh, 2, 59);
  file.constraints.push_back(TVF::N_field_constraint::direction_in_face(5, mesh.from_frame(5, 0.3, 0.7)));
  file.constraints.push_back(
      TVF::N_field_constraint::vector_at_point(9, {0.1, 0.7, 0.2}, mesh.from_frame(9, 0.5, 1.0 / 7)));
  const int anchor = nops->vertex_fan(interior).faces[1];
  file.constraints.push_back(TVF::N_field_constraint::singularity_at_vertex(interior, 1, anchor, mesh.from_frame(anchor, 0.1, 1.0 / 3)));
  std::stringstream text;
  TVF::write_n_field_constraint_file(text, file, mesh);
  const TVF::N_field_constraint_file read = TVF::read_n_field_constraint_file(text, ops.shared_matrices());
  EXPECT_EQ(read.n, 4);
  EXPECT_EQ(read.omega, 0.25);
  EXPECT_EQ(read.order, 1);
  EXPECT_EQ(read.singularities, file.singularities);
  ASSERT_EQ(read.constraints.size(), file.constraints.size());
  for(std::size_t i = 0; i < read.constraints.size(); ++i)
  {
    EXPECT_EQ(read.constraints[i].kind, file.constraints[i].kind);
    EXPECT_EQ(read.constraints[i].face, file.constraints[i].face);
    EXPECT_EQ(read.constraints[i].vertex, file.constraints[i].vertex);
    EXPECT_EQ(read.constraints[i].index, file.constraints[i].index);
    EXPECT_EQ(read.constraints[i].vector, file.constraints[i].vector); // bit for bit (17 digits)
    EXPECT_EQ(read.constraints[i].barycentric, file.constraints[i].barycentric);
  }
  auto reason = [&](const std::string& json) {
    std::istringstream in(json);
    try
    {
      TVF::read_n_field_constraint_file(in, ops.shared_matrices());
    }
    catch(const TVF::Invalid_input& e)
    {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  auto contains = [](const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; };
  EXPECT_TRUE(contains(reason(R"({"constraints": []})"), "missing \"n\"")) << reason(R"({"constraints": []})");
  EXPECT_TRUE(contains(reason(R"({"n": 0, "constraints": []})"), "at least 1"));
  EXPECT_TRUE(contains(reason(R"({"n": 4, "constraints": [{"type": "twist", "face": 1}]})"), "constraint 0: unknown type"));
  EXPECT_TRUE(contains(reason(R"({"n": 4, "constraints": [{"type": "vector", "face": 1, "vector": [0, 0]}]})"),
                       "array of 3 numbers"));
  const std::string at_boundary = R"({"n": 4, "singularities": [{"vertex": )" + std::to_string(boundary) +
                                  R"(, "index": 1}], "constraints": []})";
  EXPECT_TRUE(contains(reason(at_boundary), "on the boundary")) << reason(at_boundary);
  const std::string ring_too_far = R"({"n": 4, "constraints": [{"type": "singularity", "vertex": )" +
                                   std::to_string(interior) + R"(, "index": 9}]})";
  EXPECT_TRUE(contains(reason(ring_too_far), "constraint 0")) << reason(ring_too_far);
  EXPECT_TRUE(contains(reason("{\"n\": 4,\n \"constraints\": [,]}"), "line 2"));
  // Misspelt and repeated keys are refused, naming the key.
  EXPECT_TRUE(contains(reason(R"({"n": 4, "ordre": 1, "constraints": []})"), "unknown key \"ordre\""));
  EXPECT_TRUE(contains(reason(R"({"n": 4, "n": 2, "constraints": []})"), "the key \"n\" appears twice"));
  EXPECT_TRUE(contains(reason(R"({"n": 4, "constraints": [{"type": "vector", "face": 1, "vector": [1, 0, 0], "wieght": 1}]})"),
                       "unknown key \"wieght\" for a vector constraint"));
  EXPECT_TRUE(contains(reason(R"({"n": 4, "singularities": [{"vertex": 3, "idx": 1}], "constraints": []})"),
                       "singularity 0: unknown key \"idx\""));
}

TEST(NFieldSpline, OneRingSingularityInAReducedBasis)
{
  // A basis that resolves the one-ring (about one eigenfield per 350 faces, measured) meets the
  // relations: the reduced spline has exactly the prescribed index there.  320 faces, d = 60.
  Mesh torus = make_torus(16, 10);
  jitter_vertices(torus, 0.05, 61);
  const auto ops = n_field_operators(torus, 4);
  const auto basis = std::make_shared<const TVF::N_field_basis>(ops, 60);
  TVF::Reduced_n_field_spline_solver reduced(basis, 60);
  reduced.add(random_vector_constraints(ops->mesh(), 2, 67));
  const int v = 5;
  reduced.add(TVF::N_field_constraint::singularity_at_vertex(v, -1));
  EXPECT_EQ(TVF::n_field_indices(*ops, reduced.field())[v], -1);
  EXPECT_LT(reduced.report().constraint_residual, 1e-9);
}

TEST(NFieldSpline, GenericInterfaceOnALoadedBasis)
{
  Mesh sphere = make_icosphere(2);
  TVF::N_field_spline<Mesh> computed(sphere, 2, TVF::parameters::number_of_eigenfields(40));
  const std::string path = scratch_path("sphere2.tvfn");
  computed.basis()->save(path);
  TVF::Discrete_operators<Mesh> ops(sphere);
  const auto nops = std::make_shared<const TVF::N_field_operators>(ops.shared_matrices(), 2);
  const auto loaded = std::make_shared<const TVF::N_field_basis>(TVF::N_field_basis::load(nops, path));
  TVF::N_field_spline<Mesh> reused(sphere, loaded);
  const Face_index f(11);
  const auto h = sphere.halfedge(f);
  const Vector_3 v = sphere.point(sphere.target(h)) - sphere.point(sphere.source(h));
  computed.add_vector(f, v);
  reused.add_vector(f, v);
  auto a = sphere.add_property_map<Face_index, Vector_3>("f:a", Vector_3(0, 0, 0)).first;
  auto b = sphere.add_property_map<Face_index, Vector_3>("f:b", Vector_3(0, 0, 0)).first;
  computed.field(a);
  reused.field(b);
  for(Face_index g : sphere.faces()) EXPECT_EQ(a[g], b[g]);
}

TEST(NFieldSpline, RefusedTensionLeavesTheSolverAsItWas)
{
  // m = 3 supports omega = 0 only at full resolution: set_omega(1) is refused with its reason,
  // and the solver keeps its tension and answer.
  Mesh torus = make_torus(12, 8);
  jitter_vertices(torus, 0.05, 73);
  const auto ops = n_field_operators(torus, 2);
  TVF::Full_n_field_spline_solver full(ops, TVF::Spline_options(), 3);
  full.add(random_vector_constraints(ops->mesh(), 3, 79));
  const Eigen::VectorXd before = full.field();
  try
  {
    full.set_omega(1);
    ADD_FAILURE() << "omega > 0 with m = 3 was accepted";
  }
  catch(const TVF::Invalid_input& e)
  {
    EXPECT_NE(std::string(e.what()).find("m = 1 or 2 only"), std::string::npos) << e.what();
  }
  EXPECT_EQ(full.options().omega, 0.);
  EXPECT_LT((full.field() - before).norm(), 1e-12 * before.norm());
}
