// The edge uses that the labels, the merging of coplanar faces and the sheets walk (EdgeUses:
// 8-byte entries bucketed by the lower point, a face's corner found again from its corners)
// agree with the plain grouping they replace: a map from each undirected edge to its uses
// (face, corner) in order of face then corner, on random faces over few points (fans of many
// faces on one edge, faces using an edge twice, repeated corners).

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include "clip/solid/edge_uses.h"
#include "support/case_budget.h"

namespace contain::test {
namespace {

using clip::solid::corner_of_edge;
using clip::solid::EdgeUses;
using Face = std::array<std::int32_t, 3>;
using Grouped =
    std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::pair<std::uint32_t, int>>>;

// Each undirected edge (a < b, or a == a) with its uses (face, corner) by face, then corner.
Grouped by_map(const std::vector<Face>& faces) {
  Grouped out;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = faces[f][static_cast<std::size_t>(k)];
      const std::int32_t b = faces[f][static_cast<std::size_t>((k + 1) % 3)];
      out[{std::min(a, b), std::max(a, b)}].emplace_back(static_cast<std::uint32_t>(f), k);
    }
  }
  return out;
}

// The same read from EdgeUses: a face's nth use of an edge in a group is its nth corner there.
Grouped by_edge_uses(const std::vector<Face>& faces) {
  const EdgeUses uses =
      clip::solid::edge_uses(faces.size(), [&](std::size_t f) -> const Face& { return faces[f]; });
  Grouped out;
  clip::solid::for_each_edge(
      uses, [&](std::int32_t a, std::int32_t b, std::span<const std::uint64_t> group) {
        auto& list = out[{a, b}];
        EXPECT_TRUE(list.empty()) << "edge visited twice";
        for (std::size_t i = 0; i < group.size(); ++i) {
          const std::uint32_t f = EdgeUses::face(group[i]);
          int nth = 0;
          for (std::size_t j = 0; j < i; ++j)
            nth += EdgeUses::face(group[j]) == f ? 1 : 0;
          list.emplace_back(f, corner_of_edge(faces[f], a, b, nth));
        }
      });
  return out;
}

TEST(EdgeUses, GroupsEveryUseAsAMapOfEdgesDoesOnRandomFacesWithFansAndRepeatedCorners) {
  std::mt19937 rng(25);
  int cases = 0, fans = 0, twice = 0;
  for (int c = 0; c < case_budget(400, 10); ++c) {
    const int points = 2 + static_cast<int>(rng() % 12);
    const std::size_t count = 1 + rng() % 60;
    std::uniform_int_distribution<std::int32_t> point(0, points - 1);
    std::vector<Face> faces(count);
    for (Face& f : faces)
      f = {point(rng), point(rng), point(rng)};
    const Grouped expected = by_map(faces);
    ASSERT_EQ(by_edge_uses(faces), expected) << "case " << c;
    ++cases;
    for (const auto& [edge, list] : expected) {
      fans += list.size() > 2 ? 1 : 0;
      for (std::size_t i = 1; i < list.size(); ++i)
        twice += list[i].first == list[i - 1].first ? 1 : 0;
    }
  }
  // Not vacuous: edges of more than two faces and faces using an edge twice were met.
  EXPECT_GE(cases, 40);
  EXPECT_GE(fans, 40);
  EXPECT_GE(twice, 40);
}

TEST(EdgeUses, ClosedMeshHasTwoOppositeUsesOfEveryEdge) {
  // An octahedron: every edge in two faces, in opposite directions.
  const std::vector<Face> faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  const EdgeUses uses =
      clip::solid::edge_uses(faces.size(), [&](std::size_t f) -> const Face& { return faces[f]; });
  int edges = 0;
  clip::solid::for_each_edge(
      uses, [&](std::int32_t a, std::int32_t b, std::span<const std::uint64_t> group) {
        ASSERT_EQ(group.size(), 2U);
        ++edges;
        const Face& x = faces[EdgeUses::face(group[0])];
        const Face& y = faces[EdgeUses::face(group[1])];
        const int i = corner_of_edge(x, a, b, 0), j = corner_of_edge(y, a, b, 0);
        EXPECT_EQ(x[static_cast<std::size_t>(i)], y[static_cast<std::size_t>((j + 1) % 3)]);
      });
  EXPECT_EQ(edges, 12);
}

}  // namespace
}  // namespace contain::test
