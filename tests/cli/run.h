#pragma once
// Runs the built `contain` executable as a user would and captures what it prints.

#include <filesystem>
#include <string>
#include <vector>

namespace contain::test {

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs `contain` with `args` (each passed as one argument, no shell), feeding `input` on stdin.
[[nodiscard]] CliRun run_contain(const std::vector<std::string>& args,
                                 const std::string& input = "");

/// A fresh directory for one test's files, removed with the object.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  /// Writes `text` to `name` inside the directory and returns its path.
  [[nodiscard]] std::string write(const std::string& name, const std::string& text) const;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace contain::test
