// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The reduced simulator's saved precomputation (.pdr): it loads to the same trajectory, bit for
// bit, and is refused for another model or other reduction options, or when truncated or
// corrupt; the precomputation reports its progress and can be cancelled.

#include "expect_reason.h"
#include "pd_reduced_test_support.h"
#include "scratch_path.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace PD = CGAL::Projective_dynamics;
namespace params = PD::parameters;
using pd_test::box_model;
using pd_test::small_box;
using pd_test::small_hyper;

namespace {

std::vector<char> file_bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_bytes(const std::string& path, const std::vector<char>& bytes, std::size_t count)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(count));
}

// A scene: gravity, a floor the box falls onto, one pinned corner; `steps` steps.
std::vector<PD::Positions> trajectory(PD::Reduced_simulator& sim, int steps)
{
  sim.set_pinned_vertices({0});
  sim.add_floor({0, 0, -0.1}, {0, 0, 1});
  std::vector<PD::Positions> out;
  for(int t = 0; t < steps; ++t) sim.step(), out.push_back(sim.positions());
  return out;
}

PD::Elastic_model model_of(const PD::Tet_mesh& mesh)
{
  return PD::make_solid_model(mesh, params::strain_stiffness(1e4).density(1e3));
}

// The box's tetrahedra in two groups (halves of 162), of stiffness 1e4 and 2e4.
PD::Elastic_model two_group_box()
{
  const PD::Tet_mesh mesh = small_box();
  PD::Positions x(Eigen::Index(mesh.points.size()), 3);
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
    for(int c = 0; c < 3; ++c) x(Eigen::Index(i), c) = mesh.points[i][std::size_t(c)];
  PD::Elastic_model model(x, PD::lumped_masses(mesh.points, mesh.tetrahedra, 1e3));
  const std::size_t half = mesh.tetrahedra.size() / 2;
  model.add_tet_strain({mesh.tetrahedra.begin(), mesh.tetrahedra.begin() + std::ptrdiff_t(half)}, 1e4);
  model.add_tet_strain({mesh.tetrahedra.begin() + std::ptrdiff_t(half), mesh.tetrahedra.end()}, 2e4);
  return model;
}

} // namespace

TEST(ProjectiveDynamicsReduced, SavedPrecomputationLoadsToTheSameTrajectory)
{
  for(bool hyper : {false, true})
  {
    PD::Reduction_options r = small_hyper();
    r.hyper_reduction = hyper;
    PD::Simulator_options o;
    o.time_step = 1.0 / 60;
    const std::string path = tvf_test::scratch_path(hyper ? "hyper.pdr" : "reduced.pdr");
    PD::Reduced_simulator made(box_model(), o, r);
    made.save(path);
    // Loaded with another time step, iterations and stiffness, then given the saved ones: only
    // K depends on them.
    PD::Simulator_options other = o;
    other.time_step = 1.0 / 30, other.iterations = 3;
    PD::Reduced_simulator loaded = PD::Reduced_simulator::load(box_model(5e3), path, other, r);
    EXPECT_EQ(loaded.dimension(), made.dimension());
    EXPECT_EQ(loaded.samples(), made.samples());
    EXPECT_EQ(loaded.sampled_elements(), made.sampled_elements());
    EXPECT_EQ(loaded.used_vertices(), made.used_vertices());
    loaded.set_time_step(o.time_step);
    loaded.set_iterations(o.iterations);
    loaded.set_stiffness(0, 1e4);
    const std::vector<PD::Positions> a = trajectory(made, 40), b = trajectory(loaded, 40);
    double largest = 0;
    for(std::size_t t = 0; t < a.size(); ++t) largest = std::max(largest, (a[t] - b[t]).cwiseAbs().maxCoeff());
    EXPECT_EQ(largest, 0.0) << "hyper " << hyper << ": the loaded simulator's trajectory differs";
    // It moved (fell onto the floor), so the comparison says something.
    EXPECT_GT((a.back() - box_model().rest_positions()).norm(), 0.01) << "hyper " << hyper;
    // Two element groups, each with its own stiffness, saved and loaded.
    {
      PD::Reduced_simulator two(two_group_box(), o, r);
      two.save(path);
      PD::Reduced_simulator again = PD::Reduced_simulator::load(two_group_box(), path, o, r);
      EXPECT_EQ(trajectory(two, 10).back(), trajectory(again, 10).back()) << "hyper " << hyper << ", two groups";
      EXPECT_THROW_REASON(PD::Reduced_simulator::load(box_model(), path, o, r), PD::Invalid_input, "made for 2 element groups, the model has 1");
      made.save(path);
    }
    // The named-parameter form, and its own stiffness and density (masses are not saved).
    if(hyper)
      EXPECT_NO_THROW(PD::Reduced_simulator::load(
          PD::make_solid_model(small_box(), params::strain_stiffness(2e4).density(500)), path,
          params::number_of_samples(12).number_of_constraint_samples(20).number_of_projection_columns(40)
              .number_of_sampled_elements(80).pin_stiffness(10).time_step(0.01)));
  }
}

