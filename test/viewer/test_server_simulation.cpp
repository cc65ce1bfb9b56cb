// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `simulation` session of `tvf serve` (real-time Projective Dynamics, Chapter 3) over a
// real socket, on a square cloth made here (17 x 17 vertices, side 1, at z = 0): it falls onto
// the floor and lies still there, a grabbed corner goes where it is taken, a softer cloth
// hanging from a corner sags from the very next frame on, every frame carries only finite
// positions of the surface, and every bad message is refused with its reason.

#include "server_test_support.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

namespace {

using namespace server_test;

const int sim_test_side = 17; // vertices along a side of the cloth
const int sim_test_vertices = sim_test_side * sim_test_side;

// The cloth as an OFF file in the temporary folder.
std::string sim_test_cloth_path()
{
  const std::string path = testing::TempDir() + "tvf_simulation_cloth.off";
  std::ofstream out(path);
  const int n = sim_test_side;
  out << "OFF\n" << n * n << " " << 2 * (n - 1) * (n - 1) << " 0\n";
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) out << double(i) / (n - 1) << " " << double(j) / (n - 1) << " 0\n";
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i)
    {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      out << "3 " << a << " " << b << " " << d << "\n3 " << a << " " << d << " " << c << "\n";
    }
  return path;
}

class Simulation_server_test : public ::testing::Test
{
public:
  static void SetUpTestSuite()
  {
    server = new Server_process({TVF_TOOL, "serve", sim_test_cloth_path(), "-n", "10", "--port", "0", "--stall-timeout", "5"});
  }
  static void TearDownTestSuite() { delete server; }
  inline static Server_process* server = nullptr;
};

typedef std::array<double, 3> Sim_point;

// A frame's positions, checked: the only array, one finite point per surface vertex.
std::vector<Sim_point> sim_test_positions(const Message& frame, int vertices = sim_test_vertices)
{
  EXPECT_EQ(frame.floats.size(), 1u);
  EXPECT_TRUE(frame.integers.empty());
  const std::vector<float>& p = frame.floats.at("positions");
  EXPECT_EQ(p.size(), std::size_t(3 * vertices));
  std::vector<Sim_point> out(p.size() / 3);
  for(std::size_t v = 0; v < out.size(); ++v)
    for(int k = 0; k < 3; ++k)
    {
      EXPECT_TRUE(std::isfinite(p[3 * v + std::size_t(k)])) << "vertex " << v;
      out[v][std::size_t(k)] = p[3 * v + std::size_t(k)];
    }
  return out;
}

double sim_test_lowest(const std::vector<Sim_point>& q)
{
  double z = 1e300;
  for(const Sim_point& p : q) z = std::min(z, p[2]);
  return z;
}

// Largest distance a vertex moved between two frames.
double sim_test_motion(const std::vector<Sim_point>& a, const std::vector<Sim_point>& b)
{
  double d = 0;
  for(std::size_t v = 0; v < a.size(); ++v)
    d = std::max(d, std::hypot(a[v][0] - b[v][0], a[v][1] - b[v][1], a[v][2] - b[v][2]));
  return d;
}

// A paused simulation of the cloth after its hello (info, mesh, first frame).
struct Sim_test_session
{
  Client client;
  Message info;
  std::vector<Sim_point> now;
  long long next_request = 2;
  int vertices;
  explicit Sim_test_session(const Address& address, const std::string& extra = ",\"playing\":false",
                            int vertex_count = sim_test_vertices)
    : client(address), vertices(vertex_count)
  {
    client.send("{\"type\":\"hello\",\"kind\":\"simulation\",\"request\":1" + extra + "}");
    info = client.expect("info");
    const Message mesh = client.expect("mesh");
    EXPECT_EQ(mesh.floats.at("positions").size(), std::size_t(3 * vertices));
    const Message first = client.expect("frame");
    EXPECT_EQ(first.json.get<int>("request"), 1);
    now = sim_test_positions(first, vertices);
  }
  // Sends `members` as a request; the frames before its answer, and the answer (`state` or `error`).
  Message ask(const std::string& members, std::vector<std::vector<Sim_point>>* frames = nullptr)
  {
    const long long id = next_request++;
    client.send("{\"request\":" + std::to_string(id) + "," + members + "}");
    for(;;)
    {
      Message m = client.receive();
      if(m.type() == "frame")
      {
        now = sim_test_positions(m, vertices);
        if(frames) frames->push_back(now);
        continue;
      }
      if(m.json.get<long long>("request", -1) == id) return m;
      ADD_FAILURE() << "unexpected message " << m.type();
    }
  }
  std::string refusal(const std::string& members)
  {
    const Message m = ask(members);
    EXPECT_EQ(m.type(), "error");
    return m.json.get<std::string>("message", "");
  }
  void steps(int count, std::vector<std::vector<Sim_point>>* frames = nullptr)
  {
    const Message m = ask("\"type\":\"step\",\"count\":" + std::to_string(count), frames);
    EXPECT_EQ(m.type(), "state") << m.json.get<std::string>("message", "");
  }
};

