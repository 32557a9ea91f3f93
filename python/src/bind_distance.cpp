// contain.MeshDistance, contain.RegionDistance, contain.MeshPairDistance, contain.ConvexDistance:
// distances, closest points and features as numpy arrays, computed without the GIL on all cores.

#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/distance/convex_distance.h"
#include "contain/distance/mesh_distance.h"
#include "contain/distance/mesh_pair_distance.h"
#include "contain/distance/region_distance.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

template <class T>
py::array_t<T> owned(std::vector<T>&& values) {
  auto* held = new std::vector<T>(std::move(values));
  py::capsule base(held, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>({static_cast<py::ssize_t>(held->size())}, held->data(), base);
}

py::array_t<bool> booleans(const std::vector<std::uint8_t>& yes) {
  py::array_t<bool> out(static_cast<py::ssize_t>(yes.size()));
  bool* data = out.mutable_data();
  for (std::size_t i = 0; i < yes.size(); ++i)
    data[i] = yes[i] != 0;
  return out;
}

// The closest point where there is none (an empty mesh or region: distance inf, feature -1):
// NaN rather than a made-up (0, 0, 0), so that no caller uses it as a point of the boundary.
constexpr double kNoPoint = std::numeric_limits<double>::quiet_NaN();

// MeshDistance and ConvexDistance alike (the feature is a triangle, or a face).
template <class Prepared>
py::dict mesh_query(const Prepared& prepared, const py::handle& points, bool signed_distance,
                    bool closest, int threads) {
  const Doubles array = as_matrix(points, 3, "points");
  require_finite(array, "points", threads);
  const std::span<const Vec3> p = as_vec3(array);
  std::vector<distance::Closest3> answers(p.size());
  {
    py::gil_scoped_release release;
    prepared.distance(p, answers, {.signed_distance = signed_distance, .closest_point = closest},
                      {.threads = threads});
  }
  std::vector<double> d(p.size()), q(3 * p.size());
  std::vector<std::int32_t> tri(p.size());
  std::vector<std::int8_t> where(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    d[i] = answers[i].distance;
    const Vec3 at = answers[i].feature < 0 ? Vec3{kNoPoint, kNoPoint, kNoPoint} : answers[i].point;
    q[3 * i] = at.x;
    q[3 * i + 1] = at.y;
    q[3 * i + 2] = at.z;
    tri[i] = answers[i].feature;
    where[i] = static_cast<std::int8_t>(answers[i].location);
  }
  const auto n = static_cast<py::ssize_t>(p.size());
  py::dict out;
  out["distance"] = owned(std::move(d));
  out["point"] = to_numpy(std::move(q), n, 3);
  out["triangle"] = owned(std::move(tri));
  out["location"] = owned(std::move(where));
  return out;
}

py::dict region_query(const distance::RegionDistance& prepared, const py::handle& points,
                      bool signed_distance, bool closest, int threads) {
  const Doubles array = as_matrix(points, 2, "points");
  require_finite(array, "points", threads);
  const std::span<const Vec2> p = as_vec2(array);
  std::vector<distance::Closest2> answers(p.size());
  {
    py::gil_scoped_release release;
    prepared.distance(p, answers, {.signed_distance = signed_distance, .closest_point = closest},
                      {.threads = threads});
  }
  std::vector<double> d(p.size()), q(2 * p.size());
  std::vector<std::int32_t> ring(p.size()), edge(p.size());
  std::vector<std::int8_t> where(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    d[i] = answers[i].distance;
    const Vec2 at = answers[i].ring < 0 ? Vec2{kNoPoint, kNoPoint} : answers[i].point;
    q[2 * i] = at.x;
    q[2 * i + 1] = at.y;
    ring[i] = answers[i].ring;
    edge[i] = answers[i].edge;
    where[i] = static_cast<std::int8_t>(answers[i].location);
  }
  const auto n = static_cast<py::ssize_t>(p.size());
  py::dict out;
  out["distance"] = owned(std::move(d));
  out["point"] = to_numpy(std::move(q), n, 2);
  out["ring"] = owned(std::move(ring));
  out["edge"] = owned(std::move(edge));
  out["location"] = owned(std::move(where));
  return out;
}

// The command's rule for `--within D` (exit 3 otherwise), so that no NaN, negative or infinite
// clearance answers silently: a finite number >= 0.
double clearance(double d) {
  if (!(std::isfinite(d) && d >= 0)) {
    fail(ErrorKind::invalid_value,
         "d must be a finite number >= 0 (as the command's --within D), got " +
             py::repr(py::float_(d)).cast<std::string>());
  }
  return d;
}

std::string solid_word(bool solid) {
  return solid ? "solid" : "open surface";
}

// A MeshPairDistance with the sizes its repr shows (the prepared pair keeps no counts).
struct PreparedPair {
  distance::MeshPairDistance pair;
  std::size_t a_triangles = 0;
  std::size_t b_triangles = 0;
};

py::dict pair_answers(const std::vector<distance::PairDistance3>& r) {
  std::vector<double> d(r.size()), pa(3 * r.size()), pb(3 * r.size());
  std::vector<std::int32_t> ta(r.size()), tb(r.size());
  py::list contact;
  for (std::size_t i = 0; i < r.size(); ++i) {
    d[i] = r[i].distance;
    pa[3 * i] = r[i].point_a.x;
    pa[3 * i + 1] = r[i].point_a.y;
    pa[3 * i + 2] = r[i].point_a.z;
    pb[3 * i] = r[i].point_b.x;
    pb[3 * i + 1] = r[i].point_b.y;
    pb[3 * i + 2] = r[i].point_b.z;
    ta[i] = r[i].triangle_a;
    tb[i] = r[i].triangle_b;
    contact.append(distance::to_string(r[i].contact));
  }
  const auto n = static_cast<py::ssize_t>(r.size());
  py::dict out;
  out["distance"] = owned(std::move(d));
  out["point_a"] = to_numpy(std::move(pa), n, 3);
  out["point_b"] = to_numpy(std::move(pb), n, 3);
  out["triangle_a"] = owned(std::move(ta));
  out["triangle_b"] = owned(std::move(tb));
  out["contact"] = contact;
  return out;
}

py::dict convex_pairs(const distance::ConvexDistance& a, const distance::ConvexDistance& b,
                      const py::handle& poses) {
  const std::vector<Transform> t = to_transforms(poses, "poses");
  std::vector<distance::PairDistance3> r(t.size());
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < t.size(); ++i)
      r[i] = distance::convex_convex(a, b, t[i]);
  }
  return pair_answers(r);
}

