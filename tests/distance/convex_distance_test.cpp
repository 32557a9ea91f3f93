// ConvexDistance (points) and convex_convex (pairs, GJK-guided) against the GMP oracles: the
// point answers are the exact closest face rounded once with the exact sign; the pair answers
// are the exact closest face pair (ties to the lowest) or 0 for touching and nested solids,
// whatever GJK did.

#include "contain/distance/convex_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "contain/inside/point_in_convex.h"
#include "distance/mesh_oracle.h"
#include "scenes/scenes.h"
#include "support/case_budget.h"
#include "support/exact_distance.h"

namespace contain::distance {
namespace {

// A prism over a regular n-gon (radius r, height h), outward faces: convex, with coplanar
// triangle pairs on its sides (ties between faces).
Mesh prism(int n, double r, double h) {
  Mesh m;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    m.vertices.push_back({r * std::cos(a), r * std::sin(a), 0});
  }
  for (int i = 0; i < n; ++i)
    m.vertices.push_back(
        {m.vertices[static_cast<std::size_t>(i)].x, m.vertices[static_cast<std::size_t>(i)].y, h});
  for (int i = 1; i + 1 < n; ++i) {
    m.triangles.push_back({0, i + 1, i});          // bottom, seen from below
    m.triangles.push_back({n, n + i, n + i + 1});  // top
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    m.triangles.push_back({i, j, n + j});
    m.triangles.push_back({i, n + j, n + i});
  }
  return m;
}

// A bipyramid over a regular n-gon: apexes at z = +-h.
Mesh bipyramid(int n, double r, double h) {
  Mesh m;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * (i + 0.25) / n;
    m.vertices.push_back({r * std::cos(a), r * std::sin(a), 0});
  }
  m.vertices.push_back({0, 0, h});
  m.vertices.push_back({0, 0, -h});
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    m.triangles.push_back({i, j, n});
    m.triangles.push_back({j, i, n + 1});
  }
  return m;
}

ConvexDistance prepared(const Mesh& m) {
  auto polyhedron = ConvexPolyhedron::from_mesh(m);
  EXPECT_TRUE(polyhedron.ok()) << (polyhedron ? "" : polyhedron.error().message);
  auto c = ConvexDistance::prepare(*polyhedron);
  EXPECT_TRUE(c.ok());
  return std::move(*c);
}

TEST(ConvexDistance, PointsMatchTheExactOracleWithTheExactSign) {
  const Mesh m = bipyramid(7, 1.0, 1.3);
  const ConvexDistance c = prepared(m);
  const ConvexPolyhedron& solid = c.polyhedron();
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(-2, 2);
  std::vector<Vec3> points;
  for (int i = 0; i < test::case_budget(600, 5); ++i)
    points.push_back({u(rng), u(rng), u(rng)});
  for (const Vec3& v : m.vertices)  // on vertices, on edge midpoints, on face centroids
    points.push_back(v);
  for (const TriangleIndices& t : m.triangles) {
    const Vec3 a = m.vertices[static_cast<std::size_t>(t[0])];
    const Vec3 b = m.vertices[static_cast<std::size_t>(t[1])];
    const Vec3 cc = m.vertices[static_cast<std::size_t>(t[2])];
    points.push_back(0.5 * (a + b));
    points.push_back((1.0 / 3.0) * ((a + b) + cc));
    points.push_back(points.back() + Vec3{1e-9, -1e-9, 1e-9});
  }
  std::vector<Closest3> batch(points.size());
  c.distance(points, batch, {.signed_distance = true}, {.threads = 2});
  int failures = 0;
  for (std::size_t i = 0; i < points.size() && failures < 10; ++i) {
    const Vec3 p = points[i];
    const Closest3 got = c.distance(p, {.signed_distance = true});
    const std::string diff = test::compare_with_oracle(got, test::mesh_oracle(m, p), true);
    const Location where = inside::point_in_convex(solid, p);
    const bool sign_ok = where == Location::inside     ? got.distance < 0
                         : where == Location::boundary ? got.distance == 0
                                                       : got.distance > 0;
    if (!diff.empty() || !sign_ok || got.location != where ||
        !(batch[i].distance == got.distance) || batch[i].feature != got.feature) {
      ADD_FAILURE() << "point " << i << " " << test::hex3(p) << ": " << diff;
      ++failures;
    }
  }
  EXPECT_EQ(failures, 0);
}

