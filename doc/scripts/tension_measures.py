#!/usr/bin/env python3
"""Measures of the water's tension cut-off (doc/water_validation.md).

    /usr/bin/python3 doc/scripts/tension_measures.py front RUN [RUN ...]
    /usr/bin/python3 doc/scripts/tension_measures.py pressure RUN BODY

front: for dam-break runs (prm/water_column_collapse_n*.prm, column width
a = 0.114 m), the front Z = z/a at T = t sqrt(2 g/a) = 2 and 3, its slope
dZ/dT over T = 2-3.2 (a straight-line fit), and the clustering of the
last particles_*.vtu: the share of the points not flagged as free surface
whose nearest neighbour is closer than a quarter of the mean spacing
sqrt(median point volume).

pressure: for each particles_*.vtu of RUN after the first, the share of
body BODY's points in tension (pressure below -1 Pa), the lowest point
pressure, and the same for projected_pressure (the projected nodal stress,
the field the grid integrates), and the share flagged as free surface.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402
from read_vtu import particle_files, read_vtu  # noqa: E402


def front(run, a=0.114, g=9.81):
    with open(os.path.join(run, "monitors.csv")) as f:
        rows = list(monitors_csv.DictReader(f))
    t = np.array([float(r["time"]) for r in rows])
    z = np.array([float(r["front_position"]) for r in rows])
    return t * math.sqrt(2 * g / a), z / a


def clustering(run):
    from scipy.spatial import cKDTree
    f = read_vtu(particle_files(run)[-1])
    x = f["Points"][:, :2]
    inside = f["free_surface"] == 0
    spacing = math.sqrt(np.median(f["volume"]))
    d, _ = cKDTree(x).query(x[inside], k=2)
    return np.mean(d[:, 1] < 0.25 * spacing)


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("front", "pressure"):
        sys.exit(__doc__)
    if sys.argv[1] == "front":
        print("run  Z(T=2)  Z(T=3)  dZ/dT(T=2-3.2)  close_pairs")
        for run in sys.argv[2:]:
            T, Z = front(run)
            w = (T >= 2) & (T <= 3.2)
            slope = np.polyfit(T[w], Z[w], 1)[0]
            print(f"{run}  {np.interp(2, T, Z):.3f}  {np.interp(3, T, Z):.3f}"
                  f"  {slope:.3f}  {clustering(run):.2%}")
        return
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    run, body = sys.argv[2], int(sys.argv[3])
    print("file  in_tension  lowest_p_kPa  projected_in_tension  "
          "lowest_projected_kPa  free_surface")
    for name in particle_files(run)[1:]:
        f = read_vtu(name)
        w = f["body_id"] == body
        p, q = f["pressure"][w], f["projected_pressure"][w]
        print(f"{os.path.basename(name)}  {np.mean(p < -1):.1%}  "
              f"{p.min() / 1e3:.1f}  {np.mean(q < -1):.1%}  "
              f"{q.min() / 1e3:.1f}  {np.mean(f['free_surface'][w]):.1%}")


if __name__ == "__main__":
    main()