py::array_t<bool> convex_pairs_within(const distance::ConvexDistance& a,
                                      const distance::ConvexDistance& b, const py::handle& poses,
                                      double d) {
  clearance(d);
  const std::vector<Transform> t = to_transforms(poses, "poses");
  std::vector<std::uint8_t> yes(t.size());
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < t.size(); ++i)
      yes[i] = distance::convex_convex_within(a, b, t[i], d) ? 1 : 0;
  }
  return booleans(yes);
}

constexpr const char* kQueryDoc = R"doc(
Distances of many points, on `threads` threads (0: all cores), without the GIL.

points: ({dim}) array-like of float (NaN or infinite values raise ContainError).
signed: negative inside, exactly 0 on the boundary (the exact location), positive outside.
closest: also the closest points (each coordinate the double nearest to the exact one).
Returns a dict of numpy arrays: 'distance' (N,) float64, the double nearest to each exact
distance; 'point' (N, {dim}) float64 (NaN when there is no boundary: an empty shape, distance
inf, feature -1); {feature}; 'location' (N,) int8 (-1 outside, 0 boundary, 1 inside; -1 when
not signed).
)doc";

std::string query_doc(const char* dim, const char* feature) {
  std::string s = kQueryDoc;
  for (const auto& [key, value] : {std::pair{std::string("{dim}"), std::string(dim)},
                                   std::pair{std::string("{feature}"), std::string(feature)}}) {
    for (std::size_t at = s.find(key); at != std::string::npos; at = s.find(key))
      s.replace(at, key.size(), value);
  }
  return s;
}

}  // namespace

