// contain inside: one line per point, "in", "on" or "out".

#include <memory>
#include <string>
#include <vector>

#include "common.h"
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
#include "verbs.h"

namespace contain::cli {
namespace {

struct InsideOptions : PointQuery {
  std::string mesh;
  std::string polygon;
  std::string csg;
  std::string index;  // --index FILE: a saved index (contain index build)
};

// Locates every point through `locator.locate(span, span, options)`, chunked for progress.
template <class Locator, class Point>
std::vector<Location> locate_all(const Locator& locator, const std::vector<Point>& points,
                                 const InsideOptions& o) {
  std::vector<Location> locations(points.size());
  Progress progress("points", points.size(), !o.quiet && stderr_is_terminal());
  progress.run([&](std::size_t begin, std::size_t end) {
    locator.locate(std::span<const Point>(points).subspan(begin, end - begin),
                   std::span<Location>(locations).subspan(begin, end - begin),
                   {.threads = o.threads});
  });
  return locations;
}

int run_polygon(const InsideOptions& o) {
  auto region = read_region_warned(o.polygon);
  if (!region) return report(region.error());
  auto points = io::read_points2(o.points);
  if (!points) return report(points.error());
  const inside::PolygonIndex index(*region, {.fill = o.fill});
  const std::vector<Location> locations = locate_all(index, points->points, o);
  return emit(format_locations(locations, o.boundary), o.out);
}

int run_csg(const InsideOptions& o) {
  auto tree = io::read_csg_json(o.csg);
  if (!tree) return report(tree.error());
  auto solid = inside::CsgSolid::prepare(*tree);
  if (!solid) {
    Error error = solid.error();
    if (error.source.empty()) error.source = o.csg;
    return report(error);
  }
  auto points = io::read_points3(o.points);
  if (!points) return report(points.error());
  const std::vector<Location> locations = locate_all(*solid, points->points, o);
  return emit(format_locations(locations, o.boundary), o.out);
}

// A closed mesh is the solid of its winding number, exactly (a self-intersecting one too: no
// self-crossing check is needed); any other mesh the generalized winding number, with a warning
// naming the regime and why (the contract: never `out` everywhere in silence).
int run_mesh(const InsideOptions& o) {
  auto file = io::read_mesh(o.mesh);
  if (!file) return report(file.error());
  auto points = io::read_points3(o.points);
  if (!points) return report(points.error());
  // Few points: no grid (the index's cost model); the answers are the same.
  const inside::MeshIndex index(file->mesh,
                                {.queries = std::max<std::size_t>(points->points.size(), 1)});
  const std::string warning = io::mesh_warning(index.regime(), index.report());
  if (!warning.empty()) warn(o.mesh + ": " + warning);
  const std::vector<Location> locations = locate_all(index, points->points, o);
  return emit(format_locations(locations, o.boundary), o.out);
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
