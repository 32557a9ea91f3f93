#include "contain/io/wkb.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "contain/io/wkt.h"

namespace contain::io {
namespace {

const Ring kWkbSquare{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
const Ring kWkbHole{{1, 1}, {1, 2}, {2, 2}, {2, 1}};

// WKB written by hand in either byte order, independent of the writer under test.
class Bytes {
 public:
  explicit Bytes(bool big) : big_(big) {}
  Bytes& order() {
    out_.push_back(big_ ? '\0' : '\x01');
    return *this;
  }
  Bytes& u32(std::uint32_t v) {
    for (int i = 0; i < 4; ++i) {
      const int shift = big_ ? 8 * (3 - i) : 8 * i;
      out_.push_back(static_cast<char>((v >> shift) & 0xff));
    }
    return *this;
  }
  Bytes& f64(double d) {
    const auto v = std::bit_cast<std::uint64_t>(d);
    for (int i = 0; i < 8; ++i) {
      const int shift = big_ ? 8 * (7 - i) : 8 * i;
      out_.push_back(static_cast<char>((v >> shift) & 0xff));
    }
    return *this;
  }
  // A closed ring with `extra` ordinates (z, m) of 9 after each x y.
  Bytes& ring(const Ring& ring, int extra = 0) {
    u32(static_cast<std::uint32_t>(ring.size() + 1));
    for (std::size_t i = 0; i <= ring.size(); ++i) {
      const Vec2 p = ring[i % ring.size()];
      f64(p.x).f64(p.y);
      for (int k = 0; k < extra; ++k)
        f64(9);
    }
    return *this;
  }
  [[nodiscard]] const std::string& str() const { return out_; }

 private:
  bool big_;
  std::string out_;
};

TEST(Wkb, ReadsAPolygonWithAHoleInBothByteOrders) {
  for (const bool big : {false, true}) {
    Bytes b(big);
    b.order().u32(3).u32(2).ring(kWkbSquare).ring(kWkbHole);
    auto r = parse_wkb(b.str(), "a.wkb");
    ASSERT_TRUE(r.ok()) << r.error().what();
    ASSERT_EQ(r->polygons.size(), 1u);
    EXPECT_EQ(r->polygons[0].rings, (std::vector<Ring>{kWkbSquare, kWkbHole})) << big;
  }
}

TEST(Wkb, ReadsMultiPolygonsAndCollectionsOfThemInOrder) {
  Bytes b(false);
  b.order().u32(7).u32(2);                   // collection of 2
  b.order().u32(6).u32(2);                   //   multipolygon of 2
  b.order().u32(3).u32(1).ring(kWkbSquare);  //     square
  b.order().u32(3).u32(0);                   //     empty polygon
  Bytes big(true);                           //   a member in big endian
  big.order().u32(3).u32(1).ring(kWkbHole);
  auto r = parse_wkb(b.str() + big.str(), "a.wkb");
  ASSERT_TRUE(r.ok()) << r.error().what();
  ASSERT_EQ(r->polygons.size(), 2u);
  EXPECT_EQ(r->polygons[0].rings[0], kWkbSquare);
  EXPECT_EQ(r->polygons[1].rings[0], kWkbHole);
}

TEST(Wkb, DropsZAndMOrdinatesOfIsoAndEwkbCodesAndSkipsTheSrid) {
  struct Case {
    std::uint32_t code;
    int extra;
    bool srid;
  };
  for (const Case c : {Case{1003, 1, false}, Case{2003, 1, false}, Case{3003, 2, false},
                       Case{0x80000003u, 1, false}, Case{0xC0000003u, 2, false},
                       Case{0x20000003u, 0, true}, Case{0xA0000003u, 1, true}}) {
    Bytes b(false);
    b.order().u32(c.code);
    if (c.srid) b.u32(4326);
    b.u32(1).ring(kWkbSquare, c.extra);
    auto r = parse_wkb(b.str(), "a.wkb");
    ASSERT_TRUE(r.ok()) << c.code << ": " << r.error().what();
    EXPECT_EQ(r->polygons[0].rings[0], kWkbSquare) << c.code;
  }
}

TEST(Wkb, ReadsTheHexFormOfPostgisInEitherCase) {
  const std::string binary = format_wkb(MultiPolygon{{Polygon{{kWkbSquare, kWkbHole}}}});
  std::string upper, lower;
  for (unsigned char c : binary) {
    constexpr char digits[] = "0123456789ABCDEF";
    upper += digits[c >> 4];
    upper += digits[c & 15];
  }
  for (char c : upper)
    lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const std::string& text : {upper, lower}) {
    auto r = parse_wkb(text, "hex");
    ASSERT_TRUE(r.ok()) << r.error().what();
    EXPECT_EQ(r->polygons[0].rings, (std::vector<Ring>{kWkbSquare, kWkbHole}));
  }
  EXPECT_EQ(parse_wkb(upper.substr(1), "hex").error().kind, ErrorKind::parse);
  EXPECT_EQ(parse_wkb(upper.substr(0, 10) + "zz", "hex").error().kind, ErrorKind::parse);
}

TEST(Wkb, WriterRoundTripsEveryDoubleBitForBitAndMatchesTheWktReading) {
  std::mt19937_64 random(7);
  std::uniform_int_distribution<std::uint64_t> bits;
  for (int trial = 0; trial < 200; ++trial) {
    Ring ring;
    for (int k = 0; k < 5; ++k) {
      double x = 0, y = 0;
      do {
        x = std::bit_cast<double>(bits(random));
        y = std::bit_cast<double>(bits(random));
      } while (!std::isfinite(x) || !std::isfinite(y));
      ring.push_back({x, y});
    }
    const MultiPolygon region{{Polygon{{ring}}}};
    auto back = parse_wkb(format_wkb(region), "w");
    ASSERT_TRUE(back.ok()) << back.error().what();
    EXPECT_EQ(*back, region);
    auto via_wkt = parse_wkt(format_wkt(region), "t");
    ASSERT_TRUE(via_wkt.ok());
    EXPECT_EQ(*back, *via_wkt);
  }
  EXPECT_EQ(format_wkb(MultiPolygon{}).size(), 9u);  // MULTIPOLYGON EMPTY
  auto one = parse_wkb(format_wkb(Polygon{{kWkbSquare}}), "p");
  ASSERT_TRUE(one.ok());
  EXPECT_EQ(one->polygons[0].rings[0], kWkbSquare);
}

// fuzz_wkb: a ring given with its closing point twice is stored ending on its first point; the
// writer once took that for the closing point and dropped it, so the ring lost a point on the way
// back.
TEST(Wkb, ARingStillEndingOnItsFirstPointSurvivesTheWriter) {
  const Ring ring{{0, 0}, {4, 0}, {2, 3}, {0, 0}};
  const MultiPolygon region{{Polygon{{ring}}}};
  auto back = parse_wkb(format_wkb(region), "w");
  ASSERT_TRUE(back.ok()) << back.error().what();
  EXPECT_EQ(back->all_rings(), region.all_rings());
  auto via_wkt = parse_wkt(format_wkt(region), "t");
  ASSERT_TRUE(via_wkt.ok());
  EXPECT_EQ(*back, *via_wkt);
}

TEST(Wkb, NamesOtherGeometryTypesAsUnsupported) {
  Bytes point(false);
  point.order().u32(1).f64(1).f64(2);
  auto r = parse_wkb(point.str(), "p.wkb");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::unsupported);
  EXPECT_NE(r.error().message.find("Point"), std::string::npos) << r.error().message;
  EXPECT_EQ(r.error().source, "p.wkb");
  Bytes line(false);
  line.order().u32(6).u32(1).order().u32(2).u32(0);  // a LineString inside a MultiPolygon
  EXPECT_EQ(parse_wkb(line.str(), "l").error().kind, ErrorKind::parse);
}

TEST(Wkb, RejectsTruncatedLyingAndTrailingBytesWithTheOffset) {
  Bytes b(false);
  b.order().u32(3).u32(1).ring(kWkbSquare);
  const std::string good = b.str();
  for (std::size_t cut = 0; cut < good.size(); ++cut) {
    auto r = parse_wkb(good.substr(0, cut), "t");
    ASSERT_FALSE(r.ok()) << cut;
    EXPECT_EQ(r.error().kind, ErrorKind::parse) << cut;
  }
  auto trailing = parse_wkb(good + "x", "t");
  ASSERT_FALSE(trailing.ok());
  EXPECT_NE(trailing.error().message.find("byte 93"), std::string::npos)
      << trailing.error().message;
  Bytes lying(false);
  lying.order().u32(3).u32(0xffffffffu);
  EXPECT_EQ(parse_wkb(lying.str(), "t").error().kind, ErrorKind::parse);
  Bytes order(false);
  order.u32(0);
  EXPECT_EQ(parse_wkb("\x02" + order.str(), "t").error().kind, ErrorKind::parse);
}

TEST(Wkb, RejectsNanCoordinatesAndDegenerateRings) {
  Bytes nan(false);
  nan.order().u32(3).u32(1).u32(4).f64(0).f64(0).f64(1).f64(0);
  nan.f64(std::numeric_limits<double>::quiet_NaN()).f64(1).f64(0).f64(0);
  EXPECT_EQ(parse_wkb(nan.str(), "t").error().kind, ErrorKind::invalid_value);
  Bytes two(false);
  two.order().u32(3).u32(1).ring(Ring{{0, 0}, {1, 0}});
  EXPECT_EQ(parse_wkb(two.str(), "t").error().kind, ErrorKind::degenerate);
}

TEST(Wkb, DeeplyNestedCollectionsFailCleanly) {
  std::string bytes;
  for (int i = 0; i < 200; ++i) {
    Bytes b(false);
    b.order().u32(7).u32(1);
    bytes += b.str();
  }
  Bytes leaf(false);
  leaf.order().u32(3).u32(0);
  auto r = parse_wkb(bytes + leaf.str(), "deep");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::unsupported);
}

}  // namespace
}  // namespace contain::io
