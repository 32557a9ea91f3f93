// contain clip --subject/--clip/--op (polygon booleans), end to end, per ../shared/spec/cli.md.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "cli/run.h"

namespace contain::test {
namespace {

const char* const square_a = "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))\n";
const char* const square_b = "POLYGON ((1 1, 3 1, 3 3, 1 3, 1 1))\n";

CliRun boolean(const TempDir& dir, const std::string& op, std::vector<std::string> extra = {}) {
  std::vector<std::string> args{
      "clip", "--subject", dir.write("a.wkt", square_a), "--clip", dir.write("b.wkt", square_b),
      "--op", op};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_contain(args);
}

TEST(ClipBooleanCli, EachOpPrintsOneValidWktGeometry) {
  TempDir dir;
  const CliRun i = boolean(dir, "intersection");
  EXPECT_EQ(i.exit_code, 0) << i.err;
  EXPECT_EQ(i.out, "POLYGON ((2 2, 1 2, 1 1, 2 1, 2 2))\n");
  const CliRun u = boolean(dir, "union");
  EXPECT_EQ(u.out, "POLYGON ((0 0, 2 0, 2 1, 3 1, 3 3, 1 3, 1 2, 0 2, 0 0))\n");
  const CliRun d = boolean(dir, "difference");
  EXPECT_EQ(d.out, "POLYGON ((0 0, 2 0, 2 1, 1 1, 1 2, 0 2, 0 0))\n");
  const CliRun x = boolean(dir, "xor");
  EXPECT_EQ(x.out.rfind("MULTIPOLYGON (((", 0), 0u) << x.out;
}

TEST(ClipBooleanCli, DisjointIntersectionIsEmpty) {
  TempDir dir;
  const std::string a = dir.write("a.wkt", square_a);
  const std::string far = dir.write("f.wkt", "POLYGON ((5 5, 6 5, 6 6, 5 6, 5 5))\n");
  const CliRun run = run_contain({"clip", "--subject", a, "--clip", far, "--op", "intersection"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "MULTIPOLYGON EMPTY\n");
}

TEST(ClipBooleanCli, FillRuleReadsSelfOverlappingRings) {
  TempDir dir;
  // Two counter-clockwise squares in one MULTIPOLYGON, overlapping in [1,2]^2.
  const std::string two = dir.write(
      "two.wkt", "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)), ((1 1, 3 1, 3 3, 1 3, 1 1)))\n");
  const std::string big = dir.write("big.wkt", "POLYGON ((-9 -9, 9 -9, 9 9, -9 9, -9 -9))\n");
  const CliRun even = run_contain(
      {"clip", "--subject", two, "--clip", big, "--op", "intersection", "--fill", "evenodd"});
  EXPECT_EQ(even.exit_code, 0) << even.err;
  EXPECT_EQ(even.out.rfind("MULTIPOLYGON", 0), 0u) << even.out;  // the overlap is left out
  const CliRun nonzero = run_contain(
      {"clip", "--subject", two, "--clip", big, "--op", "intersection", "--fill", "nonzero"});
  EXPECT_EQ(nonzero.out, "POLYGON ((0 0, 2 0, 2 1, 3 1, 3 3, 1 3, 1 2, 0 2, 0 0))\n");
}

TEST(ClipBooleanCli, GeoJsonAndSvgFormatsAndOutFile) {
  TempDir dir;
  const CliRun g = boolean(dir, "intersection", {"--format", "geojson"});
  EXPECT_EQ(g.exit_code, 0) << g.err;
  EXPECT_EQ(g.out.rfind("{\"type\":\"Polygon\"", 0), 0u) << g.out;
  const CliRun s = boolean(dir, "union", {"--format", "svg"});
  EXPECT_EQ(s.exit_code, 0) << s.err;
  EXPECT_NE(s.out.find("<svg"), std::string::npos);
  const std::string out = (dir.path() / "r.wkt").string();
  const CliRun f = boolean(dir, "difference", {"--out", out});
  EXPECT_EQ(f.exit_code, 0) << f.err;
  EXPECT_TRUE(f.out.empty());
  std::ifstream in(out);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "POLYGON ((0 0, 2 0, 2 1, 1 1, 1 2, 0 2, 0 0))\n");
}

TEST(ClipBooleanCli, BadInputExitsThreeAndUsageErrorsExitTwo) {
  TempDir dir;
  const std::string a = dir.write("a.wkt", square_a);
  const std::string bad = dir.write("bad.wkt", "POLYGON ((0 0, 1 0, nan 1, 0 0))\n");
  EXPECT_EQ(run_contain({"clip", "--subject", a, "--clip", bad, "--op", "union"}).exit_code, 3);
  EXPECT_EQ(
      run_contain({"clip", "--subject", a, "--clip", "missing.wkt", "--op", "union"}).exit_code, 3);
  EXPECT_EQ(run_contain({"clip", "--subject", a, "--clip", a, "--op", "merge"}).exit_code, 2);
  EXPECT_EQ(run_contain({"clip", "--subject", a, "--op", "union"}).exit_code, 2);
}

}  // namespace
}  // namespace contain::test
