// contain.aabb, contain.bounding_sphere, contain.bounding_circle.

#include <pybind11/stl.h>

#include <string>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/bound/aabb.h"
#include "contain/bound/bounding_circle.h"
#include "contain/bound/bounding_sphere.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

bound::SphereMethod parse_method(const std::string& method) {
  if (method == "exact") return bound::SphereMethod::exact;
  if (method == "ritter") return bound::SphereMethod::ritter;
  throw py::value_error("method must be 'exact' or 'ritter', got '" + method + "'");
}

bound::MeshVertices parse_vertices(const std::string& vertices) {
  if (vertices == "referenced") return bound::MeshVertices::referenced;
  if (vertices == "all") return bound::MeshVertices::all;
  throw py::value_error("vertices must be 'referenced' or 'all', got '" + vertices + "'");
}

py::tuple ball(Vec3 center, double radius) {
  return py::make_tuple(py::array_t<double>(3, &center.x), radius);
}

py::tuple disc(Vec2 center, double radius) {
  return py::make_tuple(py::array_t<double>(2, &center.x), radius);
}

}  // namespace

void bind_bound(py::module_& m) {
  m.def(
      "aabb",
      [](const ShapeLike& argument, const std::string& vertices) {
        const py::handle shape = argument.object;
        const bound::MeshVertices which = parse_vertices(vertices);
        if (is_mesh_like(shape)) {
          const Box3 box = bound::aabb(*to_mesh(shape, "shape"), {.vertices = which});
          return py::make_tuple(py::array_t<double>(3, &box.min.x),
                                py::array_t<double>(3, &box.max.x));
        }
        if (is_region_like(shape)) {
          const Box2 box = bound::aabb(to_region(shape, "shape"));
          return py::make_tuple(py::array_t<double>(2, &box.min.x),
                                py::array_t<double>(2, &box.max.x));
        }
        const py::array array = py::array::ensure(shape);
        if (array && array.ndim() == 2 && array.shape(1) == 2) {
          const Doubles points = as_matrix(array, 2, "points");
          const Box2 box = bound::aabb(as_vec2(points));
          return py::make_tuple(py::array_t<double>(2, &box.min.x),
                                py::array_t<double>(2, &box.max.x));
        }
        PyErr_Clear();
        const Doubles points = as_matrix(shape, 3, "points");
        const Box3 box = bound::aabb(as_vec3(points));
        return py::make_tuple(py::array_t<double>(3, &box.min.x),
                              py::array_t<double>(3, &box.max.x));
      },
      "shape"_a, py::kw_only(), "vertices"_a = "referenced", R"doc(
The smallest closed axis-aligned box, exactly (comparisons only), as (min, max) arrays.
vertices (meshes): 'referenced' (those a triangle uses: the surface; the CLI's answer) or
'all' (the whole vertex array).
shape: (N, 3) or (N, 2) points, anything mesh-like (its referenced vertices) or region-like.
Empty input gives min = +inf, max = -inf.
)doc");
  m.def(
      "bounding_sphere",
      [](const ShapeLike& argument, const std::string& method, const std::string& vertices) {
        const py::handle shape = argument.object;
        const bound::BoundingSphereOptions options{.method = parse_method(method),
                                                   .vertices = parse_vertices(vertices)};
        if (is_mesh_like(shape)) {
          const MeshRef ref = to_mesh(shape, "shape");
          const Mesh& mesh = *ref;
          Result<Sphere> sphere = [&] {
            py::gil_scoped_release release;
            return bound::bounding_sphere(mesh, options);
          }();
          const Sphere s = take(std::move(sphere));
          return ball(s.center, s.radius);
        }
        const Doubles points = as_matrix(shape, 3, "points");
        const auto span = as_vec3(points);
        Result<Sphere> sphere = [&] {
          py::gil_scoped_release release;
          return bound::bounding_sphere(span, options);
        }();
        const Sphere s = take(std::move(sphere));
        return ball(s.center, s.radius);
      },
      "shape"_a, py::kw_only(), "method"_a = "exact", "vertices"_a = "referenced", R"doc(
A closed ball holding every point, as (center, radius): center a float64 array of 3.
shape: (N, 3) points or anything mesh-like (its referenced vertices). method: 'exact' (the minimal ball,
Welzl with move-to-front; radius within ~1e-14 relative) or 'ritter' (fast, larger). Every
point is inside the returned ball, checked exactly. No points or NaN/Inf raise ContainError.
vertices (meshes): 'referenced' (default) or 'all', as in aabb.
)doc");
  m.def(
      "bounding_circle",
      [](const ShapeLike& argument, const std::string& method) {
        const py::handle shape = argument.object;
        const bound::BoundingCircleOptions options{.method = parse_method(method)};
        if (is_region_like(shape)) {
          const Circle c = take(bound::bounding_circle(to_region(shape, "shape"), options));
          return disc(c.center, c.radius);
        }
        const Doubles points = as_matrix(shape, 2, "points");
        const Circle c = take(bound::bounding_circle(as_vec2(points), options));
        return disc(c.center, c.radius);
      },
      "shape"_a, py::kw_only(), "method"_a = "exact", R"doc(
A closed disc holding every point, as (center, radius): the 2D bounding_sphere.
shape: (N, 2) points or anything region-like (its ring points).
)doc");
}

}  // namespace contain::python
