// The per-vertex proofs that let the pair stage skip neighbour pairs (star_proof.h) are sound:
// around every proven vertex, no pair of triangles gets anything from the pair stage's own test
// (no constraint, no coplanar partner, not even a crossing point made on the way) and no pair
// meets beyond the corners it shares (collide::self_intersections, an independent exact test).
// Degenerate stars (flat, folded, winding twice, saddles, duplicate or zero-area triangles, two
// cones at one apex, a vertex of two inputs, a fan too large) are not proven; the proofs hold on
// random closed meshes, smooth, noisy and snapped to a coarse grid; and the booleans of random
// and degenerate pairs are the same with and without the skip.

#include "clip/solid/star_proof.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numbers>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "clip/solid/engine.h"
#include "clip/solid/solid_oracle.h"
#include "contain/collide/self_intersections.h"
#include "contain/predicates/orient2d.h"
#include "contain/predicates/orient3d.h"
#include "support/case_budget.h"

namespace contain::test {
namespace {

using clip::solid::Constraint;
using clip::solid::pair_gives_work;
using clip::solid::PointStore;
using clip::solid::proven_vertices;
using clip::solid::Soup;

Soup soup_of(const std::vector<Mesh>& inputs) {
  Result<Soup> soup = clip::solid::make_soup(inputs);
  EXPECT_TRUE(soup.ok());
  return soup.ok() ? std::move(*soup) : Soup{};
}

// The triangles around vertex v.
std::vector<std::int32_t> star_of(const Soup& soup, std::int32_t v) {
  std::vector<std::int32_t> star;
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const TriangleIndices& c = soup.triangles[t];
    if (c[0] == v || c[1] == v || c[2] == v) star.push_back(static_cast<std::int32_t>(t));
  }
  return star;
}

// Brute force around v: every pair of its triangles through the pair stage's own test (on a
// soup of the star alone: the test sees only the two triangles' positions and which corners
// they share) and the star through collide::self_intersections. True when nothing is found.
bool star_settled(const Soup& soup, std::int32_t v) {
  const std::vector<std::int32_t> star = star_of(soup, v);
  std::vector<TriangleIndices> triangles;
  for (const std::int32_t t : star)
    triangles.push_back(soup.triangles[static_cast<std::size_t>(t)]);
  const Soup small = raw_soup(soup.vertices, triangles);
  bool settled = true;
  for (std::int32_t t = 0; t < static_cast<std::int32_t>(triangles.size()); ++t) {
    for (std::int32_t u = t + 1; u < static_cast<std::int32_t>(triangles.size()); ++u)
      settled = settled && !pair_gives_work(small, t, u);
  }
  const Mesh mesh{soup.vertices, triangles};
  return settled && collide::self_intersections(mesh, {.limit = 1}).empty();
}

// Every proven vertex of the soup passes the brute force; returns how many are proven.
std::size_t check_proofs(const Soup& soup, const std::string& what) {
  const std::vector<bool> proven = proven_vertices(soup);
  EXPECT_EQ(proven.size(), soup.vertices.size());
  std::size_t count = 0;
  for (std::size_t v = 0; v < proven.size(); ++v) {
    if (!proven[v]) continue;
    ++count;
    EXPECT_TRUE(star_settled(soup, static_cast<std::int32_t>(v))) << what << ": vertex " << v;
  }
  return count;
}

// A cone: apex 0, ring 1 ... n (ring[i] joined to ring[i + 1]), triangles apex ring[i]
// ring[i + 1] as given.
struct Fan {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
};

Fan cone(Vec3 apex, const std::vector<Vec3>& ring) {
  Fan fan{{apex}, {}};
  const auto n = static_cast<std::int32_t>(ring.size());
  for (std::int32_t i = 0; i < n; ++i) {
    fan.vertices.push_back(ring[static_cast<std::size_t>(i)]);
    fan.triangles.push_back({0, 1 + i, 1 + (i + 1) % n});
  }
  return fan;
}

// n points on the circle of radius 1 at height z(i), the i-th at angle i * step.
std::vector<Vec3> circle_ring(int n, double step, const std::function<double(int)>& z) {
  std::vector<Vec3> ring;
  for (int i = 0; i < n; ++i) {
    ring.push_back({std::cos(i * step), std::sin(i * step), z(i)});
  }
  return ring;
}

bool apex_proven(const Fan& fan) {
  const Soup soup = raw_soup(fan.vertices, fan.triangles);
  check_proofs(soup, "fan");
  return proven_vertices(soup)[0];
}

constexpr double full_turn = 2.0 * std::numbers::pi;

TEST(StarProof, ConvexAndConcaveConesAreProvenAndTheirPairsGiveNothing) {
  for (const int n : {3, 4, 6, 9, 16}) {
    const std::vector<Vec3> ring = circle_ring(n, full_turn / n, [](int) { return 0.0; });
    EXPECT_TRUE(apex_proven(cone({0.1, -0.2, 1.0}, ring))) << n;
    EXPECT_TRUE(apex_proven(cone({0.1, -0.2, -1.0}, ring))) << n;
    // Clockwise as given: the proof does not depend on the orientation.
    std::vector<Vec3> reversed_ring(ring.rbegin(), ring.rend());
    EXPECT_TRUE(apex_proven(cone({0.0, 0.0, 0.5}, reversed_ring))) << n;
  }
  // A steep cone seen from the side (the dominant axis is not z).
  EXPECT_TRUE(apex_proven(cone({0, 0, 0}, {{1, 1, 0.1}, {1, -1, 0.2}, {1, -1, -1}, {1, 1, -1}})));
}

TEST(StarProof, AFlatFanIsNotProvenItsPairsAreCoplanarPartners) {
  const Fan fan = cone({0, 0, 0}, circle_ring(6, full_turn / 6, [](int) { return 0.0; }));
  EXPECT_FALSE(apex_proven(fan));
  // Why the proof asks for strict turns: opposite triangles of a flat fan share only the apex,
  // yet the pair stage makes them coplanar partners.
  EXPECT_TRUE(pair_gives_work(raw_soup(fan.vertices, fan.triangles), 0, 3));
  // Flat in part: a pyramid's apex is proven, not once a side is split into two coplanar
  // triangles.
  EXPECT_TRUE(apex_proven(cone({0, 0, 0}, {{1, 0, -1}, {0, 1, -1}, {-1, 0, -1}, {0, -1, -1}})));
  EXPECT_FALSE(apex_proven(
      cone({0, 0, 0}, {{1, 0, -1}, {0.5, 0.5, -1}, {0, 1, -1}, {-1, 0, -1}, {0, -1, -1}})));
}

TEST(StarProof, AFanFoldedOntoItselfIsNotProven) {
  // The ring turns back: the third sector is clockwise.
  EXPECT_FALSE(apex_proven(cone({0, 0, 1}, {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 1, 0.5}})));
  // Two triangles folded onto each other across their edge.
  EXPECT_FALSE(apex_proven(cone({0, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {1, 1, 0}})));
}

