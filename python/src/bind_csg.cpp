// contain.Csg (a CSG tree as a value: from the contract's JSON form or built with helpers) and
// contain.CsgSolid (the prepared tree: exact point location in batches).

#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/clip/csg_to_mesh.h"
#include "contain/inside/csg.h"
#include "contain/io/csg_json.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

// The first exception raised by a Python implicit function during a query: the leaf answers
// NaN (outside) meanwhile, and the query raises it when done.
std::mutex implicit_error_mutex;
std::exception_ptr implicit_error;

void raise_implicit_error() {
  std::exception_ptr error;
  {
    const std::lock_guard lock(implicit_error_mutex);
    std::swap(error, implicit_error);
  }
  if (error) std::rethrow_exception(error);
}

ImplicitFunction python_implicit(py::function function) {
  // Dropped with the GIL held whichever thread lets go of the last copy.
  const std::shared_ptr<py::function> held(new py::function(std::move(function)),
                                           [](py::function* f) {
                                             py::gil_scoped_acquire gil;
                                             delete f;
                                           });
  return [held](Vec3 p) -> double {
    py::gil_scoped_acquire gil;
    try {
      return (*held)(p.x, p.y, p.z).cast<double>();
    } catch (...) {
      const std::lock_guard lock(implicit_error_mutex);
      if (!implicit_error) implicit_error = std::current_exception();
      return std::numeric_limits<double>::quiet_NaN();
    }
  };
}

// The contract's JSON form: a mapping (dumped with json), JSON text, or a file.
Csg csg_from_json(const py::handle& object, const py::object& base_dir) {
  io::CsgJsonOptions options{.source = "<csg>"};
  if (!base_dir.is_none()) options.base_dir = base_dir.cast<std::filesystem::path>();
  if (py::isinstance<py::dict>(object) || py::isinstance<py::list>(object)) {
    const std::string text = py::module_::import("json").attr("dumps")(object).cast<std::string>();
    options.source = "<csg dict>";
    return take(io::parse_csg_json(text, options));
  }
  if (py::isinstance<py::str>(object)) {
    const std::string text = object.cast<std::string>();
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && text[first] == '{')
      return take(io::parse_csg_json(text, options));
  }
  if (py::isinstance<py::str>(object) ||
      py::isinstance(object, py::module_::import("os").attr("PathLike"))) {
    return take(io::read_csg_json(object.cast<std::filesystem::path>()));
  }
  throw py::type_error(
      "a CSG tree is a contain.Csg, a dict of the JSON form ({\"difference\": [A, B]}, ...), "
      "JSON text or a .json path; got " +
      std::string(py::str(py::type::of(object).attr("__name__"))));
}

Csg to_csg(const py::handle& object) {
  if (py::isinstance<Csg>(object)) return object.cast<Csg>();
  return csg_from_json(object, py::none());
}

std::vector<Csg> operands_of(const py::args& args) {
  std::vector<Csg> operands;
  // union(a, b, c) or union([a, b, c])
  if (args.size() == 1 && py::isinstance<py::list>(args[0])) {
    for (const py::handle item : args[0])
      operands.push_back(to_csg(item));
    return operands;
  }
  for (const py::handle item : args)
    operands.push_back(to_csg(item));
  return operands;
}

std::string leaf_name(const CsgLeaf& leaf) {
  static constexpr const char* kNames[] = {"sphere", "box",      "halfspace",
                                           "convex", "implicit", "mesh"};
  return kNames[leaf.index()];
}

std::vector<Location> solid_locate(const inside::CsgSolid& solid, const py::handle& points,
                                   int threads) {
  const Doubles array = as_matrix(points, 3, "points");
  require_finite(array, "points", threads);
  std::vector<Location> out(static_cast<std::size_t>(array.shape(0)));
  {
    py::gil_scoped_release release;
    solid.locate(as_vec3(array), out, BatchOptions{.threads = threads});
  }
  raise_implicit_error();
  return out;
}

}  // namespace

