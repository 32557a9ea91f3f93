#include "contain/io/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace contain::io {
namespace {

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  return buffer;
}

std::string escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string style_attributes(const SvgStyle& style) {
  return "fill=\"" + style.fill + "\" fill-opacity=\"" + number(style.fill_opacity) +
         "\" stroke=\"" + style.stroke + "\" stroke-width=\"" + number(style.stroke_width) + "\"";
}

// "#rrggbb" scaled toward black by `light` in [0, 1] (1: the colour itself); another spelling of a
// colour is returned unchanged (it cannot be shaded).
std::string shade(const std::string& colour, double light) {
  unsigned r = 0, g = 0, b = 0;
  if (colour.size() != 7 || std::sscanf(colour.c_str(), "#%02x%02x%02x", &r, &g, &b) != 3) {
    return colour;
  }
  const auto scale = [light](unsigned c) {
    return static_cast<unsigned>(std::lround(std::clamp(light, 0.0, 1.0) * c));
  };
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", scale(r) & 0xffu, scale(g) & 0xffu,
                scale(b) & 0xffu);
  return buffer;
}

struct Axes {
  Vec3 right, up, toward;  // toward the viewer
};

Axes view_axes(const View3& view) {
  const double a = view.azimuth_deg * std::numbers::pi / 180.0;
  const double e = view.elevation_deg * std::numbers::pi / 180.0;
  return {{-std::sin(a), std::cos(a), 0.0},
          {-std::sin(e) * std::cos(a), -std::sin(e) * std::sin(a), std::cos(e)},
          {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)}};
}

}  // namespace

Vec2 project(Vec3 p, const View3& view) {
  const Axes axes = view_axes(view);
  return {dot(p, axes.right), dot(p, axes.up)};
}

double view_depth(Vec3 p, const View3& view) {
  return dot(p, view_axes(view).toward);
}

Box2 projected_bounds(std::span<const Vec3> points, const View3& view) {
  Box2 box;
  for (const Vec3& p : points)
    box.expand(project(p, view));
  return box;
}

SvgCanvas::SvgCanvas(const Box2& world, double width_px) : width_(width_px) {
  Box2 box = world.empty() ? Box2{{0, 0}, {1, 1}} : world;
  double dx = box.max.x - box.min.x, dy = box.max.y - box.min.y;
  const double size = std::max({dx, dy, 1e-300});
  if (dx <= 0) dx = size;
  if (dy <= 0) dy = size;
  const double margin = 0.04 * std::max(dx, dy);
  world_ = {{box.min.x - margin, box.min.y - margin},
            {box.min.x + dx + margin, box.min.y + dy + margin}};
  scale_ = width_ / (world_.max.x - world_.min.x);
  height_ = (world_.max.y - world_.min.y) * scale_;
}

Vec2 SvgCanvas::to_pixels(Vec2 world) const {
  return {(world.x - world_.min.x) * scale_, (world_.max.y - world.y) * scale_};
}

void SvgCanvas::region(std::span<const Ring> rings, const SvgStyle& style) {
  std::string d;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 p = to_pixels(ring[i]);
      d += (i == 0 ? "M" : "L") + number(p.x) + " " + number(p.y) + " ";
    }
    if (!ring.empty()) d += "Z ";
  }
  body_ += "<path d=\"" + d + "\" fill-rule=\"evenodd\" " + style_attributes(style) + "/>\n";
}

void SvgCanvas::segments(std::span<const Segment2> segments, const SvgStyle& style) {
  for (const Segment2& s : segments) {
    const Vec2 a = to_pixels(s.a), b = to_pixels(s.b);
    body_ += "<line x1=\"" + number(a.x) + "\" y1=\"" + number(a.y) + "\" x2=\"" + number(b.x) +
             "\" y2=\"" + number(b.y) + "\" " + style_attributes(style) +
             " stroke-linecap=\"round\"/>\n";
  }
}

