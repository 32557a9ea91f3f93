// contain demo: every capability on built-in scenes (no files needed), with a short report,
// timings and pictures written into a folder.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "common.h"
#include "contain/bound/aabb.h"
#include "contain/bound/bounding_sphere.h"
#include "contain/inside/csg.h"
#include "contain/inside/polygon_index.h"
#include "contain/io/svg.h"
#include "scenes/scenes.h"
#include "verbs.h"

namespace contain::cli {
namespace {

struct DemoOptions {
  std::string out_dir = "contain-demo";
  int threads = 0;
};

class Stopwatch {
 public:
  [[nodiscard]] double ms() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
        .count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

struct Counts {
  std::size_t inside = 0, boundary = 0, outside = 0;
};

Counts count(std::span<const Location> locations) {
  Counts c;
  for (Location l : locations) {
    if (l == Location::inside) ++c.inside;
    if (l == Location::boundary) ++c.boundary;
    if (l == Location::outside) ++c.outside;
  }
  return c;
}

Ring circle_ring(Vec2 center, double radius) {
  Ring ring;
  for (int i = 0; i < 180; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 180;
    ring.push_back({center.x + radius * std::cos(a), center.y + radius * std::sin(a)});
  }
  return ring;
}

void legend(io::SvgCanvas& canvas) {
  const io::LocationColours colours;
  canvas.legend(colours.inside, "in");
  canvas.legend(colours.boundary, "on (exact)");
  canvas.legend(colours.outside, "out");
}

Status save(const std::filesystem::path& dir, const std::string& name, const std::string& svg) {
  return write_output(svg, (dir / name).string());
}

// Point in polygon: a concave region with two holes and a cloud of points, plus the region's
// own vertices, which lie exactly on its boundary.
Status polygon_scene(const DemoOptions& o, const std::filesystem::path& dir) {
  const Polygon region = scenes::demo_polygon();
  std::vector<Vec2> points = scenes::uniform_points(bounding_box(region.rings), 1'000'000, 42);
  std::size_t vertices = 0;
  for (const Ring& ring : region.rings) {
    points.insert(points.end(), ring.begin(), ring.end());
    vertices += ring.size();
  }
  const Stopwatch build;
  const inside::PolygonIndex index(region, {.fill = Fill::even_odd});
  const double build_ms = build.ms();
  std::vector<Location> locations(points.size());
  const Stopwatch query;
  index.locate(points, locations, {.threads = o.threads});
  const double query_ms = query.ms();
  const Counts c = count(locations);
  fmt::print("point in polygon   {} points against a concave polygon with 2 holes ({} vertices)\n",
             points.size(), vertices);
  fmt::print(
      "                   index built in {:.2f} ms; located in {:.1f} ms ({:.1f} M points/s)\n",
      build_ms, query_ms, points.size() / query_ms / 1e3);
  fmt::print("                   {} in, {} on, {} out\n", c.inside, c.boundary, c.outside);

  io::SvgCanvas canvas(bounding_box(region.rings), 800);
  canvas.title("contain inside --polygon: 6,000 of the points, coloured by location");
  canvas.region(region.rings, {.fill = "#dde8f5", .stroke = "#1f3b5c", .stroke_width = 1.5});
  const std::size_t shown = 6000;
  std::vector<Vec2> sample(points.begin(), points.begin() + shown);
  std::vector<Location> sample_at(locations.begin(), locations.begin() + shown);
  const auto first_vertex = static_cast<std::ptrdiff_t>(points.size() - vertices);
  sample.insert(sample.end(), points.begin() + first_vertex, points.end());  // all "on"
  sample_at.insert(sample_at.end(), locations.begin() + first_vertex, locations.end());
  canvas.points(sample, sample_at, 1.6);
  legend(canvas);
  return save(dir, "inside-polygon.svg", canvas.str());
}

// CSG: (ball ∪ box) − small ball, cut by the plane z = 0 into a grid of points; grid lines meet
// the box faces exactly, so the regularised boundary shows.
Status csg_scene(const DemoOptions& o, const std::filesystem::path& dir) {
  using inside::Csg;
  const Csg tree = Csg::subtract(Csg::unite({Csg::leaf(Sphere{{0, 0, 0}, 1.0}),
                                             Csg::leaf(Box3{{0, -0.5, -0.5}, {1.75, 0.5, 0.5}})}),
                                 Csg::leaf(Sphere{{0.25, 0.25, 0}, 0.375}));
  auto solid = inside::CsgSolid::prepare(tree);
  if (!solid) return solid.error();
  std::vector<Vec3> grid;
  const int n = 161;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j)
      grid.push_back({-1.25 + 3.25 * i / (n - 1), -1.25 + 2.5 * j / (n - 1), 0});
  }
  std::vector<Location> locations(grid.size());
  const Stopwatch query;
  solid->locate(grid, locations, {.threads = o.threads});
  const double query_ms = query.ms();
  const Counts c = count(locations);
  fmt::print(
      "CSG solid          (ball u box) - ball, {} grid points in the plane z = 0: {:.1f} ms\n",
      grid.size(), query_ms);
  fmt::print("                   {} in, {} on, {} out\n", c.inside, c.boundary, c.outside);

