// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "frame_writer.h"

#include "tool.h"

#include <CGAL/Model_reduction/Vtk_polydata.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace tvf_tool {

Frame_writer::Frame_writer(std::string folder, std::string format, std::vector<std::array<int, 3>> surface,
                           double time_step)
  : folder_(std::move(folder)), format_(std::move(format)), surface_(std::move(surface)), time_step_(time_step)
{
  if(folder_.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(folder_, error);
  if(error) throw Tool_error("cannot make the folder '" + folder_ + "': " + error.message());
}

bool Frame_writer::known_format(const std::string& format)
{
  return format == "obj" || format == "ply" || format == "vtp";
}

void Frame_writer::write(int frame, const Positions& q)
{
  if(folder_.empty()) return;
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.%s", frame, format_.c_str());
  const std::string path = folder_ + "/" + name;
  std::ofstream out(path);
  if(!out) throw Tool_error("cannot open '" + path + "' for writing");
  MR::internal::prepare_exact_output(out); // every bit: pinned vertices read back at rest exactly
  if(format_ == "obj")
  {
    for(Eigen::Index v = 0; v < q.rows(); ++v) out << "v " << q(v, 0) << ' ' << q(v, 1) << ' ' << q(v, 2) << '\n';
    for(const auto& t : surface_) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
  else if(format_ == "ply")
  {
    out << "ply\nformat ascii 1.0\nelement vertex " << q.rows()
        << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << surface_.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for(Eigen::Index v = 0; v < q.rows(); ++v) out << q(v, 0) << ' ' << q(v, 1) << ' ' << q(v, 2) << '\n';
    for(const auto& t : surface_) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  }
  else
  {
    MR::Vtk_polydata data;
    data.points.resize(std::size_t(q.rows()));
    for(Eigen::Index v = 0; v < q.rows(); ++v) data.points[std::size_t(v)] = {q(v, 0), q(v, 1), q(v, 2)};
    for(const auto& t : surface_) data.polygons.push_back({t[0], t[1], t[2]});
    MR::write_vtk_polydata(out, data);
  }
  out.close();
  if(!out) throw Tool_error("writing '" + path + "' failed");
  names_.push_back(name);
}

std::string Frame_writer::finish() const
{
  if(names_.empty()) return std::string();
  const std::string written = "wrote " + std::to_string(names_.size()) + " frames to " + folder_;
  if(format_ != "vtp") return written;
  const std::string path = folder_ + "/frames.pvd";
  std::ofstream out(path);
  MR::internal::prepare_exact_output(out);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for(std::size_t i = 0; i < names_.size(); ++i)
    out << "    <DataSet timestep=\"" << double(i) * time_step_ << "\" file=\"" << names_[i] << "\"/>\n";
  out << "  </Collection>\n</VTKFile>\n";
  out.close();
  if(!out) throw Tool_error("writing '" + path + "' failed");
  return written + ", series " + path;
}

} // namespace tvf_tool
