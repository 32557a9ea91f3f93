#include "io/plugin_search.h"

#include <dlfcn.h>

#include <cstdlib>
#include <system_error>
#include <utility>

#ifndef CONTAIN_INSTALL_LIBDIR
#define CONTAIN_INSTALL_LIBDIR "lib"
#endif

namespace contain::io::detail {
namespace {

namespace fs = std::filesystem;

// Any object of this binary: dladdr names the file it was loaded from.
const char plugin_search_anchor = 0;

void add_plugin_paths_beside(const fs::path& binary, const char* file_name,
                             std::vector<fs::path>& out) {
  std::error_code error;
  const fs::path file = fs::canonical(binary, error);
  if (error) return;
  out.push_back(file.parent_path() / file_name);
  out.push_back(file.parent_path().parent_path() / CONTAIN_INSTALL_LIBDIR / "contain" / file_name);
}

}  // namespace

std::vector<fs::path> plugin_candidates(const char* environment_variable, const char* file_name,
                                        std::vector<fs::path> compiled_in) {
  if (const char* given = std::getenv(environment_variable); given != nullptr && *given != 0) {
    return {fs::path(given)};
  }
  std::vector<fs::path> out;
  Dl_info info{};
  if (dladdr(&plugin_search_anchor, &info) != 0 && info.dli_fname != nullptr &&
      *info.dli_fname != 0) {
    add_plugin_paths_beside(info.dli_fname, file_name, out);
  }
  add_plugin_paths_beside("/proc/self/exe", file_name, out);
  for (fs::path& path : compiled_in)
    out.push_back(std::move(path));
  std::vector<fs::path> unique;
  for (fs::path& path : out) {
    path = path.lexically_normal();
    bool seen = false;
    for (const fs::path& kept : unique)
      seen = seen || kept == path;
    if (!seen) unique.push_back(std::move(path));
  }
  return unique;
}

}  // namespace contain::io::detail
