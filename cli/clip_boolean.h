#pragma once
// The polygon-boolean branch of `contain clip` (--subject/--clip/--op), kept apart from the
// segment, polygon and mesh branches of cli/clip.cpp, which calls these.

#include <string>
#include <vector>

#include "common.h"
#include "contain/clip/polygon_boolean.h"

namespace contain::cli {

struct ClipBooleanOptions {
  std::string subject;
  std::vector<std::string> clips;  // --clip, repeatable for the mesh booleans (clip_solid.cpp)
  clip::Op op = clip::Op::intersection;
  Fill fill = Fill::even_odd;
  std::string format = "wkt";
  std::vector<std::string> shapes;  // `clip A B --op OP`: the subject and the clip
  CLI::Option* format_option = nullptr;
  CLI::Option* op_option = nullptr;
  CLI::Option* fill_option = nullptr;
};

/// Adds --subject, --clip, --op, --fill and --format to the `clip` subcommand; --op is required
/// with --subject, and --subject with --clip (--subject MESH --op union alone repairs a solid).
void add_clip_boolean_options(CLI::App& cmd, ClipBooleanOptions& options);

/// True when the command line asked for a boolean (--subject, shapes A B or --op given).
[[nodiscard]] bool clip_boolean_requested(const ClipBooleanOptions& options);

/// Reads both regions (one --clip), computes the boolean and writes it to `out` (stdout when empty
/// or "-"): WKT (POLYGON, MULTIPOLYGON or their EMPTY), GeoJSON, or an SVG of subject, clip and
/// result. Returns the exit code.
[[nodiscard]] int run_clip_boolean(const ClipBooleanOptions& options, const std::string& out);

}  // namespace contain::cli
