// Ring text written with std::to_chars into room reserved once per ring (src/io/ring_text.h).

#include "io/ring_text.h"

#include <array>
#include <charconv>
#include <cstddef>

namespace contain::io::detail {

namespace {

// The longest shortest form of a double: sign, 17 digits, point, "e-308": 24; with room.
constexpr std::size_t kMaxNumber = 32;

char* write_number(char* at, double value) {
  return std::to_chars(at, at + kMaxNumber, value).ptr;
}

}  // namespace

void append_ring_text(std::string& out, const Ring& ring, RingSyntax syntax) {
  const bool wkt = syntax == RingSyntax::wkt;
  out += wkt ? '(' : '[';
  // A point at a time into a buffer on the stack, appended once: no character appends, and no
  // room reserved (and zeroed) in `out` for the longest numbers.
  std::array<char, 2 * kMaxNumber + 8> point{};
  for (std::size_t i = 0; !ring.empty() && i <= ring.size(); ++i) {
    const Vec2& q = ring[i == ring.size() ? 0 : i];
    char* at = point.data();
    if (wkt) {
      if (i > 0) {
        *at++ = ',';
        *at++ = ' ';
      }
      at = write_number(at, q.x);
      *at++ = ' ';
      at = write_number(at, q.y);
    } else {
      if (i > 0) *at++ = ',';
      *at++ = '[';
      at = write_number(at, q.x);
      *at++ = ',';
      at = write_number(at, q.y);
      *at++ = ']';
    }
    out.append(point.data(), at);
  }
  out += wkt ? ')' : ']';
}

}  // namespace contain::io::detail
