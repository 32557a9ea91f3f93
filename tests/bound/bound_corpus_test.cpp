// The shared corpus of bounds (shared/corpus/mesh-cases/bound/bound.jsonl): per mesh the exact
// AABB of the referenced vertices and the minimal enclosing sphere's radius (40 digits).
#include <gtest/gtest.h>

#include <charconv>
#include <fstream>
#include <string>
#include <vector>

#include "bound/ball_checks.h"
#include "bound/test_mesh_reader.h"
#include "contain/bound/aabb.h"
#include "contain/bound/bounding_sphere.h"
#include "contain/bound/mesh_vertices.h"
#include "support/shared_corpus.h"

namespace contain::bound {
namespace {

// The text after `"key":` in a one-line JSON object (enough for the corpus' flat layout).
std::string after_key(const std::string& line, const std::string& key) {
  const std::size_t at = line.find("\"" + key + "\"");
  if (at == std::string::npos) return {};
  return line.substr(line.find(':', at) + 1);
}

double parse_number(const std::string& text) {
  std::size_t begin = text.find_first_of("-0123456789");
  std::size_t end = text.find_first_not_of("-+.0123456789eE", begin);
  // A number that runs to the end: data() + npos is pointer overflow (clang's UBSan stops here).
  if (begin == std::string::npos) return 0.0;
  if (end == std::string::npos) end = text.size();
  double value = 0.0;
  std::from_chars(text.data() + begin, text.data() + end, value);
  return value;
}

Vec3 parse_triple(const std::string& text) {
  const std::size_t open = text.find('[');
  const std::size_t c1 = text.find(',', open);
  const std::size_t c2 = text.find(',', c1 + 1);
  return {parse_number(text.substr(open + 1)), parse_number(text.substr(c1 + 1)),
          parse_number(text.substr(c2 + 1))};
}

std::string parse_string(const std::string& text) {
  const std::size_t open = text.find('"');
  return text.substr(open + 1, text.find('"', open + 1) - open - 1);
}

TEST(BoundCorpus, AabbIsEqualAndTheSphereIsMinimalAndContainsEveryVertex) {
  CONTAIN_REQUIRE_SHARED();
  const auto shared = *test::shared_dir();
  std::ifstream cases(shared / "corpus/mesh-cases/bound/bound.jsonl");
  ASSERT_TRUE(cases) << "bound.jsonl is missing";
  std::string line;
  int count = 0;
  while (std::getline(cases, line)) {
    if (line.empty()) continue;
    ++count;
    const std::string name = parse_string(after_key(line, "mesh"));
    const std::string aabb_text = after_key(line, "aabb");
    const Box3 truth_box{parse_triple(after_key(aabb_text, "min")),
                         parse_triple(after_key(aabb_text, "max"))};
    const double radius_exact = parse_number(parse_string(after_key(line, "radius_exact")));
    std::string why;
    // Mesh paths are relative to the folder holding shared/.
    const auto mesh = test::read_test_mesh(shared.parent_path() / name, why);
    ASSERT_TRUE(mesh) << name << ": " << why;
    const std::vector<Vec3> vertices = referenced_vertices(*mesh);

    EXPECT_EQ(aabb(*mesh), truth_box) << name;
    auto exact = bounding_sphere(*mesh);
    ASSERT_TRUE(exact.ok()) << name;
    EXPECT_NEAR(exact->radius, radius_exact, 1e-9 * radius_exact) << name;
    EXPECT_EQ(test::count_outside(*exact, vertices), 0u) << name;
    const double excess = test::relative_excess(*exact, vertices);
    EXPECT_GE(excess, 0.0) << name;
    EXPECT_LE(excess, 1e-12) << name;

    auto ritter = bounding_sphere(*mesh, {.method = SphereMethod::ritter});
    ASSERT_TRUE(ritter.ok()) << name;
    EXPECT_EQ(test::count_outside(*ritter, vertices), 0u) << name;
    EXPECT_GE(ritter->radius, radius_exact * (1.0 - 1e-12)) << name;
  }
  EXPECT_GE(count, 14);
}

}  // namespace
}  // namespace contain::bound
