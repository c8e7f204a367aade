#!/usr/bin/python3
"""Plots of a quadmc results folder: error against N and work-precision, as SVG.

Use:   /usr/bin/python3 bench/plot.py results/<scene> [more folders...]
Needs: Debian's python3 and python3-matplotlib (run.sh installs them); stdlib csv, no pandas.
Not for: reading anything but the CSV files of a results folder (their column contract is
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
and the two summary figures that the answer at the top of README.md links (the names of
lib/include/quadmc/report/answer_first.hpp, keep the two in step), each as SVG and PNG:
  slope_against_theory.svg, .png       every series' fitted slope (95% interval as a bar) against
                                       its theory slope, coloured by verdict, with the diagonal:
                                       a disagreement is a point off the line (slopes.csv).
  who_leads.svg, .png                  the "Who leads at equal N" tables as a picture: a row per
                                       integrand family and s, a column per N, the winning method
                                       as the cell's colour (who_leads.csv), faded and hatched
                                       where the winner is a rounding-floor point (the methods
                                       then differ by rounding); not drawn when the file has no
                                       row (no table on the page) or is absent (a folder from
                                       before it).
Output is deterministic (fixed svg.hashsalt, no date in the metadata, no software version in the
PNG), so regenerating the plots of unchanged data does not churn git.
"""

import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # headless: no display on CI machines
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)

plt.rcParams["svg.hashsalt"] = "quadmc"
plt.rcParams["figure.figsize"] = (7.0, 5.0)

CONVERGENCE_COLUMNS = ["integrand", "s", "method", "evaluations", "repetitions", "rmse", "seconds"]
SLOPES_COLUMNS = ["integrand", "s", "method", "slope", "theory"]
SUMMARY_SLOPES_COLUMNS = SLOPES_COLUMNS + ["ci_low", "ci_high", "verdict"]
WHO_LEADS_COLUMNS = ["family", "s", "N", "method"]
SLOPE_FIGURE = "slope_against_theory"
WHO_LEADS_FIGURE = "who_leads"
# One colour per verdict (slope_verdict.hpp), the same in every folder: agreement green, a
# difference with a computed reason blue or grey, a finding (no computed reason) red or orange.
VERDICT_COLORS = {
    "agrees": "#2ca02c",
    "within_envelope": "#17becf",
    "superconvergent": "#1f77b4",
    "pre_asymptotic": "#9467bd",
    "at_floor": "#7f7f7f",
    "steeper": "#ff7f0e",
    "shallower": "#d62728",
    "above_envelope": "#8c564b",
}
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


def save_both(fig, folder, stem):
    """The summary figures as SVG and PNG, both without a date or a version in them."""
    fig.tight_layout()
    fig.savefig(f"{folder}/{stem}.svg", format="svg", metadata={"Date": None})
    fig.savefig(f"{folder}/{stem}.png", format="png", dpi=100, metadata={"Software": None})
    plt.close(fig)
    return [f"{stem}.svg", f"{stem}.png"]


def plot_slopes_against_theory(folder):
    """Every series with a fit and a theory as one marker: x its theory slope, y its fitted slope
    with the 95% interval as a bar, coloured by verdict; the diagonal slope = theory."""
    rows = read_csv(f"{folder}/slopes.csv", SUMMARY_SLOPES_COLUMNS)
    fig, ax = plt.subplots(figsize=(6.5, 6.0))
    drawn = {}
    left_out = 0
    for row in rows:
        slope, theory = number(row["slope"]), number(row["theory"])
        if math.isnan(slope) or math.isnan(theory):
            left_out += 1  # no fit or no theory: nothing to place
            continue
        drawn.setdefault(row["verdict"], []).append(
            (theory, slope, number(row["ci_low"]), number(row["ci_high"])))
    every = [p for points in drawn.values() for p in points]
    if every:
        low = min(min(p[0], p[1]) for p in every)
        high = max(max(p[0], p[1]) for p in every)
        pad = 0.05 * (high - low) + 0.1
        ax.plot([low - pad, high + pad], [low - pad, high + pad], "-", color="gray",
                linewidth=0.8, label="slope = theory")
    # Findings last, so that no agreeing marker hides one.
    order = list(VERDICT_COLORS) + sorted(v for v in drawn if v not in VERDICT_COLORS)
    for verdict in order:
        points = drawn.get(verdict)
        if not points:
            continue
        color = VERDICT_COLORS.get(verdict, "black")
        below = [p[1] - p[2] if not math.isnan(p[2]) else 0.0 for p in points]
        above = [p[3] - p[1] if not math.isnan(p[3]) else 0.0 for p in points]
        ax.errorbar([p[0] for p in points], [p[1] for p in points], yerr=[below, above],
                    fmt="o", color=color, markersize=4, elinewidth=0.7, alpha=0.75,
                    label=f"{verdict} ({len(points)})")
    ax.set_xlabel("theory slope")
    ax.set_ylabel("fitted slope of |error| or RMSE against N (95% interval)")
    title = f"{len(every)} series: fitted slope against theory"
    if left_out:
        title += f" ({left_out} without a fit or a theory left out)"
    ax.set_title(title, fontsize=10)
    ax.grid(True, linewidth=0.4, alpha=0.5)
    ax.legend(fontsize=7, loc="best")
    return save_both(fig, folder, SLOPE_FIGURE)


