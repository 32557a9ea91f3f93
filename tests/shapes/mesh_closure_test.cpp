#include "contain/shapes/mesh_closure.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "scenes/scenes.h"

namespace contain {
namespace {

Mesh unit_box() {
  return scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}});
}

TEST(MeshClosure, BoxAndTorusAreClosed) {
  EXPECT_FALSE(unmatched_edge(unit_box()).has_value());
  EXPECT_FALSE(unmatched_edge(scenes::torus(2.0, 0.5, 24, 12)).has_value());
}

TEST(MeshClosure, EmptyMeshIsTheClosedEmptySolid) {
  EXPECT_FALSE(unmatched_edge(Mesh{}).has_value());
}

TEST(MeshClosure, RemovedTriangleNamesTheFirstEdgeOfTheHole) {
  Mesh m = unit_box();
  const TriangleIndices gone = m.triangles[3];
  m.triangles.erase(m.triangles.begin() + 3);
  const std::optional<UnmatchedEdge> e = unmatched_edge(m);
  ASSERT_TRUE(e.has_value());
  // The hole's rim is the removed triangle's edges, each left without its reverse.
  EXPECT_EQ(e->count, 1);
  EXPECT_EQ(e->reverse, 0);
  bool on_rim = false;
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = m.vertex(gone[static_cast<std::size_t>(k)]);
    const Vec3 b = m.vertex(gone[static_cast<std::size_t>((k + 1) % 3)]);
    on_rim = on_rim || (e->from == b && e->to == a);
  }
  EXPECT_TRUE(on_rim);
  const TriangleIndices& t = m.triangles[static_cast<std::size_t>(e->triangle)];
  int corners_on_edge = 0;
  for (const std::int32_t v : t) {
    corners_on_edge += (m.vertex(v) == e->from || m.vertex(v) == e->to) ? 1 : 0;
  }
  EXPECT_EQ(corners_on_edge, 2);
}

TEST(MeshClosure, FlippedTriangleUnbalancesItsEdges) {
  Mesh m = unit_box();
  std::swap(m.triangles[0][1], m.triangles[0][2]);
  const std::optional<UnmatchedEdge> e = unmatched_edge(m);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->count, 2);
  EXPECT_EQ(e->reverse, 0);
  EXPECT_EQ(e->triangle, 0);
}

TEST(MeshClosure, TwoBoxesSharingAnEdgeAreClosedThoughNotManifold) {
  const Mesh m = scenes::joined(unit_box(), scenes::box_mesh(Box3{{1, 1, 0}, {2, 2, 1}}));
  EXPECT_FALSE(unmatched_edge(m).has_value());
}

