#include "contain/inside/mesh_index.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "contain/inside/point_in_mesh.h"
#include "contain/shapes/mesh_validation.h"
#include "inside/mesh_test_meshes.h"
#include "scenes/scenes.h"
#include "support/perturbed_ray_oracle.h"

namespace contain::inside {
namespace {

using test::grid_cube;
using test::oracle_locate;

// Points on the half-integer grid over [lo - 0.5, hi + 0.5]^3 (rays through vertices, along
// edges, in face planes), the mesh's vertices and edge midpoints, and random points.
std::vector<Vec3> probe_points(const Mesh& mesh, double lo, double hi, double step) {
  std::vector<Vec3> points;
  for (double x = lo - 0.5; x <= hi + 0.5; x += step)
    for (double y = lo - 0.5; y <= hi + 0.5; y += step)
      for (double z = lo - 0.5; z <= hi + 0.5; z += step)
        points.push_back({x, y, z});
  for (const Vec3& v : mesh.vertices)
    points.push_back(v);
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Vec3 b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const Vec3 c = mesh.vertices[static_cast<std::size_t>(t[2])];
    points.push_back(0.5 * a + 0.5 * b);
    points.push_back(0.5 * (0.5 * a + 0.5 * b) + 0.5 * c);
    points.push_back({0.5 * a.x + 0.5 * b.x - 7.0, 0.5 * a.y + 0.5 * b.y, 0.5 * a.z + 0.5 * b.z});
  }
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(lo - 0.5, hi + 0.5);
  for (int k = 0; k < 300; ++k)
    points.push_back({u(rng), u(rng), u(rng)});
  return points;
}

// The index under several grid resolutions (one cell; default; fine) and without a grid (few
// queries: every triangle tested) against the oracle.
void expect_matches_oracle(const Mesh& mesh, const std::vector<Vec3>& points) {
  std::vector<Location> truth;
  truth.reserve(points.size());
  for (const Vec3& p : points)
    truth.push_back(oracle_locate(mesh, p));
  const MeshIndexOptions grids[] = {
      {.cells_per_triangle = 0.0, .min_cells = 1},
      {},
      {.cells_per_triangle = 200.0},
      {.queries = 1},
  };
  for (const MeshIndexOptions& options : grids) {
    const MeshIndex index(mesh, options);
    ASSERT_EQ(index.regime(), MeshRegime::closed_exact);
    for (std::size_t i = 0; i < points.size(); ++i) {
      ASSERT_EQ(index.locate(points[i]), truth[i])
          << "point " << points[i].x << " " << points[i].y << " " << points[i].z << " cells "
          << index.stats().cells;
    }
  }
}

TEST(MeshIndex, GridCubeWithManyCoplanarTrianglesMatchesTheExactOracle) {
  const Mesh mesh = grid_cube(0, 4, 4);
  expect_matches_oracle(mesh, probe_points(mesh, 0, 4, 0.5));
}

TEST(MeshIndex, OctahedronWithVerticesOnTheAxesMatchesTheExactOracle) {
  const Mesh mesh = test::octahedron(2);
  expect_matches_oracle(mesh, probe_points(mesh, -2, 2, 0.5));
}

TEST(MeshIndex, NonConvexPrismMatchesTheExactOracle) {
  const Mesh mesh = test::l_prism();
  expect_matches_oracle(mesh, probe_points(mesh, 0, 4, 0.5));
}

TEST(MeshIndex, TorusWithIrrationalVerticesMatchesTheExactOracle) {
  const Mesh mesh = scenes::torus(1.5, 0.5, 16, 8);
  expect_matches_oracle(mesh, probe_points(mesh, -2, 2, 0.25));
}

// The empty cells' winding numbers come from each triangle's hits of the rows' sample lines;
// under big tilted triangles the grid leaves empty cells inside a triangle's box (its plane
// misses them), where the hit's side decides. At the centre of every cell of fine grids over
// two overlapping octahedra (winding number 2 where they overlap) and an inverted one inside
// (subtracting), with turned copies (other slopes), the index answers as the oracle's winding
// number.
TEST(MeshIndex, EveryCellUnderBigTiltedTrianglesHoldsTheOraclesAnswer) {
  Mesh shifted = test::octahedron(1.5);
  for (Vec3& v : shifted.vertices)
    v = v + Vec3{0.75, 0.5, 0.25};
  Mesh inverted = test::octahedron(0.4);
  for (auto& t : inverted.triangles)
    std::swap(t[1], t[2]);
  const Mesh overlap = scenes::joined(scenes::joined(test::octahedron(2), shifted), inverted);
  Mesh turned = overlap;
  for (Vec3& v : turned.vertices)
    v = {0.6 * v.x - 0.8 * v.y, 0.8 * v.x + 0.6 * v.y, v.z + 0.3 * v.x};
  for (const Mesh& mesh : {overlap, turned}) {
    for (const double per_triangle : {100.0, 400.0}) {
      const MeshIndex index(mesh, {.cells_per_triangle = per_triangle});
      const MeshIndex::Stats s = index.stats();
      ASSERT_GT(s.cells, s.surface_cells);
      const Box3& b = index.bounds();
      for (int k = 0; k < s.nz; ++k)
        for (int j = 0; j < s.ny; ++j)
          for (int i = 0; i < s.nx; ++i) {
            const Vec3 p{b.min.x + (i + 0.5) / s.nx * (b.max.x - b.min.x),
                         b.min.y + (j + 0.5) / s.ny * (b.max.y - b.min.y),
                         b.min.z + (k + 0.5) / s.nz * (b.max.z - b.min.z)};
            if (oracle_locate(mesh, p) == Location::boundary) continue;  // not a cell's answer
            const Location solid =
                test::oracle_winding(mesh, p) > 0 ? Location::inside : Location::outside;
            ASSERT_EQ(index.locate(p), solid)
                << p.x << " " << p.y << " " << p.z << " cells " << s.cells;
          }
    }
  }
}

TEST(MeshIndex, AMeshTurnedInsideOutHoldsNoPointAsForTheBooleans) {
  // Winding number -1 inside: the empty solid (contain clip --op union writes no triangle).
  Mesh mesh = grid_cube(0, 4, 2);
  for (auto& t : mesh.triangles)
    std::swap(t[1], t[2]);
  const MeshIndex inward(mesh);
  for (const Vec3& p : probe_points(mesh, 0, 4, 0.5))
    ASSERT_EQ(inward.locate(p), Location::outside) << p.x << " " << p.y << " " << p.z;
  EXPECT_EQ(inward.regime(), MeshRegime::closed_exact);
  EXPECT_TRUE(inward.report().watertight());
}

TEST(MeshIndex, ScalingByAPowerOfTwoChangesNoAnswer) {
  const Mesh mesh = scenes::torus(1.5, 0.5, 16, 8);
  const std::vector<Vec3> points = probe_points(mesh, -2, 2, 0.5);
  const MeshIndex index(mesh);
  for (double s : {0x1p-500, 0x1p500, 0x1p-1000}) {
    const MeshIndex scaled(test::scaled(mesh, s));
    for (const Vec3& p : points)
      ASSERT_EQ(scaled.locate(s * p), index.locate(p)) << s;
  }
}

TEST(MeshIndex, BatchAnswersAreTheSameForAnyThreadCount) {
  const Mesh mesh = scenes::torus(1.0, 0.4, 60, 24);
  const MeshIndex index(mesh);
  const std::vector<Vec3> points = scenes::uniform_points(index.bounds(), 20000, 5);
  std::vector<Location> one(points.size()), two(points.size()), three(points.size());
  index.locate(points, one, {.threads = 1});
  index.locate(points, two, {.threads = 2});
  index.locate(points, three, {.threads = 3});
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, three);
  for (std::size_t i = 0; i < points.size(); i += 97)
    ASSERT_EQ(index.locate(points[i]), one[i]);
}

