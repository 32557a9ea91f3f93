// A's point location in a PlacedMeshPair is prepared in proportion to the work: the perturbed
// ray through A's hierarchy until the rays cost as much as A's MeshIndex, then the index, built
// once. These tests prove that `a_holds` answers as a MeshIndex built up front on random points
// and on the degenerate ones (vertices, points on edges and faces, rays through vertices and
// along edges, nested and inverted shells, a reflecting placement), before and after the index
// is built, and from several threads at once.
#include <gtest/gtest.h>
#include <span>

#include <algorithm>
#include <random>
#include <thread>
#include <vector>

#include "contain/bound/aabb.h"
#include "contain/inside/placed_mesh.h"
#include "scenes/scenes.h"

namespace contain::inside {
namespace {

// Off the surface: random points over the box and beyond, and each vertex moved along one axis
// (its ray then runs through other vertices and along edges).
std::vector<Vec3> points_off_and_grazing(const Mesh& mesh, std::size_t count, std::uint64_t seed) {
  const Box3 box = bound::aabb(std::span<const Vec3>(mesh.vertices));
  std::vector<Vec3> points = scenes::uniform_points(
      {box.min - Vec3{0.5, 0.5, 0.5}, box.max + Vec3{0.5, 0.5, 0.5}}, count, seed);
  for (const Vec3& v : mesh.vertices) {
    points.push_back(v - Vec3{0.25, 0, 0});
    points.push_back(v + Vec3{0, 0.125, 0});
    points.push_back(v - Vec3{0, 0, 0.125});
  }
  return points;
}

// On the surface: vertices, edge midpoints and face centroids (where exact).
std::vector<Vec3> surface_points_of(const Mesh& mesh) {
  std::vector<Vec3> points(mesh.vertices.begin(), mesh.vertices.end());
  for (const TriangleIndices& t : mesh.triangles) {
    const Vec3 a = mesh.vertex(t[0]), b = mesh.vertex(t[1]), c = mesh.vertex(t[2]);
    points.push_back(0.5 * a + 0.5 * b);
    points.push_back((1.0 / 3.0) * (a + b + c));
  }
  return points;
}

// `a_holds` against the index built up front from A as placed (its solid the image of A's):
// first the points off the surface (rays only, while the budget lasts), then those on it.
void expect_holds_as_index(const Mesh& mesh, const Transform& ta, std::uint64_t seed) {
  const PlacedMeshPair pair(mesh, scenes::box_mesh({{0, 0, 0}, {1, 1, 1}}), {.transform_a = ta});
  ASSERT_TRUE(pair.a.solid());
  const MeshIndex index(placed_solid(mesh, ta));
  const std::vector<Vec3> off = points_off_and_grazing(pair.a.mesh, 300, seed);
  for (const Vec3& q : off)
    ASSERT_EQ(pair.a_holds(q), index.locate(q) == Location::inside)
        << q.x << " " << q.y << " " << q.z;
  for (const Vec3& q : surface_points_of(pair.a.mesh))
    ASSERT_EQ(pair.a_holds(q), index.locate(q) == Location::inside)
        << q.x << " " << q.y << " " << q.z;
  ASSERT_TRUE(pair.index_a_built());  // points on the surface ask the index
  for (const Vec3& q : off)
    ASSERT_EQ(pair.a_holds(q), index.locate(q) == Location::inside);
}

Mesh turned_inside_out(Mesh mesh) {
  for (TriangleIndices& t : mesh.triangles)
    std::swap(t[1], t[2]);
  return mesh;
}

TEST(PlacedMeshPairLazy, AHoldsAnswersAsTheIndexOnATorusACubeAndNestedShells) {
  const Mesh cube = scenes::box_mesh({{0, 0, 0}, {1, 1, 1}});
  const Mesh torus = scenes::torus(1.0, 0.4, 24, 12);
  const Mesh same_way =
      scenes::joined(cube, scenes::box_mesh({{0.25, 0.25, 0.25}, {0.75, 0.75, 0.75}}));
  const Mesh cavity = scenes::joined(
      cube, turned_inside_out(scenes::box_mesh({{0.25, 0.25, 0.25}, {0.75, 0.75, 0.75}})));
  const Mesh touching = scenes::joined(cube, scenes::box_mesh({{1, 0, 0}, {2, 1, 1}}));
  Transform shift;
  shift.t = {0.5, -0.25, 2};
  Transform mirror;  // a reflection: the placed solid is the image of A's
  mirror.r = {{{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  mirror.t = {3, 0, 0};
  std::uint64_t seed = 1;
  for (const Mesh* mesh : {&cube, &torus, &same_way, &cavity, &touching})
    for (const Transform* ta : {&shift, &mirror})
      expect_holds_as_index(*mesh, *ta, seed++);
}

TEST(PlacedMeshPairLazy, RaysAloneAnswerUntilTheyCostAsMuchAsTheIndex) {
  const Mesh torus = scenes::torus(1.0, 0.4, 24, 12);
  const PlacedMeshPair pair(torus, torus);
  const MeshIndex index(torus);
  EXPECT_FALSE(pair.index_a_built());
  EXPECT_EQ(pair.a_holds({1, 0, 0}), true);
  EXPECT_EQ(pair.a_holds({0, 0, 0}), false);
  EXPECT_FALSE(pair.index_a_built());  // two rays: far below the index's cost
  // Many rays: the index gets built, and the answers stay those of the index.
  const std::vector<Vec3> points = points_off_and_grazing(torus, 20000, 7);
  for (const Vec3& q : points)
    ASSERT_EQ(pair.a_holds(q), index.locate(q) == Location::inside);
  EXPECT_TRUE(pair.index_a_built());
}

TEST(PlacedMeshPairLazy, ConcurrentQueriesBuildTheIndexOnceAndAnswerAsIt) {
  const Mesh torus = scenes::torus(1.0, 0.4, 24, 12);
  const MeshIndex index(torus);
  const std::vector<Vec3> points = points_off_and_grazing(torus, 20000, 11);
  std::vector<std::uint8_t> expected(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    expected[i] = index.locate(points[i]) == Location::inside;
  for (int round = 0; round < 3; ++round) {
    const PlacedMeshPair pair(torus, torus);
    const PlacedMeshPair copy = pair;  // shares the lazy index
    std::vector<std::vector<std::uint8_t>> answers(4, std::vector<std::uint8_t>(points.size()));
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < answers.size(); ++t) {
      threads.emplace_back([&, t] {
        const PlacedMeshPair& p = t % 2 == 0 ? pair : copy;
        for (std::size_t k = 0; k < points.size(); ++k) {
          const std::size_t i = (k + t * points.size() / 4) % points.size();
          answers[t][i] = p.a_holds(points[i]);
        }
      });
    }
    for (std::thread& thread : threads)
      thread.join();
    for (const auto& a : answers)
      ASSERT_EQ(a, expected);
    EXPECT_TRUE(pair.index_a_built());
    EXPECT_TRUE(copy.index_a_built());
    EXPECT_EQ(&pair.index_a(), &copy.index_a());  // one index for both
  }
}

TEST(PlacedMeshPairLazy, AnEmptyAHasAnEmptyIndexAndHoldsNothing) {
  const PlacedMeshPair pair(Mesh{}, scenes::box_mesh({{0, 0, 0}, {1, 1, 1}}));
  EXPECT_FALSE(pair.a_holds({0.5, 0.5, 0.5}));
  EXPECT_EQ(pair.index_a().locate({0.5, 0.5, 0.5}), Location::outside);
  const PlacedMeshPair none;
  EXPECT_FALSE(none.index_a_built());
  EXPECT_EQ(none.index_a().locate({0, 0, 0}), Location::outside);
}

}  // namespace
}  // namespace contain::inside
