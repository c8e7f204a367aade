#!/usr/bin/python3
"""Scale-out of `quadmc run` on Open MPI: measured at 1 and 2 ranks, modelled at 8, 64 and 1024.

Use:   /usr/bin/python3 bench/scaling.py --quadmc build/release/bench/quadmc \\
           --scene bench/scenes/default.toml --scene bench/scenes/stress.toml --out results/scaling
Writes OUT/README.md and OUT/scaling.csv (replacing only those two files), and prints the table.

Measured: each scene is run with `--threads 1` on one process, then under
`mpirun -np 2 --threads 1`, wall time of the whole command each (plots off: a copy of the scene
with [output] plots = false is run from a scratch folder); the two runs' convergence.csv must be
equal in every column but the timing ones (bench/same_results.py), or the script fails.

Modelled: the cost of a cell is what the one-process run spent on it (its convergence.csv):
`seconds`, the wall time of its repetitions, plus its stable timing, `seconds_per_estimate` ×
`timed_estimates` when it was repeated. Whether its method shares chunks between processes
comes from the same run's `--cells-csv` (column shares_chunks: method::shares_chunks, the flag
the planner splits by; `--model-only FOLDER…` re-models runs kept with --keep, whose folders hold
that file as cells.csv). A cell costing more than total/(4K) whose method shares chunks is split
across the K ranks by chunks (bench/quadmc/mpi_run.hpp): it takes cost / (min(K, C)·η), C its chunks
per repetition (N / 12288 rounded up: sampling's chunk, the smaller of the library's two, so the
model is on the generous side for rules). The ideal model takes η = 1; the second takes η the
split cells' efficiency measured in the 2-rank run (their cost at 1 rank over 2 × their wall
time at 2 ranks, at most 1: what splitting costs beside the work — the exchanges and waits, the
naive sum's second chain (core/split_naive_sum.hpp) — and what two busy cores cost each other;
with --model-only only the ideal one); the other cells — a costly cell whose method does not
share chunks among them — go to ranks by LPT (largest first to the least-loaded rank). Speedup = total / (Σ split times + LPT makespan); the model ignores
communication (one allgather per window of 4096 chunks and one gather per run) and the ranks'
start-up, so it is an upper bound, and it says which cell bounds it.
"""

import argparse
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
CHUNK = 12288
MPIRUN = ["mpirun", "--oversubscribe", "--allow-run-as-root", "--mca", "btl", "self,vader",
          "--mca", "btl_vader_single_copy_mechanism", "none"]


def sharing(cells_csv):
    """Method label -> whether its cells share chunks, from `quadmc run --cells-csv`."""
    shares = {}
    with open(cells_csv, newline="", encoding="utf-8") as f:
        for row in csv.DictReader(f):
            flag = row["shares_chunks"] == "1"
            if shares.setdefault(row["method"], flag) != flag:
                sys.exit(f"scaling.py: {cells_csv}: method {row['method']} has cells that share "
                         "chunks and cells that do not; the model keys the flag by method")
    return shares


def placements(cells_csv):
    """(split cells, split cells whose method does not share) of a `--cells-csv` file."""
    split = unshared = 0
    with open(cells_csv, newline="", encoding="utf-8") as f:
        for row in csv.DictReader(f):
            if row["placement"] == "split":
                split += 1
                unshared += row["shares_chunks"] != "1"
    return split, unshared


def cells(csv_path, shares):
    with open(csv_path, newline="", encoding="utf-8") as f:
        for row in csv.DictReader(f):
            seconds = cell_seconds(row)
            evals = int(row["evaluations"])
            name = f'{row["method"]} × {row["integrand"]}, N = {row["N"] or row["tolerance"]}'
            if row["method"] not in shares:
                sys.exit(f"scaling.py: method {row['method']} is not in the run's cells CSV")
            yield name, seconds, max(1, math.ceil(evals / CHUNK)), shares[row["method"]]


def cell_seconds(row):
    seconds = float(row["seconds"])  # all repetitions of the cell
    timed = int(row.get("timed_estimates") or 0)
    if timed > 1:
        seconds += float(row["seconds_per_estimate"]) * timed
    return seconds


def split_efficiency(one_csv, two_csv, two_cells):
    """η: the split cells' cost at 1 rank over 2 × their wall time at 2 ranks (capped at 1)."""
    split = set()
    with open(two_cells, newline="", encoding="utf-8") as f:
        for row in csv.DictReader(f):
            if row["placement"] == "split":
                split.add((row["integrand"], row["method"], row["N"], row["tolerance"]))

    def split_seconds(path):
        total = 0.0
        with open(path, newline="", encoding="utf-8") as f:
            for row in csv.DictReader(f):
                key = (row["integrand"], row["method"], row["N"] if not row["tolerance"] else "",
                       row["tolerance"])
                if key in split:
                    total += cell_seconds(row)
        return total

    one, two = split_seconds(one_csv), split_seconds(two_csv)
    return min(1.0, one / (2.0 * two)) if two > 0 else 1.0


