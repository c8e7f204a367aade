"""bench/examples/python_tour.py, run as the README says a new user runs it: it finishes, writes
its plot, and its numpy integrand gives the catalogue integrand's estimate (the line it prints)."""
import os
import re
import subprocess
import sys

SOURCE_DIR = os.path.join(os.path.dirname(__file__), "..", "..")


def test_the_tour_runs_and_writes_its_plot(tmp_path):
    tour = os.path.join(SOURCE_DIR, "bench", "examples", "python_tour.py")
    done = subprocess.run([sys.executable, tour, str(tmp_path)], capture_output=True, text=True,
                          check=False, env=dict(os.environ, MPLBACKEND="Agg"))
    assert done.returncode == 0, done.stderr
    plot = tmp_path / "error_vs_n.png"
    assert plot.stat().st_size > 0
    # The same function, points and summation order: the same estimate to every printed digit.
    match = re.search(r"numpy (\S+) ± \S+, catalogue (\S+),", done.stdout)
    assert match, done.stdout
    assert match.group(1) == match.group(2)
    for method in ("plain_mc", "sobol", "simpson"):
        assert re.search(rf"^{method} +slope ", done.stdout, re.M), done.stdout
