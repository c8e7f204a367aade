#!/usr/bin/python3
"""Draws the pictures of `quadmc render` from the files it wrote.

Usage: render.py FOLDER. Reads images.csv and pixels.f64 (the images as float64, little-endian,
one after the other; the command removes both once this script has run), rmse.csv, slopes.csv,
error_spectrum.csv, lowpass.csv and light_sampling.csv of FOLDER, and writes exact.png (the exact image and where the light is
fully seen, partly hidden, hidden), comparison.png (estimates and signed errors of the three
estimators at one spp), errors_<estimator>.png (the signed error of every point set at every
spp), rmse.png (image RMSE against spp with the fitted slopes), error_spectrum.png (from
error_spectrum.csv and lowpass.csv: the error's power by frequency and its RMSE after each
low-pass, at the largest spp) and light_sampling.png (the 1 x L against L x 1 experiment). Computes no statistic: every number comes from the command
(bench/quadmc/render_command.hpp). Debian's python3-matplotlib (and its numpy), headless (Agg).
"""

import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402

# PNG metadata without the matplotlib version: the same images give the same bytes.
META = {"Software": None}
SHOWN_SPP = 16


def read(folder, name):
    path = os.path.join(folder, name)
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def symmetric_limit(errors):
    """A symmetric colour limit that a few extreme pixels do not dictate: the 99.5th percentile."""
    v = max(float(np.percentile(np.abs(e), 99.5)) for e in errors)
    return v if v > 0 else 1.0


def show(ax, img, extent, **kw):
    im = ax.imshow(img, extent=extent, interpolation="nearest", **kw)
    ax.set_xticks([])
    ax.set_yticks([])
    return im


