// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command-line tool `tvf`: what its subcommands share.
//
// Only tool_mesh.cpp includes Surface_mesh (every translation unit that does costs
// 7 s or more to compile): it reads the mesh and the field files that need the mesh
// type, and hands the subcommands the index-based view (Intrinsic_mesh,
// Operator_matrices) and fields as frame coordinates (`2 nf`, face index order).

#ifndef TVF_TOOL_TOOL_H
#define TVF_TOOL_TOOL_H

#include <CGAL/Model_reduction/Mesh_repair_report.h>
#include <CGAL/Tangent_vector_fields/Operator_matrices.h>

#include <Eigen/Core>
#include <boost/program_options.hpp>

#include <array>
#include <chrono>
#include <initializer_list>
#include <iosfwd>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {
class Eigenfield_basis;
struct Spline_report;
}
} // namespace CGAL

namespace tvf_tool {

namespace TVF = CGAL::Tangent_vector_fields;
namespace MR = CGAL::Model_reduction;
namespace po = boost::program_options;

/// A bad command line (unknown option, missing or contradictory options): exit code 2.
class Usage_error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Any other failure (unreadable file, refused mesh, infeasible constraints): exit code 1.
class Tool_error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// The arguments after the subcommand's name.
typedef std::vector<std::string> Arguments;

struct Subcommand
{
  const char* name;
  const char* summary;
  int (*run)(const Arguments&);
};

// The subcommands (commands_*.cpp).
int info_command(const Arguments&);
int decompose_command(const Arguments&);
int basis_command(const Arguments&);
int basis_info_command(const Arguments&);
int eigenfield_command(const Arguments&);
int filter_command(const Arguments&);
int compress_command(const Arguments&);
int decompress_command(const Arguments&);
int design_command(const Arguments&);
int render_command(const Arguments&);
int streamlines_command(const Arguments&);
int export_command(const Arguments&);
int serve_command(const Arguments&);
// Vibration modes (commands_vibration_modes.cpp, commands_mode_segmentation.cpp,
// commands_mode_simulation.cpp).
int modes_command(const Arguments&);
int segment_command(const Arguments&);
int vibrate_command(const Arguments&);
int fit_command(const Arguments&);
// Motion capture compression (commands_motion.cpp).
int fit_motion_command(const Arguments&);
// Projective Dynamics (commands_projective_dynamics.cpp).
int simulate_command(const Arguments&);
// n-direction fields (commands_n_fields.cpp); basis, design, export and render hand over to the
// n-field forms when `wants_n_field` (a `--n` option) or, for design, `constraint_file_has_n`.
int smoothest_command(const Arguments&);
int singularities_command(const Arguments&);
int n_field_basis_command(const Arguments&);
int n_field_design_command(const Arguments&);
int n_field_export_command(const Arguments&);
int n_field_streamlines_command(const Arguments&);
int n_field_render_command(const Arguments&);
bool wants_n_field(const Arguments& args);
bool constraint_file_has_n(const Arguments& args);

/// The basis size is `-k K` (`--eigenfields K`) in every command; `-n K`, the vector-field
/// basis' old spelling, is accepted for it everywhere (`--n N` stays the symmetry).
Arguments with_basis_size_alias(const Arguments& args);

/// \brief The command line of one subcommand: options, one positional argument, `--help`.
///
/// Every subcommand has `-h, --help` and `-q, --quiet`; those that read a mesh also
/// get `--mollify` and `--strict`.
class Command_line
{
public:
  /// `usage`: e.g. "tvf info <mesh> [options]"; `description`: a paragraph for --help.
  Command_line(std::string usage, std::string description, bool reads_mesh = true);

  /// A group of options shown under `title` in the help.
  po::options_description& group(const std::string& title);
  /// The positional argument (at most one value).
  void positional(const std::string& name, const std::string& help);

  /// Parses; returns false if `--help` was asked for (and prints the help on stdout).
  /// \throws Usage_error for unknown options, bad values, extra arguments.
  bool parse(const Arguments& args);

