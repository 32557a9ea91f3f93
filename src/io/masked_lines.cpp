#include "io/masked_lines.h"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "io/number_bound.h"

namespace contain::io::detail {
namespace {

// Blocks of 64 bytes classified at a time: 16 KB of text, 6 KB of masks (in the L1 cache).
constexpr std::size_t kMaskBlocks = 256;
// Bytes a taken line may read past its first: the 64 of its window and the 8 of a load at its
// last byte (the fraction's digits of its last token).
constexpr std::size_t kLineReach = 64 + 8;

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

// Points taken by the masks, staged in a small array with their tokens' digits, and appended a
// run at a time with their boxes: a vector's emplace_back in the scan's loop is a call (too large
// a function for the compiler to inline it), and the boxes are bounded together (TokenDigits).
template <class Bounded>
struct StagedPoints {
  static constexpr int kColumns = std::is_same_v<Bounded, BoundedPoint2> ? 2 : 3;
  static constexpr int kRoom = TokenDigits::kRoom / 3;
  Bounded staged[kRoom];
  TokenDigits digits;
  int held = 0;
  std::vector<Bounded>& points;
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
    points.insert(points.end(), staged, staged + held);
    held = 0;
  }
};

// Runs of plain lines, read a block of masks at a time (not a line at a time): every token
// start, end and line found from the masks at once, the whole run checked to be plain lines of
// exactly kColumns plain tokens by bit operations on the masks, and only then its tokens bounded.
// A run that is not (a comment, a comma, an exponent, a blank line, a token of another shape)
// is left, untouched, to the line-by-line scan.
constexpr std::size_t kRunBlocks = 16;  // 1 KB of text
// Tokens a plain run can hold: a plain token and its separator take 4 bytes at least.
constexpr int kRunTokens = 16 * static_cast<int>(kRunBlocks);

struct RunTokens {
  unsigned start[kRunTokens];  // the first byte, from the run's first
  unsigned end[kRunTokens];    // the last byte
  unsigned line[kRunTokens];   // the line in the run, from 0
  unsigned dot[kRunTokens];    // the point
};

// Bit i: the parity of the set bits 0 to i of `x`.
[[gnu::always_inline]] inline std::uint64_t prefix_parity(std::uint64_t x) {
  x ^= x << 1;
  x ^= x << 2;
  x ^= x << 4;
  x ^= x << 8;
  x ^= x << 16;
  x ^= x << 32;
  return x;
}

// The bits from `from` on (0 to 63).
[[gnu::always_inline]] inline std::uint64_t bits_from(unsigned from) {
  return ~std::uint64_t{0} << from;
}
// The bits below `to` (1 to 64).
[[gnu::always_inline]] inline std::uint64_t bits_below(unsigned to) {
  return ~std::uint64_t{0} >> (64 - to);
}

// Checks the run of whole lines [from, to) of the text at `base` (`masks[k]` those of its block
// `first_block + k`; `from` a line's first byte, `to` past a newline) and finds its tokens into
// `run`: true when every line of it is kColumns plain tokens apart by blanks (number_bound.h's
// shape: an optional minus, 1 to 7 digits, a point, one or more digits), with the count of its
// lines in `lines`; false otherwise (then nothing is known of it).
template <int kColumns>
[[gnu::always_inline]] inline bool check_run(const char* base, const ByteMasks* masks,
                                             std::size_t first_block, std::size_t from,
                                             std::size_t to, RunTokens& run, unsigned& lines) {
  const std::size_t last_block = (to - 1) / 64;
  const std::size_t origin = from;  // token positions count from here
  std::uint64_t bad = 0;
  std::uint64_t token_carry = 0;  // the byte before the block is in a token (bit 0)
  std::uint64_t digit_carry = 0;  // the byte before the block is a digit (bit 0)
  std::uint64_t parity = 0;       // all ones when the starts and points before are odd
  int starts_count = 0, ends_count = 0;
  unsigned newlines = 0;
  for (std::size_t block = from / 64; block <= last_block; ++block) {
    const ByteMasks& m = masks[block - first_block];
    std::uint64_t range = ~std::uint64_t{0};
    if (block == from / 64) range &= bits_from(static_cast<unsigned>(from % 64));
    if (block == last_block) range &= bits_below(static_cast<unsigned>((to - 1) % 64) + 1);
    const std::uint64_t separator = m.blank | m.newline;
    const std::uint64_t token = ~separator & range;
    // The next block's first byte: in a token, a digit (none past the run: it ends in a newline).
    std::uint64_t next_token = 0, next_digit = 0;
    if (block < last_block) {
      const ByteMasks& n = masks[block + 1 - first_block];
      next_token = ~(n.blank | n.newline) & 1;
      next_digit = ~n.non_digit & 1;
    }
    const std::uint64_t starts = token & ~(token << 1 | token_carry);
    const std::uint64_t ends = token & ~(token >> 1 | next_token << 63);
    const std::uint64_t digit = ~m.non_digit;
    const std::uint64_t point = m.point & range;
    // Only digits, points and minus signs in tokens; a minus only first; a point between digits.
    bad |= m.non_digit & token & ~m.point & ~m.minus;
    bad |= m.minus & range & ~starts;
    bad |= point & ~(digit << 1 | digit_carry);
    bad |= point & ~(digit >> 1 | next_digit << 63);
    // One point a token: starts and points alternate, a start first (a point is never a start:
    // a digit is before it).
    const std::uint64_t odd = prefix_parity(starts | point) ^ parity;
    bad |= (starts & ~odd) | (point & odd);
    parity = static_cast<std::uint64_t>(0) - (odd >> 63);
    token_carry = token >> 63;
    digit_carry = (digit & range) >> 63;
    // The tokens, each with its line (the newlines before it in the run).
    const std::uint64_t newline = m.newline & range;
    if (starts_count + std::popcount(starts) > kRunTokens) return false;
    const auto offset = static_cast<unsigned>(64 * block - origin);
    for (std::uint64_t s = starts; s != 0; s &= s - 1) {
      const auto at = static_cast<unsigned>(std::countr_zero(s));
      run.start[starts_count] = offset + at;
      run.line[starts_count] =
          newlines + static_cast<unsigned>(std::popcount(newline & ~bits_from(at)));
      ++starts_count;
    }
    for (std::uint64_t e = ends; e != 0; e &= e - 1) {
      if (ends_count == kRunTokens) return false;
      run.end[ends_count++] = offset + static_cast<unsigned>(std::countr_zero(e));
    }
    newlines += static_cast<unsigned>(std::popcount(newline));
  }
  if (bad != 0 || parity != 0 || starts_count != ends_count ||
      starts_count != kColumns * static_cast<int>(newlines)) {
    return false;
  }
  // Line k holds tokens kColumns k to kColumns k + kColumns - 1: exactly kColumns a line (the
  // lines of the tokens never decrease), so no blank line and no line of another count.
  for (unsigned k = 0; k < newlines; ++k) {
    if (run.line[kColumns * k] != k || run.line[kColumns * k + kColumns - 1] != k) return false;
  }
  // 1 to 7 digits before the point (at least one: a digit is before it).
  const char* const text = base + origin;
  for (int t = 0; t < starts_count; ++t) {
    const unsigned digits_at = run.start[t] + (text[run.start[t]] == '-' ? 1u : 0u);
    const std::uint64_t flags = non_digit_bits(load8(text + digits_at));
    if (flags == 0) return false;  // 8 digits or more
    run.dot[t] = digits_at + static_cast<unsigned>(std::countr_zero(flags)) / 8;
  }
  lines = newlines;
  return true;
}

template <class Bounded>
[[gnu::always_inline]] inline PointLinesScan scan_masked(std::string_view text,
                                                         std::vector<Bounded>& points, MaskIsa isa,
                                                         BoundDigits bound, std::int64_t* walked) {
  constexpr int kColumns = std::is_same_v<Bounded, BoundedPoint2> ? 2 : 3;
  PointLinesScan scan;
  const char* const base = text.data();
  const std::size_t size = text.size();
  StagedPoints<Bounded> out{.points = points, .bound = bound};
  // Lines taken by the masks and left to the walk: a text of which more than a third goes to the
  // walk (commas, comments, exponents) is walked from there on, whole, as without masks (a line
  // walked alone costs the masks and a call more than in the walk of the whole text).
  std::int64_t taken_lines = 0, walked_lines = 0;
  // The lines of [from, to) by the exact walk, taken into the scan; false where it stopped.
  const auto walk = [&](std::size_t from, std::size_t to) {
    out.flush();
    const PointLinesScan part = scan_bounded_lines(text.substr(from, to - from), points);
    if (scan.first_row == 0 && part.first_row != 0) scan.first_row = scan.lines + part.first_row;
    scan.lines += part.lines;
    walked_lines += part.lines;
    if (walked != nullptr) *walked += part.lines;
    return part.complete;
  };
  ByteMasks masks[kMaskBlocks];
  std::size_t held_from = 0, held = 0;  // the masks of blocks [held_from, held_from + held)
  const std::size_t whole_blocks = size / 64;
  RunTokens run;
  std::size_t run_refused_to = 0;  // no run tried before this byte
  std::size_t at = 0;              // the line's first byte
  while (size - at >= kLineReach && walked_lines <= taken_lines / 2 + 16) {
    const std::size_t block = at / 64;
    if (block + 2 > whole_blocks) break;
    if (block + 2 > held_from + held) {
      held_from = block;
      held = std::min(kMaskBlocks, whole_blocks - block);
      classify_blocks(base + 64 * block, held, masks, isa);
    }
    // A run of plain lines from here: to the last newline of the next kRunBlocks blocks held
    // (one more held for the token ends), with room for the loads of its last token after it.
    if (at >= run_refused_to) {
      const std::size_t run_last = std::min(block + kRunBlocks, held_from + held - 1) - 1;
      std::size_t to = 0;
      for (std::size_t k = run_last + 1; k-- > block && to == 0;) {
        const std::uint64_t newline =
            masks[k - held_from].newline &
            (k == block ? bits_from(static_cast<unsigned>(at % 64)) : ~std::uint64_t{0});
        if (newline != 0) to = 64 * k + 64 - static_cast<std::size_t>(std::countl_zero(newline));
      }
      unsigned run_lines = 0;
      if (to > at && size - to >= kLineReach &&
          check_run<kColumns>(base, masks, held_from, at, to, run, run_lines)) {
        const char* const run_text = base + at;
        for (unsigned k = 0; k < run_lines; ++k) {
          if (out.held == out.kRoom) out.flush();
          for (int c = 0; c < kColumns; ++c) {
            const int t = kColumns * static_cast<int>(k) + c;
            const bool negative = run_text[run.start[t]] == '-';
            store_token(out.digits, kColumns * out.held + c, run_text,
                        run.start[t] + (negative ? 1u : 0u), run.dot[t], run.end[t], negative);
          }
          Bounded& point = out.staged[out.held++];
          point.first = run_text + run.start[kColumns * k];
          point.last = run_text + run.end[kColumns * k + kColumns - 1] + 1;
        }
        if (scan.first_row == 0) scan.first_row = scan.lines + 1;
        scan.lines += run_lines;
        taken_lines += run_lines;
        at = to;
        continue;
      }
      // Line by line to the run's end (it is tried once).
      run_refused_to = std::max(to, at + 1);
    }
    const std::size_t b = block - held_from;
    const auto shift = static_cast<unsigned>(at % 64);
    const char* const line = base + at;
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
template <class Bounded>
PointLinesScan scan_baseline(std::string_view text, std::vector<Bounded>& points, MaskIsa isa,
                             std::int64_t* walked) {
  return scan_masked(text, points, isa, &bound_digits_baseline, walked);
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

template <class Bounded>
[[gnu::target("bmi,bmi2,popcnt")]] PointLinesScan scan_bit_instructions(
    std::string_view text, std::vector<Bounded>& points, MaskIsa isa, std::int64_t* walked) {
  // The boxes eight at a time where the CPU has AVX-512DQ, else four (AVX2: the masks' versions
  // that come here are AVX2's or wider).
  const BoundDigits bound = isa == MaskIsa::avx512 && mask_isa_available(isa) && has_avx512_dq_vl()
                                ? &bound_digits_avx512
                            : mask_isa_available(MaskIsa::avx2) ? &bound_digits_avx2
                                                                : &bound_digits_baseline;
  return scan_masked(text, points, isa, bound, walked);
}

#endif

template <class Bounded>
PointLinesScan scan_dispatched(std::string_view text, std::vector<Bounded>& points, MaskIsa isa,
                               std::int64_t* walked) {
#if defined(__GNUC__) && defined(__x86_64__)
  if ((isa == MaskIsa::avx2 || isa == MaskIsa::avx512) && mask_isa_available(isa) &&
      has_bit_instructions()) {
    return scan_bit_instructions(text, points, isa, walked);
  }
#endif
  return scan_baseline(text, points, isa, walked);
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
  return scan_dispatched(text, points, isa, walked);
}
PointLinesScan scan_bounded_masked(std::string_view text, std::vector<BoundedPoint3>& points,
                                   MaskIsa isa, std::int64_t* walked) {
  return scan_dispatched(text, points, isa, walked);
}

}  // namespace contain::io::detail
