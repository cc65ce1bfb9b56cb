// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/internal/constraint_json.h>

#include <boost/property_tree/json_parser.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace CGAL {
namespace Tangent_vector_fields {

namespace internal {

double Json_reader::number(const char* key) const
{
  if(!has(key)) fail(std::string("missing \"") + key + "\"");
  double x = 0;
  if(!read_json_number(node.get_child(key), x)) fail(std::string("\"") + key + "\" is not a number");
  if(!std::isfinite(x)) fail(std::string("\"") + key + "\" is not finite");
  return x;
}

int Json_reader::index(const char* key) const
{
  const double x = number(key);
  if(x != std::floor(x) || x < 0 || x > 2e9) fail(std::string("\"") + key + "\" is not a valid index");
  return static_cast<int>(x);
}

std::array<double, 3> Json_reader::triple(const char* key) const
{
  if(!has(key)) fail(std::string("missing \"") + key + "\"");
  std::array<double, 3> v{{0, 0, 0}};
  int k = 0;
  for(const auto& child : node.get_child(key))
  {
    if(!child.first.empty() || k == 3 || !read_json_number(child.second, v[k++]))
      fail(std::string("\"") + key + "\" must be an array of 3 numbers");
  }
  if(k != 3) fail(std::string("\"") + key + "\" must be an array of 3 numbers");
  for(double x : v)
    if(!std::isfinite(x)) fail(std::string("\"") + key + "\" has a non-finite entry");
  return v;
}

std::array<double, 3> Json_reader::point(const Intrinsic_mesh& mesh, int face) const
{
  if(face >= mesh.number_of_faces()) fail("face " + std::to_string(face) + " out of range");
  if(has("point")) return barycentric_coordinates(mesh, face, triple("point"));
  if(has("barycentric"))
  {
    const std::array<double, 3> w = triple("barycentric");
    const std::array<double, 3> v = triple("vertices");
    try
    {
      return barycentric_in_face_order(mesh, face, {{int(v[0]), int(v[1]), int(v[2])}}, w);
    }
    catch(const Invalid_input& e)
    {
      fail(e.what());
    }
  }
  fail("a point in a face needs \"point\" or \"vertices\" and \"barycentric\"");
}

} // namespace internal

namespace {

typedef boost::property_tree::ptree Tree;
typedef internal::Json_reader Reader;

Field_constraint parse(const Tree& node, const std::string& name, const Intrinsic_mesh& mesh)
{
  const Reader r{node, name};
  if(!node.data().empty() || node.empty()) r.fail("not a JSON object");
  const std::string type = node.get<std::string>("type", "");
  if(type == "vector") return Field_constraint::vector_in_face(r.index("face"), r.triple("vector"));
  if(type == "direction") return Field_constraint::direction_in_face(r.index("face"), r.triple("direction"));
  if(type == "divergence")
  {
    if(r.has("vertex")) return Field_constraint::divergence_at_vertex(r.index("vertex"), r.number("value"));
    const int face = r.index("face");
    return Field_constraint::divergence_at_point(face, r.point(mesh, face), r.number("value"));
  }
  if(type == "curl")
  {
    if(r.has("edge")) return Field_constraint::curl_at_edge(r.index("edge"), r.number("value"));
    const int face = r.index("face");
    return Field_constraint::curl_at_point(face, r.point(mesh, face), r.number("value"));
  }
  if(type == "boundary_alignment")
  {
    try
    {
      return Field_constraint::boundary_alignment(mesh, r.index("edge"));
    }
    catch(const Invalid_input& e)
    {
      r.fail(e.what());
    }
  }
  r.fail("unknown type \"" + type + "\" (vector, direction, divergence, curl, boundary_alignment)");
}

} // namespace

namespace internal {

bool read_json_number(const boost::property_tree::ptree& node, double& x)
{
  const std::string& text = node.data();
  if(!node.empty() || text.empty()) return false;
  char* end = nullptr;
  x = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

Field_constraint parse_constraint(const boost::property_tree::ptree& node, const std::string& name,
                                  const Operator_matrices& operators, double* weight)
{
  Field_constraint c = parse(node, name, operators.mesh());
  // Validates indices and values now, so that errors name the constraint.
  try
  {
    constraint_rows(operators, c);
  }
  catch(const Invalid_input& e)
  {
    throw Invalid_input(name + ": " + e.what());
  }
  if(weight)
  {
    const Reader r{node, name};
    *weight = r.has("weight") ? r.number("weight") : 1.0;
    if(!(*weight > 0)) r.fail("the weight must be positive");
  }
  return c;
}

Constraint_file parse_constraint_file(const boost::property_tree::ptree& root, const Operator_matrices& operators)
{
  Constraint_file file;
  if(root.count("omega"))
  {
    try
    {
      file.omega = root.get<double>("omega");
    }
    catch(const boost::property_tree::ptree_bad_data&)
    {
      throw Invalid_input("constraint file: omega is not a number");
    }
    file.has_omega = true;
    if(!std::isfinite(file.omega) || file.omega < 0) throw Invalid_input("constraint file: omega must be >= 0");
  }
  if(!root.count("constraints")) throw Invalid_input("constraint file: no \"constraints\" array");
  int position = 0;
  for(const auto& child : root.get_child("constraints"))
  {
    if(!child.first.empty()) throw Invalid_input("constraint file: \"constraints\" must be an array");
    double weight = 1;
    file.constraints.push_back(
        parse_constraint(child.second, "constraint " + std::to_string(position), operators, &weight));
    file.weights.push_back(weight);
    ++position;
  }
  return file;
}

} // namespace internal

Constraint_file read_constraint_file(std::istream& in, const Operator_matrices& operators)
{
  Tree root;
  try
  {
    boost::property_tree::read_json(in, root);
  }
  catch(const boost::property_tree::json_parser_error& e)
  {
    throw Invalid_input("constraint file: " + e.message() + " at line " + std::to_string(e.line()));
  }
  return internal::parse_constraint_file(root, operators);
}

Constraint_file read_constraint_file(const std::string& path, const Operator_matrices& operators)
{
  std::ifstream in(path);
  if(!in) throw Invalid_input("cannot open constraint file " + path);
  return read_constraint_file(in, operators);
}

void write_constraint_file(std::ostream& out, const Constraint_file& file, const Intrinsic_mesh& mesh)
{
  out << std::setprecision(17) << "{\n  \"omega\": " << file.omega << ",\n  \"constraints\": [";
  auto triple = [](const std::array<double, 3>& v) {
    std::ostringstream s;
    s << std::setprecision(17) << "[" << v[0] << ", " << v[1] << ", " << v[2] << "]";
    return s.str();
  };
  for(std::size_t i = 0; i < file.constraints.size(); ++i)
  {
    const Field_constraint& c = file.constraints[i];
    out << (i ? ",\n    " : "\n    ") << "{";
    switch(c.kind)
    {
    case Constraint_kind::vector: out << "\"type\": \"vector\", \"face\": " << c.face << ", \"vector\": " << triple(c.vector); break;
    case Constraint_kind::direction:
      out << "\"type\": \"direction\", \"face\": " << c.face << ", \"direction\": " << triple(c.vector);
      break;
    case Constraint_kind::divergence:
    case Constraint_kind::curl:
      out << "\"type\": \"" << (c.kind == Constraint_kind::divergence ? "divergence" : "curl") << "\", ";
      if(c.vertex >= 0) out << "\"vertex\": " << c.vertex;
      else if(c.edge >= 0) out << "\"edge\": " << c.edge;
      else
      {
        const auto& v = mesh.face_vertices(c.face);
        out << "\"face\": " << c.face << ", \"vertices\": [" << v[0] << ", " << v[1] << ", " << v[2]
            << "], \"barycentric\": " << triple(c.barycentric);
      }
      out << ", \"value\": " << c.value;
      break;
    }
    if(i < file.weights.size() && file.weights[i] != 1) out << ", \"weight\": " << file.weights[i];
    out << "}";
  }
  out << "\n  ]\n}\n";
}

} // namespace Tangent_vector_fields
} // namespace CGAL
