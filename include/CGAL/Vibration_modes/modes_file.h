// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_MODES_FILE_H
#define CGAL_VIBRATION_MODES_MODES_FILE_H

/// \file modes_file.h
/// Saving and loading modes, ordinary or compressed (`.vmb` files, the shared package's
/// binary result files): the vectors, energies, objectives and reports of `Modes`, what they
/// were computed with (group size, pinned vertices, shell stiffnesses, the sparsity weight
/// mu), and the identity of the mesh: its connectivity, its edge lengths and its position.
/// A file is loaded only onto the mesh it was computed on, in the same position (modes are
/// displacement vectors and turn with the mesh); a refusal says which of these differs.
/// \code
/// VM::save_vibration_modes(mesh, modes, "elephant.vmb", VM::parameters::pinned_vertices(feet));
/// VM::Modes again = VM::load_vibration_modes(mesh, "elephant.vmb", VM::parameters::pinned_vertices(feet));
/// \endcode

#include <CGAL/Discrete_shells/make_shell_energy.h>
#include <CGAL/Vibration_modes/Modes.h>
#include <CGAL/Vibration_modes/errors.h>
#include <CGAL/Vibration_modes/named_function_parameters.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Vibration_modes {

/// What a set of modes was computed with, stored beside it.
struct Mode_settings
{
  /// Unknowns per vertex: 3 for a shell's displacements, 1 for a scalar (Laplacian) problem.
  int group_size = 3;
  /// The pinned vertices (any order; compared as sets).
  std::vector<int> pinned_vertices;
  /// The shell's stiffnesses (ignored for a scalar problem).
  Discrete_shells::Shell_stiffness stiffness;
};

/// Writes `modes` with `settings` and the identity of the mesh (`positions` stacked, `triangles`).
/// \throws Invalid_input if the file cannot be written, or the modes' height is not
///         `group_size` per vertex.
void save_modes(const std::string& path, const Modes& modes, const Mode_settings& settings,
                const Eigen::VectorXd& positions, const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles);

/// Reads modes saved by `save_modes` for this mesh.  If `expected` is given, the stored
/// settings must equal it (same group size unless `expected->group_size` is 0, pinned set, and
/// for a shell the stiffnesses to 1e-12 relative);
/// `found`, if given, receives the stored settings.
/// \throws Invalid_input "cannot load the vibration modes from '<path>': <reason>", the reason
///         one of: not a vibration modes file; file format version; "it belongs to a mesh with
///         other connectivity"; "... with other edge lengths"; "it belongs to the mesh in
///         another position"; "computed with other pinned vertices"; "... with other
///         stiffnesses"; "... for group size"; the file is truncated or corrupt.
Modes load_modes(const std::string& path, const Eigen::VectorXd& positions,
                 const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles,
                 const Mode_settings* expected = nullptr, Mode_settings* found = nullptr);

namespace internal {

template <class TriangleMesh, class NamedParameters>
Mode_settings mode_settings_of(const TriangleMesh& mesh, const Modes& modes, const NamedParameters& np)
{
  Mode_settings s;
  s.group_size = modes.vectors.rows() == Eigen::Index(num_vertices(mesh)) ? 1 : 3;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::pinned_vertices_t>::value)
  {
    const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
    for(const auto& v : parameters::get_parameter_reference(np, internal_np::pinned_vertices))
      s.pinned_vertices.push_back(int(get(vim, v)));
  }
  s.stiffness = Discrete_shells::shell_stiffness(np);
  return s;
}

} // namespace internal

/// Saves `modes` computed on `mesh` (by `vibration_modes` or `compressed_vibration_modes` with
/// the same named parameters).
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{pinned_vertices, stretching_stiffness, area_stiffness, bending_stiffness}
///     as given to the computation; stored and checked on loading \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, vertex_index_map} as in CGAL \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
void save_vibration_modes(const TriangleMesh& mesh, const Modes& modes, const std::string& path,
                          const NamedParameters& np = parameters::default_values())
{
  save_modes(path, modes, internal::mode_settings_of(mesh, modes, np), Discrete_shells::stacked_positions(mesh, np),
             Discrete_shells::mesh_triangles(mesh, np));
}

/// Loads modes saved for `mesh` with the same named parameters (pins and stiffnesses), and
/// refuses a file of another mesh, position, pins or stiffnesses with the reason.
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
Modes load_vibration_modes(const TriangleMesh& mesh, const std::string& path,
                           const NamedParameters& np = parameters::default_values())
{
  Mode_settings expected = internal::mode_settings_of(mesh, Modes(), np);
  expected.group_size = 0; // any: a scalar or a shell problem
  return load_modes(path, Discrete_shells::stacked_positions(mesh, np), Discrete_shells::mesh_triangles(mesh, np),
                    &expected);
}

} // namespace Vibration_modes
} // namespace CGAL

#endif
