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
/// Anything the region rule takes (shapes.h, to_region): a Region, WKT/GeoJSON/WKB, a path,
/// shapely and GeoPandas objects, rings.
struct RegionLike {
  pybind11::object object;
};
/// Anything the mesh rule takes (shapes.h, to_mesh): a Mesh, a path, (vertices, faces),
/// trimesh and Open3D meshes.
struct MeshLike {
  pybind11::object object;
};
/// None, 12 numbers, a (3, 4) or a (4, 4) matrix.
struct TransformLike {
  pybind11::object object;
};
/// A shape of the bounding functions or of collide: mesh-like, region-like, or points.
struct ShapeLike {
  pybind11::object object;
};

}  // namespace contain::python

namespace pybind11::detail {

// Every caster accepts every object (the function checks it and raises a clear error); they
// differ only in the name help() shows.
template <typename T, auto Name>
struct any_object_caster {
  PYBIND11_TYPE_CASTER(T, Name);
  bool load(handle source, bool) {
    value.object = reinterpret_borrow<object>(source);
    return true;
  }
  static handle cast(const T& v, return_value_policy, handle) { return v.object.inc_ref(); }
};

template <>
struct type_caster<contain::python::ArrayLike>
    : any_object_caster<contain::python::ArrayLike, const_name("numpy.typing.ArrayLike")> {};
template <>
struct type_caster<contain::python::RegionLike>
    : any_object_caster<contain::python::RegionLike, const_name("contain.RegionLike")> {};
template <>
struct type_caster<contain::python::MeshLike>
    : any_object_caster<contain::python::MeshLike, const_name("contain.MeshLike")> {};
template <>
struct type_caster<contain::python::TransformLike>
    : any_object_caster<contain::python::TransformLike,
                        const_name("numpy.typing.ArrayLike | None")> {};
template <>
struct type_caster<contain::python::ShapeLike>
    : any_object_caster<contain::python::ShapeLike,
                        const_name(
                            "contain.MeshLike | contain.RegionLike | numpy.typing.ArrayLike")> {};

}  // namespace pybind11::detail
