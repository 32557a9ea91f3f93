#include "contain/io/wkt.h"

#include <gtest/gtest.h>

#include <bit>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "contain/io/geojson.h"
#include "io/temp_file.h"
#include "support/shared_corpus.h"

namespace contain::io {
namespace {

const Ring kSquare{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
const Ring kHole{{1, 1}, {1, 2}, {2, 2}, {2, 1}};

TEST(Wkt, ReadsAPolygonWithAHoleDroppingTheClosingPoints) {
  auto r = parse_wkt("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))", "a.wkt");
  ASSERT_TRUE(r.ok()) << r.error().what();
  ASSERT_EQ(r->polygons.size(), 1u);
  EXPECT_EQ(r->polygons[0].rings, (std::vector<Ring>{kSquare, kHole}));
}

TEST(Wkt, ReadsKeywordsInAnyCaseAndAnyWhiteSpace) {
  auto r = parse_wkt(
      "\n  multiPolygon(\n((0 0,4 0,\n4 4,0 4,0 0)),\t( (1 1, 1 2, 2 2, 2 1, 1 1)))\n", "a.wkt");
  ASSERT_TRUE(r.ok()) << r.error().what();
  ASSERT_EQ(r->polygons.size(), 2u);
  EXPECT_EQ(r->polygons[1].rings[0], kHole);
}

TEST(Wkt, DropsZAndMOrdinates) {
  for (const char* text : {"POLYGON Z ((0 0 9, 4 0 9, 4 4 9, 0 4 9, 0 0 9))",
                           "POLYGON M ((0 0 9, 4 0 9, 4 4 9, 0 4 9, 0 0 9))",
                           "POLYGON ZM ((0 0 9 8, 4 0 9 8, 4 4 9 8, 0 4 9 8, 0 0 9 8))",
                           "POLYGON ((0 0 9, 4 0 9, 4 4 9, 0 4 9, 0 0 9))"}) {
    auto r = parse_wkt(text, "a.wkt");
    ASSERT_TRUE(r.ok()) << text << ": " << r.error().what();
    EXPECT_EQ(r->polygons[0].rings[0], kSquare) << text;
  }
}

TEST(Wkt, EmptyFormsGiveNoPolygon) {
  for (const char* text :
       {"POLYGON EMPTY", "MULTIPOLYGON EMPTY", "polygon z empty", "MULTIPOLYGON (EMPTY, EMPTY)"}) {
    auto r = parse_wkt(text, "a.wkt");
    ASSERT_TRUE(r.ok()) << text << ": " << r.error().what();
    EXPECT_TRUE(r->polygons.empty()) << text;
  }
  auto mixed = parse_wkt("MULTIPOLYGON (EMPTY, ((0 0, 4 0, 4 4, 0 4, 0 0)))", "a.wkt");
  ASSERT_TRUE(mixed.ok());
  EXPECT_EQ(mixed->polygons.size(), 1u);
}

TEST(Wkt, AcceptsAnEwktSridPrefix) {
  auto r = parse_wkt("SRID=4326;POLYGON((0 0, 4 0, 4 4, 0 4, 0 0))", "a.wkt");
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->polygons[0].rings[0], kSquare);
}

struct BadWkt {
  const char* text;
  ErrorKind kind;
  std::int64_t line;
};

TEST(Wkt, RejectsMalformedInputNamingTheKindAndLine) {
  const BadWkt cases[] = {
      {"", ErrorKind::parse, 1},
      {"   \n\n", ErrorKind::parse, 3},
      {"POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)", ErrorKind::parse, 1},        // truncated
      {"POLYGON ((0 0, 4 0,\n 4 4, 0 4, 0 0)) x", ErrorKind::parse, 2},   // trailing text
      {"POLYGON ((0 0, 4 0,\n 4 four, 0 4, 0 0))", ErrorKind::parse, 2},  // bad number
      {"POLYGON ((0 0, 4 0, 4 4x, 0 4, 0 0))", ErrorKind::parse, 1},      // glued garbage
      {"POLYGON ((0 0, 4 0,\n\n nan 4, 0 4, 0 0))", ErrorKind::invalid_value, 3},
      {"POLYGON ((0 0, 4 0, inf 4, 0 4, 0 0))", ErrorKind::invalid_value, 1},
      {"POLYGON ((0 0, 1e400 0, 4 4, 0 4, 0 0))", ErrorKind::invalid_value, 1},
      {"POLYGON ((0 0, 4 0 1, 4 4, 0 4, 0 0))", ErrorKind::parse, 1},  // mixed dimension
      {"POLYGON Z ((0 0, 4 0, 4 4, 0 4, 0 0))", ErrorKind::parse, 1},  // tag says 3
      {"POLYGON ((0, 4 0, 4 4, 0 4, 0 0))", ErrorKind::parse, 1},
      {"POLYGON ((0 0 0 0 0, 4 0, 4 4))", ErrorKind::parse, 1},
      {"POLYGON ((0 0, 4 0, 0 0))", ErrorKind::degenerate, 1},
      {"LINESTRING (0 0, 1 1)", ErrorKind::unsupported, 1},
      {"POINT (0 0)", ErrorKind::unsupported, 1},
      {"POLYGONE ((0 0, 4 0, 4 4))", ErrorKind::parse, 1},
      {"POLYGON X ((0 0, 4 0, 4 4))", ErrorKind::parse, 1},
      {"POLYGON (0 0, 4 0, 4 4)", ErrorKind::parse, 1},
      {"POLYGON ((0 0; 4 0, 4 4))", ErrorKind::parse, 1},
      {"MULTIPOLYGON ((0 0, 4 0, 4 4))", ErrorKind::parse, 1},
      {"POLYGON ((0 0, 4 0, 4 4)) POLYGON ((0 0, 4 0, 4 4))", ErrorKind::parse, 1},
  };
  for (const BadWkt& c : cases) {
    auto r = parse_wkt(c.text, "bad.wkt");
    ASSERT_FALSE(r.ok()) << c.text;
    EXPECT_EQ(r.error().kind, c.kind) << c.text << ": " << r.error().what();
    EXPECT_EQ(r.error().line, c.line) << c.text << ": " << r.error().what();
    EXPECT_EQ(r.error().source, "bad.wkt");
  }
}

// Issue 24: GeoJSON's GeometryCollection of polygons was read, WKT's refused; both now give the
// polygons of their members, and a member that is not a region is refused alike.
TEST(Wkt, GeometryCollectionsOfPolygonsReadAsTheirPolygonsAsInGeoJson) {
  const auto collection = parse_wkt(
      "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 1 1, 0 0)),\n"
      " GEOMETRYCOLLECTION (MULTIPOLYGON (((5 5, 6 5, 6 6, 5 5)), EMPTY), POLYGON EMPTY))",
      "gc.wkt");
  ASSERT_TRUE(collection) << collection.error().what();
  const auto same =
      parse_wkt("MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), ((5 5, 6 5, 6 6, 5 5)))", "m.wkt");
  ASSERT_TRUE(same);
  EXPECT_EQ(*collection, *same);
  const auto geojson = parse_geojson(
      R"({"type": "GeometryCollection", "geometries": [
        {"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1],[0,0]]]},
        {"type": "GeometryCollection", "geometries": [
          {"type": "MultiPolygon", "coordinates": [[[[5,5],[6,5],[6,6],[5,5]]]]}]}]})",
      "gc.geojson");
  ASSERT_TRUE(geojson) << geojson.error().what();
  EXPECT_EQ(*collection, *geojson);
  EXPECT_TRUE(parse_wkt("GEOMETRYCOLLECTION EMPTY", "e.wkt")->polygons.empty());
  const auto point =
      parse_wkt("GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 1 1, 0 0)),\n POINT (1 2))", "p.wkt");
  ASSERT_FALSE(point);
  EXPECT_EQ(point.error().kind, ErrorKind::unsupported);
  EXPECT_EQ(point.error().line, 2);
  std::string deep;
  for (int i = 0; i < 100; ++i)
    deep += "GEOMETRYCOLLECTION (";
  const auto nested = parse_wkt(deep + "POLYGON EMPTY" + std::string(100, ')'), "d.wkt");
  ASSERT_FALSE(nested);
  EXPECT_EQ(nested.error().kind, ErrorKind::unsupported);
  const auto unclosed = parse_wkt("GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 1 1, 0 0))", "u.wkt");
  ASSERT_FALSE(unclosed);
  EXPECT_EQ(unclosed.error().kind, ErrorKind::parse);
}