  bool has(const std::string& name) const { return values_.count(name) > 0 && !values_[name].defaulted(); }
  template <class T>
  T get(const std::string& name) const
  {
    return values_[name].as<T>();
  }
  /// The positional argument; Usage_error if it is missing.
  std::string positional_value() const;
  bool quiet() const { return has("quiet"); }
  bool mollify() const { return has("mollify"); }
  bool strict() const { return has("strict"); }

  /// Usage_error unless `name` was given.
  void require(const std::string& name, const std::string& why = std::string()) const;
  /// Usage_error if more than one of `names` was given.
  void at_most_one(std::initializer_list<const char*> names) const;
  /// Usage_error unless exactly one of `names` was given.
  void exactly_one(std::initializer_list<const char*> names) const;

  void print_help(std::ostream& out) const;

private:
  std::string usage_, description_, positional_name_, positional_help_;
  std::vector<std::pair<std::string, std::unique_ptr<po::options_description>>> groups_;
  po::variables_map values_;
};

/// With `--quiet`, `say` prints nothing and no progress is shown.
void set_quiet(bool quiet);
/// The report: printf to stdout (nothing with `--quiet`).
void say(const char* format, ...) __attribute__((format(printf, 1, 2)));
/// One line "tvf: warning: <text>" on stderr (nothing with `--quiet`).
void warn(const std::string& text);
/// With `--strict` (set by `Command_line::parse`), `Tool_mesh` refuses a mesh file that
/// needs repair instead of repairing it with a warning.
void set_strict_mesh_input(bool strict);
bool strict_mesh_input();

/// Progress on stderr, drawn only when stderr is a terminal (and not `--quiet`), so
/// that scripts and the tests see nothing but errors there.
class Progress_bar
{
public:
  Progress_bar();
  ~Progress_bar();
  void update(const std::string& stage, double fraction);
  void finish();

private:
  bool enabled_, open_ = false;
  int last_percent_ = -1;
  std::string last_stage_;
};

/// A step of unknown length: on a terminal, "label ..." while it runs.  Measures its time.
class Step
{
public:
  explicit Step(const std::string& label);
  ~Step();
  double seconds() const;
  void done();

private:
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  bool shown_, done_ = false;
};

double seconds_since(std::chrono::steady_clock::time_point start);

/// Where a field comes from: a file (`.tvf`, `.rawfield`, `.vtp`, `.ply`), or the face
/// properties `name_x`, `name_y`, `name_z` of the mesh file itself (`from_mesh_file`).
struct Field_source
{
  std::string file;
  std::string name;   ///< array (`.vtp`) or face properties (`.ply`); empty: the only / first one
  int direction = 0;  ///< which vector per face of a `.rawfield` of degree > 1
  bool from_mesh_file = false;
  std::string describe() const;
};

/// A field in frame coordinates with the name it gets in `.vtp` and `.ply` files.
struct Named_field
{
  std::string name;
  Eigen::VectorXd x;
};

/// \brief A mesh read from a file, repaired, checked, with its operators.
///
/// The file is read as a polygon soup and made a triangle mesh by `Model_reduction::polygon_soup_to_mesh`
/// (polygons triangulated, orientations made consistent, non-manifold vertices and edges
/// cut apart), with a warning naming the changes; with `--strict` (`strict_mesh_input()`)
/// a file that needs any of that is refused instead.  Fields given per polygon of the
/// file (PLY face properties, `.tvf`, `.rawfield`, ...) go to the triangles the polygon
/// became.
class Tool_mesh
{
public:
  /// \throws Tool_error with a one-line reason (missing file, unknown format,
  ///         unreadable or refused mesh, a repair refused by `--strict`).
  Tool_mesh(const std::string& path, bool mollify);
  ~Tool_mesh();
  Tool_mesh(const Tool_mesh&) = delete;
  Tool_mesh& operator=(const Tool_mesh&) = delete;

