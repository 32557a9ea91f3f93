#include "contain/inside/point_in_convex.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "contain/values/transform.h"
#include "support/exact.h"

namespace contain::inside {
namespace {

// The unit cube, faces counter-clockwise from outside; vertex index x + 2y + 4z.
Mesh cube_mesh(double size = 1) {
  std::vector<Vec3> v;
  for (int i = 0; i < 8; ++i)
    v.push_back({size * (i & 1), size * ((i >> 1) & 1), size * (i >> 2)});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<TriangleIndices> t;
  for (const auto& q : quads) {
    t.push_back({q[0], q[1], q[2]});
    t.push_back({q[0], q[2], q[3]});
  }
  return *Mesh::from_arrays(std::move(v), std::move(t));
}

std::vector<Plane> cube_planes() {
  return {{1, 0, 0, 0}, {-1, 0, 0, 1}, {0, 1, 0, 0}, {0, -1, 0, 1}, {0, 0, 1, 0}, {0, 0, -1, 1}};
}

TEST(ConvexPolyhedron, PlanesAndMeshAgreeOnFacesEdgesVerticesInsideAndOutside) {
  const auto from_planes = ConvexPolyhedron::from_planes(cube_planes());
  const auto from_mesh = ConvexPolyhedron::from_mesh(cube_mesh());
  ASSERT_TRUE(from_planes.ok());
  ASSERT_TRUE(from_mesh.ok()) << from_mesh.error().what();
  const std::pair<Vec3, Location> cases[] = {{{0.5, 0.5, 0.5}, Location::inside},
                                             {{0, 0.5, 0.5}, Location::boundary},
                                             {{1, 1, 0.5}, Location::boundary},
                                             {{1, 1, 1}, Location::boundary},
                                             {{0.5, 0.5, 0}, Location::boundary},
                                             {{0.25, 0.75, 0}, Location::boundary},
                                             {{1.5, 0.5, 0.5}, Location::outside},
                                             {{0.5, 0.5, -1e-300}, Location::outside},
                                             {{1, 1, 1.0000000000000002}, Location::outside}};
  for (const auto& [p, want] : cases) {
    EXPECT_EQ(point_in_convex(*from_planes, p), want);
    EXPECT_EQ(point_in_convex(*from_mesh, p), want);
  }
}

TEST(ConvexPolyhedron, EmptyPlaneListIsAllOfSpace) {
  const auto all = ConvexPolyhedron::from_planes({});
  ASSERT_TRUE(all.ok());
  EXPECT_EQ(point_in_convex(*all, {1e300, -1e300, 0}), Location::inside);
}

TEST(ConvexPolyhedron, IntersectionWithoutInteriorIsAllBoundary) {
  const auto slab = ConvexPolyhedron::from_planes({{1, 0, 0, 0}, {-1, 0, 0, 0}});
  ASSERT_TRUE(slab.ok());
  EXPECT_EQ(point_in_convex(*slab, {0, 5, 5}), Location::boundary);
  EXPECT_EQ(point_in_convex(*slab, {1e-300, 5, 5}), Location::outside);
}

TEST(ConvexPolyhedron, RejectsZeroNormalAndNonFinitePlanes) {
  auto zero = ConvexPolyhedron::from_planes({{1, 0, 0, 0}, {0, 0, 0, 1}});
  ASSERT_FALSE(zero.ok());
  EXPECT_EQ(zero.error().kind, ErrorKind::degenerate);
  EXPECT_NE(zero.error().message.find("plane 1"), std::string::npos);
  auto nan = ConvexPolyhedron::from_planes({{std::numeric_limits<double>::quiet_NaN(), 0, 0, 0}});
  ASSERT_FALSE(nan.ok());
  EXPECT_EQ(nan.error().kind, ErrorKind::invalid_value);
}

TEST(ConvexPolyhedron, InwardOrientedMeshIsFlipped) {
  Mesh m = cube_mesh();
  for (TriangleIndices& t : m.triangles)
    std::swap(t[1], t[2]);
  const auto c = ConvexPolyhedron::from_mesh(m);
  ASSERT_TRUE(c.ok());
  EXPECT_EQ(point_in_convex(*c, {0.5, 0.5, 0.5}), Location::inside);
  EXPECT_EQ(point_in_convex(*c, {2, 0.5, 0.5}), Location::outside);
}

TEST(ConvexPolyhedron, RejectsANonConvexMesh) {
  Mesh m = cube_mesh();
  m.vertices[7] = {0.6, 0.6, 0.6};  // dent one corner inward
  const auto c = ConvexPolyhedron::from_mesh(m);
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().message.find("not convex"), std::string::npos);
}

TEST(ConvexPolyhedron, RejectsAnOpenMesh) {
  Mesh m = cube_mesh();
  m.triangles.pop_back();
  const auto c = ConvexPolyhedron::from_mesh(m);
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().message.find("not closed"), std::string::npos);
}

