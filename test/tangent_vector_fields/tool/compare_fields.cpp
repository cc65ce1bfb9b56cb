// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// compare_fields A B TOLERANCE: whether two face-field text files (.tvf: "TVF_FACE_FIELD 1",
// "faces N"; .rawfield: "n N"; then the vectors) hold the same field: same header, same count
// of numbers, A not zero, and every number of B within TOLERANCE times A's largest absolute
// number of A's.  Prints the largest difference; exit code 0 if they agree, 1 if not.  The
// command-line round trips compare what they read back with what was written (no library:
// the files are read as plain numbers).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Field_text
{
  std::string header;
  std::vector<double> numbers;
};

bool read(const char* path, Field_text& out)
{
  std::ifstream in(path);
  if(!in) return false;
  std::string first;
  in >> first;
  std::string second, third, fourth;
  if(first == "TVF_FACE_FIELD") in >> second >> third >> fourth; // version, "faces", N
  else in >> second;                                                // rawfield: n, N
  out.header = first + " " + second + " " + third + " " + fourth;
  std::string token;
  while(in >> token)
  {
    char* end = nullptr;
    const double x = std::strtod(token.c_str(), &end);
    if(end == token.c_str() || *end != '\0' || !std::isfinite(x)) return false;
    out.numbers.push_back(x);
  }
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 4)
  {
    std::fprintf(stderr, "usage: compare_fields A B TOLERANCE\n");
    return 2;
  }
  Field_text a, b;
  if(!read(argv[1], a) || !read(argv[2], b))
  {
    std::fprintf(stderr, "cannot read both files as fields of finite numbers\n");
    return 1;
  }
  const double tolerance = std::atof(argv[3]);
  if(a.header != b.header || a.numbers.size() != b.numbers.size())
  {
    std::fprintf(stderr, "different fields: '%s' with %zu numbers, '%s' with %zu\n", a.header.c_str(), a.numbers.size(),
                 b.header.c_str(), b.numbers.size());
    return 1;
  }
  double largest = 0, difference = 0;
  for(std::size_t i = 0; i < a.numbers.size(); ++i)
  {
    largest = std::max(largest, std::abs(a.numbers[i]));
    difference = std::max(difference, std::abs(a.numbers[i] - b.numbers[i]));
  }
  std::printf("%zu numbers, largest %.17g, largest difference %.3g (%.3g relative, tolerance %g)\n", a.numbers.size(),
              largest, difference, largest > 0 ? difference / largest : difference, tolerance);
  if(!(largest > 0))
  {
    std::fprintf(stderr, "the reference field is zero: nothing is compared\n");
    return 1;
  }
  return difference <= tolerance * largest ? 0 : 1;
}
