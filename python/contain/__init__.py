"""Exact point containment, collision and clipping in 2D and 3D, on numpy arrays.

The Python face of the contain C++ library. Two layers, as in C++: one-shot functions
(point_in_polygon, point_in_mesh, collide, polygon_boolean, bounding_sphere, ...) and prepared
objects that own their acceleration structure and answer batches on every core with the GIL
released (MeshIndex, PolygonIndex, MeshPair, CsgSolid, ConvexPolyhedron, FastWindingNumber,
MovingMeshPair). Continuous collision: vertex_face_ccd and edge_edge_ccd on (N, 8, 3) arrays,
mesh_mesh_ccd and MovingMeshPair.

Shapes come as users hold them, by one rule (contain.as_mesh, contain.as_region): a mesh is a
contain.Mesh, a trimesh.Trimesh, an Open3D TriangleMesh, a (vertices, faces) pair or a mesh
file path; a region is a contain.Region, a shapely geometry, a GeoPandas GeoSeries or
GeoDataFrame, anything with __geo_interface__, WKT / GeoJSON / WKB, a region file path or rings.
Regions go back out with to_shapely() and __geo_interface__; Region and Mesh draw themselves in
a notebook (_repr_svg_).

Points go in as (N, 3) or (N, 2) float64 arrays, read in place when C-contiguous (any other
layout or real dtype is converted once); answers come out as int8 arrays of
contain.Location values (-1 outside, 0 boundary, 1 inside), or as bool arrays under an explicit
boundary policy (contains(points, boundary='inside' | 'outside' | 'raise')).

Library errors raise contain.ContainError (a ValueError) carrying the library's message with
file and line; unreadable files raise contain.ContainIOError (also an OSError). Wrong dtypes
raise TypeError and wrong shapes ValueError, naming the expected shape.

    >>> import numpy as np, contain
    >>> index = contain.MeshIndex(contain.read_mesh("part.obj"))
    >>> answers = index.locate(np.random.default_rng(1).uniform(-1, 1, (1_000_000, 3)))
    >>> (answers == contain.Location.inside).sum()

contain.dask classifies Dask arrays and dataframes of points on a cluster, building each index
once per worker process. See docs/python.md and docs/scale.md.

Many shapes at once: RegionLayer (which regions of a GIS layer hold each point, as (point,
region) index pairs), SolidScene (which solids hold each point, which solids touch), and
contain.layers.sjoin for GeoDataFrames; see docs/layers.md.
"""

from ._contain import (
    BoxClipper,
    Contact,
    ContainError,
    ContainIOError,
    ConvexContact,
    ConvexDistance,
    ConvexPolyhedron,
    ConvexShape,
    Csg,
    FastWindingNumber,
    CsgSolid,
    Location,
    Mesh,
    MeshBooleanResult,
    MeshDistance,
    MeshImpact,
    MeshIndex,
    MeshPair,
    MeshPairDistance,
    MeshReport,
    MovingMeshPair,
    PointChunks,
    PolygonIndex,
    Region,
    RegionLayer,
    SelfIntersections,
    SolidScene,
    RegionDistance,
    TileIterator,
    aabb,
    as_mesh,
    as_region,
    bounding_circle,
    bounding_sphere,
    clip_mesh,
    clip_polygon,
    clip_polylines,
    clip_segments,
    mesh_section,
    shadow,
    slice_mesh,
    collide,
    convex_collide,
    convex_convex,
    convex_convex_within,
    convex_intersect,
    edge_edge_ccd,
    format_mesh,
    format_wkt,
    generalized_winding_number,
    is_mesh_like,
    iter_points,
    iter_tiles,
    mesh_boolean,
    mesh_mesh_ccd,
    orient2d,
    orient3d,
    pair_search,
    parse_mesh,
    parse_wkt,
    point_in_convex_polygon,
    point_in_mesh,
    point_in_polygon,
    point_in_triangle,
    polygon_boolean,
    read_mesh,
    read_points,
    read_region,
    repair_solid,
    segment_segment,
    segment_triangle,
    segments_intersect,
    self_intersections,
    sutherland_hodgman,
    tile,
    tri_tri,
    tri_tri_2d,
    validate_mesh,
    vertex_face_ccd,
    weld_vertices,
    winding_number,
    write_mesh,
    write_wkt,
)
from ._contain import __version__

__all__ = [
    "BoxClipper",
    "Contact",
    "ContainError",
    "ContainIOError",
    "ConvexContact",
    "ConvexDistance",
    "ConvexPolyhedron",
    "ConvexShape",
    "Csg",
    "FastWindingNumber",
    "CsgSolid",
    "Location",
    "Mesh",
    "MeshBooleanResult",
    "MeshDistance",
    "MeshImpact",
    "MeshIndex",
    "MeshPair",
    "MeshPairDistance",
    "MeshReport",
    "MovingMeshPair",
    "PointChunks",
    "PolygonIndex",
    "Region",
    "RegionLayer",
    "SelfIntersections",
    "SolidScene",
    "RegionDistance",
    "TileIterator",
    "aabb",
    "as_mesh",
    "as_region",
    "bounding_circle",
    "bounding_sphere",
    "clip_mesh",
    "clip_polygon",
    "clip_polylines",
    "clip_segments",
    "mesh_section",
    "shadow",
    "slice_mesh",
    "collide",
    "convex_collide",
    "convex_convex",
    "convex_convex_within",
    "convex_intersect",
    "edge_edge_ccd",
    "format_mesh",
    "format_wkt",
    "generalized_winding_number",
    "is_mesh_like",
    "iter_points",
    "iter_tiles",
    "mesh_boolean",
    "mesh_mesh_ccd",
    "orient2d",
    "orient3d",
    "pair_search",
    "parse_mesh",
    "parse_wkt",
    "point_in_convex_polygon",
    "point_in_mesh",
    "point_in_polygon",
    "point_in_triangle",
    "polygon_boolean",
    "read_mesh",
    "read_points",
    "read_region",
    "repair_solid",
    "segment_segment",
    "segment_triangle",
    "segments_intersect",
    "self_intersections",
    "sutherland_hodgman",
    "tile",
    "tri_tri",
    "tri_tri_2d",
    "validate_mesh",
    "vertex_face_ccd",
    "weld_vertices",
    "winding_number",
    "write_mesh",
    "write_wkt",
]

# Old names of classes, kept for now: each use warns (a DeprecationWarning naming the new one).
_RENAMED = {"WindingNumber": "FastWindingNumber"}


def __getattr__(name):
    if name in _RENAMED:
        import warnings

        new = _RENAMED[name]
        warnings.warn(f"contain.{name} is deprecated: use contain.{new} (the name of the C++ "
                      "type; docs/python.md, Renamed)", DeprecationWarning, stacklevel=2)
        return globals()[new]
    raise AttributeError(f"module 'contain' has no attribute {name!r}")
