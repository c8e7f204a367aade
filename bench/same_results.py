#!/usr/bin/python3
"""Check that two quadmc results folders hold the same numbers in every column but timing.

Use:   /usr/bin/python3 bench/same_results.py EXPECTED ACTUAL [--relative-tolerance R]
       (CI: the committed results/default against a fresh run of README command 1)
Exit:  0 when convergence.csv, slopes.csv and who_leads.csv agree row for row, 1 with one line
       per difference (file, row key, column, both values; at most 20 shown), 2 for a usage or
       read error.
Not for: judging whether a change made convergence better or worse — that is `quadmc compare`,
which fits slopes and allows noise. This script says whether a figure moved at all, so a change
that moves one must come with regenerated results.

Compared: every column of the files except the timing ones (`seconds`, `evals_per_second`,
`seconds_per_estimate`, `seconds_spread`, `timed_estimates`), which depend on the machine's load. Rows are matched by their key (integrand, s, method, and N
and tolerance for convergence.csv, family, s and N for who_leads.csv); a row or column present on
one side only is a difference. who_leads.csv (the page's "Who leads at equal N" tables) is compared
where EXPECTED has it (a folder from before the file has none) and only with R = 0: it is made from
convergence.csv's errors, and where two methods are level to the last bits, bits that differ may
name the other one.
With R = 0 (the default) fields must be equal as text: the writer prints the shortest text that
reads back to the same double, so equal text is equal bits. R > 0 is for two machines with
different vector units, whose exp/cos differ in the last bits (the README's SIMD section): numbers
then agree when |a − b| ≤ R·max(|a|, |b|, |reference|), the row's exact integral setting the
scale of its error columns. Stdlib only (csv), so it runs wherever python3 does.
"""

import argparse
import csv
import math
import os
import sys

TIMING_COLUMNS = {"seconds", "evals_per_second", "seconds_per_estimate", "seconds_spread",
                  "timed_estimates"}
KEYS = {
    "convergence.csv": ("integrand", "s", "method", "N", "tolerance"),
    "slopes.csv": ("integrand", "s", "method"),
    "who_leads.csv": ("family", "s", "N"),
}
OPTIONAL_FILES = {"who_leads.csv"}  # added later: compared where the expected folder has it
EXACT_ONLY_FILES = {"who_leads.csv"}  # winners of near ties: compared as text only
OPTIONAL_KEYS = {"tolerance"}  # a column added later: empty when a file predates it
SHOWN = 20


def read_rows(path, key_columns):
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            header = reader.fieldnames or []
            rows = {}
            for row in reader:
                key = tuple(row.get(k, "") for k in key_columns)
                if key in rows:
                    print(f"same_results.py: {path}: row {'/'.join(key)} appears twice",
                          file=sys.stderr)
                    sys.exit(2)
                rows[key] = row
    except OSError as e:
        print(f"same_results.py: cannot read {path}: {e.strerror}", file=sys.stderr)
        sys.exit(2)
    missing = [k for k in key_columns if k not in header and k not in OPTIONAL_KEYS]
    if missing:
        print(f"same_results.py: {path}: no column {missing[0]}", file=sys.stderr)
        sys.exit(2)
    return header, rows


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def same(a, b, scale, tolerance):
    if a == b:
        return True
    if tolerance == 0.0:
        return False
    x, y = number(a), number(b)
    if x is None or y is None or math.isnan(x) or math.isnan(y):
        return False
    return abs(x - y) <= tolerance * max(abs(x), abs(y), scale)


def differences(expected_dir, actual_dir, name, tolerance):
    key_columns = KEYS[name]
    header_e, rows_e = read_rows(f"{expected_dir}/{name}", key_columns)
    header_a, rows_a = read_rows(f"{actual_dir}/{name}", key_columns)
    out = []
    for column in header_e:
        if column not in header_a and column not in TIMING_COLUMNS:
            out.append(f"{name}: column {column} is missing from {actual_dir}")
    for column in header_a:
        if column not in header_e and column not in TIMING_COLUMNS:
            out.append(f"{name}: column {column} is new in {actual_dir}")
    columns = [c for c in header_e if c in header_a and c not in TIMING_COLUMNS]
    for key, row_e in rows_e.items():
        row_a = rows_a.get(key)
        if row_a is None:
            out.append(f"{name}: row {'/'.join(key)} is missing from {actual_dir}")
            continue
        scale = abs(number(row_e.get("reference", "")) or 0.0)
        for column in columns:
            if not same(row_e[column], row_a[column], scale, tolerance):
                out.append(f"{name}: {'/'.join(key)}: {column}: expected {row_e[column]!r}, "
                           f"got {row_a[column]!r}")
    for key in rows_a:
        if key not in rows_e:
            out.append(f"{name}: row {'/'.join(key)} is new in {actual_dir}")
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("expected", help="results folder taken as right (e.g. results/default)")
    parser.add_argument("actual", help="results folder to check")
    parser.add_argument("--relative-tolerance", type=float, default=0.0, metavar="R",
                        help="0 = equal as text (default); see the module comment")
    args = parser.parse_args()
    if not (args.relative_tolerance >= 0.0 and math.isfinite(args.relative_tolerance)):
        parser.error(f"--relative-tolerance: expected a finite number >= 0, got "
                     f"{args.relative_tolerance}")
    found = []
    for name in KEYS:
        if name in OPTIONAL_FILES and not os.path.exists(f"{args.expected}/{name}"):
            continue
        if name in EXACT_ONLY_FILES and args.relative_tolerance != 0.0:
            continue
        found += differences(args.expected, args.actual, name, args.relative_tolerance)
    if found:
        for line in found[:SHOWN]:
            print(line)
        more = len(found) - SHOWN
        print(f"same_results.py: {len(found)} differences" + (f" ({more} not shown)" if more > 0
                                                               else ""))
        sys.exit(1)
    mode = "equal as text" if args.relative_tolerance == 0.0 else (
        f"within a relative {args.relative_tolerance:g}")
    print(f"same_results.py: {args.actual} matches {args.expected} in every non-timing column "
          f"({mode})")


if __name__ == "__main__":
    main()
