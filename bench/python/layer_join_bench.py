#!/usr/bin/python3
"""Spatial join, whole process: N points against a layer of regions with contain, GeoPandas'
sjoin and PostGIS, on the same files, in one run.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python/layer_join_bench.py \\
        --contain build/release/contain --out bench/results/debian12-2core/layer_join.txt

Layers (Debian's real data, converted by scenes/gis_layers.py into --work):
  countries  Natural Earth 1:110m (python3-geopandas), 177 regions, ids: positions (the names
             hold spaces, which would make the output's lines ambiguous)
  gshhg      GSHHG shorelines at --gshhg-resolution (gmt, gmt-gshhg-*): land, lakes, islands in
             lakes, ponds, one region a polygon, id 'id' (a GeoPackage)
  boroughs   New York City boroughs (python3-geopandas), 5 regions, id 'BoroCode' (the layer of
             the issue's GeoPandas figure)

Points: uniform in the layer's box, written with 6 decimals (GPS precision), plus 1% taken from
the layer's own vertices written exactly (every one lies on a boundary, many on the border of
two regions), shuffled; one text file per layer, read by all three.

Each tool runs as a whole process, reading the layer and the points and writing the joined
(point, id) pairs:
  contain   contain inside --layer L --id ID --points P --out O  (--threads 1, then 0 = all)
  GeoPandas read_csv, points_from_xy, read_file, sjoin(predicate='intersects'), to_csv of the
            pairs; on the first --geopandas-points points only (it needs about 40 us a point to
            make the shapely points alone); its rate is scaled to N for the ratio
  PostGIS   a PostgreSQL 15 server of its own (as `nobody` under root) on a socket in --work;
            layer by ogr2ogr (GiST index), points by COPY into a table, then ST_MakePoint and a
            GiST index; timed: CREATE TABLE AS the join ON ST_Intersects(region, point) with
            parallel workers off (one thread) and on (max_parallel_workers_per_gather = 2), on
            the layer as loaded and on its polygons cut by ST_Subdivide(geom, 256) (PostGIS'
            advice for large polygons; DISTINCT pairs); JIT off; a join running past
            --postgis-timeout seconds is stopped and reported as such; the load, index and
            subdivision times are printed apart
Answers: the pair counts of the three must agree with contain's (boundary points included, as
ST_Intersects and predicate='intersects' count them); disagreements are printed.
"""

import argparse
import datetime
import os
import pathlib
import platform
import pwd
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import numpy as np

PROJECT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(PROJECT / "scenes"))
import gis_layers  # noqa: E402

PG_BIN = pathlib.Path("/usr/lib/postgresql/15/bin")


def machine():
    model = "unknown CPU"
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            model = line.split(":", 1)[1].strip()
            break
    return f"{os.cpu_count()}-core {platform.machine()} ({model}), {platform.platform()}"


def load():
    return " ".join(f"{value:.2f}" for value in os.getloadavg())


def timed(command, **kwargs):
    """Runs a command; returns (wall s, CPU s of the child: user + sys)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(command, check=True, **kwargs)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def log(out, text=""):
    print(text, flush=True)
    out.write(text + "\n")
    out.flush()


# ---- data -----------------------------------------------------------------------------------


def layer_vertices(path):
    import contain
    import contain.layers
    import geopandas

    frame = geopandas.read_file(path)
    rings = [ring for region in contain.layers.regions_of(frame.geometry) for ring in region]
    return np.concatenate(rings), frame.total_bounds


def write_points(path, n, bounds, vertices, seed):
    rng = np.random.default_rng(seed)
    on = n // 100
    x0, y0, x1, y1 = bounds
    uniform = np.column_stack([rng.uniform(x0, x1, n - on), rng.uniform(y0, y1, n - on)])
    chosen = vertices[rng.integers(0, len(vertices), on)]
    order = rng.permutation(n)
    with open(path, "w") as f:
        rows = np.empty(n, dtype=object)
        # Six decimals for the uniform points, the exact shortest repr for the vertices.
        text_uniform = [f"{a:.6f} {b:.6f}" for a, b in uniform]
        text_on = [f"{a!r} {b!r}" for a, b in chosen]
        rows[: n - on] = text_uniform
        rows[n - on:] = text_on
        f.write("\n".join(rows[order]))
        f.write("\n")


# ---- contain --------------------------------------------------------------------------------


def run_contain(contain, layer, id_field, points, out_path, threads):
    ids = ["--id", id_field] if id_field else []
    wall, cpu = timed([contain, "inside", "--layer", str(layer), *ids, "--points", str(points),
                       "--threads", str(threads), "--quiet", "--out", str(out_path)])
    pairs = on = 0
    with open(out_path) as f:
        for line in f:
            if line != "-\n":
                words = line.split()
                pairs += len(words)
                on += sum(w.endswith(":on") for w in words)
    return wall, cpu, pairs, on


# ---- GeoPandas ------------------------------------------------------------------------------

GEOPANDAS_SCRIPT = r"""
import sys, warnings
import pandas as pd, geopandas
warnings.simplefilter("ignore")
points_path, layer_path, n, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
table = pd.read_csv(points_path, sep=" ", header=None, names=["x", "y"], nrows=n,
                    float_precision="round_trip")  # the default parser is not correctly rounded
