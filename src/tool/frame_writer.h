// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Frame sequences of a moving triangle mesh, one file per frame (OBJ, PLY or VTP, the VTP
// frames with a ParaView .pvd series): what `tvf simulate` and `tvf vibrate` write.

#ifndef TVF_TOOL_FRAME_WRITER_H
#define TVF_TOOL_FRAME_WRITER_H

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace tvf_tool {

class Frame_writer
{
public:
  typedef Eigen::Matrix<double, Eigen::Dynamic, 3> Positions;
  /// An empty `folder` writes nothing.  \throws Tool_error if the folder cannot be made.
  Frame_writer(std::string folder, std::string format, std::vector<std::array<int, 3>> surface, double time_step);
  /// True for "obj", "ply" and "vtp".
  static bool known_format(const std::string& format);
  /// Writes frame_NNNN.<format>.  \throws Tool_error naming the file.
  void write(int frame, const Positions& q);
  /// Writes the ParaView series frames.pvd (VTP frames only); returns what was written, as
  /// "wrote N frames to FOLDER[, series PATH]" ("" if no frame was).
  std::string finish() const;
  std::size_t count() const { return names_.size(); }

private:
  std::string folder_, format_;
  std::vector<std::array<int, 3>> surface_;
  double time_step_;
  std::vector<std::string> names_;
};

} // namespace tvf_tool

#endif
