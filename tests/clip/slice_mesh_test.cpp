// Sections of solids by planes, and shadows, against the exact oracle of support/slice_oracle.h.

#include "contain/clip/slice_mesh.h"

#include "contain/clip/polygon_boolean.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <tuple>
#include <vector>

#include "clip/boolean_checks.h"
#include "clip/slice/stages.h"
#include "clip/slice_meshes.h"
#include "contain/inside/point_in_polygon.h"
#include "contain/predicates/rounded_crossing.h"
#include "contain/shapes/mesh_closure.h"
#include "scenes/scenes.h"
#include "support/case_budget.h"
#include "support/slice_oracle.h"

namespace contain::test {
namespace {

using clip::Axis;
using clip::Section;

double coord(Vec3 p, int i) {
  return i == 0 ? p.x : (i == 1 ? p.y : p.z);
}
Vec2 project(Vec3 p, int axis) {
  return {coord(p, (axis + 1) % 3), coord(p, (axis + 2) % 3)};
}

std::vector<Section> slice(const Mesh& mesh, const std::vector<double>& values, Axis axis,
                           int threads = 1) {
  auto result = clip::slice_mesh(mesh, values, {.axis = axis}, {.threads = threads});
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().what());
  return result.ok() ? std::move(result).value() : std::vector<Section>{};
}
Section slice_one(const Mesh& mesh, double c, Axis axis = Axis::z) {
  const std::vector<Section> s = slice(mesh, {c}, axis);
  return s.empty() ? Section{} : s.front();
}

Box2 projected_box(const Mesh& mesh, int axis) {
  Box2 box;
  for (const Vec3& v : mesh.vertices)
    box.expand(project(v, axis));
  return box;
}

// Sample points of the plane: where the oracle says the 3D point is an interior point of the
// solid, the section holds it, and nowhere else (points exactly on the computed boundary, within
// rounding of the exact one, are skipped).
void expect_matches_oracle(const Mesh& mesh, int axis, const Section& section, int samples,
                           std::uint64_t seed) {
  const Box2 box = projected_box(mesh, axis);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(box.min.x - 0.1, box.max.x + 0.1);
  std::uniform_real_distribution<double> uy(box.min.y - 0.1, box.max.y + 0.1);
  int inside = 0;
  for (int i = 0; i < samples; ++i) {
    const Vec2 p{ux(rng), uy(rng)};
    const Location got = inside::point_in_polygon(section.region, p);
    if (got == Location::boundary) continue;
    const bool expected = oracle_in_section(mesh, axis, p, section.value);
    inside += expected ? 1 : 0;
    ASSERT_EQ(got == Location::inside, expected)
        << "plane " << section.value << " axis " << axis << " point " << p.x << " " << p.y;
  }
  (void)inside;
}

// The exact intersection of triangle t with the plane, in the plane's coordinates: the two
// extreme points of its vertices on the plane and its edges' crossings.
std::vector<Vec2> exact_cut(const Triangle3& t, int axis, double c) {
  const Vec3 p[3] = {t.a, t.b, t.c};
  std::vector<Vec2> out;
  for (int i = 0; i < 3; ++i) {
    const Vec3 a = p[i];
    const Vec3 b = p[(i + 1) % 3];
    if (coord(a, axis) == c) out.push_back(project(a, axis));
    if ((coord(a, axis) - c) * (coord(b, axis) - c) < 0) {
      const QPoint2 q = oracle_crossing(a, b, axis, c);
      out.push_back({q.u.get_d(), q.v.get_d()});
    }
  }
  return out;
}

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len2 = d.x * d.x + d.y * d.y;
  const double t =
      len2 > 0 ? std::clamp(((p.x - a.x) * d.x + (p.y - a.y) * d.y) / len2, 0.0, 1.0) : 0.0;
  const Vec2 q = a + t * d;
  return std::hypot(p.x - q.x, p.y - q.y);
}

// Provenance, edge by edge: both ends of every output edge lie on the exact cut of its triangle
// by the plane, within the rounding of the section's vertices (a few ulps of the coordinates).
void expect_provenance(const Mesh& mesh, int axis, const Section& section) {
  const std::vector<Ring> rings = section.region.all_rings();
  ASSERT_EQ(section.triangles.size(), rings.size());
  double scale = 1e-300;
  for (const Vec3& v : mesh.vertices)
    scale = std::max(scale, std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}));
  const double tolerance = 64 * scale * std::numeric_limits<double>::epsilon();
  for (std::size_t r = 0; r < rings.size(); ++r) {
    ASSERT_EQ(section.triangles[r].size(), rings[r].size());
    for (std::size_t k = 0; k < rings[r].size(); ++k) {
      const std::int32_t t = section.triangles[r][k];
      ASSERT_GE(t, 0);
      ASSERT_LT(static_cast<std::size_t>(t), mesh.triangles.size());
      const std::vector<Vec2> cut =
          exact_cut(mesh.triangle(static_cast<std::size_t>(t)), axis, section.value);
      ASSERT_GE(cut.size(), 2U) << "triangle " << t << " does not meet the plane";
      for (const Vec2 end : {rings[r][k], rings[r][(k + 1) % rings[r].size()]}) {
        EXPECT_LE(distance_to_segment(end, cut[0], cut[1]), tolerance)
            << "edge " << k << " of ring " << r << " is not on triangle " << t;
      }
    }
  }
}

void expect_section_right(const Mesh& mesh, int axis, const Section& section, int samples,
                          std::uint64_t seed) {
  EXPECT_TRUE(is_valid_ogc(section.region)) << "plane " << section.value;
  expect_matches_oracle(mesh, axis, section, samples, seed);
  expect_provenance(mesh, axis, section);
}

mpq_class area(const MultiPolygon& region) {
  return exact_signed_area(region);
}

