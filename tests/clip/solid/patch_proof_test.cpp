// The patch proofs of the pair stage (patch_proof.h) are sound: a set of triangles proven an
// embedded patch never holds two triangles that meet beyond their shared corners or edge
// (predicates::triangles_meet_beyond_shared on every pair, brute force), on height fields
// folded, jittered and cut at random, coplanar overlaps, a ring winding twice, spiral strips and
// touching triangles; the proofs are not vacuous (height fields and the subtrees of smooth
// spheres are proven); and the pair stage of self-intersecting inputs gives the same points and
// work with the skip as with every pair tested (so the same boolean).

#include "clip/solid/patch_proof.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "clip/solid/engine.h"
#include "clip/solid/solid_oracle.h"
#include "clip/solid/star_proof.h"
#include "contain/predicates/closest_feature.h"
#include "contain/predicates/triangles_meet.h"
#include "scenes/scenes.h"
#include "support/case_budget.h"

namespace contain::test {
namespace {

using clip::solid::embedded_patch;
using clip::solid::PatchProofs;
using clip::solid::Soup;

Triangle3 triangle_of(const Soup& soup, std::size_t t) {
  const TriangleIndices& v = soup.triangles[t];
  return {soup.vertices[static_cast<std::size_t>(v[0])],
          soup.vertices[static_cast<std::size_t>(v[1])],
          soup.vertices[static_cast<std::size_t>(v[2])]};
}

// Brute force: some pair of the soup's triangles meets beyond the corners it shares (by
// position), or a triangle has zero area or comes twice.
bool some_pair_meets(const Soup& soup) {
  const std::size_t n = soup.triangles.size();
  for (std::size_t t = 0; t < n; ++t) {
    const Triangle3 a = triangle_of(soup, t);
    if (predicates::collinear(a.a, a.b, a.c)) return true;
    for (std::size_t u = t + 1; u < n; ++u) {
      const Triangle3 b = triangle_of(soup, u);
      const std::array<int, 3> shared = predicates::shared_corners(a, b);
      if (std::count(shared.begin(), shared.end(), -1) == 0) return true;
      if (predicates::triangles_meet_beyond_shared(a, b, shared)) return true;
    }
  }
  return false;
}

std::vector<std::int32_t> all_of(const Soup& soup) {
  std::vector<std::int32_t> patch(soup.triangles.size());
  for (std::size_t t = 0; t < patch.size(); ++t)
    patch[t] = static_cast<std::int32_t>(t);
  return patch;
}

// Whether the whole soup is claimed embedded; a claim is checked by brute force.
bool claimed(const Soup& soup, const std::string& what) {
  const bool embedded = embedded_patch(soup, all_of(soup));
  if (embedded) {
    EXPECT_FALSE(some_pair_meets(soup)) << what;
  }
  return embedded;
}

// An n x n grid of squares over [0, n]^2, vertex (i, j) at position(i, j), each square cut
// along a diagonal chosen by `cut`, triangles counter-clockwise seen from +z in the grid.
template <class Position, class Cut>
Soup grid_patch(int n, Position position, Cut cut) {
  std::vector<Vec3> vertices;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i)
      vertices.push_back(position(i, j));
  }
  std::vector<TriangleIndices> triangles;
  const auto id = [&](int i, int j) { return static_cast<std::int32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const std::int32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (cut(i, j)) {
        triangles.push_back({a, b, c});
        triangles.push_back({a, c, d});
      } else {
        triangles.push_back({a, b, d});
        triangles.push_back({b, c, d});
      }
    }
  }
  return raw_soup(vertices, triangles);
}

TEST(PatchProof, HeightFieldsAreEmbeddedWhateverTheirHeights) {
  std::mt19937_64 rng(250);
  const int cases = case_budget(40, 4);
  for (int k = 0; k < cases; ++k) {
    const double height = std::array{0.0, 0.1, 10.0, 1e6}[static_cast<std::size_t>(k % 4)];
    std::uniform_real_distribution<double> z(-height, height);
    std::bernoulli_distribution coin(0.5);
    const int n = 2 + k % 9;
    const Soup soup = grid_patch(
        n,
        [&](int i, int j) {
          return Vec3{i * 0.5, j * 0.25, z(rng)};
        },
        [&](int, int) { return coin(rng); });
    EXPECT_TRUE(claimed(soup, "height field " + std::to_string(k))) << k;
  }
  // Turned to face -x (the projection dropping x), and reversed (turning the other way).
  const Soup turned = grid_patch(
      5,
      [](int i, int j) {
        return Vec3{std::sin(i + j) * 0.3, i * 1.0, j * 1.0};
      },
      [](int i, int j) { return (i + j) % 2 == 0; });
  EXPECT_TRUE(claimed(turned, "turned"));
  std::vector<TriangleIndices> flipped = turned.triangles;
  for (TriangleIndices& t : flipped)
    std::swap(t[1], t[2]);
  EXPECT_TRUE(claimed(raw_soup(turned.vertices, flipped), "reversed"));
}

