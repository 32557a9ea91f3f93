// GDAL is loaded only when a GDAL source is named: the contain command does not link it (every
// process paid 117 shared libraries and 50-60 ms when it did), and a plugin that is missing or
// is not contain's own gives a clear error naming where contain looked.

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "cli/run.h"

namespace contain::test {
namespace {

// The shared libraries the dynamic linker loads for `contain` before main, as ldd lists them.
std::string libraries_loaded_at_start() {
  const CliRun run = run_program("env", {"LD_TRACE_LOADED_OBJECTS=1", CONTAIN_EXE});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return run.out;
}

TEST(GdalPluginCli, ContainStartsWithoutLoadingGdal) {
  const std::string libraries = libraries_loaded_at_start();
  ASSERT_NE(libraries.find("libc.so"), std::string::npos) << libraries;
  EXPECT_EQ(libraries.find("libgdal"), std::string::npos) << libraries;
  EXPECT_EQ(libraries.find("libpq"), std::string::npos) << libraries;
}

TEST(GdalPluginCli, AMissingPluginIsAClearErrorNamingWhereContainLooked) {
  TempDir dir;
  const std::string points = dir.write("p.txt", "0 0\n");
  const std::string plugin = (dir.path() / "nowhere" / "libcontain_gdal.so").string();
  const CliRun run =
      run_program("env", {"CONTAIN_GDAL_PLUGIN=" + plugin, CONTAIN_EXE, "inside", "--layer",
                          (dir.path() / "parcels.shp").string(), "--points", points});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find(plugin + ": not there"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("CONTAIN_GDAL_PLUGIN"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("'.shp' layers needs GDAL"), std::string::npos) << run.err;
  EXPECT_TRUE(run.out.empty());
}

TEST(GdalPluginCli, ALibraryThatIsNotContainsPluginIsRefusedNotCalled) {
  // libm: a real shared library without the plugin's entry points.
  std::istringstream lines(libraries_loaded_at_start());
  std::string line;
  std::string libm;
  while (std::getline(lines, line)) {
    const auto arrow = line.find("=> ");
    if (line.find("libm.so") == std::string::npos || arrow == std::string::npos) continue;
    libm = line.substr(arrow + 3, line.find(" (") - arrow - 3);
  }
  if (libm.empty()) GTEST_SKIP() << "contain does not load libm here";
  TempDir dir;
  const std::string points = dir.write("p.txt", "0 0\n");
  const CliRun run =
      run_program("env", {"CONTAIN_GDAL_PLUGIN=" + libm, CONTAIN_EXE, "inside", "--layer",
                          (dir.path() / "parcels.gpkg").string(), "--points", points});
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find(libm + ": not the plugin of this contain"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace contain::test