TEST(SliceMesh, BoxCutInsideIsItsSquareExactly) {
  const Mesh box = scenes::box_mesh(Box3{{0, 0, 0}, {1, 2, 3}});
  const Section s = slice_one(box, 0.7);
  ASSERT_EQ(s.region.polygons.size(), 1U);
  ASSERT_EQ(s.region.polygons[0].rings.size(), 1U);
  EXPECT_EQ(area(s.region), 2);
  EXPECT_GT(signed_area2(s.region.polygons[0].rings[0]), 0) << "shells run counter-clockwise";
  expect_section_right(box, 2, s, 200, 1);
}

TEST(SliceMesh, BoxCutAtItsTopOrBottomFaceIsEmpty) {
  const Mesh box = scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}});
  EXPECT_TRUE(slice_one(box, 1.0).region.empty());
  EXPECT_TRUE(slice_one(box, 0.0).region.empty());
  EXPECT_TRUE(slice_one(box, 1.5).region.empty());
  EXPECT_TRUE(slice_one(box, -1e-300).region.empty());
}

TEST(SliceMesh, TwoStackedBoxesCutAtTheSharedFaceGiveTheSquare) {
  const Mesh stacked = joined(scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}}),
                              scenes::box_mesh(Box3{{0, 0, 1}, {1, 1, 2}}));
  const Section s = slice_one(stacked, 1.0);
  EXPECT_EQ(area(s.region), 1);
  ASSERT_EQ(s.region.polygons.size(), 1U);
  expect_section_right(stacked, 2, s, 200, 2);
  // Boxes offset at the shared plane: the section is where both touch it, the overlap.
  const Mesh offset = joined(scenes::box_mesh(Box3{{0, 0, 0}, {2, 2, 1}}),
                             scenes::box_mesh(Box3{{1, 1, 1}, {3, 3, 2}}));
  const Section o = slice_one(offset, 1.0);
  EXPECT_EQ(area(o.region), 1);
  expect_section_right(offset, 2, o, 300, 3);
}

TEST(SliceMesh, OverlappingCubesInOneFileCountOnce) {
  const Mesh two = joined(scenes::box_mesh(Box3{{0, 0, 0}, {2, 2, 2}}),
                          scenes::box_mesh(Box3{{1, 1, 1}, {3, 3, 3}}));
  for (const double c : {0.5, 1.0, 1.5, 2.0, 2.5}) {
    const Section s = slice_one(two, c);
    // At z = 1 and 2 one cube touches the plane from one side only: it adds nothing.
    EXPECT_EQ(area(s.region), c <= 1 || c >= 2 ? 4 : 7) << c;
    expect_section_right(two, 2, s, 200, 4);
  }
}

TEST(SliceMesh, NestedShellsCountOnceAndAnInsideOutShellSubtracts) {
  const Mesh outer = scenes::box_mesh(Box3{{0, 0, 0}, {4, 4, 4}});
  const Mesh inner = scenes::box_mesh(Box3{{1, 1, 1}, {3, 3, 3}});
  const Section nested = slice_one(joined(outer, inner), 2.0);
  EXPECT_EQ(area(nested.region), 16);
  const Mesh hollow = joined(outer, inner, true);
  const Section h = slice_one(hollow, 2.0);
  EXPECT_EQ(area(h.region), 12);
  ASSERT_EQ(h.region.polygons.size(), 1U);
  EXPECT_EQ(h.region.polygons[0].rings.size(), 2U) << "a square with a square hole";
  expect_section_right(hollow, 2, h, 300, 5);
  // At the cavity's floor and ceiling its points are inside on one side only: not interior
  // points, so the section has the hole there too.
  for (const double c : {1.0, 3.0}) {
    const Section f = slice_one(hollow, c);
    EXPECT_EQ(area(f.region), 12) << c;
    expect_section_right(hollow, 2, f, 300, 6);
  }
}

TEST(SliceMesh, HollowSphereGivesAnnuliMatchingTheOracle) {
  const Mesh hollow =
      joined(uv_sphere({0, 0, 0}, 2.0, 16, 24), uv_sphere({0.1, 0, 0}, 1.0, 12, 18), true);
  EXPECT_EQ(oracle_side_windings(hollow, 2, {0.05, 0.01}, 0.0).above, 0);
  EXPECT_EQ(oracle_side_windings(hollow, 2, {1.5, 0.01}, 0.0).above, 1);
  const std::vector<double> values{-1.9, -0.5, 0.0, 0.3, 0.77, 1.5};
  const std::vector<Section> sections = slice(hollow, values, Axis::z);
  ASSERT_EQ(sections.size(), values.size());
  for (const Section& s : sections)
    expect_section_right(hollow, 2, s, case_budget(300, 5), 7);
  // The equator passes through a ring of vertices: still one annulus.
  ASSERT_EQ(sections[2].region.polygons.size(), 1U);
  EXPECT_EQ(sections[2].region.polygons[0].rings.size(), 2U);
}

TEST(SliceMesh, TorusCutBothWaysMatchesTheOracle) {
  const Mesh torus = scenes::torus(2.0, 0.6, 24, 12);
  for (const Axis axis : {Axis::z, Axis::x, Axis::y}) {
    const int k = static_cast<int>(axis);
    std::vector<double> values{-0.55, -0.3, 0.0, 0.123, 0.6};
    if (axis != Axis::z) values.insert(values.end(), {-2.0, 1.4, 2.1, 2.6});
    const std::vector<Section> sections = slice(torus, values, axis);
    for (const Section& s : sections)
      expect_section_right(torus, k, s, case_budget(200, 5), 8);
  }
  // Across the hole: two discs; through the axis plane z = 0: an annulus.
  EXPECT_EQ(slice_one(torus, 0.0, Axis::x).region.polygons.size(), 2U);
  const Section flat = slice_one(torus, 0.0, Axis::z);
  ASSERT_EQ(flat.region.polygons.size(), 1U);
  EXPECT_EQ(flat.region.polygons[0].rings.size(), 2U);
}