def model(costs, ranks, efficiency=1.0):
    total = sum(c for _, c, _, _ in costs)
    threshold = total / (4.0 * ranks)
    split = [(n, c, k) for n, c, k, shares in costs if c > threshold and shares]
    rest = sorted(((n, c) for n, c, _, shares in costs if c <= threshold or not shares),
                  key=lambda x: -x[1])
    split_time = sum(c / (min(ranks, k) * efficiency) for _, c, k in split)
    loads = [0.0] * ranks
    for _, c in rest:
        i = loads.index(min(loads))
        loads[i] += c
    makespan = split_time + max(loads)
    # What bounds it: the split cell with the longest time on its ranks, or the largest unsplit.
    worst_split = max(split, key=lambda x: x[1] / min(ranks, x[2]), default=None)
    largest_rest = rest[0] if rest else None
    if worst_split and (not largest_rest or
                        worst_split[1] / min(ranks, worst_split[2]) >= largest_rest[1]):
        bound = (f"split cell {worst_split[0]}: {worst_split[2]} chunks, "
                 f"{worst_split[1] / (min(ranks, worst_split[2]) * efficiency):.3g} s on its "
                 "ranks")
    elif largest_rest:
        bound = f"largest unsplit cell {largest_rest[0]}: {largest_rest[1]:.3g} s"
    else:
        bound = "—"
    return total / makespan, len(split), bound


def add_model(row, costs, efficiency=math.nan):
    row["split_efficiency_2"] = efficiency
    for k in (8, 64, 1024):
        speedup, split, bound = model(costs, k)
        row[f"model_speedup_{k}"] = speedup
        row[f"model_efficiency_{k}"] = speedup / k
        row[f"split_cells_{k}"] = split
        row[f"bound_{k}"] = bound
        eta_speedup = model(costs, k, efficiency)[0] if not math.isnan(efficiency) else math.nan
        row[f"model_eta_speedup_{k}"] = eta_speedup
        row[f"model_eta_efficiency_{k}"] = eta_speedup / k


def shown_args():
    """The command line as the page shows it: --keep names a scratch folder of this machine."""
    args, skip = [], False
    for a in sys.argv[1:]:
        if skip:
            skip = False
        elif a == "--keep":
            skip = True
        elif not a.startswith("--keep="):
            args.append(a)
    return args


def timed(command, cwd):
    start = time.monotonic()
    done = subprocess.run(command, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                          text=True, check=False)
    seconds = time.monotonic() - start
    if done.returncode != 0:
        sys.exit(f"scaling.py: {' '.join(command)} failed ({done.returncode}): {done.stderr}")
    return seconds


