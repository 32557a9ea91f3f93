// MeshDistance against the brute-force GMP oracle: distance rounded once, closest point rounded
// per coordinate, closest triangle with ties to the lowest index, exact sign, exact `within`.

#include "contain/distance/mesh_distance.h"
#include "contain/bound/aabb.h"

#include <gtest/gtest.h>
#include <span>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "distance/mesh_oracle.h"
#include "scenes/scenes.h"
#include "support/case_budget.h"

namespace contain::distance {
namespace {

using test::compare_with_oracle;
using test::mesh_oracle;

Mesh scaled(const Mesh& m, double s) {
  Mesh out = m;
  for (Vec3& v : out.vertices)
    v = s * v;
  return out;
}

// A closed cube of side 2 on an integer lattice, each face split into 4 triangles around its
// centre: on-edge, on-face and on-vertex points are exact, and many distances tie.
Mesh lattice_cube() {
  Mesh m;
  const double c = 2.0;
  auto add = [&](Vec3 v) {
    m.vertices.push_back(v);
    return static_cast<std::int32_t>(m.vertices.size() - 1);
  };
  // corners
  std::int32_t k[2][2][2];
  for (int x = 0; x < 2; ++x)
    for (int y = 0; y < 2; ++y)
      for (int z = 0; z < 2; ++z)
        k[x][y][z] = add({x * c, y * c, z * c});
  auto face = [&](std::int32_t a, std::int32_t b, std::int32_t cc, std::int32_t d) {
    // a b c d counter-clockwise seen from outside; centre e
    const Vec3 e =
        0.25 * (m.vertices[static_cast<std::size_t>(a)] + m.vertices[static_cast<std::size_t>(b)] +
                m.vertices[static_cast<std::size_t>(cc)] + m.vertices[static_cast<std::size_t>(d)]);
    const std::int32_t ie = add(e);
    m.triangles.push_back({a, b, ie});
    m.triangles.push_back({b, cc, ie});
    m.triangles.push_back({cc, d, ie});
    m.triangles.push_back({d, a, ie});
  };
  face(k[0][0][0], k[0][1][0], k[1][1][0], k[1][0][0]);  // z = 0, normal -z
  face(k[0][0][1], k[1][0][1], k[1][1][1], k[0][1][1]);  // z = c
  face(k[0][0][0], k[1][0][0], k[1][0][1], k[0][0][1]);  // y = 0
  face(k[0][1][0], k[0][1][1], k[1][1][1], k[1][1][0]);  // y = c
  face(k[0][0][0], k[0][0][1], k[0][1][1], k[0][1][0]);  // x = 0
  face(k[1][0][0], k[1][1][0], k[1][1][1], k[1][0][1]);  // x = c
  return m;
}

// A soup with the cases peers trip over: degenerate triangles (collinear corners, repeated
// vertices, zero-length edges), a face duplicated with the opposite orientation (libigl 644).
Mesh degenerate_soup(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Mesh m;
  auto v = [&] {
    m.vertices.push_back({u(rng), u(rng), u(rng)});
    return static_cast<std::int32_t>(m.vertices.size() - 1);
  };
  for (int i = 0; i < 20; ++i)
    m.triangles.push_back({v(), v(), v()});
  const std::int32_t a = v(), b = v();
  const Vec3 mid =
      0.5 * (m.vertices[static_cast<std::size_t>(a)] + m.vertices[static_cast<std::size_t>(b)]);
  m.vertices.push_back(mid);
  const auto c = static_cast<std::int32_t>(m.vertices.size() - 1);
  m.triangles.push_back({a, b, c});  // (nearly) collinear
  m.triangles.push_back({a, a, b});  // repeated vertex
  m.triangles.push_back({c, c, c});  // a point
  m.triangles.push_back(
      {m.triangles[3][0], m.triangles[3][2], m.triangles[3][1]});  // duplicate, flipped
  return m;
}

Mesh open_torus() {
  Mesh m = scenes::torus(2.0, 0.7, 16, 10);
  std::vector<TriangleIndices> kept;
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    if (i % 7 != 3) kept.push_back(m.triangles[i]);
  m.triangles = kept;
  return m;
}

std::vector<Vec3> probe_points(const Mesh& mesh, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Box3 box = bound::aabb(std::span<const Vec3>(mesh.vertices));
  const Vec3 ext = box.max - box.min;
  std::uniform_real_distribution<double> u(-0.3, 1.3);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Vec3> out;
  for (int i = 0; i < count; ++i) {
    switch (i % 5) {
      case 0:
      case 1:  // uniform around the box
        out.push_back(
            {box.min.x + u(rng) * ext.x, box.min.y + u(rng) * ext.y, box.min.z + u(rng) * ext.z});
        break;
      case 2:  // a vertex, exactly
        out.push_back(mesh.vertices[rng() % mesh.vertices.size()]);
        break;
      default: {  // on a triangle (rounded), then 1e-9 off in a random direction, or not
        const TriangleIndices& t = mesh.triangles[rng() % mesh.triangles.size()];
        double s = unit(rng), r = unit(rng);
        if (s + r > 1) {
          s = 1 - s;
          r = 1 - r;
        }
        const Vec3 a = mesh.vertices[static_cast<std::size_t>(t[0])];
        const Vec3 b = mesh.vertices[static_cast<std::size_t>(t[1])];
        const Vec3 c = mesh.vertices[static_cast<std::size_t>(t[2])];
        Vec3 p = a + s * (b - a) + r * (c - a);
        if (i % 5 == 3) p = p + 1e-9 * Vec3{unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5};
        out.push_back(p);
      }
    }
  }
  return out;
}

int check_mesh(const Mesh& mesh, const std::vector<Vec3>& points, bool check_within) {
  const MeshDistance prepared(mesh);
  int failures = 0;
  for (const Vec3& p : points) {
    const Closest3 got = prepared.distance(p, {.signed_distance = true});
    const auto want = mesh_oracle(mesh, p);
    const std::string diff = compare_with_oracle(got, want, true);
    if (!diff.empty()) {
      ADD_FAILURE() << diff << "at " << test::hex3(p);
      if (++failures >= 10) return failures;
      continue;
    }
    // The sign is the exact location; 0 exactly on the surface.
    const Location where = prepared.index().locate(p);
    EXPECT_EQ(got.location, where);
    if (where == Location::inside) {
      EXPECT_TRUE(got.distance < 0 || got.distance == 0.0);
    }
    if (where == Location::outside) {
      EXPECT_GE(got.distance, 0.0);
    }
    EXPECT_EQ(where == Location::boundary, want.squared_distance == 0) << test::hex3(p);
    if (where == Location::boundary) {
      EXPECT_TRUE(got.distance == 0.0 && !std::signbit(got.distance));
    }
    if (check_within) {
      const double d = std::fabs(got.distance);
      for (double dd : {d, std::nextafter(d, 0.0), std::nextafter(d, DBL_MAX)}) {
        const mpq_class q(dd);
        EXPECT_EQ(prepared.within(p, dd), want.squared_distance <= q * q)
            << "within " << dd << " at " << test::hex3(p);
      }
    }
  }
  return failures;
}

TEST(MeshDistance, ClosedTorusMatchesTheExactOracle) {
  const Mesh torus = scenes::torus(2.0, 0.7, 16, 10);
  EXPECT_EQ(check_mesh(torus, probe_points(torus, test::case_budget(500, 5), 1), true), 0);
}

TEST(MeshDistance, LatticeCubeWithExactTiesKeepsTheLowestTriangle) {
  const Mesh cube = lattice_cube();
  std::vector<Vec3> points;
  // every lattice point of a 7^3 grid around the cube (step 1/2): vertices, edge and face points,
  // centre, and points equidistant from several faces
  for (int x = -1; x <= 5; ++x)
    for (int y = -1; y <= 5; ++y)
      for (int z = -1; z <= 5; ++z)
        points.push_back({0.5 * x, 0.5 * y, 0.5 * z});
  EXPECT_EQ(check_mesh(cube, points, true), 0);
}

TEST(MeshDistance, OpenMeshDistancesAreExactAndSignsComeFromTheWindingNumber) {
  const Mesh torus = open_torus();
  const MeshDistance prepared(torus);
  EXPECT_EQ(prepared.regime(), inside::MeshRegime::winding_number);
  EXPECT_EQ(check_mesh(torus, probe_points(torus, test::case_budget(300, 5), 2), false), 0);
}

TEST(MeshDistance, DegenerateTrianglesAndFlippedDuplicatesAreHandledExactly) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const Mesh soup = degenerate_soup(seed);
    EXPECT_EQ(check_mesh(soup, probe_points(soup, test::case_budget(400, 5), seed), true), 0);
  }
}

