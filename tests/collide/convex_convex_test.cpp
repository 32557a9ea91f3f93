#include "contain/collide/convex_convex.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "contain/collide/polyhedra_reference.h"
#include "contain/predicates/orient3d.h"
#include "contain/shapes/mesh.h"

namespace contain::collide {
namespace {

// A tetrahedron on four integer points (small grid: touching and shared features are common),
// as a closed outward mesh; coplanar draws are redrawn.
Mesh tetrahedron(std::mt19937_64& rng, int lo, int hi, Vec3 offset) {
  std::uniform_int_distribution<int> u(lo, hi);
  for (;;) {
    Vec3 p[4];
    for (Vec3& x : p)
      x = Vec3{double(u(rng)), double(u(rng)), double(u(rng))} + offset;
    const Sign s = predicates::orient3d(p[0], p[1], p[2], p[3]);
    if (s == Sign::zero) continue;
    if (s == Sign::positive) std::swap(p[1], p[2]);  // p3 below the face 0 1 2 seen from outside
    auto mesh =
        Mesh::from_arrays({p[0], p[1], p[2], p[3]}, {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}});
    return *mesh;
  }
}

ConvexShape shape_of(const Mesh& mesh) {
  auto solid = ConvexPolyhedron::from_mesh(mesh);
  EXPECT_TRUE(solid.ok());
  auto shape = ConvexShape::polyhedron(*solid);
  EXPECT_TRUE(shape.ok());
  return *shape;
}

Box3 random_box(std::mt19937_64& rng, int lo, int hi) {
  std::uniform_int_distribution<int> u(lo, hi);
  Box3 b;
  for (int i = 0; i < 2; ++i)
    b.expand(Vec3{double(u(rng)), double(u(rng)), double(u(rng))});
  return b;
}

Mesh box_mesh(const Box3& b) {
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i)
    v.push_back({(i & 1) != 0 ? b.max.x : b.min.x, (i & 2) != 0 ? b.max.y : b.min.y,
                 (i & 4) != 0 ? b.max.z : b.min.z});
  std::vector<TriangleIndices> t;
  static constexpr int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : kQuads) {
    t.push_back({q[0], q[1], q[2]});
    t.push_back({q[0], q[2], q[3]});
  }
  return *Mesh::from_arrays(std::move(v), std::move(t));
}

TEST(ConvexConvex, BoxesMatchTheExactOverlapTestIncludingTouching) {
  std::mt19937_64 rng(0xc0c0);
  int touching = 0;
  for (int i = 0; i < 3000; ++i) {
    const Box3 a = random_box(rng, 0, 6), b = random_box(rng, 0, 6);
    const ConvexContact got = convex_convex(ConvexShape::box(a), ConvexShape::box(b));
    EXPECT_EQ(got.intersect, a.overlaps(b)) << i;
    EXPECT_TRUE(got.exact);
    touching += a.overlaps(b) && (a.max.x == b.min.x || b.max.x == a.min.x || a.max.y == b.min.y ||
                                  b.max.y == a.min.y || a.max.z == b.min.z || b.max.z == a.min.z);
  }
  EXPECT_GT(touching, 100);  // the grid makes touching common
}

TEST(ConvexConvex, TetrahedraMatchThePolyhedronReferenceOnRandomAndTouchingPairs) {
  std::mt19937_64 rng(0xc0c1);
  int hits = 0;
  for (int i = 0; i < 250; ++i) {
    const Mesh a = tetrahedron(rng, 0, 4, {0, 0, 0});
    const Mesh b = tetrahedron(rng, 0, 4, {double(i % 3), 0, 0});
    const bool want = mesh_mesh_reference(a, b).contact.intersect;
    const ConvexContact got = convex_convex(shape_of(a), shape_of(b));
    EXPECT_EQ(got.intersect, want) << i;
    EXPECT_TRUE(got.exact);
    hits += want;
  }
  EXPECT_GT(hits, 20);
  EXPECT_LT(hits, 230);
}

