"""quadmc.run: a scene (a file, TOML text or a dict) run in the module as `quadmc run` runs it
(bench/python/run.cpp): its results folder equals the command's in every column but timing, its
tables are the CSV files' rows, a bad scene is ValueError with the parser's line, and Ctrl-C stops
a long run with KeyboardInterrupt."""
import csv
import math
import os
import pathlib
import signal
import sys
import threading
import tomllib
import types

import pytest

import quadmc
from quadmc._toml import to_toml

ROOT = pathlib.Path(__file__).resolve().parents[2]
MINIMAL = ROOT / "bench" / "scenes" / "minimal.toml"
# The columns that depend on the machine's load, which bench/same_results.py and
# tests/cli/quadmc_command.hpp (columns_but_timing) leave out of every comparison.
TIMING = {"seconds", "evals_per_second", "seconds_per_estimate", "seconds_spread",
          "timed_estimates"}


def columns_but_timing(path):
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    keep = [i for i, name in enumerate(rows[0]) if name not in TIMING]
    return [[row[i] for i in keep] for row in rows]


@pytest.fixture(scope="module")
def command_folder(command, tmp_path_factory):
    out = tmp_path_factory.mktemp("command") / "minimal"
    done = command("run", str(MINIMAL), "--out", str(out))
    assert done.returncode == 0, done.stderr
    return out


@pytest.fixture(scope="module")
def results():
    return quadmc.run(MINIMAL)


def minimal_as(kind):
    text = MINIMAL.read_text(encoding="utf-8")
    return {"path": str(MINIMAL), "pathlike": MINIMAL, "text": text,
            "dict": tomllib.loads(text)}[kind]


@pytest.mark.parametrize("kind", ["path", "pathlike", "text", "dict"])
def test_the_folder_is_the_commands_but_for_timing(command_folder, tmp_path, kind):
    results = quadmc.run(minimal_as(kind))
    said = results.write(tmp_path / "module", plots=False)
    assert said == f"wrote {tmp_path / 'module'}"
    for name in ("convergence.csv", "slopes.csv"):
        expected = columns_but_timing(command_folder / name)
        assert columns_but_timing(tmp_path / "module" / name) == expected, (kind, name)
    # The same build wrote both: meta.csv names it in the same words.
    assert (tmp_path / "module" / "meta.csv").read_text() == \
        (command_folder / "meta.csv").read_text()


def test_the_tables_are_the_csv_rows(results, command_folder):
    with open(command_folder / "convergence.csv", newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert len(results.convergence) == len(rows) > 0
    for got, row in zip(results.convergence, rows):
        assert list(got) == list(row)
        assert (got["integrand"], got["method"], got["N"]) == \
            (row["integrand"], row["method"], int(row["N"]))
        assert isinstance(got["N"], int) and isinstance(got["rmse"], float)
        assert got["rmse"] == float(row["rmse"])  # the shortest text reads back to the double
        # Empty fields are None; the timing columns come from another run than the command's,
        # and a cell timed once leaves its spread empty, so only the others are compared.
        for key, text in row.items():
            if key not in TIMING:
                assert (got[key] is None) == (text == "")
    assert [r["method"] for r in results.slopes] == ["simpson", "plain_mc"]
    assert results.name == "example"


def test_findings_are_the_slope_rows_with_a_finding_verdict(results):
    findings = [r for r in results.slopes if r["verdict"] in ("steeper", "shallower",
                                                             "above_envelope")]
    assert results.findings == findings
    assert all(r["verdict"] in quadmc._run.FINDING_VERDICTS for r in results.findings)


class _StandInPandas(types.ModuleType):
    """A module named pandas whose DataFrame only records how it was called.

    python3-pandas is not among the packages the tests need (README command 2), so this checks our
    side of to_pandas, installed or not: which rows and columns it hands to pandas.DataFrame. It does not check pandas itself, nor that a real
    DataFrame built from these arguments has the columns we expect: that is pandas' contract
    (DataFrame(list of dicts) takes the keys as columns; columns= names them when no row does).
    """

    def __init__(self):
        super().__init__("pandas")
        self.calls = []

    def DataFrame(self, data=None, columns=None):  # noqa: N802 (pandas' name)
        self.calls.append((data, columns))
        return ("frame", len(self.calls) - 1)


def test_to_pandas_passes_each_table_to_a_dataframe(results, monkeypatch):
    pandas = _StandInPandas()
    monkeypatch.setitem(sys.modules, "pandas", pandas)
    frames = results.to_pandas()
    assert sorted(frames) == ["convergence", "findings", "slopes"]
    tables = {"convergence": results.convergence, "slopes": results.slopes,
              "findings": results.findings}
    assert len(pandas.calls) == 3
    for name, table in tables.items():
        data, columns = pandas.calls[frames[name][1]]
        assert data == table, name  # the rows as the lists hold them, in CSV order
        # findings may have no row at all; its frame still gets slopes.csv's columns, in order.
        assert columns == (list(results.slopes[0]) if name == "findings" else None), name
    assert len(results.convergence) > 0 and len(results.slopes) > 0


def test_to_pandas_without_pandas_says_what_to_install(results, monkeypatch):
    # None in sys.modules makes `import pandas` raise ImportError whether or not it is installed.
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match=r"to_pandas needs pandas.*python3-pandas.*"
                                          r"\.convergence, \.slopes, \.findings") as raised:
        results.to_pandas()
    assert "\n" not in str(raised.value)  # one line
    assert isinstance(raised.value.__cause__, ImportError)  # the import's own error, chained