TEST(ConvexDistance, WithinIsExactAtTheDistanceItself) {
  const ConvexDistance c = prepared(scenes::box_mesh({{0, 0, 0}, {1, 1, 1}}));
  EXPECT_TRUE(c.within({1.5, 0.5, 0.5}, 0.5));
  EXPECT_FALSE(c.within({1.5, 0.5, 0.5}, std::nextafter(0.5, 0.0)));
  EXPECT_TRUE(c.within({0.5, 0.5, 0.5}, 0.5));  // the centre is 0.5 from every face
  EXPECT_EQ(c.distance({0.5, 0.5, 0.25}, {.signed_distance = true}).distance, -0.25);
}

TEST(ConvexDistance, APolyhedronOfPlanesOnlyIsRefusedWithAClearError) {
  auto planes = ConvexPolyhedron::from_planes({Plane{1, 0, 0, 0}, Plane{-1, 0, 0, 1}});
  ASSERT_TRUE(planes.ok());
  const auto c = ConvexDistance::prepare(*planes);
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.error().kind, ErrorKind::unsupported);
  EXPECT_FALSE(point_convex(*planes, {0, 0, 0}).ok());
  const auto box = ConvexPolyhedron::from_mesh(scenes::box_mesh({{0, 0, 0}, {2, 2, 2}}));
  ASSERT_TRUE(box.ok());
  EXPECT_EQ(point_convex(*box, {5, 1, 1})->distance, 3.0);
}

// The pair against the brute-force GMP oracle over every face pair (and exact nesting), and
// against MeshPairDistance on the same meshes.
void check_pair(const Mesh& ma, const Mesh& mb, const ConvexDistance& a, const ConvexDistance& b,
                const MeshPairDistance& meshes, const Transform& tb, int& failures) {
  const PairDistance3 got = convex_convex(a, b, tb);
  const PairDistance3 reference = meshes.distance(tb);
  const Mesh wb = placed(mb, tb);
  const test::PairOracle want = test::pair_oracle(ma, wb);
  const ConvexPolyhedron pa = *ConvexPolyhedron::from_mesh(ma);
  const auto pb = ConvexPolyhedron::from_mesh(wb);
  bool nested = false;
  if (want.d2 > 0 && pb) {
    nested = inside::point_in_convex(pa, wb.vertices[0]) == Location::inside ||
             inside::point_in_convex(*pb, ma.vertices[0]) == Location::inside;
  }
  const double d = nested ? 0.0 : test::nearest_double_sqrt(want.d2);
  bool ok = got.distance == d && reference.distance == d;
  const bool vertex_witness = got.contact == inside::PairWitness::vertex_of_a_in_b ||
                              got.contact == inside::PairWitness::vertex_of_b_in_a;
  if (vertex_witness) {
    ok = ok && (nested || want.d2 == 0);
  } else {
    ok = ok && !nested && got.triangle_a == want.a && got.triangle_b == want.b;
    ok = ok && (want.d2 == 0) == (got.contact == inside::PairWitness::triangles);
    // MeshPairDistance may witness an overlap by another vertex (its meshes keep the input's
    // vertex order); where both report the surfaces, the closest points agree bit for bit.
    if (reference.contact == got.contact)
      ok = ok && got.point_a == reference.point_a && got.point_b == reference.point_b;
  }
  if (!ok) {
    char buf[240];
    std::snprintf(buf, sizeof buf, "got %a (%d, %d, %s) mesh pair %a want %a (%d, %d, nested %d)",
                  got.distance, got.triangle_a, got.triangle_b, to_string(got.contact),
                  reference.distance, d, want.a, want.b, nested ? 1 : 0);
    ADD_FAILURE() << buf;
    ++failures;
  }
  for (const double dd : {d, std::nextafter(d, 0.0), std::nextafter(d, 1e300)}) {
    const mpq_class q(dd);
    const bool want_within = nested || want.d2 <= q * q;
    if (convex_convex_within(a, b, tb, dd) != want_within) {
      ADD_FAILURE() << "within " << dd;
      ++failures;
    }
  }
}