TEST(Wkt, NeverCrashesOnAnyPrefixOfValidText) {
  const std::string text =
      "MULTIPOLYGON Z (((0 0 1, 4 0 1, 4 4 1, 0 4 1, 0 0 1), (1 1 1, 1 2 1, 2 2 1, 2 1 1, 1 1 1)))";
  for (std::size_t n = 0; n < text.size(); ++n) {
    auto r = parse_wkt(text.substr(0, n), "prefix.wkt");
    EXPECT_FALSE(r.ok()) << n;
  }
  EXPECT_TRUE(parse_wkt(text, "full.wkt").ok());
}

TEST(Wkt, SurvivesRandomCorruption) {
  const std::string text =
      "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1)), ((5 5, 6 5, 5 6)))";
  std::mt19937_64 rng(3);
  const std::string alphabet = "(), .-+eE0123456789NnIiZzMEMPTY\n\t";
  for (int trial = 0; trial < 2000; ++trial) {
    std::string copy = text;
    for (int k = 0; k < 2; ++k)
      copy[rng() % copy.size()] = alphabet[rng() % alphabet.size()];
    auto r = parse_wkt(copy, "corrupt.wkt");
    if (!r.ok()) {
      EXPECT_FALSE(r.error().message.empty());
      EXPECT_GE(r.error().line, 1);
    }
  }
}