void SvgCanvas::points(std::span<const Vec2> points, std::span<const Location> locations,
                       double radius_px, const LocationColours& colours) {
  // One group per location keeps the file small and lets boundary dots draw on top.
  const Location order[] = {Location::outside, Location::inside, Location::boundary};
  for (Location which : order) {
    const std::string& colour = which == Location::inside     ? colours.inside
                                : which == Location::boundary ? colours.boundary
                                                              : colours.outside;
    body_ += "<g fill=\"" + colour + "\">\n";
    for (std::size_t i = 0; i < points.size() && i < locations.size(); ++i) {
      if (locations[i] != which) continue;
      const Vec2 p = to_pixels(points[i]);
      body_ += "<circle cx=\"" + number(p.x) + "\" cy=\"" + number(p.y) + "\" r=\"" +
               number(which == Location::boundary ? radius_px * 1.8 : radius_px) + "\"/>\n";
    }
    body_ += "</g>\n";
  }
}

void SvgCanvas::points(std::span<const Vec2> points, std::string_view colour, double radius_px) {
  body_ += "<g fill=\"" + std::string(colour) + "\">\n";
  for (const Vec2& world : points) {
    const Vec2 p = to_pixels(world);
    body_ += "<circle cx=\"" + number(p.x) + "\" cy=\"" + number(p.y) + "\" r=\"" +
             number(radius_px) + "\"/>\n";
  }
  body_ += "</g>\n";
}

void SvgCanvas::cells(const Box2& area, int columns, int rows,
                      std::span<const std::string> colours) {
  if (columns <= 0 || rows <= 0) return;
  const double w = (area.max.x - area.min.x) / columns, h = (area.max.y - area.min.y) / rows;
  body_ += "<g shape-rendering=\"crispEdges\">\n";
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns;) {
      const std::size_t k = static_cast<std::size_t>(j) * static_cast<std::size_t>(columns) +
                            static_cast<std::size_t>(i);
      if (k >= colours.size()) break;
      int end = i + 1;
      while (end < columns && k + static_cast<std::size_t>(end - i) < colours.size() &&
             colours[k + static_cast<std::size_t>(end - i)] == colours[k])
        ++end;
      if (!colours[k].empty()) {
        // Top left corner in pixels: world y grows upward, pixel y downward.
        const Vec2 a = to_pixels({area.min.x + i * w, area.min.y + (j + 1) * h});
        const Vec2 b = to_pixels({area.min.x + end * w, area.min.y + j * h});
        body_ += "<rect x=\"" + number(a.x) + "\" y=\"" + number(a.y) + "\" width=\"" +
                 number(b.x - a.x + 0.3) + "\" height=\"" + number(b.y - a.y + 0.3) + "\" fill=\"" +
                 colours[k] + "\"/>\n";
      }
      i = end;
    }
  }
  body_ += "</g>\n";
}

std::size_t SvgCanvas::mesh(const Mesh& mesh, const View3& view, const MeshStyle& style) {
  const Axes axes = view_axes(view);
  // Light from above left of the viewer, so that faces turned alike toward the viewer (a cap and
  // a wall) still differ.
  const Vec3 light = (-0.35 * axes.right + 0.6 * axes.up + 0.72 * axes.toward) *
                     (1.0 / std::sqrt(0.35 * 0.35 + 0.6 * 0.6 + 0.72 * 0.72));
  struct Face {
    double depth;
    double facing;  // cosine between the normal and the direction to the viewer
    double light;   // cosine between the normal and the direction to the light
    std::size_t index;
  };
  std::vector<Face> faces;
  faces.reserve(mesh.triangles.size());
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const TriangleIndices& t = mesh.triangles[i];
    const Vec3 a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const Vec3 b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const Vec3 c = mesh.vertices[static_cast<std::size_t>(t[2])];
    const Vec3 n = cross(b - a, c - a);
    const double norm = length(n);
    const bool usable = norm > 0 && std::isfinite(norm);
    faces.push_back({dot((a + b + c) * (1.0 / 3.0), axes.toward),
                     usable ? dot(n, axes.toward) / norm : 0.0, usable ? dot(n, light) / norm : 0.0,
                     i});
  }
  if (style.max_triangles > 0 && faces.size() > style.max_triangles) {
    std::erase_if(faces, [](const Face& f) { return f.facing < 0; });
    if (faces.size() > style.max_triangles) {
      const std::size_t step = (faces.size() + style.max_triangles - 1) / style.max_triangles;
      std::vector<Face> kept;
      for (std::size_t i = 0; i < faces.size(); i += step)
        kept.push_back(faces[i]);
      faces = std::move(kept);
    }
  }
  std::stable_sort(faces.begin(), faces.end(),
                   [](const Face& x, const Face& y) { return x.depth < y.depth; });
  body_ += "<g stroke-linejoin=\"round\" stroke-width=\"" + number(style.edge_width) + "\">\n";
  for (const Face& f : faces) {
    const TriangleIndices& t = mesh.triangles[f.index];
    std::string d = "M";
    for (int k = 0; k < 3; ++k) {
      const Vec3 v = mesh.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
      const Vec2 p = to_pixels({dot(v, axes.right), dot(v, axes.up)});
      d += (k == 0 ? "" : "L") + number(p.x) + " " + number(p.y);
    }
    // Either side lit alike: an inward or open surface still reads as a shape.
    const std::string fill = shade(style.colour, 0.4 + 0.6 * std::abs(f.light));
    body_ += "<path d=\"" + d + "Z\" fill=\"" + fill + "\" stroke=\"" +
             (style.edge == "none" ? fill : style.edge) + "\"/>\n";
  }
  body_ += "</g>\n";
  return faces.size();
}

