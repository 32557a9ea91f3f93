// validate_mesh first tries a quick proof that a mesh is a closed, oriented 2-manifold without
// duplicates, and falls back to the full analysis at the first sign of anything else: its
// reports must be those of the full analysis, field by field, on meshes of each kind.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <utility>
#include <vector>

#include "contain/shapes/mesh_validation.h"
#include "scenes/scenes.h"

namespace contain {
namespace {

// `proven_quickly`: whether the quick proof itself must hold (closed, oriented, no pinch, no
// duplicate) or must give way to the full analysis.
void expect_same_report(const Mesh& m, const std::string& what, bool proven_quickly) {
  SCOPED_TRACE(what);
  EXPECT_EQ(shapes::detail::topology_proven_quickly(m), proven_quickly);
  const MeshReport got = validate_mesh(m);
  const MeshReport want = shapes::detail::validate_mesh_in_full(m);
  EXPECT_EQ(got.vertices, want.vertices);
  EXPECT_EQ(got.referenced_vertices, want.referenced_vertices);
  EXPECT_EQ(got.triangles, want.triangles);
  EXPECT_EQ(got.edges, want.edges);
  EXPECT_EQ(got.border_edges, want.border_edges);
  EXPECT_EQ(got.nonmanifold_edges, want.nonmanifold_edges);
  EXPECT_EQ(got.inconsistent_edges, want.inconsistent_edges);
  EXPECT_EQ(got.degenerate_triangles, want.degenerate_triangles);
  EXPECT_EQ(got.duplicated_triangles, want.duplicated_triangles);
  EXPECT_EQ(got.pinch_vertices, want.pinch_vertices);
  EXPECT_EQ(got.components, want.components);
  EXPECT_EQ(got.euler_characteristic, want.euler_characteristic);
  EXPECT_EQ(got.genus, want.genus);
  EXPECT_EQ(got.signed_volume, want.signed_volume);
  EXPECT_EQ(got.summary(), want.summary());
}

TEST(MeshValidationQuick, ClosedOrientedMeshesReportAsTheFullAnalysis) {
  expect_same_report(scenes::torus(1.0, 0.4, 30, 12), "torus", true);
  expect_same_report(scenes::uv_sphere({0, 0, 0}, 1.0, 8, 12), "sphere, poles of valence 12", true);
  expect_same_report(
      scenes::joined(scenes::torus(1.0, 0.4, 8, 6), scenes::uv_sphere({5, 0, 0}, 1, 4, 5)),
      "two components", true);
  Mesh unused = scenes::torus(1.0, 0.4, 8, 6);
  unused.vertices.push_back({9, 9, 9});
  expect_same_report(unused, "an unreferenced vertex", true);
}

TEST(MeshValidationQuick, InsideOutAndFlippedMeshesReportAsTheFullAnalysis) {
  Mesh inside_out = scenes::torus(1.0, 0.4, 10, 8);
  for (TriangleIndices& t : inside_out.triangles)
    std::swap(t[1], t[2]);
  expect_same_report(inside_out, "every triangle flipped (still consistent)", true);
  Mesh one_flipped = scenes::torus(1.0, 0.4, 10, 8);
  std::swap(one_flipped.triangles[7][0], one_flipped.triangles[7][1]);
  expect_same_report(one_flipped, "one triangle flipped", false);
}

TEST(MeshValidationQuick, OpenNonManifoldAndDuplicatedMeshesReportAsTheFullAnalysis) {
  Mesh open = scenes::torus(1.0, 0.4, 10, 8);
  open.triangles.pop_back();
  expect_same_report(open, "a missing triangle", false);
  Mesh fin = scenes::torus(1.0, 0.4, 10, 8);
  fin.vertices.push_back({3, 3, 3});
  fin.triangles.push_back({fin.triangles[0][0], fin.triangles[0][1],
                           static_cast<std::int32_t>(fin.vertices.size() - 1)});
  expect_same_report(fin, "a fin on an edge: three triangles, one direction twice", false);
  Mesh same = scenes::torus(1.0, 0.4, 10, 8);
  same.triangles.push_back(same.triangles[3]);
  expect_same_report(same, "a triangle repeated in the same orientation", false);
  Mesh pillow = scenes::torus(1.0, 0.4, 10, 8);
  pillow.vertices.insert(pillow.vertices.end(), {{5, 0, 0}, {6, 0, 0}, {5, 1, 0}});
  const auto v = static_cast<std::int32_t>(pillow.vertices.size() - 3);
  pillow.triangles.push_back({v, v + 1, v + 2});
  pillow.triangles.push_back({v, v + 2, v + 1});
  expect_same_report(pillow, "a triangle and its reverse: closed, oriented, duplicated", false);
  Mesh repeated_index = scenes::torus(1.0, 0.4, 10, 8);
  repeated_index.triangles[5][2] = repeated_index.triangles[5][0];
  expect_same_report(repeated_index, "a repeated index", false);
}

TEST(MeshValidationQuick, PinchVerticesReportAsTheFullAnalysis) {
  // Two tori welded at one vertex: every edge matched, oriented, but that vertex has two fans.
  const Mesh a = scenes::torus(1.0, 0.4, 10, 8);
  Mesh both = scenes::joined(a, a);
  const auto n = static_cast<std::int32_t>(a.vertices.size());
  for (TriangleIndices& t : both.triangles)
    for (std::int32_t& v : t)
      if (v == n) v = 0;
  expect_same_report(both, "a pinch vertex", false);
  Mesh cone_twice;  // two cones sharing their apex, each closed by a fan at its base
  cone_twice.vertices = {{0, 0, 0},  {1, 0, 1},  {0, 1, 1},   {-1, -1, 1},
                         {1, 0, -1}, {0, 1, -1}, {-1, -1, -1}};
  cone_twice.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2},
                          {0, 5, 4}, {0, 6, 5}, {0, 4, 6}, {4, 5, 6}};
  expect_same_report(cone_twice, "two tetrahedra sharing a vertex", false);
}

