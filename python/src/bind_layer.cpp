// contain.RegionLayer and contain.SolidScene: many shapes at once (a spatial join of points
// against regions with ids, which solids hold each point, every touching pair of solids).

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "arguments.h"
#include "arrays.h"
#include "bindings.h"
#include "contain/collide/mesh_scene.h"
#include "contain/inside/index_file.h"
#include "contain/inside/region_layer.h"
#include "contain/inside/solid_scene.h"
#include "contain/io/index_io.h"
#include "contain/io/layer_io.h"
#include "contain/io/scene_json.h"
#include "errors.h"
#include "shapes.h"

namespace contain::python {
namespace {

using namespace pybind11::literals;

// A layer, the ids of its regions and the fingerprint of the regions (saved with it).
struct Layer {
  inside::RegionLayer index;
  std::vector<std::string> ids;
  std::uint64_t source = 0;

  // The regions prepared under `fill` (the GIL released).
  static Layer prepared(const std::vector<MultiPolygon>& regions, std::vector<std::string> ids,
                        Fill fill) {
    Layer layer{{}, std::move(ids), 0};
    py::gil_scoped_release release;
    layer.index = inside::RegionLayer(regions, {.fill = fill});
    layer.source = inside::fingerprint(regions, fill);
    return layer;
  }
  [[nodiscard]] std::vector<std::byte> bytes() const {
    return inside::format_index(index, source, ids);
  }
  static Layer from(inside::SavedRegionLayer saved) {
    std::vector<std::string> ids = std::move(saved.ids);
    if (ids.empty()) {
      for (std::size_t r = 0; r < saved.layer.size(); ++r)
        ids.push_back(std::to_string(r));
    }
    return {std::move(saved.layer), std::move(ids), saved.source};
  }
};

// A scene: its meshes (each distinct mesh once), objects and ids; the two prepared forms are
// built on first use (a user may only ever ask one of the two questions).
struct Scene {
  std::vector<Mesh> meshes;
  std::vector<inside::SceneObject> objects;
  std::vector<std::string> ids;
  mutable std::once_flag inside_once, collide_once;
  mutable std::unique_ptr<inside::SolidScene> inside;
  mutable std::unique_ptr<collide::MeshScene> collide;

