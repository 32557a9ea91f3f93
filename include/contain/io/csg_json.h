#pragma once
/// \file
/// Reads CSG solids from the JSON form of the CLI contract (`contain inside --csg FILE`).
///
/// Grammar (one key per object):
///   {"union": [A, B, ...]}  {"intersection": [A, ...]}  {"difference": [A, B]}  {"complement": A}
///   {"sphere": {"center": [x, y, z], "radius": r}}      {"box": {"min": [x, y, z], "max": [..]}}
///   {"halfspace": [a, b, c, d]}  (a x + b y + c z + d >= 0)
///   {"convex": [[a, b, c, d], ...]}  (intersection of half-spaces; [] is all of space)
///   {"implicit": "1 - x^2 - y^2 - z^2"}  (inside where >= 0; muparser syntax, variables x, y, z)
///   {"mesh": "file.obj"}  (relative to the JSON file)
///
/// The result is a shapes::Csg, the tree as data; inside::CsgSolid::prepare locates points in it.

#include <filesystem>
#include <string>
#include <string_view>

#include "contain/core/result.h"
#include "contain/shapes/csg.h"

namespace contain::io {

/// How parse_csg_json names its input and finds mesh files.
struct CsgJsonOptions {
  std::string source = "<string>";  ///< the name errors give (a file name, "<stdin>")
  std::filesystem::path base_dir;   ///< where relative mesh paths are resolved
};

/// Parses a CSG tree from JSON text.
///
/// Errors (Result, never exceptions), with `source` set and, for JSON syntax errors, the 1-based
/// line of the offending byte; messages start with the JSON path of the offending value:
/// - ErrorKind::parse: malformed JSON ("syntax error while parsing value ..."), muparser syntax
///   errors in implicit expressions (muparser's message and the position in the expression);
/// - ErrorKind::invalid_value: "union[1].sphere.radius: expected a number", NaN/Inf or numbers
///   out of the double range, negative radius, box min > max, wrong array length, unknown key,
///   an object with no or several keys, empty union/intersection;
/// - ErrorKind::degenerate: a half-space (or convex plane) with a zero normal;
/// - mesh leaves (`{"mesh": "f.obj"}`, read with io::read_mesh into a CsgMesh): the
///   mesh reader's errors with its kind ("mesh: dir/f.obj:12: ..."), and ErrorKind::degenerate
///   for a mesh that is not closed (a CSG leaf needs a solid); messages name the resolved file.
///
/// Implicit leaves: the expression is compiled once here (so errors surface now) and evaluated by
/// a small pool of muparser instances, one per concurrent caller, behind a mutex that guards
/// only the pool: the returned function is safe to call from several threads at once, as
/// CsgSolid's batch locate does. An evaluation error at run time (none is expected after
/// compilation) gives NaN, which is `outside`.
/// Complexity: linear in the size of the text.
[[nodiscard]] Result<Csg> parse_csg_json(std::string_view text, const CsgJsonOptions& options = {});

/// Reads and parses a CSG file; mesh paths are relative to the file's folder. ErrorKind::io when
/// the file cannot be read.
[[nodiscard]] Result<Csg> read_csg_json(const std::filesystem::path& file);

}  // namespace contain::io
