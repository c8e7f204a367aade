#!/usr/bin/python3
"""Checks the results of bench/examples/own_integrand's scene (./run.sh consumer runs it).

The outside project's integrands, method and computed reference, each against a value derived
here independently of quadmc:
  - sum_squared, s = 3: the reference is the family's exact value s/3 + s(s − 1)/4 = 5/2, and
    Simpson, exact on polynomials of degree ≤ 3, reaches it to rounding (|error| ≤ 1e-14);
  - gaussian_of_sum, s = 2: no exact value in the family; the plan's computed reference must
    agree with the one-dimensional form of the integral over t = x₁ + x₂ (triangular density):
      ∫₀¹ t e^(−t²/2) dt + ∫₁² (2 − t) e^(−t²/2) dt
      = (1 − e^(−1/2)) + 2√(π/2)(erf(√2) − erf(1/√2)) − (e^(−1/2) − e^(−2)),
    within 1e-12 relative (its stated uncertainty is below that);
  - antithetic_mc ran on both, every cell, with a finite error.
Usage: check_own_integrand.py RESULTS_FOLDER; exits 1 naming the first check that fails.
"""
import csv
import math
import sys


def fail(message):
    print(f"check_own_integrand.py: {message}", file=sys.stderr)
    sys.exit(1)


def main():
    with open(f"{sys.argv[1]}/convergence.csv", newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    by = {}
    for r in rows:
        by.setdefault((r["integrand"], r["method"]), []).append(r)

    exact = 3 / 3 + 3 * 2 / 4
    simpson = by.get(("sum_squared_s3", "simpson")) or fail("no simpson × sum_squared_s3 rows")
    for r in simpson:
        if float(r["reference"]) != exact:
            fail(f"sum_squared_s3: reference {r['reference']}, expected {exact}")
        if abs(float(r["estimate_mean"]) - exact) > 1e-14 * exact:
            fail(f"sum_squared_s3: Simpson at N = {r['N']} gives {r['estimate_mean']}, "
                 f"expected {exact} to rounding")

    e = math.exp
    closed = (1 - e(-0.5)) + 2 * math.sqrt(math.pi / 2) * (
        math.erf(math.sqrt(2)) - math.erf(1 / math.sqrt(2))) - (e(-0.5) - e(-2))
    gauss = by.get(("gaussian_of_sum_s2", "simpson")) or fail("no gaussian_of_sum_s2 rows")
    computed = float(gauss[0]["reference"])
    if abs(computed - closed) > 1e-12 * closed:
        fail(f"gaussian_of_sum_s2: computed reference {computed!r}, expected {closed!r}")

    for integrand in ("sum_squared_s3", "gaussian_of_sum_s2"):
        runs = by.get((integrand, "antithetic_mc")) or fail(f"no antithetic_mc × {integrand}")
        if len(runs) != 5 or not all(math.isfinite(float(r["rmse"])) for r in runs):
            fail(f"antithetic_mc × {integrand}: expected 5 cells with a finite rmse")
    print(f"own_integrand: sum_squared exact {exact} (Simpson to rounding), gaussian_of_sum "
          f"computed reference {computed!r} = closed form {closed!r}: ok")


if __name__ == "__main__":
    main()
