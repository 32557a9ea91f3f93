// MeshPairDistance and predicates::closest_flats against a brute-force GMP oracle: every triangle
// pair's exact distance (0 if they intersect, by the collide tests' independent GMP test, else
// the least of the 6 vertex-triangle and 9 edge-edge exact distances), ties to the lowest pair;
// nesting by exact point location.

#include "contain/distance/mesh_pair_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "contain/inside/point_in_mesh.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/rounded_distance.h"
#include "distance/mesh_oracle.h"
#include "scenes/scenes.h"
#include "support/case_budget.h"
#include "support/exact_distance.h"

namespace contain::distance {
namespace {

// The flat pair's exact squared distance, from its definition (crossing pairs are 0).
mpq_class flat_pair_distance(const predicates::FlatPair3& x) {
  if ((x.a.size == 2 && x.b.size == 3) || (x.a.size == 3 && x.b.size == 2)) return 0;
  // reuse the point-flat and line-line definitions through the oracle helpers
  predicates::FlatPair3 n = x;
  if (n.a.size > n.b.size) std::swap(n.a, n.b);
  const test::QVec3 p = test::exact(n.a.points[0]);
  const test::QVec3 q0 = test::exact(n.b.points[0]);
  if (n.a.size == 1 && n.b.size == 1) {
    const test::QVec3 d = test::qsub(p, q0);
    return test::qdot(d, d);
  }
  if (n.a.size == 1 && n.b.size == 2) {
    const test::QVec3 u = test::qsub(test::exact(n.b.points[1]), q0);
    const test::QVec3 c = test::qcross(test::qsub(p, q0), u);
    return test::qdot(c, c) / test::qdot(u, u);
  }
  if (n.a.size == 1) {
    const test::QVec3 nn = test::qcross(test::qsub(test::exact(n.b.points[1]), q0),
                                        test::qsub(test::exact(n.b.points[2]), q0));
    const mpq_class s = test::qdot(test::qsub(p, q0), nn);
    return s * s / test::qdot(nn, nn);
  }
  const test::QVec3 m = test::qcross(test::qsub(test::exact(n.a.points[1]), p),
                                     test::qsub(test::exact(n.b.points[1]), q0));
  const mpq_class s = test::qdot(test::qsub(q0, p), m);
  return s * s / test::qdot(m, m);
}

Vec3 lattice_point(std::mt19937_64& rng, int n) {
  std::uniform_int_distribution<int> d(-n, n);
  return {0.5 * d(rng), 0.5 * d(rng), 0.5 * d(rng)};
}

TEST(ClosestFlats, TrianglePairsMatchTheExactOracleIncludingCrossingsAndTouching) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1, 1);
  int failures = 0;
  for (int i = 0; i < test::case_budget(3000, 5) && failures < 10; ++i) {
    const bool lat = i % 2 == 0;
    auto pick = [&] { return lat ? lattice_point(rng, 3) : Vec3{u(rng), u(rng), u(rng)}; };
    Triangle3 s{pick(), pick(), pick()}, t{pick(), pick(), pick()};
    if (i % 7 == 0) t.a = s.b;                // shared vertex
    if (i % 11 == 0) t = {s.b, s.a, pick()};  // shared edge
    const predicates::FlatPair3 pair = predicates::closest_flats(s, t);
    const mpq_class want = test::exact_triangle_pair(s, t);
    if (flat_pair_distance(pair) != want) {
      ADD_FAILURE() << "triangle pair " << i << " " << test::hex3(s.a) << test::hex3(s.b)
                    << test::hex3(s.c) << " / " << test::hex3(t.a) << test::hex3(t.b)
                    << test::hex3(t.c);
      ++failures;
      continue;
    }
    if (predicates::rounded_distance(pair) != test::nearest_double_sqrt(want)) {
      ADD_FAILURE() << "rounding, pair " << i;
      ++failures;
    }
  }
  EXPECT_EQ(failures, 0);
}

