#include "contain/io/wkb.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace contain::io {
namespace {

// The geometry types of ISO 19125-1 §8.2.3 (the value modulo 1000 of an ISO code).
constexpr std::uint32_t kPolygon = 3;
constexpr std::uint32_t kMultiPolygon = 6;
constexpr std::uint32_t kCollection = 7;

// EWKB flag bits (PostGIS): set in the high bits of the type code.
constexpr std::uint32_t kEwkbZ = 0x80000000u;
constexpr std::uint32_t kEwkbM = 0x40000000u;
constexpr std::uint32_t kEwkbSrid = 0x20000000u;

// Collections may nest; a hostile input must not exhaust the stack.
constexpr int kMaxDepth = 64;

// std::byteswap is C++23.
std::uint32_t swap_bytes(std::uint32_t v) {
  return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}
std::uint64_t swap_bytes(std::uint64_t v) {
  return (static_cast<std::uint64_t>(swap_bytes(static_cast<std::uint32_t>(v))) << 32) |
         swap_bytes(static_cast<std::uint32_t>(v >> 32));
}

const char* type_name(std::uint32_t type) {
  switch (type) {
    case 1:
      return "Point";
    case 2:
      return "LineString";
    case 4:
      return "MultiPoint";
    case 5:
      return "MultiLineString";
    case 8:
      return "CircularString";
    case 9:
      return "CompoundCurve";
    case 10:
      return "CurvePolygon";
    case 11:
      return "MultiCurve";
    case 12:
      return "MultiSurface";
    case 15:
      return "PolyhedralSurface";
    case 16:
      return "TIN";
    case 17:
      return "Triangle";
    default:
      return nullptr;
  }
}

class WkbReader {
 public:
  WkbReader(std::string_view bytes, const std::string& source) : bytes_(bytes), source_(source) {}

  Result<MultiPolygon> read() {
    if (bytes_.empty()) return fail(ErrorKind::parse, "the input is empty: expected WKB");
    MultiPolygon region;
    if (auto s = geometry(region, 0, /*inside_multi=*/false); !s) return s.error();
    if (at_ != bytes_.size()) {
      return fail(ErrorKind::parse,
                  std::to_string(bytes_.size() - at_) + " bytes after the end of the geometry");
    }
    return region;
  }

 private:
  struct Header {
    std::uint32_t type = 0;  // 1..17
    int ordinates = 2;       // 2, 3 or 4 numbers a position
  };

  Error error(ErrorKind kind, const std::string& message) const {
    return Error{
        .kind = kind, .message = "byte " + std::to_string(at_) + ": " + message, .source = source_};
  }
  Result<MultiPolygon> fail(ErrorKind kind, const std::string& message) const {
    return error(kind, message);
  }

  bool need(std::size_t count, Error& out) const {
    if (bytes_.size() - at_ >= count) return true;
    out = error(ErrorKind::parse, "truncated: expected " + std::to_string(count) +
                                      " more bytes, found " + std::to_string(bytes_.size() - at_));
    return false;
  }

  std::uint32_t u32() {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes_.data() + at_, 4);
    at_ += 4;
    return swap_ ? swap_bytes(v) : v;
  }

  double f64() {
    std::uint64_t v = 0;
    std::memcpy(&v, bytes_.data() + at_, 8);
    at_ += 8;
    return std::bit_cast<double>(swap_ ? swap_bytes(v) : v);
  }

  Result<Header> header() {
    Error e;
    if (!need(5, e)) return e;
    const auto order = static_cast<unsigned char>(bytes_[at_]);
    if (order > 1) {
      return error(
          ErrorKind::parse,
          "byte order must be 0 (big endian) or 1 (little endian), found " + std::to_string(order));
    }
    ++at_;
    swap_ = (order == 1) != (std::endian::native == std::endian::little);
    std::uint32_t code = u32();
    Header h;
    if (code & kEwkbZ) ++h.ordinates;
    if (code & kEwkbM) ++h.ordinates;
    if (code & kEwkbSrid) {
      if (!need(4, e)) return e;
      (void)u32();  // the SRID: a region is plain coordinates
    }
    code &= ~(kEwkbZ | kEwkbM | kEwkbSrid);
    const std::uint32_t dims = code / 1000;  // ISO: 1 Z, 2 M, 3 ZM
    if (dims > 3)
      return error(ErrorKind::parse, "unknown geometry type code " + std::to_string(code));
    h.ordinates += dims == 3 ? 2 : (dims > 0 ? 1 : 0);
    h.type = code % 1000;
    return h;
  }

  Status geometry(MultiPolygon& region, int depth, bool inside_multi) {
    if (depth > kMaxDepth) {
      return error(ErrorKind::unsupported,
                   "collections nested deeper than " + std::to_string(kMaxDepth));
    }
    const std::size_t start = at_;
    auto h = header();
    if (!h) return h.error();
    if (h->type == kPolygon) return polygon(region, h->ordinates);
    if (inside_multi) {
      at_ = start;
      return error(ErrorKind::parse, "a MultiPolygon may hold only Polygons");
    }
    if (h->type == kMultiPolygon || h->type == kCollection) {
      Error e;
      if (!need(4, e)) return e;
      const std::uint32_t count = u32();
      // Each member takes at least 9 bytes (an empty polygon): a count beyond that is a lie.
      if (count > (bytes_.size() - at_) / 9) {
        return error(ErrorKind::parse, std::to_string(count) + " members cannot fit in the " +
                                           std::to_string(bytes_.size() - at_) + " bytes left");
      }
      for (std::uint32_t i = 0; i < count; ++i) {
        if (auto s = geometry(region, depth + 1, h->type == kMultiPolygon); !s) return s;
      }
      return Ok{};
    }
    at_ = start;
    const char* name = type_name(h->type);
    if (name != nullptr) {
      return error(ErrorKind::unsupported,
                   std::string(name) + " is not a region: expected Polygon or MultiPolygon");
    }
    return error(ErrorKind::parse, "unknown geometry type " + std::to_string(h->type));
  }

