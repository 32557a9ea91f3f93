#pragma once
/// \file
/// What counts as a mesh and as a region, written once for every binding (the rule of
/// docs/python.md, "Shapes you already hold"), and the other conversions the bindings share:
/// option strings, transforms, the `Location` enum and booleans under a boundary policy.
///
/// A binding that takes a shape declares the parameter as `MeshLike` or `RegionLike`
/// (arguments.h, so help() names the rule) and converts it with `to_mesh` / `to_region`:
///
///     m.def("area_of", [](const RegionLike& region) {
///       const MultiPolygon r = to_region(region.object, "region");  // any region a user holds
///       ...
///     }, "region"_a);
///     m.def("volume_of", [](const MeshLike& mesh) {
///       const MeshRef m = to_mesh(mesh.object, "mesh");  // borrowed when it is a contain.Mesh
///       return something(*m);
///     }, "mesh"_a);
///
/// Errors follow the module's rule: an object of no accepted kind raises TypeError naming the
/// parameter and the kinds; malformed content raises ContainError (ValueError) with the
/// library's message; an unreadable file ContainIOError (OSError).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "contain/core/location.h"
#include "contain/shapes/convex_polyhedron.h"
#include "contain/shapes/mesh.h"
#include "contain/shapes/polygon.h"
#include "contain/values/box.h"
#include "contain/values/plane.h"
#include "contain/values/transform.h"

namespace contain::python {

namespace py = pybind11;

/// A mesh argument: the caller's contain.Mesh, borrowed (no copy; the Python object is kept
/// alive), or a mesh converted from another object and owned. Hold it while using the mesh.
class MeshRef {
 public:
  /// Borrows the Mesh held by `owner` (a contain.Mesh).
  explicit MeshRef(py::object owner);
  /// Owns `mesh`.
  explicit MeshRef(Mesh mesh);

  [[nodiscard]] const Mesh& operator*() const { return *mesh_; }
  [[nodiscard]] const Mesh* operator->() const { return mesh_; }
  /// The mesh as a Python contain.Mesh (the caller's own object when borrowed).
  [[nodiscard]] py::object object() const;

