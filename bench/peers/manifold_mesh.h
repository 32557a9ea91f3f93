#pragma once
// contain's Mesh to and from Manifold's MeshGL64 for the Manifold drivers. Manifold has no file
// reader in its core library, so the drivers read and write OFF with contain::io (the same
// reader and writer as contain's own runs).

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include <manifold/manifold.h>

#include "bench/peers/peer_driver.h"
#include "contain/io/mesh_io.h"

namespace contain::bench {

// The mesh with its coordinates turned cyclically so that `axis` (0 x, 1 y, 2 z) becomes z:
// Manifold slices and projects along z only, and a cyclic turn keeps the orientation.
[[nodiscard]] inline manifold::MeshGL64 to_manifold(const Mesh& mesh, int axis = 2) {
  manifold::MeshGL64 out;
  out.numProp = 3;
  out.vertProperties.reserve(3 * mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) {
    const double c[3] = {v.x, v.y, v.z};
    for (int i = 1; i <= 3; ++i)
      out.vertProperties.push_back(c[(axis + i) % 3]);
  }
  out.triVerts.reserve(3 * mesh.triangles.size());
  for (const TriangleIndices& t : mesh.triangles) {
    for (std::int32_t v : t)
      out.triVerts.push_back(static_cast<std::uint64_t>(v));
  }
  return out;
}

[[nodiscard]] inline Mesh from_manifold(const manifold::MeshGL64& mesh) {
  Mesh out;
  const std::size_t stride = mesh.numProp;
  for (std::size_t v = 0; v < mesh.NumVert(); ++v) {
    const double* p = &mesh.vertProperties[v * stride];
    out.vertices.push_back({p[0], p[1], p[2]});
  }
  for (std::size_t t = 0; t < mesh.NumTri(); ++t) {
    const std::uint64_t* c = &mesh.triVerts[3 * t];
    out.triangles.push_back({static_cast<std::int32_t>(c[0]), static_cast<std::int32_t>(c[1]),
                             static_cast<std::int32_t>(c[2])});
  }
  return out;
}

// The mesh of an OFF file, or nothing after a message naming the file and the reason.
[[nodiscard]] inline std::optional<Mesh> read_off(const std::string& path) {
  Result<io::MeshFile> file = io::read_mesh(path);
  if (!file) {
    std::fprintf(stderr, "%s\n", file.error().what().c_str());
    return std::nullopt;
  }
  return std::move(file->mesh);
}

// Manifold's solid of `mesh` (its half-edge structure is built here: the costly part of reading),
// or nothing after a message when Manifold refuses the mesh.
[[nodiscard]] inline std::optional<manifold::Manifold> build_manifold(const Mesh& mesh,
                                                                      const std::string& name,
                                                                      int axis = 2) {
  manifold::Manifold solid(to_manifold(mesh, axis));
  if (solid.Status() != manifold::Manifold::Error::NoError) {
    std::fprintf(stderr, "%s: Manifold refuses it: Manifold::Error %d\n", name.c_str(),
                 static_cast<int>(solid.Status()));
    return std::nullopt;
  }
  return solid;
}

// The solid of a mesh file for the slicing drivers, with the time of building it on stderr
// ("kernel build"), or nothing after a message.
[[nodiscard]] inline std::optional<manifold::Manifold> load_solid(const std::string& path,
                                                                  int axis) {
  const std::optional<Mesh> mesh = read_off(path);
  if (!mesh) return std::nullopt;
  const KernelClock clock;
  std::optional<manifold::Manifold> solid = build_manifold(*mesh, path, axis);
  if (solid) clock.report("build");
  return solid;
}

}  // namespace contain::bench
