// contain clip --mesh, end to end.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "cli/run.h"

namespace contain::test {
namespace {

const char* const kClipCubeOff =
    "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n"
    "3 3 0 4\n3 3 4 7\n";

TEST(ClipMeshCli, CappedCutIsAClosedSolidOnStdoutAsOff) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", kClipCubeOff);
  const CliRun run = run_contain({"clip", "--mesh", mesh, "--halfspace=0,0,1,-0.5", "--cap"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  ASSERT_EQ(run.out.rfind("OFF\n", 0), 0u) << run.out;
  // The result is a closed solid: its bound is the upper half-box.
  const std::string half = dir.write("half.off", run.out);
  const CliRun bound = run_contain({"bound", half});
  EXPECT_EQ(bound.out.rfind("{\"aabb\":{\"min\":[0,0,0.5],\"max\":[1,1,1]}", 0), 0u) << bound.out;
  const CliRun probe = run_contain({"inside", "--mesh", half, "--points", "-"},
                                   "0.5 0.5 0.75\n0.5 0.5 0.25\n0.5 0.5 0.5\n");
  EXPECT_EQ(probe.out, "in\nout\non\n") << probe.err;
}

TEST(ClipMeshCli, BoxWithOutFileInTheFormatOfItsExtension) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", kClipCubeOff);
  const std::string out = (dir.path() / "small.obj").string();
  const CliRun run =
      run_contain({"clip", "--mesh", mesh, "--box", "0.5,0.5,0.5,2,2,2", "--cap", "--out", out});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("v 0.5 0.5 0.5"), std::string::npos) << text.str();
}

TEST(ClipMeshCli, CapOfAnOpenMeshExitsWith3) {
  TempDir dir;
  const std::string mesh = dir.write("tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(run_contain({"clip", "--mesh", mesh, "--halfspace=1,0,0,-0.5", "--cap"}).exit_code, 3);
  const CliRun open = run_contain({"clip", "--mesh", mesh, "--halfspace=1,0,0,-0.5"});
  EXPECT_EQ(open.exit_code, 0) << open.err;
  EXPECT_NE(open.out.find("0.5 0 0"), std::string::npos) << open.out;
}

}  // namespace
}  // namespace contain::test
