#pragma once
// The contract between contain::io (gdal_layer.cpp, the loader) and its GDAL plugin,
// libcontain_gdal.so (gdal_plugin.cpp), built from this tree by the same compiler. Linking GDAL
// into io made every contain process load 117 shared libraries before main (50-60 ms and 37 MB
// for `contain --version`); the plugin is opened only when a GDAL source is named.
//
// C++ values cross the boundary (std::string, Layer, Result): both sides are built from the
// same headers, and the plugin's id names the version and the shape of the contract, so a
// plugin of another build is refused rather than called.

#include <optional>
#include <string>

#include "contain/core/result.h"
#include "contain/io/layer.h"

#ifndef CONTAIN_VERSION
#error "CONTAIN_VERSION must be defined (CMake defines it for contain_io and contain_gdal)"
#endif

#define CONTAIN_GDAL_PLUGIN_EXPORT __attribute__((visibility("default")))

namespace contain::io::detail {

/// The plugin's file name, in every place it is looked for.
inline constexpr const char* gdal_plugin_file = "libcontain_gdal.so";

/// What the plugin says it is. The number counts changes of the contract (the entry points'
/// types, Layer, LayerOptions, Error): raise it with any of them.
inline constexpr const char* gdal_plugin_id = "contain " CONTAIN_VERSION " gdal plugin 1";

/// `const char* contain_gdal_plugin_id()`: returns gdal_plugin_id.
inline constexpr const char* gdal_plugin_id_symbol = "contain_gdal_plugin_id";
using GdalPluginId = const char* (*)();

/// `void contain_gdal_read_layer(source, options, out)`: read_gdal_layer's work; `out` receives
/// the layer or the error.
inline constexpr const char* gdal_plugin_read_symbol = "contain_gdal_read_layer";
using GdalReadLayer = void (*)(const std::string& source, const LayerOptions& options,
                               std::optional<Result<Layer>>& out);

}  // namespace contain::io::detail
