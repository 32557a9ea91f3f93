// contain distance end to end, per ../shared/spec/cli.md: one line per point (%.17g), --signed,
// --closest (point and TRIANGLE or RING:EDGE), --within (yes/no, exact), two shapes with poses and
// --json.

#include <gtest/gtest.h>

#include <string>

#include "cli/run.h"

namespace contain::test {
namespace {

// A unit cube, outward, as OFF.
const char* kDistanceCube =
    "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 2 3 7\n3 2 7 6\n"
    "3 1 2 6\n3 1 6 5\n3 0 4 7\n3 0 7 3\n";

TEST(DistanceCli, PointsAgainstAMeshSignedWithClosestPointAndTriangle) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", kDistanceCube);
  const CliRun run = run_contain({"distance", "--mesh", cube, "--signed", "--closest"},
                                 "# comment\n0.5 0.5 0.25\n3 0.5 0.5\n\n1 1 1\n0.5,0.5,2\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out,
            "-0.25 0.5 0.5 0 0\n"  // nearest face z = 0: triangles 0 and 1 tie, 0 wins
            "2 1 0.5 0.5 8\n"      // face x = 1, triangles 8 and 9: the diagonal 1-6, 8 first
            "0 1 1 1 2\n"          // a vertex: the lowest triangle holding it
            "1 0.5 0.5 1 2\n");    // face z = 1, triangles 2 and 3: on their diagonal, 2 first
  EXPECT_TRUE(run.err.empty()) << run.err;
}

TEST(DistanceCli, UnsignedDistanceIsTheDoubleNearestToTheExactValue) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", kDistanceCube);
  // sqrt(3) from (2, 2, 2) to the corner (1, 1, 1): 1.7320508075688772 is the nearest double.
  const CliRun run = run_contain({"distance", "--mesh", cube}, "2 2 2\n0.5 0.5 0.5\n");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, "1.7320508075688772\n0.5\n");
}

TEST(DistanceCli, WithinIsExactAtTheDistanceItself) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", kDistanceCube);
  // distance 0.1 from (1.1, 0.5, 0.5): the double 0.1 is above the exact 1.1 - 1 (the double
  // 1.1 is 1.100000000000000088817841970012523..., so the gap is 0.100000000000000088...), and
  // the double 0.1 = 0.1000000000000000055511151231257827: below it, so "no".
  const CliRun run =
      run_contain({"distance", "--mesh", cube, "--within", "0.1"}, "1.1 0.5 0.5\n1.05 0.5 0.5\n");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, "no\nyes\n");
  const CliRun exact =
      run_contain({"distance", "--mesh", cube, "--within", "0.5"}, "1.5 0.5 0.5\n");
  EXPECT_EQ(exact.out, "yes\n");
}

TEST(DistanceCli, PointsAgainstARegionWithRingAndEdge) {
  TempDir dir;
  const std::string square =
      dir.write("sq.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))");
  const CliRun run = run_contain({"distance", "--polygon", square, "--signed", "--closest"},
                                 "2 2\n0.5 0.5\n-3 -4\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "1 1 2 1:0\n-0.5 0.5 0 0:0\n5 0 0 0:0\n");
  const CliRun within =
      run_contain({"distance", "--polygon", square, "--within", "1"}, "2 2\n2.5 2\n");
  EXPECT_EQ(within.out, "yes\nyes\n");
}

TEST(DistanceCli, TwoMeshesSeparatedTouchingAndNestedWithPosesAndJson) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", kDistanceCube);
  const std::string poses = dir.write("poses.txt",
                                      "1 0 0 3 0 1 0 0 0 0 1 0\n"  // 2 apart along x
                                      "1 0 0 1 0 1 0 0 0 0 1 0\n"  // touching faces
                                      "0.5 0 0 0.25 0 0.5 0 0.25 0 0 0.5 0.25\n");  // nested
  const CliRun run = run_contain({"distance", cube, cube, "--poses", poses});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(has(run.out, "2 1 0 0 3 0 0\n")) << run.out;
  const CliRun json = run_contain({"distance", cube, cube, "--poses", poses, "--json"});
  EXPECT_TRUE(has(json.out, "\"distance\":2,\"contact\":\"separate\"")) << json.out;
  EXPECT_TRUE(has(json.out, "\"distance\":0,\"contact\":\"touching\"")) << json.out;
  EXPECT_TRUE(has(json.out, "\"distance\":0,\"contact\":\"vertex_of_b_in_a\"")) << json.out;
  const CliRun within = run_contain({"distance", cube, cube, "--poses", poses, "--within", "1.5"});
  EXPECT_EQ(within.out, "no\nyes\nyes\n");
}

TEST(DistanceCli, TwoRegionsAndMixedKindsAreRefused) {
  TempDir dir;
  const std::string a = dir.write("a.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))");
  const std::string b = dir.write("b.wkt", "POLYGON ((6 0, 7 0, 7 1, 6 1, 6 0))");
  const CliRun run = run_contain({"distance", a, b});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, "2 4 0 6 0\n");
  const std::string cube = dir.write("cube.off", kDistanceCube);
  EXPECT_EQ(run_contain({"distance", a, cube}).exit_code, 3);
  EXPECT_EQ(run_contain({"distance", a, b, "--transform-b", "1,0,0,0,0,1,0,0,0,0,1,0"}).exit_code,
            2);
}

TEST(DistanceCli, OpenMeshSignsWarnAsInsideDoes) {
  TempDir dir;
  const std::string tri = dir.write("tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const CliRun run = run_contain({"distance", "--mesh", tri, "--signed"}, "0.25 0.25 1\n");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, "1\n");
  EXPECT_TRUE(has(run.err, "not closed")) << run.err;
  const CliRun unsigned_run = run_contain({"distance", "--mesh", tri}, "0.25 0.25 1\n");
  EXPECT_TRUE(unsigned_run.err.empty());
}

TEST(DistanceCli, UsageErrorsAreExitTwoAndBadNumbersExitThree) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", kDistanceCube);
  EXPECT_EQ(run_contain({"distance"}).exit_code, 2);
  // A D that is a number but not a distance is bad input (issue 24: the contract's exit 3).
  EXPECT_EQ(run_contain({"distance", "--mesh", cube, "--within", "-1"}, "0 0 0\n").exit_code, 3);
  EXPECT_EQ(run_contain({"distance", "--mesh", cube, "--within", "nan"}, "0 0 0\n").exit_code, 3);
  EXPECT_EQ(run_contain({"distance", "--mesh", cube, cube, cube}, "0 0 0\n").exit_code, 2);
}

}  // namespace
}  // namespace contain::test
