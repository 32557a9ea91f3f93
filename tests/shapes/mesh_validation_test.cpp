#include "contain/shapes/mesh_validation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "scenes/scenes.h"

namespace contain {
namespace {

// The unit cube [0,1]^3, outward (counter-clockwise seen from outside), 12 triangles.
Mesh cube(Vec3 o = {0, 0, 0}) {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back(o + Vec3{double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

Mesh two_cubes() {
  Mesh a = cube(), b = cube({3, 0, 0});
  for (auto& t : b.triangles)
    for (auto& v : t)
      v += 8;
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  a.triangles.insert(a.triangles.end(), b.triangles.begin(), b.triangles.end());
  return a;
}

TEST(MeshValidation, CubeIsAClosedOutwardGenusZeroManifold) {
  const MeshReport r = validate_mesh(cube());
  EXPECT_TRUE(r.closed());
  EXPECT_TRUE(r.manifold());
  EXPECT_TRUE(r.consistently_oriented());
  EXPECT_TRUE(r.outward());
  EXPECT_TRUE(r.watertight());
  EXPECT_EQ(r.edges, 18u);
  EXPECT_EQ(r.euler_characteristic, 2);
  EXPECT_EQ(r.genus, 0);
  EXPECT_EQ(r.components, 1u);
  EXPECT_DOUBLE_EQ(r.signed_volume, 1.0);
  EXPECT_NE(r.summary().find("closed: yes"), std::string::npos);
}

TEST(MeshValidation, InvertedCubeIsClosedButNotOutward) {
  Mesh m = cube();
  for (auto& t : m.triangles)
    std::swap(t[1], t[2]);
  const MeshReport r = validate_mesh(m);
  EXPECT_TRUE(r.closed());
  EXPECT_TRUE(r.consistently_oriented());
  EXPECT_FALSE(r.outward());
  EXPECT_LT(r.signed_volume, 0.0);
}

TEST(MeshValidation, OneFlippedFaceMakesThreeEdgesInconsistent) {
  Mesh m = cube();
  std::swap(m.triangles[0][1], m.triangles[0][2]);
  const MeshReport r = validate_mesh(m);
  EXPECT_TRUE(r.closed());
  EXPECT_EQ(r.inconsistent_edges, 3u);
  EXPECT_FALSE(r.consistently_oriented());
  EXPECT_FALSE(r.genus.has_value());
}

TEST(MeshValidation, MissingFaceLeavesFourBorderEdges) {
  Mesh m = cube();
  m.triangles.resize(10);  // the face x = 1 is gone
  const MeshReport r = validate_mesh(m);
  EXPECT_FALSE(r.closed());
  EXPECT_EQ(r.border_edges, 4u);
  EXPECT_TRUE(r.manifold());
  EXPECT_NE(r.summary().find("border edges: 4"), std::string::npos);
}

TEST(MeshValidation, DuplicatedFaceIsCountedAndItsEdgesAreNonManifold) {
  Mesh m = cube();
  m.triangles.push_back({0, 1, 2});  // the first face again, reversed order
  const MeshReport r = validate_mesh(m);
  EXPECT_EQ(r.duplicated_triangles, 1u);
  EXPECT_EQ(r.nonmanifold_edges, 3u);
  EXPECT_FALSE(r.closed());
}

TEST(MeshValidation, TwoCubesTouchingAtAVertexMakeAPinchVertex) {
  Mesh m = two_cubes();
  // Move the second cube so that its vertex 8 + 0 coincides with the first cube's vertex 7, then
  // weld: one vertex joins two fans.
  for (std::size_t i = 8; i < 16; ++i)
    m.vertices[i] = m.vertices[i] - Vec3{2, -1, -1};
  const WeldResult w = weld_vertices(m);
  EXPECT_EQ(w.merged, 1u);
  const MeshReport r = validate_mesh(w.mesh);
  EXPECT_TRUE(r.closed());
  EXPECT_FALSE(r.manifold());
  ASSERT_EQ(r.pinch_vertices.size(), 1u);
  EXPECT_EQ(r.pinch_vertices[0], 7);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.euler_characteristic, 3);
}

TEST(MeshValidation, TwoSeparateCubesAreTwoComponentsOfGenusZero) {
  const MeshReport r = validate_mesh(two_cubes());
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.euler_characteristic, 4);
  EXPECT_EQ(r.genus, 0);
}

TEST(MeshValidation, ZeroAreaIsDecidedExactly) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0.5, 0.5, 0.5}};
  m.triangles = {{0, 1, 2}, {0, 0, 1}, {1, 3, 2}};
  EXPECT_EQ(validate_mesh(m).degenerate_triangles, 3u) << "collinear, repeated index";
  Mesh off;
  off.vertices = {{0, 0, 0}, {1, 1, 1}, {2, 2, std::nextafter(2.0, 3.0)}};
  off.triangles = {{0, 1, 2}};
  EXPECT_EQ(validate_mesh(off).degenerate_triangles, 0u) << "one ulp off the line has area";
  Mesh tiny;  // area ~1e-300: not zero
  tiny.vertices = {{0, 0, 0}, {1e-150, 0, 0}, {0, 1e-150, 0}};
  tiny.triangles = {{0, 1, 2}};
  EXPECT_EQ(validate_mesh(tiny).degenerate_triangles, 0u);
}

