// contain clip: segments (Cohen-Sutherland, Liang-Barsky, Cyrus-Beck, balls), polygons and
// meshes by half-spaces (Sutherland-Hodgman). One function per form of the contract; the
// polygon booleans (--subject/--clip/--op) slot in beside them.

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "clip_boolean.h"
#include "clip_solid.h"
#include "common.h"
#include "contain/clip/box_clipper.h"
#include "contain/clip/clip_polygon.h"
#include "contain/clip/mesh_clip.h"
#include "contain/clip/segment_region.h"
#include "contain/io/geojson.h"
#include "contain/io/mesh_io.h"
#include "contain/io/number_table.h"
#include "contain/io/region_io.h"
#include "contain/io/svg.h"
#include "contain/io/wkt.h"
#include "contain/shapes/convex_polyhedron.h"
#include "contain/shapes/mesh_validation.h"
#include "output_format.h"
#include "progress.h"
#include "timings.h"
#include "verbs.h"

namespace contain::cli {
namespace {

struct ClipOptions {
  // Segments, polygons and meshes by half-spaces.
  std::string segments;
  std::string polygon;
  std::string mesh;
  std::string box;
  std::vector<std::string> halfspaces;
  std::string convex;
  std::string sphere;
  std::string circle;
  std::string algorithm;
  bool keep_bridges = false;
  std::string tiles;
  bool cap = false;
  std::string out;
  int threads = 0;
  bool quiet = false;
};

Error usage(std::string message) {
  return {ErrorKind::usage, "clip: " + std::move(message)};
}

// The numbers of a list-valued option, exactly `count` of them (one of `counts`).
Result<std::vector<double>> numbers(const std::string& text, const char* option,
                                    std::initializer_list<std::size_t> counts) {
  auto values = parse_numbers(text, option);
  if (!values) return values.error();
  for (std::size_t c : counts) {
    if (values->size() == c) return values;
  }
  std::string want;
  for (std::size_t c : counts)
    want += (want.empty() ? "" : " or ") + std::to_string(c);
  return usage(std::string(option) + " takes " + want + " numbers here, got " +
               std::to_string(values->size()));
}

Result<std::vector<Plane>> planes_of(const ClipOptions& o) {
  std::vector<Plane> planes;
  for (const std::string& h : o.halfspaces) {
    auto v = numbers(h, "--halfspace", {4});
    if (!v) return v.error();
    planes.push_back({(*v)[0], (*v)[1], (*v)[2], (*v)[3]});
  }
  return planes;
}

Result<std::vector<HalfPlane>> half_planes_of(const ClipOptions& o) {
  std::vector<HalfPlane> planes;
  for (const std::string& h : o.halfspaces) {
    auto v = numbers(h, "--halfspace", {3});
    if (!v) return v.error();
    planes.push_back({(*v)[0], (*v)[1], (*v)[2]});
  }
  return planes;
}

// A box whose min corner lies above its max corner is a mistake, not an empty region: exit 3.
Status check_corners(const std::string& text, const std::vector<double>& v) {
  const std::size_t d = v.size() / 2;
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  for (std::size_t i = 0; i < d; ++i) {
    if (v[i] > v[d + i]) {
      return Error{ErrorKind::invalid_value,
                   fmt::format("clip: --box {}: the min corner is above the max corner in {} "
                               "({} > {}); give the min corner first",
                               text, kAxis[i], v[i], v[d + i])};
    }
  }
  return Ok{};
}

Result<Box3> box3_of(const std::string& text) {
  auto v = numbers(text, "--box", {6});
  if (!v) return v.error();
  if (auto s = check_corners(text, *v); !s) return s.error();
  return Box3{{(*v)[0], (*v)[1], (*v)[2]}, {(*v)[3], (*v)[4], (*v)[5]}};
}

Result<Box2> box2_of(const std::string& text) {
  auto v = numbers(text, "--box", {4});
  if (!v) return v.error();
  if (auto s = check_corners(text, *v); !s) return s.error();
  return Box2{{(*v)[0], (*v)[1]}, {(*v)[2], (*v)[3]}};
}

// A ball or disc of negative radius is a mistake (it was read as its absolute value): exit 3.
Status check_radius(const char* option, const std::string& text, double radius) {
  if (radius >= 0) return Ok{};
  return Error{ErrorKind::invalid_value,
               fmt::format("clip: {} {}: the radius is negative ({})", option, text, radius)};
}

// --convex in 2D: the shell of the first polygon of a region file.
Result<Ring> convex_ring_of(const std::string& path) {
  auto region = read_region_warned(path);
  if (!region) return region.error();
  if (region->polygons.empty() || region->polygons.front().rings.empty()) {
    return Error{ErrorKind::degenerate, "the convex polygon is empty", path};
  }
  return region->polygons.front().rings.front();
}

// --convex in 3D: a closed convex mesh.
Result<ConvexPolyhedron> convex_solid_of(const std::string& path) {
  auto file = io::read_mesh(path);
  if (!file) return file.error();
  auto solid = ConvexPolyhedron::from_mesh(file->mesh);
  if (!solid) {
    Error e = solid.error();
    if (e.source.empty()) e.source = path;
    return e;
  }
  return solid;
}

// --- segments ------------------------------------------------------------------------------

std::string format_segments(int columns, std::span<const Segment2> out2,
                            std::span<const Segment3> out3, std::span<const std::uint8_t> kept) {
  std::string text;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (!kept[i]) {
      text += "-\n";
    } else if (columns == 4) {
      const Segment2& s = out2[i];
      text += fmt::format("{} {} {} {}\n", s.a.x, s.a.y, s.b.x, s.b.y);
    } else {
      const Segment3& s = out3[i];
      text += fmt::format("{} {} {} {} {} {}\n", s.a.x, s.a.y, s.a.z, s.b.x, s.b.y, s.b.z);
    }
  }
  return text;
}

// The rows of a table of 4 (2D) or 6 (3D) numbers as segments.
std::vector<Segment2> segments2_of(const io::NumberTable& table) {
  std::vector<Segment2> segments(table.rows());
  const double* v = table.values.data();
  for (Segment2& s : segments) {
    s = {{v[0], v[1]}, {v[2], v[3]}};
    v += 4;
  }
  return segments;
}
std::vector<Segment3> segments3_of(const io::NumberTable& table) {
  std::vector<Segment3> segments(table.rows());
  const double* v = table.values.data();
  for (Segment3& s : segments) {
    s = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    v += 6;
  }
  return segments;
}

// The one region option given, for 2D segments.
Result<clip::SegmentRegion2> region2_of(const ClipOptions& o) {
  if (!o.box.empty()) {
    auto box = box2_of(o.box);
    if (!box) return box.error();
    return clip::SegmentRegion2(*box);
  }
  if (!o.halfspaces.empty()) {
    auto planes = half_planes_of(o);
    if (!planes) return planes.error();
    return clip::SegmentRegion2(std::move(*planes));
  }
  if (!o.convex.empty()) {
    auto ring = convex_ring_of(o.convex);
    if (!ring) return ring.error();
    return clip::SegmentRegion2(std::move(*ring));
  }
  auto c = numbers(o.circle, "--circle", {3});
  if (!c) return c.error();
  if (auto r = check_radius("--circle", o.circle, (*c)[2]); !r) return r.error();
  return clip::SegmentRegion2(Circle{{(*c)[0], (*c)[1]}, (*c)[2]});
}

// The one region option given, for 3D segments.
Result<clip::SegmentRegion3> region3_of(const ClipOptions& o) {
  if (!o.box.empty()) {
    auto box = box3_of(o.box);
    if (!box) return box.error();
    return clip::SegmentRegion3(*box);
  }
  if (!o.halfspaces.empty()) {
    auto planes = planes_of(o);
    if (!planes) return planes.error();
    return clip::SegmentRegion3(std::move(*planes));
  }
  if (!o.convex.empty()) {
    auto solid = convex_solid_of(o.convex);
    if (!solid) return solid.error();
    return clip::SegmentRegion3(std::move(*solid));
  }
  auto s = numbers(o.sphere, "--sphere", {4});
  if (!s) return s.error();
  if (auto r = check_radius("--sphere", o.sphere, (*s)[3]); !r) return r.error();
  return clip::SegmentRegion3(Sphere{{(*s)[0], (*s)[1], (*s)[2]}, (*s)[3]});
}

clip::SegmentClipper clipper_of(const std::string& algorithm) {
  if (algorithm == "cohen-sutherland") return clip::SegmentClipper::cohen_sutherland;
  if (algorithm == "liang-barsky") return clip::SegmentClipper::liang_barsky;
  if (algorithm == "cyrus-beck") return clip::SegmentClipper::cyrus_beck;
  return clip::SegmentClipper::automatic;
}

// Clips the segments by the region in chunks, with progress after each (one library call per
// chunk, on all threads).
template <class S, class Region>
Status clip_all(const std::vector<S>& in, const Region& region, std::vector<S>& out,
                std::span<std::uint8_t> kept, const ClipOptions& o) {
  const clip::SegmentClipOptions options{.clipper = clipper_of(o.algorithm)};
  Status status = Ok{};
  Progress progress("segments", in.size(), !o.quiet && stderr_is_terminal());
  progress.run([&](std::size_t begin, std::size_t end) {
    if (!status) return;
    status = clip::clip_segments(std::span<const S>(in).subspan(begin, end - begin), region,
                                 std::span<S>(out).subspan(begin, end - begin),
                                 kept.subspan(begin, end - begin), options, {.threads = o.threads});
  });
  return status;
}

int run_segments(const ClipOptions& o) {
  const int regions = !o.box.empty() + !o.halfspaces.empty() + !o.convex.empty() +
                      !o.sphere.empty() + !o.circle.empty();
  if (regions != 1) {
    return report(
        usage("--segments needs one region: --box, --halfspace, --convex, --sphere or "
              "--circle"));
  }
  if (!o.algorithm.empty() && o.box.empty() && o.algorithm != "cyrus-beck") {
    return report(usage("--algorithm " + o.algorithm + " clips by a --box only"));
  }
  auto table = io::read_number_table(o.segments, {.columns = {4, 6}});
  if (!table) return report(table.error());
  enter_phase(Phase::query);
  const int columns =
      table->columns == 0 ? (o.sphere.empty() && o.halfspaces.empty() ? 4 : 6) : table->columns;
  const bool three_d = columns == 6;
  if ((three_d && !o.circle.empty()) || (!three_d && !o.sphere.empty())) {
    return report({ErrorKind::invalid_value,
                   three_d ? "segments have 6 numbers (3D) but --circle is 2D"
                           : "segments have 4 numbers (2D) but --sphere is 3D",
                   o.segments == "-" ? "<stdin>" : o.segments});
  }
  std::vector<std::uint8_t> kept(table->rows());
  std::vector<Segment2> out2;
  std::vector<Segment3> out3;
  if (three_d) {
    const std::vector<Segment3> in = segments3_of(*table);
    out3.resize(in.size());
    auto region = region3_of(o);
    if (!region) return report(region.error());
    if (Status s = clip_all(in, *region, out3, kept, o); !s) return report(s.error());
  } else {
    const std::vector<Segment2> in = segments2_of(*table);
    out2.resize(in.size());
    auto region = region2_of(o);
    if (!region) return report(region.error());
    if (Status s = clip_all(in, *region, out2, kept, o); !s) return report(s.error());
  }
  return emit(format_segments(columns, out2, out3, kept), o.out);
}

// --- polygons --------------------------------------------------------------------------------

std::string polygon_wkt(const MultiPolygon& result) {
  if (result.polygons.empty()) return "POLYGON EMPTY\n";
  if (result.polygons.size() == 1) return io::format_wkt(result.polygons.front()) + "\n";
  return io::format_wkt(result) + "\n";
}

// Where --tiles writes: one stream of lines "COLUMN ROW WKT", or with a pattern in --out one file
// a tile, in the format its extension names.
struct TileOutput {
  bool per_file = false;
  std::string pattern;
  std::optional<io::RegionFormat> format;  // per file
  bool svg = false;                        // per file
};

// The --out of --tiles: a pattern must name {column} and {row} and nothing else in braces, and
// its extension a region format (.wkt, .geojson/.json) or .svg; one file of all tiles holds
// lines of WKT, so an extension naming another format is refused (issue 24: tiles.geojson held
// WKT).
Result<TileOutput> tile_output(const std::string& out) {
  TileOutput t;
  t.pattern = out;
  t.per_file = out.find('{') != std::string::npos || out.find('}') != std::string::npos;
  const std::string ext = std::filesystem::path(out).extension().string();
  std::string lower;
  for (char c : ext)
    lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!t.per_file) {
    if (io::region_format(out) == io::RegionFormat::geojson || lower == ".svg") {
      return usage("--tiles --out " + out +
                   ": one file of every tile holds lines 'COLUMN ROW WKT', not " + lower +
                   "; write one file a tile with a pattern such as 'tiles/{column}_{row}" + lower +
                   "'");
    }
    return t;
  }
  bool column = false, row = false;
  for (std::size_t at = 0; at < out.size();) {
    const std::size_t open = out.find_first_of("{}", at);
    if (open == std::string::npos) break;
    const std::size_t close = out[open] == '{' ? out.find('}', open) : std::string::npos;
    if (close == std::string::npos) {
      return usage("--tiles --out " + out + ": an unmatched brace; the pattern's fields are " +
                   "{column} and {row}");
    }
    const std::string field = out.substr(open, close - open + 1);
    if (field == "{column}") {
      column = true;
    } else if (field == "{row}") {
      row = true;
    } else {
      return usage("--tiles --out " + out + ": unknown field " + field +
                   " (the fields are {column} and {row})");
    }
    at = close + 1;
  }
  if (!column || !row) {
    return usage("--tiles --out " + out + ": the pattern must name both {column} and {row}, " +
                 "or every tile would go to the same file");
  }
  t.format = io::region_format(out);
  t.svg = lower == ".svg";
  if (!t.format && !t.svg) {
    return usage("--tiles --out " + out + ": the extension '" + lower +
                 "' names no format of a tile: use .wkt, .geojson or .svg");
  }
  return t;
}

