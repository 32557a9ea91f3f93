// Continuous collision: contain.vertex_face_ccd / edge_edge_ccd on (N, 8, 3) arrays,
// contain.MeshImpact, contain.MovingMeshPair and contain.mesh_mesh_ccd.

#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/collide/ccd.h"
#include "contain/collide/moving_mesh_pair.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

static_assert(sizeof(collide::CcdQuery) == 24 * sizeof(double),
              "a CcdQuery is 24 contiguous doubles, the rows of an (N, 8, 3) array");

// (N, 8, 3) queries (or one (8, 3) query) as a C-contiguous float64 (N, 24) array, in place
// when the caller's array qualifies.
Doubles as_queries(const py::handle& object, bool& single) {
  py::array array = py::array::ensure(object);
  if (!array) {
    PyErr_Clear();
    throw py::type_error("queries must be an array of real numbers of shape (N, 8, 3)");
  }
  single = array.ndim() == 2;
  if (!((array.ndim() == 3 && array.shape(1) == 8 && array.shape(2) == 3) ||
        (single && array.shape(0) == 8 && array.shape(1) == 3))) {
    std::string shape = "(";
    for (py::ssize_t d = 0; d < array.ndim(); ++d)
      shape += (d > 0 ? ", " : "") + std::to_string(array.shape(d));
    throw py::value_error("queries must have shape (N, 8, 3) (or (8, 3) for one query), got " +
                          shape + (array.ndim() == 1 ? ",)" : ")"));
  }
  const py::ssize_t n = single ? 1 : array.shape(0);
  return as_matrix(array.attr("reshape")(n, 24), 24, "queries");
}

template <class Batch>
py::object ccd_batch(const ArrayLike& queries, int threads, Batch&& batch) {
  bool single = false;
  const Doubles rows = as_queries(queries.object, single);
  require_finite(rows, "queries", threads);
  const auto n = static_cast<std::size_t>(rows.shape(0));
  const std::span<const collide::CcdQuery> in(
      reinterpret_cast<const collide::CcdQuery*>(rows.data()), n);
  std::vector<collide::Impact> impacts(n);
  {
    py::gil_scoped_release release;
    batch(in, std::span<collide::Impact>(impacts), BatchOptions{.threads = threads});
  }
  if (single) return py::make_tuple(impacts[0].hit, impacts[0].time);
  py::array_t<bool> hit(static_cast<py::ssize_t>(n));
  py::array_t<double> time(static_cast<py::ssize_t>(n));
  bool* h = hit.mutable_data();
  double* t = time.mutable_data();
  for (std::size_t i = 0; i < n; ++i) {
    h[i] = impacts[i].hit;
    t[i] = impacts[i].time;
  }
  return py::make_tuple(hit, time);
}

// A motion from two placements (each None, 12 numbers, (3, 4) or (4, 4)).
collide::Motion to_motion(const py::handle& from, const py::handle& to, const char* from_name,
                          const char* to_name) {
  collide::Motion m;
  m.from = to_transform(from, from_name);
  m.to = to.is_none() ? m.from : to_transform(to, to_name);
  return m;
}

// Motions of B: (N, 24), (N, 2, 12), (N, 2, 3, 4) or (N, 2, 4, 4): the two placements of
// each motion are read as 2N poses by the module's one pose rule (to_transforms).
std::vector<collide::Motion> to_motions(const py::handle& object) {
  py::array array = py::array::ensure(object);
  const char* shapes = "motions must have shape (N, 24), (N, 2, 12), (N, 2, 3, 4) or (N, 2, 4, 4)";
  if (!array) {
    PyErr_Clear();
    throw py::type_error(shapes);
  }
  const auto dim = [&](py::ssize_t d) { return array.ndim() > d ? array.shape(d) : -1; };
  const py::ssize_t n = dim(0);
  py::object poses;
  if (array.ndim() == 1 && n == 0) {
    poses = array.attr("reshape")(0, 12);
  } else if (array.ndim() == 2 && dim(1) == 24) {
    poses = array.attr("reshape")(2 * n, 12);
  } else if (array.ndim() == 3 && dim(1) == 2 && dim(2) == 12) {
    poses = array.attr("reshape")(2 * n, 12);
  } else if (array.ndim() == 4 && dim(1) == 2 && (dim(2) == 3 || dim(2) == 4) && dim(3) == 4) {
    poses = array.attr("reshape")(2 * n, dim(2), 4);
  } else {
    throw py::value_error(std::string(shapes) + ", got " +
                          py::str(array.attr("shape")).cast<std::string>());
  }
  const std::vector<Transform> placements = to_transforms(poses, "motions", 2);
  std::vector<collide::Motion> out(static_cast<std::size_t>(n > 0 ? n : 0));
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = {placements[2 * i], placements[2 * i + 1]};
  return out;
}

