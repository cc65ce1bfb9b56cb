// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Vibration_modes/modes_file.h>

#include <CGAL/Model_reduction/internal/binary_file.h>
#include <CGAL/Model_reduction/internal/mesh_identity.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace CGAL {
namespace Vibration_modes {

namespace {

namespace MRI = Model_reduction::internal;

const char file_magic[8] = {'V', 'I', 'B', 'M', 'O', 'D', 'E', 'S'};
const std::uint32_t file_version = 2; // 2: the compressed modes' convergence flags
const char* const what = "vibration modes";

void write_vector(std::ostream& out, const Eigen::VectorXd& v) { MRI::write_matrix(out, v); }

void write_ints(std::ostream& out, const std::vector<int>& v)
{
  MRI::write_value<std::int64_t>(out, std::int64_t(v.size()));
  for(int x : v) MRI::write_value<std::int32_t>(out, x);
}

std::vector<int> read_ints(MRI::Binary_reader& r, std::uint64_t most, const char* name)
{
  const std::int64_t count = r.value<std::int64_t>();
  if(count < 0 || std::uint64_t(count) > most) r.fail(std::string("inconsistent count of ") + name);
  std::vector<int> v(static_cast<std::size_t>(count));
  for(int& x : v) x = r.value<std::int32_t>();
  return v;
}

bool same_stiffness(const Discrete_shells::Shell_stiffness& a, const Discrete_shells::Shell_stiffness& b)
{
  // Written and read as doubles: equal unless computed differently; 1e-12 allows a value
  // that went through a decimal printout and back.
  auto close = [](double x, double y) { return std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y)); };
  return close(a.stretching, b.stretching) && close(a.area, b.area) && close(a.bending, b.bending);
}

} // namespace

void save_modes(const std::string& path, const Modes& m, const Mode_settings& s, const Eigen::VectorXd& positions,
                const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles)
{
  const Eigen::Index vertices = positions.size() / 3;
  if(s.group_size < 1 || m.vectors.rows() != s.group_size * vertices)
    throw Invalid_input("cannot save the vibration modes to '" + path + "': " + std::to_string(m.vectors.rows()) +
                        " rows are not " + std::to_string(s.group_size) + " per vertex of the mesh");
  std::ofstream out(path, std::ios::binary);
  if(!out) throw Invalid_input("cannot write the vibration modes to '" + path + "'");
  MRI::write_header(out, file_magic, file_version, MRI::triangle_mesh_identity(positions, triangles));
  for(double x : MRI::position_signature(positions)) MRI::write_value(out, x);
  MRI::write_value<std::int32_t>(out, s.group_size);
  std::vector<int> pinned = s.pinned_vertices;
  std::sort(pinned.begin(), pinned.end());
  pinned.erase(std::unique(pinned.begin(), pinned.end()), pinned.end());
  write_ints(out, pinned);
  for(double x : {s.stiffness.stretching, s.stiffness.area, s.stiffness.bending, m.sparsity_weight, m.complete_below})
    MRI::write_value(out, x);
  MRI::write_value<std::int32_t>(out, m.kernel_dimension);
  for(int x : {m.completeness.expected, m.completeness.inertia}) MRI::write_value<std::int32_t>(out, x);
  MRI::write_value(out, m.completeness.shift);
  MRI::write_matrix(out, m.vectors);
  for(const Eigen::VectorXd* v : {&m.energies, &m.residuals, &m.objectives, &m.l1_norms, &m.support_fractions})
    write_vector(out, *v);
  write_ints(out, m.outer_iterations);
  write_ints(out, m.inner_iterations);
  write_ints(out, m.converged);
  MRI::write_value(out, file_magic);
  if(!out) throw Invalid_input("writing the vibration modes to '" + path + "' failed");
}