TEST(StarProof, ARingWindingTwiceOrThriceIsNotProvenAndItsPairsCross) {
  for (const auto& [n, windings] : {std::pair{5, 2}, std::pair{7, 2}, std::pair{7, 3}}) {
    const Fan fan =
        cone({0, 0, 1}, circle_ring(n, windings * full_turn / n, [](int) { return 0.0; }));
    EXPECT_FALSE(apex_proven(fan)) << n << " " << windings;
    // Every sector turns one way and every turn of the ring too: only the winding tells.
    EXPECT_FALSE(star_settled(raw_soup(fan.vertices, fan.triangles), 0)) << n << " " << windings;
  }
}

TEST(StarProof, SaddlesAreNotProven) {
  // Height fields whose turns change sign: the strict convexity fails, so no proof (whatever
  // the pair test would say of their pairs: the proof is only sufficient).
  EXPECT_FALSE(apex_proven(
      cone({0, 0, 0}, circle_ring(6, full_turn / 6, [](int i) { return i % 2 ? 0.5 : -0.5; }))));
  EXPECT_FALSE(apex_proven(cone(
      {0, 0, 0}, circle_ring(8, full_turn / 8, [](int i) { return (i / 2) % 2 ? 0.5 : -0.5; }))));
  // A saddle seen along x (the dominant axis there).
  EXPECT_FALSE(apex_proven(cone({0, 0, 0}, {{1, 1, 0}, {-1, 0, 1}, {1, -1, 0}, {-1, 0, -1}})));
}

