"""quadmc.integrate: one method of the registry on one integrand at one N, as a scene's cell.

The C++ half is _quadmc._integrate (bench/python/integrate.cpp: the callable wrapper, threads and
streams); this half names the defaults and folds the repetitions into one result.
"""
import math
from dataclasses import dataclass, field

from ._quadmc import Integrand, _integrate


@dataclass(frozen=True)
class Integration:
    """What quadmc.integrate returns.

    value: the mean of the repetitions' estimates (`values`, in repetition order).
    std_error: its standard error: from each repetition's own std_error, sqrt(sum se_r^2)/R, for
        a method that estimates its own (plain Monte Carlo); from the spread of the repetitions,
        sd(values)/sqrt(R), for randomized quasi-Monte Carlo, whose error bars are replicates
        (docs/theory.md#replicate-error-bars); NaN where there is none (a rule; one replicate).
    error_estimate: the method's own error estimate folded as std_error (own) or equal to it
        (replicates); NaN where the method has none.
    evaluations, seconds: totals over the repetitions.
    """
    value: float
    std_error: float
    error_estimate: float
    evaluations: int
    seconds: float
    method: str
    n: int
    values: list = field(default_factory=list)


def _root_sum_of_squares_over(values, count):
    return math.sqrt(math.fsum(v * v for v in values)) / count


def _replicate_std_error(values):
    r = len(values)
    if r < 2:
        return math.nan
    mean = math.fsum(values) / r
    return math.sqrt(math.fsum((v - mean) ** 2 for v in values) / (r - 1) / r)


def _fold(done):
    values = done["values"]
    r = len(values)
    if done["replicates"]:
        std_error = _replicate_std_error(values)
        error_estimate = std_error
    else:
        std_error = _root_sum_of_squares_over(done["std_errors"], r)
        error_estimate = _root_sum_of_squares_over(done["error_estimates"], r)
    return Integration(value=math.fsum(values) / r, std_error=std_error,
                       error_estimate=error_estimate, evaluations=sum(done["evaluations"]),
                       seconds=math.fsum(done["seconds"]), method=done["method"], n=done["n"],
                       values=list(values))


def integrate(f, method, n, s=None, seed=0, repetitions=1, threads=0, name=None,
              rng="philox4x32_10", **options):
    """Integrates f with `method` (a name of quadmc.methods()) at N = n, as a scene's cell.

    f: a quadmc.Integrand (quadmc.integrand(...)), or any callable taking an (m, s) float64 array
        of points in [0, 1]^s and returning m values; s is then required. A callable runs on one
        thread, called once per batch of 256 points with the GIL held; an Integrand runs on
        `threads` (0: all cores) with the GIL released. Results do not depend on threads.
    n: N as a scene's budget.N, mapped to the method's size (ValueError with the reason when it
        cannot be). options: the method's [[method]] keys (strings, numbers, bools, lists, dicts).
    repetitions: independent runs of a randomized method (a deterministic one runs once).
    seed, name: repetition r uses the stream a scene with this seed gives the cell of integrand
        `name` (default "<family>_s<s>", the name of a scene's [[integrand]] with dimension = s;
        "python_s<s>" for a callable), the method's default label, budget.N = n, repetition r:
        the same arguments give the same bits.
    rng: the generator of the method's random numbers, "philox4x32_10" (Philox4x32-10, the
        default) or "ars4x32_7" (ARS-4x32-7), as a scene's top-level rng: the same seed gives
        other values under the other. A catalogue Integrand's own random parameters are drawn
        when quadmc.integrand makes it, by Philox under both. ValueError naming rng otherwise.
    """
    if name is None:
        if isinstance(f, Integrand):
            name = f"{f.name}_s{f.dimension}"
        else:
            name = f"python_s{s}"
    done = _integrate(f, method, n, s, seed, repetitions, threads, str(name), rng, options)
    return _fold(done)
