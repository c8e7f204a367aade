#!/usr/bin/python3
"""scipy's qmc_quad as a scene method's peer (peer_scipy_qmc_quad, peer_scene_methods.cpp).

Use:   started once per run by quadmc_with_peers, PYTHONPATH = the quadmc module's folder:
         /usr/bin/python3 bench/peers/scipy_qmc_quad.py
Needs: Debian's python3-scipy (scipy 1.10: qmc_quad is scipy.integrate._quadrature._qmc_quad
       there, public as scipy.integrate.qmc_quad from scipy 1.11) and the quadmc module.
Does:  prints "ready scipy <version>" once scipy and quadmc import, then answers one request per
       line on stdin, a JSON object
         {"family", "s", "seed", "scalars", "vectors", "strings": the instance's parameters,
          "n_points", "n_estimates", "qrng_seed"}
       with one line
         ok <integral> <standard_error> <evaluations> <exact>
       (Python's shortest round-trip reprs): qmc_quad of the same catalogue instance
       (quadmc.integrand with those parameters) over its domain, with n_estimates estimates of
       n_points scrambled Sobol' points each (scipy.stats.qmc.Sobol, scramble=True, seeded by
       qrng_seed), every evaluation counted (qmc_quad's own checks of the integrand included);
       <exact> lets the caller check that the instance is the one it built. A request that
       fails gets "error <one line>"; end of input ends the process.
Exit:  0 at end of input, 3 when scipy or quadmc does not import (one line on stdout).
"""

import json
import sys


def main():
    try:
        import numpy as np
        import scipy
        from scipy.stats import qmc
        try:
            from scipy.integrate import qmc_quad  # scipy >= 1.11: func takes x of shape (d, n)
            points_first = False
        except ImportError:
            from scipy.integrate._quadrature import _qmc_quad as qmc_quad  # 1.10: (n, d)
            points_first = True
        import quadmc
    except ImportError as e:
        print(f"error cannot import ({e}): install python3-scipy and build the quadmc module",
              flush=True)
        return 3
    print(f"ready scipy {scipy.__version__}", flush=True)

    for line in sys.stdin:
        try:
            r = json.loads(line)
            params = {**r["scalars"], **r["vectors"], **r["strings"]}
            f = quadmc.integrand(r["family"], s=r["s"], seed=r["seed"], **params)
            s = f.dimension
            evaluations = 0

            def func(x):
                # Rows of points for the quadmc integrand, whichever layout this scipy passes;
                # qmc_quad also calls it on one point (a 1D array) to check it.
                nonlocal evaluations
                x = np.asarray(x, dtype=np.float64)
                if x.ndim == 1:
                    x = x.reshape(1, s)
                elif not points_first:
                    x = x.T
                x = np.ascontiguousarray(x)
                evaluations += x.shape[0]
                y = f(x)
                bad = ~np.isfinite(y)
                if bad.any():  # named, as the suite's own kernels name a non-finite value
                    i = int(np.argmax(bad))
                    raise ValueError(f"{f.name} is {y[i]!r} at x = {x[i].tolist()!r}")
                return y

            lower = [a for a, _ in f.domain]
            upper = [b for _, b in f.domain]
            engine = qmc.Sobol(d=s, scramble=True, seed=np.random.default_rng(r["qrng_seed"]))
            result = qmc_quad(func, lower, upper, n_points=r["n_points"],
                              n_estimates=r["n_estimates"], qrng=engine)
            print(f"ok {float(result.integral)!r} {float(result.standard_error)!r} "
                  f"{evaluations} {float(f.exact)!r}", flush=True)
        except Exception as e:  # one failed request, named; the next one is served
            message = " ".join(str(e).split())
            print(f"error {type(e).__name__}: {message}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
