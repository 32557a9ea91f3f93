#pragma once
// The common body of the mesh reader targets: any bytes give a mesh or an error, never a crash;
// a mesh read is valid (finite, indices in range, at least one triangle) and survives a round
// trip through the lossless writers.

#include <cmath>
#include <string>
#include <string_view>

#include "contain/io/mesh_io.h"
#include "contain/shapes/mesh_validation.h"
#include "fuzz_support.h"

namespace contain::fuzz {

inline void check_mesh_round_trip(const Mesh& mesh, io::MeshFormat format) {
  auto again = io::parse_mesh(io::format_mesh(mesh, format), format, "round trip");
  if (!again) std::fprintf(stderr, "%s\n", again.error().what().c_str());
  FUZZ_CHECK(again.ok());
  FUZZ_CHECK(again->mesh == mesh);
}

inline int fuzz_mesh_reader(const std::uint8_t* data, std::size_t size, io::MeshFormat family) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  auto file = io::parse_mesh(bytes, family, "fuzz");
  if (!file) {
    FUZZ_CHECK(!file.error().message.empty());
    FUZZ_CHECK(file.error().source == "fuzz");
    return 0;
  }
  const Mesh& mesh = file->mesh;
  FUZZ_CHECK(!mesh.triangles.empty());
  for (const Vec3& v : mesh.vertices) {
    FUZZ_CHECK(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
  }
  const auto n = static_cast<std::int64_t>(mesh.vertices.size());
  for (const TriangleIndices& t : mesh.triangles) {
    for (const std::int32_t i : t)
      FUZZ_CHECK(i >= 0 && i < n);
  }
  const MeshReport report = validate_mesh(mesh);
  FUZZ_CHECK(report.triangles == mesh.triangles.size());
  // OBJ, OFF and PLY keep every double and every index: reading back gives the same mesh.
  check_mesh_round_trip(mesh, io::MeshFormat::off);
  check_mesh_round_trip(
      mesh, size % 2 == 0 ? io::MeshFormat::obj : io::MeshFormat::ply_binary_little_endian);
  return 0;
}

}  // namespace contain::fuzz
