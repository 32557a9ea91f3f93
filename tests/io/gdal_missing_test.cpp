// A build without GDAL: the GDAL-only formats give a clear error naming what to install. This
// binary compiles the plugin's loader (src/io/gdal_layer.cpp) without the plugin's paths, as a
// build where GDAL was not found does, so the message is checked in every build.

#include <gtest/gtest.h>

#include "contain/io/layer_io.h"

namespace contain::io {
namespace {

TEST(LayerWithoutGdal, GdalFormatsSayToInstallLibgdalDevAndNameTheFormatsThatWork) {
  EXPECT_FALSE(has_gdal());
  for (const char* source : {"parcels.shp", "parcels.gpkg", "PG:dbname=gis"}) {
    const auto layer = read_gdal_layer(source, {});
    ASSERT_FALSE(layer);
    EXPECT_EQ(layer.error().kind, ErrorKind::unsupported);
    EXPECT_EQ(layer.error().source, source);
    EXPECT_NE(layer.error().message.find("libgdal-dev"), std::string::npos);
    EXPECT_NE(layer.error().message.find(".wkt"), std::string::npos);
    EXPECT_NE(layer.error().message.find("GeoJSON"), std::string::npos);
  }
  EXPECT_NE(read_gdal_layer("a.shp", {}).error().message.find("'.shp' layers"), std::string::npos);
}

}  // namespace
}  // namespace contain::io