TEST(StarProof, DuplicateAndZeroAreaTrianglesAreNotProven) {
  Fan fan = cone({0, 0, 1}, circle_ring(6, full_turn / 6, [](int) { return 0.0; }));
  ASSERT_TRUE(apex_proven(fan));
  Fan duplicated = fan;
  duplicated.triangles.push_back(duplicated.triangles[2]);
  EXPECT_FALSE(apex_proven(duplicated));
  Fan reversed_copy = fan;
  const TriangleIndices t = fan.triangles[2];
  reversed_copy.triangles.push_back({t[0], t[2], t[1]});
  EXPECT_FALSE(apex_proven(reversed_copy));
  // Ring vertex 7 on the segment from the apex to ring vertex 2: triangle apex 2 7 has zero area.
  Fan slit = fan;
  slit.vertices.push_back({0.5 * (0.0 + fan.vertices[2].x), 0.5 * (0.0 + fan.vertices[2].y),
                           0.5 * (1.0 + fan.vertices[2].z)});
  slit.triangles[1] = {0, 2, 7};
  slit.triangles.push_back({0, 7, 3});
  EXPECT_FALSE(apex_proven(slit));
  // A triangle naming the apex twice.
  Fan repeated = fan;
  repeated.triangles.push_back({0, 0, 3});
  EXPECT_FALSE(apex_proven(repeated));
}

TEST(StarProof, OpenStarsTwoConesAtOneApexAndLargeFansAreNotProven) {
  Fan open = cone({0, 0, 1}, circle_ring(6, full_turn / 6, [](int) { return 0.0; }));
  open.triangles.pop_back();
  EXPECT_FALSE(apex_proven(open));
  // Two cones, up and down, sharing the apex: two rings.
  Fan both = cone({0, 0, 0}, circle_ring(4, full_turn / 4, [](int) { return 1.0; }));
  const Fan down = cone({0, 0, 0}, circle_ring(5, full_turn / 5, [](int) { return -1.0; }));
  for (std::size_t i = 1; i < down.vertices.size(); ++i)
    both.vertices.push_back(down.vertices[i]);
  for (const TriangleIndices& t : down.triangles)
    both.triangles.push_back({0, t[1] + 4, t[2] + 4});
  EXPECT_FALSE(apex_proven(both));
  // More triangles than a star's walk takes: left to the pair test.
  EXPECT_FALSE(
      apex_proven(cone({0, 0, 1}, circle_ring(40, full_turn / 40, [](int) { return 0.0; }))));
}

// The sphere turned about its vertex 0 (a point reflection, so reversed to stay outward): the
// two touch at that vertex only.
Mesh mirrored_about_vertex(const Mesh& sphere) {
  Mesh mirrored = sphere;
  const Vec3 p = sphere.vertices[0];
  for (Vec3& v : mirrored.vertices)
    v = {2 * p.x - v.x, 2 * p.y - v.y, 2 * p.z - v.z};
  return reversed(mirrored);
}

TEST(StarProof, AVertexOfTwoInputsIsNotProven) {
  const Mesh sphere = icosphere(2, 1.0, {0, 0, 0});
  const Soup soup = soup_of({sphere, mirrored_about_vertex(sphere)});
  ASSERT_EQ(soup.vertices.size(), 2 * sphere.vertices.size() - 1);
  const std::vector<bool> proven = proven_vertices(soup);
  for (std::size_t v = 0; v < soup.vertices.size(); ++v) {
    // Vertex 0 is the one both name; the others are smooth spheres' vertices.
    EXPECT_EQ(proven[v], v != 0) << v;
  }
  EXPECT_EQ(check_proofs(soup, "touching spheres"), soup.vertices.size() - 1);
  // The same solid twice: every vertex in both inputs.
  EXPECT_EQ(check_proofs(soup_of({sphere, sphere}), "twice"), 0U);
  // A tetrahedron's sharp corners: no coordinate axis sees all three faces from one side, so
  // none is proven there (left to the pair test, as are the corners of axis-aligned faces).
  const Mesh a = tetrahedron({0, 0, 0}, {1, 0.2, 0.1}, {0.3, 1, 0.2}, {0.1, 0.2, 1});
  check_proofs(
      soup_of({a, tetrahedron({0, 0, 0}, {-1, -0.3, 0.1}, {0.2, -1, -0.1}, {-0.2, -0.1, -1})}),
      "tetrahedra");
}