TEST(SliceMesh, LatticeStaircaseWithFacesOnEveryPlaneMatchesTheOracle) {
  const Mesh stairs = voxel_mesh(5, [](int i, int j, int k) { return k <= i && (j + k) % 5 != 4; });
  for (const Axis axis : {Axis::z, Axis::x, Axis::y}) {
    const int k = static_cast<int>(axis);
    std::vector<double> values;
    for (int v = -1; v <= 6; ++v) {
      values.push_back(v);
      values.push_back(v + 0.5);
    }
    const std::vector<Section> sections = slice(stairs, values, axis);
    for (const Section& s : sections)
      expect_section_right(stairs, k, s, case_budget(150, 5), 9);
  }
  // At z = 2 the treads of layer k = 1 are touched from below only, the gaps of layer 2 from
  // above only: the section is the unit squares filled in both layers, i >= 2 and j not 2 or 3.
  EXPECT_EQ(area(slice_one(stairs, 2.0).region), 9);
}

TEST(SliceMesh, PlanesThroughVerticesAndAlongEdgesOfRotatedCubes) {
  // Overlapping rotated cubes: section edges cross at new points, rounded and snapped by the 2D
  // engine, and provenance must still name the triangle each edge runs along.
  const Mesh a = rotated_cube({0, 0, 0}, 1.0, 0.3, 0.2);
  const Mesh b = rotated_cube({0.7, 0.4, 0.1}, 0.9, 1.1, -0.4);
  const Mesh both = joined(a, b);
  std::vector<double> values{-0.9, -0.31, 0.0, 0.2, 0.45, 0.93};
  for (const Vec3& v : both.vertices)
    values.push_back(v.z);  // planes through every vertex
  const std::vector<Section> sections = slice(both, values, Axis::z);
  int new_points = 0;  // vertices that are neither a mesh vertex nor an edge's crossing
  for (const Section& s : sections) {
    expect_section_right(both, 2, s, case_budget(150, 5), 10);
    std::vector<Vec2> curve_points;
    for (std::size_t t = 0; t < both.triangles.size(); ++t) {
      const Triangle3 tri = both.triangle(t);
      const Vec3 p[3] = {tri.a, tri.b, tri.c};
      for (int i = 0; i < 3; ++i) {
        const Vec3 u = p[i];
        const Vec3 w = p[(i + 1) % 3];
        if (u.z == s.value) curve_points.push_back({u.x, u.y});
        if ((u.z - s.value) * (w.z - s.value) < 0) {
          const Vec3 x = predicates::rounded_axis_crossing(u, w, 2, s.value);
          curve_points.push_back({x.x, x.y});
        }
      }
    }
    for (const Ring& ring : s.region.all_rings()) {
      for (const Vec2 q : ring) {
        if (std::find(curve_points.begin(), curve_points.end(), q) == curve_points.end()) {
          ++new_points;
        }
      }
    }
  }
  EXPECT_GT(new_points, 0) << "the cubes' sections cross: the engine made points of its own";
}

TEST(SliceMesh, ProvenanceOfEdgesBetweenRoundedPointsIsTheSegmentTheyRunAlong) {
  // Two segments of triangles 7 and 3 crossing at a point that is no double; the engine's edge
  // from one rounded crossing to a point a few ulps off segment 7's line, made by snapping,
  // lies on neither exactly: it takes the segment it runs along, 7, not the lower index.
  const std::vector<clip::slice::CrossingSegment> segments{
      {1, 2, {0.0, 0.0}, {3.0, 1.0}, 7},
      {3, 4, {0.0, 1.0}, {1.0, -2.0}, 3},
  };
  const Vec2 on7{1.5, std::nextafter(0.5, 1.0)};
  const Vec2 crossing{0.6, std::nextafter(0.2, 0.0)};
  MultiPolygon region;
  region.polygons.push_back({{{crossing, on7, {3.0, 1.0}, {0.0, 1.0}}}});
  const auto triangles = clip::slice::edge_triangles(region, segments);
  ASSERT_EQ(triangles.size(), 1U);
  ASSERT_EQ(triangles[0].size(), 4U);
  EXPECT_EQ(triangles[0][0], 7) << "between two new points, along segment 7";
  EXPECT_EQ(triangles[0][1], 7) << "ending at segment 7's end";
}

TEST(SliceMesh, GenericSectionAreasMatchTheExactArea) {
  // No vertex on the plane, a simple solid: the exact section is bounded by the exact crossing
  // segments, whose shoelace sum is its area; the output differs by the rounding of its
  // vertices to the nearest doubles.
  const Mesh sphere = uv_sphere({0.3, -0.2, 0.1}, 1.7, 20, 30);
  const Mesh torus = scenes::torus(2.0, 0.6, 32, 16);
  for (const Mesh* mesh : {&sphere, &torus}) {
    for (const double c : {-0.41, 0.013, 0.29, 0.5}) {
      const Section s = slice_one(*mesh, c);
      mpq_class exact = 0;
      for (std::size_t t = 0; t < mesh->triangles.size(); ++t) {
        const Triangle3 tri = mesh->triangle(t);
        const Vec3 p[3] = {tri.a, tri.b, tri.c};
        std::vector<QPoint2> ends;
        int down = -1;
        for (int i = 0; i < 3; ++i) {
          const Vec3 u = p[i];
          const Vec3 w = p[(i + 1) % 3];
          if ((u.z - c) * (w.z - c) < 0) {
            ends.push_back(oracle_crossing(u, w, 2, c));
            if (u.z > c) down = static_cast<int>(ends.size()) - 1;
          }
        }
        if (ends.size() != 2) continue;
        const QPoint2& from = ends[static_cast<std::size_t>(down)];
        const QPoint2& to = ends[static_cast<std::size_t>(1 - down)];
        exact += from.u * to.v - from.v * to.u;
      }
      exact /= 2;
      const mpq_class diff = abs(area(s.region) - exact);
      EXPECT_LT(diff.get_d(), 1e-13 * exact.get_d()) << c;
      EXPECT_GT(exact, 0);
    }
  }
}

