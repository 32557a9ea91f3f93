// contain demo: runs on its built-in scene and writes the pictures it names.

#include <gtest/gtest.h>

#include <filesystem>

#include "cli/run.h"

namespace contain::test {
namespace {

TEST(DemoCli, RunsEveryCapabilityAndWritesThePicturesAndMeshesItNames) {
  TempDir dir;
  const std::string out = (dir.path() / "pictures").string();
  const CliRun run = run_contain({"demo", "--out-dir", out});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* name :
       {"inside-polygon.svg", "inside-csg.svg", "inside-mesh.svg", "collide.svg", "collide-ccd.svg",
        "clip-segments.svg", "clip-sutherland-hodgman.svg", "clip-boolean.svg", "clip-mesh.svg",
        "clip-mesh.obj", "clip-mesh.ply", "bound-torus.svg"}) {
    EXPECT_NE(run.out.find(name), std::string::npos) << name;
    const std::filesystem::path file = std::filesystem::path(out) / name;
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    EXPECT_GT(std::filesystem::file_size(file), 1000u) << file;
  }
  EXPECT_NE(run.out.find("point in polygon"), std::string::npos);
  EXPECT_NE(run.out.find("CSG"), std::string::npos);
  EXPECT_NE(run.out.find("minimal sphere"), std::string::npos);
  EXPECT_NE(run.out.find("cube nested in the tube      intersect"), std::string::npos);
  EXPECT_NE(run.out.find("bar through the hole         disjoint"), std::string::npos);
  EXPECT_NE(run.out.find("closed and consistently oriented"), std::string::npos);
  EXPECT_NE(run.out.find("bullet through a thin plate: t = 0 disjoint, t = 1 disjoint; swept: hit"),
            std::string::npos);
}

}  // namespace
}  // namespace contain::test
