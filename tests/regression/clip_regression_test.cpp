// tests/data/clip: segments by boxes, polygons by boxes and half-planes, meshes cut and capped,
// polygon booleans, sections of solids (contain slice), and bad clip options, with their recorded
// results, checked through the library and through the `contain clip` and `contain slice`
// commands.

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "contain/clip/clip_polygon.h"
#include "contain/clip/cohen_sutherland.h"
#include "contain/clip/liang_barsky.h"
#include "contain/clip/mesh_clip.h"
#include "contain/clip/polygon_boolean.h"
#include "contain/clip/slice_mesh.h"
#include "contain/io/mesh_io.h"
#include "contain/io/number_table.h"
#include "contain/io/region_io.h"
#include "contain/io/wkt.h"
#include "regression/regression_corpus.h"

namespace contain::test {
namespace {

std::vector<double> numbers(const std::string& text, char separator) {
  std::vector<double> out;
  std::istringstream in(text);
  for (std::string word; std::getline(in, word, separator);) {
    if (!word.empty()) out.push_back(std::stod(word));  // strtod: correctly rounded
  }
  return out;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

// The command writes one polygon as POLYGON, the library's format_wkt(MultiPolygon) always as
// MULTIPOLYGON: the library result is compared with the recorded text read back, point by point.
void expect_region(const MultiPolygon& result, const std::vector<std::string>& out) {
  ASSERT_EQ(out.size(), 1u);
  auto recorded = io::parse_wkt(out.front(), "cases.txt");
  ASSERT_TRUE(recorded.ok()) << recorded.error().what();
  EXPECT_EQ(result, *recorded) << io::format_wkt(result);
}

MultiPolygon read_region_or_fail(const std::string& path) {
  auto region = io::read_region(path);
  EXPECT_TRUE(region.ok()) << region.error().what();
  return region.ok() ? *region : MultiPolygon{};
}

// Segments by a box with the named algorithm: each kept segment's endpoints are the recorded
// numbers bit for bit, '-' where nothing is left.
void expect_segments(const RegressionCase& c) {
  auto table = io::read_number_table(*c.option("--segments"));
  ASSERT_TRUE(table.ok()) << table.error().what();
  const std::vector<double> b = numbers(*c.option("--box"), ',');
  ASSERT_EQ(b.size(), 4u);
  const Box2 box{{b[0], b[1]}, {b[2], b[3]}};
  const std::string algorithm = c.option("--algorithm").value_or("liang-barsky");
  ASSERT_EQ(table->rows(), c.out.size());
  for (std::size_t i = 0; i < table->rows(); ++i) {
    ASSERT_EQ(table->columns, 4);
    const double* row = table->values.data() + i * 4;
    const Segment2 s{{row[0], row[1]}, {row[2], row[3]}};
    const clip::ClippedSegment2 r = algorithm == "cohen-sutherland" ? clip::cohen_sutherland(s, box)
                                                                    : clip::liang_barsky(s, box);
    if (c.out[i] == "-") {
      EXPECT_FALSE(r.kept) << "segment " << i;
      continue;
    }
    ASSERT_TRUE(r.kept) << "segment " << i;
    const std::vector<double> want = numbers(c.out[i], ' ');
    ASSERT_EQ(want.size(), 4u);
    EXPECT_EQ((std::vector<double>{r.segment.a.x, r.segment.a.y, r.segment.b.x, r.segment.b.y}),
              want)
        << "segment " << i;
  }
}

// Sections (contain slice): each recorded line is the plane's value, a tab and the section.
void expect_sections(const RegressionCase& c) {
  auto file = io::read_mesh(*c.option("--mesh"));
  ASSERT_TRUE(file.ok()) << file.error().what();
  std::vector<double> values;
  for (std::size_t i = 0; i + 1 < c.run.size(); ++i) {
    if (c.run[i] == "--z") values.push_back(std::stod(c.run[i + 1]));
  }
  auto sections = clip::slice_mesh(file->mesh, values);
  ASSERT_TRUE(sections.ok()) << sections.error().what();
  ASSERT_EQ(sections->size(), c.out.size());
  for (std::size_t i = 0; i < c.out.size(); ++i) {
    const std::size_t tab = c.out[i].find('\t');
    ASSERT_NE(tab, std::string::npos);
    EXPECT_EQ((*sections)[i].value, std::stod(c.out[i].substr(0, tab)));
    expect_region((*sections)[i].region, {c.out[i].substr(tab + 1)});
  }
}

void expect_library_result(const RegressionCase& c) {
  if (c.verb() == "slice") {
    expect_sections(c);
  } else if (const auto op = c.option("--op")) {
    const std::map<std::string, clip::Op> ops{{"intersection", clip::Op::intersection},
                                              {"union", clip::Op::union_},
                                              {"difference", clip::Op::difference},
                                              {"xor", clip::Op::xor_}};
    const MultiPolygon result =
        clip::polygon_boolean(read_region_or_fail(*c.option("--subject")),
                              read_region_or_fail(*c.option("--clip")), {.op = ops.at(*op)});
    expect_region(result, c.out);
  } else if (const auto polygon = c.option("--polygon")) {
    const MultiPolygon region = read_region_or_fail(*polygon);
    MultiPolygon result;
    if (const auto box = c.option("--box")) {
      const std::vector<double> b = numbers(*box, ',');
      ASSERT_EQ(b.size(), 4u);
      result = clip::clip_polygon(region, Box2{{b[0], b[1]}, {b[2], b[3]}});
    } else {
      const std::vector<double> h = numbers(*c.option("--halfspace"), ',');
      ASSERT_EQ(h.size(), 3u);
      const std::vector<HalfPlane> planes{{h[0], h[1], h[2]}};
      result = clip::clip_polygon(region, planes);
    }
    expect_region(result, c.out);
  } else if (const auto mesh = c.option("--mesh")) {
    auto file = io::read_mesh(*mesh);
    ASSERT_TRUE(file.ok()) << file.error().what();
    const std::vector<double> h = numbers(*c.option("--halfspace"), ',');
    ASSERT_EQ(h.size(), 4u);
    const std::vector<Plane> planes{{h[0], h[1], h[2], h[3]}};
    const Mesh cut = clip::clip_mesh(file->mesh, planes, {.cut = clip::MeshCut::cap});
    EXPECT_EQ(lines_of(io::format_mesh(cut, io::MeshFormat::off)), c.out);
  } else if (c.option("--segments")) {
    expect_segments(c);
  } else {
    ADD_FAILURE() << "case " << c.name << ": no library check for this command";
  }
}

TEST(RegressionCorpus, ClipCasesGiveTheirRecordedResultsThroughTheLibrary) {
  const auto cases = read_regression_cases("clip");
  ASSERT_FALSE(cases.empty());
  for (const RegressionCase& c : cases) {
    SCOPED_TRACE("case " + c.name + " (cases.txt:" + std::to_string(c.line) + ")");
    ASSERT_TRUE(c.verb() == "clip" || c.verb() == "slice");
    // Refused options (inverted box, negative radius, --cap of an open mesh) are the command's
    // checks of its arguments: the command part below covers them.
    if (c.exit_code != 0) continue;
    expect_library_result(c);
  }
}

TEST(RegressionCorpus, ClipCasesGiveTheirRecordedResultsThroughTheCommand) {
  for (const RegressionCase& c : read_regression_cases("clip"))
    expect_cli_gives_recorded_answer(c);
}

TEST(RegressionCorpus, EveryClipFileHasACase) {
  expect_every_file_has_a_case("clip", read_regression_cases("clip"));
}

}  // namespace
}  // namespace contain::test
