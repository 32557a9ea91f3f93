#!/usr/bin/python3
"""Real GIS layers that Debian ships, converted for the tests and benchmarks (never committed).

- Natural Earth countries (1:110m, 177 countries) and the New York City boroughs: the data sets
  of python3-geopandas (geopandas.datasets), read where the package installs them.
- GSHHG shorelines (Wessel and Smith): land (level 1), lakes (2), islands in lakes (3) and ponds
  on those islands (4), exported by GMT (`gmt coast -M -W`, package gmt with gmt-gshhg-low /
  -high / -full) at a resolution c (crude), l (low), i (intermediate), h, f. GMT writes each
  shoreline cut into the pieces of its storage bins; the pieces are joined again here by their
  exactly equal end points, and the few polygons cut by the antimeridian (Eurasia at the Bering
  Strait, Fiji) are closed along it, Antarctica around the South Pole. Each polygon is one
  region with properties id ("L<level>-<n>") and level; a lake's polygon lies inside its land's
  polygon (the land is not holed), so a point on a lake is held by both.

    /usr/bin/python3 scenes/gis_layers.py gshhg --resolution l --out /tmp/gshhg_l.geojson
    /usr/bin/python3 scenes/gis_layers.py countries
    /usr/bin/python3 scenes/gis_layers.py boroughs

Coordinates are written as the shortest decimals that read back as the same doubles (Python's
repr), so every reader (contain's GeoJSON, GDAL) gets the doubles GMT printed. The GeoJSON can
be converted to other formats with ogr2ogr (`gpkg` below does it).
"""

from __future__ import annotations

import argparse
import collections
import json
import pathlib
import shutil
import subprocess
import sys
import tempfile
import zipfile
from typing import Dict, List, Optional, Tuple

GEOPANDAS_DATASETS = pathlib.Path("/usr/lib/python3/dist-packages/geopandas/datasets")

Point = Tuple[float, float]


def countries() -> pathlib.Path:
    """The Natural Earth 1:110m countries shapefile of python3-geopandas (attribute 'name')."""
    path = GEOPANDAS_DATASETS / "naturalearth_lowres" / "naturalearth_lowres.shp"
    if not path.exists():
        raise SystemExit(f"{path} is missing: install python3-geopandas")
    return path


def boroughs() -> str:
    """The New York City boroughs shapefile of python3-geopandas as a GDAL /vsizip/ path
    (attribute 'BoroName'; coordinates in feet, EPSG:2263)."""
    archive = GEOPANDAS_DATASETS / "nybb_16a.zip"
    if not archive.exists():
        raise SystemExit(f"{archive} is missing: install python3-geopandas")
    shp = next(n for n in zipfile.ZipFile(archive).namelist() if n.endswith(".shp"))
    return f"/vsizip/{archive}/{shp}"


def _gmt_pieces(resolution: str) -> List[Tuple[int, List[Point]]]:
    gmt = shutil.which("gmt")
    if gmt is None:
        raise SystemExit("gmt is missing: install gmt and gmt-gshhg-low (or -high, -full)")
    with tempfile.TemporaryDirectory() as scratch:  # GMT leaves gmt.history in its folder
        text = subprocess.run([gmt, "coast", "-Rd", f"-D{resolution}", "-W", "-M"], check=True,
                              capture_output=True, text=True, cwd=scratch).stdout
    pieces: List[Tuple[int, List[Point]]] = []
    for line in text.splitlines():
        if line.startswith(">"):
            pieces.append((int(line.rsplit(" ", 1)[1]), []))  # "> Shore Bin # 1, Level 1"
        elif line.strip():
            x, y = line.split()
            pieces[-1][1].append((float(x), float(y)))
    return [(level, points) for level, points in pieces if len(points) >= 2]


def _close_at_the_antimeridian(chain: List[Point]) -> Optional[List[Point]]:
    """Closes a chain cut by x = +-180: along the meridian, or around a pole (Antarctica)."""
    (sx, sy), (ex, ey) = chain[0], chain[-1]
    if abs(sx) != 180.0 or abs(ex) != 180.0:
        return None
    if sx == ex:
        return chain  # the closing edge runs along the meridian
    pole = -90.0 if sy + ey < 0 else 90.0
    return chain + [(ex, pole), (sx, pole)]


