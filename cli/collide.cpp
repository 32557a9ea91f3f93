// contain collide: discrete collision of two meshes (solids, or surfaces when not closed) or
// two 2D regions; one answer per pose of B.

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "collide_ccd.h"
#include "common.h"
#include "contain/collide/mesh_mesh.h"
#include "contain/collide/region_region.h"
#include "contain/io/mesh_io.h"
#include "contain/io/mesh_warning.h"
#include "contain/io/number_table.h"
#include "contain/io/region_io.h"
#include "contain/shapes/mesh_validation.h"
#include "many.h"
#include "progress.h"
#include "timings.h"
#include "verbs.h"

namespace contain::cli {
namespace {

struct CollideOptions {
  std::string a, b;
  std::string scene;
  std::string transform_a, transform_b, poses;
  bool json = false;
  int threads = 0;
  bool quiet = false;
  std::string out;
};

std::string json_point(Vec3 v) {
  return fmt::format("[{},{},{}]", v.x, v.y, v.z);
}

std::string mesh_json(const collide::Contact& c, const collide::MeshPair& pair, const Mesh& b,
                      const Transform& tb) {
  std::string w;
  switch (c.witness) {
    case inside::PairWitness::triangles:
      w = fmt::format(",\"witness\":{{\"kind\":\"triangles\",\"triangle_a\":{},\"triangle_b\":{}}}",
                      c.triangle_a, c.triangle_b);
      break;
    case inside::PairWitness::vertex_of_a_in_b:
      w = fmt::format(",\"witness\":{{\"kind\":\"vertex_of_a_in_b\",\"vertex\":{},\"point\":{}}}",
                      c.vertex, json_point(pair.a_vertices()[static_cast<std::size_t>(c.vertex)]));
      break;
    case inside::PairWitness::vertex_of_b_in_a:
      w = fmt::format(",\"witness\":{{\"kind\":\"vertex_of_b_in_a\",\"vertex\":{},\"point\":{}}}",
                      c.vertex, json_point(tb.apply(b.vertex(c.vertex))));
      break;
    default:
      break;
  }
  return fmt::format("{{\"intersect\":{}{},\"node_pairs\":{},\"exact_tests\":{}}}\n",
                     c.intersect ? "true" : "false", w, c.node_pairs, c.exact_tests);
}

std::string answer(bool intersect) {
  return intersect ? "intersect\n" : "disjoint\n";
}

int run_regions(const CollideOptions& o) {
  if (!o.transform_a.empty() || !o.transform_b.empty() || !o.poses.empty()) {
    return report(Error{ErrorKind::usage,
                        "--transform-a, --transform-b and --poses apply to meshes (3D) only"});
  }
  auto a = read_region_warned(o.a);
  if (!a) return report(a.error());
  auto b = read_region_warned(o.b);
  if (!b) return report(b.error());
  enter_phase(Phase::query);
  const collide::Contact c = collide::region_region(*a, *b);
  if (!o.json) return emit(answer(c.intersect), o.out);
  std::string w;
  if (c.witness == inside::PairWitness::edges) {
    w = fmt::format(",\"witness\":{{\"kind\":\"edges\",\"edge_a\":{},\"edge_b\":{}}}", c.triangle_a,
                    c.triangle_b);
  } else if (c.intersect) {
    w = fmt::format(",\"witness\":{{\"kind\":\"{}\",\"vertex\":{}}}", collide::to_string(c.witness),
                    c.vertex);
  }
  return emit(fmt::format("{{\"intersect\":{}{}}}\n", c.intersect ? "true" : "false", w), o.out);
}

int run_meshes(const CollideOptions& o) {
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
  const collide::MeshPair pair(a->mesh, b->mesh, {.transform_a = ta});
  for (const auto& [solid, name, mesh] : {std::tuple{pair.a_is_solid(), o.a, &a->mesh},
                                          std::tuple{pair.b_is_solid(), o.b, &b->mesh}}) {
    if (solid) {
      warn_of_solid(name, *mesh);
      continue;
    }
    warn(io::open_mesh_warning(name, validate_mesh(*mesh), io::OpenMeshReading::surface_contact));
  }
  enter_phase(Phase::query);
  std::vector<collide::Contact> contacts(poses.size());
  Progress progress("poses", poses.size(), !o.quiet && stderr_is_terminal());
  progress.run([&](std::size_t begin, std::size_t end) {
    pair.collide(std::span<const Transform>(poses).subspan(begin, end - begin),
                 std::span<collide::Contact>(contacts).subspan(begin, end - begin),
                 {.threads = o.threads});
  });
  enter_phase(Phase::write);
  std::string text;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    text +=
        o.json ? mesh_json(contacts[i], pair, b->mesh, poses[i]) : answer(contacts[i].intersect);
  }
  return emit(text, o.out);
}

}  // namespace

