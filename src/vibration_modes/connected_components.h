// Copyright (c) 2026 The Vibration_modes authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_VIBRATION_MODES_SRC_CONNECTED_COMPONENTS_H
#define CGAL_VIBRATION_MODES_SRC_CONNECTED_COMPONENTS_H

#include <CGAL/Discrete_shells/Shell_energy.h>

#include <vector>

namespace CGAL {
namespace Vibration_modes {
namespace internal {

/// The component of each of `n` vertices (0 to `count - 1`; -1 for a vertex in no triangle).
std::vector<int> connected_components(Eigen::Index n, const std::vector<Discrete_shells::Shell_energy::Triangle>& triangles,
                                      int& count);

} // namespace internal
} // namespace Vibration_modes
} // namespace CGAL

#endif
