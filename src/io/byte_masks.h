#pragma once
/// \file
/// Private: the classes of a point file's bytes, 64 at a time, as bit masks (bit i: byte i of a
/// block), the first stage of the masked point scanner (io/masked_lines.h): the blanks (' ',
/// '\t', '\r', '\v', '\f': detail::is_blank), the newlines, and every byte that is not a decimal
/// digit (blanks, newlines, signs, points, letters, NUL, bytes above 127: all of them).
///
/// Versions: scalar (every build), SSE2 (the x86-64 baseline), AVX2 and AVX-512BW (chosen at run
/// time where the CPU has them; no -march needed). All give the same masks bit for bit (tested
/// on every byte value at every position); the scanner's results depend only on the masks.

#include <cstddef>
#include <cstdint>

namespace contain::io::detail {

/// The classes of 64 bytes (see the file comment).
struct ByteMasks {
  std::uint64_t blank = 0;
  std::uint64_t newline = 0;
  std::uint64_t non_digit = 0;
};

/// A version of classify_blocks.
enum class MaskIsa : std::uint8_t { scalar, sse2, avx2, avx512 };

/// Whether this build and this CPU run the version `isa`.
[[nodiscard]] bool mask_isa_available(MaskIsa isa);

/// The widest version this build and this CPU run, chosen once.
[[nodiscard]] MaskIsa best_mask_isa();

/// The masks of the `blocks` blocks of 64 bytes at `text` into `out[0..blocks)`, with the
/// version `isa` (the scalar one where it is not available).
void classify_blocks(const char* text, std::size_t blocks, ByteMasks* out, MaskIsa isa);

}  // namespace contain::io::detail
