// The search tree's oriented boxes (search_tree.h) against the GMP oracle: for every lane of
// every node, the lower bound a query point gets is at most the exact squared distance of each
// item below the lane, for triangles and segments, on random soups, closed surfaces, coplanar
// and degenerate (lattice) items, points on corners and a hair off the surface, at unit scale,
// at 2^-300 and 2^300, and far from the origin.

#include "distance/search_tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "support/case_budget.h"
#include "support/exact_distance.h"

namespace contain::distance::detail {
namespace {

// Sanitizer builds run a fifth of the points (support/case_budget.h).
constexpr int kPoints = test::case_budget(100, 5);

// A sphere-like closed surface of 2 * rings * segments triangles (curved patches, where the
// oriented boxes are thin).
std::vector<Vec3> sphere_corners(int rings, int segments) {
  std::vector<Vec3> out;
  auto at = [&](int i, int j) {
    const double theta = M_PI * i / rings, phi = 2 * M_PI * j / segments;
    return Vec3{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
  };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      out.insert(out.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      out.insert(out.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return out;
}

// Random triangles, half of them small.
std::vector<Vec3> soup_corners(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i) {
    const Vec3 c{u(rng), u(rng), u(rng)};
    const double s = i % 2 == 0 ? 0.05 : 0.5;
    for (int k = 0; k < 3; ++k)
      out.push_back(c + Vec3{s * u(rng), s * u(rng), s * u(rng)});
  }
  return out;
}

// Triangles with corners on a coarse lattice: repeated and collinear corners, coplanar sets.
std::vector<Vec3> lattice_corners(std::mt19937_64& rng, int n) {
  std::uniform_int_distribution<int> l(-3, 3);
  std::vector<Vec3> out;
  for (int i = 0; i < 3 * n; ++i)
    out.push_back({0.5 * l(rng), 0.5 * l(rng), i % 4 == 0 ? 0.0 : 0.5 * l(rng)});
  return out;
}

// A flat grid of triangles in the plane z = x / 3 (the lanes are slabs of width zero).
std::vector<Vec3> flat_corners(int n) {
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      auto at = [&](int a, int b) {
        const double x = 0.1 * (i + a), y = 0.1 * (j + b);
        return Vec3{x, y, x / 3};
      };
      out.insert(out.end(), {at(0, 0), at(1, 0), at(1, 1)});
      out.insert(out.end(), {at(0, 0), at(1, 1), at(0, 1)});
    }
  return out;
}

// Segments on the plane z = 0, as the 2D searches give them: a circle's edges and a lattice.
std::vector<Vec3> segment_corners(std::mt19937_64& rng) {
  std::vector<Vec3> out;
  for (int k = 0; k < 120; ++k) {
    const double a = 2 * M_PI * k / 120, b = 2 * M_PI * (k + 1) / 120;
    out.insert(out.end(), {{std::cos(a), std::sin(a), 0}, {std::cos(b), std::sin(b), 0}});
  }
  std::uniform_int_distribution<int> l(-3, 3);
  for (int k = 0; k < 60; ++k)
    out.insert(out.end(), {{0.5 * l(rng), 0.5 * l(rng), 0}, {0.5 * l(rng), 0.5 * l(rng), 0}});
  return out;
}

mpq_class exact_d2(Vec3 p, std::span<const Vec3> corners, int per_item, std::int32_t item) {
  const auto i = static_cast<std::size_t>(item) * static_cast<std::size_t>(per_item);
  if (per_item == 3) {
    return test::exact_closest(p, Triangle3{corners[i], corners[i + 1], corners[i + 2]})
        .squared_distance;
  }
  return test::exact_closest(p, Segment3{corners[i], corners[i + 1]}).squared_distance;
}

// Query points: random in and around the items' box, on corners, and a hair off corners.
std::vector<Vec3> query_points(std::mt19937_64& rng, std::span<const Vec3> corners, bool planar) {
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::uniform_int_distribution<std::size_t> pick(0, corners.size() - 1);
  std::vector<Vec3> out;
  for (int i = 0; i < kPoints; ++i) {
    Vec3 p;
    switch (i % 3) {
      case 0:
        p = {u(rng), u(rng), u(rng)};
        break;
      case 1:
        p = corners[pick(rng)];
        break;
      default:
        p = corners[pick(rng)] + Vec3{1e-9 * u(rng), 1e-9 * u(rng), 1e-9 * u(rng)};
    }
    if (planar) p.z = 0;
    out.push_back(p);
  }
  return out;
}

// Checks every lane of the tree over `corners` (scaled by s, then moved by `offset`) for each
// query point; returns the number of lanes whose bound is within a factor 2 of the exact
// distance of their nearest item (the bound is of use), at unit scale.
int check_tree(std::span<const Vec3> unit_corners, int per_item, const std::vector<Vec3>& points,
               double s, Vec3 offset, const char* what) {
  std::vector<Vec3> corners;
  for (const Vec3& v : unit_corners)
    corners.push_back(v * s + offset);
  const SearchTree tree(corners, per_item, {.max_leaf_items = 4});
  const std::size_t items = corners.size() / static_cast<std::size_t>(per_item);
  int useful = 0;
  for (const Vec3& unit_p : points) {
    const Vec3 p = unit_p * s + offset;
    // The exact squared distance of each item, by position in leaf order.
    std::vector<mpq_class> exact(items);
    for (std::size_t k = 0; k < items; ++k)
      exact[k] = exact_d2(p, corners, per_item, tree.items()[k]);
    const std::vector<SearchTree::LaneBound> lanes = tree.lane_bounds(p);
    EXPECT_FALSE(lanes.empty());
    for (const SearchTree::LaneBound& lane : lanes) {
      EXPECT_GE(lane.bound, 0.0);
      mpq_class nearest = exact[static_cast<std::size_t>(lane.first)];
      for (std::int32_t k = lane.first; k < lane.end; ++k)
        nearest = std::min(nearest, exact[static_cast<std::size_t>(k)]);
      if (!(mpq_class(lane.bound) <= nearest)) {
        ADD_FAILURE() << what << ": a lane's bound " << lane.bound << " exceeds " << nearest.get_d()
                      << " at p = (" << p.x << ", " << p.y << ", " << p.z << "), scale " << s;
        return useful;
      }
      if (nearest > 0 && mpq_class(lane.bound) * 2 >= nearest) ++useful;
    }
  }
  return useful;
}

struct Family {
  const char* name;
  std::vector<Vec3> corners;
  int per_item;
  bool planar;
};

std::vector<Family> families() {
  std::mt19937_64 rng(21);
  return {{"sphere", sphere_corners(10, 16), 3, false},
          {"soup", soup_corners(rng, 150), 3, false},
          {"lattice", lattice_corners(rng, 150), 3, false},
          {"flat grid", flat_corners(10), 3, false},
          {"segments", segment_corners(rng), 2, true}};
}

TEST(SearchTreeBounds, OrientedBoxesNeverExceedTheExactDistanceOfTheirItems) {
  std::mt19937_64 rng(22);
  for (const Family& f : families()) {
    const std::vector<Vec3> points = query_points(rng, f.corners, f.planar);
    const int useful = check_tree(f.corners, f.per_item, points, 1.0, {}, f.name);
    // The bounds are of use: many lanes are put within a factor 2 of their distance.
    EXPECT_GT(useful, kPoints) << f.name;
  }
}

TEST(SearchTreeBounds, OrientedBoxesStayBelowAtTinyAndHugeScalesAndFarFromTheOrigin) {
  // At 2^-300 and 2^300 the floats cannot hold the coordinates: the lanes must give 0 (or any
  // bound below the exact one), never more. Far from the origin (1e6 on each axis) the boxes are
  // kept about the tree's centre.
  std::mt19937_64 rng(23);
  for (const Family& f : families()) {
    const std::vector<Vec3> points = query_points(rng, f.corners, f.planar);
    check_tree(f.corners, f.per_item, points, 0x1p-300, {}, f.name);
    check_tree(f.corners, f.per_item, points, 0x1p300, {}, f.name);
    const Vec3 far = f.planar ? Vec3{1e6, -1e6, 0} : Vec3{1e6, -1e6, 1e6};
    const int useful = check_tree(f.corners, f.per_item, points, 1.0, far, f.name);
    EXPECT_GT(useful, kPoints / 2) << f.name << " far from the origin";
  }
}

TEST(SearchTreeBounds, ChildrenOfManyItemsBoundedByTheirAxisAlignedBoxesStayBelowToo) {
  // 3072 triangles: the root's children hold more than the 512 items above which a child keeps
  // the coordinate axes around its box (search_tree.cpp).
  std::mt19937_64 rng(24);
  const std::vector<Vec3> corners = sphere_corners(32, 48);
  std::vector<Vec3> points = query_points(rng, corners, false);
  points.resize(points.size() / 3);
  EXPECT_GT(check_tree(corners, 3, points, 1.0, {}, "large sphere"), 0);
  check_tree(corners, 3, points, 1.0, Vec3{-3e5, 1e6, 2e6}, "large sphere, moved");
}

TEST(SearchTreeBounds, PointsBeyondTheFloatRangeGetNoBoundRatherThanAWrongOne) {
  const std::vector<Vec3> corners = sphere_corners(6, 8);
  const SearchTree tree(corners, 3, {.max_leaf_items = 2});
  for (const Vec3 p : {Vec3{1e300, 0, 0}, Vec3{-1e200, 1e200, 3}, Vec3{0, 0, 0x1p101}}) {
    const std::vector<SearchTree::LaneBound> lanes = tree.lane_bounds(p);
    EXPECT_FALSE(lanes.empty());
    for (const SearchTree::LaneBound& lane : lanes) {
      EXPECT_EQ(lane.bound, 0.0);
    }
  }
}

}  // namespace
}  // namespace contain::distance::detail