TEST(MeshClosure, PairedHalfEdgesRunTheOtherWayAlongTheSameEdge) {
  // A torus (every edge manifold), two boxes sharing an edge (four uses: no pair there), and a
  // triangle with a repeated corner (its edge and reverse in one triangle: no pair).
  const Mesh torus = scenes::torus(2.0, 0.5, 24, 12);
  Mesh pair_of_boxes = unit_box();
  const Mesh second = scenes::box_mesh(Box3{{1, 1, 0}, {2, 2, 1}});
  const auto offset = static_cast<std::int32_t>(pair_of_boxes.vertices.size());
  pair_of_boxes.vertices.insert(pair_of_boxes.vertices.end(), second.vertices.begin(),
                                second.vertices.end());
  for (TriangleIndices t : second.triangles)
    pair_of_boxes.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  Mesh folded = unit_box();
  folded.triangles.push_back({0, 0, 1});
  for (const Mesh* mesh : std::initializer_list<const Mesh*>{&torus, &pair_of_boxes, &folded}) {
    const Mesh welded = weld_vertices(*mesh).mesh;
    const auto twin = paired_half_edges(welded);
    ASSERT_TRUE(twin.has_value());
    ASSERT_EQ(twin->size(), 3 * welded.triangles.size());
    // Each undirected edge's uses, counted by brute force.
    std::map<std::pair<std::int32_t, std::int32_t>, int> uses;
    const auto half = [&](std::size_t h) {
      const TriangleIndices& t = welded.triangles[h / 3];
      return std::pair{t[h % 3], t[(h + 1) % 3]};
    };
    for (std::size_t h = 0; h < twin->size(); ++h) {
      const auto [a, b] = half(h);
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
    std::size_t paired = 0;
    for (std::size_t h = 0; h < twin->size(); ++h) {
      const auto [a, b] = half(h);
      const bool manifold = a != b && uses[{std::min(a, b), std::max(a, b)}] == 2 &&
                            welded.triangles[h / 3][0] != welded.triangles[h / 3][1] &&
                            welded.triangles[h / 3][1] != welded.triangles[h / 3][2] &&
                            welded.triangles[h / 3][2] != welded.triangles[h / 3][0];
      const std::int32_t g = (*twin)[h];
      if (!manifold) {
        EXPECT_EQ(g, -1) << "half-edge " << h;
        continue;
      }
      ASSERT_GE(g, 0) << "half-edge " << h;
      EXPECT_EQ(half(static_cast<std::size_t>(g)), std::pair(b, a));
      EXPECT_EQ((*twin)[static_cast<std::size_t>(g)], static_cast<std::int32_t>(h));
      ++paired;
    }
    EXPECT_GT(paired, 0U);
  }
  // Open: nothing, and unmatched_edge names the edge.
  Mesh open = unit_box();
  open.triangles.pop_back();
  EXPECT_FALSE(paired_half_edges(open).has_value());
  EXPECT_TRUE(unmatched_edge(open).has_value());
}

TEST(MeshClosure, AnswerFromWeldedArraysIsTheAnswerFromTheMesh) {
  // The mesh booleans' soup holds several inputs' welded vertices and triangles: the span form
  // on one input's triangles gives the edge unmatched_edge gives on that input alone.
  Mesh box = unit_box();
  box.triangles.erase(box.triangles.begin() + 3);
  const WeldResult weld = weld_vertices(box);
  std::vector<Vec3> vertices = weld.mesh.vertices;
  vertices.push_back({5, 5, 5});  // another input's vertex, referenced by none of these
  const auto edge = unmatched_edge(box);
  const auto from_arrays = unmatched_edge(vertices, weld.mesh.triangles);
  ASSERT_TRUE(edge.has_value());
  ASSERT_TRUE(from_arrays.has_value());
  EXPECT_TRUE(from_arrays->from == edge->from && from_arrays->to == edge->to);
  EXPECT_EQ(from_arrays->triangle, edge->triangle);
  EXPECT_EQ(from_arrays->count, edge->count);
  EXPECT_EQ(from_arrays->reverse, edge->reverse);
  EXPECT_FALSE(unmatched_edge(weld_vertices(unit_box()).mesh.vertices,
                              weld_vertices(unit_box()).mesh.triangles)
                   .has_value());
}

TEST(MeshClosure, UnweldedCopyIsJudgedByPosition) {
  const Mesh box = unit_box();
  Mesh soup;  // every triangle with its own three vertices, as an STL file stores them
  for (std::size_t t = 0; t < box.triangles.size(); ++t) {
    const Triangle3 tri = box.triangle(t);
    const auto base = static_cast<std::int32_t>(soup.vertices.size());
    soup.vertices.insert(soup.vertices.end(), {tri.a, tri.b, tri.c});
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  EXPECT_FALSE(unmatched_edge(soup).has_value());
  EXPECT_FALSE(unmatched_edge(weld_vertices(soup)).has_value());
  soup.triangles.pop_back();
  const auto edge = unmatched_edge(soup);
  ASSERT_TRUE(edge.has_value());
  // The answer from the welded mesh, which slicing reuses, is the same edge.
  const auto from_weld = unmatched_edge(weld_vertices(soup));
  ASSERT_TRUE(from_weld.has_value());
  EXPECT_TRUE(from_weld->from == edge->from && from_weld->to == edge->to);
  EXPECT_EQ(from_weld->triangle, edge->triangle);
  EXPECT_EQ(from_weld->count, edge->count);
  EXPECT_EQ(from_weld->reverse, edge->reverse);
}

TEST(MeshClosure, ClosednessMatchesACountOfEveryDirectedEdgeOnRandomMeshes) {
  // Random triangles over few vertices (repeated corners, doubled and reversed triangles, edges
  // used by many triangles), then each made closed by adding its reverse: the quick balance test
  // and the full search agree with a plain count of directed edges.
  std::mt19937_64 rng(26);
  std::uniform_int_distribution<std::int32_t> vertex(0, 7);
  for (int round = 0; round < 300; ++round) {
    Mesh mesh;
    for (int i = 0; i < 8; ++i)
      mesh.vertices.push_back({static_cast<double>(i), static_cast<double>(i * i), 0.0});
    const int n = 1 + round % 9;
    for (int t = 0; t < n; ++t)
      mesh.triangles.push_back({vertex(rng), vertex(rng), vertex(rng)});
    if (round % 2 == 1) {
      for (int t = 0; t < n; ++t) {
        const TriangleIndices f = mesh.triangles[static_cast<std::size_t>(t)];
        mesh.triangles.push_back({f[0], f[2], f[1]});
      }
    }
    std::map<std::pair<std::int32_t, std::int32_t>, int> count;
    for (const TriangleIndices& f : mesh.triangles) {
      for (std::size_t k = 0; k < 3; ++k) {
        if (f[k] != f[(k + 1) % 3]) ++count[{f[k], f[(k + 1) % 3]}];
      }
    }
    bool closed = true;
    for (const auto& [edge, uses] : count) {
      const auto reverse = count.find({edge.second, edge.first});
      closed = closed && reverse != count.end() && reverse->second == uses;
    }
    const auto edge = unmatched_edge(weld_vertices(mesh));
    ASSERT_EQ(edge.has_value(), !closed) << "round " << round;
    if (edge) {
      EXPECT_NE(edge->count, edge->reverse);
    }
  }
}

TEST(MeshClosure, DegenerateTriangleWithARepeatedCornerIsNeutral) {
  Mesh m = unit_box();
  m.triangles.push_back({0, 0, 1});
  EXPECT_FALSE(unmatched_edge(m).has_value());
}

TEST(MeshClosure, DoubledShellIsClosed) {
  Mesh m = unit_box();
  const std::size_t n = m.triangles.size();
  for (std::size_t t = 0; t < n; ++t)
    m.triangles.push_back(m.triangles[t]);
  EXPECT_FALSE(unmatched_edge(m).has_value());
  m.triangles.pop_back();
  const std::optional<UnmatchedEdge> e = unmatched_edge(m);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->count, 2);
  EXPECT_EQ(e->reverse, 1);
}

}  // namespace
}  // namespace contain
