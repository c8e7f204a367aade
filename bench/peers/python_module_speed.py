#!/usr/bin/python3
"""The Python module `quadmc` timed against scipy.stats.qmc and against its own C++, in one
interpreter, for bench/peers/quadmc_peers (python_module_speed.hpp).

Use:   PYTHONPATH=build/<preset>/python /usr/bin/python3 bench/peers/python_module_speed.py \
           ROUNDS SEED
Needs: the module built in that folder (bench/python/), Debian's python3-numpy and python3-scipy.
Does:  two groups of contenders, each run ROUNDS times in alternating rounds (every contender once
       per round, in a fixed order, so that a burst of load on the shared machine hits them all),
       timed with time.perf_counter around the call alone (the interpreter start and the imports
       are not timed; the previous result is released before the clock starts):
  points (s = 8, N = 2^20 points, 64 MiB of float64):
    quadmc_points   quadmc.points("sobol", N, 8, seed=SEED, randomization="lms_shift")
    scipy_points    scipy.stats.qmc.Sobol(8, scramble=True, seed=SEED).random(N)
    numpy_ones      numpy.ones((N, 8)): allocating and writing a fresh 64 MiB array once, which
                    both results above pay too (their first touch of each page)
  points_reused: the same three calls, after glibc's malloc is told to keep what is freed
                    (mallopt: M_MMAP_MAX = 0, so no block is mmapped, M_TRIM_THRESHOLD = 2^30,
                    so the heap is never given back): from the second call on, each result lands
                    in memory the previous one used, and no page is touched for the first time.
                    Fresh minus reused is what the first touch of 64 MiB cost each of them (with
                    glibc's defaults every 64 MiB block is a new mmap: above its 32 MiB
                    M_MMAP_THRESHOLD ceiling). Run last: the setting stays for the process.
  integrand (genz_gaussian in s = 8, plain_mc at N = 2^20, one thread):
    integrate_catalogue  quadmc.integrate(quadmc.integrand("genz_gaussian", ...), threads=1)
    integrate_numpy      quadmc.integrate(f, s=8) with f the same integrand written in numpy
    integrate_ones       quadmc.integrate(g, s=8) with g returning numpy.ones(m): the calls alone
    numpy_all            f on 2^20 points in one call (no quadmc.integrate)
    numpy_batches        f on the same points in the blocks quadmc.integrate calls f on: 86
                         calls, 85 of 12288 points (a Monte Carlo chunk) and one of 4096
    catalogue_batches    the catalogue Integrand on the same blocks (C++ batch evaluate)
Prints: a line "# versions: numpy V, scipy V" and then one tab-separated line per contender:
       group key s n median min max rounds cores, times in seconds; cores = process CPU time /
       wall time over its rounds (time.process_time, every thread of the process).
Exit:  0 done, 2 bad arguments, 3 the module, numpy or scipy missing (one line on stderr).
"""

import statistics
import sys
import time

S = 8
N = 2**20
# The blocks quadmc.integrate calls a callable on for plain_mc at s = 8: one per Monte Carlo chunk
# of 12288 points (lib/include/quadmc/core/batching.hpp; bench/python/integrate.cpp).
BATCH = 12288
# genz_gaussian's parameters, fixed so that the numpy twin and the catalogue compute the same f.
A = [1.0, 2.0, 0.5, 1.5, 0.75, 1.25, 0.9, 1.1]
U = [0.3, 0.6, 0.45, 0.2, 0.7, 0.5, 0.35, 0.8]


def points_group(quadmc, np, qmc, seed):
    def quadmc_points():
        return quadmc.points("sobol", N, S, seed=seed, randomization="lms_shift")

    def scipy_points():
        return qmc.Sobol(S, scramble=True, seed=seed).random(N)

    def numpy_ones():
        return np.ones((N, S))

    return [("quadmc_points", quadmc_points), ("scipy_points", scipy_points),
            ("numpy_ones", numpy_ones)]


