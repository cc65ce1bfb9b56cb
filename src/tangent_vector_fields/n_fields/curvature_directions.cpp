// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/curvature_direction_field.h>

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <exception>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

typedef Simple_cartesian<double> Kernel;
typedef Monge_via_jet_fitting<Kernel> Jet_fitting;

struct Principal_direction
{
  Kernel::Vector_3 direction{0, 0, 0};
  double anisotropy = 0; // |k1 - k2|
  double curvedness = 0; // |k1| + |k2|
  bool fitted = false;
};

// Vertices within `rings` edges of v (v first), by breadth-first search.
void ring_neighbourhood(const std::vector<std::vector<int>>& neighbours, int v, int rings, std::vector<int>& out,
                        std::vector<int>& mark, int stamp)
{
  out.assign(1, v);
  mark[v] = stamp;
  std::size_t begin = 0;
  for(int r = 0; r < rings; ++r)
  {
    const std::size_t end = out.size();
    for(std::size_t i = begin; i < end; ++i)
      for(int w : neighbours[out[i]])
        if(mark[w] != stamp)
        {
          mark[w] = stamp;
          out.push_back(w);
        }
    begin = end;
  }
}

} // namespace

Eigen::VectorXd curvature_directions(const Intrinsic_mesh& mesh, Curvature_direction_report* report)
{
  const int nv = mesh.number_of_vertices(), nf = mesh.number_of_faces();
  std::vector<std::vector<int>> neighbours(nv);
  for(int e = 0; e < mesh.number_of_edges(); ++e)
  {
    const auto& ends = mesh.edge_vertices(e);
    neighbours[ends[0]].push_back(ends[1]);
    neighbours[ends[1]].push_back(ends[0]);
  }
  // A degree-2 jet has 6 coefficients; 10 points leave it over-determined (noise averages out).
  const int wanted = 10, needed = 6;
  std::vector<Principal_direction> at_vertex(nv);
  std::vector<int> ring, mark(nv, -1);
  std::vector<Kernel::Point_3> points;
  Jet_fitting fitting;
  for(int v = 0; v < nv; ++v)
  {
    if(mesh.is_isolated_vertex(v)) continue;
    ring_neighbourhood(neighbours, v, 2, ring, mark, 2 * v);
    if(static_cast<int>(ring.size()) < wanted) ring_neighbourhood(neighbours, v, 3, ring, mark, 2 * v + 1);
    if(static_cast<int>(ring.size()) < needed) continue;
    points.clear();
    for(int w : ring)
    {
      const auto& p = mesh.position(w);
      points.emplace_back(p[0], p[1], p[2]);
    }
    Jet_fitting::Monge_form monge;
    try
    {
      monge = fitting(points.begin(), points.end(), 2, 2);
    }
    catch(const std::exception&)
    {
      continue; // CGAL's preconditions (degenerate neighbourhoods): no direction here
    }
    const double k1 = monge.principal_curvatures(0), k2 = monge.principal_curvatures(1);
    Principal_direction& d = at_vertex[v];
    d.direction = std::abs(k1) >= std::abs(k2) ? monge.maximal_principal_direction() : monge.minimal_principal_direction();
    d.anisotropy = std::abs(k1 - k2);
    d.curvedness = std::abs(k1) + std::abs(k2);
    const double length = std::sqrt(d.direction.squared_length());
    d.fitted = std::isfinite(d.curvedness) && std::isfinite(length) && length > 0;
    if(!d.fitted) d = Principal_direction();
  }
  // Per face: the corners' lines averaged with doubled angles (a line and its opposite agree).
  Eigen::VectorXd x = Eigen::VectorXd::Zero(2 * nf);
  std::vector<std::complex<double>> doubled(nf);
  double weighted_square = 0, area = 0;
  for(int f = 0; f < nf; ++f)
  {
    std::complex<double> sum = 0;
    double curvedness = 0;
    for(int v : mesh.face_vertices(f))
    {
      const Principal_direction& d = at_vertex[v];
      if(!d.fitted) continue;
      curvedness += d.curvedness / 3;
      const auto ab = mesh.to_frame(f, {d.direction.x(), d.direction.y(), d.direction.z()});
      const std::complex<double> u(ab[0], ab[1]);
      if(std::abs(u) == 0) continue;
      // Doubled angle; the in-plane share of the direction (|u|^2 / |d|^2) weighs it too.
      sum += d.anisotropy * (u * u) / d.direction.squared_length();
    }
    doubled[f] = sum / 3.;
    weighted_square += mesh.face_area(f) * curvedness * curvedness;
    area += mesh.face_area(f);
  }
  const double rms = area > 0 ? std::sqrt(weighted_square / area) : 0;
  if(rms > 0 && std::isfinite(rms))
    for(int f = 0; f < nf; ++f)
    {
      const std::complex<double> line = std::polar(std::abs(doubled[f]) / rms, std::arg(doubled[f]) / 2);
      x[2 * f] = line.real();
      x[2 * f + 1] = line.imag();
    }
  if(report)
  {
    *report = Curvature_direction_report();
    for(int v = 0; v < nv; ++v)
      if(!mesh.is_isolated_vertex(v)) ++(at_vertex[v].fitted ? report->fitted_vertices : report->unfitted_vertices);
    report->curvature_scale = rms;
  }
  return x;
}

} // namespace Tangent_vector_fields
} // namespace CGAL
