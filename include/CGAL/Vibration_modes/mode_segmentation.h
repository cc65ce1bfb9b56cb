// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_MODE_SEGMENTATION_H
#define CGAL_VIBRATION_MODES_MODE_SEGMENTATION_H

/// \file mode_segmentation.h
/// Segmentation from the supports of (compressed) modes (SPEC 13, "Uses"): each vertex goes
/// to the mode with the largest `|u_i(v)|` (the Euclidean length of the vertex's displacement
/// in mode `i`; modes are `M`-normalised, so this is the mass density of the mode's
/// mass-weighted norm `m_v |u_i(v)|` divided by the vertex's own mass, the same for every
/// mode at `v`), or to none if every mode vanishes there or the winner is below
/// `threshold` times its own peak; the vertices of one mode are then split into connected
/// regions (through the triangles' edges).
/// \code
/// auto label = mesh.add_property_map<vertex_descriptor, int>("v:segment", -1).first;
/// int regions = VM::segment_by_modes(mesh, modes, label, VM::parameters::segmentation_threshold(0.05));
/// \endcode

#include <CGAL/Discrete_shells/make_shell_energy.h>
#include <CGAL/Vibration_modes/Modes.h>
#include <CGAL/Vibration_modes/errors.h>
#include <CGAL/Vibration_modes/named_function_parameters.h>

#include <vector>

namespace CGAL {
namespace Vibration_modes {

struct Mode_segmentation
{
  /// Region of each vertex (0 to `number_of_regions - 1`), -1 if unassigned.
  std::vector<int> region;
  /// The mode each region comes from.
  std::vector<int> region_mode;
  /// Vertices per region.
  std::vector<int> region_size;
  int number_of_regions() const { return int(region_mode.size()); }
};

/// The segmentation of a mesh of `triangles` by the columns of `modes` (`group_size` rows per
/// vertex, e.g. `Modes::vectors`).
/// \throws Invalid_input for no modes, modes with NaN, a height that is not `group_size` per
///         vertex of the triangles, or a threshold outside [0, 1).
Mode_segmentation segment_by_modes(const Eigen::MatrixXd& modes, int group_size,
                                   const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles,
                                   double threshold = 0);

/// The segmentation of `mesh` by `modes` (computed on it, in its vertex index map's order)
/// into `label_map` (vertex descriptor -> an integer type; -1 for unassigned vertices).
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{segmentation_threshold} a vertex whose winning mode is below this
///     fraction of its peak is left unassigned; `double` in [0, 1); default 0 \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map} as in CGAL \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the number of regions.
/// \throws as above; nothing is written then.
template <class TriangleMesh, class VertexLabelMap, class NamedParameters = parameters::Default_named_parameters>
int segment_by_modes(const TriangleMesh& mesh, const Modes& modes, VertexLabelMap label_map,
                     const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const double threshold = choose_parameter(get_parameter(np, internal_np::segmentation_threshold), 0.0);
  const Eigen::Index n = Eigen::Index(num_vertices(mesh));
  const int group_size = n > 0 && modes.vectors.rows() == n ? 1 : 3;
  const Mode_segmentation s =
      segment_by_modes(modes.vectors, group_size, Discrete_shells::mesh_triangles(mesh, np), threshold);
  if(Eigen::Index(s.region.size()) != n)
    throw Invalid_input("mode segmentation: the modes have " + std::to_string(modes.vectors.rows()) +
                        " rows, not 3 (or 1) per vertex of the mesh");
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  typedef typename boost::property_traits<VertexLabelMap>::value_type Label;
  for(auto v : vertices(mesh)) put(label_map, v, Label(s.region[std::size_t(get(vim, v))]));
  return s.number_of_regions();
}

} // namespace Vibration_modes
} // namespace CGAL

#endif
