// The bounded point scanner by byte masks (src/io/masked_lines.h, src/io/byte_masks.h): every
// version of the byte classes gives the scalar masks on every byte value at every position, and
// the scanner gives exactly what the exact walk (scan_bounded_lines) gives, with every version:
// the same points, boxes bit for bit, spans, lines, first row and stopping line, on random point
// files and on hostile ones (every byte that sends a line back to the walk, at every position
// of a block; tokens across block edges; long digit strings; CR LF; comments; no final newline;
// huge, tiny and negative-zero numbers; leading zeros; errors).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "contain/io/points_io.h"
#include "io/byte_masks.h"
#include "io/masked_lines.h"
#include "io/point_lines.h"
#include "io/temp_file.h"

namespace contain::io {
namespace {

using detail::MaskIsa;

std::vector<MaskIsa> versions_here() {
  std::vector<MaskIsa> out;
  for (MaskIsa isa : {MaskIsa::scalar, MaskIsa::sse2, MaskIsa::avx2, MaskIsa::avx512}) {
    if (detail::mask_isa_available(isa)) out.push_back(isa);
  }
  return out;
}

// Bit for bit (a negative zero is not a zero); boxes of doubles have no padding.
template <class Bounded>
bool same_box(const Bounded& a, const Bounded& b) {
  return std::memcmp(&a.box, &b.box, sizeof a.box) == 0;
}

// The masked scan of `text` with every version gives the walk's scan, points and spans.
template <class Bounded>
void expect_as_the_walk(const std::string& text) {
  std::vector<Bounded> expected;
  const detail::PointLinesScan walk = detail::scan_bounded_lines(text, expected);
  for (MaskIsa isa : versions_here()) {
    std::vector<Bounded> got;
    const detail::PointLinesScan masked = detail::scan_bounded_masked(text, got, isa);
    const auto name = "version " + std::to_string(static_cast<int>(isa)) + " on:\n" + text;
    ASSERT_EQ(masked.complete, walk.complete) << name;
    ASSERT_EQ(masked.lines, walk.lines) << name;
    ASSERT_EQ(masked.first_row, walk.first_row) << name;
    ASSERT_EQ(got.size(), expected.size()) << name;
    for (std::size_t i = 0; i < got.size(); ++i) {
      ASSERT_TRUE(same_box(got[i], expected[i])) << "point " << i << ", " << name;
      ASSERT_EQ(got[i].first, expected[i].first) << "point " << i << ", " << name;
      ASSERT_EQ(got[i].last, expected[i].last) << "point " << i << ", " << name;
    }
  }
}

void expect_as_the_walk_2d_and_3d(const std::string& text) {
  expect_as_the_walk<BoundedPoint2>(text);
  expect_as_the_walk<BoundedPoint3>(text);
}

// A random number as a point file writes it: mostly shortest round-trip doubles of [-1, 1],
// sometimes of any magnitude, integers, or long strings of digits.
std::string random_number(std::mt19937_64& rng) {
  // Exponents and integers (kinds 0 and 1: lines for the walk) rare enough that the masks keep
  // the text (they give it up to the walk past a third of its lines).
  std::uniform_int_distribution<int> kind(0, 29);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  char buffer[64];
  switch (kind(rng)) {
    case 0: {
      std::uniform_real_distribution<double> exponent(-320.0, 308.0);
      const double value = unit(rng) * std::pow(10.0, exponent(rng));
      return std::string(buffer, std::to_chars(buffer, buffer + 64, value).ptr);
    }
    case 1:
      return std::to_string(static_cast<long long>(rng() % 20000000) - 10000000);
    case 2: {
      std::string digits = rng() % 2 == 0 ? "-" : "";
      const int whole = 1 + static_cast<int>(rng() % 9), fraction = static_cast<int>(rng() % 30);
      for (int k = 0; k < whole; ++k)
        digits += static_cast<char>('0' + rng() % 10);
      digits += '.';
      for (int k = 0; k < fraction; ++k)
        digits += static_cast<char>('0' + rng() % 10);
      return digits;
    }
    default: {
      const double value = unit(rng) * (kind(rng) < 15 ? 1.0 : 1000.0);
      return std::string(buffer, std::to_chars(buffer, buffer + 64, value).ptr);
    }
  }
}

// Random lines of `columns` numbers apart by runs of blanks, with leading and trailing blanks
// and blank lines now and then.
std::string random_file(std::mt19937_64& rng, int columns, int lines, bool odd_blanks) {
  const char* blanks[] = {" ", " ", " ", "  ", "\t", " \t ", "\r", "\v", "\f"};
  const int kinds = odd_blanks ? 9 : 1;
  std::string text;
  for (int line = 0; line < lines; ++line) {
    if (rng() % 16 == 0) text += blanks[rng() % kinds];
    if (rng() % 32 == 0) {
      text += '\n';
      continue;
    }
    for (int k = 0; k < columns; ++k) {
      if (k > 0) text += blanks[rng() % kinds];
      text += random_number(rng);
    }
    if (rng() % 16 == 0) text += blanks[rng() % kinds];
    text += '\n';
  }
  return text;
}

// Lines of `columns` plain numbers (number_bound.h's shape: 1 to 7 digits, a point, 1 to 25
// digits, a minus or not) apart by blanks of every kind, with leading and trailing blanks and no
// blank line: lines that the masks take, for the tests of what must send them to the walk.
std::string plain_file(std::mt19937_64& rng, int columns, int lines) {
  const char* blanks[] = {" ", " ", " ", "  ", "\t", " \t ", "\r", "\v", "\f"};
  std::string text;
  for (int line = 0; line < lines; ++line) {
    if (rng() % 8 == 0) text += blanks[rng() % 9];
    for (int k = 0; k < columns; ++k) {
      if (k > 0) text += blanks[rng() % 9];
      if (rng() % 2 == 0) text += '-';
      const int whole = rng() % 4 == 0 ? 1 + static_cast<int>(rng() % 7) : 1;
      const int fraction = 1 + static_cast<int>(rng() % 25);
      for (int d = 0; d < whole; ++d)
        text += static_cast<char>('0' + rng() % 10);
      text += '.';
      for (int d = 0; d < fraction; ++d)
        text += static_cast<char>('0' + rng() % 10);
    }
    if (rng() % 8 == 0) text += blanks[rng() % 9];
    text += '\n';
  }
  return text;
}

TEST(ByteMasks, EveryVersionGivesTheScalarMasksForEveryByteValueAtEveryPosition) {
  // Block j holds byte value (j + i) mod 256 at position i: every value at every position.
  std::string text(64 * 256, '\0');
  for (std::size_t j = 0; j < 256; ++j) {
    for (std::size_t i = 0; i < 64; ++i)
      text[64 * j + i] = static_cast<char>((j + i) % 256);
  }
  std::vector<detail::ByteMasks> expected(256), got(256);
  detail::classify_blocks(text.data(), 256, expected.data(), MaskIsa::scalar);
  for (MaskIsa isa : versions_here()) {
    detail::classify_blocks(text.data(), 256, got.data(), isa);
    for (std::size_t j = 0; j < 256; ++j) {
      EXPECT_EQ(got[j].blank, expected[j].blank) << j;
      EXPECT_EQ(got[j].newline, expected[j].newline) << j;
      EXPECT_EQ(got[j].non_digit, expected[j].non_digit) << j;
    }
  }
  // And the classes themselves: block i starts with byte value i.
  for (std::size_t i = 0; i < 256; ++i) {
    const auto c = static_cast<char>(i);
    const detail::ByteMasks& block = expected[i];
    const std::uint64_t bit = 1;
    EXPECT_EQ((block.newline & bit) != 0, c == '\n') << i;
    EXPECT_EQ((block.blank & bit) != 0, detail::is_blank(c)) << i;
    EXPECT_EQ((block.non_digit & bit) != 0, !(c >= '0' && c <= '9')) << i;
  }
}

TEST(ByteMasks, TheBestVersionIsAvailable) {
  EXPECT_TRUE(detail::mask_isa_available(detail::best_mask_isa()));
  EXPECT_TRUE(detail::mask_isa_available(MaskIsa::scalar));
}

TEST(MaskedLines, RandomPointFilesGiveTheWalksPointsBoxesSpansAndLines) {
  std::mt19937_64 rng(2727);
  for (int round = 0; round < 40; ++round) {
    for (int columns : {2, 3}) {
      const std::string text = random_file(rng, columns, 200, round % 2 == 1);
      if (columns == 2) {
        expect_as_the_walk<BoundedPoint2>(text);
      } else {
        expect_as_the_walk<BoundedPoint3>(text);
      }
    }
  }
}

TEST(MaskedLines, PlainLinesAreTakenByTheMasksNotTheWalk) {
  // Only the lines of at most the last 127 bytes (short of two whole blocks) go to the walk.
  std::mt19937_64 rng(1);
  std::string text;
  char buffer[64];
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int line = 0; line < 2000; ++line) {
    text += std::string(buffer, std::to_chars(buffer, buffer + 64, unit(rng)).ptr) + " ";
    text += std::string(buffer, std::to_chars(buffer, buffer + 64, unit(rng)).ptr) + "\n";
  }
  for (MaskIsa isa : versions_here()) {
    std::vector<BoundedPoint2> points;
    std::int64_t walked = 0;
    ASSERT_TRUE(detail::scan_bounded_masked(text, points, isa, &walked).complete);
    EXPECT_EQ(points.size(), 2000u);
    EXPECT_LE(walked, 5);
  }
}

TEST(MaskedLines, RandomFilesAreMostlyTakenByTheMasks) {
  // The random files of the tests below exercise the masks, not only the walk.
  std::mt19937_64 rng(2727);
  for (int columns : {2, 3}) {
    const std::string text = random_file(rng, columns, 2000, true);
    std::vector<BoundedPoint3> points3;
    std::vector<BoundedPoint2> points2;
    std::int64_t walked = 0;
    const auto scan = columns == 2
                          ? detail::scan_bounded_masked(text, points2, MaskIsa::scalar, &walked)
                          : detail::scan_bounded_masked(text, points3, MaskIsa::scalar, &walked);
    EXPECT_TRUE(scan.complete);
    EXPECT_LT(walked, scan.lines / 3) << columns;
  }
}

TEST(MaskedLines, AFileOfCommasIsWalkedWholeAfterItsFirstLines) {
  std::mt19937_64 rng(3);
  std::string text;
  for (int line = 0; line < 1000; ++line)
    text += "0." + std::to_string(rng() % 1000000) + ",-0." + std::to_string(rng() % 1000) + "\n";
  std::vector<BoundedPoint2> points;
  std::int64_t walked = 0;
  const auto scan = detail::scan_bounded_masked(text, points, MaskIsa::scalar, &walked);
  EXPECT_TRUE(scan.complete);
  EXPECT_EQ(points.size(), 1000u);
  EXPECT_EQ(walked, 1000);
  expect_as_the_walk<BoundedPoint2>(text);
}

TEST(MaskedLines, LinesStartingAtEveryOffsetOfABlockGiveTheWalksResults) {
  std::mt19937_64 rng(64);
  const std::string body2 = random_file(rng, 2, 40, false);
  const std::string body3 = random_file(rng, 3, 40, false);
  for (int offset = 0; offset < 64; ++offset) {
    const std::string blanks(static_cast<std::size_t>(offset), ' ');
    expect_as_the_walk<BoundedPoint2>(blanks + "\n" + body2);
    expect_as_the_walk<BoundedPoint3>(blanks + "\n" + body3);
    expect_as_the_walk<BoundedPoint2>(std::string(static_cast<std::size_t>(offset), '\n') + body2);
  }
}

TEST(MaskedLines, EveryByteThatSendsALineBackToTheWalkAtEveryPositionGivesTheWalksResults) {
  std::mt19937_64 rng(99);
  const std::string body2 = random_file(rng, 2, 12, false);
  const std::string body3 = random_file(rng, 3, 8, false);
  const std::string hostile[] = {
      "#",    ",",  "e",    "E", "+",  "\r", "\t",   "x",   std::string(1, '\0'),
      "\x80", ".",  "-",    " ", "\n", "5",  "\r\n", "nan", "inf",
      ", ",   "e5", "e-400"};
  for (const std::string* body : {&body2, &body3}) {
    for (std::size_t at = 0; at < 160 && at < body->size(); ++at) {
      for (const std::string& bytes : hostile) {
        std::string replaced = *body;
        replaced.replace(at, std::min(bytes.size(), replaced.size() - at), bytes);
        expect_as_the_walk_2d_and_3d(replaced);
        std::string inserted = *body;
        inserted.insert(at, bytes);
        expect_as_the_walk_2d_and_3d(inserted);
      }
    }
  }
}

TEST(MaskedLines, EdgeShapesOfNumbersAndLinesGiveTheWalksResults) {
  const std::string filler = "0.25 0.5\n-0.75 0.125\n0.5 -0.5\n";
  const std::string filler3 = "0.25 0.5 0.1\n-0.75 0.125 0.2\n0.5 -0.5 0.3\n";
  const char* lines2[] = {
      "-0 -0.0\n",
      "-0.0 0.0\n",
      "0000001.5 -0000000.25\n",
      "1234567.5 -7654321.125\n",
      "12345678.5 1.5\n",
      "-.5 .5\n",
      "5. 5.\n",
      "1.5.5 2.5\n",
      "--1.5 2.5\n",
      "1-.5 2.5\n",
      "1.5- 2.5\n",
      "- 1.5 2.5\n",
      "1.5 2.5 3.5\n",
      "1.5\n",
      "1.5 -\n",
      "1e308 1e-320\n",
      "1.7976931348623157e308 4.9e-324\n",
      "1e400 1.5\n",
      "0.000000000000000000001 1.5\n",
      "0.99999999999999999999999 -0.99999999999999999999999\n",
      "0.1234567890123456789012345678901234567890 1.5\n",
      "1.50000000 2.99999999\n",
      "1.5 2.5#comment\n",
      "1.5 2.5 # comment\n",
      "# 1.5 2.5\n",
      "1.5,2.5\n",
      "1.5 , 2.5\n",
      "+1.5 2.5\n",
      "1.5\t2.5\r\n",
      "   \n",
      "\n",
      "\r\n",
      "  1.5   2.5  \n",
      "1.5 2.5",
      "1.5 2.5 ",
      "nan 1.5\n",
      "inf 1.5\n",
      "1.5 2.5\x80\n",
      "1.5 2.5x\n",
      "15 25\n",
      "1.5 25\n",
  };
  for (const char* line : lines2) {
    // The line alone, after enough lines for the masks, and in the middle of them.
    for (const std::string& text :
         {std::string(line), filler + filler + filler + line,
          filler + filler + filler + line + filler + filler + filler + filler,
          filler3 + filler3 + filler3 + line + filler3 + filler3 + filler3}) {
      expect_as_the_walk_2d_and_3d(text);
    }
  }
  expect_as_the_walk_2d_and_3d("");
  expect_as_the_walk_2d_and_3d("\n\n\n");
  // A line of 64 bytes or more, and one of exactly 63, among plain ones.
  const std::string line64 = "-0.1234567890123456789012345678 -0.1234567890123456789012345678\n";
  const std::string line65 = "-0.1234567890123456789012345678 -0.12345678901234567890123456789\n";
  const std::string line63 = "-0.123456789012345678901234567 -0.1234567890123456789012345678\n";
  ASSERT_EQ(line63.size(), 63u);
  ASSERT_EQ(line64.size(), 64u);
  ASSERT_EQ(line65.size(), 65u);
  for (int offset = 0; offset < 64; ++offset) {
    expect_as_the_walk_2d_and_3d(std::string(static_cast<std::size_t>(offset), '\n') + filler +
                                 line65 + filler + line64 + line63 + filler + filler + filler);
  }
}

TEST(MaskedLines, StopsAtTheWalksLineWithTheWalksPointsBeforeIt) {
  std::mt19937_64 rng(5);
  std::string text = random_file(rng, 2, 100, false);
  const std::size_t middle = text.find('\n', text.size() / 2) + 1;
  for (const char* bad : {"1.5 2.5 3.5\n", "1.5\n", "abc\n", "1.5 2.5,\n", "1.5 2.5 #\n1.5\n"}) {
    std::string broken = text;
    broken.insert(middle, bad);
    expect_as_the_walk<BoundedPoint2>(broken);
  }
}

TEST(MaskedLines, PlainFilesAreTakenByTheMasksWithTheWalksResults) {
  std::mt19937_64 rng(1027);
  for (int round = 0; round < 6; ++round) {
    const std::string text2 = plain_file(rng, 2, 1500), text3 = plain_file(rng, 3, 1000);
    expect_as_the_walk<BoundedPoint2>(text2);
    expect_as_the_walk<BoundedPoint3>(text3);
    for (MaskIsa isa : versions_here()) {
      std::vector<BoundedPoint2> points;
      std::int64_t walked = 0;
      ASSERT_TRUE(detail::scan_bounded_masked(text2, points, isa, &walked).complete);
      // Only the lines of 64 bytes or more and those of the last 127 bytes.
      std::int64_t long_lines = 0;
      for (std::size_t at = 0, end = text2.find('\n'); end != std::string::npos;
           at = end + 1, end = text2.find('\n', at)) {
        long_lines += end - at >= 64 ? 1 : 0;
      }
      EXPECT_LE(walked, long_lines + 5);
    }
  }
}

// Every byte that makes a plain line another (another character in a token, a token of another
// shape, a line of another count, a blank line, an eighth digit before a point), at every
// position of the first 1200 bytes of a plain file: the walk's results.
TEST(MaskedLines, EveryByteThatChangesAPlainLineAtEveryPositionGivesTheWalksResults) {
  std::mt19937_64 rng(4096);
  std::string body2 = "1234567.5 -7654321.25\n" + plain_file(rng, 2, 50);
  std::string body3 = "1234567.5 -7654321.25 0.5\n" + plain_file(rng, 3, 40);
  const std::string hostile[] = {"#",    ",", "e",    "+",   std::string(1, '\0'),
                                 "\x80", ".", "-",    " ",   "\n",
                                 "\r\n", "5", "0.5 ", "\n\n"};
  for (std::size_t at = 0; at < 1200; ++at) {
    for (const std::string& bytes : hostile) {
      std::string changed = body2;
      if (at % 2 == 0) {
        changed.replace(at, std::min(bytes.size(), changed.size() - at), bytes);
      } else {
        changed.insert(at, bytes);
      }
      expect_as_the_walk<BoundedPoint2>(changed);
      if (at % 8 == 0) {
        changed = body3;
        changed.insert(at, bytes);
        expect_as_the_walk<BoundedPoint3>(changed);
      }
    }
  }
}

// A token without its point (an integer) wherever it lies; and a token moved from each line to the
// next, or back (lines of one and three numbers, two lines still holding four): the walk's results.
TEST(MaskedLines, EveryTokenWithoutItsPointAndEveryMovedTokenGiveTheWalksResults) {
  std::mt19937_64 rng(31);
  for (int columns : {2, 3}) {
    const std::string body = plain_file(rng, columns, 120);
    const auto expect = [&](const std::string& text) {
      if (columns == 2) {
        expect_as_the_walk<BoundedPoint2>(text);
      } else {
        expect_as_the_walk<BoundedPoint3>(text);
      }
    };
    for (std::size_t at = body.find('.'); at != std::string::npos; at = body.find('.', at + 1)) {
      std::string changed = body;
      changed[at] = '5';
      expect(changed);
    }
    for (std::size_t end = body.find('\n'); end + 1 < body.size(); end = body.find('\n', end + 1)) {
      // The newline moved back over the line's last token: it starts the next line.
      const std::size_t blank = body.find_last_of(" \t\v\f\r", end - 1);
      std::string back = body;
      back[end] = ' ';
      back.insert(blank + 1, "\n");
      expect(back);
      // The newline moved past the next line's first token: it ends this line.
      const std::size_t next_blank = body.find_first_of(" \t\v\f\r\n", end + 1);
      std::string forward = body;
      forward.insert(next_blank, "\n");
      forward[end] = ' ';
      expect(forward);
    }
  }
}

TEST(MaskedLines, PlainLinesStartingAtEveryOffsetOfABlockGiveTheWalksResults) {
  std::mt19937_64 rng(65);
  const std::string body2 = plain_file(rng, 2, 80), body3 = plain_file(rng, 3, 60);
  for (int offset = 0; offset < 64; ++offset) {
    const std::string blanks(static_cast<std::size_t>(offset), ' ');
    expect_as_the_walk<BoundedPoint2>(blanks + "\n" + body2);
    expect_as_the_walk<BoundedPoint3>(blanks + "\n" + body3);
    expect_as_the_walk<BoundedPoint2>("0.5 0.5" + blanks + "\n" + body2);
  }
}

TEST(MaskedLines, MaskedScanBoxesHoldTheExactScansPoints) {
  // The whole reader through the masks: each box holds the exactly read point.
  std::mt19937_64 rng(11);
  const std::string text = random_file(rng, 3, 3000, true);
  std::vector<BoundedPoint3> bounded;
  ASSERT_TRUE(detail::scan_bounded_masked(text, bounded).complete);
  std::vector<Vec3> exact;
  ASSERT_TRUE(detail::scan_point_lines(text, exact).complete);
  ASSERT_EQ(bounded.size(), exact.size());
  for (std::size_t i = 0; i < exact.size(); ++i) {
    const Box3& box = bounded[i].box;
    EXPECT_TRUE(box.min.x <= exact[i].x && box.min.y <= exact[i].y && box.min.z <= exact[i].z) << i;
    EXPECT_TRUE(box.max.x >= exact[i].x && box.max.y >= exact[i].y && box.max.z >= exact[i].z) << i;
    EXPECT_EQ(exact_point(bounded[i]), exact[i]) << i;
  }
}

// The double a number's text denotes, by the oracle of the contract: std::from_chars (after a
// '+', which it does not take), and where it reports underflow or overflow, strtod (correctly
// rounded in glibc) as parse_double does; false for NaN, infinities and overflow.
bool oracle(const std::string& token, double& value) {
  const std::string body = !token.empty() && token[0] == '+' ? token.substr(1) : token;
  const auto [ptr, ec] = std::from_chars(body.data(), body.data() + body.size(), value);
  if (ptr != body.data() + body.size()) return false;
  if (ec == std::errc::result_out_of_range) value = std::strtod(body.c_str(), nullptr);
  return (ec == std::errc{} || ec == std::errc::result_out_of_range) && std::isfinite(value);
}

// The exact decimal of the midpoint of the double `d` and the next one away from zero (a
// halfway case: from_chars rounds it to the even one of the two), from long double's 64-bit
// significand, which holds it exactly, printed in full by glibc's printf.
std::string midpoint_text(double d, int digits) {
  const double next = std::nextafter(d, d < 0 ? -INFINITY : INFINITY);
  const long double mid = (static_cast<long double>(d) + static_cast<long double>(next)) / 2;
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "%.*Lf", digits, mid);
  std::string text = buffer;
  while (text.back() == '0')
    text.pop_back();
  return text;
}

