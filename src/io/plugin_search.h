#pragma once
// Private to contain::io: where a plugin of contain::io (a shared library opened with dlopen on
// first use, so that a process that never needs it never loads its dependencies) is looked for.

#include <filesystem>
#include <vector>

namespace contain::io::detail {

/// The paths to try for the plugin `file_name`, first found wins:
///   1. $`environment_variable`, a path, when it is set (then nowhere else);
///   2. beside the binary that holds contain::io (the Python extension: its package folder,
///      where the build and pip put a copy), and in ../<libdir>/contain from it (an installed or
///      moved bin/contain);
///   3. the same two beside the running executable (/proc/self/exe);
///   4. `compiled_in` (where the build tree has it, then where `cmake --install` puts it).
/// Each path normalized, none twice.
[[nodiscard]] std::vector<std::filesystem::path> plugin_candidates(
    const char* environment_variable, const char* file_name,
    std::vector<std::filesystem::path> compiled_in);

}  // namespace contain::io::detail
