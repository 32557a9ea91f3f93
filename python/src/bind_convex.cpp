// contain.ConvexPolyhedron (point location), contain.ConvexShape and contain.convex_intersect
// (GJK with exact decisions for polytopes; convex_collide, its old name, deprecated).

#include <pybind11/stl.h>

#include <cmath>
#include <string>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/collide/convex_convex.h"
#include "contain/inside/point_in_convex.h"
#include "contain/shapes/convex_polyhedron.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

Vec3 finite_vec3(const py::handle& object, const char* name) {
  const Vec3 p = as_vec3(object, name);
  if (!is_finite(p)) fail(ErrorKind::invalid_value, std::string(name) + " has a NaN or Inf");
  return p;
}

std::vector<Location> locate_all(const ConvexPolyhedron& polyhedron, const py::handle& points,
                                 int threads) {
  const Doubles array = as_matrix(points, 3, "points");
  require_finite(array, "points", threads);
  std::vector<Location> out(static_cast<std::size_t>(array.shape(0)));
  py::gil_scoped_release release;
  inside::point_in_convex(polyhedron, as_vec3(array), out, BatchOptions{.threads = threads});
  return out;
}

collide::ConvexShape to_convex_shape(const py::handle& object, const char* name) {
  if (py::isinstance<collide::ConvexShape>(object)) return object.cast<collide::ConvexShape>();
  return take(collide::ConvexShape::polyhedron(to_convex_polyhedron(object, name)));
}

collide::ConvexContact convex_intersect(const py::object& a, const py::object& b) {
  const collide::ConvexShape sa = to_convex_shape(a, "a"), sb = to_convex_shape(b, "b");
  py::gil_scoped_release release;
  return collide::convex_convex(sa, sb);
}

std::string text(double x) {
  return py::repr(py::float_(x)).cast<std::string>();
}

std::string point_text(Vec3 p) {
  return "[" + text(p.x) + ", " + text(p.y) + ", " + text(p.z) + "]";
}

// What a ConvexShape holds, for its repr: the shape keeps only its support function, so the
// builders record their arguments on the Python object (the class has a __dict__).
py::object described(collide::ConvexShape shape, std::string description) {
  py::object object = py::cast(std::move(shape));
  object.attr("_description") = std::move(description);
  return object;
}

}  // namespace

