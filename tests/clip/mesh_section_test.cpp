// The section of a mesh by a plane: closed loops on the plane for closed meshes, exact sides.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <tuple>
#include <vector>

#include "contain/clip/mesh_clip.h"
#include "scenes/scenes.h"

namespace contain::test {
namespace {

// Every segment's end starts exactly one other segment: the segments chain into closed loops.
void expect_closed_loops(const std::vector<Segment3>& segments) {
  std::map<std::tuple<double, double, double>, int> balance;
  for (const Segment3& s : segments) {
    ++balance[{s.a.x, s.a.y, s.a.z}];
    --balance[{s.b.x, s.b.y, s.b.z}];
  }
  for (const auto& [point, count] : balance)
    EXPECT_EQ(count, 0) << std::get<0>(point) << " " << std::get<1>(point) << " "
                        << std::get<2>(point);
}

double length(const std::vector<Segment3>& segments) {
  double total = 0;
  for (const Segment3& s : segments)
    total += std::sqrt(dot(s.b - s.a, s.b - s.a));
  return total;
}

TEST(MeshSection, CubeByAxisPlaneIsOneSquareLoopExactlyOnThePlane) {
  const Mesh cube = scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}});
  const std::vector<Segment3> s = clip::mesh_section(cube, {0, 0, -1, 0.3});
  ASSERT_FALSE(s.empty());
  for (const Segment3& e : s) {
    EXPECT_EQ(e.a.z, 0.3);
    EXPECT_EQ(e.b.z, 0.3);
  }
  expect_closed_loops(s);
  EXPECT_NEAR(length(s), 4.0, 1e-12);
}

TEST(MeshSection, TorusByPlaneThroughTheTubeIsTwoClosedCircles) {
  const Mesh torus = scenes::torus(2.0, 0.6, 96, 48);
  const std::vector<Segment3> s = clip::mesh_section(torus, {0, 0, 1, 0});
  expect_closed_loops(s);
  // Two polygons inscribed in the circles of radius 1.4 and 2.6 (z = 0 holds a ring of vertices).
  EXPECT_NEAR(length(s), 2 * std::numbers::pi * 4.0, 0.01);
  for (const Segment3& e : s)
    EXPECT_EQ(e.a.z, 0.0);
}

TEST(MeshSection, PlaneMissingTheMeshGivesNoSegments) {
  const Mesh cube = scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}});
  EXPECT_TRUE(clip::mesh_section(cube, {0, 0, 1, -2}).empty());
  EXPECT_TRUE(clip::mesh_section(cube, {0, 0, -1, 2}).empty());
}

TEST(MeshSection, ClosedMeshTouchingThePlaneAlongAFaceHasNoBorderThere) {
  const Mesh cube = scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}});
  // z <= 1 keeps the whole cube (the top face looks out of the half-space): no border.
  EXPECT_TRUE(clip::mesh_section(cube, {0, 0, -1, 1}).empty());
  // z >= 1 keeps nothing (the top face looks into the half-space).
  EXPECT_TRUE(clip::mesh_section(cube, {0, 0, 1, -1}).empty());
}

TEST(MeshSection, OpenTriangleGivesOneSegment) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  m.triangles = {{0, 1, 2}};
  const std::vector<Segment3> s = clip::mesh_section(m, {-1, 0, 0, 1});  // x <= 1
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].a.x, 1.0);
  EXPECT_EQ(s[0].b.x, 1.0);
  EXPECT_NEAR(length(s), 1.0, 1e-15);
}

}  // namespace
}  // namespace contain::test
