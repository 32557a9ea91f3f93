// Mesh leaves of CSG trees (inside/csg.h): exact, and the same answers as the equivalent boxes.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <vector>

#include "contain/inside/csg.h"

namespace contain::inside {
namespace {

CsgSolid prepared(const Csg& tree) {
  auto solid = CsgSolid::prepare(tree);
  EXPECT_TRUE(solid.ok()) << solid.error().what();
  return std::move(solid).value();
}

// The closed surface of the prism over a polygon that is star-shaped from its first vertex,
// between heights z0 and z1; `flip` reverses every triangle (orientation must not matter).
Mesh prism(const std::vector<Vec2>& polygon, double z0, double z1, bool flip = false) {
  Mesh mesh;
  const auto n = static_cast<std::int32_t>(polygon.size());
  for (const Vec2 q : polygon)
    mesh.vertices.push_back({q.x, q.y, z0});
  for (const Vec2 q : polygon)
    mesh.vertices.push_back({q.x, q.y, z1});
  const auto add = [&](std::int32_t a, std::int32_t b, std::int32_t c) {
    mesh.triangles.push_back(flip ? TriangleIndices{a, c, b} : TriangleIndices{a, b, c});
  };
  for (std::int32_t i = 1; i + 1 < n; ++i) {
    add(0, i + 1, i);          // bottom, seen from below counter-clockwise
    add(n, n + i, n + i + 1);  // top
  }
  for (std::int32_t i = 0; i < n; ++i) {
    const std::int32_t j = (i + 1) % n;
    add(i, j, n + j);
    add(i, n + j, n + i);
  }
  return mesh;
}

Mesh cube_mesh(Vec3 lo, Vec3 hi, bool flip = false) {
  Mesh m = prism({{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}}, lo.z, hi.z, flip);
  return m;
}

// The L: [0, 2] x [0, 2] without the notch [1, 2] x [1, 2], from z = 0 to 1; its edge at
// x = y = 1 is reflex.
Mesh l_mesh() {
  return prism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 0, 1);
}

Csg mesh_leaf(Mesh m) {
  return Csg::leaf(CsgMesh(std::move(m)));
}

// The closed surface of a union of unit cubes (given by their min corners): every unit face
// with an empty cell behind it, as two triangles; no two cubes may share only an edge.
Mesh polycube(const std::vector<std::array<int, 3>>& cells) {
  Mesh mesh;
  std::map<std::array<int, 3>, std::int32_t> index;
  const auto vertex = [&](std::array<int, 3> v) {
    const auto [it, added] = index.emplace(v, static_cast<std::int32_t>(mesh.vertices.size()));
    if (added) mesh.vertices.push_back({double(v[0]), double(v[1]), double(v[2])});
    return it->second;
  };
  const auto filled = [&](std::array<int, 3> c) {
    return std::find(cells.begin(), cells.end(), c) != cells.end();
  };
  for (const auto& c : cells) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int side : {0, 1}) {
        std::array<int, 3> next = c;
        next[static_cast<std::size_t>(axis)] += side == 0 ? -1 : 1;
        if (filled(next)) continue;
        const auto u = static_cast<std::size_t>((axis + 1) % 3);
        const auto w = static_cast<std::size_t>((axis + 2) % 3);
        std::array<int, 3> q[4];
        for (int k = 0; k < 4; ++k) {
          q[k] = c;
          q[k][static_cast<std::size_t>(axis)] += side;
          q[k][u] += (k == 1 || k == 2) ? 1 : 0;
          q[k][w] += k >= 2 ? 1 : 0;
        }
        const std::int32_t i0 = vertex(q[0]), i1 = vertex(q[1]), i2 = vertex(q[2]),
                           i3 = vertex(q[3]);
        mesh.triangles.push_back({i0, i1, i2});
        mesh.triangles.push_back({i0, i2, i3});
      }
    }
  }
  return mesh;
}

Csg union_of_cubes(const std::vector<std::array<int, 3>>& cells) {
  std::vector<Csg> boxes;
  for (const auto& c : cells) {
    const Vec3 lo{double(c[0]), double(c[1]), double(c[2])};
    boxes.push_back(Csg::leaf(Box3{lo, lo + Vec3{1, 1, 1}}));
  }
  return Csg::unite(std::move(boxes));
}