// Hostile numbers of every kind, each with the double the oracle gives (finite ones only).
std::vector<std::string> hostile_tokens(std::mt19937_64& rng) {
  std::vector<std::string> out = {
      // long mantissas and 19/20-digit runs, before and after the point
      "0.12345678901234567890123456789",
      "-0.99999999999999999999999999999",
      "9.9999999999999999999",
      "1234567.8901234567890",
      "-1234567.8901234567890",
      "12345678.901234567890",
      "1234567890123456789",
      "12345678901234567890",
      "0.0000000000000000001",
      "-0.00000000000000000000000000000000000001",
      "0.99999999999999994448884876874217297882",
      "0.99999999999999994448884876874217297883",
      "1.00000000000000011102230246251565404236",
      "9007199254740993",
      "9007199254740992.5",
      // exponents
      "1e-5",
      "2.5E+3",
      "-7.25e2",
      "1E0",
      "3e-320",
      "1e308",
      "1.7976931348623157e308",
      // subnormals and the smallest numbers
      "4.9e-324",
      "5e-324",
      "2.4703282292062327e-324",
      "2.4703282292062328e-324",
      "2.2250738585072011e-308",
      "2.2250738585072014e-308",
      "-4.9406564584124654e-324",
      // signs and zeros
      "-0.0",
      "+0.5",
      "+.5",
      "-.5",
      "0.",
      "-0",
      "+7",
      "0.000000000",
      "-0.000000001",
  };
  // Doubles in [2^20, 2^23) have 7 integer digits and their midpoints 30 to 33 decimals: lines
  // of one such number short enough for the masks (64 bytes); those in [-1, 1], 50 decimals and
  // more, go to the walk.
  std::uniform_real_distribution<double> unit(-1.0, 1.0), wide(1048576.0, 8388608.0);
  for (int k = 0; k < 60; ++k) {
    // Halfway cases: the exact midpoints of neighbouring doubles, and a digit past each.
    const double d = k % 3 == 0 ? unit(rng) : (rng() % 2 == 0 ? -1.0 : 1.0) * wide(rng);
    const std::string mid = midpoint_text(d, 80);
    out.push_back(mid);
    out.push_back(mid + "1");
    out.push_back(mid.substr(0, mid.size() - 1));  // just below (or above) halfway
  }
  for (int k = 0; k < 40; ++k) {
    // Runs of 19 and 20 digits with a point anywhere.
    std::string digits = rng() % 2 == 0 ? "-" : "";
    const int count = 19 + static_cast<int>(rng() % 2), point = static_cast<int>(rng() % 9);
    for (int d = 0; d < count; ++d) {
      if (d == point) digits += '.';
      digits += static_cast<char>('0' + (d == 0 ? 1 + rng() % 9 : rng() % 10));
    }
    out.push_back(digits);
  }
  return out;
}