TEST(MeshDistance, HugeAndTinyCoordinatesStayExact) {
  const Mesh cube = lattice_cube();
  for (const int k : {-1000, -600, -300, 300, 600, 900}) {
    const double s = std::ldexp(1.0, k);
    const Mesh m = scaled(cube, s);
    std::vector<Vec3> points;
    for (const Vec3& p :
         probe_points(cube, test::case_budget(60, 5), static_cast<std::uint64_t>(k + 2000)))
      points.push_back(s * p);
    EXPECT_EQ(check_mesh(m, points, true), 0) << "scale 2^" << k;
  }
}

// The batch answers (each query starting from its Morton predecessor's closest triangle, which
// bounds the search early and sets the direction of the cheap half-space test) against the
// oracle, and against the unhinted single queries field by field.
int check_batch(const Mesh& mesh, const std::vector<Vec3>& points) {
  const MeshDistance prepared(mesh);
  std::vector<Closest3> batch(points.size());
  prepared.distance(points, batch, {.signed_distance = true}, {.threads = 1});
  int failures = 0;
  for (std::size_t i = 0; i < points.size() && failures < 10; ++i) {
    const Closest3 single = prepared.distance(points[i], {.signed_distance = true});
    const std::string diff = compare_with_oracle(batch[i], mesh_oracle(mesh, points[i]), true);
    const bool same = batch[i].distance == single.distance &&
                      std::signbit(batch[i].distance) == std::signbit(single.distance) &&
                      batch[i].point == single.point && batch[i].feature == single.feature &&
                      batch[i].location == single.location;
    if (!diff.empty() || !same) {
      ADD_FAILURE() << diff << (same ? "" : "batch differs from single ") << "at "
                    << test::hex3(points[i]);
      ++failures;
    }
  }
  return failures;
}

