"""Classify Dask arrays and dataframes of points against a mesh or a region, past one machine.

    >>> from distributed import Client
    >>> import dask.array as da, contain.dask
    >>> client = Client("tcp://scheduler:8786")          # or Client(LocalCluster(...))
    >>> points = da.from_zarr("survey.zarr")              # (N, 3) float64, chunked by rows
    >>> answers = contain.dask.locate(points, "/data/building.obj")   # (N,) int8, lazy
    >>> (answers == contain.Location.inside).sum().compute()

What travels to the workers is a small, picklable `Shape`: the mesh or region file's path
(each worker reads the file itself: it must see the same path, e.g. a shared file system), or
its bytes (a `contain.Mesh`, a `contain.Region`, WKT text or `Shape.from_bytes`), placed in the
task graph once as one key, so that every worker fetches it once. A built index is never
pickled. Each worker process builds the prepared index (`contain.MeshIndex` or
`contain.PolygonIndex`) on its first chunk and keeps it in a module-level cache keyed by the
shape's key (the path with its size and modification time, or the SHA-256 of the bytes), so
later chunks, and later computations on the same shape, reuse it: one build per worker process,
not one per chunk. `index_builds()` counts the builds in the calling process
(`client.run(contain.dask.index_builds)` asks every worker).

Each chunk is classified on `threads` threads (default 1): Dask's workers supply the
parallelism, one chunk per worker thread, so a cluster of one-thread worker processes uses
each core once. With threads=0 a chunk uses every core of its machine (for one worker process
per machine with one thread).
"""

from __future__ import annotations

import hashlib
import json
import os
import threading
from collections import OrderedDict
from dataclasses import dataclass
from typing import Any, Optional, Sequence, Union

import numpy as np

import contain

__all__ = ["Shape", "locate", "locate_dataframe", "index_builds", "clear_cache", "LayerSource", "join_layer"]

_REGION_SUFFIXES = (".wkt", ".geojson", ".json")
_MESH_SUFFIXES = (".obj", ".off", ".stl", ".ply")
_CSG_KEYS = ("union", "intersection", "difference", "complement", "sphere", "box", "halfspace",
             "convex", "implicit", "mesh")


def _is_path_text(text: str) -> bool:
    """A str names a file when it ends in a mesh or region extension and is no WKT or JSON."""
    suffix = os.path.splitext(text)[1].lower()
    return suffix in _REGION_SUFFIXES + _MESH_SUFFIXES and "(" not in text and "{" not in text


