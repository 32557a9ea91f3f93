#include "contain/collide/mesh_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <span>
#include <vector>

#include "collide/test_meshes.h"
#include "contain/collide/mesh_mesh.h"
#include "contain/collide/tri_tri.h"
#include "scenes/scenes.h"

namespace contain::collide {
namespace {

using inside::SceneObject;

// Every pair by MeshPair, the reference a scene must equal.
std::vector<std::pair<std::int32_t, std::int32_t>> pairwise(
    const std::vector<Mesh>& meshes, const std::vector<SceneObject>& objects) {
  std::vector<std::pair<std::int32_t, std::int32_t>> out;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    for (std::size_t j = i + 1; j < objects.size(); ++j) {
      const MeshPair pair(meshes[static_cast<std::size_t>(objects[i].mesh)],
                          meshes[static_cast<std::size_t>(objects[j].mesh)],
                          {.transform_a = objects[i].transform});
      if (pair.collide(objects[j].transform).intersect) {
        out.emplace_back(static_cast<std::int32_t>(i), static_cast<std::int32_t>(j));
      }
    }
  }
  return out;
}

std::vector<std::pair<std::int32_t, std::int32_t>> ids(const std::vector<ScenePair>& pairs) {
  std::vector<std::pair<std::int32_t, std::int32_t>> out;
  for (const ScenePair& p : pairs)
    out.emplace_back(p.a, p.b);
  return out;
}

// The witness of each pair is a real contact: two touching triangles or a vertex inside.
void expect_witnesses_hold(const std::vector<Mesh>& meshes, const std::vector<SceneObject>& objects,
                           const std::vector<ScenePair>& pairs) {
  for (const ScenePair& p : pairs) {
    const SceneObject& a = objects[static_cast<std::size_t>(p.a)];
    const SceneObject& b = objects[static_cast<std::size_t>(p.b)];
    const Mesh& ma = meshes[static_cast<std::size_t>(a.mesh)];
    const Mesh& mb = meshes[static_cast<std::size_t>(b.mesh)];
    if (p.contact.witness == inside::PairWitness::triangles) {
      auto world = [](const Mesh& m, const Transform& t, std::int32_t k) {
        const TriangleIndices& x = m.triangles[static_cast<std::size_t>(k)];
        return Triangle3{t.apply(m.vertices[static_cast<std::size_t>(x[0])]),
                         t.apply(m.vertices[static_cast<std::size_t>(x[1])]),
                         t.apply(m.vertices[static_cast<std::size_t>(x[2])])};
      };
      EXPECT_TRUE(tri_tri(world(ma, a.transform, p.contact.triangle_a),
                          world(mb, b.transform, p.contact.triangle_b)));
    } else {
      EXPECT_TRUE(p.contact.witness == inside::PairWitness::vertex_of_a_in_b ||
                  p.contact.witness == inside::PairWitness::vertex_of_b_in_a);
      EXPECT_GE(p.contact.vertex, 0);
    }
  }
}

TEST(MeshScene, NestedTouchingAndSeparatedCubesEqualThePairwiseTest) {
  const std::vector<Mesh> meshes{test::box_mesh({0, 0, 0}, {1, 1, 1}),
                                 test::box_mesh({0, 0, 0}, {0.25, 0.25, 0.25})};
  const std::vector<SceneObject> objects{
      {0, test::translation({0, 0, 0})},              // 0: big
      {1, test::translation({0.375, 0.375, 0.375})},  // 1: nested in 0, no surface contact
      {0, test::translation({1, 0, 0})},              // 2: touches 0 along a face
      {0, test::translation({2, 1, 1})},              // 3: touches 2 at a corner
      {1, test::translation({5, 5, 5})},              // 4: alone
      {0, test::translation({2.5, 0, -1.5})},         // 5: a gap of 0.5 from 2
  };
  const MeshScene scene(meshes, objects);
  const std::vector<ScenePair> pairs = scene.pairs();
  EXPECT_EQ(ids(pairs),
            (std::vector<std::pair<std::int32_t, std::int32_t>>{{0, 1}, {0, 2}, {2, 3}}));
  EXPECT_EQ(ids(pairs), pairwise(meshes, objects));
  EXPECT_EQ(pairs[0].contact.witness, inside::PairWitness::vertex_of_b_in_a);
  expect_witnesses_hold(meshes, objects, pairs);
  EXPECT_TRUE(scene.is_solid(0));
}

TEST(MeshScene, QuarterTurnsThatTouchAtAFaceAnEdgeOrACornerIntersectExactly) {
  // Exact rotations (entries 0 and +-1) keep the coordinates exact, so the contacts are exact:
  // the separating axis test of the rotated node boxes must never cull them.
  const std::vector<Mesh> meshes{test::box_mesh({0, 0, 0}, {1, 2, 3})};
  auto turned = [](Vec3 t, int quarter) {
    Transform r = test::translation(t);
    if (quarter == 1) r.r = {{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}};  // about z
    if (quarter == 2) r.r = {{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}};  // about x
    return r;
  };
  // The box [0,1]x[0,2]x[0,3] turned about z and moved by t spans [t.x-2, t.x] x [t.y, t.y+1] x
  // [t.z, t.z+3]; turned about x, [t.x, t.x+1] x [t.y-3, t.y] x [t.z, t.z+2].
  const std::vector<SceneObject> objects{
      {0, turned({0, 0, 0}, 0)},  // 0: [0,1]x[0,2]x[0,3]
      {0, turned({3, 0, 0}, 1)},  // 1: [1,3]x[0,1]x[0,3]: on the face x = 1 of 0
      {0, turned({5, 1, 3}, 1)},  // 2: [3,5]x[1,2]x[3,6]: the corner (3,1,3) of 1
      {0, turned({1, 2, 3}, 2)},  // 3: [1,2]x[-1,2]x[3,5]: the edge x=1, z=3 of 0, the top of 1
      {0, turned({-1, -0.5, -4}, 0)},  // 4: [-1,0]x[-0.5,1.5]x[-4,-1]: apart
  };
  const MeshScene scene(meshes, objects);
  EXPECT_EQ(ids(scene.pairs()),
            (std::vector<std::pair<std::int32_t, std::int32_t>>{{0, 1}, {0, 3}, {1, 2}, {1, 3}}));
  EXPECT_EQ(ids(scene.pairs()), pairwise(meshes, objects));
}

TEST(MeshScene, RandomPosesOfSharedMeshesEqualThePairwiseTestOnEveryThreadCount) {
  std::mt19937_64 rng(14);
  const std::vector<Mesh> meshes{scenes::torus(1.0, 0.3, 16, 8),
                                 test::box_mesh({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}),
                                 scenes::torus(0.6, 0.1, 12, 6)};
  std::vector<SceneObject> objects;
  std::uniform_int_distribution<int> which(0, 2);
  for (int k = 0; k < 24; ++k)
    objects.push_back({which(rng), test::random_pose(rng, 3.0)});
  const MeshScene scene(meshes, objects);
  const std::vector<ScenePair> one = scene.pairs({.threads = 1});
  const auto reference = pairwise(meshes, objects);
  EXPECT_EQ(ids(one), reference);
  EXPECT_GT(reference.size(), 10u);
  EXPECT_LT(scene.candidates().size(), 24u * 23u / 2u);
  for (const int threads : {2, 5, 0}) {
    const std::vector<ScenePair> many = scene.pairs({.threads = threads});
    ASSERT_EQ(ids(many), ids(one));
    for (std::size_t k = 0; k < one.size(); ++k) {
      EXPECT_EQ(many[k].contact.witness, one[k].contact.witness);
      EXPECT_EQ(many[k].contact.triangle_a, one[k].contact.triangle_a);
      EXPECT_EQ(many[k].contact.vertex, one[k].contact.vertex);
    }
  }
  expect_witnesses_hold(meshes, objects, one);
}

TEST(MeshScene, PairsOverConsecutiveRangesOfTheCandidatesEqualAllPairs) {
  // The command's progress asks in pieces (issue 24): the pieces must add up to the whole.
  std::mt19937_64 rng(15);
  const std::vector<Mesh> meshes{scenes::torus(1.0, 0.3, 16, 8),
                                 test::box_mesh({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5})};
  std::vector<SceneObject> objects;
  for (int k = 0; k < 20; ++k)
    objects.push_back({k % 2, test::random_pose(rng, 3.0)});
  const MeshScene scene(meshes, objects);
  const std::vector<ScenePair> all = scene.pairs();
  ASSERT_GT(all.size(), 5u);
  const auto candidates = scene.candidates();
  for (const std::size_t step : {std::size_t{1}, std::size_t{3}, candidates.size()}) {
    std::vector<ScenePair> pieces;
    for (std::size_t begin = 0; begin < candidates.size(); begin += step) {
      const std::size_t n = std::min(step, candidates.size() - begin);
      const auto found = scene.pairs(std::span(candidates).subspan(begin, n), {.threads = 2});
      pieces.insert(pieces.end(), found.begin(), found.end());
    }
    ASSERT_EQ(ids(pieces), ids(all)) << "step " << step;
    for (std::size_t k = 0; k < all.size(); ++k)
      EXPECT_EQ(pieces[k].contact.witness, all[k].contact.witness);
  }
  EXPECT_TRUE(scene.pairs(std::span<const std::pair<std::int32_t, std::int32_t>>{}).empty());
}

TEST(MeshScene, OpenSurfacesMeetOnlyWhereTheySharePoints) {
  // A single triangle (a surface) inside a cube meets the solid; two separate triangles do not
  // meet, and a triangle enclosed by another surface does not meet it.
  Mesh triangle;
  triangle.vertices = {{0.25, 0.25, 0.5}, {0.75, 0.25, 0.5}, {0.25, 0.75, 0.5}};
  triangle.triangles = {{0, 1, 2}};
  const std::vector<Mesh> meshes{test::box_mesh({0, 0, 0}, {1, 1, 1}), triangle};
  const std::vector<SceneObject> objects{{0, {}}, {1, {}}, {1, test::translation({0, 0, 0.25})}};
  const MeshScene scene(meshes, objects);
  EXPECT_FALSE(scene.is_solid(1));
  EXPECT_EQ(ids(scene.pairs()), pairwise(meshes, objects));
  EXPECT_EQ(ids(scene.pairs()),
            (std::vector<std::pair<std::int32_t, std::int32_t>>{{0, 1}, {0, 2}}));
}

TEST(MeshScene, EmptyAndOutOfRangeObjectsMeetNothing) {
  const std::vector<Mesh> meshes{test::box_mesh({0, 0, 0}, {1, 1, 1}), Mesh{}};
  const std::vector<SceneObject> objects{{0, {}}, {1, {}}, {7, {}}, {0, {}}};
  const MeshScene scene(meshes, objects);
  EXPECT_EQ(ids(scene.pairs()), (std::vector<std::pair<std::int32_t, std::int32_t>>{{0, 3}}));
  EXPECT_TRUE(scene.bounds(1).empty());
  EXPECT_EQ(ids(scene_pairs(meshes, objects)), ids(scene.pairs()));
  EXPECT_TRUE(MeshScene().pairs().empty());
}

}  // namespace
}  // namespace contain::collide
