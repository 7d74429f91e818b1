#!/usr/bin/env python3
"""Time scipy.stats.qmc.PoissonDisk(radius=r).fill_space() against
poissondisk.qmc.PoissonDisk(radius=r).fill_space(), same radius, same process.

    POISSONDISK_LIBRARY=$PWD/build/libpoissondisk.so.1 PYTHONPATH=bindings/python \\
        /usr/bin/python3 bindings/python/benchmarks/compare_scipy.py [--repeats K] [N ...]

For each target N (default 10^4 and 10^5) the radius is r = sqrt(0.62 / N), at
which scipy's (Bridson) fill of the unit square gives about N points; ours, being
maximal, gives about 17% more at the same radius. Seeds 1..K for both; each time
covers making the engine and fill_space(). Prints one line per method and size
(median and range of the times, mean count) and the ratio of the medians.
A benchmark, not a test: the figures move with the machine's load.
"""

import argparse
import math
import statistics
import time

import numpy as np
from scipy.stats import qmc as scipy_qmc
import scipy

import poissondisk
from poissondisk import qmc


def fill(cls, r, seed):
    t0 = time.perf_counter()
    pts = cls(2, radius=r, seed=seed).fill_space()
    return time.perf_counter() - t0, pts


def min_pair_distance(pts):
    """The smallest pair distance (a k-d tree; not timed)."""
    from scipy.spatial import cKDTree
    d, _ = cKDTree(pts).query(pts, k=2)
    return float(d[:, 1].min())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("sizes", nargs="*", type=int, default=[10 ** 4, 10 ** 5])
    args = ap.parse_args()
    print("numpy %s, scipy %s, poissondisk %s (library %s)"
          % (np.__version__, scipy.__version__, poissondisk.__version__, poissondisk.version()))
    print("%-11s %8s %9s %10s %10s %21s %9s" % ("method", "target", "radius", "points",
                                               "median s", "range s", "min d/r"))
    for n in args.sizes:
        r = math.sqrt(0.62 / n)
        medians = {}
        for name, cls in (("scipy", scipy_qmc.PoissonDisk), ("poissondisk", qmc.PoissonDisk)):
            times, counts, mind = [], [], math.inf
            for seed in range(1, args.repeats + 1):
                t, pts = fill(cls, r, seed)
                times.append(t)
                counts.append(len(pts))
                mind = min(mind, min_pair_distance(pts) / r)
            medians[name] = statistics.median(times)
            print("%-11s %8d %9.6f %10.1f %10.3f %10.3f-%-10.3f %9.6f"
                  % (name, n, r, statistics.mean(counts), medians[name], min(times),
                     max(times), mind))
        print("%-11s %8d  scipy / poissondisk time: %.1fx"
              % ("", n, medians["scipy"] / medians["poissondisk"]))


if __name__ == "__main__":
    main()
