// Where a verb writes regions to --out, the file holds the format its extension names: never WKT
// in a file named .svg or .geojson (the trap issue 24 found in --tiles, closed for every verb).

#include <gtest/gtest.h>

#include <string>

#include "cli/cube_off.h"
#include "cli/run.h"

namespace contain::test {
namespace {

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.rfind(prefix, 0) == 0;
}

constexpr const char* kSquare = "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))\n";
constexpr const char* kShifted = "POLYGON ((1 1, 3 1, 3 3, 1 3, 1 1))\n";

TEST(OutputFormatCli, SliceWritesTheFormatOutsExtensionNames) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", cube_off(1.0));
  const std::string svg = (dir.path() / "layers.SVG").string();
  const std::string geojson = (dir.path() / "layers.geojson").string();
  const std::string wkt = (dir.path() / "layers.txt").string();
  for (const std::string& out : {svg, geojson, wkt}) {
    const CliRun run = run_contain({"slice", "--mesh", mesh, "--z", "0.5", "--out", out});
    ASSERT_EQ(run.exit_code, 0) << out << ": " << run.err;
  }
  EXPECT_TRUE(starts_with(read_text(svg), "<svg")) << read_text(svg);
  EXPECT_TRUE(starts_with(read_text(geojson), "{\"type\":\"FeatureCollection\""));
  EXPECT_TRUE(starts_with(read_text(wkt), "0.5\tMULTIPOLYGON")) << read_text(wkt);
}

TEST(OutputFormatCli, AFormatTheExtensionContradictsIsAUsageErrorNamingBoth) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", cube_off(1.0));
  const std::string out = (dir.path() / "layers.geojson").string();
  const CliRun run =
      run_contain({"slice", "--mesh", mesh, "--z", "0.5", "--format", "wkt", "--out", out});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--format wkt"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("layers.geojson"), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  // The same format spelt either way is no contradiction.
  EXPECT_EQ(
      run_contain({"slice", "--mesh", mesh, "--z", "0.5", "--format", "GeoJSON", "--out", out})
          .exit_code,
      0);
  const std::string subject = dir.write("a.wkt", kSquare);
  const std::string clip = dir.write("b.wkt", kShifted);
  const CliRun boolean = run_contain({"clip", "--subject", subject, "--clip", clip, "--op", "union",
                                      "--format", "svg", "--out", (dir.path() / "u.wkt").string()});
  EXPECT_EQ(boolean.exit_code, 2);
  EXPECT_NE(boolean.err.find("names wkt"), std::string::npos) << boolean.err;
}

TEST(OutputFormatCli, SliceJsonLinesGoToAJsonFileOrStdoutNotToARegionFormatsFile) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", cube_off(1.0));
  const CliRun svg = run_contain(
      {"slice", "--mesh", mesh, "--z", "0.5", "--json", "--out", (dir.path() / "s.svg").string()});
  EXPECT_EQ(svg.exit_code, 2);
  EXPECT_NE(svg.err.find("--json"), std::string::npos) << svg.err;
  const std::string json = (dir.path() / "s.json").string();
  const CliRun lines =
      run_contain({"slice", "--mesh", mesh, "--z", "0.5", "--json", "--out", json});
  ASSERT_EQ(lines.exit_code, 0) << lines.err;
  EXPECT_TRUE(starts_with(read_text(json), "{\"value\":0.5,\"wkt\":\"MULTIPOLYGON"));
}

TEST(OutputFormatCli, PolygonBooleansAndPolygonClippingFollowOutsExtension) {
  TempDir dir;
  const std::string subject = dir.write("a.wkt", kSquare);
  const std::string clip = dir.write("b.wkt", kShifted);
  const std::string svg = (dir.path() / "union.svg").string();
  ASSERT_EQ(
      run_contain({"clip", "--subject", subject, "--clip", clip, "--op", "union", "--out", svg})
          .exit_code,
      0);
  EXPECT_TRUE(starts_with(read_text(svg), "<svg"));
  const std::string geojson = (dir.path() / "cut.geojson").string();
  const CliRun cut =
      run_contain({"clip", "--polygon", subject, "--box", "0,0,1,1", "--out", geojson});
  ASSERT_EQ(cut.exit_code, 0) << cut.err;
  EXPECT_EQ(read_text(geojson),
            "{\"type\":\"Polygon\",\"coordinates\":[[[0,1],[0,0],[1,0],[1,1],[0,1]]]}\n");
  const std::string text = (dir.path() / "cut.txt").string();
  ASSERT_EQ(
      run_contain({"clip", "--polygon", subject, "--box", "0,0,1,1", "--out", text}).exit_code, 0);
  EXPECT_EQ(read_text(text), "POLYGON ((0 1, 0 0, 1 0, 1 1, 0 1))\n");
  const std::string picture = (dir.path() / "cut.svg").string();
  ASSERT_EQ(
      run_contain({"clip", "--polygon", subject, "--box", "0,0,1,1", "--out", picture}).exit_code,
      0);
  EXPECT_TRUE(starts_with(read_text(picture), "<svg"));
}

TEST(OutputFormatCli, NegativeThreadCountsAreUsageErrorsInPlainWords) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", cube_off(1.0));
  const std::string region = dir.write("a.wkt", kSquare);
  for (const auto& args :
       {std::vector<std::string>{"slice", "--mesh", mesh, "--z", "0.5", "--threads", "-1"},
        std::vector<std::string>{"inside", "--polygon", region, "--threads", "-3"}}) {
    const CliRun run = run_contain(args, "1 1\n");
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find("--threads: must be 0 (every core) or a positive count"),
              std::string::npos)
        << run.err;
    EXPECT_EQ(run.err.find("1797693"), std::string::npos) << run.err;
  }
}

TEST(OutputFormatCli, LayersFromAboveToGiveNoPlaneAndSaySo) {
  TempDir dir;
  const std::string mesh = dir.write("cube.off", cube_off(1.0));
  const CliRun run = run_contain({"slice", "--mesh", mesh, "--layers", "1,0.1,0"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_TRUE(run.out.empty());
  EXPECT_NE(run.err.find("no planes"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace contain::test
