// The frame of a saved index (contain/inside/index_file.h): header, checksums, fingerprints. The
// kinds' payloads are in mesh_index_file.cpp and region_layer_file.cpp.

#include "contain/inside/index_file.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <utility>

#include "inside/index_bytes.h"

namespace contain::inside {

namespace {

constexpr char magic[8] = {'c', 'o', 'n', 't', 'a', 'i', 'n', '\x1a'};
constexpr std::uint32_t byte_order_mark = 0x01020304;
constexpr std::uint32_t layout =
    sizeof(double) | (sizeof(std::size_t) << 8) | (sizeof(void*) << 16);

// Field offsets (the table in index_file.h).
constexpr std::size_t at_version = 8, at_order = 12, at_kind = 16, at_layout = 20, at_source = 24,
                      at_length = 32, at_checksum = 40, at_header_checksum = 56;

constexpr std::uint64_t p1 = 0x9E3779B185EBCA87ULL, p2 = 0xC2B2AE3D27D4EB4FULL,
                        p3 = 0x165667B19E3779F9ULL;

std::uint64_t mix(std::uint64_t acc, std::uint64_t word) {
  return std::rotl(acc + word * p2, 31) * p1;
}
std::uint64_t avalanche(std::uint64_t h) {
  h ^= h >> 33;
  h *= p2;
  h ^= h >> 29;
  h *= p3;
  return h ^ (h >> 32);
}
std::uint64_t load(const std::byte* p) {
  std::uint64_t w = 0;
  std::memcpy(&w, p, sizeof w);
  return w;
}
template <class T>
T read_at(std::span<const std::byte> bytes, std::size_t at) {
  T value{};
  std::memcpy(&value, bytes.data() + at, sizeof(T));
  return value;
}
template <class T>
void write_at(std::vector<std::byte>& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof(T));
}

Error corrupt(const std::string& what) {
  return {ErrorKind::parse, "not a usable contain index file: " + what};
}

}  // namespace

const char* to_string(IndexKind kind) {
  switch (kind) {
    case IndexKind::mesh_index:
      return "mesh_index";
    case IndexKind::region_layer:
      return "region_layer";
    case IndexKind::polygon_index:
      return "polygon_index";
  }
  return "unknown";
}

namespace {

// index_checksum over bytes that come in pieces (an IndexImage): the value over the pieces
// joined. Whole 32-byte blocks go through the four lanes as they come; a block split between
// pieces waits in `block_`.
class Checksum {
 public:
  void add(std::span<const std::byte> bytes) {
    const std::byte* p = bytes.data();
    std::size_t n = bytes.size();
    total_ += n;
    if (pending_ > 0) {
      const std::size_t take = std::min(n, sizeof block_ - pending_);
      std::memcpy(block_ + pending_, p, take);
      pending_ += take;
      p += take;
      n -= take;
      if (pending_ < sizeof block_) return;
      lanes(block_);
      pending_ = 0;
    }
    for (; n >= sizeof block_; p += sizeof block_, n -= sizeof block_)
      lanes(p);
    if (n > 0) std::memcpy(block_, p, n);
    pending_ = n;
  }

  [[nodiscard]] std::uint64_t finish() const {
    std::uint64_t h = std::rotl(v_[0], 1) + std::rotl(v_[1], 7) + std::rotl(v_[2], 12) +
                      std::rotl(v_[3], 18) + static_cast<std::uint64_t>(total_);
    std::size_t i = 0;
    for (; i + 8 <= pending_; i += 8)
      h = std::rotl(h ^ mix(0, load(block_ + i)), 27) * p1 + p3;
    for (; i < pending_; ++i)
      h = std::rotl(h ^ (static_cast<std::uint64_t>(block_[i]) * p3), 11) * p1;
    return avalanche(h);
  }

 private:
  void lanes(const std::byte* p) {
    for (int lane = 0; lane < 4; ++lane)
      v_[lane] = mix(v_[lane], load(p + 8 * static_cast<std::size_t>(lane)));
  }

  std::uint64_t v_[4] = {p1 + p2, p2, 0, 0 - p1};
  std::byte block_[32] = {};
  std::size_t pending_ = 0;
  std::size_t total_ = 0;
};

}  // namespace

std::uint64_t index_checksum(std::span<const std::byte> bytes) {
  Checksum sum;
  sum.add(bytes);
  return sum.finish();
}

std::size_t IndexImage::size() const {
  std::size_t n = 0;
  for (const std::span<const std::byte> piece : pieces_)
    n += piece.size();
  return n;
}

std::vector<std::byte> IndexImage::join() && {
  if (pieces_.size() == 1 && pieces_.front().data() == own_.data()) return std::move(own_);
  std::vector<std::byte> bytes;
  bytes.reserve(size());
  for (const std::span<const std::byte> piece : pieces_)
    bytes.insert(bytes.end(), piece.begin(), piece.end());
  return bytes;
}

