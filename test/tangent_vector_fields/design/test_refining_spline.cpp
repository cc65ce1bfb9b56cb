// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The refining spline (Refining_spline_solver.h): reduced answers at once, exact ones once
// every pull-back is in, on request or on a worker thread, against one-shot reduced and
// full solvers of the same constraint set after every kind of edit.

#include "design_test_support.h"
#include "expect_reason.h"

#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Refining_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Vector_field_spline.h>
#include <CGAL/Tangent_vector_fields/errors.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <map>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;
using namespace design_test;

namespace {

// A refining spline over the basis's first `d` fields and the Hodge solver's factorisations.
std::unique_ptr<TVF::Refining_spline_solver> refining(const Design_setup& s, int d, double omega = 0)
{
  TVF::Spline_options options;
  options.omega = omega;
  return std::make_unique<TVF::Refining_spline_solver>(std::make_unique<TVF::Reduced_spline_solver>(s.basis, d, options),
                                                       std::make_unique<TVF::Full_spline_solver>(s.hodge, options));
}

// The one-shot solvers of a constraint set: the truth a refining spline must answer with.
struct Fresh
{
  Eigen::VectorXd reduced, full;
};
Fresh fresh_solves(const Design_setup& s, int d, const std::map<TVF::Constraint_id, TVF::Field_constraint>& set,
                   double omega = 0)
{
  TVF::Spline_options options;
  options.omega = omega;
  TVF::Reduced_spline_solver reduced(s.basis, d, options);
  TVF::Full_spline_solver full(s.hodge, options);
  for(const auto& c : set)
  {
    reduced.add(c.second);
    full.add(c.second);
  }
  return {reduced.field(), full.field()};
}

} // namespace

TEST(RefiningSpline, AnswersReducedThenExactThroughEveryKindOfEdit)
{
  // The refining spline answers with the reduced spline while a pull-back is pending and with
  // the full one once none is; compared after each step with one-shot solvers of the same
  // constraint set (1e-10 / 1e-9 relative: the same algebra, other row orders).
  const Mesh mesh = make_torus(16, 10);
  Design_setup s = setup(mesh, 150);
  const TVF::Intrinsic_mesh& m = s.ops->mesh();
  const int d = 60;
  auto spline = refining(s, d);
  std::map<TVF::Constraint_id, TVF::Field_constraint> set;
  const auto constraints = mixed_constraints(m, 5, 21);
  const auto ids = spline->add(constraints);
  for(std::size_t i = 0; i < ids.size(); ++i) set[ids[i]] = constraints[i];
  double omega = 0;
  auto expect = [&](bool exact, const std::string& step) {
    const TVF::Spline_answer a = spline->answer();
    EXPECT_EQ(a.exact, exact) << step;
    EXPECT_EQ(a.basis_size, d) << step;
    const Fresh truth = fresh_solves(s, d, set, omega);
    EXPECT_LT(relative_mx_error(*s.ops, spline->field(), exact ? truth.full : truth.reduced), exact ? 1e-9 : 1e-10) << step;
    EXPECT_GT(relative_mx_error(*s.ops, truth.reduced, truth.full), 1e-3) << step; // the two answers differ
  };
  expect(false, "added, nothing pulled back");
  EXPECT_EQ(spline->answer().pending, static_cast<int>(constraints.size()));
  int calls = 0, last_total = 0;
  spline->refine([&](int done, int total) {
    EXPECT_EQ(done, ++calls);
    last_total = total;
  });
  EXPECT_EQ(calls, static_cast<int>(constraints.size()));
  EXPECT_EQ(last_total, calls);
  expect(true, "refined");
  // A value edit stays exact, also through the cached response of a drag.
  TVF::Field_constraint edited = set[ids[0]];
  edited.vector = tangent(m, edited.face, -2, 0.5);
  spline->change(ids[0], edited);
  set[ids[0]] = edited;
  expect(true, "value edit");
  EXPECT_LT(relative_mx_error(*s.ops, spline->field_after_value_edit(ids[0]), fresh_solves(s, d, set).full), 1e-9);
  // A move makes one pull-back pending: reduced until refined.
  TVF::Field_constraint moved = set[ids[1]];
  moved.face = (moved.face + 31) % m.number_of_faces();
  moved.vector = tangent(m, moved.face, 1, -1);
  spline->change(ids[1], moved);
  set[ids[1]] = moved;
  EXPECT_EQ(spline->answer().pending, 1);
  expect(false, "moved");
  spline->refine();
  expect(true, "moved and refined");
  // A removal keeps it exact; an addition does not until refined.
  spline->remove(ids[2]);
  set.erase(ids[2]);
  expect(true, "removed");
  const TVF::Field_constraint extra = TVF::Field_constraint::vector_in_face(77, tangent(m, 77, 0.3, 0.9));
  set[spline->add(extra)] = extra;
  expect(false, "added one more");
  spline->refine();
  expect(true, "refined again");
  // A new tension: every pull-back pending again.
  omega = 25;
  spline->set_omega(omega);
  EXPECT_EQ(spline->answer().pending, static_cast<int>(set.size()));
  expect(false, "new tension");
  spline->refine();
  expect(true, "new tension, refined");
  // Cancelled between constraints: what was done stays, the answer stays reduced and right.
  spline->set_omega(0);
  omega = 0;
  int asked = 0;
  spline->refine(TVF::Refinement_progress(), [&] { return ++asked > 2; });
  EXPECT_EQ(spline->answer().pending, static_cast<int>(set.size()) - 2);
  expect(false, "cancelled after two");
  spline->clear();
  EXPECT_TRUE(spline->answer().exact); // no constraint: nothing pending, the zero field
  EXPECT_EQ(spline->field().norm(), 0.);
}

