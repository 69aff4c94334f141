#!/usr/bin/python3
"""Hoop, axial and shear parts of the tension of a 3D tube membrane
(doc/membrane_validation.md, the second-order Gmsh slab).

Usage: membrane_tension_components.py MEMBRANE_VTU [...]
Reads membrane_NNNNN.vtu written with `Output/Membrane output = finite
elements` (deal.II's DataOut: one VTK Lagrange triangle of 3 or 6 points per
cell, cell fields repeated at each of its points). For each cell, the hoop
direction is t = e_z x n (n the normal of its corners' plane) and the tension
tensor sigma (N/m) gives sigma_tt (hoop), sigma_zz (axial) and sigma_tz (in-plane
shear). Prints, weighted by the cells' current areas, the mean and the
largest major principal tension ("tension"), the mean hoop, axial and |shear|,
and the mean of sqrt(((tt - zz)/2)^2 + tz^2) + (tt + zz)/2 with tz set to 0
(what the major tension would be without the shear). Debian's python3 with
numpy.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from read_vtu import read_vtu  # noqa: E402


def components(path):
    fields = read_vtu(path)
    for name in ("tension", "tension_tensor"):
        if name not in fields:
            sys.exit(f"membrane_tension_components.py: no {name} in {path} "
                     "(write it with Output/Membrane output = finite "
                     "elements)")
    # In double precision: the file holds single precision, and sums of
    # thousands of cells in it would lose digits.
    points = fields["Points"].astype(np.float64)
    n_points = len(points)
    # VTK_LAGRANGE_TRIANGLE (69, degree 2): 6 points; VTK_TRIANGLE (5): 3.
    # Anything else (a 2D membrane's lines) is no tube surface.
    types = set(int(t) for t in fields["types"])
    if types not in ({69}, {5}):
        sys.exit(f"membrane_tension_components.py: {path} holds cells of "
                 f"VTK types {sorted(types)}, not the triangles of a 3D "
                 "membrane (5, or 69 at degree 2)")
    per_cell = 6 if types == {69} else 3
    n_cells = n_points // per_cell
    corner = points.reshape(n_cells, per_cell, 3)[:, :3, :]
    normal = np.cross(corner[:, 1] - corner[:, 0], corner[:, 2] - corner[:, 0])
    area = 0.5 * np.linalg.norm(normal, axis=1)
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    hoop = np.cross(np.array([0., 0., 1.]), normal)
    hoop /= np.linalg.norm(hoop, axis=1)[:, None]
    sigma = fields["tension_tensor"].astype(np.float64).reshape(
        n_cells, per_cell, 3, 3)[:, 0]
    major = fields["tension"].astype(np.float64).reshape(n_cells,
                                                          per_cell)[:, 0]
    z = np.array([0., 0., 1.])
    tt = np.einsum("ci,cij,cj->c", hoop, sigma, hoop)
    zz = np.einsum("j,cij,i->c", z, sigma, z)
    tz = np.einsum("ci,cij,j->c", hoop, sigma, z)
    no_shear = 0.5 * (tt + zz) + np.abs(0.5 * (tt - zz))
    w = area / area.sum()
    return {
        "cells": n_cells,
        "major mean": float(w @ major),
        "major max": float(major.max()),
        "hoop mean": float(w @ tt),
        "axial mean": float(w @ zz),
        "|shear| mean": float(w @ np.abs(tz)),
        "|shear| max": float(np.abs(tz).max()),
        "major without shear": float(w @ no_shear),
    }


def main(paths):
    if not paths:
        sys.exit(__doc__)
    for path in paths:
        c = components(path)
        print(f"{path}: {c['cells']} cells (N/m, area-weighted means)")
        for key in ("major mean", "major max", "hoop mean", "axial mean",
                    "|shear| mean", "|shear| max", "major without shear"):
            print(f"  {key:20s} {c[key]:10.0f}")


if __name__ == "__main__":
    main(sys.argv[1:])
