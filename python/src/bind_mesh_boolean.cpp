// contain.mesh_boolean, contain.repair_solid, contain.MeshBooleanResult: exact booleans of solids
// given as meshes (issue 25). Meshes by the one mesh rule; each input checked closed here, so
// the error names it as the caller passed it; the boolean runs without the GIL.

#include <pybind11/stl.h>

#include <string>
#include <utility>
#include <vector>

#include "arguments.h"
#include "bindings.h"
#include "contain/clip/mesh_boolean.h"
#include "contain/io/mesh_warning.h"
#include "contain/shapes/mesh_closure.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

clip::Op parse_solid_op(const std::string& op) {
  if (op == "union") return clip::Op::union_;
  if (op == "intersection") return clip::Op::intersection;
  if (op == "difference") return clip::Op::difference;
  if (op == "xor") return clip::Op::xor_;
  throw py::value_error("op must be 'union', 'intersection', 'difference' or 'xor', got '" + op +
                        "'");
}

// The name of input `i` in messages: its path where it was given as one, else meshes[i].
std::string input_name(const py::handle& object, std::size_t i) {
  if (py::isinstance<py::str>(object) ||
      py::isinstance(object, py::module_::import("os").attr("PathLike"))) {
    return py::str(object).cast<std::string>();
  }
  return "meshes[" + std::to_string(i) + "]";
}

// The solids, each converted by the mesh rule and refused where a directed edge is unmatched.
std::vector<Mesh> solids_of(const std::vector<py::object>& objects) {
  std::vector<Mesh> solids;
  solids.reserve(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::string name = input_name(objects[i], i);
    const MeshRef mesh = to_mesh(objects[i], name.c_str());
    if (auto edge = unmatched_edge(*mesh)) {
      fail(ErrorKind::invalid_value, io::open_solid_message(name, *edge));
    }
    solids.push_back(*mesh);
  }
  return solids;
}

// mesh_boolean(a, b, ...) or mesh_boolean([a, b, ...]): a lone sequence that is not itself a
// mesh (a (vertices, faces) pair) is the list of inputs.
std::vector<py::object> inputs_of(const py::args& args) {
  std::vector<py::object> inputs;
  if (args.size() == 1 &&
      (py::isinstance<py::list>(args[0]) || py::isinstance<py::tuple>(args[0])) &&
      !is_mesh_like(args[0])) {
    for (const py::handle item : args[0])
      inputs.push_back(py::reinterpret_borrow<py::object>(item));
    return inputs;
  }
  for (const py::handle item : args)
    inputs.push_back(py::reinterpret_borrow<py::object>(item));
  return inputs;
}

clip::MeshBooleanResult run_boolean(const std::vector<Mesh>& solids, clip::Op op) {
  Result<clip::MeshBooleanResult> result = Error{};
  {
    py::gil_scoped_release release;
    result = clip::mesh_boolean(solids, {.op = op});
  }
  return take(std::move(result));
}

}  // namespace

void bind_mesh_boolean(py::module_& m) {
  py::class_<clip::MeshBooleanResult>(m, "MeshBooleanResult", R"doc(
The result of contain.mesh_boolean, contain.repair_solid and Csg.to_mesh.

mesh: the written solid (a contain.Mesh): closed (every directed edge matched by exactly one
    opposite directed edge), outward, no zero-area triangle, no two triangles meeting other than
    at shared vertices or a shared edge, all checked exactly on its doubles; no triangles for
    an empty result.
shells: its connected sheets; volume: its volume (signed tetrahedra of the written doubles);
moved: vertices the rounding repair moved off the doubles nearest to the exact points.
)doc")
      .def_readonly("mesh", &clip::MeshBooleanResult::mesh, "The written solid (a contain.Mesh).")
      .def_readonly("shells", &clip::MeshBooleanResult::shells, "Connected sheets of the mesh.")
      .def_readonly("volume", &clip::MeshBooleanResult::volume, "Volume of the written mesh.")
      .def_readonly("moved", &clip::MeshBooleanResult::moved,
                    "Vertices moved by the rounding repair.")
      .def("__repr__", [](const clip::MeshBooleanResult& r) {
        return "contain.MeshBooleanResult(" + std::to_string(r.mesh.triangles.size()) +
               " triangles, " + std::to_string(r.shells) + " shells, volume " +
               py::repr(py::float_(r.volume)).cast<std::string>() + ", " + std::to_string(r.moved) +
               " moved)";
      });

  m.def(
      "mesh_boolean",
      [](const py::args& args, const std::string& op) {
        const clip::Op which = parse_solid_op(op);
        const std::vector<Mesh> solids = solids_of(inputs_of(args));
        return run_boolean(solids, which);
      },
      py::kw_only(), "op"_a = "union", R"doc(
mesh_boolean(a, b, ..., op='union') or mesh_boolean([a, b, ...], op=...): the exact boolean of
solids given as meshes, as one contain.MeshBooleanResult (its .mesh is the solid).

Each input is anything mesh-like (contain.Mesh, a path, (vertices, faces), trimesh, Open3D), a
solid: the points where its winding number is positive, so self-intersecting meshes, nested
shells and several shells in one mesh are accepted, and a shell turned inside out subtracts. It
must be closed (each directed edge as often as its reverse, non-manifold edges are fine):
ContainError names the input and one unmatched directed edge otherwise; NaN/Inf coordinates
raise ContainError too. A mesh with no triangles is the empty solid.

op: 'union' and 'intersection' of all inputs, 'difference' (the first minus the union of the
rest), 'xor' (the points in an odd number of inputs). One input with 'union': that solid repaired
(contain.repair_solid). No input: the empty solid.
The result is exact and its written doubles are checked exactly (docs/solids.md). Runs without
the GIL.
)doc");

  m.def(
      "repair_solid",
      [](const MeshLike& mesh) {
        const std::vector<Mesh> solids = solids_of({mesh.object});
        return run_boolean(solids, clip::Op::union_);
      },
      "mesh"_a, R"doc(
The solid of one closed mesh, repaired: its self-intersections and overlaps resolved (the points
where its winding number is positive), written as a valid mesh; mesh_boolean(mesh, op='union').
Returns a contain.MeshBooleanResult. Runs without the GIL.
)doc");
}

}  // namespace contain::python
