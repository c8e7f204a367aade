#!/usr/bin/python3
"""Work-precision plots of the peers benchmark: absolute error against seconds per run.

Use:   /usr/bin/python3 bench/peers/plot_peers.py results/peers
Needs: Debian's python3 and python3-matplotlib; stdlib csv only.
Reads: <folder>/peers.csv as written by bench/peers/quadmc_peers (the rows with run = ladder:
       one thread, error = RMS over the seeds for random methods, |error| for deterministic ones).
Writes: <folder>/work_precision_<integrand>.svg, one panel per dimension s, one line per method.
Errors of exactly 0 (a rule exact for the integrand, e.g. Simpson on a sum of coordinates) are
drawn at 1e-17, below the y-range of double-precision rounding, and the panel says so.
Output is deterministic (fixed svg.hashsalt, no date in the metadata), so regenerating the
plots of unchanged data does not churn git.
"""

import csv
import math
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")  # headless
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)

plt.rcParams["svg.hashsalt"] = "quadmc"
FLOOR = 1e-17
STYLE = {  # family -> (line style, marker)
    "reference": ("-", "x"),
    "quadmc": ("-", "o"),
    "GSL": ("--", "s"),
    "Boost.Math": (":", "^"),
    "cubature": ("-.", "d"),
}
REQUIRED = ["method", "integrand", "s", "threads", "evaluations", "seconds", "abs_error", "run",
            "family"]


def main(argv):
    if len(argv) != 2:
        print("usage: plot_peers.py RESULTS_FOLDER", file=sys.stderr)
        return 2
    folder = argv[1]
    with open(f"{folder}/peers.csv", newline="") as f:
        reader = csv.DictReader(f)
        missing = [c for c in REQUIRED if c not in (reader.fieldnames or [])]
        if missing:
            print(f"plot_peers.py: {folder}/peers.csv lacks columns {missing}", file=sys.stderr)
            return 1
        rows = [r for r in reader if r["run"] == "ladder"]
    # integrand -> s -> method -> [(seconds, error)]
    data = defaultdict(lambda: defaultdict(lambda: defaultdict(list)))
    family = {}
    for r in rows:
        data[r["integrand"]][int(r["s"])][r["method"]].append(
            (float(r["seconds"]), float(r["abs_error"]), float(r["evaluations"])))
        family[r["method"]] = r["family"]
    methods = sorted(family, key=lambda m: (list(STYLE).index(family[m]), m))
    # tab20 holds 10 dark/light pairs: take the 10 dark ones first, so neighbours differ.
    colours = plt.get_cmap("tab20").colors
    order = list(range(0, 20, 2)) + list(range(1, 20, 2))
    colour = {m: colours[order[i % 20]] for i, m in enumerate(methods)}
    for integrand, by_s in data.items():
        dims = sorted(by_s)
        cols = 2
        nrows = math.ceil(len(dims) / cols)
        fig, axes = plt.subplots(nrows, cols, figsize=(12, 4.6 * nrows), squeeze=False)
        for ax, s in zip(axes.flat, dims):
            floored = False
            for m in methods:
                pts = sorted(by_s[s].get(m, []), key=lambda p: p[2])
                if not pts:
                    continue
                ls, marker = STYLE.get(family[m], ("-", "o"))
                errors = [max(e, FLOOR) for _, e, _ in pts]
                floored |= any(e < FLOOR for _, e, _ in pts)
                ax.loglog([t for t, _, _ in pts], errors, ls, marker=marker, markersize=3,
                          color=colour[m], label=m, linewidth=1.2)
            ax.set_title(f"{integrand}, s = {s}" + ("  (error 0 drawn at 1e-17)" if floored else ""),
                         fontsize=10)
            ax.set_xlabel("seconds per run (one thread)")
            ax.set_ylabel("absolute error (RMS over seeds if random)")
            ax.axhline(1e-3, color="grey", linewidth=0.6, linestyle=":")
            ax.axhline(1e-5, color="grey", linewidth=0.6, linestyle=":")
            ax.grid(True, which="major", linewidth=0.3)
        for ax in list(axes.flat)[len(dims):]:
            ax.axis("off")
        handles, labels = [], []
        for ax in axes.flat:
            for h, l in zip(*ax.get_legend_handles_labels()):
                if l not in labels:
                    handles.append(h)
                    labels.append(l)
        fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=8, frameon=False)
        fig.suptitle(f"Work-precision, {integrand}: quadmc and peers, same integrand code")
        fig.tight_layout(rect=(0, 0.1, 1, 0.97))
        fig.savefig(f"{folder}/work_precision_{integrand}.svg", metadata={"Date": None})
        plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
