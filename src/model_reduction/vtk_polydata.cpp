// Copyright (c) 2026 The Model_reduction authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// VTK XML PolyData (ASCII), written and read.

#include <CGAL/Model_reduction/Vtk_polydata.h>
#include <CGAL/Model_reduction/errors.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <istream>
#include <iterator>
#include <limits>
#include <locale>
#include <map>
#include <ostream>
#include <sstream>

namespace CGAL {
namespace Model_reduction {

namespace internal {

void prepare_exact_output(std::ostream& out)
{
  out.imbue(std::locale::classic());
  out << std::setprecision(17);
}

void check_written(const std::ostream& out, const char* what)
{
  if(!out) throw Invalid_input(std::string("writing the ") + what + " failed");
}

} // namespace internal

namespace {

using internal::prepare_exact_output;
using internal::check_written;

const Vtk_polydata::Array* find_array(const std::vector<Vtk_polydata::Array>& arrays, const std::string& name)
{
  for(const auto& a : arrays)
    if(a.name == name) return &a;
  return nullptr;
}

void write_cells(std::ostream& out, const char* section, const std::vector<std::vector<int>>& cells,
                 std::size_t number_of_points)
{
  out << "      <" << section << ">\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  long long offset = 0;
  for(const auto& c : cells)
  {
    out << "         ";
    for(int i : c)
    {
      if(i < 0 || static_cast<std::size_t>(i) >= number_of_points)
        throw Invalid_input("VTK PolyData: a cell refers to point " + std::to_string(i) + " of " +
                            std::to_string(number_of_points));
      out << ' ' << i;
    }
    out << '\n';
  }
  out << "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n         ";
  for(const auto& c : cells)
  {
    offset += static_cast<long long>(c.size());
    out << ' ' << offset;
  }
  out << "\n        </DataArray>\n      </" << section << ">\n";
}

void write_arrays(std::ostream& out, const char* section, const std::vector<Vtk_polydata::Array>& arrays,
                  std::size_t tuples)
{
  if(arrays.empty()) return;
  out << "      <" << section;
  for(const auto& a : arrays)
    if(a.components == 3)
    {
      out << " Vectors=\"" << a.name << '"';
      break;
    }
  out << ">\n";
  for(const auto& a : arrays)
  {
    if(a.components <= 0 || a.values.size() != tuples * static_cast<std::size_t>(a.components))
      throw Invalid_input("VTK PolyData: array '" + a.name + "' has " + std::to_string(a.values.size()) +
                          " values, expected " + std::to_string(tuples) + " tuples of " +
                          std::to_string(a.components));
    for(char c : a.name)
      if(c == '"' || c == '<' || c == '>' || c == '&')
        throw Invalid_input("VTK PolyData: array name '" + a.name + "' has a character XML would need escaped");
    out << "        <DataArray type=\"Float64\" Name=\"" << a.name << "\" NumberOfComponents=\"" << a.components
        << "\" format=\"ascii\">\n";
    for(std::size_t t = 0; t < tuples; ++t)
    {
      out << "         ";
      for(int k = 0; k < a.components; ++k) out << ' ' << a.values[t * a.components + k];
      out << '\n';
    }
    out << "        </DataArray>\n";
  }
  out << "      </" << section << ">\n";
}

// A minimal scanner for the XML that VTK writes: tags with attributes, and the text
// between a DataArray's start and end tags.
struct Tag
{
  std::string name; // "/Name" for an end tag
  std::map<std::string, std::string> attributes;
  bool self_closing = false;
};

class Xml_scanner
{
public:
  explicit Xml_scanner(std::string text) : text_(std::move(text)) {}