TEST(MeshValidationQuick, EmptyAndSingleTriangleMeshes) {
  expect_same_report(Mesh{}, "empty (no edge to match: closed, as the full analysis says)", true);
  Mesh one;
  one.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  one.triangles = {{0, 1, 2}};
  expect_same_report(one, "one triangle", false);
}

// Random damage (a triangle removed, repeated, flipped, turned or rewired to another vertex) to
// meshes whose vertices have few corners and many (poles of valence 20 and 40): the quick proof
// holds exactly when the full analysis finds a closed, oriented 2-manifold without duplicates, and
// the reports agree field by field.
TEST(MeshValidationQuick, RandomlyDamagedMeshesReportAsTheFullAnalysis) {
  std::mt19937 rng(27);
  const std::vector<std::pair<Mesh, std::string>> bases{
      {scenes::torus(1.0, 0.4, 12, 7), "torus"},
      {scenes::uv_sphere({0, 0, 0}, 1.0, 6, 20), "sphere, poles of valence 20"},
      {scenes::uv_sphere({0, 0, 0}, 1.0, 5, 40), "sphere, poles of valence 40"}};
  for (const auto& [base, name] : bases) {
    for (int round = 0; round < 60; ++round) {
      Mesh m = base;
      auto any = [&](std::size_t n) {
        return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
      };
      const int damages = static_cast<int>(any(3));
      for (int d = 0; d < damages; ++d) {
        const std::size_t t = any(m.triangles.size());
        switch (any(5)) {
          case 0:
            m.triangles.erase(m.triangles.begin() + static_cast<std::ptrdiff_t>(t));
            break;
          case 1:
            m.triangles.push_back(m.triangles[t]);
            break;
          case 2:
            std::swap(m.triangles[t][1], m.triangles[t][2]);
            break;
          case 3:
            m.triangles.push_back({m.triangles[t][0], m.triangles[t][2], m.triangles[t][1]});
            break;
          default:
            m.triangles[t][any(3)] = static_cast<std::int32_t>(any(m.vertices.size()));
            break;
        }
      }
      const MeshReport full = shapes::detail::validate_mesh_in_full(m);
      const bool proven = full.closed() && full.manifold() && full.consistently_oriented() &&
                          full.duplicated_triangles == 0 && full.pinch_vertices.empty();
      expect_same_report(m, name + ", round " + std::to_string(round), proven);
    }
  }
}

}  // namespace
}  // namespace contain
