// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh files as polygon soups, through CGAL's readers; PLY face properties through
// CGAL's PLY parser, since the soup readers drop them.

#include "mesh_input.h"

#include "tool.h"

#include <CGAL/IO/GOCAD.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/OFF/File_header_OFF.h>
#include <CGAL/IO/OFF/File_header_extended_OFF.h>
#include <CGAL/IO/binary_file_io.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <locale>
#include <map>
#include <set>
#include <sstream>

namespace tvf_tool {

namespace {

// The `double` and `float` properties of the face elements of a PLY file, in file order;
// false if the file cannot be parsed.
bool read_ply_face_properties(const std::string& path, std::vector<std::pair<std::string, std::vector<double>>>& out)
{
  namespace ply = CGAL::IO::internal;
  std::ifstream in(path, std::ios::binary);
  ply::PLY_reader reader(false);
  if(!in || !reader.init(in)) return false;
  for(std::size_t i = 0; i < reader.number_of_elements(); ++i)
  {
    ply::PLY_element& element = reader.element(i);
    const bool is_face = element.name() == "face" || element.name() == "faces";
    std::vector<std::pair<std::size_t, std::size_t>> wanted; // (property, entry of out)
    if(is_face)
      for(std::size_t k = 0; k < element.number_of_properties(); ++k)
      {
        ply::PLY_read_number* p = element.property(k);
        if(dynamic_cast<ply::PLY_read_typed_number<double>*>(p) || dynamic_cast<ply::PLY_read_typed_number<float>*>(p))
        {
          wanted.emplace_back(k, out.size());
          out.emplace_back(p->name(), std::vector<double>());
        }
      }
    for(std::size_t j = 0; j < element.number_of_items(); ++j)
    {
      for(std::size_t k = 0; k < element.number_of_properties(); ++k)
      {
        element.property(k)->get(in);
        if(in.fail()) return false;
      }
      for(const auto& [k, entry] : wanted)
      {
        ply::PLY_read_number* p = element.property(k);
        if(auto* d = dynamic_cast<ply::PLY_read_typed_number<double>*>(p))
          out[entry].second.push_back(d->buffer());
        else
          out[entry].second.push_back(dynamic_cast<ply::PLY_read_typed_number<float>*>(p)->buffer());
      }
    }
  }
  return true;
}

// The triangles of the `tristrips` elements of a PLY file (scans store their faces so): each
// list of vertex indices holds strips separated by -1, and strip s0 s1 s2 s3 ... gives
// (s0 s1 s2), (s2 s1 s3), (s2 s3 s4), ... (every other one turned, so that all keep the
// strip's orientation); a triangle with a repeated vertex (where strips are stitched) is no
// face.  Empty if the file has none; Tool_error for an index that is not a vertex.
std::vector<std::vector<std::size_t>> read_ply_triangle_strips(const std::string& path, std::size_t vertices)
{
  namespace ply = CGAL::IO::internal;
  std::vector<std::vector<std::size_t>> triangles;
  std::ifstream in(path, std::ios::binary);
  ply::PLY_reader reader(false);
  if(!in || !reader.init(in)) return triangles;
  std::vector<long long> strip;
  auto end_strip = [&] {
    for(std::size_t i = 0; i + 2 < strip.size(); ++i)
    {
      const long long a = strip[i + (i % 2)], b = strip[i + 1 - (i % 2)], c = strip[i + 2];
      if(a != b && b != c && a != c)
        triangles.push_back({std::size_t(a), std::size_t(b), std::size_t(c)});
    }
    strip.clear();
  };
  for(std::size_t i = 0; i < reader.number_of_elements(); ++i)
  {
    ply::PLY_element& element = reader.element(i);
    const bool strips = element.name() == "tristrips";
    for(std::size_t j = 0; j < element.number_of_items(); ++j)
      for(std::size_t k = 0; k < element.number_of_properties(); ++k)
      {
        ply::PLY_read_number* p = element.property(k);
        p->get(in);
        if(in.fail()) throw Tool_error("cannot read a polygon mesh from '" + path + "' (malformed PLY triangle strips)");
        if(!strips || (p->name() != "vertex_indices" && p->name() != "vertex_index")) continue;
        std::vector<long long> indices;
        if(auto* l = dynamic_cast<ply::PLY_read_typed_list<std::int32_t>*>(p))
          indices.assign(l->buffer().begin(), l->buffer().end());
        else if(auto* u = dynamic_cast<ply::PLY_read_typed_list<std::uint32_t>*>(p))
          for(std::uint32_t x : u->buffer()) indices.push_back(x == 0xFFFFFFFFu ? -1 : (long long)x);
        else
          throw Tool_error("'" + path + "': the triangle strips' vertex indices must be int or uint lists");
        for(long long x : indices)
        {
          if(x == -1) end_strip();
          else if(x < 0 || x >= (long long)vertices)
            throw Tool_error("'" + path + "': a triangle strip refers to vertex " + std::to_string(x) + " of " +
                             std::to_string(vertices));
          else strip.push_back(x);
        }
        end_strip();
      }
  }
  return triangles;
}

// Bytes of a PLY scalar type, 0 for a name that is not one.
int ply_type_size(const std::string& type)
{
  static const std::map<std::string, int> sizes = {
      {"char", 1},  {"uchar", 1},  {"int8", 1},  {"uint8", 1},  {"short", 2},   {"ushort", 2},  {"int16", 2},
      {"uint16", 2}, {"int", 4},   {"uint", 4},  {"int32", 4},  {"uint32", 4},  {"float", 4},   {"float32", 4},
      {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

// CGAL 5.5's PLY reader adds a "property" to the last element read without checking that
// there is one (a property line before any element line crashes it), and reads an element's
// count as std::size_t ("-1" becomes 2^64 - 1, items it then loops over).  Returns the reason
// to refuse such a header, or "".  Found by test/fuzz's mesh target.
std::string ply_header_defect(const std::string& path)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff bytes = in.tellg();
  in.seekg(0);
  std::string line, element;
  std::map<std::string, std::string> properties; // name to type ("list" for lists) of the element being declared
  bool element_seen = false, format_seen = false;
  // CGAL reads a vertex's coordinates from its properties x, y and z as float or double without
  // checking that they exist or have such a type (a null dereference for each): a vertex element
  // ("vertex" or "vertices", as CGAL names it) must declare all three as floating-point scalars.
  const auto vertex_defect = [&]() -> std::string {
    if(element != "vertex" && element != "vertices") return "";
    for(const char* c : {"x", "y", "z"})
    {
      const auto it = properties.find(c);
      if(it == properties.end()) return "element '" + element + "' has no property '" + c + "'";
      // Types that are no PLY type at all are refused with the body's walk.
      const std::string& type = it->second;
      const bool floating = type == "float" || type == "float32" || type == "double" || type == "float64";
      if(type == "list" || (ply_type_size(type) > 0 && !floating))
        return "the property '" + std::string(c) + "' of element '" + element + "' has the type '" +
               type.substr(0, 40) + "', not float or double";
    }
    return "";
  };
  for(int n = 0; n < 100000 && std::getline(in, line); ++n)
  {
    std::istringstream words(line);
    std::string keyword, name, count;
    words >> keyword;
    // A garbled format line left CGAL guessing the encoding (6 GB for a list read as binary).
    if(keyword == "format")
    {
      std::string kind, version;
      words >> kind >> version;
      if(kind != "ascii" && kind != "binary_little_endian" && kind != "binary_big_endian")
        return "the format '" + kind.substr(0, 40) + "' is not ascii, binary_little_endian or binary_big_endian";
      format_seen = true;
    }
    if((keyword == "end_header" || keyword == "element") && !format_seen) return "no format line before the elements";
    if(keyword == "end_header") return vertex_defect();
    if(keyword == "property" && !element_seen) return "a property before any element";
    if(keyword == "property")
    {
      std::string first, word, last;
      words >> first;
      for(last = first; words >> word;) last = word; // the name ends the line ("property list uchar int vertex_indices")
      properties[last] = first;
    }
    if(keyword != "element") continue;
    const std::string defect = vertex_defect();
    if(!defect.empty()) return defect;
    element_seen = true;
    words >> name >> count;
    element = name;
    properties.clear();
    // Every item of an element takes a byte at least, unless it has no properties: a count
    // up to the file's size is plenty.
    if(count.empty() || count.size() > 18 || count.find_first_not_of("0123456789") != std::string::npos ||
       std::stoll(count) > bytes)
      return "element '" + name.substr(0, 40) + "' has the count '" + count.substr(0, 40) +
             "', not a whole number up to the file's size";
  }
  // Without one, CGAL still read a body: there (found by the mesh fuzzer) it took a list count
  // of 1.4 billion from bytes that no walk of the declared elements reaches.
  return "no end_header line";
}

// CGAL 5.5's PLY reader sizes a list by the count the file gives, unchecked (a count of 482
// million in a 231-byte file: 1.9 GB; found by test/fuzz's mesh target).  Walks the body as
// the header declares it and refuses unknown property types and list counts larger than the
// rest of the file could hold.  A body that ends early is left to CGAL.
std::string ply_body_defect(const std::string& path)
{
  auto printable = [](std::string text) { // file bytes in a message
    text = text.substr(0, 40);
    for(char& c : text)
      if(c < 32 || c > 126) c = '?';
    return text;
  };
  struct Property
  {
    int count_size = 0; // > 0: a list with a count of this many bytes
    bool count_signed = false;
    int size = 0; // of the scalar, or of each list entry
  };
  std::vector<std::pair<long long, std::vector<Property>>> elements;
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff bytes = in.tellg();
  in.seekg(0);
  std::string line, format;
  for(int n = 0; n < 100000 && std::getline(in, line); ++n)
  {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if(keyword == "format") words >> format;
    else if(keyword == "element")
    {
      std::string name;
      long long count = 0;
      words >> name >> count; // checked by ply_header_defect
      elements.push_back({count, {}});
    }
    else if(keyword == "property" && !elements.empty())
    {
      std::vector<std::string> w;
      for(std::string t; words >> t;) w.push_back(t);
      Property p;
      const std::string type = w.empty() ? "" : w[0];
      if(type == "list")
      {
        if(w.size() < 4 || !ply_type_size(w[1]) || !ply_type_size(w[2]))
          return "a list property with types that are not PLY types: '" + printable(line) + "'";
        p.count_size = ply_type_size(w[1]);
        p.count_signed = w[1][0] != 'u';
        p.size = ply_type_size(w[2]);
      }
      else if(!(p.size = ply_type_size(type)))
        return "the property type '" + printable(type) + "' is not a PLY type";
      elements.back().second.push_back(p);
    }
    else if(keyword == "end_header")
      break;
  }
  const bool ascii = format == "ascii", little = format == "binary_little_endian";
  auto remaining = [&] { return static_cast<long long>(bytes - in.tellg()); };
  auto too_many = [&](long long count, long long entry_bytes) {
    return count < 0 || count > remaining() / entry_bytes;
  };
  for(const auto& [count, properties] : elements)
    for(long long item = 0; item < count; ++item)
      for(const Property& p : properties)
      {
        if(ascii)
        {
          std::string token;
          if(!(in >> token)) return "";
          if(!p.count_size) continue;
          char* end = nullptr;
          const long long n = std::strtoll(token.c_str(), &end, 10);
          if(*end != 0 || too_many(n, 2))
            return "a list of '" + printable(token) + "' entries, more than the rest of the file holds";
          for(long long k = 0; k < n; ++k)
            if(!(in >> token)) return "";
          continue;
        }
        if(!p.count_size)
        {
          in.seekg(p.size, std::ios::cur);
          if(!in || remaining() < 0) return "";
          continue;
        }
        unsigned char raw[4] = {0, 0, 0, 0};
        if(!in.read(reinterpret_cast<char*>(raw), p.count_size)) return "";
        unsigned long long u = 0;
        for(int k = 0; k < p.count_size; ++k) u |= static_cast<unsigned long long>(raw[little ? k : p.count_size - 1 - k]) << (8 * k);
        long long n = static_cast<long long>(u);
        if(p.count_signed && (u >> (8 * p.count_size - 1)) & 1) n -= 1LL << (8 * p.count_size);
        if(too_many(n, p.size)) return "a list of " + std::to_string(n) + " entries, more than the rest of the file holds";
        in.seekg(n * p.size, std::ios::cur);
      }
  return "";
}

// The numbers at the start of a line of an OFF file, read as CGAL's scanner reads them: up to
// a comment or the first word that is not a number.
std::vector<double> off_numbers(const std::string& line)
{
  std::istringstream words(line.substr(0, line.find('#')));
  words.imbue(std::locale::classic());
  std::vector<double> numbers;
  double x;
  while(words >> x) numbers.push_back(x);
  return numbers;
}

std::string off_number(double x)
{
  std::ostringstream out;
  out << x;
  return out.str();
}

// CGAL 5.5's OFF header reader doubles the announced edge count as an int, undefined beyond
// INT_MAX / 2 (found by test/fuzz's mesh target).  Reads the header up to that count with the
// same stream operations as CGAL's reader, so that exactly the headers it would double are seen;
// returns the reason to refuse, or "".
std::string off_edge_count_defect(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  char c;
  while((in >> c) && c == '#') in >> CGAL::skip_until_EOL;
  if(!in) return "";
  std::string keyword(1, c);
  while(keyword.size() < 41 && in.get(c) && std::isalnum(c)) keyword += c;
  // The prefixes CGAL accepts before OFF or SKEL: ST, C, N, 4, n (n adds a dimension count).
  std::size_t j = 0;
  for(const char* prefix : {"ST", "C", "N", "4"})
    if(keyword.compare(j, std::strlen(prefix), prefix) == 0) j += std::strlen(prefix);
  const bool dimensional = keyword.compare(j, 1, "n") == 0;
  if(dimensional) ++j;
  const std::string kind = keyword.substr(j);
  if(kind != "OFF") return ""; // SKEL has no edge count; anything else CGAL refuses
  in >> CGAL::skip_comment_OFF >> c;
  if(!in) return "";
  long long edges = 0;
  if(std::isdigit(static_cast<unsigned char>(c)))
  {
    in.putback(c);
    int n;
    in >> n;                 // vertices
    if(dimensional) in >> n; // then vertices
    in >> n;                 // facets
    if(!in || n < 0) return "";
    int n_h;
    in >> n_h;
    if(!in) return ""; // CGAL stops before doubling an unreadable count
    edges = n_h;
  }
  else
  {
    keyword.assign(1, c);
    while(keyword.size() < 41 && in.get(c) && std::isalnum(c)) keyword += c;
    if(keyword != "BINARY") return "";
    if(c != '\n') in >> CGAL::skip_until_EOL;
    std::int32_t counts[4] = {0, 0, 0, 0};
    for(int k = 0; k < (dimensional ? 4 : 3); ++k) CGAL::I_Binary_read_big_endian_integer32(in, counts[k]);
    if(counts[dimensional ? 2 : 1] < 0) return "";
    edges = counts[dimensional ? 3 : 2];
  }
  const long long limit = std::numeric_limits<int>::max() / 2;
  if(edges > limit || edges < -limit)
    return "the header announces " + std::to_string(edges) + " edges, more than CGAL's OFF reader can count";
  return "";
}

// CGAL 5.5's OFF reader trusts what an ASCII file announces: it reserves the header's counts,
// converts a facet's vertex count and indices to std::size_t unchecked (undefined for negative,
// fractional or huge ones), and reads colour entries past the end of short lines or of lines
// that are missing.  Returns the reason to refuse such a file, read as CGAL's scanner reads it,
// or "" (also for binary OFF: CGAL decides).  Each case was found by test/fuzz's mesh target.
std::string off_structure_defect(const std::string& path)
{
  if(const std::string defect = off_edge_count_defect(path); !defect.empty()) return defect;
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const double bytes = static_cast<double>(in.tellg());
  in.seekg(0);
  // The header is read by CGAL's own scanner, so that every header it accepts ("COFF\x91 5 30 0",
  // "OFF'4 ...") is checked as CGAL understands it; the lines after it are followed here.
  CGAL::File_header_OFF header(false);
  if(!(in >> header) || header.binary()) return ""; // CGAL fails on it, or decides (binary)
  const long long vertices = static_cast<long long>(header.size_of_vertices()),
                  facets = static_cast<long long>(header.size_of_facets());
  // CGAL reserves the announced counts before reading (433 million facets in a 53-byte file:
  // gigabytes).  A vertex or a facet takes at least a number and a separator: 2 bytes.
  if(2 * (double(vertices) + double(facets)) > bytes)
    return "the header announces " + std::to_string(vertices) + " vertices and " + std::to_string(facets) +
           " facets, more than a file of " + std::to_string(static_cast<long long>(bytes)) + " bytes can hold";
  std::string line;
  // Lines with content, comments and blank lines skipped as CGAL's scanner skips them.
  const auto next_line = [&]() -> bool {
    while(std::getline(in, line))
    {
      const std::size_t first = line.find_first_not_of(" \t\r");
      if(first != std::string::npos && line[first] != '#') return true;
    }
    return false;
  };
  // CGAL sets an error for a line too short but reads its colour first, past its end; and with
  // colours (COFF) it reads 3 colour entries from a line whose entries after its data are not
  // 0, 1, 3 or 4.
  const bool colours = header.has_colors();
  const std::size_t homogeneous = header.is_homogeneous() ? 1 : 0;
  const std::size_t vertex_colour_at = (3 + homogeneous) * (header.has_normals() ? 2 : 1); // then the texture
  const std::size_t vertex_numbers = vertex_colour_at + (header.has_textures() ? 2 + homogeneous : 0);
  // Once a vertex (or a facet) has a colour, CGAL reads one for every later vertex (facet): from
  // past the end of a line that has none.
  bool vertex_coloured = false, facet_coloured = false;
  // CGAL converts a colour to integers unchecked: an index into its colour map (negative: read
  // before the map; huge: undefined), or 3 entries to unsigned char (whole ones as they are,
  // fractional ones times 255).
  const auto colour_defect = [&](const std::string& item, const double* colour, std::size_t entries) {
    if(entries == 1)
      return colour[0] >= 0 && colour[0] < 2147483648.
                 ? std::string()
                 : item + " has the colour index " + off_number(colour[0]) + ", not one of a colour map";
    bool whole = true;
    for(int i = 0; i < 3; ++i) whole = whole && colour[i] == std::floor(colour[i]);
    for(int i = 0; i < 3; ++i)
    {
      const double byte = whole ? colour[i] : 255 * colour[i];
      if(!(byte > -1 && byte < 256))
        return item + " has the colour entry " + off_number(colour[i]) + ", outside 0 .. 255 (whole) or 0 .. 1";
    }
    return std::string();
  };
  const auto line_defect = [&](const std::string& what, long long k, const std::vector<double>& numbers,
                               std::size_t needed, std::size_t first_colour, bool& coloured) {
    if(numbers.size() < needed)
      return what + " " + std::to_string(k) + " starts with " + std::to_string(numbers.size()) + " numbers where " +
             std::to_string(needed) + " are needed ('" + line.substr(0, 40) + "')";
    const std::size_t extra = numbers.size() - needed;
    if(!colours) return std::string();
    const std::string item = what + " " + std::to_string(k);
    if(extra == 0 && coloured) return item + " has no colour, but an earlier " + what + " has one";
    coloured = coloured || extra > 0;
    if(extra == 0) return std::string();
    if(extra == 1 || extra == 3 || extra == 4) return colour_defect(item, numbers.data() + first_colour, extra);
    return item + " has " + std::to_string(extra) + " numbers after its data; a colour has 1, 3 or 4";
  };
  for(long long v = 0; v < vertices; ++v)
  {
    // One vertex a line, as CGAL reads them; CGAL reads the colour of a missing line too.
    if(!next_line())
      return "the file ends after " + std::to_string(v) + " of its " + std::to_string(vertices) + " vertices";
    const std::string defect =
        line_defect("vertex", v, off_numbers(line), vertex_numbers, vertex_colour_at, vertex_coloured);
    if(!defect.empty()) return defect;
  }
  for(long long f = 0; f < facets; ++f)
  {
    if(!next_line())
      return "the file ends after " + std::to_string(f) + " of its " + std::to_string(facets) + " facets";
    const std::vector<double> numbers = off_numbers(line);
    if(numbers.empty()) return ""; // CGAL fails on it
    const double count = numbers[0];
    if(!(count >= 0 && count == std::floor(count) && count <= double(numbers.size() - 1)))
      return "facet " + std::to_string(f) + " announces " + std::to_string(count) + " vertices but its line holds " +
             std::to_string(numbers.size() - 1) + " numbers after the count";
    const std::size_t facet_numbers = 1 + static_cast<std::size_t>(count);
    const std::string defect = line_defect("facet", f, numbers, facet_numbers, facet_numbers, facet_coloured);
    if(!defect.empty()) return defect;
    // CGAL converts each index (read as a double) to std::size_t unchecked: 1e90 is undefined.
    for(std::size_t k = 1; k <= static_cast<std::size_t>(count); ++k)
      if(!(numbers[k] >= 0 && numbers[k] < double(vertices) && numbers[k] == std::floor(numbers[k])))
        return "facet " + std::to_string(f) + " has the vertex index " + off_number(numbers[k]) +
               ", not a whole number below the " + std::to_string(vertices) + " vertices";
  }
  return "";
}

} // namespace

std::vector<std::string> Mesh_file::face_field_names() const
{
  std::set<std::string> names;
  for(const auto& p : face_properties) names.insert(p.first);
  std::vector<std::string> fields;
  for(const auto& p : face_properties)
  {
    const std::string& n = p.first;
    if(n.size() < 3 || n.compare(n.size() - 2, 2, "_x") != 0) continue;
    const std::string base = n.substr(0, n.size() - 2);
    if(names.count(base + "_y") && names.count(base + "_z")) fields.push_back(base);
  }
  return fields;
}

std::vector<std::array<double, 3>> Mesh_file::face_field(const std::string& name) const
{
  const std::vector<double>* axes[3] = {nullptr, nullptr, nullptr};
  const char* suffix[3] = {"_x", "_y", "_z"};
  for(const auto& p : face_properties)
    for(int k = 0; k < 3; ++k)
      if(p.first == name + suffix[k]) axes[k] = &p.second;
  std::vector<std::array<double, 3>> vectors;
  if(!axes[0] || !axes[1] || !axes[2]) return vectors;
  for(std::size_t i = 0; i < axes[0]->size(); ++i) vectors.push_back({{(*axes[0])[i], (*axes[1])[i], (*axes[2])[i]}});
  return vectors;
}

Mesh_file read_mesh_file(const std::string& path)
{
  {
    std::ifstream probe(path);
    if(!probe) throw Tool_error("cannot open mesh file '" + path + "': " + std::strerror(errno));
  }
  const std::string ext = extension(path);
  static const std::set<std::string> formats = {"off", "obj", "ply", "stl", "ts"};
  if(!formats.count(ext))
    throw Tool_error("'" + path + "': unknown mesh format" + (ext.empty() ? std::string() : " '." + ext + "'") +
                     " (the tool reads .off, .obj, .ply, .stl and .ts)");
  if(ext == "off")
  {
    const std::string defect = off_structure_defect(path);
    if(!defect.empty()) throw Tool_error("cannot read a polygon mesh from '" + path + "' (malformed OFF: " + defect + ")");
  }
  if(ext == "ply")
  {
    std::string defect = ply_header_defect(path);
    if(!defect.empty()) throw Tool_error("cannot read a polygon mesh from '" + path + "' (malformed PLY header: " + defect + ")");
    defect = ply_body_defect(path);
    if(!defect.empty())
      throw Tool_error("cannot read a polygon mesh from '" + path + "' (malformed PLY: " + defect + ")");
  }
  Mesh_file file;
  bool ok = false;
  try
  {
    // By our lower-case extension: CGAL's dispatch (read_polygon_soup) wants it in lower case.
    const auto np = CGAL::parameters::verbose(false);
    if(ext == "off") ok = CGAL::IO::read_OFF(path, file.points, file.polygons, np);
    else if(ext == "obj") ok = CGAL::IO::read_OBJ(path, file.points, file.polygons, np);
    else if(ext == "stl") ok = CGAL::IO::read_STL(path, file.points, file.polygons, np);
    else if(ext == "ts") ok = CGAL::IO::read_GOCAD(path, file.points, file.polygons, np);
    else if((ok = CGAL::IO::read_PLY(path, file.points, file.polygons, np)))
    {
      // The mesh is what counts: a PLY whose properties this parser cannot follow just has none.
      if(!read_ply_face_properties(path, file.face_properties)) file.face_properties.clear();
      if(file.polygons.empty()) file.polygons = read_ply_triangle_strips(path, file.points.size());
    }
  }
  catch(const std::exception& e)
  {
    throw Tool_error("cannot read a mesh from '" + path + "': " + one_line(e.what()));
  }
  if(!ok) throw Tool_error("cannot read a polygon mesh from '" + path + "' (malformed file)");
  for(const auto& p : file.face_properties)
    if(p.second.size() != file.polygons.size())
      throw Tool_error("'" + path + "': face property '" + p.first + "' has " + std::to_string(p.second.size()) +
                       " values for " + std::to_string(file.polygons.size()) + " faces");
  return file;
}

} // namespace tvf_tool
