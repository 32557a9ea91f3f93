// contain index build: prepare a shape once and save the index (docs/index-files.md); and the
// other side, contain inside --index.

#include "index.h"

#include <fmt/format.h>

#include <memory>
#include <span>
#include <vector>

#include "contain/inside/index_file.h"
#include "contain/inside/mesh_index.h"
#include "contain/io/index_io.h"
#include "contain/io/mesh_io.h"
#include "contain/io/mesh_warning.h"
#include "contain/io/points_io.h"
#include "verbs.h"

namespace contain::cli {
namespace {

int build_mesh_index(const std::string& mesh_path, const std::string& out) {
  auto file = io::read_mesh(mesh_path);
  if (!file) return report(file.error());
  const inside::MeshIndex index(file->mesh);
  const std::string warning = io::mesh_warning(index.regime(), index.report());
  if (!warning.empty()) warn(mesh_path + ": " + warning);
  if (Status s = io::write_index(inside::format_index(index), out); !s) return report(s.error());
  return exit_ok;
}

}  // namespace

int run_inside_index(const PointQuery& o, const std::string& index_path, const std::string& mesh) {
  auto file = io::read_index_file(index_path);
  if (!file) return report(file.error());
  if (file->header.kind != inside::IndexKind::mesh_index) {
    return report({ErrorKind::invalid_value,
                   fmt::format("holds a {}; contain inside --index answers from a mesh_index",
                               inside::to_string(file->header.kind)),
                   index_path});
  }
  if (!mesh.empty()) {
    auto source = io::read_mesh(mesh);
    if (!source) return report(source.error());
    if (inside::fingerprint(source->mesh) != file->header.source) {
      return report({ErrorKind::invalid_value,
                     fmt::format("was built from another mesh than {} (the triangles' "
                                 "fingerprints differ): build it again with 'contain index "
                                 "build --mesh {} --out {}'",
                                 mesh, mesh, index_path),
                     index_path});
    }
  }
  auto index = io::read_mesh_index(*file, index_path);
  if (!index) return report(index.error());
  const std::string warning = io::mesh_warning(index->regime(), index->report());
  if (!warning.empty()) warn((mesh.empty() ? index_path : mesh) + ": " + warning);
  auto points = io::read_points3(o.points);
  if (!points) return report(points.error());
  std::vector<Location> locations(points->points.size());
  index->locate(points->points, locations, {.threads = o.threads});
  return emit(format_locations(locations, o.boundary), o.out);
}

Verb add_index(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "index",
      "Prepared indexes saved to a file, so that later queries of the same shape load "
      "the index instead of building it (contain inside --index FILE)");
  cmd->require_subcommand(1);
  CLI::App* build = cmd->add_subcommand(
      "build",
      "Prepare a shape's index and save it (a versioned binary file, checked on load: "
      "magic, format version, byte order, the shape's fingerprint, checksums)");
  auto mesh = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  build->add_option("--mesh", *mesh, "3D solid bounded by a triangle mesh (.obj .off .stl .ply)")
      ->option_text("FILE")
      ->required();
  build->add_option("--out", *out, "the index file to write")->option_text("FILE")->required();
  build->footer(
      "Examples:\n"
      "  contain index build --mesh part.obj --out part.cidx\n"
      "  contain inside --index part.cidx --points probes.xyz\n"
      "  contain inside --mesh part.obj --index part.cidx --points probes.xyz   # checks that "
      "part.cidx was built from part.obj\n"
      "A damaged, truncated, foreign or mismatched index file is refused (exit 3), never "
      "trusted. The file is for this build's format version and this machine's byte order.");
  return {cmd, [mesh, out]() { return build_mesh_index(*mesh, *out); }};
}

}  // namespace contain::cli