// An icosphere with each vertex moved by `noise` times a random vector (radial only or in every
// direction), optionally rounded to multiples of `grid` (coplanar faces, collinear and
// coincident corners).
Mesh noisy_sphere(int levels, double noise, bool radial, double grid, std::mt19937_64& rng,
                  Vec3 center = {0, 0, 0}) {
  Mesh mesh = icosphere(levels, 1.0, center);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (Vec3& v : mesh.vertices) {
    if (radial) {
      const double s = 1.0 + noise * u(rng);
      v = {center.x + (v.x - center.x) * s, center.y + (v.y - center.y) * s,
           center.z + (v.z - center.z) * s};
    } else {
      v = {v.x + noise * u(rng), v.y + noise * u(rng), v.z + noise * u(rng)};
    }
    if (grid > 0)
      v = {grid * std::round(v.x / grid), grid * std::round(v.y / grid),
           grid * std::round(v.z / grid)};
  }
  return mesh;
}

TEST(StarProof, RandomClosedMeshesProofsAreSound) {
  std::mt19937_64 rng(25);
  const int cases = case_budget(24, 6);
  std::size_t proven = 0, vertices = 0;
  for (int k = 0; k < cases; ++k) {
    const double noise = std::array{0.0, 0.01, 0.1, 0.4}[static_cast<std::size_t>(k % 4)];
    const double grid = std::array{0.0, 0.0, 0.25, 0.5}[static_cast<std::size_t>(k / 4 % 4)];
    const Mesh mesh = noisy_sphere(1 + k % 3, noise, k % 2 == 0, grid, rng);
    const Soup soup = soup_of({mesh});
    proven += check_proofs(soup, "sphere " + std::to_string(k));
    vertices += soup.vertices.size();
  }
  // Not vacuous: the smooth spheres are proven throughout, the noisy ones in part, the snapped
  // ones hardly (coplanar neighbours); a fifth in all even in the reduced builds' four cases.
  EXPECT_GT(proven, vertices / 5);
  EXPECT_LT(proven, vertices);
  // A smooth icosphere: every vertex.
  const Soup smooth = soup_of({icosphere(3, 1.0, {0, 0, 0})});
  EXPECT_EQ(check_proofs(smooth, "icosphere"), smooth.vertices.size());
}

// The pair stage of the inputs' soup with the skip and with every pair tested: the same points
// in the store and the same work for every triangle (constraints with their edges, coplanar
// partners, in the same order), so that every later stage, and the boolean of any operation,
// is the same. Counts what makes the comparison mean something: the constraints found and the
// vertices proven.
struct Compared {
  std::size_t constraints = 0;
  std::size_t proven = 0;
};

Compared same_with_and_without(const std::vector<Mesh>& inputs, const std::string& what) {
  Compared compared;
  const Soup soup = soup_of(inputs);
  PointStore tested_store;
  PointStore proven_store;
  tested_store.add_vertices(soup);
  proven_store.add_vertices(soup);
  const clip::solid::PairWork tested =
      clip::solid::intersect_pairs(soup, tested_store, clip::solid::Neighbours::tested);
  const clip::solid::PairWork proven =
      clip::solid::intersect_pairs(soup, proven_store, clip::solid::Neighbours::proven);
  const std::vector<bool> proven_flags = proven_vertices(soup);
  compared.proven =
      static_cast<std::size_t>(std::count(proven_flags.begin(), proven_flags.end(), true));
  EXPECT_EQ(tested_store.size(), proven_store.size()) << what;
  if (tested_store.size() != proven_store.size()) return compared;
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(tested_store.size()); ++i) {
    const Vec3 a = tested_store.rounded(i), b = proven_store.rounded(i);
    EXPECT_TRUE(a.x == b.x && a.y == b.y && a.z == b.z) << what << ": point " << i;
  }
  EXPECT_EQ(tested.size(), proven.size()) << what;
  if (tested.size() != proven.size()) return compared;
  for (std::size_t t = 0; t < tested.size(); ++t) {
    const std::span<const Constraint> x = tested[t].constraints;
    const std::span<const Constraint> y = proven[t].constraints;
    EXPECT_EQ(x.size(), y.size()) << what << ": triangle " << t;
    if (x.size() != y.size()) continue;
    for (std::size_t k = 0; k < x.size(); ++k) {
      EXPECT_TRUE(x[k].a == y[k].a && x[k].b == y[k].b && x[k].edge == y[k].edge)
          << what << ": triangle " << t << ", constraint " << k;
    }
    EXPECT_TRUE(std::ranges::equal(tested[t].coplanar, proven[t].coplanar))
        << what << ": triangle " << t;
    compared.constraints += x.size();
  }
  return compared;
}

