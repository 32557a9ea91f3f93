// The ring writer of WKT and GeoJSON (src/io/ring_text.cpp): each coordinate the shortest
// std::to_chars form, as the writers always wrote them, and the append forms of format_wkt /
// format_geojson equal to the returning ones.

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "contain/io/geojson.h"
#include "contain/io/wkt.h"
#include "io/ring_text.h"

namespace contain::test {
namespace {

std::string shortest(double value) {
  std::array<char, 32> buffer{};
  return {buffer.data(), std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr};
}

// The ring's WKT and GeoJSON text built number by number, the writers' reference.
std::string wkt_ring(const Ring& ring) {
  std::string out = "(";
  for (std::size_t i = 0; i <= ring.size(); ++i) {
    const Vec2& q = ring[i % ring.size()];
    out += (i ? ", " : "") + shortest(q.x) + " " + shortest(q.y);
  }
  return out + ")";
}
std::string json_ring(const Ring& ring) {
  std::string out = "[";
  for (std::size_t i = 0; i <= ring.size(); ++i) {
    const Vec2& q = ring[i % ring.size()];
    out += (i ? ",[" : "[") + shortest(q.x) + "," + shortest(q.y) + "]";
  }
  return out + "]";
}

std::vector<double> edge_doubles() {
  return {0.0,
          -0.0,
          1.0,
          -3.0,
          1e-7,
          1e15,
          1e16,
          123456789012345680.0,
          1e300,
          -1e300,
          0.1,
          1.0 / 3.0,
          std::numeric_limits<double>::max(),
          -std::numeric_limits<double>::max(),
          std::numeric_limits<double>::min(),
          std::numeric_limits<double>::denorm_min(),
          -std::numeric_limits<double>::denorm_min(),
          4.9406564584124654e-320,
          std::nextafter(1.0, 2.0),
          9007199254740993.0};
}

TEST(RingText, CoordinatesAreTheShortestToCharsFormOfEdgeAndRandomDoubles) {
  std::vector<double> numbers = edge_doubles();
  std::mt19937_64 random(26);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1074, 1023);
  for (int i = 0; i < 20000; ++i)
    numbers.push_back(std::ldexp(unit(random), exponent(random)));
  std::uniform_int_distribution<std::uint64_t> bits;
  for (int i = 0; i < 20000; ++i) {
    const double any = std::bit_cast<double>(bits(random));
    if (std::isfinite(any)) numbers.push_back(any);
  }
  MultiPolygon region;
  for (std::size_t i = 0; i + 6 <= numbers.size(); i += 6) {
    region.polygons.push_back(Polygon{{Ring{{numbers[i], numbers[i + 1]},
                                            {numbers[i + 2], numbers[i + 3]},
                                            {numbers[i + 4], numbers[i + 5]}}}});
  }
  std::string wkt = "MULTIPOLYGON (";
  std::string json = R"({"type":"MultiPolygon","coordinates":[)";
  for (std::size_t p = 0; p < region.polygons.size(); ++p) {
    wkt += (p ? ", (" : "(") + wkt_ring(region.polygons[p].rings[0]) + ")";
    json += (p ? ",[" : "[") + json_ring(region.polygons[p].rings[0]) + "]";
  }
  EXPECT_EQ(io::format_wkt(region), wkt + ")");
  EXPECT_EQ(io::format_geojson(region), json + "]}");
}

TEST(RingText, AppendingFormsAddToTheTextAsTheReturningFormsWrite) {
  const MultiPolygon region{
      {Polygon{{Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, Ring{{1, 1}, {1, 2}, {2, 2}, {2, 1}}}},
       Polygon{{Ring{{5, 5}, {6, 5}, {6, 6.5}}}}}};
  std::string text = "prefix ";
  io::format_wkt(region, text);
  EXPECT_EQ(text, "prefix " + io::format_wkt(region));
  text = "prefix ";
  io::format_geojson(region, text);
  EXPECT_EQ(text, "prefix " + io::format_geojson(region));
  text.clear();
  io::format_wkt(MultiPolygon{}, text);
  EXPECT_EQ(text, "MULTIPOLYGON EMPTY");
  EXPECT_EQ(io::format_wkt(region),
            "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1)), ((5 5, 6 5, "
            "6 6.5, 5 5)))");
}

TEST(RingText, AnEmptyRingIsAnEmptyPairOfBracketsAndARingIsClosedByItsFirstPoint) {
  std::string text = "x";
  io::detail::append_ring_text(text, Ring{}, io::detail::RingSyntax::wkt);
  io::detail::append_ring_text(text, Ring{}, io::detail::RingSyntax::geojson);
  EXPECT_EQ(text, "x()[]");
  text.clear();
  io::detail::append_ring_text(text, Ring{{-0.0, 1e-7}}, io::detail::RingSyntax::wkt);
  io::detail::append_ring_text(text, Ring{{0.5, -2}, {1e21, 3}}, io::detail::RingSyntax::geojson);
  EXPECT_EQ(text, "(-0 1e-07, -0 1e-07)[[0.5,-2],[1e+21,3],[0.5,-2]]");
}

}  // namespace
}  // namespace contain::test