layer = geopandas.read_file(layer_path)
points = geopandas.GeoDataFrame(geometry=geopandas.points_from_xy(table.x, table.y), crs=layer.crs)
joined = geopandas.sjoin(points, layer, predicate="intersects")
joined[["index_right"]].to_csv(out)
print(len(joined))
"""


def run_geopandas(points, layer, n, out_path):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    result = subprocess.run([sys.executable, "-c", GEOPANDAS_SCRIPT, str(points), str(layer), str(n),
                             str(out_path)], check=True, capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, int(result.stdout.split()[-1])


# ---- PostGIS --------------------------------------------------------------------------------


class Postgis:
    """A PostgreSQL 15 server with PostGIS on a socket in a scratch directory."""

    def __init__(self, work):
        if not (PG_BIN / "postgres").exists():
            raise SystemExit("PostgreSQL 15 is missing: install postgresql-15-postgis-3")
        self.dir = pathlib.Path(tempfile.mkdtemp(prefix="pg-", dir=work))
        self.user = None
        if os.geteuid() == 0:
            nobody = pwd.getpwnam("nobody")
            self.user, self.group = nobody.pw_uid, nobody.pw_gid
            os.chown(self.dir, self.user, self.group)
            os.chmod(self.dir, 0o700)
        self.started = False
        self._server([str(PG_BIN / "initdb"), "-D", str(self.dir / "data"), "-A", "trust", "-U",
                      "postgres", "--no-sync", "--no-locale", "-E", "UTF8"])
        self._server([str(PG_BIN / "pg_ctl"), "-D", str(self.dir / "data"), "-l", str(self.dir / "log"),
                      "-w", "-o", f"-k {self.dir} -c listen_addresses='' -F -c shared_buffers=1GB "
                      "-c work_mem=256MB -c maintenance_work_mem=1GB -c max_wal_size=8GB", "start"])
        self.started = True
        self.sql("CREATE EXTENSION postgis;")

    def _server(self, command):
        kwargs = {"user": self.user, "group": self.group} if self.user is not None else {}
        subprocess.run(command, check=True, capture_output=True, **kwargs)

    @property
    def connection(self):
        return f"PG:host={self.dir} user=postgres dbname=postgres"

    def sql(self, statement):
        """Runs SQL; returns (wall s, output)."""
        start = time.perf_counter()
        result = subprocess.run(["psql", "-h", str(self.dir), "-U", "postgres", "-d", "postgres", "-v",
                                 "ON_ERROR_STOP=1", "-q", "-t", "-A", "-c", statement],
                                capture_output=True, text=True)
        if result.returncode != 0:
            raise RuntimeError(f"psql failed: {result.stderr.strip()}\n  in: {statement}")
        return time.perf_counter() - start, result.stdout.strip()

    def timed_sql(self, statement):
        """Runs SQL in a session of its own; returns (wall s, backend CPU s, output). The CPU
        time is the backend's user + system time from /proc (parallel workers not included)."""
        session = subprocess.Popen(["psql", "-h", str(self.dir), "-U", "postgres", "-d", "postgres", "-v",
                                    "ON_ERROR_STOP=1", "-q", "-t", "-A"], stdin=subprocess.PIPE,
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, bufsize=1)

        def ask(sql):
            session.stdin.write(sql + "\n\\echo __done__\n")
            session.stdin.flush()
            lines = []
            for line in session.stdout:
                if line.strip() == "__done__":
                    return "\n".join(lines)
                lines.append(line.rstrip("\n"))
            raise RuntimeError(f"psql failed: {session.stderr.read().strip()}\n  in: {sql}")

        def cpu(pid):
            fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
            return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")

        try:
            pid = int(ask("SELECT pg_backend_pid();").split()[-1])
            before = cpu(pid)
            start = time.perf_counter()
            out = ask(statement)
            wall = time.perf_counter() - start
            used = cpu(pid) - before
        finally:
            session.stdin.close()
            session.wait()
        return wall, used, out.strip()

    def close(self):
        if self.started:
            self._server([str(PG_BIN / "pg_ctl"), "-D", str(self.dir / "data"), "-m", "immediate", "-w", "stop"])
        shutil.rmtree(self.dir, ignore_errors=True)