TEST(StarProof, PairStageOfRandomPairsGivesTheSameWorkWithAndWithoutTheSkip) {
  std::mt19937_64 rng(2025);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  const int cases = case_budget(12, 6);
  for (int k = 0; k < cases; ++k) {
    const double noise = std::array{0.0, 0.02, 0.2}[static_cast<std::size_t>(k % 3)];
    const double grid = k % 4 == 3 ? 0.125 : 0.0;
    const Mesh a = noisy_sphere(2, noise, k % 2 == 0, grid, rng);
    const Mesh b = noisy_sphere(1 + k % 2, noise, k % 2 == 1, grid, rng, {u(rng), u(rng), u(rng)});
    const Compared compared = same_with_and_without({a, b}, "case " + std::to_string(k));
    // Not vacuous: overlapping spheres cross, and their vertices are mostly proven (skipped).
    EXPECT_GT(compared.constraints, 0U) << "case " << k;
    EXPECT_GT(compared.proven, 0U) << "case " << k;
  }
}

TEST(StarProof, PairStageOfDegeneratePairsGivesTheSameWorkWithAndWithoutTheSkip) {
  const Mesh sphere = icosphere(2, 1.0, {0, 0, 0});
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh mirrored = mirrored_about_vertex(sphere);
  const std::vector<std::vector<Mesh>> pairs = {
      {sphere, sphere},                        // identical inputs
      {sphere, reversed(sphere)},              // one inside out
      {cube, box_mesh({1, 0, 0}, {2, 1, 1})},  // a shared face
      {cube, box_mesh({1, 1, 1}, {2, 2, 2})},  // a shared corner
      {sphere, mirrored},                      // touching at a vertex
      {sphere, icosphere(2, 1.0, {0, 0, 2})},  // nearly touching
      {sphere, cube},                          // the cube's corner inside
  };
  Compared all;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const Compared compared = same_with_and_without(pairs[k], "pair " + std::to_string(k));
    all.constraints += compared.constraints;
    all.proven += compared.proven;
  }
  // Not vacuous: some pairs cross or share faces, and the spheres' vertices are proven.
  EXPECT_GT(all.constraints, 0U);
  EXPECT_GT(all.proven, 0U);
}

}  // namespace
}  // namespace contain::test

