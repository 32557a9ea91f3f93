#include "contain/io/layer_io.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/temp_file.h"
#include "io/text_scan.h"

namespace contain::io {
namespace {

MultiPolygon square(double x0, double y0, double x1, double y1) {
  return MultiPolygon{{Polygon{{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}}}};
}

TEST(WktLayer, OneShapeALineSkippingBlankAndCommentLines) {
  const auto layer = parse_wkt_layer(
      "# parcels\nPOLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))\n\n   \nPOLYGON EMPTY\n"
      "MULTIPOLYGON (((2 2, 3 2, 3 3, 2 2)), ((5 5, 6 5, 6 6, 5 5)))\n",
      "parcels.wkt");
  ASSERT_TRUE(layer) << layer.error().what();
  EXPECT_EQ(layer->ids, (std::vector<std::string>{"0", "1", "2"}));
  ASSERT_EQ(layer->regions.size(), 3u);
  EXPECT_EQ(layer->regions[0], square(0, 0, 1, 1));
  EXPECT_TRUE(layer->regions[1].polygons.empty());
  EXPECT_EQ(layer->regions[2].polygons.size(), 2u);
}

TEST(WktLayer, ErrorNamesTheLineOfTheFile) {
  const auto layer = parse_wkt_layer(
      "POLYGON ((0 0, 1 0, 1 1, 0 0))\n# note\n\nPOLYGON ((0 0, 1 0, x 1, 0 0))\n", "p.wkt");
  ASSERT_FALSE(layer);
  EXPECT_EQ(layer.error().line, 4);
  EXPECT_EQ(layer.error().source, "p.wkt");
  const auto point = parse_wkt_layer("POINT (1 2)\n", "p.wkt");
  ASSERT_FALSE(point);
  EXPECT_EQ(point.error().kind, ErrorKind::unsupported);
}

TEST(WktLayer, AnIdAttributeIsAUsageError) {
  const auto layer = parse_wkt_layer("POLYGON ((0 0, 1 0, 1 1, 0 0))\n", "p.wkt", {.id = "name"});
  ASSERT_FALSE(layer);
  EXPECT_EQ(layer.error().kind, ErrorKind::usage);
}

const char* const kCollection = R"({"type": "FeatureCollection", "features": [
  {"type": "Feature", "id": "a", "properties": {"name": "west", "code": 7, "ratio": 0.10},
   "geometry": {"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1],[0,1],[0,0]]]}},
  {"type": "Feature", "id": 12345678901234567, "properties": {"name": "east", "code": -3, "ratio": 1e2},
   "geometry": {"type": "MultiPolygon", "coordinates": [[[[1,0],[2,0],[2,1],[1,1],[1,0]]]]}},
  {"type": "Feature", "id": "c", "properties": {"name": "nothing", "code": 0, "ratio": 2},
   "geometry": null}
]})";

TEST(GeoJsonLayer, EveryFeatureIsARegionWithItsIdMember) {
  const auto layer = parse_geojson_layer(kCollection, "l.geojson");
  ASSERT_TRUE(layer) << layer.error().what();
  // Numbers are ids as written, even past 2^53.
  EXPECT_EQ(layer->ids, (std::vector<std::string>{"a", "12345678901234567", "c"}));
  ASSERT_EQ(layer->regions.size(), 3u);
  EXPECT_EQ(layer->regions[0], square(0, 0, 1, 1));
  EXPECT_EQ(layer->regions[1], square(1, 0, 2, 1));
  EXPECT_TRUE(layer->regions[2].polygons.empty());  // a null geometry keeps its position
}

// Integers as written (past 2^53 too); other numbers as the values GDAL reads from the same
// file (issue 24: 0.10 and 1e2 are the doubles 0.1 and 100, whoever reads them).
TEST(GeoJsonLayer, IdsFromAPropertyKeepIntegersAsWrittenAndOtherNumbersAsValues) {
  auto by_name = parse_geojson_layer(kCollection, "l.geojson", {.id = "name"});
  ASSERT_TRUE(by_name) << by_name.error().what();
  EXPECT_EQ(by_name->ids, (std::vector<std::string>{"west", "east", "nothing"}));
  auto by_code = parse_geojson_layer(kCollection, "l.geojson", {.id = "code"});
  ASSERT_TRUE(by_code);
  EXPECT_EQ(by_code->ids, (std::vector<std::string>{"7", "-3", "0"}));
  auto by_ratio = parse_geojson_layer(kCollection, "l.geojson", {.id = "ratio"});
  ASSERT_TRUE(by_ratio);
  EXPECT_EQ(by_ratio->ids, (std::vector<std::string>{"0.1", "100", "2"}));
}

TEST(GeoJsonLayer, BooleanAndWholeDoubleIdsAreTheirValues) {
  const auto layer = parse_geojson_layer(R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"v": true, "n": 3.0, "d": "2024-01-31"}, "geometry": null},
    {"type": "Feature", "properties": {"v": false, "n": -4e0, "d": "2024-02-01"}, "geometry": null}
  ]})",
                                         "b.geojson", {.id = "v"});
  ASSERT_TRUE(layer) << layer.error().what();
  EXPECT_EQ(layer->ids, (std::vector<std::string>{"true", "false"}));
  const auto n = parse_geojson_layer(R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"n": 3.0}, "geometry": null},
    {"type": "Feature", "properties": {"n": -4e0}, "geometry": null},
    {"type": "Feature", "properties": {"n": 1.5e300}, "geometry": null}]})",
                                     "n.geojson", {.id = "n"});
  ASSERT_TRUE(n) << n.error().what();
  EXPECT_EQ(n->ids, (std::vector<std::string>{"3", "-4", "1.5e+300"}));
}