std::string tile_file_text(const MultiPolygon& tile, const TileOutput& output) {
  if (output.svg) return io::format_svg(tile);
  if (output.format == io::RegionFormat::geojson) {
    return (tile.polygons.size() == 1 ? io::format_geojson(tile.polygons.front())
                                      : io::format_geojson(tile)) +
           "\n";
  }
  return polygon_wkt(tile);
}

std::string tile_path(std::string path, int column, int row) {
  for (const auto& [key, value] : {std::pair<std::string, int>{"{column}", column},
                                   std::pair<std::string, int>{"{row}", row}}) {
    for (std::size_t at = path.find(key); at != std::string::npos; at = path.find(key))
      path.replace(at, key.size(), std::to_string(value));
  }
  return path;
}

// --tiles NX,NY: the region cut into a grid over --box (or its bounding box), one result per
// tile: lines "COLUMN ROW WKT", or one file per tile when --out holds {column} and {row}. The
// tiles are cut and written a band at a time, so a grid of millions of tiles is never held
// whole.
int run_tiles(const ClipOptions& o) {
  if (!o.halfspaces.empty() || !o.convex.empty() || o.keep_bridges) {
    return report(
        usage("--tiles cuts by a grid of boxes: it takes --box (the grid's bounds), "
              "not --halfspace, --convex or --keep-bridges"));
  }
  auto counts = numbers(o.tiles, "--tiles", {2});
  if (!counts) return report(counts.error());
  const double nx = (*counts)[0], ny = (*counts)[1];
  if (!(nx >= 1 && ny >= 1 && nx == std::floor(nx) && ny == std::floor(ny) && nx * ny <= 1 << 24)) {
    return report({ErrorKind::invalid_value,
                   "clip: --tiles " + o.tiles +
                       ": give two whole numbers of columns and rows, each at least 1, at most "
                       "16,777,216 tiles in all"});
  }
  auto output = tile_output(o.out);
  if (!output) return report(output.error());
  auto region = read_region_warned(o.polygon);
  if (!region) return report(region.error());
  enter_phase(Phase::query);
  clip::TileGrid grid{.columns = static_cast<int>(nx), .rows = static_cast<int>(ny)};
  if (!o.box.empty()) {
    auto box = box2_of(o.box);
    if (!box) return report(box.error());
    grid.bounds = *box;
  } else {
    grid.bounds = bounding_box(region->all_rings());
    if (grid.bounds.empty()) {
      return report({ErrorKind::degenerate,
                     "the region is empty: give the grid's bounds with --box", o.polygon});
    }
  }
  const clip::BoxClipper clipper(std::move(*region));
  const std::size_t total = static_cast<std::size_t>(grid.columns) * grid.rows;
  // A band of whole rows, at least 4096 tiles: enough work for every thread between writes.
  const std::size_t band =
      std::max<std::size_t>(1, 4096 / static_cast<std::size_t>(grid.columns)) * grid.columns;
  std::ofstream file;
  const bool to_stdout = output->per_file || o.out.empty() || o.out == "-";
  if (!to_stdout) {
    file.open(o.out, std::ios::binary);
    if (!file) return report({ErrorKind::io, "cannot open for writing", o.out});
  }
  Progress progress("tiles", total, !o.quiet && stderr_is_terminal());
  for (std::size_t first = 0; first < total; first += band) {
    const std::vector<MultiPolygon> tiles =
        clip::tile_range(clipper, grid, first, band, {.threads = o.threads});
    std::string lines;
    for (std::size_t k = 0; k < tiles.size(); ++k) {
      const int column = static_cast<int>((first + k) % grid.columns);
      const int row = static_cast<int>((first + k) / grid.columns);
      if (output->per_file) {
        const Status written =
            write_output(tile_file_text(tiles[k], *output), tile_path(o.out, column, row));
        if (!written) return report(written.error());
      } else {
        lines += fmt::format("{} {} {}", column, row, polygon_wkt(tiles[k]));
      }
    }
    if (to_stdout) {
      if (!output->per_file) std::fwrite(lines.data(), 1, lines.size(), stdout);
    } else if (!file.write(lines.data(), static_cast<std::streamsize>(lines.size()))) {
      return report({ErrorKind::io, "write failed", o.out});
    }
    progress.update(first + tiles.size());
  }
  std::fflush(stdout);
  return exit_ok;
}

