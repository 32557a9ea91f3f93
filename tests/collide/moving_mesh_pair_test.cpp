// Continuous collision of moving meshes: the bullet through a thin plate, contact and nesting at
// t = 0, deforming meshes, and the hierarchy's answer against the brute force minimum over every
// vertex-face and edge-edge pair (the definition), on random motions.

#include "contain/collide/moving_mesh_pair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "collide/ccd_oracle.h"
#include "collide/test_meshes.h"
#include "contain/collide/ccd.h"
#include "contain/collide/mesh_mesh.h"
#include "support/case_budget.h"

namespace contain::collide {
namespace {

Motion translate(Vec3 from, Vec3 to) {
  return {test::translation(from), test::translation(to)};
}

// The definition: the least primitive time over all pairs, no hierarchy, no pruning.
std::optional<double> brute_force(const Mesh& a, std::span<const Vec3> a0, std::span<const Vec3> a1,
                                  const Mesh& b, std::span<const Vec3> b0,
                                  std::span<const Vec3> b1) {
  std::optional<double> best;
  const auto take = [&](const Impact& i) {
    if (i.hit && (!best || i.time < *best)) best = i.time;
  };
  for (const TriangleIndices& x : a.triangles) {
    for (const TriangleIndices& y : b.triangles) {
      const auto at = [](std::span<const Vec3> p, std::int32_t v) {
        return p[static_cast<std::size_t>(v)];
      };
      for (int k = 0; k < 3; ++k) {
        const auto xk = x[static_cast<std::size_t>(k)], yk = y[static_cast<std::size_t>(k)];
        take(vertex_face_ccd({at(a0, xk), at(b0, y[0]), at(b0, y[1]), at(b0, y[2]), at(a1, xk),
                              at(b1, y[0]), at(b1, y[1]), at(b1, y[2])}));
        take(vertex_face_ccd({at(b0, yk), at(a0, x[0]), at(a0, x[1]), at(a0, x[2]), at(b1, yk),
                              at(a1, x[0]), at(a1, x[1]), at(a1, x[2])}));
      }
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          const auto p = x[static_cast<std::size_t>(i)],
                     q = x[static_cast<std::size_t>((i + 1) % 3)];
          const auto r = y[static_cast<std::size_t>(j)],
                     s = y[static_cast<std::size_t>((j + 1) % 3)];
          take(edge_edge_ccd({at(a0, p), at(a0, q), at(b0, r), at(b0, s), at(a1, p), at(a1, q),
                              at(b1, r), at(b1, s)}));
        }
      }
    }
  }
  return best;
}

std::vector<Vec3> placed_vertices(const Mesh& m, const Transform& t) {
  std::vector<Vec3> out;
  for (const Vec3& v : m.vertices)
    out.push_back(t.apply(v));
  return out;
}

TEST(MovingMeshPair, FastBoxThroughAThinPlateIsHitThoughBothPosesAreDisjoint) {
  const Mesh plate = test::box_mesh({-1, -1, -0.01}, {1, 1, 0.01});
  const Mesh bullet = test::box_mesh({-0.05, -0.05, -0.05}, {0.05, 0.05, 0.05});
  const Motion motion = translate({0.1, 0.2, 3}, {0.1, 0.2, -3});
  EXPECT_FALSE(mesh_mesh(plate, bullet, {}, motion.from).intersect);
  EXPECT_FALSE(mesh_mesh(plate, bullet, {}, motion.to).intersect);
  const MeshImpact m = mesh_mesh_ccd(plate, bullet, {}, motion);
  ASSERT_TRUE(m.hit);
  // The bullet's bottom face (z = -0.05 + 3 - 6t) reaches the plate's top (0.01) at
  // t = 2.94 / 6 = 0.49, rounded down; contact first at a face, so every primitive touching then
  // is a vertex-face or edge-edge pair at the same time.
  const std::optional<double> expected =
      brute_force(plate, plate.vertices, plate.vertices, bullet,
                  placed_vertices(bullet, motion.from), placed_vertices(bullet, motion.to));
  ASSERT_TRUE(expected.has_value());
  EXPECT_EQ(m.time, *expected);
  EXPECT_NEAR(m.time, 0.49, 1e-15);
  EXPECT_LE(m.time, 0.49);
  EXPECT_NE(m.witness, MeshImpactWitness::initial);
  EXPECT_GT(m.primitive_tests, 0U);
}

