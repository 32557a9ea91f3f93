// contain inside --layer through GDAL: Shapefile, GeoPackage and FlatGeobuf written by ogr2ogr
// (gdal-bin) from the project's GeoJSON give the same bytes as the GeoJSON itself.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cli/layer_data.h"
#include "cli/run.h"

namespace contain::test {
namespace {

// Converts the GeoJSON layer with ogr2ogr; an empty string with the failure recorded.
std::string convert(const TempDir& dir, const std::string& geojson, const std::string& name,
                    const std::string& driver, const std::vector<std::string>& extra = {}) {
  const std::string out = (dir.path() / name).string();
  std::vector<std::string> args{"-f", driver, out, geojson};
  args.insert(args.end(), extra.begin(), extra.end());
  const CliRun run = run_program("ogr2ogr", args);
  if (run.exit_code == 127) {
    ADD_FAILURE() << "ogr2ogr not found: install gdal-bin (the README's test line does)";
    return "";
  }
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return out;
}

TEST(InsideLayerGdalCli, ShapefileGeoPackageAndFlatGeobufGiveTheSameBytesAsGeoJson) {
  TempDir dir;
  const std::string geojson = dir.write("layer.geojson", layer_geojson());
  const std::string points = dir.write("p.txt", case_points());
  const CliRun reference =
      run_contain({"inside", "--layer", geojson, "--id", "name", "--points", points});
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  ASSERT_EQ(reference.out, expected_by_name());
  const std::vector<std::string> files{
      convert(dir, geojson, "layer.shp", "ESRI Shapefile"),
      convert(dir, geojson, "layer.gpkg", "GPKG", {"-nln", "parcels"}),
      // FlatGeobuf's spatial index stores the features in Hilbert order, which is then the
      // file's order; without it the order is the GeoJSON's (see the next test).
      convert(dir, geojson, "layer.fgb", "FlatGeobuf", {"-lco", "SPATIAL_INDEX=NO"}),
  };
  for (const std::string& file : files) {
    if (file.empty()) continue;
    const CliRun run = run_contain({"inside", "--layer", file, "--id", "name", "--points", points});
    EXPECT_EQ(run.exit_code, 0) << file << ": " << run.err;
    EXPECT_EQ(run.out, reference.out) << file;
    // Positions without --id: the same as the GeoJSON's.
    const CliRun positions = run_contain({"inside", "--layer", file, "--points", points});
    const CliRun reference_positions =
        run_contain({"inside", "--layer", geojson, "--points", points});
    EXPECT_EQ(positions.out, reference_positions.out) << file;
  }
}

// The same ids on every line, each line in the file's own order.
std::string sorted_lines(const std::string& text) {
  std::string out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    std::vector<std::string> words;
    std::size_t p = start;
    while (p < end) {
      std::size_t q = text.find(' ', p);
      if (q == std::string::npos || q > end) q = end;
      words.push_back(text.substr(p, q - p));
      p = q + 1;
    }
    std::sort(words.begin(), words.end());
    for (std::size_t k = 0; k < words.size(); ++k)
      out += (k > 0 ? " " : "") + words[k];
    out += '\n';
    start = end + 1;
  }
  return out;
}

TEST(InsideLayerGdalCli, FlatGeobufWithItsSpatialIndexListsTheSameIdsInItsOwnOrder) {
  TempDir dir;
  const std::string geojson = dir.write("layer.geojson", layer_geojson());
  const std::string points = dir.write("p.txt", case_points());
  const std::string fgb = convert(dir, geojson, "indexed.fgb", "FlatGeobuf");
  ASSERT_FALSE(fgb.empty());
  const CliRun reference =
      run_contain({"inside", "--layer", geojson, "--id", "name", "--points", points});
  const CliRun run = run_contain({"inside", "--layer", fgb, "--id", "name", "--points", points});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(sorted_lines(run.out), sorted_lines(reference.out));
}

TEST(InsideLayerGdalCli, LayerNameChoosesAmongSeveralAndMissingNamesAreListed) {
  TempDir dir;
  const std::string geojson = dir.write("layer.geojson", layer_geojson());
  const std::string gpkg = convert(dir, geojson, "two.gpkg", "GPKG", {"-nln", "first"});
  ASSERT_FALSE(gpkg.empty());
  const CliRun second = run_program(
      "ogr2ogr", {"-update", "-nln", "second", "-where", "name = 'lake'", gpkg, geojson});
  ASSERT_EQ(second.exit_code, 0) << second.err;
  const CliRun ambiguous = run_contain({"inside", "--layer", gpkg}, "25 25\n");
  EXPECT_EQ(ambiguous.exit_code, 2);
  EXPECT_NE(ambiguous.err.find("first, second"), std::string::npos) << ambiguous.err;
  const CliRun chosen =
      run_contain({"inside", "--layer", gpkg, "--layer-name", "second", "--id", "name"}, "25 25\n");
  EXPECT_EQ(chosen.exit_code, 0) << chosen.err;
  EXPECT_EQ(chosen.out, "lake\n");
  const CliRun fid =
      run_contain({"inside", "--layer", gpkg, "--layer-name", "first", "--id", "fid"}, "25 25\n");
  EXPECT_EQ(fid.out, "10 11\n");  // GeoPackage FIDs count from 1
  const CliRun unknown = run_contain({"inside", "--layer", gpkg, "--layer-name", "third"}, "0 0\n");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("first"), std::string::npos) << unknown.err;
  const CliRun field =
      run_contain({"inside", "--layer", gpkg, "--layer-name", "first", "--id", "owner"}, "0 0\n");
  EXPECT_EQ(field.exit_code, 2);
  EXPECT_NE(field.err.find("name"), std::string::npos) << field.err;
}

