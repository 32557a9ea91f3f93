// Meshes by half-spaces: clipped faces stay in the region, caps make closed oriented solids.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "contain/clip/box_halfspaces.h"
#include "contain/clip/mesh_clip.h"
#include "contain/shapes/mesh_validation.h"
#include "scenes/scenes.h"
#include "support/exact.h"

namespace contain::test {
namespace {

// The unit cube [0, 1]^3 as a closed, outward mesh.
Mesh cube() {
  return scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}});
}

void expect_solid(const Mesh& m, double volume, double tolerance) {
  const MeshReport r = validate_mesh(m);
  EXPECT_TRUE(r.closed()) << r.summary();
  EXPECT_TRUE(r.consistently_oriented()) << r.summary();
  EXPECT_TRUE(r.manifold()) << r.summary();
  EXPECT_NEAR(r.signed_volume, volume, tolerance) << r.summary();
}

TEST(MeshClip, CappedCubeCornerIsAClosedOutwardSolid) {
  const std::vector<Plane> cut = {{1, 1, 1, -1.5}};
  const Mesh m = clip::clip_mesh(cube(), cut, {.cut = clip::MeshCut::cap});
  expect_solid(m, 0.5, 1e-12);  // the plane through the centre halves the cube
  const Mesh open = clip::clip_mesh(cube(), cut);
  EXPECT_FALSE(validate_mesh(open).closed());
  for (const Vec3& v : open.vertices)
    EXPECT_NE(exact_side_of_plane(cut[0], v), Sign::negative);
}

TEST(MeshClip, BoxClipOfCubeIsTheSmallCubeWithExactFaceCoordinates) {
  const Mesh m =
      clip::clip_mesh(cube(), Box3{{0.25, 0.25, 0.25}, {2, 2, 2}}, {.cut = clip::MeshCut::cap});
  expect_solid(m, 0.75 * 0.75 * 0.75, 1e-12);
  for (const Vec3& v : m.vertices) {
    EXPECT_TRUE(Box3({{0.25, 0.25, 0.25}, {1, 1, 1}}).contains(v));
  }
}

TEST(MeshClip, FaceOnThePlaneStaysWhenItBoundsTheKeptSide) {
  const std::vector<Plane> x_le_1 = {{-1, 0, 0, 1}};
  EXPECT_EQ(clip::clip_mesh(cube(), x_le_1).triangles.size(), 12u);
  const std::vector<Plane> x_ge_1 = {{1, 0, 0, -1}};
  EXPECT_TRUE(clip::clip_mesh(cube(), x_ge_1, {.cut = clip::MeshCut::cap}).triangles.empty());
}

TEST(MeshClip, TorusCutThroughItsHoleGetsAnnularCapsAndStaysClosed) {
  const Mesh torus = scenes::torus(2.0, 0.5, 48, 24);
  const double full = validate_mesh(torus).signed_volume;
  // z >= 0.1 cuts the tube along an annulus (a cap with a hole).
  const std::vector<Plane> up = {{0, 0, 1, -0.1}};
  const Mesh top = clip::clip_mesh(torus, up, {.cut = clip::MeshCut::cap});
  const MeshReport r = validate_mesh(top);
  EXPECT_TRUE(r.closed() && r.consistently_oriented()) << r.summary();
  EXPECT_GT(r.signed_volume, 0.0);
  EXPECT_LT(r.signed_volume, 0.5 * full);
  // x >= 0.3 cuts the ring twice: two disc-shaped caps.
  const std::vector<Plane> side = {{1, 0, 0, -0.3}};
  const Mesh half = clip::clip_mesh(torus, side, {.cut = clip::MeshCut::cap});
  const MeshReport h = validate_mesh(half);
  EXPECT_TRUE(h.closed() && h.consistently_oriented() && h.manifold()) << h.summary();
  EXPECT_GT(h.signed_volume, 0.0);
}