TEST(ConvexPolyhedron, RejectsDegenerateTrianglesAndFlatMeshes) {
  // A "tetrahedron" with all four vertices in z = 0.
  const Mesh flat = *Mesh::from_arrays({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}},
                                       {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  const auto c = ConvexPolyhedron::from_mesh(flat);
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.error().kind, ErrorKind::degenerate);
  const Mesh line = *Mesh::from_arrays({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 1, 0}},
                                       {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}});
  const auto d = ConvexPolyhedron::from_mesh(line);
  ASSERT_FALSE(d.ok());
  EXPECT_EQ(d.error().kind, ErrorKind::degenerate);
}

// Random tetrahedra and points pushed onto face planes in floating point (near-ties), and
// exact points (vertices, edge midpoints of integer tetrahedra).
TEST(ConvexPolyhedron, MeshAndPlaneFormsAgreeWithTheGmpOracleOnRandomAndDegeneratePoints) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> k(-8, 8);
  int boundary = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const bool integer = trial % 2 == 0;
    auto coord = [&] { return integer ? static_cast<double>(k(rng)) : u(rng); };
    std::vector<Vec3> v{{coord(), coord(), coord()},
                        {coord(), coord(), coord()},
                        {coord(), coord(), coord()},
                        {coord(), coord(), coord()}};
    if (test::exact_orient3d(v[0], v[1], v[2], v[3]) == Sign::zero) continue;
    if (test::exact_orient3d(v[0], v[1], v[2], v[3]) == Sign::positive) std::swap(v[1], v[2]);
    // Now v3 is on the negative (inner) side of face 0 1 2 seen with outward normal.
    const std::vector<TriangleIndices> faces{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}};
    const auto mesh = Mesh::from_arrays(v, faces);
    const auto poly = ConvexPolyhedron::from_mesh(*mesh);
    ASSERT_TRUE(poly.ok()) << poly.error().what();
    std::vector<Plane> planes;  // only for exact integer input: plane coefficients are exact
    for (const TriangleIndices& f : faces) {
      const Vec3 a = v[f[0]], n = cross(v[f[1]] - a, v[f[2]] - a);
      planes.push_back({-n.x, -n.y, -n.z, dot(n, a)});
    }
    const auto from_planes = ConvexPolyhedron::from_planes(planes);
    for (int s = 0; s < 40; ++s) {
      Vec3 p;
      if (s < 4) {
        p = v[static_cast<std::size_t>(s)];
      } else if (s < 10) {
        p = 0.5 * (v[static_cast<std::size_t>(s % 4)] + v[static_cast<std::size_t>((s + 1) % 4)]);
      } else {
        const TriangleIndices& f = faces[static_cast<std::size_t>(s % 4)];
        const double x = 0.5 * (u(rng) + 1), y = 0.5 * (u(rng) + 1) * (1 - x);
        const Vec3 a = v[f[0]];
        p = a + x * (v[f[1]] - a) + y * (v[f[2]] - a);
      }
      Location truth = Location::inside;
      for (const TriangleIndices& f : faces) {
        const Sign side = test::exact_orient3d(v[f[0]], v[f[1]], v[f[2]], p);
        if (side == Sign::positive) truth = Location::outside;
        if (side == Sign::zero && truth != Location::outside) truth = Location::boundary;
      }
      boundary += truth == Location::boundary;
      EXPECT_EQ(point_in_convex(*poly, p), truth);
      if (integer) {
        Location plane_truth = Location::inside;
        for (const Plane& h : planes) {
          const Sign side = test::exact_side_of_plane(h, p);
          if (side == Sign::negative) plane_truth = Location::outside;
          if (side == Sign::zero && plane_truth != Location::outside) {
            plane_truth = Location::boundary;
          }
        }
        EXPECT_EQ(point_in_convex(*from_planes, p), plane_truth);
        EXPECT_EQ(plane_truth, truth);  // integer planes are exact: same solid
      }
    }
  }
  EXPECT_GT(boundary, 500);
}