Modes load_modes(const std::string& path, const Eigen::VectorXd& positions,
                 const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles, const Mode_settings* expected,
                 Mode_settings* found)
{
  std::uint64_t bytes = 0;
  std::ifstream in = MRI::open_binary_file(path, what, bytes);
  MRI::Binary_reader r(in, path, bytes, what);
  r.expect_header(file_magic, file_version, MRI::triangle_mesh_identity(positions, triangles));
  const std::array<double, 4> here = MRI::position_signature(positions);
  for(int k = 0; k < 4; ++k)
  {
    // The sums agree to rounding (1e-16 of the sum of |coordinates|) for the same positions;
    // 1e-9 leaves room, and a motion of the mesh by more than that is a different position.
    const double stored = r.value<double>();
    if(!(std::abs(stored - here[std::size_t(k)]) <= 1e-9 * here[3]))
      r.fail("it belongs to the mesh in another position (moved or turned: modes are displacement vectors and turn "
             "with the mesh)");
  }
  Mode_settings s;
  s.group_size = r.value<std::int32_t>();
  const Eigen::Index vertices = positions.size() / 3;
  if(s.group_size != 1 && s.group_size != 3) r.fail("the group size is corrupt");
  s.pinned_vertices = read_ints(r, std::uint64_t(vertices), "pinned vertices");
  for(int v : s.pinned_vertices)
    if(v < 0 || v >= vertices) r.fail("a pinned vertex is outside the mesh");
  Modes m;
  for(double* x : {&s.stiffness.stretching, &s.stiffness.area, &s.stiffness.bending, &m.sparsity_weight, &m.complete_below})
    *x = r.value<double>();
  m.kernel_dimension = r.value<std::int32_t>();
  m.completeness.expected = r.value<std::int32_t>();
  m.completeness.inertia = r.value<std::int32_t>();
  m.completeness.shift = r.value<double>();
  if(expected)
  {
    if(expected->group_size != 0 && expected->group_size != s.group_size)
      r.fail("computed for group size " + std::to_string(s.group_size) + " (" +
             (s.group_size == 1 ? "a scalar problem" : "a shell") + "), not " + std::to_string(expected->group_size));
    std::vector<int> pins = expected->pinned_vertices;
    std::sort(pins.begin(), pins.end());
    pins.erase(std::unique(pins.begin(), pins.end()), pins.end());
    if(pins != s.pinned_vertices)
      r.fail("computed with other pinned vertices (" + std::to_string(s.pinned_vertices.size()) + " stored, " +
             std::to_string(pins.size()) + " given)");
    if(s.group_size == 3 && !same_stiffness(expected->stiffness, s.stiffness))
      r.fail("computed with other stiffnesses (stored k_s " + std::to_string(s.stiffness.stretching) + ", k_a " +
             std::to_string(s.stiffness.area) + ", k_b " + std::to_string(s.stiffness.bending) + ")");
  }
  m.vectors = r.matrix(s.group_size * vertices, -1, "modes");
  const Eigen::Index count = m.vectors.cols();
  auto vector = [&](const char* name, bool may_be_empty) {
    Eigen::MatrixXd v = r.matrix(-1, 1, name);
    if(v.rows() != count && !(may_be_empty && v.rows() == 0)) r.fail(std::string("the ") + name + " have the wrong size");
    return Eigen::VectorXd(v);
  };
  m.energies = vector("energies", false);
  m.residuals = vector("residuals", true);
  m.objectives = vector("objectives", true);
  m.l1_norms = vector("l1 norms", true);
  m.support_fractions = vector("support fractions", true);
  m.outer_iterations = read_ints(r, std::uint64_t(count), "outer iterations");
  m.inner_iterations = read_ints(r, std::uint64_t(count), "inner iterations");
  m.converged = read_ints(r, std::uint64_t(count), "convergence flags");
  for(int c : m.converged)
    if(c != 0 && c != 1) r.fail("a convergence flag is corrupt");
  r.expect_magic(file_magic, "the file is corrupt (no end marker)");
  if(!m.vectors.allFinite() || !m.energies.allFinite() || !m.residuals.allFinite() || !m.objectives.allFinite() ||
     !m.l1_norms.allFinite() || !m.support_fractions.allFinite() || !std::isfinite(m.sparsity_weight))
    r.fail("the file holds non-finite numbers");
  if(found) *found = s;
  return m;
}

} // namespace Vibration_modes
} // namespace CGAL
