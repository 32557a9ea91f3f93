#include "contain/io/points_io.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <chrono>
#include <cmath>
#include <random>
#include <sstream>

#include "contain/io/number_table.h"
#include "io/temp_file.h"

namespace contain::io {
namespace {

TEST(PointsIo, Reads2DPointsSeparatedBySpacesOrCommasAndSkipsBlankAndCommentLines) {
  auto r =
      parse_points2("# header\n1 2\n\n  3.5,\t-4\n# again\n5 , 6e1 # trailing comment\n", "pts");
  ASSERT_TRUE(r.ok()) << r.error().what();
  ASSERT_EQ(r->points.size(), 3u);
  EXPECT_EQ(r->points[0], (Vec2{1, 2}));
  EXPECT_EQ(r->points[1], (Vec2{3.5, -4}));
  EXPECT_EQ(r->points[2], (Vec2{5, 60}));
  EXPECT_EQ(r->lines, (std::vector<std::int64_t>{2, 4, 6}));
}

TEST(PointsIo, Reads3DPointsWithCrLfLineEndsAndAByteOrderMark) {
  auto r = parse_points3("\xEF\xBB\xBF+1 .5 -0\r\n2. 3e-2 4\r\n", "pts");
  ASSERT_TRUE(r.ok()) << r.error().what();
  ASSERT_EQ(r->points.size(), 2u);
  EXPECT_EQ(r->points[0], (Vec3{1, 0.5, 0}));
  EXPECT_TRUE(std::signbit(r->points[0].z));
  EXPECT_EQ(r->points[1], (Vec3{2, 0.03, 4}));
}

TEST(PointsIo, ShortestRoundTripDecimalsReadBackAsTheSameDoubles) {
  std::mt19937_64 rng(7);
  std::string text;
  std::vector<Vec2> expected;
  for (int i = 0; i < 2000; ++i) {
    // Random bit patterns cover subnormals and extreme exponents; skip NaN and infinities.
    Vec2 p{std::bit_cast<double>(rng()), std::bit_cast<double>(rng())};
    if (!is_finite(p)) continue;
    expected.push_back(p);
    char buf[64];
    auto a = std::to_chars(buf, buf + 64, p.x);
    *a.ptr++ = ' ';
    auto b = std::to_chars(a.ptr, buf + 64, p.y);
    text.append(buf, b.ptr);
    text += '\n';
  }
  auto r = parse_points2(text, "pts");
  ASSERT_TRUE(r.ok()) << r.error().what();
  ASSERT_EQ(r->points.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(r->points[i].x),
              std::bit_cast<std::uint64_t>(expected[i].x));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(r->points[i].y),
              std::bit_cast<std::uint64_t>(expected[i].y));
  }
}

TEST(PointsIo, UnderflowRoundsCorrectlyToZeroOrASubnormal) {
  auto r = parse_points2("1e-400 5e-324\n", "pts");
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->points[0].x, 0.0);
  EXPECT_EQ(r->points[0].y, std::numeric_limits<double>::denorm_min());
}

TEST(PointsIo, RejectsALineOfTheOtherDimensionNamingTheLine) {
  auto r = parse_points2("1 2\n3 4 5\n", "pts");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::invalid_value);
  EXPECT_EQ(r.error().line, 2);
  EXPECT_EQ(r.error().source, "pts");
  EXPECT_NE(r.error().message.find("3 numbers"), std::string::npos) << r.error().message;
}

TEST(PointsIo, Rejects2DPointsWhere3DAreExpected) {
  auto r = parse_points3("1 2\n", "pts");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, 1);
}

TEST(PointsIo, RejectsNaNInfinityAndOverflowAsInvalidValues) {
  for (const char* text : {"1 nan\n", "inf 2\n", "-infinity 1\n", "1 1e400\n", "-1e309 0\n"}) {
    auto r = parse_points2(std::string("0 0\n") + text, "pts");
    ASSERT_FALSE(r.ok()) << text;
    EXPECT_EQ(r.error().kind, ErrorKind::invalid_value) << text;
    EXPECT_EQ(r.error().line, 2) << text;
  }
}