TEST(MovingMeshPair, ShapesTouchingAtTimeZeroGiveZeroWithTheDiscreteWitness) {
  const Mesh a = test::box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh b = test::box_mesh({1, 0, 0}, {2, 1, 1});  // sharing the face x = 1
  const MeshImpact m = mesh_mesh_ccd(a, b, {}, translate({0, 0, 0}, {5, 0, 0}));
  ASSERT_TRUE(m.hit);
  EXPECT_EQ(m.time, 0.0);
  EXPECT_EQ(m.witness, MeshImpactWitness::initial);
  EXPECT_TRUE(m.initial.intersect);
}

TEST(MovingMeshPair, NestedSolidsAtTimeZeroGiveZero) {
  const Mesh outer = test::box_mesh({-2, -2, -2}, {2, 2, 2});
  const Mesh inner = test::box_mesh({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5});
  const MeshImpact m = mesh_mesh_ccd(outer, inner, {}, translate({0, 0, 0}, {0.1, 0, 0}));
  ASSERT_TRUE(m.hit);
  EXPECT_EQ(m.time, 0.0);
  EXPECT_EQ(m.initial.witness, inside::PairWitness::vertex_of_b_in_a);
}

TEST(MovingMeshPair, MovingApartMisses) {
  const Mesh a = test::box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh b = test::box_mesh({2, 0, 0}, {3, 1, 1});
  const MeshImpact m = mesh_mesh_ccd(a, b, {}, translate({0, 0, 0}, {4, 0, 0}));
  EXPECT_FALSE(m.hit);
  EXPECT_EQ(m.witness, MeshImpactWitness::none);
  EXPECT_TRUE(std::isinf(m.time));
}

TEST(MovingMeshPair, BothMeshesMovingMeetWhereTheirFacesMeet) {
  const Mesh a = test::box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh b = test::box_mesh({0, 0, 0}, {1, 1, 1});
  // A from x = 0 to x = 2, B from x = 4 to x = 0: faces x = 1 + 2t and x = 4 - 4t meet at 1/2.
  const MeshImpact m =
      mesh_mesh_ccd(a, b, translate({0, 0, 0}, {2, 0, 0}), translate({4, 0, 0}, {0, 0, 0}));
  ASSERT_TRUE(m.hit);
  EXPECT_EQ(m.time, 0.5);
}

TEST(MovingMeshPair, DeformingMeshesUseTheirVertexArrays) {
  const Mesh a = test::box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh b = test::box_mesh({3, 0, 0}, {4, 1, 1});
  std::vector<Vec3> a1 = a.vertices, b1 = b.vertices;
  // A's vertex with the largest x stretches to x = 5: it pierces B's face x = 3 at t = 1/2.
  std::size_t far = 0;
  for (std::size_t v = 0; v < a.vertices.size(); ++v)
    if (a.vertices[v].x == 1 && a.vertices[v].y == 1 && a.vertices[v].z == 1) far = v;
  b1 = b.vertices;
  a1[far] = {5, 0.5, 0.5};
  const MeshImpact m = mesh_mesh_ccd(a, a1, b, b1);
  ASSERT_TRUE(m.hit);
  EXPECT_EQ(m.time, brute_force(a, a.vertices, a1, b, b.vertices, b1));
  // The same through the prepared object with B deforming.
  const MovingMeshPair pair(b, a);
  const MeshImpact n = pair.first_contact(a1);
  ASSERT_TRUE(n.hit);
  EXPECT_EQ(n.time, m.time);
}

TEST(MovingMeshPair, HierarchyEqualsTheBruteForceMinimumOnRandomMotions) {
  std::mt19937_64 rng(21);
  const Mesh a = test::box_mesh({-1, -1, -1}, {1, 1, 1});
  const Mesh b = test::box_mesh({-0.5, -0.3, -0.2}, {0.5, 0.3, 0.2});
  int hits = 0, runs = 0;
  const int count = test::reduced_cases ? 40 : 300;  // support/case_budget.h
  for (int i = 0; i < count; ++i) {
    const Motion ma{test::random_pose(rng, 2.0), test::random_pose(rng, 2.0)};
    const Motion mb{test::random_pose(rng, 2.0), test::random_pose(rng, 2.0)};
    const MeshImpact m = mesh_mesh_ccd(a, b, ma, mb);
    if (m.witness == MeshImpactWitness::initial) continue;
    ++runs;
    const std::optional<double> expected =
        brute_force(a, placed_vertices(a, ma.from), placed_vertices(a, ma.to), b,
                    placed_vertices(b, mb.from), placed_vertices(b, mb.to));
    ASSERT_EQ(m.hit, expected.has_value()) << "motion " << i;
    if (expected) {
      ++hits;
      ASSERT_EQ(m.time, *expected) << "motion " << i;
    }
  }
  EXPECT_GT(hits, 5);
  EXPECT_GT(runs - hits, 5);
}

