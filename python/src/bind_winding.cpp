// The textbook's smaller containment tests on batches: contain.point_in_triangle,
// point_in_convex_polygon, winding_number (2D, exact), generalized_winding_number and
// contain.FastWindingNumber (3D, floating point; WindingNumber, its old name, deprecated).

#include <pybind11/stl.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/core/parallel.h"
#include "contain/inside/fast_winding_number.h"
#include "contain/inside/point_in_convex_polygon.h"
#include "contain/inside/point_in_triangle.h"
#include "contain/inside/winding_number.h"
#include "contain/inside/winding_number_3d.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

// Points (N, dim), checked finite.
Doubles points_of(const py::handle& object, py::ssize_t dim, int threads) {
  const Doubles array = as_matrix(object, dim, "points");
  require_finite(array, "points", threads);
  return array;
}

template <class T, class Fill>
std::vector<T> each(std::size_t n, int threads, Fill&& fill) {
  std::vector<T> out(n);
  py::gil_scoped_release release;
  parallel_for(n, BatchOptions{.threads = threads}, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      out[i] = fill(i);
  });
  return out;
}

py::array_t<double> doubles(std::vector<double>&& values) {
  auto* owned = new std::vector<double>(std::move(values));
  py::capsule base(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>({static_cast<py::ssize_t>(owned->size())}, owned->data(), base);
}

inside::TriangleMethod parse_triangle_method(const std::string& method) {
  if (method == "projected") return inside::TriangleMethod::projected;
  if (method == "same_side") return inside::TriangleMethod::same_side;
  throw py::value_error("method must be 'projected' or 'same_side', got '" + method + "'");
}

std::vector<double> fast_winding(const inside::FastWindingNumber& w, const Doubles& points,
                                 int threads) {
  const auto p = as_vec3(points);
  return each<double>(p.size(), threads, [&](std::size_t i) { return w.evaluate(p[i]); });
}

}  // namespace