TEST(Wkt, WritesClosedRingsAndReadsBackBitForBit) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  MultiPolygon m;
  for (int p = 0; p < 3; ++p) {
    Polygon polygon;
    for (int r = 0; r < 2; ++r) {
      Ring ring;
      for (int i = 0; i < 5; ++i)
        ring.push_back({u(rng) / 3.0, u(rng) * 1e-300});
      polygon.rings.push_back(ring);
    }
    m.polygons.push_back(polygon);
  }
  m.polygons[0].rings[0][0] = {0.1, -0.0};
  const std::string text = format_wkt(m);
  EXPECT_EQ(text.rfind("MULTIPOLYGON (((0.1 -0, ", 0), 0u) << text;
  auto back = parse_wkt(text, "rt.wkt");
  ASSERT_TRUE(back.ok()) << back.error().what();
  EXPECT_EQ(*back, m);
  EXPECT_TRUE(std::signbit(back->polygons[0].rings[0][0].y));

  auto single = parse_wkt(format_wkt(m.polygons[1]), "rt.wkt");
  ASSERT_TRUE(single.ok());
  ASSERT_EQ(single->polygons.size(), 1u);
  EXPECT_EQ(single->polygons[0], m.polygons[1]);
}

TEST(Wkt, WritesTheEmptyForms) {
  EXPECT_EQ(format_wkt(MultiPolygon{}), "MULTIPOLYGON EMPTY");
  EXPECT_EQ(format_wkt(Polygon{}), "POLYGON EMPTY");
  EXPECT_EQ(format_wkt(Polygon{{kSquare}}), "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))");
}

TEST(Wkt, ReadsAFileAndReportsAMissingOne) {
  test::TempFile file(".wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))\n");
  auto r = read_wkt(file.path());
  ASSERT_TRUE(r.ok()) << r.error().what();
  auto missing = read_wkt("/nonexistent/x.wkt");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().kind, ErrorKind::io);
}

// Every WKT of the shared 2D corpus (GEOS, Boost.Geometry and Clipper2 test cases) reads, or is
// refused for a stated reason: another geometry type or a degenerate ring; never a parse error.
TEST(Wkt, ReadsEveryPolygonOfTheSharedCorpus) {
  CONTAIN_REQUIRE_SHARED();
  const auto dir = *test::shared_dir() / "corpus" / "poly2d";
  int read = 0;
  int refused = 0;
  for (const char* name :
       {"geos-overlay.jsonl", "boost-overlay-cases.jsonl", "clipper2-polygons.jsonl"}) {
    std::ifstream in(dir / name);
    ASSERT_TRUE(in) << name;
    std::string line;
    while (std::getline(in, line)) {
      const auto record = nlohmann::json::parse(line);
      for (const char* key : {"wkt_a", "wkt_b"}) {
        if (!record.contains(key) || !record[key].is_string()) continue;
        const std::string text = record[key].get<std::string>();
        auto r = parse_wkt(text, name);
        if (r.ok()) {
          ++read;
          // and what is read writes back to the same region
          auto again = parse_wkt(format_wkt(*r), name);
          ASSERT_TRUE(again.ok());
          EXPECT_EQ(*again, *r);
        } else if (record.value("id", "") == "boost:issue_1138") {
          // commas missing between coordinates in Boost's own test data: rightly malformed
          EXPECT_EQ(r.error().kind, ErrorKind::parse);
        } else {
          ++refused;
          EXPECT_TRUE(r.error().kind == ErrorKind::unsupported ||
                      r.error().kind == ErrorKind::degenerate)
              << record.value("id", "?") << ": " << r.error().what();
        }
      }
    }
  }
  std::cout << "[ wkt ] corpus: " << read << " read, " << refused << " refused\n";
  EXPECT_GT(read, 2000);
}

// What the text held that OGC WKT does not allow comes back with the region, not through a
// pointer: the lines of unclosed rings, none for closed ones, and the same errors as parse_wkt.
TEST(Wkt, ParseWithNotesNamesTheLinesOfUnclosedRingsBesideTheSameRegion) {
  const std::string text = "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 0)),\n((5 5, 6 5, 6 6)))";
  const auto noted = parse_wkt_with_notes(text, "n.wkt");
  ASSERT_TRUE(noted) << noted.error().what();
  const auto plain = parse_wkt(text, "n.wkt");
  ASSERT_TRUE(plain);
  EXPECT_EQ(noted->region, *plain);
  EXPECT_EQ(noted->notes.unclosed_rings, std::vector<std::int64_t>{2});
  const auto closed = parse_wkt_with_notes("POLYGON ((0 0, 1 0, 1 1, 0 0))", "c.wkt");
  ASSERT_TRUE(closed);
  EXPECT_TRUE(closed->notes.unclosed_rings.empty());
  const auto bad = parse_wkt_with_notes("POLYGON ((0 0, 1 0", "b.wkt");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().kind, parse_wkt("POLYGON ((0 0, 1 0", "b.wkt").error().kind);
}

}  // namespace
}  // namespace contain::io