TEST(ProjectiveDynamicsReduced, SavedExplicitBasisLoadsToTheSameTrajectory)
{
  // An explicit basis (the identity, every element projected) is saved as well; its samples
  // option is not compared.
  const PD::Elastic_model model = box_model();
  const int n = model.number_of_vertices();
  Eigen::SparseMatrix<double, Eigen::RowMajor> identity(n, n);
  identity.setIdentity();
  PD::Reduction_options r = small_hyper();
  r.hyper_reduction = false;
  const PD::Simulator_options o;
  const std::string path = tvf_test::scratch_path("identity.pdr");
  PD::Reduced_simulator made(model, identity, o, r);
  made.save(path);
  r.samples = 3;
  PD::Reduced_simulator loaded = PD::Reduced_simulator::load(model, path, o, r);
  EXPECT_TRUE(loaded.samples().empty());
  EXPECT_EQ(trajectory(made, 10).back(), trajectory(loaded, 10).back());
  r.hyper_reduction = true;
  EXPECT_THROW_REASON(PD::Reduced_simulator::load(model, path, o, r), PD::Invalid_input, "hyper_reduction false in the file, true given");
}

TEST(ProjectiveDynamicsReduced, LoadRefusesAnotherModelOrOptions)
{
  const std::string path = tvf_test::scratch_path("box.pdr");
  const PD::Simulator_options o;
  const PD::Reduction_options r = small_hyper();
  PD::Reduced_simulator(box_model(), o, r).save(path);
  auto load = [&](const PD::Elastic_model& model, const PD::Reduction_options& options) {
    PD::Reduced_simulator::load(model, path, o, options);
  };
  EXPECT_NO_THROW(load(box_model(), r));
  // One vertex moved by 1 mm.
  PD::Tet_mesh moved = small_box();
  moved.points[7][1] += 1e-3;
  EXPECT_THROW_REASON(load(model_of(moved), r), PD::Invalid_input, "it belongs to a mesh with other edge lengths");
  // Another mesh.
  EXPECT_THROW_REASON(load(model_of(PD::make_tet_box(5, 3, 3, {0, 0, 0}, {1.2, .6, .6})), r), PD::Invalid_input,
                      "it belongs to a mesh with other connectivity");
  // The same mesh moved as a whole (the basis holds rest coordinates).
  PD::Tet_mesh shifted = small_box();
  for(auto& p : shifted.points) p[0] += 1;
  EXPECT_THROW_REASON(load(model_of(shifted), r), PD::Invalid_input, "its rest positions are elsewhere");
  // Other strain limits: other projections, other projection subspaces.
  EXPECT_THROW_REASON(load(PD::make_solid_model(small_box(), params::strain_stiffness(1e4).density(1e3).strain_limits(std::make_pair(0.9, 1.1))), r),
                      PD::Invalid_input, "element group 0 has other constraint sets");
  // A second element group.
  {
    PD::Elastic_model two = box_model();
    two.add_springs(std::vector<PD::Edge>{PD::Edge{{0, 1}}}, 10);
    EXPECT_THROW_REASON(load(two, r), PD::Invalid_input, "connectivity");
  }
  // Other reduction options, each named.
  PD::Reduction_options other = r;
  other.samples = 10;
  EXPECT_THROW_REASON(load(box_model(), other), PD::Invalid_input,
                      "made with other reduction options: number_of_samples 12 in the file, 10 given");
  other = r, other.radius_multiplier = 1.2;
  EXPECT_THROW_REASON(load(box_model(), other), PD::Invalid_input, "radius_multiplier 1.1 in the file, 1.2 given");
  other = r, other.projection_columns = 30;
  EXPECT_THROW_REASON(load(box_model(), other), PD::Invalid_input, "number_of_projection_columns 40 in the file, 30 given");
  other = r, other.sampled_elements = 90;
  EXPECT_THROW_REASON(load(box_model(), other), PD::Invalid_input, "number_of_sampled_elements 80 in the file, 90 given");
  other = r, other.constraint_samples = 21;
  EXPECT_THROW_REASON(load(box_model(), other), PD::Invalid_input, "number_of_constraint_samples 20 in the file, 21 given");
  other = r, other.hyper_reduction = false;
  EXPECT_THROW_REASON(load(box_model(), other), PD::Invalid_input, "hyper_reduction true in the file, false given");
  // The pin stiffness is a run-time parameter.
  other = r, other.pin_stiffness = 5;
  EXPECT_NO_THROW(load(box_model(), other));
  // No file, and a file of something else.
  EXPECT_THROW_REASON(PD::Reduced_simulator::load(box_model(), path + ".missing", o, r), PD::Invalid_input,
                      "cannot open the reduced simulator file");
  const std::string text = tvf_test::scratch_path("not.pdr");
  std::ofstream(text) << "MeshVersionFormatted 2\nDimension 3\nVertices\n0\nEnd\n";
  EXPECT_THROW_REASON(PD::Reduced_simulator::load(box_model(), text, o, r), PD::Invalid_input, "not a reduced simulator file");
}