TEST(PointsIo, RejectsTrailingGarbageAndMalformedNumbers) {
  for (const char* text : {"1.5abc 2\n", "1 2x\n", "1 2 ,\n", "1,,2\n", "0x10 1\n", "1e 2\n",
                           "- 1\n", "+-1 2\n", "1 2 3 4 5 6 7 8 9 10 11 x\n"}) {
    auto r = parse_points2(text, "pts");
    ASSERT_FALSE(r.ok()) << text;
    EXPECT_EQ(r.error().kind, ErrorKind::parse) << text;
    EXPECT_EQ(r.error().line, 1) << text;
  }
}

TEST(PointsIo, AnEmptyOrCommentOnlyFileGivesNoPoints) {
  auto empty = parse_points2("", "pts");
  ASSERT_TRUE(empty.ok());
  EXPECT_TRUE(empty->points.empty());
  auto comments = parse_points3("# nothing\n\n   \n", "pts");
  ASSERT_TRUE(comments.ok());
  EXPECT_TRUE(comments->points.empty());
}

TEST(PointsIo, AMissingFileIsAnIoErrorNamingThePath) {
  auto r = read_points2("/nonexistent/dir/points.txt");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::io);
  EXPECT_EQ(r.error().source, "/nonexistent/dir/points.txt");
}

TEST(PointsIo, ReadsFromAFileAndFromAStream) {
  test::TempFile file(".xyz", "0 1 2\n3 4 5\n");
  auto r = read_points3(file.path());
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->points.size(), 2u);
  std::istringstream in("7 8\n");
  auto s = read_points2(in, "<stdin>");
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->points[0], (Vec2{7, 8}));
  std::istringstream bad("7 x\n");
  auto t = read_points2(bad, "<stdin>");
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().what(), "<stdin>:1: expected a number, found 'x'");
}

TEST(NumberTable, ReadsTwelveNumberTransformsFromOneArgument) {
  auto r = parse_number_table("1,0,0,2.5,0,1,0,0,0,0,1,0", "--transform-b", {.columns = {12}});
  ASSERT_TRUE(r.ok()) << r.error().what();
  EXPECT_EQ(r->columns, 12);
  EXPECT_EQ(r->values[3], 2.5);
}

TEST(NumberTable, AcceptsAnyOfTheAllowedCountsButTheSameOnEveryLine) {
  auto four = parse_number_table("0 0 1 1\n2 2 3 3\n", "seg", {.columns = {4, 6}});
  ASSERT_TRUE(four.ok());
  EXPECT_EQ(four->columns, 4);
  EXPECT_EQ(four->rows(), 2u);
  auto five = parse_number_table("0 0 1 1 1\n", "seg", {.columns = {4, 6}});
  ASSERT_FALSE(five.ok());
  EXPECT_NE(five.error().message.find("expected 4 or 6"), std::string::npos);
  auto mixed = parse_number_table("0 0 1 1\n0 0 0 1 1 1\n", "seg", {.columns = {4, 6}});
  ASSERT_FALSE(mixed.ok());
  EXPECT_EQ(mixed.error().line, 2);
}

// Not a test of speed (no threshold): prints the parsing rate for the report.
TEST(PointsIo, ReportsParsingThroughput) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::string text;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    char buf[96];
    char* p = buf;
    for (int k = 0; k < 3; ++k) {
      p = std::to_chars(p, buf + 96, u(rng)).ptr;
      *p++ = k < 2 ? ' ' : '\n';
    }
    text.append(buf, p);
  }
  const auto start = std::chrono::steady_clock::now();
  auto r = parse_points3(text, "bench");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->points.size(), static_cast<std::size_t>(n));
  const double mb = static_cast<double>(text.size()) / 1e6;
  std::cout << "[ points ] parsed " << mb << " MB (" << n << " 3D points) in " << seconds
            << " s: " << mb / seconds << " MB/s\n";
  RecordProperty("points_mb_per_s", std::to_string(mb / seconds));
}

}  // namespace
}  // namespace contain::io

