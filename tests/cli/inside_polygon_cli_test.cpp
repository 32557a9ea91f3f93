// contain inside --polygon, end to end, per ../shared/spec/cli.md.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "cli/run.h"

namespace contain::test {
namespace {

const char* const square_with_hole =
    "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))\n";

TEST(InsidePolygonCli, PrintsInOnOutOnePerPointInInputOrder) {
  TempDir dir;
  const std::string region = dir.write("r.wkt", square_with_hole);
  const std::string points = dir.write("p.txt", "0.5 0.5\n2 2\n4 2\n5,5\n1 2\n");
  const CliRun run = run_contain({"inside", "--polygon", region, "--points", points});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "in\nout\non\nout\non\n");
}

// One thread writes the answers in pieces of 64 K from one reused buffer, several threads in
// parts of a block: 200,003 answers (three whole pieces and a partial one) of every kind and
// length, in a pattern that a piece written twice, dropped or out of order would break, are the
// same text either way, on stdout and into --out.
TEST(InsidePolygonCli, ManyAnswersAreWrittenInOrderWhateverTheThreadsAndTheDestination) {
  TempDir dir;
  const std::string region = dir.write("r.wkt", square_with_hole);
  const char* const kinds[] = {"0.5 0.5\n", "2 2\n", "4 2\n", "5 5\n", "1 2\n", "3.5 3.5\n"};
  const char* const answers[] = {"in\n", "out\n", "on\n", "out\n", "on\n", "in\n"};
  std::string text, expected;
  for (int i = 0; i < 200003; ++i) {
    const int k = (i * 7 + i / 65536) % 6;
    text += kinds[k];
    expected += answers[k];
  }
  const std::string points = dir.write("p.txt", text);
  for (const char* threads : {"1", "2"}) {
    const CliRun run =
        run_contain({"inside", "--polygon", region, "--points", points, "--threads", threads});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(run.out == expected) << "threads " << threads;
    const std::string out = (dir.path() / (std::string("a") + threads + ".txt")).string();
    const CliRun to_file = run_contain(
        {"inside", "--polygon", region, "--points", points, "--threads", threads, "--out", out});
    EXPECT_EQ(to_file.exit_code, 0) << to_file.err;
    EXPECT_TRUE(read_text(out) == expected) << "threads " << threads;
  }
}

TEST(InsidePolygonCli, SkipsBlankAndCommentLinesWithoutOutput) {
  TempDir dir;
  const std::string region = dir.write("r.wkt", square_with_hole);
  const CliRun run = run_contain({"inside", "--polygon", region}, "# header\n\n0.5 0.5\n\n2 2\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "in\nout\n");
}

TEST(InsidePolygonCli, BoundaryPolicyFoldsOnIntoInOrOut) {
  TempDir dir;
  const std::string region = dir.write("r.wkt", square_with_hole);
  const std::string points = dir.write("p.txt", "4 2\n0 0\n");
  EXPECT_EQ(
      run_contain({"inside", "--polygon", region, "--points", points, "--boundary", "inside"}).out,
      "in\nin\n");
  EXPECT_EQ(
      run_contain({"inside", "--polygon", region, "--points", points, "--boundary", "outside"}).out,
      "out\nout\n");
}

TEST(InsidePolygonCli, FillRuleDecidesTheOverlapOfTwoSameDirectionRings) {
  TempDir dir;
  // Two counter-clockwise squares overlapping in [1,2]^2: winding 2 there.
  const std::string region =
      dir.write("r.wkt", "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)), ((1 1, 3 1, 3 3, 1 3, 1 1)))");
  const std::string points = dir.write("p.txt", "1.5 1.5\n0.5 0.5\n");
  EXPECT_EQ(run_contain({"inside", "--polygon", region, "--points", points}).out, "out\nin\n");
  EXPECT_EQ(
      run_contain({"inside", "--polygon", region, "--points", points, "--fill", "nonzero"}).out,
      "in\nin\n");
}

TEST(InsidePolygonCli, ReadsGeoJsonRegions) {
  TempDir dir;
  const std::string region = dir.write(
      "r.geojson",
      R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,1],[0,0]]]}})");
  const CliRun run = run_contain({"inside", "--polygon", region}, "0.5 0.5\n1 1\n2 0\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "in\non\nout\n");
}

TEST(InsidePolygonCli, ThreadCountDoesNotChangeTheAnswers) {
  TempDir dir;
  const std::string region = dir.write("r.wkt", square_with_hole);
  std::string points;
  for (int i = 0; i <= 200; ++i) {
    for (int j = 0; j <= 50; ++j)
      points += std::to_string(i * 0.025) + " " + std::to_string(j * 0.1) + "\n";
  }
  const std::string file = dir.write("p.txt", points);
  const CliRun one =
      run_contain({"inside", "--polygon", region, "--points", file, "--threads", "1"});
  const CliRun two =
      run_contain({"inside", "--polygon", region, "--points", file, "--threads", "2"});
  EXPECT_EQ(one.exit_code, 0);
  EXPECT_EQ(one.out, two.out);
}

