// GDAL in its plugin: contain::io finds libcontain_gdal.so on first use (here: the build tree's
// copy), reads through it, and words GDAL's failures without leaking a connection's password.

#include <gtest/gtest.h>

#include <string>

#include "contain/io/layer_io.h"

namespace contain::io {
namespace {

TEST(GdalPlugin, IsLoadedOnFirstUseFromTheBuildTree) {
  EXPECT_TRUE(gdal_plugin_path().empty()) << "loaded before any GDAL source was named";
  ASSERT_TRUE(has_gdal());
  EXPECT_EQ(gdal_plugin_path(), CONTAIN_GDAL_PLUGIN_BUILT);
}

TEST(GdalPlugin, ASourceGdalCannotOpenIsAnIoErrorWithGdalsReason) {
  const auto layer = read_gdal_layer("/nonexistent/parcels.shp");
  ASSERT_FALSE(layer);
  EXPECT_EQ(layer.error().kind, ErrorKind::io);
  EXPECT_EQ(layer.error().source, "/nonexistent/parcels.shp");
  EXPECT_NE(layer.error().message.find("GDAL cannot open it"), std::string::npos)
      << layer.error().message;
}

TEST(GdalPlugin, AConnectionStringsPasswordNeverReachesTheError) {
  const auto layer =
      read_gdal_layer("PG:dbname=nope host=/nonexistent-socket-dir password=hunter2 user=x");
  ASSERT_FALSE(layer);
  EXPECT_EQ(layer.error().source.find("hunter2"), std::string::npos) << layer.error().source;
  EXPECT_EQ(layer.error().message.find("hunter2"), std::string::npos) << layer.error().message;
  EXPECT_NE(layer.error().source.find("password=***"), std::string::npos) << layer.error().source;
}

}  // namespace
}  // namespace contain::io
