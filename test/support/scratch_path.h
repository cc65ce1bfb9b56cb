// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Paths for the files a test writes and reads back.

#ifndef TVF_SCRATCH_PATH_H
#define TVF_SCRATCH_PATH_H

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace tvf_test {

/// A path for a file named `name` in a folder of this process alone, removed when the process
/// ends. ctest runs the tests of one executable as parallel processes sharing gtest's temporary
/// folder, so a fixed name there can be rewritten by another test between this test's write and
/// its read.
inline std::string scratch_path(const std::string& name)
{
  struct Folder
  {
    std::filesystem::path path = std::filesystem::path(::testing::TempDir()) / ("tvf_" + std::to_string(::getpid()));
    Folder() { std::filesystem::create_directories(path); }
    ~Folder()
    {
      std::error_code ignored; // a folder that cannot be removed is left behind, not an error
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Folder folder;
  return (folder.path / name).string();
}

} // namespace tvf_test

#endif // TVF_SCRATCH_PATH_H
