// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SPLINE_APPROXIMATION_APPROXIMATE_CURVE_H
#define CGAL_SPLINE_APPROXIMATION_APPROXIMATE_CURVE_H

/// \file approximate_curve.h
/// The generic front-end: a spline with the fewest knots through a range of CGAL points
/// (`Point_2`, `Point_3` of any kernel), options as named parameters.

#include <CGAL/Spline_approximation/Spline_fit.h>
#include <CGAL/Spline_approximation/named_function_parameters.h>

#include <CGAL/Dimension.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <iterator>
#include <vector>

namespace CGAL {
namespace Spline_approximation {

/// The rows of a matrix, one per point of `points` (a range of `Point_2` or `Point_3`).
template <class PointRange>
Eigen::MatrixXd points_to_matrix(const PointRange& points)
{
  typedef typename std::iterator_traits<decltype(std::begin(points))>::value_type Point;
  const int dim = CGAL::Ambient_dimension<Point>::value;
  Eigen::MatrixXd P(Eigen::Index(std::distance(std::begin(points), std::end(points))), dim);
  Eigen::Index j = 0;
  for(const Point& p : points) {
    for(int d = 0; d < dim; ++d) P(j, d) = CGAL::to_double(p.cartesian(d));
    ++j;
  }
  return P;
}

/// Fits a curve (open, or closed with `closed_curve(true)`) through `points` with the fewest knots for the goal given.
///
/// \tparam PointRange a range of CGAL `Point_2` or `Point_3`
/// \param np exactly one of `knot_penalty`, `max_error_bound`, `rms_error_bound`, and optionally:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{spline_degree} 1 to 3; `int`; default 3 \cgalParamNEnd
///   \cgalParamNBegin{knot_penalty} lambda >= 0, the cost of a knot in squared length units; `double` \cgalParamNEnd
///   \cgalParamNBegin{max_error_bound} the fewest knots with every point within this distance (> 0); `double` \cgalParamNEnd
///   \cgalParamNBegin{rms_error_bound} the fewest knots within this root-mean-square distance (> 0); `double` \cgalParamNEnd
///   \cgalParamNBegin{fit_algorithm} `Fit_algorithm`; default `penalty_decomposition` \cgalParamNEnd
///   \cgalParamNBegin{candidate_grid_size} 0: every point's parameter is a candidate knot; g: a uniform grid of g; `std::size_t`; default 0 \cgalParamNEnd
///   \cgalParamNBegin{relocate_knots_up_to} degree 1, up to this many samples: knots slid and removed by a local search after the heuristic (`Fit_options::relocate_knots_up_to`); `std::size_t`; default 1048576 \cgalParamNEnd
///   \cgalParamNBegin{coarse_start_above} above this many candidates the heuristics start from a coarse-to-fine knot set (`Fit_options::coarse_start_above`); `std::size_t`; default 4096 \cgalParamNEnd
///   \cgalParamNBegin{closed_curve} the last point joins the first (not repeated); a periodic spline; `bool`; default false \cgalParamNEnd
///   \cgalParamNBegin{curve_parameters} one strictly increasing parameter per point; `std::vector<double>`; default chord length \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Invalid_input as `fit_spline` does.
template <class PointRange, class NamedParameters = parameters::Default_named_parameters>
Spline_fit approximate_curve(const PointRange& points, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Fit_options o;
  o.degree = choose_parameter(get_parameter(np, internal_np::spline_degree), 3);
  o.algorithm = choose_parameter(get_parameter(np, internal_np::fit_algorithm), Fit_algorithm::penalty_decomposition);
  o.candidate_grid_size = choose_parameter(get_parameter(np, internal_np::candidate_grid_size), std::size_t(0));
  o.coarse_start_above = choose_parameter(get_parameter(np, internal_np::coarse_start_above), o.coarse_start_above);
  o.relocate_knots_up_to =
      choose_parameter(get_parameter(np, internal_np::relocate_knots_up_to), o.relocate_knots_up_to);
  o.closed_curve = choose_parameter(get_parameter(np, internal_np::closed_curve), false);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::knot_penalty_t>::value)
    o.penalty = double(get_parameter(np, internal_np::knot_penalty));
  if constexpr(!is_default_parameter<NamedParameters, internal_np::max_error_bound_t>::value)
    o.max_error = double(get_parameter(np, internal_np::max_error_bound));
  if constexpr(!is_default_parameter<NamedParameters, internal_np::rms_error_bound_t>::value)
    o.rms_error = double(get_parameter(np, internal_np::rms_error_bound));
  const Eigen::MatrixXd P = points_to_matrix(points);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::curve_parameters_t>::value) {
    const auto& given = get_parameter(np, internal_np::curve_parameters);
    Eigen::VectorXd t(Eigen::Index(std::distance(std::begin(given), std::end(given))));
    Eigen::Index j = 0;
    for(const auto& x : given) t[j++] = double(x);
    return fit_spline(P, t, o);
  } else {
    return fit_spline(P, o);
  }
}

} // namespace Spline_approximation
} // namespace CGAL

#endif