TEST(MeshClip, ConvexMeshRegionGivesTheSameSolidAsItsPlanes) {
  const auto solid = ConvexPolyhedron::from_mesh(cube());
  ASSERT_TRUE(solid.ok());
  const Mesh torus = scenes::torus(0.4, 0.15, 24, 12);
  Mesh moved = torus;
  for (Vec3& v : moved.vertices)
    v = v + Vec3{0.2, 0.5, 0.5};
  const Mesh a = clip::clip_mesh(moved, *solid, {.cut = clip::MeshCut::cap});
  const Mesh b = clip::clip_mesh(moved, Box3{{0, 0, 0}, {1, 1, 1}}, {.cut = clip::MeshCut::cap});
  const MeshReport ra = validate_mesh(a), rb = validate_mesh(b);
  EXPECT_TRUE(ra.closed() && ra.consistently_oriented()) << ra.summary();
  EXPECT_TRUE(rb.closed() && rb.consistently_oriented()) << rb.summary();
  EXPECT_NEAR(ra.signed_volume, rb.signed_volume, 1e-9);
}

}  // namespace
}  // namespace contain::test

namespace contain::test {
namespace {

// The boundary of a union of unit cubes (cells on an integer lattice), outward, with shared
// vertices: large flat faces whose vertices, edges and faces lie on lattice planes.
Mesh voxels(const std::vector<std::array<int, 3>>& cells) {
  std::set<std::array<int, 3>> filled(cells.begin(), cells.end());
  Mesh m;
  std::map<std::array<int, 3>, std::int32_t> index;
  auto vertex = [&](std::array<int, 3> p) {
    const auto [it, fresh] = index.try_emplace(p, static_cast<std::int32_t>(m.vertices.size()));
    if (fresh) m.vertices.push_back({double(p[0]), double(p[1]), double(p[2])});
    return it->second;
  };
  for (const auto& c : filled) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int dir = -1; dir <= 1; dir += 2) {
        std::array<int, 3> n = c;
        n[axis] += dir;
        if (filled.contains(n)) continue;
        // The face of the cell toward n, counter-clockwise seen from outside.
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        std::array<int, 3> base = c;
        if (dir > 0) base[axis] += 1;
        std::array<std::array<int, 3>, 4> q;
        for (int k = 0; k < 4; ++k) {
          q[k] = base;
          q[k][u] += (k == 1 || k == 2) ? 1 : 0;
          q[k][v] += (k >= 2) ? 1 : 0;
        }
        std::int32_t i[4];
        for (int k = 0; k < 4; ++k)
          i[k] = vertex(q[k]);
        if (dir > 0) {
          m.triangles.push_back({i[0], i[1], i[2]});
          m.triangles.push_back({i[0], i[2], i[3]});
        } else {
          m.triangles.push_back({i[0], i[2], i[1]});
          m.triangles.push_back({i[0], i[3], i[2]});
        }
      }
    }
  }
  return m;
}

int cells_in(const std::vector<std::array<int, 3>>& cells, const Box3& b) {
  int count = 0;
  for (const auto& c : cells) {
    count += c[0] >= b.min.x && c[0] + 1 <= b.max.x && c[1] >= b.min.y && c[1] + 1 <= b.max.y &&
             c[2] >= b.min.z && c[2] + 1 <= b.max.z;
  }
  return count;
}

// Stairs and a block with a square hole through it: flat faces of many cells.
std::vector<std::vector<std::array<int, 3>>> lattice_solids() {
  std::vector<std::array<int, 3>> stairs, ring;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z <= x; ++z)
        stairs.push_back({x, y, z});
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 2; ++z)
        if (x != 1 || y != 1) ring.push_back({x, y, z});
  return {stairs, ring};
}

// Issue 13's class: box planes through vertices, along edges and on faces of large flat faces,
// on every side: every capped result is a closed, consistently oriented solid whose volume is
// the exact count of cells in the box.
TEST(MeshClip, LatticeBoxesThroughVerticesEdgesAndFacesGiveClosedSolids) {
  for (const auto& cells : lattice_solids()) {
    const Mesh solid = voxels(cells);
    ASSERT_TRUE(validate_mesh(solid).closed() && validate_mesh(solid).manifold());
    int tried = 0;
    for (int x0 = -1; x0 <= 3; ++x0)
      for (int y0 = -1; y0 <= 2; ++y0)
        for (int z0 = -1; z0 <= 3; ++z0)
          for (int s = 1; s <= 3; ++s) {
            const Box3 box{{double(x0), double(y0), double(z0)},
                           {double(x0 + s), double(y0 + 1 + s % 2), double(z0 + s)}};
            const Mesh m = clip::clip_mesh(solid, box, {.cut = clip::MeshCut::cap});
            const int expected = cells_in(cells, box);
            if (expected == 0) continue;  // may touch along a face: no volume
            ++tried;
            const MeshReport r = validate_mesh(m);
            ASSERT_TRUE(r.closed() && r.consistently_oriented())
                << x0 << " " << y0 << " " << z0 << " " << s << "\n"
                << r.summary();
            EXPECT_NEAR(r.signed_volume, expected, 1e-12) << x0 << " " << y0 << " " << z0;
          }
    EXPECT_GT(tried, 100);
  }
}

