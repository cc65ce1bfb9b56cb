// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Vibration_modes/mode_export.h>
#include <CGAL/Vibration_modes/errors.h>

#include <fstream>

namespace CGAL {
namespace Vibration_modes {

namespace {
int values_per_vertex(const Eigen::VectorXd& positions, const Modes& modes)
{
  const Eigen::Index n = positions.size() / 3;
  if(n == 0 || positions.size() != 3 * n) throw Invalid_input("mode export: positions are not 3 coordinates per vertex");
  if(modes.vectors.rows() == 3 * n) return 3;
  if(modes.vectors.rows() == n) return 1;
  throw Invalid_input("mode export: modes have " + std::to_string(modes.vectors.rows()) + " values for " +
                      std::to_string(n) + " vertices (1 or 3 per vertex expected)");
}
} // namespace

Model_reduction::Vtk_polydata modes_polydata(const Eigen::VectorXd& positions,
                                             const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles,
                                             const Modes& modes)
{
  const int g = values_per_vertex(positions, modes);
  const Eigen::Index n = positions.size() / 3;
  Model_reduction::Vtk_polydata data;
  data.points.reserve(std::size_t(n));
  for(Eigen::Index v = 0; v < n; ++v) data.points.push_back({positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]});
  for(const auto& t : triangles)
  {
    for(int k = 0; k < 3; ++k)
      if(t[k] < 0 || t[k] >= n) throw Invalid_input("mode export: a triangle names vertex " + std::to_string(t[k]));
    data.polygons.push_back({t[0], t[1], t[2]});
  }
  Model_reduction::Vtk_polydata::Array support{"mode_support", 1, std::vector<double>(std::size_t(n), 0.0)};
  for(Eigen::Index i = 0; i < modes.vectors.cols(); ++i)
  {
    Model_reduction::Vtk_polydata::Array a{"mode_" + std::to_string(i + 1), g, {}};
    a.values.assign(modes.vectors.col(i).data(), modes.vectors.col(i).data() + modes.vectors.rows());
    for(Eigen::Index v = 0; v < n; ++v) support.values[std::size_t(v)] += modes.vectors.col(i).segment(g * v, g).squaredNorm() > 0;
    data.point_data.push_back(std::move(a));
  }
  data.point_data.push_back(std::move(support));
  return data;
}

void write_modes_vtp(const std::string& filename, const Eigen::VectorXd& positions,
                     const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles, const Modes& modes)
{
  const Model_reduction::Vtk_polydata data = modes_polydata(positions, triangles, modes);
  std::ofstream out(filename);
  if(!out) throw Invalid_input("'" + filename + "': cannot be opened for writing");
  Model_reduction::write_vtk_polydata(out, data);
  out.close();
  if(!out) throw Invalid_input("'" + filename + "': writing failed");
}

Eigen::VectorXd displaced_positions(const Eigen::VectorXd& positions, const Modes& modes, int i, double scale)
{
  if(values_per_vertex(positions, modes) != 3)
    throw Invalid_input("displaced positions: a scalar mode does not move the vertices");
  if(i < 0 || i >= modes.vectors.cols())
    throw Invalid_input("displaced positions: mode " + std::to_string(i) + " asked for, " +
                        std::to_string(modes.vectors.cols()) + " modes exist");
  return positions + scale * modes.vectors.col(i);
}

} // namespace Vibration_modes
} // namespace CGAL
