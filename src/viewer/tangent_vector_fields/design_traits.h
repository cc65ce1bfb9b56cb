// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What differs between the editor's two designs (editor_design.cpp): the constraint type,
// the solvers, the constraint files and what the page draws of a field.

#ifndef TVF_VIEWER_KINDS_H
#define TVF_VIEWER_KINDS_H

#include "field_session.h"
#include "messages.h"
#include "tool.h" // field_norm

#include <CGAL/Tangent_vector_fields/Eigenfield_basis.h>
#include <CGAL/Tangent_vector_fields/Full_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Hodge_solver.h>
#include <CGAL/Tangent_vector_fields/N_field_basis.h>
#include <CGAL/Tangent_vector_fields/N_field_singularities.h>
#include <CGAL/Tangent_vector_fields/N_field_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Reduced_face_vectors.h>
#include <CGAL/Tangent_vector_fields/Reduced_spline_solver.h>
#include <CGAL/Tangent_vector_fields/Streamline_tracer.h>
#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/n_field_constraint_file_io.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tvf_viewer {
namespace design_traits {

typedef TVF::internal::Json Json;

inline TVF::Spline_options spline_options(double omega)
{
  TVF::Spline_options options;
  options.omega = omega;
  return options;
}

// The page receives fields as float32: a constraint beyond 1e30 would give a field it
// cannot show (the library takes values up to the largest double).
inline void check_displayable(double magnitude, const std::string& what)
{
  if(magnitude > 1e30)
    throw Message_error(what + " of " + short_number(magnitude) +
                        " is beyond what the page shows (float32 fields: 1e30 at most); scale the values down");
}

inline double largest_coordinate(const std::array<double, 3>& v)
{
  return std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
}

// A constraint file as the designs exchange it.
template <class Constraint>
struct File
{
  std::vector<Constraint> constraints;
  std::vector<double> weights;
  bool has_omega = false;
  double omega = 0;
};

// The largest angle between the directions of two fields given per face by the angles of
// their frame or power coordinates (divided by n), over the faces where both are longer than
// 1e-3 of their largest: where a direction means something.
inline double largest_angle(const Eigen::VectorXd& a, const Eigen::VectorXd& b, int n)
{
  const Eigen::Index nf = a.size() / 2;
  double max_a = 0, max_b = 0, angle = 0;
  for(Eigen::Index f = 0; f < nf; ++f)
  {
    max_a = std::max(max_a, std::hypot(a[2 * f], a[2 * f + 1]));
    max_b = std::max(max_b, std::hypot(b[2 * f], b[2 * f + 1]));
  }
  for(Eigen::Index f = 0; f < nf; ++f)
  {
    const double x0 = a[2 * f], y0 = a[2 * f + 1], x1 = b[2 * f], y1 = b[2 * f + 1];
    if(std::hypot(x0, y0) < 1e-3 * max_a || std::hypot(x1, y1) < 1e-3 * max_b) continue;
    angle = std::max(angle, std::abs(std::atan2(x0 * y1 - y0 * x1, x0 * x1 + y0 * y1)) / n);
  }
  return angle;
}

// --- vector fields ----------------------------------------------------------------------------

struct Vector_kind
{
  typedef TVF::Field_constraint Constraint;
  typedef TVF::Reduced_spline_solver Reduced;
  typedef TVF::Full_spline_solver Full;

  std::shared_ptr<const Field_model> model;
  std::shared_ptr<const TVF::Eigenfield_basis> basis;

  // Preview strokes through the reduced field face by face.
  static constexpr bool has_preview = true;
  std::shared_ptr<TVF::Reduced_face_vectors> face_vectors(int d) const
  {
    const std::shared_ptr<const TVF::Eigenfield_rows> rows = model->eigenfield_rows(d);
    return rows ? std::make_shared<TVF::Reduced_face_vectors>(rows) : nullptr;
  }
  std::shared_ptr<const TVF::Streamline_surface> surface() const { return model->streamline_surface(); }

  int n() const { return 1; }
  int order() const { return 2; }
  int available() const { return basis->size(); }
  int kernel_dimension() const { return basis->number_of_harmonic(); }
  const TVF::Operator_matrices& matrices() const { return model->matrices(); }

  Constraint parse(const Json& c, double& weight) const
  {
    const Constraint constraint = TVF::internal::parse_constraint(c, "constraint", matrices(), &weight);
    check_displayable(largest_coordinate(constraint.vector), "a vector coordinate");
    check_displayable(std::abs(constraint.value), "a value");
    return constraint;
  }
  File<Constraint> parse_file(const Json& root) const
  {
    const TVF::Constraint_file f = TVF::internal::parse_constraint_file(root, matrices());
    return {f.constraints, f.weights, f.has_omega, f.omega};
  }
  std::string write_file(const File<Constraint>& f, int) const
  {
    TVF::Constraint_file file;
    file.omega = f.omega;
    file.has_omega = true;
    file.constraints = f.constraints;
    file.weights = f.weights;
    std::ostringstream out;
    TVF::write_constraint_file(out, file, matrices().mesh());
    return out.str();
  }
  std::unique_ptr<Reduced> reduced(int size, double omega, int) const
  {
    return std::make_unique<Reduced>(basis, size, spline_options(omega));
  }
  std::function<std::unique_ptr<Full>(double)> full_factory(int) const
  {
    const std::shared_ptr<const TVF::Hodge_solver> hodge = model->hodge();
    return [hodge](double omega) { return std::make_unique<Full>(hodge, spline_options(omega)); };
  }
  double norm(const Eigen::VectorXd& x) const { return tvf_tool::field_norm(matrices(), x); }

