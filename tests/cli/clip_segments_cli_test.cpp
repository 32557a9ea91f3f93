// contain clip --segments, end to end, per ../shared/spec/cli.md.

#include <gtest/gtest.h>

#include "cli/run.h"

namespace contain::test {
namespace {

TEST(ClipSegmentsCli, BoxPrintsClippedEndpointsOrDashInInputOrder) {
  const std::string input = "-2 0.5 2 0.5\n# comment\n5 5 6 6\n0 0 0.5 0.5\n-1 1 1 -1\n";
  for (const char* algorithm : {"", "cohen-sutherland", "liang-barsky", "cyrus-beck"}) {
    std::vector<std::string> args = {"clip", "--segments", "-", "--box", "0,0,1,1"};
    if (*algorithm != '\0') {
      args.push_back("--algorithm");
      args.push_back(algorithm);
    }
    const CliRun run = run_contain(args, input);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, "0 0.5 1 0.5\n-\n0 0 0.5 0.5\n0 0 0 0\n") << algorithm;
  }
}

TEST(ClipSegmentsCli, QuietIsAcceptedAndManySegmentsKeepTheirOrder) {
  // More segments than a progress chunk (4096, used when stderr is a terminal); --quiet, as in
  // the other verbs, turns progress off and leaves stderr empty.
  std::string input;
  std::string want;
  for (int i = 0; i < 10000; ++i) {
    input += i % 2 == 0 ? "-2 0.5 2 0.5\n" : "5 5 6 6\n";
    want += i % 2 == 0 ? "0 0.5 1 0.5\n" : "-\n";
  }
  for (const char* algorithm : {"", "liang-barsky"}) {
    std::vector<std::string> args = {"clip", "--segments", "-", "--box", "0,0,1,1", "--quiet"};
    if (*algorithm != '\0') {
      args.push_back("--algorithm");
      args.push_back(algorithm);
    }
    const CliRun run = run_contain(args, input);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    EXPECT_EQ(run.out, want) << algorithm;
  }
}

TEST(ClipSegmentsCli, ThreeDimensionalBoxSphereAndHalfspace) {
  TempDir dir;
  const std::string file = dir.write("s.txt", "-2 0 0 2 0 0\n0 2 0 2 2 0\n");
  CliRun run = run_contain({"clip", "--segments", file, "--box", "-1,-1,-1,1,1,1"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "-1 0 0 1 0 0\n-\n");
  run = run_contain({"clip", "--segments", file, "--sphere", "0,0,0,1"});
  EXPECT_EQ(run.out, "-1 0 0 1 0 0\n-\n");
  run = run_contain({"clip", "--segments", file, "--halfspace=1,0,0,-1"});
  EXPECT_EQ(run.out, "1 0 0 2 0 0\n1 2 0 2 2 0\n");
}

TEST(ClipSegmentsCli, TangentToTheCircleGivesAZeroLengthSegment) {
  const CliRun run = run_contain({"clip", "--segments", "-", "--circle", "0,0,1"}, "-2 1 2 1\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "0 1 0 1\n");
}

TEST(ClipSegmentsCli, ConvexPolygonFile) {
  TempDir dir;
  const std::string tri = dir.write("t.wkt", "POLYGON ((0 0, 4 0, 0 4, 0 0))");
  const CliRun run = run_contain({"clip", "--segments", "-", "--convex", tri}, "-1 1 5 1\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "0 1 3 1\n");
}

TEST(ClipSegmentsCli, BadInputExitsWith3AndUsageErrorsWith2) {
  EXPECT_EQ(run_contain({"clip", "--segments", "-", "--box", "0,0,1,1"}, "0 0 nan 1\n").exit_code,
            3);
  EXPECT_EQ(run_contain({"clip", "--segments", "-", "--box", "0,0,1,1"}, "0 0 1\n").exit_code, 3);
  EXPECT_EQ(run_contain({"clip", "--segments", "-", "--box", "0,0,0,1,1,1"}, "0 0 1 1\n").exit_code,
            2);
  EXPECT_EQ(run_contain({"clip", "--segments", "-"}, "0 0 1 1\n").exit_code, 2);
  EXPECT_EQ(run_contain({"clip", "--segments", "-", "--box", "0,0,1,1", "--algorithm", "magic"}, "")
                .exit_code,
            2);
}

}  // namespace
}  // namespace contain::test