// Every point of {-0.5, 0, 0.25, ..., 2.5}^3 (faces, edges and vertices of the unit boxes).
std::vector<Vec3> grid() {
  std::vector<Vec3> out;
  const double xs[] = {-0.5, 0, 0.25, 0.5, 1, 1.5, 2, 2.5};
  for (double x : xs)
    for (double y : xs)
      for (double z : xs)
        out.push_back({x, y, z});
  return out;
}

void expect_same(const Csg& a, const Csg& b, const char* what) {
  const CsgSolid sa = prepared(a), sb = prepared(b);
  int boundary = 0;
  for (const Vec3 p : grid()) {
    const Location la = sa.locate(p);
    ASSERT_EQ(la, sb.locate(p)) << what << " at " << p.x << " " << p.y << " " << p.z;
    boundary += la == Location::boundary;
  }
  EXPECT_GT(boundary, 0) << what;  // the grid exercises the neighbourhood analysis
}

// Trees with one leaf slot, each touching the leaf on faces, edges or vertices.
std::vector<std::pair<const char*, std::function<Csg(Csg)>>> trees() {
  const auto box = [](Vec3 lo, Vec3 hi) { return Csg::leaf(Box3{lo, hi}); };
  return {
      {"leaf", [](Csg x) { return x; }},
      {"complement", [](Csg x) { return Csg::complement(x); }},
      {"union with a box sharing a face",
       [=](Csg x) {
         return Csg::unite({x, box({1, 0, 0}, {2, 1, 1})});
       }},
      {"union with a box sharing an edge",
       [=](Csg x) {
         return Csg::unite({x, box({1, 1, 0}, {2, 2, 1})});
       }},
      {"union with a box sharing a vertex",
       [=](Csg x) {
         return Csg::unite({x, box({1, 1, 1}, {2, 2, 2})});
       }},
      {"intersection with an overlapping box",
       [=](Csg x) {
         return Csg::intersection({x, box({0.5, 0, -1}, {2, 0.5, 2})});
       }},
      {"minus a half-space through the middle",
       [](Csg x) {
         return Csg::difference(x, Csg::leaf(Plane{1, 0, 0, -0.5}));
       }},
      {"minus a ball centred on a vertex",
       [](Csg x) {
         return Csg::difference(x, Csg::leaf(Sphere{{1, 1, 1}, 0.5}));
       }},
      {"intersection with a ball cutting the edges",
       [](Csg x) {
         return Csg::intersection({x, Csg::leaf(Sphere{{0.5, 0.5, 0.5}, 0.75})});
       }},
      {"union with a ball tangent to a face",
       [](Csg x) {
         return Csg::unite({x, Csg::leaf(Sphere{{1.5, 0.5, 0.5}, 0.5})});
       }},
  };
}

TEST(CsgMesh, CubeMeshLeafAnswersExactlyLikeTheBoxInEveryTree) {
  const Box3 cube{{0, 0, 0}, {1, 1, 1}};
  for (const auto& [what, tree] : trees()) {
    expect_same(tree(mesh_leaf(cube_mesh(cube.min, cube.max))), tree(Csg::leaf(cube)), what);
  }
}

TEST(CsgMesh, AMeshTurnedInsideOutIsTheEmptySolidAsForTheBooleans) {
  // Its winding number is -1 inside: no point of it, not even of its surface, is in the solid,
  // so a union with it changes nothing and an intersection with it is empty.
  const Csg inverted = mesh_leaf(cube_mesh({0, 0, 0}, {1, 1, 1}, true));
  const Csg box = Csg::leaf(Box3{{0, 0, 0}, {2, 2, 2}});
  expect_same(Csg::unite({box, inverted}), box, "box + inverted cube");
  const CsgSolid alone = prepared(inverted);
  for (const Vec3 p : {Vec3{0.5, 0.5, 0.5}, Vec3{1, 0.5, 0.5}, Vec3{0, 0, 0}, Vec3{2, 2, 2}})
    EXPECT_EQ(alone.locate(p), Location::outside);
  const CsgSolid both = prepared(Csg::intersection({box, inverted}));
  EXPECT_EQ(both.locate({0.5, 0.5, 0.5}), Location::outside);
}

