#!/usr/bin/python3
"""Points per second of contain.dask.locate on 1 and 2 Dask worker processes, and the speed-up.

Run with Debian's python3 and the module on PYTHONPATH (the build tree's python/ or an
installed prefix), from the project root:

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python/dask_locate_bench.py \
        --out bench/results/debian12-2core/dask_locate.txt

Scene: the armadillo of ../shared/corpus/meshes (86,482 triangles, closed) when ../shared is
there, else a built-in torus; points uniform in the mesh's box padded by 10%, generated on the
workers by dask.array.random, persisted and rebalanced there before timing (so the timed part is the
classification, the scheduling and the reduction, not the data's transfer). Each cluster is a
distributed.LocalCluster of n worker processes with one thread each on 127.0.0.1; each chunk is
classified on one thread (contain.dask's default). Timed: the fastest of --repeat runs of
(contain.dask.locate(points, mesh) == inside).sum().compute(), after a warm-up run in which each
worker builds its index (once; its time is reported apart). Also reported, without Dask: one
process on 1 and 2 threads (MeshIndex.locate), the ceiling that the workers approach.

The machine may be shared: the load average is printed, and the workers' CPU time
(time.process_time in each worker, summed) beside the wall-clock time. Points per worker
CPU-second do not depend on what else runs; twice the 2-worker figure over the 1-worker figure
is the speed-up two idle cores would give (the wall-clock speed-up is what this run got).
"""

import argparse
import datetime
import os
import pathlib
import platform
import subprocess
import sys
import time

import numpy as np

import contain
import contain.dask

PROJECT = pathlib.Path(__file__).resolve().parents[2]


def machine():
    model = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{os.cpu_count()}-core {platform.machine()} ({model}), {platform.platform()}, Python {platform.python_version()}"


def load():
    return " ".join(f"{value:.2f}" for value in os.getloadavg())


def scene(args):
    armadillo = PROJECT.parent / "shared/corpus/meshes/armadillo.obj"
    if args.mesh:
        path = pathlib.Path(args.mesh)
    elif armadillo.exists():
        path = armadillo
    else:
        sys.path.insert(0, str(PROJECT / "tests/python"))
        from meshes import torus

        path = pathlib.Path("/tmp/contain_bench_torus.ply")
        contain.write_mesh(torus(rings=256, sides=128), path)
    return path


def scale(block, offset, span):
    return block * np.array(span) + np.array(offset)


def best_of(repeat, run, settle=lambda: None):
    times = []
    result = None
    for _ in range(repeat):
        settle()
        start = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - start)
    return min(times), result


def settled(client, keep):
    """Waits until the scheduler holds only the persisted points: a repeated graph has the same
    keys, and results still held from the previous run would be reused instead of computed."""

    def wait():
        while client.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks)) > keep:
            time.sleep(0.02)

    return wait


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--points", type=int, default=20_000_000)
    parser.add_argument("--chunk", type=int, default=500_000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--mesh", help="a mesh file (default: the armadillo of ../shared)")
    parser.add_argument("--out", help="also write the report to this file")
    args = parser.parse_args()

    import dask.array as da
    import distributed

    path = scene(args)
    index = contain.MeshIndex.from_file(path)
    low, high = index.bounds
    pad = 0.1 * (high - low)
    lines = []

    def say(text=""):
        print(text, flush=True)
        lines.append(text)

    commit = subprocess.run(["git", "-C", str(PROJECT), "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    say("# PYTHONPATH=build/release/python /usr/bin/python3 bench/python/dask_locate_bench.py "
        + " ".join(sys.argv[1:]))
    say(f"# machine: {machine()}; shared machine, load average at start: {load()}")
    say(f"# {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%dT%H:%M:%SZ}, commit {commit}, "
        f"dask {__import__('dask').__version__}, distributed {distributed.__version__}, numpy {np.__version__}")
    say(f"mesh {path.name}: {index.stats['triangles']} triangles, {index.regime}; "
        f"{args.points:,} points uniform in its box + 10%, chunks of {args.chunk:,}; best of {args.repeat}")

    local = np.random.default_rng(1).uniform(low - pad, high + pad, (min(args.points, 5_000_000), 3))
    for threads in (1, 2):
        seconds, _ = best_of(args.repeat, lambda: index.locate(local, threads=threads))
        say(f"  one process, no Dask, {threads} thread{'s' if threads > 1 else ' '}      "
            f"{len(local) / seconds / 1e6:7.2f} M points/s")

    rates = {}
    cpu_rates = {}
    for workers in args.workers:
        cluster = distributed.LocalCluster(n_workers=workers, processes=True, threads_per_worker=1,
                                           host="127.0.0.1", dashboard_address=None)
        with distributed.Client(cluster) as client:
            # Bounds as plain floats inside each task: numpy arrays as arguments would become graph
            # keys that every chunk depends on, and the scheduler would then put every chunk on the
            # worker holding them. Rebalanced after persisting, so each worker holds its share.
            unit = da.random.RandomState(5).uniform(size=(args.points, 3), chunks=(args.chunk, 3))
            points = unit.map_blocks(scale, dtype=np.float64,
                                     offset=tuple(float(v) for v in low - pad),
                                     span=tuple(float(v) for v in high - low + 2 * pad))
            points = client.persist(points)
            distributed.wait(points)
            client.rebalance(points)
            held = sorted(client.run(lambda dask_worker: len(dask_worker.data)).values())
            task = lambda: int((contain.dask.locate(points, path) == 1).sum().compute())  # noqa: E731
            keep = client.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks))
            wait = settled(client, keep)
            wait()
            start = time.perf_counter()
            inside = task()
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
                assert again == inside
            seconds, cpu = min(runs)
            builds = client.run(contain.dask.index_builds)
            rates[workers] = args.points / seconds
            cpu_rates[workers] = args.points / cpu
            say(f"  Dask, {workers} worker process{'es' if workers > 1 else '  '} x 1 thread  "
                f"{rates[workers] / 1e6:7.2f} M points/s  ({seconds:.2f} s wall, workers' CPU "
                f"{cpu:.2f} s = {cpu / seconds / workers:.0%} of {workers} core{'s' if workers > 1 else ''}; "
                f"first run with index builds {warm:.2f} s; builds per worker "
                f"{sorted(builds.values())}; chunks held per worker {held}; inside {inside:,})")
        cluster.close()
    if 1 in rates and 2 in rates:
        say(f"  speed-up 2 workers / 1 worker: x{rates[2] / rates[1]:.2f} wall-clock; points per "
            f"worker CPU-second {cpu_rates[1] / 1e6:.2f} M (1 worker) and {cpu_rates[2] / 1e6:.2f} M "
            f"(2 workers): x{2 * cpu_rates[2] / cpu_rates[1]:.2f} on two idle cores")
    say(f"# load average at end: {load()}")
    if args.out:
        pathlib.Path(args.out).write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
