// contain.validate_mesh (contain.MeshReport), contain.weld_vertices and
// contain.self_intersections (contain.SelfIntersections).

#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/collide/self_intersections.h"
#include "contain/shapes/mesh_validation.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

py::array_t<std::int32_t> int32_array(const std::vector<std::int32_t>& values) {
  return py::array_t<std::int32_t>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::dict report_dict(const MeshReport& r) {
  py::dict d;
  d["vertices"] = r.vertices;
  d["referenced_vertices"] = r.referenced_vertices;
  d["triangles"] = r.triangles;
  d["edges"] = r.edges;
  d["components"] = r.components;
  d["border_edges"] = r.border_edges;
  d["nonmanifold_edges"] = r.nonmanifold_edges;
  d["inconsistent_edges"] = r.inconsistent_edges;
  d["degenerate_triangles"] = r.degenerate_triangles;
  d["duplicated_triangles"] = r.duplicated_triangles;
  py::list pinch;
  for (const std::int32_t v : r.pinch_vertices)
    pinch.append(v);
  d["pinch_vertices"] = pinch;
  d["euler_characteristic"] = r.euler_characteristic;
  d["genus"] = r.genus ? py::object(py::int_(*r.genus)) : py::object(py::none());
  d["signed_volume"] = r.signed_volume;
  d["closed"] = r.closed();
  d["manifold"] = r.manifold();
  d["consistently_oriented"] = r.consistently_oriented();
  d["outward"] = r.outward();
  d["watertight"] = r.watertight();
  return d;
}

// The pairs as an (K, 2) int32 array, first < second in each row.
py::array_t<std::int32_t> pair_array(const std::vector<collide::TrianglePair>& pairs) {
  py::array_t<std::int32_t> out({static_cast<py::ssize_t>(pairs.size()), py::ssize_t{2}});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    view(static_cast<py::ssize_t>(k), 0) = pairs[k].first;
    view(static_cast<py::ssize_t>(k), 1) = pairs[k].second;
  }
  return out;
}

std::size_t count_argument(long long value, const char* name) {
  if (value < 0) throw py::value_error(std::string(name) + " must be at least 0");
  return static_cast<std::size_t>(value);
}

void bind_self_intersections(py::module_& m) {
  using collide::SelfIntersections;
  py::class_<SelfIntersections>(m, "SelfIntersections", R"doc(
What contain.self_intersections found: pairs of triangles of one mesh that meet where they are
not joined. pairs: (K, 2) int32 array of triangle numbers (first < second), the first K <= keep
pairs found, in a deterministic order; count: pairs found (every pair unless the search stopped
at limit: stopped). bool(result): the mesh crosses (or folds onto) itself.
)doc")
      .def_property_readonly(
          "pairs", [](const SelfIntersections& s) { return pair_array(s.pairs); },
          "(K, 2) int32 array: the first pairs found (at most keep), first < second a row.")
      .def_readonly("count", &SelfIntersections::count,
                    "Pairs found: all of them unless the search stopped at limit.")
      .def_readonly("stopped", &SelfIntersections::stopped,
                    "True when the search stopped at limit, so count may be short of the total.")
      .def("__bool__", [](const SelfIntersections& s) { return !s.empty(); })
      .def("__repr__", [](const SelfIntersections& s) {
        std::string text = "contain.SelfIntersections(" + std::to_string(s.count) +
                           (s.stopped ? "+" : "") + (s.count == 1 ? " pair" : " pairs");
        if (!s.pairs.empty()) {
          text += ", first (" + std::to_string(s.pairs.front().first) + ", " +
                  std::to_string(s.pairs.front().second) + ")";
        }
        return text + ")";
      });

  m.def(
      "self_intersections",
      [](const MeshLike& mesh, long long keep, long long limit) {
        const collide::SelfIntersectionsOptions options{.keep = count_argument(keep, "keep"),
                                                        .limit = count_argument(limit, "limit")};
        const MeshRef ref = to_mesh(mesh.object, "mesh");
        py::gil_scoped_release release;
        return collide::self_intersections(*ref, options);
      },
      "mesh"_a, py::kw_only(), "keep"_a = 8, "limit"_a = 0, R"doc(
The pairs of triangles of a mesh (anything mesh-like) that meet where they are not joined:
whether a closed mesh overlaps itself. No query needs it to be right: inside(), MeshIndex,
collide, MeshPair and MeshPairDistance all read a closed mesh as the solid of its winding
number, where overlapping parts count once (repair_solid writes that solid without overlaps).

Triangles that share a corner (a vertex at the same coordinates: an unwelded mesh is judged as
its welded twin) count only when they meet beyond the corners they share (a triangle crossing
its neighbour, a fold onto the neighbour's plane); triangles sharing nothing count for any
common point, touching included. Degenerate and duplicated triangles are left to
validate_mesh. Exact (orient3d and orient2d signs); deterministic; one thread, the GIL released.

keep: at most this many pairs are returned in .pairs; limit: stop once this many are found
(0: count every pair; 1 answers "does it cross itself at all" for the cost of the first pair).
Returns a SelfIntersections (pairs, count, stopped; false when the mesh does not cross itself).

Example:
    >>> found = contain.self_intersections("part.stl", limit=1)
    >>> if found: print("triangles", *found.pairs[0], "cross")
)doc");
}

}  // namespace