Verb add_collide(CLI::App& app) {
  auto o = std::make_shared<CollideOptions>();
  auto c = std::make_shared<CcdCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "collide",
      "Collision: do two solids (meshes, per pose) or two 2D regions intersect; every touching "
      "pair of a scene (--scene); continuous: first contact of moving meshes (--from-b/--to-b) "
      "or of primitives (--ccd)");
  cmd->add_option("A", o->a, "a mesh (.obj .off .stl .ply) or a 2D region (.wkt .geojson)");
  cmd->add_option("B", o->b, "the same kind of shape as A");
  cmd->add_option("--scene", o->scene,
                  "many solids instead of A and B: {\"objects\": [{\"id\": ..., \"mesh\": "
                  "\"part.stl\", \"transform\": [12 numbers]}, ...]} (mesh paths relative to the "
                  "file); prints every intersecting pair 'ID1 ID2' in file order")
      ->option_text("FILE");
  cmd->add_option("--transform-a", o->transform_a,
                  "place A: 12 numbers r00 r01 r02 t0 r10 r11 r12 t1 r20 r21 r22 t2 (x' = R x + t)")
      ->option_text("T");
  cmd->add_option("--transform-b", o->transform_b, "place B (12 numbers, as --transform-a)")
      ->option_text("T");
  cmd->add_option("--poses", o->poses, "one transform of B a line: one answer a line")
      ->option_text("FILE");
  cmd->add_option("--from-a", c->from_a,
                  "continuous: A's placement at t = 0 (12 numbers, as --transform-a); its vertices "
                  "move on straight lines to --to-a")
      ->option_text("T");
  cmd->add_option("--to-a", c->to_a, "continuous: A's placement at t = 1")->option_text("T");
  cmd->add_option("--from-b", c->from_b, "continuous: B's placement at t = 0")->option_text("T");
  cmd->add_option("--to-b", c->to_b, "continuous: B's placement at t = 1")->option_text("T");
  cmd->add_option("--motions", c->motions,
                  "continuous: one motion of B a line (24 numbers: its placement at t = 0, then "
                  "at t = 1); one answer a line")
      ->option_text("FILE");
  cmd->add_option("--ccd", c->kind,
                  "continuous collision of primitives from --queries: vertex-face or edge-edge")
      ->check(CLI::IsMember({"vertex-face", "edge-edge"}))
      ->option_text("KIND");
  cmd->add_option("--queries", c->queries,
                  "with --ccd: the CCD benchmark's CSV (8 rows a query, exact rationals) or any "
                  "other file with 24 numbers a line")
      ->option_text("FILE");
  cmd->add_flag("--json", o->json,
                "one JSON object a result: intersect, a witness (a pair of triangles or a "
                "contained vertex) and work counts");
  add_threads_option(*cmd, o->threads);
  add_quiet_option(*cmd, o->quiet);
  cmd->add_option("--out", o->out, "write the answers to FILE instead of stdout")
      ->option_text("FILE");
  cmd->footer(
      "Solids and regions are closed sets: touching counts, one inside the other counts.\n"
      "A mesh that is not closed is a surface (a warning says so).\n"
      "Examples:\n"
      "  contain collide gear.stl shaft.stl --transform-b 1,0,0,2.5,0,1,0,0,0,0,1,0\n"
      "  contain collide a.off b.off --poses poses.txt --json\n"
      "  contain collide parcel.wkt road.geojson\n"
      "  contain collide --scene assembly.json --json --threads 2\n"
      "Continuous collision (the earliest time of contact, rounded down to a double):\n"
      "  contain collide plate.off bullet.off --from-b 1,0,0,0,0,1,0,0,0,0,1,3 "
      "--to-b 1,0,0,0,0,1,0,0,0,0,1,-3\n"
      "  contain collide --ccd vertex-face --queries data_0_0.csv");
  return {
      cmd, [o, c]() {
        c->a = o->a;
        c->b = o->b;
        c->transform_a = o->transform_a;
        c->transform_b = o->transform_b;
        c->json = o->json;
        c->threads = o->threads;
        c->quiet = o->quiet;
        c->out = o->out;
        if (!o->scene.empty()) {
          if (!o->a.empty() || !o->transform_a.empty() || !o->transform_b.empty() ||
              !o->poses.empty() || has_motion(*c) || !c->kind.empty() || !c->queries.empty()) {
            return report({ErrorKind::usage,
                           "collide: --scene takes no shapes A B, transforms, poses, motions or "
                           "CCD queries (the scene file places its objects)"});
          }
          return run_collide_scene(o->scene, o->json, o->threads, o->quiet, o->out);
        }
        if (c->kind.empty() && !c->queries.empty()) {
          // The kind decides how the 8 points of a query are read: guessing answers another
          // question (issue 24: a vertex-face hit printed as an edge-edge miss).
          return report(Error{ErrorKind::usage,
                              "collide: --queries FILE needs --ccd vertex-face or --ccd edge-edge "
                              "(how each query's 8 points are read)"});
        }
        if (!c->kind.empty()) return run_ccd_queries(*c);
        if (o->a.empty() || o->b.empty()) {
          return report(Error{ErrorKind::usage,
                              "collide needs two shapes A and B (or --scene "
                              "FILE, or --ccd KIND --queries FILE)"});
        }
        if (has_motion(*c)) {
          if (is_region_path(o->a) || is_region_path(o->b) || !o->poses.empty()) {
            return report(Error{ErrorKind::usage,
                                "--from-X, --to-X and --motions move meshes (3D); --poses "
                                "does not go with them"});
          }
          return run_moving_meshes(*c);
        }
        return is_region_path(o->a) ? run_regions(*o) : run_meshes(*o);
      }};
}

}  // namespace contain::cli
