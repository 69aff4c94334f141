"""Snapshots of a geocontainer run like the paper's Figs. 11-14
(doc/geocontainer_validation.md): water points coloured by pressure
(0-9 kPa; the pressure of the stress the grid integrates,
`projected_pressure`, where the output has it) in the top row and by vorticity (-90 to 90 1/s) in the bottom
row, the sand in grey and the membrane as a line, at the given times.

    /usr/bin/python3 doc/scripts/plot_geocontainer_snapshots.py out.png \
        output/geocontainer_polygon 0.2,0.4,0.6,0.8,1.0

Reads particles_NNNNN.vtu and membrane_NNNNN.vtu through the .pvd files'
time stamps. Uses Debian's python3-matplotlib and python3-numpy.
"""
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from read_vtu import read_vtu  # noqa: E402


def series(directory, name):
    """(time, file) pairs of a .pvd collection."""
    text = open(os.path.join(directory, name + ".pvd")).read()
    return [(float(t), os.path.join(directory, f)) for t, f in
            re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', text)]


def nearest(pairs, t):
    return min(pairs, key=lambda p: abs(p[0] - t))


def membrane_points(path):
    fields = read_vtu(path)
    return (fields["Points"][:, :2],
            np.asarray(fields["connectivity"], int).reshape(-1, 2))


out, directory = sys.argv[1], sys.argv[2]
times = [float(t) for t in sys.argv[3].split(",")]
particles = series(directory, "particles")
membranes = series(directory, "membrane")
fig, axes = plt.subplots(2, len(times), figsize=(3.2 * len(times), 5.6),
                         squeeze=False)
for j, t in enumerate(times):
    t_p, f_p = nearest(particles, t)
    fields = read_vtu(f_p)
    x, y = fields["Points"][:, 0], fields["Points"][:, 1]
    water = fields["body_id"] != 0
    pts, segments = membrane_points(nearest(membranes, t)[1])
    pressure = ("projected_pressure" if "projected_pressure" in fields
                else "pressure")
    for i, (name, scale, cmap, vmin, vmax) in enumerate(
            ((pressure, 1e-3, "viridis", 0, 9),
             ("vorticity", 1.0, "coolwarm", -90, 90))):
        ax = axes[i][j]
        sc = ax.scatter(x[water], y[water], c=scale * fields[name][water],
                        s=0.3, cmap=cmap, vmin=vmin, vmax=vmax,
                        rasterized=True)
        ax.scatter(x[~water], y[~water], c="0.55", s=0.3, rasterized=True)
        for a, b in segments:
            ax.plot(pts[[a, b], 0], pts[[a, b], 1], "k", lw=0.8)
        ax.set_xlim(0.5, 1.5)
        ax.set_ylim(0.0, 1.0)
        ax.set_aspect("equal")
        ax.set_title("t = %.2f s" % t_p, fontsize=9)
        ax.tick_params(labelsize=7)
        if j == len(times) - 1:
            fig.colorbar(sc, ax=ax, shrink=0.8).set_label(
                "pressure (kPa)" if i == 0 else "vorticity (1/s)",
                fontsize=8)
fig.tight_layout()
fig.savefig(out, dpi=110)
print("wrote", out)
