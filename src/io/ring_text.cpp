// Ring text, a point at a time through a stack buffer (write_double) (src/io/ring_text.h).

#include "io/ring_text.h"

#include <array>
#include <cstddef>

#include "io/text_scan.h"

namespace contain::io::detail {

void append_ring_text(std::string& out, const Ring& ring, RingSyntax syntax) {
  const bool wkt = syntax == RingSyntax::wkt;
  out += wkt ? '(' : '[';
  // A point at a time into a buffer on the stack, appended once: no character appends, and no
  // room reserved (and zeroed) in `out` for the longest numbers.
  std::array<char, 2 * kMaxDoubleChars + 8> point{};
  for (std::size_t i = 0; !ring.empty() && i <= ring.size(); ++i) {
    const Vec2& q = ring[i == ring.size() ? 0 : i];
    char* at = point.data();
    if (wkt) {
      if (i > 0) {
        *at++ = ',';
        *at++ = ' ';
      }
      at = write_double(at, q.x);
      *at++ = ' ';
      at = write_double(at, q.y);
    } else {
      if (i > 0) *at++ = ',';
      *at++ = '[';
      at = write_double(at, q.x);
      *at++ = ',';
      at = write_double(at, q.y);
      *at++ = ']';
    }
    out.append(point.data(), static_cast<std::size_t>(at - point.data()));
  }
  out += wkt ? ')' : ']';
}

}  // namespace contain::io::detail
