#include "bound/test_mesh_reader.h"

#include <charconv>
#include <fstream>
#include <sstream>
#include <vector>

namespace contain::test {
namespace {

bool parse_double(const std::string& token, double& out) {
  const char* end = token.data() + token.size();
  auto [ptr, ec] = std::from_chars(token.data(), end, out);
  return ec == std::errc() && ptr == end;
}

void add_fan(const std::vector<std::int32_t>& face, std::vector<TriangleIndices>& triangles) {
  for (std::size_t i = 1; i + 1 < face.size(); ++i) {
    triangles.push_back({face[0], face[i], face[i + 1]});
  }
}

std::optional<Mesh> finish(std::vector<Vec3> vertices, std::vector<TriangleIndices> triangles,
                           std::string& why) {
  auto mesh = Mesh::from_arrays(std::move(vertices), std::move(triangles));
  if (!mesh.ok()) {
    why = mesh.error().message;
    return std::nullopt;
  }
  return std::move(mesh).value();
}

std::optional<Mesh> read_obj(std::istream& in, std::string& why) {
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      std::string x, y, z;
      words >> x >> y >> z;
      Vec3 p;
      if (!parse_double(x, p.x) || !parse_double(y, p.y) || !parse_double(z, p.z)) {
        why.assign("bad vertex line: ").append(line);
        return std::nullopt;
      }
      vertices.push_back(p);
    } else if (tag == "f") {
      std::vector<std::int32_t> face;
      std::string corner;
      while (words >> corner) {
        const long index = std::stol(corner.substr(0, corner.find('/')));
        const long n = static_cast<long>(vertices.size());
        face.push_back(static_cast<std::int32_t>(index < 0 ? n + index : index - 1));
      }
      add_fan(face, triangles);
    }
  }
  return finish(std::move(vertices), std::move(triangles), why);
}

std::optional<Mesh> read_off(std::istream& in, std::string& why) {
  // Tokens without comments; the header may be "OFF" alone or "OFF v f e" on one line.
  std::vector<std::string> tokens;
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string w;
    while (words >> w)
      tokens.push_back(w);
  }
  std::size_t at = 0;
  if (tokens.empty() || tokens[at++] != "OFF") {
    why = "missing OFF header";
    return std::nullopt;
  }
  const auto nv = static_cast<std::size_t>(std::stol(tokens.at(at++)));
  const auto nf = static_cast<std::size_t>(std::stol(tokens.at(at++)));
  ++at;  // edge count
  std::vector<Vec3> vertices(nv);
  for (Vec3& p : vertices) {
    if (!parse_double(tokens.at(at), p.x) || !parse_double(tokens.at(at + 1), p.y) ||
        !parse_double(tokens.at(at + 2), p.z)) {
      why = "bad OFF vertex";
      return std::nullopt;
    }
    at += 3;
  }
  std::vector<TriangleIndices> triangles;
  for (std::size_t f = 0; f < nf; ++f) {
    const auto k = static_cast<std::size_t>(std::stol(tokens.at(at++)));
    std::vector<std::int32_t> face;
    for (std::size_t i = 0; i < k; ++i) {
      face.push_back(static_cast<std::int32_t>(std::stol(tokens.at(at++))));
    }
    add_fan(face, triangles);
  }
  return finish(std::move(vertices), std::move(triangles), why);
}

}  // namespace

std::optional<Mesh> read_test_mesh(const std::filesystem::path& path, std::string& why) {
  std::ifstream in(path);
  if (!in) {
    why.assign("cannot open ").append(path.string());
    return std::nullopt;
  }
  if (path.extension() == ".off") return read_off(in, why);
  return read_obj(in, why);
}

}  // namespace contain::test
