#include "contain/shapes/convex_polyhedron.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "scenes/scenes.h"
#include "support/exact.h"

namespace contain::test {
namespace {

// The cube [0, size]^3, two coplanar triangles a side, each side's diagonal from its lowest
// corner.
Mesh cube_mesh(double size = 1) {
  return scenes::box_mesh({{0, 0, 0}, {size, size, size}});
}

Mesh tetrahedron_mesh() {
  return *Mesh::from_arrays({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}},
                            {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
}

// A pyramid over the strictly convex polygon (i, i^2, 0), i = -k..k (points on a parabola), with
// its apex above: the apex has 2k + 1 faces, the base is a fan of 2k - 1 coplanar triangles from
// (-k, k^2, 0), which has 2k + 1 faces. Integer coordinates.
Mesh pyramid_mesh(int k) {
  std::vector<Vec3> v;
  for (int i = -k; i <= k; ++i)
    v.push_back({static_cast<double>(i), static_cast<double>(i * i), 0});
  const auto n = static_cast<std::int32_t>(v.size());
  v.push_back({0, static_cast<double>(k * k - 1), 5});  // above the polygon's inside
  std::vector<TriangleIndices> t;
  for (std::int32_t j = 1; j + 1 < n; ++j)
    t.push_back({0, j + 1, j});  // the base, seen from below
  for (std::int32_t j = 0; j < n; ++j)
    t.push_back({j, (j + 1) % n, n});  // the sides
  return *Mesh::from_arrays(std::move(v), std::move(t));
}

ConvexPolyhedron polyhedron(const Mesh& mesh) {
  auto p = ConvexPolyhedron::from_mesh(mesh);
  EXPECT_TRUE(p.ok()) << p.error().what();
  return *p;
}

// The faces having corner v, by a scan of every face.
std::vector<std::int32_t> scanned_faces_around(const ConvexPolyhedron& p, std::int32_t v) {
  std::vector<std::int32_t> out;
  for (std::size_t f = 0; f < p.face_indices().size(); ++f) {
    const TriangleIndices& t = p.face_indices()[f];
    if (t[0] == v || t[1] == v || t[2] == v) out.push_back(static_cast<std::int32_t>(f));
  }
  return out;
}

void expect_faces_around_match_a_scan(const ConvexPolyhedron& p) {
  std::size_t total = 0;
  for (std::size_t v = 0; v < p.vertices().size(); ++v) {
    const auto around = p.faces_around(static_cast<std::int32_t>(v));
    const std::vector<std::int32_t> got(around.begin(), around.end());
    EXPECT_EQ(got, scanned_faces_around(p, static_cast<std::int32_t>(v))) << "vertex " << v;
    total += got.size();
  }
  EXPECT_EQ(total, 3 * p.face_indices().size());
}

mpq_class exact_dot(Vec3 d, Vec3 v) {
  const QVec3 qd = exact(d), qv = exact(v);
  return qd.x * qv.x + qd.y * qv.y + qd.z * qv.z;
}

// The exact argmax of dot(d, vertex) over all vertices (GMP), ties to the lowest index.
std::int32_t exact_argmax(const ConvexPolyhedron& p, Vec3 d) {
  std::int32_t best = -1;
  mpq_class best_dot;
  for (std::size_t k = 0; k < p.vertices().size(); ++k) {
    const mpq_class dot = exact_dot(d, p.vertices()[k]);
    if (best < 0 || dot > best_dot) {
      best = static_cast<std::int32_t>(k);
      best_dot = dot;
    }
  }
  return best;
}

TEST(ConvexPolyhedron, VerticesAreTheDistinctCornersInLexicographicOrder) {
  Mesh cube = cube_mesh(2);
  cube.vertices.push_back({-1, -1, -1});  // unused: not a corner of the solid
  const ConvexPolyhedron p = polyhedron(cube);
  ASSERT_EQ(p.vertices().size(), 8u);
  for (std::size_t k = 1; k < p.vertices().size(); ++k) {
    const Vec3 a = p.vertices()[k - 1], b = p.vertices()[k];
    EXPECT_TRUE(a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)))) << k;
  }
  ASSERT_EQ(p.face_indices().size(), p.faces().size());
  for (std::size_t f = 0; f < p.faces().size(); ++f) {
    const Triangle3 got = p.face(static_cast<std::int32_t>(f));
    EXPECT_TRUE(got.a == p.faces()[f].a && got.b == p.faces()[f].b && got.c == p.faces()[f].c) << f;
  }
}

TEST(ConvexPolyhedron, EachTetrahedronVertexHasExactlyItsThreeFaces) {
  const ConvexPolyhedron p = polyhedron(tetrahedron_mesh());
  ASSERT_EQ(p.vertices().size(), 4u);
  for (std::int32_t v = 0; v < 4; ++v)
    EXPECT_EQ(p.faces_around(v).size(), 3u) << v;
  expect_faces_around_match_a_scan(p);
}

