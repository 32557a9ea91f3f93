#include "contain/io/csg_json.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "contain/io/mesh_io.h"
#include "contain/io/mesh_warning.h"
#include "contain/shapes/mesh_validation.h"
#include "muparser_function.h"

namespace contain::io {
namespace {

// Why a mesh read for a leaf cannot be one (empty if it can). The reader has checked its numbers
// and indices; a leaf must be closed, as inside::CsgSolid::prepare requires, and the words are
// those of the warning for the regime such a mesh would get. A file without faces is the empty
// solid, as for `contain clip`.
std::string mesh_leaf_problem(const Mesh& mesh) {
  if (mesh.triangles.empty()) return "";  // the empty solid: a valid operand
  const MeshReport report = validate_mesh(mesh);
  if (report.closed()) return "";
  return "mesh is not closed, a closed mesh is required (" +
         mesh_warning(inside::MeshRegime::winding_number, report) + ")";
}

using nlohmann::json;

class Reader {
 public:
  explicit Reader(const CsgJsonOptions& options) : options_(options) {}

  // Trees deeper than this are refused: reading (and later evaluating) a tree recurses once
  // per level, so a file of 10^5 nested complements would overflow the stack.
  static constexpr int kMaxDepth = 256;

  Result<Csg> node(const json& j, const std::string& path) {
    if (depth_ >= kMaxDepth) {
      return fail("",
                  "the CSG tree is nested more than " + std::to_string(kMaxDepth) + " levels deep",
                  ErrorKind::unsupported);
    }
    ++depth_;
    Result<Csg> out = node_at_depth(j, path);
    --depth_;
    return out;
  }

 private:
  Result<Csg> node_at_depth(const json& j, const std::string& path) {
    if (!j.is_object()) return fail(path, "expected an object, got " + describe(j));
    if (j.size() != 1) {
      return fail(path, "expected an object with exactly one key, got " + std::to_string(j.size()));
    }
    const std::string& key = j.begin().key();
    const json& value = j.begin().value();
    const std::string here = join(path, key);
    if (key == "union" || key == "intersection") return list(key, value, here);
    if (key == "difference") return difference(value, here);
    if (key == "complement") {
      Result<Csg> inner = node(value, here);
      if (!inner) return inner;
      return Csg::complement(std::move(inner).value());
    }
    if (key == "sphere") return sphere(value, here);
    if (key == "box") return box(value, here);
    if (key == "halfspace") return halfspace(value, here);
    if (key == "convex") return convex(value, here);
    if (key == "implicit") return implicit(value, here);
    if (key == "mesh") return mesh(value, here);
    return fail(path, "unknown key \"" + key +
                          "\" (expected union, intersection, difference, complement, sphere, box, "
                          "halfspace, convex, implicit or mesh)");
  }

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }
  static std::string index(const std::string& path, std::size_t i) {
    return path + "[" + std::to_string(i) + "]";
  }
  static std::string describe(const json& j) {
    if (j.is_number()) return "a number";
    if (j.is_array()) return "an array";
    if (j.is_object()) return "an object";
    if (j.is_string()) return "a string";
    if (j.is_boolean()) return "a boolean";
    return "null";
  }

  Error fail(const std::string& path, const std::string& message,
             ErrorKind kind = ErrorKind::invalid_value) const {
    return Error{kind, path.empty() ? message : path + ": " + message, options_.source, 0};
  }

  Result<std::vector<Csg>> operands(const json& j, const std::string& path) {
    if (!j.is_array()) return fail(path, "expected an array, got " + describe(j));
    std::vector<Csg> out;
    for (std::size_t i = 0; i < j.size(); ++i) {
      Result<Csg> c = node(j[i], index(path, i));
      if (!c) return c.error();
      out.push_back(std::move(c).value());
    }
    return out;
  }

  Result<Csg> list(const std::string& key, const json& j, const std::string& path) {
    Result<std::vector<Csg>> ops = operands(j, path);
    if (!ops) return ops.error();
    if (ops->empty()) return fail(path, "expected at least one operand");
    return key == "union" ? Csg::unite(std::move(ops).value())
                          : Csg::intersection(std::move(ops).value());
  }