int run_polygon(const ClipOptions& o) {
  if (!o.tiles.empty()) return run_tiles(o);
  const int regions = !o.box.empty() + !o.halfspaces.empty() + !o.convex.empty();
  if (regions != 1) {
    return report(usage("--polygon needs one region: --halfspace (repeatable), --box or --convex"));
  }
  auto region = read_region_warned(o.polygon);
  if (!region) return report(region.error());
  enter_phase(Phase::query);
  const clip::PolygonClipOptions options{.output = o.keep_bridges
                                                       ? clip::PolygonClipOutput::bridged
                                                       : clip::PolygonClipOutput::pieces};
  MultiPolygon result;
  if (!o.box.empty()) {
    auto box = box2_of(o.box);
    if (!box) return report(box.error());
    result = clip::clip_polygon(*region, *box, options);
  } else if (!o.halfspaces.empty()) {
    auto planes = half_planes_of(o);
    if (!planes) return report(planes.error());
    result = clip::clip_polygon(*region, *planes, options);
  } else {
    auto ring = convex_ring_of(o.convex);
    if (!ring) return report(ring.error());
    result = clip::clip_polygon(*region, *ring, options);
  }
  // WKT, unless --out's extension names GeoJSON or SVG (never WKT in a file named otherwise).
  const std::string format = region_format_named_by(o.out).value_or("wkt");
  if (format == "svg") return emit(io::format_svg(result), o.out);
  if (format == "geojson") {
    return emit((result.polygons.size() == 1 ? io::format_geojson(result.polygons.front())
                                             : io::format_geojson(result)) +
                    "\n",
                o.out);
  }
  return emit(polygon_wkt(result), o.out);
}