TEST(ProjectiveDynamicsReduced, TruncatedOrCorruptFileRefused)
{
  const std::string path = tvf_test::scratch_path("whole.pdr"), bad = tvf_test::scratch_path("bad.pdr");
  const PD::Simulator_options o;
  const PD::Reduction_options r = small_hyper();
  const PD::Elastic_model model = box_model();
  PD::Reduced_simulator(model, o, r).save(path);
  const std::vector<char> bytes = file_bytes(path);
  ASSERT_GT(bytes.size(), 1000u);
  auto load_bad = [&] { PD::Reduced_simulator::load(model, bad, o, r); };
  // Truncated anywhere: refused, "truncated" (or no end marker when only it is cut).
  for(std::size_t cut : {std::size_t(0), std::size_t(5), std::size_t(64), std::size_t(200), bytes.size() / 2, bytes.size() - 9})
  {
    write_bytes(bad, bytes, cut);
    EXPECT_THROW_REASON(load_bad(), PD::Invalid_input, "the file is truncated");
  }
  write_bytes(bad, bytes, bytes.size() - 1);
  EXPECT_THROW_REASON(load_bad(), PD::Invalid_input, "cannot load the reduced simulator from");
  // A basis column index out of range (the first one: after the header of 64 bytes, the
  // position signature, one group, the options, U's size and its row starts).
  const int n = model.number_of_vertices();
  const std::size_t first_column = 64 + 32 + 4 + 20 + 34 + 16 + 8 + 4 * (std::size_t(n) + 1) + 8;
  std::vector<char> corrupt = bytes;
  const std::int32_t huge = 1 << 30;
  std::memcpy(corrupt.data() + first_column, &huge, 4);
  write_bytes(bad, corrupt, corrupt.size());
  EXPECT_THROW_REASON(load_bad(), PD::Invalid_input, "the file is corrupt (a basis column index)");
  // A NaN in the first basis value (after the column indices and the values' matrix size).
  corrupt = bytes;
  std::int64_t nonzeros = 0;
  std::memcpy(&nonzeros, bytes.data() + first_column - 8, 8);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::memcpy(corrupt.data() + first_column + 4 * std::size_t(nonzeros) + 16, &nan, 8);
  write_bytes(bad, corrupt, corrupt.size());
  EXPECT_THROW_REASON(load_bad(), PD::Invalid_input, "non-finite");
  // Bytes flipped, densely in the structure before the numbers (header, groups, options, U's
  // sizes, row starts and first column indices) and sparsely in the numbers: refused with a
  // reason or loaded (a changed number can be a valid one), never a crash or another exception.
  std::vector<std::size_t> places;
  for(std::size_t at = 0; at < first_column + 64; at += 7) places.push_back(at);
  for(std::size_t at = first_column + 64; at < bytes.size(); at += bytes.size() / 60) places.push_back(at);
  int refused = 0;
  for(std::size_t at : places)
  {
    corrupt = bytes;
    corrupt[at] = char(corrupt[at] ^ 0x5a);
    write_bytes(bad, corrupt, corrupt.size());
    try
    {
      load_bad();
    }
    catch(const PD::Invalid_input& e)
    {
      ++refused;
      EXPECT_NE(std::string(e.what()).find("cannot load the reduced simulator from"), std::string::npos) << e.what();
    }
  }
  // Most flips in the structure are caught (a flip in a low bit of a signature is rounding).
  EXPECT_GT(refused, int(places.size()) / 3) << places.size() << " flips";
}

