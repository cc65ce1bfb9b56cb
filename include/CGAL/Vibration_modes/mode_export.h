// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_MODE_EXPORT_H
#define CGAL_VIBRATION_MODES_MODE_EXPORT_H

/// \file mode_export.h
/// Modes for other programs: the mesh with every mode as a point array of a VTK PolyData
/// file (ParaView: colour by a mode's magnitude, or "Warp By Vector"), and a mode as a
/// displaced mesh.

#include <CGAL/Discrete_shells/make_shell_energy.h>
#include <CGAL/Model_reduction/Vtk_polydata.h>
#include <CGAL/Vibration_modes/Modes.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace CGAL {
namespace Vibration_modes {

/// The mesh (`positions` stacked, `triangles`) with one point array per mode, named
/// `mode_1`, `mode_2`, ... (3 components for displacements, 1 for scalar modes), and the
/// point array `mode_support` (how many modes are non-zero at each vertex).
/// \throws Invalid_input if the modes do not have one value (or 3) per vertex.
Model_reduction::Vtk_polydata modes_polydata(const Eigen::VectorXd& positions,
                                             const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles,
                                             const Modes& modes);

/// Writes `modes_polydata` to `filename` (`.vtp`).
/// \throws Invalid_input naming the file if it cannot be written.
void write_modes_vtp(const std::string& filename, const Eigen::VectorXd& positions,
                     const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles, const Modes& modes);

/// The stacked positions moved by `scale` times mode `i` (displacement modes only).
/// \throws Invalid_input for a scalar mode or `i` out of range.
Eigen::VectorXd displaced_positions(const Eigen::VectorXd& positions, const Modes& modes, int i, double scale);

/// \brief Writes `mesh` and its modes as VTK PolyData (vertices in the vertex index map's
/// order, as the modes are).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map, vertex_index_map} as in CGAL \cgalParamNEnd
/// \cgalNamedParamsEnd
template <class TriangleMesh, class NamedParameters = parameters::Default_named_parameters>
void write_modes_vtp(const std::string& filename, const TriangleMesh& mesh, const Modes& modes,
                     const NamedParameters& np = parameters::default_values())
{
  write_modes_vtp(filename, Discrete_shells::stacked_positions(mesh, np), Discrete_shells::mesh_triangles(mesh, np),
                  modes);
}

} // namespace Vibration_modes
} // namespace CGAL

#endif
