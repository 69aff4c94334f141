#!/usr/bin/env python3
"""The sinking velocity of a bag released at rest under water, by a drag balance.

    /usr/bin/python3 doc/scripts/drag_balance.py ellipse|polygon [RUN]

(m + m_a) dv/dt = (m - rho V) g - rho C_d W v^2 / 2, released at rest:

    v(t) = v_t tanh(a_0 t / v_t),  a_0 = (m - rho V) g / (m + m_a),
    v_t = sqrt(2 (m - rho V) g / (rho C_d W)),

m the sand and textile per unit length, V the section's area, m_a its
potential-flow added mass (doc/scripts/added_mass.py), W its width across
the motion (the ellipse's 2a, the pentagon's 0.271 m). C_d is that of a
bluff two-dimensional section broadside to the flow at a high Reynolds
number (here about 2e5): 1.98 for a flat plate (Hoerner, Fluid-Dynamic
Drag, 1965, ch. 3) and about 1.6 for an elliptic cylinder of axis ratio
1:2 broadside (Delany & Sorensen, NACA TN 3038, 1953); the ellipse here
is flatter (1:3) and the pentagon pointed, so the table gives the band
C_d = 1.6 to 2.0. It ignores the wake's growth from rest (drag at the
steady coefficient from the start) and the walls.

With RUN (a run's output directory with monitors.csv) it prints the run's
velocity beside the balance's at the same times.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402
from added_mass import (AREA, CIRCUMFERENCE, POLYGON,  # noqa: E402
                        ellipse_axes, polygon_area)
from release_acceleration import section_added_mass  # noqa: E402


def balance(shape, rho=1000., g=9.81):
    if shape == "ellipse":
        width = 2 * ellipse_axes(CIRCUMFERENCE, AREA)[0]
        area = AREA
    else:
        x = [p[0] for p in POLYGON]
        width = max(x) - min(x)
        area = polygon_area(POLYGON)
    m = 1900 * area + 0.3 * CIRCUMFERENCE
    net = (m - rho * area) * g
    m_a = section_added_mass(shape, rho)
    a0 = net / (m + m_a)
    return (width, a0, m_a,
            lambda cd: math.sqrt(2 * net / (rho * cd * width)))


def main():
    if len(sys.argv) not in (2, 3) or sys.argv[1] not in ("ellipse",
                                                          "polygon"):
        sys.exit(__doc__)
    shape = sys.argv[1]
    width, a0, _, terminal = balance(shape)
    coefficients = (1.6, 2.0)
    times = [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0]
    run = None
    if len(sys.argv) == 3:
        with open(os.path.join(sys.argv[2], "monitors.csv")) as f:
            rows = list(monitors_csv.DictReader(f))
        t = np.array([float(r["time"]) for r in rows])
        v = -np.array([float(r["container_velocity_y"]) for r in rows])
        run = (t, v)
        times = [T for T in times if T <= t[-1] + 1e-9]
    print(f"{shape}: W = {width:.3f} m, a_0 = {a0:.3f} m/s^2, v_t = "
          + ", ".join(f"{terminal(c):.3f} m/s (C_d = {c})"
                      for c in coefficients))
    print("t (s)  " + "  ".join(f"C_d={c}" for c in coefficients)
          + ("  run" if run else ""))
    for T in times:
        cols = [terminal(c) * math.tanh(a0 * T / terminal(c))
                for c in coefficients]
        line = f"{T:4.2f}   " + "  ".join(f"{x:7.3f}" for x in cols)
        if run:
            line += f"  {np.interp(T, run[0], run[1]):6.3f}"
        print(line)


if __name__ == "__main__":
    main()
