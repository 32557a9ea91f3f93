// Issue 24: collide and the mesh-pair distance read a closed mesh as the same solid as
// inside::MeshIndex: where its winding number is positive (overlapping parts and nested shells
// of the same orientation count once, an inverted shell is a cavity), by ray parity where the
// orientation is inconsistent, and under a reflecting placement the image of that solid. A small
// cube placed in a cell of a random self-overlapping mesh of boxes (no surface near it) meets the
// mesh exactly where the GMP oracle's winding number says the cell is in the solid, whichever
// side of the pair holds the mesh (A's index or B's ray), for MeshPair, MeshPairDistance and
// MeshScene; and inside::SolidScene (`inside --scene`) holds the cube's corner exactly then.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "collide/test_meshes.h"
#include "contain/bound/aabb.h"
#include "contain/collide/mesh_mesh.h"
#include "contain/collide/mesh_scene.h"
#include "contain/distance/mesh_pair_distance.h"
#include "contain/inside/mesh_index.h"
#include "contain/inside/solid_scene.h"
#include "contain/values/box.h"
#include "support/perturbed_ray_oracle.h"

namespace contain::collide {
namespace {

// Three to five boxes with integer corners in [0, 4]^3, a third of them turned inside out; with
// `flip`, one triangle reversed (every edge still of two triangles: no winding number).
Mesh random_boxes(std::mt19937_64& rng, bool flip) {
  std::uniform_int_distribution<int> corner(0, 4), count(3, 5), inverted(0, 2);
  Mesh m;
  for (int n = count(rng), b = 0; b < n; ++b) {
    std::array<double, 3> lo{}, hi{};
    for (std::size_t k = 0; k < 3; ++k) {
      const int u = corner(rng);
      int v = corner(rng);
      while (v == u)
        v = corner(rng);
      lo[k] = std::min(u, v);
      hi[k] = std::max(u, v);
    }
    Mesh box = test::box_mesh({lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]});
    const auto base = static_cast<std::int32_t>(m.vertices.size());
    const bool inward = inverted(rng) == 0;
    m.vertices.insert(m.vertices.end(), box.vertices.begin(), box.vertices.end());
    for (TriangleIndices t : box.triangles) {
      if (inward) std::swap(t[1], t[2]);
      m.triangles.push_back({base + t[0], base + t[1], base + t[2]});
    }
  }
  if (flip) std::swap(m.triangles[0][1], m.triangles[0][2]);
  return m;
}

// Does every directed edge occur as often as its reverse, by position? (The oracle's own count.)
bool directed_edges_match(const Mesh& m) {
  std::map<std::pair<std::array<double, 3>, std::array<double, 3>>, int> balance;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Triangle3 tri = m.triangle(t);
    const Vec3 c[3] = {tri.a, tri.b, tri.c};
    for (int e = 0; e < 3; ++e) {
      const std::array<double, 3> p{c[e].x, c[e].y, c[e].z};
      const std::array<double, 3> q{c[(e + 1) % 3].x, c[(e + 1) % 3].y, c[(e + 1) % 3].z};
      if (p < q) {
        ++balance[{p, q}];
      } else {
        --balance[{q, p}];
      }
    }
  }
  return std::all_of(balance.begin(), balance.end(), [](const auto& e) { return e.second == 0; });
}

// A signed permutation of the axes (a reflection half the time) and an integer shift: the placed
// coordinates are exact. `det` is its determinant.
Transform random_placement(std::mt19937_64& rng, int& det) {
  std::array<int, 3> axis{0, 1, 2};
  std::shuffle(axis.begin(), axis.end(), rng);
  std::uniform_int_distribution<int> coin(0, 1), shift(-2, 2);
  Transform t;
  t.r = {};
  det = 1;
  for (std::size_t i = 0; i < 3; ++i) {
    const int s = coin(rng) ? 1 : -1;
    t.r[i][static_cast<std::size_t>(axis[i])] = s;
    det *= s;
  }
  for (std::size_t i = 0; i < 3; ++i)  // the permutation's sign
    for (std::size_t j = i + 1; j < 3; ++j)
      det *= axis[i] < axis[j] ? 1 : -1;
  t.t = {static_cast<double>(shift(rng)), static_cast<double>(shift(rng)),
         static_cast<double>(shift(rng))};
  return t;
}

