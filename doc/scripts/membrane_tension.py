#!/usr/bin/python3
"""Tension statistics of a 2D membrane output (doc/accuracy_vs_cost.md §1).

Usage: membrane_tension.py MEMBRANE_VTU [...]
For each membrane_NNNNN.vtu (fsgmpm's ASCII output) prints the number of
cables, the mean, median, standard deviation and largest tension (N/m), the
number of slack cables (tension 0), and the tension of every cable along the
membrane in kN/m: a zigzag of taut and slack cables shows there. Debian's
python3 only.
"""
import re
import statistics
import sys


def tensions(path):
    with open(path) as f:
        text = f.read()
    match = re.search(r'<DataArray[^>]*Name="tension"[^>]*>(.*?)</DataArray>',
                      text, re.S)
    if match is None:
        sys.exit(f"membrane_tension.py: no tension field in {path}")
    return [float(x) for x in match.group(1).split()]


def main(paths):
    if not paths:
        sys.exit(__doc__)
    for path in paths:
        T = tensions(path)
        slack = sum(1 for t in T if t <= 0)
        print(f"{path}: {len(T)} cables, mean {statistics.mean(T):.0f}, "
              f"median {statistics.median(T):.0f}, "
              f"sd {statistics.pstdev(T):.0f}, max {max(T):.0f} N/m, "
              f"{slack} slack")
        print("  kN/m: " + " ".join(f"{t / 1e3:.0f}" for t in T))


if __name__ == "__main__":
    main(sys.argv[1:])