 private:
  py::object owner_;             // the borrowed contain.Mesh, or none
  std::shared_ptr<Mesh> owned_;  // the converted mesh, or null
  const Mesh* mesh_ = nullptr;
};

/// THE mesh rule. Accepted, tried in this order:
/// 1. a contain.Mesh (borrowed);
/// 2. a path (str or os.PathLike): read with contain.read_mesh (.obj .off .stl .ply);
/// 3. an object with `vertices` and `faces` arrays (trimesh.Trimesh, or any such object),
///    or with `vertices` and `triangles` (Open3D's geometry.TriangleMesh, whose Vector3dVector
///    and Vector3iVector numpy reads without a copy), or with `vertex["positions"]` and
///    `triangle["indices"]` tensors (Open3D's t.geometry.TriangleMesh, read with .numpy());
/// 4. a mapping with keys "vertices" and "faces";
/// 5. a pair (vertices, faces): a tuple or list of two array-likes, (V, 3) real numbers and
///    (M, 3) integer indices.
/// Vertices may be any real dtype (float32 is widened exactly); the mesh is validated as
/// contain.Mesh(vertices, faces) is.
[[nodiscard]] MeshRef to_mesh(const py::handle& object, const char* name);

/// The validated mesh of (V, 3) real vertices and (M, 3) integer faces (ContainError for NaN/Inf
/// or an index out of range; TypeError / ValueError for wrong dtypes and shapes).
[[nodiscard]] Mesh mesh_from_arrays(const py::handle& vertices, const py::handle& faces);

/// True when `to_mesh` would take `object` by its kind (it may still reject the contents): a
/// contain.Mesh, a path whose extension names a mesh format, an object or mapping of the
/// kinds above, or a pair whose first member has 3 columns. For functions that take either a
/// mesh or a region (collide, aabb).
[[nodiscard]] bool is_mesh_like(const py::handle& object);

/// THE region rule. Accepted, tried in this order:
/// 1. a contain.Region;
/// 2. bytes, bytearray or memoryview: WKB or PostGIS EWKB (io::parse_wkb);
/// 3. a str: GeoJSON text when it starts with '{', hex WKB when it is all hexadecimal digits,
///    WKT when it holds '(' or the word EMPTY, and otherwise a file path;
/// 4. an os.PathLike: a region file read with contain.read_region (.wkt .geojson .json);
/// 5. an object with `__geo_interface__` (shapely geometries, GeoPandas GeoSeries and
///    GeoDataFrames, geojson objects): by its `wkb` bytes where it has them (shapely, exact and
///    fast), by its geometries' WKB for GeoPandas (geometry.to_wkb(), rows in order, missing
///    geometries skipped), else its interface mapping read as GeoJSON; every Polygon and
///    MultiPolygon of it (features and collections gathered in order), another type raising
///    ContainError;
/// 6. an object whose `geometry` attribute is such an object (a GeoDataFrame row);
/// 7. a GeoJSON mapping (a dict with "type");
/// 8. one ring as a (K, 2) array, or rings as an (R, K, 2) array or a sequence of (K, 2)
///    array-likes: one polygon of those rings (closed paths in the direction written).
/// Coordinates reach the library as the exact doubles of the object (WKB and shapely's floats
/// bit for bit; GeoJSON through shortest round-trip decimals).
[[nodiscard]] MultiPolygon to_region(const py::handle& object, const char* name);

/// True when `object` is of a kind `to_region` takes first-hand (Region, WKB bytes, text, a
/// path with a region extension, __geo_interface__, a GeoJSON mapping). Rings are not
/// recognised here (they could be points): callers decide them by shape.
[[nodiscard]] bool is_region_like(const py::handle& object);

/// A convex region in 3D: a contain.ConvexPolyhedron, a closed convex mesh (anything
/// mesh-like; ConvexPolyhedron::from_mesh checks it exactly), or an (M, 4) array of half-space
/// planes a b c d (inside where a x + b y + c z + d >= 0).
[[nodiscard]] ConvexPolyhedron to_convex_polyhedron(const py::handle& object, const char* name);

/// Half-planes a x + b y + c >= 0: one (3,) or several (M, 3). Finite (ContainError otherwise).
[[nodiscard]] std::vector<HalfPlane> to_half_planes(const py::handle& object, const char* name);
/// Half-spaces a x + b y + c z + d >= 0: one (4,) or several (M, 4). Finite.
[[nodiscard]] std::vector<Plane> to_planes(const py::handle& object, const char* name);
/// A box (min, max) of 2 or 3 numbers each, finite, min <= max on every axis (ContainError
/// otherwise, as the command's exit 3 for an inverted --box).
[[nodiscard]] Box2 to_box2(const py::handle& object, const char* name);
[[nodiscard]] Box3 to_box3(const py::handle& object, const char* name);
/// A convex ring: (K, 2) points, K >= 3, finite.
[[nodiscard]] Ring to_convex_ring(const py::handle& object, const char* name);

/// The region as a shapely geometry (Polygon for one polygon, else MultiPolygon) through WKB;
/// ImportError naming python3-shapely when shapely is missing.
[[nodiscard]] py::object region_to_shapely(const MultiPolygon& region);

/// The region as a GeoJSON mapping {"type": "MultiPolygon", "coordinates": ...} (the doubles
/// exactly): its `__geo_interface__`.
[[nodiscard]] py::dict region_geo_interface(const MultiPolygon& region);

/// "even_odd", "nonzero", "positive", "negative", and "evenodd" (the command's spelling) for
/// even_odd; ValueError naming every accepted word otherwise.
[[nodiscard]] Fill parse_fill(const std::string& fill);
[[nodiscard]] const char* fill_name(Fill fill);

/// A transform: None (identity), 12 numbers in the contract's row order r00 r01 r02 t0 r10 ...,
/// a (3, 4) matrix [R | t] or a (4, 4) matrix whose last row is 0 0 0 1.
[[nodiscard]] Transform to_transform(const py::handle& object, const char* name);

/// Poses, THE rule of every batch that takes transforms (MeshPair.collide,
/// MeshPairDistance, convex pairs, motions): (N, 12) rows in the contract's order, (N, 3, 4) or
/// (N, 4, 4) matrices, or one transform as `to_transform` takes it ((12,), (3, 4), (4, 4)): a
/// batch of one. TypeError / ValueError naming `name` and the accepted shapes; a NaN or infinite
/// pose raises ContainError naming its row, name[i] (or name[i / per_item][i % per_item] when
/// each item is `per_item` consecutive poses, as the two placements of a motion).
[[nodiscard]] std::vector<Transform> to_transforms(const py::handle& object, const char* name,
                                                   py::ssize_t per_item = 1);

/// The `contain.Location` IntEnum member of `location` (created by `make_location_enum`).
[[nodiscard]] py::object location_object(Location location);
/// Creates `contain.Location` (enum.IntEnum: outside = -1, boundary = 0, inside = 1).
void make_location_enum(py::module_& module);

/// The answers of `contains(points, boundary=...)` under the command's --boundary policies:
/// booleans for "inside" (boundary counts as inside), "outside", or "raise" (ContainError naming
/// the first boundary point); for "report" (the command's default) the int8 locations
/// themselves, -1 outside, 0 boundary, 1 inside, as `locate` gives them. ValueError for another
/// word.
[[nodiscard]] py::object under_boundary_policy(std::vector<Location>&& locations,
                                               const std::string& boundary);

/// Checks the policy word before any work is done.
void check_boundary_policy(const std::string& boundary);

/// Adds contain.as_mesh, contain.as_region, contain.is_mesh_like (the rules above, for Python
/// code such as contain.dask) to the module.
void bind_shapes(py::module_& m);

}  // namespace contain::python
