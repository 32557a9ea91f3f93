#include "contain/io/svg.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace contain::io {
namespace {

std::size_t count(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos;
       at = text.find(needle, at + needle.size()))
    ++n;
  return n;
}

TEST(SvgCells, RunsOfOneColourAlongARowBecomeOneRectangleAndBlankCellsAreSkipped) {
  SvgCanvas canvas({{0, 0}, {4, 2}}, 400);
  // Row 0: red red blue (blank); row 1: four greens.
  const std::vector<std::string> colours = {"#ff0000", "#ff0000", "#0000ff", "",
                                            "#00ff00", "#00ff00", "#00ff00", "#00ff00"};
  canvas.cells({{0, 0}, {4, 2}}, 4, 2, colours);
  const std::string svg = canvas.str();
  EXPECT_EQ(count(svg, "fill=\"#ff0000\""), 1u);
  EXPECT_EQ(count(svg, "fill=\"#0000ff\""), 1u);
  EXPECT_EQ(count(svg, "fill=\"#00ff00\""), 1u);
  EXPECT_EQ(count(svg, "<rect"), 4u);  // three runs and the white background
}

TEST(SvgCells, FewerColoursThanCellsOrNoCellsDrawOnlyWhatIsGiven) {
  SvgCanvas canvas({{0, 0}, {1, 1}}, 100);
  const std::vector<std::string> colours = {"#123456"};
  canvas.cells({{0, 0}, {1, 1}}, 3, 3, colours);
  canvas.cells({{0, 0}, {1, 1}}, 0, 5, colours);
  const std::string svg = canvas.str();
  EXPECT_EQ(count(svg, "fill=\"#123456\""), 1u);
}

// The unit cube [0, 1]^3, outward.
Mesh cube() {
  Mesh m;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x)
        m.vertices.push_back({double(x), double(y), double(z)});
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

TEST(Svg, ProjectionKeepsZUpAndTheViewAxesOrthonormal) {
  const View3 view{.azimuth_deg = 30, .elevation_deg = 40};
  const Vec2 up = project({0, 0, 1}, view);
  EXPECT_NEAR(up.x, 0.0, 1e-15);
  EXPECT_NEAR(up.y, std::cos(40 * 3.141592653589793 / 180), 1e-15);
  // Straight from the front (azimuth -90: the viewer on -y) x goes right and z up, exactly.
  const View3 front{.azimuth_deg = -90, .elevation_deg = 0};
  const Vec2 p = project({2, 5, 3}, front);
  EXPECT_NEAR(p.x, 2.0, 1e-15);
  EXPECT_NEAR(p.y, 3.0, 1e-15);
  EXPECT_GT(view_depth({0, -1, 0}, front), view_depth({0, 1, 0}, front));
}

TEST(Svg, MeshDrawsEveryTriangleBackToFrontShadedByFacing) {
  const Mesh m = cube();
  const View3 view{};
  SvgCanvas canvas(projected_bounds(m.vertices, view), 300);
  EXPECT_EQ(canvas.mesh(m, view), 12u);
  const std::string svg = canvas.str();
  EXPECT_EQ(count(svg, "<path "), 12u);
  EXPECT_EQ(svg.rfind("</svg>"), svg.size() - 7);
  // Faces squarely facing the viewer are lighter than grazing ones: more than one shade.
  EXPECT_GE(count(svg, "fill=\"#"), 12u);
  EXPECT_NE(svg.find("fill=\"#"), std::string::npos);
}

TEST(Svg, MeshPastTheLimitDropsBackFacesFirstAndSaysSo) {
  const Mesh m = cube();
  SvgCanvas canvas(projected_bounds(m.vertices, {}), 300);
  // Seen from the default view three faces (six triangles) face the viewer.
  EXPECT_EQ(canvas.mesh(m, {}, {.max_triangles = 6}), 6u);
  const std::string picture = mesh_svg(m, {.title = "cube", .max_triangles = 3});
  EXPECT_NE(picture.find("cube (3 of 12 triangles drawn)"), std::string::npos) << picture;
}

TEST(Svg, RegionPictureFillsWithTheEvenOddRuleAndEscapesTheTitle) {
  const MultiPolygon region{
      {Polygon{{Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, Ring{{1, 1}, {1, 3}, {3, 3}, {3, 1}}}}}};
  const std::string svg = region_svg(region, {.title = "a < b & c"});
  EXPECT_EQ(count(svg, "<path "), 1u);
  EXPECT_NE(svg.find("fill-rule=\"evenodd\""), std::string::npos);
  EXPECT_EQ(count(svg, "Z "), 2u);  // two rings, one path
  EXPECT_NE(svg.find("a &lt; b &amp; c"), std::string::npos);
  // An empty region and an empty mesh still give a whole document.
  EXPECT_NE(region_svg(MultiPolygon{}).find("</svg>"), std::string::npos);
  EXPECT_NE(mesh_svg(Mesh{}).find("</svg>"), std::string::npos);
}

}  // namespace
}  // namespace contain::io