  // The next tag, skipping text, comments, declarations; false at the end.
  bool next(Tag& tag)
  {
    for(;;)
    {
      const std::size_t open = text_.find('<', pos_);
      if(open == std::string::npos) return false;
      if(text_.compare(open, 4, "<!--") == 0)
      {
        const std::size_t end = text_.find("-->", open);
        if(end == std::string::npos) throw Invalid_input("VTK PolyData: unterminated comment");
        pos_ = end + 3;
        continue;
      }
      const std::size_t close = text_.find('>', open);
      if(close == std::string::npos) throw Invalid_input("VTK PolyData: unterminated tag");
      pos_ = close + 1;
      if(text_[open + 1] == '?' || text_[open + 1] == '!') continue;
      std::string body = text_.substr(open + 1, close - open - 1);
      tag = Tag();
      if(!body.empty() && body.back() == '/')
      {
        tag.self_closing = true;
        body.pop_back();
      }
      std::size_t i = 0;
      while(i < body.size() && !std::isspace(static_cast<unsigned char>(body[i]))) ++i;
      tag.name = body.substr(0, i);
      while(i < body.size())
      {
        while(i < body.size() && std::isspace(static_cast<unsigned char>(body[i]))) ++i;
        const std::size_t eq = body.find('=', i);
        if(i >= body.size() || eq == std::string::npos) break;
        std::string key = body.substr(i, eq - i);
        while(!key.empty() && std::isspace(static_cast<unsigned char>(key.back()))) key.pop_back();
        std::size_t q = eq + 1;
        while(q < body.size() && std::isspace(static_cast<unsigned char>(body[q]))) ++q;
        if(q >= body.size() || (body[q] != '"' && body[q] != '\''))
          throw Invalid_input("VTK PolyData: malformed attribute in <" + tag.name + ">");
        const std::size_t end = body.find(body[q], q + 1);
        if(end == std::string::npos) throw Invalid_input("VTK PolyData: unterminated attribute in <" + tag.name + ">");
        tag.attributes[key] = body.substr(q + 1, end - q - 1);
        i = end + 1;
      }
      return true;
    }
  }

