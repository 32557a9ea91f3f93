// contain.read_points and iter_points: a point file into numpy arrays, whole or a chunk at a
// time, by the library's reader, with its errors naming file and line (numpy.loadtxt took 1.85 s
// for the 10^6 points of 59 MB this reads in 0.28 s on one thread: 23:31 UTC 29 Nov, load 9).

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "arrays.h"
#include "bindings.h"
#include "contain/io/number_table.h"
#include "contain/io/points_io.h"
#include "errors.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

static_assert(sizeof(Vec2) == 2 * sizeof(double) && sizeof(Vec3) == 3 * sizeof(double),
              "a point's numbers are its doubles side by side, as numpy's rows");

// The points' numbers, row after row (the layout numpy's (N, 2) / (N, 3) arrays have).
template <class Point>
std::span<const double> numbers_of(std::span<const Point> points) {
  return {reinterpret_cast<const double*>(points.data()),
          points.size() * sizeof(Point) / sizeof(double)};
}

// How many numbers the first point line of a regular file holds, read from its first 64 KB by
// the library's table parser (its blanks, commas, comments, byte order mark); nothing when those
// hold no whole point line or the line is not a row of numbers (the reader then names it).
std::optional<int> numbers_on_first_point_line(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::array<char, 1U << 16U> head{};
  file.read(head.data(), static_cast<std::streamsize>(head.size()));
  const auto size = static_cast<std::size_t>(file.gcount());
  const std::string_view text(head.data(), size);
  const bool whole = size < head.size();  // the file ends within: its last line counts too
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t newline = text.find('\n', start);
    if (newline == std::string_view::npos && !whole) return std::nullopt;
    const std::size_t end = newline == std::string_view::npos ? text.size() : newline + 1;
    const auto row = io::parse_number_table(text.substr(start, end - start), "");
    if (!row) return std::nullopt;
    if (row->rows() > 0) return row->columns;
    start = end;
  }
  return std::nullopt;
}

// Every point of the file, its numbers appended in file order (GIL released by the caller).
template <class Point>
Status read_all(const std::filesystem::path& path, int threads, std::vector<double>& values,
                Status (*read)(const std::filesystem::path&, const io::ChunkedReading&,
                               const std::function<void(std::span<const Point>, double)>&)) {
  return read(path, io::ChunkedReading{.threads = threads},
              [&](std::span<const Point> points, double /*share*/) {
                const std::span<const double> numbers = numbers_of(points);
                values.insert(values.end(), numbers.begin(), numbers.end());
              });
}

// The arguments both readers share, checked; the dimension when it is given. It is guessed only
// from a regular file: the first line of a pipe or of standard input, read to guess, would be
// lost to the reader.
void check_arguments(const char* name, const std::filesystem::path& path,
                     std::optional<int> dimension, int threads) {
  const std::string function = std::string("contain.") + name;
  if (dimension && *dimension != 2 && *dimension != 3) {
    throw py::value_error(function + ": dimension must be 2 or 3, not " +
                          std::to_string(*dimension));
  }
  if (threads < 0) throw py::value_error(function + ": threads must be 0 (all) or more");
  std::error_code error;
  if (!dimension && (path == "-" || (std::filesystem::exists(path, error) &&
                                     !std::filesystem::is_regular_file(path, error)))) {
    throw py::value_error(function +
                          ": standard input, a pipe or a device needs dimension=2 or 3 (it is "
                          "guessed from a regular file's first point line only)");
  }
}

// A first line of 2 numbers makes a 2D file; any other count is read as 3D, whose reader then
// names the line and its count.
int columns_of(const std::filesystem::path& path, std::optional<int> dimension) {
  return dimension ? *dimension : numbers_on_first_point_line(path) == 2 ? 2 : 3;
}

