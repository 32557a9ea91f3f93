#pragma once
// A small layer for the end-to-end tests of `contain inside --layer`, written by hand so that
// every answer is known: a 3 x 2 block of unit squares sharing edges and corners, two
// overlapping squares, land with a lake and an island in the lake, and the lake itself.

#include <string>

namespace contain::test {

/// The layer as a GeoJSON FeatureCollection; property "name" holds the ids below, "code" a
/// number; features carry no "id" member (so positions are the default ids).
///   0..5  s00 s10 s20 s01 s11 s21: square (i, j) = [i, i+1] x [j, j+1]
///   6, 7  ovA [10, 14]^2 and ovB [12, 16]^2 (overlapping)
///   8     land [20, 30]^2 with the lake [22, 28]^2 as a hole
///   9     island [24, 26]^2 in the lake
///   10    lake [22, 28]^2
inline std::string layer_geojson() {
  auto square = [](const std::string& name, int code, double x0, double y0, double x1, double y1,
                   const std::string& hole = "") {
    auto ring = [](double a, double b, double c, double d) {
      return "[[" + std::to_string(a) + "," + std::to_string(b) + "],[" + std::to_string(c) + "," +
             std::to_string(b) + "],[" + std::to_string(c) + "," + std::to_string(d) + "],[" +
             std::to_string(a) + "," + std::to_string(d) + "],[" + std::to_string(a) + "," +
             std::to_string(b) + "]]";
    };
    return R"({"type":"Feature","properties":{"name":")" + name + R"(","code":)" +
           std::to_string(code) + R"(},"geometry":{"type":"Polygon","coordinates":[)" +
           ring(x0, y0, x1, y1) + (hole.empty() ? "" : "," + hole) + "]}}";
  };
  std::string features;
  int code = 100;
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 3; ++i) {
      features += square("s" + std::to_string(i) + std::to_string(j), code++, i, j, i + 1, j + 1);
      features += ",\n";
    }
  }
  features += square("ovA", code++, 10, 10, 14, 14) + ",\n";
  features += square("ovB", code++, 12, 12, 16, 16) + ",\n";
  // The lake hole runs clockwise, as OGC writes holes.
  features +=
      square("land", code++, 20, 20, 30, 30, "[[22,22],[22,28],[28,28],[28,22],[22,22]]") + ",\n";
  features += square("island", code++, 24, 24, 26, 26) + ",\n";
  features += square("lake", code++, 22, 22, 28, 28);
  return "{\"type\":\"FeatureCollection\",\"features\":[\n" + features + "\n]}\n";
}

/// The same regions as WKT, one a line (ids: positions 0..10).
inline std::string layer_wkt() {
  std::string out = "# the layer of layer_geojson(), one region a line\n";
  auto square = [](double x0, double y0, double x1, double y1) {
    auto p = [](double x, double y) { return std::to_string(x) + " " + std::to_string(y); };
    return "(" + p(x0, y0) + ", " + p(x1, y0) + ", " + p(x1, y1) + ", " + p(x0, y1) + ", " +
           p(x0, y0) + ")";
  };
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 3; ++i)
      out += "POLYGON (" + square(i, j, i + 1, j + 1) + ")\n";
  }
  out += "POLYGON (" + square(10, 10, 14, 14) + ")\n";
  out += "\nPOLYGON (" + square(12, 12, 16, 16) + ")\n";
  out += "POLYGON (" + square(20, 20, 30, 30) + ", (22 22, 22 28, 28 28, 28 22, 22 22))\n";
  out += "POLYGON (" + square(24, 24, 26, 26) + ")\n";
  out += "POLYGON (" + square(22, 22, 28, 28) + ")\n";
  return out;
}

/// Points with their expected lines under --id name (report policy).
struct LayerCase {
  const char* point;
  const char* by_name;
};

inline constexpr LayerCase kLayerCases[] = {
    {"0.5 0.5", "s00"},
    {"1 0.5", "s00:on s10:on"},              // shared edge
    {"1 1", "s00:on s10:on s01:on s11:on"},  // shared corner of four
    {"2 1", "s10:on s20:on s11:on s21:on"},  // another
    {"3 2", "s21:on"},                       // outer corner
    {"1.5 2", "s11:on"},                     // outer edge
    {"3.5 0.5", "-"},                        // outside
    {"13 13", "ovA ovB"},                    // overlap
    {"14 13", "ovA:on ovB"},                 // edge of one, inside the other
    {"12 12", "ovA ovB:on"},                 // corner of ovB inside ovA
    {"21 21", "land"},                       // land
    {"23 23", "lake"},                       // water: in the hole of land
    {"22 25", "land:on lake:on"},            // the shore
    {"25 25", "island lake"},                // the island in the lake
    {"24 25", "island:on lake"},             // the island's shore
    {"-1e308 1e308", "-"},                   // far away
};

/// The points of kLayerCases, one a line.
inline std::string case_points() {
  std::string points;
  for (const LayerCase& c : kLayerCases)
    points += std::string(c.point) + "\n";
  return points;
}

/// The expected answers of kLayerCases under --id name.
inline std::string expected_by_name() {
  std::string out;
  for (const LayerCase& c : kLayerCases)
    out += std::string(c.by_name) + "\n";
  return out;
}

}  // namespace contain::test