// The engine's answer for one curve (union, positive) and its provenance: what simple_section
// and nested_section must reproduce exactly when they claim a plane.
void expect_simple_section_is_the_engines(std::span<const clip::slice::CrossingSegment> segments,
                                          int& claimed, int& declined) {
  std::vector<std::vector<std::int32_t>> under;
  std::vector<Ring> rings = clip::slice::chain_rings(segments, &under);
  const MultiPolygon engine =
      clip::polygon_boolean(rings, {}, {.op = clip::Op::union_, .fill = Fill::positive});
  const auto engine_triangles = clip::slice::edge_triangles(engine, segments);
  Section fast;
  if (!clip::slice::simple_section(rings, under, segments.size(), fast) &&
      !clip::slice::nested_section(rings, under, segments.size(), fast)) {
    ++declined;
    return;
  }
  ++claimed;
  ASSERT_EQ(fast.region.polygons.size(), engine.polygons.size());
  for (std::size_t i = 0; i < engine.polygons.size(); ++i)
    EXPECT_EQ(fast.region.polygons[i].rings, engine.polygons[i].rings) << "polygon " << i;
  EXPECT_EQ(fast.triangles, engine_triangles);
}

// The crossing segments of the plane z = c through every triangle of `mesh` (c on no vertex).
std::vector<clip::slice::CrossingSegment> curve_of(const Mesh& mesh, double c) {
  const clip::slice::SweepMesh prepared =
      clip::slice::prepare(mesh, clip::slice::frame_of(Axis::z));
  std::vector<std::int32_t> all(prepared.triangles.size());
  std::iota(all.begin(), all.end(), 0);
  clip::slice::PlaneCurves curves = clip::slice::crossing_segments(prepared, all, c);
  EXPECT_FALSE(curves.touches) << c;
  return std::move(curves.above);
}

// The rule of chain_rings spelled out: segments by (from_key, triangle, input position), each
// walk starting at the first unused one and taking at each key the first unused segment leaving
// it; zero-length pieces left out, walks of fewer than 3 points dropped.
std::vector<Ring> reference_rings(std::span<const clip::slice::CrossingSegment> segments,
                                  std::vector<std::vector<std::int32_t>>& triangles) {
  std::vector<std::size_t> order(segments.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::tie(segments[a].from_key, segments[a].triangle) <
           std::tie(segments[b].from_key, segments[b].triangle);
  });
  std::vector<char> used(segments.size(), 0);
  const auto usable = [&](std::size_t i) {
    return used[i] == 0 && segments[i].from_key != segments[i].to_key;
  };
  std::vector<Ring> rings;
  for (const std::size_t start : order) {
    if (!usable(start)) continue;
    Ring ring;
    std::vector<std::int32_t> under;
    for (std::size_t s = start;;) {
      used[s] = 1;
      ring.push_back(segments[s].from);
      under.push_back(segments[s].triangle);
      const auto next = std::find_if(order.begin(), order.end(), [&](std::size_t i) {
        return usable(i) && segments[i].from_key == segments[s].to_key;
      });
      if (next == order.end()) break;
      s = *next;
    }
    if (ring.size() < 3) continue;
    rings.push_back(std::move(ring));
    triangles.push_back(std::move(under));
  }
  return rings;
}

TEST(SliceMesh, ChainedRingsFollowTheRuleWhateverTheOrderOfTheSegments) {
  // Generic planes (every key left once: the cycles of a permutation), planes through vertices
  // and along faces (keys left several times: the general walk), through spheres, a torus and
  // stacked boxes, with the segments shuffled: the sweep hands them over in no fixed order.
  const Mesh sphere = uv_sphere({0.0, 0.0, 0.0}, 1.0, 12, 17);
  const Mesh torus = scenes::torus(2.0, 0.6, 24, 12);
  const Mesh stacked = joined(scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}}),
                              scenes::box_mesh(Box3{{0, 0, 1}, {1, 1, 2}}));
  std::mt19937_64 rng(26);
  int cases = 0;
  for (const Mesh* mesh : {&sphere, &torus, &stacked}) {
    const clip::slice::SweepMesh prepared =
        clip::slice::prepare(*mesh, clip::slice::frame_of(Axis::z));
    std::vector<std::int32_t> all(prepared.triangles.size());
    std::iota(all.begin(), all.end(), 0);
    std::vector<double> planes = {0.1234, -0.377, 0.5, 1.0};
    for (std::size_t v = 0; v < prepared.vertices.size(); v += 7)
      planes.push_back(prepared.vertices[v].z);
    for (const double c : planes) {
      clip::slice::PlaneCurves curves = clip::slice::crossing_segments(prepared, all, c);
      for (std::vector<clip::slice::CrossingSegment>* side : {&curves.above, &curves.below}) {
        std::shuffle(side->begin(), side->end(), rng);
        std::vector<std::vector<std::int32_t>> want_under, got_under;
        const std::vector<Ring> want = reference_rings(*side, want_under);
        const std::vector<Ring> got = clip::slice::chain_rings(*side, &got_under);
        ASSERT_EQ(got, want) << "plane " << c;
        ASSERT_EQ(got_under, want_under) << "plane " << c;
        ++cases;
      }
    }
  }
  EXPECT_GT(cases, 40);
}

