#include "contain/io/svg.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace contain::io {
namespace {

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
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
  EXPECT_EQ(occurrences(svg, "fill=\"#ff0000\""), 1u);
  EXPECT_EQ(occurrences(svg, "fill=\"#0000ff\""), 1u);
  EXPECT_EQ(occurrences(svg, "fill=\"#00ff00\""), 1u);
  EXPECT_EQ(occurrences(svg, "<rect"), 4u);  // three runs and the white background
}

TEST(SvgCells, FewerColoursThanCellsOrNoCellsDrawOnlyWhatIsGiven) {
  SvgCanvas canvas({{0, 0}, {1, 1}}, 100);
  const std::vector<std::string> colours = {"#123456"};
  canvas.cells({{0, 0}, {1, 1}}, 3, 3, colours);
  canvas.cells({{0, 0}, {1, 1}}, 0, 5, colours);
  const std::string svg = canvas.str();
  EXPECT_EQ(occurrences(svg, "fill=\"#123456\""), 1u);
}

}  // namespace
}  // namespace contain::io