// Hostile numbers among plain lines (three plain lines to one hostile, so the masks keep the text
// and meet the hostile lines one by one), with CR LF or LF ends and no final newline: every
// version's points read back as the oracle's doubles bit for bit, inside their boxes, and as the
// walk's; and the whole reader from a file gives the same doubles.
TEST(MaskedLines, HostileNumbersReadBackAsTheFromCharsDoublesInTheirBoxes) {
  std::mt19937_64 rng(2027);
  const std::vector<std::string> tokens = hostile_tokens(rng);
  char buffer[64];
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto plain = [&] {
    return std::string(buffer, std::to_chars(buffer, buffer + 64, unit(rng)).ptr);
  };
  for (int columns : {2, 3}) {
    for (const char* end : {"\n", "\r\n"}) {
      std::string text;
      std::vector<double> expected;
      for (std::size_t t = 0; t < tokens.size(); ++t) {
        for (int line = 0; line < 3; ++line) {
          for (int k = 0; k < columns; ++k) {
            const std::string number = plain();
            text += (k > 0 ? " " : "") + number;
            expected.push_back(std::stod(number));
          }
          text += end;
        }
        // The hostile token at each column in turn, plain numbers beside it.
        for (int k = 0; k < columns; ++k) {
          const std::string number =
              k == static_cast<int>(t % static_cast<std::size_t>(columns)) ? tokens[t] : plain();
          double value = 0.0;
          ASSERT_TRUE(oracle(number, value)) << number;
          text += (k > 0 ? " " : "") + number;
          expected.push_back(value);
        }
        if (t + 1 < tokens.size()) text += end;  // the last line without its newline
      }
      if (columns == 2) {
        expect_as_the_walk<BoundedPoint2>(text);
      } else {
        expect_as_the_walk<BoundedPoint3>(text);
      }
      for (MaskIsa isa : versions_here()) {
        std::vector<double> got;
        std::vector<BoundedPoint2> points2;
        std::vector<BoundedPoint3> points3;
        std::int64_t walked = 0;
        const auto scan = columns == 2 ? detail::scan_bounded_masked(text, points2, isa, &walked)
                                       : detail::scan_bounded_masked(text, points3, isa, &walked);
        ASSERT_TRUE(scan.complete) << static_cast<int>(isa);
        // Most lines by the masks, not the walk.
        EXPECT_LT(walked, scan.lines / 2) << static_cast<int>(isa);
        for (const BoundedPoint2& p : points2) {
          const Vec2 v = exact_point(p);
          EXPECT_TRUE(p.box.contains(v));
          got.insert(got.end(), {v.x, v.y});
        }
        for (const BoundedPoint3& p : points3) {
          const Vec3 v = exact_point(p);
          EXPECT_TRUE(p.box.contains(v));
          got.insert(got.end(), {v.x, v.y, v.z});
        }
        ASSERT_EQ(got.size(), expected.size());
        for (std::size_t i = 0; i < got.size(); ++i) {
          ASSERT_EQ(std::bit_cast<std::uint64_t>(got[i]), std::bit_cast<std::uint64_t>(expected[i]))
              << "number " << i << " (version " << static_cast<int>(isa) << ")";
        }
      }
      // The whole reader (blocks of 256 KB, 997 bytes, and mapped).
      const test::TempFile file(".txt", text);
      for (const ChunkedReading reading :
           {ChunkedReading{}, ChunkedReading{.block = 997}, ChunkedReading{.map = true}}) {
        std::vector<double> got;
        const auto take = [&](auto piece, double) {
          for (const auto& p : piece) {
            const auto v = exact_point(p);
            if constexpr (std::is_same_v<decltype(v), const Vec2>) {
              got.insert(got.end(), {v.x, v.y});
            } else {
              got.insert(got.end(), {v.x, v.y, v.z});
            }
          }
        };
        const Status status = columns == 2
                                  ? read_points2_bounded(file.path(), reading,
                                                         [&](std::span<const BoundedPoint2> piece,
                                                             double share) { take(piece, share); })
                                  : read_points3_bounded(file.path(), reading,
                                                         [&](std::span<const BoundedPoint3> piece,
                                                             double share) { take(piece, share); });
        ASSERT_TRUE(status.ok()) << status.error().what();
        ASSERT_EQ(got.size(), expected.size());
        for (std::size_t i = 0; i < got.size(); ++i) {
          ASSERT_EQ(std::bit_cast<std::uint64_t>(got[i]), std::bit_cast<std::uint64_t>(expected[i]))
              << "number " << i;
        }
      }
    }
  }
}

