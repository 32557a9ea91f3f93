#pragma once
/// \file
/// A tiny test-only reader of the corpus meshes (OBJ `v`/`f` lines, `f a/b/c` forms, negative
/// indices; OFF). The project's real readers live in contain::io; the bound tests must not
/// depend on them.

#include <filesystem>
#include <optional>
#include <string>

#include "contain/shapes/mesh.h"

namespace contain::test {

/// The mesh in `path` (.obj or .off), polygons fanned into triangles; nothing on failure, with
/// the reason in `why`.
[[nodiscard]] std::optional<Mesh> read_test_mesh(const std::filesystem::path& path,
                                                 std::string& why);

}  // namespace contain::test