TEST(ConvexConvex, TetrahedronAgainstBoxMatchesTheReference) {
  std::mt19937_64 rng(0xc0c2);
  for (int i = 0; i < 150; ++i) {
    const Mesh a = tetrahedron(rng, 0, 5, {0, 0, 0});
    const Box3 box = random_box(rng, 1, 4);
    const bool want = mesh_mesh_reference(a, box_mesh(box)).contact.intersect;
    EXPECT_EQ(convex_convex(shape_of(a), ConvexShape::box(box)).intersect, want) << i;
    EXPECT_EQ(convex_convex(ConvexShape::box(box), shape_of(a)).intersect, want) << i;
  }
}

TEST(ConvexConvex, NearlyTouchingBoxesAreDecidedExactly) {
  const Box3 a{{0, 0, 0}, {1, 1, 1}};
  const double gap = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(
      convex_convex(ConvexShape::box(a), ConvexShape::box({{gap, 0, 0}, {2, 1, 1}})).intersect);
  EXPECT_TRUE(convex_convex(ConvexShape::box(a), ConvexShape::box({{1, 1, 1}, {2, 2, 2}}))
                  .intersect);  // a shared corner
  EXPECT_TRUE(
      convex_convex(ConvexShape::box(a), ConvexShape::box({{0.25, 0.25, 0.25}, {0.5, 0.5, 0.5}}))
          .intersect);  // nested
}

TEST(ConvexConvex, SpheresAndBoxesMatchTheClosedFormAwayFromTouching) {
  std::mt19937_64 rng(0xc0c3);
  std::uniform_real_distribution<double> u(-2, 2), r(0.1, 1.5);
  for (int i = 0; i < 3000; ++i) {
    const Sphere s{{u(rng), u(rng), u(rng)}, r(rng)};
    if (i % 2 == 0) {
      const Sphere t{{u(rng), u(rng), u(rng)}, r(rng)};
      const double gap = length(s.center - t.center) - (s.radius + t.radius);
      if (std::fabs(gap) < 1e-9) continue;
      const ConvexContact got = convex_convex(ConvexShape::sphere(s), ConvexShape::sphere(t));
      EXPECT_EQ(got.intersect, gap < 0) << i;
      EXPECT_FALSE(got.exact);
      if (!got.intersect) {
        EXPECT_NEAR(got.distance, gap, 1e-6);
      }
    } else {
      Box3 box;
      box.expand(Vec3{u(rng), u(rng), u(rng)});
      box.expand(Vec3{u(rng), u(rng), u(rng)});
      const Vec3 c = s.center;
      const Vec3 q{std::clamp(c.x, box.min.x, box.max.x), std::clamp(c.y, box.min.y, box.max.y),
                   std::clamp(c.z, box.min.z, box.max.z)};
      const double gap = length(c - q) - s.radius;
      if (std::fabs(gap) < 1e-9) continue;
      EXPECT_EQ(convex_convex(ConvexShape::sphere(s), ConvexShape::box(box)).intersect, gap < 0)
          << i;
      EXPECT_EQ(convex_convex(ConvexShape::box(box), ConvexShape::sphere(s)).intersect, gap < 0)
          << i;
    }
  }
}

TEST(ConvexConvex, TouchingSpheresCountAsIntersecting) {
  EXPECT_TRUE(
      convex_convex(ConvexShape::sphere({{0, 0, 0}, 1}), ConvexShape::sphere({{3, 0, 0}, 2}))
          .intersect);
  EXPECT_TRUE(
      convex_convex(ConvexShape::sphere({{0, 0, 0}, 1}), ConvexShape::box({{1, -1, -1}, {2, 1, 1}}))
          .intersect);
}

TEST(ConvexConvex, PolyhedronGivenByPlanesIsUnsupported) {
  const auto solid = ConvexPolyhedron::from_planes({Plane{1, 0, 0, 0}});
  ASSERT_TRUE(solid.ok());
  const auto shape = ConvexShape::polyhedron(*solid);
  ASSERT_FALSE(shape.ok());
  EXPECT_EQ(shape.error().kind, ErrorKind::unsupported);
}

}  // namespace
}  // namespace contain::collide
