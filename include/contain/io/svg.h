#pragma once
/// \file
/// A small SVG drawing of 2D geometry (and of 3D results projected onto a plane): regions, points
/// coloured by location, segments, shaded triangle meshes, labels and a legend. World y points
/// up; the picture is scaled to fit the given world box with a margin. The pictures of
/// `contain demo`, `contain clip --format svg` and the notebook views of the Python module
/// (`_repr_svg_`) all come from here.

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "contain/core/location.h"
#include "contain/shapes/mesh.h"
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

/// An orthographic view of 3D geometry: seen from the direction with azimuth `azimuth_deg`
/// (degrees about +z from +x) and elevation `elevation_deg` (degrees above the xy plane), with +z
/// pointing up in the picture. The default looks from the front right, a little from above.
struct View3 {
  double azimuth_deg = -60.0;
  double elevation_deg = 25.0;
};

/// Where `p` lands in the picture plane of `view` (x to the right, y up). Floating point.
[[nodiscard]] Vec2 project(Vec3 p, const View3& view);
/// How near `p` is to the viewer along the view direction (larger is nearer).
[[nodiscard]] double view_depth(Vec3 p, const View3& view);
/// The box of the projections of `points`.
[[nodiscard]] Box2 projected_bounds(std::span<const Vec3> points, const View3& view);

/// How `SvgCanvas::mesh` draws.
struct MeshStyle {
  std::string colour = "#4c8dc9";  ///< the colour of a triangle facing the viewer
  std::string edge = "none";       ///< triangle edges ("none": no edges)
  double edge_width = 0.25;        ///< in pixels
  /// Past this many triangles (0: no limit) the ones facing away are left out first (hidden
  /// behind the front of a closed surface anyway), then every k-th of the rest is drawn; the
  /// picture is then a sketch, which `SvgCanvas::mesh` returns the count of.
  std::size_t max_triangles = 0;
};

class SvgCanvas {
 public:
  /// A canvas showing `world` (grown by 4% on each side) in a picture `width_px` wide. Any
  /// input gives a valid document with finite numbers: a width that is not at least 1 (NaN
  /// too) is 400, one above 10^6 is 10^6; a world box that is empty or not finite is the unit
  /// square; extents below 1e-200 (subnormal ones) are drawn 1e-200 wide; a box wider than the
  /// largest double is drawn in exact quarter units. A View3 angle that is not finite is the
  /// default view's.
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
  /// Draws a grid of `columns` x `rows` equal cells filling `area`, cell (i, j) (column i from
  /// area.min.x, row j from area.min.y) in colours[j * columns + i]; an empty colour leaves the
  /// cell blank. Runs of equal colours along a row become one rectangle, so a colour map with a
  /// few dozen levels stays small. Fewer colours than cells: the rest are blank.
  void cells(const Box2& area, int columns, int rows, std::span<const std::string> colours);
  /// Draws the triangles of `mesh` seen in `view` (the canvas's world box is in the projected
  /// plane: see `projected_bounds`), back to front (painter's order by the triangles' centroid
  /// depth), each shaded by how squarely it faces a light above left of the viewer (either side
  /// lit alike). Returns the number drawn.
  std::size_t mesh(const Mesh& mesh, const View3& view, const MeshStyle& style = {});
  /// Writes a caption at the top left, above the picture (squeezed to the picture's width
  /// where it would run over).
  void title(std::string_view text);
  /// Adds a legend entry (a swatch and its label) at the top right, in call order; the legend's
  /// box fits its longest label and stays inside the picture, which grows to hold it.
  void legend(std::string_view colour, std::string_view label);

  /// The whole SVG document.
  [[nodiscard]] std::string str() const;

 private:
  [[nodiscard]] Vec2 to_pixels(Vec2 world) const;

  Box2 world_;  // in units of unit_
  double unit_ = 1.0;
  double scale_ = 1.0;
  double width_ = 0.0;
  double height_ = 0.0;
  std::string body_;
  std::vector<std::pair<std::string, std::string>> legend_;
  std::string title_;
};

/// What `format_svg` and `format_svg` draw.
struct PictureOptions {
  double width_px = 400.0;
  std::string title;              ///< a caption at the top ("": none)
  View3 view{};                   ///< meshes only
  std::size_t max_triangles = 0;  ///< meshes only: see MeshStyle::max_triangles
};

/// A whole SVG document showing one region: filled under the even-odd rule of its rings (holes
/// show as holes), outlined, scaled to its bounding box. The notebook view of contain.Region.
[[nodiscard]] std::string format_svg(const MultiPolygon& region,
                                     const PictureOptions& options = {});

/// A whole SVG document showing one mesh in `options.view`, shaded (see `SvgCanvas::mesh`). The
/// notebook view of contain.Mesh.
[[nodiscard]] std::string format_svg(const Mesh& mesh, const PictureOptions& options = {});

}  // namespace contain::io
