// contain bound: the AABB and a bounding sphere (circle in 2D) of a mesh or region, as JSON.

#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "common.h"
#include "contain/bound/aabb.h"
#include "contain/bound/bounding_circle.h"
#include "contain/bound/bounding_sphere.h"
#include "contain/io/mesh_io.h"
#include "contain/io/region_io.h"
#include "timings.h"
#include "verbs.h"

namespace contain::cli {
namespace {

struct BoundOptions {
  std::string file;
  bound::SphereMethod method = bound::SphereMethod::exact;
  std::string out;
};

// fmt prints the shortest decimal that reads back as the same double.
std::string json(Vec3 v) {
  return fmt::format("[{},{},{}]", v.x, v.y, v.z);
}
std::string json(Vec2 v) {
  return fmt::format("[{},{}]", v.x, v.y);
}

int run_mesh(const BoundOptions& o) {
  auto file = io::read_mesh(o.file);
  if (!file) return report(file.error());
  enter_phase(Phase::query);
  const Box3 box = bound::aabb(file->mesh);
  auto sphere = bound::bounding_sphere(file->mesh, {.method = o.method});
  if (!sphere) {
    Error error = sphere.error();
    error.source = o.file;
    return report(error);
  }
  const std::string text = fmt::format(
      "{{\"aabb\":{{\"min\":{},\"max\":{}}},\"sphere\":{{\"center\":{},\"radius\":{}}}}}\n",
      json(box.min), json(box.max), json(sphere->center), sphere->radius);
  return emit(text, o.out);
}

int run_region(const BoundOptions& o) {
  auto region = read_region_warned(o.file);
  if (!region) return report(region.error());
  enter_phase(Phase::query);
  const Box2 box = bound::aabb(*region);
  auto circle = bound::bounding_circle(*region, {.method = o.method});
  if (!circle) {
    Error error = circle.error();
    error.source = o.file;
    return report(error);
  }
  const std::string text = fmt::format(
      "{{\"aabb\":{{\"min\":{},\"max\":{}}},\"circle\":{{\"center\":{},\"radius\":{}}}}}\n",
      json(box.min), json(box.max), json(circle->center), circle->radius);
  return emit(text, o.out);
}

}  // namespace

Verb add_bound(CLI::App& app) {
  auto o = std::make_shared<BoundOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bound",
      "Bounding volumes as JSON: a mesh's box and sphere (exact or Ritter), a region's box and "
      "circle");
  cmd->add_option("FILE", o->file,
                  "a mesh (.obj .off .stl .ply: its vertices used by faces) or a 2D region "
                  "(.wkt .geojson: a circle instead of a sphere)")
      ->required();
  const std::map<std::string, bound::SphereMethod> methods{{"exact", bound::SphereMethod::exact},
                                                           {"ritter", bound::SphereMethod::ritter}};
  cmd->add_option("--sphere", o->method,
                  "exact: the minimal enclosing sphere (default); ritter: Ritter's fast, "
                  "slightly larger one. Both contain every vertex, checked exactly")
      ->transform(CLI::CheckedTransformer(methods, CLI::ignore_case))
      ->option_text("exact|ritter");
  cmd->add_option("--out", o->out, "write the JSON to FILE instead of stdout")->option_text("FILE");
  cmd->footer(
      "Examples:\n"
      "  contain bound bunny.ply\n"
      "    {\"aabb\":{\"min\":[..],\"max\":[..]},\"sphere\":{\"center\":[..],\"radius\":r}}\n"
      "  contain bound part.stl --sphere ritter\n"
      "  contain bound parcels.wkt      (2D: \"circle\" in place of \"sphere\")");
  return {cmd, [o]() { return is_region_path(o->file) ? run_region(*o) : run_mesh(*o); }};
}

}  // namespace contain::cli