TEST(SliceMesh, WalkedCurvesAreTheChainedRingsAndDeclineVerticesOnThePlane) {
  // The walk along paired half-edges gives the rings (and triangles) that chaining the
  // crossing segments through their keys gives, on generic planes through spheres apart, a
  // torus and overlapping spheres; it declines planes through a vertex, and stretches without a
  // pairing (two boxes sharing an edge: four triangles on it).
  const Mesh far =
      joined(uv_sphere({0.0, 0.0, 0.0}, 1.0, 24, 40), uv_sphere({3.1, 0.4, 0.05}, 0.9, 18, 29));
  const Mesh torus = scenes::torus(2.0, 0.6, 24, 12);
  const Mesh overlapping =
      joined(uv_sphere({0.0, 0.0, 0.0}, 1.0, 24, 40), uv_sphere({0.7, 0.3, 0.0}, 0.8, 18, 29));
  int walked = 0;
  for (const Mesh* mesh : {&far, &torus, &overlapping}) {
    const clip::slice::SweepMesh prepared =
        clip::slice::prepare(*mesh, clip::slice::frame_of(Axis::z));
    std::vector<std::int32_t> all(prepared.triangles.size());
    std::iota(all.begin(), all.end(), 0);
    std::mt19937_64 rng(7);
    std::shuffle(all.begin(), all.end(), rng);
    // The triangles a sweep holds at c: not flat, reaching c.
    const auto active_at = [&](double c) {
      std::vector<std::int32_t> active;
      for (const std::int32_t t : all) {
        const auto u = static_cast<std::size_t>(t);
        if (prepared.low(u) <= c && c <= prepared.high(u) && prepared.low(u) < prepared.high(u))
          active.push_back(t);
      }
      return active;
    };
    for (const double c : {0.1234, -0.377, 0.0123, 0.4}) {
      const std::vector<std::int32_t> active = active_at(c);
      clip::slice::WalkScratch scratch;
      std::vector<clip::slice::CrossingSegment> segments;
      std::vector<clip::slice::ChainCycle> cycles;
      ASSERT_TRUE(clip::slice::walk_curve(prepared, active, c, scratch, segments, cycles)) << c;
      std::vector<std::int32_t> walk(segments.size());
      std::iota(walk.begin(), walk.end(), 0);
      std::vector<Ring> got;
      std::vector<std::vector<std::int32_t>> got_under, want_under;
      std::vector<std::int32_t> rotated;
      clip::slice::write_cycles(segments, walk, cycles, got, &got_under, rotated);
      const std::vector<Ring> want = clip::slice::chain_rings(
          clip::slice::crossing_segments(prepared, active, c).above, &want_under);
      ASSERT_EQ(got, want) << c;
      ASSERT_EQ(got_under, want_under) << c;
      ++walked;
    }
    // A plane through a vertex is left to the general stages.
    const double on = prepared.vertices[prepared.vertices.size() / 2].z;
    clip::slice::WalkScratch scratch;
    std::vector<clip::slice::CrossingSegment> segments;
    std::vector<clip::slice::ChainCycle> cycles;
    const std::vector<std::int32_t> active = active_at(on);
    ASSERT_FALSE(active.empty());
    EXPECT_FALSE(clip::slice::walk_curve(prepared, active, on, scratch, segments, cycles));
  }
  const Mesh touching = joined(scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}}),
                               scenes::box_mesh(Box3{{1, 1, 0}, {2, 2, 1}}));
  const clip::slice::SweepMesh prepared =
      clip::slice::prepare(touching, clip::slice::frame_of(Axis::z));
  std::vector<std::int32_t> all(prepared.triangles.size());
  std::iota(all.begin(), all.end(), 0);
  std::erase_if(all, [&](std::int32_t t) {
    return prepared.low(static_cast<std::size_t>(t)) == prepared.high(static_cast<std::size_t>(t));
  });
  clip::slice::WalkScratch scratch;
  std::vector<clip::slice::CrossingSegment> segments;
  std::vector<clip::slice::ChainCycle> cycles;
  EXPECT_FALSE(clip::slice::walk_curve(prepared, all, 0.5, scratch, segments, cycles));
  EXPECT_EQ(walked, 12);
  // And the sections through it are the oracle's (the general stages decide them).
  auto sections = clip::slice_mesh(touching, std::vector<double>{0.5});
  ASSERT_TRUE(sections);
  EXPECT_EQ((*sections)[0].region.polygons.size(), 2U);
}

TEST(SliceMesh, SimpleSectionsThatSkipTheEngineAreTheEnginesAnswerBitForBit) {
  // Spheres apart (disjoint boxes: claimed), overlapping (rings that cross: the engine), nested
  // (a hollow sphere's annulus, a torus's two rings: nested_section claims them), and
  // random convex, star-shaped and self-crossing polygons as curves, some touching, some
  // clockwise, some with a repeated point.
  const Mesh a = uv_sphere({0.0, 0.0, 0.0}, 1.0, 24, 40);
  const Mesh far = joined(a, uv_sphere({3.1, 0.4, 0.05}, 0.9, 18, 29));
  const Mesh overlapping = joined(a, uv_sphere({0.7, 0.3, 0.0}, 0.8, 18, 29));
  const Mesh hollow = joined(a, uv_sphere({0.0, 0.0, 0.0}, 0.5, 12, 17), true);
  const Mesh torus = scenes::torus(2.0, 0.6, 32, 16);
  int claimed = 0, declined = 0;
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> z(-0.95, 0.95);
  for (const Mesh* mesh : {&a, &far, &overlapping, &hollow, &torus}) {
    for (int i = 0; i < case_budget(40, 4); ++i) {
      const double c = z(rng);
      expect_simple_section_is_the_engines(curve_of(*mesh, c), claimed, declined);
    }
  }
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < case_budget(400, 4); ++i) {
    std::vector<clip::slice::CrossingSegment> segments;
    const int rings = 1 + static_cast<int>(unit(rng) * 3);
    std::uint64_t key = 0;
    for (int r = 0; r < rings; ++r) {
      // Points on a circle at sorted angles: convex, occasionally collinear or repeated once
      // rounded (tiny radius), clockwise when reversed.
      const int n = 3 + static_cast<int>(unit(rng) * 8);
      const double radius = unit(rng) < 0.1 ? 1e-300 : 0.2 + unit(rng);
      const Vec2 center{3.0 * unit(rng), 3.0 * unit(rng)};
      std::vector<double> angles(static_cast<std::size_t>(n));
      for (double& t : angles)
        t = 6.283185307179586 * unit(rng);
      std::sort(angles.begin(), angles.end());
      if (unit(rng) < 0.2) std::reverse(angles.begin(), angles.end());
      if (unit(rng) < 0.1) std::shuffle(angles.begin(), angles.end(), rng);  // self-crossing
      // Half of the rings star-shaped (radii varying): concave, simple, around the center.
      const bool star = unit(rng) < 0.5;
      std::vector<Vec2> points;
      for (const double t : angles) {
        const double rt = star ? radius * (0.5 + 0.5 * unit(rng)) : radius;
        points.push_back(center + rt * Vec2{std::cos(t), std::sin(t)});
      }
      const std::uint64_t first = key;
      for (int k = 0; k < n; ++k) {
        const std::uint64_t to = k + 1 == n ? first : key + 1;
        segments.push_back({key, to, points[static_cast<std::size_t>(k)],
                            points[static_cast<std::size_t>((k + 1) % n)],
                            static_cast<std::int32_t>(segments.size())});
        ++key;
      }
    }
    std::shuffle(segments.begin(), segments.end(), rng);
    expect_simple_section_is_the_engines(segments, claimed, declined);
  }
  EXPECT_GT(claimed, 0);
  EXPECT_GT(declined, 0);
}