TEST(MeshValidation, WeldingMergesExactlyEqualPositionsIncludingSignedZeros) {
  Mesh soup;
  soup.vertices = {{0, 0, 0},
                   {1, 0, 0},
                   {0, 1, 0},
                   {-0.0, 0, 0},
                   {1, 0, 0},
                   {0, 0, 1},
                   {0, 1, std::nextafter(0.0, 1.0)}};
  soup.triangles = {{0, 1, 2}, {3, 4, 5}, {0, 6, 5}};
  const WeldResult w = weld_vertices(soup);
  EXPECT_EQ(w.merged, 2u);
  EXPECT_EQ(w.mesh.vertices.size(), 5u);
  EXPECT_EQ(w.mesh.triangles[1], (TriangleIndices{0, 1, 3}));
  EXPECT_EQ(w.remap[6], 4);
}

TEST(MeshValidation, WeldingKeepsFirstOccurrencesAndNeverMergesNaN) {
  // Many repeats of few round positions (integers and halves, whose low bits are all zero) in a
  // shuffled order: each vertex maps to the first vertex at its position, new numbers in order
  // of first occurrence, exactly as a search by position finds them.
  std::mt19937_64 rng(26);
  std::uniform_int_distribution<int> cell(-6, 6);
  Mesh soup;
  for (int i = 0; i < 5000; ++i)
    soup.vertices.push_back({cell(rng) / 2.0, cell(rng) * 1.0, cell(rng) == 0 ? -0.0 : 0.0});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  soup.vertices.push_back({nan, 0, 0});
  soup.vertices.push_back({nan, 0, 0});
  const WeldResult w = weld_vertices(soup);
  std::vector<std::int32_t> first;  // the first vertex of each new number
  for (std::size_t i = 0; i < soup.vertices.size(); ++i) {
    const Vec3 p = soup.vertices[i];
    std::int32_t want = -1;
    for (std::size_t k = 0; k < first.size() && want < 0; ++k) {
      const Vec3 q = soup.vertices[static_cast<std::size_t>(first[k])];
      if (q.x == p.x && q.y == p.y && q.z == p.z) want = static_cast<std::int32_t>(k);
    }
    if (want < 0) {
      want = static_cast<std::int32_t>(first.size());
      first.push_back(static_cast<std::int32_t>(i));
    }
    ASSERT_EQ(w.remap[i], want) << "vertex " << i;
  }
  ASSERT_EQ(w.mesh.vertices.size(), first.size());
  EXPECT_EQ(w.merged, soup.vertices.size() - first.size());
  EXPECT_EQ(w.remap[5000] + 1, w.remap[5001]);  // NaN equals nothing, itself included
}

// The report's topology by definition, in the plainest way: a map from each edge to its uses,
// a search over each vertex's corners along shared edges, a set of sorted triples, a search
// over vertices along edges.
MeshReport brute_force_topology(const Mesh& m) {
  MeshReport r;
  std::map<std::pair<int, int>, std::vector<std::pair<std::size_t, bool>>> uses;
  std::set<int> referenced;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      referenced.insert(a);
      if (a != b) uses[{std::min(a, b), std::max(a, b)}].push_back({t, a < b});
    }
  }
  r.referenced_vertices = referenced.size();
  r.edges = uses.size();
  for (const auto& [edge, list] : uses) {
    r.border_edges += list.size() == 1;
    r.nonmanifold_edges += list.size() >= 3;
    r.inconsistent_edges += list.size() == 2 && list[0].second == list[1].second;
  }
  for (const int v : referenced) {
    // Corners at v: triangles holding v; two are joined when they share an edge at v (or are
    // the same triangle).
    std::vector<std::size_t> tris;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      if (std::count(m.triangles[t].begin(), m.triangles[t].end(), v) > 0) tris.push_back(t);
    std::vector<bool> seen(tris.size(), false);
    std::vector<std::size_t> stack{0};
    seen[0] = true;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      for (std::size_t j = 0; j < tris.size(); ++j) {
        if (seen[j]) continue;
        for (const auto& [edge, list] : uses) {
          if (edge.first != v && edge.second != v) continue;
          bool has_i = false, has_j = false;
          for (const auto& [t, forward] : list) {
            has_i = has_i || t == tris[i];
            has_j = has_j || t == tris[j];
          }
          if (has_i && has_j) {
            seen[j] = true;
            stack.push_back(j);
            break;
          }
        }
      }
    }
    if (std::find(seen.begin(), seen.end(), false) != seen.end()) r.pinch_vertices.push_back(v);
  }
  std::set<std::array<std::int32_t, 3>> triples;
  for (const TriangleIndices& t : m.triangles) {
    std::array<std::int32_t, 3> s = t;
    std::sort(s.begin(), s.end());
    r.duplicated_triangles += triples.insert(s).second ? 0 : 1;
  }
  std::set<int> left = referenced;
  while (!left.empty()) {
    ++r.components;
    std::vector<int> stack{*left.begin()};
    left.erase(left.begin());
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (const auto& [edge, list] : uses) {
        const int w = edge.first == v ? edge.second : edge.second == v ? edge.first : -1;
        if (w >= 0 && left.erase(w) > 0) stack.push_back(w);
      }
    }
  }
  return r;
}

