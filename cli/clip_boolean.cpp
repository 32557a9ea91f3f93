// contain clip --subject A --clip B --op OP: the general polygon booleans.

#include "clip_boolean.h"

#include <map>
#include <string>
#include <vector>

#include "contain/io/geojson.h"
#include "contain/io/region_io.h"
#include "contain/io/svg.h"
#include "contain/io/wkt.h"
#include "output_format.h"
#include "timings.h"

namespace contain::cli {
namespace {

std::string svg_of(const MultiPolygon& subject, const MultiPolygon& clip,
                   const MultiPolygon& result) {
  const std::vector<Ring> a = subject.all_rings(), b = clip.all_rings(), r = result.all_rings();
  std::vector<Ring> all = a;
  all.insert(all.end(), b.begin(), b.end());
  io::SvgCanvas canvas(bounding_box(all), 800);
  canvas.title("contain clip: subject, clip and result");
  canvas.region(
      a, {.fill = "#1f77b4", .stroke = "#1f77b4", .stroke_width = 1.0, .fill_opacity = 0.15});
  canvas.region(
      b, {.fill = "#ff7f0e", .stroke = "#ff7f0e", .stroke_width = 1.0, .fill_opacity = 0.15});
  canvas.region(r,
                {.fill = "#2ca02c", .stroke = "#145214", .stroke_width = 2.0, .fill_opacity = 0.5});
  canvas.legend("#1f77b4", "subject");
  canvas.legend("#ff7f0e", "clip");
  canvas.legend("#2ca02c", "result");
  return canvas.str();
}

}  // namespace

void add_clip_boolean_options(CLI::App& cmd, ClipBooleanOptions& o) {
  auto* subject = cmd.add_option("--subject", o.subject,
                                 "subject of a boolean: a region (.wkt or .geojson) or a solid "
                                 "(a mesh: .obj .off .stl .ply)")
                      ->option_text("FILE");
  auto* clip = cmd.add_option("--clip", o.clips,
                              "clip of a boolean: a region, or a mesh (repeatable for meshes)")
                   ->option_text("FILE");
  const std::map<std::string, clip::Op> ops{{"intersection", clip::Op::intersection},
                                            {"union", clip::Op::union_},
                                            {"difference", clip::Op::difference},
                                            {"xor", clip::Op::xor_}};
  auto* op = cmd.add_option("--op", o.op, "the boolean: subject op clip")
                 ->transform(CLI::CheckedTransformer(ops, CLI::ignore_case))
                 ->option_text("intersection|union|difference|xor");
  subject->needs(op);
  clip->needs(subject);
  o.op_option = op;
  cmd.add_option("shapes", o.shapes,
                 "A B: the subject and the clip of a polygon boolean, as 'clip A B --op OP' "
                 "(the same as --subject A --clip B)")
      ->option_text("A B");
  add_fill_option(cmd, o.fill);
  o.fill_option = cmd.get_option("--fill");
  o.format_option =
      cmd.add_option("--format", o.format, "output of a boolean: wkt (default), geojson or svg")
          ->check(CLI::IsMember({"wkt", "geojson", "svg"}, CLI::ignore_case))
          ->option_text("wkt|geojson|svg");
}

bool clip_boolean_requested(const ClipBooleanOptions& o) {
  return !o.subject.empty() || !o.shapes.empty() || o.op_option->count() > 0;
}

int run_clip_boolean(const ClipBooleanOptions& given, const std::string& out) {
  ClipBooleanOptions o = given;
  if (!o.shapes.empty()) {
    if (!o.subject.empty()) {
      return report(
          {ErrorKind::usage, "clip: give the shapes as A B or as --subject A --clip B, not both"});
    }
    if (o.shapes.size() != 2) {
      return report({ErrorKind::usage,
                     "clip A B --op OP: two shapes, got " + std::to_string(o.shapes.size())});
    }
    if (o.op_option->count() == 0) {
      return report({ErrorKind::usage, "clip A B needs --op intersection|union|difference|xor"});
    }
    o.subject = o.shapes[0];
    o.clips = {o.shapes[1]};
  }
  if (o.subject.empty()) {
    return report({ErrorKind::usage,
                   "clip: --op needs the shapes: 'clip A B --op OP' or --subject A --clip B"});
  }
  if (o.clips.size() != 1) {
    return report({ErrorKind::usage, "clip: a polygon boolean takes one --clip region, got " +
                                         std::to_string(o.clips.size())});
  }
  const auto chosen = region_output_format(*o.format_option, o.format, out, "clip");
  if (!chosen) return report(chosen.error());
  const std::string& format = *chosen;
  auto subject = read_region_warned(o.subject);
  if (!subject) return report(subject.error());
  auto clip_region = read_region_warned(o.clips[0]);
  if (!clip_region) return report(clip_region.error());
  enter_phase(Phase::query);
  const MultiPolygon result =
      clip::polygon_boolean(*subject, *clip_region, {.op = o.op, .fill = o.fill});
  std::string text;
  if (format == "geojson") {
    text = result.polygons.size() == 1 ? io::format_geojson(result.polygons[0])
                                       : io::format_geojson(result);
  } else if (format == "svg") {
    text = svg_of(*subject, *clip_region, result);
  } else {
    text =
        result.polygons.size() == 1 ? io::format_wkt(result.polygons[0]) : io::format_wkt(result);
  }
  text += '\n';
  return emit(text, out);
}

}  // namespace contain::cli
