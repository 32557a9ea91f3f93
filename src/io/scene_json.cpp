#include "contain/io/scene_json.h"

#include <algorithm>
#include <initializer_list>
#include <map>
#include <string_view>

#include "contain/io/mesh_io.h"
#include "io/json_tree.h"
#include "io/text_scan.h"

namespace contain::io {
namespace {

using detail::JsonValue;
using detail::make_error;

class SceneReader {
 public:
  SceneReader(std::string_view text, const SceneJsonOptions& options)
      : text_(text), options_(options) {}

  Result<Scene> read(const JsonValue& root) {
    const JsonValue* objects =
        root.kind == JsonValue::Kind::object ? root.member("objects") : nullptr;
    if (objects == nullptr || objects->kind != JsonValue::Kind::array) {
      return fail(root, ErrorKind::parse, "a scene is {\"objects\": [...]}");
    }
    if (auto s = known_members(root, "the scene", {"objects"}); !s) return s.error();
    Scene scene;
    for (std::size_t k = 0; k < objects->items.size(); ++k) {
      if (auto s = read_object(objects->items[k], k, scene); !s) return s.error();
    }
    return scene;
  }

 private:
  Status read_object(const JsonValue& object, std::size_t k, Scene& scene) {
    const std::string at = "objects[" + std::to_string(k) + "]";
    if (object.kind != JsonValue::Kind::object) {
      return fail(object, ErrorKind::parse,
                  at + ": expected an object, found " + detail::kind_name(object.kind));
    }
    // A misspelt "transfrom" would leave the object unmoved: every member must be known.
    if (auto s = known_members(object, at, {"id", "mesh", "transform"}); !s) return s;
    // id: a string, a number as written, or the position.
    const JsonValue* id = object.member("id");
    if (id == nullptr) {
      scene.ids.push_back(std::to_string(k));
    } else if (id->kind == JsonValue::Kind::string || id->kind == JsonValue::Kind::number) {
      scene.ids.push_back(id->text);
    } else {
      return fail(*id, ErrorKind::parse, at + ".id: expected a string or a number");
    }
    // mesh: read once per resolved path.
    const JsonValue* mesh = object.member("mesh");
    if (mesh == nullptr || mesh->kind != JsonValue::Kind::string) {
      return fail(mesh != nullptr ? *mesh : object, ErrorKind::parse,
                  at + ".mesh: expected the path of a mesh file");
    }
    std::filesystem::path file(mesh->text);
    if (file.is_relative() && !options_.base_dir.empty()) file = options_.base_dir / file;
    const std::string key = file.lexically_normal().string();
    auto found = mesh_index_.find(key);
    if (found == mesh_index_.end()) {
      auto read = read_mesh(file);
      if (!read) return read.error();
      found = mesh_index_.emplace(key, static_cast<std::int32_t>(scene.meshes.size())).first;
      scene.meshes.push_back(std::move(read->mesh));
      scene.mesh_files.push_back(file.string());
    }
    scene.mesh_of.push_back(found->second);
    // transform: 12 numbers, flat or three rows of 4.
    Transform transform;
    if (const JsonValue* t = object.member("transform"); t != nullptr) {
      std::vector<double> numbers;
      if (!collect(*t, numbers, 0) || numbers.size() != 12) {
        return fail(*t, ErrorKind::parse,
                    at + ".transform: expected 12 numbers (r00 r01 r02 t0 r10 r11 r12 t1 r20 "
                         "r21 r22 t2), flat or as three rows of 4");
      }
      auto checked = Transform::from_row_major(numbers);
      if (!checked)
        return fail(*t, checked.error().kind, at + ".transform: " + checked.error().message);
      transform = *checked;
    }
    scene.transforms.push_back(transform);
    return Ok{};
  }

  // ErrorKind::invalid_value naming the first member of `object` not in `known`, and `what`.
  Status known_members(const JsonValue& object, const std::string& what,
                       std::initializer_list<std::string_view> known) const {
    for (const detail::JsonMember& m : object.members) {
      if (std::find(known.begin(), known.end(), m.key) != known.end()) continue;
      std::string names;
      for (const std::string_view k : known)
        names += (names.empty() ? "\"" : ", \"") + std::string(k) + "\"";
      return fail(m.value, ErrorKind::invalid_value,
                  what + ": unknown member \"" + m.key + "\" (the members are " + names + ")");
    }
    return Ok{};
  }

  // The numbers of a flat array, or of an array of 3 arrays of 4.
  static bool collect(const JsonValue& v, std::vector<double>& out, int depth) {
    if (v.kind != JsonValue::Kind::array || depth > 1) return false;
    for (const JsonValue& item : v.items) {
      if (item.kind == JsonValue::Kind::number) {
        out.push_back(item.number);
      } else if (depth == 0 && item.kind == JsonValue::Kind::array && item.items.size() == 4) {
        if (!collect(item, out, 1)) return false;
      } else {
        return false;
      }
    }
    return true;
  }

  [[nodiscard]] Error fail(const JsonValue& at, ErrorKind kind, std::string message) const {
    return make_error(kind, std::move(message), options_.source,
                      detail::line_of_offset(text_, at.offset));
  }

  std::string_view text_;
  const SceneJsonOptions& options_;
  std::map<std::string, std::int32_t> mesh_index_;
};

}  // namespace

Result<Scene> parse_scene_json(std::string_view text, const SceneJsonOptions& options) {
  text = detail::skip_bom(text);
  static constexpr std::string_view kKeep[] = {"id"};
  auto root = detail::parse_json_tree(text, options.source, kKeep);
  if (!root) return root.error();
  return SceneReader(text, options).read(*root);
}

Result<Scene> read_scene_json(const std::filesystem::path& file) {
  auto text = detail::read_file(file);
  if (!text) return text.error();
  return parse_scene_json(*text,
                          {.source = detail::source_name(file), .base_dir = file.parent_path()});
}

}  // namespace contain::io
