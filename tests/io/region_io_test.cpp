#include "contain/io/region_io.h"

#include <gtest/gtest.h>

#include "io/temp_file.h"

namespace contain::io {
namespace {

TEST(RegionIo, DispatchesByExtensionCaseInsensitively) {
  test::TempFile wkt(".WKT", "POLYGON ((0 0, 1 0, 0 1, 0 0))");
  test::TempFile json(".GeoJSON",
                      R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[0,1],[0,0]]]})");
  auto a = read_region(wkt.path());
  auto b = read_region(json.path());
  ASSERT_TRUE(a.ok()) << a.error().what();
  ASSERT_TRUE(b.ok()) << b.error().what();
  EXPECT_EQ(*a, *b);
}

TEST(RegionIo, RejectsAnUnknownExtensionAsUnsupported) {
  test::TempFile txt(".txt", "POLYGON ((0 0, 1 0, 0 1, 0 0))");
  auto r = read_region(txt.path());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::unsupported);
}

TEST(RegionIo, PassesReaderErrorsThroughWithTheFileAndLine) {
  test::TempFile wkt(".wkt", "POLYGON ((0 0,\n1 0, 0 z, 0 0))");
  auto r = read_region(wkt.path());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().source, wkt.path().string());
  EXPECT_EQ(r.error().line, 2);
  auto missing = read_region("/nonexistent/region.geojson");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().kind, ErrorKind::io);
}

}  // namespace
}  // namespace contain::io
