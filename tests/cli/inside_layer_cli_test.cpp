// contain inside --layer, end to end, per ../shared/spec/cli.md ("Many shapes at once").

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "cli/layer_data.h"
#include "cli/run.h"

namespace contain::test {
namespace {

// Replaces each name of the layer by its position (the ids of a layer without names).
std::string names_to_positions(std::string text) {
  const std::vector<std::string> names{"s00", "s10", "s20",  "s01",    "s11", "s21",
                                       "ovA", "ovB", "land", "island", "lake"};
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    bool replaced = false;
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (text.compare(i, names[k].size(), names[k]) == 0) {
        out += std::to_string(k);
        i += names[k].size();
        replaced = true;
        break;
      }
    }
    if (!replaced) out += text[i++];
  }
  return out;
}

TEST(InsideLayerCli, PrintsTheIdsOfTheHoldingRegionsInFileOrderWithOnAndDash) {
  TempDir dir;
  const std::string layer = dir.write("layer.geojson", layer_geojson());
  const std::string points = dir.write("p.txt", case_points());
  const CliRun run = run_contain({"inside", "--layer", layer, "--id", "name", "--points", points});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, expected_by_name());
  EXPECT_EQ(run.err, "");
}

TEST(InsideLayerCli, BoundaryPolicyWritesOnAsPlainIdsOrLeavesThemOut) {
  TempDir dir;
  const std::string layer = dir.write("layer.geojson", layer_geojson());
  const std::string points = dir.write("p.txt", "1 1\n14 13\n0.5 0.5\n3 2\n");
  const CliRun inside = run_contain(
      {"inside", "--layer", layer, "--id", "name", "--points", points, "--boundary", "inside"});
  EXPECT_EQ(inside.exit_code, 0) << inside.err;
  EXPECT_EQ(inside.out, "s00 s10 s01 s11\novA ovB\ns00\ns21\n");
  const CliRun outside = run_contain(
      {"inside", "--layer", layer, "--id", "name", "--points", points, "--boundary", "outside"});
  EXPECT_EQ(outside.out, "-\novB\ns00\n-\n");
}

TEST(InsideLayerCli, IdsArePositionsWithoutNamesAndNumbersAsWritten) {
  TempDir dir;
  const std::string layer = dir.write("layer.geojson", layer_geojson());
  const std::string points = dir.write("p.txt", case_points());
  const CliRun by_position = run_contain({"inside", "--layer", layer, "--points", points});
  EXPECT_EQ(by_position.exit_code, 0) << by_position.err;
  EXPECT_EQ(by_position.out, names_to_positions(expected_by_name()));
  const CliRun by_code =
      run_contain({"inside", "--layer", layer, "--id", "code", "--points", points});
  EXPECT_EQ(by_code.out.substr(0, 4), "100\n");
  // Feature "id" members are the ids when every feature has one.
  const std::string with_ids = dir.write("ids.geojson", R"({"type":"FeatureCollection","features":[
      {"type":"Feature","id":"north","properties":{},
       "geometry":{"type":"Polygon","coordinates":[[[0,1],[1,1],[1,2],[0,2],[0,1]]]}},
      {"type":"Feature","id":7,"properties":{},
       "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,1],[0,0]]]}}]})");
  const CliRun feature_ids = run_contain({"inside", "--layer", with_ids}, "0.5 1\n0.5 0.5\n");
  EXPECT_EQ(feature_ids.out, "north:on 7:on\n7\n");
  EXPECT_EQ(feature_ids.err, "");
  // Ids with spaces make a line ambiguous: said on stderr, the answers unchanged.
  std::string spaced = layer_geojson();
  spaced.replace(spaced.find("\"s00\""), 5, "\"s 00\"");
  const CliRun warned = run_contain(
      {"inside", "--layer", dir.write("spaced.geojson", spaced), "--id", "name"}, "0.5 0.5\n");
  EXPECT_EQ(warned.out, "s 00\n");
  EXPECT_NE(warned.err.find("white space"), std::string::npos) << warned.err;
}

TEST(InsideLayerCli, WktLayerGivesTheSameAnswersAsGeoJson) {
  TempDir dir;
  const std::string wkt = dir.write("layer.wkt", layer_wkt());
  const std::string points = dir.write("p.txt", case_points());
  const CliRun run = run_contain({"inside", "--layer", wkt, "--points", points});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, names_to_positions(expected_by_name()));
}

TEST(InsideLayerCli, ThreadCountsGiveTheSameBytes) {
  TempDir dir;
  const std::string layer = dir.write("layer.geojson", layer_geojson());
  std::mt19937_64 rng(1);
  std::uniform_int_distribution<int> q(-2, 4 * 31);  // quarter steps: edges, corners, holes
  std::string points;
  for (int k = 0; k < 100000; ++k)
    points += std::to_string(q(rng) * 0.25) + " " + std::to_string(q(rng) * 0.25) + "\n";
  const std::string file = dir.write("p.txt", points);
  const CliRun one = run_contain({"inside", "--layer", layer, "--points", file, "--threads", "1"});
  ASSERT_EQ(one.exit_code, 0) << one.err;
  for (const char* threads : {"2", "3", "0"}) {
    const CliRun many =
        run_contain({"inside", "--layer", layer, "--points", file, "--threads", threads});
    EXPECT_EQ(many.out, one.out) << threads << " threads";
  }
  EXPECT_NE(one.out.find(":on"), std::string::npos);
}

TEST(InsideLayerCli, ErrorsAreUsageOrBadInput) {
  TempDir dir;
  const std::string layer = dir.write("layer.geojson", layer_geojson());
  const CliRun no_layer = run_contain({"inside", "--id", "name"}, "0 0\n");
  EXPECT_EQ(no_layer.exit_code, 2);
  const CliRun both = run_contain({"inside", "--layer", layer, "--polygon", layer}, "0 0\n");
  EXPECT_EQ(both.exit_code, 2);
  const CliRun missing =
      run_contain({"inside", "--layer", (dir.path() / "nope.geojson").string()}, "0 0\n");
  EXPECT_EQ(missing.exit_code, 3);
  // An attribute that no feature has is a usage error, as for a Shapefile (issue 24).
  const CliRun property = run_contain({"inside", "--layer", layer, "--id", "owner"}, "0 0\n");
  EXPECT_EQ(property.exit_code, 2);
  EXPECT_NE(property.err.find("owner"), std::string::npos) << property.err;
  const CliRun points = run_contain({"inside", "--layer", layer}, "0 0 0\n");
  EXPECT_EQ(points.exit_code, 3);
}

}  // namespace
}  // namespace contain::test