py::array_t<double> read_points(const std::filesystem::path& path, std::optional<int> dimension,
                                int threads) {
  check_arguments("read_points", path, dimension, threads);
  const bool from_stdin = path == "-";
  std::vector<double> values;
  Status status = Ok{};
  int columns = 0;
  {
    py::gil_scoped_release release;
    columns = columns_of(path, dimension);
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

// The points of a file a chunk at a time, for files larger than memory: the library's reader runs
// on a thread of its own and hands over one chunk at a time (it waits while a chunk is untaken),
// so the process holds the reader's block with its parsed points (up to 8 MB of text on several
// threads) and at most three chunks (the one
// being filled, the one waiting, the caller's). Every chunk but the last has exactly `chunk`
// points. Dropping the iterator stops the reader.
class PointChunks {
 public:
  PointChunks(std::filesystem::path path, int columns, std::size_t chunk, int threads)
      : columns_(columns), chunk_values_(chunk * static_cast<std::size_t>(columns)) {
    reader_ = std::thread([this, path = std::move(path), chunk, threads] {
      const io::ChunkedReading reading{.chunk = chunk, .threads = threads};
      Status status = Ok{};
      try {
        status = columns_ == 2 ? io::read_points2_chunked(path, reading, hand_over<Vec2>())
                               : io::read_points3_chunked(path, reading, hand_over<Vec3>());
        // The points read before the end or before an error's block, as a last short chunk.
        if (!filling_.empty()) give(std::move(filling_));
      } catch (const Stopped&) {
      } catch (const std::exception& e) {
        status = Error{.kind = ErrorKind::io,
                       .message = std::string("reading stopped: ") + e.what(),
                       .source = path.string()};
      }
      const std::lock_guard lock(mutex_);
      if (!status) error_ = status.error();
      finished_ = true;
      changed_.notify_all();
    });
  }
  PointChunks(const PointChunks&) = delete;
  PointChunks& operator=(const PointChunks&) = delete;
  ~PointChunks() {
    {
      const std::lock_guard lock(mutex_);
      stopped_ = true;
      changed_.notify_all();
    }
    // Soon for a file: the reader stops at its next piece (a block's parse at most); a pipe's
    // reader first waits for the pipe's next data or its end. It never needs the GIL.
    reader_.join();
  }

  py::array_t<double> next() {
    std::vector<double> values;
    for (bool ready = false; !ready;) {
      {
        py::gil_scoped_release release;
        std::unique_lock lock(mutex_);
        ready = changed_.wait_for(lock, std::chrono::milliseconds(100),
                                  [&] { return waiting_.has_value() || finished_; });
        if (ready && waiting_) {
          values = std::move(*waiting_);
          waiting_.reset();
          changed_.notify_all();
        }
      }
      // A wait on a slow pipe answers Ctrl-C (KeyboardInterrupt) within a tenth of a second.
      if (!ready && PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
    if (values.empty()) {
      if (error_) throw Failure{*std::exchange(error_, std::nullopt)};
      throw py::stop_iteration();
    }
    const auto rows = static_cast<py::ssize_t>(values.size() / static_cast<std::size_t>(columns_));
    return to_numpy(std::move(values), rows, columns_);
  }

  [[nodiscard]] int columns() const { return columns_; }

 private:
  struct Stopped {};  // thrown through the reader when the iterator is dropped

  // The reader's consumer: its pieces (at most a chunk each, shorter at its blocks' ends) copied
  // into whole chunks of `chunk` points (a piece lives only within the call).
  template <class Point>
  std::function<void(std::span<const Point>, double)> hand_over() {
    return [this](std::span<const Point> points, double /*share*/) {
      if (stopped_) throw Stopped{};  // dropped while a long chunk fills: no more parsing
      const std::span<const double> numbers = numbers_of(points);
      const double* first = numbers.data();
      const double* const last = first + numbers.size();
      while (first != last) {
        // Room for a whole chunk up front, up to 24 MB (a chunk of 10^9 points grows as read).
        if (filling_.empty()) filling_.reserve(std::min<std::size_t>(chunk_values_, 3U << 20U));
        const std::size_t take = std::min<std::size_t>(chunk_values_ - filling_.size(),
                                                       static_cast<std::size_t>(last - first));
        filling_.insert(filling_.end(), first, first + take);
        first += take;
        if (filling_.size() == chunk_values_) give(std::exchange(filling_, {}));
      }
    };
  }

  // Hands `values` over once the previous chunk was taken (on the reader's thread).
  void give(std::vector<double>&& values) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !waiting_.has_value() || stopped_; });
    if (stopped_) throw Stopped{};
    waiting_ = std::move(values);
    changed_.notify_all();
  }

  int columns_;
  std::size_t chunk_values_;
  std::vector<double> filling_;  // the reader's thread's only
  std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<std::vector<double>> waiting_;
  std::optional<Error> error_;
  bool finished_ = false;
  std::atomic<bool> stopped_ = false;  // set under mutex_; read by the reader between pieces
  std::thread reader_;  // last: joined (by the destructor's body) before the members it uses go
};

std::unique_ptr<PointChunks> iter_points(const std::filesystem::path& path,
                                         std::optional<int> dimension, std::size_t chunk,
                                         int threads) {
  check_arguments("iter_points", path, dimension, threads);
  if (chunk == 0 || chunk > (std::size_t{1} << 40U)) {
    throw py::value_error("contain.iter_points: chunk must be 1 to 2^40 points");
  }
  int columns = 0;
  {
    py::gil_scoped_release release;
    columns = columns_of(path, dimension);
  }
  return std::make_unique<PointChunks>(path, columns, chunk, threads);
}

}  // namespace

void bind_points(py::module_& m) {
  py::class_<PointChunks>(m, "PointChunks", R"doc(
The points of a file as arrays of at most `chunk` rows, in file order (iter_points): a file of
any size is read in bounded memory. A malformed line raises ContainError when the iteration
reaches it, after the chunks before it. columns: 2 or 3.
)doc")
      .def("__iter__", [](PointChunks& it) -> PointChunks& { return it; })
      .def("__next__", &PointChunks::next)
      .def_property_readonly("columns", &PointChunks::columns, "2 or 3: the points' dimension.")
      .def("__repr__", [](const PointChunks& it) {
        return "contain.PointChunks(" + std::to_string(it.columns()) + "D points)";
      });
  m.def("iter_points", &iter_points, "path"_a, "dimension"_a = py::none(), py::kw_only(),
        "chunk"_a = std::size_t{1} << 20, "threads"_a = 0, R"doc(
The points of a point file (the format of read_points) as float64 arrays of shape (K, 2) or
(K, 3), K at most `chunk`, in file order: for files larger than memory, e.g.
`for block in contain.iter_points("huge.xyz"): index.locate(block)`. The file is parsed ahead on
`threads` threads (0: all cores) while the caller works on the last chunk; at most three chunks
and a block of text with its points (tens of MB) are held at once, whatever the file's size.
Errors as read_points, raised when the iteration reaches the bad line; an iterator dropped early
stops the reading.
)doc");
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
