#!/usr/bin/python3
"""Compare the fields of two VTU (or HDF5) files written by fsgmpm.

Usage: compare_vtu.py <reference.vtu> <result.vtu> [--skip NAME]... [--quiet]

Reads every array with doc/scripts/read_vtu.py (every dataset with h5py
for a .h5 file) and requires the values to
be identical (bit for bit, as written), except the arrays named with
--skip. Exits 1 and names the arrays that differ or are missing; with
--quiet prints nothing if all agree.

With --points-in-any-order (the points of an MPI run: each process writes
its own, rank after rank, where a serial run writes them cell by cell),
the rows of the per-point arrays are put in one canonical order (sorted
by all their values) in both files before the comparison, and the
cells (one vertex per point) are only counted.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "doc", "scripts"))
from read_vtu import read_vtu  # noqa: E402


def read(path):
    if not path.endswith(".h5"):
        return read_vtu(path)
    import h5py
    arrays = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, item: arrays.__setitem__(name, item[()])
                     if isinstance(item, h5py.Dataset) else None)
    return arrays


def canonical(arrays):
    """The per-point arrays with their rows sorted (by every value of the
    row, the arrays in name order); the vertex cells replaced by their
    number."""
    points = arrays["Points"] if "Points" in arrays else arrays["nodes"]
    n = len(points)
    cells = {"connectivity", "offsets", "types", "cells"}
    names = sorted(k for k in arrays if k not in cells and len(arrays[k]) == n)
    columns = [arrays[k].reshape(n, -1)[:, j] for k in names
               for j in range(arrays[k].reshape(n, -1).shape[1])]
    order = np.lexsort(columns[::-1])
    result = {k: arrays[k][order] for k in names}
    for k in cells & set(arrays):
        result[k] = np.array([len(arrays[k])])
    return result


def main(argv):
    skip = [argv[i + 1] for i in range(len(argv) - 1) if argv[i] == "--skip"]
    quiet = "--quiet" in argv
    files = [a for i, a in enumerate(argv[1:], 1)
             if a not in ("--skip", "--quiet", "--points-in-any-order")
             and argv[i - 1] != "--skip"]
    reference, result = read(files[0]), read(files[1])
    if "--points-in-any-order" in argv:
        reference, result = canonical(reference), canonical(result)
    compared = [k for k in reference if k not in skip]
    bad = [k for k in compared
           if k not in result
           or reference[k].tobytes() != result[k].tobytes()
           or reference[k].dtype != result[k].dtype]
    if bad:
        print("  %s: differs in %s" % (files[1], ", ".join(bad)))
        return 1
    if not quiet:
        print("  %s: %d arrays identical" % (os.path.basename(files[1]),
                                            len(compared)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
