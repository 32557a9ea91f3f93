// The GDAL plugin, libcontain_gdal.so: layers through GDAL/OGR (every vector format GDAL reads
// and PostGIS tables). It is the only code that links GDAL; contain::io opens it with dlopen
// when a GDAL source is named (gdal_layer.cpp), so a contain process that reads no GIS layer
// never loads GDAL's hundred-odd shared libraries. The regions that leave hold the doubles OGR
// read, nothing recomputed.

#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "contain/io/layer_io.h"
#include "io/gdal_plugin.h"
#include "io/text_scan.h"

namespace contain::io {
namespace {

using detail::make_error;

bool equal_ci(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i]))) {
      return false;
    }
  }
  return true;
}

// GDAL reports through a per-thread handler stack: collect its messages instead of letting it
// print on stderr, and put the last failure into our error.
class CollectGdalErrors {
 public:
  CollectGdalErrors() { CPLPushErrorHandlerEx(&CollectGdalErrors::handle, this); }
  ~CollectGdalErrors() { CPLPopErrorHandler(); }
  CollectGdalErrors(const CollectGdalErrors&) = delete;
  CollectGdalErrors& operator=(const CollectGdalErrors&) = delete;

  [[nodiscard]] std::string last() const { return last_.empty() ? "no reason given" : last_; }
  [[nodiscard]] bool failed() const { return !last_.empty(); }
  void clear() { last_.clear(); }

 private:
  static void CPL_STDCALL handle(CPLErr level, CPLErrorNum, const char* message) {
    auto* self = static_cast<CollectGdalErrors*>(CPLGetErrorHandlerUserData());
    if (self != nullptr && level >= CE_Failure && message != nullptr) self->last_ = message;
  }
  std::string last_;
};

std::string layer_names(GDALDataset& dataset) {
  std::string names;
  for (int i = 0; i < dataset.GetLayerCount(); ++i) {
    if (i > 0) names += ", ";
    names += dataset.GetLayer(i)->GetName();
  }
  return names.empty() ? "none" : names;
}

std::string field_names(OGRLayer& layer) {
  OGRFeatureDefn* defn = layer.GetLayerDefn();
  std::string names;
  const char* fid = layer.GetFIDColumn();
  names = fid != nullptr && *fid != '\0' ? std::string(fid) + " (FID)" : "FID";
  for (int i = 0; i < defn->GetFieldCount(); ++i) {
    names += ", ";
    names += defn->GetFieldDefn(i)->GetNameRef();
  }
  return names;
}

// A field's value as an id, spelt as parse_geojson_layer spells the same value (issue 24: a
// layer read through GDAL or by our own GeoJSON reader gives the same ids): booleans
// true/false, numbers by detail::number_id, dates and times in ISO 8601 as GeoJSON writes them
// ("2024-01-31", "2024-01-31T10:20:30Z"), anything else as OGR formats it.
std::string field_id(const OGRFeature& feature, int field) {
  const OGRFieldDefn& defn = *feature.GetFieldDefnRef(field);
  switch (defn.GetType()) {
    case OFTInteger:
      if (defn.GetSubType() == OFSTBoolean) {
        return feature.GetFieldAsInteger(field) != 0 ? "true" : "false";
      }
      return std::to_string(feature.GetFieldAsInteger(field));
    case OFTInteger64:
      return std::to_string(feature.GetFieldAsInteger64(field));
    case OFTReal:
      return detail::number_id(feature.GetFieldAsDouble(field));
    case OFTDate:
    case OFTTime:
    case OFTDateTime: {
      int year = 0, month = 0, day = 0, hour = 0, minute = 0, tz = 0;
      float second = 0;
      feature.GetFieldAsDateTime(field, &year, &month, &day, &hour, &minute, &second, &tz);
      char text[64];
      std::string out;
      if (defn.GetType() != OFTTime) {
        std::snprintf(text, sizeof text, "%04d-%02d-%02d", year, month, day);
        out = text;
        if (defn.GetType() == OFTDate) return out;
        out += 'T';
      }
      if (second == std::floor(second)) {
        std::snprintf(text, sizeof text, "%02d:%02d:%02d", hour, minute, static_cast<int>(second));
      } else {
        std::snprintf(text, sizeof text, "%02d:%02d:%06.3f", hour, minute,
                      static_cast<double>(second));
      }
      out += text;
      if (tz == 100) {
        out += 'Z';
      } else if (tz > 1) {  // 100 + quarter hours east of UTC
        const int quarters = tz - 100;
        std::snprintf(text, sizeof text, "%c%02d:%02d", quarters < 0 ? '-' : '+',
                      std::abs(quarters) / 4, std::abs(quarters) % 4 * 15);
        out += text;
      }
      return out;
    }
    default:
      return feature.GetFieldAsString(field);
  }
}

class GeometryReader {
 public:
  GeometryReader(const std::string& source, std::size_t feature)
      : source_(source), feature_(feature) {}

  Status read(const OGRGeometry& geometry, MultiPolygon& out) const {
    if (geometry.IsEmpty()) return Ok{};
    switch (wkbFlatten(geometry.getGeometryType())) {
      case wkbPolygon:
        return read_polygon(*geometry.toPolygon(), out);
      case wkbMultiPolygon:
        for (const OGRPolygon* polygon : *geometry.toMultiPolygon()) {
          if (auto s = read_polygon(*polygon, out); !s) return s;
        }
        return Ok{};
      case wkbGeometryCollection:
        for (const OGRGeometry* member : *geometry.toGeometryCollection()) {
          if (auto s = read(*member, out); !s) return s;
        }
        return Ok{};
      case wkbCurvePolygon:
      case wkbMultiSurface:
      case wkbCompoundCurve:
      case wkbCircularString:
        return fail(ErrorKind::unsupported,
                    std::string("a curved geometry (") + geometry.getGeometryName() +
                        ") is not read: convert it to polygons first, e.g. ogr2ogr -nlt "
                        "MULTIPOLYGON");
      default:
        return fail(ErrorKind::unsupported,
                    std::string("geometry type ") + geometry.getGeometryName() +
                        " is not a region: a layer holds Polygon or MultiPolygon features");
    }
  }

