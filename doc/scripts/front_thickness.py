#!/usr/bin/env python3
"""The dam-break front read at a layer thickness, against the monitor's.

    /usr/bin/python3 doc/scripts/front_thickness.py [--width A] RUN [RUN ...]

For each output step of RUN (particles.pvd) the water's layer thickness
along the floor is sum(V_p) / dx over strips of width dx = A / 20 (one
cell of the shipped 20-cell runs), counted from the wall x = 0; the front
at thickness d is the right edge of the last strip, in the run of strips
from the wall, whose thickness is at least d (d = 1, 2 and 4 mm). The
monitor's front_position (the furthest non-flagged point plus half a
point spacing) is read from monitors.csv at the same times. For each it
prints, in Martin & Moyce's normalisation (Z = z/A, T = t sqrt(2 g/A),
A = 0.114 m by default), Z at T = 2 and 3, the late speed dZ/dT over
T = 2-3.2 (a straight-line fit) and, for an n^2 = 2 column, the RMS
against Martin & Moyce's tabulated front (T <= 3.3) without shift and
after the best delay (front_error.py's measures).
"""
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402
from front_error import read_reference, rms  # noqa: E402
from read_vtu import read_vtu  # noqa: E402


def fronts(run, width, thicknesses):
    with open(os.path.join(run, "particles.pvd")) as f:
        pvd = f.read()
    dx = width / 20
    out = {d: [] for d in thicknesses}
    times = []
    for time, name in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"',
                                 pvd):
        f = read_vtu(os.path.join(run, name))
        x = f["Points"][:, 0]
        strips = np.bincount((x / dx).astype(int), weights=f["volume"])
        thickness = strips / dx
        times.append(float(time))
        for d in thicknesses:
            thick = thickness >= d
            n = len(thick) if thick.all() else int(np.argmin(thick))
            out[d].append(n * dx)
    return np.array(times), out


def main(argv):
    width = 0.114
    if argv[:1] == ["--width"]:
        width = float(argv[1])
        argv = argv[2:]
    if not argv:
        sys.exit(__doc__)
    scale = math.sqrt(2 * 9.81 / width)
    mm = [p for p in read_reference("martin_moyce_1952_n2.csv")["front"]
          if p[0] <= 3.3 + 1e-9]
    thicknesses = (1e-3, 2e-3, 4e-3)
    print("run  front  Z(T=2)  Z(T=3)  dZ/dT(2-3.2)  mm_rms  mm_rms_delayed")
    for run in argv:
        t, by_thickness = fronts(run, width, thicknesses)
        with open(os.path.join(run, "monitors.csv")) as f:
            rows = list(monitors_csv.DictReader(f))
        tm = np.array([float(r["time"]) for r in rows])
        zm = np.array([float(r["front_position"]) for r in rows])
        series = {"monitor": np.interp(t, tm, zm)}
        for d in thicknesses:
            series[f"{d * 1e3:g} mm"] = np.array(by_thickness[d])
        T = t * scale
        for label, z in series.items():
            Z = z / width
            w = (T >= 2) & (T <= 3.2)
            slope = np.polyfit(T[w], Z[w], 1)[0] if w.sum() > 2 else math.nan
            front = list(zip(T, Z))
            ref = [(a, b) for a, b in mm if a <= T[-1]]
            best = min(rms(front, ref, 0.005 * k) for k in range(201))
            print(f"{os.path.basename(os.path.normpath(run))}  {label}  "
                  f"{np.interp(2, T, Z):.3f}  {np.interp(3, T, Z):.3f}  "
                  f"{slope:.3f}  {rms(front, ref):.3f}  {best:.3f}")


if __name__ == "__main__":
    main(sys.argv[1:])
