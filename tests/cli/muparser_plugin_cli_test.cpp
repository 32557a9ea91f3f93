// muparser is loaded only when an expression is compiled: the contain command does not link it
// (Debian's libmuparser brought the shared libstdc++ and libgomp into every process), so it can
// link the C++ runtime statically; expressions still compile and fail as before, and a plugin
// that is missing or is not contain's own gives a clear error naming where contain looked.

#include <gtest/gtest.h>

#include <string>

#include "cli/run.h"

namespace contain::test {
namespace {

// The shared libraries the dynamic linker loads for `contain` before main, as ldd lists them.
std::string libraries_loaded_before_main() {
  const CliRun run = run_program("env", {"LD_TRACE_LOADED_OBJECTS=1", CONTAIN_EXE});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return run.out;
}

TEST(MuparserPluginCli, ContainStartsWithoutLoadingMuparserGompOrFmt) {
  const std::string libraries = libraries_loaded_before_main();
  ASSERT_TRUE(has(libraries, "libc.so")) << libraries;
  EXPECT_FALSE(has(libraries, "libmuparser")) << libraries;
  EXPECT_FALSE(has(libraries, "libgomp")) << libraries;
  EXPECT_FALSE(has(libraries, "libfmt")) << libraries;
#ifdef CONTAIN_CLI_STATIC_RUNTIME
  EXPECT_FALSE(has(libraries, "libstdc++")) << libraries;
#endif
}

TEST(MuparserPluginCli, AnExpressionIsEvaluatedThroughThePlugin) {
  TempDir dir;
  const std::string csg = dir.write("s.json", R"({"difference": [
      {"implicit": "1 - x^2 - y^2 - z^2"}, {"implicit": "0.25 - x^2"}]})");
  const CliRun run = run_contain({"inside", "--csg", csg}, "0 0 0\n0.9 0 0\n0.5 0 0\n2 0 0\n");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, "out\nin\non\nout\n");
}

TEST(MuparserPluginCli, ASyntaxErrorGivesMuparsersMessageAndPosition) {
  TempDir dir;
  const std::string csg = dir.write("bad.json", R"({"implicit": "1 - x^2 +* y"})");
  const CliRun run = run_contain({"inside", "--csg", csg}, "0 0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, R"(at position 9 of "1 - x^2 +* y")")) << run.err;
  EXPECT_TRUE(has(run.err, "bad.json")) << run.err;
}

TEST(MuparserPluginCli, TwoExpressionsAreRefusedByTheirCount) {
  TempDir dir;
  const std::string csg = dir.write("two.json", R"({"implicit": "x, y"})");
  const CliRun run = run_contain({"inside", "--csg", csg}, "0 0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, "expected one expression, got 2")) << run.err;
}

TEST(MuparserPluginCli, AMissingPluginIsAClearErrorNamingWhereContainLooked) {
  TempDir dir;
  const std::string csg = dir.write("s.json", R"({"implicit": "1 - x^2 - y^2 - z^2"})");
  const std::string plugin = (dir.path() / "nowhere" / "libcontain_muparser.so").string();
  const CliRun run = run_program(
      "env", {"CONTAIN_MUPARSER_PLUGIN=" + plugin, CONTAIN_EXE, "inside", "--csg", csg}, "0 0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, plugin + ": not there")) << run.err;
  EXPECT_TRUE(has(run.err, "CONTAIN_MUPARSER_PLUGIN")) << run.err;
  EXPECT_TRUE(run.out.empty());
}

TEST(MuparserPluginCli, ALibraryThatIsNotContainsPluginIsRefusedNotCalled) {
  // libc: a real shared library without the plugin's entry points.
  const std::string libraries = libraries_loaded_before_main();
  const auto at = libraries.find("libc.so");
  const auto arrow = libraries.find("=> ", at);
  ASSERT_NE(arrow, std::string::npos) << libraries;
  const std::string libc = libraries.substr(arrow + 3, libraries.find(" (", arrow) - arrow - 3);
  TempDir dir;
  const std::string csg = dir.write("s.json", R"({"implicit": "1 - x^2 - y^2 - z^2"})");
  const CliRun run = run_program(
      "env", {"CONTAIN_MUPARSER_PLUGIN=" + libc, CONTAIN_EXE, "inside", "--csg", csg}, "0 0 0\n");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_TRUE(has(run.err, libc + ": not the plugin of this contain")) << run.err;
}

}  // namespace
}  // namespace contain::test