TEST(ConvexConvex, RandomPosesMatchTheExactOracleAndTheMeshPair) {
  const Mesh ma = prism(6, 1.0, 1.5);
  const Mesh mb = bipyramid(5, 0.7, 0.9);
  const ConvexDistance a = prepared(ma), b = prepared(mb);
  const MeshPairDistance meshes(ma, mb);
  int failures = 0;
  for (const Transform& pose : scenes::random_poses(test::case_budget(120, 5), 2.5, 43))
    if (failures < 5) check_pair(ma, mb, a, b, meshes, pose, failures);
  EXPECT_EQ(failures, 0);
}

TEST(ConvexConvex, TouchingNestedAndSeparatedBoxesOnALattice) {
  const Mesh big = scenes::box_mesh({{0, 0, 0}, {4, 4, 4}});
  const Mesh small = scenes::box_mesh({{0, 0, 0}, {1, 1, 1}});
  const ConvexDistance a = prepared(big), b = prepared(small);
  const MeshPairDistance meshes(big, small);
  int failures = 0;
  Transform t;
  for (const Vec3 shift :
       {Vec3{4, 0, 0}, Vec3{5, 0.5, 0.5}, Vec3{1.5, 1.5, 1.5}, Vec3{4, 4, 4}, Vec3{-1, -1, -1},
        Vec3{-2, 1, 3}, Vec3{3.5, 3.5, 3.5}, Vec3{6, 7, 8}, Vec3{4, 2, 2}, Vec3{-1, 4, 1.5}}) {
    t.t = shift;
    check_pair(big, small, a, b, meshes, t, failures);
  }
  EXPECT_EQ(failures, 0);
  t.t = {1.5, 1.5, 1.5};
  EXPECT_EQ(convex_convex(a, b, t).contact, inside::PairWitness::vertex_of_b_in_a);
  t.t = {-1.5, -1.5, -1.5};
  EXPECT_EQ(convex_convex(b, a, t).contact, inside::PairWitness::vertex_of_a_in_b);
  t.t = {4, 4, 4};  // corner to corner
  EXPECT_EQ(convex_convex(a, b, t).contact, inside::PairWitness::triangles);
  t.t = {6, 0, 0};
  EXPECT_EQ(convex_convex(a, b, t).distance, 2.0);
  EXPECT_TRUE(convex_convex_within(a, b, t, 2.0));
  EXPECT_FALSE(convex_convex_within(a, b, t, std::nextafter(2.0, 0.0)));
}

TEST(ConvexConvex, GjkLeavesFewFacePairsForSeparatedSolids) {
  // 64-gon prisms: 252 faces each, 63504 face pairs; GJK's direction keeps a handful.
  const Mesh m = prism(64, 1.0, 1.0);
  const ConvexDistance a = prepared(m);
  Transform t;
  t.t = {2.5, 0.3, 0.2};
  const PairDistance3 d = convex_convex(a, a, t);
  EXPECT_EQ(d.contact, inside::PairWitness::none);
  EXPECT_GT(d.distance, 0.4);
  EXPECT_LT(d.node_pairs, 200u);
  const PairDistance3 reference = MeshPairDistance(m, m).distance(t);
  EXPECT_EQ(d.distance, reference.distance);
  EXPECT_EQ(d.triangle_a, reference.triangle_a);
  EXPECT_EQ(d.triangle_b, reference.triangle_b);
}

}  // namespace
}  // namespace contain::distance
