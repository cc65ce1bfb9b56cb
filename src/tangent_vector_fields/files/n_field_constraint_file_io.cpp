// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/n_field_constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/errors.h>
#include <CGAL/Tangent_vector_fields/internal/constraint_json.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace CGAL {
namespace Tangent_vector_fields {

namespace {

// A signed integer member (indices k may be negative).
int signed_integer(const internal::Json_reader& r, const char* key)
{
  return static_cast<int>(r.integer(key, -1000000, 1000000));
}

N_field_constraint parse(const internal::Json_reader& r, const Intrinsic_mesh& mesh)
{
  r.expect_object();
  const std::string type = r.text("type");
  if(type == "vector" || type == "direction")
  {
    r.allow_only({"type", "face", type.c_str(), "point", "vertices", "barycentric"}, " for a " + type + " constraint");
    const int face = r.index("face");
    N_field_constraint c = type == "vector" ? N_field_constraint::vector_in_face(face, r.triple("vector"))
                                            : N_field_constraint::direction_in_face(face, r.triple("direction"));
    if(r.has("point") || r.has("barycentric") || r.has("vertices")) c.barycentric = r.point(mesh, face);
    return c;
  }
  if(type == "singularity")
  {
    r.allow_only({"type", "vertex", "index", "face", "vector"}, " for a singularity");
    const int vertex = r.index("vertex"), k = signed_integer(r, "index");
    if(r.has("face") || r.has("vector"))
      return N_field_constraint::singularity_at_vertex(vertex, k, r.index("face"), r.triple("vector"));
    return N_field_constraint::singularity_at_vertex(vertex, k);
  }
  r.fail("unknown type \"" + type + "\" (vector, direction, singularity)");
}

} // namespace

namespace internal {

N_field_constraint parse_n_field_constraint(const Json& node, const std::string& name, const N_field_operators& operators)
{
  const Json_reader r{node, name};
  const N_field_constraint c = parse(r, operators.mesh());
  try
  {
    constraint_rows(operators, c);
  }
  catch(const Invalid_input& e)
  {
    r.fail(e.what());
  }
  return c;
}

N_field_constraint_file parse_n_field_constraint_file(const Json& root, std::shared_ptr<const Operator_matrices> operators)
{
  const internal::Json_reader file_reader{root, "n-field constraint file"};
  file_reader.allow_only({"n", "omega", "order", "singularities", "constraints"});
  N_field_constraint_file file;
  file.n = signed_integer(file_reader, "n");
  if(file.n < 1) file_reader.fail("\"n\" must be at least 1");
  if(file_reader.has("omega"))
  {
    file.omega = file_reader.number("omega");
    if(file.omega < 0) file_reader.fail("\"omega\" must be >= 0");
  }
  if(file_reader.has("order"))
  {
    file.order = signed_integer(file_reader, "order");
    if(file.order < 1) file_reader.fail("\"order\" must be at least 1");
  }
  if(file_reader.has("singularities"))
  {
    int position = 0;
    for(const internal::Json& entry : file_reader.array("singularities"))
    {
      const internal::Json_reader r{entry, "singularity " + std::to_string(position++)};
      r.allow_only({"vertex", "index"});
      file.singularities.push_back({r.index("vertex"), signed_integer(r, "index")});
    }
  }
  // The operators check the prescribed singularities (interior vertices, no repeats).
  N_field_options options;
  options.singularities = file.singularities;
  std::unique_ptr<N_field_operators> n_operators;
  try
  {
    n_operators = std::make_unique<N_field_operators>(operators, file.n, options);
  }
  catch(const Invalid_input& e)
  {
    file_reader.fail(e.what());
  }
  int position = 0;
  for(const internal::Json& entry : file_reader.array("constraints"))
    file.constraints.push_back(parse_n_field_constraint(entry, "constraint " + std::to_string(position++), *n_operators));
  return file;
}

} // namespace internal

N_field_constraint_file read_n_field_constraint_file(std::istream& in, std::shared_ptr<const Operator_matrices> operators)
{
  return internal::parse_n_field_constraint_file(internal::parse_json(in, "n-field constraint file"), std::move(operators));
}

N_field_constraint_file read_n_field_constraint_file(const std::string& path,
                                                     std::shared_ptr<const Operator_matrices> operators)
{
  std::ifstream in(path);
  if(!in) throw Invalid_input("cannot open n-field constraint file " + path);
  return read_n_field_constraint_file(in, std::move(operators));
}

void write_n_field_constraint_file(std::ostream& out, const N_field_constraint_file& file, const Intrinsic_mesh& mesh)
{
  auto triple = [](const std::array<double, 3>& v) {
    std::ostringstream s;
    s << std::setprecision(17) << "[" << v[0] << ", " << v[1] << ", " << v[2] << "]";
    return s.str();
  };
  out << std::setprecision(17) << "{\n  \"n\": " << file.n << ",\n  \"omega\": " << file.omega
      << ",\n  \"order\": " << file.order << ",\n  \"singularities\": [";
  for(std::size_t i = 0; i < file.singularities.size(); ++i)
    out << (i ? ", " : "") << "{\"vertex\": " << file.singularities[i].first << ", \"index\": " << file.singularities[i].second
        << "}";
  out << "],\n  \"constraints\": [";
  for(std::size_t i = 0; i < file.constraints.size(); ++i)
  {
    const N_field_constraint& c = file.constraints[i];
    out << (i ? ",\n    " : "\n    ") << "{";
    switch(c.kind)
    {
    case N_field_constraint_kind::vector:
    case N_field_constraint_kind::direction:
    {
      const bool vector = c.kind == N_field_constraint_kind::vector;
      out << "\"type\": \"" << (vector ? "vector" : "direction") << "\", \"face\": " << c.face << ", \""
          << (vector ? "vector" : "direction") << "\": " << triple(c.vector);
      if(c.is_at_point())
      {
        const auto& v = mesh.face_vertices(c.face);
        out << ", \"vertices\": [" << v[0] << ", " << v[1] << ", " << v[2] << "], \"barycentric\": " << triple(c.barycentric);
      }
      break;
    }
    case N_field_constraint_kind::singularity:
      out << "\"type\": \"singularity\", \"vertex\": " << c.vertex << ", \"index\": " << c.index;
      if(c.is_anchored()) out << ", \"face\": " << c.face << ", \"vector\": " << triple(c.vector);
      break;
    }
    out << "}";
  }
  out << "\n  ]\n}\n";
}

} // namespace Tangent_vector_fields
} // namespace CGAL
