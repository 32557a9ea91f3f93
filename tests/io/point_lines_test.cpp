// The one-pass point scanner (src/io/point_lines.h) against the table parser it stands in for:
// it must take exactly the texts the table parser takes with 2 or 3 columns, with the same
// doubles bit for bit and the same lines, and refuse every text the table parser refuses (the
// reader then asks the table parser for the error's words).

#include "io/point_lines.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "contain/io/number_table.h"
#include "contain/values/vec.h"

namespace contain::io {
namespace {

template <class Point>
std::vector<double> coordinates(const std::vector<Point>& points) {
  std::vector<double> out;
  for (const Point& p : points) {
    out.push_back(p.x);
    out.push_back(p.y);
    if constexpr (sizeof(Point) == 3 * sizeof(double)) out.push_back(p.z);
  }
  return out;
}

bool same_doubles(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  }
  return true;
}

// The scanner and the table parser agree on `text`: both take it (same doubles, same lines and
// line count), or both refuse it.
template <class Point>
::testing::AssertionResult scanner_agrees(const std::string& text) {
  constexpr int kColumns = sizeof(Point) / sizeof(double);
  std::vector<Point> points;
  std::vector<std::int64_t> lines;
  const detail::PointLinesScan scan = detail::scan_point_lines(text, points, &lines, 10);
  // Lines from 11, as a later piece of a file: the byte order mark is the caller's either way.
  const auto table = parse_number_table(text, "t", {.columns = {kColumns}, .lines_before = 10});
  if (scan.complete != table.ok()) {
    return ::testing::AssertionFailure()
           << "scanner " << (scan.complete ? "took" : "refused") << " what the table parser "
           << (table.ok() ? "took" : "refused") << ": '" << text << "'"
           << (table.ok() ? "" : " (" + table.error().message + ")");
  }
  if (!scan.complete) return ::testing::AssertionSuccess();
  std::vector<std::int64_t> expected_lines = table->lines;
  if (!same_doubles(coordinates(points), table->values) || lines != expected_lines) {
    return ::testing::AssertionFailure() << "other points or lines for '" << text << "'";
  }
  const std::int64_t text_lines =
      static_cast<std::int64_t>(std::count(text.begin(), text.end(), '\n')) +
      (text.empty() || text.back() == '\n' ? 0 : 1);
  if (scan.lines != text_lines) {
    return ::testing::AssertionFailure() << scan.lines << " lines counted in '" << text << "'";
  }
  return ::testing::AssertionSuccess();
}

const std::vector<std::string>& edge_cases() {
  static const std::vector<std::string> cases = {
      "",
      "\n",
      "\n\n",
      "  \t\n",
      "#",
      "# only a comment",
      "1 2",
      "1 2\n",
      "1 2\n3 4",
      "1 2\r\n3 4\r\n",
      "1 2\r3 4\n",
      "\r\n\r\n1 2\r\n",
      "1 2 3",
      "1 2 3\n",
      "1 2 3\r\n4 5 6",
      "1",
      "1\n",
      "1 2 3 4\n",
      " 1 2\n",
      "1  2  \n",
      "1\t\v\f2\n",
      "1 2#c\n",
      "1 2 # c\n",
      "1#c 2\n",
      "1 2 3#c\n",
      "# x y\n1 2\n",
      "1,2\n",
      "1 ,2\n",
      "1, 2\n",
      "1 , 2 , 3\n",
      "1,,2\n",
      "1,2,\n",
      ",1 2\n",
      "1 2,\n",
      "1, \n",
      "1,#\n",
      "1 2x\n",
      "1 2 x\n",
      "1x 2\n",
      "x\n",
      "1 2\n3 4 5\n",
      "+1 +.5\n",
      "+-1 2\n",
      "+ 1 2\n",
      "++1 2\n",
      "-+1 2\n",
      "+\n",
      "1e 2\n",
      "1e+ 2\n",
      "1e+2 2E-2\n",
      ".e1 2\n",
      ". 2\n",
      "5. .5\n",
      "-.5 -0\n",
      "-0 -0.0 0e0\n",
      "nan 1\n",
      "1 -inf\n",
      "infinity 2\n",
      "NaN(123) 1\n",
      "1 NAN\n",
      "1e999 1\n",
      "-1e999 1\n",
      "1e-400 2\n",
      "4.9e-324 0\n",
      "2.4703282292062328e-324 1\n",
      "0x10 1\n",
      "1 0x1p3\n",
      "1 2\n\x80\n",
      std::string("1 2\n\0\n", 5),
      "1\n2\n",
      "1.7976931348623157e308 -1.7976931348623157e308\n",
      "1.7976931348623159e308 0\n",
      "123456789012345678901234567890 1e-5\n",
  };
  return cases;
}

TEST(PointLines, TakesExactlyTheEdgeCasesTheTableParserTakes) {
  for (const std::string& text : edge_cases()) {
    EXPECT_TRUE(scanner_agrees<Vec2>(text));
    EXPECT_TRUE(scanner_agrees<Vec3>(text));
  }
}

// The same edge cases with coordinate lines after them: numbers with 40 bytes or more behind
// them, so that each case is read where a number has a line of coordinates behind it.
TEST(PointLines, TakesExactlyTheEdgeCasesTheTableParserTakesWithLinesAfterThem) {
  std::string lines2;
  std::string lines3;
  for (int k = 0; k < 4; ++k) {
    lines2 += "-0.6918522583081116 0.29747557189896234\n";
    lines3 += "0.11388628377887389 -0.7195816228463322 12.5\n";
  }
  for (const std::string& text : edge_cases()) {
    EXPECT_TRUE(scanner_agrees<Vec2>(text + "\n" + lines2));
    EXPECT_TRUE(scanner_agrees<Vec3>(text + "\n" + lines3));
    EXPECT_TRUE(scanner_agrees<Vec2>(lines2 + text + "\n" + lines2));
    EXPECT_TRUE(scanner_agrees<Vec3>(lines3 + text + "\n" + lines3));
  }
}

// A line far longer than any block, with numbers of thousands of digits: the same doubles.
TEST(PointLines, OverlongLinesAndNumbersOfThousandsOfDigitsReadAsTheTableParserReadsThem) {
  const std::string digits(5000, '7');
  const std::string blanks(3000, ' ');
  for (const std::string& text :
       {"0." + digits + blanks + "1\n", digits + "e-4990 -" + digits + "e-5010\n",
        "1" + blanks + "2" + blanks + "# " + digits + "\n", "0." + digits + "x 1\n"}) {
    EXPECT_TRUE(scanner_agrees<Vec2>(text)) << text.size();
    EXPECT_TRUE(scanner_agrees<Vec3>(text + text)) << text.size();
  }
}

// Random edits of valid files (characters the grammar cares about put in, taken out, swapped):
// whatever the result, the scanner takes it exactly when the table parser does.
TEST(PointLines, TakesExactlyWhatTheTableParserTakesUnderRandomEdits) {
  std::mt19937_64 rng(27);
  const std::string alphabet = " \t\r\n,#+-.eE0123456789xnaifINF\v";
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1);
  std::uniform_real_distribution<double> value(-1e3, 1e3);
  int taken = 0;
  for (int round = 0; round < 4000; ++round) {
    std::string text;
    const int columns = 2 + round % 2;
    for (int line = 0; line < 4; ++line) {
      for (int k = 0; k < columns; ++k) {
        char buffer[40];
        text.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, value(rng)).ptr);
        text += k + 1 < columns ? (line % 3 == 1 ? ", " : " ") : (line % 2 ? "\r\n" : "\n");
      }
    }
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % (text.size() + 1);
      switch (rng() % 3) {
        case 0:
          text.insert(at, 1, alphabet[pick(rng)]);
          break;
        case 1:
          if (at < text.size()) text.erase(at, 1);
          break;
        default:
          if (at < text.size()) text[at] = alphabet[pick(rng)];
          break;
      }
    }
    const bool agrees2 = scanner_agrees<Vec2>(text);
    const bool agrees3 = scanner_agrees<Vec3>(text);
    EXPECT_TRUE(agrees2 && agrees3) << "round " << round << ": '" << text << "'";
    if (!agrees2 || !agrees3) break;
    std::vector<Vec2> points;
    taken += detail::scan_point_lines(text, points).complete ? 1 : 0;
  }
  // Both outcomes were met often (the test did not only see refused texts).
  EXPECT_GT(taken, 200);
  EXPECT_LT(taken, 3800);
}

}  // namespace
}  // namespace contain::io
