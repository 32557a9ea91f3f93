#pragma once
/// \file
/// Saved indexes as files (the format: contain/inside/index_file.h, docs/index-files.md):
/// written whole, read through a read-only memory map, errors naming the file.

#include <cstddef>
#include <span>
#include <string>

#include "contain/core/result.h"
#include "contain/inside/index_file.h"
#include "contain/inside/mesh_index.h"

namespace contain::io {

/// A file mapped read-only into memory (unmapped on destruction; movable, not copyable).
class MappedFile {
 public:
  MappedFile() = default;
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  ~MappedFile();

  /// The file's bytes (empty for an empty file).
  [[nodiscard]] std::span<const std::byte> bytes() const { return {data_, size_}; }

 private:
  friend Result<MappedFile> map_file(const std::string& path);
  const std::byte* data_ = nullptr;
  std::size_t size_ = 0;
};

/// Maps `path` read-only (ErrorKind::io naming the file if it cannot be opened or mapped).
[[nodiscard]] Result<MappedFile> map_file(const std::string& path);

/// Writes `bytes` (a whole index file: `inside::format_index`) to `path`.
[[nodiscard]] Status write_index(std::span<const std::byte> bytes, const std::string& path);
/// Writes the file of `image` (`inside::index_image`) to `path`, piece by piece: the same bytes
/// as its joined form, without that copy.
[[nodiscard]] Status write_index(const inside::IndexImage& image, const std::string& path);

/// The kind of the index saved in `path`, checked whole (`inside::parse_index_header`), with
/// the file kept mapped for `read_mesh_index(file, path)`.
struct IndexFile {
  MappedFile file;
  inside::IndexHeader header;
};
[[nodiscard]] Result<IndexFile> read_index_file(const std::string& path);

/// The `MeshIndex` saved in `path`; errors (ErrorKind::io or parse) name the file.
[[nodiscard]] Result<inside::MeshIndex> read_mesh_index(const std::string& path);
/// The `MeshIndex` of an index file already read; errors name `path`.
[[nodiscard]] Result<inside::MeshIndex> read_mesh_index(const IndexFile& file,
                                                        const std::string& path);

/// The `PolygonIndex` of an index file already read; errors name `path`.
[[nodiscard]] Result<inside::PolygonIndex> read_polygon_index(const IndexFile& file,
                                                              const std::string& path);
/// The `PolygonIndex` saved in `path`; errors (ErrorKind::io or parse) name the file.
[[nodiscard]] Result<inside::PolygonIndex> read_polygon_index(const std::string& path);

/// The `RegionLayer` (and its ids) saved in `path`; errors (ErrorKind::io or parse) name the file.
[[nodiscard]] Result<inside::SavedRegionLayer> read_region_layer_index(const std::string& path);
/// The `RegionLayer` of an index file already read; errors name `path`.
[[nodiscard]] Result<inside::SavedRegionLayer> read_region_layer_index(const IndexFile& file,
                                                                       const std::string& path);

}  // namespace contain::io
