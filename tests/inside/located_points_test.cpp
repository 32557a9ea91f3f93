// The locating readers (io::locate_points2_bounded, locate_points3_bounded with io::box_locator):
// the points answered as the scan hands them over give exactly the answers of the index's exact
// locate on the points read_points2/3 give, on random points, points on vertices and edges, points
// on and within one ulp of grid lines, in every text form (plain, exponents, '+', commas, comments,
// CR LF), on one thread and several, read or mapped, in small and default blocks; and the errors
// (message, line) of a bad line first, at a block's edge and last are the chunked reader's.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <mutex>
#include <random>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "contain/inside/mesh_index.h"
#include "contain/inside/polygon_index.h"
#include "contain/io/points_io.h"
#include "inside/mesh_test_meshes.h"
#include "inside/polygon_random.h"
#include "io/temp_file.h"

namespace contain::inside {
namespace {

// A number in one of the forms a point file may hold: most in the shortest round-trip form (a
// plain -D.F for most, an exponent for tiny ones), some in 17 digits, some with '+' or an
// exponent written out (read in full, not bounded).
std::string number_text(double v, std::mt19937_64& rng) {
  char buffer[64];
  const int form = static_cast<int>(rng() % 8);
  std::to_chars_result r{};
  if (form == 0) {
    r = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::scientific);
  } else if (form == 1) {
    r = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, 17);
  } else {
    r = std::to_chars(buffer, buffer + sizeof buffer, v);
  }
  std::string text(buffer, r.ptr);
  if (form == 2 && v >= 0.0) text = "+" + text;
  return text;
}

// The points as a point file: separators of every kind, comments and blank lines between.
std::string points_text(std::span<const double> values, int columns, std::mt19937_64& rng) {
  std::string text = "# points\n";
  for (std::size_t i = 0; i + static_cast<std::size_t>(columns) <= values.size();
       i += static_cast<std::size_t>(columns)) {
    const int decor = static_cast<int>(rng() % 40);
    if (decor == 0) text += "\n";
    if (decor == 1) text += "# a comment\n";
    for (int k = 0; k < columns; ++k) {
      if (k > 0) text += decor == 2 ? ", " : decor == 3 ? "\t" : " ";
      text += number_text(values[i + static_cast<std::size_t>(k)], rng);
    }
    text += decor == 4 ? "\r\n" : decor == 5 ? " # after\n" : "\n";
  }
  return text;
}

// The ways of reading: one thread and several, small blocks (many block edges) and the default,
// read into blocks and mapped.
std::vector<io::ChunkedReading> reading_ways() {
  std::vector<io::ChunkedReading> ways;
  for (const bool map : {false, true}) {
    ways.push_back({.chunk = 7, .threads = 1, .block = 100, .map = map});
    ways.push_back({.chunk = 1000, .threads = 1, .block = 997, .map = map});
    ways.push_back({.threads = 1, .map = map});
    ways.push_back({.chunk = 64, .threads = 2, .block = 4096, .map = map});
    ways.push_back({.threads = 3, .map = map});
  }
  return ways;
}

// How often a locator settled a point by its box and left one to the exact locate, counted on
// every reading thread.
struct Counted {
  std::atomic<std::int64_t> settled{0}, left{0};
};

template <class Locator>
Locator counted(Locator locator, Counted& counts) {
  auto settle = locator.settle;
  locator.settle = [settle, &counts](auto run, std::span<Location> out) {
    const std::uint64_t left = settle(run, out);
    counts.left += std::popcount(left);
    counts.settled += static_cast<std::int64_t>(run.size()) - std::popcount(left);
    return left;
  };
  return locator;
}

// The answers of the locating reader, or its error.
template <class Locator, class Read>
Result<std::vector<Location>> located(const std::filesystem::path& path,
                                      const io::ChunkedReading& reading, const Locator& locator,
                                      Read&& read) {
  std::vector<Location> all;
  const Status status =
      read(path, reading, locator, [&](std::span<const Location> answers, double) {
        EXPECT_LE(answers.size(), reading.chunk);
        all.insert(all.end(), answers.begin(), answers.end());
      });
  if (!status) return status.error();
  return all;
}