  Status polygon(MultiPolygon& region, int ordinates) {
    Error e;
    if (!need(4, e)) return e;
    const std::uint32_t ring_count = u32();
    if (ring_count > (bytes_.size() - at_) / 4) {
      return error(ErrorKind::parse, std::to_string(ring_count) + " rings cannot fit in the " +
                                         std::to_string(bytes_.size() - at_) + " bytes left");
    }
    std::vector<Ring> rings;
    const std::size_t position_bytes = 8 * static_cast<std::size_t>(ordinates);
    for (std::uint32_t r = 0; r < ring_count; ++r) {
      if (!need(4, e)) return e;
      const std::uint32_t points = u32();
      if (points > (bytes_.size() - at_) / position_bytes) {
        return error(ErrorKind::parse, "a ring of " + std::to_string(points) +
                                           " points cannot fit in the " +
                                           std::to_string(bytes_.size() - at_) + " bytes left");
      }
      Ring ring;
      ring.reserve(points);
      for (std::uint32_t k = 0; k < points; ++k) {
        const std::size_t here = at_;
        const double x = f64(), y = f64();
        at_ += position_bytes - 16;  // z, m
        if (!std::isfinite(x) || !std::isfinite(y)) {
          at_ = here;
          return error(ErrorKind::invalid_value, "a coordinate is NaN or infinite");
        }
        ring.push_back({x, y});
      }
      if (!ring.empty()) rings.push_back(std::move(ring));  // an EMPTY ring gives nothing
    }
    if (rings.empty()) return Ok{};
    auto made = Polygon::from_rings(std::move(rings));
    if (!made) return error(made.error().kind, made.error().message);
    region.polygons.push_back(std::move(made).value());
    return Ok{};
  }

  std::string_view bytes_;
  const std::string& source_;
  std::size_t at_ = 0;
  bool swap_ = false;
};

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Hex text is printable; WKB starts with the byte 0 or 1, never a hex digit's character.
bool looks_hex(std::string_view text) {
  return !text.empty() && hex_digit(text.front()) >= 0;
}

void put_u32(std::string& out, std::uint32_t v) {
  if constexpr (std::endian::native == std::endian::big) v = swap_bytes(v);
  char b[4];
  std::memcpy(b, &v, 4);
  out.append(b, 4);
}

void put_f64(std::string& out, double d) {
  auto v = std::bit_cast<std::uint64_t>(d);
  if constexpr (std::endian::native == std::endian::big) v = swap_bytes(v);
  char b[8];
  std::memcpy(b, &v, 8);
  out.append(b, 8);
}

void put_polygon(std::string& out, const Polygon& polygon) {
  out.push_back('\x01');
  put_u32(out, kPolygon);
  put_u32(out, static_cast<std::uint32_t>(polygon.rings.size()));
  for (const Ring& ring : polygon.rings) {
    // A stored ring is open: the closing point is always written, as the WKT writer does. A ring
    // that still ends on its first point (read from a doubled closing point) thus reads back the
    // same, bit for bit (fuzz_wkb found the writer dropping it).
    if (ring.empty()) {
      put_u32(out, 0);
      continue;
    }
    put_u32(out, static_cast<std::uint32_t>(ring.size() + 1));
    for (const Vec2& p : ring) {
      put_f64(out, p.x);
      put_f64(out, p.y);
    }
    put_f64(out, ring.front().x);
    put_f64(out, ring.front().y);
  }
}

}  // namespace

Result<MultiPolygon> parse_wkb(std::string_view bytes, const std::string& source) {
  if (!looks_hex(bytes)) return WkbReader(bytes, source).read();
  if (bytes.size() % 2 != 0) {
    return Error{
        .kind = ErrorKind::parse,
        .message = "hex WKB has an odd number of digits (" + std::to_string(bytes.size()) + ")",
        .source = source};
  }
  std::string binary(bytes.size() / 2, '\0');
  for (std::size_t i = 0; i < binary.size(); ++i) {
    const int hi = hex_digit(bytes[2 * i]), lo = hex_digit(bytes[2 * i + 1]);
    if (hi < 0 || lo < 0) {
      return Error{.kind = ErrorKind::parse,
                   .message = "hex WKB: character " + std::to_string(2 * i + (hi < 0 ? 0 : 1)) +
                              " is not a hexadecimal digit",
                   .source = source};
    }
    binary[i] = static_cast<char>(hi * 16 + lo);
  }
  return WkbReader(binary, source).read();
}

std::string format_wkb(const MultiPolygon& region) {
  std::string out;
  std::size_t count = 0;
  for (const Polygon& polygon : region.polygons)
    count += polygon.rings.empty() ? 0 : 1;
  out.push_back('\x01');
  put_u32(out, kMultiPolygon);
  put_u32(out, static_cast<std::uint32_t>(count));
  for (const Polygon& polygon : region.polygons) {
    if (!polygon.rings.empty()) put_polygon(out, polygon);
  }
  return out;
}

std::string format_wkb(const Polygon& polygon) {
  std::string out;
  put_polygon(out, polygon);
  return out;
}

}  // namespace contain::io