TEST(PatchProof, JitteredFoldedAndCutPatchesAreNeverClaimedWhenTwoTrianglesMeet) {
  std::mt19937_64 rng(2525);
  const int cases = case_budget(1200, 6);
  std::size_t claims = 0, meetings = 0;
  for (int k = 0; k < cases; ++k) {
    // Jitter up to most of a cell folds some triangles over their neighbours; flat patches
    // (height 0) overlap coplanar where they fold, low ones cross.
    const double jitter = std::array{0.2, 0.6, 1.2}[static_cast<std::size_t>(k % 3)];
    const double height = std::array{0.0, 0.05, 1.0}[static_cast<std::size_t>(k / 3 % 3)];
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::bernoulli_distribution coin(0.5);
    const int n = 2 + k % 5;
    Soup soup = grid_patch(
        n,
        [&](int i, int j) {
          return Vec3{i + jitter * u(rng), j + jitter * u(rng), height * u(rng)};
        },
        [&](int, int) { return coin(rng); });
    // Every fourth case adds a second grid over the first (crossing it, or in its plane).
    if (k % 4 == 3) {
      const Vec3 shift{n * 0.5 * u(rng), n * 0.5 * u(rng), height * u(rng)};
      std::vector<Vec3> vertices = soup.vertices;
      std::vector<TriangleIndices> triangles = soup.triangles;
      const auto offset = static_cast<std::int32_t>(vertices.size());
      for (const Vec3 v : soup.vertices)
        vertices.push_back({v.x + shift.x, v.y + shift.y, v.z + shift.z});
      for (const TriangleIndices& t : soup.triangles)
        triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
      soup = raw_soup(vertices, triangles);
    }
    // Every third case keeps a random part of the grid (holes, pieces, pinched corners).
    if (k % 3 == 2) {
      std::vector<TriangleIndices> kept;
      for (const TriangleIndices& t : soup.triangles) {
        if (coin(rng) || kept.empty()) kept.push_back(t);
      }
      soup = raw_soup(soup.vertices, kept);
    }
    const bool meet = some_pair_meets(soup);
    const bool claim = embedded_patch(soup, all_of(soup));
    EXPECT_FALSE(claim && meet) << "case " << k;
    claims += claim ? 1 : 0;
    meetings += meet ? 1 : 0;
  }
  // Not vacuous: some patches are proven, some fold onto themselves.
  EXPECT_GT(claims, 0U);
  EXPECT_GT(meetings, 0U);
}

// A cone with apex 0 whose ring of n points winds `windings` times around it, at heights
// z(i): the fan's triangles all turn one way seen from +z.
Soup winding_fan(int n, int windings, double rise) {
  std::vector<Vec3> vertices{{0, 0, 0}};
  std::vector<TriangleIndices> triangles;
  const double step = windings * 2.0 * std::numbers::pi / n;
  for (int i = 0; i < n; ++i) {
    vertices.push_back({std::cos(i * step), std::sin(i * step), rise * std::sin(i * step * 0.5)});
    triangles.push_back({0, 1 + i, 1 + (i + 1) % n});
  }
  return raw_soup(vertices, triangles);
}

TEST(PatchProof, ARingWindingTwiceIsNotEmbeddedOnceIs) {
  for (const double rise : {0.0, 0.3}) {
    EXPECT_FALSE(claimed(winding_fan(9, 2, rise), "twice")) << rise;
    EXPECT_FALSE(claimed(winding_fan(13, 3, rise), "thrice")) << rise;
    EXPECT_TRUE(claimed(winding_fan(7, 1, rise), "once")) << rise;
  }
  // Flat and winding twice, its triangles overlap.
  EXPECT_TRUE(some_pair_meets(winding_fan(9, 2, 0.0)));
}

