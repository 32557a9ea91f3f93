// contain inside: one line per point, "in", "on" or "out".

#include <algorithm>
#include <filesystem>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common.h"
#include "contain/core/huge_pages.h"
#include "contain/inside/csg.h"
#include "contain/inside/mesh_index.h"
#include "contain/inside/polygon_index.h"
#include "contain/io/csg_json.h"
#include "contain/io/mesh_io.h"
#include "contain/io/mesh_warning.h"
#include "contain/io/points_io.h"
#include "contain/io/region_io.h"
#include "index.h"
#include "many.h"
#include "progress.h"
#include "timings.h"
#include "verbs.h"

namespace contain::cli {
namespace {

struct InsideOptions : PointQuery {
  std::string mesh;
  std::string polygon;
  std::string csg;
  std::string index;  // --index FILE: a saved index (contain index build)
};

// At most how many points the file holds, without reading it (the points stream, but the mesh's
// index is built before them): a point's line takes at least 6 bytes ("0 0 0\n"), 4 in 2D
// ("0 0\n"). Standard input or an unreadable size: as many as can be, so the full index is built,
// as before.
std::size_t most_points(const std::string& path, std::size_t shortest_line = 6) {
  constexpr std::size_t unknown = std::numeric_limits<std::size_t>::max();
  if (path == "-") return unknown;
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  return error ? unknown : static_cast<std::size_t>(size / shortest_line + 1);
}

// A byte a point, in huge pages (core/huge_pages.h): 10^6 answers are 245 pages of 4 kB to fault
// in otherwise, and each element is written by the locate that follows its resize.
using Answers = HugePageVector<Location>;

// Reads the points a block at a time and answers each piece as it comes, keeping only the
// answers (a byte a point): 10^8 points cost their answers and a block of text, not 2.4 GB of
// points. Nothing is written before the whole file has been read, so a bad line late in the file
// still gives exit 3 and no output. `locate(items, out)` answers a piece.
template <class Item, class Read, class Locate>
Result<Answers> locate_streamed(const InsideOptions& o, Read&& read, Locate&& locate) {
  Answers locations;
  Progress progress("points", 0, !o.quiet && stderr_is_terminal());
  const Status status = read(o.points, io::ChunkedReading{.threads = o.threads},
                             [&](std::span<const Item> points, double share) {
                               enter_phase(Phase::query);
                               const std::size_t at = locations.size();
                               // Room for all, estimated from the first piece.
                               if (at == 0 && share > 0.0 && share < 1.0) {
                                 locations.reserve(static_cast<std::size_t>(
                                     1.05 * static_cast<double>(points.size()) / share));
                               }
                               locations.resize(at + points.size());
                               locate(points, std::span<Location>(locations).subspan(at));
                               progress.update_share(share, locations.size());
                               enter_phase(Phase::read);
                             });
  if (!status) return status.error();
  return locations;
}

// locate_streamed of a reader that answers the points as it scans them (io::locate_points2_bounded
// with a box locator): its pieces are the answers. So `--timings` counts the location in `read`
// (its `query` is the copy of the answers): the two are one pass over the points now.
template <class ReadLocated, class Locator>
Result<Answers> located_streamed(const InsideOptions& o, ReadLocated&& read,
                                 const Locator& locator) {
  return locate_streamed<Location>(
      o,
      [&](const std::string& path, const io::ChunkedReading& reading, const auto& consume) {
        return read(path, reading, locator, consume);
      },
      [](std::span<const Location> answers, std::span<Location> out) {
        std::ranges::copy(answers, out.begin());
      });
}

int answer(const Result<Answers>& locations, const InsideOptions& o) {
  if (!locations) return report(locations.error());
  return emit_locations(*locations, o.boundary, o.out, o.threads);
}

int run_polygon(const InsideOptions& o) {
  auto region = read_region_warned(o.polygon);
  if (!region) return report(region.error());
  enter_phase(Phase::prepare);
  // Few points: one cell, no grid; many in a small region: a finer grid (the index's cost
  // model; the answers are the same).
  const inside::PolygonIndex index(*region, {.fill = o.fill, .queries = most_points(o.points, 4)});
  enter_phase(Phase::read);
  // Points as boxes from their first digits, where most cells have one answer (a point there
  // needs no more digits; the others are read twice).
  const inside::PolygonIndex::Stats stats = index.stats();
  if (2 * stats.edge_cells > stats.cells) {
    return answer(locate_streamed<Vec2>(o, io::read_points2_chunked,
                                        [&](auto points, std::span<Location> out) {
                                          index.locate(points, out, {.threads = o.threads});
                                        }),
                  o);
  }
  return answer(
      located_streamed(o, io::locate_points2_bounded, io::box_locator<io::BoundedPoint2>(index)),
      o);
}

int run_csg(const InsideOptions& o) {
  auto tree = io::read_csg_json(o.csg);
  if (!tree) return report(tree.error());
  enter_phase(Phase::prepare);
  auto solid = inside::CsgSolid::prepare(*tree);
  if (!solid) {
    Error error = solid.error();
    if (error.source.empty()) error.source = o.csg;
    return report(error);
  }
  enter_phase(Phase::read);
  return answer(locate_streamed<Vec3>(o, io::read_points3_chunked,
                                      [&](auto points, std::span<Location> out) {
                                        solid->locate(points, out, {.threads = o.threads});
                                      }),
                o);
}

// A closed mesh is the solid of its winding number, exactly (a self-intersecting one too: no
// self-crossing check is needed); any other mesh the generalized winding number, with a warning
// naming the regime and why (the contract: never `out` everywhere in silence), printed once the
// points have been read (a bad point file gives its error alone, as before).
int run_mesh(const InsideOptions& o) {
  auto file = io::read_mesh(o.mesh);
  if (!file) return report(file.error());
  enter_phase(Phase::prepare);
  // Few points: no grid (the index's cost model; the answers are the same).
  const inside::MeshIndex index(std::move(file->mesh), {.queries = most_points(o.points)});
  enter_phase(Phase::read);
  // Points as boxes from their first digits, where a grid has most cells of one answer (a point
  // there needs no more digits; the others are read twice).
  const inside::MeshIndex::Stats stats = index.stats();
  const bool bounded =
      index.regime() == inside::MeshRegime::closed_exact && 2 * stats.surface_cells < stats.cells;
  auto locations = bounded
                       ? located_streamed(o, io::locate_points3_bounded,
                                          io::box_locator<io::BoundedPoint3>(index))
                       : locate_streamed<Vec3>(o, io::read_points3_chunked,
                                               [&](auto points, std::span<Location> out) {
                                                 index.locate(points, out, {.threads = o.threads});
                                               });
  if (!locations) return report(locations.error());
  const std::string warning = io::mesh_warning(index.regime(), index.report());
  if (!warning.empty()) warn(o.mesh + ": " + warning);
  return answer(locations, o);
}

}  // namespace

Verb add_inside(CLI::App& app) {
  auto o = std::make_shared<InsideOptions>();
  CLI::App* cmd = app.add_subcommand(
      "inside",
      "Point containment: in, on or out of a polygon, mesh or CSG solid for each point; which "
      "regions of a layer (GeoJSON, WKT, GDAL, PostGIS) or solids of a scene hold it");
  auto* polygon = cmd->add_option("--polygon", o->polygon,
                                  "2D region (.wkt POLYGON/MULTIPOLYGON or .geojson); points "
                                  "have 2 numbers a line")
                      ->option_text("FILE");
  auto* csg = cmd->add_option("--csg", o->csg,
                              "3D solid as a CSG tree in JSON (union, intersection, difference, "
                              "complement of sphere, box, halfspace, convex, implicit leaves)")
                  ->option_text("FILE");
  auto* mesh = cmd->add_option("--mesh", o->mesh,
                               "3D solid bounded by a triangle mesh (.obj .off .stl .ply); exact "
                               "for a closed mesh: 'in' where its winding number is positive "
                               "(overlapping parts count once, an inside-out shell subtracts), "
                               "'on' on the solid's boundary; generalized winding number (with a "
                               "warning) otherwise")
                   ->option_text("FILE");
  auto many = std::make_shared<ManyOptions>();
  auto* layer = cmd->add_option("--layer", many->layer,
                                "many 2D regions, each with an id: a GeoJSON FeatureCollection, a "
                                ".wkt file of one POLYGON/MULTIPOLYGON a line, or (GDAL) .shp, "
                                ".gpkg, .fgb, a PG:... connection string; prints the ids of the "
                                "regions holding each point")
                    ->option_text("FILE");
  auto* id = cmd->add_option("--id", many->id,
                             "with --layer: the attribute (property, field, column) holding the "
                             "ids (default: GeoJSON feature ids, else positions from 0)")
                 ->option_text("NAME");
  auto* layer_name = cmd->add_option("--layer-name", many->layer_name,
                                     "with --layer: the layer (table) of a GeoPackage or database "
                                     "holding several")
                         ->option_text("NAME");
  auto* scene = cmd->add_option("--scene", many->scene,
                                "3D solids: the scene JSON of 'contain collide --scene' "
                                "({\"objects\": [{\"id\", \"mesh\", \"transform\"}]}); prints the "
                                "ids of the solids holding each point")
                    ->option_text("FILE");
  for (CLI::Option* other : {polygon, csg, mesh, scene}) {
    layer->excludes(other);
    other->excludes(layer);
  }
  for (CLI::Option* other : {polygon, csg, mesh}) {
    scene->excludes(other);
    other->excludes(scene);
  }
  auto* index = cmd->add_option("--index", o->index,
                                "a saved index (contain index build): answers without building "
                                "one; with --mesh, --polygon or --layer, refused unless built "
                                "from it (exit 3)")
                    ->option_text("FILE");
  for (CLI::Option* other : {csg, scene}) {
    index->excludes(other);
    other->excludes(index);
  }
  polygon->excludes(csg);
  csg->excludes(polygon);
  mesh->excludes(polygon);
  mesh->excludes(csg);
  polygon->excludes(mesh);
  csg->excludes(mesh);
  cmd->add_option("--points", o->points,
                  "points, one a line (2 or 3 numbers, white space or commas; '#' comments); '-' "
                  "or absent: stdin")
      ->option_text("FILE");
  add_boundary_option(*cmd, o->boundary);
  add_fill_option(*cmd, o->fill);
  add_threads_option(*cmd, o->threads);
  add_quiet_option(*cmd, o->quiet);
  cmd->add_option("--out", o->out, "write the answers to FILE instead of stdout")
      ->option_text("FILE");
  cmd->footer(
      "Examples:\n"
      "  contain inside --polygon parcels.wkt --points survey.txt\n"
      "  printf '0.5 0.5\\n2 2\\n' | contain inside --polygon square.geojson --boundary inside\n"
      "  contain inside --mesh bunny.obj --points probes.xyz\n"
      "  contain inside --csg part.json --points probes.xyz --threads 2 --out answers.txt\n"
      "  contain inside --layer counties.gpkg --id GEOID --points gps.txt\n"
      "  contain inside --layer 'PG:dbname=gis' --layer-name parcels --id parcel_id --points "
      "p.txt\n"
      "  contain inside --scene assembly.json --points probes.xyz\n"
      "A point is 'on' only when it lies exactly on the boundary of the filled region (exact "
      "arithmetic on the given doubles).");
  CLI::Option* fill = cmd->get_option("--fill");
  return {cmd, [o, many, polygon, csg, mesh, layer, scene, id, layer_name, fill, index]() {
            if ((id->count() > 0 || layer_name->count() > 0) && layer->count() == 0) {
              return report({ErrorKind::usage, "inside: --id and --layer-name need --layer"});
            }
            // A fill rule reads rings: solids would silently drop it.
            if (fill->count() > 0 && mesh->count() + csg->count() + scene->count() > 0) {
              return report({ErrorKind::usage,
                             "inside: --fill reads the rings of 2D regions (--polygon, --layer); "
                             "--mesh, --csg and --scene are solids"});
            }
            if (layer->count() + scene->count() + index->count() > 0) {
              ManyOptions m = *many;
              static_cast<PointQuery&>(m) = *o;
              if (index->count() > 0) {
                return run_inside_index(m, {.index = o->index,
                                            .mesh = o->mesh,
                                            .polygon = o->polygon,
                                            .fill_given = fill->count() > 0});
              }
              return layer->count() > 0 ? run_layer(m) : run_scene_inside(m);
            }
            if (mesh->count() > 0) return run_mesh(*o);
            if (polygon->count() > 0) return run_polygon(*o);
            if (csg->count() > 0) return run_csg(*o);
            return report({ErrorKind::usage,
                           "inside: give the region: --mesh FILE, --polygon FILE, --csg FILE, "
                           "--layer FILE or --scene FILE"});
          }};
}

}  // namespace contain::cli
