#include "contain/distance/mesh_pair_distance.h"

#include <gtest/gtest.h>

#include <string>

#include "contain/inside/pair_witness.h"

namespace contain::distance {
namespace {

// The words of `contain distance --json` and Python's `contact` lists, unchanged by the merge of
// the two witness enums: both meeting kinds print "touching", no witness prints "separate".
TEST(DistanceWitness, WordsAreTheDistanceWordsForEveryWitness) {
  EXPECT_EQ(std::string(to_string(inside::PairWitness::none)), "separate");
  EXPECT_EQ(std::string(to_string(inside::PairWitness::triangles)), "touching");
  EXPECT_EQ(std::string(to_string(inside::PairWitness::edges)), "touching");
  EXPECT_EQ(std::string(to_string(inside::PairWitness::vertex_of_a_in_b)), "vertex_of_a_in_b");
  EXPECT_EQ(std::string(to_string(inside::PairWitness::vertex_of_b_in_a)), "vertex_of_b_in_a");
}

}  // namespace
}  // namespace contain::distance
