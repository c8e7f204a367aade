"""quadmc.run: a scene (a file, TOML text or a dict) run to results in memory, as `quadmc run`.

The C++ half is _quadmc._run_file / _run_text (bench/python/run.cpp). The tables are read back
from the CSV texts the command writes (lib/include/quadmc/report/results_csv.hpp), so their rows
and columns are the files' own.
"""
import csv
import io
import os
import subprocess
import warnings

from ._quadmc import _run_file, _run_text
from ._toml import to_toml

# The slope verdicts the results page lists as findings (lib/src/report/markdown_report.cpp): a
# slope no computed reason explains, or a point above its a-priori bound.
FINDING_VERDICTS = ("steeper", "shallower", "above_envelope")

_PLOT_SCRIPT = os.path.join(os.path.dirname(__file__), "plot.py")
# The interpreter write_results runs the plot script with (lib/src/report/results_folder.cpp).
_PLOT_PYTHON = "/usr/bin/python3"


def _field(text):
    """A CSV field as a number where it is one: int, else float; an empty field is None."""
    if text == "":
        return None
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        return text


def _rows(text):
    return [{k: _field(v) for k, v in row.items()} for row in csv.DictReader(io.StringIO(text))]


def _can_plot():
    try:
        return subprocess.run([_PLOT_PYTHON, "-c", "import matplotlib"], capture_output=True,
                              check=False).returncode == 0
    except OSError:
        return False


class SceneResults:
    """The results of quadmc.run.

    convergence, slopes: the rows of convergence.csv and slopes.csv as lists of dicts (numbers as
        int or float, empty fields as None). findings: the slope rows whose verdict is a finding.
    """

    def __init__(self, handle):
        self._handle = handle
        self.name = handle.name
        self.convergence = _rows(handle.convergence_csv())
        self.slopes = _rows(handle.slopes_csv())
        self.findings = [r for r in self.slopes if r["verdict"] in FINDING_VERDICTS]

    def to_pandas(self):
        """{"convergence", "slopes", "findings"} as pandas DataFrames."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError("SceneResults.to_pandas needs pandas, which cannot be imported "
                              "(Debian: python3-pandas); the tables are plain lists of dicts in "
                              ".convergence, .slopes, .findings") from e
        columns = {"convergence": self.convergence, "slopes": self.slopes,
                   "findings": self.findings}
        slope_columns = list(self.slopes[0]) if self.slopes else None
        return {k: pandas.DataFrame(v, columns=slope_columns if k == "findings" else None)
                for k, v in columns.items()}

    def write(self, folder, plots=None):
        """Writes the folder `quadmc run --out folder` writes; returns "wrote <folder>".

        plots: None draws the SVGs where the scene asks for them and /usr/bin/python3 has
        matplotlib (else a warning says they were left out); False never; True where the scene asks,
        an error without matplotlib.
        """
        script = ""
        if plots is not False:
            if _can_plot():
                script = _PLOT_SCRIPT
            elif plots:
                raise RuntimeError(f"plots need matplotlib, but `{_PLOT_PYTHON} -c 'import "
                                   "matplotlib'` failed: install python3-matplotlib")
            else:
                warnings.warn("quadmc: writing without plots: /usr/bin/python3 cannot import "
                              "matplotlib", stacklevel=2)
        return self._handle.write(os.fspath(folder), script)


def run(scene, threads=None):
    """Runs a scene as `quadmc run` does and returns its SceneResults.

    scene: the path of a scene file (str or os.PathLike), the TOML text of one, or a dict of the
        same shape (written as TOML by _toml.to_toml). threads: None for the scene's own.
    The GIL is released while it runs; Ctrl-C stops it (KeyboardInterrupt). A bad scene raises
    ValueError with the parser's one-line text.
    """
    if isinstance(scene, dict):
        return SceneResults(_run_text(to_toml(scene), "<dict>", threads))
    if isinstance(scene, os.PathLike):
        return SceneResults(_run_file(os.fspath(scene), threads))
    if not isinstance(scene, str):
        raise ValueError(f"invalid scene {scene!r}: expected a file path, TOML text or a dict")
    # A str is a file when it names one; else TOML text when it looks like some (a key = value),
    # else a path, which the parser reports as unreadable.
    if not os.path.isfile(scene) and ("\n" in scene or "=" in scene):
        return SceneResults(_run_text(scene, "<string>", threads))
    return SceneResults(_run_file(scene, threads))
