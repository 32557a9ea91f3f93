// The continuous collision scene of `contain demo`: a small fast box through a thin plate, apart
// at both discrete poses and hit by the sweep; and a batch of primitive queries.

#include <fmt/format.h>

#include <random>
#include <vector>

#include "contain/collide/ccd.h"
#include "contain/collide/mesh_mesh.h"
#include "contain/collide/moving_mesh_pair.h"
#include "demo_scenes.h"
#include "scenes/scenes.h"

namespace contain::cli::demo {
namespace {

// The side view (x, z) of a box's footprint at a translation.
Ring side_view(const Box3& box, Vec3 at) {
  return {{box.min.x + at.x, box.min.z + at.z},
          {box.max.x + at.x, box.min.z + at.z},
          {box.max.x + at.x, box.max.z + at.z},
          {box.min.x + at.x, box.max.z + at.z}};
}

Vec3 lerp(Vec3 a, Vec3 b, double t) {
  return a + t * (b - a);
}

}  // namespace

Status ccd_scene(const Context& context) {
  const Box3 plate_box{{-1, -1, -0.01}, {1, 1, 0.01}};
  const Box3 bullet_box{{-0.05, -0.05, -0.05}, {0.05, 0.05, 0.05}};
  const Mesh plate = scenes::box_mesh(plate_box);
  const Mesh bullet = scenes::box_mesh(bullet_box);
  const Vec3 start{-0.75, 0.2, 3.0}, end{0.75, 0.2, -3.0};
  const collide::Motion motion{shift(start), shift(end)};
  const collide::MeshPair discrete(plate, bullet);
  const bool at0 = discrete.collide(motion.from).intersect;
  const bool at1 = discrete.collide(motion.to).intersect;
  const Stopwatch clock;
  const collide::MovingMeshPair pair(plate, bullet);
  const collide::MeshImpact impact = pair.first_contact(motion);
  const double ms = clock.ms();
  fmt::print(
      "continuous         bullet through a thin plate: t = 0 {}, t = 1 {}; swept: {} at t = {} "
      "({}, {} box pairs, {} primitive tests, {:.2f} ms)\n",
      at0 ? "intersect" : "disjoint", at1 ? "intersect" : "disjoint", impact.hit ? "hit" : "miss",
      impact.time, collide::to_string(impact.witness), impact.node_pairs, impact.primitive_tests,
      ms);

  // A million random vertex-face queries on every core.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0), step(-0.1, 0.1);
  std::vector<collide::CcdQuery> queries(1000000);
  for (collide::CcdQuery& q : queries) {
    const Vec3 centre{u(rng), u(rng), u(rng)};
    const Vec3 motion_v{step(rng), step(rng), step(rng)};
    for (int i = 0; i < 4; ++i) {
      const Vec3 p = centre + Vec3{step(rng), step(rng), step(rng)};
      q[static_cast<std::size_t>(i)] = p;
      q[static_cast<std::size_t>(i + 4)] = i == 0 ? p + motion_v : p;
    }
  }
  std::vector<collide::Impact> impacts(queries.size());
  const Stopwatch batch;
  collide::vertex_face_ccd(queries, impacts, {.threads = context.threads});
  const double batch_ms = batch.ms();
  std::size_t hits = 0;
  for (const collide::Impact& i : impacts)
    hits += i.hit ? 1 : 0;
  fmt::print("{:<19}{} moving vertex-triangle pairs: {} hit, exact, {:.1f} ms ({:.0f} ns each)\n",
             "", queries.size(), hits, batch_ms,
             1e6 * batch_ms / static_cast<double>(queries.size()));

  // The picture: side view (x, z), the plate, the bullet at t = 0 and t = 1 (apart), its path
  // and the bullet at the first contact.
  io::SvgCanvas canvas({{-1.3, -3.2}, {1.3, 3.2}}, 420);
  canvas.title(
      fmt::format("contain collide --from-b --to-b: first contact at t = {:.6g}", impact.time));
  const Ring plate_ring = side_view(plate_box, {0, 0, 0});
  canvas.region(std::span<const Ring>(&plate_ring, 1),
                {.fill = "#dde8f5", .stroke = "#1f3b5c", .stroke_width = 1.2});
  const Segment2 path[] = {{{start.x, start.z}, {end.x, end.z}}};
  canvas.segments(path, {.stroke = "#888888", .stroke_width = 1.0});
  for (const Vec3 at : {start, end}) {
    const Ring r = side_view(bullet_box, at);
    canvas.region(std::span<const Ring>(&r, 1),
                  {.fill = "#2ca02c", .stroke = "#333", .fill_opacity = 0.8});
  }
  if (impact.hit) {
    const Vec3 at = lerp(start, end, impact.time);
    const Ring r = side_view(bullet_box, at);
    canvas.region(std::span<const Ring>(&r, 1),
                  {.fill = "#d62728", .stroke = "#333", .fill_opacity = 0.9});
    const Vec2 contact[] = {{at.x, at.z + bullet_box.min.z}};
    canvas.points(contact, "#000000", 3.0);
  }
  canvas.legend("#2ca02c", "t = 0 and 1: apart");
  canvas.legend("#d62728", "first contact");
  canvas.legend("#dde8f5", "thin plate");
  return save(context, "collide-ccd.svg", canvas.str());
}

}  // namespace contain::cli::demo
