#!/usr/bin/env python3
"""Front error of dam-break runs against the n^2 = 2 experiments, no shift.

Usage: front_error.py [--width A] [--zmax Z] RUN_DIR [RUN_DIR ...]

For each run (a directory with monitors.csv holding front_position) prints
the RMS error in Z = z/a of the front against
  mm     Martin & Moyce (1952) tables, T <= 3.3 (tests/reference/
         martin_moyce_1952_n2.csv), without shift, and after the best
         constant delay s >= 0 of the simulation (as the ctest reports it);
  small  Martin & Moyce Fig. 3, a = 1.125 in;
  large  Martin & Moyce Fig. 3, a = 2.25 in, to T = 9.2;
  ko     Koshizuka & Oka (1996)
(tests/reference/dam_break_fronts_n2.csv), each over the experimental points
inside the simulated time and with Z <= zmax (default 5.5: the tank of
prm/water_column_collapse_n2.prm ends at Z = 6). T = t sqrt(2 g / a) with a
the column's width (default 0.114 m).
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.path.join(HERE, "..", "..", "tests", "reference")


def read_reference(name):
    series = {}
    with open(os.path.join(REFERENCE, name)) as f:
        rows = [r for r in f if r.strip() and not r.startswith("#")]
    for row in csv.reader(rows[1:]):  # after the header row
        series.setdefault(row[0], []).append((float(row[1]), float(row[2])))
    return series


def interpolate(samples, x):
    if x <= samples[0][0]:
        return samples[0][1]
    for (t0, v0), (t1, v1) in zip(samples, samples[1:]):
        if x <= t1:
            return v0 + (v1 - v0) * (x - t0) / (t1 - t0)
    return samples[-1][1]


def rms(front, points, shift=0.0):
    e = [(interpolate(front, max(0.0, T - shift)) - Z) ** 2 for T, Z in points]
    return math.sqrt(sum(e) / len(e)) if e else float("nan")


def main(argv):
    width, zmax, runs = 0.114, 5.5, []
    i = 0
    while i < len(argv):
        if argv[i] in ("--width", "--zmax"):
            if i + 1 == len(argv):
                sys.exit(f"front_error.py: {argv[i]} needs a value")
            try:
                value = float(argv[i + 1])
            except ValueError:
                sys.exit(f"front_error.py: {argv[i]} needs a number, "
                         f"not <{argv[i + 1]}>")
            if argv[i] == "--width":
                width = value
            else:
                zmax = value
            i += 2
        else:
            runs.append(argv[i])
            i += 1
    if not runs:
        sys.exit(__doc__)
    g = 9.81
    scale = math.sqrt(2 * g / width)
    mm = read_reference("martin_moyce_1952_n2.csv")["front"]
    other = read_reference("dam_break_fronts_n2.csv")
    print(f"{'run':40s} {'mm':>6s} {'shift_ms':>8s} {'mm_sh':>6s} "
          f"{'small':>6s} {'large':>6s} {'ko':>6s}")
    for run in runs:
        path = os.path.join(run, "monitors.csv")
        try:
            with open(path) as f:
                rows = list(monitors_csv.DictReader(f))
            front = [(float(r["time"]) * scale,
                      float(r["front_position"]) / width) for r in rows]
        except (OSError, KeyError, ValueError) as e:
            sys.exit(f"front_error.py: cannot read the front from {path}: {e}")
        t_end = front[-1][0]

        def inside(points):
            return [(T, Z) for T, Z in points if T <= t_end and Z <= zmax]

        ref = inside([p for p in mm if p[0] <= 3.3 + 1e-9])
        best = min((rms(front, ref, 0.005 * k), 0.005 * k)
                   for k in range(201))
        print(f"{os.path.basename(os.path.normpath(run)):40s} "
              f"{rms(front, ref):6.3f} {1e3 * best[1] / scale:8.1f} "
              f"{best[0]:6.3f} "
              f"{rms(front, inside(other['mm_small'])):6.3f} "
              f"{rms(front, inside(other['mm_large'])):6.3f} "
              f"{rms(front, inside(other['ko'])):6.3f}")


if __name__ == "__main__":
    main(sys.argv[1:])