// --- meshes ----------------------------------------------------------------------------------

int run_mesh(const ClipOptions& o) {
  const int regions = !o.box.empty() + !o.halfspaces.empty() + !o.convex.empty();
  if (regions != 1) {
    return report(usage("--mesh needs one region: --halfspace (repeatable), --box or --convex"));
  }
  std::optional<io::MeshFormat> format = io::MeshFormat::off;
  if (!o.out.empty() && o.out != "-") {
    format = io::mesh_format_for_path(o.out);
    if (!format) return report(usage("--out " + o.out + ": unknown mesh extension"));
  }
  auto file = io::read_mesh(o.mesh);
  if (!file) return report(file.error());
  enter_phase(Phase::query);
  const clip::MeshClipOptions options{.cut = o.cap ? clip::MeshCut::cap : clip::MeshCut::open};
  if (o.cap && !validate_mesh(file->mesh).closed()) {
    return report(
        {ErrorKind::invalid_value, "--cap needs a closed mesh; this one has border edges", o.mesh});
  }
  Mesh result;
  if (!o.box.empty()) {
    auto box = box3_of(o.box);
    if (!box) return report(box.error());
    result = clip::clip_mesh(file->mesh, *box, options);
  } else if (!o.halfspaces.empty()) {
    auto planes = planes_of(o);
    if (!planes) return report(planes.error());
    result = clip::clip_mesh(file->mesh, *planes, options);
  } else {
    auto solid = convex_solid_of(o.convex);
    if (!solid) return report(solid.error());
    result = clip::clip_mesh(file->mesh, *solid, options);
  }
  return emit_mesh(result, o.out);
}

