// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Tangent_vector_fields/internal/constraint_json.h>

#include <cmath>
#include <istream>
#include <iterator>
#include <set>
#include <vector>

namespace CGAL {
namespace Tangent_vector_fields {
namespace internal {

namespace {

const char* type_name(const Json& j)
{
  if(j.is_object()) return "an object";
  if(j.is_array()) return "an array";
  if(j.is_string()) return "a string";
  if(j.is_boolean()) return "a boolean";
  if(j.is_null()) return "null";
  return "a number";
}

} // namespace

Json parse_json(const std::string& text, const std::string& what, int max_depth)
{
  // The keys seen in each open object, innermost last: a repeated key is refused (the
  // parser would silently keep the last value).
  std::vector<std::set<std::string>> keys;
  auto check = [&](int depth, Json::parse_event_t event, Json& parsed) {
    if(depth > max_depth)
      throw Invalid_input(what + ": JSON nested deeper than " + std::to_string(max_depth) + " levels");
    switch(event)
    {
    case Json::parse_event_t::object_start: keys.emplace_back(); break;
    case Json::parse_event_t::object_end: keys.pop_back(); break;
    case Json::parse_event_t::key:
      if(!keys.back().insert(parsed.get<std::string>()).second)
        throw Invalid_input(what + ": the key \"" + parsed.get<std::string>() + "\" appears twice in one object");
      break;
    default: break;
    }
    return true;
  };
  try
  {
    return Json::parse(text, check);
  }
  catch(const Json::parse_error& e)
  {
    // e.what() reads "[json.exception.parse_error.101] parse error at line L, column C: ..."
    const std::string message = e.what();
    const std::size_t start = message.find("] ");
    throw Invalid_input(what + ": " + (start == std::string::npos ? message : message.substr(start + 2)));
  }
  catch(const Json::out_of_range& e)
  {
    const std::string message = e.what();
    const std::size_t start = message.find("] ");
    throw Invalid_input(what + ": " + (start == std::string::npos ? message : message.substr(start + 2)));
  }
}

Json parse_json(std::istream& in, const std::string& what, int max_depth)
{
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if(in.bad()) throw Invalid_input(what + ": reading failed");
  return parse_json(text, what, max_depth);
}

void Json_reader::expect_object() const
{
  if(!node.is_object()) fail(std::string("not a JSON object (") + type_name(node) + ")");
}

void Json_reader::allow_only(const std::vector<const char*>& keys, const std::string& context) const
{
  expect_object();
  for(const auto& item : node.items())
  {
    bool known = false;
    for(const char* k : keys) known = known || item.key() == k;
    if(known) continue;
    std::string list;
    for(const char* k : keys) list += std::string(list.empty() ? "" : ", ") + "\"" + k + "\"";
    fail("unknown key \"" + item.key() + "\"" + context + " (expected " + list + ")");
  }
}

const Json& Json_reader::member(const char* key) const
{
  expect_object();
  const auto it = node.find(key);
  if(it == node.end()) fail(std::string("missing \"") + key + "\"");
  return *it;
}

double Json_reader::number(const char* key) const
{
  const Json& j = member(key);
  if(!j.is_number()) fail(std::string("\"") + key + "\" must be a number, not " + type_name(j));
  const double x = j.get<double>();
  if(!std::isfinite(x)) fail(std::string("\"") + key + "\" is not finite");
  return x;
}

long long Json_reader::integer(const char* key, long long lowest, long long highest) const
{
  const double x = number(key);
  if(x != std::floor(x) || x < double(lowest) || x > double(highest))
    fail(std::string("\"") + key + "\" must be an integer in [" + std::to_string(lowest) + ", " + std::to_string(highest) + "]");
  return static_cast<long long>(x);
}

int Json_reader::index(const char* key) const
{
  const double x = number(key);
  if(x != std::floor(x) || x < 0 || x > 2e9) fail(std::string("\"") + key + "\" is not a valid index");
  return static_cast<int>(x);
}

std::string Json_reader::text(const char* key) const
{
  const Json& j = member(key);
  if(!j.is_string()) fail(std::string("\"") + key + "\" must be a string, not " + type_name(j));
  return j.get<std::string>();
}

const Json& Json_reader::array(const char* key) const
{
  const Json& j = member(key);
  if(!j.is_array()) fail(std::string("\"") + key + "\" must be an array, not " + type_name(j));
  return j;
}

std::array<double, 3> Json_reader::triple(const char* key) const
{
  const Json& j = member(key);
  if(!j.is_array() || j.size() != 3) fail(std::string("\"") + key + "\" must be an array of 3 numbers");
  std::array<double, 3> v{{0, 0, 0}};
  for(int k = 0; k < 3; ++k)
  {
    if(!j[k].is_number()) fail(std::string("\"") + key + "\" must be an array of 3 numbers");
    v[k] = j[k].get<double>();
    if(!std::isfinite(v[k])) fail(std::string("\"") + key + "\" has a non-finite entry");
  }
  return v;
}

std::array<double, 3> Json_reader::point(const Intrinsic_mesh& mesh, int face) const
{
  if(face >= mesh.number_of_faces()) fail("face " + std::to_string(face) + " out of range");
  if(has("point"))
  {
    if(has("barycentric") || has("vertices")) fail("give \"point\" or \"vertices\" and \"barycentric\", not both");
    return barycentric_coordinates(mesh, face, triple("point"));
  }
  if(has("barycentric"))
  {
    const std::array<double, 3> w = triple("barycentric");
    const std::array<double, 3> v = triple("vertices");
    for(double x : v)
      if(x != std::floor(x) || x < 0 || x > 2e9) fail("\"vertices\" must be 3 vertex indices");
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
} // namespace Tangent_vector_fields
} // namespace CGAL
