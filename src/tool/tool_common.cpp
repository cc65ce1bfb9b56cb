// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command line of a subcommand, the report, progress bars, and the field input
// and output options that several subcommands share.

#include "tool.h"

#include <CGAL/Tangent_vector_fields/Spline_solver.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace tvf_tool {

// --- Command line --------------------------------------------------------------------

Command_line::Command_line(std::string usage, std::string description, bool reads_mesh)
  : usage_(std::move(usage)), description_(std::move(description))
{
  po::options_description& general = group("general");
  general.add_options()("help,h", "show this help and exit")("quiet,q", "print nothing but errors");
  if(reads_mesh)
    general.add_options()("mollify", "intrinsic mollification: make degenerate faces usable by adding a constant to "
                                     "all edge lengths (Sharp and Crane 2020); done with a warning when a mesh has "
                                     "degenerate faces, unless --strict")(
        "strict", "refuse a mesh file that needs repair (polygons to triangulate, orientations to make consistent, "
                  "non-manifold vertices or edges, degenerate or duplicate polygons) or mollification (degenerate "
                  "faces) instead of repairing it");
}

po::options_description& Command_line::group(const std::string& title)
{
  for(const auto& g : groups_)
    if(g.first == title) return *g.second;
  groups_.emplace_back(title, std::make_unique<po::options_description>(title, 100, 50));
  return *groups_.back().second;
}

void Command_line::positional(const std::string& name, const std::string& help)
{
  positional_name_ = name;
  positional_help_ = help;
}

bool Command_line::parse(const Arguments& args)
{
  po::options_description all;
  for(const auto& g : groups_) all.add(*g.second);
  po::options_description hidden;
  po::positional_options_description positional;
  if(!positional_name_.empty())
  {
    hidden.add_options()(positional_name_.c_str(), po::value<std::vector<std::string>>(), "");
    positional.add(positional_name_.c_str(), -1);
    all.add(hidden);
  }
  try
  {
    po::store(po::command_line_parser(args).options(all).positional(positional).run(), values_);
    if(values_.count("help"))
    {
      print_help(std::cout);
      return false;
    }
    po::notify(values_);
  }
  catch(const po::error& e)
  {
    throw Usage_error(e.what());
  }
  if(!positional_name_.empty() && values_.count(positional_name_) &&
     values_[positional_name_].as<std::vector<std::string>>().size() > 1)
    throw Usage_error("unexpected argument '" + values_[positional_name_].as<std::vector<std::string>>()[1] +
                      "' (only one " + positional_name_ + " is read)");
  set_quiet(quiet());
  set_strict_mesh_input(strict());
  return true;
}

std::string Command_line::positional_value() const
{
  if(positional_name_.empty() || !values_.count(positional_name_))
    throw Usage_error("the " + positional_name_ + " argument is missing");
  return values_[positional_name_].as<std::vector<std::string>>().front();
}

void Command_line::require(const std::string& name, const std::string& why) const
{
  if(!values_.count(name)) throw Usage_error("the option '--" + name + "' is required" + (why.empty() ? "" : " " + why));
}

void Command_line::at_most_one(std::initializer_list<const char*> names) const
{
  std::vector<std::string> given;
  for(const char* n : names)
    if(has(n)) given.push_back(std::string("--") + n);
  if(given.size() > 1) throw Usage_error("the options '" + given[0] + "' and '" + given[1] + "' exclude each other");
}

void Command_line::exactly_one(std::initializer_list<const char*> names) const
{
  at_most_one(names);
  for(const char* n : names)
    if(has(n)) return;
  std::string list;
  for(const char* n : names) list += (list.empty() ? "'--" : ", '--") + std::string(n) + "'";
  throw Usage_error("one of " + list + " is required");
}

void Command_line::print_help(std::ostream& out) const
{
  out << "usage: " << usage_ << "\n\n" << description_ << "\n";
  if(!positional_name_.empty()) out << "\n  <" << positional_name_ << ">  " << positional_help_ << "\n";
  for(const auto& g : groups_) out << '\n' << *g.second;
}

// --- Report and progress ---------------------------------------------------------------

namespace {
bool quiet_mode = false;
bool strict_mode = false;

bool stderr_is_terminal() { return !quiet_mode && isatty(STDERR_FILENO) != 0; }
} // namespace

