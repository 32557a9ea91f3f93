// contain inside --csg, end to end, per ../shared/spec/cli.md.

#include <gtest/gtest.h>

#include "cli/run.h"

namespace contain::test {
namespace {

TEST(InsideCsgCli, TouchingBoxesShareAFaceThatIsInsideTheirUnion) {
  TempDir dir;
  const std::string csg = dir.write("s.json", R"({"union": [
      {"box": {"min": [0, 0, 0], "max": [1, 1, 1]}},
      {"box": {"min": [1, 0, 0], "max": [2, 1, 1]}}]})");
  const CliRun run =
      run_contain({"inside", "--csg", csg}, "1 0.5 0.5\n2 0.5 0.5\n3 0 0\n0.5 0.5 0.5\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "in\non\nout\nin\n");
}

TEST(InsideCsgCli, SurfaceOfAInsideBIsBoundaryOfTheirIntersection) {
  TempDir dir;
  const std::string csg = dir.write("s.json", R"({"intersection": [
      {"sphere": {"center": [0, 0, 0], "radius": 5}},
      {"halfspace": [0, 0, 1, 0]}]})");
  const CliRun run = run_contain({"inside", "--csg", csg}, "3 4 0\n0 0 0\n0 0 1\n0 0 -1\n0 0 5\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "on\non\nin\nout\non\n");
}

TEST(InsideCsgCli, ImplicitExpressionLeafIsInsideWhereNonNegative) {
  TempDir dir;
  const std::string csg = dir.write("s.json", R"({"implicit": "1 - x^2 - y^2 - z^2"})");
  const CliRun run = run_contain({"inside", "--csg", csg}, "0 0 0\n1 0 0\n2 0 0\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "in\non\nout\n");
}

TEST(InsideCsgCli, DifferenceLeavesTheCutSurfaceOnTheBoundary) {
  TempDir dir;
  const std::string csg = dir.write("s.json", R"({"difference": [
      {"box": {"min": [0, 0, 0], "max": [2, 2, 2]}},
      {"halfspace": [1, 0, 0, -1]}]})");
  const CliRun run = run_contain({"inside", "--csg", csg}, "0.5 1 1\n1 1 1\n1.5 1 1\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "in\non\nout\n");
}

TEST(InsideCsgCli, NegativeRadiusIsBadInputNamingTheFile) {
  TempDir dir;
  const std::string csg =
      dir.write("bad.json", R"({"sphere": {"center": [0, 0, 0], "radius": -1}})");
  const CliRun run = run_contain({"inside", "--csg", csg}, "0 0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("bad.json"), std::string::npos) << run.err;
}

TEST(InsideCsgCli, MalformedJsonIsBadInputNamingTheLine) {
  TempDir dir;
  const std::string csg = dir.write("bad.json", "{\"union\": [\n  {\"sphere\": }\n]}");
  const CliRun run = run_contain({"inside", "--csg", csg}, "0 0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("bad.json:2"), std::string::npos) << run.err;
}

TEST(InsideCsgCli, TwoDimensionalPointsAreBadInput) {
  TempDir dir;
  const std::string csg = dir.write("s.json", R"({"sphere": {"center": [0, 0, 0], "radius": 1}})");
  EXPECT_EQ(run_contain({"inside", "--csg", csg}, "0 0\n").exit_code, 3);
}

}  // namespace
}  // namespace contain::test