TEST(RefiningSpline, BackgroundRefinementThroughEditsAndCancellation)
{
  // The worker thread pulls back what is added or moved while edits go on; stale work (moved
  // or removed constraints) is dropped; a stop leaves a consistent answer (reduced or exact,
  // each equal to its one-shot solve).  Run under ThreadSanitizer for the note of issue 14.
  const Mesh mesh = make_torus(16, 10);
  Design_setup s = setup(mesh, 150);
  const TVF::Intrinsic_mesh& m = s.ops->mesh();
  const int d = 60, nf = m.number_of_faces();
  auto spline = refining(s, d);
  std::map<TVF::Constraint_id, TVF::Field_constraint> set;
  auto check = [&](const std::string& step) {
    TVF::Spline_answer a; // what this field is (the worker may finish right after)
    const Eigen::VectorXd x = spline->field(&a);
    const Fresh truth = fresh_solves(s, d, set);
    EXPECT_LT(relative_mx_error(*s.ops, x, a.exact ? truth.full : truth.reduced), a.exact ? 1e-9 : 1e-10)
        << step << (a.exact ? " (exact)" : " (reduced)");
  };
  std::atomic<int> reported{0};
  spline->refine_in_background([&](int, int) { ++reported; });
  EXPECT_TRUE(spline->refining_in_background());
  for(int i = 0; i < 8; ++i) // a burst of adds, moves and a removal while the worker runs
  {
    const int f = (i * 613 + 5) % nf;
    const TVF::Field_constraint c = TVF::Field_constraint::vector_in_face(f, tangent(m, f, 1, 0.1 * i));
    const TVF::Constraint_id id = spline->add(c);
    set[id] = c;
    if(i % 3 == 1)
    {
      const int g = (f + 101) % nf;
      const TVF::Field_constraint moved = TVF::Field_constraint::vector_in_face(g, tangent(m, g, -1, 0.5));
      spline->change(id, moved);
      set[id] = moved;
    }
    if(i == 4)
    {
      spline->remove(id);
      set.erase(id);
    }
    check("during the burst, step " + std::to_string(i));
  }
  ASSERT_TRUE(spline->wait_until_exact(std::chrono::minutes(2)));
  EXPECT_GT(reported.load(), 0);
  check("after waiting");
  EXPECT_TRUE(spline->answer().exact);
  // Value edits keep it exact without the worker.
  const TVF::Constraint_id first = set.begin()->first;
  TVF::Field_constraint c = set[first];
  c.vector = tangent(m, c.face, 0.2, -3);
  spline->change(first, c);
  set[first] = c;
  EXPECT_TRUE(spline->answer().exact);
  check("value edit");
  // Stopped at once after more edits: consistent, and a later refine completes it.
  for(int i = 0; i < 4; ++i)
  {
    const int f = (i * 97 + 41) % nf; // faces no constraint uses
    const TVF::Field_constraint more = TVF::Field_constraint::vector_in_face(f, tangent(m, f, 0.5, 1));
    set[spline->add(more)] = more;
  }
  spline->stop_background();
  EXPECT_FALSE(spline->refining_in_background());
  check("stopped");
  // Stopped means nothing more is pulled back: whatever was pending at the stop stays
  // pending through a wait long enough for a running worker to finish a torus of this size
  // (a pull-back takes about a millisecond here).
  const TVF::Spline_answer at_stop = spline->answer();
  EXPECT_EQ(spline->wait_until_exact(std::chrono::milliseconds(300)), at_stop.exact);
  EXPECT_EQ(spline->answer().pending, at_stop.pending);
  spline->refine();
  EXPECT_TRUE(spline->answer().exact);
  check("refined after the stop");
  // A tension change while the worker runs restarts it on the new energy.
  spline->refine_in_background();
  spline->set_omega(10);
  EXPECT_TRUE(spline->refining_in_background());
  ASSERT_TRUE(spline->wait_until_exact(std::chrono::minutes(2)));
  TVF::Full_spline_solver full(s.hodge, [] { TVF::Spline_options o; o.omega = 10; return o; }());
  for(const auto& e : set) full.add(e.second);
  EXPECT_LT(relative_mx_error(*s.ops, spline->field(), full.field()), 1e-9);
}

