// contain collide --scene and contain inside --scene, end to end, per ../shared/spec/cli.md
// ("Many solids at once"; inside --scene is this project's extension of the contract).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/cube_off.h"
#include "cli/run.h"

namespace contain::test {
namespace {

std::string shift(double x, double y, double z) {
  return "1,0,0," + std::to_string(x) + ",0,1,0," + std::to_string(y) + ",0,0,1," +
         std::to_string(z);
}

struct Placed {
  const char* id;
  const char* mesh;
  double x, y, z;
};

// big at 0, small nested in it, big touching big's face, small touching that one's corner, a
// far one and one a little apart.
const std::vector<Placed> kObjects{
    {"base", "big.off", 0, 0, 0},  {"core", "small.off", 0.375, 0.375, 0.375},
    {"side", "big.off", 1, 0, 0},  {"tip", "small.off", 2, 1, 1},
    {"far", "small.off", 9, 9, 9}, {"gap", "big.off", 3.5, 0, 0},
};

std::string scene_json() {
  std::string objects;
  for (const Placed& p : kObjects) {
    if (!objects.empty()) objects += ",\n";
    objects += std::string(R"({"id": ")") + p.id + R"(", "mesh": "meshes/)" + p.mesh +
               R"(", "transform": [)" + shift(p.x, p.y, p.z) + "]}";
  }
  return "{\"objects\": [\n" + objects + "\n]}\n";
}

class SceneCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directories(dir.path() / "meshes");
    (void)dir.write("meshes/big.off", cube_off(1.0));
    (void)dir.write("meshes/small.off", cube_off(0.25));
    scene = dir.write("scene.json", scene_json());
  }
  TempDir dir;
  std::string scene;
};

TEST_F(SceneCli, CollidePrintsEveryTouchingOrNestedPairInFileOrder) {
  const CliRun run = run_contain({"collide", "--scene", scene});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "base core\nbase side\nside tip\n");
}

TEST_F(SceneCli, CollideSceneEqualsThePairwiseCommandOnEveryPair) {
  std::string expected;
  for (std::size_t i = 0; i < kObjects.size(); ++i) {
    for (std::size_t j = i + 1; j < kObjects.size(); ++j) {
      const Placed& a = kObjects[i];
      const Placed& b = kObjects[j];
      const CliRun pair =
          run_contain({"collide", (dir.path() / "meshes" / a.mesh).string(),
                       (dir.path() / "meshes" / b.mesh).string(), "--transform-a",
                       shift(a.x, a.y, a.z), "--transform-b", shift(b.x, b.y, b.z)});
      ASSERT_EQ(pair.exit_code, 0) << pair.err;
      if (pair.out == "intersect\n") expected += std::string(a.id) + " " + b.id + "\n";
    }
  }
  EXPECT_EQ(run_contain({"collide", "--scene", scene, "--threads", "1"}).out, expected);
  EXPECT_EQ(run_contain({"collide", "--scene", scene, "--threads", "2"}).out, expected);
}

TEST_F(SceneCli, CollideJsonGivesAWitnessPerPair) {
  const CliRun run = run_contain({"collide", "--scene", scene, "--json"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(
      run.out.find(
          R"({"a":"base","b":"core","intersect":true,"witness":{"kind":"vertex_of_b_in_a","vertex":0,"point":[0.375,0.375,0.375]}})"),
      std::string::npos)
      << run.out;
  EXPECT_NE(
      run.out.find(R"({"a":"base","b":"side","intersect":true,"witness":{"kind":"triangles")"),
      std::string::npos)
      << run.out;
  EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 3);
}

TEST_F(SceneCli, InsideSceneGivesTheIdsOfTheSolidsHoldingEachPoint) {
  const CliRun run = run_contain({"inside", "--scene", scene},
                                 "0.5 0.5 0.5\n1 0.5 0.5\n0.375 0.5 0.5\n2.1 1.1 1.1\n7 7 7\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "base core\nbase:on side:on\nbase core:on\ntip\n-\n");
  const CliRun folded =
      run_contain({"inside", "--scene", scene, "--boundary", "outside"}, "1 0.5 0.5\n");
  EXPECT_EQ(folded.out, "-\n");
}

TEST_F(SceneCli, BadScenesAreBadInputAndMisuseIsAUsageError) {
  const std::string no_mesh = dir.write("bad.json", R"({"objects": [{"id": "x"}]})");
  const CliRun a = run_contain({"collide", "--scene", no_mesh});
  EXPECT_EQ(a.exit_code, 3);
  EXPECT_NE(a.err.find("objects[0].mesh"), std::string::npos) << a.err;
  const std::string missing =
      dir.write("missing.json", R"({"objects": [{"mesh": "meshes/none.off"}]})");
  EXPECT_EQ(run_contain({"collide", "--scene", missing}).exit_code, 3);
  const std::string transform = dir.write(
      "t.json", "{\"objects\": [\n{\"mesh\": \"meshes/big.off\", \"transform\": [1, 2, 3]}]}");
  const CliRun t = run_contain({"collide", "--scene", transform});
  EXPECT_EQ(t.exit_code, 3);
  EXPECT_NE(t.err.find(":2:"), std::string::npos) << t.err;
  EXPECT_EQ(run_contain({"collide", "--scene", scene, (dir.path() / "meshes/big.off").string()})
                .exit_code,
            2);
  EXPECT_EQ(run_contain({"collide"}).exit_code, 2);
}

}  // namespace
}  // namespace contain::test