TEST(MeshIndex, PointsOutsideTheBoxAndEmptyMeshesAreOutside) {
  const MeshIndex index(grid_cube(0, 1, 1));
  EXPECT_EQ(index.locate({2, 0.5, 0.5}), Location::outside);
  EXPECT_EQ(index.locate({0.5, 0.5, -1e-300}), Location::outside);
  EXPECT_EQ(index.locate({0.5, 0.5, 0.5}), Location::inside);
  EXPECT_EQ(index.locate({1, 1, 1}), Location::boundary);
  const MeshIndex empty;
  EXPECT_EQ(empty.locate({0, 0, 0}), Location::outside);
}

TEST(MeshIndex, OpenMeshUsesTheWindingNumberAndReportsItsBorderEdges) {
  Mesh mesh = grid_cube(0, 1, 1);
  // Drop the two triangles of the face x = 1.
  std::vector<TriangleIndices> kept;
  for (const auto& t : mesh.triangles) {
    bool on_face = true;
    for (auto v : t)
      on_face = on_face && mesh.vertices[static_cast<std::size_t>(v)].x == 1.0;
    if (!on_face) kept.push_back(t);
  }
  mesh.triangles = kept;
  const MeshIndex index(mesh);
  EXPECT_EQ(index.regime(), MeshRegime::winding_number);
  EXPECT_EQ(index.report().border_edges, 4u);
  EXPECT_EQ(index.locate({0.5, 0.5, 0.5}), Location::inside);  // winding ~ 5/6
  EXPECT_EQ(index.locate({0.1, 0.5, 0.5}), Location::inside);
  EXPECT_EQ(index.locate({1.5, 0.5, 0.5}), Location::outside);
  EXPECT_EQ(index.locate({-0.5, 0.5, 0.5}), Location::outside);
  EXPECT_EQ(index.locate({0, 0.25, 0.75}), Location::boundary);  // on a face that is there
  EXPECT_EQ(index.locate({1, 0, 0.5}), Location::boundary);      // on the border edge
  EXPECT_EQ(index.locate({1.25, 0.5, 0.5}), Location::outside);  // beyond the hole
}

