// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The outcome on every mesh file of CGAL's data tree, read through
// Model_reduction::polygon_soup_to_mesh and decomposed, against a golden table
// (robustness/cgal_data_tree.golden).

#include "hodge_checks.h"
#include "test_meshes.h"

#include <CGAL/Tangent_vector_fields/hodge_decomposition.h>
#include <CGAL/Model_reduction/polygon_soup_to_mesh.h>

#include <CGAL/IO/polygon_soup_io.h>

#include <gtest/gtest.h>

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

namespace TVF = CGAL::Tangent_vector_fields;
namespace MR = CGAL::Model_reduction;
using namespace tvf_test;

// --- CGAL's data tree: a golden table of outcomes -------------------------------------------

namespace {

// Every .off, .obj, .ply and .stl file under `dir`, as paths relative to it, sorted.
std::vector<std::string> mesh_files(const std::string& dir)
{
  std::vector<std::string> files;
  std::function<void(const std::string&)> walk = [&](const std::string& relative) {
    DIR* handle = opendir((dir + "/" + relative).c_str());
    if(!handle) return;
    while(dirent* entry = readdir(handle))
    {
      const std::string name = entry->d_name;
      if(name == "." || name == "..") continue;
      const std::string path = relative.empty() ? name : relative + "/" + name;
      struct stat info;
      if(stat((dir + "/" + path).c_str(), &info) != 0) continue;
      const std::string ext = name.substr(name.find_last_of('.') + 1);
      if(S_ISDIR(info.st_mode))
        walk(path);
      else if(ext == "off" || ext == "obj" || ext == "ply" || ext == "stl")
        files.push_back(path);
    }
    closedir(handle);
  };
  walk("");
  std::sort(files.begin(), files.end());
  return files;
}

const char* defect_name(TVF::Mesh_defect d)
{
  static const char* names[] = {"empty",          "non-triangle-face", "non-manifold-edge",
                                "non-manifold-vertex", "inconsistent-orientation", "garbage",
                                "invalid-index",  "non-finite-coordinate", "degenerate-face"};
  return names[static_cast<int>(d)];
}

// The repairs in one word: "-" for none, else e.g. "triangulated=6:12,reoriented=3".
std::string repair_tags(const MR::Mesh_repair_report& r)
{
  std::string s;
  auto add = [&s](const std::string& tag, std::size_t n, std::size_t m = 0) {
    if(n == 0) return;
    s += (s.empty() ? "" : ",") + tag + "=" + std::to_string(n) + (m ? ":" + std::to_string(m) : "");
  };
  add("simplified", r.simplified_polygons);
  add("split", r.split_polygons);
  add("degenerate", r.removed_degenerate_polygons);
  add("duplicates", r.removed_duplicate_polygons);
  add("triangulated", r.triangulated_polygons, r.triangles_from_polygons);
  add("reoriented", r.reoriented_polygons);
  add("edges", r.non_manifold_edges);
  add("vertices", r.duplicated_vertices);
  return s.empty() ? "-" : s;
}

// One row of the table: "<outcome> <faces> <harmonic dimension> <repairs>".
std::string outcome_of(const std::string& path)
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
    return "refused:unreadable 0 - -";
  Mesh mesh;
  MR::Mesh_repair_report report;
  try
  {
    report = MR::polygon_soup_to_mesh(points, polygons, mesh);
  }
  catch(const TVF::Invalid_mesh& e)
  {
    return std::string("refused:") + defect_name(e.defect()) + " 0 - -";
  }
  const std::string faces = std::to_string(mesh.number_of_faces()), tags = repair_tags(report);
  for(bool mollify : {false, true})
  {
    try
    {
      TVF::Hodge_decomposition<Mesh> hodge(mesh, TVF::parameters::use_intrinsic_mollification(mollify));
      const TVF::Hodge_solver& solver = hodge.solver();
      // Each part checked for what it claims through the operators (hodge_checks.h); a part
      // may be empty only where the mesh has no room for it (no divergence or curl at all).
      const Hodge_check check = check_hodge_parts(solver, random_field(int(mesh.number_of_faces()), 7));
      EXPECT_LT(check.worst(), 1e-8) << check.report();
      if(check.input_has_divergence) EXPECT_GT(check.exact_share, 0.05) << check.report();
      if(check.input_has_curl) EXPECT_GT(check.coexact_share, 0.05) << check.report();
      if(check.harmonic_dimension > 0)
        EXPECT_GT(check.harmonic_share, 0.01 * std::sqrt(double(check.harmonic_dimension) / check.field_size))
            << check.report();
      EXPECT_TRUE(solver.harmonic_basis().allFinite());
      // The numerical rank of the harmonic basis against the topology's 2g + b - 1 per component.
      const int dimension = int(solver.harmonic_basis().cols());
      EXPECT_EQ(dimension, hodge.topology().harmonic_dimension()) << hodge.topology().summary();
      return std::string(mollify ? "mollified " : "processed ") + faces + " " + std::to_string(dimension) + " " + tags;
    }
    catch(const TVF::Invalid_mesh& e)
    {
      if(e.defect() != TVF::Mesh_defect::degenerate_face || mollify)
        return std::string("refused:") + defect_name(e.defect()) + " " + faces + " - " + tags;
    }
    catch(const TVF::Numerical_failure& e)
    {
      ADD_FAILURE() << "a mesh the checks accepted failed numerically: " << e.what();
      return "failed " + faces + " - " + tags;
    }
  }
  return "unreachable";
}

} // namespace

TEST(DataTree, GoldenTable)
{
  const std::string dir = cgal_data_dir();
  if(dir.empty()) GTEST_SKIP() << cgal_data_missing();
  const std::vector<std::string> files = mesh_files(dir);
  ASSERT_GT(files.size(), 100u);

  std::map<std::string, std::string> golden;
  std::ifstream table(TVF_GOLDEN_TABLE);
  ASSERT_TRUE(table) << "cannot read " << TVF_GOLDEN_TABLE;
  for(std::string line; std::getline(table, line);)
  {
    if(line.empty() || line[0] == '#') continue;
    const std::size_t space = line.find(' ');
    golden[line.substr(0, space)] = line.substr(line.find_first_not_of(' ', space));
  }

  // TVF_WRITE_GOLDEN=<file>: write the table found here (to review and commit after a change).
  const char* write_to = std::getenv("TVF_WRITE_GOLDEN");
  std::ofstream out;
  if(write_to) out.open(write_to);
  std::map<std::string, int> tally;
  for(const std::string& name : files)
  {
    SCOPED_TRACE(name);
    const std::string outcome = outcome_of(dir + "/" + name);
    ++tally[outcome.substr(0, outcome.find(' '))];
    if(out) out << name << ' ' << outcome << '\n';
    const auto expected = golden.find(name);
    if(expected == golden.end())
      ADD_FAILURE() << name << ": not in the golden table (" << outcome << ")";
    else
      EXPECT_EQ(expected->second, outcome) << name << ": the outcome changed";
  }
  for(const auto& [name, row] : golden)
    if(!std::binary_search(files.begin(), files.end(), name))
      ADD_FAILURE() << name << ": in the golden table but not in the data tree";
  std::cout << "Data tree tally: " << files.size() << " files";
  for(const auto& [outcome, count] : tally) std::cout << ", " << count << " " << outcome;
  std::cout << std::endl;
}
