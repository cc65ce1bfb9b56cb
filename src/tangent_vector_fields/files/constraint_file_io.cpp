// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/internal/constraint_json.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {


namespace {

typedef internal::Json_reader Reader;

// Each kind's members ("weight" is added when the caller takes weights).
Field_constraint parse(const Reader& r, const Intrinsic_mesh& mesh, bool weighted)
{
  r.expect_object();
  const std::string type = r.text("type");
  auto allow = [&](std::vector<const char*> keys) {
    keys.push_back("type");
    if(weighted) keys.push_back("weight");
    r.allow_only(keys, " for a " + type + " constraint");
  };
  if(type == "vector")
  {
    allow({"face", "vector"});
    return Field_constraint::vector_in_face(r.index("face"), r.triple("vector"));
  }
  if(type == "direction")
  {
    allow({"face", "direction"});
    return Field_constraint::direction_in_face(r.index("face"), r.triple("direction"));
  }
  if(type == "divergence")
  {
    allow({"vertex", "face", "point", "vertices", "barycentric", "value"});
    if(r.has("vertex"))
    {
      if(r.has("face")) r.fail("give \"vertex\" or a point of a \"face\", not both");
      return Field_constraint::divergence_at_vertex(r.index("vertex"), r.number("value"));
    }
    const int face = r.index("face");
    return Field_constraint::divergence_at_point(face, r.point(mesh, face), r.number("value"));
  }
  if(type == "curl")
  {
    allow({"edge", "face", "point", "vertices", "barycentric", "value"});
    if(r.has("edge"))
    {
      if(r.has("face")) r.fail("give \"edge\" or a point of a \"face\", not both");
      return Field_constraint::curl_at_edge(r.index("edge"), r.number("value"));
    }
    const int face = r.index("face");
    return Field_constraint::curl_at_point(face, r.point(mesh, face), r.number("value"));
  }
  if(type == "boundary_alignment")
  {
    allow({"edge"});
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

Field_constraint parse_constraint(const Json& node, const std::string& name, const Operator_matrices& operators,
                                  double* weight)
{
  const Reader r{node, name};
  Field_constraint c = parse(r, operators.mesh(), weight != nullptr);
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
    *weight = r.has("weight") ? r.number("weight") : 1.0;
    if(!(*weight > 0)) r.fail("the weight must be positive");
  }
  return c;
}

Constraint_file parse_constraint_file(const Json& root, const Operator_matrices& operators)
{
  const Reader file_reader{root, "constraint file"};
  file_reader.allow_only({"omega", "constraints"});
  Constraint_file file;
  if(file_reader.has("omega"))
  {
    file.omega = file_reader.number("omega");
    file.has_omega = true;
    if(file.omega < 0) file_reader.fail("\"omega\" must be >= 0");
  }
  int position = 0;
  for(const Json& entry : file_reader.array("constraints"))
  {
    double weight = 1;
    file.constraints.push_back(parse_constraint(entry, "constraint " + std::to_string(position), operators, &weight));
    file.weights.push_back(weight);
    ++position;
  }
  return file;
}

} // namespace internal

Constraint_file read_constraint_file(std::istream& in, const Operator_matrices& operators)
{
  return internal::parse_constraint_file(internal::parse_json(in, "constraint file"), operators);
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
