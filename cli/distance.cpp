// contain distance: how far points are from a mesh's surface or a region's rings (unsigned or
// signed, with the closest point and feature, or the exact clearance test), and how far apart
// two meshes or two regions are (per pose of B).

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "common.h"
#include "contain/distance/mesh_distance.h"
#include "contain/distance/mesh_pair_distance.h"
#include "contain/distance/region_distance.h"
#include "contain/distance/region_pair_distance.h"
#include "contain/io/mesh_io.h"
#include "contain/io/mesh_warning.h"
#include "contain/io/number_table.h"
#include "contain/io/points_io.h"
#include "contain/io/region_io.h"
#include "contain/shapes/mesh_validation.h"
#include "progress.h"
#include "timings.h"
#include "verbs.h"

namespace contain::cli {
namespace {

struct DistanceOptions {
  std::string mesh, polygon, points = "-";
  std::string a, b, transform_a, transform_b, poses;
  bool signed_distance = false;
  bool closest = false;
  bool json = false;
  double within = 0.0;
  bool has_within = false;
  Fill fill = Fill::even_odd;
  int threads = 0;
  bool quiet = false;
  std::string out;
};

// %.17g: enough digits to read back the same double.
std::string number(double x) {
  return fmt::format("{:.17g}", x);
}

// "not closed" warnings as data turned into words in io (the contract: the same as `inside`).
void warn_open_mesh(const std::string& name, const Mesh& mesh) {
  warn(io::open_mesh_warning(name, validate_mesh(mesh), io::OpenMeshReading::winding_number_sign));
}

// An empty region has no boundary: its distance is infinite (documented) and nothing is within
// D, but there is no closest point to print (issue 24: "inf 0 0 -1:-1" made one up).
Error no_closest_point(const std::string& path) {
  return {ErrorKind::invalid_value,
          "the region is empty (no rings), so it has no closest point: its distance is inf, "
          "without --closest",
          path};
}

// Runs `work(begin, end)` over n points in chunks with progress on a terminal.
template <class Work>
void with_progress(std::size_t n, const DistanceOptions& o, Work&& work) {
  Progress progress("points", n, !o.quiet && stderr_is_terminal());
  progress.run(work);
}

int run_mesh_points(const DistanceOptions& o) {
  auto file = io::read_mesh(o.mesh);
  if (!file) return report(file.error());
  auto points = io::read_points3(o.points);
  if (!points) return report(points.error());
  enter_phase(Phase::prepare);
  const bool signs = o.signed_distance;
  // Few points: the signs without the index's grid (its cost model; the same answers).
  const distance::MeshDistance prepared(
      file->mesh, {.index = {.queries = points->points.size()}, .signs = signs});
  // The signs are inside's answers: for a closed mesh the solid of its winding number, crossing
  // itself or not.
  if (signs && prepared.regime() != inside::MeshRegime::closed_exact) {
    warn_open_mesh(o.mesh, file->mesh);
  }
  enter_phase(Phase::query);
  const std::vector<Vec3>& p = points->points;
  std::string text;
  if (o.has_within) {
    std::vector<std::uint8_t> yes(p.size());
    with_progress(p.size(), o, [&](std::size_t begin, std::size_t end) {
      prepared.within(std::span<const Vec3>(p).subspan(begin, end - begin), o.within,
                      std::span<std::uint8_t>(yes).subspan(begin, end - begin),
                      {.threads = o.threads});
    });
    for (const std::uint8_t y : yes)
      text += y ? "yes\n" : "no\n";
    return emit(text, o.out);
  }
  std::vector<distance::Closest3> answers(p.size());
  with_progress(p.size(), o, [&](std::size_t begin, std::size_t end) {
    prepared.distance(std::span<const Vec3>(p).subspan(begin, end - begin),
                      std::span<distance::Closest3>(answers).subspan(begin, end - begin),
                      {.signed_distance = signs, .closest_point = o.closest},
                      {.threads = o.threads});
  });
  for (const distance::Closest3& c : answers) {
    text += number(c.distance);
    if (o.closest) {
      text += fmt::format(" {} {} {} {}", number(c.point.x), number(c.point.y), number(c.point.z),
                          c.feature);
    }
    text += '\n';
  }
  return emit(text, o.out);
}

int run_polygon_points(const DistanceOptions& o) {
  auto region = read_region_warned(o.polygon);
  if (!region) return report(region.error());
  if (o.closest && region->polygons.empty()) {
    return report(no_closest_point(o.polygon));
  }
  auto points = io::read_points2(o.points);
  if (!points) return report(points.error());
  enter_phase(Phase::prepare);
  const distance::RegionDistance prepared(
      *region, {.fill = o.fill, .signs = o.signed_distance, .queries = points->points.size()});
  enter_phase(Phase::query);
  const std::vector<Vec2>& p = points->points;
  std::string text;
  if (o.has_within) {
    std::vector<std::uint8_t> yes(p.size());
    with_progress(p.size(), o, [&](std::size_t begin, std::size_t end) {
      prepared.within(std::span<const Vec2>(p).subspan(begin, end - begin), o.within,
                      std::span<std::uint8_t>(yes).subspan(begin, end - begin),
                      {.threads = o.threads});
    });
    for (const std::uint8_t y : yes)
      text += y ? "yes\n" : "no\n";
    return emit(text, o.out);
  }
  std::vector<distance::Closest2> answers(p.size());
  with_progress(p.size(), o, [&](std::size_t begin, std::size_t end) {
    prepared.distance(std::span<const Vec2>(p).subspan(begin, end - begin),
                      std::span<distance::Closest2>(answers).subspan(begin, end - begin),
                      {.signed_distance = o.signed_distance, .closest_point = o.closest},
                      {.threads = o.threads});
  });
  for (const distance::Closest2& c : answers) {
    text += number(c.distance);
    if (o.closest) {
      text += fmt::format(" {} {} {}:{}", number(c.point.x), number(c.point.y), c.ring, c.edge);
    }
    text += '\n';
  }
  return emit(text, o.out);
}

std::string json_vec(Vec3 v) {
  return fmt::format("[{},{},{}]", number(v.x), number(v.y), number(v.z));
}
std::string json_vec(Vec2 v) {
  return fmt::format("[{},{}]", number(v.x), number(v.y));
}

int run_regions(const DistanceOptions& o) {
  if (!o.transform_a.empty() || !o.transform_b.empty() || !o.poses.empty()) {
    return report(Error{ErrorKind::usage,
                        "--transform-a, --transform-b and --poses apply to meshes (3D) only"});
  }
  if (!is_region_path(o.b)) {
    return report(Error{ErrorKind::invalid_value,
                        "A is a 2D region and B a mesh: both must be regions or both meshes", o.b});
  }
  auto a = read_region_warned(o.a);
  if (!a) return report(a.error());
  auto b = read_region_warned(o.b);
  if (!b) return report(b.error());
  enter_phase(Phase::query);
  if (!o.has_within) {
    if (a->polygons.empty()) return report(no_closest_point(o.a));
    if (b->polygons.empty()) return report(no_closest_point(o.b));
  }
  if (o.has_within) {
    return emit(
        distance::region_region_within(*a, *b, o.within, {.fill = o.fill}) ? "yes\n" : "no\n",
        o.out);
  }
  const distance::PairDistance2 d = distance::region_region(*a, *b, {.fill = o.fill});
  if (o.json) {
    return emit(fmt::format("{{\"distance\":{},\"contact\":\"{}\",\"points\":[{},{}],\"edge_a\":"
                            "\"{}:{}\",\"edge_b\":\"{}:{}\",\"vertex\":{}}}\n",
                            number(d.distance), distance::to_string(d.contact), json_vec(d.point_a),
                            json_vec(d.point_b), d.ring_a, d.edge_a, d.ring_b, d.edge_b, d.vertex),
                o.out);
  }
  return emit(fmt::format("{} {} {} {} {}\n", number(d.distance), number(d.point_a.x),
                          number(d.point_a.y), number(d.point_b.x), number(d.point_b.y)),
              o.out);
}

int run_meshes(const DistanceOptions& o) {
  if (is_region_path(o.b)) {
    return report(Error{ErrorKind::invalid_value,
                        "A is a mesh and B a 2D region: both must be meshes or both regions", o.b});
  }
  auto placements = read_placements(o.transform_a, o.transform_b, o.poses);
  if (!placements) return report(placements.error());
  const Transform ta = placements->a;
  const std::vector<Transform>& poses = placements->b;
  auto a = io::read_mesh(o.a);
  if (!a) return report(a.error());
  auto b = io::read_mesh(o.b);
  if (!b) return report(b.error());
  enter_phase(Phase::prepare);
  const distance::MeshPairDistance pair(a->mesh, b->mesh, {.transform_a = ta});
  for (const auto& [solid, name, mesh] : {std::tuple{pair.a_is_solid(), o.a, &a->mesh},
                                          std::tuple{pair.b_is_solid(), o.b, &b->mesh}}) {
    if (solid) {
      warn_of_solid(name, *mesh);
      continue;
    }
    warn(io::open_mesh_warning(name, validate_mesh(*mesh), io::OpenMeshReading::surface_distance));
  }
  enter_phase(Phase::query);
  std::string text;
  if (o.has_within) {
    std::vector<std::uint8_t> yes(poses.size());
    pair.within(poses, o.within, yes, {.threads = o.threads});
    for (const std::uint8_t y : yes)
      text += y ? "yes\n" : "no\n";
    return emit(text, o.out);
  }
  std::vector<distance::PairDistance3> answers(poses.size());
  Progress progress("poses", poses.size(), !o.quiet && stderr_is_terminal());
  progress.run([&](std::size_t begin, std::size_t end) {
    pair.distance(std::span<const Transform>(poses).subspan(begin, end - begin),
                  std::span<distance::PairDistance3>(answers).subspan(begin, end - begin),
                  {.threads = o.threads});
  });
  enter_phase(Phase::write);
  for (const distance::PairDistance3& d : answers) {
    if (o.json) {
      text += fmt::format(
          "{{\"distance\":{},\"contact\":\"{}\",\"points\":[{},{}],\"triangle_a\":{},"
          "\"triangle_b\":{},\"vertex\":{},\"node_pairs\":{},\"exact_pairs\":{}}}\n",
          number(d.distance), distance::to_string(d.contact), json_vec(d.point_a),
          json_vec(d.point_b), d.triangle_a, d.triangle_b, d.vertex, d.node_pairs, d.contenders);
    } else {
      text += fmt::format("{} {} {} {} {} {} {}\n", number(d.distance), number(d.point_a.x),
                          number(d.point_a.y), number(d.point_a.z), number(d.point_b.x),
                          number(d.point_b.y), number(d.point_b.z));
    }
  }
  return emit(text, o.out);
}

}  // namespace

Verb add_distance(CLI::App& app) {
  auto o = std::make_shared<DistanceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "distance",
      "Distance: points from a mesh or a region (signed, closest point, clearance --within), or "
      "two meshes (per pose) or two regions apart");
  auto* mesh =
      cmd->add_option("--mesh", o->mesh, "points against this mesh's surface (.obj .off .stl .ply)")
          ->option_text("FILE");
  auto* polygon = cmd->add_option("--polygon", o->polygon,
                                  "points against this 2D region's rings (.wkt .geojson); points "
                                  "have 2 numbers a line")
                      ->option_text("FILE");
  mesh->excludes(polygon);
  polygon->excludes(mesh);
  cmd->add_option("--points", o->points,
                  "points, one a line (2 or 3 numbers, white space or commas; '#' comments); '-' "
                  "or absent: stdin")
      ->option_text("FILE");
  cmd->add_flag("--signed", o->signed_distance,
                "negative inside, 0 exactly on the boundary (the sign is the exact `inside` "
                "answer)");
  cmd->add_flag("--closest", o->closest,
                "also print the closest point and the closest triangle (mesh) or RING:EDGE "
                "(region)");
  cmd->add_option("--within", o->within,
                  "print yes where the distance is at most D, no otherwise (exact)")
      ->option_text("D")
      ->each([o](const std::string&) { o->has_within = true; });
  cmd->add_option("A", o->a, "two shapes: a mesh (.obj .off .stl .ply) or a 2D region");
  cmd->add_option("B", o->b, "the same kind of shape as A");
  cmd->add_option("--transform-a", o->transform_a,
                  "place A: 12 numbers r00 r01 r02 t0 r10 r11 r12 t1 r20 r21 r22 t2 (x' = R x + t)")
      ->option_text("T");
  cmd->add_option("--transform-b", o->transform_b, "place B (12 numbers, as --transform-a)")
      ->option_text("T");
  cmd->add_option("--poses", o->poses, "one transform of B a line: one answer a line")
      ->option_text("FILE");
  cmd->add_flag("--json", o->json,
                "two shapes: one JSON object a result with distance, points and the features");
  add_fill_option(*cmd, o->fill);
  add_threads_option(*cmd, o->threads);
  add_quiet_option(*cmd, o->quiet);
  cmd->add_option("--out", o->out, "write the answers to FILE instead of stdout")
      ->option_text("FILE");
  cmd->footer(
      "Distances are printed as the double nearest to the exact value (%.17g).\n"
      "Examples:\n"
      "  contain distance --mesh part.stl --points probes.xyz --signed --closest\n"
      "  contain distance --polygon parcels.wkt --points wells.txt --within 25\n"
      "  contain distance tool.stl fixture.stl --transform-b 1,0,0,2.5,0,1,0,0,0,0,1,0 --json\n"
      "  contain distance gear.off shaft.off --poses poses.txt --within 0.002");
  CLI::Option* fill = cmd->get_option("--fill");
  return {
      cmd, [o, mesh, polygon, fill]() {
        // A bad number is bad input (exit 3), as the contract has it for NaN coordinates.
        if (o->has_within && !(std::isfinite(o->within) && o->within >= 0)) {
          return report({ErrorKind::invalid_value,
                         "--within: D must be a finite number >= 0, not " + number(o->within)});
        }
        const bool points_form = mesh->count() > 0 || polygon->count() > 0;
        // Options that this form would silently drop are refused.
        if (o->has_within && (o->closest || o->signed_distance || o->json)) {
          return report({ErrorKind::usage,
                         "distance: --within prints yes/no only: it does not go with "
                         "--closest, --signed or --json"});
        }
        if (points_form && o->json) {
          return report({ErrorKind::usage,
                         "distance: --json is for two shapes A B; points print one line each"});
        }
        if (points_form &&
            (!o->transform_a.empty() || !o->transform_b.empty() || !o->poses.empty())) {
          return report({ErrorKind::usage,
                         "distance: --transform-a, --transform-b and --poses place two shapes "
                         "A B; points against --mesh/--polygon are not moved"});
        }
        if (fill->count() > 0 && (mesh->count() > 0 || (!o->a.empty() && !is_region_path(o->a)))) {
          return report({ErrorKind::usage,
                         "distance: --fill reads the rings of 2D regions; meshes have none"});
        }
        if (!points_form && (o->closest || o->signed_distance)) {
          return report({ErrorKind::usage,
                         "distance: --closest and --signed are for points (--mesh or "
                         "--polygon); two shapes always print their closest points"});
        }
        if (points_form && (!o->a.empty() || !o->b.empty())) {
          return report({ErrorKind::usage,
                         "distance: give either --mesh/--polygon with points, or two shapes "
                         "A B"});
        }
        if (mesh->count() > 0) return run_mesh_points(*o);
        if (polygon->count() > 0) return run_polygon_points(*o);
        if (o->a.empty() || o->b.empty()) {
          return report({ErrorKind::usage,
                         "distance: give --mesh FILE or --polygon FILE (with --points), or "
                         "two shapes A B"});
        }
        return is_region_path(o->a) ? run_regions(*o) : run_meshes(*o);
      }};
}

}  // namespace contain::cli