namespace contain::io {
namespace {

// The pieces of read_points*_chunked, in order, as one array.
template <class Point, class Read>
Result<std::vector<Point>> read_in_pieces(const std::filesystem::path& path,
                                          const ChunkedReading& reading, Read&& read) {
  std::vector<Point> all;
  const Status status = read(path, reading, [&](std::span<const Point> piece, double) {
    EXPECT_LE(piece.size(), reading.chunk);
    all.insert(all.end(), piece.begin(), piece.end());
  });
  if (!status) return status.error();
  return all;
}

bool same_bits(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i].x) != std::bit_cast<std::uint64_t>(b[i].x) ||
        std::bit_cast<std::uint64_t>(a[i].y) != std::bit_cast<std::uint64_t>(b[i].y)) {
      return false;
    }
  }
  return true;
}

// The ways of reading a file in pieces the tests below compare with the whole-file reader: piece
// sizes, blocks of a few lines (so that lines and slices straddle the ends of blocks) and threads.
std::vector<ChunkedReading> readings() {
  std::vector<ChunkedReading> out;
  for (const std::size_t chunk : {1u, 7u, 64u, 1000u}) {
    out.push_back({.chunk = chunk});
  }
  for (const std::size_t block : {64u, 100u, 997u, 4096u}) {
    for (const int threads : {1, 2, 3}) {
      out.push_back({.chunk = 50, .threads = threads, .block = block});
    }
  }
  out.push_back({.threads = 0});
  return out;
}

std::string describe(const ChunkedReading& r) {
  return "chunk " + std::to_string(r.chunk) + " threads " + std::to_string(r.threads) + " block " +
         std::to_string(r.block);
}

// Plain pieces are parsed straight into points, any other through the table parser: every
// piece size, block and thread count gives the whole-file reader's doubles bit for bit, and its
// errors (kind, line and message) exactly.
TEST(PointsIo, ChunkedReadingGivesTheWholeFileReadersPointsBitForBitAndItsErrors) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  std::string text;
  char buffer[64];
  for (int line = 0; line < 400; ++line) {
    const double x = line % 37 == 5 ? -0.0 : u(rng), y = line % 41 == 3 ? 5e-324 : u(rng) * 1e-9;
    std::string a(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
    std::string b(buffer, std::to_chars(buffer, buffer + sizeof buffer, y).ptr);
    switch (line % 50) {
      case 7:
        text += "# a comment line\n";
        break;
      case 13:
        text += "\n";
        break;
      case 21:
        text += a + ", " + b + "\n";
        continue;
      case 29:
        text += "\t+" + std::string(a[0] == '-' ? "1" : a) + "  " + b + " # tail\r\n";
        continue;
      case 33:
        text += a + "\t" + b + "\r\n";
        continue;
      default:
        break;
    }
    text += a + " " + b + "\n";
  }
  const test::TempFile file(".txt", text + "1.5 -2.5");  // the last line without its newline
  const auto whole = read_points2(file.path());
  ASSERT_TRUE(whole.ok()) << whole.error().what();
  for (const ChunkedReading& reading : readings()) {
    const auto pieces = read_in_pieces<Vec2>(file.path(), reading, read_points2_chunked);
    ASSERT_TRUE(pieces.ok()) << describe(reading) << ": " << pieces.error().what();
    EXPECT_TRUE(same_bits(*pieces, whole->points)) << describe(reading);
  }
  // An error late in the file: the same kind, message and line whatever the piece size.
  for (const char* bad : {"1 x\n", "1 2 3\n", "1e999 2\n", "1,,2\n", "1 2,\n", "7\n", "nan 1\n",
                          "1 -inf\n", "1 2x\n", "1-2\n", "1 2 # c\r\n3 4 5"}) {
    const test::TempFile broken(".txt", text + bad);
    const auto expected = read_points2(broken.path());
    ASSERT_FALSE(expected.ok()) << bad;
    for (const ChunkedReading& reading : readings()) {
      const auto got = read_in_pieces<Vec2>(broken.path(), reading, read_points2_chunked);
      ASSERT_FALSE(got.ok()) << bad << describe(reading);
      EXPECT_EQ(got.error().kind, expected.error().kind) << bad << describe(reading);
      EXPECT_EQ(got.error().line, expected.error().line) << bad << describe(reading);
      EXPECT_EQ(got.error().message, expected.error().message) << bad << describe(reading);
    }
  }
  // 3D: the same path with three columns.
  const test::TempFile three(".txt", "1 2 3\n4\t5 6\r\n# c\n7,8,9\n10 11 12");
  const auto whole3 = read_points3(three.path());
  ASSERT_TRUE(whole3.ok());
  for (const ChunkedReading& reading : readings()) {
    const auto pieces = read_in_pieces<Vec3>(three.path(), reading, read_points3_chunked);
    ASSERT_TRUE(pieces.ok()) << describe(reading);
    EXPECT_EQ(*pieces, whole3->points) << describe(reading);
  }
  // A byte order mark and a header before the first point, a wrong count many blocks later: the
  // message names the file's first point's line (3), as one pass over the file does.
  std::string headed = "\xEF\xBB\xBF# x y z\n\n";
  for (int i = 0; i < 200; ++i)
    headed += std::to_string(i) + " 0.25 -1e-3\n";
  const test::TempFile wrong(".txt", headed + "1 2\n");
  const auto expected = read_points3(wrong.path());
  ASSERT_FALSE(expected.ok());
  EXPECT_NE(expected.error().message.find("line 3 has 3"), std::string::npos)
      << expected.error().message;
  for (const ChunkedReading& reading : readings()) {
    const auto got = read_in_pieces<Vec3>(wrong.path(), reading, read_points3_chunked);
    ASSERT_FALSE(got.ok()) << describe(reading);
    EXPECT_EQ(got.error().line, expected.error().line) << describe(reading);
    EXPECT_EQ(got.error().message, expected.error().message) << describe(reading);
  }
}