// The exact locate of every point read in full: what every locating read must give.
template <class Index, class Point>
std::vector<Location> exact_answers(const Index& index, const std::vector<Point>& points) {
  std::vector<Location> out(points.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = index.locate(points[i]);
  return out;
}

// The points of rings, their grid lines and random points around them, as doubles x, y, ...
std::vector<double> polygon_probes(const PolygonIndex& index, const std::vector<Ring>& rings,
                                   std::mt19937_64& rng) {
  const Box2 b = index.bounds();
  std::uniform_real_distribution<double> ux(b.min.x - 0.25, b.max.x + 0.25),
      uy(b.min.y - 0.25, b.max.y + 0.25);
  std::vector<double> values;
  const auto add = [&](double x, double y) {
    values.push_back(x);
    values.push_back(y);
  };
  for (int k = 0; k < 3000; ++k)
    add(ux(rng), uy(rng));
  for (const Vec2& p : test::points_near_rings(rng, rings, 3))
    add(p.x, p.y);
  // On each grid line and one ulp either side of it, at random heights (and the same across).
  for (const double x : index.grid_x()) {
    for (const double at : {x, std::nextafter(x, -1e300), std::nextafter(x, 1e300)})
      add(at, uy(rng));
  }
  for (const double y : index.grid_y()) {
    for (const double at : {y, std::nextafter(y, -1e300), std::nextafter(y, 1e300)})
      add(ux(rng), at);
  }
  return values;
}

TEST(LocatedPoints, PolygonAnswersAsScannedAreTheExactLocateOfEveryPointReadInFull) {
  std::mt19937_64 rng(27);
  for (int round = 0; round < 6; ++round) {
    const std::vector<Ring> rings =
        round % 2 == 0 ? test::random_integer_rings(rng, 3, 12, 8)
                       : std::vector<Ring>{test::random_star(rng, 40 + 30 * round, 0.0, 0.0, 1.0)};
    // A fine grid (many queries), and one cell (few: locate_settled without packed states).
    for (const std::size_t queries : {std::size_t{0}, std::size_t{1}}) {
      const PolygonIndex index(std::span<const Ring>(rings), {.queries = queries});
      const test::TempFile file(".txt", points_text(polygon_probes(index, rings, rng), 2, rng));
      const auto points = io::read_points2(file.path());
      ASSERT_TRUE(points.ok()) << points.error().what();
      const std::vector<Location> expected = exact_answers(index, points->points);
      Counted counts;
      const io::BoxLocator2 locator = counted(io::box_locator<io::BoundedPoint2>(index), counts);
      for (const io::ChunkedReading& reading : reading_ways()) {
        const auto got = located(file.path(), reading, locator, io::locate_points2_bounded);
        ASSERT_TRUE(got.ok()) << got.error().what();
        ASSERT_EQ(*got, expected) << round << " " << reading.threads << " " << reading.block;
      }
      // Both ways of answering ran: boxes settled, and boxes across lines or edges left.
      EXPECT_GT(counts.settled.load(), counts.left.load());
      EXPECT_GT(counts.left.load(), 0);
    }
  }
}

// Random points around a mesh's bounds, a quarter lattice (vertices, faces and grid planes of the
// test meshes), the same lattice one ulp off, and the vertices, as doubles x, y, z, ...
std::vector<double> mesh_probes(const Mesh& mesh, const Box3& b, std::mt19937_64& rng) {
  std::vector<double> values;
  const auto add = [&](Vec3 p) { values.insert(values.end(), {p.x, p.y, p.z}); };
  const auto around = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo - 0.5, hi + 0.5)(rng);
  };
  std::uniform_int_distribution<int> lattice(-2, 18);
  // On the lattice (`towards` 0), or one ulp off it, down (-1e300) or up (1e300).
  const auto quarter = [&](double towards) {
    const double v = 0.25 * lattice(rng);
    return towards == 0.0 ? v : std::nextafter(v, towards);
  };
  for (int k = 0; k < 3000; ++k)
    add({around(b.min.x, b.max.x), around(b.min.y, b.max.y), around(b.min.z, b.max.z)});
  for (const double towards : {0.0, -1e300, 1e300}) {
    for (int k = 0; k < 1000; ++k)
      add({quarter(towards), quarter(towards), quarter(towards)});
  }
  for (const Vec3& v : mesh.vertices)
    add(v);
  return values;
}

