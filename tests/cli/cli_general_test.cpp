// The general rules of ../shared/spec/cli.md: exit codes, stdout for results only, help.

#include <gtest/gtest.h>

#include "cli/run.h"

namespace contain::test {
namespace {

TEST(CliGeneral, NoVerbIsAUsageErrorWithExitTwo) {
  const CliRun run = run_contain({});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.out.empty());
  EXPECT_FALSE(run.err.empty());
}

TEST(CliGeneral, UnknownVerbIsAUsageErrorWithExitTwo) {
  const CliRun run = run_contain({"frobnicate"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.out.empty());
}

TEST(CliGeneral, UnknownOptionIsAUsageErrorWithExitTwo) {
  const CliRun run = run_contain({"inside", "--polygon", "x.wkt", "--no-such-option"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.out.empty());
}

TEST(CliGeneral, MissingOptionArgumentIsAUsageErrorWithExitTwo) {
  const CliRun run = run_contain({"inside", "--polygon"});
  EXPECT_EQ(run.exit_code, 2);
}

TEST(CliGeneral, HelpListsEveryVerbAndExitsZero) {
  const CliRun run = run_contain({"--help"});
  EXPECT_EQ(run.exit_code, 0);
  for (const char* verb : {"inside", "collide", "clip", "bound", "demo"}) {
    EXPECT_NE(run.out.find(verb), std::string::npos) << verb;
  }
}

TEST(CliGeneral, VerbHelpShowsAnExample) {
  for (const char* verb : {"inside", "collide", "clip", "bound", "demo"}) {
    const CliRun run = run_contain({verb, "--help"});
    EXPECT_EQ(run.exit_code, 0) << verb;
    EXPECT_NE(run.out.find("Example"), std::string::npos) << verb;
  }
}

TEST(CliGeneral, MissingInputFileIsBadInputWithExitThreeNamingTheFile) {
  const CliRun run = run_contain({"bound", "/nonexistent/where.off"});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(run.out.empty());
  EXPECT_NE(run.err.find("/nonexistent/where.off"), std::string::npos);
}

// `contain` builds only the verb named first (cli/verbs.cpp's table of names): each name must
// build its own verb, whose help is then the one printed.
TEST(CliGeneral, EachVerbNamedFirstPrintsItsOwnHelp) {
  for (const std::string verb :
       {"inside", "bound", "clip", "collide", "distance", "slice", "index", "demo"}) {
    const CliRun r = run_contain({verb, "--help"});
    EXPECT_EQ(r.exit_code, 0) << verb;
    EXPECT_TRUE(has(r.out, "Usage: contain " + verb + " ")) << verb << r.out;
  }
}

}  // namespace
}  // namespace contain::test