// The same class on planes through lattice points at an angle: closed and oriented, and a plane
// and its opposite split the volume exactly.
TEST(MeshClip, DiagonalPlanesThroughLatticeVerticesGiveClosedSolids) {
  for (const auto& cells : lattice_solids()) {
    const Mesh solid = voxels(cells);
    const double volume = static_cast<double>(cells.size());
    for (const Plane h : {Plane{1, 1, 0, -3}, Plane{1, 0, -1, 0}, Plane{1, -1, 1, -1},
                          Plane{0, 1, 1, -2}, Plane{1, 1, 1, -4}, Plane{2, -1, 0, -1}}) {
      const std::vector<Plane> a{h}, b{{-h.a, -h.b, -h.c, -h.d}};
      const MeshReport ra = validate_mesh(clip::clip_mesh(solid, a, {.cut = clip::MeshCut::cap}));
      const MeshReport rb = validate_mesh(clip::clip_mesh(solid, b, {.cut = clip::MeshCut::cap}));
      ASSERT_TRUE(ra.closed() && ra.consistently_oriented()) << h.a << h.b << h.c << h.d;
      ASSERT_TRUE(rb.closed() && rb.consistently_oriented()) << h.a << h.b << h.c << h.d;
      EXPECT_NEAR(ra.signed_volume + rb.signed_volume, volume, 1e-12);
    }
  }
}

// A cut through a vertex where the kept part touches itself (two sectors of the cap meet there),
// and crossing points that round onto one point (a vertex within 1e-19 of the plane).
TEST(MeshClip, PinchedCapsAndCrossingsThatRoundTogetherStayClosed) {
  // An L of three cells cut through its middle and along its bottom face.
  std::vector<std::array<int, 3>> l_cells = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  const Mesh l = voxels(l_cells);
  for (const double z : {0.5, 0.0}) {
    const std::vector<Plane> up{{0, 0, 1, -z}};
    const Mesh m = clip::clip_mesh(l, up, {.cut = clip::MeshCut::cap});
    const MeshReport r = validate_mesh(m);
    ASSERT_TRUE(r.closed() && r.consistently_oriented()) << z << "\n" << r.summary();
  }
  // A torus cut through its equator: the outer ring's vertices lie on z = 0, the inner ring's
  // at 0.5 sin(pi) = 6e-17 beyond it (the Python suite's instance, a strict xfail before).
  const Mesh torus = scenes::torus(2.0, 0.5, 48, 24);
  const std::vector<Plane> equator{{0, 0, 1, 0}};
  const MeshReport half =
      validate_mesh(clip::clip_mesh(torus, equator, {.cut = clip::MeshCut::cap}));
  EXPECT_TRUE(half.closed() && half.consistently_oriented()) << half.summary();
  // A bipyramid whose apex lies 1e-19 beyond the cut: its crossing points all round onto the
  // apex's (y, z); the result is closed or empty, never open.
  Mesh tip;
  tip.vertices = {{1e-19, 0.3, 0.2}, {-1, -1, -1}, {-1, 1, -1},
                  {-1, 1, 1},        {-1, -1, 1},  {-2, 0, 0}};
  tip.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 1, 4},
                   {5, 1, 2}, {5, 2, 3}, {5, 3, 4}, {5, 4, 1}};
  ASSERT_TRUE(validate_mesh(tip).closed());
  const std::vector<Plane> right{{1, 0, 0, 0}};
  const Mesh cut = clip::clip_mesh(tip, right, {.cut = clip::MeshCut::cap});
  const MeshReport r = validate_mesh(cut);
  EXPECT_TRUE(cut.triangles.empty() || (r.closed() && r.consistently_oriented())) << r.summary();
  EXPECT_EQ(r.border_edges, 0u);
}