TEST(GeoJsonLayer, PositionsWhereSomeFeatureHasNoId) {
  const auto layer = parse_geojson_layer(R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "id": 4, "properties": {}, "geometry": null},
    {"type": "Feature", "properties": {}, "geometry": null}]})",
                                         "l.geojson");
  ASSERT_TRUE(layer);
  EXPECT_EQ(layer->ids, (std::vector<std::string>{"0", "1"}));
}

TEST(GeoJsonLayer, MissingPropertyNamesTheFeatureAndLine) {
  const auto layer = parse_geojson_layer(R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "a"}, "geometry": null},
    {"type": "Feature", "properties": {"code": 1}, "geometry": null}]})",
                                         "l.geojson", {.id = "code"});
  ASSERT_FALSE(layer);
  EXPECT_EQ(layer.error().kind, ErrorKind::invalid_value);
  EXPECT_NE(layer.error().message.find("feature 0"), std::string::npos);
  EXPECT_EQ(layer.error().line, 2);
}

// A property that no feature has is a usage error listing the properties there are, as GDAL's
// reader says of a field that is not in the layer (issue 24: one exit code for both).
TEST(GeoJsonLayer, PropertyOfNoFeatureIsAUsageErrorListingTheProperties) {
  const auto layer = parse_geojson_layer(kCollection, "l.geojson", {.id = "owner"});
  ASSERT_FALSE(layer);
  EXPECT_EQ(layer.error().kind, ErrorKind::usage);
  EXPECT_NE(layer.error().message.find("'owner'"), std::string::npos);
  EXPECT_NE(layer.error().message.find("name, code, ratio"), std::string::npos)
      << layer.error().message;
}

TEST(LayerSourceName, HidesPasswordsInEveryForm) {
  for (const std::string source :
       {"PG:postgresql://alice:hunter22@db.example/gis", "PG:postgres://alice:hunter22@db:5432/gis",
        "PG:postgresql://alice@db/gis?sslmode=require&password=hunter22",
        "PG:host=db password=hunter22 dbname=gis", "PG:host=db password='hunter 22' dbname=gis",
        "PG:host=db PassWord = hunter22 dbname=gis"}) {
    const std::string name = layer_source_name(source);
    EXPECT_EQ(name.find("hunter"), std::string::npos) << name;
    EXPECT_NE(name.find("***"), std::string::npos) << name;
    EXPECT_NE(name.find("db"), std::string::npos) << name;
  }
  EXPECT_EQ(layer_source_name("parcels.gpkg"), "parcels.gpkg");
  // A driver's message that quotes the secret loses it too.
  const std::string said = detail::hide_secrets(
      "could not connect to 'postgresql://alice:hunter22@db/gis' (hunter22 refused)",
      "PG:postgresql://alice:hunter22@db/gis");
  EXPECT_EQ(said.find("hunter22"), std::string::npos) << said;
  EXPECT_EQ(layer_source_name("PG:postgresql://alice@db/gis"), "PG:postgresql://alice@db/gis");
}

