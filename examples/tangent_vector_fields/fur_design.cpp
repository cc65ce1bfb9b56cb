// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Designing a "fur" direction field from a handful of strokes, a source and a vortex
// with tangent vector field splines, in real time through the spectral basis, and
// comparing with the exact (full-resolution) spline.
//
// A stroke is a segment between two 3D points: the faces nearest to points along it
// get vector constraints along the stroke.  The source and the vortex are a
// divergence and a curl constraint at points of the surface.  The program times the
// edits a user makes (moving a stroke end, changing the vortex strength), compares the
// reduced spline with the full one, and writes both fields (PLY face properties) and
// the constraint set (JSON, readable by `read_constraint_file`).
//
// Usage: fur_design [mesh] [output-prefix] [number-of-eigenfields]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tangent_vector_fields/Soft_field_design.h>
#include <CGAL/Tangent_vector_fields/Spectral_basis.h>
#include <CGAL/Tangent_vector_fields/Vector_field_spline.h>
#include <CGAL/Tangent_vector_fields/constraint_file_io.h>
#include <CGAL/Tangent_vector_fields/face_field_io.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index Face_index;
namespace TVF = CGAL::Tangent_vector_fields;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

K::Point_3 centroid(const Mesh& mesh, Face_index f)
{
  double x = 0, y = 0, z = 0;
  for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
  {
    x += mesh.point(v).x() / 3;
    y += mesh.point(v).y() / 3;
    z += mesh.point(v).z() / 3;
  }
  return K::Point_3(x, y, z);
}

// The face whose centroid is nearest to p (a linear scan is plenty for an example).
Face_index nearest_face(const Mesh& mesh, const K::Point_3& p)
{
  Face_index best;
  double best_distance = std::numeric_limits<double>::infinity();
  for(Face_index f : mesh.faces())
  {
    const double d = CGAL::squared_distance(centroid(mesh, f), p);
    if(d < best_distance)
    {
      best_distance = d;
      best = f;
    }
  }
  return best;
}

struct Stroke
{
  K::Point_3 from, to;
};

