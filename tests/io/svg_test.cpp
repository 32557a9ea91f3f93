#include "contain/io/svg.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
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
  const std::string picture = format_svg(m, {.title = "cube", .max_triangles = 3});
  EXPECT_NE(picture.find("cube (3 of 12 triangles drawn)"), std::string::npos) << picture;
}

TEST(Svg, RegionPictureFillsWithTheEvenOddRuleAndEscapesTheTitle) {
  const MultiPolygon region{
      {Polygon{{Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, Ring{{1, 1}, {1, 3}, {3, 3}, {3, 1}}}}}};
  const std::string svg = format_svg(region, {.title = "a < b & c"});
  EXPECT_EQ(count(svg, "<path "), 1u);
  EXPECT_NE(svg.find("fill-rule=\"evenodd\""), std::string::npos);
  EXPECT_EQ(count(svg, "Z "), 2u);  // two rings, one path
  EXPECT_NE(svg.find("a &lt; b &amp; c"), std::string::npos);
  // An empty region and an empty mesh still give a whole document.
  EXPECT_NE(format_svg(MultiPolygon{}).find("</svg>"), std::string::npos);
  EXPECT_NE(format_svg(Mesh{}).find("</svg>"), std::string::npos);
}

// Every number of the document (attributes and path data) is finite.
bool only_finite_numbers(const std::string& svg) {
  return svg.find("nan") == std::string::npos && svg.find("inf") == std::string::npos;
}

TEST(Svg, SubnormalHugeAndNanInputsGiveFiniteNumbersAndKeepTheShape) {
  const auto square = [](double lo, double hi) {
    return MultiPolygon{{Polygon{{Ring{{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}}}}}};
  };
  for (const MultiPolygon& region :
       {square(0, 1e-310), square(4e-320, 5e-320), square(-1.7e308, 1.7e308), square(0, 1e-200)}) {
    const std::string svg = format_svg(region);
    EXPECT_TRUE(only_finite_numbers(svg)) << svg;
    // The square fills the picture but its 4% margins: 400 px wide, from 14.81 to 385.19.
    EXPECT_NE(svg.find("M14.81 385.19 L385.19 385.19"), std::string::npos) << svg;
  }
  const Mesh triangle{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const double bad : {std::nan(""), inf, -inf}) {
    const std::string svg =
        format_svg(triangle, {.view = {.azimuth_deg = bad, .elevation_deg = bad}});
    EXPECT_TRUE(only_finite_numbers(svg)) << svg;
    EXPECT_EQ(svg, format_svg(triangle)) << "a view angle that is not finite is the default";
    EXPECT_TRUE(only_finite_numbers(format_svg(square(0, 1), {.width_px = bad})));
  }
  EXPECT_TRUE(only_finite_numbers(format_svg(square(0, 1), {.width_px = -5})));
  EXPECT_TRUE(only_finite_numbers(format_svg(square(0, 1), {.width_px = 1e-300})));
}

// The numbers of attribute `name` in an element (its text up to '>').
double attribute(const std::string& element, const std::string& name) {
  const std::size_t at = element.find(" " + name + "=\"");
  if (at == std::string::npos) return std::nan("");
  return std::stod(element.substr(at + name.size() + 3));
}

// Titles and legends lie inside the view box: each <text> from x to x + its width (its
// textLength, else 0.62 em a character, more than the mean advance of the common sans-serif
// faces), from its baseline less one em to the baseline; each legend box likewise.
void expect_text_inside_view_box(const std::string& svg) {
  const std::size_t vb = svg.find("viewBox=\"");
  ASSERT_NE(vb, std::string::npos);
  double min_x = 0, min_y = 0, width = 0, height = 0;
  ASSERT_EQ(std::sscanf(svg.c_str() + vb + 9, "%lf %lf %lf %lf", &min_x, &min_y, &width, &height),
            4);
  int texts = 0;
  for (std::size_t at = svg.find("<text"); at != std::string::npos;
       at = svg.find("<text", at + 1)) {
    ++texts;
    const std::size_t close = svg.find('>', at), end = svg.find("</text>", at);
    const std::string element = svg.substr(at, close - at);
    const std::string content = svg.substr(close + 1, end - close - 1);
    const double x = attribute(element, "x"), y = attribute(element, "y");
    const double font = attribute(element, "font-size");
    double w = attribute(element, "textLength");
    if (std::isnan(w)) w = 0.62 * font * static_cast<double>(content.size());
    EXPECT_GE(x, min_x) << element;
    EXPECT_LE(x + w, min_x + width + 1e-9) << element << " " << content;
    EXPECT_GE(y - font, min_y) << element;
    EXPECT_LE(y, min_y + height) << element;
  }
  EXPECT_GT(texts, 0);
  for (std::size_t at = svg.find("<rect x=\""); at != std::string::npos;
       at = svg.find("<rect x=\"", at + 1)) {
    const std::string element = svg.substr(at, svg.find('>', at) - at);
    const double x = attribute(element, "x"), y = attribute(element, "y");
    const double w = attribute(element, "width"), h = attribute(element, "height");
    if (element.find("100%") != std::string::npos) continue;  // the background
    EXPECT_GE(x, min_x) << element;
    EXPECT_LE(x + w, min_x + width + 1e-9) << element;
    EXPECT_GE(y, min_y) << element;
    EXPECT_LE(y + h, min_y + height + 1e-9) << element;
  }
}

TEST(Svg, TitlesAndLegendsFitInsideTheViewBox) {
  // The demo's continuous collision picture: its title was cut off at "first contact at t = 0.".
  SvgCanvas ccd({{-2, -2}, {2, 2}}, 400);
  ccd.title(
      "contain collide --from-b --to-b: a bullet through a plate, first contact at t = "
      "0.33333333333333331 (the earliest time, rounded down)");
  ccd.legend("#1f77b4", "plate");
  ccd.legend("#d62728", "bullet at t = 0 and at the first contact");
  expect_text_inside_view_box(ccd.str());
  // A narrow picture of a flat shape: the legend is taller than the shape's picture.
  SvgCanvas flat({{0, 0}, {100, 1}}, 120);
  flat.title("flat");
  for (const char* label : {"subject", "clip", "result of the boolean"})
    flat.legend("#2ca02c", label);
  expect_text_inside_view_box(flat.str());
  expect_text_inside_view_box(
      format_svg(MultiPolygon{}, {.width_px = 50, .title = "an empty region"}));
}

}  // namespace
}  // namespace contain::io
