#pragma once
/// \file
/// Prepared indexes as bytes: a versioned, checked binary form of `MeshIndex`, `PolygonIndex` and
/// `RegionLayer`,
/// so that a service or a batch job that queries the same shape again loads the index instead of
/// building it (io reads and writes the files, memory mapped: contain/io/index_io.h).
///
/// The format (docs/index-files.md), all numbers in the writer's byte order:
///
///   offset  size  field
///        0     8  magic "contain\x1a" (a foreign file fails here)
///        8     4  format version (`index_format_version`)
///       12     4  byte-order mark 0x01020304 (a file of the other byte order is refused)
///       16     4  kind (`IndexKind`)
///       20     4  layout: sizeof(double) | sizeof(std::size_t) << 8 | sizeof(void*) << 16
///       24     8  fingerprint of the source shape (`fingerprint`)
///       32     8  payload length in bytes (the file is exactly 64 + this long)
///       40     8  payload checksum (`index_checksum`)
///       48     8  reserved, zero
///       56     8  header checksum (of bytes 0 .. 56)
///       64        payload: the kind's sections, each array preceded by its element count
///
/// Loading checks all of it before reading the payload, and the payload's reader checks every
/// count against the bytes left and every index stored in it against the array it points into,
/// so a truncated, corrupted or crafted file is an `Error` (ErrorKind::parse), never a crash, an
/// out-of-bounds read or an index that answers wrongly.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "contain/core/result.h"
#include "contain/inside/mesh_index.h"
#include "contain/inside/region_layer.h"
#include "contain/shapes/mesh.h"
#include "contain/shapes/polygon.h"

namespace contain::inside {

/// What a saved index holds.
enum class IndexKind : std::uint32_t {
  mesh_index = 1,     ///< a `MeshIndex`
  region_layer = 2,   ///< a `RegionLayer` and its regions' ids
  polygon_index = 3,  ///< a `PolygonIndex` (one region)
};

/// The enumerator's name: "mesh_index", "region_layer" or "polygon_index" ("unknown" for another
/// value).
[[nodiscard]] const char* to_string(IndexKind kind);

/// The format version this build writes and reads; a file of another version is refused.
inline constexpr std::uint32_t index_format_version = 2;

/// Bytes before the payload.
inline constexpr std::size_t index_header_size = 64;

/// A 64-bit checksum of `bytes` (four-lane multiply-rotate, about 8 GB/s a core): detects
/// corruption, not tampering.
[[nodiscard]] std::uint64_t index_checksum(std::span<const std::byte> bytes);

/// The fingerprint of what decides a mesh's answers: the multiset of its triangles' corner
/// coordinates (bit patterns, corners in the triangle's order), independent of the triangles'
/// order and of vertices no triangle uses. `fingerprint(MeshIndex(mesh)) == fingerprint(mesh)`.
/// The vertex sharing is not covered: the same triangles welded (closed, exact regime) or as a
/// soup (open, winding number) share a fingerprint; the index keeps the regime it was built with.
[[nodiscard]] std::uint64_t fingerprint(const Mesh& mesh);
/// The fingerprint of the triangles a `MeshIndex` holds (as `fingerprint(const Mesh&)`).
[[nodiscard]] std::uint64_t fingerprint(const MeshIndex& index);
/// The fingerprint of a layer's regions: every ring's vertices (bit patterns), in region, part
/// and ring order, and the fill rule.
[[nodiscard]] std::uint64_t fingerprint(std::span<const MultiPolygon> regions, Fill fill);

/// The checked header of a saved index.
struct IndexHeader {
  IndexKind kind = IndexKind::mesh_index;
  std::uint64_t source = 0;  ///< fingerprint of the shape it was built from
  std::span<const std::byte> payload;
};

/// Checks magic, version, byte order, layout, the lengths and both checksums of `bytes`.
/// Errors (ErrorKind::parse) say which check failed; `source` is left empty for the caller.
[[nodiscard]] Result<IndexHeader> parse_index_header(std::span<const std::byte> bytes);

namespace index_bytes {
class Writer;
}  // namespace index_bytes

/// A whole index file as pieces in order: bytes of its own (the header, the small sections,
/// arrays stored in another form than the index keeps them) and views of the index's own arrays
/// where the file stores them as they lie in memory, so that writing a file needs no copy of
/// the index in one buffer (for 100k triangles 21 MB less to allocate, fill and free). Valid
/// while the index it shows lives unchanged. Movable, not copyable.
class IndexImage {
 public:
  IndexImage(IndexImage&&) noexcept = default;
  IndexImage& operator=(IndexImage&&) noexcept = default;
  IndexImage(const IndexImage&) = delete;
  IndexImage& operator=(const IndexImage&) = delete;
  ~IndexImage() = default;