void bind_convex(py::module_& m) {
  py::class_<ConvexPolyhedron>(m, "ConvexPolyhedron", R"doc(
A convex polyhedron, the intersection of closed half-spaces, prepared for exact point location
(the section's figure 22.22).

ConvexPolyhedron(planes): an (M, 4) array of a b c d, inside where a x + b y + c z + d >= 0
(normals point inward; [] is all of space; unbounded or empty regions are fine).
ConvexPolyhedron(mesh): a closed convex triangle mesh (anything mesh-like), checked exactly:
closed and consistently oriented (welded), no degenerate face, convex, not flat; its faces stay
triangles so every side test is an exact orient3d on input vertices.
Wherever a convex region is taken (clip_segments, clip_mesh, Csg.convex, convex_collide) a
ConvexPolyhedron, planes or a convex mesh may be given.
)doc")
      .def(py::init([](const py::object& planes_or_mesh) {
             return to_convex_polyhedron(planes_or_mesh, "planes_or_mesh");
           }),
           "planes_or_mesh"_a, "From (M, 4) half-space planes or a closed convex mesh.")
      .def(
          "locate",
          [](const ConvexPolyhedron& p, const ArrayLike& points, int threads) -> py::object {
            if (is_one_point(points.object, 3)) {
              return [&](const ArrayLike& point) -> py::object {
                return location_object(
                    inside::point_in_convex(p, finite_vec3(point.object, "point")));
              }(points);
            }
            return to_numpy(locate_all(p, points.object, threads));
          },
          "points"_a, py::kw_only(), "threads"_a = 0,
          "Where each (N, 3) point lies: int8 -1 outside, 0 boundary, 1 inside, exactly; one "
          "point\n"
          "(3,) gives one contain.Location.")
      .def(
          "contains",
          [](const ConvexPolyhedron& p, const ArrayLike& points, const std::string& boundary,
             int threads) {
            check_boundary_policy(boundary);
            return under_boundary_policy(locate_all(p, points.object, threads), boundary);
          },
          "points"_a, py::kw_only(), "boundary"_a, "threads"_a = 0,
          "True where inside; `boundary` ('inside', 'outside', 'raise') decides the boundary\n"
          "('report': the int8 locations, as locate() and the command's --boundary report).")
      .def(
          "locate_point",
          [](const ConvexPolyhedron& p, const ArrayLike& point) {
            warn_deprecated("ConvexPolyhedron.locate_point", "ConvexPolyhedron.locate");
            return location_object(inside::point_in_convex(p, finite_vec3(point.object, "point")));
          },
          "point"_a, "Deprecated: locate(point), which takes one point too (a DeprecationWarning).")
      .def_property_readonly(
          "planes",
          [](const ConvexPolyhedron& p) {
            std::vector<double> values;
            for (const Plane& plane : p.planes())
              values.insert(values.end(), {plane.a, plane.b, plane.c, plane.d});
            return to_numpy(std::move(values), static_cast<py::ssize_t>(p.planes().size()), 4);
          },
          "The (M, 4) planes it was made from (empty for a mesh-based polyhedron).")
      .def_property_readonly(
          "faces",
          [](const ConvexPolyhedron& p) {
            std::vector<double> values;
            for (const Triangle3& t : p.faces())
              values.insert(values.end(),
                            {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z});
            py::array_t<double> flat =
                to_numpy(std::move(values), static_cast<py::ssize_t>(p.faces().size()), 9);
            return flat.attr("reshape")(p.faces().size(), 3, 3);
          },
          "The (F, 3, 3) outward faces of a mesh-based polyhedron (empty otherwise).")
      .def("__repr__", [](const ConvexPolyhedron& p) {
        return p.faces().empty()
                   ? "contain.ConvexPolyhedron(" + std::to_string(p.planes().size()) + " planes)"
                   : "contain.ConvexPolyhedron(" + std::to_string(p.faces().size()) + " faces)";
      });

  py::class_<collide::ConvexShape>(m, "ConvexShape", py::dynamic_attr(), R"doc(
A closed convex shape for convex_intersect, given by its support function: a ball, a box, or a
convex polyhedron from a mesh. Boxes and polyhedra are polytopes (exact answers); a ball makes
the answer GJK's floating-point one.

    >>> ball = contain.ConvexShape.sphere([0, 0, 0], 1)
    >>> box = contain.ConvexShape.box([1, -1, -1], [2, 1, 1])
    >>> contain.convex_intersect(ball, box).intersect
    True
)doc")
      .def_static(
          "sphere",
          [](const ArrayLike& center, double radius) {
            if (!std::isfinite(radius) || radius < 0) {
              fail(ErrorKind::invalid_value, "radius must be finite and >= 0");
            }
            const Vec3 c = finite_vec3(center.object, "center");
            return described(collide::ConvexShape::sphere({c, radius}),
                             "sphere(center=" + point_text(c) + ", radius=" + text(radius) + ")");
          },
          "center"_a, "radius"_a, "The closed ball |p - center| <= radius.")
      .def_static(
          "box",
          [](const ArrayLike& lo, const ArrayLike& hi) {
            const Box3 box{finite_vec3(lo.object, "min"), finite_vec3(hi.object, "max")};
            if (box.empty()) fail(ErrorKind::invalid_value, "box min exceeds max on some axis");
            return described(
                collide::ConvexShape::box(box),
                "box(min=" + point_text(box.min) + ", max=" + point_text(box.max) + ")");
          },
          "min"_a, "max"_a, "The closed axis-aligned box [min, max] (flat boxes are fine).")
      .def_static(
          "polyhedron",
          [](const py::object& convex) {
            const ConvexPolyhedron polyhedron = to_convex_polyhedron(convex, "convex");
            const std::size_t faces = polyhedron.faces().size();
            return described(take(collide::ConvexShape::polyhedron(polyhedron)),
                             "polyhedron(" + std::to_string(faces) + " faces)");
          },
          "convex"_a,
          "A convex polyhedron from a closed convex mesh (or a ConvexPolyhedron made from one;\n"
          "one made from planes alone has no vertices to support a direction: ContainError).")
      .def(
          "support",
          [](const collide::ConvexShape& s, const ArrayLike& direction) {
            const Vec3 p = s.support(finite_vec3(direction.object, "direction"));
            return py::array_t<double>(3, &p.x);
          },
          "direction"_a, "A point of the shape farthest in `direction` (float64 array of 3).")
      .def_property_readonly("is_polytope", &collide::ConvexShape::is_polytope,
                             "True for boxes and polyhedra (exact answers).")
      .def("__repr__", [](const py::object& self) {
        const py::object description = py::getattr(self, "_description", py::none());
        return "contain.ConvexShape." + (description.is_none() ? std::string("polyhedron()")
                                                               : description.cast<std::string>());
      });

  py::class_<collide::ConvexContact>(m, "ConvexContact", R"doc(
The answer of convex_intersect: `intersect` (also bool()), GJK's `distance` estimate (0 when they
meet; floating point) and `exact` (True when both shapes are polytopes, so `intersect` was
decided exactly).
)doc")
      .def_readonly("intersect", &collide::ConvexContact::intersect,
                    "True when the closed shapes share a point.")
      .def_readonly("distance", &collide::ConvexContact::distance,
                    "GJK's distance estimate (floating point; 0 when they meet).")
      .def_readonly("exact", &collide::ConvexContact::exact,
                    "True when `intersect` was decided exactly (two polytopes).")
      .def("__bool__", [](const collide::ConvexContact& c) { return c.intersect; })
      .def("__repr__", [](const collide::ConvexContact& c) {
        return std::string("contain.ConvexContact(intersect=") + (c.intersect ? "True" : "False") +
               ", distance=" + text(c.distance) + ", exact=" + (c.exact ? "True" : "False") + ")";
      });

  m.def("convex_intersect", &convex_intersect, "a"_a, "b"_a, R"doc(
Do two closed convex shapes share a point? GJK on their support functions (Gilbert, Johnson and
Keerthi 1988), C++ collide::convex_convex. a, b: a ConvexShape, or a convex mesh (anything
mesh-like) or ConvexPolyhedron made from one. Two polytopes (boxes, convex meshes): exact, a
separating direction certified by exact side tests, touching and overlap decided by exact
triangle tests. A ball involved: GJK's floating-point answer (`exact` False; touching within
~1e-12 of the size counts). Returns a ConvexContact.
)doc");
  m.def(
      "convex_collide",
      [](const py::object& a, const py::object& b) {
        warn_deprecated("contain.convex_collide", "contain.convex_intersect");
        return convex_intersect(a, b);
      },
      "a"_a, "b"_a,
      "Deprecated: contain.convex_intersect(a, b), the C++ name (a DeprecationWarning); the "
      "same answer.");
}

}  // namespace contain::python