// A malformed line at known lines of a file of several 256 KB blocks (the first line, lines
// about each block's end, the last line without its newline), with LF and CR LF ends: the
// reader's error names that line, with the table parser's words, whatever the block or mapping.
TEST(MaskedLines, AMalformedLineIsAnErrorWithItsOwnLineNumber) {
  std::mt19937_64 rng(404);
  char buffer[64];
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::string> lines;
  for (int line = 0; line < 16000; ++line) {  // about 600 KB: three blocks
    std::string text = std::string(buffer, std::to_chars(buffer, buffer + 64, unit(rng)).ptr);
    text += ' ';
    text += std::string(buffer, std::to_chars(buffer, buffer + 64, unit(rng)).ptr);
    lines.push_back(text);
  }
  const std::vector<std::string> bad{"0.5 x",     "0.5",          "0.5 0.5 0.5", "nan 0.5",
                                     "0.5 1e400", "0.5,,0.5",     "0.5 -",       "0.5-0.5",
                                     "1.5.5 2",   "0.25 0.5\x01", "+-1 2",       "0.5 --0.5"};
  for (const char* end : {"\n", "\r\n"}) {
    for (std::size_t at : {std::size_t{0}, std::size_t{6700}, std::size_t{6701}, std::size_t{13405},
                           lines.size() - 1}) {
      for (std::size_t b = 0; b < bad.size(); b += at == 0 ? 1 : 3) {
        std::string text;
        for (std::size_t i = 0; i < lines.size(); ++i) {
          text += i == at ? bad[b] : lines[i];
          if (i + 1 < lines.size()) text += end;
        }
        const test::TempFile file(".txt", text);
        const auto whole = read_points2(file.path());
        ASSERT_FALSE(whole.ok()) << bad[b];
        EXPECT_EQ(whole.error().line, static_cast<std::int64_t>(at) + 1) << bad[b];
        for (const ChunkedReading reading :
             {ChunkedReading{}, ChunkedReading{.block = 4096}, ChunkedReading{.map = true}}) {
          std::size_t points = 0;
          const Status status = read_points2_bounded(
              file.path(), reading,
              [&](std::span<const BoundedPoint2> piece, double) { points += piece.size(); });
          ASSERT_FALSE(status.ok()) << bad[b];
          EXPECT_EQ(status.error().line, static_cast<std::int64_t>(at) + 1) << bad[b] << " " << at;
          EXPECT_EQ(status.error().message, whole.error().message) << bad[b];
          EXPECT_LE(points, at) << bad[b];
        }
      }
    }
  }
}

