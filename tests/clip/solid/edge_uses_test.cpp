// The edge uses that the labels, the merging of coplanar faces and the sheets walk (EdgeUses:
// 8-byte entries bucketed by the lower point, a face's corner found again from its corners)
// agree with the plain grouping they replace: a map from each undirected edge to its uses
// (face, corner) in order of face then corner, on random faces over few points (fans of many
// faces on one edge, faces using an edge twice, repeated corners).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include "clip/solid/edge_uses.h"
#include "clip/solid/engine.h"
#include "contain/core/union_find.h"
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

// The labels' patches found from each point's corners (face_patches) join the faces that a
// plain map of every edge's uses joins by the rule: an edge with exactly two uses, one each
// way, of faces whose triangles are of the same input, not a curve edge. Random faces over few
// points (fans, both directions, faces using an edge twice, repeated corners, self-loops), with
// random inputs per triangle and random curve edges; the sets compared by every face's
// smallest face (both union-finds lead by the smallest).
TEST(EdgeUses, PatchesFromCornersJoinWhatAMapOfEdgeUsesJoins) {
  std::mt19937 rng(31);
  int joined = 0, kept_apart = 0;
  for (int c = 0; c < case_budget(400, 10); ++c) {
    const int points = 2 + static_cast<int>(rng() % 12);
    const int triangles = 1 + static_cast<int>(rng() % 6);
    clip::solid::Soup soup;
    for (int t = 0; t < triangles; ++t)
      soup.input.push_back(static_cast<std::int32_t>(rng() % 2));
    clip::solid::Refinement r;
    const int faces = 1 + static_cast<int>(rng() % 40);
    for (int f = 0; f < faces; ++f) {
      Face v{};
      for (auto& p : v)
        p = static_cast<std::int32_t>(rng() % static_cast<unsigned>(points));
      r.faces.push_back({v, static_cast<std::int32_t>(rng() % static_cast<unsigned>(triangles))});
    }
    // Some edges of the faces are curve edges.
    for (const auto& face : r.faces) {
      for (std::size_t k = 0; k < 3; ++k) {
        const std::int32_t a = face.v[k], b = face.v[(k + 1) % 3];
        if (a != b && rng() % 4 == 0) r.curve_edges.push_back(clip::solid::edge_key(a, b));
      }
    }
    std::sort(r.curve_edges.begin(), r.curve_edges.end());
    r.curve_edges.erase(std::unique(r.curve_edges.begin(), r.curve_edges.end()),
                        r.curve_edges.end());
    // The rule on a map of every use: (face, runs from the lower point).
    std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::pair<std::uint32_t, bool>>>
        uses;
    for (std::size_t f = 0; f < r.faces.size(); ++f) {
      for (std::size_t k = 0; k < 3; ++k) {
        const std::int32_t a = r.faces[f].v[k], b = r.faces[f].v[(k + 1) % 3];
        if (a == b) continue;  // a self-loop joins nothing
        uses[{std::min(a, b), std::max(a, b)}].emplace_back(static_cast<std::uint32_t>(f), a < b);
      }
    }
    UnionFind<std::uint32_t> expected(r.faces.size());
    for (const auto& [edge, list] : uses) {
      if (list.size() != 2 || list[0].second == list[1].second) continue;
      const std::uint32_t x = list[0].first, y = list[1].first;
      const bool same_input = soup.input[static_cast<std::size_t>(r.faces[x].triangle)] ==
                              soup.input[static_cast<std::size_t>(r.faces[y].triangle)];
      const bool curve = std::binary_search(r.curve_edges.begin(), r.curve_edges.end(),
                                            clip::solid::edge_key(edge.first, edge.second));
      if (same_input && !curve && x != y) {
        expected.unite(x, y);
        ++joined;
      } else {
        ++kept_apart;
      }
    }
    clip::solid::PatchSets found = clip::solid::face_patches(soup, r);
    for (std::uint32_t f = 0; f < r.faces.size(); ++f)
      ASSERT_EQ(found.find(f), expected.find(f)) << "case " << c << " face " << f;
  }
  // Not vacuous: edges of both kinds, many times (in proportion to the cases: the sanitized
  // build runs a tenth of them).
  EXPECT_GE(joined, case_budget(200, 10));
  EXPECT_GE(kept_apart, case_budget(200, 10));
}

}  // namespace
}  // namespace contain::test
