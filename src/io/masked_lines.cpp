#include "io/masked_lines.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>

#include "io/number_bound.h"

namespace contain::io::detail {
namespace {

// Blocks of 64 bytes classified at a time: 16 KB of text, 6 KB of masks (in the L1 cache).
constexpr std::size_t kMaskBlocks = 256;
// Bytes a taken line may read past its first: the 64 of its window and the 8 of a load at its
// last byte (the fraction's digits of its last token).
constexpr std::size_t kLineReach = 64 + 8;
// How far ahead of a line its text is fetched: the masks' next blocks.
constexpr std::size_t kPrefetchAhead = 64 * kMaskBlocks;

// The 64 bits of `field` from bit `shift` of block `block` on (the rest from the next block).
[[gnu::always_inline]] inline std::uint64_t window(const ByteMasks* masks,
                                                   std::uint64_t ByteMasks::*field,
                                                   std::size_t block, unsigned shift) {
  // (x << 1) << (63 - shift): no shift by 64 when `shift` is 0.
  return masks[block].*field >> shift | (masks[block + 1].*field << 1) << (63 - shift);
}

// The digits of the tokens of the staged points (below), bounded together when they are handed
// over: a loop the compiler vectorizes, four tokens an instruction with AVX2 and eight with
// AVX-512DQ (its 64-bit multiplies; AVX2's are built of 32-bit ones). Each lane does
// bound_from_digits' operations (number_bound.h) on eight_digits' of the fraction: the sign as a
// factor of +-1, std::min and std::max spelled as their comparisons; no a * b + c to contract
// into FMA. So the same bits as one token at a time (the tests compare every version with
// scan_bounded_lines).
struct TokenDigits {
  static constexpr int kRoom = 96;      // 32 points of 3 numbers
  std::uint64_t whole[kRoom];           // the integer part
  std::uint64_t fraction_bytes[kRoom];  // the fraction's first 8 bytes, digits padded with '0'
  double sign[kRoom];                   // -1 or 1
  double lo[kRoom], hi[kRoom];
};

[[gnu::always_inline]] inline void bound_digits(TokenDigits& d, int count) {
  for (int i = 0; i < count; ++i) {
    const std::uint64_t m = d.whole[i] * 100000000u + eight_digits(d.fraction_bytes[i]);
    // m < 10^15 < 2^52: the double of exponent 52 whose low mantissa bits are m, less 2^52, is
    // m exactly (the conversion of every version, AVX2 having no 64-bit integer to double).
    const double value = std::bit_cast<double>(m | std::uint64_t{0x4330000000000000}) - 0x1p52;
    const double lo = value * kLowScale, hi = (value + 1.0) * kHighScale;
    const double a = d.sign[i] * lo, b = d.sign[i] * hi;
    d.lo[i] = b < a ? b : a;  // std::min(a, b)
    d.hi[i] = a < b ? b : a;  // std::max(a, b)
  }
}

void bound_digits_baseline(TokenDigits& d, int count) {
  bound_digits(d, count);
}
#if defined(__GNUC__) && defined(__x86_64__)
// GCC vectorizes from -O3 on; the portable bench preset builds with -O2.
#if defined(__clang__)
[[gnu::target("avx512f,avx512dq,avx512vl")]]
#else
[[gnu::target("avx512f,avx512dq,avx512vl"), gnu::optimize("tree-vectorize")]]
#endif
void bound_digits_avx512(TokenDigits& d, int count) {
  bound_digits(d, count);
}
#if defined(__clang__)
[[gnu::target("avx2")]]
#else
[[gnu::target("avx2"), gnu::optimize("tree-vectorize")]]
#endif
void bound_digits_avx2(TokenDigits& d, int count) {
  bound_digits(d, count);
}
#endif
using BoundDigits = void (*)(TokenDigits&, int);

// Stores the digits of a plain token of the line at `line` (its digits from `digits_at`, after
// its minus when `negative`; its point at `dot`; its last byte at `last`) as token `i`.
[[gnu::always_inline]] inline void store_token(TokenDigits& d, int i, const char* line,
                                               unsigned digits_at, unsigned dot, unsigned last,
                                               bool negative) {
  const auto whole_count = static_cast<int>(dot - digits_at);  // 1 to 7
  std::uint64_t whole = static_cast<unsigned char>(line[digits_at]) - std::uint64_t{'0'};
  if (whole_count > 1) {  // rare in most files (coordinates below 10): a branch predicted well
    const int pad = 8 - whole_count;  // leading zeros, 1 to 6
    const std::uint64_t zeros = (std::uint64_t{1} << (8 * pad)) - 1;
    whole = eight_digits(load8(line + digits_at) << (8 * pad) | (0x3030303030303030u & zeros));
  }
  const auto fraction_count = static_cast<int>(last - dot);  // 1 or more
  d.whole[i] = whole;
  d.fraction_bytes[i] = padded_fraction_bytes(load8(line + dot + 1), fraction_count);
  // -1.0 or 1.0 without a branch (random signs mispredict half the time): 1.0 with the sign bit.
  d.sign[i] = std::bit_cast<double>(std::uint64_t{0x3ff0000000000000} |
                                    static_cast<std::uint64_t>(negative) << 63);
}

// Whether `bits` has exactly `count` (1 or more) bits set: without a population count, which the
// x86-64 baseline has not (it is a call to libgcc there).
template <int kCount>
[[gnu::always_inline]] inline bool has_bits(std::uint64_t bits) {
  for (int k = 1; k < kCount; ++k)
    bits &= bits - 1;
  return bits != 0 && (bits & (bits - 1)) == 0;
}

// Where a scan's points go: appended to a vector, or handed to a sink a run at a time. `walk`
// takes lines the masks left to scan_bounded_lines.
template <class Point>
struct VectorOutput {
  using Bounded = Point;
  std::vector<Bounded>& points;
  void append(const Bounded* first, int count) {
    points.insert(points.end(), first, first + count);
  }
  PointLinesScan walk(std::string_view text) { return scan_bounded_lines(text, points); }
};
template <class Point>
struct SinkOutput {
  using Bounded = Point;
  const BoundedSink<Bounded>& sink;
  void append(const Bounded* first, int count) {
    if (count > 0) sink.take(sink.context, {first, static_cast<std::size_t>(count)});
  }
  PointLinesScan walk(std::string_view text) {
    return scan_bounded_runs<Bounded>(
        text, [this](std::span<const Bounded> run) { sink.take(sink.context, run); });
  }
};

// Points taken by the masks, staged in a small array with their tokens' digits, and handed over a
// run at a time with their boxes: a vector's emplace_back in the scan's loop is a call (too large
// a function for the compiler to inline it), and the boxes are bounded together (TokenDigits).
template <class Output>
struct StagedPoints {
  using Bounded = typename Output::Bounded;
  static constexpr int kColumns = std::is_same_v<Bounded, BoundedPoint2> ? 2 : 3;
  static constexpr int kRoom = TokenDigits::kRoom / 3;
  Bounded staged[kRoom];
  TokenDigits digits;
  int held = 0;
  Output& output;
  BoundDigits bound;