std::string sim_test_vector(const Sim_point& p)
{
  std::ostringstream s;
  s.precision(17);
  s << "[" << p[0] << "," << p[1] << "," << p[2] << "]";
  return s.str();
}

TEST_F(Simulation_server_test, offered_after_the_other_kinds_with_real_time_sizes)
{
  Client fields(server->address());
  fields.send("{\"type\":\"hello\",\"request\":1}");
  EXPECT_EQ(fields.expect("info").json.get<std::string>("kind"), "vector_field");
  Sim_test_session s(server->address());
  EXPECT_EQ(s.info.json.get<std::string>("kind"), "simulation");
  EXPECT_EQ(s.info.json.get<std::string>("body.mode"), "shell"); // the cloth is open
  // A flat cloth has no reduced subspace (its samples' affine maps lose z): full PD, and why.
  EXPECT_EQ(s.info.json.get<std::string>("body.simulator"), "full");
  EXPECT_NE(s.info.json.get<std::string>("body.fallback").find("dependent columns"), std::string::npos);
  EXPECT_FALSE(s.info.json.get<bool>("mesh.closed"));
  EXPECT_NEAR(s.info.json.get<double>("floor"), -0.025, 1e-12); // a tenth of the side, quartered
  Client other(server->address());
  other.send("{\"type\":\"hello\",\"kind\":\"simulations\"}");
  EXPECT_NE(other.expect_error().find("curve, simulation"), std::string::npos);
}

TEST_F(Simulation_server_test, bad_messages_are_refused_with_their_reason)
{
  Client open(server->address());
  open.send("{\"type\":\"hello\",\"kind\":\"simulation\",\"mode\":\"solid\"}");
  EXPECT_NE(open.expect_error().find("the surface is open: a solid needs a closed surface"), std::string::npos);
  open.send("{\"type\":\"play\"}");
  EXPECT_NE(open.expect_error().find("send \"hello\" first"), std::string::npos);

  Sim_test_session s(server->address());
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"\"type\":\"grab\",\"vertex\":289", "unknown vertex 289: the surface has 289 vertices (0 to 288)"},
      {"\"type\":\"grab\",\"vertex\":-1", "unknown vertex -1"},
      {"\"type\":\"grab\",\"vertex\":1.5", "unknown vertex 1.5"},
      {"\"type\":\"grab\",\"vertex\":0,\"point\":[0,0,0]", "give either \"vertex\" or \"point\""},
      {"\"type\":\"grab\",\"vertex\":0,\"target\":[0,null,1]", "\"target\" has a NaN coordinate (null)"},
      {"\"type\":\"grab\",\"point\":[0,0]", "\"point\" must be an array of 3 numbers"},
      {"\"type\":\"move\",\"target\":[0,0,1]", "nothing is grabbed: send \"grab\" first"},
      {"\"type\":\"stiffness\",\"value\":0", "the stiffness must be > 0 (got 0)"},
      {"\"type\":\"stiffness\",\"value\":-3", "the stiffness must be > 0 (got -3)"},
      {"\"type\":\"stiffness\",\"value\":null", "\"value\" is NaN (null)"},
      {"\"type\":\"stiffness\",\"value\":1e30", "is outside ["},
      {"\"type\":\"stiffness\"", "missing \"value\""},
      {"\"type\":\"time_step\",\"value\":0.5", "the time step must lie in (0, 0.1] seconds (got 0.5)"},
      {"\"type\":\"time_step\",\"value\":0", "the time step must lie in (0, 0.1]"},
      {"\"type\":\"step\",\"count\":0", "\"count\" must be an integer in [1, 1000]"},
      {"\"type\":\"poke\",\"vertex\":3,\"velocity\":[1e9,0,0]", "is above"},
      {"\"type\":\"poke\",\"vertex\":3", "missing \"velocity\""},
      {"\"type\":\"stiffnes\",\"value\":1", "unknown message type \"stiffnes\""},
      {"\"type\":\"play\",\"speed\":2", "speed"},
      {"\"type\":\"hello\",\"mode\":\"liquid\"", "\"mode\" must be \"shell\" or \"solid\""},
      {"\"type\":\"hello\",\"simulator\":\"fast\"", "\"simulator\" must be \"reduced\" or \"full\""}};
  for(const auto& [message, reason] : cases)
    EXPECT_NE(s.refusal(message).find(reason), std::string::npos) << message;
  // Nothing was changed by them: the simulation steps on, at the default stiffness.
  std::vector<std::vector<Sim_point>> frames;
  const Message state = s.ask("\"type\":\"step\",\"count\":2", &frames);
  EXPECT_EQ(state.type(), "state");
  EXPECT_EQ(frames.size(), 2u);
  EXPECT_EQ(state.json.get<int>("step"), 2);
  EXPECT_DOUBLE_EQ(state.json.get<double>("stiffness"), s.info.json.get<double>("stiffness.default"));
  EXPECT_EQ(state.json.get<std::string>("grabbed"), "null");
}

