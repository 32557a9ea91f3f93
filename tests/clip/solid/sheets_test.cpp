// The sheets of the result kept apart around an edge held by more than two faces: every
// directed edge of the renumbered faces occurs once and its reverse once, also where rounding
// left the faces around the edge out of their alternating order (found on a torus minus itself
// turned a quarter: merged points put two opposite faces in one half-plane).

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <map>
#include <random>
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

// Octahedra on random lattice points, some of their vertices identified (pinches, fans of
// four faces on an edge, faces losing area or a corner), a face flipped or dropped, a second
// octahedron sharing points: whenever the sheets report every edge paired (the check of the
// written mesh then skips its edge test), each directed edge of the renumbered faces occurs
// once and its reverse once, as the edge test would find.
TEST(SolidSheets, EdgesReportedPairedAreEachMatchedOnceByTheirReverse) {
  std::mt19937 rng(2025);
  std::uniform_int_distribution<int> coordinate(-2, 2);
  const std::array<std::array<std::int32_t, 3>, 8> octahedron = {
      {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
  int paired = 0, unpaired = 0;
  for (int c = 0; c < case_budget(3000, 10); ++c) {
    PointStore store;
    std::vector<std::int32_t> point;
    for (int i = 0; i < 12; ++i) {
      point.push_back(
          store.add(Vec3{static_cast<double>(coordinate(rng)), static_cast<double>(coordinate(rng)),
                         static_cast<double>(coordinate(rng))}));
    }
    std::vector<std::array<std::int32_t, 3>> faces;
    const int shells = 1 + static_cast<int>(rng() % 2);
    for (int shell = 0; shell < shells; ++shell) {
      for (const auto& t : octahedron) {
        faces.push_back({point[static_cast<std::size_t>(t[0] + 6 * shell)],
                         point[static_cast<std::size_t>(t[1] + 6 * shell)],
                         point[static_cast<std::size_t>(t[2] + 6 * shell)]});
      }
    }
    const auto pick = [&](std::size_t n) { return static_cast<std::size_t>(rng() % n); };
    switch (rng() % 4) {
      case 0:  // corners moved at random onto other points (fans, pinches, repeated corners)
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
      default:
        break;
    }
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

}  // namespace
}  // namespace contain::test
