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

// The L of z in [0, 1]: [0, 2]^2 without [1, 2]^2, faces as polygons (fan-triangulated from
// their first vertex; the L is star-shaped from (0, 0)).
constexpr const char* kLObj = R"(v 0 0 0
v 2 0 0
v 2 1 0
v 1 1 0
v 1 2 0
v 0 2 0
v 0 0 1
v 2 0 1
v 2 1 1
v 1 1 1
v 1 2 1
v 0 2 1
f 1 6 5 4 3 2
f 7 8 9 10 11 12
f 1 2 8 7
f 2 3 9 8
f 3 4 10 9
f 4 5 11 10
f 5 6 12 11
f 6 1 7 12
)";

TEST(InsideCsgCli, MeshLeafWithTheBoxInItsNotchIsOneSolid) {
  TempDir dir;
  (void)dir.write("l.obj", kLObj);
  const std::string csg = dir.write("s.json", R"({"union": [
      {"mesh": "l.obj"}, {"box": {"min": [1, 1, 0], "max": [2, 2, 1]}}]})");
  const CliRun run = run_contain({"inside", "--csg", csg},
                                 "1 1.5 0.5\n1 1 0.5\n0.5 0.5 0.5\n2 2 1\n0 1 0.5\n3 1 0.5\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "in\nin\nin\non\non\nout\n");
}

TEST(InsideCsgCli, OpenMeshLeafIsBadInputNamingTheMesh) {
  TempDir dir;
  std::string open = kLObj;
  open.resize(open.rfind("f 6 1 7 12"));
  (void)dir.write("open.obj", open);
  const std::string csg = dir.write("s.json", R"({"mesh": "open.obj"})");
  const CliRun run = run_contain({"inside", "--csg", csg}, "0 0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("open.obj"), std::string::npos) << run.err;
}

TEST(InsideCsgCli, TwoDimensionalPointsAreBadInput) {
  TempDir dir;
  const std::string csg = dir.write("s.json", R"({"sphere": {"center": [0, 0, 0], "radius": 1}})");
  EXPECT_EQ(run_contain({"inside", "--csg", csg}, "0 0\n").exit_code, 3);
}

}  // namespace
}  // namespace contain::test
