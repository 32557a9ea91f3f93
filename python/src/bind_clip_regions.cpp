// contain.clip_polygon, contain.clip_mesh, contain.clip_polylines and contain.sutherland_hodgman:
// regions, meshes and open paths clipped by half-planes / half-spaces, boxes and convex shapes.

#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/clip/clip_polygon.h"
#include "contain/clip/mesh_clip.h"
#include "contain/clip/polyline_clip.h"
#include "contain/clip/sutherland_hodgman.h"
#include "contain/io/wkt.h"
#include "contain/shapes/mesh_validation.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

// Exactly one of the keywords; its name.
std::string one_region(const char* what, const py::handle& halfspace, const py::handle& box,
                       const py::handle& convex) {
  const int given = !halfspace.is_none() + !box.is_none() + !convex.is_none();
  if (given != 1) {
    throw py::value_error(std::string(what) + ": give exactly one of halfspace=, box=, convex=");
  }
  return !halfspace.is_none() ? "halfspace" : (!box.is_none() ? "box" : "convex");
}

py::array_t<double> points_to_numpy(std::span<const Vec2> points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < points.size(); ++i) {
    data[2 * i] = points[i].x;
    data[2 * i + 1] = points[i].y;
  }
  return out;
}

py::array_t<double> points_to_numpy(std::span<const Vec3> points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < points.size(); ++i) {
    data[3 * i] = points[i].x;
    data[3 * i + 1] = points[i].y;
    data[3 * i + 2] = points[i].z;
  }
  return out;
}

clip::PolylinePart parse_part(const std::string& keep) {
  if (keep == "inside") return clip::PolylinePart::inside;
  if (keep == "outside") return clip::PolylinePart::outside;
  throw py::value_error("keep must be 'inside' or 'outside', got '" + keep + "'");
}

}  // namespace