namespace contain::test {
namespace {

// Two triangles in one tilted plane sharing the edge p q (each running along it either way),
// their third corners x and y at integer plane coordinates: the pair test makes them coplanar
// partners exactly when x and y lie on the same side of the edge (folded onto each other), as
// the sign of the dot product of their exact normals says too.
TEST(StarProof, CoplanarNeighboursAcrossAnEdgeArePartnersExactlyWhenFolded) {
  std::mt19937 rng(77);
  std::uniform_int_distribution<int> coordinate(-40, 40);
  // The plane O + s U + t V: integer points, exact in doubles, every axis's normal component
  // non-zero (the projection's axis is chosen, not given).
  const Vec3 origin{3, -5, 7}, along_u{1, 2, -3}, along_v{-2, 1, 4};
  const auto at = [&](int s, int t) {
    return Vec3{origin.x + s * along_u.x + t * along_v.x, origin.y + s * along_u.y + t * along_v.y,
                origin.z + s * along_u.z + t * along_v.z};
  };
  const auto side = [](std::array<int, 2> p, std::array<int, 2> q, std::array<int, 2> r) {
    const long d = static_cast<long>(q[0] - p[0]) * (r[1] - p[1]) -
                   static_cast<long>(q[1] - p[1]) * (r[0] - p[0]);
    return d > 0 ? 1 : (d < 0 ? -1 : 0);
  };
  int folded = 0, apart = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::array<std::array<int, 2>, 4> c;  // p, q, x, y
    for (auto& point : c)
      point = {coordinate(rng), coordinate(rng)};
    const int sx = side(c[0], c[1], c[2]), sy = side(c[0], c[1], c[3]);
    if (sx == 0 || sy == 0 || c[0] == c[1]) continue;
    std::vector<Vec3> vertices;
    for (const auto& point : c)
      vertices.push_back(at(point[0], point[1]));
    for (const bool t_forward : {true, false}) {
      for (const bool u_forward : {true, false}) {
        const TriangleIndices t = t_forward ? TriangleIndices{0, 1, 2} : TriangleIndices{1, 0, 2};
        const TriangleIndices u = u_forward ? TriangleIndices{0, 1, 3} : TriangleIndices{1, 0, 3};
        const Soup soup = raw_soup(vertices, {t, u});
        // The normals' dot product: positive when both turn the same way in the plane.
        const Sign agree = predicates::dot(soup.normal(0), soup.normal(1)).sign();
        const bool by_normals =
            t_forward == u_forward ? agree == Sign::positive : agree == Sign::negative;
        const bool expected = sx == sy;
        EXPECT_EQ(by_normals, expected);
        EXPECT_EQ(pair_gives_work(soup, 0, 1), expected) << trial;
        (expected ? folded : apart) += 1;
      }
    }
  }
  EXPECT_GT(folded, 200);
  EXPECT_GT(apart, 200);
}

}  // namespace
}  // namespace contain::test

namespace contain::test {
namespace {

// The proof of star_proof.h as written there, with predicates::orient2d and orient3d asked
// directly: the ring walked by following each link edge's end, the dominant axis of the fan's
// area vector in doubles, then the three conditions. The proofs share the differences and
// products of the ring among their filters; this one shares nothing.
bool proven_directly(const Soup& soup, std::int32_t v) {
  std::vector<std::array<std::int32_t, 2>> links;  // the ring edge a -> b of each triangle
  for (const TriangleIndices& t : soup.triangles) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (t[k] == v) links.push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
    }
  }
  const std::size_t n = links.size();
  if (n < 3 || n > 16) return false;
  std::vector<std::int32_t> ring;
  std::vector<bool> seen(n, false);
  std::size_t current = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (seen[current]) return false;
    seen[current] = true;
    ring.push_back(links[current][0]);
    std::size_t next = n;
    for (std::size_t j = 0; j < n && next == n; ++j) {
      if (links[j][0] == links[current][1]) next = j;
    }
    if (next == n) return false;
    current = next;
  }
  if (current != 0) return false;
  const Vec3 apex = soup.vertices[static_cast<std::size_t>(v)];
  const auto w = [&](std::size_t i) {
    return soup.vertices[static_cast<std::size_t>(ring[i % n])];
  };
  double nx = 0, ny = 0, nz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = w(i) - apex, q = w(i + 1) - apex;
    nx += p.y * q.z - p.z * q.y;
    ny += p.z * q.x - p.x * q.z;
    nz += p.x * q.y - p.y * q.x;
  }
  nx = std::fabs(nx);
  ny = std::fabs(ny);
  nz = std::fabs(nz);
  const int axis = nx >= ny && nx >= nz ? 0 : (ny >= nz ? 1 : 2);
  const Vec2 o = clip::solid::drop_axis(apex, axis);
  const auto p = [&](std::size_t i) { return clip::solid::drop_axis(w(i), axis); };
  const Sign turn = predicates::orient2d(o, p(0), p(1));
  if (turn == Sign::zero) return false;
  int crossings = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (predicates::orient2d(o, p(i), p(i + 1)) != turn) return false;
    crossings += p(i).y < o.y && p(i + 1).y >= o.y ? 1 : 0;
  }
  if (crossings != 1) return false;
  const Sign bend = predicates::orient3d(apex, w(0), w(1), w(2));
  if (bend == Sign::zero) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (predicates::orient3d(apex, w(i), w(i + 1), w(i + 2)) != bend) return false;
  }
  return true;
}

