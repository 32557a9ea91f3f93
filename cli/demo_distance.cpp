// The distance scenes of `contain demo`: a signed distance slice through a closed mesh as a colour
// map with its zero contour, and the clearance between two parts with the closest pair drawn.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "contain/clip/mesh_clip.h"
#include "contain/distance/mesh_distance.h"
#include "contain/distance/mesh_pair_distance.h"
#include "demo_scenes.h"
#include "scenes/scenes.h"

namespace contain::cli::demo {
namespace {

// The torus of the 3D scenes: major radius 2, tube radius 0.6, around the z axis.
Mesh demo_torus() {
  return scenes::torus(2.0, 0.6, 96, 48);
}

Ring circle_ring(Vec2 center, double radius) {
  Ring ring;
  for (int i = 0; i < 180; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 180;
    ring.push_back({center.x + radius * std::cos(a), center.y + radius * std::sin(a)});
  }
  return ring;
}

std::string hex(double r, double g, double b) {
  const auto byte = [](double v) {
    return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
  };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(r), byte(g), byte(b));
}

// A diverging colour map: blues inside (deeper is darker), reds outside (farther is darker), in
// bands of `step` whose shade alternates slightly, so that the bands read as iso-distance lines.
// Quantised to the bands, so equal colours run along the rows of the picture.
std::string distance_colour(double d, double step, double reach) {
  if (d == 0) return "#000000";
  const double band = std::floor(std::fabs(d) / step);
  const double t = std::min(1.0, (band + 0.5) * step / reach);
  const double shade = std::fmod(band, 2.0) == 0 ? 1.0 : 0.93;
  if (d < 0)
    return hex(shade * (0.85 - 0.80 * t), shade * (0.90 - 0.62 * t), shade * (0.97 - 0.45 * t));
  return hex(shade * (0.99 - 0.45 * t), shade * (0.90 - 0.85 * t), shade * (0.85 - 0.80 * t));
}

Transform pose(double about_z, double about_x, Vec3 at) {
  const double cz = std::cos(about_z), sz = std::sin(about_z);
  const double cx = std::cos(about_x), sx = std::sin(about_x);
  // R = Rz * Rx
  Transform t;
  t.r = {{{cz, -sz * cx, sz * sx}, {sz, cz * cx, -cz * sx}, {0, sx, cx}}};
  t.t = at;
  return t;
}

}  // namespace

// Signed distance to the torus on a grid in the plane z = 0.3, as a colour map with the zero
// contour (the torus's section) on top.
Status distance_slice_scene(const Context& context) {
  const Mesh torus = demo_torus();
  const Stopwatch build;
  const distance::MeshDistance prepared(torus);
  const double build_ms = build.ms();
  constexpr int kCells = 240;
  constexpr double kHalf = 3.2, kHeight = 0.3;
  std::vector<Vec3> grid;
  grid.reserve(kCells * kCells);
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i)
      grid.push_back({-kHalf + (i + 0.5) * (2 * kHalf / kCells),
                      -kHalf + (j + 0.5) * (2 * kHalf / kCells), kHeight});
  std::vector<distance::Closest3> answers(grid.size());
  const Stopwatch query;
  prepared.distance(grid, answers, {.signed_distance = true, .closest_point = false},
                    {.threads = context.threads});
  const double query_ms = query.ms();
  std::vector<Location> locations;
  double deepest = 0, farthest = 0;
  std::vector<std::string> colours;
  colours.reserve(answers.size());
  for (const distance::Closest3& c : answers) {
    locations.push_back(c.location);
    deepest = std::min(deepest, c.distance);
    farthest = std::max(farthest, c.distance);
    colours.push_back(distance_colour(c.distance, 0.1, 1.6));
  }
  const Counts n = count(locations);
  fmt::print(
      "signed distance    {} points in the plane z = {} to a torus of {} triangles: prepared in "
      "{:.1f} ms, answered in {:.1f} ms: {} in (deepest {:.6f}), {} on, {} out (farthest "
      "{:.6f})\n",
      grid.size(), kHeight, torus.triangles.size(), build_ms, query_ms, n.inside, deepest,
      n.boundary, n.outside, farthest);
  io::SvgCanvas canvas({{-kHalf, -kHalf}, {kHalf, kHalf}}, 760);
  canvas.title("contain distance --signed: torus, slice z = 0.3, bands of 0.1");
  canvas.cells({{-kHalf, -kHalf}, {kHalf, kHalf}}, kCells, kCells, colours);
  // The zero contour is the torus's section by the plane (its rounded crossing points; the
  // signs themselves are exact), drawn seen from above.
  std::vector<Segment2> contour;
  for (const Segment3& s : clip::mesh_section(torus, {0, 0, -1, kHeight}))
    contour.push_back({{s.a.x, s.a.y}, {s.b.x, s.b.y}});
  canvas.segments(contour, {.stroke = "#000000", .stroke_width = 1.6});
  canvas.legend(distance_colour(-0.45, 0.1, 1.6), "inside (< 0)");
  canvas.legend("#000000", "zero contour");
  canvas.legend(distance_colour(0.45, 0.1, 1.6), "outside (> 0)");
  return save(context, "distance-slice.svg", canvas.str());
}