TEST(SliceMesh, NestedSectionsThatSkipTheEngineAreTheEnginesAnswerBitForBit) {
  // Groups of concentric star-shaped rings, each ring either way round (shells, holes, islands in
  // holes, rings inside out, rings inside a shell of the same orientation), their radius bands
  // sometimes overlapping (rings that cross), sometimes touching (a shared point), rectangles
  // with collinear points, groups sometimes overlapping: what nested_section claims is the
  // engine's answer bit for bit, and it claims nested cases.
  std::mt19937_64 rng(2626);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int claimed = 0, declined = 0, holes = 0;
  for (int i = 0; i < case_budget(600, 4); ++i) {
    std::vector<Ring> rings;
    const int groups = 1 + static_cast<int>(unit(rng) * 3);
    for (int g = 0; g < groups; ++g) {
      const Vec2 center{6.0 * unit(rng), 6.0 * unit(rng)};
      const int depth = 1 + static_cast<int>(unit(rng) * 4);
      double inner = 0.1 + 0.2 * unit(rng);
      for (int d = 0; d < depth; ++d) {
        const double width = 0.1 + 0.4 * unit(rng);
        const bool overlap = unit(rng) < 0.1;
        Ring ring;
        if (unit(rng) < 0.15) {  // a rectangle with collinear points on its sides
          const double h = inner + width;
          ring = {center + Vec2{-h, -h}, center + Vec2{0.0, -h}, center + Vec2{h, -h},
                  center + Vec2{h, h},   center + Vec2{-h, h},   center + Vec2{-h, 0.0}};
        } else {
          const int n = 3 + static_cast<int>(unit(rng) * 40);
          std::vector<double> angles(static_cast<std::size_t>(n));
          for (double& t : angles)
            t = 6.283185307179586 * unit(rng);
          std::sort(angles.begin(), angles.end());
          for (const double t : angles) {
            const double r = (overlap ? inner - 0.2 : inner) + width * unit(rng);
            ring.push_back(center + r * Vec2{std::cos(t), std::sin(t)});
          }
        }
        if (unit(rng) < 0.4) std::reverse(ring.begin(), ring.end());
        if (unit(rng) < 0.05 && !rings.empty()) ring[0] = rings.back()[0];  // touching
        inner += width + 0.05;
        rings.push_back(std::move(ring));
      }
    }
    std::vector<clip::slice::CrossingSegment> segments;
    std::uint64_t key = 0;
    for (const Ring& ring : rings) {
      const std::uint64_t first = key;
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const std::uint64_t to = k + 1 == ring.size() ? first : key + 1;
        segments.push_back({key, to, ring[k], ring[(k + 1) % ring.size()],
                            static_cast<std::int32_t>(segments.size())});
        ++key;
      }
    }
    std::shuffle(segments.begin(), segments.end(), rng);
    const int before = claimed;
    expect_simple_section_is_the_engines(segments, claimed, declined);
    if (claimed > before) {
      std::vector<std::vector<std::int32_t>> under;
      const std::vector<Ring> chained = clip::slice::chain_rings(segments, &under);
      const MultiPolygon engine =
          clip::polygon_boolean(chained, {}, {.op = clip::Op::union_, .fill = Fill::positive});
      for (const Polygon& p : engine.polygons)
        holes += static_cast<int>(p.rings.size()) - 1;
    }
  }
  EXPECT_GT(claimed, 0);
  EXPECT_GT(declined, 0);
  EXPECT_GT(holes, 0);
}

TEST(SliceMesh, SweepStartsFileEachTriangleUnderTheFirstPlaneItReaches) {
  // The buckets of sweep_starts against a binary search over all planes: evenly spaced planes,
  // clustered ones with repeats, planes on vertices, one plane, planes far outside the mesh and
  // a range too wide for a double: every triangle under the first plane at or above its low,
  // none when that plane is above its high or the triangle is flat.
  const Mesh sphere = uv_sphere({0.0, 0.0, 0.0}, 1.0, 24, 40);
  const clip::slice::SweepMesh mesh = clip::slice::prepare(sphere, clip::slice::frame_of(Axis::z));
  std::mt19937_64 rng(26);
  std::uniform_real_distribution<double> unit(-1.2, 1.2);
  std::vector<std::vector<double>> sets = {
      {0.25}, {-1e300, 0.0, 1e300}, {-1.5e308, -0.5, 0.0, 1.5e308}, {5.0, 6.0}};
  for (int k = 0; k < 20; ++k) {
    std::vector<double> planes;
    const int n = 1 + static_cast<int>(std::abs(unit(rng)) * 80);
    for (int i = 0; i < n; ++i) {
      const double r = unit(rng);
      planes.push_back(
          k % 3 == 0   ? -1.0 + 2.0 * (i + 0.5) / n
          : k % 3 == 1 ? std::round(r * 8) / 8
                       : mesh.vertices[static_cast<std::size_t>(i * 7) % mesh.vertices.size()].z);
    }
    std::sort(planes.begin(), planes.end());
    sets.push_back(std::move(planes));
  }
  for (const std::vector<double>& sorted : sets) {
    const clip::slice::SweepStarts got = clip::slice::sweep_starts(mesh, sorted);
    std::vector<std::vector<std::int32_t>> want(sorted.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const double low = mesh.low(t), high = mesh.high(t);
      const auto i = static_cast<std::size_t>(std::lower_bound(sorted.begin(), sorted.end(), low) -
                                              sorted.begin());
      if (low < high && i < sorted.size() && sorted[i] <= high)
        want[i].push_back(static_cast<std::int32_t>(t));
    }
    ASSERT_EQ(got.start.size(), sorted.size() + 1);
    for (std::size_t i = 0; i < sorted.size(); ++i) {
      const std::vector<std::int32_t> filed(
          got.triangles.begin() + static_cast<std::ptrdiff_t>(got.start[i]),
          got.triangles.begin() + static_cast<std::ptrdiff_t>(got.start[i + 1]));
      ASSERT_EQ(filed, want[i]) << "plane " << i << " of " << sorted.size();
    }
  }
}

