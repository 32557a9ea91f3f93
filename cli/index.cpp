// contain index build: prepare a shape once and save the index (docs/index-files.md); and the
// other side, contain inside --index.

#include "index.h"

#include <fmt/format.h>

#include <memory>
#include <span>
#include <vector>

#include "contain/inside/index_file.h"
#include "contain/inside/mesh_index.h"
#include "contain/inside/polygon_index.h"
#include "contain/io/index_io.h"
#include "contain/io/layer_io.h"
#include "contain/io/mesh_io.h"
#include "contain/io/mesh_warning.h"
#include "contain/io/points_io.h"
#include "timings.h"
#include "verbs.h"

namespace contain::cli {
namespace {

struct BuildOptions {
  std::string mesh, polygon, layer, id, layer_name, out;
  Fill fill = Fill::even_odd;
};

int build_mesh_index(const BuildOptions& o) {
  auto file = io::read_mesh(o.mesh);
  if (!file) return report(file.error());
  enter_phase(Phase::prepare);
  // Built for saving only: the file's bytes from less memory than an index that answers.
  const inside::MeshIndexToSave index(file->mesh);
  const std::string warning = io::mesh_warning(index.regime(), index.report());
  if (!warning.empty()) warn(o.mesh + ": " + warning);
  enter_phase(Phase::write);
  if (Status s = io::write_index(index.image(), o.out); !s) return report(s.error());
  return exit_ok;
}

int build_polygon_index(const BuildOptions& o) {
  auto region = read_region_warned(o.polygon);
  if (!region) return report(region.error());
  const inside::PolygonIndex index(*region, {.fill = o.fill});
  const auto source = inside::fingerprint(std::span<const MultiPolygon>(&*region, 1), o.fill);
  if (Status s = io::write_index(inside::format_index(index, source), o.out); !s)
    return report(s.error());
  return exit_ok;
}

int build_layer_index(const BuildOptions& o) {
  auto layer = io::read_layer(o.layer, {.id = o.id, .layer_name = o.layer_name});
  if (!layer) return report(layer.error());
  for (const std::string& warning : layer->warnings)
    warn(warning);
  const inside::RegionLayer index(layer->regions, {.fill = o.fill});
  const auto bytes =
      inside::format_index(index, inside::fingerprint(layer->regions, o.fill), layer->ids);
  if (Status s = io::write_index(bytes, o.out); !s) return report(s.error());
  return exit_ok;
}

Error mismatch(const std::string& index, const std::string& shape, const std::string& rebuild) {
  return {ErrorKind::invalid_value,
          fmt::format("was built from another {} (fingerprints differ): build it again with "
                      "'contain index build {} --out {}'",
                      shape, rebuild, index),
          index};
}

// "FILE: holds a HELD, not a WANTED": the index is of another kind than the shape given.
Error other_kind(const std::string& index, const std::string& held, const std::string& wanted) {
  return {ErrorKind::invalid_value, "holds a " + held + ", not a " + wanted, index};
}

Error other_fill(const std::string& index) {
  return {ErrorKind::invalid_value, "was built with another --fill rule than the one given", index};
}

// One line per point, as contain inside --mesh / --polygon write them.
template <class Index, class Point>
int answer_points(const Index& index, const std::vector<Point>& points, const ManyOptions& o) {
  enter_phase(Phase::query);
  std::vector<Location> locations(points.size());
  index.locate(points, locations, {.threads = o.threads});
  enter_phase(Phase::write);
  return emit(format_locations(locations, o.boundary), o.out);
}

int answer_from_mesh_index(const ManyOptions& o, const IndexQuery& q, const io::IndexFile& file) {
  if (!o.layer.empty() || !q.polygon.empty()) {
    return report(
        other_kind(q.index, "mesh_index", o.layer.empty() ? "polygon_index" : "layer's index"));
  }
  if (!q.mesh.empty()) {
    auto source = io::read_mesh(q.mesh);
    if (!source) return report(source.error());
    if (inside::fingerprint(source->mesh) != file.header.source)
      return report(mismatch(q.index, "mesh than " + q.mesh, "--mesh " + q.mesh));
  }
  auto index = io::read_mesh_index(file, q.index);
  if (!index) return report(index.error());
  const std::string warning = io::mesh_warning(index->regime(), index->report());
  if (!warning.empty()) warn((q.mesh.empty() ? q.index : q.mesh) + ": " + warning);
  enter_phase(Phase::read);
  auto points = io::read_points3(o.points);
  if (!points) return report(points.error());
  return answer_points(*index, points->points, o);
}

int answer_from_polygon_index(const ManyOptions& o, const IndexQuery& q,
                              const io::IndexFile& file) {
  if (!q.mesh.empty() || !o.layer.empty()) {
    return report(
        other_kind(q.index, "polygon_index", o.layer.empty() ? "mesh_index" : "layer's index"));
  }
  auto index = io::read_polygon_index(file, q.index);
  if (!index) return report(index.error());
  if (q.fill_given && index->fill() != o.fill) {
    return report(other_fill(q.index));
  }
  if (!q.polygon.empty()) {
    auto region = read_region_warned(q.polygon);
    if (!region) return report(region.error());
    const auto regions = std::span<const MultiPolygon>(&*region, 1);
    if (inside::fingerprint(regions, index->fill()) != file.header.source)
      return report(mismatch(q.index, "region than " + q.polygon, "--polygon " + q.polygon));
  }
  enter_phase(Phase::read);
  auto points = io::read_points2(o.points);
  if (!points) return report(points.error());
  return answer_points(*index, points->points, o);
}

int answer_from_layer_index(const ManyOptions& o, const IndexQuery& q, const io::IndexFile& file) {
  if (!q.mesh.empty() || !q.polygon.empty()) {
    return report(
        other_kind(q.index, "layer's index", q.mesh.empty() ? "polygon_index" : "mesh_index"));
  }
  auto saved = io::read_region_layer_index(file, q.index);
  if (!saved) return report(saved.error());
  if (q.fill_given && saved->layer.fill() != o.fill) {
    return report(other_fill(q.index));
  }
  if (!o.layer.empty()) {
    auto layer = io::read_layer(o.layer, {.id = o.id, .layer_name = o.layer_name});
    if (!layer) return report(layer.error());
    if (inside::fingerprint(layer->regions, saved->layer.fill()) != saved->source ||
        layer->ids != saved->ids) {
      return report(
          mismatch(q.index, "layer (or other ids) than " + o.layer, "--layer " + o.layer));
    }
  }
  std::vector<std::string> ids = saved->ids;
  if (ids.empty()) {
    for (std::size_t r = 0; r < saved->layer.size(); ++r)
      ids.push_back(std::to_string(r));
  }
  return answer_layer(saved->layer, ids, o);
}

}  // namespace

int run_inside_index(const ManyOptions& o, const IndexQuery& q) {
  enter_phase(Phase::prepare);  // loading a saved index is this run's preparation
  auto file = io::read_index_file(q.index);
  if (!file) return report(file.error());
  switch (file->header.kind) {
    case inside::IndexKind::mesh_index:
      return answer_from_mesh_index(o, q, *file);
    case inside::IndexKind::polygon_index:
      return answer_from_polygon_index(o, q, *file);
    case inside::IndexKind::region_layer:
      break;
  }
  return answer_from_layer_index(o, q, *file);
}

Verb add_index(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "index",
      "Prepared indexes saved to a file, so that later queries of the same shape load "
      "the index instead of building it (contain inside --index FILE)");
  cmd->require_subcommand(1);
  CLI::App* build = cmd->add_subcommand(
      "build",
      "Prepare a mesh's, a region's or a layer's index and save it (a versioned binary file, "
      "checked "
      "on load: magic, format version, byte order, the shape's fingerprint, checksums)");
  auto o = std::make_shared<BuildOptions>();
  auto* mesh = build
                   ->add_option("--mesh", o->mesh,
                                "3D solid bounded by a triangle mesh (.obj .off .stl .ply)")
                   ->option_text("FILE");
  auto* polygon =
      build
          ->add_option("--polygon", o->polygon, "2D region (.wkt POLYGON/MULTIPOLYGON or .geojson)")
          ->option_text("FILE");
  auto* layer =
      build->add_option("--layer", o->layer, "many 2D regions with ids, as contain inside --layer")
          ->option_text("FILE");
  for (CLI::Option* a : {mesh, polygon, layer})
    for (CLI::Option* b : {mesh, polygon, layer})
      if (a != b) a->excludes(b);
  build->add_option("--id", o->id, "with --layer: the attribute holding the ids")
      ->option_text("NAME")
      ->needs(layer);
  build->add_option("--layer-name", o->layer_name, "with --layer: the layer (table) to read")
      ->option_text("NAME")
      ->needs(layer);
  add_fill_option(*build, o->fill);
  build->add_option("--out", o->out, "the index file to write")->option_text("FILE")->required();
  build->footer(
      "Examples:\n"
      "  contain index build --mesh part.obj --out part.cidx\n"
      "  contain inside --index part.cidx --points probes.xyz\n"
      "  contain inside --mesh part.obj --index part.cidx --points probes.xyz   # checks that "
      "part.cidx was built from part.obj\n"
      "  contain index build --polygon coast.wkt --fill nonzero --out coast.cidx\n"
      "  contain index build --layer counties.geojson --id GEOID --out counties.cidx\n"
      "  contain inside --index counties.cidx --points gps.txt\n"
      "A damaged, truncated, foreign or mismatched index file is refused (exit 3), never "
      "trusted. The file is for this build's format version and this machine's byte order "
      "(docs/index-files.md).");
  CLI::Option* fill = build->get_option("--fill");
  return {cmd, [o, mesh, polygon, layer, fill]() {
            if (mesh->count() + polygon->count() + layer->count() == 0) {
              return report(
                  {ErrorKind::usage, "index build: give the shape: --mesh, --polygon or --layer"});
            }
            if (mesh->count() > 0 && fill->count() > 0) {
              return report({ErrorKind::usage,
                             "index build: --fill reads the rings of a --polygon or --layer"});
            }
            if (mesh->count() > 0) return build_mesh_index(*o);
            return polygon->count() > 0 ? build_polygon_index(*o) : build_layer_index(*o);
          }};
}

}  // namespace contain::cli
