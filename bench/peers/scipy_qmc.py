#!/usr/bin/python3
"""scipy.stats.qmc point generation for bench/peers/quadmc_peers (qmc_point_peers.hpp).

Use:   /usr/bin/python3 bench/peers/scipy_qmc.py ENGINE S N SEED RUNS [points]
       ENGINE: sobol_scrambled | sobol | halton_scrambled | halton
Needs: Debian's python3-scipy (scipy 1.10) and python3-numpy.
Does:  RUNS times, builds the engine (scipy.stats.qmc.Sobol / Halton with the scramble asked for,
       seed SEED) and draws N points in S dimensions with engine.random(N), which allocates and
       fills an N x S float64 array: the same work as the C++ generators (set-up included). Prints
       the best run's seconds (time.perf_counter around engine construction and random(N); the
       interpreter start and the scipy import are not timed) and a checksum over the first and
       last point; with `points`, then every point of the last run as float.hex, one per line,
       so the C++ side can compare bits.
Exit:  0 done, 2 bad arguments, 3 scipy missing (one line on stderr).
"""

import sys
import time


def main(argv):
    if len(argv) not in (6, 7) or (len(argv) == 7 and argv[6] != "points"):
        print("usage: scipy_qmc.py ENGINE S N SEED RUNS [points]", file=sys.stderr)
        return 2
    engine, s, n, seed, runs = argv[1], int(argv[2]), int(argv[3]), int(argv[4]), int(argv[5])
    if engine not in ("sobol_scrambled", "sobol", "halton_scrambled", "halton") or s < 1 \
            or n < 1 or runs < 1:
        print(f"scipy_qmc.py: bad arguments {argv[1:]}", file=sys.stderr)
        return 2
    try:
        from scipy.stats import qmc
    except ImportError as e:
        print(f"scipy_qmc.py: cannot import scipy.stats.qmc ({e}): install python3-scipy",
              file=sys.stderr)
        return 3
    scramble = engine.endswith("_scrambled")
    kind = qmc.Sobol if engine.startswith("sobol") else qmc.Halton
    best = float("inf")
    points = None
    for _ in range(runs):
        points = None  # the previous array is released before the clock starts
        start = time.perf_counter()
        points = kind(d=s, scramble=scramble, seed=seed).random(n)
        best = min(best, time.perf_counter() - start)
    checksum = float(points[0].sum() + points[-1].sum())
    print(f"{best!r} {checksum!r}")
    if len(argv) == 7:
        out = sys.stdout
        for p in points:
            out.write(" ".join(float(v).hex() for v in p))
            out.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
