// The shared corpus of 3D inside cases (../shared/corpus/mesh-cases/inside, exact truth from
// CGAL's exact kernel) and the open meshes of ../shared/corpus/meshes.

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "contain/inside/mesh_index.h"
#include "contain/io/mesh_io.h"
#include "support/shared_corpus.h"

namespace contain::inside {
namespace {

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(PointInMeshCorpus, EveryInsideCaseMatchesTheExactTruth) {
  CONTAIN_REQUIRE_SHARED();
  const std::filesystem::path shared = *test::shared_dir();
  const std::filesystem::path root = shared.parent_path();  // paths start with shared/...
  const std::string cases = slurp(shared / "corpus" / "mesh-cases" / "inside" / "cases.json");
  const std::regex entry(
      R"re("name":\s*"([^"]+)",\s*"mesh":\s*"([^"]+)",\s*"points":\s*"([^"]+)",\s*"truth":\s*"([^"]+)")re");
  int case_count = 0;
  for (auto it = std::sregex_iterator(cases.begin(), cases.end(), entry);
       it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    SCOPED_TRACE(m[1].str());
    auto file = io::read_mesh(root / m[2].str());
    ASSERT_TRUE(file.ok()) << file.error().what();
    const MeshIndex index(file->mesh);
    EXPECT_EQ(index.regime(), MeshRegime::closed_exact);
    std::istringstream points(slurp(root / m[3].str())), truth(slurp(root / m[4].str()));
    std::vector<Vec3> ps;
    for (Vec3 p; points >> p.x >> p.y >> p.z;)
      ps.push_back(p);
    std::vector<Location> got(ps.size());
    index.locate(ps, got, {.threads = 2});
    std::size_t i = 0;
    for (std::string expected; truth >> expected; ++i) {
      ASSERT_LT(i, ps.size());
      EXPECT_EQ(to_string(got[i]), expected) << "point " << i + 1;
    }
    EXPECT_EQ(i, ps.size());
    ++case_count;
  }
  EXPECT_GE(case_count, 12);
}

TEST(PointInMeshCorpus, OpenCorpusMeshesUseTheWindingNumberAndCountTheirBorderEdges) {
  CONTAIN_REQUIRE_SHARED();
  const std::filesystem::path meshes = *test::shared_dir() / "corpus" / "meshes";
  for (const auto& [name, borders] :
       {std::pair{"stanford-bunny.obj", 223u}, std::pair{"lion.off", 36u}}) {
    SCOPED_TRACE(name);
    auto file = io::read_mesh(meshes / name);
    ASSERT_TRUE(file.ok()) << file.error().what();
    const MeshIndex index(file->mesh);
    EXPECT_EQ(index.regime(), MeshRegime::winding_number);
    EXPECT_EQ(index.report().border_edges, borders);
    // Vertices are on the surface; the box's corners are far outside; a good share of the points
    // in the box is inside (never `out` everywhere).
    const Mesh& mesh = file->mesh;
    EXPECT_EQ(index.locate(mesh.vertices[static_cast<std::size_t>(mesh.triangles[0][0])]),
              Location::boundary);
    EXPECT_EQ(index.locate(index.bounds().max + Vec3{1, 1, 1}), Location::outside);
  }
}

TEST(PointInMeshCorpus, CowWithAPinchVertexStaysExactAndReportsTheVertex) {
  CONTAIN_REQUIRE_SHARED();
  auto file = io::read_mesh(*test::shared_dir() / "corpus" / "meshes" / "cow.obj");
  ASSERT_TRUE(file.ok()) << file.error().what();
  const MeshIndex index(file->mesh);
  EXPECT_EQ(index.regime(), MeshRegime::closed_exact);
  EXPECT_EQ(index.report().pinch_vertices, std::vector<std::int32_t>{253});
  EXPECT_EQ(index.locate(file->mesh.vertices[253]), Location::boundary);
}

}  // namespace
}  // namespace contain::inside
