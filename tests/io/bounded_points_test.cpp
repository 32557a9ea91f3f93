// Points read from their numbers' first digits (src/io/number_bound.h, read_points*_bounded):
// every box holds the double std::from_chars gives for the whole token, on random digits of
// every length, signs, zeros, powers of ten and runs of nines, at every offset from the end of
// the text; tokens of other shapes are refused and read in full; the bounded readers take and
// refuse exactly the lines the chunked readers do, with the same errors, and their exact points
// are those readers' points bit for bit; a mapped file gives the pieces of its bytes read through
// a pipe.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "contain/io/points_io.h"
#include "io/number_bound.h"
#include "io/point_lines.h"
#include "io/temp_file.h"

namespace contain::io {
namespace {

// The double from_chars gives for the whole token at the start of `text`, and where it ends.
double whole_token(std::string_view text, const char*& end) {
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  EXPECT_TRUE(ec == std::errc{} || ec == std::errc::result_out_of_range) << text;
  end = ptr;
  if (ec == std::errc::result_out_of_range) {
    const char* p = text.data();
    EXPECT_EQ(detail::parse_double(p, text.data() + text.size(), value), detail::NumberStatus::ok);
  }
  return value;
}

// The token, followed by each way a token ends (nothing, blank, newline, comma, comment): the
// box holds from_chars' double and the pointer stops where from_chars stops.
void expect_bound_holds(const std::string& token) {
  for (const char* tail : {"", " ", "\n", ",1", "#", "\t2.5"}) {
    const std::string text = token + tail;
    const char* p = text.data();
    detail::NumberBound bound;
    ASSERT_TRUE(detail::bound_plain_number(p, text.data() + text.size(), bound)) << text;
    const char* end = nullptr;
    const double value = whole_token(text, end);
    EXPECT_EQ(p, end) << text;
    EXPECT_LE(bound.lo, value) << text;
    EXPECT_GE(bound.hi, value) << text;
    EXPECT_LE(bound.hi - bound.lo, 2e-8 + 1e-14 * std::abs(value)) << text;  // a useful box
  }
}

TEST(NumberBound, TheBoxHoldsTheFromCharsDoubleOfRandomPlainTokensOfEveryLength) {
  std::mt19937_64 rng(27);
  std::uniform_int_distribution<int> digit(0, 9), whole_length(1, 7), fraction_length(1, 40);
  for (int k = 0; k < 20000; ++k) {
    std::string token = k % 2 == 0 ? "-" : "";
    const int whole = whole_length(rng), fraction = fraction_length(rng);
    // Some tokens of one repeated digit (runs of 9s and 0s), most random.
    const int repeated = k % 5 == 0 ? 9 : k % 7 == 0 ? 0 : -1;
    for (int i = 0; i < whole; ++i)
      token += static_cast<char>('0' + (repeated >= 0 ? repeated : digit(rng)));
    token += '.';
    for (int i = 0; i < fraction; ++i)
      token += static_cast<char>('0' + (repeated >= 0 ? repeated : digit(rng)));
    expect_bound_holds(token);
  }
}

TEST(NumberBound, TheBoxHoldsTheDoubleNearPowersOfTenZerosAndUnderflow) {
  for (int n = 1; n <= 20; ++n) {
    const std::string nines(static_cast<std::size_t>(n), '9'),
        zeros(static_cast<std::size_t>(n), '0');
    for (const std::string& token :
         {"0." + nines, "9999999." + nines, "0." + zeros + "1", "1." + zeros, "0." + zeros,
          "-0." + zeros, "-0." + nines, "0." + zeros + "5", "9." + nines + "5", "0.0000000" + nines,
          "0.00000001" + zeros, "1000000." + zeros + "1"}) {
      expect_bound_holds(token);
    }
  }
  // Far below the smallest subnormal: from_chars reports underflow, the reader gives zero.
  expect_bound_holds("0." + std::string(400, '0') + "1");
  expect_bound_holds("-0." + std::string(330, '0') + "24703282292062328");
  // Shortest round-trip decimals of random doubles, the files' own form.
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  char buffer[64];
  for (int k = 0; k < 20000; ++k) {
    const double x = u(rng) * (k % 3 == 0 ? 1e-6 : 1.0);
    const std::string token(
        buffer, std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::fixed).ptr);
    if (token.find('.') != std::string::npos) expect_bound_holds(token);
  }
}

TEST(NumberBound, TokensOfOtherShapesAreRefusedAndThePointerStays) {
  for (const char* token : {"1",          "12",
                            "1.",         "-1.",
                            ".5",         "-.5",
                            "+1.5",       "1.5e3",
                            "1.5E-3",     "1.5e",
                            "12345678.5", "-",
                            "",           "inf",
                            "-inf",       "nan",
                            "0x1.8",      "1e5",
                            "a",          " 1.5",
                            ",1.5",       "1.0000000000000000000e1"}) {
    const std::string text = token;
    const char* p = text.data();
    detail::NumberBound bound;
    EXPECT_FALSE(detail::bound_plain_number(p, text.data() + text.size(), bound)) << token;
    EXPECT_EQ(p, text.data()) << token;
  }
}

// A text of many lines, each with random spacing, commas, comments and odd numbers.
std::string random_point_text(std::mt19937_64& rng, int lines, int columns) {
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::uniform_int_distribution<int> shape(0, 19);
  char buffer[64];
  std::string text;
  for (int line = 0; line < lines; ++line) {
    const int s = shape(rng);
    if (s == 0) {
      text += "# comment\n";
      continue;
    }
    if (s == 1) {
      text += "\n";
      continue;
    }
    for (int c = 0; c < columns; ++c) {
      if (c > 0) text += s == 2 ? ", " : s == 3 ? "," : s == 4 ? "\t" : " ";
      const double v = u(rng);
      switch ((s + c) % 9) {
        case 5:
          text += std::to_string(static_cast<int>(v));  // an integer
          break;
        case 6:
          text += std::string(
              buffer, std::to_chars(buffer, buffer + 64, v, std::chars_format::scientific).ptr);
          break;
        default:
          text += std::string(buffer, std::to_chars(buffer, buffer + 64, v).ptr);
      }
    }
    text += s == 7 ? " # tail\r\n" : s == 8 ? "\r\n" : "\n";
  }
  return text;
}

template <class Point, class Bounded>
void expect_bounded_scan_as_point_scan(std::string_view text) {
  std::vector<Point> points;
  std::vector<Bounded> bounded;
  const detail::PointLinesScan a = detail::scan_point_lines(text, points);
  const detail::PointLinesScan b = detail::scan_bounded_lines(text, bounded);
  EXPECT_EQ(a.complete, b.complete);
  EXPECT_EQ(a.lines, b.lines);
  EXPECT_EQ(a.first_row, b.first_row);
  ASSERT_EQ(points.size(), bounded.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point exact = exact_point(bounded[i]);
    using Bits = std::array<std::uint64_t, sizeof(Point) / 8>;
    EXPECT_TRUE(std::bit_cast<Bits>(exact) == std::bit_cast<Bits>(points[i]));
    EXPECT_TRUE(bounded[i].box.contains(points[i]));
  }
}

TEST(BoundedPoints, TheBoundedScanTakesTheLinesThePointScanTakesWithBoxesHoldingItsPoints) {
  std::mt19937_64 rng(9);
  for (int round = 0; round < 20; ++round) {
    const std::string two = random_point_text(rng, 300, 2);
    expect_bounded_scan_as_point_scan<Vec2, BoundedPoint2>(two);
    const std::string three = random_point_text(rng, 300, 3);
    expect_bounded_scan_as_point_scan<Vec3, BoundedPoint3>(three);
    // Broken lines: the scans stop at the same line.
    for (const char* bad : {"1.5x 2\n", "1.5 2.5 3.5\n", "1.5e 2\n", "1.5.5 2\n", "0.5,,1.5\n",
                            "0.5 nan\n", "0.5 1e999\n", "-0.5-0.5\n", "0.25 0.5,\n"}) {
      expect_bounded_scan_as_point_scan<Vec2, BoundedPoint2>(two + bad + "1.5 2.5\n");
    }
  }
}

// The pieces of a bounded reader as exact points, in order.
template <class Point, class Bounded, class Read>
Result<std::vector<Point>> exact_pieces(const std::filesystem::path& path,
                                        const ChunkedReading& reading, Read&& read) {
  std::vector<Point> all;
  const Status status = read(path, reading, [&](std::span<const Bounded> piece, double) {
    EXPECT_LE(piece.size(), reading.chunk);
    for (const Bounded& point : piece) {
      all.push_back(exact_point(point));
      EXPECT_TRUE(point.box.contains(all.back()));
    }
  });
  if (!status) return status.error();
  return all;
}

TEST(BoundedPoints, TheBoundedReadersGiveTheChunkedReadersPointsAndErrors) {
  std::mt19937_64 rng(12);
  const std::string text = random_point_text(rng, 2000, 2);
  const std::vector<ChunkedReading> ways{{.chunk = 7},
                                         {.chunk = 50, .threads = 2, .block = 100},
                                         {.chunk = 64, .block = 997},
                                         {.threads = 3, .block = 4096},
                                         {}};
  const test::TempFile file(".txt", text + "1.5 -2.5");
  const auto whole = read_points2(file.path());
  ASSERT_TRUE(whole.ok()) << whole.error().what();
  for (const ChunkedReading& reading : ways) {
    const auto got = exact_pieces<Vec2, BoundedPoint2>(file.path(), reading, read_points2_bounded);
    ASSERT_TRUE(got.ok()) << got.error().what();
    ASSERT_EQ(got->size(), whole->points.size());
    for (std::size_t i = 0; i < got->size(); ++i) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>((*got)[i].x),
                std::bit_cast<std::uint64_t>(whole->points[i].x));
      EXPECT_EQ(std::bit_cast<std::uint64_t>((*got)[i].y),
                std::bit_cast<std::uint64_t>(whole->points[i].y));
    }
  }
  for (const char* bad :
       {"1 x\n", "1.5 2.5 3.5\n", "1e999 2\n", "0.5,,2\n", "0.5 2,\n", "7\n", "nan 1\n", "1 -inf\n",
        "0.5 2.25x\n", "0.5-2.5\n", "1.5e 2\n", "0.125 0.5.5\n"}) {
    const test::TempFile broken(".txt", text + bad + "0.5 0.5\n");
    const auto expected = read_points2(broken.path());
    ASSERT_FALSE(expected.ok()) << bad;
    for (const ChunkedReading& reading : ways) {
      const auto got =
          exact_pieces<Vec2, BoundedPoint2>(broken.path(), reading, read_points2_bounded);
      ASSERT_FALSE(got.ok()) << bad;
      EXPECT_EQ(got.error().kind, expected.error().kind) << bad;
      EXPECT_EQ(got.error().line, expected.error().line) << bad;
      EXPECT_EQ(got.error().message, expected.error().message) << bad;
    }
  }
  const std::string text3 = random_point_text(rng, 500, 3);
  const test::TempFile three(".txt", text3);
  const auto whole3 = read_points3(three.path());
  ASSERT_TRUE(whole3.ok());
  for (const ChunkedReading& reading : ways) {
    const auto got = exact_pieces<Vec3, BoundedPoint3>(three.path(), reading, read_points3_bounded);
    ASSERT_TRUE(got.ok());
    EXPECT_EQ(*got, whole3->points);
  }
  const test::TempFile wrong3(".txt", text3 + "0.5 0.5\n");
  const auto expected3 = read_points3(wrong3.path());
  ASSERT_FALSE(expected3.ok());
  const auto got3 = exact_pieces<Vec3, BoundedPoint3>(wrong3.path(), {}, read_points3_bounded);
  ASSERT_FALSE(got3.ok());
  EXPECT_EQ(got3.error().message, expected3.error().message);
  EXPECT_EQ(got3.error().line, expected3.error().line);
}

}  // namespace
}  // namespace contain::io