// Bits 2k, 2k + 1 as ProvenStars::turns: the sign of orient2d of the triangle's corners dropping
// axis k.
std::uint8_t turns_directly(const Soup& soup, std::size_t t) {
  unsigned bits = 0;
  for (int k = 0; k < 3; ++k) {
    const auto at = [&](std::size_t i) {
      return clip::solid::drop_axis(soup.vertices[static_cast<std::size_t>(soup.triangles[t][i])],
                                    k);
    };
    const Sign s = predicates::orient2d(at(0), at(1), at(2));
    if (s == Sign::positive) bits |= 1U << (2 * k);
    if (s == Sign::negative) bits |= 1U << (2 * k + 1);
  }
  return static_cast<std::uint8_t>(bits);
}

// Compares the proofs, the corners, the turns and the neighbours across with the direct ones on
// `soup`; returns how many vertices are proven.
std::size_t compare_with_direct(const Soup& soup, const std::string& what) {
  const std::vector<bool> proven = proven_vertices(soup);
  const clip::solid::ProvenStars stars = clip::solid::proven_stars(soup);
  std::size_t count = 0;
  for (std::size_t v = 0; v < soup.vertices.size(); ++v) {
    EXPECT_EQ(proven[v], proven_directly(soup, static_cast<std::int32_t>(v))) << what << ": " << v;
    count += proven[v] ? 1 : 0;
  }
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const TriangleIndices& c = soup.triangles[t];
    unsigned corners = 0;
    for (std::size_t k = 0; k < 3; ++k)
      corners |= proven[static_cast<std::size_t>(c[k])] ? 1U << k : 0U;
    EXPECT_EQ(stars.corners[t], corners) << what << ": triangle " << t;
    const std::uint8_t turns = (corners & 1U) != 0 ? turns_directly(soup, t) : std::uint8_t{0};
    EXPECT_EQ(stars.turns[t], turns) << what << ": triangle " << t;
    for (std::size_t k = 0; k < 3; ++k) {
      // Across an edge with a proven end: the triangle holding the edge the other way.
      const std::int32_t u = stars.across[t][k];
      const bool known = (corners & (1U << k)) != 0 || (corners & (1U << ((k + 1) % 3))) != 0;
      EXPECT_EQ(u >= 0, known) << what << ": triangle " << t;
      if (u < 0) continue;
      const TriangleIndices& d = soup.triangles[static_cast<std::size_t>(u)];
      bool reversed_edge = false;
      for (std::size_t j = 0; j < 3; ++j)
        reversed_edge = reversed_edge || (d[j] == c[(k + 1) % 3] && d[(j + 1) % 3] == c[k]);
      EXPECT_TRUE(reversed_edge) << what << ": triangle " << t;
    }
  }
  // In leaf order (the pair stage's): the same, at each triangle's position in the tree's
  // items, with the neighbours as positions.
  const clip::solid::ProvenStars leaf =
      clip::solid::proven_stars(soup, clip::solid::StarOrder::leaf);
  const std::span<const std::int32_t> items = soup.tree.items();
  std::vector<std::int32_t> position(soup.triangles.size(), -1);
  for (std::size_t k = 0; k < items.size(); ++k)
    position[static_cast<std::size_t>(items[k])] = static_cast<std::int32_t>(k);
  EXPECT_EQ(leaf.corners, stars.corners) << what;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const auto t = static_cast<std::size_t>(items[k]);
    EXPECT_EQ(leaf.turns[k], stars.turns[t]) << what << ": triangle " << t;
    for (std::size_t e = 0; e < 3; ++e) {
      const std::int32_t u = stars.across[t][e];
      EXPECT_EQ(leaf.across[k][e], u < 0 ? -1 : position[static_cast<std::size_t>(u)])
          << what << ": triangle " << t;
    }
  }
  return count;
}

