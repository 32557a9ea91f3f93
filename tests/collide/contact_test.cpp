#include "contain/collide/contact.h"

#include <gtest/gtest.h>

#include <string>
#include <type_traits>

#include "contain/inside/pair_witness.h"

namespace contain::collide {
namespace {

TEST(WitnessKind, IsThePairWitnessOfInsideThatDistanceAlsoNames) {
  EXPECT_TRUE((std::is_same_v<WitnessKind, inside::PairWitness>));
}

// The words of `contain collide`, `contain many` and Python's `witness`, unchanged by the merge
// of the two witness enums: each witness prints its own enumerator's name.
TEST(WitnessKind, WordsAreTheEnumeratorNames) {
  EXPECT_EQ(std::string(to_string(WitnessKind::none)), "none");
  EXPECT_EQ(std::string(to_string(WitnessKind::triangles)), "triangles");
  EXPECT_EQ(std::string(to_string(WitnessKind::edges)), "edges");
  EXPECT_EQ(std::string(to_string(WitnessKind::vertex_of_a_in_b)), "vertex_of_a_in_b");
  EXPECT_EQ(std::string(to_string(WitnessKind::vertex_of_b_in_a)), "vertex_of_b_in_a");
}

}  // namespace
}  // namespace contain::collide
