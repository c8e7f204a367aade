#!/usr/bin/python3
"""A tour of `import quadmc` (README, Python): points, a Python integrand beside the catalogue's,
a scene run, and a plot of error against N.

    PYTHONPATH=build/test/python /usr/bin/python3 bench/examples/python_tour.py [OUT_FOLDER]

Writes OUT_FOLDER/error_vs_n.png (default results/python_tour/) and prints what it computed. Each
step is the suite's own: the same numbers as `quadmc points`, the catalogue's Genz Gaussian and
`quadmc run`, from the same seeds.
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import quadmc

# 1. Points: a scrambled Sobol' set and independent points, and how uniform each is.
sobol = quadmc.points("sobol", 1024, 2, seed=7, randomization="owen")
independent = quadmc.points("independent", 1024, 2, seed=7)
for name, x in (("sobol", sobol), ("independent", independent)):
    print(f"{name:12s} N = 1024, s = 2: L2-star discrepancy "
          f"{quadmc.discrepancy(x, 'l2_star'):.2e}")

# 2. A Python integrand beside the catalogue's: Genz's Gaussian exp(−Σ aⱼ²(xⱼ − uⱼ)²) written in
# numpy, integrated by plain Monte Carlo on the stream the catalogue entry gets.
a, u = [2.0, 1.0, 0.5], [0.3, 0.6, 0.9]
catalogue = quadmc.integrand("genz_gaussian", s=3, a=a, u=u)


def gaussian(x):
    return np.exp(-np.sum((np.asarray(a) * (x - np.asarray(u))) ** 2, axis=1))


mine = quadmc.integrate(gaussian, "plain_mc", 2**16, s=3, seed=1, name="genz_gaussian_s3")
theirs = quadmc.integrate(catalogue, "plain_mc", 2**16, seed=1)
print(f"plain_mc, N = 2^16: numpy {mine.value:.15f} ± {mine.std_error:.1e}, catalogue "
      f"{theirs.value:.15f}, exact {catalogue.exact:.15f}")

# 3. A scene as a dict: three methods on the same integrand, N from 2^6 to 2^16.
scene = {
    "name": "python_tour",
    "seed": 1,
    "integrand": [{"family": "genz_gaussian", "dimension": 3, "a": a, "u": u}],
    "method": [{"name": "plain_mc", "repetitions": 16},
               {"name": "sobol", "repetitions": 16},
               {"name": "simpson"}],
    "budget": {"N": [2**k for k in range(6, 17, 2)]},
    "output": {"plots": False},
}
results = quadmc.run(scene)
for row in results.slopes:
    theory = "none" if row["theory"] is None else f"{row['theory']:+.2f}"
    print(f"{row['method']:10s} slope {row['slope']:+.2f} (theory {theory}): {row['verdict']}")

# 4. Error against N, one line per method, from the run's convergence rows.
fig, ax = plt.subplots(figsize=(6, 4))
for method in ("plain_mc", "sobol", "simpson"):
    rows = [r for r in results.convergence if r["method"] == method]
    ax.loglog([r["evaluations"] for r in rows], [r["rmse"] for r in rows], "o-", label=method)
ax.set_xlabel("N (integrand evaluations)")
ax.set_ylabel("RMSE")
ax.set_title("Genz Gaussian, s = 3 (quadmc.run from Python)")
ax.legend()
ax.grid(True, which="both", alpha=0.3)
out = sys.argv[1] if len(sys.argv) > 1 else os.path.join("results", "python_tour")
os.makedirs(out, exist_ok=True)
fig.savefig(os.path.join(out, "error_vs_n.png"), dpi=100, bbox_inches="tight")
print(f"wrote {os.path.join(out, 'error_vs_n.png')}")
