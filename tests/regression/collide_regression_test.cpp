// tests/data/collide: pairs of solids and of 2D regions that touch, nest or miss by one ulp, with
// their recorded answers, checked through the library and through the `contain collide` command.

#include <gtest/gtest.h>

#include <charconv>
#include <string>
#include <vector>

#include "contain/collide/ccd.h"
#include "contain/collide/mesh_mesh.h"
#include "contain/collide/region_region.h"
#include "contain/io/ccd_queries.h"
#include "contain/io/mesh_io.h"
#include "contain/io/region_io.h"
#include "regression/regression_corpus.h"

namespace contain::test {
namespace {

bool is_region(const std::string& path) {
  return path.ends_with(".wkt") || path.ends_with(".geojson");
}

// The library's answer for the pair, spelled as the command prints it.
std::string library_answer(const std::string& a, const std::string& b) {
  bool intersect = false;
  if (is_region(a)) {
    auto ra = io::read_region(a);
    auto rb = io::read_region(b);
    EXPECT_TRUE(ra.ok() && rb.ok());
    if (!ra.ok() || !rb.ok()) return "unread";
    intersect = collide::region_region(*ra, *rb).intersect;
  } else {
    auto ma = io::read_mesh(a);
    auto mb = io::read_mesh(b);
    EXPECT_TRUE(ma.ok() && mb.ok());
    if (!ma.ok() || !mb.ok()) return "unread";
    intersect = collide::mesh_mesh(ma->mesh, mb->mesh).intersect;
  }
  return intersect ? "intersect" : "disjoint";
}

// The library's answers to a `collide --ccd KIND --queries FILE` case, one line a query as the
// command prints them (the time as the shortest decimal that reads back as the same double).
std::vector<std::string> library_ccd_answers(const RegressionCase& c) {
  const auto kind = c.option("--ccd");
  const auto file = c.option("--queries");
  EXPECT_TRUE(kind && file);
  if (!kind || !file) return {};
  auto queries = io::read_ccd_queries(*file);
  EXPECT_TRUE(queries.ok());
  if (!queries.ok()) return {"unread"};
  std::vector<std::string> out;
  for (const io::CcdPoints& q : queries->queries) {
    const collide::Impact i =
        *kind == "vertex-face" ? collide::vertex_face_ccd(q) : collide::edge_edge_ccd(q);
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, i.time).ptr;
    out.push_back(i.hit ? "hit " + std::string(text, end) : "miss");
  }
  return out;
}

TEST(RegressionCorpus, CollideCasesGiveTheirRecordedAnswersThroughTheLibrary) {
  const auto cases = read_regression_cases("collide");
  ASSERT_FALSE(cases.empty());
  for (const RegressionCase& c : cases) {
    SCOPED_TRACE("case " + c.name + " (cases.txt:" + std::to_string(c.line) + ")");
    if (c.option("--ccd")) {
      EXPECT_EQ(library_ccd_answers(c), c.out);
      continue;
    }
    ASSERT_EQ(c.run.size(), 3u) << "collide A B";
    ASSERT_EQ(c.out.size(), 1u);
    EXPECT_EQ(library_answer(c.run[1], c.run[2]), c.out.front());
    EXPECT_EQ(library_answer(c.run[2], c.run[1]), c.out.front()) << "with A and B swapped";
  }
}

TEST(RegressionCorpus, CollideCasesGiveTheirRecordedAnswersThroughTheCommand) {
  for (const RegressionCase& c : read_regression_cases("collide")) {
    expect_cli_gives_recorded_answer(c);
  }
}

TEST(RegressionCorpus, EveryCollideFileHasACase) {
  expect_every_file_has_a_case("collide", read_regression_cases("collide"));
}

}  // namespace
}  // namespace contain::test