// The proofs' filters (on the ring's shared differences and products) decide as orient2d and
// orient3d do, on scales where the products are exact, rounded, near overflow or subnormal
// (the filters' underflow guards then send every test to the exact predicates), on grids whose
// stars are flat, folded or collinear (exact zeros), and on cones flattened to within an ulp.
TEST(StarProof, SharedFiltersDecideAsThePredicates) {
  std::mt19937_64 rng(4711);
  std::size_t proven = 0, vertices = 0;
  const int cases = case_budget(60, 15);
  for (int k = 0; k < cases; ++k) {
    const double scale =
        std::array{1.0, 1e6, 0x1p-30, 1e-160, 1e150}[static_cast<std::size_t>(k % 5)];
    const double noise = std::array{0.0, 0.05, 0.3}[static_cast<std::size_t>(k % 3)];
    const double grid = k % 4 == 3 ? 0.25 : 0.0;
    Mesh mesh = noisy_sphere(1 + k % 2, noise, k % 2 == 0, grid, rng);
    for (Vec3& p : mesh.vertices)
      p = scale * p;
    const Soup soup = soup_of({mesh});
    proven += compare_with_direct(soup, "sphere " + std::to_string(k));
    vertices += soup.vertices.size();
  }
  // Not vacuous: a quarter of the vertices proven in a first count (the noisy and snapped
  // spheres hardly), some not.
  EXPECT_GT(proven, vertices / 5);
  EXPECT_LT(proven, vertices);
  // Cones of every apex height from an ulp above their ring's plane to flat and below, rings
  // wavy by an ulp: bends and turns at the filters' edge.
  for (const double height : {0.0, 0x1p-1074, 0x1p-60, -0x1p-60, 0x1p-30, 1.0}) {
    for (const double wave : {0.0, 0x1p-52, 0x1p-30}) {
      const Fan fan =
          cone({0.1, -0.2, 0.3 + height},
               circle_ring(7, full_turn / 7, [&](int i) { return 0.3 + (i % 2) * wave; }));
      const Soup soup = raw_soup(fan.vertices, fan.triangles);
      compare_with_direct(soup, "cone");
    }
  }
}

}  // namespace
}  // namespace contain::test

namespace contain::test {
namespace {

// The star proofs' filters on the shared differences and products decide only what orient2d
// and orient3d decide, on Kettner et al.'s nearly collinear points (0.5 + a ulp, 0.5 + b ulp),
// (12, 12), (24, 24) lifted into space, where a naive evaluation gets signs wrong: every decided
// sign is the predicate's, and the filters leave some undecided (those go to the predicates).
TEST(StarProof, RingFiltersDecideOnlyAsThePredicates) {
  constexpr double ulp = 0x1p-53;
  int decided = 0, undecided = 0;
  for (int a = 0; a < 64; ++a) {
    for (int b = 0; b < 64; ++b) {
      const Vec3 v{0.5 + a * ulp, 0.5 + b * ulp, 0.5 + (a * b % 7) * ulp};
      const Vec3 w1{12, 12, 12}, w2{24, 24, 24 + 0x1p-40 * (b % 3)}, w3{1, 2 + a * ulp, 3};
      const std::array<double, 3> d1{w1.x - v.x, w1.y - v.y, w1.z - v.z};
      const std::array<double, 3> d2{w2.x - v.x, w2.y - v.y, w2.z - v.z};
      const std::array<double, 3> d3{w3.x - v.x, w3.y - v.y, w3.z - v.z};
      const clip::solid::RingProducts c = clip::solid::ring_products(d1, d2);
      for (int axis = 0; axis < 3; ++axis) {
        const std::optional<Sign> s = clip::solid::filtered_turn(c, axis);
        if (!s) {
          ++undecided;
          continue;
        }
        ++decided;
        const auto at = [&](Vec3 p) { return clip::solid::drop_axis(p, axis); };
        EXPECT_EQ(*s, predicates::orient2d(at(v), at(w1), at(w2))) << a << " " << b << " " << axis;
      }
      const std::optional<Sign> s = clip::solid::filtered_bend(c, d3);
      if (!s) {
        ++undecided;
        continue;
      }
      ++decided;
      EXPECT_EQ(*s, predicates::orient3d(v, w1, w2, w3)) << a << " " << b;
    }
  }
  EXPECT_GT(decided, 0);
  EXPECT_GT(undecided, 0);
}

}  // namespace
}  // namespace contain::test
