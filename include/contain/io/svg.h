#pragma once
/// \file
/// A small SVG drawing of 2D geometry (and of 3D results projected onto a plane): regions, points
/// coloured by location, segments, labels and a legend. World y points up; the picture is scaled
/// to fit the given world box with a margin.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "contain/core/location.h"
#include "contain/shapes/polygon.h"
#include "contain/values/box.h"
#include "contain/values/segment.h"

namespace contain::io {

/// Fill, stroke and opacity of a drawn shape, as SVG colour strings ("#1f77b4", "none").
struct SvgStyle {
  std::string fill = "none";
  std::string stroke = "#333333";
  double stroke_width = 1.0;  ///< in pixels, whatever the zoom
  double fill_opacity = 1.0;
};

/// The colours used for inside / boundary / outside everywhere in contain's pictures.
struct LocationColours {
  std::string inside = "#2ca02c";
  std::string boundary = "#ff7f0e";
  std::string outside = "#d62728";
};

class SvgCanvas {
 public:
  /// A canvas showing `world` (grown by 4% on each side) in a picture `width_px` wide.
  SvgCanvas(const Box2& world, double width_px);

  /// Draws rings as one path with the even-odd rule (holes show as holes).
  void region(std::span<const Ring> rings, const SvgStyle& style);
  /// Draws each segment as a line.
  void segments(std::span<const Segment2> segments, const SvgStyle& style);
  /// Draws points as dots of `radius_px`, coloured by their location.
  void points(std::span<const Vec2> points, std::span<const Location> locations, double radius_px,
              const LocationColours& colours = {});
  /// Draws points as dots in one colour.
  void points(std::span<const Vec2> points, std::string_view colour, double radius_px);
  /// Writes a caption at the top left.
  void title(std::string_view text);
  /// Adds a legend entry (a swatch and its label) at the top right, in call order.
  void legend(std::string_view colour, std::string_view label);

  /// The whole SVG document.
  [[nodiscard]] std::string str() const;

 private:
  [[nodiscard]] Vec2 to_pixels(Vec2 world) const;

  Box2 world_;
  double scale_ = 1.0;
  double width_ = 0.0;
  double height_ = 0.0;
  std::string body_;
  std::vector<std::pair<std::string, std::string>> legend_;
  std::string title_;
};

}  // namespace contain::io
