// Ring text written with std::to_chars into room reserved once per ring (src/io/ring_text.h).

#include "io/ring_text.h"

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
  const std::size_t old = out.size();
  // Per point two numbers and at most 5 characters around them; the brackets of the ring.
  out.resize(old + (ring.size() + 1) * (2 * kMaxNumber + 5) + 2);
  char* at = out.data() + old;
  *at++ = wkt ? '(' : '[';
  for (std::size_t i = 0; !ring.empty() && i <= ring.size(); ++i) {
    const Vec2& q = ring[i == ring.size() ? 0 : i];
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
  }
  *at++ = wkt ? ')' : ']';
  out.resize(static_cast<std::size_t>(at - out.data()));
}

}  // namespace contain::io::detail
