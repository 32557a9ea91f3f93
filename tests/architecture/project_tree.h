#pragma once
// The project's own files for the checks of tests/architecture (layering, function length): read
// from the source tree the build was configured from, and the problems a check reports joined
// into one message.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include "architecture/layering.h"

namespace contain::test {

inline const std::filesystem::path kRoot = CONTAIN_SOURCE_DIR;

inline std::string read(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The .h and .cpp files under `folders` (or their CMakeLists.txt), sorted by path.
inline std::vector<SourceFile> tree(std::initializer_list<const char*> folders, bool cmake_lists) {
  std::vector<SourceFile> files;
  for (const char* folder : folders) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kRoot / folder)) {
      const std::filesystem::path& p = entry.path();
      const bool wanted = cmake_lists ? p.filename() == "CMakeLists.txt"
                                      : (p.extension() == ".h" || p.extension() == ".cpp");
      if (!entry.is_regular_file() || !wanted) continue;
      files.push_back({std::filesystem::relative(p, kRoot).generic_string(), read(p)});
    }
  }
  std::sort(files.begin(), files.end(),
            [](const SourceFile& a, const SourceFile& b) { return a.path < b.path; });
  return files;
}

/// One problem a line, for a failure message.
inline std::string joined(const std::vector<std::string>& problems) {
  std::string all;
  for (const std::string& p : problems)
    all += p + "\n";
  return all;
}

}  // namespace contain::test
