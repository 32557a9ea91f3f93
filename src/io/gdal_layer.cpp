// read_gdal_layer: GDAL is loaded on first use, from the plugin libcontain_gdal.so
// (io/gdal_plugin.h says why), so that a process reading no GIS layer never loads it.
//
// Where the plugin is looked for: io/plugin_search.h, $CONTAIN_GDAL_PLUGIN first, last where the
// build tree has it, then where `cmake --install` puts it (both compiled in; neither in a build
// without GDAL).
// A file that is not the plugin of this very version is passed over, with the reason kept for
// the error.

#include <dlfcn.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "contain/io/layer_io.h"
#include "io/gdal_plugin.h"
#include "io/plugin_search.h"
#include "io/text_scan.h"

namespace contain::io {
namespace {

namespace fs = std::filesystem;
using detail::make_error;

struct LoadedPlugin {
  detail::GdalReadLayer read = nullptr;
  std::string path;
  // Why no plugin was loaded: each candidate and what was wrong with it.
  std::string problem;
  bool built_with_gdal = false;
};

// Where this build's plugin is, compiled in: none in a build without GDAL.
std::vector<fs::path> compiled_in_paths() {
  std::vector<fs::path> out;
#ifdef CONTAIN_GDAL_PLUGIN_BUILD_PATH
  out.emplace_back(CONTAIN_GDAL_PLUGIN_BUILD_PATH);
#endif
#ifdef CONTAIN_GDAL_PLUGIN_INSTALL_PATH
  out.emplace_back(CONTAIN_GDAL_PLUGIN_INSTALL_PATH);
#endif
  return out;
}

std::vector<fs::path> candidates() {
  return detail::plugin_candidates("CONTAIN_GDAL_PLUGIN", detail::gdal_plugin_file,
                                   compiled_in_paths());
}

// Opens `path` if it is this version's plugin; otherwise says why not in `problem`.
detail::GdalReadLayer open_plugin(const fs::path& path, std::string& problem) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) {
    problem += "\n  " + path.string() + ": not there";
    return nullptr;
  }
  // RTLD_LOCAL: GDAL's symbols stay out of the process's global scope (the Python extension
  // shares its process with other modules that may load GDAL themselves).
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    problem += "\n  " + path.string() + ": cannot be loaded: " + (why != nullptr ? why : "?") +
               " (GDAL's runtime library is missing? Debian: apt-get install libgdal-dev)";
    return nullptr;
  }
  auto id = reinterpret_cast<detail::GdalPluginId>(dlsym(handle, detail::gdal_plugin_id_symbol));
  auto read =
      reinterpret_cast<detail::GdalReadLayer>(dlsym(handle, detail::gdal_plugin_read_symbol));
  if (id == nullptr || read == nullptr || std::string(id()) != detail::gdal_plugin_id) {
    problem += "\n  " + path.string() + ": not the plugin of this contain (" +
               (id != nullptr ? "it is '" + std::string(id()) + "'" : "no plugin id") +
               ", this is '" + detail::gdal_plugin_id + "')";
    dlclose(handle);
    return nullptr;
  }
  return read;  // kept open for the life of the process
}

// Set once the plugin has been looked for, so that asking where it is loads nothing.
std::atomic<const LoadedPlugin*> looked_for{nullptr};

const LoadedPlugin& plugin() {
  static std::once_flag once;
  static LoadedPlugin loaded;
  std::call_once(once, [] {
    struct Publish {
      ~Publish() { looked_for.store(&loaded, std::memory_order_release); }
    } publish;
    loaded.built_with_gdal = !compiled_in_paths().empty();
    for (const fs::path& path : candidates()) {
      loaded.read = open_plugin(path, loaded.problem);
      if (loaded.read != nullptr) {
        loaded.path = path.string();
        return;
      }
    }
  });
  return loaded;
}

std::string formats_of(const std::string& source) {
  const std::string ext = detail::lower_extension(source);
  return ext.empty() ? "this source" : "'" + ext + "' layers";
}

}  // namespace

Result<Layer> read_gdal_layer(const std::string& source, const LayerOptions& options) {
  const LoadedPlugin& loaded = plugin();
  const std::string name = detail::connection_name(source);
  if (loaded.read != nullptr) {
    std::optional<Result<Layer>> out;
    loaded.read(source, options, out);
    if (out) return std::move(*out);
    return make_error(ErrorKind::io, "the GDAL plugin " + loaded.path + " gave no answer", name);
  }
  const bool asked = std::getenv("CONTAIN_GDAL_PLUGIN") != nullptr;
  if (!loaded.built_with_gdal && !asked) {
    return make_error(
        ErrorKind::unsupported,
        "reading " + formats_of(source) +
            " needs GDAL, and this contain was built without it (install libgdal-dev, then "
            "configure and build again); without GDAL a layer can be a .wkt file (one POLYGON or "
            "MULTIPOLYGON a line) or a GeoJSON FeatureCollection",
        name);
  }
  return make_error(ErrorKind::unsupported,
                    "reading " + formats_of(source) + " needs GDAL, which contain loads from " +
                        detail::gdal_plugin_file +
                        " on first use, and none could be used:" + loaded.problem +
                        "\ninstall contain again (cmake --install) or set CONTAIN_GDAL_PLUGIN "
                        "to the plugin's path; a .wkt or GeoJSON layer needs no GDAL",
                    name);
}

bool has_gdal() {
  return plugin().read != nullptr;
}

std::string gdal_plugin_path() {
  const LoadedPlugin* loaded = looked_for.load(std::memory_order_acquire);
  return loaded != nullptr ? loaded->path : std::string();
}

}  // namespace contain::io
