#!/usr/bin/python3
"""Compare water-column-collapse runs with Martin & Moyce (1952), n^2 = 2.

Usage: plot_dam_break.py OUT.png RUN_DIR[:LABEL] [RUN_DIR[:LABEL] ...]
       [--reference FILE] [--w0 0.114] [--g 9.81] [--n2 2] [--others]

Reads monitors.csv (columns time, front_position, column_height) of each run,
normalises as Martin & Moyce (front: T = t sqrt(2g/a), Z = z/a; height:
tau = t sqrt(g/a), H = eta/(n^2 a)), prints the errors against the experiment
(RMS of Z over the tabulated T <= 3.3, RMS of H over tau <= 3, no time shift)
and draws both series over the experimental points. --others adds the
fronts of tests/reference/dam_break_fronts_n2.csv (Martin & Moyce's
smaller column and Koshizuka & Oka), which the errors do not use.
Uses Debian's /usr/bin/python3 with python3-matplotlib and python3-numpy.
"""
import argparse
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402


def read_reference(path):
    series = {"front": [], "height": []}
    with open(path) as f:
        rows = [r for r in f if not r.startswith("#")]
    for row in csv.DictReader(rows):
        series[row["series"]].append((float(row["time"]), float(row["value"])))
    return {k: np.array(v) for k, v in series.items()}


def read_monitors(run_dir):
    with open(os.path.join(run_dir, "monitors.csv")) as f:
        reader = monitors_csv.DictReader(f)
        data = {k: [] for k in reader.fieldnames}
        for row in reader:
            for k in reader.fieldnames:
                # Empty: an undefined Eq. (30) ratio (no external work yet).
                data[k].append(float(row[k]) if row[k] else float("nan"))
    return {k: np.array(v) for k, v in data.items()}


def errors(mon, ref, a, g, n2):
    t = mon["time"]
    T = t * np.sqrt(2 * g / a)
    tau = t * np.sqrt(g / a)
    Z = mon["front_position"] / a
    H = mon["column_height"] / (n2 * a)
    fr = ref["front"][ref["front"][:, 0] <= 3.3 + 1e-9]
    hr = ref["height"][ref["height"][:, 0] <= 3.0 + 1e-9]
    z_err = np.sqrt(np.mean((np.interp(fr[:, 0], T, Z) - fr[:, 1]) ** 2))
    h_err = np.sqrt(np.mean((np.interp(hr[:, 0], tau, H) - hr[:, 1]) ** 2))
    return z_err, h_err, (T, Z, tau, H)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser()
    parser.add_argument("output")
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--reference", default=os.path.join(
        here, "..", "..", "tests", "reference", "martin_moyce_1952_n2.csv"))
    parser.add_argument("--w0", type=float, default=0.114)
    parser.add_argument("--g", type=float, default=9.81)
    parser.add_argument("--n2", type=float, default=2.0)
    parser.add_argument("--others", action="store_true")
    args = parser.parse_args()
    ref = read_reference(args.reference)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax1.plot(ref["front"][:, 0], ref["front"][:, 1], "ko", label="Martin & Moyce (1952)")
    ax2.plot(ref["height"][:, 0], ref["height"][:, 1], "ko", label="Martin & Moyce (1952)")
    if args.others:
        others = {}
        with open(os.path.join(here, "..", "..", "tests", "reference",
                               "dam_break_fronts_n2.csv")) as f:
            rows = [r for r in f if not r.startswith("#")]
        for row in csv.DictReader(rows):
            others.setdefault(row["series"], []).append(
                (float(row["time_dimensionless"]), float(row["value"])))
        for key, marker, label in (
                ("mm_small", "ks", "Martin & Moyce, a = 1.125 in"),
                ("ko", "k^", "Koshizuka & Oka (1996)")):
            data = np.array(others[key])
            ax1.plot(data[:, 0], data[:, 1], marker, mfc="none", label=label)
    for run in args.runs:
        run_dir, _, label = run.partition(":")
        mon = read_monitors(run_dir)
        z_err, h_err, (T, Z, tau, H) = errors(mon, ref, args.w0, args.g, args.n2)
        label = label or os.path.basename(run_dir.rstrip("/"))
        print("%s: front RMS error in Z (T <= 3.3) = %.3f, height RMS error in H (tau <= 3) = %.3f"
              % (label, z_err, h_err))
        ax1.plot(T, Z, label="%s (RMS %.2f)" % (label, z_err))
        ax2.plot(tau, H, label="%s (RMS %.3f)" % (label, h_err))
    ax1.set_xlabel("T = t sqrt(2g/a)")
    ax1.set_ylabel("Z = front / a")
    ax1.set_xlim(0, 3.5)
    ax1.set_ylim(0.8, 4.5)
    ax2.set_xlabel("tau = t sqrt(g/a)")
    ax2.set_ylabel("H = height / (n^2 a)")
    ax2.set_xlim(0, 3.5)
    ax2.set_ylim(0, 1.05)
    for ax in (ax1, ax2):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Collapse of a water column, n^2 = %g" % args.n2)
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)


if __name__ == "__main__":
    sys.exit(main())
