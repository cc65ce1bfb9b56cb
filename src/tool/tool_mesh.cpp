// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one translation unit of the tool that includes Surface_mesh: the mesh made from the
// file's polygon soup (Model_reduction::polygon_soup_to_mesh, which repairs it), and the field files that
// need the mesh type (.tvf, .rawfield, .vtp, PLY properties), fields given per polygon of
// the file mapped to the faces they became.

#include "mesh_input.h"
#include "tool.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Tangent_vector_fields/Discrete_operators.h>
#include <CGAL/Tangent_vector_fields/face_field_io.h>
#include <CGAL/Tangent_vector_fields/field_export.h>
#include <CGAL/Model_reduction/polygon_soup_to_mesh.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <set>

namespace tvf_tool {

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index Face_index;
typedef Mesh::Property_map<Face_index, K::Vector_3> Field_map;

void check_readable(const std::string& path, const std::string& what)
{
  std::ifstream in(path);
  if(!in) throw Tool_error("cannot open " + what + " '" + path + "': " + std::strerror(errno));
}

typedef std::vector<std::array<double, 3>> Vectors;

// The mesh of a file: its polygon soup made a triangle mesh (repaired, unless `strict`),
// with the file's face fields (PLY) as face properties `f:NAME_x`, ... mapped to the faces.
// `polygon_of_face[f]` is the polygon of the file that face `f` comes from.
void load_mesh(const std::string& path, bool strict, Mesh& mesh, MR::Mesh_repair_report& report,
               std::vector<std::size_t>& polygon_of_face)
{
  const Mesh_file file = read_mesh_file(path);
  if(file.polygons.empty()) throw Tool_error("'" + path + "' has no faces");
  auto origin = mesh.add_property_map<Face_index, std::size_t>("f:tvf_polygon", 0).first;
  try
  {
    report = MR::polygon_soup_to_mesh(file.points, file.polygons, mesh, TVF::parameters::face_to_polygon_map(origin));
  }
  catch(const TVF::Invalid_mesh& e)
  {
    throw Tool_error("'" + path + "': " + one_line(e.what()));
  }
  if(strict && report.changed())
    throw Tool_error("'" + path + "' needs repairs that --strict forbids: " + report.summary());
  if(mesh.number_of_faces() == 0) throw Tool_error("'" + path + "' has no faces (" + report.summary() + ")");
  polygon_of_face.clear();
  for(Face_index f : mesh.faces()) polygon_of_face.push_back(origin[f]);
  mesh.remove_property_map(origin);
  for(const auto& [name, values] : file.face_properties)
  {
    auto map = mesh.add_property_map<Face_index, double>("f:" + name, 0.).first;
    for(Face_index f : mesh.faces()) map[f] = values[polygon_of_face[std::size_t(f)]];
  }
}

// Whether `polygons` (of a field file that holds a mesh too) are the faces of `mesh`, up to
// where each starts.
bool are_faces_of(const std::vector<std::vector<std::size_t>>& polygons, const Mesh& mesh)
{
  if(polygons.size() != mesh.number_of_faces()) return false;
  for(Face_index f : mesh.faces())
  {
    std::vector<std::size_t> a, b = polygons[std::size_t(f)];
    for(auto v : vertices_around_face(mesh.halfedge(f), mesh)) a.push_back(std::size_t(v));
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if(a != b) return false;
  }
  return true;
}

// The face field properties (NAME_x, NAME_y, NAME_z of type double) of a mesh.
std::vector<std::string> face_field_names(const Mesh& mesh)
{
  std::vector<std::string> names;
  for(const std::string& p : mesh.properties<Face_index>())
  {
    if(p.size() < 5 || p.compare(0, 2, "f:") != 0 || p.compare(p.size() - 2, 2, "_x") != 0) continue;
    const std::string name = p.substr(2, p.size() - 4);
    if(mesh.property_map<Face_index, double>("f:" + name + "_x").second &&
       mesh.property_map<Face_index, double>("f:" + name + "_y").second &&
       mesh.property_map<Face_index, double>("f:" + name + "_z").second)
      names.push_back(name);
  }
  return names;
}

std::string list_or_none(const std::vector<std::string>& names)
{
  if(names.empty()) return "none";
  std::string s;
  for(const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

// A temporary face map of vectors on a mesh, removed when it goes out of scope.
class Temporary_field
{
public:
  explicit Temporary_field(Mesh& mesh) : mesh_(mesh)
  {
    static int counter = 0;
    map_ = mesh.add_property_map<Face_index, K::Vector_3>("f:tvf_tool_field_" + std::to_string(counter++),
                                                          CGAL::NULL_VECTOR).first;
  }
  ~Temporary_field() { mesh_.remove_property_map(map_); }
  Field_map& map() { return map_; }

private:
  Mesh& mesh_;
  Field_map map_;
};

} // namespace

struct Tool_mesh::Impl
{
  std::string path;
  Mesh mesh;
  MR::Mesh_repair_report repair;
  std::vector<std::size_t> polygon_of_face;
  std::unique_ptr<TVF::Discrete_operators<Mesh>> operators;

  // `values` (one vector per face, or per polygon of the file) into `map`.
  void place(const Vectors& values, const std::string& where, Field_map& map) const;
};

void Tool_mesh::Impl::place(const Vectors& values, const std::string& where, Field_map& map) const
{
  const std::size_t faces = mesh.number_of_faces(), polygons = repair.number_of_polygons;
  const bool per_polygon = !repair.faces_match_polygons && values.size() == polygons;
  if(!per_polygon && values.size() != faces)
  {
    std::string reason = where + " has " + std::to_string(values.size()) + " vectors but the mesh has " +
                         std::to_string(faces) + " faces";
    if(!repair.faces_match_polygons)
      reason += " (made by the repair of the " + std::to_string(polygons) + " polygons of '" + path +
                "'; a field needs one vector per face, or one per polygon of the file)";
    throw Tool_error(reason);
  }
  if(per_polygon && faces == polygons)
    throw Tool_error(where + " has " + std::to_string(values.size()) + " vectors, one per face of the repaired mesh " +
                     "or one per polygon of '" + path + "', which differ (polygons were split or removed): it is " +
                     "ambiguous which is meant (a .vtp or .ply field file written by tvf holds its mesh and is not)");
  for(Face_index f : mesh.faces())
  {
    const std::array<double, 3>& w = values[per_polygon ? polygon_of_face[std::size_t(f)] : std::size_t(f)];
    map[f] = K::Vector_3(w[0], w[1], w[2]);
  }
  if(per_polygon)
    say("note: %s has one vector per polygon of '%s': each of the %zu triangles got the vector of its polygon\n",
        where.c_str(), path.c_str(), faces);
}

Tool_mesh::Tool_mesh(const std::string& path, bool mollify) : impl_(std::make_unique<Impl>())
{
  impl_->path = path;
  load_mesh(path, strict_mesh_input(), impl_->mesh, impl_->repair, impl_->polygon_of_face);
  if(impl_->repair.changed()) warn("'" + path + "' repaired: " + impl_->repair.summary());
  // The library's message names its C++ parameter where mollification would help.
  const std::string parameter = "; use the named parameter use_intrinsic_mollification(true) to process it";
  auto make = [this](bool m) {
    impl_->operators = std::make_unique<TVF::Discrete_operators<Mesh>>(
        impl_->mesh, TVF::parameters::use_intrinsic_mollification(m));
  };
  try
  {
    make(mollify);
  }
  catch(const TVF::Invalid_mesh& e)
  {
    std::string reason = one_line(e.what());
    const std::size_t at = reason.find(parameter);
    if(at == std::string::npos || mollify)
    {
      if(at != std::string::npos) reason.replace(at, parameter.size(), "; mollification did not help");
      throw Tool_error("'" + path + "': " + reason);
    }
    reason.erase(at, parameter.size());
    // Degenerate faces are mollified by default, as other defects are repaired: one warning.
    if(strict_mesh_input())
      throw Tool_error("'" + path + "': " + reason + "; --strict refuses to mollify it (--mollify asks for it)");
    try
    {
      make(true);
    }
    catch(const TVF::Invalid_mesh& again)
    {
      throw Tool_error("'" + path + "': " + reason + "; mollification did not help: " + one_line(again.what()));
    }
    warn("'" + path + "': " + reason + ": mollified (intrinsic mollification, as with --mollify: --strict refuses)");
  }
  matrices_ = impl_->operators->shared_matrices();
}

Tool_mesh::~Tool_mesh() = default;

const std::string& Tool_mesh::path() const { return impl_->path; }

double Tool_mesh::bounding_box_diagonal() const
{
  const TVF::Intrinsic_mesh& m = intrinsic();
  std::array<double, 3> lo{{HUGE_VAL, HUGE_VAL, HUGE_VAL}}, hi{{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
  for(int v = 0; v < m.number_of_vertices(); ++v)
  {
    if(m.is_isolated_vertex(v)) continue;
    for(int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], m.position(v)[k]);
      hi[k] = std::max(hi[k], m.position(v)[k]);
    }
  }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

int Tool_mesh::number_of_file_vertices() const { return static_cast<int>(impl_->mesh.number_of_vertices()); }

const MR::Mesh_repair_report& Tool_mesh::repair_report() const { return impl_->repair; }

std::vector<std::string> Tool_mesh::face_fields_in_file() const { return face_field_names(impl_->mesh); }

Eigen::VectorXd Tool_mesh::read_field(const Field_source& source) const
{
  Mesh& mesh = impl_->mesh;
  Temporary_field field(mesh);
  Field_map& map = field.map();
  const std::string where = source.describe();
  try
  {
    if(source.from_mesh_file)
    {
      // Read with the mesh and mapped to its faces there.
      if(extension(impl_->path) != "ply")
        throw Tool_error("'--field-ply " + source.name + "' reads face properties of a PLY mesh, but '" + impl_->path +
                         "' is not a .ply file");
      if(!TVF::face_field_from_properties(mesh, source.name, map))
        throw Tool_error("'" + impl_->path + "' has no face properties " + source.name + "_x, " + source.name +
                         "_y, " + source.name + "_z (face fields in it: " + list_or_none(face_field_names(mesh)) + ")");
    }
    else
    {
      const std::string& file = source.file;
      check_readable(file, "field file");
      const std::string ext = extension(file);
      if(ext == "tvf")
      {
        std::ifstream in(file);
        impl_->place(TVF::read_face_vectors(in), where, map);
      }
      else if(ext == "rawfield")
      {
        std::ifstream in(file);
        const TVF::Raw_field raw = TVF::read_raw_field(in);
        if(source.direction < 0 || source.direction >= raw.degree)
          throw Tool_error(where + " has " + std::to_string(raw.degree) + " vectors per face; direction " +
                           std::to_string(source.direction) + " does not exist");
        Vectors picked;
        for(std::size_t i = std::size_t(source.direction); i < raw.vectors.size(); i += std::size_t(raw.degree))
          picked.push_back(raw.vectors[i]);
        impl_->place(picked, where, map);
      }
      else if(ext == "vtp")
      {
        std::ifstream in(file);
        const TVF::Vtk_polydata data = TVF::read_vtk_polydata(in);
        std::string name = source.name;
        if(name.empty())
          for(const auto& a : data.cell_data)
            if(a.components == 3)
            {
              name = a.name;
              break;
            }
        const TVF::Vtk_polydata::Array* a = data.find_cell_array(name);
        if(name.empty() || !a || a->components != 3)
          throw Tool_error(where + (name.empty() ? " has no 3-component cell array"
                                                 : " has no 3-component cell array '" + name + "'"));
        if(!data.lines.empty()) throw Tool_error(where + " holds lines, not a mesh with a face field");
        Vectors values(a->number_of_tuples());
        for(std::size_t i = 0; i < values.size(); ++i)
          values[i] = {{a->values[3 * i], a->values[3 * i + 1], a->values[3 * i + 2]}};
        std::vector<std::vector<std::size_t>> polygons;
        for(const auto& p : data.polygons) polygons.emplace_back(p.begin(), p.end());
        if(are_faces_of(polygons, mesh))
          for(Face_index f : mesh.faces())
            map[f] = K::Vector_3(values[std::size_t(f)][0], values[std::size_t(f)][1], values[std::size_t(f)][2]);
        else
          impl_->place(values, where, map);
      }
      else if(ext == "ply")
      {
        const Mesh_file other = read_mesh_file(file);
        std::string name = source.name;
        const std::vector<std::string> names = other.face_field_names();
        if(name.empty())
        {
          if(names.size() != 1)
            throw Tool_error(where + " holds " + std::to_string(names.size()) + " face fields (" + list_or_none(names) +
                             "): choose one with --field-name");
          name = names.front();
        }
        const Vectors values = other.face_field(name);
        if(values.empty())
          throw Tool_error(where + " has no face properties " + name + "_x, " + name + "_y, " + name +
                           "_z (face fields in it: " + list_or_none(names) + ")");
        if(are_faces_of(other.polygons, mesh))
          for(Face_index f : mesh.faces())
            map[f] = K::Vector_3(values[std::size_t(f)][0], values[std::size_t(f)][1], values[std::size_t(f)][2]);
        else
          impl_->place(values, where, map);
      }
      else
        throw Tool_error("'" + file + "': unknown field format" + (ext.empty() ? std::string() : " '." + ext + "'") +
                         " (the tool reads .tvf, .rawfield, .vtp and .ply)");
    }
  }
  catch(const TVF::Invalid_input& e)
  {
    const std::string reason = one_line(e.what());
    throw Tool_error(source.from_mesh_file ? where + ": " + reason : about(source.file, reason));
  }
  // What the projection onto the faces removes, and a check for NaNs.
  const TVF::Intrinsic_mesh& m = intrinsic();
  double largest = 0, largest_normal = 0;
  for(Face_index f : mesh.faces())
  {
    const K::Vector_3& w = map[f];
    if(!std::isfinite(w.x()) || !std::isfinite(w.y()) || !std::isfinite(w.z()))
      throw Tool_error(where + ": the vector of face " + std::to_string(static_cast<int>(f)) + " is not finite");
    const auto& n = m.normal(static_cast<int>(f));
    largest = std::max(largest, std::sqrt(w.squared_length()));
    largest_normal = std::max(largest_normal, std::abs(w.x() * n[0] + w.y() * n[1] + w.z() * n[2]));
  }
  last_normal_fraction_ = largest > 0 ? largest_normal / largest : 0;
  return impl_->operators->to_frame_coordinates(map);
}

void Tool_mesh::write_fields(const std::string& path, const std::vector<Named_field>& fields) const
{
  Mesh& mesh = impl_->mesh;
  const std::string ext = extension(path);
  if(ext != "tvf" && ext != "rawfield" && ext != "vtp" && ext != "ply")
    throw Usage_error("cannot write a field to '" + path + "': use .tvf, .ply, .vtp or .rawfield");
  if((ext == "tvf" || ext == "rawfield") && fields.size() != 1)
    throw Usage_error("'" + path + "': a ." + ext + " file holds one field; use .vtp or .ply for several");
  try
  {
    Mesh copy;
    if(ext == "ply") copy = mesh; // before the temporary maps are added
    std::vector<std::unique_ptr<Temporary_field>> maps;
    for(const Named_field& f : fields)
    {
      if(f.x.size() != 2 * static_cast<Eigen::Index>(mesh.number_of_faces()))
        throw Tool_error("field '" + f.name + "' has " + std::to_string(f.x.size() / 2) + " vectors, the mesh " +
                         std::to_string(mesh.number_of_faces()) + " faces");
      // The last line of defence: a NaN or an infinity is never written as a result.
      if(!f.x.allFinite())
      {
        Eigen::Index face = 0;
        while(face < f.x.size() / 2 && std::isfinite(f.x[2 * face]) && std::isfinite(f.x[2 * face + 1])) ++face;
        throw Tool_error("not writing '" + path + "': the field '" + f.name + "' is not finite (NaN or infinite) at face " +
                         std::to_string(face) + "; its computation overflowed");
      }
      maps.push_back(std::make_unique<Temporary_field>(mesh));
      impl_->operators->from_frame_coordinates(f.x, maps.back()->map());
    }
    if(ext == "tvf")
      TVF::write_face_field(path, mesh, maps.front()->map());
    else if(ext == "rawfield")
      TVF::write_raw_field(path, mesh, maps.front()->map());
    else if(ext == "vtp")
    {
      std::vector<std::pair<std::string, Field_map>> named;
      for(std::size_t i = 0; i < fields.size(); ++i) named.emplace_back(fields[i].name, maps[i]->map());
      TVF::write_vtp(path, mesh, named);
    }
    else
    {
      for(std::size_t i = 0; i < fields.size(); ++i) TVF::add_face_field_properties(copy, fields[i].name, maps[i]->map());
      std::ofstream out(path, std::ios::binary);
      if(!out) throw Tool_error("cannot open '" + path + "' for writing: " + std::strerror(errno));
      CGAL::IO::set_mode(out, CGAL::IO::BINARY); // exact doubles (ASCII would round them to the stream precision)
      if(!CGAL::IO::write_PLY(out, copy) || !out)
        throw Tool_error("writing '" + path + "' failed");
    }
  }
  catch(const TVF::Invalid_input& e)
  {
    throw Tool_error(about(path, one_line(e.what())));
  }
}

} // namespace tvf_tool
