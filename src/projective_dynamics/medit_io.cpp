// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Medit .mesh files: a token reader that knows the line of every token, so that every
// refusal names where the file went wrong.

#include <CGAL/Projective_dynamics/errors.h>
#include <CGAL/Projective_dynamics/medit_io.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>

namespace CGAL {
namespace Projective_dynamics {

namespace {

class Tokens
{
public:
  Tokens(std::istream& in, const std::string& name) : in_(in), name_(name) {}

  /// The next token, or "" at the end of the input.
  std::string next()
  {
    std::string token;
    int c;
    while((c = in_.get()) != EOF)
    {
      if(c == '\n') ++line_;
      if(c == '#')
      {
        while((c = in_.get()) != EOF && c != '\n') {}
        if(c == '\n') ++line_;
        continue;
      }
      if(!std::isspace(c))
      {
        token_line_ = line_;
        token.push_back(char(c));
        while((c = in_.peek()) != EOF && !std::isspace(c) && c != '#')
          token.push_back(char(in_.get()));
        // A token longer than any number or keyword is no part of a mesh file.
        if(token.size() > 64) fail("a token of more than 64 characters");
        return token;
      }
    }
    token_line_ = line_;
    return token;
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw Invalid_input(name_ + ", line " + std::to_string(token_line_) + ": " + what);
  }

  long long integer(const char* what)
  {
    const std::string t = next();
    if(t.empty()) fail(std::string("the file ends where ") + what + " was expected");
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if(end != t.c_str() + t.size() || errno == ERANGE) fail(std::string("'") + t + "' is not " + what);
    return v;
  }

  double real(const char* what)
  {
    const std::string t = next();
    if(t.empty()) fail(std::string("the file ends where ") + what + " was expected");
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if(end != t.c_str() + t.size()) fail(std::string("'") + t + "' is not " + what);
    if(!std::isfinite(v)) fail("a non-finite value '" + t + "' where " + what + " was expected");
    return v;
  }

  /// A count of records, at most what the rest of a file of sane size could hold.
  std::size_t count(const std::string& section)
  {
    const long long n = integer(("the number of " + section).c_str());
    // 2^31 - 1: the indices are ints.
    if(n < 0 || n > std::numeric_limits<int>::max())
      fail("the number of " + section + " " + std::to_string(n) + " is out of range");
    return std::size_t(n);
  }

  int line() const { return token_line_; }

private:
  std::istream& in_;
  std::string name_;
  int line_ = 1, token_line_ = 1;
};

std::string lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

template <std::size_t N>
void read_cells(Tokens& tokens, const std::string& section, std::vector<std::array<int, N>>& cells, std::size_t vertices)
{
  const std::size_t n = tokens.count(section);
  cells.reserve(cells.size() + std::min<std::size_t>(n, 1 << 20)); // no huge reserve on a forged count
  for(std::size_t i = 0; i < n; ++i)
  {
    std::array<int, N> cell;
    for(std::size_t k = 0; k < N; ++k)
    {
      const long long v = tokens.integer("a vertex index");
      if(v < 1 || std::size_t(v) > vertices)
        tokens.fail("vertex index " + std::to_string(v) + " of " + section + " " + std::to_string(i + 1) +
                    " is outside [1, " + std::to_string(vertices) + "]");
      cell[k] = int(v - 1);
    }
    tokens.integer("a reference");
    cells.push_back(cell);
  }
}

} // namespace

Tet_mesh read_medit(std::istream& in, const std::string& name)
{
  Tokens tokens(in, name);
  Tet_mesh mesh;
  std::string t = tokens.next();
  if(lower(t) != "meshversionformatted") tokens.fail("not a Medit mesh: it does not start with MeshVersionFormatted");
  const long long version = tokens.integer("the version");
  if(version < 1 || version > 4) tokens.fail("unknown Medit version " + std::to_string(version));
  // Sections that are skipped, with the number of numbers of each record.
  static const std::map<std::string, int> skipped = {
      {"edges", 3},         {"corners", 1},          {"requiredvertices", 1}, {"ridges", 1},
      {"requirededges", 1}, {"requiredtriangles", 1}, {"quadrilaterals", 5},  {"hexahedra", 9},
      {"normals", 3},       {"normalatvertices", 2},  {"tangents", 3},        {"tangentatvertices", 2},
      {"prisms", 7},        {"identifier", 0},        {"geometry", 0}};
  bool dimension = false, vertices = false;
  while(!(t = tokens.next()).empty())
  {
    const std::string key = lower(t);
    if(key == "end") break;
    if(key == "dimension")
    {
      const long long d = tokens.integer("the dimension");
      if(d != 3) tokens.fail("dimension " + std::to_string(d) + ": only 3 is supported");
      dimension = true;
    }
    else if(key == "vertices")
    {
      if(!dimension) tokens.fail("Vertices before Dimension");
      if(vertices) tokens.fail("a second Vertices section");
      const std::size_t n = tokens.count("vertices");
      mesh.points.reserve(std::min<std::size_t>(n, 1 << 20));
      for(std::size_t i = 0; i < n; ++i)
      {
        Point p;
        for(double& c : p) c = tokens.real("a coordinate");
        tokens.integer("a reference");
        mesh.points.push_back(p);
      }
      vertices = true;
    }
    else if(key == "tetrahedra" || key == "triangles")
    {
      if(!vertices) tokens.fail(t + " before Vertices");
      if(key == "tetrahedra")
        read_cells(tokens, "tetrahedron", mesh.tetrahedra, mesh.points.size());
      else
        read_cells(tokens, "triangle", mesh.triangles, mesh.points.size());
    }
    else
    {
      const auto s = skipped.find(key);
      if(s == skipped.end()) tokens.fail("unknown section '" + t + "'");
      if(s->second == 0) continue;
      const std::size_t n = tokens.count(t);
      for(std::size_t i = 0; i < n * std::size_t(s->second); ++i) tokens.real("a number");
    }
  }
  if(!vertices) tokens.fail("no Vertices section");
  return mesh;
}

Tet_mesh read_medit(const std::string& path)
{
  std::ifstream in(path);
  if(!in) throw Invalid_input("cannot open '" + path + "' for reading");
  return read_medit(in, path);
}

void write_medit(std::ostream& out, const Tet_mesh& mesh)
{
  out.precision(17);
  out << "MeshVersionFormatted 2\nDimension 3\n\nVertices\n" << mesh.points.size() << '\n';
  for(const Point& p : mesh.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << " 0\n";
  if(!mesh.triangles.empty())
  {
    out << "\nTriangles\n" << mesh.triangles.size() << '\n';
    for(const Triangle& f : mesh.triangles) out << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << " 0\n";
  }
  out << "\nTetrahedra\n" << mesh.tetrahedra.size() << '\n';
  for(const Tetrahedron& c : mesh.tetrahedra)
    out << c[0] + 1 << ' ' << c[1] + 1 << ' ' << c[2] + 1 << ' ' << c[3] + 1 << " 0\n";
  out << "\nEnd\n";
}

void write_medit(const std::string& path, const Tet_mesh& mesh)
{
  std::ofstream out(path);
  if(!out) throw Invalid_input("cannot open '" + path + "' for writing");
  write_medit(out, mesh);
  out.flush();
  if(!out) throw Invalid_input("writing '" + path + "' failed");
}

} // namespace Projective_dynamics
} // namespace CGAL
