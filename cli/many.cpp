// Many shapes at once: which regions or solids hold each point, which solids meet.

#include "many.h"

#include <fmt/format.h>

#include <span>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "contain/collide/mesh_scene.h"
#include "contain/inside/region_layer.h"
#include "contain/inside/solid_scene.h"
#include "contain/io/layer_io.h"
#include "contain/io/mesh_warning.h"
#include "contain/io/points_io.h"
#include "contain/io/scene_json.h"
#include "progress.h"
#include "timings.h"

namespace contain::cli {
namespace {

// An id as a JSON string body: quotes, backslashes and control characters escaped.
std::string json_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += fmt::format("\\u{:04x}", static_cast<int>(c));
    } else {
      out += c;
    }
  }
  return out;
}

// Appends one line per point of `table`: the ids of its holders under `policy`.
void append_lines(std::string& out, const inside::HolderTable& table,
                  const std::vector<std::string>& ids, BoundaryPolicy policy) {
  for (std::size_t i = 0; i < table.points(); ++i) {
    bool any = false;
    for (const inside::Holder& h : table.of(i)) {
      const bool on = h.location == Location::boundary;
      if (on && policy == BoundaryPolicy::as_outside) continue;
      if (any) out += ' ';
      any = true;
      out += ids[static_cast<std::size_t>(h.shape)];
      if (on && policy == BoundaryPolicy::report) out += ":on";
    }
    if (!any) out += '-';
    out += '\n';
  }
}

// Reads the points a piece at a time (2^20 lines), locates each piece and appends its lines:
// memory is the point file's text and one piece, not every point and its holders at once.
// Nothing is written before the whole file has been read, so a bad line late in the file still
// gives exit 3 and no output.
template <class Point, class Locator, class Read>
Result<std::string> locate_lines(const Locator& locator, const std::vector<std::string>& ids,
                                 const ManyOptions& o, Read&& read) {
  std::string text;
  std::size_t done = 0;
  Progress progress("points", 0, !o.quiet && stderr_is_terminal());
  const Status status = read(
      o.points, io::ChunkedReading{.threads = o.threads},
      [&](std::span<const Point> points, double share) {
        enter_phase(Phase::query);
        append_lines(text, locator.locate(points, {.threads = o.threads}), ids, o.boundary);
        // Room for all the lines, estimated from the first piece: the string then does not
        // copy itself as it grows.
        if (done == 0 && share > 0.0 && share < 1.0) {
          text.reserve(static_cast<std::size_t>(1.1 * static_cast<double>(text.size()) / share));
        }
        done += points.size();
        progress.update_share(share, done);
        enter_phase(Phase::read);
      });
  if (!status) return status.error();
  return text;
}

// Which ids an output can tell apart, and what the user can do about one it cannot.
struct IdCheck {
  std::string_view what;
  bool marks;  // `-` and `ID:on` are marks in the output
  std::string_view remedy;
};
constexpr IdCheck kLayerIds{"the layer's", true, "choose another --id attribute, or rename it"};
constexpr IdCheck kSceneIdsInside{"the scene's", true, "rename it in the scene file"};
constexpr IdCheck kSceneIdsCollide{"the scene's", false, "rename it in the scene file"};

// An output line is ids separated by spaces and, for `inside`, `ID:on` for a boundary and `-` for
// none: an id that reads as one of those marks ("-", "a:on", "") cannot be told apart and is
// refused (exit 3); white space in an id and an id given twice are warned about. `remedy` says
// what the user can do about an id (another --id attribute, or renaming it in the file).
Status check_ids(const std::vector<std::string>& ids, const IdCheck& check,
                 const std::string& source) {
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const std::string& id = ids[k];
    const bool marked =
        check.marks && ((id.size() >= 3 && id.compare(id.size() - 3, 3, ":on") == 0) || id == "-");
    if (id.empty() || marked) {
      return Error{
          ErrorKind::invalid_value,
          fmt::format("{} id {} of shape {} cannot be told apart in the output{}: {}", check.what,
                      id.empty() ? "''" : "'" + id + "'", k,
                      check.marks ? ", where '-' means no shape and 'ID:on' a boundary" : "",
                      check.remedy),
          source};
    }
  }
  for (const std::string& id : ids) {
    if (id.find_first_of(" \t\n\r") == std::string::npos) continue;
    warn(
        fmt::format("{} ids hold white space (e.g. '{}'), so an output line does not tell where "
                    "one ends: {}",
                    check.what, id, check.remedy));
    break;
  }
  std::unordered_map<std::string_view, std::size_t> seen;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const auto [at, fresh] = seen.emplace(ids[k], k);
    if (fresh) continue;
    warn(
        fmt::format("{} id '{}' is given to shapes {} and {} (and maybe more): an output line "
                    "does not tell {}",
                    check.what, ids[k], at->second, k,
                    check.marks ? "which holds the point" : "which of them meets another"));
    break;
  }
  return Ok{};
}

}  // namespace

int run_layer(const ManyOptions& o) {
  auto layer = io::read_layer(o.layer, {.id = o.id, .layer_name = o.layer_name});
  if (!layer) return report(layer.error());
  for (const std::string& warning : layer->warnings)
    warn(warning);
  if (Status s = check_ids(layer->ids, kLayerIds, io::layer_source_name(o.layer)); !s)
    return report(s.error());
  enter_phase(Phase::prepare);
  const inside::RegionLayer index(layer->regions, {.fill = o.fill});
  return answer_layer(index, layer->ids, o);
}

