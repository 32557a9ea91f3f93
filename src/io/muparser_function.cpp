// compile_expression: muparser is loaded on first use, from the plugin libcontain_muparser.so
// (io/muparser_plugin.h says why), so that a process compiling no expression never loads it.
// Where the plugin is looked for: io/plugin_search.h, $CONTAIN_MUPARSER_PLUGIN first, last where
// the build tree has it, then where `cmake --install` puts it (both compiled in).

#include "muparser_function.h"

#include <dlfcn.h>

#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "io/muparser_plugin.h"
#include "io/plugin_search.h"

namespace contain::io::detail {
namespace {

struct MuparserPlugin {
  MuparserCompile compile = nullptr;
  MuparserError error = nullptr;
  MuparserEvaluate evaluate = nullptr;
  MuparserRelease release = nullptr;
  // Why no plugin was loaded: each candidate and what was wrong with it.
  std::string problem;
};

std::vector<std::filesystem::path> muparser_compiled_in_paths() {
  std::vector<std::filesystem::path> out;
#ifdef CONTAIN_MUPARSER_PLUGIN_BUILD_PATH
  out.emplace_back(CONTAIN_MUPARSER_PLUGIN_BUILD_PATH);
#endif
#ifdef CONTAIN_MUPARSER_PLUGIN_INSTALL_PATH
  out.emplace_back(CONTAIN_MUPARSER_PLUGIN_INSTALL_PATH);
#endif
  return out;
}

// Opens `path` if it is this version's plugin (its entry points in `out`); otherwise says why
// not in out.problem.
bool open_muparser_plugin(const std::filesystem::path& path, MuparserPlugin& out) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    out.problem += "\n  " + path.string() + ": not there";
    return false;
  }
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    out.problem += "\n  " + path.string() + ": cannot be loaded: " + (why != nullptr ? why : "?") +
                   " (muparser's runtime library is missing? Debian: apt-get install "
                   "libmuparser-dev)";
    return false;
  }
  const auto symbol = [&](const char* name) { return dlsym(handle, name); };
  auto id = reinterpret_cast<MuparserPluginId>(symbol(muparser_plugin_id_symbol));
  MuparserPlugin found;
  found.compile = reinterpret_cast<MuparserCompile>(symbol(muparser_compile_symbol));
  found.error = reinterpret_cast<MuparserError>(symbol(muparser_error_symbol));
  found.evaluate = reinterpret_cast<MuparserEvaluate>(symbol(muparser_evaluate_symbol));
  found.release = reinterpret_cast<MuparserRelease>(symbol(muparser_release_symbol));
  if (id == nullptr || found.compile == nullptr || found.error == nullptr ||
      found.evaluate == nullptr || found.release == nullptr ||
      std::string(id()) != muparser_plugin_id) {
    out.problem += "\n  " + path.string() + ": not the plugin of this contain (" +
                   (id != nullptr ? "it is '" + std::string(id()) + "'" : "no plugin id") +
                   ", this is '" + muparser_plugin_id + "')";
    dlclose(handle);
    return false;
  }
  found.problem = std::move(out.problem);
  out = std::move(found);
  return true;  // kept open for the life of the process
}

const MuparserPlugin& muparser_plugin() {
  static std::once_flag once;
  static MuparserPlugin loaded;
  std::call_once(once, [] {
    for (const std::filesystem::path& path : plugin_candidates(
             "CONTAIN_MUPARSER_PLUGIN", muparser_plugin_file, muparser_compiled_in_paths())) {
      if (open_muparser_plugin(path, loaded)) return;
    }
  });
  return loaded;
}

// An evaluator of the plugin, released by it.
struct Release {
  MuparserRelease release;
  void operator()(void* evaluator) const { release(evaluator); }
};
using Evaluator = std::unique_ptr<void, Release>;

// muparser parsers are not safe to share between threads (evaluation writes a stack in the
// parser); a pool hands each concurrent caller its own. The pool grows to the number of
// threads that ever evaluate at once and is shared by copies of the function.
struct Pool {
  const MuparserPlugin* plugin = nullptr;
  std::string expression;
  std::mutex mutex;
  std::vector<Evaluator> idle;

  // An evaluator, or null when out of memory.
  Evaluator take() {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!idle.empty()) {
        Evaluator e = std::move(idle.back());
        idle.pop_back();
        return e;
      }
    }
    return Evaluator(plugin->compile(expression.c_str()), Release{plugin->release});
  }
  void give_back(Evaluator e) {
    const std::lock_guard<std::mutex> lock(mutex);
    idle.push_back(std::move(e));
  }
};

}  // namespace

Result<ImplicitFunction> compile_expression(const std::string& expression) {
  const MuparserPlugin& plugin = muparser_plugin();
  if (plugin.compile == nullptr) {
    return Error{ErrorKind::unsupported,
                 "an expression needs muparser, which contain loads from " +
                     std::string(muparser_plugin_file) +
                     " on first use, and none could be used:" + plugin.problem +
                     "\ninstall contain again (cmake --install) or set CONTAIN_MUPARSER_PLUGIN "
                     "to the plugin's path"};
  }
  auto pool = std::make_shared<Pool>();
  pool->plugin = &plugin;
  pool->expression = expression;
  Evaluator first(plugin.compile(expression.c_str()), Release{plugin.release});
  if (!first) throw std::bad_alloc();
  if (const char* error = plugin.error(first.get()); error != nullptr) {
    return Error{ErrorKind::parse, error};
  }
  pool->idle.push_back(std::move(first));
  return ImplicitFunction([pool](Vec3 p) {
    Evaluator e;
    double value = std::numeric_limits<double>::quiet_NaN();
    try {
      e = pool->take();
      if (e) value = pool->plugin->evaluate(e.get(), p.x, p.y, p.z);
    } catch (...) {  // nothing may cross the library boundary; NaN is `outside`
      value = std::numeric_limits<double>::quiet_NaN();
    }
    try {
      if (e) pool->give_back(std::move(e));
    } catch (...) {  // out of memory: the evaluator is dropped, the pool makes another later
    }
    return value;
  });
}

}  // namespace contain::io::detail