namespace contain::io {
namespace {

// What a bounded reader handed over: each piece's size, the exact points, and its status.
struct PiecesRead {
  std::vector<std::size_t> sizes;
  std::vector<Vec2> points;
  Status status = Ok{};
};

PiecesRead read_pieces(const std::filesystem::path& path, const ChunkedReading& reading) {
  PiecesRead read;
  read.status =
      read_points2_bounded(path, reading, [&](std::span<const BoundedPoint2> piece, double) {
        read.sizes.push_back(piece.size());
        for (const BoundedPoint2& point : piece)
          read.points.push_back(exact_point(point));
      });
  return read;
}

// `text` read from a pipe (a FIFO: read() into blocks, never mapped), written by a thread.
PiecesRead read_piped(const std::string& text, const ChunkedReading& reading) {
  const test::TempFile fifo(".fifo");
  EXPECT_EQ(::mkfifo(fifo.path().c_str(), 0600), 0);
  // A reader that stops at an error closes the pipe before the writer is done: EPIPE, no signal.
  const auto old_handler = std::signal(SIGPIPE, SIG_IGN);
  std::thread writer([&] {
    const int fd = ::open(fifo.path().c_str(), O_WRONLY);
    for (std::size_t at = 0; fd >= 0 && at < text.size();) {
      const ssize_t wrote = ::write(fd, text.data() + at, text.size() - at);
      if (wrote <= 0) break;
      at += static_cast<std::size_t>(wrote);
    }
    if (fd >= 0) ::close(fd);
  });
  PiecesRead read = read_pieces(fifo.path(), reading);
  writer.join();
  std::signal(SIGPIPE, old_handler);
  return read;
}

TEST(BoundedPoints, AMappedFileGivesThePiecesPointsAndErrorsOfTheSameBytesThroughAPipe) {
  std::mt19937_64 rng(27);
  const std::string text = random_point_text(rng, 600, 2);
  const std::string long_line = "1.25" + std::string(300, ' ') + "-0.5\n";
  const std::size_t cut = text.find('\n', 997) + 1;
  const std::vector<std::string> texts{
      text,
      "\xEF\xBB\xBF" + text,                                       // a byte order mark
      text.substr(0, cut) + long_line + text.substr(cut) + "7 8",  // a line past a block
      text + "0.5 x\n" + text,                                     // an error
      text.substr(0, 4096),                                        // a block's size exactly
  };
  const std::vector<ChunkedReading> ways{
      {.chunk = 7, .block = 100}, {.chunk = 64, .block = 997}, {.threads = 2, .block = 4096}, {}};
  for (std::size_t t = 0; t < texts.size(); ++t) {
    const test::TempFile file(".txt", texts[t]);
    for (const ChunkedReading& reading : ways) {
      ChunkedReading map = reading;
      map.map = true;
      const PiecesRead mapped = read_pieces(file.path(), map);
      const PiecesRead piped = read_piped(texts[t], reading);
      EXPECT_EQ(mapped.sizes, piped.sizes) << t << " " << reading.block;
      EXPECT_EQ(mapped.points, piped.points) << t << " " << reading.block;
      ASSERT_EQ(mapped.status.ok(), piped.status.ok()) << t << " " << reading.block;
      if (!mapped.status.ok()) {
        EXPECT_EQ(mapped.status.error().line, piped.status.error().line) << t;
        EXPECT_EQ(mapped.status.error().message, piped.status.error().message) << t;
        if (t == 3) {
          EXPECT_EQ(mapped.status.error().line, 601);
        }
      }
    }
  }
}

}  // namespace
}  // namespace contain::io
