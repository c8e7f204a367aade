"""quadmc from Python: the suite's point sets, discrepancies, integrands and methods as numpy.

    import quadmc
    x = quadmc.points("sobol", 1024, 3, seed=7, randomization="owen")   # (1024, 3) float64
    quadmc.discrepancy(x, "l2_star")
    f = quadmc.integrand("genz_gaussian", s=3, seed=1)
    f(x).mean() - f.exact
    quadmc.integrate(f, "plain_mc", 2**16, repetitions=8).value        # or f a numpy callable
    quadmc.run("bench/scenes/minimal.toml").write("out")                 # as `quadmc run`

The functions come from the C++ extension _quadmc (bench/python/*.cpp, one file per concept),
built over the library; the points are bitwise those of `quadmc points`, the errors the
library's one-line messages as ValueError. Python-side helpers join this package beside it
(_integrate.py, _run.py, _toml.py).
"""
from ._integrate import Integration, integrate
from ._quadmc import (Integrand, discrepancy, integrand, integrands, methods, point_sets,
                      points)
from ._run import SceneResults, run

__all__ = ["Integrand", "Integration", "SceneResults", "discrepancy", "integrand", "integrands",
           "integrate", "methods", "point_sets", "points", "run"]
