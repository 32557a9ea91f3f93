#!/usr/bin/python3
"""Spatial join on Dask: points per second of contain.dask.join_layer on 1 and 2 worker
processes against Natural Earth's countries, and the speed-up.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python/dask_layer_bench.py \\
        --out bench/results/debian12-2core/dask_layer.txt

Points uniform over the world (-180..180, -90..90), generated on the workers, persisted and
rebalanced before timing; the layer (python3-geopandas' naturalearth_lowres shapefile) travels
as its path, each worker builds its RegionLayer once. Timed: the fastest of --repeat runs of
len(contain.dask.join_layer(points, layer)) (the pairs are made on the workers, only their count
comes back), after a warm-up run. Also: one process without Dask (RegionLayer.locate) on 1 and 2
threads, and the workers' CPU time (time.process_time summed over the workers), whose ratio says
what two idle cores would give when the machine is shared.
"""

import argparse
import datetime
import pathlib
import subprocess
import sys
import time

import numpy as np

import contain
import contain.dask

PROJECT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(PROJECT / "bench/python"))
sys.path.insert(0, str(PROJECT / "scenes"))
from dask_locate_bench import best_of, load, machine, settled  # noqa: E402
import gis_layers  # noqa: E402


def scale(block):
    return block * np.array([360.0, 180.0]) - np.array([180.0, 90.0])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--points", type=int, default=20_000_000)
    parser.add_argument("--chunk", type=int, default=500_000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--out")
    args = parser.parse_args()

    import dask.array as da
    import distributed

    layer_path = str(gis_layers.countries())
    layer = contain.RegionLayer.from_file(layer_path)
    lines = []

    def say(text=""):
        print(text, flush=True)
        lines.append(text)

    commit = subprocess.run(["git", "-C", str(PROJECT), "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    say("# PYTHONPATH=build/release/python /usr/bin/python3 bench/python/dask_layer_bench.py " + " ".join(sys.argv[1:]))
    say(f"# machine: {machine()}; shared machine, load average at start: {load()}")
    say(f"# {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%dT%H:%M:%SZ}, commit {commit}, "
        f"dask {__import__('dask').__version__}, distributed {distributed.__version__}")
    say(f"layer naturalearth_lowres: {len(layer)} regions, {layer.stats['edges']} edges; {args.points:,} points "
        f"uniform over the world, chunks of {args.chunk:,}; best of {args.repeat}")
    local = scale(np.random.default_rng(1).uniform(size=(min(args.points, 5_000_000), 2)))
    for threads in (1, 2):
        seconds, _ = best_of(args.repeat, lambda: layer.locate(local, threads=threads))
        say(f"  one process, no Dask, {threads} thread{'s' if threads > 1 else ' '}      "
            f"{len(local) / seconds / 1e6:7.2f} M points/s")
    rates, cpu_rates = {}, {}
    for workers in args.workers:
        cluster = distributed.LocalCluster(n_workers=workers, processes=True, threads_per_worker=1,
                                           host="127.0.0.1", dashboard_address=None)
        with distributed.Client(cluster) as client:
            unit = da.random.RandomState(5).uniform(size=(args.points, 2), chunks=(args.chunk, 2))
            points = client.persist(unit.map_blocks(scale, dtype=np.float64))
            distributed.wait(points)
            client.rebalance(points)
            held = sorted(client.run(lambda dask_worker: len(dask_worker.data)).values())
            task = lambda: len(contain.dask.join_layer(points, layer_path))  # noqa: E731
            keep = client.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks))
            wait = settled(client, keep)
            wait()
            start = time.perf_counter()
            pairs = task()
            warm = time.perf_counter() - start
            runs = []
            for _ in range(args.repeat):
                wait()
                before = client.run(time.process_time)
                start = time.perf_counter()
                again = task()
                wall = time.perf_counter() - start
                after = client.run(time.process_time)
                runs.append((wall, sum(after[w] - before[w] for w in after)))
                assert again == pairs
            seconds, cpu = min(runs)
            builds = client.run(contain.dask.index_builds)
            rates[workers] = args.points / seconds
            cpu_rates[workers] = args.points / cpu
            say(f"  Dask, {workers} worker process{'es' if workers > 1 else '  '} x 1 thread  "
                f"{rates[workers] / 1e6:7.2f} M points/s  ({seconds:.2f} s wall, workers' CPU {cpu:.2f} s = "
                f"{cpu / seconds / workers:.0%} of {workers} core{'s' if workers > 1 else ''}; first run {warm:.2f} s; "
                f"layer builds per worker {sorted(builds.values())}; chunks held per worker {held}; pairs {pairs:,})")
        cluster.close()
    if 1 in rates and 2 in rates:
        say(f"  speed-up 2 workers / 1 worker: x{rates[2] / rates[1]:.2f} wall-clock; points per worker "
            f"CPU-second {cpu_rates[1] / 1e6:.2f} M (1 worker) and {cpu_rates[2] / 1e6:.2f} M (2 workers): "
            f"x{2 * cpu_rates[2] / cpu_rates[1]:.2f} on two idle cores")
    say(f"# load average at end: {load()}")
    if args.out:
        pathlib.Path(args.out).write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
