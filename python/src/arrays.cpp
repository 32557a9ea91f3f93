#include "arrays.h"

#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "contain/core/parallel.h"
#include "errors.h"

namespace contain::python {
namespace {

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    if (d > 0) text += ", ";
    text += std::to_string(array.shape(d));
  }
  if (array.ndim() == 1) text += ",";
  return text + ")";
}

std::string expected_text(py::ssize_t rows, py::ssize_t columns) {
  return "(" + (rows < 0 ? std::string("N") : std::to_string(rows)) +
         (columns < 0 ? std::string(")") : ", " + std::to_string(columns) + ")");
}

// Any array-like as an ndarray; TypeError when numpy cannot read it as numbers.
py::array to_array(const py::handle& object, const char* name) {
  py::array array = py::array::ensure(object);
  if (!array) {
    PyErr_Clear();
    throw py::type_error(std::string(name) +
                         " must be a numpy array or a sequence of numbers, got " +
                         std::string(py::str(py::type::of(object).attr("__name__"))));
  }
  return array;
}

void require_real(const py::array& array, const char* name, const std::string& expected) {
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::type_error(std::string(name) +
                         " must hold real numbers (float64 preferred) of shape " + expected +
                         ", got dtype " + std::string(py::str(array.dtype())));
  }
}

bool aligned(const py::array& array) {
  return (array.flags() & py::detail::npy_api::NPY_ARRAY_ALIGNED_) != 0;
}

Doubles to_doubles(const py::array& array) {
  // A no-op for a C-contiguous aligned float64 array; otherwise one converting copy (the kind
  // is checked first, so forcecast only widens or rounds real numbers).
  Doubles doubles = Doubles::ensure(array);
  if (!doubles) throw py::error_already_set();
  if (!aligned(doubles)) {
    using namespace pybind11::literals;
    doubles = Doubles::ensure(py::module_::import("numpy").attr("array")(
        doubles, "dtype"_a = "float64", "copy"_a = true, "order"_a = "C"));
  }
  return doubles;
}

}  // namespace

Doubles as_matrix(const py::handle& object, py::ssize_t columns, const char* name,
                  py::ssize_t rows) {
  const py::array array = to_array(object, name);
  const std::string expected = expected_text(rows, columns);
  require_real(array, name, expected);
  const bool shape_ok =
      array.ndim() == 2 && array.shape(1) == columns && (rows < 0 || array.shape(0) == rows);
  // An empty list arrives as shape (0,): zero points of any width.
  const bool empty_list = array.ndim() == 1 && array.shape(0) == 0 && rows <= 0;
  if (!shape_ok && !empty_list) {
    throw py::value_error(
        std::string(name) + " must have shape " + expected + ", got " + shape_text(array) +
        (array.ndim() == 1 && array.shape(0) == columns
             ? " (one point: pass [point] or point.reshape(1, " + std::to_string(columns) + "))"
             : ""));
  }
  if (empty_list) {
    return Doubles(std::vector<py::ssize_t>{0, columns});
  }
  return to_doubles(array);
}

Doubles as_vector(const py::handle& object, py::ssize_t count, const char* name) {
  const py::array array = to_array(object, name);
  const std::string expected = count < 0 ? "(N,)" : "(" + std::to_string(count) + ",)";
  require_real(array, name, expected);
  if (array.ndim() != 1 || (count >= 0 && array.shape(0) != count)) {
    throw py::value_error(std::string(name) + " must have shape " + expected + ", got " +
                          shape_text(array));
  }
  return to_doubles(array);
}

Vec3 as_vec3(const py::handle& object, const char* name) {
  const Doubles v = as_vector(object, 3, name);
  return {v.at(0), v.at(1), v.at(2)};
}

Items as_items(const py::handle& object, py::ssize_t rows, py::ssize_t columns, const char* name) {
  py::array array = to_array(object, name);
  const std::string flat = "(N, " + std::to_string(rows * columns) + ")";
  const std::string item = rows == 1
                               ? "(" + std::to_string(columns) + ",)"
                               : "(" + std::to_string(rows) + ", " + std::to_string(columns) + ")";
  require_real(array, name, "(N, " + std::to_string(rows) + ", " + std::to_string(columns) + ")");
  Items items;
  const bool one_point = rows == 1 && array.ndim() == 1 && array.shape(0) == columns;
  const bool one_item =
      rows > 1 && array.ndim() == 2 && array.shape(0) == rows && array.shape(1) == columns;
  if (one_point || one_item) {
    items.single = true;
    array = array.attr("reshape")(1, rows * columns);
  } else if (array.ndim() == 3 && array.shape(1) == rows && array.shape(2) == columns) {
    array = array.attr("reshape")(array.shape(0), rows * columns);
  } else if (!(array.ndim() == 2 && array.shape(1) == rows * columns) &&
             !(array.ndim() == 1 && array.shape(0) == 0)) {
    throw py::value_error(std::string(name) + " must have shape (N, " + std::to_string(rows) +
                          ", " + std::to_string(columns) + "), " + flat + " or " + item + ", got " +
                          shape_text(array));
  }
  items.values = as_matrix(array, rows * columns, name);
  require_finite(items.values, name, 0);
  return items;
}

bool is_one_point(const py::handle& object, py::ssize_t dimension) {
  const py::array array = py::array::ensure(object);
  return array && array.ndim() == 1 && array.shape(0) == dimension;
}

std::size_t paired_count(const Items& a, const Items& b, const char* what) {
  if (a.size() == 1 && a.single) return b.size();
  if (b.size() == 1 && b.single) return a.size();
  if (a.size() != b.size()) {
    throw py::value_error(std::string(what) + ": the two batches differ in length (" +
                          std::to_string(a.size()) + " and " + std::to_string(b.size()) +
                          "); give equal lengths, or one single item to pair with all");
  }
  return a.size();
}