  /// The file's bytes, piece by piece, in order.
  [[nodiscard]] std::span<const std::span<const std::byte>> pieces() const { return pieces_; }
  /// The file's length.
  [[nodiscard]] std::size_t size() const;
  /// The pieces joined: the file's bytes.
  [[nodiscard]] std::vector<std::byte> join() &&;

 private:
  friend class index_bytes::Writer;
  IndexImage() = default;
  std::vector<std::byte> own_;
  std::vector<std::span<const std::byte>> pieces_;
};

/// The file of `index` (kind mesh_index; source: `fingerprint(index)`) as an image that refers
/// to `index`'s arrays: the bytes of `format_index(index)`, piece by piece.
[[nodiscard]] IndexImage index_image(const MeshIndex& index);

/// The file bytes of `index` (kind mesh_index; source: `fingerprint(index)`).
[[nodiscard]] std::vector<std::byte> format_index(const MeshIndex& index);

/// A `MeshIndex` built only to be saved (`contain index build`): its file is byte for byte the
/// file of `MeshIndex(mesh, options)`, from less memory. The surface cells' lists are kept as
/// the file stores them, the triangles' numbers (4 bytes a reference), not as the references
/// with a copy of their triangle's box that the queries read (28 bytes: for 100k triangles 18 MB
/// less to fault in and fill), and the image refers to them instead of copying them. It answers
/// no query: load its file (`parse_mesh_index`) for that.
class MeshIndexToSave {
 public:
  /// Prepares `mesh` as `MeshIndex(mesh, options)` does.
  explicit MeshIndexToSave(const Mesh& mesh, const MeshIndexOptions& options = {});
  /// As `MeshIndex::regime`.
  [[nodiscard]] MeshRegime regime() const { return index_.regime(); }
  /// As `MeshIndex::report`.
  [[nodiscard]] const MeshReport& report() const { return index_.report(); }
  /// As `MeshIndex::stats`.
  [[nodiscard]] MeshIndex::Stats stats() const { return index_.stats(); }
  /// The file, the bytes of `format_index(MeshIndex(mesh, options))`, as an image that refers to
  /// this object's arrays (valid while it lives).
  [[nodiscard]] IndexImage image() const;

 private:
  MeshIndex index_;
};
/// The file bytes of `layer` (kind region_layer) built from regions of fingerprint `source`,
/// with `ids` (empty, or one per region) saved beside it.
[[nodiscard]] std::vector<std::byte> format_index(const RegionLayer& layer, std::uint64_t source,
                                                  std::span<const std::string> ids);

/// The file bytes of `index` (kind polygon_index) built from a region of fingerprint `source`
/// (`fingerprint({region}, fill)`).
[[nodiscard]] std::vector<std::byte> format_index(const PolygonIndex& index, std::uint64_t source);

/// The `MeshIndex` saved in `bytes`: answers exactly as the index that was saved.
[[nodiscard]] Result<MeshIndex> parse_mesh_index(std::span<const std::byte> bytes);
/// The same from a header `parse_index_header` has already checked (no second checksum pass).
[[nodiscard]] Result<MeshIndex> parse_mesh_index(const IndexHeader& checked);

/// The `PolygonIndex` saved in `bytes` (the region's fingerprint is the header's `source`).
[[nodiscard]] Result<PolygonIndex> parse_polygon_index(std::span<const std::byte> bytes);
/// The same from a header `parse_index_header` has already checked.
[[nodiscard]] Result<PolygonIndex> parse_polygon_index(const IndexHeader& checked);

/// A `RegionLayer` read back, with the ids saved beside it.
struct SavedRegionLayer {
  RegionLayer layer;
  std::vector<std::string> ids;  ///< empty, or one per region
  std::uint64_t source = 0;      ///< fingerprint of the regions it was built from
};
/// The `RegionLayer` saved in `bytes`: answers exactly as the layer that was saved.
[[nodiscard]] Result<SavedRegionLayer> parse_region_layer(std::span<const std::byte> bytes);
/// The same from a header `parse_index_header` has already checked (no second checksum pass).
[[nodiscard]] Result<SavedRegionLayer> parse_region_layer(const IndexHeader& checked);

}  // namespace contain::inside
