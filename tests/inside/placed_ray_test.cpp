#include "contain/inside/placed_ray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "contain/bvh/placed_box.h"
#include "contain/inside/mesh_index.h"
#include "contain/inside/placed_mesh.h"
#include "scenes/scenes.h"
#include "support/exact.h"

namespace contain::inside {
namespace {

// locate_by_ray against `side` placed by `tf`, the way the pair queries call it.
Location locate_placed(const PlacedMesh& side, const Transform& tf, Vec3 q) {
  return locate_by_ray(
      side.bvh, q, side.rule, transform_orientation(tf),
      [&](const Box3& local) { return bvh::placed_box(local, tf); },
      [&](std::int32_t t) {
        const TriangleIndices& tri = side.mesh.triangles[static_cast<std::size_t>(t)];
        return Triangle3{tf.apply(side.mesh.vertices[static_cast<std::size_t>(tri[0])]),
                         tf.apply(side.mesh.vertices[static_cast<std::size_t>(tri[1])]),
                         tf.apply(side.mesh.vertices[static_cast<std::size_t>(tri[2])])};
      });
}

// A quarter turn about z and a dyadic shift: the placed cube's coordinates are exact, so points
// exactly on its faces, edges and corners can be written down.
Transform quarter_turn() {
  Transform tf;
  tf.r = {{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}};
  tf.t = {0.5, 0.25, 2};
  return tf;
}

TEST(LocateByRay, PointsOnAFaceAnEdgeADiagonalAndACornerOfThePlacedCubeAreBoundary) {
  // The cube [0, 2]^3 placed: x in [-1.5, 0.5], y in [0.25, 2.25], z in [2, 4].
  const PlacedMesh cube(scenes::box_mesh({{0, 0, 0}, {2, 2, 2}}));
  const Transform tf = quarter_turn();
  for (const Vec3 q :
       {Vec3{0.5, 1.0, 3.0}, Vec3{0.5, 1.25, 3.0}, Vec3{-0.5, 1.25, 4.0}, Vec3{0.5, 0.25, 3.0},
        Vec3{0.5, 0.25, 2.0}, Vec3{-1.5, 2.25, 4.0}, Vec3{-1.0, 0.25, 2.5}})
    EXPECT_EQ(locate_placed(cube, tf, q), Location::boundary) << q.x << " " << q.y << " " << q.z;
  EXPECT_EQ(locate_placed(cube, tf, {-0.5, 1.25, 3.0}), Location::inside);
  EXPECT_EQ(locate_placed(cube, tf, {0.25, 0.5, 2.0 + 0x1p-50}), Location::inside);
  EXPECT_EQ(locate_placed(cube, tf, {0.5 + 0x1p-52, 1.25, 3.0}), Location::outside);
  EXPECT_EQ(locate_placed(cube, tf, {0.5, 2.5, 3.0}), Location::outside);  // in the face's plane
  EXPECT_EQ(locate_placed(cube, tf, {-3.0, 1.25, 3.0}), Location::outside);
}

TEST(LocateByRay, EqualsTheExactMeshIndexOfThePlacedTorusAtItsVerticesAndRandomPoints) {
  const PlacedMesh torus(scenes::torus(1.0, 0.4, 16, 9));
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int pose = 0; pose < 6; ++pose) {
    double q[4] = {u(rng), u(rng), u(rng), u(rng)};
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    Transform tf;
    tf.r = {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
             {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
             {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
    tf.t = {u(rng) * 100, u(rng), u(rng)};
    const Mesh world = placed(torus.mesh, tf);
    const MeshIndex index(world);
    std::vector<Vec3> points = world.vertices;  // every one on the surface
    for (int k = 0; k < 400; ++k)
      points.push_back(tf.apply({u(rng) * 1.5, u(rng) * 1.5, u(rng) * 0.5}));
    int boundary = 0;
    for (const Vec3 p : points) {
      const Location want = index.locate(p);
      ASSERT_EQ(locate_placed(torus, tf, p), want) << "pose " << pose;
      boundary += want == Location::boundary;
    }
    EXPECT_GE(boundary, static_cast<int>(world.vertices.size()));
  }
}

TEST(OnTriangle, DegenerateTrianglesHoldExactlyThePointsOfTheirSegmentByTheOracle) {
  const Triangle3 segment{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}};  // collinear: the segment [0, 3]^3
  const Triangle3 point{{1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
  EXPECT_TRUE(on_triangle({2, 2, 2}, segment));
  EXPECT_TRUE(on_triangle({3, 3, 3}, segment));
  EXPECT_FALSE(on_triangle({3.5, 3.5, 3.5}, segment));
  EXPECT_FALSE(on_triangle({1, 1, 1 + 0x1p-52}, segment));
  EXPECT_TRUE(on_triangle({1, 2, 3}, point));
  EXPECT_FALSE(on_triangle({1, 2, 3 + 0x1p-51}, point));
  // Random points on a proper triangle's plane (as computed) against the GMP oracle.
  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Triangle3 t{{0.1, 0.2, 0.3}, {1.7, -0.4, 0.9}, {-0.6, 1.3, -0.2}};
  for (int k = 0; k < 2000; ++k) {
    const double s = std::fabs(u(rng)), r = std::fabs(u(rng)) * (1 - s);
    const Vec3 p = t.a + s * (t.b - t.a) + r * (t.c - t.a);
    const bool on_plane = test::exact_orient3d(t.a, t.b, t.c, p) == Sign::zero;
    if (!on_plane) {
      EXPECT_FALSE(on_triangle(p, t));
    } else {
      EXPECT_EQ(on_triangle(p, t),
                predicates::closest_feature(t, p) == predicates::TriangleFeature::face);
    }
  }
}

}  // namespace
}  // namespace contain::inside
