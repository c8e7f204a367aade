#!/usr/bin/python3
"""Plots of a quadmc results folder: error against N and work-precision, as SVG.

Use:   /usr/bin/python3 bench/plot.py results/<scene> [more folders...]
Needs: Debian's python3 and python3-matplotlib (run.sh installs them); stdlib csv, no pandas.
Not for: reading anything but the two CSV files of a results folder (their column contract is
lib/include/quadmc/report/results_csv.hpp; added columns are ignored, a missing one is an error).

Per (integrand, s) it writes, next to the CSV files, the two files README.md links, under names
distinct for distinct (integrand, s) (the rule of lib/include/quadmc/report/markdown_report.hpp,
keep the two in step):
  error_<name>.svg                     RMSE (|error| for a deterministic rule) against N = total
                                       evaluations, log-log, one line per method; rounding-floor
                                       points as crosses off the line; dashed theory guides with the
                                       slope of slopes.csv's `theory` column, anchored at the
                                       method's first point and drawn over its fitted range (a
                                       guide shows the rate, not a bound); for a series with an
                                       error envelope (convergence.csv's `envelope`: a rule on a
                                       jump, judged within_envelope / above_envelope) the
                                       envelope itself, dotted, instead of the guide; where a
                                       rule's Euler–Maclaurin expansion predicts its error
                                       (convergence.csv's `predicted_error`) the predicted curve,
                                       dash-dotted, beside the guide.
  work_precision_<name>.svg            RMSE against seconds per estimate (the stable timing,
                                       `seconds_per_estimate`; seconds/repetitions before it).
Output is deterministic (fixed svg.hashsalt, no date in the metadata), so regenerating the plots
of unchanged data does not churn git.
"""

import argparse
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")  # headless: no display on CI machines
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)

plt.rcParams["svg.hashsalt"] = "quadmc"
plt.rcParams["figure.figsize"] = (7.0, 5.0)

CONVERGENCE_COLUMNS = ["integrand", "s", "method", "evaluations", "repetitions", "rmse", "seconds"]
SLOPES_COLUMNS = ["integrand", "s", "method", "slope", "theory"]
SAFE = set(b"abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-")


def plot_stem(name):
    """Same rule as quadmc::plot_stem, one-to-one: bytes in [A-Za-z0-9_.-] stay, any other byte
    becomes "~XX" (two upper-case hex digits)."""
    return "".join(chr(b) if b in SAFE else f"~{b:02X}" for b in name.encode("utf-8"))


def plot_files(integrand, s):
    """Same names as quadmc::convergence_plot_file and quadmc::work_precision_plot_file: the
    stem, with "_s=<s>" appended unless the integrand's name already ends in "_s<s>"."""
    stem = plot_stem(integrand)
    name = stem if stem.endswith(f"_s{s}") else f"{stem}_s={s}"
    return f"error_{name}.svg", f"work_precision_{name}.svg"


def read_csv(path, required):
    try:
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
            header = rows[0].keys() if rows else []
    except OSError as e:
        sys.exit(f"plot.py: cannot read {path}: {e.strerror}")
    for column in required:
        if rows and column not in header:
            sys.exit(f"plot.py: {path}: missing column '{column}'")
    return rows


def number(text):
    return float(text) if text not in ("", None) else math.nan


def load(folder):
    """Series grouped by (integrand, s) in order of first appearance, methods likewise."""
    groups = {}
    for row in read_csv(f"{folder}/convergence.csv", CONVERGENCE_COLUMNS):
        key = (row["integrand"], int(row["s"]))
        series = groups.setdefault(key, {}).setdefault(row["method"], [])
        repetitions = max(int(row["repetitions"]), 1)
        series.append({
            "n": float(row["evaluations"]),
            "error": number(row["rmse"]),
            # The stable time per estimate (analysis/cell_timing.hpp); a folder from before it
            # has only the repetitions' total.
            "seconds": (number(row["seconds_per_estimate"])
                        if row.get("seconds_per_estimate") not in ("", None)
                        else number(row["seconds"]) / repetitions),
            "floor": row.get("floor", "0") == "1",
            "envelope": number(row.get("envelope")),  # absent in older folders: NaN
            "predicted": number(row.get("predicted_error")),  # absent or empty: NaN
        })
    for methods in groups.values():
        for points in methods.values():
            points.sort(key=lambda p: p["n"])
    slopes = {}
    for row in read_csv(f"{folder}/slopes.csv", SLOPES_COLUMNS):
        slopes[(row["integrand"], int(row["s"]), row["method"])] = (
            number(row["slope"]), number(row["theory"]))
    return groups, slopes


def label(method, fit):
    slope, theory = fit
    text = method
    if not math.isnan(slope):
        text += f"  (slope {slope:.2f}"
        text += f", theory {theory:.2f})" if not math.isnan(theory) else ")"
    return text


