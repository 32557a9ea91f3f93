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

/// Runs another program (`program` found on PATH unless it holds a '/') the same way; with
/// `as_uid` >= 0 the child first becomes that user (and `as_gid`), for servers that refuse to
/// run as root. exit_code 127: the program could not be started.
[[nodiscard]] CliRun run_program(const std::string& program, const std::vector<std::string>& args,
                                 const std::string& input = "", int as_uid = -1, int as_gid = -1);

/// The whole content of the file at `path` (empty when it cannot be read).
[[nodiscard]] std::string read_text(const std::filesystem::path& path);

/// Whether `text` (what a run printed) holds `part`.
[[nodiscard]] inline bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

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
