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
  /// What the source held that OGC does not allow and was read anyway, one sentence each naming
  /// the source and the line or shape (for a warning): a WKT ring not closed (read as closed), a
  /// hole with a vertex outside its shell, a polygon with a vertex inside another polygon of the
  /// same region (parts that overlap). The regions are read as written, under the fill rule.
  std::vector<std::string> warnings;
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
