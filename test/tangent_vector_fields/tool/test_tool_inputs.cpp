// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The tool's own readers and the editor's answers on hostile input: the regressions of the
// fuzzers (test/fuzz, doc/fuzzing.md).  Each test names the fuzz target that found it; the
// input it found is kept in test/fuzz/corpus/<target>/.

#include "coefficient_file.h"
#include "messages.h"
#include "mesh_input.h"
#include "scratch_path.h"
#include "tool.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

using namespace tvf_tool;
using namespace tvf_viewer;

namespace {

// A temporary file with `bytes`, named `name` in the test's folder.
std::string file_with(const std::string& name, const std::string& bytes)
{
  const std::string path = tvf_test::scratch_path(name);
  std::ofstream out(path, std::ios::binary);
  out << bytes;
  return path;
}

// The bytes of a valid .tvfc file of `k` coefficients, as `tvf compress` writes it.
std::string coefficient_bytes(int k)
{
  Coefficient_file file;
  file.faces = 80;
  file.signature = {{1, -2, 3, -4}};
  file.relative_error = 0.125;
  file.coefficients = Eigen::VectorXd::LinSpaced(k, -1, 1);
  const std::string path = tvf_test::scratch_path("valid.tvfc");
  write_coefficient_file(path, file);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// Offsets in a .tvfc file (doc/tangent_vector_fields/manual.md).
const std::size_t count_offset = 24, signature_offset = 32, error_offset = 64;

template <class T>
void put_at(std::string& bytes, std::size_t offset, T value)
{
  std::memcpy(&bytes[offset], &value, sizeof(T));
}

// The message of the Tool_error that reading `bytes` as a .tvfc file throws ("" if none).
std::string coefficient_error(const std::string& bytes)
{
  std::istringstream in(bytes);
  try
  {
    read_coefficient_file(in, bytes.size(), "x.tvfc");
  }
  catch(const Tool_error& e)
  {
    return e.what();
  }
  return "";
}

} // namespace

TEST(CoefficientFile, ReadsBackWhatCompressWrites)
{
  const std::string path = file_with("round.tvfc", coefficient_bytes(8));
  const Coefficient_file file = read_coefficient_file(path);
  EXPECT_EQ(file.faces, 80u);
  EXPECT_EQ(file.relative_error, 0.125);
  ASSERT_EQ(file.coefficients.size(), 8);
  EXPECT_EQ(file.coefficients[7], 1.0);
}

// fuzz_tvfc: a NaN relative error (bytes of the seed flipped) was accepted and printed by decompress.
TEST(CoefficientFile, NonFiniteOrOutOfRangeRelativeErrorIsRefused)
{
  for(double error : {std::numeric_limits<double>::quiet_NaN(), HUGE_VAL, -0.5, 1.5})
  {
    std::string bytes = coefficient_bytes(8);
    put_at(bytes, error_offset, error);
    EXPECT_EQ(coefficient_error(bytes), "coefficient file 'x.tvfc': the relative error at compression is not in [0, 1]")
        << error;
  }
}

TEST(CoefficientFile, NonFiniteSignatureIsRefused)
{
  std::string bytes = coefficient_bytes(8);
  put_at(bytes, signature_offset + 16, std::numeric_limits<double>::infinity());
  EXPECT_EQ(coefficient_error(bytes), "coefficient file 'x.tvfc': non-finite basis signature");
}

// A count of 2^28 in a file of 144 bytes asked for 2 GiB before the read failed.
TEST(CoefficientFile, CountBeyondTheFileSizeIsRefusedBeforeAllocating)
{
  std::string bytes = coefficient_bytes(8);
  put_at(bytes, count_offset, std::uint32_t(1) << 28);
  EXPECT_EQ(coefficient_error(bytes),
            "coefficient file 'x.tvfc': truncated (268435456 coefficients announced, 144 bytes)");
  put_at(bytes, count_offset, std::uint32_t(9)); // one more than the file holds
  EXPECT_EQ(coefficient_error(bytes), "coefficient file 'x.tvfc': truncated (9 coefficients announced, 144 bytes)");
}

TEST(CoefficientFile, NoCoefficientsIsRefused)
{
  std::string bytes = coefficient_bytes(8);
  put_at(bytes, count_offset, std::uint32_t(0));
  EXPECT_EQ(coefficient_error(bytes), "coefficient file 'x.tvfc': no coefficients");
}

// fuzz_editor: the error about a message with a byte of no UTF-8 character quoted that byte,
// and the answer was not JSON (a browser closes a WebSocket that sends invalid UTF-8).
TEST(EditorMessages, QuotedTextIsAlwaysValidUtf8Json)
{
  EXPECT_EQ(quote("constr\xe1int"), "\"constr\\ufffdint\"");
  EXPECT_EQ(quote("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x99\x82"), "\"caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x99\x82\"");
  EXPECT_EQ(quote("\xc0\xaf|\xed\xa0\x80|\xf4\x90\x80\x80|\xe2\x82"), // overlong, surrogate, > U+10FFFF, cut short
            "\"\\ufffd\\ufffd|\\ufffd\\ufffd\\ufffd|\\ufffd\\ufffd\\ufffd\\ufffd|\\ufffd\\ufffd\"");
  const std::string text = std::string("{\"type\":\"add\",\"constr\xe1int\":1}");
  std::string message;
  try
  {
    CGAL::Tangent_vector_fields::internal::parse_json(text, "not JSON");
  }
  catch(const CGAL::Tangent_vector_fields::Invalid_input& e)
  {
    message = e.what();
  }
  ASSERT_NE(message.find("ill-formed UTF-8"), std::string::npos) << message;
  const Json answer = CGAL::Tangent_vector_fields::internal::parse_json("{\"message\":" + quote(message) + "}", "answer");
  EXPECT_NE(answer["message"].get<std::string>().find("ill-formed UTF-8"), std::string::npos);
}

// The message of the Tool_error that reading the mesh file `path` throws ("" if none).
std::string mesh_error(const std::string& path)
{
  try
  {
    read_mesh_file(path);
  }
  catch(const Tool_error& e)
  {
    return e.what();
  }
  return "";
}

// fuzz_mesh: CGAL's OFF scanner converts a facet's vertex count to std::size_t unchecked: a
// negative count is undefined behaviour, a huge one is allocated (3 GB for a 3 KB file) before
// the numbers are found missing.  Such facets are refused before CGAL reads the file.
TEST(MeshInput, OffFacetCountBeyondItsLineIsRefused)
{
  const std::string header = "OFF\n3 1 0\n0 0 0\n1 0 0\n# a comment\n\n0 1 0\n";
  const std::string negative = file_with("negative_facet.off", header + "-1.5 0 1 2\n");
  EXPECT_EQ(mesh_error(negative), "cannot read a polygon mesh from '" + negative + "' (malformed OFF: facet 0 announces "
                                  "-1.500000 vertices but its line holds 3 numbers after the count)");
  const std::string huge = file_with("huge_facet.off", header + "380400716 0 1 2\n");
  EXPECT_EQ(mesh_error(huge), "cannot read a polygon mesh from '" + huge + "' (malformed OFF: facet 0 announces "
                              "380400716.000000 vertices but its line holds 3 numbers after the count)");
  const std::string good = file_with("good_facet.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n");
  EXPECT_EQ(read_mesh_file(good).polygons.size(), 1u);
  // CGAL reserved the announced facets before reading them: 433 million in a 53-byte file.
  const std::string announced = file_with("announced_facets.off", "OFF\n4 433333333 0 1\n3 0 2 1\n3 0 1 3\n"
                                                                  "3 1 2 3\n3 0 3 2\n");
  EXPECT_EQ(mesh_error(announced), "cannot read a polygon mesh from '" + announced + "' (malformed OFF: the header "
                                   "announces 4 vertices and 433333333 facets, more than a file of 52 bytes can hold)");
  // CGAL converted each vertex index to std::size_t unchecked (1.2e90: undefined behaviour).
  const std::string index = file_with("huge_index.off", header + "3 0 1 1.2e90\n");
  EXPECT_EQ(mesh_error(index), "cannot read a polygon mesh from '" + index + "' (malformed OFF: facet 0 has the "
                               "vertex index 1.2e+90, not a whole number below the 3 vertices)");
  // With colours, CGAL read 3 colour entries from a line with 2 after its data (past its end).
  const std::string colour = file_with("two_colour_entries.off", "COFF\n3 1 0\n0 0 0\n1 0 0 7 7\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(mesh_error(colour), "cannot read a polygon mesh from '" + colour + "' (malformed OFF: vertex 1 has 2 "
                                "numbers after its data; a colour has 1, 3 or 4)");
  // CGAL read the colour of a vertex line that is not there (past the end of no numbers).
  const std::string short_file = file_with("ends_early.off", "COFF\n5 3 0\n0 0 1\n2 0 1\n");
  EXPECT_EQ(mesh_error(short_file), "cannot read a polygon mesh from '" + short_file + "' (malformed OFF: the file ends "
                                    "after 2 of its 5 vertices)");
  // Once a vertex (facet) had a colour, CGAL read one for each later vertex (facet): past the
  // end of a line without one.
  const std::string uncoloured = file_with("uncoloured_vertex.off", "COFF\n3 1 0\n0 0 0 9\n1 0 0\n0 1 0 9\n3 0 1 2\n");
  EXPECT_EQ(mesh_error(uncoloured), "cannot read a polygon mesh from '" + uncoloured + "' (malformed OFF: vertex 1 "
                                    "has no colour, but an earlier vertex has one)");
  const std::string facets = file_with("uncoloured_facet.off", "COFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
                                                               "3 0 1 2 1 0 0\n3 1 3 2\n");
  EXPECT_EQ(mesh_error(facets), "cannot read a polygon mesh from '" + facets + "' (malformed OFF: facet 1 has no "
                                "colour, but an earlier facet has one)");
  // CGAL converted colours to integers unchecked: a colour-map index of 6.7e53 (undefined), a
  // negative one (read before its map), an entry of 300 (undefined as unsigned char).
  const std::string colour_index = file_with("colour_index.off", "COFF\n3 1 0\n0 0 0 6.7e53\n1 0 0 1\n0 1 0 1\n3 0 1 2\n");
  EXPECT_EQ(mesh_error(colour_index), "cannot read a polygon mesh from '" + colour_index + "' (malformed OFF: vertex "
                                      "0 has the colour index 6.7e+53, not one of a colour map)");
  const std::string negative_index = file_with("negative_index.off", "COFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 -1\n");
  EXPECT_EQ(mesh_error(negative_index), "cannot read a polygon mesh from '" + negative_index + "' (malformed OFF: "
                                        "facet 0 has the colour index -1, not one of a colour map)");
  const std::string bright = file_with("bright.off", "COFF\n3 1 0\n0 0 0 300 0 0\n1 0 0 0 0 0\n0 1 0 0 0 0\n"
                                                     "3 0 1 2\n");
  EXPECT_EQ(mesh_error(bright), "cannot read a polygon mesh from '" + bright + "' (malformed OFF: vertex 0 has the "
                                "colour entry 300, outside 0 .. 255 (whole) or 0 .. 1)");
  // Coloured vertices with uncoloured facets, and the reverse, are well formed.
  const std::string mixed = file_with("mixed_colours.off", "COFF\n3 1 0\n0 0 0 1 0 0\n1 0 0 0 1 0\n0 1 0 0.5 0.5 1\n"
                                                           "3 0 1 2\n");
  EXPECT_EQ(read_mesh_file(mixed).polygons.size(), 1u);
  // CGAL's scanner takes "OFF'4" for a keyword and its counts: the header is read by that scanner.
  const std::string odd = file_with("odd_keyword.off", "OFF'4 433333333 0 1\n3 0 2 1\n");
  EXPECT_EQ(mesh_error(odd), "cannot read a polygon mesh from '" + odd + "' (malformed OFF: the header announces "
                             "4 vertices and 433333333 facets, more than a file of 28 bytes can hold)");
  // CGAL doubled the announced edge count as an int (2 * 1092036785: undefined), in ASCII and
  // in binary headers; an edge count it can double is read as before.
  const std::string edges = file_with("announced_edges.off", "OFF\n4 1 1092036785\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n");
  EXPECT_EQ(mesh_error(edges), "cannot read a polygon mesh from '" + edges + "' (malformed OFF: the header announces "
                               "1092036785 edges, more than CGAL's OFF reader can count)");
  const std::string negative_edges = file_with("negative_edges.off", "NOFF # normals\n# a comment\n3 1 -1092036785\n");
  EXPECT_EQ(mesh_error(negative_edges), "cannot read a polygon mesh from '" + negative_edges + "' (malformed OFF: the "
                                        "header announces -1092036785 edges, more than CGAL's OFF reader can count)");
  const std::string binary = file_with("binary_edges.off", std::string("OFF BINARY\n") +
                                                               std::string("\0\0\0\3\0\0\0\1\x7f\xff\xff\xff", 12));
  EXPECT_EQ(mesh_error(binary), "cannot read a polygon mesh from '" + binary + "' (malformed OFF: the header announces "
                                "2147483647 edges, more than CGAL's OFF reader can count)");
  const std::string countable = file_with("countable_edges.off", "OFF\n3 1 1073741823\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(read_mesh_file(countable).polygons.size(), 1u);
}

// fuzz_mesh: CGAL's PLY reader crashed (a null dereference) on a property line before any
// element line; the header is checked before CGAL reads the file.
TEST(MeshInput, PlyPropertyBeforeAnyElementIsRefused)
{
  const std::string path = file_with("property_first.ply", "ply\nformat ascii 1.0\nproperty double x\n"
                                                           "element vertex 1\nend_header\n0\n");
  try
  {
    read_mesh_file(path);
    FAIL() << "accepted";
  }
  catch(const Tool_error& e)
  {
    EXPECT_EQ(std::string(e.what()), "cannot read a polygon mesh from '" + path +
                                         "' (malformed PLY header: a property before any element)");
  }
  // A garbled format line left CGAL guessing the encoding (it allocated 6 GB for a list).
  const std::string garbled = file_with("garbled_format.ply", "ply\nformaqt ascii 1.0\nelement vertex 1\n"
                                                              "property double x\nend_header\n0\n");
  EXPECT_EQ(mesh_error(garbled), "cannot read a polygon mesh from '" + garbled +
                                     "' (malformed PLY header: no format line before the elements)");
  // CGAL read the coordinates of a vertex element without x (a null dereference).
  const std::string no_x = file_with("vertex_without_x.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"
                                                             "property double y\nproperty double z\nend_header\n0 0\n");
  EXPECT_EQ(mesh_error(no_x), "cannot read a polygon mesh from '" + no_x +
                                  "' (malformed PLY header: element 'vertex' has no property 'x')");
  // CGAL read a coordinate of an integer type as a float (a null dereference), also in an
  // element named "vertices"; a float32 coordinate is read.
  const std::string integer_y = file_with("integer_y.ply", "ply\nformat ascii 1.0\nelement vertices 1\n"
                                                           "property double x\nproperty uint16 y\nproperty double z\n"
                                                           "end_header\n0 0 0\n");
  EXPECT_EQ(mesh_error(integer_y), "cannot read a polygon mesh from '" + integer_y + "' (malformed PLY header: the "
                                   "property 'y' of element 'vertices' has the type 'uint16', not float or double)");
  const std::string list_z = file_with("list_z.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                                     "property float y\nproperty list uchar float z\nend_header\n");
  EXPECT_EQ(mesh_error(list_z), "cannot read a polygon mesh from '" + list_z + "' (malformed PLY header: the "
                                "property 'z' of element 'vertex' has the type 'list', not float or double)");
  const std::string float32 = file_with("float32.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float32 x\n"
                                                       "property float32 y\nproperty float32 z\nelement face 1\n"
                                                       "property list uchar int vertex_indices\nend_header\n"
                                                       "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(read_mesh_file(float32).polygons.size(), 1u);
}

// fuzz_mesh: CGAL's PLY reader sized a list by the count the file gives (482 million in a
// 231-byte file: 1.9 GB); the body is walked first, in ASCII and in binary, and so are types.
TEST(MeshInput, PlyListCountBeyondTheFileIsRefused)
{
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n";
  const std::string huge = file_with("huge_list.ply", header + "0 0 0\n1 0 0\n0 1 0\n400000000 0 1 2\n");
  EXPECT_EQ(mesh_error(huge), "cannot read a polygon mesh from '" + huge + "' (malformed PLY: a list of '400000000' "
                              "entries, more than the rest of the file holds)");
  std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                       "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n";
  const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  binary.append(reinterpret_cast<const char*>(corners), sizeof corners);
  const std::string ok_binary = file_with("triangle.ply", binary + std::string("\x03\0\0\0\0\0\0\0\x01\0\0\0\x02\0\0\0", 16));
  EXPECT_EQ(read_mesh_file(ok_binary).polygons.size(), 1u); // a well-formed file still reads (little-endian host)
  const std::string huge_binary = file_with("huge_binary_list.ply", binary + std::string("\0\0\0\xb0\0\0\0\0", 8));
  EXPECT_EQ(mesh_error(huge_binary), "cannot read a polygon mesh from '" + huge_binary + "' (malformed PLY: a list of "
                                     "2952790016 entries, more than the rest of the file holds)");
  const std::string bad_type = file_with("bad_type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty dbl x\n"
                                                         "property float y\nproperty float z\nend_header\n0 0 0\n");
  EXPECT_EQ(mesh_error(bad_type), "cannot read a polygon mesh from '" + bad_type + "' (malformed PLY: the property "
                                  "type 'dbl' is not a PLY type)");
  // Without an end_header line CGAL still read a body, and a list count of 1.4 billion in it.
  const std::string no_end = file_with("no_end_header.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                                            "property float y\nproperty float z\n0 0 0\n");
  EXPECT_EQ(mesh_error(no_end), "cannot read a polygon mesh from '" + no_end + "' (malformed PLY header: no end_header line)");
}

// fuzz_mesh: CGAL's PLY reader took an element count of "-1.01" as 2^64 - 1 and looped over
// the items (a hang); counts must be whole numbers up to the file's size.
TEST(MeshInput, PlyElementCountThatIsNotAWholeNumberIsRefused)
{
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                             "property double z\nelement face ";
  const std::string body = "\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const std::string negative = file_with("negative_count.ply", header + "-1.01" + body);
  EXPECT_EQ(mesh_error(negative), "cannot read a polygon mesh from '" + negative + "' (malformed PLY header: element "
                                  "'face' has the count '-1.01', not a whole number up to the file's size)");
  const std::string huge = file_with("huge_count.ply", header + "99999999" + body);
  EXPECT_EQ(mesh_error(huge), "cannot read a polygon mesh from '" + huge + "' (malformed PLY header: element "
                              "'face' has the count '99999999', not a whole number up to the file's size)");
  EXPECT_EQ(read_mesh_file(file_with("one_face.ply", header + "1" + body)).polygons.size(), 1u);
}
