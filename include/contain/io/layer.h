#pragma once
/// \file
/// A layer: many 2D regions, each with an id, as read from a GIS file or a database table.

#include <string>
#include <vector>

#include "contain/shapes/polygon.h"

namespace contain::io {

/// Regions in source order with one id each (`ids.size() == regions.size()`). A feature
/// without a geometry (null) is kept as an empty region, so positions stay those of the
/// source; it holds no point.
struct Layer {
  std::vector<std::string> ids;
  std::vector<MultiPolygon> regions;
};

/// How a layer is read.
struct LayerOptions {
  /// The attribute (GeoJSON property, field of a Shapefile, column of a table) whose value is
  /// each region's id. Empty: a GeoJSON feature's "id" member where every feature has one,
  /// otherwise the position counted from 0 (the CLI contract).
  std::string id;
  /// The layer of a source with several (a GeoPackage, a PostGIS database): by name. Empty: the
  /// source's only layer (a source of several is an error that names them).
  std::string layer_name;
};

}  // namespace contain::io
