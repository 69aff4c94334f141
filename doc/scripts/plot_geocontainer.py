#!/usr/bin/python3
"""Container velocity against time (doc/geocontainer_validation.md).

    /usr/bin/python3 doc/scripts/plot_geocontainer.py out.png \
        label1=dir1/monitors.csv label2=dir2/monitors.csv ...

Plots -container_velocity_y (downward positive) of each run with the
experiment as the paper reports it (accelerating until 0.4 s, 0.8 m/s at
0.8 s) and the terminal velocity of the drag balance
V = sqrt(2 g A (rho_s - rho_w)/(rho_w C_d b)) for C_d = 1 and 2.
doc/scripts/plot.py RUN_DIR calls plot() for a geocontainer run.
Uses Debian's python3-matplotlib.
"""
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402

# The experiment's point (paper Sec. 5): 0.8 m/s at 0.8 s.
EXPERIMENT_TIME, EXPERIMENT_VELOCITY = 0.8, 0.8


def read_velocity(path):
    """Times and downward velocities of the container in monitors.csv."""
    t, v = [], []
    with open(path) as f:
        for row in monitors_csv.DictReader(f):
            t.append(float(row["time"]))
            v.append(-float(row["container_velocity_y"]))
    return t, v


def plot(out, runs):
    """Draw the runs [(label, monitors.csv path), ...] into out (a PNG)."""
    fig, ax = plt.subplots(figsize=(8, 4.5))
    t_end = 0.0
    for label, path in runs:
        t, v = read_velocity(path)
        ax.plot(t, v, label=label)
        t_end = max([t_end] + t)
    A, b, g, rs, rw = 25 / (1900 * 0.65), 0.271, 9.81, 1900.0, 1000.0
    for cd, style in ((1, ":"), (2, "-.")):
        V = math.sqrt(2 * g * A * (rs - rw) / (rw * cd * b))
        ax.axhline(V, color="gray", ls=style, lw=1,
                   label="drag balance, C_d = %g: %.2f m/s" % (cd, V))
    ax.plot([EXPERIMENT_TIME], [EXPERIMENT_VELOCITY], "ks",
            label="experiment (paper): 0.8 m/s at 0.8 s")
    ax.axvline(0.4, color="k", lw=0.5, ls="--")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("downward velocity of the sand (m/s)")
    ax.set_xlim(0, max(1.3, t_end))
    ax.legend(fontsize=7, loc="upper right")
    ax.grid(lw=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main():
    plot(sys.argv[1], [tuple(item.split("=", 1)) for item in sys.argv[2:]])


if __name__ == "__main__":
    main()