  Result<Csg> difference(const json& j, const std::string& path) {
    if (j.is_array() && j.size() != 2) {
      return fail(path, "expected an array of 2 operands, got " + std::to_string(j.size()));
    }
    Result<std::vector<Csg>> ops = operands(j, path);
    if (!ops) return ops.error();
    return Csg::difference((*ops)[0], (*ops)[1]);
  }

  Result<double> number(const json& j, const std::string& path) {
    if (!j.is_number()) return fail(path, "expected a number, got " + describe(j));
    const double v = j.get<double>();
    if (!std::isfinite(v)) return fail(path, "expected a finite number");
    return v;
  }

  Result<std::vector<double>> numbers(const json& j, const std::string& path, std::size_t count) {
    if (!j.is_array())
      return fail(path,
                  "expected an array of " + std::to_string(count) + " numbers, got " + describe(j));
    if (j.size() != count) {
      return fail(
          path, "expected " + std::to_string(count) + " numbers, got " + std::to_string(j.size()));
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < count; ++i) {
      Result<double> v = number(j[i], index(path, i));
      if (!v) return v.error();
      out.push_back(*v);
    }
    return out;
  }

  Result<Vec3> vec3(const json& j, const std::string& path) {
    Result<std::vector<double>> v = numbers(j, path, 3);
    if (!v) return v.error();
    return Vec3{(*v)[0], (*v)[1], (*v)[2]};
  }

  // An object with exactly the given keys.
  Result<Ok> keys(const json& j, const std::string& path, std::initializer_list<const char*> want) {
    if (!j.is_object()) return fail(path, "expected an object, got " + describe(j));
    for (const auto& item : j.items()) {
      if (std::none_of(want.begin(), want.end(), [&](const char* k) { return item.key() == k; })) {
        return fail(path, "unknown key \"" + item.key() + "\"");
      }
    }
    for (const char* k : want) {
      if (!j.contains(k)) return fail(path, std::string("missing key \"") + k + "\"");
    }
    return Ok{};
  }

  Result<Csg> sphere(const json& j, const std::string& path) {
    if (Result<Ok> k = keys(j, path, {"center", "radius"}); !k) return k.error();
    Result<Vec3> center = vec3(j["center"], join(path, "center"));
    if (!center) return center.error();
    Result<double> radius = number(j["radius"], join(path, "radius"));
    if (!radius) return radius.error();
    if (*radius < 0) return fail(join(path, "radius"), "expected a radius >= 0");
    return Csg::leaf(Sphere{*center, *radius});
  }

  Result<Csg> box(const json& j, const std::string& path) {
    if (Result<Ok> k = keys(j, path, {"min", "max"}); !k) return k.error();
    Result<Vec3> lo = vec3(j["min"], join(path, "min"));
    if (!lo) return lo.error();
    Result<Vec3> hi = vec3(j["max"], join(path, "max"));
    if (!hi) return hi.error();
    if (lo->x > hi->x || lo->y > hi->y || lo->z > hi->z) {
      return fail(path, "min exceeds max");
    }
    return Csg::leaf(Box3{*lo, *hi});
  }

  Result<Plane> plane(const json& j, const std::string& path) {
    Result<std::vector<double>> v = numbers(j, path, 4);
    if (!v) return v.error();
    const Plane p{(*v)[0], (*v)[1], (*v)[2], (*v)[3]};
    if (p.a == 0 && p.b == 0 && p.c == 0) {
      return fail(path, "the normal (a, b, c) is zero", ErrorKind::degenerate);
    }
    return p;
  }

  Result<Csg> halfspace(const json& j, const std::string& path) {
    Result<Plane> p = plane(j, path);
    if (!p) return p.error();
    return Csg::leaf(*p);
  }