TEST_F(Simulation_server_test, a_drop_lands_on_the_floor_and_lies_still)
{
  Sim_test_session s(server->address());
  const double floor = s.info.json.get<double>("floor"), diagonal = s.info.json.get<double>("diagonal");
  EXPECT_NEAR(sim_test_lowest(s.now), 0, 1e-6); // starts at rest where it was made
  std::vector<std::vector<Sim_point>> frames;
  s.steps(120, &frames); // two seconds
  ASSERT_EQ(frames.size(), 120u);
  // On the floor within 0.5 % of the diagonal: no vertex through it, the lowest on it.
  const double tolerance = 0.005 * diagonal;
  EXPECT_NEAR(sim_test_lowest(s.now), floor, tolerance);
  // Lying flat: every vertex on the floor.
  for(const Sim_point& p : s.now) EXPECT_NEAR(p[2], floor, tolerance);
  // Still: the last frames move no vertex by more than 1e-5 diagonals.
  frames.clear();
  s.steps(30, &frames);
  for(std::size_t f = 1; f < frames.size(); ++f) EXPECT_LT(sim_test_motion(frames[f - 1], frames[f]), 1e-5 * diagonal);
  // A drop lifts it back to where it started, and it lands again.
  s.ask("\"type\":\"drop\"");
  EXPECT_NEAR(sim_test_lowest(s.now), 0, 1e-4);
  s.steps(120);
  EXPECT_NEAR(sim_test_lowest(s.now), floor, tolerance);
}

TEST_F(Simulation_server_test, a_grabbed_corner_reaches_its_target)
{
  Sim_test_session s(server->address());
  const double diagonal = s.info.json.get<double>("diagonal");
  s.steps(30);
  // Corner 0 taken 1.5 up (the cloth hangs from it, clear of the floor), then 0.5 sideways.
  for(const Sim_point& target : {Sim_point{0, 0, 1.5}, Sim_point{0.5, 0, 1.5}})
  {
    const Message grabbed = s.ask(std::string(target[0] == 0 ? "\"type\":\"grab\",\"vertex\":0" : "\"type\":\"move\"") +
                                  ",\"target\":" + sim_test_vector(target));
    ASSERT_EQ(grabbed.type(), "state") << grabbed.json.get<std::string>("message", "");
    EXPECT_EQ(grabbed.json.get<int>("grabbed"), 0);
    s.steps(240);
    const Sim_point& p = s.now[0];
    // Held by a stiff spring in the reduced space: within 2 % of the diagonal.
    EXPECT_LT(std::hypot(p[0] - target[0], p[1] - target[1], p[2] - target[2]), 0.02 * diagonal);
  }
  // A grab by point takes the nearest vertex: (1, 1, z) is the far corner, 288.
  EXPECT_EQ(s.ask("\"type\":\"grab\",\"point\":[1.01,1.02,-5]").json.get<int>("grabbed"), sim_test_vertices - 1);
  EXPECT_EQ(s.ask("\"type\":\"release\"").json.get<std::string>("grabbed"), "null");
}

double sim_test_mean_height(const std::vector<Sim_point>& q)
{
  double z = 0;
  for(const Sim_point& p : q) z += p[2];
  return z / double(q.size());
}

