// tests/data/inside: point containment cases (polygons, meshes, CSG trees) with their recorded
// in/on/out answers, checked through the library and through the `contain inside` command.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "contain/core/location.h"
#include "contain/inside/csg.h"
#include "contain/inside/mesh_index.h"
#include "contain/inside/polygon_index.h"
#include "contain/io/csg_json.h"
#include "contain/io/mesh_io.h"
#include "contain/io/points_io.h"
#include "contain/io/region_io.h"
#include "regression/regression_corpus.h"

namespace contain::test {
namespace {

Fill fill_named(const std::string& name) {
  if (name == "nonzero") return Fill::nonzero;
  if (name == "positive") return Fill::positive;
  if (name == "negative") return Fill::negative;
  return Fill::even_odd;
}

// The answers of the library for the case's shape and points, spelled as the command prints them.
std::vector<std::string> library_answers(const RegressionCase& c) {
  std::vector<std::string> answers;
  const std::string points = c.option("--points").value_or("");
  if (const auto polygon = c.option("--polygon")) {
    auto region = io::read_region_with_notes(*polygon);
    EXPECT_TRUE(region.ok()) << region.error().what();
    auto p = io::read_points2(points);
    EXPECT_TRUE(p.ok()) << p.error().what();
    if (!region.ok() || !p.ok()) return answers;
    const bool warned = !c.err.empty();
    EXPECT_EQ(!region->notes.unclosed_rings.empty(), warned)
        << "the reader's notes of unclosed rings";
    const inside::PolygonIndex index(region->region,
                                     {.fill = fill_named(c.option("--fill").value_or(""))});
    for (const Vec2 q : p->points)
      answers.emplace_back(to_string(index.locate(q)));
  } else {
    auto p = io::read_points3(points);
    EXPECT_TRUE(p.ok()) << p.error().what();
    if (!p.ok()) return answers;
    if (const auto mesh = c.option("--mesh")) {
      auto file = io::read_mesh(*mesh);
      EXPECT_TRUE(file.ok()) << file.error().what();
      if (!file.ok()) return answers;
      const inside::MeshIndex index(file->mesh);
      // A closed mesh is its solid, crossing itself or not (issue 24): never a crossing warning.
      EXPECT_TRUE(std::none_of(c.err.begin(), c.err.end(), [](const auto& e) {
        return e.find("crosses itself") != std::string::npos;
      })) << "inside warns of no self-crossing";
      for (const Vec3 q : p->points)
        answers.emplace_back(to_string(index.locate(q)));
    } else if (const auto csg = c.option("--csg")) {
      auto tree = io::read_csg_json(*csg);
      EXPECT_TRUE(tree.ok()) << tree.error().what();
      if (!tree.ok()) return answers;
      auto solid = inside::CsgSolid::prepare(*tree);
      EXPECT_TRUE(solid.ok()) << solid.error().what();
      if (!solid.ok()) return answers;
      for (const Vec3 q : p->points)
        answers.emplace_back(to_string(solid->locate(q)));
    } else {
      ADD_FAILURE() << "case " << c.name << ": no --polygon, --mesh or --csg";
    }
  }
  return answers;
}

TEST(RegressionCorpus, InsideCasesGiveTheirRecordedAnswersThroughTheLibrary) {
  const auto cases = read_regression_cases("inside");
  ASSERT_FALSE(cases.empty());
  for (const RegressionCase& c : cases) {
    SCOPED_TRACE("case " + c.name + " (cases.txt:" + std::to_string(c.line) + ")");
    ASSERT_EQ(c.verb(), "inside");
    ASSERT_EQ(c.exit_code, 0) << "inside cases are answers; bad input belongs in tests/data/io";
    EXPECT_EQ(library_answers(c), c.out);
  }
}

TEST(RegressionCorpus, InsideCasesGiveTheirRecordedAnswersThroughTheCommand) {
  for (const RegressionCase& c : read_regression_cases("inside"))
    expect_cli_gives_recorded_answer(c);
}

TEST(RegressionCorpus, EveryInsideFileHasACase) {
  expect_every_file_has_a_case("inside", read_regression_cases("inside"));
}

}  // namespace
}  // namespace contain::test
