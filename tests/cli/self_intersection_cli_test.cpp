// Issue 24: a closed mesh that crosses itself. `inside` (and what reads its answers: signed
// distances, scenes of solids) answers the solid of its winding number, where overlapping parts
// count once: no warning. Collide and mesh-pair distance still read the inside by ray parity,
// which takes a point inside two overlapping parts as outside: they warn on stderr, naming the
// file and one pair of triangles.

#include <gtest/gtest.h>

#include <string>

#include "cli/cube_off.h"
#include "cli/run.h"

namespace contain::test {
namespace {

// Cubes [0,2]^3 and [1,3]^3 as one closed OFF mesh (the second's triangles from 12 on).
std::string overlapping_cubes_off() {
  const int faces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                            {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  std::string out = "OFF\n16 24 0\n";
  for (const int lo : {0, 1}) {
    for (int i = 0; i < 8; ++i) {
      for (int k = 0; k < 3; ++k)
        out += std::to_string((i >> k) & 1 ? lo + 2 : lo) + (k < 2 ? " " : "\n");
    }
  }
  for (const int shift : {0, 8}) {
    for (const auto& f : faces) {
      out += "3 " + std::to_string(f[0] + shift) + " " + std::to_string(f[1] + shift) + " " +
             std::to_string(f[2] + shift) + "\n";
    }
  }
  return out;
}

constexpr const char* crossing = "overlapping.off: mesh crosses itself (triangles ";

TEST(SelfIntersectionCli, InsideAnswersTheSolidOfTheWindingNumberWithoutAWarning) {
  TempDir dir;
  const std::string mesh = dir.write("overlapping.off", overlapping_cubes_off());
  // Inside both cubes, on the second's face buried in the first, on the outer surface, outside.
  const CliRun run = run_contain({"inside", "--mesh", mesh},
                                 "0.5 0.5 0.5\n1.5 1.5 1.5\n1 1.5 1.5\n0 1 1\n4 4 4\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "in\nin\nin\non\nout\n");
  EXPECT_TRUE(run.err.empty()) << run.err;
}

TEST(SelfIntersectionCli, AClosedMeshThatDoesNotCrossItselfGivesNoWarning) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", cube_off(2.0));
  const CliRun run = run_contain({"inside", "--mesh", mesh}, "1 1 1\n");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, "in\n");
  EXPECT_TRUE(run.err.empty()) << run.err;
}

TEST(SelfIntersectionCli, SignedDistanceTakesInsidesSignWithoutAWarning) {
  TempDir dir;
  const std::string mesh = dir.write("overlapping.off", overlapping_cubes_off());
  const CliRun signed_run = run_contain({"distance", "--mesh", mesh, "--signed"}, "1.5 1.5 1.5\n");
  EXPECT_EQ(signed_run.exit_code, 0) << signed_run.err;
  EXPECT_EQ(signed_run.out, "-0.5\n");  // inside the solid: a negative distance
  EXPECT_TRUE(signed_run.err.empty()) << signed_run.err;
  const CliRun plain = run_contain({"distance", "--mesh", mesh}, "1.5 1.5 1.5\n");
  EXPECT_EQ(plain.exit_code, 0);
  EXPECT_EQ(plain.out, "0.5\n");
  EXPECT_TRUE(plain.err.empty()) << plain.err;
}

TEST(SelfIntersectionCli, CollideAndMeshPairDistanceWarnForTheCrossingSolid) {
  TempDir dir;
  const std::string mesh = dir.write("overlapping.off", overlapping_cubes_off());
  const std::string cube = dir.write("cube.off", cube_off(1.0));
  const CliRun collide =
      run_contain({"collide", mesh, cube, "--transform-b", "1,0,0,10,0,1,0,0,0,0,1,0"});
  EXPECT_EQ(collide.exit_code, 0) << collide.err;
  EXPECT_EQ(collide.out, "disjoint\n");
  EXPECT_TRUE(has(collide.err, crossing)) << collide.err;
  EXPECT_FALSE(has(collide.err, "cube.off:")) << collide.err;
  const CliRun distance =
      run_contain({"distance", mesh, cube, "--transform-b", "1,0,0,10,0,1,0,0,0,0,1,0"});
  EXPECT_EQ(distance.exit_code, 0) << distance.err;
  EXPECT_TRUE(has(distance.err, crossing)) << distance.err;
}

TEST(SelfIntersectionCli, CollideScenesWarnOnceForAMeshThatCrossesItselfAndInsideScenesDoNot) {
  TempDir dir;
  (void)dir.write("overlapping.off", overlapping_cubes_off());
  (void)dir.write("cube.off", cube_off(1.0));
  const std::string scene = dir.write("scene.json",
                                      R"({"objects": [{"id": "a", "mesh": "overlapping.off"},
                      {"id": "b", "mesh": "overlapping.off",
                       "transform": [1,0,0,10, 0,1,0,0, 0,0,1,0]},
                      {"id": "c", "mesh": "cube.off", "transform": [1,0,0,20, 0,1,0,0, 0,0,1,0]}]})");
  const CliRun collide = run_contain({"collide", "--scene", scene});
  EXPECT_EQ(collide.exit_code, 0) << collide.err;
  EXPECT_TRUE(collide.out.empty()) << collide.out;
  EXPECT_TRUE(has(collide.err, "(object a): mesh crosses itself")) << collide.err;
  EXPECT_FALSE(has(collide.err, "(object b)")) << "once a mesh: " << collide.err;
  EXPECT_FALSE(has(collide.err, "cube.off")) << collide.err;
  const CliRun inside = run_contain({"inside", "--scene", scene}, "1.5 1.5 1.5\n0.5 0.5 0.5\n");
  EXPECT_EQ(inside.exit_code, 0) << inside.err;
  EXPECT_EQ(inside.out, "a\na\n");  // inside both cubes of object a: in its solid
  EXPECT_TRUE(inside.err.empty()) << inside.err;
}

}  // namespace
}  // namespace contain::test
