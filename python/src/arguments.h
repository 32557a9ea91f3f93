#pragma once
/// \file
/// Parameters taken as any Python object and checked by the function itself (arrays.h,
/// shapes.h), under the name that help() and the signatures show: "points: numpy.typing.ArrayLike"
/// instead of pybind11's "points: handle".

#include <pybind11/pybind11.h>

namespace contain::python {

/// Anything numpy reads as an array of real numbers.
struct ArrayLike {
  pybind11::object object;
};
/// A contain.Region, a WKT string or a sequence of (K, 2) rings.
struct RegionLike {
  pybind11::object object;
};
/// None, 12 numbers, a (3, 4) or a (4, 4) matrix.
struct TransformLike {
  pybind11::object object;
};
/// A shape of the bounding functions or of collide: a Mesh, a Region or WKT, or points/rings.
struct ShapeLike {
  pybind11::object object;
};

}  // namespace contain::python

namespace pybind11::detail {

// Each caster accepts every object (the function checks it and raises a clear error).
template <>
struct type_caster<contain::python::ArrayLike> {
  PYBIND11_TYPE_CASTER(contain::python::ArrayLike, const_name("numpy.typing.ArrayLike"));
  bool load(handle source, bool) {
    value.object = reinterpret_borrow<object>(source);
    return true;
  }
  static handle cast(const contain::python::ArrayLike& v, return_value_policy, handle) {
    return v.object.inc_ref();
  }
};

template <>
struct type_caster<contain::python::RegionLike> {
  PYBIND11_TYPE_CASTER(contain::python::RegionLike,
                       const_name("contain.Region | str | Sequence[numpy.typing.ArrayLike]"));
  bool load(handle source, bool) {
    value.object = reinterpret_borrow<object>(source);
    return true;
  }
  static handle cast(const contain::python::RegionLike& v, return_value_policy, handle) {
    return v.object.inc_ref();
  }
};

template <>
struct type_caster<contain::python::TransformLike> {
  PYBIND11_TYPE_CASTER(contain::python::TransformLike, const_name("numpy.typing.ArrayLike | None"));
  bool load(handle source, bool) {
    value.object = reinterpret_borrow<object>(source);
    return true;
  }
  static handle cast(const contain::python::TransformLike& v, return_value_policy, handle) {
    return v.object.inc_ref();
  }
};

template <>
struct type_caster<contain::python::ShapeLike> {
  PYBIND11_TYPE_CASTER(contain::python::ShapeLike,
                       const_name("contain.Mesh | contain.Region | str | numpy.typing.ArrayLike"));
  bool load(handle source, bool) {
    value.object = reinterpret_borrow<object>(source);
    return true;
  }
  static handle cast(const contain::python::ShapeLike& v, return_value_policy, handle) {
    return v.object.inc_ref();
  }
};

}  // namespace pybind11::detail
