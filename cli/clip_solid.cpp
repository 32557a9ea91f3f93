// contain clip --subject A.off --clip B.stl --op OP, --subject A.obj --op union, --csg FILE:
// exact booleans of solids given as meshes. Parses, calls clip::mesh_boolean or
// clip::csg_to_mesh once (an input the engine finds open is named by its file), writes the mesh.

#include "clip_solid.h"

#include <fmt/format.h>

#include <string>
#include <utility>
#include <vector>

#include "contain/clip/csg_to_mesh.h"
#include "contain/clip/mesh_boolean.h"
#include "contain/io/csg_json.h"
#include "contain/io/mesh_io.h"
#include "contain/io/mesh_warning.h"
#include "contain/shapes/mesh_closure.h"
#include "process_memory.h"
#include "timings.h"

namespace contain::cli {
namespace {

Error usage(std::string message) {
  return {ErrorKind::usage, "clip: " + std::move(message)};
}

bool is_mesh_path(const std::string& path) {
  return io::mesh_format_for_path(path).has_value();
}

// The options of the other clip forms that a mesh boolean would silently drop.
Status refuse_options(const ClipBooleanOptions& b, const ClipSolidOptions& s,
                      const std::string& out) {
  if (b.fill_option->count() > 0 || b.format_option->count() > 0) {
    return usage(
        "--fill and --format apply to polygon booleans; a mesh boolean writes a mesh in the "
        "format of --out's extension");
  }
  if (!s.csg.empty() &&
      (!b.subject.empty() || !b.clips.empty() || !b.shapes.empty() || b.op_option->count() > 0)) {
    return usage("--csg takes the whole tree from its file: no --subject, --clip or --op");
  }
  if (!out.empty() && out != "-" && !io::mesh_format_for_path(out)) {
    return usage("--out " + out + ": a mesh boolean writes a mesh: .obj, .off, .stl or .ply");
  }
  if (s.json && (out.empty() || out == "-")) {
    return usage("--json writes the counts on stdout: give the mesh a file with --out FILE");
  }
  return Ok{};
}

// The subject and the clips, from --subject/--clip or from the shapes A B ...
Result<std::vector<std::string>> input_paths(const ClipBooleanOptions& b) {
  if (!b.shapes.empty() && (!b.subject.empty() || !b.clips.empty())) {
    return usage("give the solids as A B or as --subject A --clip B, not both");
  }
  std::vector<std::string> paths = b.shapes;
  if (paths.empty()) {
    paths.push_back(b.subject);
    paths.insert(paths.end(), b.clips.begin(), b.clips.end());
  }
  if (paths.front().empty()) return usage("--clip needs --subject");
  if (b.op_option->count() == 0) {
    return usage("a mesh boolean needs --op union|intersection|difference|xor");
  }
  if (paths.size() == 1 && b.op != clip::Op::union_) {
    return usage("--op with one solid repairs it: give --op union, or --clip FILE");
  }
  for (const std::string& path : paths) {
    if (!is_mesh_path(path)) {
      return usage(path +
                   ": the subject is a mesh, so every input is a solid: a mesh "
                   "(.obj .off .stl .ply)");
    }
  }
  return paths;
}

// A solid's mesh, read (a file without faces is the empty solid).
Result<Mesh> read_solid(const std::string& path) {
  auto file = io::read_mesh(path, {.allow_empty = true});
  if (!file) return file.error();
  return std::move(file->mesh);
}

// The boolean, or (exit 3) the first input where a directed edge is unmatched, named by its
// file. The engine checks every input closed on its welded soup; only when it refuses one is
// each file's own edge looked up for the message (a second closedness pass over every input
// was 3% of a large boolean's process).
Result<clip::MeshBooleanResult> solids_boolean(const std::vector<Mesh>& solids,
                                               const std::vector<std::string>& paths, clip::Op op) {
  // run_clip_solid keeps freed memory in the process's heap: the engine's arrays go there too.
  Result<clip::MeshBooleanResult> result =
      clip::mesh_boolean(solids, {.op = op, .scratch_pool = false});
  if (result || result.error().kind != ErrorKind::invalid_value) return result;
  for (std::size_t i = 0; i < solids.size(); ++i) {
    if (auto edge = unmatched_edge(solids[i])) {
      return Error{ErrorKind::invalid_value, io::open_solid_message(paths[i], *edge)};
    }
  }
  return result;
}

Result<clip::MeshBooleanResult> compute(const ClipBooleanOptions& b, const ClipSolidOptions& s) {
  if (!s.csg.empty()) {
    auto tree = io::read_csg_json(s.csg);
    if (!tree) return tree.error();
    enter_phase(Phase::query);
    auto result = clip::csg_to_mesh(*tree);
    if (!result) {
      Error e = result.error();
      if (e.source.empty()) e.source = s.csg;
      return e;
    }
    return result;
  }
  auto paths = input_paths(b);
  if (!paths) return paths.error();
  std::vector<Mesh> solids;
  for (const std::string& path : *paths) {
    auto mesh = read_solid(path);
    if (!mesh) return mesh.error();
    solids.push_back(std::move(*mesh));
  }
  enter_phase(Phase::query);
  return solids_boolean(solids, *paths, b.op);
}

}  // namespace

void add_clip_solid_options(CLI::App& cmd, ClipSolidOptions& o) {
  cmd.add_option("--csg", o.csg,
                 "a CSG tree (the JSON of 'contain inside --csg') with polyhedral leaves, "
                 "evaluated to one mesh")
      ->option_text("FILE");
  o.json_option = cmd.add_flag("--json", o.json,
                               "mesh booleans: the result's triangles, vertices, shells, volume "
                               "and moved vertices as one JSON object (the mesh goes to --out)");
}

bool clip_solid_requested(const ClipBooleanOptions& b, const ClipSolidOptions& s) {
  if (!s.csg.empty()) return true;
  const std::string& subject = !b.subject.empty() ? b.subject
                               : b.shapes.empty() ? std::string()
                                                  : b.shapes.front();
  return !subject.empty() && is_mesh_path(subject);
}

int emit_mesh(const Mesh& mesh, const std::string& out) {
  enter_phase(Phase::write);
  if (out.empty() || out == "-") return emit(io::format_mesh(mesh, io::MeshFormat::off), "");
  const Status written = io::write_mesh(mesh, out);
  if (!written) return report(written.error());
  return exit_ok;
}

int run_clip_solid(const ClipBooleanOptions& b, const ClipSolidOptions& s, const std::string& out) {
  if (Status refused = refuse_options(b, s, out); !refused) return report(refused.error());
  keep_freed_memory_for_reuse();  // the engine's stages drop large arrays one after another
  auto result = compute(b, s);
  if (!result) return report(result.error());
  const int written = emit_mesh(result->mesh, out);
  if (written != exit_ok || !s.json) return written;
  return emit(fmt::format("{{\"triangles\":{},\"vertices\":{},\"shells\":{},\"volume\":{},"
                          "\"moved\":{}}}\n",
                          result->mesh.triangles.size(), result->mesh.vertices.size(),
                          result->shells, result->volume, result->moved),
              "");
}

}  // namespace contain::cli
