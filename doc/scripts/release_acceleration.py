#!/usr/bin/env python3
"""Initial acceleration of a geocontainer released at rest under water.

    /usr/bin/python3 doc/scripts/release_acceleration.py ellipse|polygon RUN [T]

RUN is the output directory of a run of prm/geocontainer_ellipse.prm or
prm/geocontainer_polygon.prm released fully under water (the commands are in
doc/geocontainer_validation.md, "Released under water"). From RUN/monitors.csv
(container_velocity_y, container_centre_y) over 0 <= t <= T (default
0.12 s) it prints the acceleration by two fits: of the velocity, v = a t,
and of the height, y = y_0 - a t^2 / 2. The sand's and the textile's
vibration puts steps into the velocity; both fits average over them.

The reference is the potential-flow added mass of the section
(doc/scripts/added_mass.py): a_0 = (m_bag - rho V) g / (m_bag + m_a), with
the run's own sand mass (body_mass_0) and enclosed area, the textile's
0.3 kg/m^2 over 0.62 m. The last line gives both fits' errors against it.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402
from added_mass import (AREA, CIRCUMFERENCE, POLYGON, added_mass,  # noqa: E402
                        ellipse, ellipse_axes, refine)


def section_added_mass(shape, rho=1000.):
    if shape == "ellipse":
        a, b = ellipse_axes(CIRCUMFERENCE, AREA)
        return added_mass(ellipse((0, 0), a, b, 2000), rho=rho)
    return added_mass(refine(POLYGON, 2000), rho=rho)


def measured(run, T=0.12):
    with open(os.path.join(run, "monitors.csv")) as f:
        rows = list(monitors_csv.DictReader(f))
    t = np.array([float(r["time"]) for r in rows])
    v = -np.array([float(r["container_velocity_y"]) for r in rows])
    y = np.array([float(r["container_centre_y"]) for r in rows])
    if t[-1] < T * (1 - 1e-6):
        sys.exit(f"{run} ends at {t[-1]} s, before T = {T} s")
    w = t <= T * (1 + 1e-9)
    a_velocity = np.sum(v[w] * t[w]) / np.sum(t[w] ** 2)
    a_height = -2 * np.polyfit(t[w] ** 2, y[w], 1)[0]
    first = rows[0]
    return (a_velocity, a_height, float(first["body_mass_0"]),
            float(first["enclosed_area"]))


def predicted(shape, sand_mass, area, rho=1000., g=9.81):
    m_bag = sand_mass + 0.3 * CIRCUMFERENCE
    m_a = section_added_mass(shape, rho)
    return (m_bag - rho * area) * g / (m_bag + m_a), m_a


def main():
    if len(sys.argv) not in (3, 4) or sys.argv[1] not in ("ellipse",
                                                          "polygon"):
        sys.exit(__doc__)
    shape, run = sys.argv[1], sys.argv[2]
    T = float(sys.argv[3]) if len(sys.argv) == 4 else 0.12
    a_v, a_y, sand, area = measured(run, T)
    a_0, m_a = predicted(shape, sand, area)
    print(f"{shape}: sand {sand:.3f} kg/m, enclosed area {area:.6f} m^2, "
          f"added mass {m_a:.2f} kg/m")
    print(f"potential flow a_0 = {a_0:.4f} m/s^2")
    print(f"fit v = a t over 0-{T} s: a = {a_v:.4f} m/s^2 "
          f"({a_v / a_0 - 1:+.1%})")
    print(f"fit y = y0 - a t^2/2:      a = {a_y:.4f} m/s^2 "
          f"({a_y / a_0 - 1:+.1%})")
    print(f"errors {a_v / a_0 - 1:.4f} {a_y / a_0 - 1:.4f}")


if __name__ == "__main__":
    main()