  // The text up to the end tag `</name>`, which is consumed.
  std::string text_until(const std::string& name)
  {
    const std::size_t end = text_.find("</" + name, pos_);
    if(end == std::string::npos) throw Invalid_input("VTK PolyData: missing </" + name + ">");
    const std::size_t close = text_.find('>', end);
    // Not `find + 1` unchecked: npos + 1 is 0, which restarted the scan at the top, forever
    // (fuzz_vtp: a file ending inside an end tag hung the reader).
    if(close == std::string::npos) throw Invalid_input("VTK PolyData: unterminated </" + name + ">");
    std::string body = text_.substr(pos_, end - pos_);
    pos_ = close + 1;
    return body;
  }

private:
  std::string text_;
  std::size_t pos_ = 0;
};

std::vector<double> parse_numbers(const std::string& text, const std::string& what)
{
  std::istringstream in(text);
  in.imbue(std::locale::classic());
  std::vector<double> values;
  std::string word;
  while(in >> word)
  {
    char* end = nullptr;
    const double x = std::strtod(word.c_str(), &end);
    if(end == word.c_str() || *end != '\0') throw Invalid_input("VTK PolyData: '" + word + "' in " + what + " is not a number");
    values.push_back(x);
  }
  return values;
}

// A count in an attribute: all of it a non-negative integer ("12", not "12x", "-1" or "1e3");
// 0 if absent.
long long count_attribute(const std::map<std::string, std::string>& attributes, const std::string& key)
{
  const auto it = attributes.find(key);
  if(it == attributes.end()) return 0;
  const std::string& text = it->second;
  char* end = nullptr;
  errno = 0;
  const long long n = std::strtoll(text.c_str(), &end, 10);
  if(text.empty() || end != text.c_str() + text.size() || errno == ERANGE || n < 0 || n > (1LL << 40))
    throw Invalid_input("VTK PolyData: " + key + "=\"" + text.substr(0, 40) + "\" is not a count");
  return n;
}

// Whether `x` is a whole number in [0, highest]: checked before any conversion to an integer
// type (a cast of a value out of its range is undefined).
bool is_index(double x, double highest) { return x >= 0 && x <= highest && x == std::floor(x); }

std::vector<std::vector<int>> make_cells(const std::vector<double>& connectivity, const std::vector<double>& offsets,
                                         const std::string& section)
{
  std::vector<std::vector<int>> cells;
  std::size_t start = 0;
  for(double o : offsets)
  {
    if(!is_index(o, double(connectivity.size())) || static_cast<std::size_t>(o) < start)
      throw Invalid_input("VTK PolyData: bad offsets in <" + section + ">");
    const std::size_t end = static_cast<std::size_t>(o);
    std::vector<int> cell;
    for(std::size_t i = start; i < end; ++i)
    {
      if(!is_index(connectivity[i], double(std::numeric_limits<int>::max())))
        throw Invalid_input("VTK PolyData: the connectivity of <" + section + "> holds " +
                            std::to_string(connectivity[i]) + ", not a point index");
      cell.push_back(static_cast<int>(connectivity[i]));
    }
    cells.push_back(std::move(cell));
    start = end;
  }
  if(start != connectivity.size()) throw Invalid_input("VTK PolyData: offsets do not cover the connectivity in <" + section + ">");
  return cells;
}

} // namespace

const Vtk_polydata::Array* Vtk_polydata::find_cell_array(const std::string& name) const
{
  return find_array(cell_data, name);
}

const Vtk_polydata::Array* Vtk_polydata::find_point_array(const std::string& name) const
{
  return find_array(point_data, name);
}

void write_vtk_polydata(std::ostream& out, const Vtk_polydata& data)
{
  prepare_exact_output(out);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << data.points.size() << "\" NumberOfVerts=\"0\" NumberOfLines=\""
      << data.lines.size() << "\" NumberOfStrips=\"0\" NumberOfPolys=\"" << data.polygons.size() << "\">\n";
  write_arrays(out, "PointData", data.point_data, data.points.size());
  write_arrays(out, "CellData", data.cell_data, data.number_of_cells());
  out << "      <Points>\n        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n";
  for(const auto& p : data.points) out << "          " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  out << "        </DataArray>\n      </Points>\n";
  if(!data.lines.empty()) write_cells(out, "Lines", data.lines, data.points.size());
  if(!data.polygons.empty()) write_cells(out, "Polys", data.polygons, data.points.size());
  out << "    </Piece>\n  </PolyData>\n</VTKFile>\n";
  check_written(out, "VTK PolyData file");
}

Vtk_polydata read_vtk_polydata(std::istream& in)
{
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  Xml_scanner xml(text);
  Vtk_polydata data;
  Tag tag;
  std::string section;
  bool polydata = false;
  long long expected_points = -1, expected_lines = 0, expected_polys = 0;
  std::map<std::string, std::vector<double>> cell_arrays[2]; // lines, polys: connectivity and offsets
  while(xml.next(tag))
  {
    if(tag.name == "VTKFile")
    {
      if(tag.attributes["type"] != "PolyData")
        throw Invalid_input("VTK file of type '" + tag.attributes["type"] + "', expected PolyData");
      if(tag.attributes.count("compressor")) throw Invalid_input("VTK PolyData: compressed files are not read");
      polydata = true;
    }
    else if(tag.name == "Piece")
    {
      if(expected_points >= 0) throw Invalid_input("VTK PolyData: only files of one piece are read");
      expected_points = count_attribute(tag.attributes, "NumberOfPoints");
      expected_lines = count_attribute(tag.attributes, "NumberOfLines");
      expected_polys = count_attribute(tag.attributes, "NumberOfPolys");
      if(count_attribute(tag.attributes, "NumberOfVerts") != 0 || count_attribute(tag.attributes, "NumberOfStrips") != 0)
        throw Invalid_input("VTK PolyData: vertex and strip cells are not read");
    }
    else if(tag.name == "Points" || tag.name == "Lines" || tag.name == "Polys" || tag.name == "PointData" ||
            tag.name == "CellData" || tag.name == "Verts" || tag.name == "Strips")
    {
      if(tag.name == "Verts" || tag.name == "Strips")
        throw Invalid_input("VTK PolyData: vertex and strip cells are not read");
      if(!tag.self_closing) section = tag.name;
    }
    else if(!tag.name.empty() && tag.name[0] == '/')
    {
      if(tag.name.substr(1) == section) section.clear();
    }
    else if(tag.name == "DataArray")
    {
      const std::string format = tag.attributes.count("format") ? tag.attributes["format"] : "ascii";
      if(format != "ascii")
        throw Invalid_input("VTK PolyData: data arrays in format '" + format + "' are not read (only ascii)");
      const std::string name = tag.attributes["Name"];
      const long long components =
          tag.attributes.count("NumberOfComponents") ? count_attribute(tag.attributes, "NumberOfComponents") : 1;
      if(components <= 0 || components > 1000)
        throw Invalid_input("VTK PolyData: array '" + name + "' has " + std::to_string(components) +
                            " components (1 to 1000 are read)");
      std::vector<double> values = tag.self_closing ? std::vector<double>() : parse_numbers(xml.text_until("DataArray"), name);
      if(values.size() % components != 0)
        throw Invalid_input("VTK PolyData: array '" + name + "' has a partial tuple");
      if(section == "Points")
      {
        if(components != 3) throw Invalid_input("VTK PolyData: points need 3 components");
        for(std::size_t i = 0; i < values.size(); i += 3) data.points.push_back({values[i], values[i + 1], values[i + 2]});
      }
      else if(section == "Lines" || section == "Polys")
        cell_arrays[section == "Lines" ? 0 : 1][name] = std::move(values);
      else if(section == "PointData" || section == "CellData")
        (section == "PointData" ? data.point_data : data.cell_data)
            .push_back({name, static_cast<int>(components), std::move(values)});
      else
        throw Invalid_input("VTK PolyData: data array '" + name + "' outside a known section");
    }
  }
  if(!polydata || expected_points < 0) throw Invalid_input("not a VTK PolyData file");
  for(int k = 0; k < 2; ++k)
    if(!cell_arrays[k].empty())
    {
      const std::string section = k == 0 ? "Lines" : "Polys";
      if(!cell_arrays[k].count("connectivity") || !cell_arrays[k].count("offsets"))
        throw Invalid_input("VTK PolyData: <" + section + "> needs connectivity and offsets");
      (k == 0 ? data.lines : data.polygons) =
          make_cells(cell_arrays[k]["connectivity"], cell_arrays[k]["offsets"], section);
    }
  if(static_cast<long long>(data.points.size()) != expected_points ||
     static_cast<long long>(data.lines.size()) != expected_lines ||
     static_cast<long long>(data.polygons.size()) != expected_polys)
    throw Invalid_input("VTK PolyData: the counts in <Piece> do not match the data");
  for(const auto& c : data.lines)
    for(int i : c)
      if(i < 0 || i >= expected_points) throw Invalid_input("VTK PolyData: a line refers to a missing point");
  for(const auto& c : data.polygons)
    for(int i : c)
      if(i < 0 || i >= expected_points) throw Invalid_input("VTK PolyData: a polygon refers to a missing point");
  for(const auto& a : data.point_data)
    if(a.number_of_tuples() != data.points.size())
      throw Invalid_input("VTK PolyData: point array '" + a.name + "' does not have one tuple per point");
  for(const auto& a : data.cell_data)
    if(a.number_of_tuples() != data.number_of_cells())
      throw Invalid_input("VTK PolyData: cell array '" + a.name + "' does not have one tuple per cell");
  return data;
}

} // namespace Model_reduction
} // namespace CGAL