// The same points, boxes and spans in the same order, and the same lines.
template <class Bounded>
void expect_same_scan(const detail::PointLinesScan& got, const std::vector<Bounded>& points,
                      const detail::PointLinesScan& scan, const std::vector<Bounded>& expected,
                      const std::string& name) {
  ASSERT_EQ(got.complete, scan.complete) << name;
  ASSERT_EQ(got.lines, scan.lines) << name;
  ASSERT_EQ(got.first_row, scan.first_row) << name;
  ASSERT_EQ(points.size(), expected.size()) << name;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    ASSERT_TRUE(same_box(points[i], expected[i])) << "point " << i << ", " << name;
    ASSERT_EQ(points[i].first, expected[i].first) << "point " << i << ", " << name;
    ASSERT_EQ(points[i].last, expected[i].last) << "point " << i << ", " << name;
  }
}

// The scan handing its points to a sink a run at a time gives the vector's scan: the same points,
// boxes and spans in the same order, the same lines, in runs of at most kMaxRun; and so does the
// walk handing its points over in runs (scan_bounded_runs: the locating readers' way where the
// masks do not pay, on every CPU here).
template <class Bounded>
void expect_sink_as_vector(const std::string& text) {
  std::vector<Bounded> walked;
  const detail::PointLinesScan walk = detail::scan_bounded_lines(text, walked);
  std::vector<Bounded> in_runs;
  std::size_t longest_run = 0;
  const detail::PointLinesScan runs =
      detail::scan_bounded_runs<Bounded>(text, [&](std::span<const Bounded> run) {
        in_runs.insert(in_runs.end(), run.begin(), run.end());
        longest_run = std::max(longest_run, run.size());
      });
  expect_same_scan(runs, in_runs, walk, walked, "the walk in runs on:\n" + text);
  EXPECT_LE(longest_run, detail::BoundedSink<Bounded>::kMaxRun);
  for (MaskIsa isa : versions_here()) {
    std::vector<Bounded> expected;
    const detail::PointLinesScan scan = detail::scan_bounded_masked(text, expected, isa);
    struct Taken {
      std::vector<Bounded> points;
      std::size_t runs = 0, longest = 0;
    } taken;
    const detail::BoundedSink<Bounded> sink{
        .context = &taken, .take = [](void* context, std::span<const Bounded> run) {
          auto& into = *static_cast<Taken*>(context);
          into.points.insert(into.points.end(), run.begin(), run.end());
          into.runs += 1;
          into.longest = std::max(into.longest, run.size());
        }};
    const detail::PointLinesScan sunk = detail::scan_bounded_masked(text, sink, isa);
    const auto name = "version " + std::to_string(static_cast<int>(isa)) + " on:\n" + text;
    expect_same_scan(sunk, taken.points, scan, expected, name);
    EXPECT_LE(taken.longest, detail::BoundedSink<Bounded>::kMaxRun);
    EXPECT_EQ(taken.runs > 0, !expected.empty());
  }
}

TEST(MaskedLines, TheScanIntoASinkGivesTheScanIntoAVectorOnRandomPlainAndBrokenFiles) {
  std::mt19937_64 rng(2728);
  for (int round = 0; round < 20; ++round) {
    const std::string two = random_file(rng, 2, 300, round % 2 == 1);
    const std::string three = random_file(rng, 3, 300, round % 2 == 1);
    expect_sink_as_vector<BoundedPoint2>(two);
    expect_sink_as_vector<BoundedPoint3>(three);
    expect_sink_as_vector<BoundedPoint2>(plain_file(rng, 2, 300));
    expect_sink_as_vector<BoundedPoint3>(plain_file(rng, 3, 300));
    // Stopped at a bad line, the points before it handed over; a file of commas (the walk).
    expect_sink_as_vector<BoundedPoint2>(two + "0.5 x\n" + two);
    std::string commas;
    for (int k = 0; k < 200; ++k)
      commas += random_number(rng) + ", " + random_number(rng) + "\n";
    expect_sink_as_vector<BoundedPoint2>(commas);
  }
}

}  // namespace
}  // namespace contain::io
