#include "contain/collide/contact.h"

#include <gtest/gtest.h>

#include <string>

#include "contain/inside/pair_witness.h"

namespace contain::collide {
namespace {

// The words of `contain collide`, `contain many` and Python's `witness`, unchanged by the merge
// of the two witness enums: each witness prints its own enumerator's name.
TEST(CollideWitness, WordsAreTheEnumeratorNames) {
  EXPECT_EQ(std::string(to_string(inside::PairWitness::none)), "none");
  EXPECT_EQ(std::string(to_string(inside::PairWitness::triangles)), "triangles");
  EXPECT_EQ(std::string(to_string(inside::PairWitness::edges)), "edges");
  EXPECT_EQ(std::string(to_string(inside::PairWitness::vertex_of_a_in_b)), "vertex_of_a_in_b");
  EXPECT_EQ(std::string(to_string(inside::PairWitness::vertex_of_b_in_a)), "vertex_of_b_in_a");
}

}  // namespace
}  // namespace contain::collide