py::object to_bools(std::vector<std::uint8_t>&& flags, bool single) {
  if (single) return py::bool_(!flags.empty() && flags.front() != 0);
  py::array_t<bool> out(static_cast<py::ssize_t>(flags.size()));
  bool* data = out.mutable_data();
  for (std::size_t i = 0; i < flags.size(); ++i)
    data[i] = flags[i] != 0;
  return out;
}

py::object to_int8s(std::vector<std::int8_t>&& values, bool single) {
  if (single) return py::int_(values.empty() ? 0 : values.front());
  auto* owned = new std::vector<std::int8_t>(std::move(values));
  py::capsule base(owned, [](void* p) { delete static_cast<std::vector<std::int8_t>*>(p); });
  return py::array_t<std::int8_t>({static_cast<py::ssize_t>(owned->size())}, owned->data(), base);
}

bool reads_in_place(const py::handle& object) {
  const py::array array = py::array::ensure(object);
  if (!array) {
    PyErr_Clear();
    return false;
  }
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') return false;
  const Doubles converted = to_doubles(array);
  return converted.ptr() == array.ptr() && object.ptr() == array.ptr();
}

static_assert(sizeof(Vec3) == 3 * sizeof(double) && alignof(Vec3) == alignof(double));
static_assert(sizeof(Vec2) == 2 * sizeof(double) && alignof(Vec2) == alignof(double));
static_assert(sizeof(Location) == 1);

std::span<const Vec3> as_vec3(const Doubles& array) {
  // Vec3 is a standard-layout aggregate of three doubles: a C-contiguous (N, 3) float64 buffer
  // has exactly its layout.
  return {reinterpret_cast<const Vec3*>(array.data()), static_cast<std::size_t>(array.shape(0))};
}

std::span<const Vec2> as_vec2(const Doubles& array) {
  return {reinterpret_cast<const Vec2*>(array.data()), static_cast<std::size_t>(array.shape(0))};
}

void require_finite(const Doubles& array, const char* name, int threads) {
  const double* data = array.data();
  const std::size_t count = static_cast<std::size_t>(array.size());
  const std::size_t width = array.ndim() == 2 ? static_cast<std::size_t>(array.shape(1)) : 1;
  std::atomic<std::size_t> first_bad{std::numeric_limits<std::size_t>::max()};
  {
    py::gil_scoped_release release;
    parallel_for(count, BatchOptions{.threads = threads}, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        if (!std::isfinite(data[i])) {
          std::size_t seen = first_bad.load();
          while (i < seen && !first_bad.compare_exchange_weak(seen, i)) {
          }
          return;
        }
      }
    });
  }
  const std::size_t bad = first_bad.load();
  if (bad != std::numeric_limits<std::size_t>::max()) {
    fail(ErrorKind::invalid_value, std::string(name) + "[" + std::to_string(bad / width) +
                                       "] has a NaN or infinite coordinate");
  }
}

std::vector<TriangleIndices> as_triangles(const py::handle& object) {
  const py::array array = to_array(object, "faces");
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u') {
    throw py::type_error("faces must hold integer vertex indices of shape (M, 3), got dtype " +
                         std::string(py::str(array.dtype())));
  }
  if (array.ndim() != 2 || array.shape(1) != 3) {
    throw py::value_error("faces must have shape (M, 3), got " + shape_text(array));
  }
  const auto wide =
      py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(array);
  const std::int64_t* data = wide.data();
  std::vector<TriangleIndices> triangles(static_cast<std::size_t>(array.shape(0)));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::int64_t index = data[3 * t + k];
      if (index < 0 || index > std::numeric_limits<std::int32_t>::max()) {
        fail(ErrorKind::invalid_value, "faces[" + std::to_string(t) + "] has vertex index " +
                                           std::to_string(index) +
                                           " (indices are 0-based and below 2^31)");
      }
      triangles[t][k] = static_cast<std::int32_t>(index);
    }
  }
  return triangles;
}

py::array_t<std::int8_t> to_numpy(std::vector<Location>&& locations) {
  auto* owned = new std::vector<Location>(std::move(locations));
  py::capsule base(owned, [](void* p) { delete static_cast<std::vector<Location>*>(p); });
  return py::array_t<std::int8_t>({static_cast<py::ssize_t>(owned->size())},
                                  reinterpret_cast<const std::int8_t*>(owned->data()), base);
}

py::array_t<double> to_numpy(std::vector<double>&& values, py::ssize_t rows, py::ssize_t columns) {
  auto* owned = new std::vector<double>(std::move(values));
  py::capsule base(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>({rows, columns}, owned->data(), base);
}

py::array_t<double> ring_to_numpy(const Ring& ring) {
  py::array_t<double> out({static_cast<py::ssize_t>(ring.size()), py::ssize_t{2}});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < ring.size(); ++i) {
    data[2 * i] = ring[i].x;
    data[2 * i + 1] = ring[i].y;
  }
  return out;
}

std::vector<Ring> as_rings(const py::handle& object, const char* name) {
  if (py::isinstance<py::str>(object) || !py::isinstance<py::sequence>(object)) {
    throw py::type_error(std::string(name) +
                         " must be a sequence of rings, each an (K, 2) array of x, y");
  }
  std::vector<Ring> rings;
  const std::string ring_name = std::string(name) + " ring";
  for (const py::handle item : py::reinterpret_borrow<py::sequence>(object)) {
    const Doubles points = as_matrix(item, 2, ring_name.c_str());
    const auto span = as_vec2(points);
    rings.emplace_back(span.begin(), span.end());
  }
  return rings;
}

}  // namespace contain::python