// Issue 24: a boolean property printed `false` for true, and GDAL spelt other values its own way
// (dates 2024/01/31, whole doubles 3.0 as "3.000000000000000" in a Shapefile). The same values
// give the same ids whichever reader meets them: our GeoJSON reader, GDAL on the same GeoJSON,
// or GDAL on a GeoPackage or Shapefile converted from it.
TEST(InsideLayerGdalCli, BooleanDateAndWholeDoubleIdsReadTheSameThroughGdal) {
  TempDir dir;
  std::string features;
  const char* values[][4] = {{"true", "3.0", "\"2024-01-31\"", "\"2024-01-31T10:20:30Z\""},
                             {"false", "-7.5", "\"1999-12-01\"", "\"2001-02-03T04:05:06Z\""}};
  for (int k = 0; k < 2; ++k) {
    const std::string x0 = std::to_string(2 * k), x1 = std::to_string(2 * k + 1);
    features += std::string(k > 0 ? ",\n" : "") + R"({"type":"Feature","properties":{"v":)" +
                values[k][0] + R"(,"n":)" + values[k][1] + R"(,"d":)" + values[k][2] + R"(,"t":)" +
                values[k][3] + R"(},"geometry":{"type":"Polygon","coordinates":[[[)" + x0 +
                ",0],[" + x1 + ",0],[" + x1 + ",1],[" + x0 + ",1],[" + x0 + ",0]]]}}";
  }
  const std::string geojson = dir.write(
      "typed.geojson", "{\"type\":\"FeatureCollection\",\"features\":[" + features + "]}\n");
  const std::string points = dir.write("p.txt", "0.5 0.5\n2.5 0.5\n");
  const std::string gpkg = convert(dir, geojson, "typed.gpkg", "GPKG");
  ASSERT_FALSE(gpkg.empty());
  const std::vector<std::pair<std::string, std::string>> expected{
      {"v", "true\nfalse\n"},
      {"n", "3\n-7.5\n"},
      {"d", "2024-01-31\n1999-12-01\n"},
      {"t", "2024-01-31T10:20:30Z\n2001-02-03T04:05:06Z\n"}};
  // GDAL reads a .json file as GeoJSON too, but contain's own reader takes .geojson: the copy
  // with a GDAL-only name makes GDAL read the same text.
  const std::string through_gdal = (dir.path() / "typed.geojsonl").string();
  const CliRun copy = run_program("ogr2ogr", {"-f", "GeoJSONSeq", through_gdal, geojson});
  ASSERT_EQ(copy.exit_code, 0) << copy.err;
  for (const auto& [id, out] : expected) {
    for (const std::string& source : {geojson, gpkg, through_gdal}) {
      const CliRun run = run_contain({"inside", "--layer", source, "--id", id, "--points", points});
      EXPECT_EQ(run.exit_code, 0) << source << ": " << run.err;
      EXPECT_EQ(run.out, out) << source << " --id " << id;
    }
  }
  // A Shapefile has no boolean or date-time type: its integers and dates still agree.
  const std::string shp = convert(dir, geojson, "typed.shp", "ESRI Shapefile");
  ASSERT_FALSE(shp.empty());
  for (const char* id : {"n", "d"}) {
    const CliRun run = run_contain({"inside", "--layer", shp, "--id", id, "--points", points});
    EXPECT_EQ(run.out, id == std::string("n") ? "3\n-7.5\n" : "2024-01-31\n1999-12-01\n");
  }
}

TEST(InsideLayerGdalCli, LinesAndUnreadableSourcesAreBadInput) {
  TempDir dir;
  const std::string lines =
      dir.write("lines.geojson", R"({"type":"FeatureCollection","features":[{"type":"Feature",
      "properties":{},"geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}}]})");
  const std::string shp = convert(dir, lines, "lines.shp", "ESRI Shapefile");
  ASSERT_FALSE(shp.empty());
  const CliRun run = run_contain({"inside", "--layer", shp}, "0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("LINESTRING"), std::string::npos) << run.err;
  const std::string junk = dir.write("junk.shp", "not a shapefile");
  EXPECT_EQ(run_contain({"inside", "--layer", junk}, "0 0\n").exit_code, 3);
  const CliRun pg = run_contain(
      {"inside", "--layer", "PG:host=/nonexistent-socket-dir dbname=x password=secret"}, "0 0\n");
  EXPECT_EQ(pg.exit_code, 3);
  EXPECT_EQ(pg.err.find("secret"), std::string::npos) << pg.err;
}

}  // namespace
}  // namespace contain::test
