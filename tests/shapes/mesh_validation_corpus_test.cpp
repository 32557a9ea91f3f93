// Validation of the meshes of ../shared/corpus/meshes against their README.

#include <gtest/gtest.h>

#include "contain/io/mesh_io.h"
#include "contain/shapes/mesh_validation.h"
#include "support/shared_corpus.h"

namespace contain {
namespace {

struct CorpusMesh {
  const char* file;
  bool closed;
  int genus;  // -1: not a closed manifold
  std::size_t border_edges;
};

TEST(MeshValidation, CorpusMeshesMatchTheirReadme) {
  CONTAIN_REQUIRE_SHARED();
  const CorpusMesh cases[] = {
      {"spot.obj", true, 0, 0},       {"fandisk.obj", true, 0, 0},
      {"rocker-arm.obj", true, 1, 0}, {"fertility.off", true, 4, 0},
      {"armadillo.obj", true, 0, 0},  {"stanford-bunny.obj", false, -1, 223},
      {"lion.off", false, -1, 36},
  };
  for (const CorpusMesh& c : cases) {
    SCOPED_TRACE(c.file);
    auto file = io::read_mesh(*test::shared_dir() / "corpus" / "meshes" / c.file);
    ASSERT_TRUE(file.ok()) << file.error().what();
    const MeshReport r = validate_mesh(file->mesh);
    EXPECT_EQ(r.closed(), c.closed);
    EXPECT_EQ(r.border_edges, c.border_edges);
    if (c.closed) {
      EXPECT_TRUE(r.watertight());
      EXPECT_TRUE(r.outward());
      EXPECT_EQ(r.components, 1u);
      EXPECT_EQ(r.degenerate_triangles, 0u);
      EXPECT_EQ(r.genus, c.genus);
    }
  }
}

TEST(MeshValidation, CowHasThePinchVertexItsReadmeNames) {
  CONTAIN_REQUIRE_SHARED();
  auto file = io::read_mesh(*test::shared_dir() / "corpus" / "meshes" / "cow.obj");
  ASSERT_TRUE(file.ok()) << file.error().what();
  const MeshReport r = validate_mesh(file->mesh);
  EXPECT_EQ(r.border_edges, 0u);
  EXPECT_EQ(r.nonmanifold_edges, 0u);
  EXPECT_TRUE(r.consistently_oriented());
  EXPECT_TRUE(r.closed()) << "every edge has two faces";
  EXPECT_FALSE(r.manifold());
  ASSERT_EQ(r.pinch_vertices.size(), 1u);
  EXPECT_EQ(r.pinch_vertices[0], 253);  // 254 1-based
  EXPECT_EQ(file->mesh.vertices[253], (Vec3{-3.507689, 1.700214, 0}));
  EXPECT_EQ(r.euler_characteristic, 1);
  EXPECT_FALSE(r.genus.has_value());
}

}  // namespace
}  // namespace contain