def gshhg_polygons(resolution: str = "l") -> List[Tuple[int, List[Point]]]:
    """The GSHHG polygons at `resolution` as (level, ring without the closing point)."""
    pieces = _gmt_pieces(resolution)
    polygons: List[Tuple[int, List[Point]]] = []
    open_pieces = []
    for level, points in pieces:
        if points[0] == points[-1]:
            polygons.append((level, points[:-1]))
        else:
            open_pieces.append((level, points))
    starts: Dict[Point, List[int]] = collections.defaultdict(list)
    for k, (_, points) in enumerate(open_pieces):
        starts[points[0]].append(k)
    # Join pieces end to start; a piece met before its predecessor starts a chain of its own,
    # so chains are joined again until none continues another.
    used = [False] * len(open_pieces)
    chains: List[List[Point]] = []
    for k, (level, points) in enumerate(open_pieces):
        if used[k]:
            continue
        used[k] = True
        chain = list(points)
        while chain[-1] != chain[0]:
            following = [j for j in starts.get(chain[-1], []) if not used[j]]
            if not following:
                break
            used[following[0]] = True
            chain.extend(open_pieces[following[0]][1][1:])
        if chain[-1] == chain[0]:
            polygons.append((level, chain[:-1]))
        else:
            chains.append((level, chain))
    merged = True
    while merged:
        merged = False
        by_start = {chain[0]: k for k, (_, chain) in enumerate(chains)}
        for k, (level, chain) in enumerate(chains):
            j = by_start.get(chain[-1])
            if j is not None and j != k:
                chain.extend(chains[j][1][1:])
                del chains[j]
                merged = True
                break
    lost = 0
    for level, chain in chains:
        if chain[-1] == chain[0]:
            polygons.append((level, chain[:-1]))
            continue
        closed = _close_at_the_antimeridian(chain)
        if closed is None:
            lost += 1
            continue
        polygons.append((level, closed))
    if lost:
        print(f"gis_layers: {lost} GSHHG chains could not be closed and were left out", file=sys.stderr)
    return [(level, ring) for level, ring in polygons if len(set(ring)) >= 3]


def gshhg_geojson(resolution: str = "l") -> str:
    """The GSHHG layer as a GeoJSON FeatureCollection (properties id, level)."""
    features = []
    counts: Dict[int, int] = collections.Counter()
    for level, ring in gshhg_polygons(resolution):
        counts[level] += 1
        coordinates = [[x, y] for x, y in ring] + [[ring[0][0], ring[0][1]]]
        features.append({"type": "Feature", "properties": {"id": f"L{level}-{counts[level]}", "level": level},
                         "geometry": {"type": "Polygon", "coordinates": [coordinates]}})
    return json.dumps({"type": "FeatureCollection", "features": features}, separators=(",", ":"))


def write_gshhg(out: pathlib.Path, resolution: str = "l") -> pathlib.Path:
    """Writes the GSHHG layer to `out` (.geojson; any other extension through ogr2ogr)."""
    out = pathlib.Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    geojson = out if out.suffix == ".geojson" else out.with_suffix(".geojson")
    geojson.write_text(gshhg_geojson(resolution))
    if out != geojson:
        convert(geojson, out)
    return out


def convert(source: pathlib.Path, out: pathlib.Path, *extra: str) -> pathlib.Path:
    """ogr2ogr source -> out (format by extension), replacing out."""
    drivers = {".gpkg": "GPKG", ".shp": "ESRI Shapefile", ".fgb": "FlatGeobuf", ".geojson": "GeoJSON"}
    if shutil.which("ogr2ogr") is None:
        raise SystemExit("ogr2ogr is missing: install gdal-bin")
    pathlib.Path(out).unlink(missing_ok=True)
    subprocess.run(["ogr2ogr", "-f", drivers[pathlib.Path(out).suffix], str(out), str(source), *extra],
                   check=True, capture_output=True)
    return pathlib.Path(out)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("layer", choices=["gshhg", "countries", "boroughs"])
    parser.add_argument("--resolution", default="l", choices=list("clihf"))
    parser.add_argument("--out", type=pathlib.Path, help="where to write the GSHHG layer")
    args = parser.parse_args()
    if args.layer == "countries":
        print(countries())
    elif args.layer == "boroughs":
        print(boroughs())
    else:
        out = args.out or pathlib.Path(f"gshhg_{args.resolution}.geojson")
        print(write_gshhg(out, args.resolution))


if __name__ == "__main__":
    main()