TEST(LocatedPoints, MeshAnswersAsScannedAreTheExactLocateOfEveryPointReadInFull) {
  std::mt19937_64 rng(3);
  for (const Mesh& mesh : {test::grid_cube(0.0, 4.0, 3), test::octahedron(1.5), test::l_prism(),
                           test::scaled(test::grid_cube(0.0, 4.0, 2), 0.5)}) {
    const MeshIndex index(mesh);
    const std::vector<double> values = mesh_probes(mesh, index.bounds(), rng);
    const test::TempFile file(".txt", points_text(values, 3, rng));
    const auto points = io::read_points3(file.path());
    ASSERT_TRUE(points.ok()) << points.error().what();
    const std::vector<Location> expected = exact_answers(index, points->points);
    Counted counts;
    const io::BoxLocator3 locator = counted(io::box_locator<io::BoundedPoint3>(index), counts);
    for (const io::ChunkedReading& reading : reading_ways()) {
      const auto got = located(file.path(), reading, locator, io::locate_points3_bounded);
      ASSERT_TRUE(got.ok()) << got.error().what();
      ASSERT_EQ(*got, expected) << reading.threads << " " << reading.block;
    }
    EXPECT_GT(counts.settled.load(), 0);
    EXPECT_GT(counts.left.load(), 0);
  }
}

// Each bad line first, on a line ending near a block's edge (4096) and last in `body`: the
// locating reader's error (kind, message, line) is the chunked reader's (`read_all`), every way.
template <class Locator, class Read, class ReadAll>
void expect_chunked_errors(const std::string& body, std::initializer_list<const char*> bad_lines,
                           const Locator& locator, Read&& read, ReadAll&& read_all) {
  const std::size_t edge = body.find('\n', 4096 - 40) + 1;
  for (const char* bad : bad_lines) {
    for (const std::string& text :
         {bad + body, body.substr(0, edge) + bad + body.substr(edge), body + bad}) {
      const test::TempFile file(".txt", text);
      const auto expected = read_all(file.path());
      ASSERT_FALSE(expected.ok()) << bad;
      for (const io::ChunkedReading& reading : reading_ways()) {
        const auto got = located(file.path(), reading, locator, read);
        ASSERT_FALSE(got.ok()) << bad;
        EXPECT_EQ(got.error().kind, expected.error().kind) << bad;
        EXPECT_EQ(got.error().line, expected.error().line) << bad << " " << reading.block;
        EXPECT_EQ(got.error().message, expected.error().message) << bad;
      }
    }
  }
}

TEST(LocatedPoints, ABadLineFirstAtABlockEdgeOrLastIsTheChunkedReadersError) {
  std::mt19937_64 rng(12);
  const std::vector<Ring> rings{test::random_star(rng, 30, 0.0, 0.0, 1.0)};
  const PolygonIndex index{std::span<const Ring>(rings)};
  const io::BoxLocator2 locator = io::box_locator<io::BoundedPoint2>(index);
  std::vector<double> values;
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  for (int k = 0; k < 4000; ++k)
    values.push_back(u(rng));
  const std::string body = points_text(values, 2, rng);
  const auto bad = {"1 x\n",   "1.5 2.5 3.5\n", "1e999 2\n", "0.5,,2\n",     "7\n",
                    "nan 1\n", "0.5 2.25x\n",   "0.5-2.5\n", "0.125 0.5.5\n"};
  const auto read_all = [](const auto& path) { return io::read_points2(path); };
  expect_chunked_errors(body, bad, locator, io::locate_points2_bounded, read_all);
}