TEST(ProjectiveDynamicsReduced, PrecomputationReportsProgressAndCanBeCancelled)
{
  for(bool hyper : {false, true})
  {
    std::vector<PD::Reduced_precomputation_progress> seen;
    PD::Reduction_options r = small_hyper();
    r.hyper_reduction = hyper;
    r.progress = [&](const PD::Reduced_precomputation_progress& p) { return seen.push_back(p), true; };
    // Two element groups: progress within the stages, per group.
    PD::Reduced_simulator sim(two_group_box(), PD::Simulator_options(), r);
    ASSERT_GE(seen.size(), hyper ? 7u : 4u);
    EXPECT_EQ(seen.front().fraction, 0.0);
    EXPECT_EQ(seen.front().stage, "position subspace");
    for(std::size_t q = 1; q < seen.size(); ++q)
      EXPECT_GE(seen[q].fraction, seen[q - 1].fraction) << seen[q - 1].stage << " -> " << seen[q].stage;
    EXPECT_EQ(seen.back().fraction, 1.0);
    EXPECT_EQ(seen.back().stage, "done");
    bool projected = false, subspaces = false;
    for(const auto& p : seen) projected |= p.stage == "projected matrices", subspaces |= p.stage == "projection subspaces";
    EXPECT_TRUE(projected);
    EXPECT_EQ(subspaces, hyper);
  }
  // The named parameter, void form.
  int calls = 0;
  double last = -1;
  PD::Reduced_simulator sim(box_model(), params::number_of_samples(12).number_of_constraint_samples(20)
                                             .number_of_projection_columns(40).number_of_sampled_elements(80)
                                             .progress_callback([&](const PD::Reduced_precomputation_progress& p) {
                                               ++calls, last = p.fraction;
                                             }));
  EXPECT_GT(calls, 2);
  EXPECT_EQ(last, 1.0);
  // False cancels.
  EXPECT_THROW_REASON(PD::Reduced_simulator(box_model(), params::number_of_samples(12).number_of_constraint_samples(20)
                                                             .number_of_projection_columns(40).number_of_sampled_elements(80)
                                                             .progress_callback([](const PD::Reduced_precomputation_progress& p) {
                                                               return p.stage != "projection subspaces";
                                                             })),
                      PD::Cancelled, "cancelled (at \"projection subspaces\")");
}