// Exact location in the solid bounded by `faces` over `v` (outward), by the GMP oracle.
Location oracle_location(std::span<const Vec3> v, std::span<const TriangleIndices> faces, Vec3 p) {
  Location truth = Location::inside;
  for (const TriangleIndices& f : faces) {
    const Sign side =
        test::exact_orient3d(v[static_cast<std::size_t>(f[0])], v[static_cast<std::size_t>(f[1])],
                             v[static_cast<std::size_t>(f[2])], p);
    if (side == Sign::positive) return Location::outside;
    if (side == Sign::zero) truth = Location::boundary;
  }
  return truth;
}

TEST(PointInConvex, PlacedVerticesAnswerAsTheGmpOracleOnThePlacedFaces) {
  const auto cube = ConvexPolyhedron::from_mesh(cube_mesh());
  ASSERT_TRUE(cube.ok());
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(-1, 1);
  int boundary = 0;
  for (int trial = 0; trial < 50; ++trial) {
    // A rotation about z by a rounded angle, and a translation: the placed cube is convex only
    // up to rounding, and the answer is about its faces as placed.
    const double angle = 3 * u(rng), c = std::cos(angle), s = std::sin(angle);
    Transform t;
    t.r = {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
    t.t = {u(rng), u(rng), u(rng)};
    std::vector<Vec3> placed;
    for (const Vec3& v : cube->vertices())
      placed.push_back(t.apply(v));
    for (int k = 0; k < 60; ++k) {
      // Corners, edge midpoints and random points in and near the placed cube.
      Vec3 p;
      if (k < 8) {
        p = placed[static_cast<std::size_t>(k)];
      } else if (k < 20) {
        const TriangleIndices& f = cube->face_indices()[static_cast<std::size_t>(k - 8)];
        p = 0.5 * (placed[static_cast<std::size_t>(f[0])] + placed[static_cast<std::size_t>(f[1])]);
      } else {
        p = t.apply({0.5 + 0.7 * u(rng), 0.5 + 0.7 * u(rng), 0.5 + 0.7 * u(rng)});
      }
      const Location truth = oracle_location(placed, cube->face_indices(), p);
      boundary += truth == Location::boundary;
      EXPECT_EQ(point_in_convex(*cube, placed, p), truth) << trial << " " << k;
    }
  }
  EXPECT_GT(boundary, 50);
}

TEST(PointInConvex, UnplacedVerticesAnswerAsThePolyhedronItself) {
  const auto cube = ConvexPolyhedron::from_mesh(cube_mesh(2));
  ASSERT_TRUE(cube.ok());
  std::mt19937_64 rng(31);
  std::uniform_int_distribution<int> k(-1, 5);
  for (int i = 0; i < 500; ++i) {
    const Vec3 p{0.5 * k(rng), 0.5 * k(rng), 0.5 * k(rng)};  // on, in and off the cube's planes
    EXPECT_EQ(point_in_convex(*cube, cube->vertices(), p), point_in_convex(*cube, p));
  }
}

TEST(PointInConvex, AFlatBoxIsLocatedByItsPlanesNotItsDegenerateSides) {
  const ConvexPolyhedron flat = ConvexPolyhedron::from_box({{0, 0, 1}, {2, 3, 1}});
  EXPECT_EQ(point_in_convex(flat, {1, 1, 1}), Location::boundary);
  EXPECT_EQ(point_in_convex(flat, {2, 3, 1}), Location::boundary);
  EXPECT_EQ(point_in_convex(flat, {3, 1, 1}), Location::outside);  // beyond a degenerate side
  EXPECT_EQ(point_in_convex(flat, {1, 1, 1.5}), Location::outside);
  const ConvexPolyhedron box = ConvexPolyhedron::from_box({{0, 0, 0}, {2, 3, 1}});
  EXPECT_EQ(point_in_convex(box, {1, 1, 0.5}), Location::inside);
}

TEST(ConvexPolyhedron, BatchAnswersEqualSingleAnswersWhateverTheThreadCount) {
  const auto c = ConvexPolyhedron::from_mesh(cube_mesh());
  std::vector<Vec3> points;
  for (int i = -2; i <= 6; ++i) {
    for (int j = -2; j <= 6; ++j) {
      for (int l = -2; l <= 6; ++l)
        points.push_back({i / 4.0, j / 4.0, l / 4.0});
    }
  }
  std::vector<Location> one(points.size()), three(points.size());
  point_in_convex(*c, points, one, {.threads = 1});
  point_in_convex(*c, points, three, {.threads = 3});
  EXPECT_EQ(one, three);
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_EQ(one[i], point_in_convex(*c, points[i]));
}

}  // namespace
}  // namespace contain::inside