// The instance: fandisk (large flat faces) by boxes whose planes pass through its vertices.
TEST(MeshClip, FandiskByBoxesThroughItsVerticesStaysClosed) {
  const std::filesystem::path path =
      std::filesystem::path(CONTAIN_SHARED_DIR) / "corpus" / "meshes" / "fandisk.obj";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " absent (../shared)";
  std::ifstream in(path);
  Mesh m;
  std::string tag;
  while (in >> tag) {
    if (tag == "v") {
      Vec3 v;
      in >> v.x >> v.y >> v.z;
      m.vertices.push_back(v);
    } else if (tag == "f") {
      std::array<std::int32_t, 3> t;
      for (auto& i : t) {
        std::string s;
        in >> s;
        i = std::stoi(s.substr(0, s.find('/'))) - 1;
      }
      m.triangles.push_back({t[0], t[1], t[2]});
    } else {
      std::getline(in, tag);
    }
  }
  ASSERT_TRUE(validate_mesh(m).closed());
  Box3 bounds;
  for (const Vec3 v : m.vertices)
    bounds.expand(v);
  // Boxes spanned by two vertices, some reaching past the mesh on a side (boxes 20 and 50 left
  // border edges before the cap chained its loops by angle at vertices with two ways out).
  std::mt19937_64 rng(1);
  std::uniform_int_distribution<std::size_t> pick(0, m.vertices.size() - 1);
  for (int t = 0; t < 60; ++t) {
    const Vec3 a = m.vertices[pick(rng)], c = m.vertices[pick(rng)];
    Box3 box{{std::min(a.x, c.x), std::min(a.y, c.y), std::min(a.z, c.z)},
             {std::max(a.x, c.x), std::max(a.y, c.y), std::max(a.z, c.z)}};
    if (t % 3 == 1) box.min.z = bounds.min.z - 1;
    if (t % 3 == 2) {
      box.max.x = bounds.max.x + 1;
      box.min.y = bounds.min.y;
    }
    if (!(box.min.x < box.max.x && box.min.y < box.max.y && box.min.z < box.max.z)) continue;
    const Mesh r = clip::clip_mesh(m, box, {.cut = clip::MeshCut::cap});
    if (r.triangles.empty()) continue;
    const MeshReport rep = validate_mesh(r);
    ASSERT_TRUE(rep.closed() && rep.consistently_oriented()) << t << "\n" << rep.summary();
  }
}

// Vertical prisms (z in [-1, 1]) over triangles far from the origin whose rounded shoelace sums
// are wrong: +8 for a clockwise triangle of area 2 at 2^28, 0 for a unit triangle at 2^30. The
// cut z <= 0 crosses the vertical edges exactly; the cap's side and its loop were judged by
// those sums and came out missing (an open result). Exactly, the cap closes the solid.
TEST(MeshClip, CapWhoseRoundedBorderAreaHasTheWrongSignOrIsZeroClosesTheSolid) {
  constexpr double m28 = 0x1p28, m30 = 0x1p30;
  const std::array<std::array<Vec2, 3>, 2> counter_clockwise_bases = {{
      {{{m28 - 3, m28 + 3}, {m28 - 1, m28 - 1}, {m28 + 1, m28 - 3}}},
      {{{m30, m30}, {m30 + 1, m30}, {m30, m30 + 1}}},
  }};
  for (const auto& base : counter_clockwise_bases) {
    Mesh prism;
    for (const double z : {-1.0, 1.0}) {
      for (const Vec2& p : base)
        prism.vertices.push_back({p.x, p.y, z});
    }
    prism.triangles = {{0, 2, 1}, {3, 4, 5}};  // bottom (down), top (up)
    for (std::int32_t i = 0; i < 3; ++i) {     // the side over edge i -> i + 1, outward
      const std::int32_t j = (i + 1) % 3;
      prism.triangles.push_back({i, j, j + 3});
      prism.triangles.push_back({i, j + 3, i + 3});
    }
    ASSERT_TRUE(validate_mesh(prism).closed());
    const std::vector<Plane> z_le_0 = {{0, 0, -1, 0}};
    const Mesh half = clip::clip_mesh(prism, z_le_0, {.cut = clip::MeshCut::cap});
    const MeshReport r = validate_mesh(half);
    EXPECT_TRUE(r.closed() && r.consistently_oriented() && r.manifold()) << r.summary();
    for (const Vec3& v : half.vertices)
      EXPECT_LE(v.z, 0.0);
  }
}

}  // namespace
}  // namespace contain::test
