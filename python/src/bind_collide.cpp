// contain.Contact, contain.MeshPair and contain.collide.

#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/collide/mesh_mesh.h"
#include "contain/collide/region_region.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

// Many poses of B: (N, 12), (N, 3, 4) or (N, 4, 4); one pose is (12,), (3, 4) or (4, 4).
bool is_pose_batch(const py::handle& object) {
  if (object.is_none()) return false;
  const py::array array = py::array::ensure(object);
  if (!array) return false;
  return array.ndim() == 3 || (array.ndim() == 2 && array.shape(1) == 12);
}

py::array_t<bool> collide_poses(const collide::MeshPair& pair, const py::handle& poses,
                                int threads) {
  const std::vector<Transform> transforms = to_transforms(poses, "poses");
  std::vector<collide::Contact> contacts(transforms.size());
  {
    py::gil_scoped_release release;
    pair.collide(transforms, contacts, BatchOptions{.threads = threads});
  }
  py::array_t<bool> out(static_cast<py::ssize_t>(contacts.size()));
  bool* data = out.mutable_data();
  for (std::size_t i = 0; i < contacts.size(); ++i)
    data[i] = contacts[i].intersect;
  return out;
}

}  // namespace

void bind_collide(py::module_& m) {
  py::class_<collide::Contact>(m, "Contact", R"doc(
The answer of a collision query: `intersect` (also bool(contact)) and one witness.

witness: 'none' (disjoint), 'triangles' (triangle_a of A and triangle_b of B share a point),
'edges' (2D: edge triangle_a of A and edge triangle_b of B), 'vertex_of_a_in_b' /
'vertex_of_b_in_a' (nested solids: `vertex` of one lies in the other). node_pairs and
exact_tests count the work done.
)doc")
      .def_readonly("intersect", &collide::Contact::intersect, "True when the shapes meet.")
      .def_property_readonly(
          "witness", [](const collide::Contact& c) { return collide::to_string(c.witness); },
          "What proves it: 'none', 'triangles', 'edges', 'vertex_of_a_in_b', 'vertex_of_b_in_a'.")
      .def_readonly("triangle_a", &collide::Contact::triangle_a,
                    "The triangle (2D: edge) of A of the witness pair, else -1.")
      .def_readonly("triangle_b", &collide::Contact::triangle_b,
                    "The triangle (2D: edge) of B of the witness pair, else -1.")
      .def_readonly("vertex", &collide::Contact::vertex,
                    "The vertex (in its own mesh) of a vertex witness, else -1.")
      .def_readonly("node_pairs", &collide::Contact::node_pairs,
                    "Bounding volume pairs tested (work done).")
      .def_readonly("exact_tests", &collide::Contact::exact_tests,
                    "Exact primitive tests run (work done).")
      .def("__bool__", [](const collide::Contact& c) { return c.intersect; })
      .def("__repr__", [](const collide::Contact& c) {
        return std::string("contain.Contact(intersect=") + (c.intersect ? "True" : "False") +
               ", witness='" + collide::to_string(c.witness) + "')";
      });

  py::class_<collide::MeshPair>(m, "MeshPair", R"doc(
Two meshes prepared for many collision queries, B placed by a transform per query.

A closed mesh bounds a solid (touching counts, nesting counts); an open mesh is a surface.
Every answer is exact on the transformed doubles ((r0 x + r1 y) + r2 z) + t.
Transforms: None (identity), 12 numbers r00 r01 r02 t0 r10 r11 r12 t1 r20 r21 r22 t2, a (3, 4)
[R | t] or a (4, 4) matrix with last row 0 0 0 1.

Example:
    >>> pair = contain.MeshPair(part, tool)
    >>> pair.collide(pose).intersect
    >>> hits = pair.collide(poses)        # (N, 3, 4) -> (N,) bool, on every core
)doc")
      .def(py::init([](const MeshLike& a, const MeshLike& b, const TransformLike& transform_a) {
             const MeshRef ma = to_mesh(a.object, "a"), mb = to_mesh(b.object, "b");
             const collide::MeshPairOptions options{
                 .transform_a = to_transform(transform_a.object, "transform_a")};
             py::gil_scoped_release release;
             return collide::MeshPair(*ma, *mb, options);
           }),
           "a"_a, "b"_a, py::kw_only(), "transform_a"_a = py::none(),
           "Prepares A (placed once by transform_a) and B.")
      .def(
          "collide",
          [](const collide::MeshPair& pair, const TransformLike& transform_b,
             int threads) -> py::object {
            if (is_pose_batch(transform_b.object)) {
              return collide_poses(pair, transform_b.object, threads);
            }
            const Transform t = to_transform(transform_b.object, "transform_b");
            collide::Contact contact;
            {
              py::gil_scoped_release release;
              contact = pair.collide(t);
            }
            return py::cast(contact);
          },
          "transform_b"_a = py::none(), py::kw_only(), "threads"_a = 0, R"doc(
Does A meet B placed by transform_b? One pose ((12,), (3, 4), (4, 4) or None) gives a Contact;
many poses ((N, 12), (N, 3, 4) or (N, 4, 4)) give a bool array (N,), on `threads` threads (0:
every core) without the GIL.
)doc")
      .def(
          "collide_many",
          [](const collide::MeshPair& pair, const ArrayLike& poses, int threads) {
            warn_deprecated("MeshPair.collide_many", "MeshPair.collide");
            return collide_poses(pair, poses.object, threads);
          },
          "poses"_a, py::kw_only(), "threads"_a = 0,
          "Deprecated: collide(poses), which takes many poses too (a DeprecationWarning); the "
          "same answer.")
      .def_property_readonly("a_is_solid", &collide::MeshPair::a_is_solid,
                             "True when A is closed (a solid), False for a surface.")
      .def_property_readonly("b_is_solid", &collide::MeshPair::b_is_solid,
                             "True when B is closed (a solid), False for a surface.")
      .def("__repr__", [](const collide::MeshPair& pair) {
        const auto solid = [](bool yes) { return yes ? "solid" : "open surface"; };
        return "contain.MeshPair(a: " + std::to_string(pair.a_vertices().size()) + " vertices, " +
               solid(pair.a_is_solid()) + "; b: " + solid(pair.b_is_solid()) + ")";
      });

  m.def(
      "collide",
      [](const ShapeLike& shape_a, const ShapeLike& shape_b, const TransformLike& transform_a,
         const TransformLike& transform_b, const std::string& fill) {
        const py::handle a = shape_a.object, b = shape_b.object;
        const bool mesh_a = is_mesh_like(a), mesh_b = is_mesh_like(b);
        if (mesh_a && mesh_b) {
          const MeshRef ma = to_mesh(a, "a"), mb = to_mesh(b, "b");
          const Transform ta = to_transform(transform_a.object, "transform_a");
          const Transform tb = to_transform(transform_b.object, "transform_b");
          py::gil_scoped_release release;
          return collide::mesh_mesh(*ma, *mb, ta, tb);
        }
        if (mesh_a || mesh_b) {
          throw py::type_error("collide: a and b must both be meshes or both be regions");
        }
        if (!transform_a.object.is_none() || !transform_b.object.is_none()) {
          throw py::value_error("collide: transforms apply to meshes only");
        }
        const MultiPolygon ra = to_region(a, "a");
        const MultiPolygon rb = to_region(b, "b");
        const collide::RegionRegionOptions options{.fill = parse_fill(fill)};
        py::gil_scoped_release release;
        return collide::region_region(ra, rb, options);
      },
      "a"_a, "b"_a, py::kw_only(), "transform_a"_a = py::none(), "transform_b"_a = py::none(),
      "fill"_a = "even_odd", R"doc(
Do two shapes meet? One query, a Contact.

Meshes (anything mesh-like: contain.Mesh, trimesh, Open3D, (vertices, faces), a mesh path):
closed ones are solids (touching and nesting count), open ones surfaces; each placed by an
optional transform (see MeshPair; use MeshPair for many poses).
Regions (anything region-like: shapely, GeoJSON, WKT, WKB, rings): the closed filled regions
under `fill` share a point.
)doc");
}

}  // namespace contain::python