@dataclass(frozen=True)
class Shape:
    """A mesh or region as it travels to the workers: a file path or bytes, never an index.

    kind: 'mesh' or 'csg' (3D points) or 'region' (2D points).
    key: what the worker cache is keyed by: 'path:<absolute path>:<size>:<mtime ns>' for a
        file (a changed file gets a new key), 'sha256:<hex>' for bytes.
    path / data: exactly one is set. format: the mesh format of `data` ('ply', 'obj', 'off',
        'stl'); WKT for a region's bytes. fill: the fill rule of a region.
    """

    kind: str
    key: str
    path: Optional[str] = None
    data: Optional[bytes] = None
    format: Optional[str] = None
    fill: str = "even_odd"

    @staticmethod
    def from_path(path: Union[str, os.PathLike], *, fill: str = "even_odd") -> "Shape":
        """A mesh file (.obj .off .stl .ply) or a region file (.wkt .geojson .json) by path.

        Workers open the path themselves. The key holds the size and modification time seen
        here when the file exists on this machine, else the path alone.
        """
        text = os.path.abspath(os.fspath(path))
        kind = "region" if text.lower().endswith(_REGION_SUFFIXES) else "mesh"
        try:
            stat = os.stat(text)
            key = f"path:{text}:{stat.st_size}:{stat.st_mtime_ns}"
        except OSError:
            key = f"path:{text}"
        if kind == "region":
            key += f":{fill}"
        return Shape(kind=kind, key=key, path=text, fill=fill)

    @staticmethod
    def from_bytes(data: bytes, format: str, *, fill: str = "even_odd") -> "Shape":
        """Mesh bytes in `format` ('ply', 'obj', 'off', 'stl'), or region WKT with format='wkt'."""
        data = bytes(data)
        kind = "region" if format == "wkt" else "mesh"
        key = "sha256:" + hashlib.sha256(data).hexdigest()
        if kind == "region":
            key += f":{fill}"
        return Shape(kind=kind, key=key, data=data, format=format, fill=fill)

    @staticmethod
    def csg(tree: Any) -> "Shape":
        """A CSG solid in the JSON form of `contain inside --csg`: a dict or JSON text (sent as
        bytes), or a .json file path (each worker reads it; mesh leaves relative to it).

        A tree built with contain.Csg helpers cannot travel (it may hold Python functions):
        give its JSON form. Each worker prepares one contain.CsgSolid.
        """
        if isinstance(tree, os.PathLike) or (isinstance(tree, str) and not tree.lstrip().startswith("{")):
            text = os.path.abspath(os.fspath(tree))
            try:
                stat = os.stat(text)
                key = f"csg:path:{text}:{stat.st_size}:{stat.st_mtime_ns}"
            except OSError:
                key = f"csg:path:{text}"
            return Shape(kind="csg", key=key, path=text, format="csg")
        data = (tree if isinstance(tree, str) else json.dumps(tree)).encode()
        contain.Csg.from_json(data.decode())  # refuse a malformed tree here, not on the workers
        return Shape(kind="csg", key="csg:sha256:" + hashlib.sha256(data).hexdigest(), data=data,
                     format="csg")

    @staticmethod
    def of(shape: Any, *, fill: str = "even_odd") -> "Shape":
        """A Shape from anything contain takes as a mesh or a region.

        A path (a str with a mesh or region file extension, or an os.PathLike such as
        pathlib.Path) travels as the path. Anything else goes through the module's one rule
        (contain.as_mesh / contain.as_region) and travels as bytes: a mesh (contain.Mesh,
        (vertices, faces), trimesh or Open3D meshes) as binary PLY, bit for bit; a region
        (contain.Region, WKT / GeoJSON / WKB text or bytes, shapely geometries, GeoPandas
        objects, rings) as WKT with shortest round-trip decimals, also exact. A dict of the CSG
        JSON form ({"difference": [...]}, ...) travels as its JSON (see Shape.csg).
        """
        if isinstance(shape, Shape):
            return shape
        if isinstance(shape, dict) and len(shape) == 1 and next(iter(shape)) in _CSG_KEYS:
            return Shape.csg(shape)
        if isinstance(shape, os.PathLike) or (isinstance(shape, str) and _is_path_text(shape)):
            return Shape.from_path(shape, fill=fill)
        if contain.is_mesh_like(shape):
            # Binary PLY stores the doubles: the workers get the mesh bit for bit.
            return Shape.from_bytes(contain.format_mesh(contain.as_mesh(shape), "ply"), "ply")
        try:
            region = contain.as_region(shape)
        except TypeError:
            raise TypeError(
                "shape must be a path, a mesh (contain.Mesh, (vertices, faces), trimesh, Open3D) "
                "or a region (contain.Region, WKT, GeoJSON, WKB, shapely, GeoPandas, rings), "
                "or a CSG tree's JSON form (a dict, or Shape.csg), "
                f"got {type(shape).__name__}"
            ) from None
        return Shape.from_bytes(region.to_wkt().encode(), "wkt", fill=fill)

    @property
    def dimension(self) -> int:
        """3 for a mesh or a CSG solid, 2 for a region."""
        return 2 if self.kind == "region" else 3

    def build(self) -> Any:
        """The prepared object (MeshIndex, PolygonIndex or CsgSolid): built once per worker."""
        if self.kind == "csg":
            return contain.CsgSolid(self.path if self.path is not None else self.data.decode())
        if self.kind == "mesh":
            if self.path is not None:
                return contain.MeshIndex.from_file(self.path)
            return contain.MeshIndex(contain.parse_mesh(self.data, self.format, "<mesh bytes>"))
        if self.path is not None:
            return contain.PolygonIndex.from_file(self.path, fill=self.fill)
        return contain.PolygonIndex(contain.parse_wkt(self.data.decode(), "<wkt>"), fill=self.fill)

    def __repr__(self) -> str:
        where = self.path if self.path is not None else f"{len(self.data or b'')} bytes"
        return f"contain.dask.Shape({self.kind}, {where})"