  void flush() {
    bound(digits, kColumns * held);
    for (int i = 0; i < held; ++i) {
      const double* lo = digits.lo + kColumns * i;
      const double* hi = digits.hi + kColumns * i;
      if constexpr (kColumns == 2) {
        staged[i].box = {{lo[0], lo[1]}, {hi[0], hi[1]}};
      } else {
        staged[i].box = {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
      }
    }
    output.append(staged, held);
    held = 0;
  }
};

template <class Output>
[[gnu::always_inline]] inline PointLinesScan scan_masked(std::string_view text, Output& output,
                                                         MaskIsa isa, BoundDigits bound,
                                                         std::int64_t* walked) {
  using Bounded = typename Output::Bounded;
  constexpr int kColumns = std::is_same_v<Bounded, BoundedPoint2> ? 2 : 3;
  PointLinesScan scan;
  const char* const base = text.data();
  const std::size_t size = text.size();
  StagedPoints<Output> out{.output = output, .bound = bound};
  // Lines taken by the masks and left to the walk: a text of which more than a third goes to the
  // walk (commas, comments, exponents) is walked from there on, whole, as without masks (a line
  // walked alone costs the masks and a call more than in the walk of the whole text).
  std::int64_t taken_lines = 0, walked_lines = 0;
  // The lines of [from, to) by the exact walk, taken into the scan; false where it stopped.
  const auto walk = [&](std::size_t from, std::size_t to) {
    out.flush();
    const PointLinesScan part = output.walk(text.substr(from, to - from));
    if (scan.first_row == 0 && part.first_row != 0) scan.first_row = scan.lines + part.first_row;
    scan.lines += part.lines;
    walked_lines += part.lines;
    if (walked != nullptr) *walked += part.lines;
    return part.complete;
  };
  ByteMasks masks[kMaskBlocks];
  std::size_t held_from = 0, held = 0;  // the masks of blocks [held_from, held_from + held)
  const std::size_t whole_blocks = size / 64;
  std::size_t at = 0;  // the line's first byte
  while (size - at >= kLineReach && walked_lines <= taken_lines / 2 + 16) {
    const std::size_t block = at / 64;
    if (block + 2 > whole_blocks) break;
    if (block + 2 > held_from + held) {
      held_from = block;
      held = std::min(kMaskBlocks, whole_blocks - block);
      classify_blocks(base + 64 * block, held, masks, isa);
    }
    const std::size_t b = block - held_from;
    const auto shift = static_cast<unsigned>(at % 64);
    const char* const line = base + at;
    // The text of the next masks' blocks on its way from memory while this block's lines are
    // read (a mapped file is not in the cache: reading it would wait on every line of it).
    __builtin_prefetch(line + std::min(kPrefetchAhead, size - at));
    const std::uint64_t newlines = window(masks, &ByteMasks::newline, b, shift);
    if (newlines == 0) {  // a line of 64 bytes or more
      const void* newline = std::memchr(line, '\n', size - at);
      const std::size_t to =
          newline == nullptr
              ? size
              : static_cast<std::size_t>(static_cast<const char*>(newline) - base) + 1;
      if (!walk(at, to)) return scan;
      at = to;
      continue;
    }
    const auto length = static_cast<unsigned>(std::countr_zero(newlines));
    const std::uint64_t in_line = (std::uint64_t{1} << length) - 1;
    const std::uint64_t tokens = ~window(masks, &ByteMasks::blank, b, shift) & in_line;
    if (tokens == 0) {  // blanks only
      ++scan.lines;
      ++taken_lines;
      at += length + 1;
      continue;
    }
    const std::uint64_t starts = tokens & ~(tokens << 1);
    const std::uint64_t ends = tokens & ~(tokens >> 1);  // the last byte of each token
    // Not digits: signs, points, blanks, the newline and every other byte.
    const std::uint64_t non_digit = window(masks, &ByteMasks::non_digit, b, shift);
    bool taken = has_bits<kColumns>(starts);
    unsigned first = 0, last = 0;
    if (taken) {
      if (out.held == out.kRoom) out.flush();
      std::uint64_t next_start = starts, next_end = ends;
#pragma GCC unroll 3
      for (int k = 0; k < kColumns; ++k) {
        const auto s = static_cast<unsigned>(std::countr_zero(next_start));
        const auto e = static_cast<unsigned>(std::countr_zero(next_end));
        next_start &= next_start - 1;
        next_end &= next_end - 1;
        const bool negative = line[s] == '-';
        const unsigned digits_at = s + (negative ? 1u : 0u);
        // The first byte not a digit from there on (the blank or newline past the token at the
        // latest), which must be the point: 1 to 7 digits before it, at least one after it, and
        // only digits after it to the token's end.
        const auto dot =
            digits_at + static_cast<unsigned>(std::countr_zero(non_digit >> digits_at));
        if (dot <= digits_at || dot > digits_at + 7 || dot >= e || line[dot] != '.' ||
            ((non_digit >> (dot + 1)) & ((std::uint64_t{1} << (e - dot)) - 1)) != 0) {
          taken = false;
          break;
        }
        store_token(out.digits, kColumns * out.held + k, line, digits_at, dot, e, negative);
        if (k == 0) first = s;
        last = e + 1;
      }
    }
    if (!taken) {
      if (!walk(at, at + length + 1)) return scan;
      at += length + 1;
      continue;
    }
    Bounded& point = out.staged[out.held++];  // its box at the flush
    point.first = line + first;
    point.last = line + last;
    ++scan.lines;
    ++taken_lines;
    if (scan.first_row == 0) scan.first_row = scan.lines;
    at += length + 1;
  }
  scan.complete = walk(at, size);
  return scan;
}

// The scan compiled twice: for the x86-64 baseline, and where the masks are AVX2's or wider, with
// the bit instructions those CPUs have (tzcnt, blsr, shifts by a register in one micro-op: shlx,
// shrx; the baseline's shift by cl is three). The same results: only the instructions differ
// (the tests run both).
template <class Output>
PointLinesScan scan_baseline(std::string_view text, Output& output, MaskIsa isa,
                             std::int64_t* walked) {
  return scan_masked(text, output, isa, &bound_digits_baseline, walked);
}

#if defined(__GNUC__) && defined(__x86_64__)
bool has_avx512_dq_vl() {
  static const bool has = __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl");
  return has;
}

bool has_bit_instructions() {
  static const bool has = __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2") &&
                          __builtin_cpu_supports("popcnt");
  return has;
}

template <class Output>
[[gnu::target("bmi,bmi2,popcnt")]] PointLinesScan scan_bit_instructions(std::string_view text,
                                                                        Output& output, MaskIsa isa,
                                                                        std::int64_t* walked) {
  // The boxes eight at a time where the CPU has AVX-512DQ, else four (AVX2: the masks' versions
  // that come here are AVX2's or wider).
  const BoundDigits bound = isa == MaskIsa::avx512 && mask_isa_available(isa) && has_avx512_dq_vl()
                                ? &bound_digits_avx512
                            : mask_isa_available(MaskIsa::avx2) ? &bound_digits_avx2
                                                                : &bound_digits_baseline;
  return scan_masked(text, output, isa, bound, walked);
}

#endif

template <class Output>
PointLinesScan scan_dispatched(std::string_view text, Output&& output, MaskIsa isa,
                               std::int64_t* walked) {
#if defined(__GNUC__) && defined(__x86_64__)
  if ((isa == MaskIsa::avx2 || isa == MaskIsa::avx512) && mask_isa_available(isa) &&
      has_bit_instructions()) {
    return scan_bit_instructions(text, output, isa, walked);
  }
#endif
  return scan_baseline(text, output, isa, walked);
}

}  // namespace

bool masked_scan_pays() {
#if defined(__GNUC__) && defined(__x86_64__)
  return (best_mask_isa() == MaskIsa::avx2 || best_mask_isa() == MaskIsa::avx512) &&
         has_bit_instructions();
#else
  return false;
#endif
}

PointLinesScan scan_bounded_masked(std::string_view text, std::vector<BoundedPoint2>& points,
                                   MaskIsa isa, std::int64_t* walked) {
  return scan_dispatched(text, VectorOutput<BoundedPoint2>{points}, isa, walked);
}
PointLinesScan scan_bounded_masked(std::string_view text, std::vector<BoundedPoint3>& points,
                                   MaskIsa isa, std::int64_t* walked) {
  return scan_dispatched(text, VectorOutput<BoundedPoint3>{points}, isa, walked);
}

PointLinesScan scan_bounded_masked(std::string_view text, const BoundedSink<BoundedPoint2>& sink,
                                   MaskIsa isa) {
  return scan_dispatched(text, SinkOutput<BoundedPoint2>{.sink = sink}, isa, nullptr);
}
PointLinesScan scan_bounded_masked(std::string_view text, const BoundedSink<BoundedPoint3>& sink,
                                   MaskIsa isa) {
  return scan_dispatched(text, SinkOutput<BoundedPoint3>{.sink = sink}, isa, nullptr);
}

}  // namespace contain::io::detail
