// The oriented boxes of the mesh-pair descent (src/distance/oriented_box.h): every vertex under
// a node lies exactly (rational arithmetic) in the node's box, and the floating-point lower bound
// between two boxes, one placed by a pose, never exceeds the exact squared distance between the
// triangles below them; on triangle soups with flat, needle and point triangles, at coordinates
// scaled by 2^-500 .. 2^500, far from the origin, under rotations and a scaling.

#include "distance/oriented_box.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "contain/bvh/triangle_boxes.h"
#include "distance/mesh_oracle.h"
#include "scenes/scenes.h"
#include "support/case_budget.h"
#include "support/exact_distance.h"

namespace contain::distance::detail {
namespace {

mpq_class det3(const mpq_class m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// Is p in {c + sum a_k e_k : |a_k| <= h_k}, exactly? a = E^-1 (p - c) by Cramer's rule.
bool exactly_holds(const OrientedBox& box, Vec3 p) {
  mpq_class m[3][3];
  const double e[3][3] = {{box.e[0].x, box.e[0].y, box.e[0].z},
                          {box.e[1].x, box.e[1].y, box.e[1].z},
                          {box.e[2].x, box.e[2].y, box.e[2].z}};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      m[i][k] = e[k][i];  // column k is e_k
  const mpq_class r[3] = {mpq_class(p.x) - mpq_class(box.c.x), mpq_class(p.y) - mpq_class(box.c.y),
                          mpq_class(p.z) - mpq_class(box.c.z)};
  const mpq_class det = det3(m);
  if (det == 0) return false;
  for (int k = 0; k < 3; ++k) {
    mpq_class mk[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        mk[i][j] = j == k ? r[i] : m[i][j];
    const mpq_class a = det3(mk) / det;
    if (abs(a) > mpq_class(box.h[k])) return false;
  }
  return true;
}

// A soup of n triangles in [-1, 1]^3 scaled by s and moved by `offset`: a third ordinary, then
// flat ones (all in the plane z = x), needles (two corners equal or collinear) and points.
Mesh soup(int n, double s, Vec3 offset, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Mesh m;
  for (int i = 0; i < n; ++i) {
    Vec3 p[3];
    for (Vec3& q : p)
      q = {u(rng), u(rng), u(rng)};
    switch (i % 5) {
      case 1:  // flat: the whole family in one tilted plane
        for (Vec3& q : p)
          q.z = q.x;
        break;
      case 2:  // needle: two equal corners
        p[2] = p[1];
        break;
      case 3:  // needle: collinear corners
        p[2] = p[0] + 2.0 * (p[1] - p[0]);
        break;
      case 4:  // a point
        p[1] = p[2] = p[0];
        break;
      default:
        break;
    }
    // small triangles, so that nodes are patches
    for (int k = 1; k < 3; ++k)
      p[k] = p[0] + 0.25 * (p[k] - p[0]);
    for (const Vec3& q : p)
      m.vertices.push_back(offset + s * q);
    const auto b = static_cast<std::int32_t>(3 * i);
    m.triangles.push_back({b, b + 1, b + 2});
  }
  return m;
}

// The triangles under each node.
std::vector<std::vector<std::int32_t>> triangles_below(const bvh::Bvh& bvh) {
  const auto nodes = bvh.nodes();
  const auto items = bvh.items();
  std::vector<std::vector<std::int32_t>> out(nodes.size());
  for (std::size_t k = nodes.size(); k-- > 0;) {
    const bvh::Node& n = nodes[k];
    if (n.is_leaf()) {
      out[k].assign(items.begin() + n.first, items.begin() + n.first + n.count);
    } else {
      out[k] = out[k + 1];
      const auto& second = out[static_cast<std::size_t>(n.first)];
      out[k].insert(out[k].end(), second.begin(), second.end());
    }
  }
  return out;
}

Triangle3 triangle(const Mesh& m, std::int32_t t) {
  const auto& f = m.triangles[static_cast<std::size_t>(t)];
  return {m.vertices[static_cast<std::size_t>(f[0])], m.vertices[static_cast<std::size_t>(f[1])],
          m.vertices[static_cast<std::size_t>(f[2])]};
}

const double kScales[] = {0x1p-500, 0x1p-40, 1.0, 0x1p40, 0x1p500};

TEST(OrientedBoxes, HoldEveryVertexBelowEachNodeExactly) {
  int seed = 1;
  for (const double s : kScales) {
    for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{1e6 * s, -3e6 * s, 2e6 * s}}) {
      const Mesh m = soup(60, s, offset, static_cast<std::uint64_t>(seed++));
      const bvh::Bvh bvh(bvh::triangle_boxes(m));
      const std::vector<OrientedBox> boxes = oriented_boxes(bvh, m);
      const auto below = triangles_below(bvh);
      ASSERT_EQ(boxes.size(), below.size());
      int failures = 0;
      for (std::size_t k = 0; k < boxes.size(); ++k)
        for (const std::int32_t t : below[k])
          for (const std::int32_t v : m.triangles[static_cast<std::size_t>(t)])
            if (!exactly_holds(boxes[k], m.vertices[static_cast<std::size_t>(v)])) ++failures;
      EXPECT_EQ(failures, 0) << "scale " << s;
    }
  }
}

// Nodes over more than 256 triangles take the box of their axis-aligned box (coordinate axes).
TEST(OrientedBoxes, NodesOverManyTrianglesHoldTheirVerticesToo) {
  int seed = 40;
  for (const double s : {0x1p-500, 1.0, 0x1p500}) {
    const Mesh m = soup(700, s, {1e6 * s, 0, -1e6 * s}, static_cast<std::uint64_t>(seed++));
    const bvh::Bvh bvh(bvh::triangle_boxes(m));
    const std::vector<OrientedBox> boxes = oriented_boxes(bvh, m);
    const auto below = triangles_below(bvh);
    int failures = 0, big = 0;
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      if (below[k].size() <= 256) continue;
      ++big;
      for (const std::int32_t t : below[k])
        for (const std::int32_t v : m.triangles[static_cast<std::size_t>(t)])
          if (!exactly_holds(boxes[k], m.vertices[static_cast<std::size_t>(v)])) ++failures;
    }
    EXPECT_GT(big, 0);
    EXPECT_EQ(failures, 0) << "scale " << s;
  }
}

TEST(OrientedBoxes, SurelyHoldsAgreesWithTheExactTest) {
  const Mesh m = soup(40, 1.0, {3, 4, 5}, 9);
  const bvh::Bvh bvh(bvh::triangle_boxes(m));
  const std::vector<OrientedBox> boxes = oriented_boxes(bvh, m);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-2, 2);
  int held = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p{3 + u(rng), 4 + u(rng), 5 + u(rng)};
    const OrientedBox& b = boxes[static_cast<std::size_t>(i) % boxes.size()];
    if (oriented_box_surely_holds(b, p)) {
      EXPECT_TRUE(exactly_holds(b, p)) << i;
      ++held;
    }
  }
  EXPECT_GT(held, 0);
}

