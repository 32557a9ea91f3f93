// The point store of the mesh boolean (src/clip/solid/point_store.cpp) given a soup's vertices
// by taking over the soup's index (the engine's path) against a store given the same vertices
// one by one: the same numbers, the same answers for the vertices and for points added after
// (crossings and points of doubles, new or equal to a vertex), through table growth; and each
// point's written_exactly byte as its definition on the point. The point table keyed by two
// arrays (the store's soup vertices and its own points) against one array of them all.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include "clip/solid/engine.h"
#include "contain/predicates/orient3d.h"
#include "contain/shapes/mesh.h"

namespace contain::test {
namespace {

using clip::solid::ExactPoint;
using clip::solid::PointStore;
using clip::solid::Soup;

// A closed mesh: a tetrahedron with its corners moved by `shift`.
Mesh store_test_tetrahedron(Vec3 shift) {
  Mesh m;
  m.vertices = {shift + Vec3{0, 0, 0}, shift + Vec3{1, 0, 0}, shift + Vec3{0, 1, 0},
                shift + Vec3{0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return m;
}

// Random tetrahedra on a small lattice (shared corners across inputs: welded), with the
// negative zero in some coordinates.
std::vector<Mesh> store_test_inputs(std::mt19937& rng, int count) {
  std::uniform_int_distribution<int> cell(-3, 3);
  std::vector<Mesh> inputs;
  for (int i = 0; i < count; ++i) {
    Mesh m =
        store_test_tetrahedron(Vec3{static_cast<double>(cell(rng)), static_cast<double>(cell(rng)),
                                    static_cast<double>(cell(rng))});
    for (Vec3& v : m.vertices) {
      if (v.x == 0.0) v.x = -0.0;
    }
    inputs.push_back(std::move(m));
  }
  return inputs;
}

// Where a random segment crosses the plane of the soup's triangle k % count (line_plane, as the
// pair stage makes them), or nothing when the draws stay on one side.
std::optional<ExactPoint> crossing_of_a_triangle(const Soup& soup, int k, std::mt19937& rng) {
  std::uniform_real_distribution<double> coordinate(-4.0, 4.0);
  const TriangleIndices& t = soup.triangles[static_cast<std::size_t>(k) % soup.triangles.size()];
  const Vec3 a = soup.vertices[static_cast<std::size_t>(t[0])],
             b = soup.vertices[static_cast<std::size_t>(t[1])],
             c = soup.vertices[static_cast<std::size_t>(t[2])];
  for (int draw = 0; draw < 8; ++draw) {
    const Vec3 p{coordinate(rng), coordinate(rng), coordinate(rng)};
    const Vec3 q{coordinate(rng), coordinate(rng), coordinate(rng)};
    const Sign sp = predicates::orient3d(a, b, c, p), sq = predicates::orient3d(a, b, c, q);
    if (sp != Sign::zero && sq == -sp) return clip::solid::line_plane(p, q, a, b, c);
  }
  return std::nullopt;
}

TEST(SolidPointStore, TakingOverTheSoupsIndexNumbersPointsAsAddingEachVertexDoes) {
  std::mt19937 rng(25);
  std::uniform_real_distribution<double> coordinate(-4.0, 4.0);
  int checked = 0, written_exactly = 0, crossings = 0;
  for (int round = 0; round < 60; ++round) {
    const std::vector<Mesh> inputs = store_test_inputs(rng, 1 + round % 7);
    Result<Soup> soup = clip::solid::make_soup(inputs);
    ASSERT_TRUE(soup);
    PointStore one_by_one;
    for (const Vec3 v : soup->vertices)
      (void)one_by_one.add(v);
    PointStore taken;
    // As the engine: room reserved first (odd rounds: none), then the index moved in.
    if (round % 2 == 0) taken.reserve(clip::solid::store_room(soup->vertices.size()));
    taken.add_vertices(*soup, std::move(soup->index));
    ASSERT_EQ(taken.size(), one_by_one.size());
    // The soup keeps an empty index: a later add_vertices of it adds each vertex again.
    EXPECT_EQ(soup->index.size(), 0U);
    EXPECT_EQ(soup->index.find(soup->vertices[0], soup->vertices), -1);
    for (std::size_t i = 0; i < soup->vertices.size(); ++i) {
      const auto id = static_cast<std::int32_t>(i);
      EXPECT_EQ(taken.rounded(id), soup->vertices[i]);
      EXPECT_EQ(taken.representative(id), id);
      EXPECT_EQ(taken.first_rounded_to(soup->vertices[i]), id);
      EXPECT_TRUE(taken.written_exactly(id));
    }
    // Points added after: the vertices again (found, not added), new points of doubles,
    // constructed points (centroids) and crossings of triangles' planes, more than the reserved
    // room (the table grows).
    for (int k = 0; k < 3000; ++k) {
      std::int32_t a = 0, b = 0;
      if (k % 3 == 0) {
        const Vec3 v = soup->vertices[static_cast<std::size_t>(k) % soup->vertices.size()];
        a = taken.add(v);
        b = one_by_one.add(v);
      } else if (k % 3 == 1) {
        const Vec3 v{coordinate(rng), coordinate(rng), coordinate(rng)};
        a = taken.add(v);
        b = one_by_one.add(v);
      } else if (const std::optional<ExactPoint> x =
                     k % 6 == 5 ? crossing_of_a_triangle(*soup, k, rng) : std::nullopt;
                 x) {
        // A crossing (line_plane: the points the pair stage adds), added twice: found the
        // second time by its exact equality, in both stores.
        a = taken.add(*x);
        b = one_by_one.add(*x);
        ASSERT_EQ(taken.add(*x), a);
        ASSERT_EQ(one_by_one.add(*x), b);
        ++crossings;
      } else {
        const std::int32_t p =
            static_cast<std::int32_t>(static_cast<std::size_t>(k) % taken.size());
        const std::int32_t q =
            static_cast<std::int32_t>(static_cast<std::size_t>(k * 7) % taken.size());
        a = taken.add(clip::solid::centroid(taken.point(p), taken.point(q), taken.point(q)));
        b = one_by_one.add(
            clip::solid::centroid(one_by_one.point(p), one_by_one.point(q), one_by_one.point(q)));
      }
      ASSERT_EQ(a, b);
      // Past the soup's vertices, the store's own array of doubles (PointKeys' tail).
      ASSERT_EQ(taken.rounded(a), one_by_one.rounded(b));
      ASSERT_EQ(taken.representative(a), one_by_one.representative(b));
      const ExactPoint& p = taken.point(a);
      ASSERT_EQ(taken.written_exactly(a), p.plain() || p.enclosure().lo == p.enclosure().hi);
      written_exactly += taken.written_exactly(a) ? 1 : 0;
      ++checked;
    }
    EXPECT_EQ(taken.size(), one_by_one.size());
  }
  EXPECT_EQ(checked, 60 * 3000);
  EXPECT_GT(crossings, 60 * 100);
  // Not vacuous: midpoints of lattice points are doubles (exact), others are rounded.
  EXPECT_GT(written_exactly, 60 * 1000);
  EXPECT_LT(written_exactly, checked);
}

TEST(SolidPointTable, KeysInTwoArraysNumberPointsAsTheirConcatenationDoes) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> cell(-6, 6);  // few values: many repeats, and -0 and +0
  const auto point = [&] {
    double x = 0.5 * cell(rng);
    if (x == 0.0 && cell(rng) < 0) x = -0.0;  // one key with +0
    return Vec3{x, static_cast<double>(cell(rng)), 0.25 * cell(rng)};
  };
  std::vector<Vec3> head, tail, all;
  clip::solid::PointTable split, whole;
  // The head numbered first (a soup's welded vertices), then points added to the tail.
  for (int i = 0; i < 400; ++i) {
    const Vec3 v = point();
    const auto next = static_cast<std::int32_t>(all.size());
    const auto [id, fresh] = whole.try_emplace(v, next, all);
    const auto [split_id, split_fresh] = split.try_emplace(v, next, head);
    ASSERT_EQ(id, split_id);
    ASSERT_EQ(fresh, split_fresh);
    if (fresh) {
      all.push_back(v);
      head.push_back(v);
    }
  }
  int found = 0, found_in_head = 0;
  for (int i = 0; i < 4000; ++i) {  // through several growths of the table
    const Vec3 v = point() + Vec3{static_cast<double>(i % 97), 0, 0};
    const auto next = static_cast<std::int32_t>(all.size());
    const auto [id, fresh] = whole.try_emplace(v, next, all);
    const auto [split_id, split_fresh] =
        split.try_emplace(v, next, clip::solid::PointKeys{head, tail});
    ASSERT_EQ(id, split_id);
    ASSERT_EQ(fresh, split_fresh);
    if (fresh) {
      all.push_back(v);
      tail.push_back(v);
    } else {
      ++found;
      found_in_head += static_cast<std::size_t>(split_id) < head.size() ? 1 : 0;
    }
    ASSERT_EQ(split.find(v, clip::solid::PointKeys{head, tail}), whole.find(v, all));
  }
  EXPECT_EQ(split.size(), all.size());
  // Not vacuous: points found in both arrays, and new ones.
  EXPECT_GT(found_in_head, 0);
  EXPECT_GT(found - found_in_head, 0);
  EXPECT_GT(tail.size(), 100U);
  // -0 and +0 one key, directly: a head point with a zero found by its other sign, and a point
  // with -0 added to the tail found, and not added again, by +0.
  const clip::solid::PointKeys keys{head, tail};
  int signed_zeros = 0;
  for (std::size_t i = 0; i < head.size(); ++i) {
    if (head[i].x != 0.0) continue;
    const Vec3 flipped{-head[i].x, head[i].y, head[i].z};
    ASSERT_NE(std::signbit(flipped.x), std::signbit(head[i].x));
    EXPECT_EQ(split.find(flipped, keys), static_cast<std::int32_t>(i));
    ++signed_zeros;
  }
  EXPECT_GT(signed_zeros, 0);
  const Vec3 minus{-0.0, 1000.5, -0.0}, plus{0.0, 1000.5, 0.0};
  const auto next = static_cast<std::int32_t>(all.size());
  const auto [id, fresh] = split.try_emplace(minus, next, keys);
  ASSERT_TRUE(fresh);
  tail.push_back(minus);
  const clip::solid::PointKeys grown{head, tail};
  EXPECT_EQ(split.find(plus, grown), id);
  EXPECT_EQ(split.try_emplace(plus, next + 1, grown), std::make_pair(id, false));
}

TEST(SolidPointStore, AReservedEmptyStoreFindsWhatItAdds) {
  PointStore store;
  store.reserve(100);
  EXPECT_EQ(store.first_rounded_to(Vec3{1, 2, 3}), -1);
  const std::int32_t a = store.add(Vec3{1, 2, 3});
  EXPECT_EQ(a, 0);
  EXPECT_EQ(store.add(Vec3{1, 2, 3}), 0);
  EXPECT_EQ(store.add(Vec3{-0.0, 2, 3}), 1);
  EXPECT_EQ(store.add(Vec3{0.0, 2, 3}), 1);
  EXPECT_EQ(store.first_rounded_to(Vec3{0.0, 2, 3}), 1);
  for (int i = 0; i < 1000; ++i)
    EXPECT_EQ(store.add(Vec3{static_cast<double>(i), 0.5, 0}), 2 + i);
  EXPECT_EQ(store.add(Vec3{999, 0.5, 0}), 1001);
}

}  // namespace
}  // namespace contain::test