TEST(InsidePolygonCli, WritesToOutFileAndNothingOnStdout) {
  TempDir dir;
  const std::string region = dir.write("r.wkt", square_with_hole);
  const std::string out = (dir.path() / "answers.txt").string();
  const CliRun run = run_contain({"inside", "--polygon", region, "--out", out}, "0.5 0.5\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.out.empty());
  std::ifstream in(out);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "in\n");
}

TEST(InsidePolygonCli, ThreeDimensionalPointsAreBadInputNamingTheLine) {
  TempDir dir;
  const std::string region = dir.write("r.wkt", square_with_hole);
  const std::string points = dir.write("p.txt", "0.5 0.5\n1 2 3\n");
  const CliRun run = run_contain({"inside", "--polygon", region, "--points", points});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(run.out.empty());
  EXPECT_NE(run.err.find("p.txt:2"), std::string::npos) << run.err;
}

TEST(InsidePolygonCli, NaNCoordinateIsBadInput) {
  TempDir dir;
  const std::string region = dir.write("r.wkt", square_with_hole);
  const CliRun run = run_contain({"inside", "--polygon", region}, "nan 1\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("<stdin>:1"), std::string::npos) << run.err;
}

// The forms a point file may take (CR LF, comments after the numbers, blank lines, commas, no
// final newline) give the answers of the plain file, from a file or from standard input, on 1 and
// 2 threads; a bad line late in the file is exit 3 naming its line, with no answer printed.
TEST(InsidePolygonCli, EveryPointFileFormGivesThePlainFilesAnswersAndBadLinesTheirLine) {
  TempDir dir;
  const std::string region = dir.write("r.wkt", square_with_hole);
  std::string plain;
  std::string dressed = "# x y\r\n";
  for (int i = 0; i < 300; ++i) {
    const std::string x = std::to_string(i % 9 * 0.5), y = std::to_string(i % 7 * 0.75);
    plain += x + " " + y + "\n";
    dressed += i % 5 == 0 ? "\r\n  \t\n" : "";
    dressed += i % 3 == 0 ? x + " , " + y + " # p\r\n" : "\t" + x + "\t" + y + "\r\n";
  }
  dressed.resize(dressed.size() - 2);  // no final line end
  const CliRun expected =
      run_contain({"inside", "--polygon", region, "--points", dir.write("plain.txt", plain)});
  ASSERT_EQ(expected.exit_code, 0) << expected.err;
  const std::string file = dir.write("dressed.txt", dressed);
  for (const char* threads : {"1", "2"}) {
    const CliRun run =
        run_contain({"inside", "--polygon", region, "--points", file, "--threads", threads});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, expected.out) << threads;
    const CliRun piped = run_contain(
        {"inside", "--polygon", region, "--points", "-", "--threads", threads}, dressed);
    EXPECT_EQ(piped.out, expected.out) << threads;
  }
  for (const char* bad : {"1 nan", "inf 1", "1 2x", "1 2,", "1e999 0"}) {
    const CliRun run = run_contain(
        {"inside", "--polygon", region, "--points", dir.write("bad.txt", plain + bad + "\n0 0\n")});
    EXPECT_EQ(run.exit_code, 3) << bad;
    EXPECT_TRUE(run.out.empty()) << bad;
    EXPECT_NE(run.err.find("bad.txt:301"), std::string::npos) << bad << ": " << run.err;
  }
}

TEST(InsidePolygonCli, MalformedWktIsBadInputNamingFileAndLine) {
  TempDir dir;
  const std::string region = dir.write("bad.wkt", "POLYGON ((0 0, 1 0,\n 1 x, 0 0))");
  const CliRun run = run_contain({"inside", "--polygon", region}, "0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("bad.wkt:2"), std::string::npos) << run.err;
}

TEST(InsidePolygonCli, UnknownFillRuleIsAUsageError) {
  TempDir dir;
  const std::string region = dir.write("r.wkt", square_with_hole);
  EXPECT_EQ(run_contain({"inside", "--polygon", region, "--fill", "sometimes"}, "0 0\n").exit_code,
            2);
}

TEST(InsidePolygonCli, PolygonAndCsgTogetherIsAUsageError) {
  EXPECT_EQ(run_contain({"inside", "--polygon", "a.wkt", "--csg", "b.json"}).exit_code, 2);
}

}  // namespace
}  // namespace contain::test
