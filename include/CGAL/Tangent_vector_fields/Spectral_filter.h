// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TANGENT_VECTOR_FIELDS_SPECTRAL_FILTER_H
#define CGAL_TANGENT_VECTOR_FIELDS_SPECTRAL_FILTER_H

/// \file Spectral_filter.h
/// Spectral filters of tangent fields (SPEC 6): a transfer function per type of
/// eigenfield, applied to the frequency `omega = sqrt(lambda)`, and constant factors
/// for the harmonic part and for the rest field (what the basis does not represent).

#include <cmath>
#include <functional>
#include <limits>
#include <utility>

namespace CGAL {
namespace Tangent_vector_fields {

struct Spectral_filter
{
  typedef std::function<double(double)> Transfer;

  /// Multiplies the coefficient of an exact (curl-free) eigenfield of frequency `omega`.
  Transfer exact = [](double) { return 1.; };
  /// Multiplies the coefficient of a coexact (divergence-free) eigenfield.
  Transfer coexact = [](double) { return 1.; };
  /// Multiplies the harmonic part.
  double harmonic_factor = 1;
  /// Multiplies the rest field `v - (projection of v onto the basis)`, which holds
  /// the frequencies above the basis.
  double rest_factor = 1;

  /// The same transfer for both types; the rest field gets `transfer(infinity)`
  /// when that is finite, 0 otherwise.
  static Spectral_filter from_transfer(Transfer transfer, double harmonic_factor = 1)
  {
    Spectral_filter f;
    f.exact = transfer;
    f.coexact = transfer;
    f.harmonic_factor = harmonic_factor;
    const double at_infinity = transfer(std::numeric_limits<double>::infinity());
    f.rest_factor = std::isfinite(at_infinity) ? at_infinity : 0.;
    return f;
  }
  /// Heat-kernel smoothing `exp(-t omega^2)`: the field after diffusing for time `t`.
  static Spectral_filter low_pass(double t)
  {
    return from_transfer([t](double omega) { return std::exp(-t * omega * omega); });
  }
  /// Sharpening `2 - exp(-t omega^2)`: doubles the high frequencies, keeps the low ones.
  static Spectral_filter high_pass(double t)
  {
    return from_transfer([t](double omega) { return 2 - std::exp(-t * omega * omega); });
  }
  /// Keeps frequencies in `[omega_low, omega_high]` (the harmonic part when
  /// `omega_low <= 0`), removes the rest.
  static Spectral_filter band_pass(double omega_low, double omega_high)
  {
    Spectral_filter f = from_transfer(
        [omega_low, omega_high](double omega) { return omega >= omega_low && omega <= omega_high ? 1. : 0.; },
        omega_low <= 0 ? 1. : 0.);
    f.rest_factor = std::isinf(omega_high) ? 1. : 0.;
    return f;
  }
  /// Only the curl-free part (exact eigenfields; the rest field is dropped).
  static Spectral_filter exact_part()
  {
    Spectral_filter f;
    f.coexact = [](double) { return 0.; };
    f.harmonic_factor = 0;
    f.rest_factor = 0;
    return f;
  }
  /// Only the divergence-free part without harmonic fields.
  static Spectral_filter coexact_part()
  {
    Spectral_filter f;
    f.exact = [](double) { return 0.; };
    f.harmonic_factor = 0;
    f.rest_factor = 0;
    return f;
  }
};

} // namespace Tangent_vector_fields
} // namespace CGAL

#endif