namespace index_bytes {

std::uint64_t hash_triangle(Vec3 a, Vec3 b, Vec3 c) {
  std::uint64_t h = p3;
  for (const Vec3& v : {a, b, c}) {
    h = mix(h, std::bit_cast<std::uint64_t>(v.x));
    h = mix(h, std::bit_cast<std::uint64_t>(v.y));
    h = mix(h, std::bit_cast<std::uint64_t>(v.z));
  }
  return avalanche(h);
}

std::uint64_t finish_fingerprint(std::uint64_t sum, std::size_t triangles) {
  return avalanche(mix(sum, triangles));
}

IndexImage finish_image(Writer& writer, IndexKind kind, std::uint64_t source) {
  std::vector<std::byte>& bytes = writer.bytes();
  std::memcpy(bytes.data(), magic, sizeof magic);
  write_at(bytes, at_version, index_format_version);
  write_at(bytes, at_order, byte_order_mark);
  write_at(bytes, at_kind, static_cast<std::uint32_t>(kind));
  write_at(bytes, at_layout, layout);
  write_at(bytes, at_source, source);
  Checksum payload;
  std::size_t length = 0;
  writer.visit(index_header_size, [&](std::span<const std::byte> piece) {
    payload.add(piece);
    length += piece.size();
  });
  write_at<std::uint64_t>(bytes, at_length, length);
  write_at(bytes, at_checksum, payload.finish());
  write_at(bytes, at_header_checksum,
           index_checksum(std::span<const std::byte>(bytes).first(at_header_checksum)));
  return writer.take_image();
}

std::vector<std::byte> finish_index(Writer& writer, IndexKind kind, std::uint64_t source) {
  return finish_image(writer, kind, source).join();
}

Error wrong_kind(IndexKind found, IndexKind wanted) {
  return corrupt(std::string("it holds a ") + to_string(found) + ", not a " + to_string(wanted));
}

}  // namespace index_bytes

// A sum of per-triangle hashes: the same for any order of the triangles.
std::uint64_t fingerprint(const Mesh& mesh) {
  std::uint64_t sum = 0;
  for (const TriangleIndices& t : mesh.triangles)
    sum += index_bytes::hash_triangle(mesh.vertex(t[0]), mesh.vertex(t[1]), mesh.vertex(t[2]));
  return index_bytes::finish_fingerprint(sum, mesh.triangles.size());
}

std::uint64_t fingerprint(std::span<const MultiPolygon> regions, Fill fill) {
  index_bytes::Writer w;
  w.put(static_cast<std::uint8_t>(fill));
  w.put<std::uint64_t>(regions.size());
  for (const MultiPolygon& region : regions) {
    w.put<std::uint64_t>(region.polygons.size());
    for (const Polygon& polygon : region.polygons) {
      w.put<std::uint64_t>(polygon.rings.size());
      for (const Ring& ring : polygon.rings)
        w.put_array<Vec2>(ring);
    }
  }
  return index_checksum(w.bytes());
}

Result<IndexHeader> parse_index_header(std::span<const std::byte> bytes) {
  if (bytes.size() < index_header_size || std::memcmp(bytes.data(), magic, sizeof magic) != 0)
    return corrupt("it does not start with the index magic (a foreign file?)");
  if (read_at<std::uint32_t>(bytes, at_order) != byte_order_mark)
    return corrupt("it was written on a machine of the other byte order");
  if (const auto version = read_at<std::uint32_t>(bytes, at_version);
      version != index_format_version) {
    return corrupt("format version " + std::to_string(version) + ", this build reads version " +
                   std::to_string(index_format_version) + " (build the index again)");
  }
  if (read_at<std::uint32_t>(bytes, at_layout) != layout)
    return corrupt("it was written on a machine with other sizes of double, size_t or pointers");
  if (read_at<std::uint64_t>(bytes, at_header_checksum) !=
      index_checksum(bytes.first(at_header_checksum)))
    return corrupt("the header's checksum does not match (the file is damaged)");
  const auto length = read_at<std::uint64_t>(bytes, at_length);
  if (length != bytes.size() - index_header_size) {
    return corrupt("the header says " + std::to_string(length) + " bytes of index, the file has " +
                   std::to_string(bytes.size() - index_header_size) + " (truncated?)");
  }
  const auto payload = bytes.subspan(index_header_size);
  if (read_at<std::uint64_t>(bytes, at_checksum) != index_checksum(payload))
    return corrupt("the checksum does not match (the file is damaged)");
  const auto kind = static_cast<IndexKind>(read_at<std::uint32_t>(bytes, at_kind));
  if (kind != IndexKind::mesh_index && kind != IndexKind::region_layer &&
      kind != IndexKind::polygon_index)
    return corrupt("unknown index kind " + std::to_string(static_cast<std::uint32_t>(kind)));
  return IndexHeader{kind, read_at<std::uint64_t>(bytes, at_source), payload};
}

}  // namespace contain::inside
