// contain collide, end to end (../shared/spec/cli.md, "contain collide").

#include <gtest/gtest.h>

#include <string>

#include "cli/run.h"

namespace contain::test {
namespace {

const char* kCollideCube =
    "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
    "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n"
    "3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n";

TEST(CollideCli, TouchingCubesIntersectAndSeparatedOnesAreDisjoint) {
  const TempDir dir;
  const std::string cube = dir.write("cube.off", kCollideCube);
  auto r = run_contain({"collide", cube, cube, "--transform-b", "1,0,0,1,0,1,0,0,0,0,1,0"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "intersect\n");
  r = run_contain({"collide", cube, cube, "--transform-b", "1 0 0 1.000001 0 1 0 0 0 0 1 0"});
  EXPECT_EQ(r.out, "disjoint\n");
}

TEST(CollideCli, PosesGiveOneLinePerPoseAndJsonHasAWitness) {
  const TempDir dir;
  const std::string cube = dir.write("cube.off", kCollideCube);
  const std::string poses = dir.write("poses.txt",
                                      "# shift along x\n"
                                      "1,0,0,0.5,0,1,0,0,0,0,1,0\n"
                                      "\n"
                                      "1,0,0,3,0,1,0,0,0,0,1,0\n"
                                      "0.5 0 0 0.25 0 0.5 0 0.25 0 0 0.5 0.25\n");
  auto r = run_contain({"collide", cube, cube, "--poses", poses});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "intersect\ndisjoint\nintersect\n");
  r = run_contain({"collide", cube, cube, "--poses", poses, "--json"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("{\"intersect\":true,\"witness\":{\"kind\":\"triangles\""),
            std::string::npos);
  EXPECT_NE(r.out.find("{\"intersect\":false"), std::string::npos);
  EXPECT_NE(r.out.find("\"kind\":\"vertex_of_b_in_a\""), std::string::npos);  // nested half cube
}

TEST(CollideCli, OpenMeshIsASurfaceWithAWarning) {
  const TempDir dir;
  const std::string tri = dir.write("tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const std::string cube = dir.write("cube.off", kCollideCube);
  auto r = run_contain({"collide", tri, tri, "--transform-b", "1,0,0,0,0,1,0,0,0,0,1,1e-300"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, "disjoint\n");
  EXPECT_NE(r.err.find("surface"), std::string::npos);
  r = run_contain({"collide", tri, tri});
  EXPECT_EQ(r.out, "intersect\n");
  r = run_contain({"collide", cube, tri, "--transform-b", "0.5,0,0,0.25,0,0.5,0,0.25,0,0,1,0.5"});
  EXPECT_EQ(r.out, "intersect\n");  // a surface inside a solid
}

TEST(CollideCli, RegionsCollideAsClosedSets) {
  const TempDir dir;
  const std::string a =
      dir.write("a.wkt", "POLYGON((0 0, 4 0, 4 4, 0 4, 0 0),(1 1, 1 3, 3 3, 3 1, 1 1))");
  const std::string in_hole =
      dir.write("b.wkt", "POLYGON((1.5 1.5, 2.5 1.5, 2.5 2.5, 1.5 2.5, 1.5 1.5))");
  const std::string touch = dir.write("c.wkt", "POLYGON((4 0, 5 0, 5 1, 4 1, 4 0))");
  const std::string inside =
      dir.write("d.wkt", "POLYGON((0.25 0.25, 0.75 0.25, 0.5 0.75, 0.25 0.25))");
  EXPECT_EQ(run_contain({"collide", a, in_hole}).out, "disjoint\n");
  EXPECT_EQ(run_contain({"collide", a, touch}).out, "intersect\n");
  EXPECT_EQ(run_contain({"collide", inside, a}).out, "intersect\n");
  EXPECT_NE(run_contain({"collide", a, touch, "--json"}).out.find("\"kind\":\"edges\""),
            std::string::npos);
}

TEST(CollideCli, BadInputAndUsageErrorsFollowTheContract) {
  const TempDir dir;
  const std::string cube = dir.write("cube.off", kCollideCube);
  const std::string region = dir.write("r.wkt", "POLYGON((0 0, 1 0, 0 1, 0 0))");
  EXPECT_EQ(run_contain({"collide", cube, cube, "--transform-b", "1,0,0"}).exit_code, 2);
  // NaN in a transform is a bad number: exit 3, as NaN coordinates (issue 24).
  EXPECT_EQ(
      run_contain({"collide", cube, cube, "--transform-b", "1,0,0,nan,0,1,0,0,0,0,1,0"}).exit_code,
      3);
  EXPECT_EQ(run_contain({"collide", cube, (dir.path() / "missing.off").string()}).exit_code, 3);
  EXPECT_EQ(run_contain({"collide", cube, region}).exit_code, 3);
  const std::string bad = dir.write("bad.txt", "1 0 0 0 0 1 0 0 0 0 1\n");
  const auto r = run_contain({"collide", cube, cube, "--poses", bad});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("bad.txt"), std::string::npos);
  EXPECT_EQ(run_contain({"collide", cube}).exit_code, 2);
}

}  // namespace
}  // namespace contain::test
