#include "contain/collide/self_intersections.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "contain/collide/tri_tri.h"
#include "scenes/scenes.h"

namespace contain::collide {
namespace {

// Two triangles as one mesh, each with its own three vertices (so "shared" is by coordinates).
Mesh two_triangles(const Triangle3& a, const Triangle3& b) {
  return {{a.a, a.b, a.c, b.a, b.b, b.c}, {{0, 1, 2}, {3, 4, 5}}};
}

// Two meshes as one (b's indices shifted past a's vertices).
Mesh joined(const Mesh& a, const Mesh& b) {
  Mesh out = a;
  const auto shift = static_cast<std::int32_t>(a.vertices.size());
  out.vertices.insert(out.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const TriangleIndices& t : b.triangles) {
    out.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
  }
  return out;
}

std::size_t count_of(const Mesh& mesh) {
  return self_intersections(mesh).count;
}

constexpr Vec3 p{0, 0, 0};
constexpr Vec3 q{1, 0, 0};
constexpr Vec3 r{0, 1, 0};

TEST(SelfIntersections, ClosedCubeAndTorusHaveNone) {
  EXPECT_TRUE(self_intersections(scenes::box_mesh({{0, 0, 0}, {1, 1, 1}})).empty());
  const SelfIntersections torus = self_intersections(scenes::torus(2.0, 0.5, 64, 32));
  EXPECT_EQ(torus.count, 0u);
  EXPECT_TRUE(torus.pairs.empty());
  EXPECT_FALSE(torus.stopped);
}

TEST(SelfIntersections, TwoOverlappingCubesInOneMeshCross) {
  const Mesh mesh =
      joined(scenes::box_mesh({{0, 0, 0}, {2, 2, 2}}), scenes::box_mesh({{1, 1, 1}, {3, 3, 3}}));
  const SelfIntersections found = self_intersections(mesh);
  EXPECT_GT(found.count, 0u);
  ASSERT_FALSE(found.pairs.empty());
  for (const TrianglePair& pair : found.pairs) {
    // Every pair joins a face of the first cube (triangles 0..11) with one of the second.
    EXPECT_LT(pair.first, 12);
    EXPECT_GE(pair.second, 12);
    EXPECT_TRUE(tri_tri(mesh.triangle(static_cast<std::size_t>(pair.first)),
                        mesh.triangle(static_cast<std::size_t>(pair.second))));
  }
}

TEST(SelfIntersections, TwoSeparateCubesInOneMeshDoNot) {
  EXPECT_EQ(count_of(joined(scenes::box_mesh({{0, 0, 0}, {1, 1, 1}}),
                            scenes::box_mesh({{2, 0, 0}, {3, 1, 1}}))),
            0u);
}

TEST(SelfIntersections, KeepAndLimitBoundTheAnswer) {
  const Mesh mesh =
      joined(scenes::box_mesh({{0, 0, 0}, {2, 2, 2}}), scenes::box_mesh({{1, 1, 1}, {3, 3, 3}}));
  const SelfIntersections all = self_intersections(mesh, {.keep = 2});
  ASSERT_GT(all.count, 2u);
  EXPECT_EQ(all.pairs.size(), 2u);
  EXPECT_FALSE(all.stopped);
  const SelfIntersections first = self_intersections(mesh, {.keep = 8, .limit = 1});
  EXPECT_EQ(first.count, 1u);
  EXPECT_TRUE(first.stopped);
  ASSERT_EQ(first.pairs.size(), 1u);
  EXPECT_EQ(first.pairs.front(), all.pairs.front());
}

TEST(SelfIntersections, CubeWithAVertexPushedThroughTheOppositeFaceCrosses) {
  Mesh mesh = scenes::box_mesh({{0, 0, 0}, {1, 1, 1}});
  bool moved = false;
  for (Vec3& v : mesh.vertices) {
    if (v == Vec3{1, 1, 1}) {
      v = {0.75, 0.75, -0.5};  // through the face z = 0
      moved = true;
    }
  }
  ASSERT_TRUE(moved);
  EXPECT_GT(count_of(mesh), 0u);
}

TEST(SelfIntersections, SharedEdgeAloneIsNotACrossing) {
  // Across the edge in one plane, and at an angle: they meet only along P Q.
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {q, p, {0.5, -1, 0}})), 0u);
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {q, p, {0.5, 1, 1}})), 0u);
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {q, p, {0.5, -1, -1e-300}})), 0u);
}

