#pragma once
/// \file
/// Reading a layer of regions with ids (the CLI's `--layer`): the project's own readers for
/// `.wkt` (one shape a line) and GeoJSON, and GDAL/OGR for every other vector format and for
/// databases (Shapefile, GeoPackage, FlatGeobuf, PostGIS `PG:` connection strings, ...).

#include <string>
#include <string_view>

#include "contain/core/result.h"
#include "contain/io/layer.h"

namespace contain::io {

/// Reads a layer. `source` is a path or a GDAL connection string:
/// - `.wkt`: one POLYGON or MULTIPOLYGON a line (`parse_wkt_layer`);
/// - `.geojson` / `.json`: a FeatureCollection, one region a feature (`parse_geojson_layer`);
/// - anything else (`.shp`, `.gpkg`, `.fgb`, `.gml`, `/vsizip/...`, `PG:dbname=...`): GDAL/OGR
///   (`read_gdal_layer`), in a build with GDAL; without it ErrorKind::unsupported saying that
///   this format needs GDAL (libgdal-dev) and naming the formats that work without it.
/// Every coordinate reaches the regions as the double the source holds (binary formats as
/// stored, text formats correctly rounded); Z and M are dropped.
[[nodiscard]] Result<Layer> read_layer(const std::string& source, const LayerOptions& options = {});

/// Parses a WKT layer: every line that is not blank and does not start with `#` holds one
/// POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION of them (`parse_wkt`; `POLYGON EMPTY` gives an empty
/// region). Ids: the position among those lines, from 0 (`options.id` must be empty: a WKT line has
/// no attributes, ErrorKind::usage otherwise). Errors name `source` and the line.
[[nodiscard]] Result<Layer> parse_wkt_layer(std::string_view text, const std::string& source,
                                            const LayerOptions& options = {});

/// Parses a GeoJSON layer: each Feature of a FeatureCollection is one region (Polygon,
/// MultiPolygon, a GeometryCollection of them, or null: an empty region); a single Feature or
/// a bare geometry is a layer of one region. Ids: with `options.id`, the feature property of
/// that name (a string as written, a number as written in the file, true/false); otherwise the
/// feature's "id" member where every feature has one, else the position from 0. A feature
/// without the property, or with null, is ErrorKind::invalid_value naming the feature and line.
[[nodiscard]] Result<Layer> parse_geojson_layer(std::string_view text, const std::string& source,
                                                const LayerOptions& options = {});

/// Reads a layer through GDAL/OGR: `source` is anything GDALOpenEx opens as a vector dataset
/// (a file path, a `/vsi...` path, a `PG:` connection string). Features in the order OGR reads
/// them (file order; for a database table the order of its rows); Polygon, MultiPolygon and
/// GeometryCollections of them (a curved geometry is ErrorKind::unsupported: convert it first,
/// e.g. `ogr2ogr -nlt MULTIPOLYGON`); null or empty geometries give empty regions. Ids: with
/// `options.id`, the field of that name (or the FID, when it names the layer's FID column or
/// is "FID"), as OGR formats it; otherwise the position from 0. ErrorKind::io when GDAL cannot
/// open the source (its message included), ErrorKind::usage for a missing layer or field
/// (the existing ones named), ErrorKind::unsupported in a build without GDAL or when its plugin
/// cannot be loaded (see has_gdal).
[[nodiscard]] Result<Layer> read_gdal_layer(const std::string& source,
                                            const LayerOptions& options = {});

/// Adds to `layer.warnings` the regions that OGC would not accept (see Layer::warnings), each
/// named "SOURCE: shape K"; read_layer calls it on every layer it reads. Linear in the vertices
/// for holes; parts whose boxes meet cost a point location each.
void check_layer(Layer& layer, const std::string& source);

/// How messages name a layer's source: a path as given, a connection string with its password
/// hidden (every form: `password=...`, `postgresql://user:secret@host`).
[[nodiscard]] std::string layer_source_name(const std::string& source);

/// True when layers can be read through GDAL. GDAL is not linked into contain::io: it lives in
/// the plugin libcontain_gdal.so, opened on first use (the first call of this function or of
/// read_gdal_layer), so a program that reads no GIS layer never loads it. The plugin is looked
/// for at `$CONTAIN_GDAL_PLUGIN` when that is set, else beside the binary holding contain::io and
/// in `../lib/contain/` from it, beside the running executable, in the build tree and where
/// `cmake --install` put it; only the plugin of this very version is used. When none can be
/// used, read_gdal_layer's error lists each place and what was wrong there.
[[nodiscard]] bool has_gdal();

/// The plugin's path once has_gdal() or read_gdal_layer loaded it; empty otherwise.
[[nodiscard]] std::string gdal_plugin_path();

}  // namespace contain::io
