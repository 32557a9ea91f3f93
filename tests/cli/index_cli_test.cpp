// contain index build and contain inside --index, end to end (docs/index-files.md).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "cli/cube_off.h"
#include "cli/run.h"

namespace contain::test {
namespace {

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

const std::string kCubeOff = cube_off(1.0);
const char* const kPoints = "0.5 0.5 0.5\n1 0.5 0.5\n1 1 1\n2 0 0\n0 0.25 0.75\n";

TEST(IndexCli, SavedMeshIndexAnswersAsTheMeshWithOrWithoutIt) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", kCubeOff);
  const std::string index = (dir.path() / "cube.cidx").string();
  const CliRun built = run_contain({"index", "build", "--mesh", mesh, "--out", index});
  ASSERT_EQ(built.exit_code, 0) << built.err;
  const CliRun fresh = run_contain({"inside", "--mesh", mesh}, kPoints);
  const CliRun alone = run_contain({"inside", "--index", index}, kPoints);
  const CliRun checked = run_contain({"inside", "--mesh", mesh, "--index", index}, kPoints);
  EXPECT_EQ(fresh.out, "in\non\non\nout\non\n");
  EXPECT_EQ(alone.exit_code, 0) << alone.err;
  EXPECT_EQ(alone.out, fresh.out);
  EXPECT_EQ(checked.exit_code, 0) << checked.err;
  EXPECT_EQ(checked.out, fresh.out);
}

// The file is written over in place and then cut to its length: what was there before, longer
// or shorter, leaves no trace.
TEST(IndexCli, BuildingOverAnExistingFileGivesTheSameBytesAsAFreshFile) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", kCubeOff);
  const std::string fresh = (dir.path() / "fresh.cidx").string();
  ASSERT_EQ(run_contain({"index", "build", "--mesh", mesh, "--out", fresh}).exit_code, 0);
  const std::string expected = read_bytes(fresh);
  ASSERT_GT(expected.size(), 64U);
  for (const std::string& before : {std::string(3 * expected.size(), 'x'), std::string("short")}) {
    const std::string over = (dir.path() / "over.cidx").string();
    write_bytes(over, before);
    const CliRun built = run_contain({"index", "build", "--mesh", mesh, "--out", over});
    ASSERT_EQ(built.exit_code, 0) << built.err;
    EXPECT_EQ(read_bytes(over), expected) << before.size();
  }
}

TEST(IndexCli, IndexOfAnotherMeshIsRefusedNamingBothFiles) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", kCubeOff);
  std::string moved = kCubeOff;
  moved.replace(moved.rfind("1.000000 1.000000 1.000000"), 26, "1.000000 1.000000 2.000000");
  const std::string other = dir.write("other.off", moved);
  const std::string index = (dir.path() / "cube.cidx").string();
  ASSERT_EQ(run_contain({"index", "build", "--mesh", mesh, "--out", index}).exit_code, 0);
  const CliRun run = run_contain({"inside", "--mesh", other, "--index", index}, kPoints);
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_EQ(run.out, "");
  EXPECT_NE(run.err.find("cube.cidx"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("other.off"), std::string::npos) << run.err;
}

TEST(IndexCli, TruncatedDamagedAndForeignIndexFilesExitThreeNamingTheFile) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", kCubeOff);
  const std::string index = (dir.path() / "cube.cidx").string();
  ASSERT_EQ(run_contain({"index", "build", "--mesh", mesh, "--out", index}).exit_code, 0);
  const std::string bytes = read_bytes(index);
  const std::string truncated = (dir.path() / "truncated.cidx").string();
  write_bytes(truncated, bytes.substr(0, bytes.size() / 2));
  std::string flipped_bytes = bytes;
  flipped_bytes[bytes.size() - 5] ^= 0x01;
  const std::string flipped = (dir.path() / "flipped.cidx").string();
  write_bytes(flipped, flipped_bytes);
  for (const std::string& bad : {truncated, flipped, mesh, std::string("/nonexistent.cidx")}) {
    const CliRun run = run_contain({"inside", "--index", bad}, kPoints);
    EXPECT_EQ(run.exit_code, 3) << bad;
    EXPECT_EQ(run.out, "") << bad;
    EXPECT_NE(run.err.find(bad), std::string::npos) << run.err;
  }
}

