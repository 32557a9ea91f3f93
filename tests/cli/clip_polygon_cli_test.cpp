// contain clip --polygon, end to end.

#include <gtest/gtest.h>

#include "cli/run.h"

namespace contain::test {
namespace {

const char* const u_shape = "POLYGON ((0 0, 3 0, 3 3, 2 3, 2 1, 1 1, 1 3, 0 3, 0 0))";

TEST(ClipPolygonCli, ConcavePolygonComesApartIntoAMultipolygon) {
  TempDir dir;
  const std::string file = dir.write("u.wkt", u_shape);
  const CliRun run = run_contain({"clip", "--polygon", file, "--halfspace=0,1,-2"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "MULTIPOLYGON (((3 2, 3 3, 2 3, 2 2, 3 2)), ((1 2, 1 3, 0 3, 0 2, 1 2)))\n");
}

TEST(ClipPolygonCli, KeepBridgesWritesTheSectionsSingleRing) {
  TempDir dir;
  const std::string file = dir.write("u.wkt", u_shape);
  const CliRun run =
      run_contain({"clip", "--polygon", file, "--halfspace=0,1,-2", "--keep-bridges"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "POLYGON ((0 2, 3 2, 3 3, 2 3, 2 2, 1 2, 1 3, 0 3, 0 2))\n");
}

TEST(ClipPolygonCli, BoxAndRepeatedHalfspacesAndEmptyResult) {
  TempDir dir;
  const std::string file =
      dir.write("f.wkt", "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 8, 8 8, 8 2, 2 2))");
  CliRun run = run_contain({"clip", "--polygon", file, "--box", "1,1,9,9"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "POLYGON ((1 1, 9 1, 9 9, 1 9, 1 1), (2 2, 2 8, 8 8, 8 2, 2 2))\n");
  run = run_contain({"clip", "--polygon", file, "--halfspace=1,0,-1", "--halfspace=-1,0,9",
                     "--halfspace=0,1,-1", "--halfspace=0,-1,9"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("(2 2, 2 8, 8 8, 8 2, 2 2)"), std::string::npos) << run.out;
  run = run_contain({"clip", "--polygon", file, "--box", "3,3,4,4"});
  EXPECT_EQ(run.out, "POLYGON EMPTY\n");
}

TEST(ClipPolygonCli, ConvexClipRegionAndOutputFile) {
  TempDir dir;
  const std::string file = dir.write("sq.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))");
  const std::string window = dir.write("w.wkt", "POLYGON ((2 -1, 6 -1, 6 6, 2 6, 2 -1))");
  const std::string out = (dir.path() / "r.wkt").string();
  const CliRun run = run_contain({"clip", "--polygon", file, "--convex", window, "--out", out});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  const CliRun check =
      run_contain({"inside", "--polygon", out, "--points", "-"}, "3 1\n1 1\n2 1\n");
  EXPECT_EQ(check.out, "in\nout\non\n");
}

TEST(ClipPolygonCli, MalformedPolygonExitsWith3) {
  TempDir dir;
  const std::string file = dir.write("bad.wkt", "POLYGON ((0 0, 1 0");
  EXPECT_EQ(run_contain({"clip", "--polygon", file, "--box", "0,0,1,1"}).exit_code, 3);
}

TEST(ClipPolygonCli, TilesGiveOneLinePerTileOrOneFilePerTile) {
  TempDir dir;
  const std::string file =
      dir.write("f.wkt", "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (2 3, 2 6, 4 6, 4 3, 2 3))");
  CliRun run = run_contain({"clip", "--polygon", file, "--tiles", "2,2", "--threads", "2"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out,
            "0 0 POLYGON ((0 5, 0 0, 5 0, 5 5, 4 5, 4 3, 2 3, 2 5, 0 5))\n"
            "1 0 POLYGON ((5 0, 10 0, 10 5, 5 5, 5 0))\n"
            "0 1 POLYGON ((5 10, 0 10, 0 5, 2 5, 2 6, 4 6, 4 5, 5 5, 5 10))\n"
            "1 1 POLYGON ((10 5, 10 10, 5 10, 5 5, 10 5))\n");
  // A grid over --box; tiles outside the region are empty.
  run = run_contain({"clip", "--polygon", file, "--tiles", "3,1", "--box", "10,0,13,10"});
  EXPECT_EQ(run.out, "0 0 POLYGON EMPTY\n1 0 POLYGON EMPTY\n2 0 POLYGON EMPTY\n");
  const std::string pattern = (dir.path() / "t_{column}_{row}.wkt").string();
  run = run_contain({"clip", "--polygon", file, "--tiles", "2,1", "--out", pattern});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  const CliRun check = run_contain(
      {"inside", "--polygon", (dir.path() / "t_1_0.wkt").string(), "--points", "-"}, "7 5\n3 5\n");
  EXPECT_EQ(check.out, "in\nout\n");
  run = run_contain({"clip", "--polygon", file, "--tiles", "0,2"});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("--tiles"), std::string::npos) << run.err;
  run = run_contain({"clip", "--polygon", file, "--tiles", "2,2", "--halfspace", "1,0,0"});
  EXPECT_EQ(run.exit_code, 2);
}

}  // namespace
}  // namespace contain::test