// An accordion: a strip folded back and forth with sharp concave folds, where the half-space
// test's direction (from the neighbour's closest triangle) is far from the right one.
Mesh accordion() {
  Mesh m;
  for (int i = 0; i <= 12; ++i) {
    const double x = 0.25 * i;
    const double z = (i % 2 == 0) ? 0.0 : 1.5;
    m.vertices.push_back({x, 0.0, z});
    m.vertices.push_back({x, 2.0, z});
  }
  for (std::int32_t i = 0; i < 12; ++i) {
    m.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 1});
    m.triangles.push_back({2 * i + 1, 2 * i + 2, 2 * i + 3});
  }
  return m;
}

TEST(MeshDistance, HintedBatchesMatchTheOracleOnTiesFoldsDegeneratesAndScales) {
  // Exact ties on the lattice cube: the hint must not change the lowest-index winner.
  std::vector<Vec3> grid;
  for (int x = -2; x <= 6; ++x)
    for (int y = -2; y <= 6; ++y)
      for (int z = -2; z <= 6; ++z)
        grid.push_back({0.5 * x, 0.5 * y, 0.5 * z});
  EXPECT_EQ(check_batch(lattice_cube(), grid), 0);
  // Inside the folds of an accordion and around it, vertices and points 1e-9 off included.
  const Mesh folds = accordion();
  EXPECT_EQ(check_batch(folds, probe_points(folds, test::case_budget(800, 5), 21)), 0);
  // Degenerate triangles and flipped duplicates.
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const Mesh soup = degenerate_soup(seed);
    EXPECT_EQ(check_batch(soup, probe_points(soup, test::case_budget(300, 5), seed + 40)), 0);
  }
  // Far from the origin (the test's rounding margin grows with the coordinates) and scaled.
  const Mesh torus = scenes::torus(2.0, 0.7, 24, 12);
  for (const double s : {0x1p-300, 1.0, 0x1p300}) {
    Mesh m = scaled(torus, s);
    for (Vec3& v : m.vertices)
      v = v + Vec3{s * 1e6, -s * 3e5, s * 7.0};
    std::vector<Vec3> points;
    for (const Vec3& p : probe_points(m, test::case_budget(250, 5), 33))
      points.push_back(p);
    EXPECT_EQ(check_batch(m, points), 0) << "scale " << s;
  }
  // The same points in a shuffled order: the batch sorts them, the answers stay.
  std::vector<Vec3> shuffled = probe_points(torus, test::case_budget(400, 5), 34);
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937_64(35));
  EXPECT_EQ(check_batch(torus, shuffled), 0);
}

