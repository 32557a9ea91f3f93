// Meshes by half-spaces: clipped faces stay in the region, caps make closed oriented solids.

#include <gtest/gtest.h>

#include <cmath>

#include "contain/clip/box_halfspaces.h"
#include "contain/clip/mesh_clip.h"
#include "contain/shapes/mesh_validation.h"
#include "scenes/scenes.h"
#include "support/exact.h"

namespace contain::test {
namespace {

// The unit cube [0, 1]^3 as a closed, outward mesh.
Mesh cube() {
  return scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}});
}

void expect_solid(const Mesh& m, double volume, double tolerance) {
  const MeshReport r = validate_mesh(m);
  EXPECT_TRUE(r.closed()) << r.summary();
  EXPECT_TRUE(r.consistently_oriented()) << r.summary();
  EXPECT_TRUE(r.manifold()) << r.summary();
  EXPECT_NEAR(r.signed_volume, volume, tolerance) << r.summary();
}

TEST(MeshClip, CappedCubeCornerIsAClosedOutwardSolid) {
  const std::vector<Plane> cut = {{1, 1, 1, -1.5}};
  const Mesh m = clip::mesh_clip(cube(), cut, {.cut = clip::MeshCut::cap});
  expect_solid(m, 0.5, 1e-12);  // the plane through the centre halves the cube
  const Mesh open = clip::mesh_clip(cube(), cut);
  EXPECT_FALSE(validate_mesh(open).closed());
  for (const Vec3& v : open.vertices)
    EXPECT_NE(exact_side_of_plane(cut[0], v), Sign::negative);
}

TEST(MeshClip, BoxClipOfCubeIsTheSmallCubeWithExactFaceCoordinates) {
  const Mesh m =
      clip::mesh_clip(cube(), Box3{{0.25, 0.25, 0.25}, {2, 2, 2}}, {.cut = clip::MeshCut::cap});
  expect_solid(m, 0.75 * 0.75 * 0.75, 1e-12);
  for (const Vec3& v : m.vertices) {
    EXPECT_TRUE(Box3({{0.25, 0.25, 0.25}, {1, 1, 1}}).contains(v));
  }
}

TEST(MeshClip, FaceOnThePlaneStaysWhenItBoundsTheKeptSide) {
  const std::vector<Plane> x_le_1 = {{-1, 0, 0, 1}};
  EXPECT_EQ(clip::mesh_clip(cube(), x_le_1).triangles.size(), 12u);
  const std::vector<Plane> x_ge_1 = {{1, 0, 0, -1}};
  EXPECT_TRUE(clip::mesh_clip(cube(), x_ge_1, {.cut = clip::MeshCut::cap}).triangles.empty());
}

TEST(MeshClip, TorusCutThroughItsHoleGetsAnnularCapsAndStaysClosed) {
  const Mesh torus = scenes::torus(2.0, 0.5, 48, 24);
  const double full = validate_mesh(torus).signed_volume;
  // z >= 0.1 cuts the tube along an annulus (a cap with a hole).
  const std::vector<Plane> up = {{0, 0, 1, -0.1}};
  const Mesh top = clip::mesh_clip(torus, up, {.cut = clip::MeshCut::cap});
  const MeshReport r = validate_mesh(top);
  EXPECT_TRUE(r.closed() && r.consistently_oriented()) << r.summary();
  EXPECT_GT(r.signed_volume, 0.0);
  EXPECT_LT(r.signed_volume, 0.5 * full);
  // x >= 0.3 cuts the ring twice: two disc-shaped caps.
  const std::vector<Plane> side = {{1, 0, 0, -0.3}};
  const Mesh half = clip::mesh_clip(torus, side, {.cut = clip::MeshCut::cap});
  const MeshReport h = validate_mesh(half);
  EXPECT_TRUE(h.closed() && h.consistently_oriented() && h.manifold()) << h.summary();
  EXPECT_GT(h.signed_volume, 0.0);
}

TEST(MeshClip, ConvexMeshRegionGivesTheSameSolidAsItsPlanes) {
  const auto solid = ConvexPolyhedron::from_mesh(cube());
  ASSERT_TRUE(solid.ok());
  const Mesh torus = scenes::torus(0.4, 0.15, 24, 12);
  Mesh moved = torus;
  for (Vec3& v : moved.vertices)
    v = v + Vec3{0.2, 0.5, 0.5};
  const Mesh a = clip::mesh_clip(moved, *solid, {.cut = clip::MeshCut::cap});
  const Mesh b = clip::mesh_clip(moved, Box3{{0, 0, 0}, {1, 1, 1}}, {.cut = clip::MeshCut::cap});
  const MeshReport ra = validate_mesh(a), rb = validate_mesh(b);
  EXPECT_TRUE(ra.closed() && ra.consistently_oriented()) << ra.summary();
  EXPECT_TRUE(rb.closed() && rb.consistently_oriented()) << rb.summary();
  EXPECT_NEAR(ra.signed_volume, rb.signed_volume, 1e-9);
}

}  // namespace
}  // namespace contain::test