TEST(GeoJsonLayer, BareGeometryIsALayerOfOne) {
  const auto layer = parse_geojson_layer(
      R"({"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1],[0,0]]]})", "one.geojson");
  ASSERT_TRUE(layer);
  EXPECT_EQ(layer->ids, std::vector<std::string>{"0"});
  const auto point = parse_geojson_layer(R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [1, 2]}}]})",
                                         "pt.geojson");
  ASSERT_FALSE(point);
  EXPECT_EQ(point.error().kind, ErrorKind::unsupported);
  EXPECT_EQ(point.error().line, 2);
}

// Issue 24: layers read unclosed rings, holes outside their shell and overlapping parts in
// silence, where `clip` warns of unclosed rings. read_layer now words each as a warning.
TEST(ReadLayer, WarnsOfUnclosedRingsHolesOutsideTheShellAndOverlappingParts) {
  const test::TempFile wkt(
      ".wkt",
      "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))\n"
      "POLYGON ((0 0, 4 0, 4 4, 0 4))\n"                                           // not closed
      "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (5 5, 6 5, 6 6, 5 5))\n"                // hole outside
      "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((2 2, 6 2, 6 6, 2 6, 2 2)))\n"  // overlap
      "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((4 0, 8 0, 8 4, 4 4, 4 0)))\n"  // touching
      "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (0 0, 2 1, 1 2, 0 0))\n");  // hole touching shell
  auto layer = read_layer(wkt.path().string());
  ASSERT_TRUE(layer) << layer.error().what();
  ASSERT_EQ(layer->warnings.size(), 3u);
  EXPECT_NE(layer->warnings[0].find(":2: ring not closed"), std::string::npos)
      << layer->warnings[0];
  EXPECT_NE(layer->warnings[1].find("shape 2, polygon 1: hole 1 has a vertex outside its shell"),
            std::string::npos)
      << layer->warnings[1];
  EXPECT_NE(layer->warnings[2].find("shape 3: polygons 1 and 2 overlap"), std::string::npos)
      << layer->warnings[2];
  // The same regions read as GeoJSON give the same warnings of holes and parts.
  const test::TempFile json(".geojson", R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {}, "geometry": {"type": "MultiPolygon", "coordinates":
      [[[[0,0],[4,0],[4,4],[0,4],[0,0]]], [[[2,2],[6,2],[6,6],[2,6],[2,2]]]]}}]})");
  auto geojson = read_layer(json.path().string());
  ASSERT_TRUE(geojson);
  ASSERT_EQ(geojson->warnings.size(), 1u);
  EXPECT_NE(geojson->warnings[0].find("shape 0: polygons 1 and 2 overlap"), std::string::npos);
}

TEST(ReadLayer, PicksTheReaderByExtension) {
  const test::TempFile wkt(".wkt", "POLYGON ((0 0, 1 0, 1 1, 0 0))\n");
  const test::TempFile json(".geojson", kCollection);
  auto a = read_layer(wkt.path().string());
  ASSERT_TRUE(a) << a.error().what();
  EXPECT_EQ(a->regions.size(), 1u);
  auto b = read_layer(json.path().string(), {.id = "name"});
  ASSERT_TRUE(b) << b.error().what();
  EXPECT_EQ(b->ids.front(), "west");
  auto named = read_layer(json.path().string(), {.layer_name = "x"});
  ASSERT_FALSE(named);
  EXPECT_EQ(named.error().kind, ErrorKind::usage);
  auto missing = read_layer("/nonexistent/layer.wkt");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().kind, ErrorKind::io);
}

}  // namespace
}  // namespace contain::io
