#!/usr/bin/env python3
"""Whole-process point queries and posed mesh pairs beside the peers (issue 27), one thread, paired runs.

  python3 bench/inside/whole_process.py build/bench DATA [--runs 5]

DATA is the folder bench/inside/whole_process_data.py wrote. For each workload, contain inside
(--threads 1) and each peer driver of bench/peers/ (built by the bench preset) run in turn,
A B A B ..., after one warm-up each; each run's wall time is a monotonic clock around the child,
its CPU time and peak memory the kernel's accounting of it (os.wait4). Printed: the medians, and
the median of the pair-by-pair ratios peer / contain (pairing keeps the ratio meaningful when a
shared machine's speed drifts). The answers of contain and of each peer are compared line by
line (peers without 'on' compared on in/out) and the count of differing lines printed.
"""
import argparse
import itertools
import os
import pathlib
import statistics
import subprocess
import tempfile
import time


def run(command, out_path):
    with open(out_path, "wb") as out:
        start = time.monotonic()
        child = subprocess.Popen(command, stdout=out, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(child.pid, 0)
        wall = time.monotonic() - start
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"{command[0]} failed: exit {os.waitstatus_to_exitcode(status)}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0


def differing(a_path, b_path):
    # Line by line, so that this process stays small: a child's peak memory (ru_maxrss) starts
    # from its parent's at the fork.
    fold = {"on": "out"}  # a peer without 'on' says in or out; contain's 'on' compared as out
    count = 0
    with open(a_path) as a, open(b_path) as b:
        for x, y in itertools.zip_longest(a, b):
            if x is None or y is None:
                return "lengths"
            x, y = x.strip(), y.strip()
            count += x != y and fold.get(x, x) != fold.get(y, y)
    return count


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build", type=pathlib.Path)
    parser.add_argument("data", type=pathlib.Path)
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    contain = str(args.build / "contain")
    peers = args.build / "bench" / "peers"
    d = args.data
    workloads = [
        ("10^6 points, 10k-vertex star", ["inside", "--polygon", d / "star10000.wkt", "--points", d / "points2.txt"],
         [("GEOS prepared", "geos_inside", [d / "star10000.wkt", d / "points2.txt"])]),
        ("10^6 points, 100-vertex star", ["inside", "--polygon", d / "star100.wkt", "--points", d / "points2.txt"],
         [("GEOS prepared", "geos_inside", [d / "star100.wkt", d / "points2.txt"])]),
        ("10^6 points, 100k-triangle torus", ["inside", "--mesh", d / "torus.off", "--points", d / "points3.txt"],
         [("Embree 3", "embree_inside", [d / "torus.off", d / "points3.txt"]),
          ("CGAL 5.5", "cgal_inside", [d / "torus.off", d / "points3.txt"])]),
        ("1000 poses, 40k x 20k triangles", ["collide", d / "pair_torus.off", d / "rocker.off", "--poses", d / "poses.txt"],
         [("FCL OBBRSS", "fcl_collide", [d / "pair_torus.off", d / "rocker.off", d / "poses.txt"])]),
    ]
    # Answers in a folder of this run's own: two runs side by side (helpers on one machine) must
    # not write the same files.
    scratch = pathlib.Path(tempfile.mkdtemp(prefix="whole_process_"))
    out_a, out_b = str(scratch / "a.txt"), str(scratch / "b.txt")
    print(f"{'workload':34} {'command':14} {'wall s':>8} {'cpu s':>8} {'peak MB':>8} "
          f"{'peer/contain':>12} {'cpu ratio':>9} {'differ':>8}")
    for name, contain_args, peer_list in workloads:
        if not all(os.path.exists(x) for x in contain_args if isinstance(x, pathlib.Path)):
            print(f"{name:34} data not written")
            continue
        a = [contain, *map(str, contain_args), "--threads", "1"]
        for peer_name, driver, peer_args in peer_list:
            b = [str(peers / driver), *map(str, peer_args)]
            if not os.path.exists(b[0]):
                print(f"{name:34} {peer_name:14} not built")
                continue
            run(a, out_a)
            run(b, out_b)
            ra, rb = [], []
            for _ in range(args.runs):
                ra.append(run(a, out_a))
                rb.append(run(b, out_b))
            ratio = statistics.median(y[0] / x[0] for x, y in zip(ra, rb))
            # CPU seconds: the column to read when other work shares the machine.
            cpu_ratio = statistics.median(y[1] / max(x[1], 1e-3) for x, y in zip(ra, rb))
            diff = differing(out_a, out_b)
            for label, rs, r, c, dd in (("contain", ra, "", "", ""),
                                        (peer_name, rb, f"{ratio:.2f}", f"{cpu_ratio:.2f}", diff)):
                med = [statistics.median(x[k] for x in rs) for k in range(3)]
                print(f"{name:34} {label:14} {med[0]:8.3f} {med[1]:8.3f} {med[2]:8.1f} {r:>12} {c:>9} "
                      f"{dd!s:>8}", flush=True)
    for path in (out_a, out_b):
        if os.path.exists(path):
            os.remove(path)
    scratch.rmdir()


if __name__ == "__main__":
    main()