TEST(RefiningSpline, FullSolverMadeOnTheWorkerAndDroppedWhenNotNeeded)
{
  // Made from a factory: nothing of the full solver exists until a refinement asks for it;
  // the worker makes it (its factorisation is part of the wait), stop_refining drops it and
  // its pull-backs, and a new reduced solver (another basis size) keeps the full answer.
  const Mesh mesh = make_icosphere(2);
  Design_setup s = setup(mesh, 120);
  const TVF::Intrinsic_mesh& m = s.ops->mesh();
  int made = 0;
  TVF::Refining_spline_solver spline(std::make_unique<TVF::Reduced_spline_solver>(s.basis, 40),
                                     [&](double omega) {
                                       ++made;
                                       TVF::Spline_options o;
                                       o.omega = omega;
                                       return std::make_unique<TVF::Full_spline_solver>(s.hodge, o);
                                     });
  std::map<TVF::Constraint_id, TVF::Field_constraint> set;
  for(const auto& c : mixed_constraints(m, 4, 8)) set[spline.add(c)] = c;
  EXPECT_EQ(spline.full(), nullptr);
  EXPECT_FALSE(spline.answer().exact);
  spline.refine_in_background();
  ASSERT_TRUE(spline.wait_until_exact(std::chrono::minutes(1))) << spline.refinement_error();
  EXPECT_EQ(made, 1);
  EXPECT_LT(relative_mx_error(*s.ops, spline.field(), fresh_solves(s, 40, set).full), 1e-9);
  spline.replace_reduced(std::make_unique<TVF::Reduced_spline_solver>(s.basis, 80));
  EXPECT_TRUE(spline.answer().exact);
  EXPECT_EQ(spline.answer().basis_size, 80);
  spline.stop_refining();
  EXPECT_EQ(spline.full(), nullptr);
  TVF::Spline_answer a;
  const Eigen::VectorXd x = spline.field(&a);
  EXPECT_FALSE(a.exact);
  EXPECT_LT(relative_mx_error(*s.ops, x, fresh_solves(s, 80, set).reduced), 1e-10);
  // A factory that fails on the worker: the reason is kept, the answer stays reduced.
  TVF::Refining_spline_solver failing(std::make_unique<TVF::Reduced_spline_solver>(s.basis, 40),
                                      [](double) -> std::unique_ptr<TVF::Full_spline_solver> {
                                        throw TVF::Invalid_input("no factorisation today");
                                      });
  failing.add(set.begin()->second);
  failing.refine_in_background();
  EXPECT_FALSE(failing.wait_until_exact(std::chrono::seconds(30)));
  EXPECT_NE(failing.refinement_error().find("no factorisation today"), std::string::npos) << failing.refinement_error();
  EXPECT_FALSE(failing.answer().exact);
}

