// The pair stage's work (PairWork in src/clip/solid/engine.h): what is added for triangles in
// any interleaving comes back grouped by triangle, each triangle's constraints and coplanar
// partners in the order added, against a vector of vectors per triangle filled alongside; and a
// triangle given nothing reads empty, with or without any work elsewhere.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "clip/solid/engine.h"

namespace contain::test {
namespace {

using clip::solid::Constraint;

TEST(SolidPairWork, GroupsByTriangleInTheOrderAdded) {
  for (const std::size_t triangles : {1U, 2U, 7U, 300U}) {
    for (const std::size_t adds : {0U, 1U, 5U, 2000U}) {
      std::mt19937 random(static_cast<unsigned>(triangles * 7919 + adds));
      std::uniform_int_distribution<std::size_t> pick(0, triangles - 1);
      std::uniform_int_distribution<int> kind(0, 3);
      clip::solid::PairWork work(triangles);
      std::vector<std::vector<Constraint>> constraints(triangles);
      std::vector<std::vector<std::int32_t>> coplanar(triangles);
      for (std::size_t k = 0; k < adds; ++k) {
        const auto t = static_cast<std::int32_t>(pick(random));
        const auto a = static_cast<std::int32_t>(k), b = static_cast<std::int32_t>(2 * k + 1);
        if (kind(random) == 0) {
          work.add_coplanar(t, a);
          coplanar[static_cast<std::size_t>(t)].push_back(a);
        } else {
          const Constraint c{a, b, k % 3 == 0 ? clip::solid::no_edge : std::uint64_t{k}};
          work.add_constraint(t, c);
          constraints[static_cast<std::size_t>(t)].push_back(c);
        }
      }
      work.finish();
      ASSERT_EQ(work.size(), triangles);
      std::size_t all = 0;
      for (std::size_t t = 0; t < triangles; ++t) {
        const clip::solid::TriangleWork w = work[t];
        ASSERT_EQ(w.constraints.size(), constraints[t].size()) << triangles << " " << adds;
        for (std::size_t i = 0; i < w.constraints.size(); ++i) {
          EXPECT_EQ(w.constraints[i].a, constraints[t][i].a);
          EXPECT_EQ(w.constraints[i].b, constraints[t][i].b);
          EXPECT_EQ(w.constraints[i].edge, constraints[t][i].edge);
        }
        EXPECT_TRUE(std::ranges::equal(w.coplanar, coplanar[t])) << triangles << " " << adds;
        all += constraints[t].size();
      }
      EXPECT_EQ(work.constraints(), all);
    }
  }
}

}  // namespace
}  // namespace contain::test
