// The 2D scenes of `contain demo`: point in polygon, segment clipping, Sutherland-Hodgman and a
// polygon boolean.

#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "contain/clip/clip_polygon.h"
#include "contain/clip/clip_segments.h"
#include "contain/clip/cohen_sutherland.h"
#include "contain/clip/polygon_boolean.h"
#include "contain/inside/polygon_index.h"
#include "demo_scenes.h"
#include "scenes/scenes.h"

namespace contain::cli::demo {
namespace {

const io::SvgStyle region_style{.fill = "#dde8f5", .stroke = "#1f3b5c", .stroke_width = 1.5};
const io::SvgStyle input_outline{.stroke = "#7f7f7f", .stroke_width = 1.0};

std::size_t vertex_count(const MultiPolygon& region) {
  std::size_t n = 0;
  for (const Polygon& p : region.polygons) {
    for (const Ring& r : p.rings)
      n += r.size();
  }
  return n;
}

Ring hexagon(Vec2 center, double radius) {
  Ring ring;
  for (int i = 0; i < 6; ++i) {
    const double a = 3.14159265358979323846 * (i / 3.0 + 1.0 / 6.0);
    ring.push_back({center.x + radius * std::cos(a), center.y + radius * std::sin(a)});
  }
  return ring;
}

}  // namespace

// A concave region with two holes and a million points, plus the region's own vertices, which
// lie exactly on its boundary.
Status polygon_scene(const Context& context) {
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
  index.locate(points, locations, {.threads = context.threads});
  const double query_ms = query.ms();
  const Counts c = count(locations);
  fmt::print("point in polygon   {} points, concave polygon with 2 holes ({} vertices)\n",
             points.size(), vertices);
  fmt::print(
      "                   index {:.2f} ms; located in {:.1f} ms ({:.1f} M points/s): "
      "{} in, {} on, {} out\n",
      build_ms, query_ms, points.size() / query_ms / 1e3, c.inside, c.boundary, c.outside);

  io::SvgCanvas canvas(bounding_box(region.rings), 800);
  canvas.title("contain inside --polygon: 6,000 of the points and every vertex, by location");
  canvas.region(region.rings, region_style);
  const std::size_t shown = 6000;
  std::vector<Vec2> sample(points.begin(), points.begin() + shown);
  std::vector<Location> sample_at(locations.begin(), locations.begin() + shown);
  const auto first_vertex = static_cast<std::ptrdiff_t>(points.size() - vertices);
  sample.insert(sample.end(), points.begin() + first_vertex, points.end());
  sample_at.insert(sample_at.end(), locations.begin() + first_vertex, locations.end());
  canvas.points(sample, sample_at, 1.6);
  location_legend(canvas);
  return save(context, "inside-polygon.svg", canvas.str());
}

// Segments against a box: the batch kernel on a million 3D segments for the timing, and
// Cohen-Sutherland on a few hundred 2D ones for the picture.
Status segment_scene(const Context& context) {
  const Box3 box3{{-1, -1, -1}, {1, 1, 1}};
  const std::vector<Segment3> many =
      scenes::uniform_segments(Box3{{-2, -2, -2}, {2, 2, 2}}, 1'000'000, 5);
  std::vector<Segment3> clipped(many.size());
  std::vector<std::uint8_t> kept(many.size());
  const Stopwatch batch;
  clip::clip_segments(many, box3, clipped, kept, {.threads = context.threads});
  const double batch_ms = batch.ms();
  std::size_t kept_count = 0;
  for (std::uint8_t k : kept)
    kept_count += k;

  const Box2 box{{-1, -0.6}, {1, 0.6}};
  const std::vector<Segment2> few = scenes::uniform_segments(Box2{{-2, -1.5}, {2, 1.5}}, 300, 11);
  std::vector<Segment2> parts;
  for (const Segment2& s : few) {
    if (const clip::ClippedSegment2 c = clip::cohen_sutherland(s, box)) parts.push_back(c.segment);
  }
  fmt::print(
      "segment clipping   1,000,000 3D segments against a box: {:.1f} ms ({:.0f} M/s), {} "
      "kept\n",
      batch_ms, many.size() / batch_ms / 1e3, kept_count);
  fmt::print("                   Cohen-Sutherland on {} 2D segments: {} kept\n", few.size(),
             parts.size());

  io::SvgCanvas canvas({{-2, -1.5}, {2, 1.5}}, 800);
  canvas.title("contain clip --segments --box: kept parts in green");
  const Ring outline{{box.min.x, box.min.y},
                     {box.max.x, box.min.y},
                     {box.max.x, box.max.y},
                     {box.min.x, box.max.y}};
  canvas.region(std::span<const Ring>(&outline, 1),
                {.fill = "#f2f2f2", .stroke = "#333", .stroke_width = 1.5});
  canvas.segments(few, {.stroke = "#bbbbbb", .stroke_width = 0.8});
  canvas.segments(parts, {.stroke = "#2ca02c", .stroke_width = 1.8});
  canvas.legend("#bbbbbb", "input segment");
  canvas.legend("#2ca02c", "inside the box");
  return save(context, "clip-segments.svg", canvas.str());
}

// The section's Sutherland-Hodgman on a concave region with holes: by default the pieces come
// apart into valid polygons.
Status sutherland_hodgman_scene(const Context& context) {
  const MultiPolygon region{{scenes::demo_polygon()}};
  const Ring window = hexagon({6.0, 9.0}, 6.0);  // cuts two lobes apart
  const Stopwatch clock;
  const MultiPolygon pieces = clip::clip_polygon(region, window);
  const double ms = clock.ms();
  fmt::print(
      "Sutherland-Hodgman concave polygon with holes by a convex hexagon: {} pieces, {} "
      "vertices, {:.2f} ms\n",
      pieces.polygons.size(), vertex_count(pieces), ms);
  Box2 view = bounding_box(region.polygons[0].rings);
  view.expand(bounding_box(std::span<const Ring>(&window, 1)));
  io::SvgCanvas canvas(view, 800);
  canvas.title("contain clip --polygon --convex: the pieces inside the hexagon");
  canvas.region(region.polygons[0].rings, input_outline);
  canvas.region(std::span<const Ring>(&window, 1), {.stroke = "#9467bd", .stroke_width = 2});
  for (const Polygon& piece : pieces.polygons) {
    canvas.region(
        piece.rings,
        {.fill = "#2ca02c", .stroke = "#145214", .stroke_width = 1.2, .fill_opacity = 0.6});
  }
  canvas.legend("#7f7f7f", "subject");
  canvas.legend("#9467bd", "clip window");
  canvas.legend("#2ca02c", "result pieces");
  return save(context, "clip-sutherland-hodgman.svg", canvas.str());
}

// A general boolean (exercise 22.4-3): the concave region minus a spiky star.
Status boolean_scene(const Context& context) {
  const Polygon subject = scenes::demo_polygon();
  Polygon star{{scenes::star_ring(40, {3.0, 2.0}, 2.0, 6.0, 3)}};
  const Stopwatch clock;
  const MultiPolygon result = clip::polygon_boolean(subject, star, {.op = clip::Op::difference});
  const double ms = clock.ms();
  fmt::print(
      "polygon boolean    concave polygon with holes minus a 40-point star: {} polygons, "
      "{} vertices, {:.2f} ms\n",
      result.polygons.size(), vertex_count(result), ms);
  Box2 view = bounding_box(subject.rings);
  view.expand(bounding_box(star.rings));
  io::SvgCanvas canvas(view, 800);
  canvas.title("contain clip --op difference: subject minus star");
  canvas.region(subject.rings, input_outline);
  canvas.region(star.rings, {.stroke = "#d62728", .stroke_width = 1.2});
  for (const Polygon& p : result.polygons) {
    canvas.region(
        p.rings,
        {.fill = "#1f77b4", .stroke = "#0b3a5c", .stroke_width = 1.2, .fill_opacity = 0.6});
  }
  canvas.legend("#7f7f7f", "subject");
  canvas.legend("#d62728", "clip (star)");
  canvas.legend("#1f77b4", "difference");
  return save(context, "clip-boolean.svg", canvas.str());
}

}  // namespace contain::cli::demo