def answer_lines(rows):
    """The page's answer, from its table: the measured 2-rank speedups, and per scene the rank count
    from which the modelled efficiency falls below 50 % with what bounds it (or its efficiency at
    the table's largest rank count)."""
    lines = []
    measured = [r for r in rows if not math.isnan(r["one_rank_s"])]
    if measured:
        lines.append("**Measured on 2 ranks:** " + ", ".join(
            f'{r["scene"]} {r["measured_speedup_2"]:.2f}× '
            f'({100 * r["measured_speedup_2"] / 2:.0f} % efficiency)' for r in measured) +
            "; every column but timing equals the 1-rank run.")
    parts = []
    for r in rows:
        below = [k for k in (8, 64, 1024) if r[f"model_efficiency_{k}"] < 0.5]
        if below:
            k = below[0]
            parts.append(f'{r["scene"]} falls below 50 % efficiency at {k} ranks '
                         f'({r[f"model_speedup_{k}"]:.1f}×; what bounds it: {r[f"bound_{k}"]})')
        else:
            parts.append(f'{r["scene"]} keeps {100 * r["model_efficiency_1024"]:.0f} % efficiency '
                         f'at 1024 ranks ({r["model_speedup_1024"]:.1f}×)')
    lines.append("**Modelled from the 1-rank cells' costs (ideal model):** " + "; ".join(parts) + ".")
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quadmc")
    ap.add_argument("--scene", action="append", default=[])
    ap.add_argument("--out", required=True)
    ap.add_argument("--keep", help="keep the 1- and 2-rank results folders here (with cells.csv)")
    ap.add_argument("--model-only", nargs="+", metavar="FOLDER", default=[],
                    help="model kept 1-rank folders (convergence.csv and cells.csv) without running")
    args = ap.parse_args()
    if bool(args.model_only) == bool(args.scene) or (args.scene and not args.quadmc):
        ap.error("give --quadmc with --scene (measure and model), or --model-only FOLDER…")
    quadmc = os.path.abspath(args.quadmc) if args.quadmc else ""
    rows = []
    for folder in args.model_only:
        shares = sharing(os.path.join(folder, "cells.csv"))
        costs = list(cells(os.path.join(folder, "convergence.csv"), shares))
        row = {"scene": os.path.basename(os.path.normpath(folder)), "cells": len(costs),
               "one_rank_s": math.nan, "two_ranks_s": math.nan, "measured_speedup_2": math.nan,
               "split_cells_2": "", "split_unshared_2": ""}
        add_model(row, costs)
        rows.append(row)
    with tempfile.TemporaryDirectory(prefix="quadmc_scaling_") as scratch:
        for scene in args.scene:
            name = os.path.splitext(os.path.basename(scene))[0]
            with open(scene, encoding="utf-8") as f:
                text = f.read()
            if "[output]" in text:
                sys.exit(f"scaling.py: {scene} has an [output] table; give a scene without it")
            copy = os.path.join(scratch, name + ".toml")
            # Plots off: the scaling is of the cells, not of matplotlib.
            with open(copy, "w", encoding="utf-8") as f:
                f.write(text + "\n[output]\nplots = false\n")
            one = os.path.join(scratch, name + "_1")
            two = os.path.join(scratch, name + "_2")
            one_cells = os.path.join(scratch, name + "_1_cells.csv")
            two_cells = os.path.join(scratch, name + "_2_cells.csv")
            t1 = timed([quadmc, "run", copy, "--threads", "1", "--out", one,
                        "--cells-csv", one_cells], scratch)
            t2 = timed(MPIRUN + ["-np", "2", quadmc, "run", copy, "--threads", "1", "--out", two,
                                 "--cells-csv", two_cells], scratch)
            shutil.copyfile(one_cells, os.path.join(one, "cells.csv"))
            shutil.copyfile(two_cells, os.path.join(two, "cells.csv"))
            same = subprocess.run(["/usr/bin/python3", os.path.join(HERE, "same_results.py"),
                                   one, two], capture_output=True, text=True, check=False)
            if same.returncode != 0:
                sys.exit(f"scaling.py: 2 ranks differ from 1 on {name}:\n{same.stdout}")
            costs = list(cells(os.path.join(one, "convergence.csv"), sharing(one_cells)))
            split_2, unshared_2 = placements(two_cells)
            if args.keep:
                for folder in (one, two):
                    shutil.copytree(folder, os.path.join(args.keep, os.path.basename(folder)),
                                    dirs_exist_ok=True)
            row = {"scene": name, "cells": len(costs), "one_rank_s": t1, "two_ranks_s": t2,
                   "measured_speedup_2": t1 / t2, "split_cells_2": split_2,
                   "split_unshared_2": unshared_2}
            add_model(row, costs, split_efficiency(os.path.join(one, "convergence.csv"),
                                                   os.path.join(two, "convergence.csv"),
                                                   two_cells))
            rows.append(row)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "scaling.csv"), "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    lines = ["# Scale-out on Open MPI", "",
             "Made by `" + " ".join(["/usr/bin/python3", "bench/scaling.py"] + shown_args()) + "`"
             " (the method and the model are in the script's docstring). One thread per rank; "
             "every column but timing of the 2-rank run equals the 1-rank run "
             "(`bench/same_results.py`). Only cells whose method shares chunks are split "
             "(`method::shares_chunks`, from the run's `--cells-csv`), in the run and in the "
             "model.", ""] + [f"> - {line}" for line in answer_lines(rows)] + ["",
             "| scene | cells | 1 rank (s) | 2 ranks (s) | measured speedup | split cells' "
             "efficiency η at 2 | modelled speedup (efficiency) at 8 / 64 / 1024 ranks, ideal | "
             "the same with η | cells split at 2 (run) / 8 / 64 / 1024 |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        model_text = " / ".join(f'{r[f"model_speedup_{k}"]:.1f} ({100 * r[f"model_efficiency_{k}"]:.0f} %)'
                                for k in (8, 64, 1024))
        eta_text = ("—" if math.isnan(r["split_efficiency_2"]) else
                    " / ".join(f'{r[f"model_eta_speedup_{k}"]:.1f} '
                               f'({100 * r[f"model_eta_efficiency_{k}"]:.0f} %)'
                               for k in (8, 64, 1024)))
        eta = ("—" if math.isnan(r["split_efficiency_2"]) else
               f'{100 * r["split_efficiency_2"]:.0f} %')
        split_text = " / ".join([str(r["split_cells_2"]) or "—"] +
                                [str(r[f"split_cells_{k}"]) for k in (8, 64, 1024)])
        measured = ("— | — | —" if math.isnan(r["one_rank_s"]) else
                    f'{r["one_rank_s"]:.1f} | {r["two_ranks_s"]:.1f} | '
                    f'{r["measured_speedup_2"]:.2f}×')
        lines.append(f'| {r["scene"]} | {r["cells"]} | {measured} | {eta} | {model_text} | '
                     f'{eta_text} | {split_text} |')
    lines += ["", "What bounds the modelled speedup (ideal model):", ""]
    for r in rows:
        for k in (8, 64, 1024):
            lines.append(f'- {r["scene"]}, {k} ranks: {r[f"bound_{k}"]}')
    with open(os.path.join(args.out, "README.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