  Result<Csg> convex(const json& j, const std::string& path) {
    if (!j.is_array()) return fail(path, "expected an array of planes, got " + describe(j));
    std::vector<Plane> planes;
    for (std::size_t i = 0; i < j.size(); ++i) {
      Result<Plane> p = plane(j[i], index(path, i));
      if (!p) return p.error();
      planes.push_back(*p);
    }
    auto polyhedron = ConvexPolyhedron::from_planes(std::move(planes));
    if (!polyhedron) return fail(path, polyhedron.error().message, polyhedron.error().kind);
    return Csg::leaf(std::move(polyhedron).value());
  }

  Result<Csg> implicit(const json& j, const std::string& path) {
    if (!j.is_string()) return fail(path, "expected an expression string, got " + describe(j));
    auto f = detail::compile_expression(j.get<std::string>());
    if (!f) return fail(path, f.error().message, f.error().kind);
    return Csg::leaf(std::move(f).value());
  }

  Result<Csg> mesh(const json& j, const std::string& path) {
    if (!j.is_string()) return fail(path, "expected a file name, got " + describe(j));
    const std::filesystem::path file = options_.base_dir / j.get<std::string>();
    Result<MeshFile> read = read_mesh(file, {.allow_empty = true});  // no faces: the empty solid
    // The mesh reader's error names the mesh file (and its line); the path names the leaf.
    if (!read) return fail(path, read.error().what(), read.error().kind);
    if (const std::string problem = mesh_leaf_problem(read->mesh); !problem.empty()) {
      return fail(path, file.string() + ": " + problem, ErrorKind::degenerate);
    }
    return Csg::leaf(CsgMesh(std::move(read->mesh)));
  }

  const CsgJsonOptions& options_;
  int depth_ = 0;
};

// "[json.exception.parse_error.101] parse error at line 2, column 5: ..." -> after "] ".
std::string without_id(std::string message) {
  if (message.rfind("[json.exception.", 0) == 0) {
    if (const auto cut = message.find("] "); cut != std::string::npos)
      return message.substr(cut + 2);
  }
  return message;
}

struct RepeatedName {
  std::string name;
};

std::int64_t line_of(std::string_view text, std::size_t byte) {
  const std::size_t end = std::min(text.size(), byte > 0 ? byte - 1 : 0);
  return 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(end), '\n');
}

}  // namespace

Result<Csg> parse_csg_json(std::string_view text, const CsgJsonOptions& options) {
  json document;
  // JSON leaves it to the reader which of two equal names counts (nlohmann keeps the last): a
  // second "op" or "children" would silently win, so a name given twice is an error.
  std::vector<std::set<std::string>> names;
  const auto no_repeated_names = [&](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) names.emplace_back();
    if (event == json::parse_event_t::object_end) names.pop_back();
    if (event == json::parse_event_t::key &&
        !names.back().insert(parsed.get<std::string>()).second) {
      throw RepeatedName{parsed.get<std::string>()};
    }
    return true;
  };
  try {
    document = json::parse(text.begin(), text.end(), no_repeated_names);
  } catch (const RepeatedName& e) {
    return Error{ErrorKind::parse, "the member \"" + e.name + "\" is given twice in one object",
                 options.source, 0};
  } catch (const json::parse_error& e) {
    return Error{ErrorKind::parse, without_id(e.what()), options.source, line_of(text, e.byte)};
  } catch (const json::out_of_range& e) {  // a number beyond the double range
    return Error{ErrorKind::invalid_value, without_id(e.what()), options.source, 0};
  } catch (const std::exception& e) {
    return Error{ErrorKind::parse, without_id(e.what()), options.source, 0};
  }
  try {
    return Reader(options).node(document, "");
  } catch (const std::exception& e) {  // nlohmann or allocation: never cross the API
    return Error{ErrorKind::invalid_value, e.what(), options.source, 0};
  }
}

Result<Csg> read_csg_json(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return Error{ErrorKind::io, "cannot open the file", file.string(), 0};
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) return Error{ErrorKind::io, "cannot read the file", file.string(), 0};
  return parse_csg_json(buffer.str(), {.source = file.string(), .base_dir = file.parent_path()});
}

}  // namespace contain::io