TEST(RefiningSpline, SoonestFieldIsTheAnswerItSays)
{
  // `soonest_field` may wait for the worker (when a pull-back is expected sooner than the
  // reduced field); whatever it answers must be the field of the answer it reports, equal to
  // the one-shot solve of that kind, and without a worker it never waits: reduced at once.
  const Mesh mesh = make_torus(16, 10);
  Design_setup s = setup(mesh, 150);
  const TVF::Intrinsic_mesh& m = s.ops->mesh();
  const int d = 150, nf = m.number_of_faces();
  auto spline = refining(s, d);
  std::map<TVF::Constraint_id, TVF::Field_constraint> set;
  auto add_and_check = [&](int i, bool worker) {
    const int f = (i * 389 + 11) % nf;
    const TVF::Field_constraint c = TVF::Field_constraint::vector_in_face(f, tangent(m, f, 0.3 * i, 1));
    set[spline->add(c)] = c;
    TVF::Spline_answer a;
    const Eigen::VectorXd x = spline->soonest_field(&a);
    if(!worker) EXPECT_FALSE(a.exact) << "add " << i;
    EXPECT_EQ(a.exact, a.pending == 0) << "add " << i;
    const Fresh truth = fresh_solves(s, d, set);
    EXPECT_LT(relative_mx_error(*s.ops, x, a.exact ? truth.full : truth.reduced), a.exact ? 1e-9 : 1e-10)
        << "add " << i << (a.exact ? " (exact)" : " (reduced)");
  };
  for(int i = 0; i < 3; ++i) add_and_check(i, false);
  spline->refine_in_background();
  ASSERT_TRUE(spline->wait_until_exact(std::chrono::minutes(2)));
  for(int i = 3; i < 9; ++i) add_and_check(i, true);
  ASSERT_TRUE(spline->wait_until_exact(std::chrono::minutes(2)));
  EXPECT_LT(relative_mx_error(*s.ops, spline->soonest_field(), fresh_solves(s, d, set).full), 1e-9);
}

// A caller that has shown the edit otherwise (the editor's preview strokes) names how long an
// exact field is worth waiting for: with the worker expected within that time, the answer is the
// exact field.  Batches of 20 constraints keep the worker busy far longer than the reduced field
// takes to make, where the default answers at once with the reduced field.
TEST(RefiningSpline, SoonestFieldWaitsAsLongAsTheCallerSays)
{
  const Mesh mesh = make_torus(32, 20);
  Design_setup s = setup(mesh, 150);
  const TVF::Intrinsic_mesh& m = s.ops->mesh();
  const int d = 150, nf = m.number_of_faces();
  auto spline = refining(s, d);
  std::map<TVF::Constraint_id, TVF::Field_constraint> set;
  spline->refine_in_background();
  for(int batch = 0; batch < 3; ++batch)
  {
    std::vector<TVF::Field_constraint> cs;
    for(int i = 0; i < (batch == 0 ? 1 : 20); ++i)
    {
      const int f = ((20 * batch + i) * 389 + 11) % nf;
      cs.push_back(TVF::Field_constraint::vector_in_face(f, tangent(m, f, 0.3 * i, 1)));
    }
    const std::vector<TVF::Constraint_id> ids = spline->add(cs);
    for(std::size_t i = 0; i < ids.size(); ++i) set[ids[i]] = cs[i];
    if(batch == 0) // the first pull-back tells how long one takes
    {
      ASSERT_TRUE(spline->wait_until_exact(std::chrono::minutes(2)));
      continue;
    }
    TVF::Spline_answer a;
    const Eigen::VectorXd x = spline->soonest_field(&a, 60.0);
    EXPECT_TRUE(a.exact) << "batch " << batch;
    EXPECT_LT(relative_mx_error(*s.ops, x, fresh_solves(s, d, set).full), 1e-9) << "batch " << batch;
  }
  EXPECT_THROW_REASON(spline->soonest_field(nullptr, -1.0), TVF::Invalid_input, "time worth waiting");
  EXPECT_THROW_REASON(spline->soonest_field(nullptr, std::nan("")), TVF::Invalid_input, "time worth waiting");
}

