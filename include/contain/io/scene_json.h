#pragma once
/// \file
/// Scenes of solids in the JSON form of the CLI contract (`contain collide --scene`,
/// `contain inside --scene`): objects, each a mesh file placed by a transform.
///
///   {"objects": [{"id": "gear", "mesh": "gear.stl", "transform": [12 numbers]}, ...]}

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "contain/core/result.h"
#include "contain/shapes/mesh.h"
#include "contain/values/transform.h"

namespace contain::io {

/// A scene as read: each distinct mesh file once, and per object its id, its mesh and its
/// transform (parallel vectors, one entry an object, in file order).
struct Scene {
  std::vector<Mesh> meshes;             ///< distinct mesh files, in order of first use
  std::vector<std::string> mesh_files;  ///< their paths as resolved
  std::vector<std::string> ids;         ///< per object
  std::vector<std::int32_t> mesh_of;    ///< per object: its index into `meshes`
  std::vector<Transform> transforms;    ///< per object (identity where none is given)
};

/// How parse_scene_json names its input and finds mesh files.
struct SceneJsonOptions {
  std::string source = "<string>";  ///< the name errors give
  std::filesystem::path base_dir;   ///< where relative mesh paths are resolved
};

/// Parses a scene. Per object: "mesh" (required: a path, relative to `base_dir` unless
/// absolute; read once however many objects use it), "transform" (optional: 12 numbers in the
/// contract's row order r00 r01 r02 t0 r10 ... t2, or three rows of 4; identity when absent),
/// "id" (optional: a string, or a number as written; default the position from 0). Any other
/// member (of the root or of an object) is ErrorKind::invalid_value naming it and its object:
/// a misspelt "transfrom" must not leave an object unmoved. Errors name the file and line:
/// ErrorKind::parse for malformed JSON or a missing/mistyped member ("objects[2].transform:
/// expected 12 numbers"), ErrorKind::invalid_value for NaN/Inf or out-of-range numbers; a mesh that
/// cannot be read gives the mesh reader's error. Numbers are correctly rounded, so a transform
/// reads as the same doubles as the CLI's --transform-a/--transform-b.
[[nodiscard]] Result<Scene> parse_scene_json(std::string_view text,
                                             const SceneJsonOptions& options = {});

/// Reads and parses a scene file; mesh paths are relative to the file's folder.
[[nodiscard]] Result<Scene> read_scene_json(const std::filesystem::path& file);

}  // namespace contain::io