def test_integrate_gives_a_scenes_cell(results):
    # The plain_mc cell at N = 64 of the minimal scene (seed 42, integrand genz_gaussian_s3):
    # integrate with the same seed runs its 64 repetitions on the same streams. The CSV's
    # estimate_mean is a compensated mean (analysis/cell_statistics.hpp), fsum's is exactly
    # rounded: the two differ by at most an ulp or two.
    f = quadmc.integrand("genz_gaussian", s=3, a=[1.0, 2.0, 0.5], u=[0.3, 0.6, 0.45])
    mine = quadmc.integrate(f, "plain_mc", 64, seed=42, repetitions=64)
    row = next(r for r in results.convergence if r["method"] == "plain_mc" and r["N"] == 64)
    assert abs(mine.value - row["estimate_mean"]) <= 4 * math.ulp(row["estimate_mean"])


def test_a_bad_scene_is_the_parsers_line(command, tmp_path):
    bad = 'name = "bad"\n[[integrand]]\nfamily = 3\n'
    (tmp_path / "bad.toml").write_text(bad)
    said = command("run", str(tmp_path / "bad.toml")).stderr.strip()
    with pytest.raises(ValueError) as from_file:
        quadmc.run(tmp_path / "bad.toml")
    assert f"quadmc: {from_file.value}" == said
    with pytest.raises(ValueError, match=r"^<string>:3:1: key 'integrand\[1\]\.family': "):
        quadmc.run(bad)
    with pytest.raises(ValueError,
                       match=r"^<dict>:3:1: key 'budget\.N\[2\]': values must increase"):
        quadmc.run({"integrand": [{"family": "exp"}], "method": [{"name": "simpson"}],
                    "budget": {"N": [8, 4]}})
    with pytest.raises(ValueError, match="cannot open the scene file"):
        quadmc.run(tmp_path / "missing.toml")


def test_ctrl_c_interrupts_a_long_run():
    # About 10^10 evaluations: minutes of work, so the signal 0.3 s in finds it running.
    scene = {"threads": 1, "integrand": [{"family": "genz_gaussian", "dimension": 8}],
             "method": [{"name": "plain_mc", "repetitions": 4096}],
             "budget": {"N": [2**21], "timing_min_seconds": 0}, "output": {"plots": False}}
    timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            quadmc.run(scene)
    finally:
        timer.cancel()
    # The module runs again afterwards.
    assert quadmc.integrate(quadmc.integrand("exp"), "simpson", 9).evaluations == 9


SHAPES = {
    "name": "shapes", "seed": 7, "description": "quotes \" and \\ and é\nand a line",
    "integrand": [{"family": "genz_gaussian", "dimension": 2, "a": [1.0, 2.5], "u": [0.5, 0.25]},
                  {"family": "exp", "name": "e"}],
    "method": [{"name": "simpson", "panels": [2, 4]},
               {"name": "importance", "warp": {"name": "power", "exponent": 2.0},
                "integrands": ["e"]}],
    "budget": {"N": {"from": 64, "to": 4096, "factor": 4}, "max_evaluations": 1e8},
    "output": {"plots": False, "csv": True},
    "odd key": [True, False, -3, 1e-300, math.inf],
}


def test_the_toml_emitter_round_trips_the_scene_shapes():
    assert tomllib.loads(to_toml(SHAPES)) == SHAPES
    text = to_toml({"seed": 1, "budget": {"N": [1, 2]}, "method": [{"name": "simpson"}]})
    assert text == 'seed = 1\n\n[budget]\nN = [1, 2]\n\n[[method]]\nname = "simpson"\n'


def test_the_toml_emitter_refuses_what_toml_cannot_say():
    with pytest.raises(ValueError, match=r"invalid scene value budget\.N = None"):
        to_toml({"budget": {"N": None}})
    with pytest.raises(ValueError, match="expected a dict"):
        to_toml([1, 2])
