// Copyright (c) 2026 The Spline_approximation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The BVH reader and writer.  The reader works on white-space separated words that remember
// their line and column, so every refusal can point at the word that caused it.

#include <CGAL/Spline_approximation/Bvh_motion.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <istream>
#include <iterator>
#include <ostream>
#include <sstream>

namespace CGAL {
namespace Spline_approximation {
namespace {

struct Word
{
  std::string text;
  std::size_t line = 0, column = 0;
};

bool same_text(const std::string& a, const char* b) // keywords and channel names ignore case
{
  const std::size_t n = std::strlen(b);
  if(a.size() != n) return false;
  for(std::size_t i = 0; i < n; ++i)
    if(std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

class Bvh_reader
{
public:
  Bvh_reader(std::istream& in, const std::string& name) : name_(name)
  {
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::size_t line = 1, column = 1;
    for(std::size_t i = 0; i < text.size();) {
      const char c = text[i];
      if(c == '\n') { ++line; column = 1; ++i; continue; }
      if(std::isspace(static_cast<unsigned char>(c))) { ++column; ++i; continue; }
      Word w;
      w.line = line;
      w.column = column;
      while(i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) { w.text += text[i++]; ++column; }
      words_.push_back(std::move(w));
    }
    end_line_ = line;
  }

  Bvh_motion read()
  {
    Bvh_motion m;
    expect("HIERARCHY", "a BVH file starts with HIERARCHY");
    if(!at_keyword("ROOT")) fail(peek_or_end(), "expected ROOT after HIERARCHY, found " + describe(peek_or_end()));
    while(at_keyword("ROOT")) {
      next();
      read_joint(m, -1);
    }
    if(!at_keyword("MOTION")) fail(peek_or_end(), "expected JOINT, ROOT or MOTION, found " + describe(peek_or_end()));
    next();
    expect("Frames:", "the motion starts with 'Frames: N'");
    const Word frames_word = peek_or_end();
    const double count = number(next_or_end("the number of frames"));
    if(count < 0 || count != std::floor(count) || count > 1e9)
      fail(frames_word, "the number of frames must be a whole number >= 0, not '" + frames_word.text + "'");
    expect("Frame", "'Frame Time: T' follows the number of frames");
    expect("Time:", "'Frame Time: T' follows the number of frames");
    const Word time_word = peek_or_end();
    m.frame_time = number(next_or_end("the frame time"));
    if(!(m.frame_time > 0)) fail(time_word, "the frame time must be > 0 seconds, not '" + time_word.text + "'");
    read_frames(m, Eigen::Index(count), frames_word);
    return m;
  }

private:
  [[noreturn]] void fail(const Word& w, const std::string& reason) const
  {
    throw Invalid_input("BVH '" + name_ + "' line " + std::to_string(w.line) + ", column " + std::to_string(w.column) +
                        ": " + reason);
  }
  Word end_word() const { Word w; w.text = ""; w.line = end_line_; w.column = 1; return w; }
  Word peek_or_end() const { return pos_ < words_.size() ? words_[pos_] : end_word(); }
  static std::string describe(const Word& w) { return w.text.empty() ? "the end of the file" : "'" + w.text + "'"; }
  bool at_keyword(const char* k) const { return pos_ < words_.size() && same_text(words_[pos_].text, k); }
  Word next() { return words_[pos_++]; }
  Word next_or_end(const std::string& what)
  {
    if(pos_ >= words_.size()) fail(end_word(), "the file ends where " + what + " should be");
    return next();
  }
  void expect(const char* keyword, const std::string& why)
  {
    if(!at_keyword(keyword))
      fail(peek_or_end(), std::string("expected '") + keyword + "', found " + describe(peek_or_end()) + " (" + why + ")");
    next();
  }
  double number(const Word& w) const
  {
    const char* begin = w.text.c_str();
    char* end = nullptr;
    const double x = std::strtod(begin, &end);
    if(end == begin || *end != '\0') fail(w, "'" + w.text + "' is not a number");
    // "nan", "inf" and overflowing values (strtod gives infinity) are numbers strtod reads, not data.
    if(!std::isfinite(x)) fail(w, "'" + w.text + "' is not a finite number");
    return x;
  }

  // After ROOT or JOINT (or End Site when `end_site`): name, '{', OFFSET, CHANNELS, children, '}'.
  void read_joint(Bvh_motion& m, int parent, bool end_site = false, int depth = 0)
  {
    if(depth > max_depth) // real skeletons are a few dozen deep; a hostile file must not exhaust the stack
      fail(words_[pos_ - 1], "joints nested deeper than " + std::to_string(max_depth) + " levels");
    Bvh_joint joint;
    joint.parent = parent;
    joint.end_site = end_site;
    if(!end_site) { // the name: the rest of its line (names may hold spaces), without a trailing '{'
      const Word& keyword = words_[pos_ - 1];
      while(pos_ < words_.size() && words_[pos_].line == keyword.line && words_[pos_].text != "{")
        joint.name += (joint.name.empty() ? "" : " ") + next().text;
      if(joint.name.empty()) fail(peek_or_end(), "a joint needs a name after " + keyword.text);
    }
    if(!(pos_ < words_.size() && words_[pos_].text == "{"))
      fail(peek_or_end(), "expected '{' to open " + (end_site ? std::string("the End Site") : "joint '" + joint.name + "'") +
                              ", found " + describe(peek_or_end()));
    next();
    expect("OFFSET", "every joint and End Site gives its OFFSET first");
    for(int k = 0; k < 3; ++k) joint.offset[k] = number(next_or_end("an offset coordinate"));
    joint.first_channel = m.number_of_channels();
    if(!end_site && at_keyword("CHANNELS")) read_channels(joint);
    const int index = int(m.joints.size());
    m.joints.push_back(joint);
    while(true) {
      if(pos_ < words_.size() && words_[pos_].text == "}") { next(); return; }
      if(!end_site && at_keyword("JOINT")) { next(); read_joint(m, index, false, depth + 1); continue; }
      if(!end_site && at_keyword("End")) {
        next();
        expect("Site", "'End Site'");
        read_joint(m, index, true, depth + 1);
        continue;
      }
      fail(peek_or_end(), "expected " + std::string(end_site ? "'}' to close the End Site" : "JOINT, End Site or '}' in joint '" +
                                                                   joint.name + "'") + ", found " + describe(peek_or_end()));
    }
  }

  void read_channels(Bvh_joint& joint)
  {
    next(); // CHANNELS
    const Word count_word = next_or_end("the channel count");
    const double count = number(count_word);
    if(count < 0 || count > 6 || count != std::floor(count))
      fail(count_word, "a joint has 0 to 6 channels, not '" + count_word.text + "'");
    for(int i = 0; i < int(count); ++i) {
      const Word w = next_or_end("a channel name");
      static const char* names[] = {"Xposition", "Yposition", "Zposition", "Xrotation", "Yrotation", "Zrotation"};
      int found = -1;
      for(int c = 0; c < 6; ++c)
        if(same_text(w.text, names[c])) found = c;
      if(found < 0)
        fail(w, "unknown channel '" + w.text + "' (joint '" + joint.name + "' declares " + count_word.text +
                    " channels; the names are Xposition, Yposition, Zposition, Xrotation, Yrotation, Zrotation)");
      for(Bvh_channel c : joint.channels)
        if(int(c) == found) fail(w, "channel '" + w.text + "' is listed twice in joint '" + joint.name + "'");
      joint.channels.push_back(Bvh_channel(found));
    }
  }

  // One frame per line, every channel's value on it.  The values are gathered before the matrix is
  // made: a declared count is not trusted with memory before the lines are there.
  void read_frames(Bvh_motion& m, Eigen::Index count, const Word& frames_word)
  {
    const std::size_t channels = m.number_of_channels();
    std::vector<double> values;
    values.reserve(std::min(std::size_t(count) * channels, words_.size() - pos_));
    Eigen::Index f = 0;
    while(pos_ < words_.size()) {
      const std::size_t line = words_[pos_].line;
      if(f == count)
        fail(words_[pos_], "more frame lines than the " + std::to_string(count) + " frames declared on line " +
                               std::to_string(frames_word.line));
      std::size_t c = 0;
      for(; pos_ < words_.size() && words_[pos_].line == line; ++c) {
        const Word w = next();
        if(c >= channels)
          fail(w, "frame " + std::to_string(f + 1) + " has more than the " + std::to_string(channels) +
                      " values of the skeleton's channels");
        values.push_back(number(w));
      }
      if(c < channels) {
        Word at = words_[pos_ - 1];
        at.column += at.text.size();
        fail(at, "frame " + std::to_string(f + 1) + " has " + std::to_string(c) + " values; the skeleton has " +
                     std::to_string(channels) + " channels");
      }
      ++f;
    }
    if(f < count)
      fail(frames_word, std::to_string(count) + " frames declared but the file holds " + std::to_string(f) +
                            " frame lines");
    m.frames = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        values.data(), count, Eigen::Index(channels));
  }

  static constexpr int max_depth = 1000;
  std::string name_;
  std::vector<Word> words_;
  std::size_t pos_ = 0, end_line_ = 1;
};

void write_joint(std::ostream& out, const Bvh_motion& m, std::size_t j, int depth, const char* number_format)
{
  const std::string indent(std::size_t(depth), '\t');
  const Bvh_joint& joint = m.joints[j];
  char buffer[128];
  if(joint.end_site) out << indent << "End Site\n";
  else out << indent << (joint.parent < 0 ? "ROOT " : "JOINT ") << joint.name << "\n";
  out << indent << "{\n" << indent << "\tOFFSET";
  for(int k = 0; k < 3; ++k) {
    std::snprintf(buffer, sizeof buffer, number_format, joint.offset[k]);
    out << ' ' << buffer;
  }
  out << "\n";
  if(!joint.end_site) {
    out << indent << "\tCHANNELS " << joint.channels.size();
    for(Bvh_channel c : joint.channels) out << ' ' << channel_name(c);
    out << "\n";
  }
  for(std::size_t c = j + 1; c < m.joints.size(); ++c)
    if(m.joints[c].parent == int(j)) write_joint(out, m, c, depth + 1, number_format);
  out << indent << "}\n";
}

} // namespace

const char* channel_name(Bvh_channel c)
{
  switch(c) {
  case Bvh_channel::x_position: return "Xposition";
  case Bvh_channel::y_position: return "Yposition";
  case Bvh_channel::z_position: return "Zposition";
  case Bvh_channel::x_rotation: return "Xrotation";
  case Bvh_channel::y_rotation: return "Yrotation";
  case Bvh_channel::z_rotation: return "Zrotation";
  }
  return "?";
}

std::size_t Bvh_motion::number_of_channels() const
{
  std::size_t n = 0;
  for(const Bvh_joint& j : joints) n += j.channels.size();
  return n;
}

std::size_t Bvh_motion::number_of_named_joints() const
{
  std::size_t n = 0;
  for(const Bvh_joint& j : joints) n += j.end_site ? 0 : 1;
  return n;
}

void check_bvh_motion(const Bvh_motion& motion, const std::string& caller)
{
  std::size_t column = 0;
  for(std::size_t j = 0; j < motion.joints.size(); ++j) {
    const Bvh_joint& joint = motion.joints[j];
    const std::string which = caller + ": joint " + std::to_string(j) + " ('" + joint.name + "')";
    if(joint.parent >= int(j) || joint.parent < -1) throw Invalid_input(which + ": its parent must come before it");
    if(joint.parent >= 0 && motion.joints[std::size_t(joint.parent)].end_site)
      throw Invalid_input(which + ": an End Site has no children");
    if(joint.end_site && (!joint.channels.empty() || joint.parent < 0))
      throw Invalid_input(which + ": an End Site has a parent and no channels");
    if(!joint.end_site && joint.name.empty()) throw Invalid_input(which + ": a joint needs a name");
    if(joint.first_channel != column)
      throw Invalid_input(which + ": its first channel is column " + std::to_string(joint.first_channel) + ", not " +
                          std::to_string(column) + " (the channels follow the joints' order)");
    if(joint.channels.size() > 6 || !joint.offset.allFinite())
      throw Invalid_input(which + ": at most 6 channels and a finite offset");
    column += joint.channels.size();
  }
  if(motion.frames.cols() != Eigen::Index(column))
    throw Invalid_input(caller + ": the frames have " + std::to_string(motion.frames.cols()) + " columns for " +
                        std::to_string(column) + " channels");
  if(!motion.frames.allFinite()) throw Invalid_input(caller + ": a frame holds a NaN or infinite value");
  if(!(motion.frame_time > 0) || !std::isfinite(motion.frame_time))
    throw Invalid_input(caller + ": the frame time must be finite and > 0");
}

Bvh_motion read_bvh(std::istream& in, const std::string& source_name)
{
  return Bvh_reader(in, source_name).read();
}

Bvh_motion read_bvh(const std::string& path)
{
  std::ifstream in(path);
  if(!in) throw Invalid_input("cannot open BVH file '" + path + "': " + std::strerror(errno));
  return read_bvh(in, path);
}

void write_bvh(std::ostream& out, const Bvh_motion& motion, int significant_digits)
{
  check_bvh_motion(motion, "write_bvh");
  const int digits = std::max(1, std::min(17, significant_digits));
  const std::string format = "%." + std::to_string(digits) + "g";
  out << "HIERARCHY\n";
  for(std::size_t j = 0; j < motion.joints.size(); ++j)
    if(motion.joints[j].parent < 0) write_joint(out, motion, j, 0, format.c_str());
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, format.c_str(), motion.frame_time);
  out << "MOTION\nFrames: " << motion.frames.rows() << "\nFrame Time: " << buffer << "\n";
  for(Eigen::Index f = 0; f < motion.frames.rows(); ++f) {
    for(Eigen::Index c = 0; c < motion.frames.cols(); ++c) {
      std::snprintf(buffer, sizeof buffer, format.c_str(), motion.frames(f, c) == 0 ? 0.0 : motion.frames(f, c));
      out << (c ? " " : "") << buffer;
    }
    out << "\n";
  }
}

void write_bvh(const std::string& path, const Bvh_motion& motion, int significant_digits)
{
  std::ofstream out(path);
  if(!out) throw Invalid_input("cannot open '" + path + "' for writing: " + std::strerror(errno));
  write_bvh(out, motion, significant_digits);
  out.close();
  if(!out) throw Invalid_input("writing '" + path + "' failed");
}

} // namespace Spline_approximation
} // namespace CGAL
