#include "contain/io/geojson.h"

#include <gtest/gtest.h>

#include <random>

#include "io/temp_file.h"

namespace contain::io {
namespace {

const Ring kJsonSquare{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
const Ring kJsonHole{{1, 1}, {1, 2}, {2, 2}, {2, 1}};
const char* kSquareJson = "[[[0,0],[4,0],[4,4],[0,4],[0,0]],[[1,1],[1,2],[2,2],[2,1],[1,1]]]";

TEST(GeoJson, ReadsAPolygonWithAHole) {
  auto r =
      parse_geojson(std::string(R"({"type":"Polygon","coordinates":)") + kSquareJson + "}", "a");
  ASSERT_TRUE(r.ok()) << r.error().what();
  ASSERT_EQ(r->polygons.size(), 1u);
  EXPECT_EQ(r->polygons[0].rings, (std::vector<Ring>{kJsonSquare, kJsonHole}));
}

TEST(GeoJson, GathersThePolygonsOfEveryFeatureAndCollection) {
  const std::string text = std::string(R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{"name":"a"},"geometry":{"type":"Polygon","coordinates":)") +
                           kSquareJson + R"(}},
    {"type":"Feature","geometry":null},
    {"type":"Feature","geometry":{"type":"MultiPolygon","coordinates":[[[[0,0,5],[1,0,5],[0,1,5]]],[]]}},
    {"type":"Feature","geometry":{"type":"GeometryCollection","geometries":[
      {"type":"Polygon","coordinates":[[[0,0],[2,0],[0,2],[0,0]]]}]}}]})";
  auto r = parse_geojson(text, "fc.geojson");
  ASSERT_TRUE(r.ok()) << r.error().what();
  ASSERT_EQ(r->polygons.size(), 3u);
  EXPECT_EQ(r->polygons[1].rings[0], (Ring{{0, 0}, {1, 0}, {0, 1}}));
  EXPECT_EQ(r->polygons[2].rings[0], (Ring{{0, 0}, {2, 0}, {0, 2}}));
}

struct BadJson {
  std::string text;
  ErrorKind kind;
  std::int64_t line;
};

TEST(GeoJson, RejectsMalformedInputNamingTheKindAndLine) {
  const BadJson cases[] = {
      {"", ErrorKind::parse, 1},
      {"{\"type\":\"Polygon\",\n\"coordinates\":[[[0,0],[1,0],[0,1]]]", ErrorKind::parse,
       2},  // truncated
      {"{\"type\":\"Polygon\",\n\"coordinates\":[[[0,0],[1,0],[0,x]]]}", ErrorKind::parse, 2},
      {"{\"type\":\"Polygon\",\n\"coordinates\":[[[0,0],[1,0],[0,NaN]]]}", ErrorKind::parse, 2},
      {"{\"type\":\"Polygon\",\n\n\"coordinates\":[[[0,0],[1e400,0],[0,1]]]}",
       ErrorKind::invalid_value, 3},
      {"{\"type\":\"Point\",\n\"coordinates\":[0,0]}", ErrorKind::unsupported, 1},
      {"{\"type\":\"FeatureCollection\",\"features\":[\n{\"type\":\"Feature\",\n\"geometry\":{"
       "\"type\":\"LineString\",\"coordinates\":[]}}]}",
       ErrorKind::unsupported, 3},
      {"{\"type\":\"Blob\"}", ErrorKind::parse, 1},
      {"{\"coordinates\":[]}", ErrorKind::parse, 1},
      {"[1,2]", ErrorKind::parse, 1},
      {"{\"type\":\"Polygon\"}", ErrorKind::parse, 1},
      {"{\"type\":\"Polygon\",\"coordinates\":{}}", ErrorKind::parse, 1},
      {"{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],\n[0]]]}", ErrorKind::parse, 2},
      {"{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],\n[0,\"1\"]]]}", ErrorKind::parse, 2},
      {"{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],[0,0]]]}", ErrorKind::degenerate, 1},
      {"{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],[0,1]]]} {}", ErrorKind::parse, 1},
      {std::string(10000, '['), ErrorKind::parse, 1},
      // A name given twice: which one counts is left open by JSON.
      {"{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],[0,1]]],\n\"coordinates\":[]}",
       ErrorKind::parse, 2},
  };
  for (const BadJson& c : cases) {
    auto r = parse_geojson(c.text, "bad.geojson");
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().kind, c.kind) << c.text << ": " << r.error().what();
    EXPECT_EQ(r.error().line, c.line) << c.text << ": " << r.error().what();
    EXPECT_EQ(r.error().source, "bad.geojson");
  }
}

TEST(GeoJson, SurvivesRandomCorruption) {
  const std::string text = std::string(R"({"type":"FeatureCollection","features":[{"type":"Feature",
    "geometry":{"type":"MultiPolygon","coordinates":[)") +
                           kSquareJson + "]}}]}";
  std::mt19937_64 rng(4);
  const std::string alphabet = "[]{},:\"-.e0123456789 \ntypePolygon";
  for (int trial = 0; trial < 2000; ++trial) {
    std::string copy = text;
    for (int k = 0; k < 2; ++k)
      copy[rng() % copy.size()] = alphabet[rng() % alphabet.size()];
    auto r = parse_geojson(copy, "corrupt.geojson");
    if (!r.ok()) {
      EXPECT_FALSE(r.error().message.empty());
      EXPECT_GE(r.error().line, 1) << r.error().what();
    }
  }
}

TEST(GeoJson, WritesAndReadsBackBitForBit) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  MultiPolygon m;
  for (int p = 0; p < 2; ++p) {
    Polygon polygon;
    Ring ring;
    for (int i = 0; i < 6; ++i)
      ring.push_back({u(rng) * 1e20, u(rng) / 7.0});
    polygon.rings.push_back(ring);
    m.polygons.push_back(polygon);
  }
  auto back = parse_geojson(format_geojson(m), "rt");
  ASSERT_TRUE(back.ok()) << back.error().what();
  EXPECT_EQ(*back, m);
  auto single = parse_geojson(format_geojson(m.polygons[0]), "rt");
  ASSERT_TRUE(single.ok());
  EXPECT_EQ(single->polygons.size(), 1u);
  EXPECT_EQ(single->polygons[0], m.polygons[0]);
  EXPECT_EQ(format_geojson(MultiPolygon{}), R"({"type":"MultiPolygon","coordinates":[]})");
}

TEST(GeoJson, ReadsAFileAndReportsAMissingOne) {
  test::TempFile file(".geojson",
                      std::string(R"({"type":"Polygon","coordinates":)") + kSquareJson + "}");
  auto r = read_geojson(file.path());
  ASSERT_TRUE(r.ok()) << r.error().what();
  auto missing = read_geojson("/nonexistent/x.geojson");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().kind, ErrorKind::io);
}

}  // namespace
}  // namespace contain::io