void bind_winding(py::module_& m) {
  m.def(
      "point_in_triangle",
      [](const ArrayLike& triangles, const ArrayLike& points, const std::string& method,
         int threads) {
        const Items t = as_items(triangles.object, 3, 3, "triangles");
        const Items p = as_items(points.object, 1, 3, "points");
        const std::size_t n = paired_count(t, p, "point_in_triangle");
        const inside::PointInTriangleOptions options{.method = parse_triangle_method(method)};
        std::vector<std::int8_t> out = each<std::int8_t>(n, threads, [&](std::size_t i) {
          const double* a = t.item(t.single ? 0 : i);
          const double* q = p.item(p.single ? 0 : i);
          const Triangle3 triangle{{a[0], a[1], a[2]}, {a[3], a[4], a[5]}, {a[6], a[7], a[8]}};
          return static_cast<std::int8_t>(
              inside::point_in_triangle(triangle, {q[0], q[1], q[2]}, options));
        });
        return to_int8s(std::move(out), t.single && p.single);
      },
      "triangles"_a, "points"_a, py::kw_only(), "method"_a = "projected", "threads"_a = 0,
      R"doc(
Where points of a triangle's plane lie relative to the closed triangle (the section's figures
22.23 and 22.24): 1 inside, 0 on an edge or vertex, -1 outside, exact for points in the plane.
triangles (N, 3, 3) or one (3, 3); points (N, 3) or one (3,); a single item pairs with all.
method: 'projected' (onto the coordinate plane of the largest normal component, three orient2d)
or 'same_side' (cross and dot products: answers for the orthogonal projection). Degenerate
triangles are the segment or point they span. int8 array, or an int for one pair.
)doc");

  m.def(
      "point_in_convex_polygon",
      [](const ArrayLike& ring, const ArrayLike& points, const std::string& fill, int threads) {
        const Ring r = to_convex_ring(ring.object, "ring");
        const Doubles p = points_of(points.object, 2, threads);
        const auto span = as_vec2(p);
        const inside::PointInPolygonOptions options{.fill = parse_fill(fill)};
        std::vector<Location> out(span.size());
        {
          py::gil_scoped_release release;
          parallel_for(span.size(), BatchOptions{.threads = threads},
                       [&](std::size_t begin, std::size_t end) {
                         for (std::size_t i = begin; i < end; ++i)
                           out[i] = inside::point_in_convex_polygon(r, span[i], options);
                       });
        }
        return to_numpy(std::move(out));
      },
      "ring"_a, "points"_a, py::kw_only(), "fill"_a = "even_odd", "threads"_a = 0, R"doc(
The section's same-side test for a convex ring (either direction; collinear and repeated
vertices allowed), exact: int8 (N,) for (N, 2) points, 1 inside, 0 boundary, -1 outside. Agrees
with point_in_polygon on convex rings; unspecified for a ring that is not convex.
)doc");

  m.def(
      "winding_number",
      [](const RegionLike& region, const ArrayLike& points, int threads) {
        const std::vector<Ring> rings = to_region(region.object, "region").all_rings();
        const Doubles p = points_of(points.object, 2, threads);
        const auto span = as_vec2(p);
        std::vector<std::int32_t> out =
            each<std::int32_t>(span.size(), threads, [&](std::size_t i) {
              return static_cast<std::int32_t>(inside::winding_number(rings, span[i]));
            });
        return py::array_t<std::int32_t>(static_cast<py::ssize_t>(out.size()), out.data());
      },
      "region"_a, "points"_a, py::kw_only(), "threads"_a = 0, R"doc(
The exact winding number of the region's rings (closed paths in the direction written;
counter-clockwise loops count +1) around each (N, 2) point, as int32 (N,). On an edge: the
winding number just counter-clockwise of +x (the right-up perturbation rule of
docs/robustness.md), which the fill rules of point_in_polygon read.
)doc");

  m.def(
      "generalized_winding_number",
      [](const MeshLike& mesh, const ArrayLike& points, std::optional<double> accuracy,
         int threads) {
        const MeshRef ref = to_mesh(mesh.object, "mesh");
        const Doubles p = points_of(points.object, 3, threads);
        if (accuracy) {
          if (!(*accuracy > 0)) fail(ErrorKind::invalid_value, "accuracy must be > 0");
          const inside::FastWindingNumber w = [&] {
            py::gil_scoped_release release;
            return inside::FastWindingNumber(*ref, {.accuracy = *accuracy});
          }();
          return doubles(fast_winding(w, p, threads));
        }
        const auto span = as_vec3(p);
        const Mesh& mref = *ref;
        return doubles(each<double>(span.size(), threads, [&](std::size_t i) {
          return inside::generalized_winding_number(mref, span[i]);
        }));
      },
      "mesh"_a, "points"_a, py::kw_only(), "accuracy"_a = py::none(), "threads"_a = 0, R"doc(
The generalized winding number of a mesh (anything mesh-like) at (N, 3) points, float64 (N,):
the signed solid angle of the surface over 4 pi (Jacobson et al. 2013): 1 inside and 0
outside a closed outward surface, a smooth value for open or non-manifold ones (about 1/2 at a
hole). accuracy=None sums every triangle exactly as written (O(n) a point); a number uses the
fast hierarchical form (Barill et al. 2018; larger is more accurate): build a FastWindingNumber to
reuse it. Floating point, undefined on the surface: use MeshIndex for exact in/on/out.
)doc");

  py::class_<inside::FastWindingNumber>(m, "FastWindingNumber", R"doc(
A mesh prepared for generalized winding numbers at many points (a hierarchy of triangles with a
far-field dipole per node; Barill, Dickson, Schmidt, Levin and Jacobson 2018). Floating point,
deterministic. FastWindingNumber(mesh, accuracy=3.0); evaluate(points) -> float64 (N,). C++
inside::FastWindingNumber.
)doc")
      .def(py::init([](const MeshLike& mesh, double accuracy) {
             if (!(accuracy > 0)) fail(ErrorKind::invalid_value, "accuracy must be > 0");
             const MeshRef ref = to_mesh(mesh.object, "mesh");
             py::gil_scoped_release release;
             return inside::FastWindingNumber(*ref, {.accuracy = accuracy});
           }),
           "mesh"_a, py::kw_only(), "accuracy"_a = 3.0,
           "Prepares a mesh; a node counts as one dipole farther than accuracy x its radius.")
      .def(
          "evaluate",
          [](const inside::FastWindingNumber& w, const ArrayLike& points, int threads) {
            return doubles(fast_winding(w, points_of(points.object, 3, threads), threads));
          },
          "points"_a, py::kw_only(), "threads"_a = 0,
          "The winding number at each (N, 3) point, float64 (N,), on `threads` threads.")
      .def("__repr__", [](const inside::FastWindingNumber& w) {
        return "contain.FastWindingNumber(" + std::to_string(w.triangles().size()) + " triangles)";
      });
}

}  // namespace contain::python
