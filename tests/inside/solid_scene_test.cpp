#include "contain/inside/solid_scene.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "contain/inside/mesh_index.h"
#include "scenes/scenes.h"

namespace contain::inside {
namespace {

Transform shift(Vec3 t) {
  Transform out;
  out.t = t;
  return out;
}

constexpr Holder in(std::int32_t k) {
  return {k, Location::inside};
}
constexpr Holder on(std::int32_t k) {
  return {k, Location::boundary};
}

TEST(SolidScene, NestedAndTouchingSolidsAllHoldTheirPoints) {
  const std::vector<Mesh> meshes{scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}}),
                                 scenes::box_mesh(Box3{{0, 0, 0}, {0.25, 0.25, 0.25}})};
  const std::vector<SceneObject> objects{
      {0, {}}, {1, shift({0.375, 0.375, 0.375})}, {0, shift({1, 0, 0})}, {0, shift({5, 5, 5})}};
  const SolidScene scene(meshes, objects);
  EXPECT_EQ(scene.size(), 4u);
  EXPECT_EQ(scene.locate(Vec3{0.5, 0.5, 0.5}), (std::vector<Holder>{in(0), in(1)}));
  EXPECT_EQ(scene.locate(Vec3{0.375, 0.5, 0.5}), (std::vector<Holder>{in(0), on(1)}));
  EXPECT_EQ(scene.locate(Vec3{1, 0.5, 0.5}), (std::vector<Holder>{on(0), on(2)}));  // shared face
  EXPECT_EQ(scene.locate(Vec3{1.5, 0.5, 0.5}), std::vector<Holder>{in(2)});
  EXPECT_TRUE(scene.locate(Vec3{3, 3, 3}).empty());
  EXPECT_EQ(point_in_solids(meshes, objects, {5.5, 5.5, 6}), std::vector<Holder>{on(3)});
}

TEST(SolidScene, EachObjectAnswersAsItsPlacedMeshAloneOnEveryThreadCount) {
  std::mt19937_64 rng(7);
  const std::vector<Mesh> meshes{scenes::torus(1.0, 0.4, 32, 16),
                                 scenes::box_mesh(Box3{{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}})};
  std::vector<SceneObject> objects;
  std::uniform_real_distribution<double> u(-2, 2);
  for (int k = 0; k < 25; ++k) {
    Transform t;
    const double c = std::cos(0.3 * k), s = std::sin(0.3 * k);
    t.r = {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
    t.t = {u(rng), u(rng), 0.25 * u(rng)};
    objects.push_back({k % 2, t});
  }
  const SolidScene scene(meshes, objects);
  std::vector<MeshIndex> alone;
  for (const SceneObject& o : objects) {
    Mesh world = meshes[static_cast<std::size_t>(o.mesh)];
    for (Vec3& v : world.vertices)
      v = o.transform.apply(v);
    alone.emplace_back(world);
  }
  std::vector<Vec3> points =
      scenes::uniform_points(Box3{{-3.5, -3.5, -1.5}, {3.5, 3.5, 1.5}}, 10000, 3);
  // Exactly on surfaces: the placed vertices.
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const Mesh& m = meshes[static_cast<std::size_t>(objects[k].mesh)];
    for (std::size_t v = 0; v < m.vertices.size(); v += 7)
      points.push_back(objects[k].transform.apply(m.vertices[v]));
  }
  const HolderTable table = scene.locate(points, {.threads = 1});
  EXPECT_EQ(table, scene.locate(points, {.threads = 3}));
  EXPECT_EQ(table, scene.locate(points));
  std::size_t held = 0, boundary = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::vector<Holder> expected;
    for (std::size_t k = 0; k < alone.size(); ++k) {
      const Location where = alone[k].locate(points[i]);
      if (where != Location::outside) expected.push_back({static_cast<std::int32_t>(k), where});
    }
    const auto row = table.of(i);
    ASSERT_EQ(std::vector<Holder>(row.begin(), row.end()), expected) << "point " << i;
    held += !expected.empty();
    for (const Holder& h : expected)
      boundary += h.location == Location::boundary;
  }
  EXPECT_GT(held, 300u);
  EXPECT_GT(boundary, 100u);
}

}  // namespace
}  // namespace contain::inside