# The worker-side cache: one prepared index per shape key and process. A few shapes at most
# are in use at once; the oldest is dropped past _CACHE_SIZE.
_CACHE_SIZE = 8
_lock = threading.Lock()
_indexes: "OrderedDict[str, Any]" = OrderedDict()
_builds: "dict[str, int]" = {}


def _index(shape: Shape) -> Any:
    index = _indexes.get(shape.key)
    if index is not None:
        return index
    with _lock:  # several worker threads: still one build
        index = _indexes.get(shape.key)
        if index is None:
            index = shape.build()
            _indexes[shape.key] = index
            _builds[shape.key] = _builds.get(shape.key, 0) + 1
            while len(_indexes) > _CACHE_SIZE:
                _indexes.popitem(last=False)
        return index


def index_builds(key: Optional[str] = None) -> int:
    """How many indexes this process has built (for `key` only, when given).

    On a cluster: client.run(contain.dask.index_builds) -> {worker address: count}.
    """
    if key is not None:
        return _builds.get(key, 0)
    return sum(_builds.values())


def clear_cache() -> None:
    """Drops this process's cached indexes and build counts."""
    with _lock:
        _indexes.clear()
        _builds.clear()


def _classify(points: np.ndarray, shape: Shape, boundary: Optional[str], threads: int) -> np.ndarray:
    index = _index(shape)
    if boundary is None or boundary == "report":
        return index.locate(points, threads=threads)
    return index.contains(points, boundary=boundary, threads=threads)


def _locate_block(block: np.ndarray, shape: Shape, boundary: Optional[str], threads: int) -> np.ndarray:
    return _classify(block, shape, boundary, threads)


def _check_boundary(boundary: Optional[str]) -> None:
    if boundary not in (None, "report", "inside", "outside", "raise"):
        raise ValueError(f"boundary must be None or 'report' (int8 locations), 'inside', 'outside' or 'raise', got {boundary!r}")


def locate(
    points: Any,
    shape: Any,
    *,
    fill: str = "even_odd",
    boundary: Optional[str] = None,
    threads: int = 1,
) -> Any:
    """Classifies a Dask array of points against a mesh or a region, chunk by chunk.

    points: a dask.array (or anything dask.array.asarray takes) of shape (N, 3) for a mesh or
        (N, 2) for a region, chunked along the rows (column chunks are merged).
    shape: a mesh or region file path (str or pathlib.Path), anything contain takes as a mesh
        or a region (contain.Mesh, (vertices, faces), trimesh, shapely, GeoPandas, WKT, ...:
        see Shape.of), a CSG tree's JSON form (a dict; Shape.csg for text and files) or a
        Shape. Only the path or the bytes are sent to the workers; each worker process builds
        the index once (see the module documentation).
    fill: the fill rule of a region ('even_odd' or 'evenodd', 'nonzero', 'positive', 'negative').
    boundary: None or 'report' (the command's word) gives int8 answers (-1 outside, 0 boundary, 1 inside); 'inside',
        'outside' or 'raise' give booleans under that boundary policy.
    threads: threads per chunk (default 1: the workers supply the parallelism).

    Returns a lazy dask array of shape (N,), chunked like the rows of `points`; the answers
    equal contain.MeshIndex(...).locate(points) on one machine.
    """
    import dask
    import dask.array as da
    from dask.base import tokenize

    _check_boundary(boundary)
    source = Shape.of(shape, fill=fill)
    array = da.asarray(points)
    if array.ndim != 2 or array.shape[1] != source.dimension:
        raise ValueError(
            f"points must have shape (N, {source.dimension}) for a {source.kind}, got {array.shape}"
        )
    if array.numblocks[1] != 1:
        array = array.rechunk({1: -1})
    dtype = np.dtype(np.int8 if boundary in (None, "report") else bool)
    # One graph key holds the shape; every chunk depends on it, so it travels once per worker.
    shape_key = dask.delayed(source, pure=True)
    return da.map_blocks(
        _locate_block,
        array,
        shape_key,
        boundary,
        threads,
        dtype=dtype,
        drop_axis=1,
        meta=np.empty((0,), dtype=dtype),
        # Deterministic, so the same request is the same graph (and two requests never clash).
        name="contain-locate-" + tokenize(array.name, source.key, boundary, threads),
    )