// A last line without its newline, a UTF-8 byte order mark, and both: the same points, so the
// exact locate of each, as read_points2 reads them.
TEST(LocatedPoints, ALastLineWithoutNewlineAndAByteOrderMarkAreReadAsEver) {
  std::mt19937_64 rng(44);
  const std::vector<Ring> rings{test::random_star(rng, 60, 0.0, 0.0, 1.0)};
  const PolygonIndex index{std::span<const Ring>(rings)};
  std::string body = points_text(polygon_probes(index, rings, rng), 2, rng);
  body += "0.25 0.5";  // no newline
  for (const std::string& text :
       {body, "\xEF\xBB\xBF" + body, "\xEF\xBB\xBF" + std::string("0.125 0.75")}) {
    const test::TempFile file(".txt", text);
    const auto points = io::read_points2(file.path());
    ASSERT_TRUE(points.ok()) << points.error().what();
    ASSERT_FALSE(points->points.empty());
    const std::vector<Location> expected = exact_answers(index, points->points);
    const io::BoxLocator2 locator = io::box_locator<io::BoundedPoint2>(index);
    for (const io::ChunkedReading& reading : reading_ways()) {
      const auto got = located(file.path(), reading, locator, io::locate_points2_bounded);
      ASSERT_TRUE(got.ok()) << got.error().what();
      ASSERT_EQ(*got, expected) << reading.threads << " " << reading.block;
    }
  }
}

// 3D: a bad line first, at a block's edge or last is the chunked reader's error (message, line).
TEST(LocatedPoints, A3DBadLineIsTheChunkedReadersError) {
  std::mt19937_64 rng(13);
  const Mesh mesh = test::grid_cube(0.0, 4.0, 3);
  const MeshIndex index(mesh);
  const io::BoxLocator3 locator = io::box_locator<io::BoundedPoint3>(index);
  const std::string body = points_text(mesh_probes(mesh, index.bounds(), rng), 3, rng);
  // Too few numbers, too many, a word, out of range, an empty field, a bad token's tail.
  const auto bad = {"1 2\n",      "1.5 2.5 3.5 4.5\n", "1 x 2\n",        "1e999 0 0\n",
                    "0.5,,2,3\n", "0.5 2.25x 1\n",     "0.125 0.5.5 1\n"};
  expect_chunked_errors(body, bad, locator, io::locate_points3_bounded,
                        [](const auto& path) { return io::read_points3(path); });
}

// A file of more than 3 MB read on 3 threads in the default block (8 MB) is cut into 3 slices
// (kSliceBytes: 1 MB each at least), settled and located at once on 3 threads, each with points
// left to the exact locate: the answers are still the exact locate of every point, in file order.
TEST(LocatedPoints, SlicesSettledAtOnceOnThreeThreadsAnswerEveryPointExactly) {
  std::mt19937_64 rng(31);
  const std::vector<Ring> rings{test::random_star(rng, 100, 0.0, 0.0, 1.0)};
  const PolygonIndex index{std::span<const Ring>(rings)};
  // The probes (random, near the edges, on and off grid lines) again and again, shuffled so that
  // every slice has points of each kind.
  std::vector<Vec2> probes;
  while (probes.size() < 100000) {
    const std::vector<double> values = polygon_probes(index, rings, rng);
    for (std::size_t i = 0; i + 1 < values.size(); i += 2)
      probes.push_back({values[i], values[i + 1]});
  }
  std::shuffle(probes.begin(), probes.end(), rng);
  std::vector<double> values;
  for (const Vec2& p : probes)
    values.insert(values.end(), {p.x, p.y});
  const test::TempFile file(".txt", points_text(values, 2, rng));
  ASSERT_GE(std::filesystem::file_size(file.path()), std::uintmax_t{3} << 20);
  const auto points = io::read_points2(file.path());
  ASSERT_TRUE(points.ok()) << points.error().what();
  const std::vector<Location> expected = exact_answers(index, points->points);
  for (const bool map : {false, true}) {
    // The points each reading thread left to the exact locate (a slice is one thread's).
    std::mutex mutex;
    std::map<std::thread::id, std::int64_t> left_by_thread;
    io::BoxLocator2 locator = io::box_locator<io::BoundedPoint2>(index);
    locator.settle = [settle = locator.settle, &mutex, &left_by_thread](
                         std::span<const io::BoundedPoint2> run, std::span<Location> out) {
      const std::uint64_t left = settle(run, out);
      const std::lock_guard lock(mutex);
      left_by_thread[std::this_thread::get_id()] += std::popcount(left);
      return left;
    };
    const auto got =
        located(file.path(), {.threads = 3, .map = map}, locator, io::locate_points2_bounded);
    ASSERT_TRUE(got.ok()) << got.error().what();
    ASSERT_EQ(*got, expected) << map;
    ASSERT_EQ(left_by_thread.size(), 3U) << map;
    for (const auto& [thread, left] : left_by_thread)
      EXPECT_GT(left, 0) << map;
  }
}

