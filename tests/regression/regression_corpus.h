#pragma once
// The regression corpus of tests/data/<domain>/: small named files, one per bug or edge case found,
// with their exact answers in the folder's cases.txt. A user's clone runs it without ../shared.
//
// cases.txt holds blocks of lines ('#' starts a comment line):
//   case NAME              a name saying what the case pins
//   run VERB ARG...        a `contain` command; an argument naming a file of the folder is its path
//   lib CHECK FILE         (instead of run) a library-only check the domain's test knows by name
//   exit N                 the exit status (default 0)
//   out LINE               one line of stdout, exactly (repeat in order; `out` alone: empty line)
//   err TEXT               stderr contains TEXT (repeatable)
//   end

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace contain::test {

struct RegressionCase {
  std::string name;
  int line = 0;                  // the `case` line in cases.txt, for failure messages
  std::vector<std::string> run;  // the command's arguments, files resolved; empty for `lib`
  std::vector<std::string> lib;  // CHECK FILE, file resolved; empty for `run`
  int exit_code = 0;
  std::vector<std::string> out;
  std::vector<std::string> err;

  /// The value of `flag` in `run` (e.g. "--points" FILE or "--box=..."), if the command has it.
  [[nodiscard]] std::optional<std::string> option(const std::string& flag) const;
  /// The verb (first argument of `run`), or "" for a `lib` case.
  [[nodiscard]] std::string verb() const { return run.empty() ? std::string{} : run.front(); }
};

/// tests/data/<domain> of the source tree.
[[nodiscard]] std::filesystem::path regression_dir(const std::string& domain);

/// Reads tests/data/<domain>/cases.txt. A malformed manifest fails the calling test (ADD_FAILURE
/// naming the line) and the cases read so far are returned.
[[nodiscard]] std::vector<RegressionCase> read_regression_cases(const std::string& domain);

/// Runs the case's command through the built `contain` and checks exit status, stdout line by
/// line and the stderr fragments (gtest expectations, naming the case).
void expect_cli_gives_recorded_answer(const RegressionCase& c);

/// Every file of tests/data/<domain> except README.md and cases.txt is named by some case, and
/// every case names at least one file: no orphan data, no case without data.
void expect_every_file_has_a_case(const std::string& domain,
                                  const std::vector<RegressionCase>& cases);

}  // namespace contain::test