void bind_distance(py::module_& m) {
  static const std::string query3 =
      query_doc("3", "'triangle' (N,) int32, the closest triangle (ties to the lowest)");
  static const std::string query2 =
      query_doc("2", "'ring', 'edge' (N,) int32, the closest edge (ties to the lowest)");

  py::class_<distance::MeshDistance>(m, "MeshDistance", R"doc(
A triangle mesh prepared for distance queries: the distance to its surface (closed or open),
signed by the exact containment, the closest point and triangle, and the exact clearance test.

Every decision is exact on the given doubles; each distance is the double nearest to the exact
distance (rounded once), each closest-point coordinate too. For an open mesh signs come from
the generalized winding number (`regime` says 'winding_number').

    >>> prepared = contain.MeshDistance(contain.read_mesh("part.stl"))
    >>> r = prepared.distance(points, signed=True)    # (N, 3) -> dict of arrays
    >>> r["distance"], r["point"], r["triangle"]
)doc")
      .def(py::init([](const MeshLike& mesh) {
             const MeshRef ref = to_mesh(mesh.object, "mesh");
             py::gil_scoped_release release;
             return distance::MeshDistance(*ref);
           }),
           "mesh"_a,
           "Prepares any mesh-like object (contain.as_mesh: a Mesh, a path, a trimesh or Open3D\n"
           "mesh, (vertices, faces)): its BVH and containment index.")
      .def(
          "distance",
          [](const distance::MeshDistance& prepared, const ArrayLike& points, bool signed_distance,
             bool closest, int threads) {
            return mesh_query(prepared, points.object, signed_distance, closest, threads);
          },
          "points"_a, py::kw_only(), "signed"_a = false, "closest"_a = true, "threads"_a = 0,
          query3.c_str())
      .def(
          "query",
          [](const distance::MeshDistance& prepared, const ArrayLike& points, bool signed_distance,
             bool closest, int threads) {
            warn_deprecated("MeshDistance.query", "MeshDistance.distance");
            return mesh_query(prepared, points.object, signed_distance, closest, threads);
          },
          "points"_a, py::kw_only(), "signed"_a = false, "closest"_a = true, "threads"_a = 0,
          "Deprecated: distance(points, ...), the C++ name (a DeprecationWarning); "
          "the same answer.")
      .def(
          "within",
          [](const distance::MeshDistance& prepared, const ArrayLike& points, double d,
             int threads) {
            clearance(d);
            const Doubles array = as_matrix(points.object, 3, "points");
            require_finite(array, "points", threads);
            std::vector<std::uint8_t> yes(static_cast<std::size_t>(array.shape(0)));
            {
              py::gil_scoped_release release;
              prepared.within(as_vec3(array), d, yes, {.threads = threads});
            }
            return booleans(yes);
          },
          "points"_a, "d"_a, py::kw_only(), "threads"_a = 0,
          "(N,) bool: is each point's distance to the surface at most d? Exact (squared "
          "distances against d^2, no rounding). d: finite, >= 0 (ContainError otherwise).")
      .def_property_readonly(
          "regime",
          [](const distance::MeshDistance& prepared) { return to_string(prepared.regime()); },
          "How signs are decided: 'closed_exact' or 'winding_number'.")
      .def("__len__", &distance::MeshDistance::size, "Number of triangles.")
      .def("__repr__", [](const distance::MeshDistance& prepared) {
        return "contain.MeshDistance(" + std::to_string(prepared.size()) + " triangles, regime='" +
               to_string(prepared.regime()) + "')";
      });

  py::class_<distance::RegionDistance>(m, "RegionDistance", R"doc(
A 2D region prepared for distance queries: the distance to its rings, signed by the exact
location under the fill rule, the closest point and ring:edge, and the exact clearance test.

    >>> prepared = contain.RegionDistance("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))")
    >>> prepared.distance([[2, 1]], signed=True)["distance"]     # array([-1.])
)doc")
      .def(py::init([](const RegionLike& region, const std::string& fill) {
             const MultiPolygon r = to_region(region.object, "region");
             const Fill f = parse_fill(fill);
             py::gil_scoped_release release;
             return distance::RegionDistance(r, {.fill = f});
           }),
           "region"_a, py::kw_only(), "fill"_a = "even_odd",
           "Prepares a region (contain.Region, WKT or rings) under a fill rule.")
      .def(
          "distance",
          [](const distance::RegionDistance& prepared, const ArrayLike& points,
             bool signed_distance, bool closest, int threads) {
            return region_query(prepared, points.object, signed_distance, closest, threads);
          },
          "points"_a, py::kw_only(), "signed"_a = false, "closest"_a = true, "threads"_a = 0,
          query2.c_str())
      .def(
          "query",
          [](const distance::RegionDistance& prepared, const ArrayLike& points,
             bool signed_distance, bool closest, int threads) {
            warn_deprecated("RegionDistance.query", "RegionDistance.distance");
            return region_query(prepared, points.object, signed_distance, closest, threads);
          },
          "points"_a, py::kw_only(), "signed"_a = false, "closest"_a = true, "threads"_a = 0,
          "Deprecated: distance(points, ...), the C++ name (a DeprecationWarning); "
          "the same answer.")
      .def(
          "within",
          [](const distance::RegionDistance& prepared, const ArrayLike& points, double d,
             int threads) {
            clearance(d);
            const Doubles array = as_matrix(points.object, 2, "points");
            require_finite(array, "points", threads);
            std::vector<std::uint8_t> yes(static_cast<std::size_t>(array.shape(0)));
            {
              py::gil_scoped_release release;
              prepared.within(as_vec2(array), d, yes, {.threads = threads});
            }
            return booleans(yes);
          },
          "points"_a, "d"_a, py::kw_only(), "threads"_a = 0,
          "(N,) bool: is each point's distance to the rings at most d? Exact. d: finite, >= 0.")
      .def("__len__", &distance::RegionDistance::size, "Number of edges.")
      .def("__repr__", [](const distance::RegionDistance& prepared) {
        return "contain.RegionDistance(" + std::to_string(prepared.size()) + " edges, fill='" +
               fill_name(prepared.index().fill()) + "')";
      });

  py::class_<PreparedPair>(m, "MeshPairDistance", R"doc(
Two meshes prepared for distance queries as solids (0 where they touch, overlap or nest), B
placed by a pose per query. Exact on the transformed doubles; distances rounded once. A and B
are any mesh-like objects (contain.as_mesh).

    >>> pair = contain.MeshPairDistance(tool, fixture)
    >>> r = pair.distance(poses)          # (N, 12), (N, 3, 4) or (N, 4, 4) -> dict of arrays
    >>> r["distance"], r["point_a"], r["point_b"], r["triangle_a"], r["contact"]
)doc")
      .def(py::init([](const MeshLike& a, const MeshLike& b, const TransformLike& transform_a) {
             const MeshRef ma = to_mesh(a.object, "a"), mb = to_mesh(b.object, "b");
             const Transform ta = to_transform(transform_a.object, "transform_a");
             py::gil_scoped_release release;
             return PreparedPair{distance::MeshPairDistance(*ma, *mb, {.transform_a = ta}),
                                 ma->triangles.size(), mb->triangles.size()};
           }),
           "a"_a, "b"_a, py::kw_only(), "transform_a"_a = py::none(),
           "Prepares A (placed by transform_a, fixed) and B, each any mesh-like object.")
      .def(
          "distance",
          [](const PreparedPair& prepared, const ArrayLike& poses, int threads) {
            const std::vector<Transform> t = to_transforms(poses.object, "poses");
            std::vector<distance::PairDistance3> r(t.size());
            {
              py::gil_scoped_release release;
              prepared.pair.distance(t, r, {.threads = threads});
            }
            return pair_answers(r);
          },
          "poses"_a, py::kw_only(), "threads"_a = 0,
          "Distances for each pose of B (poses: (N, 12), (N, 3, 4), (N, 4, 4) or one pose): a "
          "dict of arrays 'distance' (N,), 'point_a', 'point_b' (N, 3), 'triangle_a', "
          "'triangle_b' (N,) int32 and 'contact' (list of 'separate', 'touching', "
          "'vertex_of_a_in_b', 'vertex_of_b_in_a').")
      .def(
          "within",
          [](const PreparedPair& prepared, const ArrayLike& poses, double d, int threads) {
            clearance(d);
            const std::vector<Transform> t = to_transforms(poses.object, "poses");
            std::vector<std::uint8_t> yes(t.size());
            {
              py::gil_scoped_release release;
              prepared.pair.within(t, d, yes, {.threads = threads});
            }
            return booleans(yes);
          },
          "poses"_a, "d"_a, py::kw_only(), "threads"_a = 0,
          "(N,) bool: is the distance at each pose at most d? Exact. d: finite, >= 0.")
      .def_property_readonly(
          "a_is_solid", [](const PreparedPair& prepared) { return prepared.pair.a_is_solid(); },
          "True when A is closed (a solid).")
      .def_property_readonly(
          "b_is_solid", [](const PreparedPair& prepared) { return prepared.pair.b_is_solid(); },
          "True when B is closed (a solid).")
      .def("__repr__", [](const PreparedPair& prepared) {
        return "contain.MeshPairDistance(a: " + std::to_string(prepared.a_triangles) +
               " triangles, " + solid_word(prepared.pair.a_is_solid()) +
               "; b: " + std::to_string(prepared.b_triangles) + " triangles, " +
               solid_word(prepared.pair.b_is_solid()) + ")";
      });

  py::class_<distance::ConvexDistance>(m, "ConvexDistance", R"doc(
A convex polyhedron (given by a convex mesh) prepared for distance queries: points as
MeshDistance answers them on its faces (signs from the exact convex containment); the distance
between two convex solids under poses of the second is contain.convex_convex (GJK-guided,
decided exactly).

    >>> box = contain.ConvexDistance(contain.ConvexPolyhedron(cube_mesh))
    >>> box.distance([[2, 0.5, 0.5]], signed=True)["distance"]        # array([1.])
    >>> contain.convex_convex(box, other, poses)["distance"]        # (N,) per pose of other
)doc")
      .def(py::init([](const py::handle& convex) {
             const ConvexPolyhedron polyhedron = to_convex_polyhedron(convex, "convex");
             py::gil_scoped_release release;
             return take(distance::ConvexDistance::prepare(polyhedron));
           }),
           "convex"_a,
           "Prepares a contain.ConvexPolyhedron or a closed convex mesh (a polyhedron given only "
           "by planes has no faces to measure to: ContainError).")
      .def(
          "distance",
          [](const distance::ConvexDistance& prepared, const ArrayLike& points,
             bool signed_distance, bool closest, int threads) {
            return mesh_query(prepared, points.object, signed_distance, closest, threads);
          },
          "points"_a, py::kw_only(), "signed"_a = false, "closest"_a = true, "threads"_a = 0,
          query3.c_str())
      .def(
          "query",
          [](const distance::ConvexDistance& prepared, const ArrayLike& points,
             bool signed_distance, bool closest, int threads) {
            warn_deprecated("ConvexDistance.query", "ConvexDistance.distance");
            return mesh_query(prepared, points.object, signed_distance, closest, threads);
          },
          "points"_a, py::kw_only(), "signed"_a = false, "closest"_a = true, "threads"_a = 0,
          "Deprecated: distance(points, ...), the C++ name (a DeprecationWarning); "
          "the same answer.")
      .def(
          "within",
          [](const distance::ConvexDistance& prepared, const ArrayLike& points, double d) {
            clearance(d);
            const Doubles array = as_matrix(points.object, 3, "points");
            require_finite(array, "points", 1);
            const std::span<const Vec3> p = as_vec3(array);
            std::vector<std::uint8_t> yes(p.size());
            {
              py::gil_scoped_release release;
              for (std::size_t i = 0; i < p.size(); ++i)
                yes[i] = prepared.within(p[i], d) ? 1 : 0;
            }
            return booleans(yes);
          },
          "points"_a, "d"_a,
          "(N,) bool: is each point's distance to the surface at most d? Exact. d: finite, >= 0.")
      .def(
          "pair_distance",
          [](const distance::ConvexDistance& a, const distance::ConvexDistance& b,
             const ArrayLike& poses) {
            warn_deprecated("ConvexDistance.pair_distance(other, poses)",
                            "contain.convex_convex(a, b, poses)");
            return convex_pairs(a, b, poses.object);
          },
          "other"_a, "poses"_a,
          "Deprecated: contain.convex_convex(self, other, poses), the C++ name (a "
          "DeprecationWarning).")
      .def(
          "pair_within",
          [](const distance::ConvexDistance& a, const distance::ConvexDistance& b,
             const ArrayLike& poses, double d) {
            warn_deprecated("ConvexDistance.pair_within(other, poses, d)",
                            "contain.convex_convex_within(a, b, poses, d)");
            return convex_pairs_within(a, b, poses.object, d);
          },
          "other"_a, "poses"_a, "d"_a,
          "Deprecated: contain.convex_convex_within(self, other, poses, d), the C++ name (a "
          "DeprecationWarning).")
      .def(
          "__len__",
          [](const distance::ConvexDistance& prepared) { return prepared.faces().size(); },
          "Number of faces.")
      .def("__repr__", [](const distance::ConvexDistance& prepared) {
        return "contain.ConvexDistance(" + std::to_string(prepared.faces().size()) + " faces, " +
               std::to_string(prepared.vertices().size()) + " vertices)";
      });

  m.def(
      "convex_convex",
      [](const distance::ConvexDistance& a, const distance::ConvexDistance& b,
         const ArrayLike& poses) { return convex_pairs(a, b, poses.object); },
      "a"_a, "b"_a, "poses"_a, R"doc(
The distance between the convex solids A and B placed by each pose of B (C++
distance::convex_convex): 0 where they touch, overlap or nest; GJK-guided, every decision
exact, each distance the double nearest to the exact one. a, b: contain.ConvexDistance;
poses: (N, 12), (N, 3, 4), (N, 4, 4) or one pose. Returns the dict of MeshPairDistance.distance
('triangle_a', 'triangle_b' are face indices).
)doc");
  m.def(
      "convex_convex_within",
      [](const distance::ConvexDistance& a, const distance::ConvexDistance& b,
         const ArrayLike& poses, double d) { return convex_pairs_within(a, b, poses.object, d); },
      "a"_a, "b"_a, "poses"_a, "d"_a, R"doc(
(N,) bool: is the distance between A and B placed by each pose at most d? Exact (squared
distances against d^2, no rounding; C++ distance::convex_convex_within). d: finite, >= 0
(ContainError otherwise).
)doc");
}

}  // namespace contain::python