// A strip of `quads` quadrilaterals along a spiral that turns `turns` times, rising by `rise`
// a turn: a disk whose triangles all turn one way, its boundary one cycle, overlapping itself in
// projection after a turn (and in space when it does not rise).
Soup spiral_strip(int quads, double turns, double rise) {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  for (int i = 0; i <= quads; ++i) {
    const double a = turns * 2.0 * std::numbers::pi * i / quads;
    const double z = rise * a / (2.0 * std::numbers::pi);
    vertices.push_back({std::cos(a), std::sin(a), z});
    vertices.push_back({2 * std::cos(a), 2 * std::sin(a), z});
  }
  for (int i = 0; i < quads; ++i) {
    const auto a = static_cast<std::int32_t>(2 * i);
    triangles.push_back({a, a + 1, a + 3});
    triangles.push_back({a, a + 3, a + 2});
  }
  return raw_soup(vertices, triangles);
}

TEST(PatchProof, SpiralStripsOverlappingTheirFirstTurnAreNotEmbedded) {
  EXPECT_TRUE(claimed(spiral_strip(24, 0.75, 0.0), "three quarters"));
  for (const double rise : {0.0, 0.5}) {
    EXPECT_FALSE(claimed(spiral_strip(24, 1.25, rise), "a turn and a quarter")) << rise;
    EXPECT_FALSE(claimed(spiral_strip(40, 2.0, rise), "two turns")) << rise;
  }
  EXPECT_TRUE(some_pair_meets(spiral_strip(24, 1.25, 0.0)));
}

TEST(PatchProof, CoplanarOverlapsTouchingTrianglesAndNonDisksAreNotEmbedded) {
  // Pairs that share vertex 0 by number, so that their boundary is one chain, pinched there:
  // refused by the boundary's own test (edges meeting beyond shared ends), not for being apart.
  const auto pair_refused = [](const std::vector<Vec3>& vertices, const char* what) {
    const Soup soup = raw_soup(vertices, {{0, 1, 2}, {0, 3, 4}});
    EXPECT_TRUE(some_pair_meets(soup)) << what;  // a case the proof must refuse
    EXPECT_FALSE(claimed(soup, what));
  };
  // Two coplanar triangles overlapping beyond their shared corner.
  pair_refused({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 1, 0}, {1, 2, 0}}, "coplanar overlap");
  // A corner of one on the other's edge (coplanar, along it), and on its face from above.
  pair_refused({{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, -1, 0}, {1, 0, 0}}, "corner on an edge");
  pair_refused({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, 0}, {1, 3, 1}}, "corner on a face");
  // Two apart (two boundary cycles), the same triangle twice, a flat annulus (two cycles).
  EXPECT_FALSE(claimed(raw_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}},
                                {{0, 1, 2}, {3, 4, 5}}),
                       "two apart"));
  EXPECT_FALSE(
      claimed(raw_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 1, 2}}), "twice"));
  std::vector<Vec3> ring;
  std::vector<TriangleIndices> annulus;
  for (int i = 0; i < 8; ++i) {
    const double a = i * std::numbers::pi / 4;
    ring.push_back({std::cos(a), std::sin(a), 0});
    ring.push_back({2 * std::cos(a), 2 * std::sin(a), 0});
  }
  for (std::int32_t i = 0; i < 8; ++i) {
    const std::int32_t a = 2 * i, b = 2 * ((i + 1) % 8);
    annulus.push_back({a, a + 1, b + 1});
    annulus.push_back({a, b + 1, b});
  }
  EXPECT_FALSE(claimed(raw_soup(ring, annulus), "annulus"));
}