  const inside::SolidScene& solids() const {
    std::call_once(inside_once, [&] {
      py::gil_scoped_release release;
      inside = std::make_unique<inside::SolidScene>(meshes, objects);
    });
    return *inside;
  }
  const collide::MeshScene& pairs() const {
    std::call_once(collide_once, [&] {
      py::gil_scoped_release release;
      collide = std::make_unique<collide::MeshScene>(meshes, objects);
    });
    return *collide;
  }
};

std::vector<std::string> positions(std::size_t n) {
  std::vector<std::string> ids;
  ids.reserve(n);
  for (std::size_t k = 0; k < n; ++k)
    ids.push_back(std::to_string(k));
  return ids;
}

std::vector<std::string> ids_or_positions(const std::optional<std::vector<std::string>>& ids,
                                          std::size_t n, const char* what) {
  if (!ids) return positions(n);
  if (ids->size() != n) {
    throw py::value_error(std::string("ids: expected ") + std::to_string(n) + " (one per " + what +
                          "), got " + std::to_string(ids->size()));
  }
  return *ids;
}

// The (point, shape) pairs of a table as a (2, M) int64 array, and their locations (int8),
// keeping only the holders that `keep` accepts.
template <class Keep>
std::pair<py::array_t<std::int64_t>, py::array_t<std::int8_t>> pair_arrays(
    const inside::HolderTable& table, Keep&& keep) {
  std::size_t m = 0;
  for (const inside::Holder& h : table.holders)
    m += keep(h.location) ? 1 : 0;
  py::array_t<std::int64_t> pairs({py::ssize_t{2}, static_cast<py::ssize_t>(m)});
  py::array_t<std::int8_t> where(static_cast<py::ssize_t>(m));
  std::int64_t* first = pairs.mutable_data();  // row 0, then row 1 (C order)
  std::int64_t* second = first + m;
  std::int8_t* location = where.mutable_data();
  {
    py::gil_scoped_release release;
    std::size_t k = 0;
    for (std::size_t i = 0; i < table.points(); ++i) {
      for (const inside::Holder& h : table.of(i)) {
        if (!keep(h.location)) continue;
        first[k] = static_cast<std::int64_t>(i);
        second[k] = h.shape;
        location[k] = static_cast<std::int8_t>(h.location);
        ++k;
      }
    }
  }
  return {pairs, where};
}

// `boundary`: 'inside' keeps every holder, 'outside' only those holding the point inside,
// 'raise' raises at the first boundary point.
py::array_t<std::int64_t> query_pairs(const inside::HolderTable& table,
                                      const std::string& boundary) {
  if (boundary == "raise") {
    for (std::size_t i = 0; i < table.points(); ++i) {
      for (const inside::Holder& h : table.of(i)) {
        if (h.location == Location::boundary) {
          fail(ErrorKind::invalid_value, "point " + std::to_string(i) +
                                             " lies on the boundary of shape " +
                                             std::to_string(h.shape) + " (boundary='raise')");
        }
      }
    }
  }
  if (boundary == "outside") {
    return pair_arrays(table, [](Location l) { return l == Location::inside; }).first;
  }
  return pair_arrays(table, [](Location) { return true; }).first;
}

void check_policy(const std::string& boundary) {
  if (boundary != "inside" && boundary != "outside" && boundary != "raise" &&
      boundary != "report") {
    throw py::value_error("boundary must be 'inside', 'outside', 'raise' or 'report', got '" +
                          boundary + "'");
  }
}

// locate's answer: the pairs, or for 'report' (the command's default `--boundary report`, whose
// `ID:on` marks a boundary holder) the pairs with their locations, as holders() gives them.
py::object located(const inside::HolderTable& table, const std::string& boundary) {
  if (boundary == "report") return py::cast(pair_arrays(table, [](Location) { return true; }));
  return query_pairs(table, boundary);
}

template <class Index, class Point>
inside::HolderTable locate_table(const Index& index, const py::handle& points, int columns,
                                 int threads) {
  const Doubles array = as_matrix(points, columns, "points");
  require_finite(array, "points", threads);
  std::span<const Point> span;
  if constexpr (std::is_same_v<Point, Vec2>) {
    span = as_vec2(array);
  } else {
    span = as_vec3(array);
  }
  py::gil_scoped_release release;
  return index.locate(span, BatchOptions{.threads = threads});
}

py::tuple refuse_pickle(const py::handle& self) {
  throw py::type_error(std::string(py::str(py::type::of(self).attr("__name__"))) +
                       " is not picklable: ship its source (a file path, or the regions / "
                       "meshes themselves) and build it where it is used, as contain.dask does");
}

constexpr const char* kLocateDoc = R"doc(
The (point, shape) pairs where the shape holds the point, as shapely's STRtree.query returns
them: an int64 array of shape (2, M), row 0 the point numbers, row 1 the shape numbers (index
into ids), sorted by point then shape. Exact on the given doubles.

points: (N, {dim}) array of real numbers (a C-contiguous float64 array is read in place).
boundary: what a point exactly on a shape's boundary gives: 'inside' (the pair is kept, as
    predicate='intersects' / 'covered_by'), 'outside' (left out, as 'within'), 'raise'
    (ContainError naming the first such point), or 'report' (the command's default
    --boundary report, whose ID:on marks such a holder): the tuple (pairs, location) of
    holders(), location 1 inside, 0 on the boundary, for each pair of 'inside'.
threads: threads for the batch (0: every core); the answer does not depend on it.
)doc";

constexpr const char* kHoldersDoc = R"doc(
Every (point, shape) pair where the shape holds the point, with where it lies: a tuple
(pairs, location): pairs as locate() returns them (boundary points included), location an
int8 array of shape (M,), 1 inside, 0 on the boundary (contain.Location values).
)doc";

std::string with_dim(const char* doc, const char* dim) {
  std::string s = doc;
  return s.replace(s.find("{dim}"), 5, dim);
}

}  // namespace

