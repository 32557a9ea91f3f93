#pragma once
/// \file
/// Private: one reader and writer per mesh format, dispatched by mesh_io.cpp.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "contain/io/mesh_io.h"

namespace contain::io::detail {

/// A format as the readers' messages word it for a person ("OBJ", "binary STL", ...).
[[nodiscard]] const char* format_words(MeshFormat format);

[[nodiscard]] Result<MeshFile> parse_obj(std::string_view text, const std::string& source);
[[nodiscard]] Result<MeshFile> parse_off(std::string_view text, const std::string& source);
[[nodiscard]] Result<MeshFile> parse_stl(std::string_view bytes, const std::string& source);
[[nodiscard]] Result<MeshFile> parse_ply(std::string_view bytes, const std::string& source);

[[nodiscard]] std::string format_obj(const Mesh& mesh);
[[nodiscard]] std::string format_off(const Mesh& mesh);
[[nodiscard]] std::string format_stl(const Mesh& mesh, MeshFormat format);
[[nodiscard]] std::string format_ply(const Mesh& mesh, MeshFormat format);

/// Appends the fan (v0, vi, vi+1) of a face of `corners.size() >= 3` vertices.
inline void append_fan(std::vector<TriangleIndices>& triangles,
                       std::span<const std::int32_t> corners) {
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
    triangles.push_back({corners[0], corners[i], corners[i + 1]});
  }
}

/// The finished reader result (a mesh without triangles is refused by parse_mesh, unless asked
/// for): validates through Mesh::from_arrays (the readers have checked indices and coordinates
/// already, so a failure there is reported as is).
[[nodiscard]] Result<MeshFile> finish_mesh(std::vector<Vec3> vertices,
                                           std::vector<TriangleIndices> triangles, MeshInfo info,
                                           const std::string& source);

/// Appends "PREFIX x y z\n" with the shortest round-trip form of each coordinate, as
/// format_lines writes its vertex lines: ASCII STL's ("vertex ", a prefix of any length).
void append_vertex_line(std::string& out, const char* prefix, Vec3 v);

/// `header`, then "VERTEX x y z\n" per vertex (the shortest round-trip form of each coordinate)
/// and "FACE i j k\n" per triangle with indices from `base`: the text of OBJ, OFF and ASCII PLY.
/// VERTEX and FACE are at most 2 bytes ("v ", "f ", "3 ", ""): the lines are put in place in
/// buffers sized for them (a longer prefix is written by append_vertex_line).
[[nodiscard]] std::string format_lines(const Mesh& mesh, const std::string& header,
                                       std::string_view vertex, std::string_view face, int base);

}  // namespace contain::io::detail