def plot_who_leads(folder):
    """The "Who leads at equal N" tables as one picture: rows (family, s) in the page's order,
    columns every N of any ladder, each cell the winner's colour; a blank cell is "—" or an N
    that the family's ladder does not have."""
    path = f"{folder}/who_leads.csv"
    if not os.path.exists(path):
        return []  # a folder from before the file
    rows = read_csv(path, WHO_LEADS_COLUMNS)
    if not rows:
        return []  # no table on the page, so no figure and no link
    keys, ladder, methods, winner, floor = [], set(), [], {}, set()
    for row in rows:
        key = (row["family"], int(row["s"]))
        if key not in keys:
            keys.append(key)
        n = int(row["N"])
        ladder.add(n)
        if row["method"]:
            if row["method"] not in methods:
                methods.append(row["method"])
            winner[(key, n)] = row["method"]
            if row.get("at_floor") == "1":
                floor.add((key, n))
    ladder = sorted(ladder)
    # tab20's ten strong colours first, then their light partners, then tab20b: the methods that
    # appear first (usually those that lead most) get the colours easiest to tell apart.
    tab20 = plt.get_cmap("tab20")
    palette = ([tab20(k) for k in range(0, 20, 2)] + [tab20(k) for k in range(1, 20, 2)] +
               [plt.get_cmap("tab20b")(k) for k in range(20)])
    color_of = {m: palette[k % len(palette)] for k, m in enumerate(methods)}
    width = max(6.5, 1.6 + 0.42 * len(ladder))
    fig, ax = plt.subplots(figsize=(width, 1.4 + 0.3 * len(keys) + 0.16 * len(methods)))
    for i, key in enumerate(keys):
        for j, n in enumerate(ladder):
            method = winner.get((key, n))
            if method is None:
                continue
            at_floor = (key, n) in floor
            ax.add_patch(plt.Rectangle((j, i), 1, 1, facecolor=color_of[method],
                                       edgecolor="white", linewidth=0.5,
                                       alpha=0.35 if at_floor else 1.0,
                                       hatch="///" if at_floor else None))
    ax.set_xlim(0, len(ladder))
    ax.set_ylim(len(keys), 0)
    ax.set_xticks([j + 0.5 for j in range(len(ladder))])
    ax.set_xticklabels([f"{n:,}" for n in ladder], rotation=60, ha="right", fontsize=7)
    ax.set_yticks([i + 0.5 for i in range(len(keys))])
    ax.set_yticklabels([f"{family}, s = {s}" for family, s in keys], fontsize=7)
    ax.set_xlabel("N (integrand evaluations)")
    ax.set_title("Who leads at equal N: the method of smallest error per family, s and N",
                 fontsize=10)
    handles = [plt.Rectangle((0, 0), 1, 1, facecolor=color_of[m]) for m in methods]
    labels = list(methods)
    if floor:
        handles.append(plt.Rectangle((0, 0), 1, 1, facecolor="gray", alpha=0.35, hatch="///"))
        labels.append("winner at the rounding floor")
    ax.legend(handles, labels, fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.1),
              ncol=min(4, max(1, len(labels))), frameon=False)
    return save_both(fig, folder, WHO_LEADS_FIGURE)


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
    written += plot_slopes_against_theory(folder)
    written += plot_who_leads(folder)
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