TEST(PatchProof, PinchedBoundariesAreEmbeddedExactlyWhenTheirLobesAreApart) {
  // Two triangles sharing only corner 0: apart (a bow tie), or one within the other's angle
  // (nested at the pinch: the edges around corner 0 go out, out, in, in).
  const std::vector<Vec3> bow{{0, 0, 0}, {2, 1, 0.5}, {2, 2, 0}, {-2, -1, 0.3}, {-2, -2, 0}};
  EXPECT_TRUE(claimed(raw_soup(bow, {{0, 1, 2}, {0, 3, 4}}), "bow tie"));
  const std::vector<Vec3> nested{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 0.5, 0}, {0.5, 1, 0}};
  EXPECT_FALSE(claimed(raw_soup(nested, {{0, 1, 2}, {0, 3, 4}}), "nested"));
  EXPECT_TRUE(some_pair_meets(raw_soup(nested, {{0, 1, 2}, {0, 3, 4}})));
  // Lifted off the plane it still overlaps in projection: not claimed (though apart in space).
  const std::vector<Vec3> lifted{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 0.5, 1}, {0.5, 1, 1}};
  EXPECT_FALSE(claimed(raw_soup(lifted, {{0, 1, 2}, {0, 3, 4}}), "lifted"));
  // A square with a square hole touching its outer boundary at corner 0 (a pinched annulus):
  // outer 0 1 2 3 = (0,0) (4,0) (4,4) (0,4), hole 0 4 5 6 = (0,0) (2,1) (2,2) (1,2).
  const std::vector<Vec3> frame{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0},
                                {2, 1, 0}, {2, 2, 0}, {1, 2, 0}};
  const std::vector<TriangleIndices> pinched_annulus{{0, 1, 4}, {1, 5, 4}, {1, 2, 5},
                                                     {2, 6, 5}, {2, 3, 6}, {3, 0, 6}};
  EXPECT_TRUE(claimed(raw_soup(frame, pinched_annulus), "pinched annulus"));
  // Three lobes at one corner are left unproven.
  const std::vector<Vec3> three{{0, 0, 0},  {2, 0, 0},   {2, 1, 0}, {-1, 2, 0},
                                {-2, 1, 0}, {-1, -2, 0}, {0, -2, 0}};
  EXPECT_FALSE(claimed(raw_soup(three, {{0, 1, 2}, {0, 3, 4}, {0, 5, 6}}), "three lobes"));
}

// The subtrees of `soup`'s hierarchy proven by PatchProofs, each checked by brute force.
std::size_t settled_subtrees(const Soup& soup) {
  // The pair stage's path: the stars in leaf order, taken over by the proofs.
  clip::solid::ProvenStars stars = clip::solid::proven_stars(soup, clip::solid::StarOrder::leaf);
  const PatchProofs proofs = PatchProofs::from_leaf_order(soup, stars);
  const std::span<const bvh::Node> nodes = soup.tree.nodes();
  std::size_t settled = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!proofs.settled(static_cast<std::int32_t>(i))) continue;
    ++settled;
    std::vector<TriangleIndices> below;
    // The subtree's triangles: its leaves' items.
    std::vector<std::int32_t> stack{static_cast<std::int32_t>(i)};
    while (!stack.empty()) {
      const bvh::Node& n = nodes[static_cast<std::size_t>(stack.back())];
      const std::int32_t index = stack.back();
      stack.pop_back();
      if (n.is_leaf()) {
        for (std::int32_t k = n.first; k < n.first + n.count; ++k) {
          below.push_back(soup.triangles[static_cast<std::size_t>(
              soup.tree.items()[static_cast<std::size_t>(k)])]);
        }
      } else {
        stack.push_back(index + 1);
        stack.push_back(n.first);
      }
    }
    EXPECT_FALSE(some_pair_meets(raw_soup(soup.vertices, below))) << "node " << i;
  }
  return settled;
}

Soup welded_soup(const std::vector<Mesh>& inputs) {
  Result<Soup> soup = clip::solid::make_soup(inputs);
  EXPECT_TRUE(soup.ok());
  return soup.ok() ? std::move(*soup) : Soup{};
}

TEST(PatchProof, SubtreesOfSmoothSpheresAreSettledAndSound) {
  const Soup sphere = welded_soup({icosphere(4, 1.0, {0, 0, 0})});
  EXPECT_GT(settled_subtrees(sphere), 8U);
  // A lumpy sphere (saddles between the lumps: unproven corners there) turned off the axes,
  // then jittered by a hundredth of its edges: settled subtrees checked the same way.
  Mesh lumpy = icosphere(4, 1.0, {0, 0, 0});
  for (Vec3& v : lumpy.vertices) {
    const double r = 1.0 + 0.15 * std::sin(3 * v.x) * std::cos(2 * v.y + v.z);
    v = {r * (v.x * 0.8 - v.z * 0.6), r * v.y, r * (v.x * 0.6 + v.z * 0.8)};
  }
  const std::size_t lumpy_settled = settled_subtrees(welded_soup({lumpy}));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.0005, 0.0005);
  for (Vec3& v : lumpy.vertices)
    v = {v.x + jitter(rng), v.y + jitter(rng), v.z + jitter(rng)};
  const std::size_t jittered_settled = settled_subtrees(welded_soup({lumpy}));
  EXPECT_GT(lumpy_settled, 8U);
  EXPECT_GT(jittered_settled, 8U);
  // Two crossing spheres: settled subtrees away from the crossing.
  const Soup pair = welded_soup({icosphere(3, 1.0, {0, 0, 0}), icosphere(3, 1.0, {0.5, 0.4, 0.3})});
  EXPECT_GT(settled_subtrees(pair), 4U);
}

