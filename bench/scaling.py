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
`timed_estimates` when it was repeated (`--model-only FOLDER…` re-models kept runs, see --keep). A cell costing more than total/(4K) is split across the K
ranks by chunks (bench/quadmc/mpi_run.hpp): it takes cost / min(K, C), C its chunks per
repetition (N / 12288 rounded up: sampling's chunk, the smaller of the library's two, so the
model is on the generous side for rules); the other cells go to ranks by LPT (largest first to
the least-loaded rank). Speedup = total / (Σ split times + LPT makespan); the model ignores
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


def cells(csv_path):
    with open(csv_path, newline="", encoding="utf-8") as f:
        for row in csv.DictReader(f):
            seconds = float(row["seconds"])  # all repetitions of the cell
            timed = int(row.get("timed_estimates") or 0)
            if timed > 1:
                seconds += float(row["seconds_per_estimate"]) * timed
            evals = int(row["evaluations"])
            name = f'{row["method"]} × {row["integrand"]}, N = {row["N"] or row["tolerance"]}'
            yield name, seconds, max(1, math.ceil(evals / CHUNK))


def model(costs, ranks):
    total = sum(c for _, c, _ in costs)
    threshold = total / (4.0 * ranks)
    split = [(n, c, k) for n, c, k in costs if c > threshold]
    rest = sorted(((n, c) for n, c, _ in costs if c <= threshold), key=lambda x: -x[1])
    split_time = sum(c / min(ranks, k) for _, c, k in split)
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
                 f"{worst_split[1] / min(ranks, worst_split[2]):.3g} s on its ranks")
    elif largest_rest:
        bound = f"largest unsplit cell {largest_rest[0]}: {largest_rest[1]:.3g} s"
    else:
        bound = "—"
    return total / makespan, len(split), bound


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


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quadmc", required=True)
    ap.add_argument("--scene", action="append", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--keep", help="keep the 1- and 2-rank results folders here")
    args = ap.parse_args()
    quadmc = os.path.abspath(args.quadmc)
    rows = []
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
            t1 = timed([quadmc, "run", copy, "--threads", "1", "--out", one], scratch)
            t2 = timed(MPIRUN + ["-np", "2", quadmc, "run", copy, "--threads", "1", "--out", two],
                       scratch)
            same = subprocess.run(["/usr/bin/python3", os.path.join(HERE, "same_results.py"),
                                   one, two], capture_output=True, text=True, check=False)
            if same.returncode != 0:
                sys.exit(f"scaling.py: 2 ranks differ from 1 on {name}:\n{same.stdout}")
            costs = list(cells(os.path.join(one, "convergence.csv")))
            if args.keep:
                for folder in (one, two):
                    shutil.copytree(folder, os.path.join(args.keep, os.path.basename(folder)),
                                    dirs_exist_ok=True)
            row = {"scene": name, "cells": len(costs), "one_rank_s": t1, "two_ranks_s": t2,
                   "measured_speedup_2": t1 / t2}
            for k in (8, 64, 1024):
                speedup, split, bound = model(costs, k)
                row[f"model_speedup_{k}"] = speedup
                row[f"model_efficiency_{k}"] = speedup / k
                row[f"split_cells_{k}"] = split
                row[f"bound_{k}"] = bound
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
             "(`bench/same_results.py`).", "",
             "| scene | cells | 1 rank (s) | 2 ranks (s) | measured speedup | modelled speedup "
             "(efficiency) at 8 / 64 / 1024 ranks | cells split at 8 / 64 / 1024 |",
             "|---|---|---|---|---|---|---|"]
    for r in rows:
        model_text = " / ".join(f'{r[f"model_speedup_{k}"]:.1f} ({100 * r[f"model_efficiency_{k}"]:.0f} %)'
                                for k in (8, 64, 1024))
        split_text = " / ".join(str(r[f"split_cells_{k}"]) for k in (8, 64, 1024))
        lines.append(f'| {r["scene"]} | {r["cells"]} | {r["one_rank_s"]:.1f} | '
                     f'{r["two_ranks_s"]:.1f} | {r["measured_speedup_2"]:.2f}× | {model_text} | '
                     f'{split_text} |')
    lines += ["", "What bounds the modelled speedup:", ""]
    for r in rows:
        for k in (8, 64, 1024):
            lines.append(f'- {r["scene"]}, {k} ranks: {r[f"bound_{k}"]}')
    with open(os.path.join(args.out, "README.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