// Lines far longer than a block (the block grows to hold them), numbers of thousands of digits,
// and a bad number at the end of such a line: the whole-file reader's points and error.
TEST(PointsIo, ChunkedReadingOfLinesLongerThanABlockGivesTheWholeFileReadersPointsAndErrors) {
  const std::string digits(3000, '3');
  const std::string blanks(5000, ' ');
  std::string text;
  for (int i = 0; i < 40; ++i) {
    text += i % 7 == 3 ? "0." + digits + blanks + "-" + digits + "e-3000\r\n"
                       : std::to_string(i) + " 0.5\n";
  }
  const test::TempFile file(".txt", text + blanks + "# " + digits);  // no final newline
  const auto whole = read_points2(file.path());
  ASSERT_TRUE(whole.ok()) << whole.error().what();
  EXPECT_EQ(whole->points.size(), 40u);
  for (const ChunkedReading& reading : readings()) {
    const auto pieces = read_in_pieces<Vec2>(file.path(), reading, read_points2_chunked);
    ASSERT_TRUE(pieces.ok()) << describe(reading) << ": " << pieces.error().what();
    EXPECT_TRUE(same_bits(*pieces, whole->points)) << describe(reading);
  }
  const test::TempFile broken(".txt", text + "1" + blanks + digits + "e9999\n2 2\n");
  const auto expected = read_points2(broken.path());
  ASSERT_FALSE(expected.ok());
  EXPECT_EQ(expected.error().line, 41);
  EXPECT_EQ(expected.error().kind, ErrorKind::invalid_value);
  for (const ChunkedReading& reading : readings()) {
    const auto got = read_in_pieces<Vec2>(broken.path(), reading, read_points2_chunked);
    ASSERT_FALSE(got.ok()) << describe(reading);
    EXPECT_EQ(got.error().line, expected.error().line) << describe(reading);
    EXPECT_EQ(got.error().message, expected.error().message) << describe(reading);
  }
}

}  // namespace
}  // namespace contain::io