void bind_clip_regions(py::module_& m) {
  m.def(
      "clip_polygon",
      [](const RegionLike& region, const py::object& halfspace, const py::object& box,
         const py::object& convex, bool keep_bridges) -> py::object {
        const std::string which = one_region("clip_polygon", halfspace, box, convex);
        const MultiPolygon subject = to_region(region.object, "region");
        const clip::PolygonClipOptions options{.output = keep_bridges
                                                             ? clip::PolygonClipOutput::bridged
                                                             : clip::PolygonClipOutput::pieces};
        MultiPolygon result;
        if (which == "halfspace") {
          const std::vector<HalfPlane> planes = to_half_planes(halfspace, "halfspace");
          py::gil_scoped_release release;
          result = clip::clip_polygon(subject, planes, options);
        } else if (which == "box") {
          const Box2 b = to_box2(box, "box");
          py::gil_scoped_release release;
          result = clip::clip_polygon(subject, b, options);
        } else {
          const Ring ring = to_convex_ring(convex, "convex ring");
          py::gil_scoped_release release;
          result = clip::clip_polygon(subject, ring, options);
        }
        if (py::isinstance<py::str>(region.object)) return py::str(io::format_wkt(result));
        return py::cast(std::move(result));
      },
      "region"_a, py::kw_only(), "halfspace"_a = py::none(), "box"_a = py::none(),
      "convex"_a = py::none(), "keep_bridges"_a = false, R"doc(
The part of a region inside a convex clip region: Sutherland-Hodgman ring by ring (the
section's algorithm), the result split into valid pieces.

region: anything region-like (shapely, GeoPandas, WKT, GeoJSON, WKB, rings, a Region).
Exactly one clip region:
  halfspace=(a, b, c)   a x + b y + c >= 0, or an (M, 3) array: their intersection
  box=(min, max)        an axis-aligned box (crossings on its sides exact)
  convex=ring           a convex ring (K, 2), either direction (exact orient2d side tests)
keep_bridges: False (default) gives the pieces, an OGC-valid Region for OGC-valid input
(shells counter-clockwise, holes clockwise, each hole in its piece); True gives the section's
result, one ring per input ring with degenerate bridging edges along the clip lines (covers the
same area under the even-odd rule), as the CLI's --keep-bridges.
Returns a Region (WKT when `region` is WKT text). In/out of every vertex is exact; crossing
points are rounded (a few ulps), exact on box sides. Runs without the GIL.
)doc");

  m.def(
      "clip_mesh",
      [](const MeshLike& mesh, const py::object& halfspace, const py::object& box,
         const py::object& convex, bool cap) {
        const std::string which = one_region("clip_mesh", halfspace, box, convex);
        const MeshRef subject = to_mesh(mesh.object, "mesh");
        if (cap && !validate_mesh(*subject).closed()) {
          fail(ErrorKind::invalid_value,
               "cap=True needs a closed mesh (every edge shared by two triangles); "
               "validate_mesh(mesh) says what is open");
        }
        const clip::MeshClipOptions options{.cut = cap ? clip::MeshCut::cap : clip::MeshCut::open};
        if (which == "halfspace") {
          const std::vector<Plane> planes = to_planes(halfspace, "halfspace");
          py::gil_scoped_release release;
          return clip::clip_mesh(*subject, planes, options);
        }
        if (which == "box") {
          const Box3 b = to_box3(box, "box");
          py::gil_scoped_release release;
          return clip::clip_mesh(*subject, b, options);
        }
        const ConvexPolyhedron polyhedron = to_convex_polyhedron(convex, "convex");
        py::gil_scoped_release release;
        return clip::clip_mesh(*subject, polyhedron, options);
      },
      "mesh"_a, py::kw_only(), "halfspace"_a = py::none(), "box"_a = py::none(),
      "convex"_a = py::none(), "cap"_a = false, R"doc(
The part of a triangle mesh inside a convex region, face by face (Sutherland-Hodgman on each
triangle), as a new Mesh.

mesh: anything mesh-like (contain.Mesh, trimesh, Open3D, (vertices, faces), a path).
Exactly one clip region:
  halfspace=(a, b, c, d)  a x + b y + c z + d >= 0, or an (M, 4) array: their intersection
  box=(min, max)          an axis-aligned box
  convex=...              a convex mesh, a ConvexPolyhedron or (M, 4) planes
cap: False leaves the cut open; True closes the cut of a closed mesh with cap polygons, so the
result is again closed and consistently oriented (check with validate_mesh; ContainError when
the mesh is not closed), as the CLI's --cap.
The side of every vertex is exact; crossing points are made once per mesh edge, so the result
stays welded, rounded to a few ulps (exact on box faces). Runs without the GIL.
)doc");

  m.def(
      "clip_polylines",
      [](const py::object& polylines, const RegionLike& region, const std::string& keep,
         const std::string& fill) {
        if (py::isinstance<py::str>(polylines) || !py::isinstance<py::sequence>(polylines)) {
          throw py::type_error("polylines must be a sequence of (K, 2) arrays");
        }
        std::vector<clip::Polyline> paths;
        for (const py::handle item : py::reinterpret_borrow<py::sequence>(polylines)) {
          const Doubles points = as_matrix(item, 2, "polyline");
          require_finite(points, "polyline", 1);
          const auto span = as_vec2(points);
          paths.emplace_back(span.begin(), span.end());
        }
        const MultiPolygon r = to_region(region.object, "region");
        const clip::PolylineClipOptions options{.keep = parse_part(keep), .fill = parse_fill(fill)};
        std::vector<clip::Polyline> pieces;
        {
          py::gil_scoped_release release;
          pieces = clip::clip_polylines(paths, r, options);
        }
        py::list out;
        for (const clip::Polyline& piece : pieces)
          out.append(points_to_numpy(piece));
        return out;
      },
      "polylines"_a, "region"_a, py::kw_only(), "keep"_a = "inside", "fill"_a = "even_odd", R"doc(
The parts of open paths inside (keep='inside', the closed region) or outside (keep='outside')
a region of any shape, as a list of (K, 2) arrays in the direction of their input (what users
of Clipper2's open paths expect).

polylines: a sequence of (K, 2) arrays (open: the last point does not join the first).
region: anything region-like, read under `fill`. Every input point is kept bit for bit; entry
and exit points are new (rounded as in polygon_boolean); which parts are in is exact.
)doc");

  m.def(
      "sutherland_hodgman",
      [](const ArrayLike& polygon, const py::object& halfspace, const py::object& convex) {
        const py::array array = py::array::ensure(polygon.object);
        if (!array) PyErr_Clear();
        const bool three_d = array && array.ndim() == 2 && array.shape(1) == 3;
        if (halfspace.is_none() == convex.is_none()) {
          throw py::value_error("sutherland_hodgman: give exactly one of halfspace=, convex=");
        }
        if (three_d) {
          if (!convex.is_none()) {
            throw py::value_error("sutherland_hodgman: a 3D polygon is clipped by halfspace=");
          }
          const Doubles points = as_matrix(array, 3, "polygon");
          require_finite(points, "polygon", 1);
          const std::vector<Plane> planes = to_planes(halfspace, "halfspace");
          return points_to_numpy(clip::sutherland_hodgman(as_vec3(points), planes));
        }
        const Doubles points = as_matrix(polygon.object, 2, "polygon (K, 2) or (K, 3)");
        require_finite(points, "polygon", 1);
        const auto span = as_vec2(points);
        const Ring ring(span.begin(), span.end());
        if (!halfspace.is_none()) {
          return points_to_numpy(
              clip::sutherland_hodgman(ring, to_half_planes(halfspace, "halfspace")));
        }
        return points_to_numpy(clip::sutherland_hodgman(ring, to_convex_ring(convex, "convex")));
      },
      "polygon"_a, py::kw_only(), "halfspace"_a = py::none(), "convex"_a = py::none(), R"doc(
The section's Sutherland-Hodgman on one polygon, as it gives it: a (K, 2) ring against
half-planes (halfspace=(a, b, c) or (M, 3), one after the other) or a convex ring
(convex=(J, 2)), or a planar (K, 3) polygon against half-spaces (halfspace=(a, b, c, d) or
(M, 4)). Returns the clipped vertices as an array; a concave ring that falls apart comes back
as one ring joined by degenerate bridging edges (use clip_polygon for valid pieces); empty
(0, d) when fewer than 3 points remain. Exact in/out of every vertex.
)doc");
}

}  // namespace contain::python