void set_quiet(bool quiet) { quiet_mode = quiet; }

void set_strict_mesh_input(bool strict) { strict_mode = strict; }

bool strict_mesh_input() { return strict_mode; }

void warn(const std::string& text)
{
  if(quiet_mode) return;
  std::fflush(stdout);
  std::fprintf(stderr, "tvf: warning: %s\n", one_line(text).c_str());
  std::fflush(stderr);
}

void say(const char* format, ...)
{
  if(quiet_mode) return;
  std::fflush(stdout);
  std::cout.flush();
  va_list args;
  va_start(args, format);
  std::vprintf(format, args);
  va_end(args);
  std::fflush(stdout);
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Progress_bar::Progress_bar() : enabled_(stderr_is_terminal()) {}

Progress_bar::~Progress_bar() { finish(); }

void Progress_bar::update(const std::string& stage, double fraction)
{
  if(!enabled_) return;
  fraction = std::min(1., std::max(0., fraction));
  const int percent = static_cast<int>(100 * fraction + 0.5);
  if(percent == last_percent_ && stage == last_stage_) return;
  last_percent_ = percent;
  last_stage_ = stage;
  const int width = 30, filled = static_cast<int>(fraction * width + 0.5);
  std::fprintf(stderr, "\r  [%s%s] %3d%%  %-28.28s", std::string(filled, '#').c_str(),
               std::string(width - filled, '-').c_str(), percent, stage.c_str());
  std::fflush(stderr);
  open_ = true;
}

void Progress_bar::finish()
{
  if(open_)
  {
    std::fprintf(stderr, "\r%72s\r", "");
    std::fflush(stderr);
  }
  open_ = false;
}

Step::Step(const std::string& label)
  : label_(label), start_(std::chrono::steady_clock::now()), shown_(stderr_is_terminal())
{
  if(shown_)
  {
    std::fprintf(stderr, "  %s ...", label_.c_str());
    std::fflush(stderr);
  }
}

Step::~Step() { done(); }

double Step::seconds() const { return seconds_since(start_); }

void Step::done()
{
  if(done_) return;
  done_ = true;
  if(shown_)
  {
    std::fprintf(stderr, "\r%*s\r", static_cast<int>(label_.size()) + 8, "");
    std::fflush(stderr);
  }
}

// --- Field options ------------------------------------------------------------------------

std::string Field_source::describe() const
{
  if(from_mesh_file) return "face properties '" + name + "_x/_y/_z' of the mesh file";
  return "'" + file + "'";
}

void add_field_options(Command_line& command, const std::string& title)
{
  command.group(title).add_options()
    ("field", po::value<std::string>()->value_name("FILE"),
     "the field: .tvf (text, one vector per face), .rawfield (Directional), .vtp (a cell array), or .ply "
     "(face properties NAME_x, NAME_y, NAME_z of a PLY mesh with the same faces)")
    ("field-name", po::value<std::string>()->value_name("NAME"),
     "which array of a .vtp or which face properties of a .ply file (default: the first / the only one)")
    ("field-ply", po::value<std::string>()->value_name("NAME"),
     "read the field from the face properties NAME_x, NAME_y, NAME_z of the mesh file itself (a PLY mesh)")
    ("direction", po::value<int>()->default_value(0)->value_name("I"),
     "which vector per face of a .rawfield with several (an N-RoSy field), 0-based");
}

Eigen::VectorXd read_input_field(const Command_line& command, const Tool_mesh& mesh)
{
  command.exactly_one({"field", "field-ply"});
  Field_source source;
  if(command.has("field"))
  {
    source.file = command.get<std::string>("field");
    if(command.has("field-name")) source.name = command.get<std::string>("field-name");
  }
  else
  {
    source.from_mesh_file = true;
    source.name = command.get<std::string>("field-ply");
    if(command.has("field-name")) throw Usage_error("'--field-name' goes with '--field', not with '--field-ply'");
  }
  source.direction = command.get<int>("direction");
  Eigen::VectorXd x = mesh.read_field(source);
  if(mesh.last_normal_fraction() > 1e-6)
    say("note: the field had components normal to the faces (up to %.2g of its largest vector); they were "
        "projected away\n", mesh.last_normal_fraction());
  return x;
}

void add_output_options(Command_line& command, const std::string& what, const std::string& default_name)
{
  command.group("output").add_options()
    ("output,o", po::value<std::vector<std::string>>()->composing()->value_name("FILE"),
     (what + ", by extension: .tvf, .ply (the mesh with face properties NAME_x/_y/_z), .vtp (ParaView), "
             ".rawfield (Directional); repeat for several files").c_str())
    ("output-name", po::value<std::string>()->default_value(default_name)->value_name("NAME"),
     "name of the field in .ply and .vtp files");
}

bool write_outputs(const Command_line& command, const Tool_mesh& mesh, const Eigen::VectorXd& x)
{
  if(!command.has("output")) return false;
  const std::string name = command.get<std::string>("output-name");
  for(const std::string& path : command.get<std::vector<std::string>>("output"))
  {
    mesh.write_fields(path, {{name, x}});
    say("wrote %s\n", path.c_str());
  }
  return true;
}

// --- Small helpers -----------------------------------------------------------------------

std::string about(const std::string& path, const std::string& reason)
{
  return reason.find(path) == std::string::npos ? "'" + path + "': " + reason : reason;
}

std::string extension(const std::string& path)
{
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t dot = path.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::string();
  std::string e = path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}

double field_norm(const TVF::Operator_matrices& matrices, const Eigen::VectorXd& x)
{
  // Field and areas scaled to near 1 first (by powers of two): area times squared
  // value would overflow or underflow for huge or tiny meshes and fields.
  const double largest = x.size() > 0 ? x.cwiseAbs().maxCoeff() : 0.;
  if(!(largest > 0) || !std::isfinite(largest)) return largest > 0 ? largest : 0.;
  const double s = std::ldexp(1., std::ilogb(largest)), u = matrices.mesh().length_unit();
  const Eigen::VectorXd y = x / s;
  return std::sqrt(y.dot((matrices.field_masses() / u / u).cwiseProduct(y))) * u * s;
}

std::vector<double> to_std_vector(const Eigen::VectorXd& x) { return std::vector<double>(x.data(), x.data() + x.size()); }

void say_error_bound(const TVF::Spline_report& reduced)
{
  if(std::isnan(reduced.error_bound))
    say("  error bound: none known (a guide's alignment term, or a basis that does not say which eigenvalues it "
        "lacks)\n");
  else
    say("  error bound: |x - x*|_E <= %.3g |x*|_E against the exact spline x* (energy norm, guaranteed; --exact "
        "measures it)\n",
        reduced.error_bound);
}

void say_reduced_against_exact(const TVF::Spline_report& reduced, const TVF::Spline_report& exact, double relative_l2)
{
  // |x - x*|_E^2 = E(x) - E(x*) for a feasible x (the optimality of x*): the excess energy.
  const double excess = std::max(0., reduced.energy - exact.energy);
  const double energy_error = exact.energy > 0 ? std::sqrt(excess / exact.energy) : 0.;
  say("  exact: constraint residual %.2e; energy E_B + omega E_D = %.6g\n", exact.constraint_residual, exact.energy);
  say("  the reduced answer's error: %.3g of the exact field in the energy norm (bound %.3g), %.3g in L2\n",
      energy_error, reduced.error_bound, relative_l2);
}

std::string one_line(std::string text)
{
  while(!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
  std::string out;
  for(std::size_t i = 0; i < text.size(); ++i)
  {
    if(text[i] == '\n' || text[i] == '\r')
    {
      if(!out.empty() && out.back() != ' ') out += "; ";
      while(i + 1 < text.size() && (text[i + 1] == '\n' || text[i + 1] == '\r' || text[i + 1] == ' ')) ++i;
    }
    else out += text[i];
  }
  return out;
}

Arguments with_basis_size_alias(const Arguments& args)
{
  Arguments out = args;
  for(std::string& a : out)
  {
    if(a == "--") break; // what follows is positional
    // "-n 300" and "-n300"; not "--n", nor a value such as "-nan" or a file "-notes.tvf"
    if(a.size() >= 2 && a[0] == '-' && a[1] == 'n' && (a.size() == 2 || std::isdigit(static_cast<unsigned char>(a[2]))))
      a[1] = 'k';
  }
  return out;
}

} // namespace tvf_tool
