#include "contain/io/points_io.h"

#include <algorithm>
#include <cstring>
#include <iostream>
#include <optional>
#include <tuple>
#include <utility>

#include "contain/io/number_table.h"
#include "io/text_scan.h"

namespace contain::io {
namespace {

Result<Points2> to_points2(Result<NumberTable> table) {
  if (!table) return table.error();
  Points2 out;
  out.points.reserve(table->rows());
  const std::vector<double>& v = table->values;
  for (std::size_t i = 0; i < table->rows(); ++i)
    out.points.push_back({v[2 * i], v[2 * i + 1]});
  out.lines = std::move(table->lines);
  return out;
}

Result<Points3> to_points3(Result<NumberTable> table) {
  if (!table) return table.error();
  Points3 out;
  out.points.reserve(table->rows());
  const std::vector<double>& v = table->values;
  for (std::size_t i = 0; i < table->rows(); ++i) {
    out.points.push_back({v[3 * i], v[3 * i + 1], v[3 * i + 2]});
  }
  out.lines = std::move(table->lines);
  return out;
}

const NumberTableOptions kTwo{.columns = {2}};
const NumberTableOptions kThree{.columns = {3}};

// The usual piece of a point file: each of its lines `columns` numbers apart by blanks and
// nothing else. Parses up to `chunk` such lines from `begin` straight into `points` (appended)
// and returns where the piece ends and how many lines it has; nullopt at the first line of any
// other kind (blank, a comment, commas, a bad number, another count), for the table parser to
// read the whole piece with its rules and messages. The numbers are the same doubles (the same
// parse_double). This skips the table's passes and arrays: at 10^7 points they were a third of
// the reading.
template <class Point>
std::optional<std::pair<std::size_t, std::size_t>> parse_plain_piece(std::string_view all,
                                                                     std::size_t begin,
                                                                     std::size_t chunk,
                                                                     std::vector<Point>& points) {
  constexpr int kColumns = sizeof(Point) / sizeof(double);
  const char* p = all.data() + begin;
  const char* const end = all.data() + all.size();
  std::size_t lines = 0;
  while (p != end && lines < chunk) {
    const char* eol =
        static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    if (eol == nullptr) eol = end;
    double v[kColumns];
    detail::skip_blanks(p, eol);
    for (int k = 0; k < kColumns; ++k) {
      if (k > 0) {
        const char* after = p;
        detail::skip_blanks(p, eol);
        if (p == after) return std::nullopt;
      }
      if (p == eol || detail::parse_double(p, eol, v[k]) != detail::NumberStatus::ok) {
        return std::nullopt;
      }
    }
    detail::skip_blanks(p, eol);
    if (p != eol) return std::nullopt;
    if constexpr (kColumns == 2) {
      points.push_back({v[0], v[1]});
    } else {
      points.push_back({v[0], v[1], v[2]});
    }
    p = eol == end ? end : eol + 1;
    ++lines;
  }
  return std::pair{static_cast<std::size_t>(p - all.data()), lines};
}

// The text once, then `chunk` lines at a time: the plain pieces straight into points, any other
// through the table parser; line numbers in errors are made the file's own again.
template <class Point>
Status read_chunked(const std::filesystem::path& path, std::size_t chunk,
                    const std::function<void(std::span<const Point>, double)>& consume) {
  const bool standard_input = path == "-";
  const std::string source = standard_input ? "<stdin>" : detail::source_name(path);
  auto text = standard_input ? detail::read_stream(std::cin, source) : detail::read_file(path);
  if (!text) return text.error();
  const std::string_view all = detail::skip_bom(*text);
  constexpr int kColumns = sizeof(Point) / sizeof(double);
  const NumberTableOptions& options = kColumns == 2 ? kTwo : kThree;
  chunk = std::max<std::size_t>(chunk, 1);
  std::vector<Point> points;
  std::int64_t lines_before = 0;
  std::size_t begin = 0;
  while (begin < all.size()) {
    points.clear();
    std::size_t end = begin, lines = 0;
    if (const auto plain = parse_plain_piece(all, begin, chunk, points)) {
      std::tie(end, lines) = *plain;
    } else {
      points.clear();
      while (end < all.size() && lines < chunk) {
        const void* newline = std::memchr(all.data() + end, '\n', all.size() - end);
        end = newline == nullptr
                  ? all.size()
                  : static_cast<std::size_t>(static_cast<const char*>(newline) - all.data()) + 1;
        ++lines;
      }
      auto table = parse_number_table(all.substr(begin, end - begin), source, options);
      if (!table) {
        Error error = table.error();
        if (error.line > 0) error.line += lines_before;
        return error;
      }
      const std::vector<double>& v = table->values;
      for (std::size_t i = 0; i < table->rows(); ++i) {
        if constexpr (kColumns == 2) {
          points.push_back({v[2 * i], v[2 * i + 1]});
        } else {
          points.push_back({v[3 * i], v[3 * i + 1], v[3 * i + 2]});
        }
      }
    }
    if (!points.empty()) {
      consume(points, static_cast<double>(end) / static_cast<double>(all.size()));
    }
    lines_before += static_cast<std::int64_t>(lines);
    begin = end;
  }
  return Ok{};
}

}  // namespace

Result<Points2> parse_points2(std::string_view text, const std::string& source) {
  return to_points2(parse_number_table(text, source, kTwo));
}
Result<Points3> parse_points3(std::string_view text, const std::string& source) {
  return to_points3(parse_number_table(text, source, kThree));
}
Result<Points2> read_points2(const std::filesystem::path& path) {
  return to_points2(read_number_table(path, kTwo));
}
Result<Points3> read_points3(const std::filesystem::path& path) {
  return to_points3(read_number_table(path, kThree));
}
Status read_points2_chunked(const std::filesystem::path& path, std::size_t chunk,
                            const std::function<void(std::span<const Vec2>, double)>& consume) {
  return read_chunked<Vec2>(path, chunk, consume);
}
Status read_points3_chunked(const std::filesystem::path& path, std::size_t chunk,
                            const std::function<void(std::span<const Vec3>, double)>& consume) {
  return read_chunked<Vec3>(path, chunk, consume);
}
Result<Points2> read_points2(std::istream& in, const std::string& source) {
  return to_points2(read_number_table(in, source, kTwo));
}
Result<Points3> read_points3(std::istream& in, const std::string& source) {
  return to_points3(read_number_table(in, source, kThree));
}

}  // namespace contain::io