  std::vector<Vec2> flat;
  for (const Vec3& p : grid)
    flat.push_back({p.x, p.y});
  io::SvgCanvas canvas({{-1.25, -1.25}, {2.0, 1.25}}, 800);
  canvas.title("contain inside --csg: (ball u box) - ball, slice z = 0");
  canvas.points(flat, locations, 1.8);
  legend(canvas);
  return save(dir, "inside-csg.svg", canvas.str());
}

// Bounding volumes of a torus mesh with a lopsided cloud of points around it (as extra vertices:
// bounds can enclose all vertices): AABB, the minimal sphere and Ritter's, drawn from above.
Status bound_scene(const std::filesystem::path& dir) {
  Mesh torus = scenes::torus(2.0, 0.6, 96, 48);
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
  const Ring aabb{{box.min.x, box.min.y},
                  {box.max.x, box.min.y},
                  {box.max.x, box.max.y},
                  {box.min.x, box.max.y}};
  canvas.region(std::span<const Ring>(&aabb, 1), {.stroke = "#7f7f7f", .stroke_width = 1.5});
  const Ring minimal = circle_ring({exact->center.x, exact->center.y}, exact->radius);
  canvas.region(std::span<const Ring>(&minimal, 1), {.stroke = "#2ca02c", .stroke_width = 2});
  const Ring approximate = circle_ring({ritter->center.x, ritter->center.y}, ritter->radius);
  canvas.region(std::span<const Ring>(&approximate, 1), {.stroke = "#9467bd", .stroke_width = 1.5});
  canvas.points(top, "#1f77b4", 0.9);
  canvas.legend("#7f7f7f", "AABB");
  canvas.legend("#2ca02c", "minimal sphere");
  canvas.legend("#9467bd", "Ritter sphere");
  return save(dir, "bound-torus.svg", canvas.str());
}

int run_demo(const DemoOptions& o) {
  const std::filesystem::path dir(o.out_dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return report({ErrorKind::io, "cannot create the folder: " + ec.message(), o.out_dir});
  fmt::print("contain demo: built-in scenes, exact answers\n\n");
  for (auto scene :
       {+[](const DemoOptions&d, const std::filesystem::path&p) { return polygon_scene(d, p); },
        +[](const DemoOptions&d, const std::filesystem::path&p) { return csg_scene(d, p); },
        +[](const DemoOptions&, const std::filesystem::path&p) { return bound_scene(p); }}) {
    const Status status = scene(o, dir);
    if (!status) return report(status.error());
  }
  fmt::print("\npictures written to {}/: inside-polygon.svg, inside-csg.svg, bound-torus.svg\n",
             dir.string());
  return exit_ok;
}

}  // namespace

Verb add_demo(CLI::App& app) {
  auto o = std::make_shared<DemoOptions>();
  CLI::App* cmd = app.add_subcommand(
      "demo", "Runs every capability on built-in scenes; prints a report and writes SVG pictures");
  cmd->add_option("--out-dir", o->out_dir,
                  "folder for the pictures (created; default contain-demo)")
      ->option_text("DIR");
  add_threads_option(*cmd, o->threads);
  cmd->footer("Example:\n  contain demo --out-dir /tmp/demo && ls /tmp/demo");
  return {cmd, [o]() { return run_demo(*o); }};
}

}  // namespace contain::cli
