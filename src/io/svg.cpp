#include "contain/io/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "contain/values/max_abs.h"

namespace contain::io {
namespace {

// Pixels: always a finite number, so that no input writes "nan" or "inf" into the document
// (the canvas keeps real pictures far inside these bounds).
std::string number(double v) {
  constexpr double limit = 1e9;
  v = std::isnan(v) ? 0.0 : std::clamp(v, -limit, limit);
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  return buffer;
}

// The width of `text` at `font_px` in a sans-serif face, from above: 0.62 em a character is more
// than the average advance of DejaVu Sans, Arial and Helvetica on digits and lower case.
double text_width(std::string_view text, double font_px) {
  std::size_t characters = 0;
  for (const char c : text)
    characters += (static_cast<unsigned char>(c) & 0xc0) != 0x80;  // UTF-8 lead bytes only
  return 0.62 * font_px * static_cast<double>(characters);
}

// A <text> element at (x, baseline y) that fits in `room` pixels: where the estimate says it would
// run over, its font shrinks to fit (every renderer honours that) and textLength squeezes it too
// (for a face wider than the estimate; librsvg and some viewers ignore textLength).
std::string fitted_text(double x, double y, double font_px, std::string_view escaped,
                        std::string_view plain, double room) {
  const double width = text_width(plain, font_px);
  const bool over = width > room;
  if (over) font_px *= std::max(room, 1.0) / width;
  std::string out =
      "<text x=\"" + number(x) + "\" y=\"" + number(y) + "\" font-size=\"" + number(font_px) + "\"";
  if (over) {
    out += " textLength=\"" + number(std::max(room, 1.0)) + "\" lengthAdjust=\"spacingAndGlyphs\"";
  }
  return out + ">" + std::string(escaped) + "</text>\n";
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
      case '"':
        out += "&quot;";
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

Axes view_axes(const View3& given) {
  // An angle that is not a number (NaN, inf) is the default view's, not a picture of NaNs.
  const View3 view{
      std::isfinite(given.azimuth_deg) ? given.azimuth_deg : View3{}.azimuth_deg,
      std::isfinite(given.elevation_deg) ? given.elevation_deg : View3{}.elevation_deg};
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

SvgCanvas::SvgCanvas(const Box2& world, double width_px)
    : width_(std::isfinite(width_px) && width_px >= 1.0 ? std::min(width_px, 1e6) : 400.0) {
  const bool finite = std::isfinite(world.min.x) && std::isfinite(world.min.y) &&
                      std::isfinite(world.max.x) && std::isfinite(world.max.y);
  Box2 box = world.empty() || !finite ? Box2{{0, 0}, {1, 1}} : world;
  // A box wider than the largest double is drawn in quarter units, and one of subnormal or
  // nearly subnormal numbers in units of 2^-600 (both exact), so that its size, margin and
  // scale are finite and its shape is kept; to_pixels scales every point alike.
  const double reach = std::max(max_abs(box.min), max_abs(box.max));
  if (!std::isfinite(box.max.x - box.min.x) || !std::isfinite(box.max.y - box.min.y)) {
    unit_ = 0.25;
  } else if (reach < 1e-200) {
    unit_ = std::ldexp(1.0, 600);
  }
  box = {box.min * unit_, box.max * unit_};
  double dx = box.max.x - box.min.x, dy = box.max.y - box.min.y;
  // Extents below 1e-200 (subnormal ones too) are drawn 1e-200 wide: the scale, pixels per
  // unit, stays finite.
  constexpr double smallest = 1e-200;
  const double size = std::max({dx, dy, smallest});
  if (dx < smallest) dx = dx <= 0 ? size : smallest;
  if (dy < smallest) dy = dy <= 0 ? size : smallest;
  const double margin = 0.04 * std::max(dx, dy);
  world_ = {{box.min.x - margin, box.min.y - margin},
            {box.min.x + dx + margin, box.min.y + dy + margin}};
  scale_ = width_ / (world_.max.x - world_.min.x);
  height_ = std::min((world_.max.y - world_.min.y) * scale_, 1e7);
}

Vec2 SvgCanvas::to_pixels(Vec2 world) const {
  return {(world.x * unit_ - world_.min.x) * scale_, (world_.max.y - world.y * unit_) * scale_};
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
    const Vec3 a = mesh.vertex(t[0]);
    const Vec3 b = mesh.vertex(t[1]);
    const Vec3 c = mesh.vertex(t[2]);
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
      const Vec3 v = mesh.vertex(t[static_cast<std::size_t>(k)]);
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
  title_ = std::string(text);
}

void SvgCanvas::legend(std::string_view colour, std::string_view label) {
  legend_.emplace_back(std::string(colour), std::string(label));
}

// The title's line above the picture and the legend's box at its top right are laid out from
// the estimated width of their text (text_width), so both stay inside the view box whatever the
// picture's width: the legend box grows to its longest label, the picture grows to hold the
// legend's height, and a text that still does not fit is squeezed (textLength).
std::string SvgCanvas::str() const {
  constexpr double title_px = 16.0, legend_px = 13.0, pad = 8.0;
  const double header = title_.empty() ? 0.0 : 28.0;
  double label_width = 0.0;
  for (const auto& entry : legend_)
    label_width = std::max(label_width, text_width(entry.second, legend_px));
  const double legend_width = std::min(label_width + 34.0, std::max(width_ - 2.0, 1.0));
  const double legend_height = 18.0 * static_cast<double>(legend_.size()) + 10.0;
  const double height = legend_.empty() ? height_ : std::max(height_, legend_height + 8.0);
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width_) +
                    "\" height=\"" + number(height + header) + "\" viewBox=\"0 " + number(-header) +
                    " " + number(width_) + " " + number(height + header) +
                    "\" font-family=\"sans-serif\">\n";
  out += "<rect x=\"0\" y=\"" + number(-header) +
         "\" width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (!title_.empty()) {
    out += fitted_text(pad, -8.0, title_px, escape(title_), title_, width_ - 2.0 * pad);
  }
  out += body_;
  if (!legend_.empty()) {
    const double left = std::max(1.0, width_ - legend_width - 1.0);
    out += "<rect x=\"" + number(left) + "\" y=\"4\" width=\"" + number(legend_width) +
           "\" height=\"" + number(legend_height) +
           "\" fill=\"white\" fill-opacity=\"0.85\" stroke=\"#999\"/>\n";
    double y = 10.0;
    for (const auto& [colour, label] : legend_) {
      const double x = left + 8.0;
      out += "<rect x=\"" + number(x) + "\" y=\"" + number(y) +
             "\" width=\"12\" height=\"12\" fill=\"" + escape(colour) + "\" stroke=\"#333\"/>\n";
      out += fitted_text(x + 18.0, y + 11.0, legend_px, escape(label), label,
                         left + legend_width - (x + 18.0) - 4.0);
      y += 18.0;
    }
  }
  out += "</svg>\n";
  return out;
}

std::string format_svg(const MultiPolygon& region, const PictureOptions& options) {
  const std::vector<Ring> rings = region.all_rings();
  SvgCanvas canvas(bounding_box(rings), options.width_px);
  if (!options.title.empty()) canvas.title(options.title);
  canvas.region(rings, {.fill = "#dde8f5", .stroke = "#1f3b5c", .stroke_width = 1.5});
  return canvas.str();
}

std::string format_svg(const Mesh& mesh, const PictureOptions& options) {
  std::vector<Vec3> used;
  used.reserve(3 * mesh.triangles.size());
  for (const TriangleIndices& t : mesh.triangles)
    for (const std::int32_t v : t)
      used.push_back(mesh.vertex(v));
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