def run_postgis(server, name, layer, id_field, points, timeout, plain_timeout):
    table = f"layer_{name}"
    start = time.perf_counter()
    subprocess.run(["ogr2ogr", "-f", "PostgreSQL", server.connection, str(layer), "-nln", table,
                    "-nlt", "PROMOTE_TO_MULTI", "-lco", "GEOMETRY_NAME=geom", "-lco", "PRECISION=NO",
                    "-lco", "SPATIAL_INDEX=GIST", "-overwrite"], check=True, capture_output=True)
    layer_load = time.perf_counter() - start
    pts = f"points_{name}"
    t_copy, _ = server.sql(f"DROP TABLE IF EXISTS {pts}; CREATE UNLOGGED TABLE {pts} (id bigserial, x float8, y float8);"
                           f"COPY {pts} (x, y) FROM PROGRAM 'cat {points}' WITH (FORMAT text, DELIMITER ' ');")
    _, srid = server.sql(f"SELECT Find_SRID('public', '{table}', 'geom');")
    t_geom, _ = server.sql(f"ALTER TABLE {pts} ADD COLUMN geom geometry(Point, {srid});"
                           f"UPDATE {pts} SET geom = ST_SetSRID(ST_MakePoint(x, y), {srid});")
    t_index, _ = server.sql(f"CREATE INDEX ON {pts} USING GIST (geom); ANALYZE {pts}; ANALYZE {table};")
    region = f'"{id_field.lower()}"' if id_field else "ogc_fid"
    # PostGIS' own advice for large polygons: ST_Subdivide them (at most 256 vertices a piece),
    # so that each point is tested against a small piece. A point on a cut lies in two pieces of
    # one region: DISTINCT. GEOS cannot subdivide the few invalid polygons: kept whole.
    t_sub, _ = server.sql(
        f"DROP TABLE IF EXISTS sub_{name}; CREATE UNLOGGED TABLE sub_{name} AS "
        f"SELECT {region} AS region, ST_Subdivide(geom, 256) AS geom FROM {table} WHERE ST_IsValid(geom) "
        f"UNION ALL SELECT {region}, geom FROM {table} WHERE NOT ST_IsValid(geom);"
        f"CREATE INDEX ON sub_{name} USING GIST (geom); ANALYZE sub_{name};")
    joins = {}
    queries = {
        "plain": f"SELECT p.id, l.{region} AS region FROM {pts} p JOIN {table} l ON ST_Intersects(l.geom, p.geom)",
        "subdivided": f"SELECT DISTINCT p.id, l.region FROM {pts} p JOIN sub_{name} l ON ST_Intersects(l.geom, p.geom)",
    }
    for kind, query in queries.items():
        for label, workers in (("1 thread", 0), ("2 workers", 2)):
            try:
                wall, cpu, count = server.timed_sql(
                    f"SET jit = off; SET statement_timeout = '{timeout if kind == 'subdivided' else plain_timeout}s'; "
                    f"SET max_parallel_workers_per_gather = {workers}; DROP TABLE IF EXISTS joined;"
                    f"CREATE UNLOGGED TABLE joined AS {query}; SELECT count(*) FROM joined;")
                joins[f"{kind}, {label}"] = (wall, cpu if workers == 0 else None, int(count.split()[-1]))
            except RuntimeError as error:
                if "statement timeout" not in str(error):
                    raise
                joins[f"{kind}, {label}"] = (None, None, None)
    joins["subdivide"] = (t_sub, None, None)
    return layer_load, t_copy, t_geom, t_index, joins


