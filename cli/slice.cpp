// contain slice: sections of a solid by planes, and its shadow (../shared/spec/cli.md).

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common.h"
#include "contain/clip/mesh_slicer.h"
#include "contain/clip/slice_mesh.h"
#include "contain/io/geojson.h"
#include "contain/io/mesh_io.h"
#include "contain/io/svg.h"
#include "contain/io/wkt.h"
#include "output_format.h"
#include "progress.h"
#include "slice_svg.h"
#include "timings.h"
#include "verbs.h"

namespace contain::cli {
namespace {

// More planes than this is a mistake (a step too small for the range), not a request.
constexpr double kMaxPlanes = 1e7;

struct SliceCliOptions {
  std::string mesh;
  std::vector<std::string> z;
  std::string layers;
  clip::Axis axis = clip::Axis::z;
  std::string format = "wkt";
  bool json = false;
  bool shadow = false;
  int threads = 0;
  bool quiet = false;
  std::string out;
  CLI::Option* format_option = nullptr;
  CLI::Option* threads_option = nullptr;
};

// FROM + k STEP for k = 0, 1, ..., each rounded once (one fma: k and STEP are exact), stopping
// before the first rounded value above TO.
Result<std::vector<double>> layer_values(const std::string& text) {
  auto numbers = parse_numbers(text, "--layers");
  if (!numbers) return numbers.error();
  if (numbers->size() != 3) {
    return Error{ErrorKind::usage, "--layers: FROM,STEP,TO (three numbers), got '" + text + "'"};
  }
  const double from = (*numbers)[0];
  const double step = (*numbers)[1];
  const double to = (*numbers)[2];
  if (!(step > 0)) {
    return Error{ErrorKind::invalid_value,
                 fmt::format("--layers: STEP must be positive, got {}", step)};
  }
  std::vector<double> out;
  if (to < from) {
    // The contract's rule gives no plane; say so rather than print nothing at all.
    warn(fmt::format("--layers: TO {} is below FROM {}: no planes", to, from));
    return out;
  }
  if ((to - from) / step >= kMaxPlanes) {
    return Error{ErrorKind::invalid_value,
                 fmt::format("--layers: {},{},{} gives more than 10^7 planes", from, step, to)};
  }
  for (double k = 0;; k += 1) {
    const double value = std::fma(k, step, from);
    if (value > to) break;
    if (out.size() >= static_cast<std::size_t>(kMaxPlanes)) {
      return Error{ErrorKind::invalid_value,
                   fmt::format("--layers: {},{},{} gives more than 10^7 planes", from, step, to)};
    }
    out.push_back(value);
  }
  return out;
}

Result<std::vector<double>> plane_values(const SliceCliOptions& o) {
  if (!o.layers.empty()) return layer_values(o.layers);
  std::vector<double> out;
  for (const std::string& text : o.z) {
    auto numbers = parse_numbers(text, "--z");
    if (!numbers) return numbers.error();
    if (numbers->size() != 1) {
      return Error{ErrorKind::usage, "--z: one number per --z, got '" + text + "'"};
    }
    out.push_back(numbers->front());
  }
  return out;
}

// The triangles of each ring as JSON arrays, appended to `out`.
void append_triangles_json(const clip::Section& s, std::string& out) {
  out += '[';
  for (std::size_t r = 0; r < s.triangles.size(); ++r) {
    out += r ? ",[" : "[";
    for (std::size_t k = 0; k < s.triangles[r].size(); ++k) {
      if (k > 0) out += ',';
      std::array<char, 16> digits{};
      out.append(
          digits.data(),
          std::to_chars(digits.data(), digits.data() + digits.size(), s.triangles[r][k]).ptr);
    }
    out += ']';
  }
  out += ']';
}

// The number of points of a block of sections, to size the next block.
std::size_t point_count(std::span<const clip::Section> sections) {
  std::size_t points = 0;
  for (const clip::Section& s : sections) {
    for (const auto& edges : s.triangles)
      points += edges.size();
  }
  return points;
}

// The text of sections in WKT lines, GeoJSON features or --json lines; `first` is the index of
// sections[0] among all (a GeoJSON feature after the first begins with a comma).
std::string format_sections(std::span<const clip::Section> sections, std::size_t first,
                            const SliceCliOptions& o) {
  std::string text;
  // About 42 characters a point in WKT (two shortest doubles of 17-20 characters, a space and a
  // comma): room for 48, so that the text is never copied to a larger buffer.
  text.reserve(48 * point_count(sections) + 96 * sections.size());
  const auto out = std::back_inserter(text);
  if (o.json) {
    for (const clip::Section& s : sections) {
      fmt::format_to(out, "{{\"value\":{},\"wkt\":\"", s.value);
      io::format_wkt(s.region, text);
      text += "\",\"triangles\":";
      append_triangles_json(s, text);
      text += "}\n";
    }
    return text;
  }
  if (o.format == "geojson") {
    for (std::size_t i = 0; i < sections.size(); ++i) {
      fmt::format_to(out, "{}{{\"type\":\"Feature\",\"properties\":{{\"value\":{}}},\"geometry\":",
                     first + i ? "," : "", sections[i].value);
      io::format_geojson(sections[i].region, text);
      text += '}';
    }
    return text;
  }
  for (const clip::Section& s : sections) {
    fmt::format_to(out, "{}\t", s.value);
    io::format_wkt(s.region, text);
    text += '\n';
  }
  return text;
}

// WKT, GeoJSON and --json text in blocks of planes: each block sliced and then formatted on
// every core, written in order and dropped, so that memory holds one block of sections and its
// text (about 2^19 points), not the whole stack. The first block is small (a quick first line
// and a first measure of the points per plane); the next ones aim at kBlockPoints points.
int stream_sections(const clip::MeshSlicer& slicer, const SliceCliOptions& o) {
  constexpr std::size_t kFirstBlock = 64;
  constexpr std::size_t kBlockPoints = std::size_t{1} << 19;
  constexpr std::size_t kMaxBlock = 4096;
  auto output = Output::open(o.out);
  if (!output) return report(output.error());
  const bool geojson = !o.json && o.format == "geojson";
  if (geojson) {
    if (Status w = output->write("{\"type\":\"FeatureCollection\",\"features\":["); !w)
      return report(w.error());
  }
  const BatchOptions batch{.threads = o.threads};
  Progress progress("planes", slicer.size(), !o.quiet && stderr_is_terminal());
  std::size_t block = kFirstBlock;
  for (std::size_t begin = 0; begin < slicer.size();) {
    const std::size_t end = std::min(slicer.size(), begin + block);
    const std::vector<clip::Section> sections = slicer.slice(begin, end, batch);
    const Status written = write_in_parallel_parts(
        *output, sections.size(), batch, 1, [&](std::size_t at, std::size_t size) {
          return format_sections(std::span(sections).subspan(at, size), begin + at, o);
        });
    if (!written) return report(written.error());
    const std::size_t per_plane = std::max<std::size_t>(1, point_count(sections) / sections.size());
    block = std::clamp<std::size_t>(kBlockPoints / per_plane, 1, kMaxBlock);
    begin = end;
    progress.update(end);
  }
  if (geojson) {
    if (Status w = output->write("]}\n"); !w) return report(w.error());
  }
  const Status closed = output->close();
  return closed ? exit_ok : report(closed.error());
}

std::string format_shadow(const MultiPolygon& region, const SliceCliOptions& o) {
  if (o.format == "geojson") return io::format_geojson(region) + "\n";
  if (o.format == "svg") {
    return io::format_svg(region, {.width_px = 800, .title = "contain slice --shadow " + o.mesh});
  }
  return io::format_wkt(region) + "\n";
}

int run_slice(SliceCliOptions o) {
  const bool planes = !o.z.empty() || !o.layers.empty();
  if (o.shadow && (planes || o.json || o.threads_option->count() > 0)) {
    return report(
        {ErrorKind::usage, "slice --shadow takes no planes (--z, --layers), --json or --threads"});
  }
  if (!o.shadow && !planes) {
    return report({ErrorKind::usage,
                   "slice needs planes: --z Z (repeatable) or --layers "
                   "FROM,STEP,TO, or --shadow"});
  }
  if (!o.z.empty() && !o.layers.empty()) {
    return report({ErrorKind::usage, "slice: --z and --layers exclude each other"});
  }
  if (o.json && o.format_option->count() > 0) {
    return report({ErrorKind::usage, "slice: --json writes its own lines; leave out --format"});
  }
  const bool json_file = std::filesystem::path(o.out).extension() == ".json";
  if (const auto named = region_format_named_by(o.out); o.json && named && !json_file) {
    return report({ErrorKind::usage,
                   "slice: --json writes JSON lines, but --out " + o.out + " names " + *named});
  }
  const auto format = region_output_format(*o.format_option, o.format, o.out, "slice");
  if (!format) return report(format.error());
  o.format = *format;
  auto values = plane_values(o);
  if (!values) return report(values.error());
  auto file = io::read_mesh(o.mesh);
  if (!file) return report(file.error());
  enter_phase(Phase::query);
  const auto named = [&](Error e) {
    e.source = o.mesh;
    return report(e);
  };
  if (o.shadow) {
    auto region = clip::shadow(file->mesh, {.axis = o.axis});
    if (!region) return named(region.error());
    return emit(format_shadow(*region, o), o.out);
  }
  auto slicer = clip::MeshSlicer::make(file->mesh, *values, {.axis = o.axis});
  if (!slicer) return named(slicer.error());
  if (o.format != "svg" || o.json) return stream_sections(*slicer, o);
  // The SVG draws the whole stack at once (its frame holds every section).
  const std::vector<clip::Section> sections =
      slicer->slice(0, slicer->size(), {.threads = o.threads});
  return emit(sections_svg(sections, 0.0,
                           fmt::format("contain slice {}: {} sections", o.mesh, sections.size())),
              o.out);
}

}  // namespace

Verb add_slice(CLI::App& app) {
  auto o = std::make_shared<SliceCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "slice",
      "Sections of a solid by planes as exact 2D regions, with the triangle under each "
      "edge; or its shadow");
  cmd->add_option("--mesh", o->mesh,
                  "the solid: a closed mesh (.obj .off .stl .ply), read by its winding number "
                  "(--shadow: any mesh)")
      ->required()
      ->option_text("FILE");
  cmd->add_option("--z", o->z, "a plane's value along --axis (repeatable, in the order given)")
      ->option_text("Z")
      ->allow_extra_args(false);
  cmd->add_option("--layers", o->layers,
                  "the planes FROM + k STEP (k = 0, 1, ...), each rounded once, up to TO")
      ->option_text("FROM,STEP,TO");
  const std::map<std::string, clip::Axis> axes{
      {"x", clip::Axis::x}, {"y", clip::Axis::y}, {"z", clip::Axis::z}};
  cmd->add_option("--axis", o->axis,
                  "the planes' normal (default z); coordinates (x,y) for z, (y,z) for x, (z,x) "
                  "for y")
      ->transform(CLI::CheckedTransformer(axes, CLI::ignore_case))
      ->option_text("x|y|z");
  o->format_option =
      cmd->add_option("--format", o->format,
                      "wkt: a line per plane, value TAB MULTIPOLYGON (default); geojson: a "
                      "FeatureCollection with `value`; svg: every section, a colour a level")
          ->check(CLI::IsMember({"wkt", "geojson", "svg"}, CLI::ignore_case))
          ->option_text("wkt|geojson|svg");
  cmd->add_flag("--json", o->json,
                "a JSON object a line: value, wkt, and the triangle under each edge of each ring");
  cmd->add_flag("--shadow", o->shadow,
                "the projection of the mesh along --axis (one MULTIPOLYGON: the union of its "
                "projected triangles, an open mesh's too) instead of sections");
  add_threads_option(*cmd, o->threads);
  o->threads_option = cmd->get_option("--threads");
  add_quiet_option(*cmd, o->quiet);
  cmd->add_option("--out", o->out, "write to FILE instead of stdout")->option_text("FILE");
  cmd->footer(
      "Examples:\n"
      "  contain slice --mesh part.stl --layers 0,0.2,30      (layers for printing)\n"
      "  contain slice --mesh part.stl --z 1.5 --z 2 --json  (with the triangle of each edge)\n"
      "  contain slice --mesh part.stl --shadow --axis z --format svg --out footprint.svg");
  return {cmd, [o]() { return run_slice(*o); }};
}

}  // namespace contain::cli
