#pragma once
// The mesh-boolean branch of `contain clip` (--subject MESH [--clip MESH ...] --op OP, --csg
// FILE): the solids of ../shared/spec/cli.md, "Solids: booleans of meshes". cli/clip.cpp
// dispatches here when the subject is a mesh or --csg is given.

#include <string>

#include "clip_boolean.h"
#include "common.h"

namespace contain::cli {

struct ClipSolidOptions {
  std::string csg;
  bool json = false;
  CLI::Option* json_option = nullptr;
};

/// Adds --csg and --json to the `clip` subcommand.
void add_clip_solid_options(CLI::App& cmd, ClipSolidOptions& options);

/// True when the command line asks for a mesh boolean: --csg, or a subject (--subject or the
/// first of the shapes A B) with a mesh extension (.obj .off .stl .ply, any case).
[[nodiscard]] bool clip_solid_requested(const ClipBooleanOptions& boolean,
                                        const ClipSolidOptions& solid);

/// Reads the solids (each checked closed, naming the file and one unmatched directed edge),
/// computes the boolean (or evaluates the CSG tree) and writes the mesh to `out` (format by its
/// extension; OFF on stdout when empty or "-"), or with --json the result's counts on stdout and
/// the mesh to `out` (required). Returns the exit code.
[[nodiscard]] int run_clip_solid(const ClipBooleanOptions& boolean, const ClipSolidOptions& solid,
                                 const std::string& out);

/// Writes a mesh to `out` in the format of its extension, or as OFF on stdout when `out` is
/// empty or "-"; returns the exit code.
[[nodiscard]] int emit_mesh(const Mesh& mesh, const std::string& out);

}  // namespace contain::cli
