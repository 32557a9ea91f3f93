// contain bound, end to end, per ../shared/spec/cli.md.

#include <gtest/gtest.h>

#include "cli/run.h"

namespace contain::test {
namespace {

const char* const unit_cube_off =
    "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n"
    "3 3 0 4\n3 3 4 7\n";

TEST(BoundCli, PrintsTheAabbAndMinimalSphereOfAMeshAsJson) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", unit_cube_off);
  const CliRun run = run_contain({"bound", mesh});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out.rfind("{\"aabb\":{\"min\":[0,0,0],\"max\":[1,1,1]},\"sphere\":{\"center\":[0.5,"
                          "0.5,0.5],\"radius\":0.866025403784438",
                          0),
            0u)
      << run.out;
}

TEST(BoundCli, RitterSphereIsAtLeastTheMinimalOne) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", unit_cube_off);
  const CliRun run = run_contain({"bound", mesh, "--sphere", "ritter"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const auto at = run.out.find("\"radius\":");
  ASSERT_NE(at, std::string::npos);
  EXPECT_GE(std::stod(run.out.substr(at + 9)), 0.8660254037844386);
}

TEST(BoundCli, RegionFileGivesABoxAndACircle) {
  TempDir dir;
  const std::string region = dir.write("r.wkt", "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))");
  const CliRun run = run_contain({"bound", region});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out.rfind("{\"aabb\":{\"min\":[0,0],\"max\":[2,2]},\"circle\":{\"center\":[1,1],"
                          "\"radius\":1.414213562373095",
                          0),
            0u)
      << run.out;
}

TEST(BoundCli, MeshWithAnIndexOutOfRangeIsBadInputNamingTheLine) {
  TempDir dir;
  const std::string mesh = dir.write("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  const CliRun run = run_contain({"bound", mesh});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("bad.off:6"), std::string::npos) << run.err;
}

TEST(BoundCli, UnknownSphereMethodIsAUsageError) {
  EXPECT_EQ(run_contain({"bound", "x.off", "--sphere", "best"}).exit_code, 2);
}

TEST(BoundCli, UnknownExtensionIsBadInput) {
  TempDir dir;
  const std::string file = dir.write("mesh.xyz", "1 2 3\n");
  const CliRun run = run_contain({"bound", file});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find(".xyz"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace contain::test