TEST(ClosestFlats, SegmentPairsMatchTheExactOracleIn3DAnd2D) {
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < test::case_budget(5000, 5); ++i) {
    const bool lat = i % 2 == 0;
    auto pick = [&] { return lat ? lattice_point(rng, 3) : Vec3{u(rng), u(rng), u(rng)}; };
    Segment3 s{pick(), pick()}, t{pick(), pick()};
    if (i % 9 == 0) t.b = t.a;
    if (i % 13 == 0) t = {s.a + (s.b - s.a), s.a};
    const mpq_class want = test::exact_squared_distance(s, t);
    ASSERT_EQ(flat_pair_distance(predicates::closest_flats(s, t)), want) << i;
    const Segment2 s2{{s.a.x, s.a.y}, {s.b.x, s.b.y}}, t2{{t.a.x, t.a.y}, {t.b.x, t.b.y}};
    const mpq_class want2 = test::exact_squared_distance(s2, t2);
    ASSERT_EQ(predicates::rounded_distance(predicates::closest_flats(s2, t2)),
              test::nearest_double_sqrt(want2))
        << i;
  }
}

Transform rotation(double angle, Vec3 t) {
  const double c = std::cos(angle), s = std::sin(angle);
  Transform x;
  x.r = {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
  x.t = t;
  return x;
}

void check_pose(const MeshPairDistance& pair, const Mesh& a, const Mesh& b, const Transform& tb,
                int& failures) {
  const PairDistance3 got = pair.distance(tb);
  const Mesh wb = placed(b, tb);
  const test::PairOracle want = test::pair_oracle(a, wb);
  bool nested = false;
  if (want.d2 > 0) {
    nested = inside::point_in_mesh(a, wb.vertices[static_cast<std::size_t>(wb.triangles[0][0])]) ==
                 Location::inside ||
             inside::point_in_mesh(wb, a.vertices[static_cast<std::size_t>(a.triangles[0][0])]) ==
                 Location::inside;
  }
  const double d = nested ? 0.0 : test::nearest_double_sqrt(want.d2);
  bool ok = got.distance == d;
  if (got.contact == inside::PairWitness::vertex_of_b_in_a ||
      got.contact == inside::PairWitness::vertex_of_a_in_b) {
    // a vertex witness: distance 0, and the vertex strictly inside the other solid
    const bool of_b = got.contact == inside::PairWitness::vertex_of_b_in_a;
    const Vec3 v = of_b ? wb.vertices[static_cast<std::size_t>(got.vertex)]
                        : a.vertices[static_cast<std::size_t>(got.vertex)];
    ok = ok && (nested || want.d2 == 0) &&
         inside::point_in_mesh(of_b ? a : wb, v) == Location::inside && got.point_a == v;
  } else {
    ok = ok && !nested && got.triangle_a == want.a && got.triangle_b == want.b;
    if (want.d2 == 0) ok = ok && got.contact == inside::PairWitness::triangles;
  }
  if (!ok) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "got %a (%d, %d, %s) want %a (%d, %d, nested %d)", got.distance,
                  got.triangle_a, got.triangle_b, to_string(got.contact), d, want.a, want.b,
                  nested ? 1 : 0);
    ADD_FAILURE() << buf;
    ++failures;
  }
  // within at the distance and its neighbours, exactly
  for (const double dd : {d, std::nextafter(d, 0.0), std::nextafter(d, 1e300)}) {
    const mpq_class q(dd);
    const bool want_within = nested || want.d2 <= q * q;
    if (pair.within(tb, dd) != want_within) {
      ADD_FAILURE() << "within " << dd;
      ++failures;
    }
  }
}

TEST(MeshPairDistance, RandomPosesOfTwoTorimatchTheExactOracle) {
  const Mesh a = scenes::torus(1.0, 0.35, 10, 6);
  const Mesh b = scenes::torus(0.6, 0.2, 8, 5);
  const MeshPairDistance pair(a, b);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-2.5, 2.5), ang(0, 6.28);
  int failures = 0;
  for (int i = 0; i < test::case_budget(24, 5) && failures < 5; ++i)
    check_pose(pair, a, b, rotation(ang(rng), {u(rng), u(rng), 0.3 * u(rng)}), failures);
  EXPECT_EQ(failures, 0);
}