std::vector<Vec3> to_positions(const py::handle& object, std::size_t count, const char* name) {
  const Doubles rows = as_matrix(object, 3, name, static_cast<py::ssize_t>(count));
  require_finite(rows, name, 1);
  const std::span<const Vec3> v = as_vec3(rows);
  return {v.begin(), v.end()};
}

// Which form of MovingMeshPair.first_contact a call is, by the first argument's shape: many
// motions ((N, 24), (N, 2, 12), (N, 2, 3, 4), (N, 2, 4, 4)), B's vertices at t = 1 ((V, 3)), or
// a pose ((12,), (3, 4), (4, 4), None).
enum class FirstContactForm { pose, motions, deforming };

FirstContactForm first_contact_form(const py::object& from_b, const py::object& to_b) {
  if (from_b.is_none() || !to_b.is_none()) return FirstContactForm::pose;
  const py::array array = py::array::ensure(from_b);
  if (!array) return FirstContactForm::pose;
  const auto dim = [&](py::ssize_t d) { return array.ndim() > d ? array.shape(d) : -1; };
  if ((array.ndim() == 2 && dim(1) == 24) || (array.ndim() == 3 && dim(1) == 2) ||
      array.ndim() == 4) {
    return FirstContactForm::motions;
  }
  if (array.ndim() == 2 && dim(1) == 3) return FirstContactForm::deforming;
  return FirstContactForm::pose;
}

py::tuple first_contacts(const collide::MovingMeshPair& pair, const py::handle& motions,
                         int threads) {
  const std::vector<collide::Motion> ms = to_motions(motions);
  std::vector<collide::MeshImpact> out(ms.size());
  {
    py::gil_scoped_release release;
    pair.first_contact(ms, out, BatchOptions{.threads = threads});
  }
  py::array_t<bool> hit(static_cast<py::ssize_t>(out.size()));
  py::array_t<double> time(static_cast<py::ssize_t>(out.size()));
  for (std::size_t i = 0; i < out.size(); ++i) {
    hit.mutable_data()[i] = out[i].hit;
    time.mutable_data()[i] = out[i].time;
  }
  return py::make_tuple(hit, time);
}

py::object deforming_contact(const collide::MovingMeshPair& pair, const py::handle& b_at1) {
  const std::vector<Vec3> positions = to_positions(b_at1, pair.b_vertex_count(), "b_at1");
  collide::MeshImpact impact;
  {
    py::gil_scoped_release release;
    impact = pair.first_contact(positions);
  }
  return py::cast(impact);
}

py::object optional_pair(const std::array<std::int32_t, 2>& e) {
  if (e[0] < 0) return py::none();
  return py::make_tuple(e[0], e[1]);
}

// The primitives of the witness, as the attributes that hold them.
std::string witness_text(const collide::MeshImpact& i) {
  const auto edge = [](const std::array<std::int32_t, 2>& e) {
    return "(" + std::to_string(e[0]) + ", " + std::to_string(e[1]) + ")";
  };
  switch (i.witness) {
    case collide::MeshImpactWitness::vertex_a_face_b:
    case collide::MeshImpactWitness::vertex_b_face_a:
      return ", vertex=" + std::to_string(i.vertex) + ", triangle=" + std::to_string(i.triangle);
    case collide::MeshImpactWitness::edges:
      return ", edge_a=" + edge(i.edge_a) + ", edge_b=" + edge(i.edge_b);
    case collide::MeshImpactWitness::initial:
      return ", initial=" + py::repr(py::cast(i.initial)).cast<std::string>();
    case collide::MeshImpactWitness::none:
      break;
  }
  return "";
}

