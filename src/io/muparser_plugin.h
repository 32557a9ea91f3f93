#pragma once
// The contract between contain::io (muparser_function.cpp, the loader) and its muparser plugin,
// libcontain_muparser.so (muparser_plugin.cpp). Debian's libmuparser links libstdc++ and
// libgomp dynamically: linked into contain::io, it made every contain process load and relocate
// them before main, and kept the contain command from linking libstdc++ statically (about 1.4 ms
// of the 2k-triangle mesh boolean's 17). The plugin is opened only when an expression is
// compiled.
//
// Only C values cross the boundary (the contain command has its own static copy of the C++
// runtime, the plugin the shared one): an opaque evaluator, doubles and C strings. Nothing is
// thrown across it.

#ifndef CONTAIN_VERSION
#error "CONTAIN_VERSION must be defined (CMake defines it for contain_io and contain_muparser)"
#endif

#define CONTAIN_MUPARSER_PLUGIN_EXPORT __attribute__((visibility("default")))

namespace contain::io::detail {

/// The plugin's file name, in every place it is looked for.
inline constexpr const char* muparser_plugin_file = "libcontain_muparser.so";

/// What the plugin says it is. The number counts changes of the contract (the entry points
/// below): raise it with any of them.
inline constexpr const char* muparser_plugin_id = "contain " CONTAIN_VERSION " muparser plugin 1";

/// `const char* contain_muparser_plugin_id()`: returns muparser_plugin_id.
inline constexpr const char* muparser_plugin_id_symbol = "contain_muparser_plugin_id";
using MuparserPluginId = const char* (*)();

/// `void* contain_muparser_compile(const char* expression)`: an evaluator of the expression in
/// x, y, z, evaluated once to check it; null only when out of memory. Not safe to share between
/// threads (muparser's evaluation writes into the parser).
inline constexpr const char* muparser_compile_symbol = "contain_muparser_compile";
using MuparserCompile = void* (*)(const char* expression);

/// `const char* contain_muparser_error(const void* evaluator)`: why the expression was refused
/// (muparser's message and position, or the count of expressions when not one), owned by the
/// evaluator; null when it compiled.
inline constexpr const char* muparser_error_symbol = "contain_muparser_error";
using MuparserError = const char* (*)(const void* evaluator);

/// `double contain_muparser_evaluate(void* evaluator, double x, double y, double z)`: the value
/// at (x, y, z); NaN when muparser throws.
inline constexpr const char* muparser_evaluate_symbol = "contain_muparser_evaluate";
using MuparserEvaluate = double (*)(void* evaluator, double x, double y, double z);

/// `void contain_muparser_release(void* evaluator)`: frees it.
inline constexpr const char* muparser_release_symbol = "contain_muparser_release";
using MuparserRelease = void (*)(void* evaluator);

}  // namespace contain::io::detail
