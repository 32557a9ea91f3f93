// Issue 24: a closed mesh that crosses itself, or holds nested shells. Every verb reads it as the
// solid of its winding number, as `contain inside` does (overlapping parts count once, an inner
// shell of the same orientation adds nothing, an inverted one is a cavity): inside, signed
// distances, collide (pairs and scenes) and the mesh-pair distance, without a warning.

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "cli/cube_off.h"
#include "cli/run.h"

namespace contain::test {
namespace {

struct Shell {
  int lo, hi;     // the cube [lo, hi]^3
  bool inverted;  // its triangles turned inward
};

// Cubes as one closed OFF mesh, the k-th shell's triangles from 12 k on.
std::string shells_off(std::initializer_list<Shell> shells) {
  const int faces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                            {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  std::string out = "OFF\n" + std::to_string(8 * shells.size()) + " " +
                    std::to_string(12 * shells.size()) + " 0\n";
  for (const Shell& shell : shells) {
    for (int i = 0; i < 8; ++i) {
      for (int k = 0; k < 3; ++k)
        out += std::to_string((i >> k) & 1 ? shell.hi : shell.lo) + (k < 2 ? " " : "\n");
    }
  }
  int shift = 0;
  for (const Shell& shell : shells) {
    for (const auto& f : faces) {
      const int b = shell.inverted ? f[2] : f[1], c = shell.inverted ? f[1] : f[2];
      out += "3 " + std::to_string(f[0] + shift) + " " + std::to_string(b + shift) + " " +
             std::to_string(c + shift) + "\n";
    }
    shift += 8;
  }
  return out;
}

// Cubes [0,2]^3 and [1,3]^3 as one closed OFF mesh (the second's triangles from 12 on).
std::string overlapping_cubes_off() {
  return shells_off({{0, 2, false}, {1, 3, false}});
}

// "1,0,0,t,0,1,0,t,0,0,1,t": a translation by (t, t, t).
std::string shift_by(const std::string& t) {
  return "1,0,0," + t + ",0,1,0," + t + ",0,0,1," + t;
}

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

// A cube of side 0.2 at (t, t, t) against the mesh, either way round (the mesh as A is located
// by its index, as B by the ray of the pair queries), by collide and by the mesh-pair distance,
// agrees with `inside` at the small cube's corner.
void expect_pair_agrees_with_inside(const TempDir& dir, const std::string& mesh,
                                    const std::string& t) {
  const std::string cube = (dir.path() / "small.off").string();
  const CliRun at = run_contain({"inside", "--mesh", mesh}, t + " " + t + " " + t + "\n");
  ASSERT_EQ(at.exit_code, 0) << at.err;
  const bool in = at.out == "in\n";
  for (const bool mesh_is_a : {true, false}) {
    const std::vector<std::string> pair =
        mesh_is_a ? std::vector<std::string>{mesh, cube, "--transform-b", shift_by(t)}
                  : std::vector<std::string>{cube, mesh, "--transform-a", shift_by(t)};
    std::vector<std::string> collide{"collide"}, distance{"distance"};
    collide.insert(collide.end(), pair.begin(), pair.end());
    distance.insert(distance.end(), pair.begin(), pair.end());
    const CliRun c = run_contain(collide);
    EXPECT_EQ(c.exit_code, 0) << c.err;
    EXPECT_EQ(c.out, in ? "intersect\n" : "disjoint\n") << mesh << " at " << t;
    EXPECT_TRUE(c.err.empty()) << c.err;
    const CliRun d = run_contain(distance);
    EXPECT_EQ(d.exit_code, 0) << d.err;
    EXPECT_EQ(d.out.substr(0, 2) == "0 ", in) << mesh << " at " << t << ": " << d.out;
    EXPECT_TRUE(d.err.empty()) << d.err;
  }
}

TEST(SelfIntersectionCli, CollideAndMeshPairDistanceReadTheSolidOfTheWindingNumberAsInsideDoes) {
  TempDir dir;
  (void)dir.write("small.off", cube_off(0.2));
  const std::string overlapping = dir.write("overlapping.off", overlapping_cubes_off());
  expect_pair_agrees_with_inside(dir, overlapping, "1.4");  // inside both parts
  expect_pair_agrees_with_inside(dir, overlapping, "0.4");  // inside one part
  expect_pair_agrees_with_inside(dir, overlapping, "5");    // outside
  const std::string nested =
      dir.write("nested.off", shells_off({{0, 4, false}, {1, 3, false}}));  // still solid
  expect_pair_agrees_with_inside(dir, nested, "1.4");
  expect_pair_agrees_with_inside(dir, nested, "0.4");
  const std::string hollow =
      dir.write("hollow.off", shells_off({{0, 4, false}, {1, 3, true}}));  // a cavity
  expect_pair_agrees_with_inside(dir, hollow, "1.4");
  expect_pair_agrees_with_inside(dir, hollow, "0.4");
}

TEST(SelfIntersectionCli, TheCavityIsAGapOfTheMeshPairDistance) {
  TempDir dir;
  const std::string cube = dir.write("small.off", cube_off(0.2));
  const std::string hollow = dir.write("hollow.off", shells_off({{0, 4, false}, {1, 3, true}}));
  // The small cube [1.4, 1.6]^3 in the cavity (1, 3)^3: 0.4 from its wall.
  const CliRun d = run_contain({"distance", cube, hollow, "--transform-a", shift_by("1.4")});
  EXPECT_EQ(d.exit_code, 0) << d.err;
  EXPECT_EQ(d.out.substr(0, d.out.find(' ')), "0.39999999999999991") << d.out;
}

TEST(SelfIntersectionCli, PairsWarnOfAnInconsistentOrientationAsInsideDoes) {
  TempDir dir;
  const std::string cube = dir.write("small.off", cube_off(0.2));
  // Two disjoint cubes, the second inverted, then one triangle pair of the second flipped back:
  // every edge has two triangles, no winding number: parity, with inside's warning.
  std::string text = shells_off({{0, 2, false}, {3, 5, true}});
  const std::string inverted_face = "3 8 11 10\n";  // triangle 12: {0, 3, 2} turned inward
  const std::size_t at = text.find(inverted_face);
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, inverted_face.size(), "3 8 10 11\n");
  const std::string mesh = dir.write("mixed.off", text);
  const CliRun inside = run_contain({"inside", "--mesh", mesh}, "4 4 4\n1 1 1\n");
  ASSERT_EQ(inside.exit_code, 0) << inside.err;
  EXPECT_EQ(inside.out, "in\nin\n");
  ASSERT_TRUE(has(inside.err, "inconsistent orientation")) << inside.err;
  const CliRun collide = run_contain({"collide", mesh, cube, "--transform-b", shift_by("3.9")});
  EXPECT_EQ(collide.exit_code, 0) << collide.err;
  EXPECT_EQ(collide.out, "intersect\n");
  EXPECT_TRUE(has(collide.err, "mixed.off: mesh has inconsistent orientation")) << collide.err;
  EXPECT_FALSE(has(collide.err, "crosses itself")) << collide.err;
  const CliRun swapped = run_contain({"collide", cube, mesh, "--transform-a", shift_by("3.9")});
  EXPECT_EQ(swapped.out, "intersect\n");
  const CliRun distance = run_contain({"distance", cube, mesh, "--transform-a", shift_by("3.9")});
  EXPECT_EQ(distance.out.substr(0, 2), "0 ") << distance.out;
  EXPECT_TRUE(has(distance.err, "mixed.off: mesh has inconsistent orientation")) << distance.err;
}

TEST(SelfIntersectionCli, CollideScenesAndInsideScenesReadTheSameSolidWithoutAWarning) {
  TempDir dir;
  (void)dir.write("overlapping.off", overlapping_cubes_off());
  (void)dir.write("cube.off", cube_off(0.2));
  // b lies inside both parts of a, c inside one part of a's copy d, e apart from all.
  const std::string scene = dir.write("scene.json",
                                      R"({"objects": [{"id": "a", "mesh": "overlapping.off"},
                      {"id": "b", "mesh": "cube.off", "transform": [1,0,0,1.4, 0,1,0,1.4, 0,0,1,1.4]},
                      {"id": "d", "mesh": "overlapping.off",
                       "transform": [1,0,0,10, 0,1,0,0, 0,0,1,0]},
                      {"id": "c", "mesh": "cube.off", "transform": [1,0,0,10.4, 0,1,0,0.4, 0,0,1,0.4]},
                      {"id": "e", "mesh": "cube.off", "transform": [1,0,0,20, 0,1,0,0, 0,0,1,0]}]})");
  const CliRun collide = run_contain({"collide", "--scene", scene});
  EXPECT_EQ(collide.exit_code, 0) << collide.err;
  EXPECT_EQ(collide.out, "a b\nd c\n");
  EXPECT_TRUE(collide.err.empty()) << collide.err;
  const CliRun inside = run_contain({"inside", "--scene", scene}, "1.5 1.5 1.5\n10.5 0.5 0.5\n");
  EXPECT_EQ(inside.exit_code, 0) << inside.err;
  EXPECT_EQ(inside.out, "a b\nd c\n");
  EXPECT_TRUE(inside.err.empty()) << inside.err;
}

}  // namespace
}  // namespace contain::test