TEST(SliceMesh, CrossingVerticesAreTheNearestDoubles) {
  const Mesh sphere = uv_sphere({0.3, -0.2, 0.1}, 1.7, 10, 14);
  const double c = 0.3141;
  const Section s = slice_one(sphere, c);
  std::vector<Vec2> exact_points;
  for (std::size_t t = 0; t < sphere.triangles.size(); ++t) {
    const Triangle3 tri = sphere.triangle(t);
    const Vec3 p[3] = {tri.a, tri.b, tri.c};
    for (int i = 0; i < 3; ++i) {
      const Vec3 u = p[i];
      const Vec3 w = p[(i + 1) % 3];
      if ((u.z - c) * (w.z - c) < 0) {
        const QPoint2 q = oracle_crossing(u, w, 2, c);
        // mpq get_d truncates: the nearest double is one of the two neighbours of that.
        const auto nearest = [](const mpq_class& x) {
          const double d = x.get_d();
          double best = d;
          for (const double n : {std::nextafter(d, -1e300), std::nextafter(d, 1e300)}) {
            if (abs(mpq_class(n) - x) < abs(mpq_class(best) - x)) best = n;
          }
          return best;
        };
        exact_points.push_back({nearest(q.u), nearest(q.v)});
      }
    }
  }
  int matched = 0;
  for (const Ring& ring : s.region.all_rings()) {
    for (const Vec2 p : ring) {
      EXPECT_NE(std::find(exact_points.begin(), exact_points.end(), p), exact_points.end())
          << p.x << " " << p.y;
      ++matched;
    }
  }
  EXPECT_GT(matched, 10);
}

TEST(SliceMesh, AnswersAreTheSameWhateverTheThreadCountAndValueOrder) {
  const Mesh torus = scenes::torus(2.0, 0.6, 24, 12);
  std::vector<double> values;
  for (int i = 0; i < 40; ++i)
    values.push_back(-0.7 + 0.035 * ((i * 17) % 40));
  const std::vector<Section> one = slice(torus, values, Axis::x, 1);
  const std::vector<Section> two = slice(torus, values, Axis::x, 2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].value, values[i]);
    EXPECT_EQ(one[i].region, two[i].region) << i;
    EXPECT_EQ(one[i].triangles, two[i].triangles) << i;
    const Section alone = slice_one(torus, values[i], Axis::x);
    EXPECT_EQ(alone.region, one[i].region) << i;
  }
}

// A mesh with repeated positions (a triangle soup: each triangle its own corners) is welded
// before the sweep; one with distinct vertices is read in place. Both paths give the same answer,
// bit for bit, when the second is handed the weld's own mesh (same vertex numbers), along each
// axis (x and y convert the vertices to the frame, z does not).
TEST(SliceMesh, ATriangleSoupIsSlicedAsItsWeldedMesh) {
  const Mesh torus = scenes::torus(2.0, 0.6, 24, 12);
  Mesh soup;
  for (const TriangleIndices& t : torus.triangles) {
    const auto base = static_cast<std::int32_t>(soup.vertices.size());
    for (const std::int32_t v : t)
      soup.vertices.push_back(torus.vertices[static_cast<std::size_t>(v)]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  ASSERT_FALSE(vertices_distinct(soup.vertices));
  const Mesh welded = weld_vertices(soup).mesh;
  ASSERT_TRUE(vertices_distinct(welded.vertices));
  std::vector<double> values;
  for (int i = 0; i < 30; ++i)
    values.push_back(-2.5 + 0.17 * i);
  for (const Axis axis : {Axis::x, Axis::y, Axis::z}) {
    const std::vector<Section> from_soup = slice(soup, values, axis, 1);
    const std::vector<Section> from_welded = slice(welded, values, axis, 1);
    ASSERT_EQ(from_soup.size(), values.size());
    ASSERT_EQ(from_welded.size(), values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
      EXPECT_EQ(from_soup[i].region, from_welded[i].region) << i;
      EXPECT_EQ(from_soup[i].triangles, from_welded[i].triangles) << i;
    }
  }
}

TEST(SliceMesh, AnOpenMeshIsRefusedNamingTheEdge) {
  Mesh box = scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}});
  box.triangles.pop_back();
  const std::vector<double> values{0.5};
  const auto result = clip::slice_mesh(box, values);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().kind, ErrorKind::degenerate);
  EXPECT_NE(result.error().message.find("not closed"), std::string::npos);
  EXPECT_NE(result.error().message.find("->"), std::string::npos) << result.error().message;
  const std::vector<double> bad{0.5, std::nan("")};
  const auto nan = clip::slice_mesh(scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}}), bad);
  ASSERT_FALSE(nan.ok());
  EXPECT_EQ(nan.error().kind, ErrorKind::invalid_value);
}

