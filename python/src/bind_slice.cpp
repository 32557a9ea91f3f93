// contain.slice_mesh, contain.shadow and contain.mesh_section: a solid's sections by planes as
// Regions, its shadow, and the raw section segments of any mesh by any plane.

#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/clip/mesh_clip.h"
#include "contain/clip/slice_mesh.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

clip::Axis parse_axis(const std::string& axis) {
  if (axis == "x") return clip::Axis::x;
  if (axis == "y") return clip::Axis::y;
  if (axis == "z") return clip::Axis::z;
  throw py::value_error("axis must be 'x', 'y' or 'z', got '" + axis + "'");
}

std::vector<double> plane_values(const py::handle& values) {
  if (py::isinstance<py::float_>(values) || py::isinstance<py::int_>(values)) {
    return {values.cast<double>()};
  }
  const py::array_t<double, py::array::c_style | py::array::forcecast> array =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
  if (!array || array.ndim() != 1) {
    PyErr_Clear();
    throw py::type_error("values must be a number or a 1D sequence of numbers");
  }
  return {array.data(), array.data() + array.size()};
}

}  // namespace

void bind_slice(py::module_& m) {
  m.def(
      "slice_mesh",
      [](const MeshLike& mesh, const py::object& values, const std::string& axis, int threads,
         bool with_triangles) -> py::object {
        const MeshRef solid = to_mesh(mesh.object, "mesh");
        const std::vector<double> planes = plane_values(values);
        const clip::SliceOptions options{.axis = parse_axis(axis)};
        if (threads < 0) throw py::value_error("threads must be >= 0 (0: every core)");
        Result<std::vector<clip::Section>> result = std::vector<clip::Section>{};
        {
          py::gil_scoped_release release;
          result = clip::slice_mesh(*solid, planes, options, {.threads = threads});
        }
        std::vector<clip::Section> sections = take(std::move(result));
        py::list out;
        for (clip::Section& s : sections) {
          if (with_triangles) {
            out.append(py::make_tuple(py::cast(std::move(s.region)), py::cast(s.triangles)));
          } else {
            out.append(py::cast(std::move(s.region)));
          }
        }
        return out;
      },
      "mesh"_a, "values"_a, py::kw_only(), "axis"_a = "z", "threads"_a = 0,
      "with_triangles"_a = false, R"doc(
The sections of a solid by the planes perpendicular to `axis` at `values`: a list of Regions,
one per value, in the order given.

mesh: anything mesh-like, read as a solid: the points where its winding number is positive
(overlapping parts count once, an inside-out shell subtracts). It must be closed (each directed
edge as often as its reverse): ContainError naming an edge otherwise.
values: a number or a 1D sequence of numbers (finite: ContainError otherwise).
axis: 'x', 'y' or 'z' (default); the Region's coordinates are (x, y) for z, (y, z) for x,
(z, x) for y (counter-clockwise seen from +axis).
The section is exactly the closure of the plane's points that are interior points of the solid:
a face lying in the plane that the solid touches from one side adds nothing; two boxes stacked
on a shared face give their square. Crossing vertices are the doubles nearest to the exact
points. with_triangles=True gives (Region, triangles) pairs instead: for each ring of the
Region (polygons in order, shell then holes) the index of the mesh triangle under each edge
(vertex k to k + 1). Planes run on `threads` threads (0: every core) without the GIL; answers do
not depend on the count.
)doc");

  m.def(
      "shadow",
      [](const MeshLike& mesh, const std::string& axis) {
        const MeshRef solid = to_mesh(mesh.object, "mesh");
        const clip::SliceOptions options{.axis = parse_axis(axis)};
        Result<MultiPolygon> result = MultiPolygon{};
        {
          py::gil_scoped_release release;
          result = clip::shadow(*solid, options);
        }
        return take(std::move(result));
      },
      "mesh"_a, py::kw_only(), "axis"_a = "z", R"doc(
The shadow of a mesh along `axis`: the union of its triangles projected onto a plane
perpendicular to it, as a Region in the coordinates of slice_mesh. Any mesh: a closed one (a
solid) or an open surface (every triangle counts; triangles seen edge-on add no area). Exact
decisions; one 2D union of the silhouette edges (inner edges cancel), without the GIL.
)doc");

  m.def(
      "mesh_section",
      [](const MeshLike& mesh, const ArrayLike& plane) {
        const MeshRef subject = to_mesh(mesh.object, "mesh");
        const std::vector<Plane> planes = to_planes(plane.object, "plane");
        if (planes.size() != 1) throw py::value_error("plane must be 4 numbers a b c d");
        std::vector<Segment3> segments;
        {
          py::gil_scoped_release release;
          segments = clip::mesh_section(*subject, planes.front());
        }
        py::array_t<double> out(
            {static_cast<py::ssize_t>(segments.size()), py::ssize_t{2}, py::ssize_t{3}});
        double* data = out.mutable_data();
        for (const Segment3& s : segments) {
          for (const Vec3 p : {s.a, s.b}) {
            *data++ = p.x;
            *data++ = p.y;
            *data++ = p.z;
          }
        }
        return out;
      },
      "mesh"_a, "plane"_a, R"doc(
The section of any mesh (open or closed) by the plane a x + b y + c z + d = 0: an (N, 2, 3)
array of segments, the border edges on the plane of the part of the surface in the half-space
a x + b y + c z + d >= 0, directed as that part uses them. Exact sides; crossing points rounded
(exact on axis-aligned planes in the plane's own coordinate). For a closed mesh the segments
chain into closed loops; a face lying in the plane gives none. For filled sections of a solid
use slice_mesh.
)doc");
}

}  // namespace contain::python
