"""Spatial joins: which regions of a layer hold each point, on numpy and on GeoDataFrames.

    >>> import contain, contain.layers
    >>> layer = contain.RegionLayer.from_file("counties.gpkg", id="GEOID")
    >>> pairs = layer.locate(points)                  # (2, M) int64: point, region
    >>> joined = contain.layers.sjoin(gps, counties)  # GeoDataFrames in and out (geopandas)

`contain.RegionLayer` is the fast path: (N, 2) float64 points in, (point, region) index pairs
out as shapely's STRtree.query(points, predicate) gives them, exact on the doubles. The
functions here take what GIS code holds: shapely geometries, anything with
`__geo_interface__`, GeoSeries and GeoDataFrames (geopandas is needed only for `sjoin` and
`layer_from_geodataframe`). Coordinates are read as the exact doubles of the geometries.
"""

from __future__ import annotations

from typing import Any, Iterable, List, Optional, Sequence, Tuple

import numpy as np

import contain

__all__ = ["regions_of", "points_of", "layer_from_geodataframe", "sjoin"]

# WKB of a 2D point: byte order, type (1), x, y.
_POINT_WKB = np.dtype([("order", "u1"), ("type", "<u4"), ("x", "<f8"), ("y", "<f8")])


def _rings_of_polygon(polygon: Any) -> List[np.ndarray]:
    """The rings of one polygon as (K, 2) float64 arrays (z dropped), shell first."""
    if hasattr(polygon, "exterior"):  # a shapely polygon: its coordinate arrays, no tuples
        if polygon.is_empty:
            return []
        rings = [polygon.exterior] + list(polygon.interiors)
        return [np.asarray(ring.coords, dtype=np.float64)[:, :2] for ring in rings]
    return [np.asarray(ring, dtype=np.float64)[:, :2] for ring in polygon]


def _region_of(geometry: Any) -> List[np.ndarray]:
    """All rings of a Polygon, MultiPolygon or collection of them (one region)."""
    if geometry is None or getattr(geometry, "is_empty", False) is True:
        return []  # shapely 1.8 calls an empty Polygon a GeometryCollection without .geoms
    kind = getattr(geometry, "geom_type", None)
    if kind == "Polygon":
        return _rings_of_polygon(geometry)
    if kind in ("MultiPolygon", "GeometryCollection"):
        rings: List[np.ndarray] = []
        for part in geometry.geoms:
            rings.extend(_region_of(part))
        return rings
    mapping = geometry if isinstance(geometry, dict) else getattr(geometry, "__geo_interface__", None)
    if mapping is None:
        raise TypeError(
            f"a region must be a shapely Polygon/MultiPolygon or have __geo_interface__, got {type(geometry).__name__}"
        )
    kind = mapping.get("type")
    if kind == "Polygon":
        return _rings_of_polygon(mapping["coordinates"])
    if kind == "MultiPolygon":
        return [ring for polygon in mapping["coordinates"] for ring in _rings_of_polygon(polygon)]
    if kind == "GeometryCollection":
        return [ring for part in mapping["geometries"] for ring in _region_of(part)]
    if kind == "Feature":
        return _region_of(mapping.get("geometry"))
    raise TypeError(f"a region must be a Polygon or MultiPolygon, got a {kind}")


def regions_of(geometries: Iterable[Any]) -> List[List[np.ndarray]]:
    """Regions for contain.RegionLayer from shapely geometries or __geo_interface__ objects.

    Each Polygon or MultiPolygon (or collection of them) becomes one region: all its rings as
    (K, 2) float64 arrays, read under the even-odd rule as the OGC polygon they are. None and
    empty geometries give empty regions (they hold no point), so positions stay aligned.
    """
    return [_region_of(g) for g in geometries]


def points_of(geometries: Any) -> np.ndarray:
    """An (N, 2) float64 array of the x, y of point geometries (a GeoSeries, or a sequence).

    Read from the points' WKB in one pass, so the doubles are exact and the cost is one
    shapely call a point. Raises ValueError for geometries that are not 2D points.
    """
    return _present_points(geometries, skip_missing=False)[0]


def _present_points(geometries: Any, skip_missing: bool) -> Tuple[np.ndarray, Optional[np.ndarray]]:
    """The (K, 2) x, y of the points, and the positions they hold (None: all of them).

    skip_missing: None and empty geometries are left out (as geopandas.sjoin leaves them out of
    every match) instead of raising ValueError; any other geometry but a Point raises.
    """
    data = getattr(getattr(geometries, "values", geometries), "_data", None)
    items = data if data is not None else list(geometries)
    if len(items) == 0:
        return np.empty((0, 2), dtype=np.float64), None
    try:
        blob = b"".join(g.wkb for g in items)
    except AttributeError:
        blob = b""
    if len(blob) == _POINT_WKB.itemsize * len(items):
        records = np.frombuffer(blob, dtype=_POINT_WKB)
        xy = np.column_stack([records["x"], records["y"]])
        # shapely 2 writes an empty point as POINT (NaN NaN): such rows take the slow path.
        if np.all(records["order"] == 1) and np.all(records["type"] == 1) and np.isfinite(xy).all():
            return xy, None
    out = np.empty((len(items), 2), dtype=np.float64)
    present = np.ones(len(items), dtype=bool)
    for k, g in enumerate(items):
        if skip_missing and (g is None or g.is_empty):
            present[k] = False
            continue
        if g is None or getattr(g, "geom_type", "Point") != "Point" or g.is_empty:
            raise ValueError(f"geometry {k} is not a point: {getattr(g, 'geom_type', type(g).__name__)}")
        out[k] = g.coords[0][:2]
    bad = present & ~np.isfinite(out).all(axis=1)
    if bad.any():  # named by the frame's row here, not by its place among the present points
        raise contain.ContainError(f"points[{int(np.flatnonzero(bad)[0])}] has a NaN or infinite coordinate")
    if present.all():
        return out, None
    return out[present], np.flatnonzero(present)