def _locate_partition(
    frame: Any, shape: Shape, columns: Sequence[str], boundary: Optional[str], threads: int, name: str
) -> Any:
    import pandas as pd

    points = np.ascontiguousarray(frame[list(columns)].to_numpy(dtype=np.float64))
    return pd.Series(_classify(points, shape, boundary, threads), index=frame.index, name=name)


def locate_dataframe(
    frame: Any,
    shape: Any,
    *,
    columns: Optional[Sequence[str]] = None,
    fill: str = "even_odd",
    boundary: Optional[str] = None,
    threads: int = 1,
    name: str = "location",
) -> Any:
    """Classifies the rows of a Dask dataframe of coordinates, partition by partition.

    frame: a dask.dataframe with columns x, y[, z] (or `columns`, in that order).
    shape, fill, boundary, threads: as in locate().
    name: the name of the result.

    Returns a lazy dask Series aligned with `frame` (same index and partitions): int8 answers
    or booleans under `boundary`. Add it with frame.assign(location=...).
    """
    import dask
    import pandas as pd

    _check_boundary(boundary)
    source = Shape.of(shape, fill=fill)
    if columns is None:
        columns = ("x", "y", "z")[: source.dimension]
    columns = list(columns)
    if len(columns) != source.dimension:
        raise ValueError(f"a {source.kind} needs {source.dimension} coordinate columns, got {columns}")
    missing = [c for c in columns if c not in frame.columns]
    if missing:
        raise ValueError(f"the dataframe has no column {missing[0]!r} (columns: {list(frame.columns)})")
    dtype = np.dtype(np.int8 if boundary in (None, "report") else bool)
    return frame.map_partitions(
        _locate_partition,
        dask.delayed(source, pure=True),
        columns,
        boundary,
        threads,
        name,
        meta=pd.Series([], dtype=dtype, name=name),
    )


# ---- Spatial joins: points against a layer of regions (contain.RegionLayer) -------------------
#
# The layer travels like a Shape: as its source (a path or a PG: connection string that every
# worker can open, with the id attribute and the layer name) or as bytes (GeoJSON or WKT
# lines), one key of the graph that every partition depends on, so each worker fetches it once
# and builds the RegionLayer once (the same per-process cache as the indexes above).


