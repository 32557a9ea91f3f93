#include "contain/distance/mesh_pair_distance.h"

#include <gtest/gtest.h>

#include <string>
#include <type_traits>

#include "contain/inside/pair_witness.h"

namespace contain::distance {
namespace {

TEST(PairContact, IsThePairWitnessOfInsideThatCollideAlsoNames) {
  EXPECT_TRUE((std::is_same_v<PairContact, inside::PairWitness>));
}

// The words of `contain distance --json` and Python's `contact` lists, unchanged by the merge of
// the two witness enums: both meeting kinds print "touching", no witness prints "separate".
TEST(PairContact, WordsAreTheDistanceWordsForEveryWitness) {
  EXPECT_EQ(std::string(to_string(PairContact::none)), "separate");
  EXPECT_EQ(std::string(to_string(PairContact::triangles)), "touching");
  EXPECT_EQ(std::string(to_string(PairContact::edges)), "touching");
  EXPECT_EQ(std::string(to_string(PairContact::vertex_of_a_in_b)), "vertex_of_a_in_b");
  EXPECT_EQ(std::string(to_string(PairContact::vertex_of_b_in_a)), "vertex_of_b_in_a");
}

}  // namespace
}  // namespace contain::distance