int answer_layer(const inside::RegionLayer& index, const std::vector<std::string>& ids,
                 const ManyOptions& o) {
  enter_phase(Phase::read);
  auto text = locate_lines<Vec2>(index, ids, o, io::read_points2_chunked);
  if (!text) return report(text.error());
  return emit(*text, o.out);
}

std::vector<inside::SceneObject> scene_objects(const io::Scene& scene) {
  std::vector<inside::SceneObject> objects;
  objects.reserve(scene.mesh_of.size());
  for (std::size_t k = 0; k < scene.mesh_of.size(); ++k)
    objects.push_back({scene.mesh_of[k], scene.transforms[k]});
  return objects;
}

int run_scene_inside(const ManyOptions& o) {
  auto scene = io::read_scene_json(o.scene);
  if (!scene) return report(scene.error());
  if (Status s = check_ids(scene->ids, kSceneIdsInside, o.scene); !s) return report(s.error());
  enter_phase(Phase::prepare);
  const inside::SolidScene index(scene->meshes, scene_objects(*scene));
  // An object whose mesh is not closed is answered by the winding number: say so, once a mesh.
  std::vector<char> warned(scene->meshes.size(), 0);
  for (std::size_t k = 0; k < index.size(); ++k) {
    const auto m = static_cast<std::size_t>(scene->mesh_of[k]);
    if (warned[m]) continue;
    warned[m] = 1;
    const std::string name = scene->mesh_files[m] + " (object " + scene->ids[k] + ")";
    const std::string warning =
        io::mesh_warning(index.object(k).regime(), index.object(k).report());
    // A closed mesh is its solid (winding number positive), crossing itself or not: nothing
    // more to warn of.
    if (!warning.empty()) warn(name + ": " + warning);
  }
  enter_phase(Phase::read);
  auto text = locate_lines<Vec3>(index, scene->ids, o, io::read_points3_chunked);
  if (!text) return report(text.error());
  return emit(*text, o.out);
}

int run_collide_scene(const std::string& file, bool json, int threads, bool quiet,
                      const std::string& out) {
  auto scene = io::read_scene_json(file);
  if (!scene) return report(scene.error());
  if (Status s = check_ids(scene->ids, kSceneIdsCollide, file); !s) return report(s.error());
  enter_phase(Phase::prepare);
  const collide::MeshScene prepared(scene->meshes, scene_objects(*scene));
  std::vector<char> warned(scene->meshes.size(), 0);
  for (std::size_t k = 0; k < prepared.size(); ++k) {
    const auto m = static_cast<std::size_t>(scene->mesh_of[k]);
    if (warned[m]) continue;
    warned[m] = 1;
    if (prepared.is_solid(k)) {
      warn_of_solid(scene->mesh_files[m] + " (object " + scene->ids[k] + ")", scene->meshes[m]);
      continue;
    }
    warn(io::open_mesh_warning(scene->mesh_files[m] + " (object " + scene->ids[k] + ")",
                               io::OpenMeshReading::surface_contact_in_scene));
  }
  // The library's batch on consecutive ranges of the broad phase's candidates (pair tests vary
  // in cost, so a range of about 1% each), with progress between them on a terminal.
  enter_phase(Phase::query);
  const auto candidates = prepared.candidates();
  std::vector<collide::ScenePair> pairs;
  Progress progress("candidate pairs", candidates.size(), !quiet && stderr_is_terminal());
  progress.run(
      [&](std::size_t begin, std::size_t end) {
        const auto found =
            prepared.pairs(std::span(candidates).subspan(begin, end - begin), {.threads = threads});
        pairs.insert(pairs.end(), found.begin(), found.end());
      },
      1);
  std::string text;
  for (const collide::ScenePair& p : pairs) {
    const std::string& a = scene->ids[static_cast<std::size_t>(p.a)];
    const std::string& b = scene->ids[static_cast<std::size_t>(p.b)];
    if (!json) {
      text += a + ' ' + b + '\n';
      continue;
    }
    const collide::Contact& c = p.contact;
    std::string witness;
    if (c.witness == inside::PairWitness::triangles) {
      witness = fmt::format(R"({{"kind":"triangles","triangle_a":{},"triangle_b":{}}})",
                            c.triangle_a, c.triangle_b);
    } else {
      // The vertex of one object inside the other, in world coordinates.
      const bool of_a = c.witness == inside::PairWitness::vertex_of_a_in_b;
      const std::size_t k = static_cast<std::size_t>(of_a ? p.a : p.b);
      const Mesh& mesh = scene->meshes[static_cast<std::size_t>(scene->mesh_of[k])];
      const Vec3 w = scene->transforms[k].apply(mesh.vertex(c.vertex));
      witness = fmt::format(R"({{"kind":"{}","vertex":{},"point":[{},{},{}]}})",
                            collide::to_string(c.witness), c.vertex, w.x, w.y, w.z);
    }
    text += fmt::format(R"({{"a":"{}","b":"{}","intersect":true,"witness":{}}})", json_escape(a),
                        json_escape(b), witness) +
            '\n';
  }
  return emit(text, out);
}

}  // namespace contain::cli