def draw(ax, x_of, points, color, name):
    """Clean points as a line with dots, floor points as crosses; zero values cannot be drawn on
    a log axis and are left out (README.md lists them)."""
    clean = [p for p in points if not p["floor"] and p["error"] > 0 and x_of(p) > 0]
    floor = [p for p in points if p["floor"] and p["error"] > 0 and x_of(p) > 0]
    ax.plot([x_of(p) for p in clean], [p["error"] for p in clean], "o-", color=color,
            markersize=3.5, linewidth=1.2, label=name)
    if floor:
        ax.plot([x_of(p) for p in floor], [p["error"] for p in floor], "x", color=color,
                markersize=6, linestyle="none")
    return clean


def finish(fig, ax, path, xlabel, title, floor_seen, theory_seen, envelope_seen=False,
           predicted_seen=False):
    # Only positive values are drawn (draw()); where none is left, every error was exactly 0
    # (a rule exact to the last bit, e.g. on a 1e-10-wide interval) and log axes have nothing
    # to show: the plot says so instead of matplotlib refusing to scale an empty axis.
    if any(len(line.get_xdata()) for line in ax.get_lines()):
        ax.set_xscale("log")
        ax.set_yscale("log")
    else:
        ax.text(0.5, 0.5, "every error is exactly 0: nothing to draw on log axes",
                ha="center", va="center", transform=ax.transAxes, fontsize=9)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("RMSE over repetitions (|error| for rules)")
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="major", linewidth=0.4, alpha=0.5)
    handles, labels = ax.get_legend_handles_labels()
    if floor_seen:
        handles.append(plt.Line2D([], [], color="gray", marker="x", linestyle="none"))
        labels.append("rounding floor (not fitted)")
    if theory_seen:
        handles.append(plt.Line2D([], [], color="gray", linestyle="--"))
        labels.append("theory slope")
    if envelope_seen:
        handles.append(plt.Line2D([], [], color="gray", linestyle=":"))
        labels.append("error envelope (a-priori bound)")
    if predicted_seen:
        handles.append(plt.Line2D([], [], color="gray", linestyle="-."))
        labels.append("Euler–Maclaurin prediction")
    ax.legend(handles, labels, fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(path, format="svg", metadata={"Date": None})
    plt.close(fig)


def plot_folder(folder):
    groups, slopes = load(folder)
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    written = []
    for (integrand, s), methods in groups.items():
        fig, ax = plt.subplots()
        wfig, wax = plt.subplots()
        floor_seen = theory_seen = envelope_seen = predicted_seen = False
        for k, (method, points) in enumerate(methods.items()):
            color = colors[k % len(colors)]
            fit = slopes.get((integrand, s, method), (math.nan, math.nan))
            name = label(method, fit)
            clean = draw(ax, lambda p: p["n"], points, color, name)
            draw(wax, lambda p: p["seconds"], points, color, method)
            floor_seen |= any(p["floor"] for p in points)
            theory = fit[1]
            bounded = [p for p in points if p["envelope"] > 0]  # NaN compares false
            if bounded:
                # The bound the verdict is judged against, at every N (floor points included).
                ax.plot([p["n"] for p in bounded], [p["envelope"] for p in bounded], ":",
                        color=color, linewidth=1.0, alpha=0.8)
                envelope_seen = True
            elif not math.isnan(theory) and clean:
                # Over the fitted (clean) range only: past the floor a guide would stretch the
                # axis to errors no double can hold.
                n0, e0 = clean[0]["n"], clean[0]["error"]
                n1 = clean[-1]["n"]
                ax.plot([n0, n1], [e0, e0 * (n1 / n0) ** theory], "--", color=color,
                        linewidth=0.9, alpha=0.7)
                theory_seen = True
            predicted = [p for p in points if p["predicted"] > 0]  # NaN compares false
            if predicted:
                # The predicted error of every cell where the expansion is predictive, floor
                # cells included: below the floor it shows what rounding hides.
                ax.plot([p["n"] for p in predicted], [p["predicted"] for p in predicted], "-.",
                        color=color, linewidth=0.9, alpha=0.8)
                predicted_seen = True
        error_file, work_precision_file = plot_files(integrand, s)
        finish(fig, ax, f"{folder}/{error_file}", "N (integrand evaluations per estimate)",
               f"{integrand}, s = {s}: error against N", floor_seen, theory_seen, envelope_seen,
               predicted_seen)
        finish(wfig, wax, f"{folder}/{work_precision_file}", "seconds per estimate",
               f"{integrand}, s = {s}: work-precision", floor_seen, False)
        written += [error_file, work_precision_file]
    return written


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+", help="results folders (results/<scene>)")
    args = parser.parse_args()
    for folder in args.folders:
        written = plot_folder(folder.rstrip("/"))
        print(f"plot.py: {folder}: {len(written)} plots")


if __name__ == "__main__":
    main()