@dataclass(frozen=True)
class LayerSource:
    """A layer as it travels to the workers: a path / connection string, or bytes.

    key: the worker cache key ('layer:path:<path>:<size>:<mtime>' for a file, 'layer:<source>'
        for a database, 'layer:sha256:<hex>' for bytes), with the id, layer name and fill.
    format: for bytes, 'geojson' (a FeatureCollection) or 'wkt' (one shape a line).
    """

    key: str
    path: Optional[str] = None
    data: Optional[bytes] = None
    format: Optional[str] = None
    id: Optional[str] = None
    layer_name: Optional[str] = None
    fill: str = "even_odd"

    @staticmethod
    def from_path(
        path: Union[str, os.PathLike], *, id: Optional[str] = None, layer_name: Optional[str] = None, fill: str = "even_odd"
    ) -> "LayerSource":
        """A layer file (.wkt, .geojson, or any GDAL vector format) or a 'PG:...' string."""
        text = os.fspath(path)
        if text.upper().startswith("PG:"):
            key = f"layer:{text}"
        else:
            text = os.path.abspath(text)
            try:
                stat = os.stat(text)
                key = f"layer:path:{text}:{stat.st_size}:{stat.st_mtime_ns}"
            except OSError:
                key = f"layer:path:{text}"
        key += f":{id}:{layer_name}:{fill}"
        return LayerSource(key=key, path=text, id=id, layer_name=layer_name, fill=fill)

    @staticmethod
    def from_bytes(data: bytes, format: str, *, id: Optional[str] = None, fill: str = "even_odd") -> "LayerSource":
        """GeoJSON (format='geojson') or WKT lines (format='wkt') as bytes."""
        if format not in ("geojson", "wkt"):
            raise ValueError(f"format must be 'geojson' or 'wkt', got {format!r}")
        data = bytes(data)
        key = f"layer:sha256:{hashlib.sha256(data).hexdigest()}:{format}:{id}:{fill}"
        return LayerSource(key=key, data=data, format=format, id=id, fill=fill)

    @staticmethod
    def of(
        layer: Any, *, id: Optional[str] = None, layer_name: Optional[str] = None, fill: str = "even_odd"
    ) -> "LayerSource":
        """A LayerSource from a LayerSource, a path or connection string, or a GeoDataFrame.

        A GeoDataFrame travels as GeoJSON (its coordinates written as the shortest decimals that
        read back as the same doubles); its ids are the `id` column, else its index labels.
        """
        if isinstance(layer, LayerSource):
            return layer
        if isinstance(layer, (str, os.PathLike)):
            return LayerSource.from_path(layer, id=id, layer_name=layer_name, fill=fill)
        if hasattr(layer, "geometry") and hasattr(layer, "to_json"):
            frame = layer[[id, layer.geometry.name]] if id is not None else layer[[layer.geometry.name]]
            text = frame.to_json(na="null", drop_id=False)
            return LayerSource.from_bytes(text.encode(), "geojson", id=id, fill=fill)
        raise TypeError(
            f"layer must be a path, a 'PG:...' string, a GeoDataFrame or a LayerSource, got {type(layer).__name__}"
        )

    @property
    def dimension(self) -> int:
        return 2

    def build(self) -> Any:
        """The contain.RegionLayer: what each worker builds once."""
        if self.path is not None:
            return contain.RegionLayer.from_file(self.path, self.id, self.layer_name, fill=self.fill)
        return contain.RegionLayer.parse(self.data.decode(), self.format, self.id, fill=self.fill)

    def __repr__(self) -> str:
        where = self.path if self.path is not None else f"{len(self.data or b'')} bytes of {self.format}"
        return f"contain.dask.LayerSource({where})"


def _join_pairs(points: np.ndarray, source: LayerSource, boundary: str, threads: int) -> Any:
    """The layer, its (2, M) pairs and, for boundary='report', their int8 locations (else None)."""
    layer = _index(source)
    if boundary == "report":
        pairs, where = layer.holders(points, threads=threads)
        return layer, pairs, where
    return layer, layer.locate(points, boundary=boundary, threads=threads), None


def _join_frame(labels: Any, points: np.ndarray, source: LayerSource, boundary: str, threads: int) -> Any:
    import pandas as pd

    layer, pairs, where = _join_pairs(points, source, boundary, threads)
    ids = np.asarray(layer.ids, dtype=object)
    columns = {
        "point": np.asarray(labels)[pairs[0]],
        "region": pairs[1],
        "id": ids[pairs[1]] if len(ids) else np.empty(0, dtype=object),
    }
    if where is not None:
        columns["location"] = where
    return pd.DataFrame(columns)


