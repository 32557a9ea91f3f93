#pragma once
// Shared by the libFuzzer targets: an invariant check that aborts (libFuzzer then saves the
// input), and a reader that turns fuzz bytes into finite coordinates biased towards degeneracy.

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "contain/values/vec.h"

// Aborts with the failed condition: libFuzzer reports a crash and writes the input out.
#define FUZZ_CHECK(cond)                                                                \
  do {                                                                                  \
    if (!(cond)) {                                                                      \
      std::fprintf(stderr, "%s:%d: invariant failed: %s\n", __FILE__, __LINE__, #cond); \
      std::abort();                                                                     \
    }                                                                                   \
  } while (0)

namespace contain::fuzz {

/// Reads fuzz bytes front to back; past the end every read gives zero, so any input decodes.
class FuzzInput {
 public:
  FuzzInput(const std::uint8_t* data, std::size_t size) : p_(data), end_(data + size) {}

  [[nodiscard]] bool empty() const { return p_ == end_; }
  [[nodiscard]] std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }

  std::uint8_t byte() { return p_ == end_ ? 0 : *p_++; }

  std::uint64_t bits64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i)
      v = (v << 8) | byte();
    return v;
  }

  /// An integer in [lo, hi] (hi - lo < 256).
  int small_int(int lo, int hi) { return lo + byte() % (hi - lo + 1); }

  /// Chooses once how the coordinates of a shape are scaled: by 2^k, which keeps every exact
  /// relation of the small-integer coordinates (collinear, coplanar, on an edge) as it is, so
  /// degenerate cases reach the huge and tiny ranges (1e300, 1e-300) too.
  void choose_scale() {
    const std::uint8_t s = byte();
    scale_exponent_ = s < 192 ? 0 : static_cast<int>(s % 63) * 32 - 1000;  // 2^-1000 .. 2^984
  }

  /// A finite coordinate: mostly small integers and quarters (so that points coincide, lie on
  /// lines and planes), sometimes a small integer nudged by one ulp-scale step, sometimes raw
  /// double bits (any finite value, subnormals included).
  double coordinate() {
    const std::uint8_t mode = byte();
    double v = 0.0;
    switch (mode % 8) {
      case 0:
      case 1:
      case 2:
      case 3:
        v = static_cast<double>(static_cast<int>(byte() % 17) - 8);
        break;
      case 4:
        v = static_cast<double>(static_cast<int>(byte()) - 128) / 4.0;
        break;
      case 5:
        v = static_cast<double>(static_cast<int>(byte() % 17) - 8) +
            std::ldexp(static_cast<double>(static_cast<int>(byte() % 5) - 2), -52);
        break;
      case 6: {
        v = std::bit_cast<double>(bits64());
        if (!std::isfinite(v)) v = 0.0;
        return v;  // raw bits are not rescaled
      }
      default:
        v = static_cast<double>(static_cast<int>(byte()) - 128) * 1024.0 + byte();
        break;
    }
    return scale_exponent_ == 0 ? v : std::ldexp(v, scale_exponent_);
  }

  Vec2 point2() { return {coordinate(), coordinate()}; }
  Vec3 point3() { return {coordinate(), coordinate(), coordinate()}; }

 private:
  const std::uint8_t* p_;
  const std::uint8_t* end_;
  int scale_exponent_ = 0;
};

}  // namespace contain::fuzz