TEST(CsgMesh, LShapedMeshEqualsTheUnionOfItsTwoBoxes) {
  // Its reflex edge and the reflex vertices at its ends are not intersections of half-spaces.
  const Csg boxes =
      Csg::unite({Csg::leaf(Box3{{0, 0, 0}, {2, 1, 1}}), Csg::leaf(Box3{{0, 0, 0}, {1, 2, 1}})});
  for (const auto& [what, tree] : trees())
    expect_same(tree(mesh_leaf(l_mesh())), tree(boxes), what);
}

TEST(CsgMesh, PolycubeWithSaddleAndReflexVerticesEqualsTheUnionOfItsCubes) {
  // A corner cube and its three neighbours: at (1, 1, 1) four of the eight octants are filled,
  // a vertex whose neighbourhood no intersection of half-spaces describes.
  const std::vector<std::array<int, 3>> cells = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Mesh mesh = polycube(cells);
  ASSERT_EQ(MeshIndex(mesh).regime(), MeshRegime::closed_exact);
  for (const auto& [what, tree] : trees())
    expect_same(tree(mesh_leaf(mesh)), tree(union_of_cubes(cells)), what);
  // A staircase: cells touching (1, 1, 1) in alternate octants make a saddle there.
  const std::vector<std::array<int, 3>> stairs = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},
                                                  {1, 1, 1}, {0, 0, 1}, {0, 1, 1}};
  const Mesh stair_mesh = polycube(stairs);
  ASSERT_EQ(MeshIndex(stair_mesh).regime(), MeshRegime::closed_exact);
  for (const auto& [what, tree] : trees())
    expect_same(tree(mesh_leaf(stair_mesh)), tree(union_of_cubes(stairs)), what);
}

TEST(CsgMesh, OctahedronMeshAnswersLikeTheConvexPolyhedronOfItsFaces) {
  // Faces not aligned with the axes: the +x rays of points on them meet edges and vertices.
  Mesh octahedron;
  octahedron.vertices = {{2, 1, 1}, {0, 1, 1}, {1, 2, 1}, {1, 0, 1}, {1, 1, 2}, {1, 1, 0}};
  for (std::int32_t x : {0, 1})
    for (std::int32_t y : {2, 3})
      for (std::int32_t z : {4, 5}) {
        const bool odd = (x + y + z) % 2 == 1;  // keep the faces counter-clockwise outside
        octahedron.triangles.push_back(odd ? TriangleIndices{x, z, y} : TriangleIndices{x, y, z});
      }
  auto convex = ConvexPolyhedron::from_mesh(octahedron);
  ASSERT_TRUE(convex.ok()) << convex.error().what();
  for (const auto& [what, tree] : trees())
    expect_same(tree(mesh_leaf(octahedron)), tree(Csg::leaf(*convex)), what);
}

TEST(CsgMesh, LShapedMeshUnitedWithTheBoxInItsNotchIsOneSolid) {
  const Csg whole = Csg::unite({mesh_leaf(l_mesh()), Csg::leaf(Box3{{1, 1, 0}, {2, 2, 1}})});
  const CsgSolid solid = prepared(whole);
  // Interior points of the shared faces and of the reflex edge are inside.
  EXPECT_EQ(solid.locate({1, 1.5, 0.5}), Location::inside);
  EXPECT_EQ(solid.locate({1.5, 1, 0.5}), Location::inside);
  EXPECT_EQ(solid.locate({1, 1, 0.5}), Location::inside);
  EXPECT_EQ(solid.locate({1, 1, 0}), Location::boundary);
  expect_same(whole, Csg::leaf(Box3{{0, 0, 0}, {2, 2, 1}}), "L + notch");
}

TEST(CsgMesh, TwoTouchingCubeMeshesUniteIntoOneBox) {
  const Csg pair = Csg::unite(
      {mesh_leaf(cube_mesh({0, 0, 0}, {1, 1, 1})), mesh_leaf(cube_mesh({1, 0, 0}, {2, 1, 1}))});
  EXPECT_EQ(prepared(pair).locate({1, 0.5, 0.5}), Location::inside);
  expect_same(pair, Csg::leaf(Box3{{0, 0, 0}, {2, 1, 1}}), "two cube meshes");
}

