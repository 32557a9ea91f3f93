// libFuzzer target: loading a saved index (inside::parse_mesh_index, parse_region_layer) on any
// payload. The first byte chooses: 0 the bytes as a whole file (header checks), 1 a mesh index's
// payload, 2 a layer's, 3 a polygon index's, framed under a correct header with correct checksums,
// so that the mutations reach the payload's own checks instead of failing the checksum. A payload
// is refused with a message or loads an index that answers without reading out of bounds (ASan),
// and that saves and loads again to the same answers.
#include <cstring>
#include <vector>

#include "contain/inside/index_file.h"
#include "fuzz_support.h"

namespace {

using contain::inside::IndexKind;

std::vector<std::byte> framed(const std::uint8_t* payload, std::size_t size, IndexKind kind) {
  std::vector<std::byte> bytes(contain::inside::index_header_size + size);
  const char magic[8] = {'c', 'o', 'n', 't', 'a', 'i', 'n', '\x1a'};
  const std::uint32_t head[4] = {
      contain::inside::index_format_version, 0x01020304, static_cast<std::uint32_t>(kind),
      sizeof(double) | (sizeof(std::size_t) << 8) | (sizeof(void*) << 16)};
  std::memcpy(bytes.data(), magic, 8);
  std::memcpy(bytes.data() + 8, head, 16);
  const std::uint64_t length = size;
  std::memcpy(bytes.data() + 32, &length, 8);
  if (size > 0) std::memcpy(bytes.data() + 64, payload, size);
  const std::uint64_t sum =
      contain::inside::index_checksum(std::span<const std::byte>(bytes).subspan(64));
  std::memcpy(bytes.data() + 40, &sum, 8);
  const std::uint64_t head_sum =
      contain::inside::index_checksum(std::span<const std::byte>(bytes).first(56));
  std::memcpy(bytes.data() + 56, &head_sum, 8);
  return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t mode = data[0] % 4;
  const std::vector<std::byte> bytes =
      mode == 0 ? std::vector<std::byte>(reinterpret_cast<const std::byte*>(data) + 1,
                                         reinterpret_cast<const std::byte*>(data) + size)
                : framed(data + 1, size - 1,
                         mode == 1   ? IndexKind::mesh_index
                         : mode == 2 ? IndexKind::region_layer
                                     : IndexKind::polygon_index);
  contain::fuzz::FuzzInput in(data, size);
  if (mode == 3) {
    auto index = contain::inside::parse_polygon_index(bytes);
    if (!index) {
      FUZZ_CHECK(!index.error().message.empty());
      return 0;
    }
    auto again = contain::inside::parse_polygon_index(contain::inside::format_index(*index, 0));
    FUZZ_CHECK(again.ok());
    for (int i = 0; i < 16; ++i) {
      const contain::Vec2 p{in.coordinate(), in.coordinate()};
      FUZZ_CHECK(index->locate(p) == again->locate(p));
    }
    return 0;
  }
  if (mode != 2) {
    auto index = contain::inside::parse_mesh_index(bytes);
    if (!index) {
      FUZZ_CHECK(!index.error().message.empty());
      return 0;
    }
    auto again = contain::inside::parse_mesh_index(contain::inside::format_index(*index));
    FUZZ_CHECK(again.ok());
    for (int i = 0; i < 16; ++i) {
      const contain::Vec3 p{in.coordinate(), in.coordinate(), in.coordinate()};
      FUZZ_CHECK(index->locate(p) == again->locate(p));
    }
    return 0;
  }
  auto saved = contain::inside::parse_region_layer(bytes);
  if (!saved) {
    FUZZ_CHECK(!saved.error().message.empty());
    return 0;
  }
  auto again = contain::inside::parse_region_layer(
      contain::inside::format_index(saved->layer, saved->source, saved->ids));
  FUZZ_CHECK(again.ok());
  for (int i = 0; i < 16; ++i) {
    const contain::Vec2 p{in.coordinate(), in.coordinate()};
    FUZZ_CHECK(saved->layer.locate(p) == again->layer.locate(p));
  }
  return 0;
}