def keep_freed_memory():
    """Asks glibc's malloc never to mmap a block nor to trim the heap (mallopt(3))."""
    import ctypes
    libc = ctypes.CDLL(None)
    m_trim_threshold, m_mmap_max = -1, -4  # <malloc.h>
    if libc.mallopt(m_mmap_max, 0) != 1 or libc.mallopt(m_trim_threshold, 2**30) != 1:
        raise RuntimeError("mallopt refused M_MMAP_MAX = 0 or M_TRIM_THRESHOLD = 2^30")


def integrand_group(quadmc, np, seed):
    a = np.array(A)
    u = np.array(U)
    a2 = a * a

    def gaussian(x):
        # genz_gaussian: exp(−Σ_j a_j² (x_j − u_j)²), functions/genz.hpp; the numpy a user writes.
        d = x - u
        return np.exp(-(d * d) @ a2)

    def ones(x):
        return np.ones(len(x))

    catalogue = quadmc.integrand("genz_gaussian", s=S, a=A, u=U)
    x = quadmc.points("independent", N, S, seed=seed)

    def integrate_catalogue():
        return quadmc.integrate(catalogue, "plain_mc", N, seed=seed, threads=1)

    def integrate_numpy():
        return quadmc.integrate(gaussian, "plain_mc", N, s=S, seed=seed)

    def integrate_ones():
        return quadmc.integrate(ones, "plain_mc", N, s=S, seed=seed)

    def numpy_all():
        return gaussian(x)

    def numpy_batches():
        for first in range(0, N, BATCH):
            y = gaussian(x[first:first + BATCH])
        return y

    def catalogue_batches():
        for first in range(0, N, BATCH):
            y = catalogue(x[first:first + BATCH])
        return y

    # The twin is the catalogue's integrand: the same values to a few ulp (numpy's exp, and the
    # order of its sum, against the library's), else the comparison would be of two functions.
    both = gaussian(x[:BATCH]), catalogue(x[:BATCH])
    if not np.allclose(both[0], both[1], rtol=1e-13, atol=0):
        raise RuntimeError("the numpy genz_gaussian differs from the catalogue's")
    return [("integrate_catalogue", integrate_catalogue), ("integrate_numpy", integrate_numpy),
            ("integrate_ones", integrate_ones), ("numpy_all", numpy_all),
            ("numpy_batches", numpy_batches), ("catalogue_batches", catalogue_batches)]


def rounds_of(contenders, rounds):
    walls = {key: [] for key, _ in contenders}
    cpus = {key: 0.0 for key, _ in contenders}
    for k in range(rounds + 1):
        for key, fn in contenders:
            result = None  # noqa: F841 (the previous result is released before the clock starts)
            cpu = time.process_time()
            start = time.perf_counter()
            result = fn()  # noqa: F841
            if k > 0:  # round 0 warms up (code, tables, and in points_reused the heap)
                walls[key].append(time.perf_counter() - start)
                cpus[key] += time.process_time() - cpu
    return walls, cpus


def main(argv):
    if len(argv) != 3 or not argv[1].isdigit() or not argv[2].isdigit() or int(argv[1]) < 1:
        print("usage: python_module_speed.py ROUNDS SEED", file=sys.stderr)
        return 2
    rounds, seed = int(argv[1]), int(argv[2])
    try:
        import numpy as np
        import quadmc
        import scipy
        from scipy.stats import qmc
    except ImportError as e:
        print(f"python_module_speed.py: {e} (PYTHONPATH must name the module's folder, "
              "build/<preset>/python; numpy and scipy: python3-numpy, python3-scipy)",
              file=sys.stderr)
        return 3
    print(f"# versions: numpy {np.__version__}, scipy {scipy.__version__}")
    groups = [("integrand", integrand_group(quadmc, np, seed)),
              ("points", points_group(quadmc, np, qmc, seed)),
              ("points_reused", None)]
    for group, contenders in groups:
        if contenders is None:
            keep_freed_memory()
            contenders = points_group(quadmc, np, qmc, seed)
        walls, cpus = rounds_of(contenders, rounds)
        for key, _ in contenders:
            w = walls[key]
            print("\t".join([group, key, str(S), str(N), repr(statistics.median(w)), repr(min(w)),
                             repr(max(w)), str(rounds), repr(cpus[key] / sum(w))]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
