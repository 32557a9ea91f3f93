// The 3D scenes of `contain demo`: CSG and mesh containment, mesh-mesh collision, mesh clipping
// with caps, and bounding volumes.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "contain/bound/aabb.h"
#include "contain/bound/bounding_sphere.h"
#include "contain/clip/mesh_clip.h"
#include "contain/collide/mesh_mesh.h"
#include "contain/inside/csg.h"
#include "contain/inside/mesh_index.h"
#include "contain/io/mesh_io.h"
#include "contain/shapes/mesh_validation.h"
#include "demo_scenes.h"
#include "scenes/scenes.h"

namespace contain::cli::demo {
namespace {

Ring circle_ring(Vec2 center, double radius) {
  Ring ring;
  for (int i = 0; i < 180; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 180;
    ring.push_back({center.x + radius * std::cos(a), center.y + radius * std::sin(a)});
  }
  return ring;
}

Ring rectangle(Vec2 min, Vec2 max) {
  return {{min.x, min.y}, {max.x, min.y}, {max.x, max.y}, {min.x, max.y}};
}

// The torus every 3D scene shares: major radius 2, tube radius 0.6, around the z axis.
Mesh demo_torus() {
  return scenes::torus(2.0, 0.6, 96, 48);
}

}  // namespace

// CSG: (ball ∪ box) − small ball, on a grid in the plane z = 0; grid lines meet the box faces
// exactly, so the regularised boundary shows.
Status csg_scene(const Context& context) {
  const Csg tree = Csg::subtract(Csg::unite({Csg::leaf(Sphere{{0, 0, 0}, 1.0}),
                                             Csg::leaf(Box3{{0, -0.5, -0.5}, {1.75, 0.5, 0.5}})}),
                                 Csg::leaf(Sphere{{0.25, 0.25, 0}, 0.375}));
  auto solid = inside::CsgSolid::prepare(tree);
  if (!solid) return solid.error();
  const std::vector<Vec3> grid = scenes::grid_points({{-1.25, -1.25}, {2.0, 1.25}}, 161, 0.0);
  std::vector<Location> locations(grid.size());
  const Stopwatch query;
  solid->locate(grid, locations, {.threads = context.threads});
  const double query_ms = query.ms();
  const Counts c = count(locations);
  fmt::print(
      "CSG solid          (ball u box) - ball, {} grid points in the plane z = 0: {:.1f} ms: "
      "{} in, {} on, {} out\n",
      grid.size(), query_ms, c.inside, c.boundary, c.outside);
  std::vector<Vec2> flat;
  for (const Vec3& p : grid)
    flat.push_back({p.x, p.y});
  io::SvgCanvas canvas({{-1.25, -1.25}, {2.0, 1.25}}, 800);
  canvas.title("contain inside --csg: (ball u box) - ball, slice z = 0");
  canvas.points(flat, locations, 1.8);
  location_legend(canvas);
  return save(context, "inside-csg.svg", canvas.str());
}

// Point in a closed mesh: a million points around a torus, and a slice for the picture.
Status mesh_scene(const Context& context) {
  const Mesh torus = demo_torus();
  const Stopwatch build;
  const inside::MeshIndex index(torus);
  const double build_ms = build.ms();
  const std::vector<Vec3> cloud =
      scenes::uniform_points(Box3{{-3, -3, -1}, {3, 3, 1}}, 1'000'000, 9);
  std::vector<Location> locations(cloud.size());
  const Stopwatch query;
  index.locate(cloud, locations, {.threads = context.threads});
  const double query_ms = query.ms();
  const Counts c = count(locations);
  fmt::print(
      "point in mesh      {} points around a torus of {} triangles ({}): index {:.1f} ms, "
      "located in {:.1f} ms ({:.1f} M points/s): {} in, {} on, {} out\n",
      cloud.size(), torus.triangles.size(),
      index.regime() == inside::MeshRegime::closed_exact ? "closed-exact" : "winding-number",
      build_ms, query_ms, cloud.size() / query_ms / 1e3, c.inside, c.boundary, c.outside);
  // The slice z = 0.3 crosses the tube where the triangles are slanted; z = 0 would hit only
  // vertices of the mesh.
  const std::vector<Vec3> grid = scenes::grid_points({{-3, -3}, {3, 3}}, 161, 0.3);
  std::vector<Location> slice(grid.size());
  index.locate(grid, slice, {.threads = context.threads});
  std::vector<Vec2> flat;
  for (const Vec3& p : grid)
    flat.push_back({p.x, p.y});
  io::SvgCanvas canvas({{-3, -3}, {3, 3}}, 700);
  canvas.title("contain inside --mesh: torus, slice z = 0.3");
  canvas.points(flat, slice, 1.6);
  location_legend(canvas);
  return save(context, "inside-mesh.svg", canvas.str());
}

// Mesh-mesh collision: a bar at a few poses around the torus (through the hole, grazing the
// tube, through it, away), and a small cube nested inside the tube.
Status collide_scene(const Context& context) {
  const Mesh torus = demo_torus();
  const Mesh bar = scenes::box_mesh({{-0.25, -0.25, -1.5}, {0.25, 0.25, 1.5}});
  const Mesh cube = scenes::box_mesh({{-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}});
  const collide::MeshPair torus_bar(torus, bar);
  const collide::MeshPair torus_cube(torus, cube);
  struct Pose {
    const char* what;
    const collide::MeshPair* pair;
    Vec3 at;
  };
  const Pose poses[] = {{"bar through the hole", &torus_bar, {0, 0, 0}},
                        {"bar grazing the inner side", &torus_bar, {1.2, 0, 0}},
                        {"bar through the tube", &torus_bar, {2.0, 0, 0}},
                        {"bar beside the torus", &torus_bar, {3.0, 0, 0}},
                        {"cube nested in the tube", &torus_cube, {-2.0, 0, 0}}};
  io::SvgCanvas canvas({{-3, -3}, {3.5, 3}}, 700);
  canvas.title("contain collide: torus and bars from above (nested cube at left)");
  const Ring outer = circle_ring({0, 0}, 2.6), inner = circle_ring({0, 0}, 1.4);
  const Ring tube[] = {outer, inner};
  canvas.region(tube, {.fill = "#dde8f5", .stroke = "#1f3b5c", .stroke_width = 1.2});
  const Stopwatch clock;
  for (const Pose& pose : poses) {
    const collide::Contact contact = pose.pair->collide(shift(pose.at));
    fmt::print("{:<19}{:<28} {:<9} (witness: {}, {} box pairs, {} exact tests)\n",
               &pose == poses ? "collision" : "", pose.what,
               contact.intersect ? "intersect" : "disjoint", collide::to_string(contact.witness),
               contact.node_pairs, contact.exact_tests);
    const double half = pose.pair == &torus_bar ? 0.25 : 0.1;
    const Ring footprint =
        rectangle({pose.at.x - half, pose.at.y - half}, {pose.at.x + half, pose.at.y + half});
    const char* colour = contact.intersect ? "#d62728" : "#2ca02c";
    canvas.region(std::span<const Ring>(&footprint, 1),
                  {.fill = colour, .stroke = "#333", .fill_opacity = 0.8});
  }
  fmt::print("{:<19}5 poses in {:.2f} ms\n", "", clock.ms());
  canvas.legend("#d62728", "intersect");
  canvas.legend("#2ca02c", "disjoint");
  return save(context, "collide.svg", canvas.str());
}

// Mesh clipping with caps: the torus cut by two half-spaces stays a closed solid; written as OBJ
// and PLY, drawn from the side.
Status mesh_clip_scene(const Context& context) {
  const Mesh torus = demo_torus();
  const Plane keep[] = {{0, 0, -1, 0.25}, {1, 0, 0, 1.0}};  // z <= 0.25 and x >= -1
  const Stopwatch clock;
  const Mesh cut = clip::clip_mesh(torus, keep, {.cut = clip::MeshCut::cap});
  const double ms = clock.ms();
  const MeshReport report = validate_mesh(cut);
  fmt::print("mesh clipping      torus by 2 half-spaces with caps: {} triangles in {:.2f} ms, {}\n",
             cut.triangles.size(), ms,
             report.watertight() ? "closed and consistently oriented" : "NOT closed");
  for (const char* name : {"clip-mesh.obj", "clip-mesh.ply"}) {
    if (Status s = io::write_mesh(cut, context.dir / name); !s) return s;
    record(name);
  }
  const io::View3 view{.azimuth_deg = -70.0, .elevation_deg = 30.0};
  io::SvgCanvas canvas(io::projected_bounds(cut.vertices, view), 800);
  canvas.title("contain clip --mesh --cap: torus with z <= 0.25 and x >= -1");
  canvas.mesh(cut, view);
  return save(context, "clip-mesh.svg", canvas.str());
}

// Bounding volumes of the torus with a lopsided cloud of extra vertices (bounds can enclose all
// vertices): AABB, the minimal sphere and Ritter's, drawn from above.
Status bound_scene(const Context& context) {
  Mesh torus = demo_torus();
  const std::vector<Vec3> cloud =
      scenes::uniform_points(Box3{{0.5, -1.0, -0.5}, {3.5, 1.5, 0.5}}, 2000, 7);
  torus.vertices.insert(torus.vertices.end(), cloud.begin(), cloud.end());
  const Box3 box = bound::aabb(torus, {.vertices = bound::MeshVertices::all});
  const Stopwatch exact_time;
  auto exact = bound::bounding_sphere(
      torus, {.method = bound::SphereMethod::exact, .vertices = bound::MeshVertices::all});
  const double exact_ms = exact_time.ms();
  auto ritter = bound::bounding_sphere(
      torus, {.method = bound::SphereMethod::ritter, .vertices = bound::MeshVertices::all});
  if (!exact) return exact.error();
  if (!ritter) return ritter.error();
  fmt::print(
      "bounding volumes   torus and a cloud, {} points: AABB [{:.3f} {:.3f} {:.3f}]..[{:.3f} "
      "{:.3f} {:.3f}]\n",
      torus.vertices.size(), box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z);
  fmt::print(
      "                   minimal sphere r = {:.6f} ({:.2f} ms), Ritter r = {:.6f} ({:+.2f}%)\n",
      exact->radius, exact_ms, ritter->radius, 100.0 * (ritter->radius / exact->radius - 1.0));
  std::vector<Vec2> top;
  for (const Vec3& v : torus.vertices)
    top.push_back({v.x, v.y});
  const double reach = std::max(exact->radius, ritter->radius) + 0.2;
  io::SvgCanvas canvas({{exact->center.x - reach, exact->center.y - reach},
                        {exact->center.x + reach, exact->center.y + reach}},
                       700);
  canvas.title("contain bound: torus and cloud seen from above");
  const Ring aabb = rectangle({box.min.x, box.min.y}, {box.max.x, box.max.y});
  canvas.region(std::span<const Ring>(&aabb, 1), {.stroke = "#7f7f7f", .stroke_width = 1.5});
  const Ring minimal = circle_ring({exact->center.x, exact->center.y}, exact->radius);
  canvas.region(std::span<const Ring>(&minimal, 1), {.stroke = "#2ca02c", .stroke_width = 2});
  const Ring approximate = circle_ring({ritter->center.x, ritter->center.y}, ritter->radius);
  canvas.region(std::span<const Ring>(&approximate, 1), {.stroke = "#9467bd", .stroke_width = 1.5});
  canvas.points(top, "#1f77b4", 0.9);
  canvas.legend("#7f7f7f", "AABB");
  canvas.legend("#2ca02c", "minimal sphere");
  canvas.legend("#9467bd", "Ritter sphere");
  return save(context, "bound-torus.svg", canvas.str());
}

}  // namespace contain::cli::demo
