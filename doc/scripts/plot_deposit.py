#!/usr/bin/python3
"""Deposit profiles of granular-column-collapse runs.

Usage: plot_deposit.py OUT.png RUN_DIR[:LABEL] [RUN_DIR[:LABEL] ...]
       [--L0 0.2] [--bin 0.01]

For each run, reads the last particles_*.vtu of RUN_DIR and draws the
deposit surface (the highest point top, y + half a point spacing, in bins
of width --bin along x), with the initial column (from particles_00000.vtu)
dashed. Prints the run-out (monitor runout, last row of monitors.csv) and
(L - L0)/L0. doc/scripts/plot.py RUN_DIR calls plot() for a deposit
run. Uses Debian's /usr/bin/python3 with python3-matplotlib and
python3-numpy.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402
from read_vtu import particle_files, read_vtu  # noqa: E402


def surface(path, bin_width):
    fields = read_vtu(path)
    x, y = fields["Points"][:, 0], fields["Points"][:, 1]
    top = y + 0.5 * np.sqrt(fields["volume"])
    edges = np.arange(0, x.max() + 2 * bin_width, bin_width)
    index = np.digitize(x, edges) - 1
    heights = np.zeros(len(edges) - 1)
    np.maximum.at(heights, index, top)
    return edges, heights


def last_runout(run_dir):
    with open(os.path.join(run_dir, "monitors.csv")) as f:
        rows = list(monitors_csv.DictReader(f))
    return float(rows[-1]["runout"]) if rows and "runout" in rows[-1] \
        else float("nan")


def plot(output, runs, L0=0.2, bin_width=0.01, out=sys.stdout):
    """Draw the deposit surfaces of the runs [(run_dir, label), ...] into
    output (a PNG path) and print each run-out to out. Raises
    FileNotFoundError for a run without particles_*.vtu."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(9, 3.5))
    for run_dir, label in runs:
        label = label or os.path.basename(os.path.normpath(run_dir))
        files = particle_files(run_dir)
        if not files:
            plt.close(fig)
            raise FileNotFoundError("no particles_*.vtu in " + run_dir)
        edges, heights = surface(files[-1], bin_width)
        runout = last_runout(run_dir)
        print("%s: run-out %.4f m, (L - L0)/L0 = %.3f"
              % (label, runout, (runout - L0) / L0), file=out)
        line, = ax.step(edges[:-1], heights, where="post",
                        label="%s ((L-L0)/L0 = %.2f)"
                        % (label, (runout - L0) / L0))
        edges0, heights0 = surface(files[0], bin_width)
        ax.step(edges0[:-1], heights0, where="post", ls="--", lw=0.8,
                color=line.get_color())
    ax.set_xlabel("x from the back wall (m)")
    ax.set_ylabel("deposit surface (m)")
    ax.set_aspect("equal")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(output, dpi=120)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output")
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--L0", type=float, default=0.2)
    parser.add_argument("--bin", type=float, default=0.01)
    args = parser.parse_args()
    runs = []
    for run in args.runs:
        run_dir, _, label = run.partition(":")
        runs.append((run_dir, label))
    try:
        plot(args.output, runs, args.L0, args.bin)
    except FileNotFoundError as e:
        sys.exit("plot_deposit.py: %s" % e)


if __name__ == "__main__":
    main()