// Tori that cross (B's centre on A's tube surface, random orientations): the surfaces meet along
// curves, and the answer is the meeting pair lowest in (triangle of A, triangle of B) that the
// descent searches for directly once one pair is found to meet.
TEST(MeshPairDistance, CrossingToriReportTheLowestMeetingPair) {
  const Mesh a = scenes::torus(1.0, 0.35, 12, 7);
  const Mesh b = scenes::torus(0.5, 0.15, 9, 6);
  const MeshPairDistance pair(a, b);
  int failures = 0, touching = 0;
  int i = 0;
  for (Transform t : scenes::random_poses(test::case_budget(10, 5) + 2, 0.0, 23)) {
    const double angle = 0.7 * i++;
    t.t = {1.35 * std::cos(angle), 1.35 * std::sin(angle), 0.0};
    if (pair.distance(t).contact == inside::PairWitness::triangles) ++touching;
    check_pose(pair, a, b, t, failures);
  }
  EXPECT_GT(touching, 0);
  EXPECT_EQ(failures, 0);
}

TEST(MeshPairDistance, TouchingNestedAndSeparatedBoxesOnALattice) {
  const Mesh big = scenes::box_mesh({{0, 0, 0}, {4, 4, 4}});
  const Mesh small = scenes::box_mesh({{0, 0, 0}, {1, 1, 1}});
  const MeshPairDistance pair(big, small);
  int failures = 0;
  Transform t;
  for (const Vec3 shift : {Vec3{4, 0, 0}, Vec3{5, 0.5, 0.5}, Vec3{1.5, 1.5, 1.5}, Vec3{4, 4, 4},
                           Vec3{-1, -1, -1}, Vec3{-2, 1, 3}, Vec3{3.5, 3.5, 3.5}, Vec3{6, 7, 8}}) {
    t.t = shift;
    check_pose(pair, big, small, t, failures);
  }
  EXPECT_EQ(failures, 0);
  t.t = {1.5, 1.5, 1.5};
  EXPECT_EQ(pair.distance(t).contact, inside::PairWitness::vertex_of_b_in_a);
  const MeshPairDistance inverse(small, big);
  t.t = {-1.5, -1.5, -1.5};
  EXPECT_EQ(inverse.distance(t).contact, inside::PairWitness::vertex_of_a_in_b);
  t.t = {4, 0, 0};
  EXPECT_EQ(pair.distance(t).contact, inside::PairWitness::triangles);
  EXPECT_EQ(pair.distance(t).distance, 0.0);
  t.t = {6, 0, 0};
  EXPECT_EQ(pair.distance(t).distance, 2.0);
}

// A's first vertex (the one the nesting stage tests for its component) exactly on B's surface:
// inside a face, on the diagonal between two of its triangles, on an edge of the box, on a
// corner. The ray parity from a point on the surface means nothing; the nesting test must call
// it the boundary, so that the answer is the touching pair of the descent, not "nested".
TEST(MeshPairDistance, VertexOfAExactlyOnBsFaceDiagonalEdgeOrCornerIsTouchingNotNested) {
  const Mesh small = scenes::box_mesh({{0, 0, 0}, {1, 1, 1}});
  const Mesh big = scenes::box_mesh({{0, 0, 0}, {4, 4, 4}});
  const MeshPairDistance pair(small, big);
  Transform t;
  for (const Vec3 shift :
       {Vec3{-4, -1, -3}, Vec3{-4, -2, -2}, Vec3{-4, -2, -4}, Vec3{-4, -4, -4}, Vec3{-4, -3, -1}}) {
    t.t = shift;
    const PairDistance3 d = pair.distance(t);
    EXPECT_EQ(d.distance, 0.0);
    EXPECT_EQ(d.contact, inside::PairWitness::triangles) << shift.y << " " << shift.z;
    EXPECT_GE(d.triangle_a, 0);
    EXPECT_TRUE(pair.within(t, 0.0));
  }
  // Just off the face, outside: a gap; just inside: nested.
  t.t = {-4 - 0x1p-40, -1, -3};
  EXPECT_EQ(pair.distance(t).contact, inside::PairWitness::none);
  EXPECT_FALSE(pair.within(t, 0.0));
  t.t = {-4 + 0x1p-40, -1, -3};
  EXPECT_EQ(pair.distance(t).distance, 0.0);
}