void bind_mesh_report(py::module_& m) {
  bind_self_intersections(m);
  py::class_<MeshReport>(m, "MeshReport", R"doc(
What a triangle mesh is as a surface (contain.validate_mesh): counts, the defects found and the
properties they imply. Edges are unordered pairs of vertex indices (weld_vertices first if a
file repeats positions). str(report) is the readable summary; to_dict() the data (JSON-ready).

Properties: closed (every edge of two triangles), manifold (no edge of three or more, no pinch
vertex), consistently_oriented, outward (closed, consistent, positive volume), watertight
(a solid: closed, manifold, consistent, no duplicated triangles).
)doc")
      .def_readonly("vertices", &MeshReport::vertices, "Vertices in the vertex array.")
      .def_readonly("referenced_vertices", &MeshReport::referenced_vertices,
                    "Vertices used by some triangle.")
      .def_readonly("triangles", &MeshReport::triangles, "Triangles.")
      .def_readonly("edges", &MeshReport::edges, "Distinct edges.")
      .def_readonly("components", &MeshReport::components,
                    "Connected components (through shared vertices).")
      .def_readonly("border_edges", &MeshReport::border_edges, "Edges of exactly one triangle.")
      .def_readonly("nonmanifold_edges", &MeshReport::nonmanifold_edges,
                    "Edges of three or more triangles.")
      .def_readonly("inconsistent_edges", &MeshReport::inconsistent_edges,
                    "Two-triangle edges used in the same direction by both.")
      .def_readonly("degenerate_triangles", &MeshReport::degenerate_triangles,
                    "Triangles of zero area, decided exactly.")
      .def_readonly("duplicated_triangles", &MeshReport::duplicated_triangles,
                    "Triangles with the same three vertices as an earlier one.")
      .def_property_readonly(
          "pinch_vertices", [](const MeshReport& r) { return int32_array(r.pinch_vertices); },
          "Vertices where several fans meet only at the vertex (0-based, ascending; int32).")
      .def_readonly("euler_characteristic", &MeshReport::euler_characteristic,
                    "V - E + F over referenced vertices, distinct edges and triangles.")
      .def_readonly("genus", &MeshReport::genus,
                    "Total genus of a closed, manifold, consistently oriented mesh; else None.")
      .def_readonly("signed_volume", &MeshReport::signed_volume,
                    "Signed volume, positive when facing outward (closed, consistent meshes).")
      .def_property_readonly("closed", &MeshReport::closed, "Every edge shared by two triangles.")
      .def_property_readonly("manifold", &MeshReport::manifold,
                             "No edge of three or more triangles and no pinch vertex.")
      .def_property_readonly("consistently_oriented", &MeshReport::consistently_oriented,
                             "Every two-triangle edge used in opposite directions.")
      .def_property_readonly("outward", &MeshReport::outward,
                             "Closed, consistently oriented and of positive volume.")
      .def_property_readonly("watertight", &MeshReport::watertight,
                             "A solid: closed, manifold, consistent, no duplicated triangles.")
      .def("to_dict", &report_dict, "Every field and property as a dict (JSON-ready).")
      .def("__str__", &MeshReport::summary)
      .def("__repr__", [](const MeshReport& r) {
        return "contain.MeshReport(" + std::to_string(r.triangles) + " triangles, " +
               (r.watertight() ? "watertight" : (r.closed() ? "closed" : "open")) + ")";
      });

  m.def(
      "validate_mesh",
      [](const MeshLike& mesh) {
        const MeshRef ref = to_mesh(mesh.object, "mesh");
        py::gil_scoped_release release;
        return validate_mesh(*ref);
      },
      "mesh"_a, R"doc(
Checks a mesh (anything mesh-like) as a surface and returns a MeshReport: closed, 2-manifold,
consistently oriented, outward, watertight; border, non-manifold and inconsistent edges,
degenerate (exactly zero-area) and duplicated triangles, pinch vertices, components, Euler
characteristic, genus, signed volume. O(n log n). print(report) shows the summary.

Example:
    >>> report = contain.validate_mesh(trimesh.load("part.stl"))
    >>> report.watertight, report.border_edges, report.genus
)doc");

  m.def(
      "weld_vertices",
      [](const MeshLike& mesh) {
        const MeshRef ref = to_mesh(mesh.object, "mesh");
        WeldResult w = weld_vertices(*ref);
        auto remap = int32_array(w.remap);
        return py::make_tuple(std::move(w.mesh), remap);
      },
      "mesh"_a, R"doc(
Merges vertices whose coordinates are equal as doubles (exactly: no tolerance; +0 == -0),
keeping the first of each group, and renumbers the triangles. Returns (welded Mesh, remap)
where remap[i] is the new index of old vertex i (int32). Unreferenced vertices are kept.
)doc");
}

}  // namespace contain::python