// For every node pair of A and B placed by `tb`: lower <= the exact least squared distance of
// the triangles below them (B's vertices placed by Transform::apply, as the descent uses them).
// Counts the node pairs with a positive bound in `positive`.
int check_lower(const Mesh& a, const Mesh& b, const Transform& tb, int& positive) {
  const bvh::Bvh ba(bvh::triangle_boxes(a)), bb(bvh::triangle_boxes(b));
  const std::vector<OrientedBox> oa = oriented_boxes(ba, a), ob = oriented_boxes(bb, b);
  const OrientedPose pose = oriented_pose(tb, oriented_extent(oa), oriented_extent(ob));
  const Mesh wb = placed(b, tb);
  const std::size_t na = a.triangles.size(), nb = b.triangles.size();
  // The exact distance of a triangle pair only where the exact gap of their boxes does not
  // already prove it at or above the bound (most pairs): the same verdict, a fraction of the GMP.
  std::vector<mpq_class> gap(na * nb);
  std::vector<std::optional<mpq_class>> d2(na * nb);
  for (std::size_t i = 0; i < na; ++i)
    for (std::size_t j = 0; j < nb; ++j)
      gap[i * nb + j] = test::triangle_box_gap(triangle(a, static_cast<std::int32_t>(i)),
                                               triangle(wb, static_cast<std::int32_t>(j)));
  const auto exact = [&](std::int32_t i, std::int32_t j) -> const mpq_class& {
    std::optional<mpq_class>& v =
        d2[static_cast<std::size_t>(i) * nb + static_cast<std::size_t>(j)];
    if (!v) v = test::exact_triangle_pair(triangle(a, i), triangle(wb, j));
    return *v;
  };
  const auto below_a = triangles_below(ba), below_b = triangles_below(bb);
  int failures = 0;
  for (std::size_t x = 0; x < oa.size(); ++x) {
    for (std::size_t y = 0; y < ob.size(); ++y) {
      const double lo = oriented_box_lower(oa[x], ob[y], tb.apply(ob[y].c), pose);
      if (lo == 0) continue;
      ++positive;
      // The first triangle pair below these nodes that is closer than the bound, if any.
      const auto closer = [&]() -> std::optional<std::pair<std::int32_t, std::int32_t>> {
        const mpq_class bound(lo);
        for (const std::int32_t i : below_a[x])
          for (const std::int32_t j : below_b[y]) {
            const std::size_t k = static_cast<std::size_t>(i) * nb + static_cast<std::size_t>(j);
            if (gap[k] < bound && exact(i, j) < bound) return std::pair{i, j};
          }
        return std::nullopt;
      }();
      if (closer) {
        ADD_FAILURE() << "node pair " << x << ", " << y << ": lower " << lo << " above "
                      << exact(closer->first, closer->second).get_d() << " (triangles "
                      << closer->first << ", " << closer->second << ")";
        ++failures;
      }
    }
  }
  return failures;
}

