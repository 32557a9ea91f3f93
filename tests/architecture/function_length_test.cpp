// Issue 23's rule, enforced: no function in src/ or include/ over 120 lines. The checker on small
// made-up files first (it must measure functions and only functions), then on the project.

#include "architecture/function_length.h"

#include <gtest/gtest.h>

#include <string>

#include "architecture/project_tree.h"

namespace contain::test {
namespace {

std::string lines(int n, const std::string& line) {
  std::string out;
  for (int i = 0; i < n; ++i)
    out += line + "\n";
  return out;
}

TEST(FunctionLength, FunctionOverTheLimitIsReportedWithItsFirstLineAndLength) {
  const std::string text = "#include <x>\n\nint f(int a)\n{\n" + lines(3, "  ++a;") + "}\n";
  const auto problems = check_function_lengths({{"src/a.cpp", text}}, 5);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].find("src/a.cpp:3: 6 lines (at most 5): int f(int a)"), 0u) << problems[0];
  EXPECT_TRUE(check_function_lengths({{"src/a.cpp", text}}, 6).empty());
}

TEST(FunctionLength, MembersInClassesAndNamespacesAndQualifiedSignaturesAreMeasured) {
  const std::string text = "namespace n {\nstruct S {\n  int g() const noexcept {\n" +
                           lines(4, "    x;") + "  }\n};\nauto S::h() const -> int {\n" +
                           lines(4, "  x;") + "}\n}  // namespace n\n";
  const auto problems = check_function_lengths({{"include/contain/n/s.h", text}}, 5);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find(":3: 6 lines"), std::string::npos) << problems[0];
  EXPECT_NE(problems[1].find(":10: 6 lines"), std::string::npos) << problems[1];
}

TEST(FunctionLength, BracesInCommentsStringsInitializersAndLambdasDoNotSplitAFunction) {
  const std::string text = "S::S(int a) : v_{a}, w_(a) {\n  // }\n  f(\"}\", '}');\n" +
                           lines(2, "  auto l = [] { return 1; };") + "}\n" +
                           "const int table[] = {\n" + lines(9, "  1,") + "};\n";
  const auto problems = check_function_lengths({{"src/s.cpp", text}}, 5);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("src/s.cpp:1: 6 lines"), std::string::npos) << problems[0];
}

TEST(FunctionLength, NoFunctionOfTheLibraryIsLongerThan120Lines) {
  const auto files = tree({"src", "include"}, false);
  ASSERT_GT(files.size(), 100u);
  const auto problems = check_function_lengths(files, 120);
  EXPECT_TRUE(problems.empty()) << joined(problems);
}

}  // namespace
}  // namespace contain::test
