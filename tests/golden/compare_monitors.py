#!/usr/bin/python3
"""Compare two monitors.csv files column by column.

Usage: compare_monitors.py <reference.csv> <result.csv> [--rtol R]

Every column present in the reference must be in the result with the same
number of rows. The difference of a value is taken relative to the largest
magnitude of its column in the reference (so columns that pass through zero,
such as external work at the start, are not judged by round-off against
zero). Prints the worst relative difference of each column and exits 1 if any
exceeds R (default 1e-9), or if the columns or rows differ.
"""
import csv
import math
import re
import sys


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    # The header names carry units ("time[s]"): compared without them, so
    # that references written before the units still compare.
    header = [re.sub(r"\[[^\]]*\]$", "", name) for name in rows[0]]
    data = rows[1:]
    return {name: [float(r[i]) for r in data] for i, name in enumerate(header)}, header


def main(argv):
    rtol = 1e-9
    args = []
    i = 1
    while i < len(argv):
        if argv[i] == "--rtol":
            rtol = float(argv[i + 1])
            i += 2
        else:
            args.append(argv[i])
            i += 1
    if len(args) != 2:
        print(__doc__)
        return 2
    ref, header = read(args[0])
    new, new_header = read(args[1])
    failed = False
    missing = [c for c in header if c not in new]
    extra = [c for c in new_header if c not in ref]
    if missing or extra:
        print("  columns differ: missing %s, extra %s" % (missing, extra))
        failed = True
    worst_all = 0.0
    for name in header:
        if name not in new:
            continue
        a, b = ref[name], new[name]
        if len(a) != len(b):
            print("  %-24s rows differ: %d in the reference, %d here" % (name, len(a), len(b)))
            failed = True
            continue
        scale = max((abs(x) for x in a), default=0.0)
        worst, row = 0.0, -1
        for k, (x, y) in enumerate(zip(a, b)):
            if math.isnan(x) != math.isnan(y):
                worst, row = math.inf, k
                break
            d = abs(x - y)
            rel = d / scale if scale > 0 else (0.0 if d == 0 else math.inf)
            if rel > worst:
                worst, row = rel, k
        flag = "FAIL" if worst > rtol else "ok"
        failed |= worst > rtol
        worst_all = max(worst_all, worst)
        print("  %-24s worst relative difference %.3e%s  %s"
              % (name, worst, " (row %d)" % (row + 1) if row >= 0 else "", flag))
    print("  worst over all columns %.3e (tolerance %.1e)" % (worst_all, rtol))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
