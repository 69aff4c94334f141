#!/usr/bin/python3
"""Output/Write grid: the background grid's VTU against the mesh and the points.

Usage: grid_output.py FSGMPM SOURCE_DIR

Runs the coarse 2D dam break (60 x 25 squares, 3 000 triangles) and the 3D
one of tests/mpi (tetrahedra) for a few steps with grid output, and checks
every grid file written:
- one cell per triangle or tetrahedron of the mesh (VTK type 5 or 10), each
  with its own dim + 1 vertices, as deal.II's DataOut writes simplices;
- the cells tile the box: their areas (volumes), from the single-precision
  coordinates, add up to the box's (measured 1.0e-8 relative in 2D, 9e-9
  in 3D; asserted 1e-7), and no cell is smaller than half the mean (the
  box meshes' cells are all equal in 2D, 5/6 of the mean or more in 3D);
- every copy of a node (one per cell around it) carries the same values;
- mass: the nodal masses add up to the points' masses of the same output
  step (the shape functions are a partition of unity), to the single
  precision of the files (measured 3.5e-9 in 2D, 1.4e-8 in 3D; asserted
  1e-7).
Uses Debian's python3-numpy.
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "doc", "scripts"))
from read_vtu import read_vtu  # noqa: E402

failures = []


def check(name, ok, detail=""):
    print(("ok   " if ok else "FAIL ") + name + (" " + detail if detail else ""))
    if not ok:
        failures.append(name)


def cell_measures(points, dim):
    """Signed area (2D) or volume (3D) of every cell, dim + 1 points each."""
    x = points.reshape(-1, dim + 1, 3)[:, :, :dim].astype(np.float64)
    edges = x[:, 1:, :] - x[:, :1, :]
    return np.linalg.det(edges) / (2.0 if dim == 2 else 6.0)


def check_run(label, fsgmpm, prm, dim, box, n_cells, settings):
    with tempfile.TemporaryDirectory() as out:
        command = [fsgmpm, prm, "--set", "Output/Directory=" + out,
                   "--set", "Output/Write grid=true",
                   "--set", "Output/Write particles=true"] + settings
        result = subprocess.run(command, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True)
        check(label + ": run", result.returncode == 0, result.stdout[-500:]
              if result.returncode else "")
        grids = sorted(f for f in os.listdir(out)
                       if f.startswith("grid_") and f.endswith(".vtu"))
        check(label + ": grid files written", len(grids) >= 3,
              str(len(grids)))
        worst_mass = 0.0
        for name in grids:
            grid = read_vtu(os.path.join(out, name))
            points = read_vtu(os.path.join(out, name.replace(
                "grid_", "particles_")))
            cells = len(grid["types"])
            ok = (cells == n_cells
                  and np.all(grid["types"] == (5 if dim == 2 else 10))
                  and len(grid["Points"]) == (dim + 1) * cells
                  and np.array_equal(grid["connectivity"],
                                     np.arange((dim + 1) * cells))
                  and np.array_equal(grid["offsets"],
                                     (dim + 1) * np.arange(1, cells + 1)))
            check(label + " " + name + ": one cell per mesh cell", ok)
            measure = np.abs(cell_measures(grid["Points"], dim))
            box_measure = np.prod(box)
            check(label + " " + name + ": cells tile the box",
                  abs(measure.sum() - box_measure) < 1e-7 * box_measure
                  and measure.min() > 0.5 * box_measure / cells,
                  "sum %.9g box %.9g" % (measure.sum(), box_measure))
            # Copies of one node: equal coordinates, equal values.
            xyz = grid["Points"].astype(np.float64)
            keys = np.round(xyz / (np.max(box) * 1e-6)).astype(np.int64)
            _, first, inverse = np.unique(keys, axis=0, return_index=True,
                                          return_inverse=True)
            inverse = inverse.reshape(-1)
            same = True
            for field in ["nodal_mass", "velocity_x", "velocity_y",
                          "velocity_z"][:dim + 1]:
                values = grid[field]
                same = same and np.array_equal(values, values[first][inverse])
            check(label + " " + name + ": copies of a node agree", same)
            nodal = grid["nodal_mass"][first].astype(np.float64).sum()
            total = points["mass"].astype(np.float64).sum()
            error = abs(nodal - total) / total
            worst_mass = max(worst_mass, error)
            if name != grids[0]:  # the first file is before any p2g
                check(label + " " + name + ": nodal mass = points' mass",
                      error < 1e-7, "relative %.2e" % error)
        print(label + ": worst relative mass difference %.2e" % worst_mass)


def main(argv):
    fsgmpm, source = argv[1], argv[2]
    check_run("2D", fsgmpm,
              os.path.join(source, "prm", "default_dam_break.prm"), 2,
              [0.684, 0.285], 2 * 60 * 25,
              ["--set", "Grid/Subdivisions=60, 25",
               "--set", "Simulation/Maximum number of steps=40",
               "--set", "Output/Output interval=0.0001"])
    check_run("3D", fsgmpm,
              os.path.join(source, "tests", "mpi", "dam_break_3d.prm"), 3,
              [0.684, 0.285, 0.057], 5 * 24 * 10 * 2,
              ["--set", "Simulation/Maximum number of steps=40",
               "--set", "Output/Output interval=0.0002"])
    if failures:
        print("%d check(s) failed" % len(failures))
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