def layer_from_geodataframe(frame: Any, id: Optional[str] = None, *, fill: str = "even_odd") -> "contain.RegionLayer":
    """A contain.RegionLayer of a GeoDataFrame's (or GeoSeries') polygons, in row order.

    id: a column whose values (as str) are the ids; default the frame's index labels.
    """
    geometry = frame.geometry if hasattr(frame, "geometry") else frame
    if id is not None:
        ids = [str(v) for v in frame[id]]
    else:
        ids = [str(v) for v in frame.index]
    return contain.RegionLayer(regions_of(geometry), ids, fill=fill)


def sjoin(
    points: Any,
    regions: Any,
    how: str = "inner",
    predicate: str = "intersects",
    *,
    fill: str = "even_odd",
    threads: int = 0,
    lsuffix: str = "left",
    rsuffix: str = "right",
) -> Any:
    """geopandas.sjoin(points, regions) for points against polygons, exact and on every core.

    points: a GeoDataFrame of Point geometries (the left frame); None and empty points match
        nothing (as in geopandas.sjoin: left out of 'inner', kept with NaN by 'left'); a point
        with a NaN or infinite coordinate raises ContainError naming its row, points[k]
        (geopandas' own spatial index raises too).
    regions: a GeoDataFrame of Polygon / MultiPolygon geometries (the right frame; None and
        empty geometries hold no point), or a
        contain.RegionLayer built from it in the same row order (to join several point sets
        against one prepared layer).
    how: 'inner' (one row per (point, region) pair) or 'left' (also the points held by no
        region, with NaN in the right columns).
    predicate: 'intersects' or 'covered_by' (a point on a region's boundary joins it),
        'within' (only points strictly inside).

    Returns a GeoDataFrame as geopandas.sjoin does: the left rows repeated per match, in point
    order then region order, with 'index_right' and the right frame's columns (name clashes get
    the suffixes). The answers are exact on the doubles of the geometries; geopandas' own sjoin
    decides with GEOS on the same doubles, so the pairs agree except where GEOS and exact
    arithmetic differ on points a rounding error away from an edge.
    """
    import pandas as pd

    if how not in ("inner", "left"):
        raise ValueError(f"how must be 'inner' or 'left', got {how!r}")
    boundary = {"intersects": "inside", "covered_by": "inside", "within": "outside"}.get(predicate)
    if boundary is None:
        raise ValueError(f"predicate must be 'intersects', 'covered_by' or 'within', got {predicate!r}")
    if not isinstance(regions, contain.RegionLayer):
        left_crs, right_crs = getattr(points, "crs", None), getattr(regions, "crs", None)
        if left_crs != right_crs:
            import warnings

            warnings.warn(f"the points' CRS ({left_crs}) and the regions' ({right_crs}) differ: the coordinates are "
                          "joined as they are (reproject with to_crs first)", UserWarning, stacklevel=2)
    layer = regions if isinstance(regions, contain.RegionLayer) else layer_from_geodataframe(regions, fill=fill)
    xy, present = _present_points(points.geometry, skip_missing=True)
    pairs = layer.locate(xy, boundary=boundary, threads=threads)
    left_rows, right_rows = pairs[0], pairs[1]
    if present is not None:  # back to the frame's rows: missing points join nothing
        left_rows = present[left_rows]
    if how == "left":
        held = np.zeros(len(points), dtype=bool)
        held[left_rows] = True
        lonely = np.flatnonzero(~held)
        left_rows = np.concatenate([left_rows, lonely])
        right_rows = np.concatenate([right_rows, np.full(len(lonely), -1, dtype=np.int64)])
        order = np.lexsort((right_rows, left_rows))
        left_rows, right_rows = left_rows[order], right_rows[order]
    joined = points.iloc[left_rows]
    # Rows by position; -1 (a point held by no region, 'left' only) is no label, so reindex
    # gives it NaN and changes a column's dtype only where such a row exists, as geopandas does.
    if isinstance(regions, contain.RegionLayer):
        ids = pd.Series(regions.ids, dtype=object).reindex(right_rows).to_numpy()
        extra = pd.DataFrame({"index_right": ids})
    else:
        table = regions.drop(columns=regions.geometry.name).reset_index()
        taken = table.reindex(right_rows).reset_index(drop=True)
        taken = taken.rename(columns={taken.columns[0]: "index_right"})
        clashes = set(taken.columns) & set(joined.columns)
        extra = taken.rename(columns={c: f"{c}_{rsuffix}" for c in clashes})
        joined = joined.rename(columns={c: f"{c}_{lsuffix}" for c in clashes if c != joined.geometry.name})
    extra.index = joined.index
    return pd.concat([joined, extra], axis=1)
