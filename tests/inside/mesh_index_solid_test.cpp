// MeshIndex on closed meshes answers the solid of the winding number (issue 24): the solid that
// clip::mesh_boolean repairs (`contain clip --op union`), checked against an exact GMP oracle on
// random self-overlapping meshes with inverted shells, whose faces overlap in coplanar pieces and
// whose probes' rays run through vertices and along edges.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "contain/clip/mesh_boolean.h"
#include "contain/inside/csg.h"
#include "contain/inside/mesh_index.h"
#include "support/perturbed_ray_oracle.h"

namespace contain::inside {
namespace {

// The closed box [lo, hi] as 12 triangles, outward, or inward when `inverted`, appended to m.
void add_box(Mesh& m, std::array<int, 3> lo, std::array<int, 3> hi, bool inverted) {
  const auto base = static_cast<std::int32_t>(m.vertices.size());
  for (int i = 0; i < 8; ++i) {
    m.vertices.push_back({static_cast<double>(i & 1 ? hi[0] : lo[0]),
                          static_cast<double>(i & 2 ? hi[1] : lo[1]),
                          static_cast<double>(i & 4 ? hi[2] : lo[2])});
  }
  const int faces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                            {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (const auto& f : faces) {
    m.triangles.push_back(inverted ? TriangleIndices{base + f[0], base + f[2], base + f[1]}
                                   : TriangleIndices{base + f[0], base + f[1], base + f[2]});
  }
}

// The solid's answer at a point of the half-integer grid, for meshes of boxes with integer
// corners: off the surface, the sign of the winding number; on it, the eight points a quarter
// away in every octant (every open cell around q of the axis planes through it holds one, and
// no other face lies between) decide: all in, inside; none, outside; else boundary.
Location oracle_solid(const Mesh& mesh, Vec3 q) {
  bool on = false;
  for (std::size_t t = 0; t < mesh.triangles.size() && !on; ++t)
    on = test::oracle_on_triangle(mesh.triangle(t), q);
  if (!on) return test::oracle_winding(mesh, q) > 0 ? Location::inside : Location::outside;
  int in = 0;
  for (int s = 0; s < 8; ++s) {
    const Vec3 sample{q.x + (s & 1 ? 0.25 : -0.25), q.y + (s & 2 ? 0.25 : -0.25),
                      q.z + (s & 4 ? 0.25 : -0.25)};
    in += test::oracle_winding(mesh, sample) > 0 ? 1 : 0;
  }
  return in == 8 ? Location::inside : in == 0 ? Location::outside : Location::boundary;
}

// Three to five boxes with corners in [0, 4]^3, a third of them turned inside out: overlapping
// parts, coplanar overlapping faces, inverted shells that hollow out others or stand alone.
Mesh random_boxes(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> corner(0, 4), count(3, 5), flip(0, 2);
  Mesh m;
  const int n = count(rng);
  for (int b = 0; b < n; ++b) {
    std::array<int, 3> lo{}, hi{};
    for (int k = 0; k < 3; ++k) {
      int u = corner(rng), v = corner(rng);
      while (u == v)
        v = corner(rng);
      lo[static_cast<std::size_t>(k)] = std::min(u, v);
      hi[static_cast<std::size_t>(k)] = std::max(u, v);
    }
    add_box(m, lo, hi, flip(rng) == 0);
  }
  return m;
}

// Probes on the half-integer grid over [-0.5, 4.5]^3 (on faces, edges and vertices, rays along
// edges and through vertices) and random doubles in the box.
std::vector<Vec3> probes(std::mt19937_64& rng, int grid, int random) {
  std::uniform_int_distribution<int> half(-1, 9);
  std::uniform_real_distribution<double> u(-0.5, 4.5);
  std::vector<Vec3> points;
  for (int k = 0; k < grid; ++k)
    points.push_back({0.5 * half(rng), 0.5 * half(rng), 0.5 * half(rng)});
  for (int k = 0; k < random; ++k)
    points.push_back({u(rng), u(rng), u(rng)});
  return points;
}

TEST(MeshIndexSolid, SelfOverlappingAndInvertedBoxesAnswerTheExactSolidAndItsRepair) {
  std::mt19937_64 rng(2024);
  for (int trial = 0; trial < 12; ++trial) {
    const Mesh mesh = random_boxes(rng);
    const MeshIndex index(mesh);
    ASSERT_EQ(index.regime(), MeshRegime::closed_exact);
    const std::vector<Mesh> inputs{mesh};
    auto repaired = clip::mesh_boolean(inputs, {.op = clip::Op::union_});
    ASSERT_TRUE(repaired.ok()) << repaired.error().what();
    ASSERT_EQ(repaired->moved, 0u);  // integer corners: the repair is exact
    const MeshIndex solid(repaired->mesh);
    const MeshIndex direct(mesh, {.queries = 1});  // no grid: every triangle tested
    ASSERT_EQ(direct.stats().cells, 0u);
    for (const Vec3 q : probes(rng, 150, 50)) {
      const Location got = index.locate(q);
      ASSERT_EQ(direct.locate(q), got) << trial << ": " << q.x << " " << q.y << " " << q.z;
      ASSERT_EQ(got, oracle_solid(mesh, q)) << trial << ": " << q.x << " " << q.y << " " << q.z;
      ASSERT_EQ(got, solid.locate(q)) << trial << ": " << q.x << " " << q.y << " " << q.z;
    }
  }
}

TEST(MeshIndexSolid, FacesSharedOrBuriedAreInteriorAndAHollowIsOutside) {
  Mesh mesh;
  add_box(mesh, {0, 0, 0}, {2, 2, 2}, false);
  add_box(mesh, {2, 0, 0}, {4, 2, 2}, false);  // touching along x = 2
  add_box(mesh, {1, 1, 1}, {3, 3, 3}, false);  // overlapping both
  const MeshIndex index(mesh);
  EXPECT_EQ(index.locate({2, 0.5, 0.5}), Location::inside);    // the shared face
  EXPECT_EQ(index.locate({1, 1.5, 1.5}), Location::inside);    // a face buried in the first box
  EXPECT_EQ(index.locate({2, 1, 1.5}), Location::inside);      // an edge inside
  EXPECT_EQ(index.locate({1.5, 1.5, 1.5}), Location::inside);  // inside all three parts' overlap
  EXPECT_EQ(index.locate({2, 0, 0.5}), Location::boundary);    // the outer surface
  EXPECT_EQ(index.locate({0, 0, 0}), Location::boundary);
  Mesh hollow;
  add_box(hollow, {0, 0, 0}, {4, 4, 4}, false);
  add_box(hollow, {1, 1, 1}, {3, 3, 3}, true);  // an inverted shell subtracts
  const MeshIndex shell(hollow);
  EXPECT_EQ(shell.locate({2, 2, 2}), Location::outside);
  EXPECT_EQ(shell.locate({1, 2, 2}), Location::boundary);
  EXPECT_EQ(shell.locate({0.5, 2, 2}), Location::inside);
  add_box(hollow, {1, 1, 1}, {3, 3, 3}, true);  // twice: winding number -1 in the hollow
  EXPECT_EQ(MeshIndex(hollow).locate({2, 2, 2}), Location::outside);
  EXPECT_EQ(MeshIndex(hollow).locate({1, 2, 2}), Location::boundary);
}

TEST(MeshIndexSolid, CsgMeshLeavesReadTheSameSolid) {
  Mesh mesh;
  add_box(mesh, {0, 0, 0}, {2, 2, 2}, false);
  add_box(mesh, {1, 1, 1}, {3, 3, 3}, false);
  auto solid = CsgSolid::prepare(Csg::leaf(CsgMesh(mesh)));
  ASSERT_TRUE(solid.ok()) << solid.error().what();
  const MeshIndex index(mesh);
  for (const Vec3 q : {Vec3{1.5, 1.5, 1.5}, Vec3{1, 1.5, 1.5}, Vec3{2, 1.5, 1.5}, Vec3{2, 2, 2},
                       Vec3{0, 1, 1}, Vec3{2, 2.5, 2.5}, Vec3{5, 5, 5}}) {
    EXPECT_EQ(solid->locate(q), index.locate(q)) << q.x << " " << q.y << " " << q.z;
  }
  EXPECT_EQ(solid->locate({1, 1.5, 1.5}), Location::inside);
}

// Degenerate parts that keep every directed edge matched: a zero-area triangle along an edge of
// the first box with its reverse, and a face of it repeated twice more, once reversed.
Mesh with_degenerate_parts(Mesh m) {
  const auto mid = static_cast<std::int32_t>(m.vertices.size());
  m.vertices.push_back(0.5 * m.vertices[0] + 0.5 * m.vertices[2]);  // on the edge 0-2
  m.triangles.push_back({0, 2, mid});
  m.triangles.push_back({0, mid, 2});
  const TriangleIndices face = m.triangles[0];
  m.triangles.push_back(face);
  m.triangles.push_back({face[0], face[2], face[1]});
  return m;
}

TEST(MeshIndexSolid, WithoutAGridTheIndexAnswersAsWithOneOnDegenerateAndInvertedMeshes) {
  // The few-query index (the mesh kept, each triangle tested) against the grid's and the
  // oracle's answers on the half-integer grid: on faces, edges, vertices, the zero-area
  // triangle and the repeated face; the index taking the mesh over (moved) answers alike.
  std::mt19937_64 rng(77);
  for (int trial = 0; trial < 10; ++trial) {
    const Mesh mesh = with_degenerate_parts(random_boxes(rng));
    const MeshIndex grid(mesh);
    const MeshIndex direct(mesh, {.queries = 1});
    const MeshIndex moved(Mesh(mesh), {.queries = 1});
    ASSERT_EQ(direct.regime(), MeshRegime::closed_exact);
    ASSERT_EQ(direct.stats().cells, 0u);
    ASSERT_EQ(direct.stats().triangles, mesh.triangles.size());
    ASSERT_GT(direct.report().degenerate_triangles, 0u);
    ASSERT_GT(direct.report().duplicated_triangles, 0u);
    ASSERT_TRUE(direct.bounds() == grid.bounds());
    std::vector<Vec3> points = probes(rng, 150, 30);
    points.insert(points.end(), mesh.vertices.begin(), mesh.vertices.end());
    for (const Vec3 q : points) {
      const Location want = oracle_solid(mesh, q);
      ASSERT_EQ(grid.locate(q), want) << trial << ": " << q.x << " " << q.y << " " << q.z;
      ASSERT_EQ(direct.locate(q), want) << trial << ": " << q.x << " " << q.y << " " << q.z;
      ASSERT_EQ(moved.locate(q), want) << trial << ": " << q.x << " " << q.y << " " << q.z;
    }
  }
}

TEST(MeshIndexSolid, WithoutAGridAClosedMeshWithInconsistentOrientationKeepsRayParity) {
  Mesh mesh;
  add_box(mesh, {0, 0, 0}, {2, 2, 2}, false);
  std::swap(mesh.triangles[0][1], mesh.triangles[0][2]);
  std::swap(mesh.triangles[1][1], mesh.triangles[1][2]);
  const MeshIndex grid(mesh);
  const MeshIndex direct(mesh, {.queries = 1});
  ASSERT_EQ(direct.rule(), SolidRule::parity);
  for (int x = -1; x <= 5; ++x)
    for (int y = -1; y <= 5; ++y)
      for (int z = -1; z <= 5; ++z) {
        const Vec3 q{0.5 * x, 0.5 * y, 0.5 * z};
        ASSERT_EQ(direct.locate(q), grid.locate(q)) << q.x << " " << q.y << " " << q.z;
      }
  EXPECT_EQ(direct.locate({1, 1, 1}), Location::inside);
  EXPECT_EQ(direct.locate({1, 1, 0}), Location::boundary);
  EXPECT_EQ(direct.locate({1, 1, 3}), Location::outside);
}

TEST(MeshIndexSolid, AClosedMeshWithInconsistentOrientationKeepsRayParity) {
  // One box's face pair flipped: every edge still has two triangles, but no winding number.
  Mesh mesh;
  add_box(mesh, {0, 0, 0}, {2, 2, 2}, false);
  std::swap(mesh.triangles[0][1], mesh.triangles[0][2]);
  std::swap(mesh.triangles[1][1], mesh.triangles[1][2]);
  const MeshIndex index(mesh);
  ASSERT_EQ(index.regime(), MeshRegime::closed_exact);
  EXPECT_GT(index.report().inconsistent_edges, 0u);
  EXPECT_EQ(index.locate({1, 1, 1}), Location::inside);
  EXPECT_EQ(index.locate({1, 1, 0}), Location::boundary);
  EXPECT_EQ(index.locate({1, 1, 3}), Location::outside);
}

}  // namespace
}  // namespace contain::inside

namespace contain::inside {
namespace {

TEST(MeshIndexSolid, TheApexOfAConeOf512SidesIsBoundaryByTwoSamples) {
  // 512 planes through the apex: the arrangement's sampling grows with their cube; the two
  // samples on either side of one face prove the boundary at once.
  constexpr int n = 512;
  Mesh cone;
  cone.vertices = {{0, 0, 1}, {0, 0, 0}};
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.141592653589793 * i / n;
    cone.vertices.push_back({std::cos(a), std::sin(a), 0});
  }
  for (int i = 0; i < n; ++i) {
    const std::int32_t a = 2 + i, b = 2 + (i + 1) % n;
    cone.triangles.push_back({0, a, b});
    cone.triangles.push_back({1, b, a});
  }
  for (const std::size_t queries : {std::size_t{0}, std::size_t{1}}) {
    const MeshIndex index(cone, {.queries = queries});
    EXPECT_EQ(index.locate({0, 0, 1}), Location::boundary);
    EXPECT_EQ(index.locate({0, 0, 0}), Location::boundary);
    EXPECT_EQ(index.locate({0, 0, 0.5}), Location::inside);
  }
}

}  // namespace
}  // namespace contain::inside
