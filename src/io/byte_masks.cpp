#include "io/byte_masks.h"

#include "io/text_scan.h"

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#define CONTAIN_BYTE_MASKS_X86 1
#endif

namespace contain::io::detail {
namespace {

void classify_scalar(const char* text, std::size_t blocks, ByteMasks* out) {
  for (std::size_t b = 0; b < blocks; ++b) {
    ByteMasks m;
    for (int i = 0; i < 64; ++i) {
      const char c = text[64 * b + static_cast<std::size_t>(i)];
      const std::uint64_t bit = std::uint64_t{1} << i;
      if (c == '\n') m.newline |= bit;
      if (is_blank(c)) m.blank |= bit;
      if (static_cast<unsigned char>(c - '0') >= 10) m.non_digit |= bit;
    }
    out[b] = m;
  }
}

#if defined(CONTAIN_BYTE_MASKS_X86)
// Unsigned x - lo <= span, as min(x - lo, span) == x - lo, tests a range of byte values in three
// instructions (SSE2 and AVX2 have no unsigned byte compare). Blanks: ' ' and '\t' .. '\r' but
// '\n'. Helpers, not lambdas: a lambda does not take its function's target.
[[gnu::always_inline]] inline __m128i within16(__m128i v, char lo, char span) {
  const __m128i t = _mm_sub_epi8(v, _mm_set1_epi8(lo));
  return _mm_cmpeq_epi8(_mm_min_epu8(t, _mm_set1_epi8(span)), t);
}
[[gnu::always_inline]] inline std::uint64_t bits16(__m128i m) {
  return static_cast<std::uint64_t>(static_cast<unsigned>(_mm_movemask_epi8(m)));
}

void classify_sse2(const char* text, std::size_t blocks, ByteMasks* out) {
  for (std::size_t b = 0; b < blocks; ++b) {
    ByteMasks m;
    for (int q = 0; q < 4; ++q) {
      const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(text + 64 * b + 16 * q));
      const __m128i newline = _mm_cmpeq_epi8(v, _mm_set1_epi8('\n'));
      const __m128i blank = _mm_or_si128(_mm_andnot_si128(newline, within16(v, '\t', 4)),
                                         _mm_cmpeq_epi8(v, _mm_set1_epi8(' ')));
      const int shift = 16 * q;
      m.blank |= bits16(blank) << shift;
      m.newline |= bits16(newline) << shift;
      m.non_digit |= (~bits16(within16(v, '0', 9)) & 0xffffu) << shift;
    }
    out[b] = m;
  }
}

[[gnu::target("avx2"), gnu::always_inline]] inline __m256i within32(__m256i v, char lo, char span) {
  const __m256i t = _mm256_sub_epi8(v, _mm256_set1_epi8(lo));
  return _mm256_cmpeq_epi8(_mm256_min_epu8(t, _mm256_set1_epi8(span)), t);
}
[[gnu::target("avx2"), gnu::always_inline]] inline std::uint64_t bits32(__m256i m) {
  return std::uint64_t{static_cast<std::uint32_t>(_mm256_movemask_epi8(m))};
}

// classify_sse2 on 32 bytes a step.
[[gnu::target("avx2")]] void classify_avx2(const char* text, std::size_t blocks, ByteMasks* out) {
  for (std::size_t b = 0; b < blocks; ++b) {
    ByteMasks m;
    for (int h = 0; h < 2; ++h) {
      const __m256i v =
          _mm256_loadu_si256(reinterpret_cast<const __m256i*>(text + 64 * b + 32 * h));
      const __m256i newline = _mm256_cmpeq_epi8(v, _mm256_set1_epi8('\n'));
      const __m256i blank = _mm256_or_si256(_mm256_andnot_si256(newline, within32(v, '\t', 4)),
                                            _mm256_cmpeq_epi8(v, _mm256_set1_epi8(' ')));
      const int shift = 32 * h;
      m.blank |= bits32(blank) << shift;
      m.newline |= bits32(newline) << shift;
      m.non_digit |= (~bits32(within32(v, '0', 9)) & 0xffffffffu) << shift;
    }
    out[b] = m;
  }
}

// The same with 64 bytes a step, the compares giving the masks themselves (AVX-512BW).
[[gnu::target("avx512bw")]] void classify_avx512(const char* text, std::size_t blocks,
                                                 ByteMasks* out) {
  const __m512i zero = _mm512_set1_epi8('0'), tab = _mm512_set1_epi8('\t');
  const __m512i nine = _mm512_set1_epi8(9), four = _mm512_set1_epi8(4);
  const __m512i newline_byte = _mm512_set1_epi8('\n'), space = _mm512_set1_epi8(' ');
  for (std::size_t b = 0; b < blocks; ++b) {
    const __m512i v = _mm512_loadu_si512(text + 64 * b);
    const __mmask64 newline = _mm512_cmpeq_epi8_mask(v, newline_byte);
    const __mmask64 controls = _mm512_cmple_epu8_mask(_mm512_sub_epi8(v, tab), four);
    const __mmask64 blank = (controls & ~newline) | _mm512_cmpeq_epi8_mask(v, space);
    const __mmask64 digit = _mm512_cmple_epu8_mask(_mm512_sub_epi8(v, zero), nine);
    out[b] = {.blank = blank, .newline = newline, .non_digit = ~digit};
  }
}
#endif

}  // namespace

bool mask_isa_available(MaskIsa isa) {
  switch (isa) {
    case MaskIsa::scalar:
      return true;
#if defined(CONTAIN_BYTE_MASKS_X86)
    case MaskIsa::sse2:
      return __builtin_cpu_supports("sse2");
    case MaskIsa::avx2:
      return __builtin_cpu_supports("avx2");
    case MaskIsa::avx512:
      return __builtin_cpu_supports("avx512bw");
#endif
    default:
      return false;
  }
}

MaskIsa best_mask_isa() {
  static const MaskIsa best = [] {
    for (MaskIsa isa : {MaskIsa::avx512, MaskIsa::avx2, MaskIsa::sse2}) {
      if (mask_isa_available(isa)) return isa;
    }
    return MaskIsa::scalar;
  }();
  return best;
}

void classify_blocks(const char* text, std::size_t blocks, ByteMasks* out, MaskIsa isa) {
#if defined(CONTAIN_BYTE_MASKS_X86)
  if (mask_isa_available(isa)) {
    switch (isa) {
      case MaskIsa::avx512:
        return classify_avx512(text, blocks, out);
      case MaskIsa::avx2:
        return classify_avx2(text, blocks, out);
      case MaskIsa::sse2:
        return classify_sse2(text, blocks, out);
      default:
        break;
    }
  }
#endif
  (void)isa;
  classify_scalar(text, blocks, out);
}

}  // namespace contain::io::detail