TEST(SelfIntersections, CoplanarFoldOverASharedEdgeCrosses) {
  // Both on the same side of P Q in one plane: they overlap beyond the edge, whether the far
  // corner lies inside the neighbour, outside it, or their far edges cross.
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {q, p, {1, 1, 0}})), 1u);
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {q, p, {0.25, 0.25, 0}})), 1u);
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {q, p, {0.5, 5, 0}})), 1u);
  // A hair off the plane, the fold is a sharp crease that meets only along the edge.
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {q, p, {1, 1, 0x1p-60}})), 0u);
}

TEST(SelfIntersections, SharedVertexAloneIsNotACrossing) {
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {p, {-1, 0, 0}, {0, -1, 0}})), 0u);
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {p, {-1, -1, 1}, {-1, -1, -1}})), 0u);
  // Touching the corner's two edges from outside the angle, in the plane.
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {p, {-1, 0, 0}, {0, -1, 1}})), 0u);
}

TEST(SelfIntersections, TriangleThroughItsNeighboursInteriorAtASharedVertexCrosses) {
  // The far edge of b pierces a's interior.
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {p, {0.25, 0.25, -1}, {0.25, 0.25, 1}})), 1u);
  // b stands on a along the diagonal: a's far edge meets b.
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {p, {1, 1, 0}, {1, 1, 1}})), 1u);
  // Coplanar, b inside a's angle at P.
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {p, {0.1, 0.2, 0}, {0.2, 0.1, 0}})), 1u);
  // b runs along a's edge P Q beyond P, out of the plane otherwise.
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {p, {0.5, 0, 0}, {0, -1, 1}})), 1u);
}

TEST(SelfIntersections, TouchingWithoutASharedCornerCounts) {
  // Non-adjacent triangles meeting at one point (a corner on the other's face) count: tri_tri.
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {{0.25, 0.25, 0}, {0, 0, 1}, {1, 0, 1}})), 1u);
}

TEST(SelfIntersections, DuplicatedAndDegenerateTrianglesAreLeftToValidation) {
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {p, r, q})), 0u);
  // A sliver with the shared vertex in the middle of its long side.
  EXPECT_EQ(count_of(two_triangles({p, q, r}, {{-1, 0, 0}, p, {1, 0, 0}})), 0u);
}

TEST(SelfIntersections, EmptyMeshHasNone) {
  EXPECT_TRUE(self_intersections(Mesh{}).empty());
}

TEST(SelfIntersections, HierarchyFindsEveryPairOfASoup) {
  // Triangles with no shared corners: every intersecting pair, brute force against the
  // hierarchy's traversal.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 10.0), d(-1.0, 1.0);
  Mesh soup;
  for (std::int32_t t = 0; t < 300; ++t) {
    const Vec3 c{u(rng), u(rng), u(rng)};
    for (int k = 0; k < 3; ++k)
      soup.vertices.push_back(c + Vec3{d(rng), d(rng), d(rng)});
    soup.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  std::size_t brute = 0;
  for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
    for (std::size_t j = i + 1; j < soup.triangles.size(); ++j) {
      brute += tri_tri(soup.triangle(i), soup.triangle(j)) ? 1 : 0;
    }
  }
  ASSERT_GT(brute, 0u);
  EXPECT_EQ(self_intersections(soup).count, brute);
}

}  // namespace
}  // namespace contain::collide