// Random poses per case: one under the sanitizers, where the GMP oracle of every triangle pair
// made this the longest test of the suite (86 s).
constexpr int kRandomPoses = test::case_budget(2, 2);

TEST(OrientedBoxLower, NeverExceedsTheExactDistanceOfTheTrianglesBelow) {
  int failures = 0;
  int positive = 0;
  std::uint64_t seed = 20;
  for (const double s : kScales) {
    for (const double far : {0.0, 1e6}) {
      const Vec3 offset{far * s, far * s, -far * s};
      const Mesh a = soup(20, s, offset, seed++);
      const Mesh b = soup(15, 0.5 * s, {}, seed++);
      for (Transform t : scenes::random_poses(kRandomPoses, 2.5 * s, seed++)) {
        t.t = offset + t.t;
        failures += check_lower(a, b, t, positive);
      }
      // A scaling (not rigid) and a pose that brings B within rounding of A.
      Transform shrink;
      shrink.r = {{{0.5, 0.25, 0}, {0, 0.5, 0}, {0.125, 0, 0.5}}};
      shrink.t = offset + Vec3{2.25 * s, 0, 0};
      failures += check_lower(a, b, shrink, positive);
      Transform close;
      close.t = offset + Vec3{2 * s + 0x1p-30 * s, 0, 0};
      failures += check_lower(a, b, close, positive);
    }
  }
  // A mesh whose upper nodes take axis-aligned boxes.
  const Mesh big = soup(300, 1.0, {1e6, 0, 0}, seed++);
  const Mesh small = soup(12, 0.5, {}, seed++);
  for (Transform t : scenes::random_poses(kRandomPoses, 2.5, seed++)) {
    t.t = Vec3{1e6, 0, 0} + t.t;
    failures += check_lower(big, small, t, positive);
  }
  EXPECT_GT(positive, 1000) << positive;  // the bound is not vacuous
  EXPECT_EQ(failures, 0);
}

// Two unit squares facing each other across a gap of 0.1, tilted 45 degrees about two axes:
// the axis-aligned boxes of such patches overlap; the oriented bound is the gap.
TEST(OrientedBoxLower, IsNearTheGapOfTwoFacingSquaresAtAnyOrientation) {
  const auto square = [](double z) {
    Mesh m;
    m.vertices = {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
  };
  const double c = std::sqrt(0.5);
  Transform tilt;  // 45 degrees about x, then 45 about z
  tilt.r = {{{c, -c * c, c * c}, {c, c * c, -c * c}, {0, c, c}}};
  const Mesh a = placed(square(0), tilt);
  const Mesh b = square(0.1);
  const bvh::Bvh ba(bvh::triangle_boxes(a)), bb(bvh::triangle_boxes(b));
  const std::vector<OrientedBox> oa = oriented_boxes(ba, a), ob = oriented_boxes(bb, b);
  const OrientedPose pose = oriented_pose(tilt, oriented_extent(oa), oriented_extent(ob));
  const double lo = oriented_box_lower(oa[0], ob[0], tilt.apply(ob[0].c), pose);
  EXPECT_GT(lo, 0.0099);
  EXPECT_LE(lo, 0.0101);
  int positive = 0;
  EXPECT_EQ(check_lower(a, b, tilt, positive), 0);
  EXPECT_GT(positive, 0);
}

}  // namespace
}  // namespace contain::distance::detail