def main(folder):
    index = read(folder, "images.csv")
    data = np.fromfile(os.path.join(folder, "pixels.f64"), dtype="<f8")
    images = {}
    for row in index:
        w, h, off = int(row["width"]), int(row["height"]), int(row["offset"])
        images[row["name"]] = data[off:off + w * h].reshape(h, w)
    first = index[0]
    extent = [float(first["x_min"]), float(first["x_max"]), float(first["y_min"]),
              float(first["y_max"])]
    exact = images["exact"]
    vmax = float(exact.max())
    estimates = [r for r in index if r["kind"] == "estimate"]
    estimators = list(dict.fromkeys(r["estimator"] for r in estimates))
    sets = list(dict.fromkeys(r["point_set"] for r in estimates))
    spps = sorted({int(r["spp"]) for r in estimates})

    # exact.png
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.4))
    im = show(axes[0], exact, extent, cmap="inferno", vmin=0, vmax=vmax)
    axes[0].set_title("exact irradiance E (Lambert's formula)", fontsize=10)
    fig.colorbar(im, ax=axes[0], fraction=0.046)
    vis = images["visibility"]
    cmap = ListedColormap(["#f2d16b", "#8c8c8c", "#1f1f3d"])
    im = show(axes[1], vis, extent, cmap=cmap, vmin=-0.5, vmax=2.5)
    bar = fig.colorbar(im, ax=axes[1], fraction=0.046, ticks=[0, 1, 2])
    bar.ax.set_yticklabels(["full light", "penumbra", "umbra"])
    axes[1].set_title("how much of the light each pixel sees", fontsize=10)
    for ax in axes:
        ax.set_xticks([extent[0], extent[1]])
        ax.set_yticks([extent[2], extent[3]])
        ax.tick_params(labelsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, "exact.png"), dpi=90, metadata=META)
    plt.close(fig)

    # comparison.png: one spp, the three estimators with independent points, then light_area with
    # the other sets.
    spp = min(spps, key=lambda n: abs(n - SHOWN_SPP))
    first_set = "independent" if "independent" in sets else sets[0]
    shown = [(e, first_set) for e in estimators]
    if "light_area" in estimators:
        shown += [("light_area", s) for s in sets if s != first_set and s in ("jittered", "sobol")]
    errs = [images["{}/{}/{}".format(e, s, spp)] - exact for e, s in shown]
    cols = len(shown) + 1
    fig, axes = plt.subplots(2, cols, figsize=(2.6 * cols, 5.9), squeeze=False)
    show(axes[0][0], exact, extent, cmap="inferno", vmin=0, vmax=vmax)
    axes[0][0].set_title("exact", fontsize=9)
    show(axes[1][0], vis, extent, cmap=cmap, vmin=-0.5, vmax=2.5)
    axes[1][0].set_title("full / penumbra / umbra", fontsize=9)
    rmse = {(r["estimator"], r["point_set"], int(r["spp"])): float(r["rmse"])
            for r in read(folder, "rmse.csv")}
    for j, ((e, s), err) in enumerate(zip(shown, errs), start=1):
        show(axes[0][j], images["{}/{}/{}".format(e, s, spp)], extent, cmap="inferno", vmin=0,
             vmax=vmax)
        axes[0][j].set_title("{}\n{}, {} spp".format(e, s, spp), fontsize=9)
        # Each error on its own symmetric scale, ±3 RMSE, stated under it: on one common scale
        # the light-area errors would be invisible beside the hemisphere ones.
        lim = 3.0 * rmse[(e, s, spp)] or 1.0
        show(axes[1][j], err, extent, cmap="RdBu_r", vmin=-lim, vmax=lim)
        axes[1][j].set_title("error, RMSE {:.3g}".format(rmse[(e, s, spp)]), fontsize=9)
        axes[1][j].set_xlabel("colour scale ±{:.2g}".format(lim), fontsize=8)
    fig.suptitle("estimates (top) and estimate − exact (bottom; blue below, red above)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, "comparison.png"), dpi=80, metadata=META)
    plt.close(fig)

    # errors_<estimator>.png: rows point sets, columns spp, one symmetric scale per column.
    for e in estimators:
        fig, axes = plt.subplots(len(sets), len(spps), figsize=(2.3 * len(spps), 2.3 * len(sets)),
                                 squeeze=False)
        for j, n in enumerate(spps):
            col = [images["{}/{}/{}".format(e, s, n)] - exact for s in sets]
            lim = symmetric_limit(col)
            for i, s in enumerate(sets):
                show(axes[i][j], col[i], extent, cmap="RdBu_r", vmin=-lim, vmax=lim)
                axes[i][j].set_xlabel("RMSE {:.3g}".format(rmse[(e, s, n)]), fontsize=7)
                if j == 0:
                    axes[i][j].set_ylabel(s, fontsize=9)
            axes[0][j].set_title("{} spp, ±{:.2g}".format(n, lim), fontsize=9)
        fig.suptitle("{}: estimate − exact (blue below, red above)".format(e), fontsize=10)
        fig.tight_layout()
        fig.savefig(os.path.join(folder, "errors_{}.png".format(e)), dpi=70, metadata=META)
        plt.close(fig)

    # rmse.png
    slopes = {(r["estimator"], r["point_set"]): r for r in read(folder, "slopes.csv")}
    styles = {"uniform_hemisphere": ":", "cosine_hemisphere": "--", "light_area": "-"}
    markers = {"uniform_hemisphere": "v", "cosine_hemisphere": "s", "light_area": "o"}
    fig, ax = plt.subplots(figsize=(8.5, 5.0))
    for e in estimators:
        for k, s in enumerate(sets):
            ys = [rmse[(e, s, n)] for n in spps]
            f = slopes.get((e, s))
            label = "{} / {}".format(e, s)
            if f is not None and f["status"] == "ok":
                label += "  {:.2f}".format(float(f["slope"]))
            ax.plot(spps, ys, ls=styles.get(e, "-"), marker=markers.get(e, "o"), ms=4,
                    color="C{}".format(k % 10), label=label)
    top = max(rmse.values())
    ax.plot(spps, [top * (n / spps[0]) ** -0.5 for n in spps], color="k", lw=0.6, ls="-.",
            label="slope −1/2")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("samples per pixel")
    ax.set_ylabel("image RMSE")
    ax.set_title("Image RMSE against spp (fitted slope in the legend)")
    ax.grid(True, which="major", lw=0.3, color="0.85")
    # Below the axes: inside, the legend would hide the steepest lines at large spp.
    ax.legend(fontsize=7, ncol=3, loc="upper center", bbox_to_anchor=(0.5, -0.12))
    fig.savefig(os.path.join(folder, "rmse.png"), dpi=90, bbox_inches="tight", metadata=META)
    plt.close(fig)

    # error_spectrum.png: per estimator at the largest spp, each set's relative error power by
    # frequency ring (white noise: 1) and its RMSE after each Gaussian low-pass.
    spectrum = read(folder, "error_spectrum.csv")
    lowpass = read(folder, "lowpass.csv")
    top = str(spps[-1])
    fig, axes = plt.subplots(2, len(estimators), figsize=(4.2 * len(estimators), 7.0),
                             squeeze=False)
    for j, e in enumerate(estimators):
        for k, s in enumerate(sets):
            ring = [r for r in spectrum
                    if (r["estimator"], r["point_set"], r["spp"]) == (e, s, top)
                    and r["relative_power"] not in ("nan", "")]
            axes[0][j].plot([float(r["frequency"]) for r in ring],
                            [float(r["relative_power"]) for r in ring],
                            color="C{}".format(k % 10), lw=1.0, label=s)
            cut = [r for r in lowpass if (r["estimator"], r["point_set"], r["spp"]) == (e, s, top)]
            axes[1][j].plot([float(r["sigma"]) for r in cut], [float(r["rmse"]) for r in cut],
                            color="C{}".format(k % 10), marker="o", ms=3, lw=1.0, label=s)
        axes[0][j].axhline(1.0, color="k", lw=0.6, ls="-.")
        axes[0][j].set_yscale("log")
        axes[0][j].set_xlabel("frequency (cycles per pixel)")
        axes[0][j].set_title("{}, spp {}".format(e, top), fontsize=9)
        axes[1][j].set_yscale("log")
        axes[1][j].set_xlabel("low-pass σ (pixels)")
        for a in (axes[0][j], axes[1][j]):
            a.grid(True, lw=0.3, color="0.85")
    axes[0][0].set_ylabel("error power / mean square (white noise: 1)")
    axes[1][0].set_ylabel("RMSE after the low-pass")
    axes[1][-1].legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, "error_spectrum.png"), dpi=80, metadata=META)
    plt.close(fig)

    # light_sampling.png
    rows = [r for r in index if r["kind"] == "light_sampling"]
    if rows:
        ref = images["exact_mean"]
        stats = {(r["pixel_samples"], r["light_samples"], r["correlation"]): r
                 for r in read(folder, "light_sampling.csv")}
        layouts = list(dict.fromkeys((r["pixel_samples"], r["light_samples"]) for r in rows))
        corr = ["correlated", "decorrelated"]
        errs = {(p, l, c): images["light_sampling/{}x{}/{}".format(p, l, c)] - ref
                for p, l in layouts for c in corr}
        lim = symmetric_limit(list(errs.values()))
        fig, axes = plt.subplots(len(layouts), 2, figsize=(8.4, 4.0 * len(layouts)),
                                 squeeze=False)
        for i, (p, l) in enumerate(layouts):
            for j, c in enumerate(corr):
                im = show(axes[i][j], errs[(p, l, c)], extent, cmap="RdBu_r", vmin=-lim, vmax=lim)
                st = stats[(p, l, c)]
                axes[i][j].set_title(
                    "{} pixel × {} light samples, {}\nRMSE {:.3g}, neighbour correlation {:.2f}"
                    .format(p, l, c, float(st["rmse"]), float(st["neighbour_correlation"])),
                    fontsize=9)
        fig.colorbar(im, ax=[a for r in axes for a in r], fraction=0.03, pad=0.02,
                     label="estimate − exact pixel mean")
        fig.savefig(os.path.join(folder, "light_sampling.png"), dpi=80, bbox_inches="tight",
                    metadata=META)
        plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: render.py FOLDER")
    main(sys.argv[1])
