#include "contain/io/mesh_io.h"

#include <cmath>
#include <limits>

#include "contain/io/index_io.h"
#include "io/mesh_formats.h"
#include "io/text_scan.h"

namespace contain::io {

const char* to_string(MeshFormat format) {
  switch (format) {
    case MeshFormat::obj:
      return "obj";
    case MeshFormat::off:
      return "off";
    case MeshFormat::stl_ascii:
      return "stl_ascii";
    case MeshFormat::stl_binary:
      return "stl_binary";
    case MeshFormat::ply_ascii:
      return "ply_ascii";
    case MeshFormat::ply_binary_little_endian:
      return "ply_binary_little_endian";
    case MeshFormat::ply_binary_big_endian:
      return "ply_binary_big_endian";
  }
  return "mesh";
}

namespace detail {

const char* format_words(MeshFormat format) {
  switch (format) {
    case MeshFormat::obj:
      return "OBJ";
    case MeshFormat::off:
      return "OFF";
    case MeshFormat::stl_ascii:
      return "ASCII STL";
    case MeshFormat::stl_binary:
      return "binary STL";
    case MeshFormat::ply_ascii:
      return "ASCII PLY";
    case MeshFormat::ply_binary_little_endian:
      return "binary little-endian PLY";
    case MeshFormat::ply_binary_big_endian:
      return "binary big-endian PLY";
  }
  return "mesh";
}

}  // namespace detail

std::optional<MeshFormat> mesh_format_for_path(const std::filesystem::path& path) {
  const std::string ext = detail::lower_extension(path);
  if (ext == ".obj") return MeshFormat::obj;
  if (ext == ".off") return MeshFormat::off;
  if (ext == ".stl") return MeshFormat::stl_binary;
  if (ext == ".ply") return MeshFormat::ply_binary_little_endian;
  return std::nullopt;
}

namespace {

Result<MeshFile> parse_family(std::string_view bytes, MeshFormat family,
                              const std::string& source) {
  switch (family) {
    case MeshFormat::obj:
      return detail::parse_obj(bytes, source);
    case MeshFormat::off:
      return detail::parse_off(bytes, source);
    case MeshFormat::stl_ascii:
    case MeshFormat::stl_binary:
      return detail::parse_stl(bytes, source);
    case MeshFormat::ply_ascii:
    case MeshFormat::ply_binary_little_endian:
    case MeshFormat::ply_binary_big_endian:
      return detail::parse_ply(bytes, source);
  }
  return detail::make_error(ErrorKind::unsupported, "unknown mesh format", source);
}

}  // namespace

Result<MeshFile> parse_mesh(std::string_view bytes, MeshFormat family, const std::string& source,
                            const MeshReadOptions& options) {
  auto file = parse_family(bytes, family, source);
  if (file && file->mesh.triangles.empty() && !options.allow_empty) {
    return detail::make_error(
        ErrorKind::degenerate,
        std::string(detail::format_words(file->info.format)) + " file without faces: no mesh",
        source);
  }
  return file;
}

Result<MeshFile> read_mesh(const std::filesystem::path& path, const MeshReadOptions& options) {
  const std::optional<MeshFormat> format = mesh_format_for_path(path);
  if (!format) {
    return detail::make_error(ErrorKind::unsupported,
                              "cannot tell the mesh format from the extension '" +
                                  detail::lower_extension(path) + "': use .obj, .off, .stl or .ply",
                              detail::source_name(path));
  }
  // Parsed in place from a read-only map of a regular file: no copy, no zeroed buffer to fault
  // in. Anything else (no such file, a directory, a pipe, an empty file) is read as before,
  // which gives the same errors.
  if (auto mapped = map_file(path.string()); mapped && !mapped->bytes().empty()) {
    const std::span<const std::byte> bytes = mapped->bytes();
    return parse_mesh({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, *format,
                      detail::source_name(path), options);
  }
  auto bytes = detail::read_file(path);
  if (!bytes) return bytes.error();
  return parse_mesh(*bytes, *format, detail::source_name(path), options);
}

std::string format_mesh(const Mesh& mesh, MeshFormat format) {
  switch (format) {
    case MeshFormat::obj:
      return detail::format_obj(mesh);
    case MeshFormat::off:
      return detail::format_off(mesh);
    case MeshFormat::stl_ascii:
    case MeshFormat::stl_binary:
      return detail::format_stl(mesh, format);
    case MeshFormat::ply_ascii:
    case MeshFormat::ply_binary_little_endian:
    case MeshFormat::ply_binary_big_endian:
      return detail::format_ply(mesh, format);
  }
  return {};
}

Status write_mesh(const Mesh& mesh, const std::filesystem::path& path,
                  const MeshWriteOptions& options) {
  std::optional<MeshFormat> format = options.format;
  if (!format) format = mesh_format_for_path(path);
  if (!format) {
    return detail::make_error(ErrorKind::unsupported,
                              "cannot tell the mesh format from the extension '" +
                                  detail::lower_extension(path) + "': use .obj, .off, .stl or .ply",
                              detail::source_name(path));
  }
  if (*format == MeshFormat::stl_binary) {
    constexpr double kFloatMax = std::numeric_limits<float>::max();
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      const Vec3& v = mesh.vertices[i];
      if (!(std::abs(v.x) <= kFloatMax && std::abs(v.y) <= kFloatMax &&
            std::abs(v.z) <= kFloatMax)) {
        return detail::make_error(
            ErrorKind::invalid_value,
            "vertex " + std::to_string(i) + " is beyond the range of binary STL's 32-bit floats",
            detail::source_name(path));
      }
    }
  }
  return detail::write_file(path, format_mesh(mesh, *format));
}

namespace detail {

Result<MeshFile> finish_mesh(std::vector<Vec3> vertices, std::vector<TriangleIndices> triangles,
                             MeshInfo info, const std::string& source) {
  auto mesh = Mesh::from_arrays(std::move(vertices), std::move(triangles));
  if (!mesh) {
    Error e = mesh.error();
    e.source = source;
    return e;
  }
  return MeshFile{std::move(*mesh), info};
}

}  // namespace detail
}  // namespace contain::io
