#!/usr/bin/python3
"""Compare water-column-collapse runs with Martin & Moyce (1952), n^2 = 2.

Usage: plot_dam_break.py OUT.png RUN_DIR[:LABEL] [RUN_DIR[:LABEL] ...]
       [--reference FILE] [--w0 0.114] [--g 9.81] [--n2 2] [--others]

Reads monitors.csv (columns time, front_position, column_height) of each run,
normalises as Martin & Moyce (front: T = t sqrt(2g/a), Z = z/a; height:
tau = t sqrt(g/a), H = eta/(n^2 a)), prints the errors against the experiment
(RMS of Z over the tabulated T <= 3.3, RMS of H over tau <= 3, no time shift)
and draws both series over the experimental points. A run that ends before
T = 3.3 or tau = 3 is compared over the experimental points inside its time
only (nothing is extrapolated past the end of a run), with a warning on
standard error that says how many points it covers. --others adds the
fronts of tests/reference/dam_break_fronts_n2.csv (Martin & Moyce's
smaller column and Koshizuka & Oka), which the errors do not use.
doc/scripts/plot.py RUN_DIR calls plot() for a dam-break run.
Uses Debian's /usr/bin/python3 with python3-matplotlib and python3-numpy.
"""
import argparse
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.path.join(HERE, "..", "..", "tests", "reference",
                         "martin_moyce_1952_n2.csv")
# The ranges of the experiment the errors are taken over.
T_MAX, TAU_MAX = 3.3, 3.0


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
    """RMS errors of Z and H over the experimental points that lie inside
    the run's time (T <= 3.3, tau <= 3 when the run covers them), and the
    normalised series. The fourth element gives, per series, the number of
    points used and of points in the full range."""
    t = mon["time"]
    T = t * np.sqrt(2 * g / a)
    tau = t * np.sqrt(g / a)
    Z = mon["front_position"] / a
    H = mon["column_height"] / (n2 * a)
    fr = ref["front"][ref["front"][:, 0] <= T_MAX + 1e-9]
    hr = ref["height"][ref["height"][:, 0] <= TAU_MAX + 1e-9]
    fr_in = fr[fr[:, 0] <= T[-1] + 1e-12]
    hr_in = hr[hr[:, 0] <= tau[-1] + 1e-12]

    def rms(points, x, y):
        if len(points) == 0:
            return float("nan")
        return np.sqrt(np.mean((np.interp(points[:, 0], x, y) - points[:, 1]) ** 2))

    z_err = rms(fr_in, T, Z)
    h_err = rms(hr_in, tau, H)
    coverage = {"front": (len(fr_in), len(fr)), "height": (len(hr_in), len(hr))}
    return z_err, h_err, (T, Z, tau, H), coverage


def coverage_warnings(label, mon, coverage, a, g):
    """Lines for standard error when the run ends before the reference's
    range; empty when it covers it."""
    t_end = mon["time"][-1]
    lines = []
    for key, name, end, scale, symbol in (
            ("front", "front", T_MAX, np.sqrt(2 * g / a), "T"),
            ("height", "height", TAU_MAX, np.sqrt(g / a), "tau")):
        used, total = coverage[key]
        if used < total:
            lines.append(
                "warning: %s ends at t = %.4g s (%s = %.3g), before the end of "
                "Martin & Moyce's %s data used (%s = %g, t = %.4g s): the %s "
                "error is over %d of %d points, the curve is not extrapolated"
                % (label, t_end, symbol, t_end * scale, name, symbol, end,
                   end / scale, name, used, total))
    return lines


def plot(output, runs, reference=REFERENCE, w0=0.114, g=9.81, n2=2.0,
         others=False, out=sys.stdout, err=sys.stderr):
    """Draw the runs [(run_dir, label), ...] over Martin & Moyce into
    output (a PNG path); print the errors to out and the warnings of runs
    that end before the reference's range to err. Returns
    [(label, z_err, h_err), ...]."""
    ref = read_reference(reference)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    ax1.plot(ref["front"][:, 0], ref["front"][:, 1], "ko", label="Martin & Moyce (1952)")
    ax2.plot(ref["height"][:, 0], ref["height"][:, 1], "ko", label="Martin & Moyce (1952)")
    if others:
        data_others = {}
        with open(os.path.join(HERE, "..", "..", "tests", "reference",
                               "dam_break_fronts_n2.csv")) as f:
            rows = [r for r in f if not r.startswith("#")]
        for row in csv.DictReader(rows):
            data_others.setdefault(row["series"], []).append(
                (float(row["time_dimensionless"]), float(row["value"])))
        for key, marker, label in (
                ("mm_small", "ks", "Martin & Moyce, a = 1.125 in"),
                ("ko", "k^", "Koshizuka & Oka (1996)")):
            data = np.array(data_others[key])
            ax1.plot(data[:, 0], data[:, 1], marker, mfc="none", label=label)
    results = []
    for run_dir, label in runs:
        mon = read_monitors(run_dir)
        label = label or os.path.basename(os.path.normpath(run_dir))
        z_err, h_err, (T, Z, tau, H), coverage = errors(mon, ref, w0, g, n2)
        for line in coverage_warnings(label, mon, coverage, w0, g):
            print(line, file=err)
        partial = lambda key: "" if coverage[key][0] == coverage[key][1] \
            else " over %d of %d points" % coverage[key]
        print("%s: front RMS error in Z (T <= %.3g) = %.3f%s, "
              "height RMS error in H (tau <= %.3g) = %.3f%s"
              % (label, min(T_MAX, T[-1]), z_err, partial("front"),
                 min(TAU_MAX, tau[-1]), h_err, partial("height")), file=out)
        ax1.plot(T, Z, label="%s (RMS %.2f%s)" % (label, z_err, partial("front")))
        ax2.plot(tau, H, label="%s (RMS %.3f%s)" % (label, h_err, partial("height")))
        results.append((label, z_err, h_err))
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
    fig.suptitle("Collapse of a water column, n^2 = %g" % n2)
    fig.tight_layout()
    fig.savefig(output, dpi=110)
    plt.close(fig)
    return results


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("output")
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--reference", default=REFERENCE)
    parser.add_argument("--w0", type=float, default=0.114)
    parser.add_argument("--g", type=float, default=9.81)
    parser.add_argument("--n2", type=float, default=2.0)
    parser.add_argument("--others", action="store_true")
    args = parser.parse_args()
    runs = []
    for run in args.runs:
        run_dir, _, label = run.partition(":")
        runs.append((run_dir, label))
    plot(args.output, runs, args.reference, args.w0, args.g, args.n2,
         args.others)


if __name__ == "__main__":
    sys.exit(main())