void bind_layer(py::module_& m) {
  static const std::string locate2 = with_dim(kLocateDoc, "2");
  static const std::string locate3 = with_dim(kLocateDoc, "3");

  py::class_<Layer>(m, "RegionLayer", R"doc(
Many 2D regions, each with an id, prepared once for exact point location: for each point the
regions that hold it (a spatial join of points against polygons).

Every region is answered exactly as alone (contain.PolygonIndex under the layer's fill rule):
a point on an edge shared by two neighbouring regions is held by both (on their boundaries), a
point inside two overlapping regions by both, a point in a hole by none (unless a region fills
it). A tree over the regions' boxes sends each point only to the regions near it.

Build: RegionLayer(regions, ids=None, fill='even_odd') with a sequence of regions (each a
contain.Region, a WKT string or a sequence of (K, 2) rings), or RegionLayer.from_file(source,
id=None, layer_name=None) for a .wkt layer (one shape a line), a GeoJSON FeatureCollection, or
(with GDAL) a Shapefile, GeoPackage, FlatGeobuf or 'PG:...' PostGIS table.
Query: locate(points, boundary='inside') -> (2, M) int64 pairs as shapely's STRtree.query;
holders(points) -> (pairs, location). contain.layers.sjoin joins GeoDataFrames.

Example:
    >>> layer = contain.RegionLayer(["POLYGON ((0 0, 1 0, 1 1, 0 1))",
    ...                              "POLYGON ((1 0, 2 0, 2 1, 1 1))"], ids=["a", "b"])
    >>> layer.locate([[0.5, 0.5], [1, 0.5], [5, 5]])
    array([[0, 1, 1],
           [0, 0, 1]])
)doc")
      .def(py::init([](const py::sequence& regions, std::optional<std::vector<std::string>> ids,
                       const std::string& fill) {
             std::vector<MultiPolygon> polygons;
             polygons.reserve(py::len(regions));
             for (const py::handle region : regions)
               polygons.push_back(to_region(region, "regions[k]"));
             const Fill rule = parse_fill(fill);
             return Layer::prepared(polygons, ids_or_positions(ids, polygons.size(), "region"),
                                    rule);
           }),
           "regions"_a, "ids"_a = py::none(), py::kw_only(), "fill"_a = "even_odd",
           "Prepares the regions (each a Region, WKT string or sequence of rings); ids: one\n"
           "string per region (default: positions '0', '1', ...).")
      .def_static(
          "from_file",
          [](const std::string& source, std::optional<std::string> id,
             std::optional<std::string> layer_name, const std::string& fill) {
            const Fill rule = parse_fill(fill);
            Result<io::Layer> result = [&] {
              py::gil_scoped_release release;
              return io::read_layer(source,
                                    {.id = id.value_or(""), .layer_name = layer_name.value_or("")});
            }();
            io::Layer read = take(std::move(result));
            // What OGC would not accept, read anyway: as the command warns on stderr.
            for (const std::string& warning : read.warnings) {
              if (PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 1) != 0) {
                throw py::error_already_set();
              }
            }
            return Layer::prepared(read.regions, std::move(read.ids), rule);
          },
          "source"_a, "id"_a = py::none(), "layer_name"_a = py::none(), py::kw_only(),
          "fill"_a = "even_odd", R"doc(
Reads a layer: a .wkt file (one POLYGON/MULTIPOLYGON a line), a .geojson FeatureCollection, or
with GDAL any vector source (.shp, .gpkg, .fgb, 'PG:dbname=... host=...'). id: the attribute
holding the ids (default: GeoJSON feature ids, else positions); layer_name: the layer (table)
of a source holding several. Coordinates are the doubles of the file.
)doc")
      .def_static(
          "parse",
          [](const std::string& text, const std::string& format, std::optional<std::string> id,
             const std::string& fill) {
            const Fill rule = parse_fill(fill);
            if (format != "geojson" && format != "wkt") {
              throw py::value_error("format must be 'geojson' or 'wkt', got '" + format + "'");
            }
            const io::LayerOptions options{.id = id.value_or("")};
            Result<io::Layer> result = [&] {
              py::gil_scoped_release release;
              return format == "wkt" ? io::parse_wkt_layer(text, "<wkt>", options)
                                     : io::parse_geojson_layer(text, "<geojson>", options);
            }();
            io::Layer read = take(std::move(result));
            return Layer::prepared(read.regions, std::move(read.ids), rule);
          },
          "text"_a, "format"_a, "id"_a = py::none(), py::kw_only(), "fill"_a = "even_odd",
          "Parses a layer from text: format 'geojson' (a FeatureCollection) or 'wkt' (one\n"
          "POLYGON/MULTIPOLYGON a line); id as in from_file.")
      .def(
          "locate",
          [](const Layer& layer, const ArrayLike& points, const std::string& boundary,
             int threads) {
            check_policy(boundary);
            return located(
                locate_table<inside::RegionLayer, Vec2>(layer.index, points.object, 2, threads),
                boundary);
          },
          "points"_a, py::kw_only(), "boundary"_a = "inside", "threads"_a = 0, locate2.c_str())
      .def(
          "holders",
          [](const Layer& layer, const ArrayLike& points, int threads) {
            auto table =
                locate_table<inside::RegionLayer, Vec2>(layer.index, points.object, 2, threads);
            return pair_arrays(table, [](Location) { return true; });
          },
          "points"_a, py::kw_only(), "threads"_a = 0, kHoldersDoc)
      .def_property_readonly(
          "ids", [](const Layer& layer) { return layer.ids; },
          "The id of each region, in order (a list of str).")
      .def_property_readonly(
          "fill", [](const Layer& layer) { return fill_name(layer.index.fill()); },
          "The fill rule of every region.")
      .def_property_readonly(
          "stats",
          [](const Layer& layer) {
            const auto s = layer.index.stats();
            return py::dict("regions"_a = s.regions, "edges"_a = s.edges, "cells"_a = s.cells,
                            "edge_refs"_a = s.edge_refs, "tree_nodes"_a = s.tree_nodes,
                            "bytes"_a = s.bytes);
          },
          "Sizes of the structure (regions, edges, cells, edge_refs, tree_nodes, bytes).")
      .def("__len__", [](const Layer& layer) { return layer.index.size(); })
      .def(
          "save",
          [](const Layer& layer, const std::filesystem::path& path) {
            (void)take(io::write_index(layer.bytes(), path.string()));
          },
          "path"_a,
          "Writes the prepared layer and its ids to a file (docs/index-files.md);\n"
          "RegionLayer.load reads it back, as does 'contain inside --index'.")
      .def_static(
          "load",
          [](const std::filesystem::path& path) {
            auto loaded = [&] {
              py::gil_scoped_release release;
              return io::read_region_layer_index(path.string());
            }();
            return Layer::from(take(std::move(loaded)));
          },
          "path"_a,
          "Reads a layer that save() (or 'contain index build --layer') wrote, every field\n"
          "checked: it answers exactly as the layer that was saved. A damaged, truncated or\n"
          "foreign file raises ContainError naming the file.")
      .def(py::pickle(
          [](const Layer& layer) {
            const std::vector<std::byte> bytes = layer.bytes();
            return py::make_tuple(
                py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
          },
          [](const py::tuple& state) {
            if (state.size() != 1) throw py::value_error("contain.RegionLayer: bad pickle state");
            const std::string bytes = state[0].cast<std::string>();
            return Layer::from(take(inside::parse_region_layer(std::as_bytes(std::span(bytes)))));
          }))
      .def("__repr__", [](const Layer& layer) {
        return "contain.RegionLayer(" + std::to_string(layer.index.size()) + " regions, " +
               std::to_string(layer.index.stats().edges) + " edges, fill='" +
               fill_name(layer.index.fill()) + "')";
      });

  py::class_<Scene>(m, "SolidScene", R"doc(
A scene of solids: meshes placed by transforms, each object with an id. Answers which objects
hold each point (locate, holders) and which objects touch or overlap (pairs), exactly, with the
semantics of contain.MeshIndex and contain.collide: closed meshes bound solids (closed sets:
touching and nesting count), other meshes are surfaces.

Build: SolidScene(meshes, transforms=None, ids=None) with one mesh per object, each any mesh
the module takes (contain.Mesh, a path, a trimesh or Open3D mesh, a (vertices, faces) pair:
the rule of contain.as_mesh; pass the same object several times to share it), or SolidScene.from_file(path) for the scene
JSON of `contain collide --scene`.

Example:
    >>> cube = contain.read_mesh("cube.obj")
    >>> scene = contain.SolidScene([cube, cube], [None, [1,0,0,1, 0,1,0,0, 0,0,1,0]], ids=["a", "b"])
    >>> scene.pairs()          # they share a face
    array([[0],
           [1]])
)doc")
      .def(py::init([](const py::sequence& meshes, const py::object& transforms,
                       std::optional<std::vector<std::string>> ids) {
             auto scene = std::make_unique<Scene>();
             const std::size_t n = py::len(meshes);
             // The same Python object given twice (a contain.Mesh, a trimesh, a path, ...) is
             // one mesh, converted and prepared once.
             std::vector<PyObject*> seen;
             for (const py::handle mesh : meshes) {
               std::int32_t index = -1;
               for (std::size_t k = 0; k < seen.size(); ++k) {
                 if (seen[k] == mesh.ptr()) index = static_cast<std::int32_t>(k);
               }
               if (index < 0) {
                 index = static_cast<std::int32_t>(seen.size());
                 seen.push_back(mesh.ptr());
                 scene->meshes.push_back(*to_mesh(mesh, "meshes[k]"));
               }
               scene->objects.push_back({index, Transform{}});
             }
             if (!transforms.is_none()) {
               const py::sequence list = transforms.cast<py::sequence>();
               if (py::len(list) != n) {
                 throw py::value_error("transforms: expected " + std::to_string(n) +
                                       " (one per mesh), got " + std::to_string(py::len(list)));
               }
               for (std::size_t k = 0; k < n; ++k)
                 scene->objects[k].transform = to_transform(list[k], "transforms[k]");
             }
             scene->ids = ids_or_positions(ids, n, "object");
             return scene;
           }),
           "meshes"_a, "transforms"_a = py::none(), "ids"_a = py::none(),
           "One mesh per object (as contain.as_mesh takes it); transforms: None or one per object "
           "(None, 12 numbers,\n"
           "(3, 4) or (4, 4)); ids: one string per object (default: positions).")
      .def_static(
          "from_file",
          [](const std::filesystem::path& path) {
            io::Scene read = take(io::read_scene_json(path));
            auto scene = std::make_unique<Scene>();
            scene->meshes = std::move(read.meshes);
            for (std::size_t k = 0; k < read.mesh_of.size(); ++k)
              scene->objects.push_back({read.mesh_of[k], read.transforms[k]});
            scene->ids = std::move(read.ids);
            return scene;
          },
          "path"_a,
          "Reads the scene JSON of `contain collide --scene` ({\"objects\": [{\"id\", \"mesh\",\n"
          "\"transform\"}]}; mesh paths relative to the file).")
      .def(
          "locate",
          [](const Scene& scene, const ArrayLike& points, const std::string& boundary,
             int threads) {
            check_policy(boundary);
            return located(
                locate_table<inside::SolidScene, Vec3>(scene.solids(), points.object, 3, threads),
                boundary);
          },
          "points"_a, py::kw_only(), "boundary"_a = "inside", "threads"_a = 0, locate3.c_str())
      .def(
          "holders",
          [](const Scene& scene, const ArrayLike& points, int threads) {
            auto table =
                locate_table<inside::SolidScene, Vec3>(scene.solids(), points.object, 3, threads);
            return pair_arrays(table, [](Location) { return true; });
          },
          "points"_a, py::kw_only(), "threads"_a = 0, kHoldersDoc)
      .def(
          "pairs",
          [](const Scene& scene, int threads) {
            const collide::MeshScene& prepared = scene.pairs();
            std::vector<collide::ScenePair> found;
            {
              py::gil_scoped_release release;
              found = prepared.pairs({.threads = threads});
            }
            py::array_t<std::int64_t> out({py::ssize_t{2}, static_cast<py::ssize_t>(found.size())});
            std::int64_t* a = out.mutable_data();
            for (std::size_t k = 0; k < found.size(); ++k) {
              a[k] = found[k].a;
              a[found.size() + k] = found[k].b;
            }
            return out;
          },
          py::kw_only(), "threads"_a = 0, R"doc(
Every pair of objects that intersect (touching and nesting count for solids), as a (2, K)
int64 array of object numbers (a < b), sorted: the answer of `contain collide --scene`.
threads: candidate pairs tested on this many threads (0: every core).
)doc")
      .def(
          "contacts",
          [](const Scene& scene, int threads) {
            const collide::MeshScene& prepared = scene.pairs();
            std::vector<collide::ScenePair> found;
            {
              py::gil_scoped_release release;
              found = prepared.pairs({.threads = threads});
            }
            py::list out;
            for (const collide::ScenePair& p : found) {
              out.append(py::make_tuple(p.a, p.b, p.contact));
            }
            return out;
          },
          py::kw_only(), "threads"_a = 0,
          "The intersecting pairs with their witnesses: a list of (a, b, contain.Contact).")
      .def_property_readonly(
          "ids", [](const Scene& scene) { return scene.ids; }, "The id of each object.")
      .def("__len__", [](const Scene& scene) { return scene.objects.size(); })
      .def("__reduce__", &refuse_pickle)
      .def("__repr__", [](const Scene& scene) {
        return "contain.SolidScene(" + std::to_string(scene.objects.size()) + " objects, " +
               std::to_string(scene.meshes.size()) + " meshes)";
      });
}

}  // namespace contain::python