// Vector constraints along a stroke: 4 samples, each pinning the stroke direction in
// the nearest face (distinct faces only).
std::vector<std::pair<Face_index, K::Vector_3>> stroke_constraints(const Mesh& mesh, const Stroke& s)
{
  std::vector<std::pair<Face_index, K::Vector_3>> out;
  const K::Vector_3 direction = (s.to - s.from) / std::sqrt((s.to - s.from).squared_length());
  for(int i = 0; i < 4; ++i)
  {
    const K::Point_3 p = s.from + (s.to - s.from) * ((i + 0.5) / 4);
    const Face_index f = nearest_face(mesh, p);
    if(std::none_of(out.begin(), out.end(), [&](const auto& c) { return c.first == f; })) out.emplace_back(f, direction);
  }
  return out;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : TVF_DEFAULT_MESH;
  const std::string prefix = argc > 2 ? argv[2] : "fur_design";
  const int eigenfields = argc > 3 ? std::atoi(argv[3]) : 400;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh, CGAL::parameters::verbose(false)) || is_empty(mesh))
  {
    std::cerr << "error: cannot read a polygon mesh from '" << input << "'\n";
    return 1;
  }
  std::cout << "mesh: " << input << ", " << mesh.number_of_faces() << " faces\n";
  try
  {
    // 1. The spectral basis: the expensive, one-off part.
    auto t = std::chrono::steady_clock::now();
    TVF::Spectral_basis<Mesh> basis(mesh, TVF::parameters::number_of_eigenfields(eigenfields));
    std::cout << "basis of " << basis.size() << " eigenfields: " << seconds_since(t) << " s\n";

    // 2. Strokes across the bounding box (the long axis, "combing" the fur), a source
    //    near one end and a vortex near the other.
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
    const double sx = box.xmax() - box.xmin(), sy = box.ymax() - box.ymin(), sz = box.zmax() - box.zmin();
    auto at = [&](double u, double v, double w) {
      return K::Point_3(box.xmin() + u * sx, box.ymin() + v * sy, box.zmin() + w * sz);
    };
    const std::vector<Stroke> strokes = {{at(0.2, 0.5, 0.9), at(0.8, 0.5, 0.9)},
                                         {at(0.3, 0.2, 0.5), at(0.7, 0.3, 0.5)},
                                         {at(0.3, 0.8, 0.5), at(0.7, 0.7, 0.5)}};
    const Face_index source_face = nearest_face(mesh, at(0.1, 0.5, 0.5));
    const Face_index vortex_face = nearest_face(mesh, at(0.9, 0.5, 0.3));
    const double strength = 20 / std::sqrt(CGAL::to_double(CGAL::Polygon_mesh_processing::area(mesh)));

    // 3. The reduced spline (on the basis) and the full one (on all 2 nf unknowns); each
    //    constraint is pulled back when added, so the set-up is timed with the solve.
    auto reduced_field = mesh.add_property_map<Face_index, K::Vector_3>("f:fur_reduced").first;
    auto full_field = mesh.add_property_map<Face_index, K::Vector_3>("f:fur_full").first;
    TVF::Vector_field_spline<Mesh> reduced(basis);
    TVF::Vector_field_spline<Mesh> full(mesh);
    std::vector<TVF::Constraint_id> stroke_ids;
    TVF::Constraint_id vortex_id = -1;
    double seconds[2];
    for(TVF::Vector_field_spline<Mesh>* spline : {&reduced, &full})
    {
      t = std::chrono::steady_clock::now();
      stroke_ids.clear();
      for(const Stroke& s : strokes)
        for(const auto& c : stroke_constraints(mesh, s)) stroke_ids.push_back(spline->add_vector(c.first, c.second));
      spline->add_divergence(source_face, centroid(mesh, source_face), strength);
      vortex_id = spline->add_curl(vortex_face, centroid(mesh, vortex_face), strength);
      spline->field(spline == &reduced ? reduced_field : full_field);
      seconds[spline == &reduced ? 0 : 1] = seconds_since(t);
    }
    std::cout << stroke_ids.size() << " stroke constraints, a source and a vortex\n";
    const double reduced_seconds = seconds[0], full_seconds = seconds[1];
    auto compare = [&]() {
      double difference = 0, norm = 0;
      std::vector<double> angles;
      for(Face_index f : mesh.faces())
      {
        const double area = CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(f, mesh));
        difference += area * (reduced_field[f] - full_field[f]).squared_length();
        norm += area * full_field[f].squared_length();
        const double c = reduced_field[f] * full_field[f], s = std::sqrt(CGAL::cross_product(reduced_field[f], full_field[f]).squared_length());
        angles.push_back(std::atan2(s, c) * 180 / M_PI);
      }
      std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
      std::printf("  reduced vs full: relative L2 error %.3g, median angle %.2f degrees\n", std::sqrt(difference / norm),
                  angles[angles.size() / 2]);
    };
    std::printf("set-up and solve: reduced %.2f ms, full %.3f s (factorisations included), fields written\n",
                1e3 * reduced_seconds, full_seconds);
    compare();
    std::printf("  constraint residual: reduced %.1e, full %.1e\n", reduced.report().constraint_residual,
                full.report().constraint_residual);
    for(const std::string& w : full.report().warnings) std::cout << "  note: " << w << "\n";

    // 4. Edits as in an editor: swing the first stroke's direction, change the vortex strength.
    const int edits = 100;
    t = std::chrono::steady_clock::now();
    for(int i = 0; i < edits; ++i)
    {
      const double angle = 0.02 * i;
      reduced.set_vector(stroke_ids[0], K::Vector_3(std::cos(angle), std::sin(angle), 0));
      reduced.set_value(vortex_id, strength * (1 + 0.01 * i));
      reduced.solver().report(); // solves (coefficients only)
    }
    const double edit_seconds = seconds_since(t) / edits;
    t = std::chrono::steady_clock::now();
    reduced.field(reduced_field);
    const double write_seconds = seconds_since(t);
    std::printf("edit (two constraint values changed, re-solved): %.3f ms; full field written: %.2f ms\n",
                1e3 * edit_seconds, 1e3 * write_seconds);
    t = std::chrono::steady_clock::now();
    full.set_vector(stroke_ids[0], K::Vector_3(std::cos(0.02 * (edits - 1)), std::sin(0.02 * (edits - 1)), 0));
    full.set_value(vortex_id, strength * (1 + 0.01 * (edits - 1)));
    full.field(full_field);
    std::printf("the same edit at full resolution: %.2f ms\n", 1e3 * seconds_since(t));
    compare();

    // 5. For comparison, soft constraints (Fisher et al. 2007): Dirichlet energy plus
    //    weighted misfits, in the same basis.  The constraints are then only approached.
    t = std::chrono::steady_clock::now();
    TVF::Reduced_soft_design soft(basis.shared_basis());
    for(TVF::Constraint_id id : reduced.solver().constraint_ids()) soft.add(reduced.solver().constraint(id), 100.0);
    const Eigen::VectorXd soft_field = soft.field();
    double misfit = 0, largest = 0;
    for(TVF::Constraint_id id : reduced.solver().constraint_ids())
      for(const TVF::Constraint_row& row : TVF::constraint_rows(soft.operators(), reduced.solver().constraint(id)))
      {
        misfit = std::max(misfit, std::abs(row.dot(soft_field) - row.value));
        largest = std::max(largest, std::abs(row.value));
      }
    std::printf("soft design (weight 100): %.2f ms, constraints missed by up to %.1f%% of the largest value\n",
                1e3 * seconds_since(t), 100 * misfit / largest);

    // 6. Files: both fields, and the constraints.
    TVF::add_face_field_properties(mesh, "fur_reduced", reduced_field);
    TVF::add_face_field_properties(mesh, "fur_full", full_field);
    std::ofstream ply(prefix + ".ply", std::ios::binary);
    CGAL::IO::write_PLY(ply, mesh);
    TVF::Constraint_file file;
    for(TVF::Constraint_id id : reduced.solver().constraint_ids()) file.constraints.push_back(reduced.solver().constraint(id));
    std::ofstream json(prefix + ".json");
    TVF::write_constraint_file(json, file, reduced.solver().operators().mesh());
    std::cout << "wrote " << prefix << ".ply (face properties fur_reduced_*, fur_full_*) and " << prefix
              << ".json (the constraints)\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
