#!/usr/bin/python3
"""Final geotube shape(s) over the analytic shape.

Usage: plot_geotube.py <geotube_shape executable> <out.png> <nominal area>
                       <label>:<run output directory> ...
Each run directory holds membrane_shape.csv and monitors.csv (the last row
gives the enclosed area and membrane length). The analytic shapes are for
the nominal circumference 9.2 m and area (black), and for each run's
measured area and length (dashed). doc/scripts/plot.py RUN_DIR calls
plot() for a geotube run (without the executable it draws the run's shape
alone). Debian's python3 with matplotlib.
"""
import csv
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import os

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402


def analytic(exe, length, area):
    out = subprocess.check_output([exe, str(length), str(area)]).decode()
    lines = [l for l in out.splitlines() if l and l[0] not in "#x"]
    xy = [tuple(map(float, l.split(","))) for l in lines]
    return [p[0] for p in xy] + [xy[0][0]], [p[1] for p in xy] + [xy[0][1]]


def plot(exe, png, area, runs, circumference=9.2):
    """Draw the final shapes of the runs [(label, directory), ...] into png,
    with the analytic shapes of tests/reference/geotube_shape (exe; None:
    the runs' shapes alone) for the nominal circumference and area and for
    each run's own."""
    fig, ax = plt.subplots(figsize=(9, 5))
    if exe:
        nx, ny = analytic(exe, circumference, area)
        ax.plot(nx, ny, "k-", lw=1.6,
                label="analytic, nominal A = %s m$^2$" % area)
    for label, directory in runs:
        with open(os.path.join(directory, "membrane_shape.csv")) as f:
            xy = [(float(r["x"]), float(r["y"])) for r in csv.DictReader(f)]
        with open(os.path.join(directory, "monitors.csv")) as f:
            last = list(monitors_csv.DictReader(f))[-1]
        xc = 0.5 * (min(p[0] for p in xy) + max(p[0] for p in xy))
        x = [p[0] - xc for p in xy] + [xy[0][0] - xc]
        y = [p[1] for p in xy] + [xy[0][1]]
        line, = ax.plot(x, y, "-", lw=1.2, label=label)
        if exe:
            ax_, ay_ = analytic(exe, last["membrane_length"],
                                last["enclosed_area"])
            ax.plot(ax_, ay_, "--", lw=0.8, color=line.get_color(),
                    label="analytic, measured A = %.3f m$^2$"
                    % float(last["enclosed_area"]))
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.legend(fontsize=7, loc="upper right")
    ax.grid(lw=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def main():
    exe, png, area, runs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    plot(exe, png, area, [tuple(run.split(":", 1)) for run in runs])


if __name__ == "__main__":
    main()