// The counts of a batch's work come back from the call that did it (no hidden per-thread state):
// one query per point whatever the thread count, every contender from a bounded triangle, and the
// same answers as the plain batch.
TEST(MeshDistance, DistanceWithStatsCountsTheWorkOfItsOwnBatchOnAnyThreadCount) {
  const Mesh torus = scenes::torus(2.0, 0.7, 32, 16);
  const MeshDistance prepared(torus);
  const std::vector<Vec3> points = probe_points(torus, test::case_budget(4000, 5), 10);
  std::vector<Closest3> plain(points.size()), one(points.size()), two(points.size());
  prepared.distance(points, plain, {.signed_distance = true}, {.threads = 1});
  const MeshDistanceStats a =
      prepared.distance_with_stats(points, one, {.signed_distance = true}, {.threads = 1});
  const MeshDistanceStats b =
      prepared.distance_with_stats(points, two, {.signed_distance = true}, {.threads = 2});
  EXPECT_EQ(a.queries, points.size());
  EXPECT_EQ(b.queries, points.size());
  EXPECT_GE(a.nodes, points.size());
  EXPECT_LE(a.contenders, a.triangles);
  EXPECT_GE(a.contenders, points.size());  // at least the winner of each query
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_EQ(one[i].distance, plain[i].distance);
    ASSERT_EQ(two[i].distance, plain[i].distance);
    ASSERT_EQ(two[i].feature, plain[i].feature);
  }
  const MeshDistanceStats none = prepared.distance_with_stats({}, {});
  EXPECT_EQ(none.queries, 0u);
  EXPECT_EQ(none.nodes, 0u);
}

TEST(MeshDistance, BatchAnswersEqualSingleAnswersOnAnyThreadCount) {
  const Mesh torus = scenes::torus(2.0, 0.7, 32, 16);
  const MeshDistance prepared(torus);
  const std::vector<Vec3> points = probe_points(torus, test::case_budget(20000, 5), 9);
  std::vector<Closest3> one(points.size()), two(points.size());
  prepared.distance(points, one, {.signed_distance = true}, {.threads = 1});
  prepared.distance(points, two, {.signed_distance = true}, {.threads = 2});
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Closest3 single = prepared.distance(points[i], {.signed_distance = true});
    ASSERT_EQ(one[i].distance, single.distance);
    ASSERT_EQ(two[i].distance, single.distance);
    ASSERT_EQ(two[i].feature, single.feature);
    ASSERT_EQ(two[i].point, single.point);
  }
  std::vector<std::uint8_t> w1(points.size()), w2(points.size());
  prepared.within(points, 0.25, w1, {.threads = 1});
  prepared.within(points, 0.25, w2, {.threads = 2});
  EXPECT_EQ(w1, w2);
}

TEST(MeshDistance, EmptyMeshIsInfinitelyFarAndNonFinitePointsGetNaN) {
  const MeshDistance empty;
  EXPECT_EQ(empty.distance({0, 0, 0}).distance, std::numeric_limits<double>::infinity());
  EXPECT_FALSE(empty.within({0, 0, 0}, 1e300));
  const MeshDistance cube(lattice_cube());
  EXPECT_TRUE(std::isnan(cube.distance({std::nan(""), 0, 0}).distance));
  EXPECT_TRUE(std::isnan(cube.distance({0, std::numeric_limits<double>::infinity(), 0}).distance));
  EXPECT_FALSE(cube.within({std::nan(""), 0, 0}, 1.0));
  EXPECT_FALSE(cube.within({0, 0, 0}, -1.0));
  EXPECT_FALSE(cube.within({0, 0, 0}, std::nan("")));
}

TEST(MeshDistance, OneShotEqualsPrepared) {
  const Mesh torus = scenes::torus(2.0, 0.7, 16, 10);
  const MeshDistance prepared(torus);
  for (const Vec3& p : probe_points(torus, test::case_budget(50, 5), 5)) {
    const Closest3 a = point_mesh(torus, p, {.signed_distance = true});
    const Closest3 b = prepared.distance(p, {.signed_distance = true});
    EXPECT_EQ(a.distance, b.distance);
    EXPECT_EQ(a.feature, b.feature);
    EXPECT_EQ(a.point, b.point);
  }
}

}  // namespace
}  // namespace contain::distance
