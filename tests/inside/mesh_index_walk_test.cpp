// MeshIndex's walks (mesh_index.cpp, "Walks"): a point in a surface cell counts its crossings
// along whichever of the six axis directions reaches an empty cell (or leaves the grid) through the
// fewest cells. On boxes with faces across every axis, their surface cells' shortest walks go
// every way (a point under the top face walks up, one by the left face walks back along x, ...):
// each answer must be the exact oracle's, for random points, points on the grid's planes, lines
// and corners (hits exactly on a slab's plane), and points on the faces, edges and vertices.

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

#include "contain/inside/grid_axis.h"
#include "contain/inside/mesh_index.h"
#include "inside/mesh_test_meshes.h"
#include "scenes/scenes.h"
#include "support/perturbed_ray_oracle.h"

namespace contain::inside {
namespace {

// The reference: the index without a grid (every triangle tested by locate_direct: no walk),
// itself checked against the exact oracle off the surface on every 16th point (the sign of the
// winding number, or its parity for a mesh read by parity).
Location walk_reference(const Mesh& mesh, const MeshIndex& direct, Vec3 p, std::size_t n) {
  const Location answer = direct.locate(p);
  if (n % 16 != 0 || answer == Location::boundary) return answer;
  const int w = test::oracle_winding(mesh, p);
  EXPECT_EQ(answer, direct.inside_by_count(w) ? Location::inside : Location::outside)
      << p.x << " " << p.y << " " << p.z;
  return answer;
}

// Probes for an index: random points in and around the bounds, the grid's planes crossed with
// random coordinates, its lines and corners, and the mesh's vertices, edge midpoints and faces.
std::vector<Vec3> walk_probes(const Mesh& mesh, const MeshIndex& index, std::mt19937_64& rng) {
  const Box3& b = index.bounds();
  const MeshIndex::Stats s = index.stats();
  const GridAxis x(b.min.x, b.max.x, s.nx), y(b.min.y, b.max.y, s.ny), z(b.min.z, b.max.z, s.nz);
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  auto random_in = [&](double lo, double hi) { return lo + u(rng) * (hi - lo); };
  auto any_line = [&](const GridAxis& a) {
    std::uniform_int_distribution<int> pick(0, a.cells());
    return a.line(pick(rng));
  };
  std::vector<Vec3> points;
  for (int n = 0; n < 3000; ++n) {
    Vec3 p{random_in(b.min.x, b.max.x), random_in(b.min.y, b.max.y), random_in(b.min.z, b.max.z)};
    const int on_lines = n % 8;  // which coordinates sit on a grid plane
    if (on_lines & 1) p.x = any_line(x);
    if (on_lines & 2) p.y = any_line(y);
    if (on_lines & 4) p.z = any_line(z);
    points.push_back(p);
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle3 tri = mesh.triangle(t);
    points.push_back(tri.a);
    points.push_back(0.5 * tri.a + 0.5 * tri.b);
    points.push_back(0.5 * (0.5 * tri.a + 0.5 * tri.b) + 0.5 * tri.c);
  }
  return points;
}

void expect_walks_match(const Mesh& mesh, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const MeshIndex direct(mesh, {.queries = 1});
  for (const double per_triangle : {16.0, 100.0, 1000.0}) {
    const MeshIndex index(mesh, {.cells_per_triangle = per_triangle});
    ASSERT_EQ(index.regime(), MeshRegime::closed_exact);
    ASSERT_GT(index.stats().surface_cells, 0u);
    const std::vector<Vec3> probes = walk_probes(mesh, index, rng);
    for (std::size_t n = 0; n < probes.size(); ++n) {
      const Vec3 p = probes[n];
      ASSERT_EQ(index.locate(p), walk_reference(mesh, direct, p, n))
          << p.x << " " << p.y << " " << p.z << " cells " << index.stats().cells;
    }
  }
}

// A box [lo, hi] with corners given as integers, outward or inward, appended to `m`.
void add_walk_box(Mesh& m, std::array<double, 3> lo, std::array<double, 3> hi, bool inverted) {
  const auto base = static_cast<std::int32_t>(m.vertices.size());
  for (int i = 0; i < 8; ++i) {
    m.vertices.push_back({i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]});
  }
  const int faces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                            {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (const auto& f : faces) {
    m.triangles.push_back(inverted ? TriangleIndices{base + f[0], base + f[2], base + f[1]}
                                   : TriangleIndices{base + f[0], base + f[1], base + f[2]});
  }
}

TEST(MeshIndexWalks, FlatFacesAcrossEveryAxisAnswerAsTheOracle) {
  // Coplanar triangles on every face: walks along a face's plane meet edges in the plane.
  expect_walks_match(test::grid_cube(0, 4, 6), 1);
}

TEST(MeshIndexWalks, OverlappingAndInvertedBoxesKeepTheirWindingNumbers) {
  // Winding numbers 2 (overlap) and -1 (an inverted box alone), boxes whose faces lie on one
  // another's planes, and a thin slab along x (long runs of surface cells that way).
  Mesh m;
  add_walk_box(m, {0, 0, 0}, {4, 3, 2}, false);
  add_walk_box(m, {2, 1, 1}, {6, 4, 3}, false);
  add_walk_box(m, {4.5, -1, -1}, {5.5, 0, 0}, true);
  add_walk_box(m, {-1, 0, 0.75}, {7, 4, 1.25}, false);
  expect_walks_match(m, 2);
}

TEST(MeshIndexWalks, TiltedTorusesAnswerAsTheOracleWhateverWayTheirFlatSidesFace) {
  // The torus about z, then about x and y (its flat top facing each axis), and turned by an
  // irrational angle; vertices irrational.
  const Mesh torus = scenes::torus(1.5, 0.5, 24, 12);
  for (int turn = 0; turn < 4; ++turn) {
    Mesh m = torus;
    for (Vec3& v : m.vertices) {
      if (turn == 1) v = {v.z, v.x, v.y};
      if (turn == 2) v = {v.y, v.z, v.x};
      if (turn == 3) v = {0.6 * v.x - 0.8 * v.z, v.y + 0.1 * v.x, 0.8 * v.x + 0.6 * v.z};
    }
    expect_walks_match(m, 10 + static_cast<std::uint64_t>(turn));
  }
}

TEST(MeshIndexWalks, AMeshReadByParityKeepsItsParityAlongEveryAxis) {
  // Two faces' triangles turned: every edge has two triangles, the orientation is inconsistent.
  Mesh m = test::grid_cube(0, 4, 3);
  std::swap(m.triangles[0][1], m.triangles[0][2]);
  std::swap(m.triangles[1][1], m.triangles[1][2]);
  ASSERT_EQ(MeshIndex(m).rule(), SolidRule::parity);
  expect_walks_match(m, 3);
}

}  // namespace
}  // namespace contain::inside