 private:
  Status read_polygon(const OGRPolygon& polygon, MultiPolygon& out) const {
    std::vector<Ring> rings;
    for (const OGRLinearRing* ring : polygon) {
      Ring points;
      const int n = ring->getNumPoints();
      points.reserve(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i)
        points.push_back({ring->getX(i), ring->getY(i)});
      if (!points.empty()) rings.push_back(std::move(points));
    }
    if (rings.empty()) return Ok{};
    auto checked = Polygon::from_rings(std::move(rings));
    if (!checked) {
      return fail(checked.error().kind, "polygon " + std::to_string(out.polygons.size() + 1) +
                                            ": " + checked.error().message);
    }
    out.polygons.push_back(std::move(*checked));
    return Ok{};
  }

  [[nodiscard]] Error fail(ErrorKind kind, const std::string& message) const {
    return make_error(kind, "feature " + std::to_string(feature_) + ": " + message, source_);
  }

  const std::string& source_;
  std::size_t feature_;
};

Result<Layer> read_layer_through_gdal(const std::string& source, const LayerOptions& options) {
  static std::once_flag registered;
  std::call_once(registered, [] {
    // libpq waits for an unreachable host as long as the system's TCP timeout (minutes): a
    // layer should fail in seconds. The user's own PGCONNECT_TIMEOUT wins.
    setenv("PGCONNECT_TIMEOUT", "10", 0);
    GDALAllRegister();
  });
  const std::string name = detail::connection_name(source);
  CollectGdalErrors errors;
  GDALDatasetUniquePtr dataset(
      GDALDataset::Open(source.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  if (!dataset) {
    return make_error(
        ErrorKind::io,
        "GDAL cannot open it as a vector layer: " + detail::hide_secrets(errors.last(), source),
        name);
  }
  OGRLayer* layer = nullptr;
  if (!options.layer_name.empty()) {
    layer = dataset->GetLayerByName(options.layer_name.c_str());
    if (layer == nullptr) {
      return make_error(
          ErrorKind::usage,
          "no layer named '" + options.layer_name + "' (layers: " + layer_names(*dataset) + ")",
          name);
    }
  } else if (dataset->GetLayerCount() == 1) {
    layer = dataset->GetLayer(0);
  } else {
    return make_error(
        ErrorKind::usage,
        dataset->GetLayerCount() == 0
            ? std::string("the source holds no vector layer")
            : "the source holds " + std::to_string(dataset->GetLayerCount()) +
                  " layers: choose one with --layer-name (layers: " + layer_names(*dataset) + ")",
        name);
  }
  int field = -1;
  bool use_fid = false;
  if (!options.id.empty()) {
    field = layer->GetLayerDefn()->GetFieldIndex(options.id.c_str());
    if (field < 0) {
      const char* fid = layer->GetFIDColumn();
      use_fid = equal_ci(options.id, "FID") ||
                (fid != nullptr && *fid != '\0' && equal_ci(options.id, fid));
      if (!use_fid) {
        return make_error(ErrorKind::usage,
                          "no attribute '" + options.id + "' in layer '" + layer->GetName() +
                              "' (attributes: " + field_names(*layer) + ")",
                          name);
      }
    }
  }
  Layer out;
  errors.clear();
  layer->ResetReading();
  for (;;) {
    OGRFeatureUniquePtr feature(layer->GetNextFeature());
    if (!feature) break;
    const std::size_t k = out.regions.size();
    MultiPolygon& region = out.regions.emplace_back();
    if (const OGRGeometry* geometry = feature->GetGeometryRef(); geometry != nullptr) {
      if (auto s = GeometryReader(name, k).read(*geometry, region); !s) return s.error();
    }
    if (use_fid) {
      out.ids.push_back(std::to_string(feature->GetFID()));
    } else if (field >= 0) {
      if (!feature->IsFieldSetAndNotNull(field)) {
        return make_error(ErrorKind::invalid_value,
                          "feature " + std::to_string(k) + " has no value of '" + options.id + "'",
                          name);
      }
      out.ids.push_back(field_id(*feature, field));
    } else {
      out.ids.push_back(std::to_string(k));
    }
  }
  // A read that fails part way ends the features early: never return a truncated layer.
  if (errors.failed()) {
    return make_error(ErrorKind::io,
                      "GDAL failed after " + std::to_string(out.regions.size()) +
                          " features: " + detail::hide_secrets(errors.last(), source),
                      name);
  }
  return out;
}

}  // namespace
}  // namespace contain::io

// The plugin's two entry points (io/gdal_plugin.h): everything else in it stays hidden.
extern "C" CONTAIN_GDAL_PLUGIN_EXPORT const char* contain_gdal_plugin_id() {
  return contain::io::detail::gdal_plugin_id;
}

extern "C" CONTAIN_GDAL_PLUGIN_EXPORT void contain_gdal_read_layer(
    const std::string& source, const contain::io::LayerOptions& options,
    std::optional<contain::Result<contain::io::Layer>>& out) {
  out.emplace(contain::io::read_layer_through_gdal(source, options));
}