// Two cloths hanging from a corner, stepped alike (the simulation is deterministic): one is
// made a thousand times softer.  Its very next frame is lower than the other's (gravity
// outweighs its strain now), and it hangs lower from then on.
TEST_F(Simulation_server_test, a_softer_cloth_sags_from_the_next_frame_on)
{
  Sim_test_session softer(server->address()), same(server->address());
  const double diagonal = softer.info.json.get<double>("diagonal");
  for(Sim_test_session* s : {&softer, &same})
  {
    ASSERT_EQ(s->ask("\"type\":\"grab\",\"vertex\":0,\"target\":[0,0,1.8]").type(), "state");
    s->steps(120);
  }
  ASSERT_EQ(sim_test_motion(softer.now, same.now), 0.0); // alike so far
  const Message changed = softer.ask("\"type\":\"stiffness\",\"value\":" +
                                     std::to_string(1e-3 * softer.info.json.get<double>("stiffness.default")));
  ASSERT_EQ(changed.type(), "state");
  EXPECT_NEAR(changed.json.get<double>("stiffness"), 1e-3 * softer.info.json.get<double>("stiffness.default"), 1e-6);
  softer.steps(1);
  same.steps(1);
  EXPECT_GT(sim_test_motion(softer.now, same.now), 1e-4 * diagonal);
  EXPECT_LT(sim_test_mean_height(softer.now), sim_test_mean_height(same.now) - 1e-5 * diagonal);
  // A second later, over a second: lower by more than 2 % of the diagonal on average.
  softer.steps(60);
  same.steps(60);
  std::vector<std::vector<Sim_point>> a, b;
  softer.steps(60, &a);
  same.steps(60, &b);
  double lower = 0;
  for(std::size_t f = 0; f < a.size(); ++f) lower += (sim_test_lowest(b[f]) - sim_test_lowest(a[f])) / double(a.size());
  EXPECT_GT(lower, 0.02 * diagonal);
}

TEST_F(Simulation_server_test, playing_paces_the_frames_and_reports_timings)
{
  Sim_test_session s(server->address(), ",\"playing\":true");
  // Frames arrive unasked, each with its simulation time; the interval after the first.
  int frames = 0;
  while(frames < 20)
  {
    const Message m = s.client.receive();
    ASSERT_EQ(m.type(), "frame");
    sim_test_positions(m);
    EXPECT_GE(m.json.get<double>("timings.simulation_ms"), 0.0);
    if(frames++ > 0) EXPECT_GT(m.json.get<double>("timings.interval_ms"), 0.0);
  }
  const Message paused = s.ask("\"type\":\"pause\"");
  EXPECT_FALSE(paused.json.get<bool>("playing"));
  EXPECT_GE(paused.json.get<int>("step"), 20);
}

// CGAL's sphere (162 vertices, closed): the hyper-reduced simulator, as a shell and as a solid.
class Simulation_sphere_test : public ::testing::Test
{
public:
  static void SetUpTestSuite()
  {
    server = new Server_process({TVF_TOOL, "serve", sphere_path(), "-n", "10", "--port", "0", "--stall-timeout", "5"});
  }
  static void TearDownTestSuite() { delete server; }
  inline static Server_process* server = nullptr;
};

TEST_F(Simulation_sphere_test, reduced_shell_and_solid_land_on_the_floor)
{
  for(const std::string mode : {"shell", "solid"})
  {
    Sim_test_session s(server->address(), ",\"playing\":false,\"mode\":\"" + mode + "\"", 162);
    EXPECT_EQ(s.info.json.get<std::string>("body.mode"), mode);
    EXPECT_EQ(s.info.json.get<std::string>("body.simulator"), "reduced");
    EXPECT_EQ(s.info.json.get<std::string>("body.fallback", ""), "");
    const double floor = s.info.json.get<double>("floor"), diagonal = s.info.json.get<double>("diagonal");
    const double start = sim_test_lowest(s.now);
    EXPECT_GT(start, floor + 0.1 * diagonal);
    s.steps(150);
    // The floor holds the surface's vertices (a solid's: through its tetrahedra's boundary)
    // within 1 % of the diagonal, and the body rests on it.
    EXPECT_NEAR(sim_test_lowest(s.now), floor, 0.01 * diagonal) << mode;
  }
  Sim_test_session full(server->address(), ",\"playing\":false,\"simulator\":\"full\"", 162);
  EXPECT_EQ(full.info.json.get<std::string>("body.simulator"), "full");
}

} // namespace