  const std::string& path() const;
  const TVF::Intrinsic_mesh& intrinsic() const { return matrices_->mesh(); }
  std::shared_ptr<const TVF::Intrinsic_mesh> shared_intrinsic() const { return matrices_->shared_mesh(); }
  const TVF::Operator_matrices& matrices() const { return *matrices_; }
  std::shared_ptr<const TVF::Operator_matrices> shared_matrices() const { return matrices_; }
  int number_of_faces() const { return intrinsic().number_of_faces(); }
  double area() const { return matrices_->face_areas().sum(); }
  /// Diagonal of the bounding box of the vertices that lie in faces.
  double bounding_box_diagonal() const;
  /// Vertices of the mesh, including those in no face.
  int number_of_file_vertices() const;
  /// What the repair of the file changed (`changed()` is false for a file taken as it is).
  const MR::Mesh_repair_report& repair_report() const;
  /// Names of the face fields stored as PLY face properties `name_x`, `name_y`, `name_z`.
  std::vector<std::string> face_fields_in_file() const;

  /// Reads a field; the result is in frame coordinates (projected onto the faces).  A
  /// field with one vector per face of the mesh is taken as it is; if the repair split or
  /// removed polygons, a field with one vector per polygon of the mesh file is mapped:
  /// each triangle gets the vector of its polygon.
  /// \throws Tool_error naming the file and the reason (wrong vector count, a count that
  ///         fits both the faces and the polygons while they differ, ...).
  Eigen::VectorXd read_field(const Field_source& source) const;
  /// Writes fields to `path`, the format chosen by the extension: `.tvf` and
  /// `.rawfield` hold one field, `.vtp` and `.ply` (the mesh with face properties) any number.
  void write_fields(const std::string& path, const std::vector<Named_field>& fields) const;
  /// Largest normal component of the last field read, relative to its largest vector
  /// (what the projection onto the faces removed).
  double last_normal_fraction() const { return last_normal_fraction_; }

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::shared_ptr<const TVF::Operator_matrices> matrices_;
  mutable double last_normal_fraction_ = 0;
};

/// `--field`, `--field-name`, `--field-ply`, `--direction` in a group of `command`.
void add_field_options(Command_line& command, const std::string& title = "field input");
/// Reads the field the field options name.  \throws Usage_error if none or two are given.
Eigen::VectorXd read_input_field(const Command_line& command, const Tool_mesh& mesh);

/// `-o, --output` (repeatable) and `--output-name`.
void add_output_options(Command_line& command, const std::string& what, const std::string& default_name);
/// Writes `x` to every `--output` file; returns false if no output was given.
bool write_outputs(const Command_line& command, const Tool_mesh& mesh, const Eigen::VectorXd& x);

/// Loads a basis saved by `tvf basis` (or `Spectral_basis::save`) and checks that it
/// belongs to the mesh.  \throws Tool_error naming the file and the reason.
std::shared_ptr<const TVF::Eigenfield_basis> load_basis(const Tool_mesh& mesh, const std::string& path);
/// The `--basis FILE` option of the spectral subcommands (required or optional).
void add_basis_option(Command_line& command, bool required);

/// `reason`, prefixed with `'path': ` unless it names the file already.
std::string about(const std::string& path, const std::string& reason);
/// The extension of `path` in lower case, without the dot ("" if none).
std::string extension(const std::string& path);
/// The norm `sqrt(x^T MX x)` of a field.
double field_norm(const TVF::Operator_matrices& matrices, const Eigen::VectorXd& x);
// A reduced spline's guaranteed error bound (Spline_report::error_bound), one line.
void say_error_bound(const TVF::Spline_report& reduced);
// After --exact: the reduced answer's measured error next to its bound.  `relative_l2` is
// |x_reduced - x_exact| / |x_exact| (L2); the energy-norm error follows from the two energies.
void say_reduced_against_exact(const TVF::Spline_report& reduced, const TVF::Spline_report& exact, double relative_l2);
/// Vertex values (divergence, curl) of a field as a `std::vector`.
std::vector<double> to_std_vector(const Eigen::VectorXd& x);
/// Replaces line breaks by "; " so that an error stays on one line.
std::string one_line(std::string text);

} // namespace tvf_tool

#endif