# ---- main -----------------------------------------------------------------------------------


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--contain", default=str(PROJECT / "build/release/contain"))
    parser.add_argument("--points", type=int, default=10_000_000)
    parser.add_argument("--geopandas-points", type=int, default=1_000_000)
    parser.add_argument("--gshhg-resolution", default="i")
    parser.add_argument("--layers", default="countries,gshhg,boroughs")
    parser.add_argument("--no-postgis", action="store_true")
    parser.add_argument("--postgis-timeout", type=int, default=1800,
                        help="seconds allowed to one PostGIS join on the subdivided layer")
    parser.add_argument("--postgis-plain-timeout", type=int, default=600,
                        help="seconds allowed to one PostGIS join on the layer as loaded")
    parser.add_argument("--work", type=pathlib.Path, default=pathlib.Path("/tmp/contain-layer-bench"))
    parser.add_argument("--out", type=pathlib.Path)
    args = parser.parse_args()
    args.work.mkdir(parents=True, exist_ok=True)
    os.chmod(args.work, 0o755)
    out = open(args.out, "w") if args.out else open(os.devnull, "w")
    log(out, f"# layer_join_bench {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC")
    log(out, f"# {machine()}")
    log(out, f"# command: {' '.join(sys.argv)}")
    log(out, f"# load average at start: {load()}")

    layers = {}
    wanted = args.layers.split(",")
    if "countries" in wanted:
        layers["countries"] = (gis_layers.countries(), None)  # names hold spaces: positions
    if "gshhg" in wanted:
        start = time.perf_counter()
        path = gis_layers.write_gshhg(args.work / f"gshhg_{args.gshhg_resolution}.gpkg", args.gshhg_resolution)
        log(out, f"# GSHHG {args.gshhg_resolution} exported and converted in {time.perf_counter() - start:.1f} s")
        layers["gshhg"] = (path, "id")
    if "boroughs" in wanted:
        layers["boroughs"] = (gis_layers.boroughs(), "BoroCode")

    # A run stopped with SIGTERM still stops its server (the finally below).
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    server = None if args.no_postgis else Postgis(args.work)
    try:
        for name, (path, id_field) in layers.items():
            vertices, bounds = layer_vertices(path)
            points = args.work / f"points_{name}_{args.points}.txt"
            if not points.exists():
                write_points(points, args.points, bounds, vertices, seed=len(name))
            import contain
            layer = contain.RegionLayer.from_file(str(path), id_field)  # for its sizes
            stats = layer.stats
            log(out, "")
            log(out, f"## {name}: {path}")
            log(out, f"# {stats['regions']} regions, {stats['edges']} edges, {stats['bytes'] / stats['edges']:.0f} bytes "
                     f"per edge; {args.points} points ({args.points // 100} layer vertices), load {load()}")
            results, cpu_results = {}, {}
            for threads in (1, 0):
                wall, cpu, pairs, on = run_contain(args.contain, path, id_field, points,
                                                   args.work / f"out_{name}.txt", threads)
                results[threads] = wall
                cpu_results[threads] = cpu
                log(out, f"contain --threads {threads or 'all'}: {wall:.2f} s wall, {cpu:.2f} s CPU, "
                         f"{args.points / wall / 1e6:.2f} M points/s; {pairs} pairs ({on} on a boundary)")
            contain_pairs = pairs
            n_gpd = min(args.geopandas_points, args.points)
            if n_gpd > 0:
                wall, cpu, gpd_pairs = run_geopandas(points, path, n_gpd, args.work / f"gpd_{name}.csv")
                # contain's pairs on the same first n_gpd points
                with open(args.work / f"out_{name}.txt") as f:
                    head = sum(len(line.split()) for _, line in zip(range(n_gpd), f) if line != "-\n")
                scaled = wall * args.points / n_gpd
                log(out, f"GeoPandas sjoin (whole process, {n_gpd} points): {wall:.1f} s wall, {cpu:.1f} s CPU, "
                         f"{n_gpd / wall / 1e3:.1f} k points/s; {gpd_pairs} pairs (contain: {head}); "
                         f"scaled to {args.points}: {scaled:.0f} s; contain 1 thread is {scaled / results[1]:.0f}x faster "
                         f"(wall), {cpu * args.points / n_gpd / cpu_results[1]:.0f}x less CPU")
            if server is not None:
                layer_load, t_copy, t_geom, t_index, joins = run_postgis(server, name, path, id_field, points,
                                                                         args.postgis_timeout,
                                                                         args.postgis_plain_timeout)
                t_sub = joins.pop("subdivide")[0]
                log(out, f"PostGIS load: layer {layer_load:.1f} s, COPY points {t_copy:.1f} s, ST_MakePoint "
                         f"{t_geom:.1f} s, GiST index + ANALYZE {t_index:.1f} s; ST_Subdivide + index {t_sub:.1f} s")
                for label, (wall, cpu, count) in joins.items():
                    if wall is None:
                        limit = args.postgis_timeout if label.startswith("subdivided") else args.postgis_plain_timeout
                        log(out, f"PostGIS join ST_Intersects, {label}: stopped after {limit} s "
                                 f"(statement_timeout): contain 1 thread is > {limit / results[1]:.0f}x faster")
                        continue
                    cpu_text = (f", backend CPU {cpu:.2f} s (contain 1 thread: {cpu / cpu_results[1]:.1f}x less CPU)"
                                if cpu is not None else "")
                    log(out, f"PostGIS join ST_Intersects, {label}: {wall:.2f} s wall{cpu_text}, {count} pairs "
                             f"({'equal' if count == contain_pairs else 'DIFFERENT from'} contain's {contain_pairs}); "
                             f"contain 1 thread is {wall / results[1]:.1f}x faster (join alone, wall), "
                             f"{(wall + t_copy + t_geom + t_index) / results[1]:.1f}x with loading")
    finally:
        if server is not None:
            server.close()
    log(out, f"# load average at end: {load()}")


if __name__ == "__main__":
    main()
