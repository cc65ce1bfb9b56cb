// Copyright (c) 2026 The Projective_dynamics authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Saving and loading the precomputation of a Reduced_simulator (.pdr).

#include "reduced_simulator_impl.h"

namespace CGAL {
namespace Projective_dynamics {

// The precomputation file (.pdr), in the shared binary format (binary_file.h):
//   header (magic "PDREDUCE", version, byte order, the model's identity: connectivity = its
//     vertex count and every row's vertices of S; geometry = the element measures' sum and
//     the element graph's edge lengths)
//   4 doubles   position signature of the rest positions
//   int32       groups; per group: int32 type, int64 elements, uint64 hash of its constants
//   the shaping reduction options: uint8 explicit basis, int32 samples, double radius
//     multiplier, uint8 hyper, int32 constraint samples, double constraint radius multiplier,
//     int32 l, int32 s
//   U: int64 rows, cols; ints (int64 count, int32 each) row starts, columns; values (matrix)
//   ints        samples
//   per group   L (k x k)
//   hyper: per group ints sampled elements, J V (sampled rows x l), F (k x l)
//   magic       end marker
namespace {

namespace MRI = Model_reduction::internal;

const char file_magic[8] = {'P', 'D', 'R', 'E', 'D', 'U', 'C', 'E'};
const std::uint32_t file_version = 1;
const char* const file_what = "reduced simulator";

MRI::Mesh_identity model_identity(const Elastic_model& model)
{
  MRI::Mesh_identity id;
  MRI::Hasher h;
  const Sparse& S = model.selection_matrix();
  h.add(std::int64_t(model.number_of_vertices()));
  h.add(std::int64_t(S.rows()));
  for(Eigen::Index i = 0; i < S.rows(); ++i)
  {
    h.add(std::int64_t(-1)); // row separator
    for(Sparse::InnerIterator it(S, i); it; ++it) h.add(std::int64_t(it.col()));
  }
  id.connectivity = h.h;
  double total = 0;
  for(const Element& el : model.elements()) total += el.measure;
  const internal::Element_graph g = internal::element_graph(model);
  id.geometry = MRI::geometry_signature(total, g.lengths);
  return id;
}

Eigen::VectorXd stacked(const Positions& x)
{
  Eigen::VectorXd v(x.size());
  for(Eigen::Index i = 0; i < x.rows(); ++i) v.segment<3>(3 * i) = x.row(i).transpose();
  return v;
}

struct Group_description
{
  std::int32_t type = 0;
  std::int64_t elements = 0;
  std::uint64_t constants = 0; // the elements' constraint sets and measures
};

std::vector<Group_description> group_descriptions(const Elastic_model& model)
{
  std::vector<Group_description> d(std::size_t(model.number_of_groups()));
  std::vector<MRI::Hasher> h(d.size());
  for(int g = 0; g < model.number_of_groups(); ++g) d[std::size_t(g)].type = std::int32_t(model.group_type(g));
  for(const Element& el : model.elements())
  {
    Group_description& gd = d[std::size_t(el.group)];
    ++gd.elements;
    MRI::Hasher& hg = h[std::size_t(el.group)];
    hg.add(std::int32_t(el.rows));
    for(double x : {el.min_value, el.max_value, el.fallback[0], el.fallback[1], el.fallback[2]}) hg.add(x);
  }
  for(std::size_t g = 0; g < d.size(); ++g) d[g].constants = h[g].h;
  return d;
}

const char* type_name(std::int32_t t)
{
  switch(t)
  {
  case std::int32_t(Element_type::spring): return "springs";
  case std::int32_t(Element_type::triangle_strain): return "triangle strain";
  case std::int32_t(Element_type::tet_strain): return "tetrahedron strain";
  case std::int32_t(Element_type::bending): return "bending";
  default: return "of an unknown type";
  }
}

void write_ints(std::ostream& out, const int* v, std::size_t count)
{
  MRI::write_value<std::int64_t>(out, std::int64_t(count));
  for(std::size_t q = 0; q < count; ++q) MRI::write_value<std::int32_t>(out, v[q]);
}
void write_ints(std::ostream& out, const std::vector<int>& v) { write_ints(out, v.data(), v.size()); }

std::vector<int> read_ints(MRI::Binary_reader& r, std::uint64_t most, const char* name)
{
  const std::int64_t count = r.value<std::int64_t>();
  if(count < 0 || std::uint64_t(count) > most) r.fail(std::string("the file is corrupt (the count of ") + name + ")");
  std::vector<int> v(static_cast<std::size_t>(count));
  for(int& x : v) x = r.value<std::int32_t>();
  return v;
}

// The shortest of 15 or 17 digits that reads back as x.
std::string number(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.15g", x);
  if(std::strtod(buffer, nullptr) != x) std::snprintf(buffer, sizeof(buffer), "%.17g", x);
  return buffer;
}

} // namespace

void Reduced_simulator::save(const std::string& path) const
{
  const Impl& I = *impl_;
  std::ofstream out(path, std::ios::binary);
  if(!out) throw Invalid_input("cannot write the reduced simulator to '" + path + "'");
  MRI::write_header(out, file_magic, file_version, model_identity(I.model));
  for(double x : MRI::position_signature(stacked(I.model.rest_positions()))) MRI::write_value(out, x);
  const std::vector<Group_description> groups = group_descriptions(I.model);
  MRI::write_value<std::int32_t>(out, std::int32_t(groups.size()));
  for(const Group_description& g : groups)
  {
    MRI::write_value(out, g.type);
    MRI::write_value(out, g.elements);
    MRI::write_value(out, g.constants);
  }
  MRI::write_value<std::uint8_t>(out, I.samples.empty() ? 1 : 0);
  MRI::write_value<std::int32_t>(out, I.r.samples);
  MRI::write_value(out, I.r.radius_multiplier);
  MRI::write_value<std::uint8_t>(out, I.r.hyper_reduction ? 1 : 0);
  MRI::write_value<std::int32_t>(out, I.r.constraint_samples);
  MRI::write_value(out, I.r.constraint_radius_multiplier);
  MRI::write_value<std::int32_t>(out, I.r.projection_columns);
  MRI::write_value<std::int32_t>(out, I.r.sampled_elements);
  Sparse U = I.U;
  U.makeCompressed();
  MRI::write_value<std::int64_t>(out, U.rows());
  MRI::write_value<std::int64_t>(out, U.cols());
  write_ints(out, U.outerIndexPtr(), std::size_t(U.rows()) + 1);
  write_ints(out, U.innerIndexPtr(), std::size_t(U.nonZeros()));
  MRI::write_matrix(out, Eigen::Map<const Eigen::VectorXd>(U.valuePtr(), U.nonZeros()));
  write_ints(out, I.samples);
  for(const internal::Reduced_group& G : I.groups) MRI::write_matrix(out, G.L);
  if(I.r.hyper_reduction)
    for(const internal::Reduced_group& G : I.groups)
    {
      write_ints(out, G.sampled);
      MRI::write_matrix(out, G.JV);
      MRI::write_matrix(out, G.F);
    }
  MRI::write_value(out, file_magic);
  if(!out) throw Invalid_input("writing the reduced simulator to '" + path + "' failed");
}

Reduced_simulator Reduced_simulator::load(Elastic_model model, const std::string& path, const Simulator_options& options,
                                          const Reduction_options& reduction)
{
  check_options(options);
  const int n = model.number_of_vertices();
  std::uint64_t bytes = 0;
  std::ifstream in = MRI::open_binary_file(path, file_what, bytes);
  MRI::Binary_reader r(in, path, bytes, file_what);
  r.expect_header(file_magic, file_version, model_identity(model));
  const std::array<double, 4> here = MRI::position_signature(stacked(model.rest_positions()));
  for(int q = 0; q < 4; ++q)
  {
    // Equal to rounding for the same positions (see modes_file.cpp); the basis holds the rest
    // coordinates, so a moved or turned model needs its own.
    const double stored = r.value<double>();
    if(!(std::abs(stored - here[std::size_t(q)]) <= 1e-9 * here[3]))
      r.fail("its rest positions are elsewhere (the model was moved or turned: the basis holds the rest coordinates)");
  }
  const std::vector<Group_description> groups = group_descriptions(model);
  const std::int32_t group_count = r.value<std::int32_t>();
  if(group_count != std::int32_t(groups.size()))
    r.fail("made for " + std::to_string(group_count) + " element groups, the model has " + std::to_string(groups.size()));
  for(std::size_t g = 0; g < groups.size(); ++g)
  {
    Group_description d;
    d.type = r.value<std::int32_t>();
    d.elements = r.value<std::int64_t>();
    d.constants = r.value<std::uint64_t>();
    const std::string which = "element group " + std::to_string(g);
    if(d.type != groups[g].type)
      r.fail(which + " is " + type_name(d.type) + " in the file, " + type_name(groups[g].type) + " in the model");
    if(d.elements != groups[g].elements)
      r.fail(which + " has " + std::to_string(d.elements) + " elements in the file, " + std::to_string(groups[g].elements) +
             " in the model");
    if(d.constants != groups[g].constants)
      r.fail(which + " has other constraint sets (strain limits or rest constants) in the file");
  }
  const bool explicit_basis = r.value<std::uint8_t>() != 0;
  Reduction_options stored;
  stored.samples = r.value<std::int32_t>();
  stored.radius_multiplier = r.value<double>();
  stored.hyper_reduction = r.value<std::uint8_t>() != 0;
  stored.constraint_samples = r.value<std::int32_t>();
  stored.constraint_radius_multiplier = r.value<double>();
  stored.projection_columns = r.value<std::int32_t>();
  stored.sampled_elements = r.value<std::int32_t>();
  {
    auto differ = [&](const char* name, const std::string& in_file, const std::string& given) {
      r.fail(std::string("made with other reduction options: ") + name + " " + in_file + " in the file, " + given + " given");
    };
    if(stored.hyper_reduction != reduction.hyper_reduction)
      differ("hyper_reduction", stored.hyper_reduction ? "true" : "false", reduction.hyper_reduction ? "true" : "false");
    if(!explicit_basis)
    {
      if(stored.samples != reduction.samples)
        differ("number_of_samples", std::to_string(stored.samples), std::to_string(reduction.samples));
      if(stored.radius_multiplier != reduction.radius_multiplier)
        differ("radius_multiplier", number(stored.radius_multiplier), number(reduction.radius_multiplier));
    }
    if(stored.hyper_reduction)
    {
      if(stored.constraint_samples != reduction.constraint_samples)
        differ("number_of_constraint_samples", std::to_string(stored.constraint_samples), std::to_string(reduction.constraint_samples));
      if(stored.constraint_radius_multiplier != reduction.constraint_radius_multiplier)
        differ("constraint_radius_multiplier", number(stored.constraint_radius_multiplier),
               number(reduction.constraint_radius_multiplier));
      if(stored.projection_columns != reduction.projection_columns)
        differ("number_of_projection_columns", std::to_string(stored.projection_columns), std::to_string(reduction.projection_columns));
      if(stored.sampled_elements != reduction.sampled_elements)
        differ("number_of_sampled_elements", std::to_string(stored.sampled_elements), std::to_string(reduction.sampled_elements));
    }
  }
  Reduction_options checked = reduction;
  if(explicit_basis) checked.samples = 1;
  check_reduction(checked, n);

  Reduced_simulator sim;
  sim.impl_ = std::make_unique<Impl>(std::move(model), options, reduction);
  Impl& I = *sim.impl_;
  const auto start = Clock::now();
  // U, checked entry by entry (a corrupt index must not reach Eigen).
  const std::int64_t rows = r.value<std::int64_t>(), cols = r.value<std::int64_t>();
  if(rows != n) r.fail("the basis has " + std::to_string(rows) + " rows for " + std::to_string(n) + " vertices");
  if(cols < 1 || cols > std::int64_t(4) * n || (!explicit_basis && cols != 4 * std::int64_t(reduction.samples)))
    r.fail("the file is corrupt (the basis has " + std::to_string(cols) + " columns)");
  const std::vector<int> outer = read_ints(r, std::uint64_t(n) + 1, "basis rows");
  if(outer.size() != std::size_t(n) + 1 || outer.front() != 0) r.fail("the file is corrupt (the basis rows)");
  for(int i = 0; i < n; ++i)
    if(outer[std::size_t(i) + 1] < outer[std::size_t(i)]) r.fail("the file is corrupt (the basis rows)");
  const std::vector<int> inner = read_ints(r, bytes / 4, "basis entries");
  if(inner.size() != std::size_t(outer.back())) r.fail("the file is corrupt (the basis entries)");
  for(int i = 0; i < n; ++i)
    for(int q = outer[std::size_t(i)]; q < outer[std::size_t(i) + 1]; ++q)
      if(inner[std::size_t(q)] < 0 || inner[std::size_t(q)] >= cols ||
         (q > outer[std::size_t(i)] && inner[std::size_t(q)] <= inner[std::size_t(q) - 1]))
        r.fail("the file is corrupt (a basis column index)");
  const Eigen::MatrixXd values = r.matrix(Eigen::Index(inner.size()), 1, "basis values");
  if(!values.allFinite()) r.fail("the file holds non-finite numbers (the basis)");
  I.U = Eigen::Map<const Sparse>(n, Eigen::Index(cols), Eigen::Index(inner.size()), outer.data(), inner.data(), values.data());
  I.samples = read_ints(r, std::uint64_t(n), "samples");
  if(explicit_basis ? !I.samples.empty() : I.samples.size() != std::size_t(reduction.samples))
    r.fail("the file is corrupt (the number of samples)");
  for(int v : I.samples)
    if(v < 0 || v >= n) r.fail("the file is corrupt (a sample outside the mesh)");
  Eigen::MatrixXd rest;
  if(!explicit_basis) rest = Position_subspace{I.U, I.samples}.rest_coordinates();
  try
  {
    I.prepare_masses(explicit_basis ? nullptr : &rest);
  }
  catch(const Numerical_failure& e)
  {
    r.fail(std::string("the file is corrupt (") + e.what() + ")");
  }
  const std::vector<std::vector<int>> members = I.group_layout();
  const Eigen::Index k = I.U.cols();
  for(internal::Reduced_group& G : I.groups)
  {
    G.L = r.matrix(k, k, "projected matrices");
    if(!G.L.allFinite()) r.fail("the file holds non-finite numbers (a projected matrix)");
  }
  if(reduction.hyper_reduction)
  {
    const auto& elements = I.model.elements();
    for(std::size_t g = 0; g < I.groups.size(); ++g)
    {
      internal::Reduced_group& G = I.groups[g];
      G.sampled = read_ints(r, members[g].size(), "sampled elements");
      if(G.sampled.size() != std::min(members[g].size(), std::size_t(reduction.sampled_elements)))
        r.fail("the file is corrupt (the number of sampled elements of group " + std::to_string(g) + ")");
      int sampled_rows = 0;
      for(std::size_t q = 0; q < G.sampled.size(); ++q)
      {
        const int e = G.sampled[q];
        if(e < 0 || e >= I.model.number_of_elements() || elements[std::size_t(e)].group != int(g) ||
           (q > 0 && e <= G.sampled[q - 1]))
          r.fail("the file is corrupt (a sampled element of group " + std::to_string(g) + ")");
        sampled_rows += elements[std::size_t(e)].rows;
      }
      const Eigen::Index l = members[g].empty() ? -1 : reduction.projection_columns;
      G.JV = r.matrix(members[g].empty() ? 0 : sampled_rows, l, "projection subspace rows");
      G.F = r.matrix(members[g].empty() ? 0 : k, l, "projected subspace matrices F");
      if(!G.JV.allFinite() || !G.F.allFinite()) r.fail("the file holds non-finite numbers (a projection subspace)");
    }
    internal::Hyper_sampling h;
    try
    {
      h = internal::finish_sampling(I.model, I.U, I.groups);
    }
    catch(const Numerical_failure& e)
    {
      r.fail(std::string("the file is corrupt (") + e.what() + ")");
    }
    I.used = std::move(h.used), I.sampled_all = std::move(h.sampled_all), I.sampled_row = std::move(h.sampled_row);
    I.S_used = std::move(h.S_used), I.U_used = std::move(h.U_used);
  }
  r.expect_magic(file_magic, "the file is corrupt (no end marker)");
  I.default_collision();
  I.timings.precomputation = seconds_since(start);
  return sim;
}

} // namespace Projective_dynamics
} // namespace CGAL
