// contain inside --mesh, end to end, per ../shared/spec/cli.md.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "cli/run.h"

namespace contain::test {
namespace {

// The unit cube [0,1]^3, outward.
const char* const kCube =
    "OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
    "3 0 2 1\n3 1 2 3\n3 4 5 6\n3 5 7 6\n3 0 1 4\n3 1 5 4\n"
    "3 2 6 3\n3 3 6 7\n3 0 4 2\n3 2 4 6\n3 1 3 5\n3 3 7 5\n";

TEST(InsideMeshCli, ClosedCubeAnswersInOnOutExactly) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", kCube);
  const CliRun run = run_contain({"inside", "--mesh", mesh},
                                 "0.5 0.5 0.5\n1 0.5 0.5\n1 1 1\n2 0 0\n# comment\n\n"
                                 "0.5,0.5,1.0000000000000002\n0 0.25 0.75\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "in\non\non\nout\nout\non\n");
  EXPECT_EQ(run.err, "") << "a closed manifold needs no warning";
}

TEST(InsideMeshCli, BoundaryPolicyFoldsOnAndThreadsChangeNothing) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", kCube);
  const std::string points = dir.write("p.txt", "1 0.5 0.5\n0.5 0.5 0.5\n3 3 3\n");
  EXPECT_EQ(run_contain({"inside", "--mesh", mesh, "--points", points, "--boundary", "inside"}).out,
            "in\nin\nout\n");
  EXPECT_EQ(
      run_contain({"inside", "--mesh", mesh, "--points", points, "--boundary", "outside"}).out,
      "out\nin\nout\n");
  EXPECT_EQ(run_contain({"inside", "--mesh", mesh, "--points", points, "--threads", "2"}).out,
            "on\nin\nout\n");
}

TEST(InsideMeshCli, OpenMeshWarnsOnStderrAndUsesTheWindingNumber) {
  TempDir dir;
  // The cube without its top face (z = 1): 4 border edges.
  const std::string mesh = dir.write(
      "open.obj",
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
      "f 1 3 2\nf 2 3 4\nf 1 2 5\nf 2 6 5\nf 3 7 4\nf 4 7 8\nf 1 5 3\nf 3 5 7\nf 2 4 6\nf 4 8 6\n");
  const std::string out = (dir.path() / "answers.txt").string();
  const CliRun run =
      run_contain({"inside", "--mesh", mesh, "--out", out}, "0.5 0.5 0.3\n0.5 0.5 2\n0 0.5 0.5\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "");
  EXPECT_NE(run.err.find("4 border edges"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("winding number"), std::string::npos) << run.err;
  std::ifstream in(out);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(written, "in\nout\non\n");
}

TEST(InsideMeshCli, MissingOrMalformedMeshIsBadInputNamingTheFile) {
  TempDir dir;
  const CliRun missing = run_contain({"inside", "--mesh", (dir.path() / "none.off").string()}, "");
  EXPECT_EQ(missing.exit_code, 3);
  EXPECT_NE(missing.err.find("none.off"), std::string::npos) << missing.err;
  const std::string bad = dir.write("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 x\n0 1 0\n3 0 1 2\n");
  const CliRun malformed = run_contain({"inside", "--mesh", bad}, "0 0 0\n");
  EXPECT_EQ(malformed.exit_code, 3);
  EXPECT_NE(malformed.err.find("bad.off:4"), std::string::npos) << malformed.err;
  const std::string cube = dir.write("cube.off", kCube);
  const CliRun flat = run_contain({"inside", "--mesh", cube}, "0.5 0.5\n");
  EXPECT_EQ(flat.exit_code, 3) << "2D points for a 3D solid";
}

TEST(InsideMeshCli, MeshExcludesTheOtherRegions) {
  TempDir dir;
  const std::string cube = dir.write("cube.off", kCube);
  const CliRun run = run_contain({"inside", "--mesh", cube, "--polygon", "x.wkt"}, "");
  EXPECT_EQ(run.exit_code, 2);
}

}  // namespace
}  // namespace contain::test
