// contain demo: runs on its built-in scenes and writes the pictures it names.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "cli/run.h"

namespace contain::test {
namespace {

// One run of the demo and the pictures it wrote.
class DemoCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<TempDir>();
    out_ = (dir_->path() / "pictures").string();
    run_ = std::make_unique<CliRun>(run_contain({"demo", "--out-dir", out_}));
  }
  static void TearDownTestSuite() {
    run_.reset();
    dir_.reset();
  }
  static std::string picture(const char* name) {
    std::ifstream in(std::filesystem::path(out_) / name);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  static inline std::unique_ptr<TempDir> dir_;
  static inline std::string out_;
  static inline std::unique_ptr<CliRun> run_;
};

// One test, not one per capability: ctest runs each test in a process of its own, and the demo
// takes over a minute under the sanitizers.
TEST_F(DemoCli, RunsEveryCapabilityWritesThePicturesItNamesAndReportsTheDistanceScenes) {
  const CliRun& run = *run_;
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* name :
       {"inside-polygon.svg", "inside-csg.svg", "inside-mesh.svg", "collide.svg", "collide-ccd.svg",
        "clip-segments.svg", "clip-sutherland-hodgman.svg", "clip-boolean.svg", "clip-mesh.svg",
        "clip-mesh.obj", "clip-mesh.ply", "bound-torus.svg", "distance-slice.svg",
        "distance-clearance.svg", "solid-bracket.obj", "solid-bracket.svg", "slice-layers.svg",
        "slice-shadow.svg"}) {
    EXPECT_NE(run.out.find(name), std::string::npos) << name;
    const std::filesystem::path file = std::filesystem::path(out_) / name;
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    EXPECT_GT(std::filesystem::file_size(file), 1000u) << file;
  }
  EXPECT_NE(run.out.find("point in polygon"), std::string::npos);
  EXPECT_NE(run.out.find("CSG"), std::string::npos);
  EXPECT_NE(run.out.find("minimal sphere"), std::string::npos);
  EXPECT_NE(run.out.find("cube nested in the tube      intersect"), std::string::npos);
  EXPECT_NE(run.out.find("bar through the hole         disjoint"), std::string::npos);
  EXPECT_NE(run.out.find("closed and consistently oriented"), std::string::npos);
  EXPECT_NE(run.out.find("CSG bracket"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("vertices moved, closed"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("bullet through a thin plate: t = 0 disjoint, t = 1 disjoint; swept: hit"),
            std::string::npos);
  // The distance scenes: signs, the closest pair, touching and nesting.
  EXPECT_NE(run.out.find("signed distance    57600 points"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("clearance          torus"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("(separate), within 0.25: no"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("bar against the outer side: distance 0 (touching)"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("cube nested in the tube: distance 0 (vertex_of_b_in_a)"),
            std::string::npos)
      << run.out;
  // The slice is a colour map (runs of cells) with the zero contour (lines) drawn on top; the
  // clearance picture draws the closest pair.
  const std::string slice = picture("distance-slice.svg");
  const std::size_t cells = slice.find("shape-rendering=\"crispEdges\"");
  ASSERT_NE(cells, std::string::npos);
  EXPECT_NE(slice.find("<line", cells), std::string::npos);
  EXPECT_NE(picture("distance-clearance.svg").find("closest pair"), std::string::npos);
  // The slicing scene: stacked layers, one colour a level, and the shadows.
  EXPECT_NE(run.out.find("slicing           37 layers"), std::string::npos) << run.out;
  EXPECT_NE(picture("slice-layers.svg").find("#fde725"), std::string::npos);
}

}  // namespace
}  // namespace contain::test