TEST(IndexCli, SavedLayerIndexAnswersWithTheLayersIds) {
  TempDir dir;
  const std::string layer = dir.write("squares.geojson",
                                      R"({"type": "FeatureCollection", "features": [
  {"type": "Feature", "properties": {"name": "west"},
   "geometry": {"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1],[0,1],[0,0]]]}},
  {"type": "Feature", "properties": {"name": "east"},
   "geometry": {"type": "Polygon", "coordinates": [[[1,0],[2,0],[2,1],[1,1],[1,0]]]}}]})");
  const std::string index = (dir.path() / "squares.cidx").string();
  const CliRun built =
      run_contain({"index", "build", "--layer", layer, "--id", "name", "--out", index});
  ASSERT_EQ(built.exit_code, 0) << built.err;
  const std::string points = "0.5 0.5\n1 0.5\n1.5 0.5\n3 3\n";
  const CliRun fresh = run_contain({"inside", "--layer", layer, "--id", "name"}, points);
  EXPECT_EQ(fresh.out, "west\nwest:on east:on\neast\n-\n");
  const CliRun alone = run_contain({"inside", "--index", index}, points);
  EXPECT_EQ(alone.exit_code, 0) << alone.err;
  EXPECT_EQ(alone.out, fresh.out);
  const CliRun checked =
      run_contain({"inside", "--layer", layer, "--id", "name", "--index", index}, points);
  EXPECT_EQ(checked.out, fresh.out) << checked.err;
  // Other ids than the index was built with: refused, as another layer would be.
  const CliRun other = run_contain({"inside", "--layer", layer, "--index", index}, points);
  EXPECT_EQ(other.exit_code, 3);
  EXPECT_NE(other.err.find("squares.cidx"), std::string::npos) << other.err;
  // A layer's index is not a mesh's.
  const std::string mesh = dir.write("cube.off", kCubeOff);
  EXPECT_EQ(run_contain({"inside", "--mesh", mesh, "--index", index}, kPoints).exit_code, 3);
}

TEST(IndexCli, SavedPolygonIndexAnswersAsThePolygonAndRefusesAnotherRegionOrFill) {
  TempDir dir;
  const std::string square =
      dir.write("square.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1))\n");
  const std::string other = dir.write("other.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))\n");
  const std::string index = (dir.path() / "square.cidx").string();
  ASSERT_EQ(run_contain({"index", "build", "--polygon", square, "--out", index}).exit_code, 0);
  const std::string points = "0.5 0.5\n2 2\n1 1\n4 2\n5 5\n1 2\n";
  const CliRun fresh = run_contain({"inside", "--polygon", square}, points);
  EXPECT_EQ(fresh.out, "in\nout\non\non\nout\non\n");
  EXPECT_EQ(run_contain({"inside", "--index", index}, points).out, fresh.out);
  EXPECT_EQ(run_contain({"inside", "--polygon", square, "--index", index}, points).out, fresh.out);
  const CliRun mismatch = run_contain({"inside", "--polygon", other, "--index", index}, points);
  EXPECT_EQ(mismatch.exit_code, 3);
  EXPECT_NE(mismatch.err.find("other.wkt"), std::string::npos) << mismatch.err;
  const CliRun fill = run_contain({"inside", "--index", index, "--fill", "nonzero"}, points);
  EXPECT_EQ(fill.exit_code, 3);
  EXPECT_NE(fill.err.find("--fill"), std::string::npos) << fill.err;
}

TEST(IndexCli, IndexBuildWithoutAShapeIsAUsageError) {
  TempDir dir;
  const CliRun run = run_contain({"index", "build", "--out", (dir.path() / "x").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--mesh"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace contain::test