void bind_csg(py::module_& m) {
  py::class_<Csg>(m, "Csg", R"doc(
A CSG tree as a value (exercise 22.4-2): regularised unions, intersections, differences and
complements of closed solids. Build it with the helpers and operators, or from the contract's
JSON form; prepare it with contain.CsgSolid to locate points.

Leaves: Csg.sphere(center, r), Csg.box(min, max), Csg.halfspace([a, b, c, d]) (a x + b y + c z
+ d >= 0), Csg.convex(planes or a convex mesh), Csg.mesh(closed mesh: anything mesh-like),
Csg.implicit("1 - x^2 - y^2 - z^2" or a Python function f(x, y, z) -> float; inside where >= 0).
Operations: Csg.union(a, b, ...) or a | b, Csg.intersection(a, b, ...) or a & b,
Csg.difference(a, b) or a - b, Csg.complement(a) or ~a.
JSON: Csg.from_json({"difference": [{"sphere": {"center": [0, 0, 0], "radius": 1}},
{"halfspace": [0, 0, 1, -0.5]}]}), JSON text, or a file path (pathlib.Path).

Example:
    >>> part = (contain.Csg.sphere([0, 0, 0], 1) | contain.Csg.box([0, -1, -1], [2, 1, 1])) \
    ...        - contain.Csg.halfspace([0, 0, 1, -0.5])
    >>> contain.CsgSolid(part).locate([[0, 0, 0.5], [0, 0, 0.75]])
    array([ 0, -1], dtype=int8)
)doc")
      .def_static(
          "sphere",
          [](const ArrayLike& center, double radius) {
            return Csg::leaf(Sphere{as_vec3(center.object, "center"), radius});
          },
          "center"_a, "radius"_a, "The closed ball |p - center| <= radius.")
      .def_static(
          "box",
          [](const ArrayLike& lo, const ArrayLike& hi) {
            return Csg::leaf(Box3{as_vec3(lo.object, "min"), as_vec3(hi.object, "max")});
          },
          "min"_a, "max"_a, "The closed axis-aligned box [min, max].")
      .def_static(
          "halfspace",
          [](const ArrayLike& plane) {
            const Doubles c = as_vector(plane.object, 4, "plane");
            return Csg::leaf(Plane{c.at(0), c.at(1), c.at(2), c.at(3)});
          },
          "plane"_a, "The closed half-space a x + b y + c z + d >= 0 of plane = (a, b, c, d).")
      .def_static(
          "convex",
          [](const py::object& convex) {
            return Csg::leaf(to_convex_polyhedron(convex, "convex"));
          },
          "convex"_a,
          "A convex polyhedron: (M, 4) planes (intersection of half-spaces), a closed convex\n"
          "mesh (anything mesh-like) or a ConvexPolyhedron.")
      .def_static(
          "mesh",
          [](const MeshLike& mesh) { return Csg::leaf(CsgMesh(*to_mesh(mesh.object, "mesh"))); },
          "mesh"_a,
          "The solid bounded by a closed triangle mesh (anything mesh-like): where its winding\n"
          "number is positive, located exactly; CsgSolid refuses an open mesh.")
      .def_static(
          "implicit",
          [](const py::object& function) {
            if (py::isinstance<py::str>(function)) {
              py::dict leaf;
              leaf["implicit"] = function;
              return csg_from_json(leaf, py::none());
            }
            if (!PyCallable_Check(function.ptr())) {
              throw py::type_error("implicit takes an expression (str) or a function f(x, y, z)");
            }
            return Csg::leaf(python_implicit(function));
          },
          "function"_a, R"doc(
The solid { p : f(p) >= 0 }: f a muparser expression in x, y, z ("1 - x^2 - y^2 - z^2"; safe
on every thread, the fast choice) or a Python function f(x, y, z) -> float (called with the
GIL, one point at a time; an exception it raises is raised by the query). Only as exact as the
evaluation of f; boundary where f == 0 exactly.
)doc")
      .def_static(
          "union", [](const py::args& args) { return Csg::unite(operands_of(args)); },
          "The union of the operands (Csg or JSON forms); of none: the empty set.")
      .def_static(
          "intersection", [](const py::args& args) { return Csg::intersection(operands_of(args)); },
          "The intersection of the operands; of none: all of space.")
      .def_static(
          "difference",
          [](const py::object& a, const py::object& b) {
            return Csg::difference(to_csg(a), to_csg(b));
          },
          "a"_a, "b"_a, "a minus b (regularised).")
      .def_static(
          "complement", [](const py::object& a) { return Csg::complement(to_csg(a)); }, "a"_a,
          "The closure of the complement of a.")
      .def_static("from_json", &csg_from_json, "tree"_a, "base_dir"_a = py::none(), R"doc(
A tree from the contract's JSON form (`contain inside --csg`): a dict, JSON text, or a file path
(str or pathlib.Path). {"union": [A, ...]}, {"intersection": [...]}, {"difference": [A, B]},
{"complement": A}, {"sphere": {"center": [x, y, z], "radius": r}}, {"box": {"min": [...],
"max": [...]}}, {"halfspace": [a, b, c, d]}, {"convex": [[a, b, c, d], ...]}, {"implicit":
"expression"}, {"mesh": "file.obj"} (relative to the file's folder, or to `base_dir` for a dict
or text). Errors name the JSON path of the offending value.
)doc")
      .def("__or__",
           [](const Csg& a, const py::object& b) {
             return Csg::unite({a, to_csg(b)});
           })
      .def("__and__",
           [](const Csg& a, const py::object& b) {
             return Csg::intersection({a, to_csg(b)});
           })
      .def("__sub__",
           [](const Csg& a, const py::object& b) { return Csg::difference(a, to_csg(b)); })
      .def("__invert__", [](const Csg& a) { return Csg::complement(a); })
      .def_property_readonly(
          "op", [](const Csg& c) { return shapes::to_string(c.op()); },
          "'leaf', 'union', 'intersection', 'difference' or 'complement'.")
      .def_property_readonly(
          "operands",
          [](const Csg& c) { return std::vector<Csg>(c.operands().begin(), c.operands().end()); },
          "The operands of an operation (a list of Csg; empty for a leaf).")
      .def_property_readonly(
          "leaf",
          [](const Csg& c) -> py::object {
            if (c.op() != CsgOp::leaf) return py::none();
            return py::str(leaf_name(c.solid()));
          },
          "The kind of a leaf ('sphere', 'box', 'halfspace', 'convex', 'implicit', 'mesh'),\n"
          "None for an operation.")
      .def(
          "to_mesh",
          [](const Csg& tree) {
            Result<clip::MeshBooleanResult> result = Error{};
            {
              py::gil_scoped_release release;
              result = clip::csg_to_mesh(tree);
            }
            return take(std::move(result));
          },
          R"doc(
The tree's solid as one written mesh, by the exact mesh booleans (contain.mesh_boolean, one
n-ary call per union or intersection): a contain.MeshBooleanResult whose .mesh is closed,
outward and free of self-intersections on its doubles (docs/solids.md).
Leaves: meshes (solids by their winding number), boxes, convex polyhedra, and half-spaces (or
convex polyhedra given by planes) within a box: those are read inside the box of the tree's
bounded solids (an intersection with a box, a difference from a mesh), and a tree whose solid is
unbounded raises ContainError. A sphere or implicit leaf raises ContainError naming its place
("difference[1].sphere: a sphere is not polyhedral ..."), before any boolean runs. Runs without
the GIL.
)doc")
      .def("__repr__", [](const Csg& c) {
        if (c.op() == CsgOp::leaf) return "contain.Csg." + leaf_name(c.solid()) + "(...)";
        return "contain.Csg(" + std::string(shapes::to_string(c.op())) + " of " +
               std::to_string(c.operands().size()) + ")";
      });

  py::class_<inside::CsgSolid>(m, "CsgSolid", R"doc(
A CSG tree prepared for exact point location (the prepared object of contain.Csg).

CsgSolid(tree): a Csg, or its JSON form (dict, JSON text, path). Validates every leaf (finite
numbers, radius >= 0, box min <= max, non-zero normals, closed meshes), naming the leaf by its
place in the tree ("intersection[1].difference[0]: radius is negative").

Semantics: regularised operations, so the answer depends only on what fills space near the
point: a point on A's surface strictly inside B is 'boundary' of A & B and 'inside' A | B; the
face shared by two touching boxes is 'inside' their union. Exact for balls, boxes,
half-spaces, convex polyhedra and closed meshes (docs/containment.md); implicit leaves are as
exact as their evaluation.

Query: locate(points) -> int8 (-1/0/1) on every core, contains(points, boundary=...),
locate_point(p). Example in contain.Csg.
)doc")
      .def(py::init([](const py::object& tree) {
             return take(inside::CsgSolid::prepare(to_csg(tree)));
           }),
           "tree"_a, "Validates and prepares a Csg (or its JSON form).")
      .def(
          "locate",
          [](const inside::CsgSolid& solid, const ArrayLike& points, int threads) -> py::object {
            if (is_one_point(points.object, 3)) {
              return [&](const ArrayLike& point) -> py::object {
                const Vec3 p = as_vec3(point.object, "point");
                if (!is_finite(p)) fail(ErrorKind::invalid_value, "point has a NaN or Inf");
                const Location where = solid.locate(p);
                raise_implicit_error();
                return location_object(where);
              }(points);
            }
            return to_numpy(solid_locate(solid, points.object, threads));
          },
          "points"_a, py::kw_only(), "threads"_a = 0, R"doc(
Where each point lies: int8 (N,), -1 outside, 0 boundary, 1 inside. points: (N, 3); one point
(3,) gives one contain.Location. Runs on
`threads` threads (0: every core) without the GIL (Python implicit functions take it per call).
)doc")
      .def(
          "contains",
          [](const inside::CsgSolid& solid, const ArrayLike& points, const std::string& boundary,
             int threads) {
            check_boundary_policy(boundary);
            return under_boundary_policy(solid_locate(solid, points.object, threads), boundary);
          },
          "points"_a, py::kw_only(), "boundary"_a, "threads"_a = 0,
          "True where inside; `boundary` ('inside', 'outside', 'raise') decides the boundary\n"
          "('report': the int8 locations, as locate() and the command's --boundary report).")
      .def(
          "locate_point",
          [](const inside::CsgSolid& solid, const ArrayLike& point) {
            warn_deprecated("CsgSolid.locate_point", "CsgSolid.locate");
            const Vec3 p = as_vec3(point.object, "point");
            if (!is_finite(p)) fail(ErrorKind::invalid_value, "point has a NaN or Inf");
            const Location where = solid.locate(p);
            raise_implicit_error();
            return location_object(where);
          },
          "point"_a, "Deprecated: locate(point), which takes one point too (a DeprecationWarning).")
      .def_property_readonly("leaf_count", &inside::CsgSolid::leaf_count, "Leaves of the tree.")
      .def("__repr__", [](const inside::CsgSolid& solid) {
        return "contain.CsgSolid(" + std::to_string(solid.leaf_count()) + " leaves)";
      });
}

}  // namespace contain::python
