// The shared corpus (../shared/corpus/mesh-cases, exact truth from CGAL's exact kernel) through
// the distance queries: signs against the inside truth, and distance 0 exactly where the collide
// truth says two solids meet. Skipped with a message where ../shared is absent.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "contain/distance/mesh_distance.h"
#include "contain/distance/mesh_pair_distance.h"
#include "contain/io/mesh_io.h"
#include "contain/io/number_table.h"
#include "support/case_budget.h"
#include "support/shared_corpus.h"

namespace contain::distance {
namespace {

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The rounded distance d is the double nearest to the exact one, so the exact distance lies
// strictly between d's neighbours (a tie between two doubles is never a distance to a point of
// doubles but could be; `within` at the neighbours then still brackets it): exact `within` must
// say no just below d and yes just above.
bool brackets(const MeshDistance& mesh, Vec3 p, double d) {
  if (d == 0) return mesh.within(p, 0.0);
  return !mesh.within(p, std::nextafter(d, 0.0)) && mesh.within(p, std::nextafter(d, INFINITY));
}

TEST(DistanceCorpus, SignedDistanceSignsMatchTheExactInsideTruthAndWithinBracketsTheDistance) {
  CONTAIN_REQUIRE_SHARED();
  const std::filesystem::path shared = *test::shared_dir();
  const std::filesystem::path root = shared.parent_path();  // paths start with shared/...
  const auto cases = nlohmann::json::parse(slurp(shared / "corpus/mesh-cases/inside/cases.json"));
  ASSERT_GE(cases.size(), 12u);
  int judged = 0;
  for (const auto& c : cases) {
    const std::string name = c["name"].get<std::string>();
    SCOPED_TRACE(name);
    auto file = io::read_mesh(root / c["mesh"].get<std::string>());
    ASSERT_TRUE(file.ok()) << file.error().what();
    const MeshDistance mesh(file->mesh);
    std::istringstream points(slurp(root / c["points"].get<std::string>()));
    std::istringstream truth(slurp(root / c["truth"].get<std::string>()));
    std::vector<Vec3> ps;
    for (Vec3 p; points >> p.x >> p.y >> p.z;)
      ps.push_back(p);
    std::vector<Closest3> got(ps.size());
    mesh.distance(ps, got, {.signed_distance = true}, {.threads = 2});
    // Every point's sign; the within bracket on every point (every 10th under the sanitizers).
    std::size_t i = 0;
    for (std::string expected; truth >> expected; ++i) {
      ASSERT_LT(i, ps.size());
      const double d = got[i].distance;
      const char* sign = d < 0 ? "in" : d > 0 ? "out" : "on";
      EXPECT_EQ(sign, expected) << "point " << i + 1 << " distance " << d;
      EXPECT_FALSE(std::signbit(d) && d == 0) << "point " << i + 1 << ": -0.0";
      if (!test::reduced_cases || i % 10 == 0) {
        EXPECT_TRUE(brackets(mesh, ps[i], std::fabs(d))) << "point " << i + 1 << " " << d;
      }
      ++judged;
    }
    EXPECT_EQ(i, ps.size());
  }
  EXPECT_GT(judged, 10000);
}

std::vector<nlohmann::json> read_jsonl(const std::filesystem::path& path) {
  std::vector<nlohmann::json> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) rows.push_back(nlohmann::json::parse(line));
  }
  return rows;
}

Transform transform_of(const double* v) {
  return Transform::from_row_major(std::span<const double>(v, 12)).value();
}

TEST(DistanceCorpus, MeshPairsAreAtDistanceZeroExactlyWhereTheSolidsMeet) {
  CONTAIN_REQUIRE_SHARED();
  const std::filesystem::path root = test::shared_dir()->parent_path();
  const auto groups = read_jsonl(*test::shared_dir() / "corpus/mesh-cases/collide/cases.jsonl");
  ASSERT_GT(groups.size(), 10u);
  int judged = 0;
  for (const auto& g : groups) {
    const std::string a_path = g["a"].get<std::string>(), b_path = g["b"].get<std::string>();
    // Under the sanitizers the constructed meshes only (the scanned models cost seconds there).
    if (test::reduced_cases && (a_path.find("mesh-cases/meshes/") == std::string::npos ||
                                b_path.find("mesh-cases/meshes/") == std::string::npos)) {
      continue;
    }
    SCOPED_TRACE(g["name"].get<std::string>());
    const auto a = io::read_mesh(root / a_path);
    const auto b = io::read_mesh(root / b_path);
    ASSERT_TRUE(a.ok() && b.ok());
    const auto poses =
        io::read_number_table(root / g["poses"].get<std::string>(), {.columns = {12}});
    ASSERT_TRUE(poses.ok());
    Transform ta;
    if (!g["transform_a"].is_null()) {
      std::vector<double> v = g["transform_a"].get<std::vector<double>>();
      ta = transform_of(v.data());
    }
    const MeshPairDistance pair(a->mesh, b->mesh, {.transform_a = ta});
    ASSERT_EQ(poses->rows(), g["truth"].size());
    for (std::size_t i = 0; i < poses->rows(); ++i) {
      const Transform tb = transform_of(&poses->values[i * 12]);
      const PairDistance3 d = pair.distance(tb);
      const bool meet = g["truth"][i] == "intersect";
      const std::string where = "pose " + std::to_string(i + 1) + " (" +
                                g["kinds"][i].get<std::string>() + ") " + to_string(d.contact);
      EXPECT_EQ(d.distance == 0, meet) << where << " distance " << d.distance;
      EXPECT_EQ(d.contact != inside::PairWitness::none, meet) << where;
      EXPECT_EQ(pair.within(tb, 0.0), meet) << where;
      if (!meet) {
        EXPECT_GT(d.distance, 0.0) << where;
        EXPECT_TRUE(pair.within(tb, std::nextafter(d.distance, INFINITY))) << where;
        EXPECT_FALSE(pair.within(tb, std::nextafter(d.distance, 0.0))) << where;
      }
      ++judged;
    }
  }
  EXPECT_GT(judged, test::reduced_cases ? 60 : 100);
}

}  // namespace
}  // namespace contain::distance
