#!/usr/bin/env python3
"""The air cavity a geocontainer drags into the water as it enters.

    /usr/bin/python3 doc/scripts/entry_cavity.py polygon|ellipse RUN [H [LEVEL]]

For each output step (RUN/particles.pvd) of a drop (prm/geocontainer_*.prm) it
bins the points of every body into squares of side H (default 0.02 m;
take at least twice the point spacing, so that no square inside the water
is empty by chance) over 0.5 m on each side of the bag and below the
water's initial level LEVEL (default 0.8 m), and counts the empty squares
that connect to the top row: the air open to the atmosphere below the
undisturbed surface, i.e. the cavity behind the bag. Its area A and its
deepest point are printed with rho g A, the extra buoyancy it gives the bag
while the bag's top faces it (the bag displaces its own area and the
cavity's), against the bag's net weight (m - rho V) g.

The last columns compare the run's deceleration with a balance of those
forces, (m + m_a) dv/dt = (m - rho V) g - rho g A - rho C_d W v^2 / 2
(C_d = 2, m_a the section's potential-flow added mass:
doc/scripts/drag_balance.py), dv/dt of the run by central differences of
container_velocity_y over +-0.05 s.
"""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402
from drag_balance import balance  # noqa: E402
from read_vtu import read_vtu  # noqa: E402


def open_cavity(f, centre, h, level):
    from scipy.ndimage import label
    x, y = f["Points"][:, 0], f["Points"][:, 1]
    xs = np.arange(centre - 0.5, centre + 0.5 + 1e-9, h)
    ys = np.arange(level - np.floor(level / h) * h, level + 1e-9, h)
    counts, _, _ = np.histogram2d(x, y, bins=[xs, ys])
    empty = counts == 0
    labels, _ = label(empty)
    top = [v for v in set(labels[:, -1].tolist()) if v > 0]
    connected = np.isin(labels, top) & empty
    rows = np.where(connected.any(axis=0))[0]
    deepest = ys[rows.min()] if len(rows) else float("nan")
    return connected.sum() * h * h, deepest


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("ellipse", "polygon"):
        sys.exit(__doc__)
    shape, run = sys.argv[1], sys.argv[2]
    h = float(sys.argv[3]) if len(sys.argv) > 3 else 0.02
    level = float(sys.argv[4]) if len(sys.argv) > 4 else 0.8
    rho, g, cd = 1000., 9.81, 2.0
    # The section's width and added mass (one panel solve).
    width, _, m_a, _ = balance(shape)
    with open(os.path.join(run, "monitors.csv")) as f:
        rows = list(monitors_csv.DictReader(f))
    t = np.array([float(r["time"]) for r in rows])
    v = -np.array([float(r["container_velocity_y"]) for r in rows])
    xc = np.array([float(r["container_centre_x"]) for r in rows])
    mass = float(rows[0]["body_mass_0"]) + 0.3 * 0.62
    area = float(rows[0]["enclosed_area"])
    net = (mass - rho * area) * g
    inertia = mass + m_a
    print(f"{shape}: net weight {net:.0f} N/m, m + m_a = {inertia:.1f} kg/m, "
          f"squares of {h} m")
    print("t (s)  v (m/s)  cavity (m^2)  deepest (m)  rho g A (N/m)  "
          "dv/dt run  dv/dt balance")
    with open(os.path.join(run, "particles.pvd")) as f:
        pvd = f.read()
    for time, name in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"',
                                 pvd):
        T = float(time)
        if T <= 0 or T > t[-1] + 1e-9:
            continue
        f = read_vtu(os.path.join(run, name))
        A, deepest = open_cavity(f, np.interp(T, t, xc), h, level)
        vT = np.interp(T, t, v)
        lo, hi = max(T - 0.05, t[0]), min(T + 0.05, t[-1])
        dvdt = (np.interp(hi, t, v) - np.interp(lo, t, v)) / (hi - lo)
        model = (net - rho * g * A - 0.5 * rho * cd * width * vT * vT) / inertia
        print(f"{T:4.2f}  {vT:7.3f}  {A:12.4f}  {deepest:11.2f}  "
              f"{rho * g * A:13.0f}  {dvdt:9.2f}  {model:13.2f}")


if __name__ == "__main__":
    main()