void SvgCanvas::title(std::string_view text) {
  title_ = escape(text);
}

void SvgCanvas::legend(std::string_view colour, std::string_view label) {
  legend_.emplace_back(std::string(colour), escape(label));
}

std::string SvgCanvas::str() const {
  const double header = title_.empty() ? 0.0 : 28.0;
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width_) +
                    "\" height=\"" + number(height_ + header) + "\" viewBox=\"0 " +
                    number(-header) + " " + number(width_) + " " + number(height_ + header) +
                    "\" font-family=\"sans-serif\">\n";
  out += "<rect x=\"0\" y=\"" + number(-header) +
         "\" width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (!title_.empty()) out += "<text x=\"8\" y=\"-8\" font-size=\"16\">" + title_ + "</text>\n";
  out += body_;
  double y = 10.0;
  if (!legend_.empty()) {
    out += "<rect x=\"" + number(width_ - 158.0) + "\" y=\"4\" width=\"152\" height=\"" +
           number(18.0 * static_cast<double>(legend_.size()) + 10.0) +
           "\" fill=\"white\" fill-opacity=\"0.85\" stroke=\"#999\"/>\n";
  }
  for (const auto& [colour, label] : legend_) {
    const double x = width_ - 150.0;
    out += "<rect x=\"" + number(x) + "\" y=\"" + number(y) +
           "\" width=\"12\" height=\"12\" fill=\"" + colour + "\" stroke=\"#333\"/>\n";
    out += "<text x=\"" + number(x + 18) + "\" y=\"" + number(y + 11) + "\" font-size=\"13\">" +
           label + "</text>\n";
    y += 18.0;
  }
  out += "</svg>\n";
  return out;
}

std::string region_svg(const MultiPolygon& region, const PictureOptions& options) {
  const std::vector<Ring> rings = region.all_rings();
  SvgCanvas canvas(bounding_box(rings), options.width_px);
  if (!options.title.empty()) canvas.title(options.title);
  canvas.region(rings, {.fill = "#dde8f5", .stroke = "#1f3b5c", .stroke_width = 1.5});
  return canvas.str();
}

std::string mesh_svg(const Mesh& mesh, const PictureOptions& options) {
  std::vector<Vec3> used;
  used.reserve(3 * mesh.triangles.size());
  for (const TriangleIndices& t : mesh.triangles)
    for (const std::int32_t v : t)
      used.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
  SvgCanvas canvas(projected_bounds(used, options.view), options.width_px);
  const std::size_t drawn =
      canvas.mesh(mesh, options.view, {.max_triangles = options.max_triangles});
  std::string title = options.title;
  if (drawn < mesh.triangles.size()) {
    title += (title.empty() ? "" : " ") + std::string("(") + std::to_string(drawn) + " of " +
             std::to_string(mesh.triangles.size()) + " triangles drawn)";
  }
  if (!title.empty()) canvas.title(title);
  return canvas.str();
}

}  // namespace contain::io
