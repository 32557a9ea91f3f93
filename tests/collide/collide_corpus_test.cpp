// The shared corpus (exact truth from CGAL's exact kernel): triangle pairs and mesh poses.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "contain/collide/mesh_mesh.h"
#include "contain/collide/tri_tri.h"
#include "contain/collide/tri_tri_2d.h"
#include "contain/io/mesh_io.h"
#include "contain/io/number_table.h"
#include "support/shared_corpus.h"

namespace contain::collide {
namespace {

std::vector<nlohmann::json> read_jsonl(const std::filesystem::path& path) {
  std::vector<nlohmann::json> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) rows.push_back(nlohmann::json::parse(line));
  }
  return rows;
}

Vec3 v3(const nlohmann::json& p) {
  return {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()};
}
Vec2 v2(const nlohmann::json& p) {
  return {p[0].get<double>(), p[1].get<double>()};
}

TEST(CollideCorpus, TriangleTriangle3dMatchesExactTruth) {
  CONTAIN_REQUIRE_SHARED();
  const auto rows = read_jsonl(*test::shared_dir() / "corpus/mesh-cases/tritri/tritri3.jsonl");
  ASSERT_GT(rows.size(), 100u);
  for (const auto& r : rows) {
    const Triangle3 a{v3(r["a"][0]), v3(r["a"][1]), v3(r["a"][2])};
    const Triangle3 b{v3(r["b"][0]), v3(r["b"][1]), v3(r["b"][2])};
    EXPECT_EQ(tri_tri(a, b), r["truth"] == "intersect") << "id " << r["id"] << " " << r["kind"];
  }
}

TEST(CollideCorpus, TriangleTriangle2dMatchesExactTruth) {
  CONTAIN_REQUIRE_SHARED();
  const auto rows = read_jsonl(*test::shared_dir() / "corpus/mesh-cases/tritri/tritri2.jsonl");
  ASSERT_GT(rows.size(), 100u);
  for (const auto& r : rows) {
    const Triangle2 a{v2(r["a"][0]), v2(r["a"][1]), v2(r["a"][2])};
    const Triangle2 b{v2(r["b"][0]), v2(r["b"][1]), v2(r["b"][2])};
    EXPECT_EQ(tri_tri(a, b), r["truth"] == "intersect") << "id " << r["id"] << " " << r["kind"];
  }
}

Transform transform_of(const double* v) {
  return Transform::from_row_major(std::span<const double>(v, 12)).value();
}

TEST(CollideCorpus, MeshPosesMatchExactTruth) {
  CONTAIN_REQUIRE_SHARED();
  const std::filesystem::path root = test::shared_dir()->parent_path();
  const auto groups = read_jsonl(*test::shared_dir() / "corpus/mesh-cases/collide/cases.jsonl");
  ASSERT_GT(groups.size(), 10u);
  int judged = 0;
  for (const auto& g : groups) {
    // The constructed meshes only: the groups on the large scanned models (armadillo, ...) run
    // through the command in SharedCorpus.CollisionMatchesExactTruth, which keeps this test fast
    // in the sanitizer build.
    if (g["a"].get<std::string>().find("mesh-cases/meshes/") == std::string::npos ||
        g["b"].get<std::string>().find("mesh-cases/meshes/") == std::string::npos) {
      continue;
    }
    const auto a = io::read_mesh(root / g["a"].get<std::string>());
    const auto b = io::read_mesh(root / g["b"].get<std::string>());
    ASSERT_TRUE(a.ok() && b.ok()) << g["name"];
    const auto poses =
        io::read_number_table(root / g["poses"].get<std::string>(), {.columns = {12}});
    ASSERT_TRUE(poses.ok()) << g["name"];
    Transform ta;
    if (!g["transform_a"].is_null()) {
      std::vector<double> v = g["transform_a"].get<std::vector<double>>();
      ta = transform_of(v.data());
    }
    const MeshPair pair(a->mesh, b->mesh, {.transform_a = ta});
    ASSERT_EQ(poses->rows(), g["truth"].size()) << g["name"];
    for (std::size_t i = 0; i < poses->rows(); ++i) {
      const Contact c = pair.collide(transform_of(&poses->values[i * 12]));
      EXPECT_EQ(c.intersect, g["truth"][i] == "intersect")
          << g["name"] << " pose " << i + 1 << " (" << g["kinds"][i] << ")";
      ++judged;
    }
  }
  EXPECT_GT(judged, 60);
}

}  // namespace
}  // namespace contain::collide
