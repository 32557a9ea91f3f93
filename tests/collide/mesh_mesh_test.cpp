#include "contain/collide/mesh_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "collide/test_meshes.h"
#include "contain/collide/polyhedra_reference.h"
#include "scenes/scenes.h"

namespace contain::collide {
namespace {

using test::box_mesh;
using test::translation;

const double kTiny = std::ldexp(1.0, -30);

TEST(MeshPair, TouchingCubesIntersectAndGapsOfTwoToTheMinus30DoNot) {
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  const MeshPair pair(cube, cube);
  EXPECT_TRUE(pair.collide(translation({1, 0, 0})).intersect);                  // face
  EXPECT_TRUE(pair.collide(translation({1, 1, 0})).intersect);                  // edge
  EXPECT_TRUE(pair.collide(translation({1, 1, 1})).intersect);                  // vertex
  EXPECT_TRUE(pair.collide(translation({1, 0.5, 0.25})).intersect);             // partial face
  EXPECT_FALSE(pair.collide(translation({1 + kTiny, 0, 0})).intersect);         // gap
  EXPECT_FALSE(pair.collide(translation({1 + kTiny, 1, 1})).intersect);         // vertex gap
  EXPECT_TRUE(pair.collide(translation({1 - kTiny, 1 - kTiny, 0})).intersect);  // penetration
  EXPECT_FALSE(pair.collide(translation({5, 5, 5})).intersect);
  const Contact c = pair.collide(translation({1, 0, 0}));
  EXPECT_EQ(c.witness, inside::PairWitness::triangles);
  EXPECT_GE(c.triangle_a, 0);
  EXPECT_GE(c.triangle_b, 0);
}

TEST(MeshPair, NestedSolidsIntersectWithAContainedVertexWitnessBothWays) {
  const Mesh big = box_mesh({0, 0, 0}, {4, 4, 4}), small = box_mesh({0, 0, 0}, {1, 1, 1});
  const Contact in = MeshPair(big, small).collide(translation({1, 1, 1}));
  EXPECT_TRUE(in.intersect);
  EXPECT_EQ(in.witness, inside::PairWitness::vertex_of_b_in_a);
  const Contact rev = MeshPair(small, big).collide(translation({-1, -1, -1}));
  EXPECT_TRUE(rev.intersect);
  EXPECT_EQ(rev.witness, inside::PairWitness::vertex_of_a_in_b);
  EXPECT_TRUE(MeshPair(big, small).collide(translation({3, 1, 1})).intersect);  // touching inside
  // Nested under a rotation (no surface contact): still intersecting.
  std::mt19937_64 rng(1);
  Transform t = test::random_pose(rng, 0.0);
  t.t = {2, 2, 2};
  EXPECT_TRUE(MeshPair(big, small).collide(t).intersect);
}

// A's vertex exactly on B's surface (face, face diagonal, edge, corner), in both roles: the
// surfaces share that point, so the witness is a triangle pair, never a contained vertex.
TEST(MeshPair, VertexExactlyOnTheOtherSurfaceIntersectsWithATrianglePairWitness) {
  const Mesh small = box_mesh({0, 0, 0}, {1, 1, 1}), big = box_mesh({0, 0, 0}, {4, 4, 4});
  for (const Vec3 shift :
       {Vec3{-4, -1, -3}, Vec3{-4, -2, -2}, Vec3{-4, -2, -4}, Vec3{-4, -4, -4}}) {
    const Contact a_on_b = MeshPair(small, big).collide(translation(shift));
    EXPECT_TRUE(a_on_b.intersect);
    EXPECT_EQ(a_on_b.witness, inside::PairWitness::triangles);
    const Contact b_on_a = MeshPair(big, small).collide(translation(-1.0 * shift));
    EXPECT_TRUE(b_on_a.intersect);
    EXPECT_EQ(b_on_a.witness, inside::PairWitness::triangles);
  }
  EXPECT_FALSE(MeshPair(small, big).collide(translation({-4 - 0x1p-40, -1, -3})).intersect);
}

TEST(MeshPair, CrossingBeamsWithNoVertexInsideEitherIntersect) {
  // A plus sign: every vertex of each beam lies outside the other; only edges pierce faces.
  const Mesh beam_x = box_mesh({-3, -0.5, -0.5}, {3, 0.5, 0.5});
  const Mesh beam_y = box_mesh({-0.5, -3, -0.25}, {0.5, 3, 0.25});
  EXPECT_TRUE(MeshPair(beam_x, beam_y).collide({}).intersect);
  const ReferenceResult ref = mesh_mesh_reference(beam_x, beam_y);
  EXPECT_TRUE(ref.contact.intersect);
  EXPECT_EQ(ref.stage, ReferenceStage::edges);
}

TEST(MeshPair, OpenSurfacesMeetOnlyWhereTheySharePoints) {
  Mesh tri;
  tri.vertices = {{0.25, 0.25, 0.5}, {0.75, 0.25, 0.5}, {0.25, 0.75, 0.5}};
  tri.triangles = {{0, 1, 2}};
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  const MeshPair in_solid(cube, tri);
  EXPECT_FALSE(in_solid.b_is_solid());
  EXPECT_TRUE(in_solid.collide({}).intersect);  // a surface inside a solid meets it
  EXPECT_TRUE(MeshPair(tri, cube).collide({}).intersect);
  const MeshPair two(tri, tri);
  EXPECT_TRUE(two.collide(translation({0.25, 0, 0})).intersect);
  EXPECT_FALSE(two.collide(translation({0, 0, kTiny})).intersect);
  // An open cube (one face removed) around a small triangle: no shared point, no solid.
  Mesh open = cube;
  open.triangles.pop_back();
  open.triangles.pop_back();
  EXPECT_FALSE(MeshPair(open, tri).collide({}).intersect);
}

TEST(MeshPair, FastPathAgreesWithTheSectionsReferenceOnRandomPoses) {
  const Mesh torus = scenes::torus(1.0, 0.3, 12, 8);
  const Mesh box = box_mesh({-0.2, -0.2, -1.5}, {0.2, 0.2, 1.5});
  std::mt19937_64 rng(2);
  const MeshPair pair(torus, box);
  const MeshPair self(torus, torus);
  int hits = 0;
  for (int i = 0; i < 60; ++i) {
    const Transform t = test::random_pose(rng, 1.6);
    const bool fast = pair.collide(t).intersect;
    ASSERT_EQ(fast, mesh_mesh_reference(torus, box, {}, t).contact.intersect) << i;
    ASSERT_EQ(self.collide(t).intersect, mesh_mesh_reference(torus, torus, {}, t).contact.intersect)
        << i;
    hits += fast;
  }
  EXPECT_GT(hits, 8);
  EXPECT_LT(hits, 52);
}

TEST(MeshPair, TransformOfAIsAppliedOnce) {
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  const MeshPair pair(cube, cube, {.transform_a = translation({10, 0, 0})});
  EXPECT_FALSE(pair.collide({}).intersect);
  EXPECT_TRUE(pair.collide(translation({11, 0, 0})).intersect);
  EXPECT_TRUE(mesh_mesh(cube, cube, translation({10, 0, 0}), translation({9, 1, 1})).intersect);
}

TEST(MeshPair, BatchGivesTheSingleAnswers) {
  const Mesh torus = scenes::torus(1.0, 0.3, 16, 8);
  const MeshPair pair(torus, torus);
  std::mt19937_64 rng(3);
  std::vector<Transform> poses;
  for (int i = 0; i < 64; ++i)
    poses.push_back(test::random_pose(rng, 2.5));
  std::vector<Contact> out(poses.size());
  pair.collide(poses, out, {.threads = 2});
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_EQ(out[i].intersect, pair.collide(poses[i]).intersect);
  }
}

TEST(PolyhedraReference, BoundingVolumesAnswerFarApartPairs) {
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  EXPECT_EQ(mesh_mesh_reference(cube, cube, {}, translation({3, 0, 0})).stage,
            ReferenceStage::bounding_volumes);
  EXPECT_FALSE(
      mesh_mesh_reference(cube, cube, {}, translation({1 + kTiny, 0, 0})).contact.intersect);
  EXPECT_TRUE(mesh_mesh_reference(cube, cube, {}, translation({1, 1, 1})).contact.intersect);
  const Mesh big = box_mesh({0, 0, 0}, {4, 4, 4});
  const ReferenceResult nested = mesh_mesh_reference(big, cube, {}, translation({1, 1, 1}));
  EXPECT_TRUE(nested.contact.intersect);
  EXPECT_EQ(nested.stage, ReferenceStage::vertices);
}

// A's point location is lazy (inside::PlacedMeshPair::a_holds): rays through A's hierarchy for
// the first poses, A's MeshIndex once they cost as much. A pair shared by thousands of poses on
// four threads, which builds the index part way, answers every pose as a fresh pair that only
// casts rays: nested, crossing, touching and separate poses alike.
TEST(MeshPair, LazyIndexOfAAnswersEveryPoseAsRaysAloneOnConcurrentBatches) {
  const Mesh a = scenes::torus(1.0, 0.4, 12, 8);
  Mesh b = scenes::torus(1.0, 0.4, 8, 6);
  for (Vec3& v : b.vertices)
    v = 0.125 * v;
  std::vector<Transform> poses = scenes::random_poses(6000, 1.5, 27);
  for (std::size_t i = 0; i < poses.size(); i += 2)
    poses[i].t.z = 0.0;  // half of them about the tube's core: many nested in A
  const MeshPair shared(a, b);
  std::vector<Contact> batch(poses.size());
  shared.collide(poses, batch, {.threads = 4});
  EXPECT_TRUE(shared.prepared().index_a_built());
  int nested = 0;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Contact fresh = MeshPair(a, b).collide(poses[i]);
    ASSERT_EQ(batch[i].intersect, fresh.intersect) << i;
    ASSERT_EQ(batch[i].witness, fresh.witness) << i;
    ASSERT_EQ(batch[i].vertex, fresh.vertex) << i;
    ASSERT_EQ(batch[i].triangle_a, fresh.triangle_a) << i;
    ASSERT_EQ(batch[i].triangle_b, fresh.triangle_b) << i;
    nested += fresh.witness == inside::PairWitness::vertex_of_b_in_a;
  }
  EXPECT_GT(nested, 100);
}

}  // namespace
}  // namespace contain::collide