  std::vector<float> vectors(const Eigen::VectorXd& x, double& magnitude_max) const
  {
    return to_3d(matrices().mesh(), x, magnitude_max);
  }
  static std::vector<float> to_3d(const TVF::Intrinsic_mesh& mesh, const Eigen::VectorXd& x, double& magnitude_max)
  {
    const int nf = mesh.number_of_faces();
    std::vector<float> out(3 * static_cast<std::size_t>(nf));
    magnitude_max = 0;
    for(int f = 0; f < nf; ++f)
    {
      const auto v = mesh.from_frame(f, x[2 * f], x[2 * f + 1]);
      for(int k = 0; k < 3; ++k) out[3 * f + k] = static_cast<float>(v[k]);
      magnitude_max = std::max(magnitude_max, std::hypot(x[2 * f], x[2 * f + 1]));
    }
    return out;
  }
  double angle(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const { return largest_angle(a, b, 1); }
  bool has_scalar(const std::string& kind) const { return kind == "divergence" || kind == "curl"; }
  Eigen::VectorXd scalar(const std::string& kind, const Eigen::VectorXd& x) const
  {
    return kind == "divergence" ? matrices().divergence(x) : matrices().curl(x);
  }
  TVF::Streamline_tracer tracer(const Eigen::VectorXd& x) const { return {matrices().shared_mesh(), x}; }
  std::vector<std::pair<int, int>> singularities(const Eigen::VectorXd&) const { return {}; }
};

// --- n-direction fields -----------------------------------------------------------------------

struct N_field_kind
{
  typedef TVF::N_field_constraint Constraint;
  typedef TVF::Reduced_n_field_spline_solver Reduced;
  typedef TVF::Full_n_field_spline_solver Full;

  std::shared_ptr<const Field_model> model;
  std::shared_ptr<const TVF::N_field_basis> basis;

  // No preview yet: its strokes would need the index of the vertices they reach.
  static constexpr bool has_preview = false;
  std::shared_ptr<TVF::Reduced_face_vectors> face_vectors(int) const { return nullptr; }
  std::shared_ptr<const TVF::Streamline_surface> surface() const { return model->streamline_surface(); }

  const TVF::N_field_operators& operators() const { return basis->operators(); }
  int n() const { return basis->n(); }
  int available() const { return basis->size(); }
  int kernel_dimension() const { return basis->kernel_dimension(); }

  Constraint parse(const Json& c, double& weight) const
  {
    weight = 1;
    const Constraint constraint = TVF::internal::parse_n_field_constraint(c, "constraint", operators());
    check_displayable(largest_coordinate(constraint.vector), "a vector coordinate");
    return constraint;
  }
  File<Constraint> parse_file(const Json& root) const
  {
    const TVF::N_field_constraint_file f =
        TVF::internal::parse_n_field_constraint_file(root, model->shared_matrices());
    if(f.n != n())
      throw Message_error("the file is for n = " + std::to_string(f.n) + ", the session designs n = " +
                          std::to_string(n()) + " (set_n first)");
    if(!f.singularities.empty())
      throw Message_error("the file prescribes singularities in the connection (\"singularities\"), which needs a "
                          "basis of its own: place singularity constraints instead, or use tvf design");
    File<Constraint> out;
    out.constraints = f.constraints;
    out.weights.assign(f.constraints.size(), 1.0);
    out.has_omega = root.contains("omega");
    out.omega = f.omega;
    return out;
  }
  std::string write_file(const File<Constraint>& f, int order) const
  {
    TVF::N_field_constraint_file file;
    file.n = n();
    file.omega = f.omega;
    file.order = order;
    file.constraints = f.constraints;
    std::ostringstream out;
    TVF::write_n_field_constraint_file(out, file, model->matrices().mesh());
    return out.str();
  }
  std::unique_ptr<Reduced> reduced(int size, double omega, int order) const
  {
    return std::make_unique<Reduced>(basis, size, spline_options(omega), order);
  }
  std::function<std::unique_ptr<Full>(double)> full_factory(int order) const
  {
    const std::shared_ptr<const TVF::N_field_operators> operators = basis->shared_operators();
    return [operators, order](double omega) { return std::make_unique<Full>(operators, spline_options(omega), order); };
  }
  double norm(const Eigen::VectorXd& z) const { return std::sqrt(z.dot(operators().masses().cwiseProduct(z))); }

  std::vector<float> vectors(const Eigen::VectorXd& z, double& magnitude_max) const
  {
    return Vector_kind::to_3d(model->matrices().mesh(), operators().to_vectors(z), magnitude_max);
  }
  double angle(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const { return largest_angle(a, b, n()); }
  bool has_scalar(const std::string& kind) const { return kind == "energy"; }
  Eigen::VectorXd scalar(const std::string&, const Eigen::VectorXd& z) const { return operators().energy_density(z); }
  TVF::Streamline_tracer tracer(const Eigen::VectorXd& z) const { return {operators(), z}; }
  std::vector<std::pair<int, int>> singularities(const Eigen::VectorXd& z) const
  {
    std::vector<std::pair<int, int>> out;
    for(const TVF::N_field_singularity& s : TVF::n_field_singularities(operators(), z)) out.push_back({s.vertex, s.index});
    return out;
  }
};

} // namespace design_traits
} // namespace tvf_viewer

#endif
