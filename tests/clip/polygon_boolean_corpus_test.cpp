// The peers' overlay cases of ../shared/corpus/poly2d (GEOS, Boost.Geometry, Clipper2): every
// judged pair, all four operations, against the exact areas computed there (CGAL exact
// arrangement), with the corpus README's tolerance max(1e-9 |truth|, 1e-12 S), S the largest
// extent of A u B squared; and every result valid by OGC rules (exact check).

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>
#include <tuple>

#include <nlohmann/json.hpp>

#include "clip/boolean_checks.h"
#include "contain/clip/polygon_boolean.h"
#include "contain/io/wkt.h"
#include "support/shared_corpus.h"

namespace contain::clip {
namespace {

struct Tally {
  int pairs = 0;
  int skipped = 0;
};

// The checker's rule (../shared/tools/check_poly2d.py): OGC pairs with an invalid input and
// Boost's open-ring cases are not judged.
bool judged(const nlohmann::json& r) {
  if (!r.contains("truth_area_intersection")) return false;
  if (r.contains("flags")) {
    for (const auto& f : r["flags"]) {
      if (f == "open_rings") return false;
    }
  }
  if (!r.contains("fill") || r["fill"].is_null()) {
    if (r.value("valid_a", true) == false || r.value("valid_b", true) == false) return false;
  }
  return true;
}

Fill fill_of(const nlohmann::json& r) {
  if (!r.contains("fill") || r["fill"].is_null()) return Fill::even_odd;
  const std::string f = r["fill"];
  if (f == "nonzero") return Fill::nonzero;
  if (f == "positive") return Fill::positive;
  if (f == "negative") return Fill::negative;
  return Fill::even_odd;
}

// Runs the judged pairs of one file; with `shards` > 1 only the lines i with i % shards ==
// `shard`, so that a long file runs as several tests in parallel.
Tally run_file(const std::string& name, int shard = 0, int shards = 1) {
  Tally tally;
  const auto path = *test::shared_dir() / "corpus" / "poly2d" / name;
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::set<std::tuple<std::string, std::string, std::string>> seen;
  std::string line;
  for (int index = 0; std::getline(in, line); ++index) {
    if (index % shards != shard) continue;
    const nlohmann::json r = nlohmann::json::parse(line);
    const std::string fill_name = r.contains("fill") && !r["fill"].is_null() ? r["fill"] : "";
    if (!seen.insert({r["wkt_a"], r["wkt_b"], fill_name}).second) continue;
    if (!judged(r)) {
      ++tally.skipped;
      continue;
    }
    const std::string id = r["id"];
    auto a = io::parse_wkt(r["wkt_a"].get<std::string>(), id);
    auto b = io::parse_wkt(r["wkt_b"].get<std::string>(), id);
    EXPECT_TRUE(a.ok() && b.ok()) << id;
    if (!a.ok() || !b.ok()) continue;
    ++tally.pairs;
    const double scale = r.value("area_scale", 1.0);
    const std::pair<Op, const char*> ops[] = {{Op::intersection, "truth_area_intersection"},
                                              {Op::union_, "truth_area_union"},
                                              {Op::difference, "truth_area_difference"},
                                              {Op::xor_, "truth_area_symdifference"}};
    for (const auto& [op, key] : ops) {
      const MultiPolygon result = polygon_boolean(*a, *b, {.op = op, .fill = fill_of(r)});
      const double truth = r[key];
      const double area = test::exact_signed_area(result).get_d();
      EXPECT_LE(std::abs(area - truth), std::max(1e-9 * std::abs(truth), 1e-12 * scale))
          << id << " " << key << ": area " << area << " truth " << truth;
      EXPECT_TRUE(test::is_valid_ogc(result)) << id << " " << key;
    }
  }
  return tally;
}

TEST(PolygonBooleanCorpus, GeosOverlayCasesMatchExactAreasAndAreValid) {
  CONTAIN_REQUIRE_SHARED();
  const Tally t = run_file("geos-overlay.jsonl");
  EXPECT_GE(t.pairs, 400);
}

TEST(PolygonBooleanCorpus, BoostOverlayCasesMatchExactAreasAndAreValid) {
  CONTAIN_REQUIRE_SHARED();
  const Tally t = run_file("boost-overlay-cases.jsonl");
  EXPECT_GE(t.pairs, 450);
}

// Clipper2's file is the longest (several minutes under the sanitizers): three tests, one per
// third of its lines, run side by side.
class Clipper2Cases : public ::testing::TestWithParam<int> {};
constexpr int clipper2_shards = 3;

TEST_P(Clipper2Cases, UnderTheirFillRulesMatchExactAreasAndAreValid) {
  CONTAIN_REQUIRE_SHARED();
  const Tally t = run_file("clipper2-polygons.jsonl", GetParam(), clipper2_shards);
  EXPECT_GE(t.pairs, 190 / clipper2_shards);
}
INSTANTIATE_TEST_SUITE_P(PolygonBooleanCorpus, Clipper2Cases, ::testing::Range(0, clipper2_shards));

}  // namespace
}  // namespace contain::clip