std::string mesh_side(std::size_t vertices, bool solid) {
  return std::to_string(vertices) + " vertices, " + (solid ? "solid" : "open surface");
}

}  // namespace

void bind_ccd(py::module_& m) {
  m.def(
      "vertex_face_ccd",
      [](const ArrayLike& queries, int threads) {
        return ccd_batch(queries, threads, [](auto in, auto out, BatchOptions o) {
          collide::vertex_face_ccd(in, out, o);
        });
      },
      "queries"_a, py::kw_only(), "threads"_a = 0, R"doc(
Exact continuous collision of a vertex and a triangle, every point moving on a straight line
from t = 0 to t = 1.

queries: (N, 8, 3) real numbers in the CCD benchmark's order: the vertex, then the triangle's
three corners at t = 0, then the same four at t = 1 (or one (8, 3) query). Returns (hit, time):
a bool array (N,) (the vertex lies in the closed triangle at some t in [0, 1]) and a float64
array (N,) (hit: the largest double <= the earliest contact time, 0 for contact at t = 0;
miss: inf); for one (8, 3) query, a (bool, float) pair. Exact on every input double (no false
hit, no missed hit), degenerate cases included. Runs on `threads` threads (0: every core)
without the GIL; a NaN or infinite coordinate raises ContainError naming its row.

    >>> hit, time = contain.vertex_face_ccd(queries)   # queries.shape == (N, 8, 3)
)doc");
  m.def(
      "edge_edge_ccd",
      [](const ArrayLike& queries, int threads) {
        return ccd_batch(queries, threads, [](auto in, auto out, BatchOptions o) {
          collide::edge_edge_ccd(in, out, o);
        });
      },
      "queries"_a, py::kw_only(), "threads"_a = 0, R"doc(
Exact continuous collision of two edges (closed segments), as vertex_face_ccd.

queries: (N, 8, 3): the two ends of edge a, then of edge b, at t = 0, then the same four at
t = 1. Returns (hit, time) as vertex_face_ccd.
)doc");

  py::class_<collide::MeshImpact>(m, "MeshImpact", R"doc(
The first contact of two moving meshes: `hit` (also bool(impact)), `time` (the largest double <=
the earliest contact time; 0 when they touch or nest at t = 0; inf on a miss) and the witness.

witness: 'none', 'initial' (touching or nested at t = 0: `initial` is the discrete Contact),
'vertex_a_face_b' / 'vertex_b_face_a' (`vertex` of one mesh meets `triangle` of the other),
'edges' (`edge_a` of A meets `edge_b` of B, each a pair of vertex indices).
)doc")
      .def_readonly("hit", &collide::MeshImpact::hit, "True when the shapes touch in [0, 1].")
      .def_readonly("time", &collide::MeshImpact::time,
                    "The largest double <= the earliest contact time (inf when they never touch).")
      .def_property_readonly(
          "witness", [](const collide::MeshImpact& i) { return to_string(i.witness); },
          "'none', 'initial', 'vertex_a_face_b', 'vertex_b_face_a' or 'edges'.")
      .def_readonly("vertex", &collide::MeshImpact::vertex,
                    "Vertex-face witnesses: the vertex in its own mesh, else -1.")
      .def_readonly("triangle", &collide::MeshImpact::triangle,
                    "Vertex-face witnesses: the triangle of the other mesh, else -1.")
      .def_property_readonly(
          "edge_a", [](const collide::MeshImpact& i) { return optional_pair(i.edge_a); },
          "Edge witnesses: A's edge as (vertex, vertex), else None.")
      .def_property_readonly(
          "edge_b", [](const collide::MeshImpact& i) { return optional_pair(i.edge_b); },
          "Edge witnesses: B's edge as (vertex, vertex), else None.")
      .def_readonly("initial", &collide::MeshImpact::initial,
                    "The discrete test at t = 0 (a Contact).")
      .def_readonly("node_pairs", &collide::MeshImpact::node_pairs,
                    "Pairs of swept boxes tested (work done).")
      .def_readonly("primitive_tests", &collide::MeshImpact::primitive_tests,
                    "Vertex-face and edge-edge queries run (work done).")
      .def("__bool__", [](const collide::MeshImpact& i) { return i.hit; })
      .def("__repr__", [](const collide::MeshImpact& i) {
        return std::string("contain.MeshImpact(hit=") + (i.hit ? "True" : "False") +
               ", time=" + py::repr(py::float_(i.time)).cast<std::string>() + ", witness='" +
               to_string(i.witness) + "'" + witness_text(i) + ")";
      });

  py::class_<collide::MovingMeshPair>(m, "MovingMeshPair", R"doc(
Two meshes prepared for continuous collision: A with a fixed motion, B moved per query.

Every vertex moves on the straight line from its position under the placement at t = 0 to its
position under the placement at t = 1 (placements: None, 12 numbers, (3, 4) or (4, 4)), or, for
a deforming A, from A's vertices to `a_at1`. Closed meshes are solids: the answer is 0 where
they touch or nest at t = 0, else the earliest time their surfaces touch, exact, rounded down to
a double, with the witness pair of primitives.

    >>> pair = contain.MovingMeshPair(plate, bullet)
    >>> pair.first_contact(from_b=start, to_b=end).time
    >>> hit, time = pair.first_contact_many(motions)   # (N, 2, 3, 4) -> (N,), (N,)
)doc")
      .def(py::init([](const MeshLike& a, const MeshLike& b, const TransformLike& from_a,
                       const TransformLike& to_a, const py::object& a_at1) {
             const MeshRef ma = to_mesh(a.object, "a"), mb = to_mesh(b.object, "b");
             collide::MovingMeshPairOptions options;
             options.motion_a = to_motion(from_a.object, to_a.object, "from_a", "to_a");
             if (!a_at1.is_none())
               options.a_at1 = to_positions(a_at1, ma->vertices.size(), "a_at1");
             py::gil_scoped_release release;
             return collide::MovingMeshPair(*ma, *mb, options);
           }),
           "a"_a, "b"_a, py::kw_only(), "from_a"_a = py::none(), "to_a"_a = py::none(),
           "a_at1"_a = py::none(),
           "Prepares A (moving from from_a to to_a, or deforming to a_at1: (len(a.vertices), 3)) "
           "and B.")
      .def(
          "first_contact",
          [](const collide::MovingMeshPair& pair, const py::object& from_b, const py::object& to_b,
             int threads) -> py::object {
            switch (first_contact_form(from_b, to_b)) {
              case FirstContactForm::motions:
                return first_contacts(pair, from_b, threads);
              case FirstContactForm::deforming:
                return deforming_contact(pair, from_b);
              case FirstContactForm::pose:
                break;
            }
            const collide::Motion motion = to_motion(from_b, to_b, "from_b", "to_b");
            collide::MeshImpact impact;
            {
              py::gil_scoped_release release;
              impact = pair.first_contact(motion);
            }
            return py::cast(impact);
          },
          "from_b"_a = py::none(), "to_b"_a = py::none(), py::kw_only(), "threads"_a = 0, R"doc(
The first contact of A (on its own motion) and B, C++ MovingMeshPair::first_contact:
- first_contact(from_b, to_b): B moving from from_b (t = 0) to to_b (t = 1; None: from_b),
  poses (12,), (3, 4) or (4, 4); a MeshImpact.
- first_contact(b_at1): B deforming from its own vertices (t = 0) to b_at1 (t = 1,
  (len(b.vertices), 3)); a MeshImpact.
- first_contact(motions): many motions of B, (N, 24) (placement at t = 0, then at t = 1, 12
  numbers each), (N, 2, 12), (N, 2, 3, 4) or (N, 2, 4, 4); (hit, time) arrays (N,), on
  `threads` threads (0: every core) without the GIL.
)doc")
      .def(
          "first_contact_deforming",
          [](const collide::MovingMeshPair& pair, const ArrayLike& b_at1) {
            warn_deprecated("MovingMeshPair.first_contact_deforming",
                            "MovingMeshPair.first_contact(b_at1)");
            return deforming_contact(pair, b_at1.object);
          },
          "b_at1"_a,
          "Deprecated: first_contact(b_at1) (a DeprecationWarning); the same MeshImpact.")
      .def(
          "first_contact_many",
          [](const collide::MovingMeshPair& pair, const ArrayLike& motions, int threads) {
            warn_deprecated("MovingMeshPair.first_contact_many",
                            "MovingMeshPair.first_contact(motions)");
            return first_contacts(pair, motions.object, threads);
          },
          "motions"_a, py::kw_only(), "threads"_a = 0,
          "Deprecated: first_contact(motions) (a DeprecationWarning); the same (hit, time).")
      .def_property_readonly("a_is_solid", &collide::MovingMeshPair::a_is_solid,
                             "True when A is closed (a solid).")
      .def_property_readonly("b_is_solid", &collide::MovingMeshPair::b_is_solid,
                             "True when B is closed (a solid).")
      .def("__repr__", [](const collide::MovingMeshPair& pair) {
        return "contain.MovingMeshPair(a: " + mesh_side(pair.a_vertex_count(), pair.a_is_solid()) +
               "; b: " + mesh_side(pair.b_vertex_count(), pair.b_is_solid()) + ")";
      });

  m.def(
      "mesh_mesh_ccd",
      [](const MeshLike& a_like, const MeshLike& b_like, const TransformLike& from_a,
         const TransformLike& to_a, const TransformLike& from_b, const TransformLike& to_b,
         const py::object& a_at1, const py::object& b_at1) {
        const MeshRef a_ref = to_mesh(a_like.object, "a"), b_ref = to_mesh(b_like.object, "b");
        const Mesh &a = *a_ref, &b = *b_ref;
        if (!a_at1.is_none() || !b_at1.is_none()) {
          if (!from_a.object.is_none() || !to_a.object.is_none() || !from_b.object.is_none() ||
              !to_b.object.is_none()) {
            throw py::value_error(
                "mesh_mesh_ccd: give placements (from_a, to_a, from_b, to_b) or vertex arrays "
                "(a_at1, b_at1), not both");
          }
          const std::vector<Vec3> pa =
              a_at1.is_none() ? a.vertices : to_positions(a_at1, a.vertices.size(), "a_at1");
          const std::vector<Vec3> pb =
              b_at1.is_none() ? b.vertices : to_positions(b_at1, b.vertices.size(), "b_at1");
          py::gil_scoped_release release;
          return collide::mesh_mesh_ccd(a, pa, b, pb);
        }
        const collide::Motion ma = to_motion(from_a.object, to_a.object, "from_a", "to_a");
        const collide::Motion mb = to_motion(from_b.object, to_b.object, "from_b", "to_b");
        py::gil_scoped_release release;
        return collide::mesh_mesh_ccd(a, b, ma, mb);
      },
      "a"_a, "b"_a, py::kw_only(), "from_a"_a = py::none(), "to_a"_a = py::none(),
      "from_b"_a = py::none(), "to_b"_a = py::none(), "a_at1"_a = py::none(),
      "b_at1"_a = py::none(), R"doc(
The first contact of two moving meshes, one query (a MeshImpact; see MovingMeshPair).

Rigid placements: each mesh moves from from_X (t = 0) to to_X (t = 1); a missing to_X means the
mesh stays at from_X. Deforming meshes: a_at1 and b_at1 give the vertices at t = 1 (the meshes'
own vertices are their positions at t = 0).
)doc");
}

}  // namespace contain::python