def _join_block(block: np.ndarray, offset: int, source: LayerSource, boundary: str, threads: int) -> Any:
    return _join_frame(np.arange(offset, offset + len(block), dtype=np.int64), block, source, boundary, threads)


def _join_partition(
    frame: Any, source: LayerSource, columns: Sequence[str], boundary: str, threads: int
) -> Any:
    points = np.ascontiguousarray(frame[list(columns)].to_numpy(dtype=np.float64))
    return _join_frame(frame.index.to_numpy(), points, source, boundary, threads)


def join_layer(
    points: Any,
    layer: Any,
    *,
    columns: Optional[Sequence[str]] = None,
    id: Optional[str] = None,
    layer_name: Optional[str] = None,
    fill: str = "even_odd",
    boundary: str = "inside",
    threads: int = 1,
) -> Any:
    """The spatial join of Dask points against a layer, as a lazy Dask DataFrame of pairs.

    points: a dask.array of shape (N, 2) chunked by rows, or a dask.dataframe with x, y columns
        (or `columns`).
    layer: a layer path (.wkt, .geojson, .shp, .gpkg, .fgb, ...) or 'PG:...' connection string
        that every worker can open, a GeoDataFrame (sent as GeoJSON bytes), or a LayerSource;
        id / layer_name / fill as in contain.RegionLayer.from_file. Each worker process builds
        the RegionLayer once (see index_builds()).
    boundary: 'inside' (a point on a region's boundary joins it, as predicate='intersects'),
        'outside' (only points strictly inside, as 'within'), or 'report' (the command's
        default --boundary report: the pairs of 'inside' with an int8 column 'location', 1
        inside, 0 on the boundary, as the command's ID:on).
    threads: threads per partition (default 1: the workers supply the parallelism).

    Returns a lazy dask DataFrame with one row per (point, region) pair where the region holds
    the point: 'point' (the row number of the array, or the frame's index label), 'region' (the
    region's position in the layer) and 'id' (its id), in point order then region order within
    each partition, partitions in order. Exactly the pairs of contain.RegionLayer.locate on one
    machine.
    """
    import dask
    import dask.array as da
    import dask.dataframe as dd
    import pandas as pd

    if boundary not in ("inside", "outside", "report"):
        raise ValueError(f"boundary must be 'inside', 'outside' or 'report', got {boundary!r}")
    source = LayerSource.of(layer, id=id, layer_name=layer_name, fill=fill)
    meta = pd.DataFrame(
        {
            "point": pd.Series([], dtype=np.int64),
            "region": pd.Series([], dtype=np.int64),
            "id": pd.Series([], dtype=object),
        }
    )
    if boundary == "report":
        meta = meta.assign(location=pd.Series([], dtype=np.int8))
    source_key = dask.delayed(source, pure=True)
    if isinstance(points, dd.DataFrame):
        columns = list(columns) if columns is not None else ["x", "y"]
        if len(columns) != 2:
            raise ValueError(f"a layer needs 2 coordinate columns, got {columns}")
        missing = [c for c in columns if c not in points.columns]
        if missing:
            raise ValueError(f"the dataframe has no column {missing[0]!r} (columns: {list(points.columns)})")
        meta = meta.assign(point=pd.Series([], dtype=points.index.dtype))
        return points.map_partitions(_join_partition, source_key, columns, boundary, threads, meta=meta)
    array = da.asarray(points)
    if array.ndim != 2 or array.shape[1] != 2:
        raise ValueError(f"points must have shape (N, 2) for a layer, got {array.shape}")
    if array.numblocks[1] != 1:
        array = array.rechunk({1: -1})
    offsets = np.concatenate([[0], np.cumsum(array.chunks[0])[:-1]]).astype(np.int64)
    blocks = array.to_delayed().ravel()
    parts = [
        dask.delayed(_join_block)(block, int(offset), source_key, boundary, threads)
        for block, offset in zip(blocks, offsets)
    ]
    return dd.from_delayed(parts, meta=meta, verify_meta=False)