// Far from the origin the placed boxes of B's hierarchy carry rounding of the size of the
// gaps: rotated poses that bring a corner of B within 1e-9 .. 1e-13 of A's face (or onto it, as
// computed) must still find the exact closest pair.
TEST(MeshPairDistance, RotatedPosesFarFromTheOriginWithGapsAtTheRoundingScale) {
  const double far = 1e6;
  const Mesh a = scenes::box_mesh({{far, far, far}, {far + 1, far + 1, far + 1}});
  const Mesh b = scenes::torus(0.3, 0.1, 12, 6);
  const MeshPairDistance pair(a, b);
  int failures = 0;
  int poses = 0;
  for (Transform t : scenes::random_poses(test::case_budget(12, 5) + 2, 0.0, 17)) {
    for (const double gap : {1e-9, 1e-11, 1e-13, 0.0}) {
      // B placed with its lowest x just beyond A's face x = far + 1, opposite A's middle.
      t.t = {0, far + 0.5, far + 0.5};
      double min_x = INFINITY;
      for (const Vec3& v : b.vertices)
        min_x = std::min(min_x, t.apply(v).x);
      t.t.x = far + 1 + gap - min_x;
      check_pose(pair, a, b, t, failures);
      ++poses;
    }
  }
  EXPECT_GT(poses, 0);
  EXPECT_EQ(failures, 0);
}

TEST(MeshPairDistance, BatchOfPosesEqualsSingleQueriesOnAnyThreadCount) {
  const Mesh a = scenes::torus(1.0, 0.35, 24, 12);
  const Mesh b = scenes::torus(0.6, 0.2, 16, 8);
  const MeshPairDistance pair(a, b);
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(-2.5, 2.5), ang(0, 6.28);
  std::vector<Transform> poses;
  for (int i = 0; i < 64; ++i)
    poses.push_back(rotation(ang(rng), {u(rng), u(rng), 0.3 * u(rng)}));
  std::vector<PairDistance3> one(poses.size()), two(poses.size());
  pair.distance(poses, one, {.threads = 1});
  pair.distance(poses, two, {.threads = 2});
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_EQ(one[i].distance, two[i].distance);
    EXPECT_EQ(one[i].triangle_a, two[i].triangle_a);
    EXPECT_EQ(one[i].point_b, two[i].point_b);
  }
  EXPECT_EQ(mesh_mesh(a, b, {}, poses[3]).distance, one[3].distance);
}

// A's point location is lazy (inside::PlacedMeshPair::a_holds): a pair shared by many poses on
// four threads, which builds A's index part way, answers every pose as a fresh pair (rays only).
TEST(MeshPairDistance, LazyIndexOfAAnswersEveryPoseAsRaysAloneOnConcurrentBatches) {
  const Mesh a = scenes::torus(1.0, 0.4, 12, 8);
  Mesh b = scenes::torus(1.0, 0.4, 8, 6);
  for (Vec3& v : b.vertices)
    v = 0.125 * v;
  std::vector<Transform> poses = scenes::random_poses(3000, 1.5, 28);
  for (std::size_t i = 0; i < poses.size(); i += 2)
    poses[i].t.z = 0.0;
  const MeshPairDistance shared(a, b);
  std::vector<PairDistance3> batch(poses.size());
  shared.distance(poses, batch, {.threads = 4});
  int nested = 0;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const PairDistance3 fresh = MeshPairDistance(a, b).distance(poses[i]);
    ASSERT_EQ(batch[i].distance, fresh.distance) << i;
    ASSERT_EQ(batch[i].contact, fresh.contact) << i;
    ASSERT_EQ(batch[i].triangle_a, fresh.triangle_a) << i;
    ASSERT_EQ(batch[i].triangle_b, fresh.triangle_b) << i;
    ASSERT_TRUE(batch[i].point_a == fresh.point_a && batch[i].point_b == fresh.point_b) << i;
    nested += fresh.contact == inside::PairWitness::vertex_of_b_in_a;
  }
  EXPECT_GT(nested, 100);
}

}  // namespace
}  // namespace contain::distance