TEST(SliceMesh, EmptyMeshAndNoValues) {
  const std::vector<double> values{0.0, 1.0};
  const auto empty = clip::slice_mesh(Mesh{}, values);
  ASSERT_TRUE(empty.ok());
  ASSERT_EQ(empty->size(), 2U);
  EXPECT_TRUE((*empty)[0].region.empty());
  const auto none = clip::slice_mesh(scenes::box_mesh(Box3{{0, 0, 0}, {1, 1, 1}}), {});
  ASSERT_TRUE(none.ok());
  EXPECT_TRUE(none->empty());
}

// ---- shadows ----------------------------------------------------------------------------------

void expect_shadow_matches_oracle(const Mesh& mesh, int axis, const MultiPolygon& region,
                                  int samples, std::uint64_t seed) {
  EXPECT_TRUE(is_valid_ogc(region));
  const Box2 box = projected_box(mesh, axis);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(box.min.x - 0.1, box.max.x + 0.1);
  std::uniform_real_distribution<double> uy(box.min.y - 0.1, box.max.y + 0.1);
  for (int i = 0; i < samples; ++i) {
    const Vec2 p{ux(rng), uy(rng)};
    const Location got = inside::point_in_polygon(region, p);
    if (got == Location::boundary) continue;
    ASSERT_EQ(got == Location::inside, oracle_in_shadow(mesh, axis, p)) << p.x << " " << p.y;
  }
}

MultiPolygon shadow_of(const Mesh& mesh, Axis axis) {
  auto result = clip::shadow(mesh, {.axis = axis});
  EXPECT_TRUE(result.ok());
  return result.ok() ? *result : MultiPolygon{};
}

TEST(Shadow, BoxIsItsFaceAndTorusAnAnnulus) {
  const Mesh box = scenes::box_mesh(Box3{{0, 0, 0}, {1, 2, 3}});
  EXPECT_EQ(area(shadow_of(box, Axis::z)), 2);
  EXPECT_EQ(area(shadow_of(box, Axis::x)), 6);
  EXPECT_EQ(area(shadow_of(box, Axis::y)), 3);
  const MultiPolygon ring = shadow_of(scenes::torus(2.0, 0.6, 24, 12), Axis::z);
  ASSERT_EQ(ring.polygons.size(), 1U);
  EXPECT_EQ(ring.polygons[0].rings.size(), 2U);
}

TEST(Shadow, OpenSurfacesCastTheUnionOfTheirProjectedTriangles) {
  // A box without its lid, one triangle, a wall seen edge-on, a sphere with holes, and a strip
  // folded back over itself (triangles projected clockwise beside counter-clockwise ones).
  Mesh lidless = scenes::box_mesh(Box3{{0, 0, 0}, {1, 2, 3}});
  lidless.triangles.pop_back();
  lidless.triangles.pop_back();
  ASSERT_TRUE(unmatched_edge(lidless).has_value());
  for (const Axis axis : {Axis::x, Axis::y, Axis::z}) {
    expect_shadow_matches_oracle(lidless, static_cast<int>(axis), shadow_of(lidless, axis), 300,
                                 26);
  }
  EXPECT_EQ(area(shadow_of(lidless, Axis::z)), 2);
  Mesh triangle;
  triangle.vertices = {{0, 0, 5}, {2, 0, 6}, {0, 1, 7}};
  triangle.triangles = {{0, 2, 1}};  // clockwise seen from +z
  EXPECT_EQ(area(shadow_of(triangle, Axis::z)), 1);
  Mesh wall;
  wall.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  wall.triangles = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_TRUE(shadow_of(wall, Axis::z).empty());
  EXPECT_EQ(area(shadow_of(wall, Axis::y)), 1);
  Mesh holes = uv_sphere({0.2, -0.1, 0.3}, 1.0, 12, 17);
  for (std::size_t t = holes.triangles.size(); t-- > 0;) {
    if (t % 5 == 0) holes.triangles.erase(holes.triangles.begin() + static_cast<std::ptrdiff_t>(t));
  }
  Mesh fold;  // a strip along x rising to z = 1, then folding back over itself at z = 2
  for (int i = 0; i <= 6; ++i) {
    const double x = i <= 3 ? i : 6 - i - 0.5;
    fold.vertices.push_back({x, 0.0, i * 0.5});
    fold.vertices.push_back({x + 0.25, 1.0, i * 0.5 + 0.1});
  }
  for (std::int32_t i = 0; i < 6; ++i) {
    fold.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 1});
    fold.triangles.push_back({2 * i + 1, 2 * i + 2, 2 * i + 3});
  }
  for (const Mesh* mesh : {&holes, &fold}) {
    for (const Axis axis : {Axis::x, Axis::y, Axis::z}) {
      expect_shadow_matches_oracle(*mesh, static_cast<int>(axis), shadow_of(*mesh, axis), 400, 7);
    }
  }
}

TEST(Shadow, ConcaveSelfOverlappingAndHollowMeshesMatchTheOracle) {
  const Mesh stairs = voxel_mesh(5, [](int i, int j, int k) { return k <= i && (j + k) % 5 != 4; });
  const Mesh cubes =
      joined(rotated_cube({0, 0, 0}, 1.0, 0.3, 0.2), rotated_cube({0.7, 0.4, 0.1}, 0.9, 1.1, -0.4));
  const Mesh hollow =
      joined(uv_sphere({0, 0, 0}, 2.0, 12, 16), uv_sphere({0.1, 0, 0}, 1.0, 8, 12), true);
  const Mesh torus = scenes::torus(2.0, 0.6, 24, 12);
  for (const Mesh* mesh : {&stairs, &cubes, &hollow, &torus}) {
    for (const Axis axis : {Axis::z, Axis::x, Axis::y}) {
      expect_shadow_matches_oracle(*mesh, static_cast<int>(axis), shadow_of(*mesh, axis),
                                   case_budget(300, 5), 11);
    }
  }
}

}  // namespace
}  // namespace contain::test