// The pair stage's work and how many points it stored.
struct PairWork {
  clip::solid::PairWork work;
  std::size_t points = 0;
};

PairWork pair_work(const Soup& soup, clip::solid::Neighbours neighbours) {
  clip::solid::PointStore store;
  store.add_vertices(soup);
  PairWork out;
  out.work = clip::solid::intersect_pairs(soup, store, neighbours);
  out.points = store.size();
  return out;
}

// The same points stored and the same work for each triangle (constraints by point numbers and
// in order, coplanar partners in order): every later stage, and so the boolean of any
// operation, is the same. Returns the number of constraints.
std::size_t expect_same_work(const PairWork& x, const PairWork& y, const std::string& what) {
  EXPECT_EQ(x.points, y.points) << what;
  EXPECT_EQ(x.work.size(), y.work.size()) << what;
  if (x.points != y.points || x.work.size() != y.work.size()) return 0;
  std::size_t constraints = 0;
  for (std::size_t t = 0; t < x.work.size(); ++t) {
    const std::span<const clip::solid::Constraint> a = x.work[t].constraints;
    const std::span<const clip::solid::Constraint> b = y.work[t].constraints;
    EXPECT_EQ(a.size(), b.size()) << what << ": triangle " << t;
    for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
      EXPECT_TRUE(a[k].a == b[k].a && a[k].b == b[k].b && a[k].edge == b[k].edge)
          << what << ": triangle " << t << ", constraint " << k;
    }
    EXPECT_TRUE(std::ranges::equal(x.work[t].coplanar, y.work[t].coplanar))
        << what << ": triangle " << t;
    constraints += a.size();
  }
  return constraints;
}

TEST(PatchProof, PairStageOfSelfIntersectingInputsIsTheSameWithAndWithoutTheSkip) {
  // One input two overlapping spheres (self-intersecting), the other a sphere across both; one
  // with an inside-out sphere; a sphere with itself; two self-intersecting inputs; a bumpy
  // sphere (saddles, unproven corners) with a self-intersecting input. (Spheres of 5,120
  // triangles and more: the soups pass `patch_proofs_from`.)
  const Mesh a = icosphere(4, 1.0, {0, 0, 0});
  const Mesh b = icosphere(4, 1.0, {0.6, 0.1, -0.2});
  const Mesh c = icosphere(4, 0.8, {0.3, 0.9, 0.4});
  // Bumpy: every vertex moved along its radius by up to 3% (saddles, unproven corners).
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> bump(0.97, 1.03);
  Mesh bumpy = icosphere(5, 1.0, {0, 0, 0});
  for (Vec3& v : bumpy.vertices) {
    const double f = bump(rng);
    v = {v.x * f, v.y * f, v.z * f};
  }
  const std::vector<std::vector<Mesh>> cases = {{joined(a, b), c},
                                                {joined(a, reversed(c)), b},
                                                {a, a},
                                                {joined(a, b), joined(b, c)},
                                                {bumpy, joined(b, c)}};
  std::size_t constraints = 0, settled = 0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const Soup soup = welded_soup(cases[k]);
    ASSERT_GE(soup.triangles.size(), clip::solid::patch_proofs_from);
    constraints += expect_same_work(pair_work(soup, clip::solid::Neighbours::tested),
                                    pair_work(soup, clip::solid::Neighbours::proven),
                                    "case " + std::to_string(k));
    // The pair stage's path (leaf order, taken over), and the same proofs from the stars in
    // triangle order: every node settled alike.
    clip::solid::ProvenStars leaf = clip::solid::proven_stars(soup, clip::solid::StarOrder::leaf);
    const PatchProofs proofs = PatchProofs::from_leaf_order(soup, leaf);
    const clip::solid::ProvenStars by_triangle =
        clip::solid::proven_stars(soup, clip::solid::StarOrder::triangle);
    const PatchProofs copied(soup, by_triangle);
    for (std::size_t i = 0; i < soup.tree.nodes().size(); ++i) {
      const auto node = static_cast<std::int32_t>(i);
      EXPECT_EQ(proofs.settled(node), copied.settled(node)) << "case " << k << ": node " << i;
      settled += proofs.settled(node) ? 1 : 0;
    }
  }
  // Not vacuous: the inputs cross, and subtrees are skipped.
  EXPECT_GT(constraints, 0U);
  EXPECT_GT(settled, 0U);
}

}  // namespace
}  // namespace contain::test