TEST(MeshValidation, TopologyMatchesABruteForceCountOnRandomMeshes) {
  // Few vertices and many triangles: shared, non-manifold, inconsistent and border edges,
  // repeated indices, duplicates, pinches and isolated vertices all occur.
  std::mt19937_64 rng(27);
  for (int round = 0; round < 400; ++round) {
    const int nv = 3 + static_cast<int>(rng() % 10);
    const int nt = 1 + static_cast<int>(rng() % 16);
    Mesh m;
    for (int i = 0; i < nv; ++i)
      m.vertices.push_back({double(rng() % 5), double(rng() % 5), double(rng() % 5)});
    std::uniform_int_distribution<int> vertex(0, nv - 1);
    for (int t = 0; t < nt; ++t) {
      const int a = vertex(rng);
      const int b = rng() % 6 == 0 ? a : vertex(rng);
      m.triangles.push_back({a, b, vertex(rng)});
      if (rng() % 4 == 0) m.triangles.push_back({b, a, m.triangles.back()[2]});  // reversed
    }
    const MeshReport want = brute_force_topology(m);
    const MeshReport got = validate_mesh(m);
    SCOPED_TRACE("round " + std::to_string(round));
    EXPECT_EQ(got.referenced_vertices, want.referenced_vertices);
    EXPECT_EQ(got.edges, want.edges);
    EXPECT_EQ(got.border_edges, want.border_edges);
    EXPECT_EQ(got.nonmanifold_edges, want.nonmanifold_edges);
    EXPECT_EQ(got.inconsistent_edges, want.inconsistent_edges);
    EXPECT_EQ(got.pinch_vertices, want.pinch_vertices);
    EXPECT_EQ(got.duplicated_triangles, want.duplicated_triangles);
    EXPECT_EQ(got.components, want.components);
  }
}

TEST(MeshValidation, TorusSceneHasGenusOne) {
  const MeshReport r = validate_mesh(scenes::torus(1.0, 0.4, 30, 12));
  EXPECT_TRUE(r.watertight());
  EXPECT_EQ(r.genus, 1);
  EXPECT_TRUE(r.outward());
}

// vertices_distinct is the weld's question without the weld: it must agree with weld_vertices
// (merged == 0) on every vertex list, with duplicates at any distance apart, +0 against -0, NaN
// (equal to nothing) and many positions sharing coordinates.
TEST(VerticesDistinct, AgreesWithTheWeldOnRandomListsWithAndWithoutDuplicates) {
  std::mt19937_64 rng(2611);
  std::uniform_int_distribution<int> small(-3, 3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int with = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Mesh m;
    const int n = 1 + static_cast<int>(rng() % 3000);
    // Coarse coordinates: at this count some lists repeat a position, some do not.
    const double scale = trial % 2 == 0 ? 1.0 : 1e-3;
    for (int i = 0; i < n; ++i) {
      m.vertices.push_back(
          {scale * small(rng) + (trial % 4 == 1 ? i : 0), scale * small(rng), scale * small(rng)});
    }
    if (trial % 5 == 0) m.vertices.push_back({nan, 0, 0});
    if (trial % 7 == 0) m.vertices.push_back({nan, 0, 0});
    if (trial % 3 == 0) m.vertices.push_back({-0.0, 0.0, -0.0});
    if (trial % 6 == 0) m.vertices.push_back({0.0, -0.0, 0.0});
    const bool distinct = weld_vertices(m).merged == 0;
    with += distinct ? 0 : 1;
    EXPECT_EQ(vertices_distinct(m.vertices), distinct) << "trial " << trial;
  }
  EXPECT_GT(with, 0);
  EXPECT_LT(with, 400);
}

TEST(VerticesDistinct, SmallListsAndSignedZeros) {
  EXPECT_TRUE(vertices_distinct({}));
  EXPECT_TRUE(vertices_distinct(std::vector<Vec3>{{1, 2, 3}}));
  EXPECT_TRUE(vertices_distinct(std::vector<Vec3>{{1, 2, 3}, {1, 2, 4}}));
  EXPECT_FALSE(vertices_distinct(std::vector<Vec3>{{0.0, 1, 2}, {-0.0, 1, 2}}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(vertices_distinct(std::vector<Vec3>{{nan, 1, 2}, {nan, 1, 2}}));
  // The last vertex repeats the first, far apart in the list.
  std::vector<Vec3> far;
  for (int i = 0; i < 100000; ++i)
    far.push_back({static_cast<double>(i), 0.5 * i, -0.25 * i});
  EXPECT_TRUE(vertices_distinct(far));
  far.push_back(far.front());
  EXPECT_FALSE(vertices_distinct(far));
}

}  // namespace
}  // namespace contain
