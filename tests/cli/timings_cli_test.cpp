// --timings on every verb: where the wall time went, on stderr, with stdout unchanged.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cube_off.h"
#include "cli/run.h"

namespace contain::test {
namespace {

// The run with --timings prints the same stdout and exit code as without, and on stderr the five
// lines of docs/scale.md in order, whose phases add up to the total (every moment counts in one
// phase; each figure is rounded to a microsecond). Returns each phase's milliseconds.
std::map<std::string, double> expect_timings(const std::vector<std::string>& args,
                                             const std::string& input = "") {
  const CliRun plain = run_contain(args, input);
  std::vector<std::string> timed_args = args;
  timed_args.push_back("--timings");
  const CliRun timed = run_contain(timed_args, input);
  EXPECT_EQ(plain.exit_code, 0) << args[0] << ": " << plain.err;
  EXPECT_EQ(timed.exit_code, 0) << args[0] << ": " << timed.err;
  EXPECT_EQ(timed.out, plain.out) << args[0];
  EXPECT_EQ(plain.err.find("timings"), std::string::npos) << args[0] << ": " << plain.err;
  const std::regex line(R"(contain: timings: (\w+) (\d+\.\d{3}) ms)");
  std::vector<std::string> phases;
  std::map<std::string, double> spent;
  double sum = 0.0;
  double total = -1.0;
  std::istringstream err(timed.err);
  for (std::string text; std::getline(err, text);) {
    std::smatch m;
    if (!std::regex_match(text, m, line)) continue;
    phases.push_back(m[1]);
    spent[m[1]] = std::stod(m[2]);
    if (m[1] == "total") {
      total = std::stod(m[2]);
    } else {
      sum += std::stod(m[2]);
    }
  }
  EXPECT_EQ(phases, (std::vector<std::string>{"read", "prepare", "query", "write", "total"}))
      << args[0] << ": " << timed.err;
  EXPECT_LE(std::abs(sum - total), 0.005) << args[0] << ": " << timed.err;
  return spent;
}

TEST(TimingsCli, InsidePrintsWhereTheTimeWentAndTheSameAnswers) {
  TempDir dir;
  const std::string square = dir.write("sq.wkt", "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))");
  expect_timings({"inside", "--polygon", square}, "1 1\n3 3\n0 1\n");
  const std::string cube = dir.write("cube.off", cube_off(1.0));
  expect_timings(
      {"inside", "--mesh", cube, "--points", dir.write("p.xyz", "0.5 0.5 0.5\n2 0 0\n")});
}

TEST(TimingsCli, CollidePrintsWhereTheTimeWentAndTheSameAnswers) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", cube_off(1.0));
  const std::string other = dir.write("other.off", cube_off(2.0));
  expect_timings({"collide", cube, other});
}

TEST(TimingsCli, ClipPrintsWhereTheTimeWentAndTheSameAnswers) {
  TempDir dir;
  const std::string square = dir.write("sq.wkt", "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))");
  expect_timings({"clip", "--polygon", square, "--box", "1,1,3,3"});
  expect_timings({"clip", "--segments", dir.write("s.txt", "0 0 3 3\n"), "--box", "0,0,1,1"});
}

// A boolean of solids counts its engine as the query and its mesh as the write, not all of it
// as reading (every phase's clock is entered by the verb).
TEST(TimingsCli, SolidBooleanCountsTheEngineAsQueryAndTheMeshAsWrite) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", cube_off(1.0));
  const std::string other = dir.write("other.off", cube_off(2.0));
  const std::string out = (dir.path() / "union.off").string();
  const std::map<std::string, double> spent =
      expect_timings({"clip", cube, other, "--op", "union", "--out", out});
  EXPECT_GT(spent.at("query"), 0.0);
  EXPECT_GT(spent.at("write"), 0.0);
  const std::string csg =
      dir.write("tree.json", R"({"difference": [{"box": {"min": [0, 0, 0], "max": [2, 2, 2]}},
                           {"box": {"min": [1, 1, 1], "max": [3, 3, 3]}}]})");
  EXPECT_GT(expect_timings({"clip", "--csg", csg, "--out", out}).at("query"), 0.0);
}

TEST(TimingsCli, SlicePrintsWhereTheTimeWentAndTheSameAnswers) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", cube_off(1.0));
  expect_timings({"slice", "--mesh", cube, "--z", "0.5"});
}

TEST(TimingsCli, DistancePrintsWhereTheTimeWentAndTheSameAnswers) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", cube_off(1.0));
  expect_timings({"distance", "--mesh", cube}, "2 0 0\n0.5 0.5 0.5\n");
  const std::string other = dir.write("other.off", cube_off(2.0));
  expect_timings({"distance", cube, other});
}

TEST(TimingsCli, BoundPrintsWhereTheTimeWentAndTheSameAnswers) {
  TempDir dir;
  expect_timings({"bound", dir.write("cube.off", cube_off(1.0))});
}

// The index verb's subcommand takes the flag after its own options too (`contain index build
// ... --timings`): reading the mesh, building the index and saving it are timed.
TEST(TimingsCli, IndexBuildPrintsWhereTheTimeWentAfterItsSubcommand) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", cube_off(1.0));
  const std::string saved = (dir.path() / "cube.cidx").string();
  const std::map<std::string, double> spent =
      expect_timings({"index", "build", "--mesh", cube, "--out", saved});
  EXPECT_GT(spent.at("prepare"), 0.0);
  EXPECT_GT(spent.at("write"), 0.0);
  expect_timings({"inside", "--index", saved}, "0.5 0.5 0.5\n2 0 0\n");
}

}  // namespace
}  // namespace contain::test