// The options of one form that another would silently drop (issue 24): a usage error naming
// them and the form.
Status refuse_ignored(const ClipOptions& o, bool segments, bool polygon) {
  const char* form = segments ? "--segments" : polygon ? "--polygon" : "--mesh";
  std::vector<std::string> dropped;
  const auto drop = [&](bool given, const char* option) {
    if (given) dropped.emplace_back(option);
  };
  drop(!segments && !o.algorithm.empty(), "--algorithm");
  drop(!segments && !o.sphere.empty(), "--sphere");
  drop(!segments && !o.circle.empty(), "--circle");
  drop(!polygon && o.keep_bridges, "--keep-bridges");
  drop(!polygon && !o.tiles.empty(), "--tiles");
  drop(polygon || segments ? o.cap : false, "--cap");
  if (dropped.empty()) return Ok{};
  std::string names;
  for (const std::string& d : dropped)
    names += (names.empty() ? "" : ", ") + d;
  return usage(names + " does not apply to " + form);
}

}  // namespace

Verb add_clip(CLI::App& app) {
  auto o = std::make_shared<ClipOptions>();
  CLI::App* cmd = app.add_subcommand(
      "clip",
      "Clipping: segments by boxes, half-spaces, convex regions and balls; polygons and meshes by "
      "half-spaces, boxes or convex shapes; polygons cut into tiles (--tiles); booleans of "
      "polygons "
      "and of solids (A B --op, n-ary with --clip repeated, a solid repaired with --op union), CSG "
      "trees evaluated to one mesh (--csg)");
  auto* segments = cmd->add_option("--segments", o->segments,
                                   "segments, one a line: 4 numbers (2D) or 6 (3D); '-': stdin")
                       ->option_text("FILE");
  auto* polygon = cmd->add_option("--polygon", o->polygon,
                                  "2D region (.wkt or .geojson) clipped by half-planes")
                      ->option_text("FILE");
  auto* mesh = cmd->add_option("--mesh", o->mesh,
                               "mesh (.obj .off .stl .ply) clipped by "
                               "half-spaces")
                   ->option_text("FILE");
  segments->excludes(polygon)->excludes(mesh);
  polygon->excludes(segments)->excludes(mesh);
  mesh->excludes(segments)->excludes(polygon);
  cmd->add_option("--box", o->box, "the box: min corner then max corner (4 or 6 numbers)")
      ->option_text("MIN..,MAX..");
  cmd->add_option("--halfspace", o->halfspaces,
                  "a x + b y + c z + d >= 0 (2D: a x + b y + c >= 0); repeatable")
      ->option_text("a,b,c[,d]");
  cmd->add_option("--convex", o->convex,
                  "convex region: a convex polygon (.wkt) in 2D, a closed convex mesh in 3D")
      ->option_text("FILE");
  cmd->add_option("--sphere", o->sphere, "ball for 3D segments")->option_text("cx,cy,cz,r");
  cmd->add_option("--circle", o->circle, "disc for 2D segments")->option_text("cx,cy,r");
  cmd->add_option("--algorithm", o->algorithm,
                  "segment clipper for --box (default: the "
                  "branch-free batch kernel, exact decisions)")
      ->check(CLI::IsMember({"cohen-sutherland", "liang-barsky", "cyrus-beck"}));
  cmd->add_option("--tiles", o->tiles,
                  "polygons: cut into a grid of NX x NY boxes over --box (default: the region's "
                  "bounding box), on all cores; one line 'COLUMN ROW WKT' per tile (row 0 at min "
                  "y), or one file per tile when --out holds {column} and {row}, in the format "
                  "of its extension (.wkt, .geojson, .svg)")
      ->option_text("NX,NY");
  cmd->add_flag("--keep-bridges", o->keep_bridges,
                "polygons: the section's one ring per input ring, with degenerate bridging edges");
  cmd->add_flag("--cap", o->cap, "meshes: close the cut of a closed mesh with cap polygons");
  auto boolean = std::make_shared<ClipBooleanOptions>();  // --subject/--clip/--op: clip_boolean.cpp
  add_clip_boolean_options(*cmd, *boolean);
  auto solid = std::make_shared<ClipSolidOptions>();  // meshes as solids: clip_solid.cpp
  add_clip_solid_options(*cmd, *solid);
  add_threads_option(*cmd, o->threads);
  add_quiet_option(*cmd, o->quiet);
  cmd->add_option("--out", o->out, "write the result to FILE (meshes: format by extension)")
      ->option_text("FILE");
  cmd->footer(
      "Examples:\n"
      "  contain clip --segments lines.txt --box 0,0,0,1,1,1 --algorithm liang-barsky\n"
      "  contain clip --segments lines2d.txt --circle 0,0,1\n"
      "  contain clip --polygon parcels.wkt --box 0,0,100,100\n"
      "  contain clip --polygon country.wkt --tiles 16,16 --out 'tiles/{column}_{row}.wkt'\n"
      "  contain clip --mesh bunny.obj --halfspace=0,0,1,-0.5 --cap --out top.ply\n"
      "  contain clip --segments rays.txt --sphere 0,0,0,1\n"
      "  contain clip --polygon field.wkt --convex hull.wkt --out inside.wkt\n"
      "  contain clip a.wkt b.geojson --op union --format geojson\n"
      "  contain clip --subject a.wkt --clip b.wkt --op difference --fill nonzero --format svg\n"
      "  contain clip --subject part.stl --clip hole.off --clip slot.off --op difference "
      "--out part.obj\n"
      "  contain clip --csg bracket.json --out bracket.obj --json\n"
      "Segments print their clipped endpoints, or '-' where nothing is left; a segment that only "
      "touches the region prints a zero-length segment.");
  return {cmd, [o, boolean, solid, segments, polygon, mesh]() {
            const bool by_region = segments->count() + polygon->count() + mesh->count() > 0 ||
                                   !o->box.empty() || !o->halfspaces.empty() ||
                                   !o->convex.empty() || !o->sphere.empty() || !o->circle.empty() ||
                                   !o->tiles.empty() || o->cap || o->keep_bridges ||
                                   !o->algorithm.empty();
            const bool solids = clip_solid_requested(*boolean, *solid);
            if (by_region && (solids || clip_boolean_requested(*boolean))) {
              return report(usage(
                  "a boolean (--op, --csg) takes its shapes only: --segments, --polygon, --mesh, "
                  "--box, --halfspace, --convex, --sphere, --circle, --tiles, --cap, "
                  "--keep-bridges and --algorithm belong to the other forms"));
            }
            if (solids) return run_clip_solid(*boolean, *solid, o->out);
            if (solid->json) {
              return report(usage("--json applies to mesh booleans (a mesh --subject, --csg)"));
            }
            if (clip_boolean_requested(*boolean)) return run_clip_boolean(*boolean, o->out);
            // Options of the booleans that the other forms would silently drop.
            for (const CLI::Option* ignored : {boolean->format_option, boolean->fill_option}) {
              if (ignored->count() > 0) {
                return report(usage(ignored->get_name() +
                                    " applies to polygon booleans (--op) only; --tiles and "
                                    "--polygon write WKT, or the format --out's extension "
                                    "names"));
              }
            }
            if (Status s = refuse_ignored(*o, segments->count() > 0, polygon->count() > 0); !s) {
              return report(s.error());
            }
            if (segments->count() > 0) return run_segments(*o);
            if (polygon->count() > 0) return run_polygon(*o);
            if (mesh->count() > 0) return run_mesh(*o);
            return report(usage("give what to clip: --segments, --polygon or --mesh"));
          }};
}

}  // namespace contain::cli
