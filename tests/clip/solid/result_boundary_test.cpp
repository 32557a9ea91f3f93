// within_boundary proves a written vertex near the exact result's boundary, and refuses one
// that is not: points just inside and just outside the bound from a face, an edge and a
// corner of a triangle whose corners are implicit points (crossings of segments and a plane)
// or doubles; a mesh with vertices and no faces; the empty mesh.

#include "clip/solid/result_boundary.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "clip/solid/engine.h"
#include "clip/solid/exact_point.h"

namespace contain::test {
namespace {

using clip::solid::PointStore;
using clip::solid::within_boundary;
using Faces = std::vector<std::array<std::int32_t, 3>>;

Mesh points(std::vector<Vec3> vertices) {
  Mesh m;
  m.vertices = std::move(vertices);
  return m;
}

// One face in the plane z = 0: (0, 0), (1, 0), (0, 1), scale 1, bound 1e-9.
struct OneFace {
  PointStore store;
  Faces faces;
  OneFace() {
    const std::int32_t a = store.add(Vec3{0, 0, 0});
    const std::int32_t b = store.add(Vec3{1, 0, 0});
    const std::int32_t c = store.add(Vec3{0, 1, 0});
    faces.push_back({a, b, c});
  }
};

TEST(SolidResultBoundary, VerticesWithinTheBoundOfAFaceAnEdgeOrACornerAreProven) {
  const OneFace f;
  for (const Vec3 p :
       {Vec3{0.25, 0.25, 0.9e-9}, Vec3{0.25, 0.25, -0.9e-9}, Vec3{0.5, -0.6e-9, 0.6e-9},
        Vec3{-0.5e-9, -0.5e-9, 0.5e-9}, Vec3{0.5, 0.5, 0.0}}) {
    EXPECT_TRUE(within_boundary(points({p}), f.faces, f.store, 1e-9, 1.0))
        << p.x << " " << p.y << " " << p.z;
  }
}

TEST(SolidResultBoundary, VerticesBeyondTheBoundAreRefused) {
  const OneFace f;
  for (const Vec3 p : {Vec3{0.25, 0.25, 1.1e-9}, Vec3{0.5, -0.8e-9, 0.8e-9},
                       Vec3{-0.6e-9, -0.6e-9, 0.6e-9}, Vec3{0.6, 0.6, 0.0}}) {
    EXPECT_FALSE(within_boundary(points({{0.1, 0.1, 0.0}, p}), f.faces, f.store, 1e-9, 1.0))
        << p.x << " " << p.y << " " << p.z;
  }
}

TEST(SolidResultBoundary, ImplicitCornersAreRoundedWithinTheShrunkBound) {
  // A face whose corner is the crossing of a segment with a plane (an implicit point, not a
  // double): a vertex at that corner's nearest doubles is proven, one 2e-9 away is not.
  PointStore store;
  const std::int32_t a = store.add(Vec3{0, 0, 0});
  const std::int32_t b = store.add(Vec3{1, 0, 0});
  const clip::solid::ExactPoint crossing = clip::solid::line_plane(
      Vec3{0, 0, -1}, Vec3{1.0 / 3.0, 1, 2}, Vec3{-5, -5, 0}, Vec3{5, -5, 0}, Vec3{0, 5, 0});
  const std::int32_t c = store.add(crossing);
  const Faces faces = {{a, b, c}};
  const Vec3 corner = store.rounded(c);
  EXPECT_TRUE(within_boundary(points({corner}), faces, store, 1e-9, 1.0));
  EXPECT_FALSE(
      within_boundary(points({{corner.x, corner.y, corner.z + 2e-9}}), faces, store, 1e-9, 1.0));
}

TEST(SolidResultBoundary, NoFacesProveNoVertexAndTheEmptyMeshPasses) {
  const OneFace f;
  EXPECT_FALSE(within_boundary(points({{0, 0, 0}}), {}, f.store, 1e-9, 1.0));
  EXPECT_TRUE(within_boundary(Mesh{}, {}, f.store, 1e-9, 1.0));
  EXPECT_TRUE(within_boundary(Mesh{}, f.faces, f.store, 1e-9, 1.0));
}

}  // namespace
}  // namespace contain::test