TEST(MovingMeshPair, WitnessPrimitiveHasTheReportedTimeByTheOracle) {
  const Mesh plate = test::box_mesh({-1, -1, -0.01}, {1, 1, 0.01});
  const Mesh bullet = test::box_mesh({-0.05, -0.05, -0.05}, {0.05, 0.05, 0.05});
  std::mt19937_64 rng(22);
  for (int i = 0; i < 20; ++i) {
    const Motion mb{test::random_pose(rng, 1.0), test::random_pose(rng, 1.0)};
    const MeshImpact m = mesh_mesh_ccd(plate, bullet, {}, mb);
    if (!m.hit || m.witness == MeshImpactWitness::initial) continue;
    const std::vector<Vec3> b0 = placed_vertices(bullet, mb.from),
                            b1 = placed_vertices(bullet, mb.to);
    std::optional<double> t;
    if (m.witness == MeshImpactWitness::edges) {
      t = test::exact_edge_edge_time(
          {plate.vertices[static_cast<std::size_t>(m.edge_a[0])],
           plate.vertices[static_cast<std::size_t>(m.edge_a[1])],
           b0[static_cast<std::size_t>(m.edge_b[0])], b0[static_cast<std::size_t>(m.edge_b[1])],
           plate.vertices[static_cast<std::size_t>(m.edge_a[0])],
           plate.vertices[static_cast<std::size_t>(m.edge_a[1])],
           b1[static_cast<std::size_t>(m.edge_b[0])], b1[static_cast<std::size_t>(m.edge_b[1])]});
    } else {
      const bool a_vertex = m.witness == MeshImpactWitness::vertex_a_face_b;
      const auto& tri = (a_vertex ? bullet : plate).triangles[static_cast<std::size_t>(m.triangle)];
      const auto pos = [&](bool of_a, int time, std::int32_t v) {
        return of_a ? plate.vertices[static_cast<std::size_t>(v)]
                    : (time == 0 ? b0 : b1)[static_cast<std::size_t>(v)];
      };
      test::CcdQuery q;
      for (int time = 0; time < 2; ++time) {
        q[static_cast<std::size_t>(4 * time)] = pos(a_vertex, time, m.vertex);
        for (int k = 0; k < 3; ++k)
          q[static_cast<std::size_t>(4 * time + 1 + k)] =
              pos(!a_vertex, time, tri[static_cast<std::size_t>(k)]);
      }
      t = test::exact_vertex_face_time(q);
    }
    ASSERT_TRUE(t.has_value());
    EXPECT_EQ(*t, m.time);
  }
}

TEST(MovingMeshPair, BatchesEqualSingleQueriesWhateverTheThreadCount) {
  std::mt19937_64 rng(23);
  const Mesh a = test::box_mesh({-1, -1, -1}, {1, 1, 1});
  const Mesh b = test::box_mesh({-0.5, -0.3, -0.2}, {0.5, 0.3, 0.2});
  std::vector<Motion> motions;
  for (int i = 0; i < 64; ++i)
    motions.push_back({test::random_pose(rng, 3.0), test::random_pose(rng, 3.0)});
  const MovingMeshPair pair(a, b);
  std::vector<MeshImpact> one(motions.size()), many(motions.size());
  pair.first_contact(motions, one, {.threads = 1});
  pair.first_contact(motions, many, {.threads = 3});
  for (std::size_t i = 0; i < motions.size(); ++i) {
    const MeshImpact s = pair.first_contact(motions[i]);
    EXPECT_EQ(one[i].hit, s.hit);
    EXPECT_EQ(many[i].hit, s.hit);
    if (s.hit) {
      EXPECT_EQ(one[i].time, s.time);
      EXPECT_EQ(many[i].time, s.time);
      EXPECT_EQ(many[i].witness, s.witness);
      EXPECT_EQ(many[i].vertex, s.vertex);
    }
  }
}

TEST(MovingMeshPair, EmptyMeshesNeverTouch) {
  const Mesh a = test::box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh empty;
  EXPECT_FALSE(mesh_mesh_ccd(a, empty, {}, {}).hit);
  EXPECT_FALSE(mesh_mesh_ccd(empty, a, {}, {}).hit);
}

}  // namespace
}  // namespace contain::collide
