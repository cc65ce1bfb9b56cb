// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Fur of a field read face by face (the editor's preview of a reduced field) and fur on
// several threads, against the fur of the whole field on one thread.

#include "expect_reason.h"
#include "test_meshes.h"
#include "visual_test_support.h"

#include <CGAL/Tangent_vector_fields/Streamlines.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <set>
#include <vector>

namespace TVF = CGAL::Tangent_vector_fields;
using namespace tvf_test;

namespace {

// A whole field read face by face, counting what the tracer asks for.
class Counting_source : public TVF::Face_vector_source
{
public:
  explicit Counting_source(const Eigen::VectorXd& x) : x_(x), asked_(x.size() / 2) {}
  int number_of_faces() const override { return static_cast<int>(x_.size() / 2); }
  std::array<double, 2> face_vector(int f) const override
  {
    ++calls;
    ++asked_[f];
    return {x_[2 * f], x_[2 * f + 1]};
  }
  int most_asked() const
  {
    int most = 0;
    for(const std::atomic<int>& a : asked_) most = std::max(most, a.load());
    return most;
  }
  mutable std::atomic<int> calls{0}; // atomic: fur on several threads asks at once

private:
  Eigen::VectorXd x_;
  mutable std::vector<std::atomic<int>> asked_;
};

} // namespace

// Fur traced through the faces it reaches only (a field on demand, as the editor's preview of
// a reduced field) is the fur of the whole field: the same roots, walks and lengths.  The whole
// field's tracer is the truth.
TEST(Streamlines, FurOfAFieldOnDemandIsTheFurOfTheWholeFieldAndReadsFewFaces)
{
  Mesh sphere = make_icosphere(4); // 5120 faces
  Field field = field_map(sphere, "rotation");
  rotated_height_gradient(sphere, field);
  TVF::Mesh_streamline_tracer<Mesh> whole(sphere, field);
  const Eigen::VectorXd x = whole.adapter().read_field(field);
  const auto mesh = whole.adapter().intrinsic_mesh();
  const int nf = mesh->number_of_faces();
  const TVF::Streamline_surface surface(mesh);
  TVF::Fur_options fur;
  fur.number_of_strokes = 200;
  fur.length = 0.05;
  fur.scale_length_by_magnitude = true;
  fur.magnitude_reference = TVF::Fur_options::Magnitude_reference::roots;
  const auto source = std::make_shared<Counting_source>(x);
  const TVF::Streamline_tracer on_demand(surface, source);
  const std::vector<TVF::Streamline> strokes = on_demand.fur(fur), truth = whole.tracer().fur(fur);
  ASSERT_EQ(strokes.size(), truth.size());
  ASSERT_GT(strokes.size(), 150u);
  for(std::size_t i = 0; i < strokes.size(); ++i)
  {
    EXPECT_EQ(strokes[i].faces, truth[i].faces) << "stroke " << i;
    EXPECT_EQ(strokes[i].points, truth[i].points) << "stroke " << i;
    EXPECT_EQ(strokes[i].forward_stop, truth[i].forward_stop) << "stroke " << i;
  }
  // Each face read once, and only the roots' faces and those the strokes pass (with their
  // neighbours around the vertices walked through): a fraction of the sphere.
  EXPECT_EQ(source->most_asked(), 1);
  EXPECT_EQ(static_cast<std::size_t>(source->calls), on_demand.faces_read());
  EXPECT_LT(source->calls, nf / 4) << source->calls << " faces read of " << nf;
  std::set<int> passed;
  for(const TVF::Streamline& s : strokes) passed.insert(s.faces.begin(), s.faces.end());
  EXPECT_GE(source->calls, static_cast<int>(passed.size()));
  // Its largest magnitude is over the faces read; the whole field's tracer knows all faces.
  EXPECT_LE(on_demand.maximum_magnitude(), whole.tracer().maximum_magnitude());
  EXPECT_GT(on_demand.maximum_magnitude(), 0.9 * whole.tracer().maximum_magnitude());
  // Lengths relative to the largest magnitude over all faces: a field on demand cannot know it.
  fur.magnitude_reference = TVF::Fur_options::Magnitude_reference::all_faces;
  EXPECT_THROW_REASON(on_demand.fur(fur), TVF::Invalid_input, "largest magnitude at the roots");
  // Without scaling both agree again (the zero-field test relative to the roots' largest).
  fur.scale_length_by_magnitude = false;
  fur.magnitude_reference = TVF::Fur_options::Magnitude_reference::roots;
  const std::vector<TVF::Streamline> plain = on_demand.fur(fur), plain_truth = whole.tracer().fur(fur);
  ASSERT_EQ(plain.size(), plain_truth.size());
  for(std::size_t i = 0; i < plain.size(); ++i) EXPECT_EQ(plain[i].points, plain_truth[i].points) << "stroke " << i;
  // A source of another mesh is refused.
  EXPECT_THROW_REASON(TVF::Streamline_tracer(surface, std::make_shared<Counting_source>(Eigen::VectorXd::Zero(4))),
                      TVF::Invalid_input, "the field has 2 faces");
}

// Fur on several threads is the fur of one: each thread's generator is moved on past the roots
// of the threads before it, so the roots, and so the strokes and their order, are the same.  Each
// thread reads the faces its strokes reach; the tracer counts them all.
TEST(Streamlines, FurOnSeveralThreadsIsTheFurOfOneThread)
{
  Mesh sphere = make_icosphere(4); // 5120 faces
  Field field = field_map(sphere, "rotation");
  rotated_height_gradient(sphere, field);
  TVF::Mesh_streamline_tracer<Mesh> whole(sphere, field);
  const Eigen::VectorXd x = whole.adapter().read_field(field);
  const TVF::Streamline_surface surface(whole.adapter().intrinsic_mesh());
  TVF::Fur_options fur;
  fur.number_of_strokes = 1500; // enough for three threads of 256 roots or more
  fur.length = 0.05;
  fur.scale_length_by_magnitude = true;
  fur.magnitude_reference = TVF::Fur_options::Magnitude_reference::roots;
  fur.threads = 1;
  const std::vector<TVF::Streamline> one = whole.tracer().fur(fur);
  ASSERT_GT(one.size(), 1400u);
  for(int threads : {2, 3})
  {
    fur.threads = threads;
    const auto source = std::make_shared<Counting_source>(x);
    const TVF::Streamline_tracer on_demand(surface, source);
    for(const std::vector<TVF::Streamline>& strokes : {whole.tracer().fur(fur), on_demand.fur(fur)})
    {
      ASSERT_EQ(strokes.size(), one.size()) << threads << " threads";
      for(std::size_t i = 0; i < strokes.size(); ++i)
      {
        EXPECT_EQ(strokes[i].faces, one[i].faces) << "stroke " << i << ", " << threads << " threads";
        EXPECT_EQ(strokes[i].points, one[i].points) << "stroke " << i << ", " << threads << " threads";
      }
    }
    EXPECT_EQ(static_cast<std::size_t>(source->calls.load()), on_demand.faces_read());
    EXPECT_LE(source->most_asked(), threads); // once per thread at most
  }
  fur.threads = -1;
  EXPECT_THROW_REASON(whole.tracer().fur(fur), TVF::Invalid_input, "threads must be 0 (one per core) or more");
}
