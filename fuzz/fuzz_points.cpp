// libFuzzer target: point files and number tables (io::parse_points2/3, parse_number_table).
// The first byte picks the reader; every number read is finite, every row has the announced
// count, and lines are increasing.
#include <cmath>
#include <string_view>

#include "contain/io/number_table.h"
#include "contain/io/points_io.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace contain;
  if (size == 0) return 0;
  const std::uint8_t which = data[0] % 3;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  if (which == 0) {
    auto points = io::parse_points2(text, "fuzz");
    if (!points) return 0;
    FUZZ_CHECK(points->points.size() == points->lines.size());
    for (std::size_t i = 0; i < points->points.size(); ++i) {
      FUZZ_CHECK(std::isfinite(points->points[i].x) && std::isfinite(points->points[i].y));
      FUZZ_CHECK(points->lines[i] >= 1 && (i == 0 || points->lines[i] > points->lines[i - 1]));
    }
  } else if (which == 1) {
    auto points = io::parse_points3(text, "fuzz");
    if (!points) return 0;
    FUZZ_CHECK(points->points.size() == points->lines.size());
    for (const Vec3& p : points->points) {
      FUZZ_CHECK(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    }
  } else {
    auto table = io::parse_number_table(text, "fuzz");
    if (!table) {
      FUZZ_CHECK(table.error().line >= 1);  // every table error names its line
      return 0;
    }
    FUZZ_CHECK(table->values.size() == table->rows() * static_cast<std::size_t>(table->columns));
    for (const double v : table->values)
      FUZZ_CHECK(std::isfinite(v));
  }
  return 0;
}