// Clearance between two parts: a bar tilted beside the torus; the closest pair of points and
// the exact test "within 0.25". Then the bar moved into contact and a small cube nested in the
// tube (distance 0, which FCL and coal report as positive for nested non-convex meshes).
Status clearance_scene(const Context& context) {
  const Mesh torus = demo_torus();
  // The bar's local frame starts at its face x = 0, so that placed at x = 2.6 that face lies
  // exactly on the torus's outer vertex (2.6, 0, 0).
  const Mesh bar = scenes::box_mesh({{0, -0.2, -1.2}, {0.4, 0.2, 1.2}});
  const Mesh cube = scenes::box_mesh({{-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}});
  const Stopwatch build;
  const distance::MeshPairDistance torus_bar(torus, bar);
  const distance::MeshPairDistance torus_cube(torus, cube);
  const double build_ms = build.ms();
  const Transform apart = pose(0.5, 0.45, {3.1, 1.1, 0.25});
  const Transform touching = pose(0.0, 0.0, {2.6, 0.0, 0.0});
  Transform nested;
  nested.t = {-2.0, 0.0, 0.0};
  const Stopwatch clock;
  const distance::PairDistance3 d = torus_bar.distance(apart);
  const bool within_quarter = torus_bar.within(apart, 0.25);
  const distance::PairDistance3 contact = torus_bar.distance(touching);
  const distance::PairDistance3 inside = torus_cube.distance(nested);
  const double ms = clock.ms();
  fmt::print(
      "clearance          torus ({} triangles) and a tilted bar: distance {:.9f} between "
      "triangles {} and {} ({}), within 0.25: {}\n",
      torus.triangles.size(), d.distance, d.triangle_a, d.triangle_b,
      distance::to_string(d.contact), within_quarter ? "yes" : "no");
  fmt::print(
      "{:<19}bar against the outer side: distance {} ({}); cube nested in the tube: "
      "distance {} ({})\n",
      "", contact.distance, distance::to_string(contact.contact), inside.distance,
      distance::to_string(inside.contact));
  fmt::print("{:<19}prepared in {:.1f} ms, 3 distances and a within test in {:.2f} ms\n", "",
             build_ms, ms);

  io::SvgCanvas canvas({{-3, -3}, {4.6, 3}}, 760);
  canvas.title(fmt::format("contain distance: torus and a tilted bar from above, clearance {:.6f}",
                           d.distance));
  const Ring tube[] = {circle_ring({0, 0}, 2.6), circle_ring({0, 0}, 1.4)};
  canvas.region(tube, {.fill = "#dde8f5", .stroke = "#1f3b5c", .stroke_width = 1.2});
  std::vector<Segment2> edges;
  for (const TriangleIndices& t : bar.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = apart.apply(bar.vertex(t[k]));
      const Vec3 b = apart.apply(bar.vertex(t[(k + 1) % 3]));
      edges.push_back({{a.x, a.y}, {b.x, b.y}});
    }
  }
  canvas.segments(edges, {.stroke = "#8c564b", .stroke_width = 1.0});
  const Segment2 gap{{d.point_a.x, d.point_a.y}, {d.point_b.x, d.point_b.y}};
  canvas.segments(std::span<const Segment2>(&gap, 1), {.stroke = "#d62728", .stroke_width = 2.5});
  const Vec2 ends[] = {gap.a, gap.b};
  canvas.points(ends, "#d62728", 4.0);
  canvas.legend("#dde8f5", "torus (part A)");
  canvas.legend("#8c564b", "bar (part B)");
  canvas.legend("#d62728", "closest pair");
  return save(context, "distance-clearance.svg", canvas.str());
}

}  // namespace contain::cli::demo
