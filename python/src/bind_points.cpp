// contain.read_points: a point file into a numpy array by the library's reader, with its errors
// naming file and line (numpy.loadtxt took 1.85 s for the 10^6 points of 59 MB this reads in
// 0.28 s on one thread: 23:31 UTC 29 Nov, load 9).

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "arrays.h"
#include "bindings.h"
#include "contain/io/points_io.h"
#include "errors.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

static_assert(sizeof(Vec2) == 2 * sizeof(double) && sizeof(Vec3) == 3 * sizeof(double),
              "a point's numbers are its doubles side by side, as numpy's rows");

// How many numbers the first point line of the file holds (separated as the reader separates
// them: white space and commas), from its first 64 KB; 0 when those hold no point line.
std::size_t numbers_on_first_point_line(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::array<char, 1U << 16U> head{};
  file.read(head.data(), static_cast<std::streamsize>(head.size()));
  const std::string_view text(head.data(), static_cast<std::size_t>(file.gcount()));
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = text.substr(start, end - start);
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first != std::string_view::npos && line[first] != '#') {
      std::size_t numbers = 0;
      bool in_number = false;
      for (const char c : line) {
        const bool separator = c == ' ' || c == '\t' || c == '\r' || c == ',';
        if (!separator && !in_number) ++numbers;
        in_number = !separator;
      }
      return numbers;
    }
    start = end + 1;
  }
  return 0;
}

// Every point of the file, its numbers appended in file order (GIL released by the caller).
template <class Point>
Status read_all(const std::filesystem::path& path, int threads, std::vector<double>& values,
                Status (*read)(const std::filesystem::path&, const io::ChunkedReading&,
                               const std::function<void(std::span<const Point>, double)>&)) {
  return read(path, io::ChunkedReading{.threads = threads},
              [&](std::span<const Point> points, double /*share*/) {
                const auto* first = reinterpret_cast<const double*>(points.data());
                values.insert(values.end(), first, first + points.size() * sizeof(Point) / 8);
              });
}

py::array_t<double> read_points(const std::filesystem::path& path, std::optional<int> dimension,
                                int threads) {
  if (dimension && *dimension != 2 && *dimension != 3) {
    throw py::value_error("contain.read_points: dimension must be 2 or 3, not " +
                          std::to_string(*dimension));
  }
  if (threads < 0) throw py::value_error("contain.read_points: threads must be 0 (all) or more");
  const bool from_stdin = path == "-";
  if (!dimension && from_stdin) {
    throw py::value_error("contain.read_points: standard input (\"-\") needs dimension=2 or 3");
  }
  std::vector<double> values;
  Status status = Ok{};
  int columns = 0;
  {
    py::gil_scoped_release release;
    // A first line of 2 numbers makes a 2D file; any other count is read as 3D, whose reader
    // then names the line and its count.
    columns = dimension ? *dimension : numbers_on_first_point_line(path) == 2 ? 2 : 3;
    if (!from_stdin) {
      std::error_code error;
      const auto bytes = std::filesystem::file_size(path, error);
      // A point line has at least 2 bytes a number ("0 0\n"); a typical one about 20: room
      // for the usual case without growing, a bound on what a short file wastes.
      if (!error) values.reserve(static_cast<std::size_t>(bytes / 16 + 16));
    }
    status = columns == 2 ? read_all<Vec2>(path, threads, values, io::read_points2_chunked)
                          : read_all<Vec3>(path, threads, values, io::read_points3_chunked);
  }
  if (!status.ok()) throw Failure{status.error()};
  const auto rows = static_cast<py::ssize_t>(values.size() / static_cast<std::size_t>(columns));
  return to_numpy(std::move(values), rows, columns);
}

}  // namespace

void bind_points(py::module_& m) {
  m.def("read_points", &read_points, "path"_a, "dimension"_a = py::none(), py::kw_only(),
        "threads"_a = 0, R"doc(
Reads a point file into a float64 array of shape (N, 2) or (N, 3): one point a line, its numbers
separated by white space or commas, blank lines and '#' lines skipped (the format of
`contain inside --points`). Each value is the double nearest to its decimal text, as
`contain inside` reads it; the file is parsed on `threads` threads (0: all cores) without the GIL.

`dimension` (2 or 3) is what every point line must hold; by default the count of numbers on the
file's first point line (a file without points then gives an array of shape (0, 3)). The path
"-" reads standard input and needs `dimension`.

Raises ContainIOError (an OSError) when the file cannot be read, ContainError naming the file
and line for a malformed number, a NaN or infinite value, or a line with another count.
)doc");
}

}  // namespace contain::python
