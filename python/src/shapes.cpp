#include "shapes.h"

#include <array>

#include "arrays.h"
#include "contain/io/wkt.h"
#include "errors.h"

namespace contain::python {
namespace {

py::object location_enum;  // contain.Location, alive as long as the module (held there too)

}  // namespace

Fill parse_fill(const std::string& fill) {
  if (fill == "even_odd" || fill == "evenodd") return Fill::even_odd;
  if (fill == "nonzero") return Fill::nonzero;
  if (fill == "positive") return Fill::positive;
  if (fill == "negative") return Fill::negative;
  throw py::value_error("fill must be 'even_odd', 'nonzero', 'positive' or 'negative', got '" +
                        fill + "'");
}

const char* fill_name(Fill fill) {
  switch (fill) {
    case Fill::even_odd:
      return "even_odd";
    case Fill::nonzero:
      return "nonzero";
    case Fill::positive:
      return "positive";
    case Fill::negative:
      return "negative";
  }
  return "even_odd";
}

MultiPolygon to_region(const py::handle& object, const char* name) {
  if (py::isinstance<MultiPolygon>(object)) return object.cast<MultiPolygon>();
  if (py::isinstance<py::str>(object)) {
    return take(io::parse_wkt(object.cast<std::string>(), std::string(name) + " (WKT)"));
  }
  if (!py::isinstance<py::sequence>(object)) {
    throw py::type_error(std::string(name) +
                         " must be a contain.Region, a WKT string or a sequence of (K, 2) rings");
  }
  std::vector<Ring> rings = as_rings(object, name);
  // Polygon::from_rings rejects NaN/Inf and rings of fewer than 3 points, naming them.
  MultiPolygon region;
  if (!rings.empty()) region.polygons.push_back(take(Polygon::from_rings(std::move(rings))));
  return region;
}

Transform to_transform(const py::handle& object, const char* name) {
  if (object.is_none()) return Transform{};
  const py::array array = py::array::ensure(object);
  if (!array) {
    PyErr_Clear();
    throw py::type_error(std::string(name) +
                         " must be None, 12 numbers, a (3, 4) or (4, 4) matrix");
  }
  Doubles numbers;
  if (array.ndim() == 1) {
    numbers = as_vector(array, 12, name);
  } else if (array.ndim() == 2 && array.shape(0) == 4 && array.shape(1) == 4) {
    numbers = as_matrix(array, 4, name, 4);
    const double* m = numbers.data();
    if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1) {
      throw py::value_error(std::string(name) +
                            ": the last row of a (4, 4) matrix must be 0 0 0 1");
    }
  } else {
    numbers = as_matrix(array, 4, name, 3);
  }
  return take(Transform::from_row_major(std::span<const double>(numbers.data(), 12)));
}

void make_location_enum(py::module_& module) {
  const py::object int_enum = py::module_::import("enum").attr("IntEnum");
  py::list members;
  members.append(py::make_tuple("outside", -1));
  members.append(py::make_tuple("boundary", 0));
  members.append(py::make_tuple("inside", 1));
  using namespace pybind11::literals;
  location_enum = int_enum("Location", members, "module"_a = "contain");
  location_enum.attr("__doc__") =
      "Where a point lies relative to a closed region: outside = -1, boundary = 0, inside = 1.\n"
      "The int8 arrays of the batch calls hold these values; compare them with the members\n"
      "(answers == contain.Location.inside). boundary is decided exactly on the given doubles.";
  module.attr("Location") = location_enum;
}

py::object location_object(Location location) {
  return location_enum(static_cast<int>(location));
}

void check_boundary_policy(const std::string& boundary) {
  if (boundary != "inside" && boundary != "outside" && boundary != "raise") {
    throw py::value_error("boundary must be 'inside', 'outside' or 'raise', got '" + boundary +
                          "'");
  }
}

py::array_t<bool> to_booleans(const std::vector<Location>& locations, const std::string& boundary) {
  check_boundary_policy(boundary);
  const bool on_is_in = boundary == "inside";
  py::array_t<bool> out(static_cast<py::ssize_t>(locations.size()));
  bool* data = out.mutable_data();
  for (std::size_t i = 0; i < locations.size(); ++i) {
    if (locations[i] == Location::boundary && boundary == "raise") {
      fail(ErrorKind::invalid_value,
           "point " + std::to_string(i) +
               " lies on the boundary and boundary='raise' (use boundary='inside' or 'outside')");
    }
    data[i] = locations[i] == Location::inside || (on_is_in && locations[i] == Location::boundary);
  }
  return out;
}

}  // namespace contain::python
