#pragma once
/// \file
/// Private: the bounded point scanner by byte masks, the fast way of read_points*_bounded and,
/// through a BoundedSink, of locate_points*_bounded. It gives exactly what scan_bounded_lines
/// (io/point_lines.h) gives on every text: the same points with the same boxes bit for bit, the
/// same [first, last) spans, the same lines, the same line where it stops. Tested against it on
/// random and hostile texts.
///
/// How. The bytes' classes come 64 at a time as bit masks (io/byte_masks.h: blanks, newlines,
/// non-digits; SSE2, AVX2 or AVX-512BW). A line is read from a 64-bit window of the masks at its
/// first byte: its newline is the window's first newline bit, its tokens the runs of non-blank
/// bits (starts and ends by shifts, each found by a count of trailing zeros). A token is taken
/// when its first non-digit after an optional minus is a point with 1 to 7 digits before it and
/// one or more after it, and no non-digit follows to the token's end: the plain shape of
/// number_bound.h, whose box then comes from the integer part and the first 8 fraction digits
/// (8-byte loads, bound_from_digits: the computation of bound_plain_number, bit for bit). A line
/// is taken when it has exactly 2 or 3 such tokens (or only blanks). Any other line (a comment,
/// a comma, an exponent, a '+', a line of 65 bytes or more, an error) and the lines of at most
/// the last 127 bytes of the text (those starting in its last whole block or after) are walked by
/// scan_bounded_lines itself, one line at a time, so the results there are that walk's by
/// construction; once more than a third of the lines went to the walk, the rest of the text does,
/// in one walk (a file of commas reads as fast as before).

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "contain/io/points_io.h"
#include "io/byte_masks.h"
#include "io/point_lines.h"

namespace contain::io::detail {

/// scan_bounded_lines(text, points), by byte masks of the version `isa` (see the file comment);
/// the results are the same whatever the version. `walked`, when given, counts the lines left to
/// scan_bounded_lines (for the tests: plain lines are not).
PointLinesScan scan_bounded_masked(std::string_view text, std::vector<BoundedPoint2>& points,
                                   MaskIsa isa = best_mask_isa(), std::int64_t* walked = nullptr);
/// The same for 3D points.
PointLinesScan scan_bounded_masked(std::string_view text, std::vector<BoundedPoint3>& points,
                                   MaskIsa isa = best_mask_isa(), std::int64_t* walked = nullptr);

/// Where a scan hands its points over a run at a time instead of appending them to a vector:
/// `take(context, run)` sees the points in text order, runs of at most kMaxRun (32 for a run the
/// masks took, up to 64 from the walk), each run's [first, last) text valid during the call. What
/// a caller does with each point while its box is in the cache (locate it: locate_points2_bounded)
/// costs no array of points, and no second pass over them.
template <class Bounded>
struct BoundedSink {
  static constexpr std::size_t kMaxRun = 64;
  void* context = nullptr;
  void (*take)(void* context, std::span<const Bounded> run) = nullptr;
};

/// scan_bounded_masked(text, points, isa), the points handed to `sink` a run at a time instead:
/// the same points, in the same order, the same results.
PointLinesScan scan_bounded_masked(std::string_view text, const BoundedSink<BoundedPoint2>& sink,
                                   MaskIsa isa = best_mask_isa());
/// The same for 3D points.
PointLinesScan scan_bounded_masked(std::string_view text, const BoundedSink<BoundedPoint3>& sink,
                                   MaskIsa isa = best_mask_isa());

/// Whether this CPU reads faster by masks than by scan_bounded_lines: where it has AVX2 (with
/// BMI1/2, as every AVX2 CPU) or AVX-512 (the whole `contain inside` of 10^6 points in a
/// 100-vertex star 15-18% less CPU, docs/benchmarks.md); with SSE2 alone the masked scan is no
/// faster than the walk.
[[nodiscard]] bool masked_scan_pays();

}  // namespace contain::io::detail