// A locator missing a function is an Error naming it, not std::bad_function_call on a reading
// thread (std::terminate).
TEST(LocatedPoints, AnEmptyLocatorIsAnErrorNotACrash) {
  const test::TempFile file(".txt", "0.5 0.5\n1.5 2.5\n");
  for (const io::ChunkedReading& reading : reading_ways()) {
    const auto got2 = located(file.path(), reading, io::BoxLocator2{}, io::locate_points2_bounded);
    ASSERT_FALSE(got2.ok());
    EXPECT_EQ(got2.error().kind, ErrorKind::usage);
    EXPECT_NE(got2.error().message.find("locator"), std::string::npos) << got2.error().message;
    const auto got3 = located(file.path(), reading, io::BoxLocator3{}, io::locate_points3_bounded);
    ASSERT_FALSE(got3.ok());
    EXPECT_EQ(got3.error().kind, ErrorKind::usage);
  }
  // One function alone is as empty.
  std::mt19937_64 rng(5);
  const std::vector<Ring> rings{test::random_star(rng, 20, 0.0, 0.0, 1.0)};
  const PolygonIndex index{std::span<const Ring>(rings)};
  io::BoxLocator2 half = io::box_locator<io::BoundedPoint2>(index);
  half.locate = nullptr;
  const auto got = located(file.path(), {.threads = 2}, half, io::locate_points2_bounded);
  ASSERT_FALSE(got.ok());
  EXPECT_EQ(got.error().kind, ErrorKind::usage);
}

// A settle that sets bits past its run (which name no point) gives the answers of one that does
// not: the reader reads no point past the run.
TEST(LocatedPoints, StrayBitsPastTheRunAreIgnored) {
  std::mt19937_64 rng(8);
  const std::vector<Ring> rings{test::random_star(rng, 50, 0.0, 0.0, 1.0)};
  const PolygonIndex index{std::span<const Ring>(rings)};
  const test::TempFile file(".txt", points_text(polygon_probes(index, rings, rng), 2, rng));
  const auto points = io::read_points2(file.path());
  ASSERT_TRUE(points.ok()) << points.error().what();
  const std::vector<Location> expected = exact_answers(index, points->points);
  io::BoxLocator2 stray = io::box_locator<io::BoundedPoint2>(index);
  std::atomic<std::int64_t> short_runs{0};
  stray.settle = [settle = stray.settle, &short_runs](std::span<const io::BoundedPoint2> run,
                                                      std::span<Location> out) {
    const std::uint64_t left = settle(run, out);
    if (run.size() >= 64) return left;
    ++short_runs;
    return left | ~std::uint64_t{0} << run.size();
  };
  for (const io::ChunkedReading& reading : reading_ways()) {
    const auto got = located(file.path(), reading, stray, io::locate_points2_bounded);
    ASSERT_TRUE(got.ok()) << got.error().what();
    ASSERT_EQ(*got, expected) << reading.threads << " " << reading.block;
  }
  EXPECT_GT(short_runs.load(), 0);
}

}  // namespace
}  // namespace contain::inside