TEST(MeshIndex, PinchVertexKeepsTheExactRegimeAndIsReported) {
  Mesh mesh = grid_cube(0, 1, 1);
  Mesh other = grid_cube(1, 2, 1);
  const auto offset = static_cast<std::int32_t>(mesh.vertices.size());
  for (Vec3 v : other.vertices)
    mesh.vertices.push_back(v);
  for (auto t : other.triangles)
    mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const WeldResult welded = weld_vertices(mesh);  // the cubes share the vertex (1, 1, 1)
  ASSERT_EQ(welded.merged, 1u);
  const MeshIndex index(welded.mesh);
  EXPECT_EQ(index.regime(), MeshRegime::closed_exact);
  EXPECT_EQ(index.report().pinch_vertices.size(), 1u);
  for (const Vec3& p : probe_points(welded.mesh, -1, 2, 0.5))
    ASSERT_EQ(index.locate(p), oracle_locate(welded.mesh, p));
}

TEST(MeshIndex, ATriangleAndItsReverseCloseEveryEdgeAndBoundNoVolume) {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 1}};
  const MeshIndex index(mesh);
  EXPECT_EQ(index.regime(), MeshRegime::closed_exact);
  EXPECT_EQ(index.report().duplicated_triangles, 1u);
  // Winding number 0 on both sides: the empty solid, whose boundary is empty too.
  EXPECT_EQ(index.locate({0.5, 0.5, 0}), Location::outside);
  EXPECT_EQ(index.locate({0.5, 0.5, 1e-300}), Location::outside);
  EXPECT_EQ(index.locate({1.5, 1.5, 0}), Location::outside);
}

TEST(PointInMesh, OneShotGivesTheIndexAnswers) {
  const Mesh mesh = test::l_prism();
  const MeshIndex index(mesh);
  for (const Vec3& p : probe_points(mesh, 0, 4, 1.0))
    EXPECT_EQ(point_in_mesh(mesh, p), index.locate(p));
}

}  // namespace
}  // namespace contain::inside
