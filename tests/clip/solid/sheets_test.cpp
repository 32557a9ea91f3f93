// The sheets of the result kept apart around an edge held by more than two faces: every
// directed edge of the renumbered faces occurs once and its reverse once, also where rounding
// left the faces around the edge out of their alternating order (found on a torus minus itself
// turned a quarter: merged points put two opposite faces in one half-plane).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "clip/solid/engine.h"
#include "support/case_budget.h"

namespace contain::test {
namespace {

using clip::solid::PointStore;
using clip::solid::Sheets;

// How often each directed edge of the faces occurs.
std::map<std::pair<std::int32_t, std::int32_t>, int> directed_edges(const Sheets& sheets) {
  std::map<std::pair<std::int32_t, std::int32_t>, int> count;
  for (const auto& t : sheets.faces) {
    for (std::size_t k = 0; k < 3; ++k)
      ++count[{t[k], t[(k + 1) % 3]}];
  }
  return count;
}

// The four faces on the edge p q along the x axis: a (p -> q) and c (q -> p) in the half-plane
// y > 0, z = 0 (the same angle), b (q -> p) at a quarter turn, d (p -> q) at three quarters.
// Sorted by angle, a and c tie, and a before c gives p -> q, q -> p, q -> p, p -> q.
Sheets fan_with_a_tie(const std::array<int, 4>& order) {
  PointStore store;
  const std::int32_t p = store.add(Vec3{0, 0, 0}), q = store.add(Vec3{1, 0, 0});
  const std::int32_t a = store.add(Vec3{0.5, 1, 0}), c = store.add(Vec3{0.25, 2, 0});
  const std::int32_t b = store.add(Vec3{0.5, 0, 1}), d = store.add(Vec3{0.5, 0, -1});
  const std::array<std::array<std::int32_t, 3>, 4> all = {
      {{p, q, a}, {q, p, c}, {q, p, b}, {p, q, d}}};
  std::vector<std::array<std::int32_t, 3>> faces;
  for (const int i : order)
    faces.push_back(all[static_cast<std::size_t>(i)]);
  return clip::solid::separate_sheets(faces, store);
}

TEST(SolidSheets, AFanOutOfAlternatingOrderIsPairedWithEveryDirectedEdgeOnce) {
  for (const std::array<int, 4> order : {std::array{0, 1, 2, 3}, std::array{1, 0, 2, 3},
                                         std::array{2, 3, 0, 1}, std::array{3, 2, 1, 0}}) {
    const Sheets sheets = fan_with_a_tie(order);
    ASSERT_EQ(sheets.faces.size(), 4U);
    int on_axis = 0;  // the directed edges between the written copies of p and q
    for (const auto& [edge, n] : directed_edges(sheets)) {
      EXPECT_EQ(n, 1);
      const std::int32_t from = sheets.points[static_cast<std::size_t>(edge.first)];
      const std::int32_t to = sheets.points[static_cast<std::size_t>(edge.second)];
      if ((from == 0 && to == 1) || (from == 1 && to == 0)) {
        ++on_axis;
        EXPECT_EQ(directed_edges(sheets).count({edge.second, edge.first}), 1U)
            << "order " << order[0] << order[1] << order[2] << order[3];
      }
    }
    EXPECT_EQ(on_axis, 4);  // two sheets, each with p q once each way
  }
}

// One or two octahedra on 12 random lattice points of [-range, range]^3 (with `share`, the
// second drawn to share a point or an edge with the first, or neither), then a draw of
// rng() % `changes` picks: 0 corners moved at random onto other points (fans, pinches, repeated
// corners), 1 two faces' corners swapped, 2 a face dropped, 3 the faces shuffled (only when
// `changes` > 4), none otherwise.
std::vector<std::array<std::int32_t, 3>> random_octahedra(std::mt19937& rng, PointStore& store,
                                                          int range, bool share, unsigned changes) {
  std::uniform_int_distribution<int> coordinate(-range, range);
  const std::array<std::array<std::int32_t, 3>, 8> octahedron = {
      {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
  std::vector<std::int32_t> point;
  for (int i = 0; i < 12; ++i) {
    point.push_back(
        store.add(Vec3{static_cast<double>(coordinate(rng)), static_cast<double>(coordinate(rng)),
                       static_cast<double>(coordinate(rng))}));
  }
  const int shells = 1 + static_cast<int>(rng() % 2);
  if (share && shells == 2) {
    switch (rng() % 3) {
      case 0:  // sharing a point
        point[6] = point[0];
        break;
      case 1:  // sharing an edge
        point[6] = point[0];
        point[8] = point[2];
        break;
      default:  // apart (or meeting where the lattice repeats a position)
        break;
    }
  }
  std::vector<std::array<std::int32_t, 3>> faces;
  for (int shell = 0; shell < shells; ++shell) {
    for (const auto& t : octahedron) {
      faces.push_back({point[static_cast<std::size_t>(t[0] + 6 * shell)],
                       point[static_cast<std::size_t>(t[1] + 6 * shell)],
                       point[static_cast<std::size_t>(t[2] + 6 * shell)]});
    }
  }
  const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
  switch (rng() % changes) {
    case 0:
      for (auto& f : faces) {
        for (auto& v : f)
          v = v == point[pick(12)] ? point[pick(12)] : v;
      }
      break;
    case 1:
      std::swap(faces[pick(faces.size())][0], faces[pick(faces.size())][1]);
      break;
    case 2:
      faces.erase(faces.begin() + static_cast<std::ptrdiff_t>(pick(faces.size())));
      break;
    case 3:
      if (changes > 4) std::shuffle(faces.begin(), faces.end(), rng);
      break;
    default:
      break;
  }
  return faces;
}

// Octahedra on random lattice points, some of their vertices identified (pinches, fans of
// four faces on an edge, faces losing area or a corner), a face flipped or dropped, a second
// octahedron sharing points: whenever the sheets report every edge paired (the check of the
// written mesh then skips its edge test), each directed edge of the renumbered faces occurs
// once and its reverse once, as the edge test would find.
TEST(SolidSheets, EdgesReportedPairedAreEachMatchedOnceByTheirReverse) {
  std::mt19937 rng(2025);
  int paired = 0, unpaired = 0;
  for (int c = 0; c < case_budget(3000, 10); ++c) {
    PointStore store;
    const std::vector<std::array<std::int32_t, 3>> faces =
        random_octahedra(rng, store, 2, false, 4);
    const Sheets sheets = clip::solid::separate_sheets(faces, store);
    (sheets.paired ? paired : unpaired) += 1;
    if (!sheets.paired) continue;
    for (const auto& [edge, n] : directed_edges(sheets)) {
      ASSERT_EQ(n, 1) << "case " << c;
      ASSERT_EQ(directed_edges(sheets).count({edge.second, edge.first}), 1U) << "case " << c;
    }
  }
  // Not vacuous: both answers, many times.
  EXPECT_GE(paired, 50);
  EXPECT_GE(unpaired, 50);
}

// A bipyramid of `sides` sides around the z axis: its two apexes have `sides` corners each.
std::vector<std::array<std::int32_t, 3>> bipyramid(PointStore& store, int sides) {
  std::vector<std::int32_t> ring;
  for (int i = 0; i < sides; ++i) {
    const double angle = 6.283185307179586 * i / sides;
    ring.push_back(store.add(Vec3{std::cos(angle), std::sin(angle), 0.0}));
  }
  const std::int32_t top = store.add(Vec3{0, 0, 1}), bottom = store.add(Vec3{0, 0, -1});
  std::vector<std::array<std::int32_t, 3>> faces;
  for (int i = 0; i < sides; ++i) {
    const std::int32_t a = ring[static_cast<std::size_t>(i)];
    const std::int32_t b = ring[static_cast<std::size_t>((i + 1) % sides)];
    faces.push_back({a, b, top});
    faces.push_back({b, a, bottom});
  }
  return faces;
}

// The sheets found from each point's umbrella (single_umbrellas, the engine's way for closed
// manifold results) are those of the general grouping of edge uses (sheets_by_edges) whenever
// it answers, and it answers whenever the general way finds every edge paired and one written
// vertex per point (its points have at most 64 corners): octahedra on random lattice points
// with corners moved onto other points (pinches, fans, repeated corners), a face flipped or
// dropped, a second octahedron apart or sharing a point (pinched: two umbrellas) or an edge (a
// fan of four faces), faces in shuffled order; bipyramids of 40 sides (answered) and 70 (more
// than 64 corners at the apexes: the general way).
TEST(SolidSheets, SingleUmbrellasAreTheGeneralSheetsWheneverEveryPointHasOne) {
  std::mt19937 rng(77);
  int answered = 0, general = 0;
  const auto compare = [&](const std::vector<std::array<std::int32_t, 3>>& faces,
                           const PointStore& store, const std::string& what) {
    const Sheets all = clip::solid::sheets_by_edges(faces, store);
    const std::optional<Sheets> fast = clip::solid::single_umbrellas(faces);
    if (fast) {
      ++answered;
      EXPECT_TRUE(fast->paired) << what;
      EXPECT_TRUE(all.paired) << what;
      EXPECT_EQ(fast->faces, all.faces) << what;
      EXPECT_EQ(fast->points, all.points) << what;
      return;
    }
    ++general;
    std::map<std::int32_t, int> corners;
    for (const auto& f : faces) {
      for (const std::int32_t p : f)
        ++corners[p];
    }
    bool few = true;
    for (const auto& [p, n] : corners)
      few = few && n <= 64;
    EXPECT_FALSE(all.paired && all.points.size() == corners.size() && few)
        << what << ": every point one umbrella, not answered";
  };
  for (int c = 0; c < case_budget(3000, 10); ++c) {
    PointStore store;
    const std::vector<std::array<std::int32_t, 3>> faces = random_octahedra(rng, store, 3, true, 5);
    compare(faces, store, "case " + std::to_string(c));
  }
  for (const int sides : {40, 70}) {
    PointStore store;
    const std::vector<std::array<std::int32_t, 3>> faces = bipyramid(store, sides);
    const int before = answered;
    compare(faces, store, "bipyramid " + std::to_string(sides));
    EXPECT_EQ(answered > before, sides <= 64) << sides;
  }
  // Not vacuous: both ways, many times (in proportion to the cases: the sanitized build runs a
  // tenth of them).
  EXPECT_GE(answered, case_budget(100, 10));
  EXPECT_GE(general, case_budget(100, 10));
}

}  // namespace
}  // namespace contain::test