TEST(SolidNesting, ACubeInACellMeetsASelfOverlappingMeshWhereTheOracleWindingNumberSaysInside) {
  std::mt19937_64 rng(24);
  const Mesh cube = test::box_mesh({-0.0625, -0.0625, -0.0625}, {0.0625, 0.0625, 0.0625});
  int inside_seen = 0, outside_seen = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const bool flip = trial % 4 == 3;
    const Mesh mesh = random_boxes(rng, flip);
    int det = 1;
    const Transform place = random_placement(rng, det);
    const Mesh world = placed(mesh, place);  // exact: integers
    const bool by_winding = directed_edges_match(mesh);
    ASSERT_TRUE(by_winding || flip);
    const distance::MeshPairDistance mesh_first(mesh, cube, {.transform_a = place});
    const MeshPair mesh_is_a(mesh, cube, {.transform_a = place});
    // Cells of the mesh's box and of the layer around it.
    const Box3 box = bound::aabb(std::span<const Vec3>(world.vertices));
    std::uniform_real_distribution<double> u(0.15, 0.85);
    std::uniform_int_distribution<int> cx(static_cast<int>(box.min.x) - 1,
                                          static_cast<int>(box.max.x)),
        cy(static_cast<int>(box.min.y) - 1, static_cast<int>(box.max.y)),
        cz(static_cast<int>(box.min.z) - 1, static_cast<int>(box.max.z));
    for (int probe = 0; probe < 25; ++probe) {
      // The cube's centre inside one unit cell, 0.15 from its walls: no face of the mesh near it.
      Transform pose = test::random_pose(rng, 0.0);
      pose.t = {cx(rng) + u(rng), cy(rng) + u(rng), cz(rng) + u(rng)};
      const Vec3 corner = pose.apply(cube.vertices[0]);
      const int w = test::oracle_winding(world, corner);
      const bool expected = by_winding ? det * w > 0 : (w & 1) != 0;
      (expected ? inside_seen : outside_seen) += 1;
      const std::string at = std::to_string(trial) + "/" + std::to_string(probe);
      EXPECT_EQ(mesh_is_a.collide(pose).intersect, expected) << at;
      EXPECT_EQ(mesh_first.distance(pose).distance == 0.0, expected) << at;
      const MeshPair mesh_is_b(cube, mesh, {.transform_a = pose});
      const Contact c = mesh_is_b.collide(place);
      EXPECT_EQ(c.intersect, expected) << at;
      if (expected) {
        EXPECT_EQ(c.witness, inside::PairWitness::vertex_of_a_in_b) << at;
      }
      const distance::MeshPairDistance cube_first(cube, mesh, {.transform_a = pose});
      EXPECT_EQ(cube_first.distance(place).distance == 0.0, expected) << at;
      const std::vector<Mesh> meshes{mesh, cube};
      const std::vector<inside::SceneObject> objects{{0, place}, {1, pose}};
      EXPECT_EQ(MeshScene(meshes, objects).pairs().size(), expected ? 1u : 0u) << at;
      // `inside --scene` holds the cube's corner in the mesh's object exactly then.
      const std::vector<inside::Holder> holders =
          inside::SolidScene(std::span<const Mesh>(meshes).first(1),
                             std::span<const inside::SceneObject>(objects).first(1))
              .locate(corner);
      EXPECT_EQ(holders.size(), expected ? 1u : 0u) << at;
    }
  }
  EXPECT_GT(inside_seen, 50);  // both answers were exercised
  EXPECT_GT(outside_seen, 50);
}

TEST(SolidNesting, NestedShellsOfOneOrientationAreOneSolidAndAnInvertedOneIsACavity) {
  const Mesh cube = test::box_mesh({0, 0, 0}, {0.25, 0.25, 0.25});
  const auto shells = [](bool inner_inverted) {
    Mesh m = test::box_mesh({0, 0, 0}, {4, 4, 4});
    const Mesh inner = test::box_mesh({1, 1, 1}, {3, 3, 3});
    m.vertices.insert(m.vertices.end(), inner.vertices.begin(), inner.vertices.end());
    for (TriangleIndices t : inner.triangles) {
      if (inner_inverted) std::swap(t[1], t[2]);
      m.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
    }
    return m;
  };
  const Transform in_inner = test::translation({1.5, 1.5, 1.5});
  const Transform between = test::translation({0.5, 0.5, 0.5});
  for (const bool inverted : {false, true}) {
    const Mesh mesh = shells(inverted);
    const MeshPair pair(mesh, cube), swapped(cube, mesh, {.transform_a = in_inner});
    EXPECT_EQ(pair.collide(in_inner).intersect, !inverted);
    EXPECT_EQ(swapped.collide(Transform{}).intersect, !inverted);
    EXPECT_TRUE(pair.collide(between).intersect);
    const distance::MeshPairDistance d(cube, mesh, {.transform_a = in_inner});
    // In the cavity the cube [1.5, 1.75]^3 is 0.5 from the inner shell's walls.
    EXPECT_EQ(d.distance(Transform{}).distance, inverted ? 0.5 : 0.0);
  }
}

}  // namespace
}  // namespace contain::collide
