#pragma once
/// \file
/// numpy arrays in and out of the library's flat types, without copies where the layout allows.
///
/// The input rule, the same for every function of the module: anything numpy can turn into an
/// array is accepted (arrays, lists, tuples); its dtype must be a real number (floating point or
/// integer, kinds 'f', 'i', 'u'), else TypeError; its shape must be the one named, else
/// ValueError naming the expected and the given shape. A C-contiguous, aligned float64 array is
/// read in place (zero-copy: `(N, 3)` float64 is exactly `Vec3[N]`); any other layout or real
/// dtype (a transposed view, every other row, float32, int64) is copied once into a C-contiguous
/// float64 array, which is exact for every float32 and for integers up to 2^53.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "contain/core/location.h"
#include "contain/shapes/mesh.h"
#include "contain/shapes/polygon.h"
#include "contain/values/vec.h"

namespace contain::python {

namespace py = pybind11;

/// A C-contiguous float64 array (the caller's own when it qualified, else a converted copy).
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// `object` as a float64 array of shape (N, columns) (rows == -1) or (rows, columns); `name`
/// and the expected shape appear in the messages.
[[nodiscard]] Doubles as_matrix(const py::handle& object, py::ssize_t columns, const char* name,
                                py::ssize_t rows = -1);

/// `object` as a float64 vector of exactly `count` values (count == -1: any length).
[[nodiscard]] Doubles as_vector(const py::handle& object, py::ssize_t count, const char* name);
/// Three numbers (any sequence or array of 3) as a point.
[[nodiscard]] Vec3 as_vec3(const py::handle& object, const char* name);

/// A batch of small fixed-shape items (triangles, segments, boxes), flat: row i of `values` is
/// item i's `rows * columns` numbers in row-major order. `single` is true when the caller gave
/// one item (shape (rows, columns)), so that answers can come back as a scalar.
struct Items {
  Doubles values;
  bool single = false;
  [[nodiscard]] std::size_t size() const { return static_cast<std::size_t>(values.shape(0)); }
  [[nodiscard]] const double* item(std::size_t i) const {
    return values.data() + i * static_cast<std::size_t>(values.shape(1));
  }
};

/// `object` as items of shape (rows, columns): an array of shape (N, rows, columns), (N, rows *
/// columns) or one item (rows, columns) (for rows == 1: (N, columns) or one (columns,)). Real
/// dtypes only, checked finite (ContainError naming
/// the item otherwise); ValueError naming the accepted shapes.
[[nodiscard]] Items as_items(const py::handle& object, py::ssize_t rows, py::ssize_t columns,
                             const char* name);

/// True when `object` is one point of `dimension` numbers (shape (dimension,)), which a batch
/// call such as `locate` answers with a scalar; anything else is read as a batch.
[[nodiscard]] bool is_one_point(const py::handle& object, py::ssize_t dimension);

/// The item count of a pair of batches, one of which may be a single item that pairs with every
/// item of the other; ValueError when both are batches of different lengths.
[[nodiscard]] std::size_t paired_count(const Items& a, const Items& b, const char* what);

/// A new bool array (N,) or, for single items, a Python bool.
[[nodiscard]] py::object to_bools(std::vector<std::uint8_t>&& flags, bool single);

/// A new int8 array (N,) of signs or locations, or, for single items, a Python int.
[[nodiscard]] py::object to_int8s(std::vector<std::int8_t>&& values, bool single);

/// True when `as_matrix` would read `object` in place (for the tests of the zero-copy claim).
[[nodiscard]] bool reads_in_place(const py::handle& object);

/// The rows of an (N, 3) / (N, 2) array as points, in place.
[[nodiscard]] std::span<const Vec3> as_vec3(const Doubles& array);
[[nodiscard]] std::span<const Vec2> as_vec2(const Doubles& array);

/// Raises ContainError (invalid_value) naming the first row with a NaN or infinite value.
/// Runs without the GIL on `threads` threads.
void require_finite(const Doubles& array, const char* name, int threads);

/// `object` as an (N, 3) array of triangle vertex indices (any integer dtype; values must fit
/// in int32, else ValueError). Copied: a Mesh owns its indices.
[[nodiscard]] std::vector<TriangleIndices> as_triangles(const py::handle& object);

/// A new numpy array of `locations` (int8: -1 outside, 0 boundary, 1 inside) that owns them:
/// the vector is moved into the array's base object, no copy.
[[nodiscard]] py::array_t<std::int8_t> to_numpy(std::vector<Location>&& locations);

/// A new numpy float64 array of shape (rows, columns) owning `values` (moved, no copy).
[[nodiscard]] py::array_t<double> to_numpy(std::vector<double>&& values, py::ssize_t rows,
                                           py::ssize_t columns);

/// A numpy (K, 2) float64 array copied from a ring.
[[nodiscard]] py::array_t<double> ring_to_numpy(const Ring& ring);

/// A sequence of rings (each an (K, 2) array-like) as rings.
[[nodiscard]] std::vector<Ring> as_rings(const py::handle& object, const char* name);

}  // namespace contain::python
