// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Medit .mesh files (Projective_dynamics): read_medit; what it accepts must write and read back
// the same; a mesh that passes check_tet_mesh becomes a solid model and takes two simulator
// steps (up to 500 tetrahedra), whose positions must be finite or refused.  Linked against the
// Projective_dynamics library alone (no tool, no Surface_mesh), so it builds in a minute.
// Inputs starting with "PDREDUCE" are reduced-simulator precomputations (.pdr) instead, loaded
// for one fixed small model (`Reduced_simulator::load`): refused with Invalid_input, or loaded and
// stepped twice (finite positions or a Numerical_failure).  The seed box.pdr is that model's own
// file (written by `save` with the options below).

#include <CGAL/Projective_dynamics/Reduced_simulator.h>
#include <CGAL/Projective_dynamics/Simulator.h>
#include <CGAL/Projective_dynamics/errors.h>
#include <CGAL/Projective_dynamics/make_models.h>
#include <CGAL/Projective_dynamics/medit_io.h>
#include <CGAL/Projective_dynamics/mesh_generators.h>

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace PD = CGAL::Projective_dynamics;

// Every UBSan report ends the run, as for the other targets (fuzz_support.cpp).
extern "C" const char* __ubsan_default_options() { return "halt_on_error=1:print_stacktrace=1"; }

namespace {
[[noreturn]] void fail(const std::string& what)
{
  std::fprintf(stderr, "medit fuzz: %s\n", what.c_str());
  std::abort();
}
// The reduced simulator's file: the model and options its seed was saved with (6.8 KB).
int load_reduced(const std::uint8_t* data, std::size_t size)
{
  static const PD::Elastic_model model = PD::make_solid_model(PD::make_tet_box(2, 2, 2, {0, 0, 0}, {1, 1, 1}));
  PD::Simulator_options o;
  o.threads = 1;
  o.iterations = 3;
  PD::Reduction_options r;
  r.samples = 2, r.constraint_samples = 2, r.projection_columns = 6, r.sampled_elements = 26;
  // load reads a path: the input goes to a file of this process in TMPDIR (scripts/fuzz.sh).
  struct Scratch_file
  {
    std::string path =
        (std::filesystem::temp_directory_path() / ("fuzz_medit_" + std::to_string(::getpid()) + ".pdr")).string();
    ~Scratch_file() { std::remove(path.c_str()); }
  };
  static const Scratch_file scratch;
  const std::string& path = scratch.path;
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  try
  {
    PD::Reduced_simulator sim = PD::Reduced_simulator::load(model, path, o, r);
    sim.add_floor({0, 0, 0}, {0, 0, 1});
    sim.step();
    sim.step();
    if(!sim.positions().allFinite()) fail("a loaded reduced simulator's step returned non-finite positions");
  }
  catch(const PD::Invalid_input&)
  {
  }
  catch(const PD::Numerical_failure&) // a loaded K that is not positive definite, or overflow
  {
  }
  return 0;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size >= 8 && std::memcmp(data, "PDREDUCE", 8) == 0) return load_reduced(data, size);
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  PD::Tet_mesh mesh;
  try
  {
    mesh = PD::read_medit(in, "fuzz.mesh");
  }
  catch(const PD::Invalid_input&)
  {
    return 0;
  }
  std::stringstream again;
  PD::write_medit(again, mesh);
  const PD::Tet_mesh back = PD::read_medit(again, "rewritten.mesh"); // anything it throws is a finding
  if(back.points != mesh.points || back.tetrahedra != mesh.tetrahedra || back.triangles != mesh.triangles)
    fail("an accepted .mesh file does not read back the same after writing");
  if(mesh.tetrahedra.size() > 500) return 0;
  try
  {
    PD::check_tet_mesh(mesh);
    PD::Simulator sim(PD::make_solid_model(mesh), PD::parameters::number_of_iterations(3).number_of_threads(1));
    sim.add_floor({0, 0, 0}, {0, 0, 1});
    sim.step();
    sim.step();
    if(!sim.positions().allFinite() || !sim.velocities().allFinite()) fail("a step returned non-finite positions");
  }
  catch(const PD::Invalid_mesh&)
  {
  }
  catch(const PD::Invalid_input&) // e.g. a vertex in no tetrahedron: no mass
  {
  }
  catch(const PD::Numerical_failure&) // coordinates near overflow
  {
  }
  return 0;
}
