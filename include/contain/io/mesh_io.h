#pragma once
/// \file
/// Triangle mesh files: OBJ, OFF, STL (ASCII and binary) and PLY (ASCII, binary little and big
/// endian), read into a `Mesh` and written back.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "contain/core/result.h"
#include "contain/shapes/mesh.h"

namespace contain::io {

/// A file format with its encoding.
enum class MeshFormat : std::uint8_t {
  obj,
  off,
  stl_ascii,
  stl_binary,
  ply_ascii,
  ply_binary_little_endian,
  ply_binary_big_endian,
};

/// The enumerator's name ("obj", "stl_binary", "ply_binary_little_endian", ...); the readers'
/// messages word a format for a person ("binary STL").
[[nodiscard]] const char* to_string(MeshFormat format);

/// What a reader saw besides the mesh.
struct MeshInfo {
  MeshFormat format = MeshFormat::off;
  /// Faces read: polygons of any size, each fan-triangulated into size - 2 triangles.
  std::int64_t faces = 0;
  /// STL only: vertices merged because their three coordinates were equal (as doubles: +0 and -0
  /// alike; no tolerance).
  std::int64_t welded_vertices = 0;
};

/// A mesh read from a file, with what the reader saw.
struct MeshFile {
  Mesh mesh;
  MeshInfo info;
};

/// The format family named by a path's extension (case-insensitive): `.obj` -> obj, `.off` ->
/// off, `.stl` -> stl_binary, `.ply` -> ply_binary_little_endian (the writers' defaults; the
/// readers detect the encoding from the content); nothing for another extension.
[[nodiscard]] std::optional<MeshFormat> mesh_format_for_path(const std::filesystem::path& path);

/// How `read_mesh` and `parse_mesh` read.
struct MeshReadOptions {
  /// Accept a well-formed file with no faces as the empty mesh (the empty solid of the mesh
  /// booleans, and what they write for an empty result) instead of ErrorKind::degenerate.
  bool allow_empty = false;
};

/// Reads a mesh, choosing the reader by the extension (`mesh_format_for_path`).
///
/// Formats: OBJ (`v x y z [w]` — w ignored; `f` with `a`, `a/b`, `a//c`, `a/b/c` and negative
/// relative indices; `vt vn vp g o s usemtl mtllib l p` and comments ignored; free-form geometry
/// is ErrorKind::unsupported). OFF (`OFF`, `COFF`, `NOFF`, `CNOFF`, `STOFF` headers, the counts
/// on the header line or the next, `#` comments, extra numbers on vertex lines such as colours
/// and normals, face colours after the indices). STL: binary when the size is 84 + 50 n for the
/// count n of its header, otherwise ASCII if it starts with `solid`; vertices are welded when
/// their coordinates compare equal exactly (+0 = -0, no tolerance) (binary STL's floats are widened
/// exactly to double). PLY: `format ascii|binary_little_endian|binary_big_endian 1.0`; the `vertex`
/// element's x, y, z of any numeric type; the `face` element's `vertex_indices` (or `vertex_index`)
/// list of any integer type; other elements and properties are skipped. Polygonal faces are
/// fan-triangulated (v0, vi, vi+1) in the order written, so a convex face keeps its orientation; a
/// non-convex face's fan may cover the wrong area.
///
/// Errors (never an exception, never a crash, for any bytes): ErrorKind::io (missing file, a
/// directory); ErrorKind::unsupported (unknown extension, a PLY without x/y/z or faces of a
/// 2-vertex list, an OFF of another dimension, an index count past int32); ErrorKind::parse
/// (empty file, bad header, a non-number, truncated data, fewer elements than the header counts,
/// trailing garbage); ErrorKind::invalid_value (NaN/Inf coordinates, an index out of range or
/// 0 in OBJ); ErrorKind::degenerate (a face of fewer than 3 vertices, a mesh without
/// triangles unless `options.allow_empty`). Text formats name the 1-based line; binary formats give
/// the byte offset in the message. Linear time; numbers via std::from_chars (correctly rounded).
[[nodiscard]] Result<MeshFile> read_mesh(const std::filesystem::path& path,
                                         const MeshReadOptions& options = {});

/// Parses mesh bytes already in memory. `family` picks the reader: obj, off, either STL or
/// either PLY value (the encoding is detected from the bytes). `source` names them in errors.
[[nodiscard]] Result<MeshFile> parse_mesh(std::string_view bytes, MeshFormat family,
                                          const std::string& source,
                                          const MeshReadOptions& options = {});

/// The bytes of `mesh` in `format`. OBJ, OFF and ASCII PLY write every coordinate as the
/// shortest decimal that reads back as the same double, so reading gives the same mesh bit for
/// bit (as do binary PLY, which stores doubles). STL stores 32-bit floats: coordinates are
/// rounded to float (exact only for doubles that are floats; beyond float range they become
/// infinities, which `write_mesh` refuses and every reader rejects), facet normals are unit
/// normals rounded to float, and reading welds the corners back into shared vertices, so
/// unreferenced or duplicate-position vertices do not survive. ASCII STL is written with the
/// doubles in full (lossless but for the welding) and zero normals.
[[nodiscard]] std::string format_mesh(const Mesh& mesh, MeshFormat format);

/// How `write_mesh` writes.
struct MeshWriteOptions {
  /// The format; unset: from the path's extension (`mesh_format_for_path`).
  std::optional<MeshFormat> format;
};

/// Writes `mesh` to `path` (replaced). Errors: ErrorKind::unsupported for an extension that
/// names no format (when `options.format` is unset), ErrorKind::invalid_value for binary STL of
/// a coordinate beyond float range, ErrorKind::io when the file cannot be written.
[[nodiscard]] Status write_mesh(const Mesh& mesh, const std::filesystem::path& path,
                                const MeshWriteOptions& options = {});

}  // namespace contain::io