// The generic class answers exactly too: on a basis it answers at once with the reduced spline
// and its error bound, `refine()` (this thread) and `refine_in_background()` (a worker) turn
// its field into the one-shot full-resolution spline of the same constraints, an added
// constraint makes it reduced again until refined, and `answer()` / `field(out, &which)` say
// which one a field is.  Against `vector_field_spline` (the one-shot full solve, another path).
TEST(RefiningSpline, GenericSplineGivesTheExactAnswerOnRequestAndInTheBackground)
{
  Mesh mesh = make_torus(16, 10);
  TVF::Spectral_basis<Mesh> basis(mesh, TVF::parameters::number_of_eigenfields(40));
  TVF::Vector_field_spline<Mesh> spline(basis, TVF::parameters::spline_tension(1.0));
  const TVF::Intrinsic_mesh& m = spline.solver().operators().mesh();
  std::vector<TVF::Field_constraint> constraints = mixed_constraints(m, 3, 9);
  spline.add(constraints);
  auto field_of = [&](auto& s, TVF::Spline_answer* which) {
    return face_vectors(mesh, [&](auto map) { s.field(map, which); });
  };
  auto exact_of = [&](const std::vector<TVF::Field_constraint>& c) {
    return face_vectors(mesh, [&](auto map) { TVF::vector_field_spline(mesh, c, map, TVF::parameters::spline_tension(1.0)); });
  };
  auto difference = [](const std::vector<Vector_3>& a, const std::vector<Vector_3>& b) {
    return largest_relative_difference(a, b);
  };
  TVF::Spline_answer which;
  const std::vector<Vector_3> reduced = field_of(spline, &which);
  EXPECT_FALSE(which.exact);
  EXPECT_EQ(which.basis_size, 40);
  EXPECT_FALSE(spline.is_exact());
  EXPECT_GT(spline.report().error_bound, 0.);
  const std::vector<Vector_3> exact = exact_of(constraints);
  EXPECT_GT(difference(reduced, exact), 1e-3) << "a reduced answer that is exact tells nothing";

  int progress_calls = 0;
  spline.refine([&](int done, int total) { progress_calls += done <= total; });
  EXPECT_GT(progress_calls, 0);
  EXPECT_TRUE(spline.is_exact());
  EXPECT_EQ(spline.report().error_bound, 0.);
  // Same constraints, other row order and factorisation: 1e-9 of the largest vector.
  EXPECT_LT(difference(field_of(spline, &which), exact), 1e-9);
  EXPECT_TRUE(which.exact);

  // A new constraint: reduced at once, exact again from the worker.
  constraints.push_back(TVF::Field_constraint::vector_in_face(77, tangent(m, 77, 0.5, -1)));
  spline.add(constraints.back());
  spline.refine_in_background();
  field_of(spline, &which);
  const std::vector<Vector_3> exact_after = exact_of(constraints);
  ASSERT_TRUE(spline.wait_until_exact(std::chrono::seconds(60))) << spline.refinement_error();
  EXPECT_LT(difference(field_of(spline, &which), exact_after), 1e-9);
  EXPECT_TRUE(which.exact);
  spline.stop_refining();
  EXPECT_FALSE(spline.is_exact()) << "without the full pull-backs the answer is reduced again";

  // At full resolution every answer is exact and refining is nothing to do.
  TVF::Vector_field_spline<Mesh> full(mesh, TVF::parameters::spline_tension(1.0));
  full.add(constraints);
  EXPECT_TRUE(full.is_exact());
  full.refine();
  EXPECT_LT(difference(field_of(full, &which), exact_after), 1e-12);
  EXPECT_TRUE(which.exact);
}