TEST(CsgMesh, MeshMinusBallLeavesTheCutSurfaceOnTheBoundary) {
  const Csg cut =
      Csg::difference(mesh_leaf(cube_mesh({0, 0, 0}, {2, 2, 2})), Csg::leaf(Sphere{{1, 1, 2}, 1}));
  const CsgSolid solid = prepared(cut);
  EXPECT_EQ(solid.locate({1, 1, 1}), Location::boundary);  // bottom of the ball
  EXPECT_EQ(solid.locate({1, 1, 0.5}), Location::inside);
  EXPECT_EQ(solid.locate({1, 1, 1.5}), Location::outside);
  EXPECT_EQ(solid.locate({1, 1, 2}), Location::outside);   // ball centre on the top face
  EXPECT_EQ(solid.locate({0, 0, 2}), Location::boundary);  // a corner away from the ball
  EXPECT_EQ(solid.locate({0, 1, 2}), Location::boundary);  // where the ball meets two faces
  EXPECT_EQ(solid.locate({1, 0, 0}), Location::boundary);
  expect_same(
      cut, Csg::difference(Csg::leaf(Box3{{0, 0, 0}, {2, 2, 2}}), Csg::leaf(Sphere{{1, 1, 2}, 1})),
      "cube - ball");
}

TEST(CsgMesh, MeshLeafAloneAgreesWithMeshIndex) {
  const Mesh mesh = l_mesh();
  const MeshIndex index(mesh);
  const CsgSolid solid = prepared(Csg::leaf(CsgMesh(mesh)));
  for (const Vec3 p : grid())
    EXPECT_EQ(solid.locate(p), index.locate(p));
}

// A mesh without triangles is the empty solid (issue 25: an empty mesh is the empty solid), a
// valid operand: a union with it is its other operand, an intersection with it is empty, a
// difference by it is the first operand, and alone it holds no point.
TEST(CsgMesh, MeshWithoutTrianglesIsTheEmptySolid) {
  const Csg box = Csg::leaf(Box3{{0, 0, 0}, {1, 1, 1}});
  const Csg empty = mesh_leaf(Mesh{});
  const CsgSolid both = prepared(Csg::unite({box, empty}));
  const CsgSolid common = prepared(Csg::intersection({box, empty}));
  const CsgSolid minus = prepared(Csg::difference(box, empty));
  const CsgSolid alone = prepared(empty);
  const CsgSolid just_box = prepared(box);
  for (const Vec3 p : grid()) {
    EXPECT_EQ(both.locate(p), just_box.locate(p));
    EXPECT_EQ(minus.locate(p), just_box.locate(p));
    EXPECT_EQ(common.locate(p), Location::outside);
    EXPECT_EQ(alone.locate(p), Location::outside);
  }
}

TEST(CsgMesh, OpenMeshIsADegenerateLeafNamedByItsPosition) {
  Mesh open = cube_mesh({0, 0, 0}, {1, 1, 1});
  open.triangles.pop_back();
  auto solid = CsgSolid::prepare(
      Csg::unite({Csg::leaf(Box3{{0, 0, 0}, {1, 1, 1}}), mesh_leaf(std::move(open))}));
  ASSERT_FALSE(solid.ok());
  EXPECT_EQ(solid.error().kind, ErrorKind::degenerate);
  EXPECT_EQ(solid.error().message.rfind("union[1]: mesh is not closed", 0), 0u)
      << solid.error().message;
}

TEST(CsgMesh, IndexOutOfRangeIsAnInvalidLeaf) {
  Mesh bad = cube_mesh({0, 0, 0}, {1, 1, 1});
  bad.triangles[0][1] = 99;
  auto solid = CsgSolid::prepare(mesh_leaf(std::move(bad)));
  ASSERT_FALSE(solid.ok());
  EXPECT_EQ(solid.error().kind, ErrorKind::invalid_value);
}

}  // namespace
}  // namespace contain::inside
