#!/usr/bin/python3
"""Draws the point-set gallery of `quadmc gallery` from the CSV files it wrote.

Usage: gallery.py FOLDER. Reads scatter.csv, strata.csv, discrepancy.csv and spectrum.csv of
FOLDER and writes gallery.png (one row per point set: scatter at N = 16, 64, 256 with strata and
1D projections, discrepancies under each square, the power spectrum last) and spectra.png (every
set's radially averaged power spectrum on one plot). The user's own sets (`--points`, listed in
user_points.csv when there are any) get the last rows, labelled as theirs with the realizations
their spectrum averages, and dashed curves in spectra.png. Computes nothing: every number comes
from the command (bench/quadmc/gallery_command.hpp). Debian's python3-matplotlib, headless (Agg).
Not for results folders of `quadmc run` (bench/plot.py draws those).
"""

import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SIZES = (16, 64, 256)
# Rows and columns of width 1/N are drawn only where they stay readable.
MAX_LINES = 64


def read(folder, name):
    with open(os.path.join(folder, name), newline="") as f:
        return list(csv.DictReader(f))


def user_sets(folder):
    """The user's sets (--points): name -> realizations of its spectrum (at the largest N)."""
    if not os.path.exists(os.path.join(folder, "user_points.csv")):
        return {}
    out = {}
    for r in read(folder, "user_points.csv"):
        out[r["set"]] = r["realizations"]
    return out


def main(folder):
    points = defaultdict(lambda: ([], []))
    order = []
    for row in read(folder, "scatter.csv"):
        key = (row["set"], int(row["n"]))
        if row["set"] not in order:
            order.append(row["set"])
        points[key][0].append(float(row["x1"]))
        points[key][1].append(float(row["x2"]))
    strata = {(r["set"], int(r["n"])): r for r in read(folder, "strata.csv")}
    disc = {(r["set"], int(r["n"])): r for r in read(folder, "discrepancy.csv")}
    spectra = defaultdict(list)
    for r in read(folder, "spectrum.csv"):
        spectra[r["set"]].append(r)
    users = user_sets(folder)

    rows = len(order)
    fig, axes = plt.subplots(rows, len(SIZES) + 1, figsize=(13, 3.1 * rows))
    if rows == 1:
        axes = [axes]
    for i, name in enumerate(order):
        for j, n in enumerate(SIZES):
            ax = axes[i][j]
            xs, ys = points[(name, n)]
            g = strata.get((name, n))
            if g is not None:
                cols, nrows = int(g["columns"]), int(g["rows"])
                if g["kind"] == "cells" or max(cols, nrows) <= MAX_LINES:
                    for c in range(1, cols):
                        ax.axvline(c / cols, color="0.8", lw=0.5, zorder=0)
                    for c in range(1, nrows):
                        ax.axhline(c / nrows, color="0.8", lw=0.5, zorder=0)
            ax.scatter(xs, ys, s=max(1.0, 40.0 / n ** 0.5), color="C0", lw=0)
            # 1D projections: ticks on a strip below (x1) and left of (x2) the unit square.
            ax.vlines(xs, -0.09, -0.03, color="C3", lw=0.5)
            ax.hlines(ys, -0.09, -0.03, color="C3", lw=0.5)
            ax.plot([0, 1, 1, 0, 0], [0, 0, 1, 1, 0], color="k", lw=0.6)
            ax.set_xlim(-0.1, 1.01)
            ax.set_ylim(-0.1, 1.01)
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            for side in ax.spines.values():
                side.set_visible(False)
            d = disc[(name, n)]
            ax.set_xlabel(
                "D*={:.4f} CD={:.4f} WD={:.4f}".format(
                    float(d["l2_star"]), float(d["centered"]), float(d["wraparound"])
                ),
                fontsize=7,
            )
            if i == 0:
                ax.set_title("N = {}".format(n), fontsize=10)
            if j == 0:
                label = name + ("\n(your points, no strata)" if name in users else "")
                ax.set_ylabel(label, fontsize=10)
        ax = axes[i][len(SIZES)]
        bins = spectra[name]
        r = [int(b["radius"]) for b in bins]
        p = [float(b["mean_power"]) for b in bins]
        e = [float(b["standard_error"]) for b in bins]
        ax.fill_between(r, [a - 2 * b for a, b in zip(p, e)], [a + 2 * b for a, b in zip(p, e)],
                        color="C0", alpha=0.3, lw=0)
        ax.plot(r, p, color="C0", lw=1)
        ax.axhline(1.0, color="k", lw=0.5, ls="--")
        n_spec = int(bins[0]["n"])
        ax.axvline(n_spec ** 0.5, color="0.5", lw=0.5, ls=":")
        ax.set_yscale("symlog", linthresh=0.1)
        ax.set_ylim(bottom=0)
        ax.set_xlabel("|f|", fontsize=8)
        ax.tick_params(labelsize=7)
        if i == 0:
            ax.set_title("power spectrum, N = {}, {} realizations".format(
                n_spec, bins[0]["realizations"]), fontsize=9)
        elif name in users:
            ax.set_title("{} realizations (your files)".format(bins[0]["realizations"]),
                         fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, "gallery.png"), dpi=80)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(8, 5))
    for k, name in enumerate(order):
        bins = spectra[name]
        label = name
        if name in users:
            label = "{} (yours, {} realizations)".format(name, bins[0]["realizations"])
        ax.plot([int(b["radius"]) for b in bins], [float(b["mean_power"]) for b in bins],
                label=label, color="C{}".format(k % 10), lw=1.2,
                ls="--" if name in users else "-")
    n_spec = int(spectra[order[0]][0]["n"])
    ax.axhline(1.0, color="k", lw=0.5, ls="--")
    ax.axvline(n_spec ** 0.5, color="0.5", lw=0.5, ls=":")
    ax.set_yscale("symlog", linthresh=0.1)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("frequency |f| (integer, radially averaged)")
    ax.set_ylabel("mean power P(f)")
    each = "{} realizations each".format(spectra[order[0]][0]["realizations"])
    if users:
        each = "{} realizations per suite set (yours: as labelled)".format(
            spectra[order[0]][0]["realizations"])
    ax.set_title("Radially averaged periodogram, N = {}, {}".format(n_spec, each))
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, "spectra.png"), dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: gallery.py FOLDER")
    main(sys.argv[1])