TEST(ConvexPolyhedron, FacesAroundListCoplanarTrianglesOfOneSideEach) {
  const ConvexPolyhedron p = polyhedron(cube_mesh());
  expect_faces_around_match_a_scan(p);
  // Corner (0, 0, 0) (vertex 0 in lexicographic order) is on 3 sides; the split diagonals of
  // cube_mesh all start at it, so each side gives it both of its coplanar triangles.
  EXPECT_EQ(p.faces_around(0).size(), 6u);
}

TEST(ConvexPolyhedron, AVertexWithManyFacesListsThemAllAscending) {
  const int k = 10;
  const ConvexPolyhedron p = polyhedron(pyramid_mesh(k));
  expect_faces_around_match_a_scan(p);
  // The apex is the only vertex with z > 0; the fan's origin (-k, k^2, 0) is vertex 0.
  std::int32_t apex = -1;
  for (std::size_t v = 0; v < p.vertices().size(); ++v)
    if (p.vertices()[v].z > 0) apex = static_cast<std::int32_t>(v);
  ASSERT_GE(apex, 0);
  EXPECT_EQ(p.faces_around(apex).size(), static_cast<std::size_t>(2 * k + 1));
  EXPECT_EQ(p.faces_around(0).size(), static_cast<std::size_t>(2 * k - 1 + 2));
  const auto around = p.faces_around(apex);
  EXPECT_TRUE(std::is_sorted(around.begin(), around.end()));
}

TEST(ConvexPolyhedron, SupportIsTheExactArgmaxOfABruteForceScanWithTiesToTheLowestIndex) {
  // Small integers: every dot product is exact in doubles, so the floating-point argmax must be
  // the exact one, and the many ties (axis directions, faces parallel to d) go to the lowest index.
  const ConvexPolyhedron shapes[] = {polyhedron(tetrahedron_mesh()), polyhedron(cube_mesh(3)),
                                     polyhedron(pyramid_mesh(6)),
                                     ConvexPolyhedron::from_box({{-2, 1, 0}, {5, 1, 7}})};
  std::mt19937_64 rng(23);
  std::uniform_int_distribution<int> coordinate(-3, 3);
  for (const ConvexPolyhedron& p : shapes) {
    for (int i = 0; i < 2000; ++i) {
      const Vec3 d{static_cast<double>(coordinate(rng)), static_cast<double>(coordinate(rng)),
                   static_cast<double>(coordinate(rng))};
      const std::int32_t want = exact_argmax(p, d);
      ASSERT_EQ(p.support_index(d), want) << d.x << " " << d.y << " " << d.z;
      const Vec3 s = p.support(d);
      EXPECT_TRUE(s == p.vertices()[static_cast<std::size_t>(want)]);
    }
  }
}

TEST(ConvexPolyhedron, SupportOnRandomDirectionsIsAVertexNoOtherBeatsByMoreThanRounding) {
  const ConvexPolyhedron p = polyhedron(pyramid_mesh(8));
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 d{normal(rng), normal(rng), normal(rng)};
    const std::int32_t got = p.support_index(d);
    const std::int32_t want = exact_argmax(p, d);
    // The same vertex, or another only at a near tie: its exact dot product short of the
    // maximum by at most the rounding of two computed ones (coordinates here are below 100).
    const double scale = std::fabs(d.x) * 100 + std::fabs(d.y) * 100 + std::fabs(d.z) * 100;
    EXPECT_LE(exact_dot(d, p.vertices()[static_cast<std::size_t>(want)]) -
                  exact_dot(d, p.vertices()[static_cast<std::size_t>(got)]),
              mpq_class(8 * 0x1p-53 * scale))
        << i;
  }
}

TEST(ConvexPolyhedron, PlanesOnlyPolyhedronHasNoVerticesAndNoSupport) {
  const auto p = ConvexPolyhedron::from_planes({{1, 0, 0, 0}, {-1, 0, 0, 1}});
  ASSERT_TRUE(p.ok());
  EXPECT_TRUE(p->vertices().empty());
  EXPECT_TRUE(p->face_indices().empty());
  EXPECT_EQ(p->support_index({1, 0, 0}), -1);
  EXPECT_TRUE(std::isnan(p->support({1, 0, 0}).x));
}

TEST(ConvexPolyhedron, FromBoxKeepsCornersInBitOrderAndItsSixPlanes) {
  const Box3 box{{-1, 0, 2}, {3, 0, 5}};  // flat in y: its y sides are degenerate triangles
  const ConvexPolyhedron p = ConvexPolyhedron::from_box(box);
  ASSERT_EQ(p.vertices().size(), 8u);
  for (int i = 0; i < 8; ++i) {
    const Vec3 want{(i & 1) != 0 ? 3.0 : -1.0, 0.0, (i & 4) != 0 ? 5.0 : 2.0};
    EXPECT_TRUE(p.vertices()[static_cast<std::size_t>(i)] == want) << i;
  }
  EXPECT_EQ(p.planes().size(), 6u);
  EXPECT_TRUE(p.faces().empty());
  EXPECT_EQ(p.face_indices().size(), 12u);
  expect_faces_around_match_a_scan(p);
}

}  // namespace
}  // namespace contain::test
