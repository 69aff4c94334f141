#!/usr/bin/python3
"""Output/Format = hdf5 against the VTU output of the same run.

Usage: hdf5_output.py FSGMPM SOURCE_DIR

Runs the coarse geotube (points and membrane), in 2D to 2 s and in 3D to
0.5 s, twice each, once with VTU and once with HDF5 + XDMF output, and checks, reading the XDMF as ParaView
does (every DataItem followed to its HDF5 dataset):
- both series have the same steps at the same times;
- every dataset the XDMF names exists with the dimensions it states, the
  topology lists every point once (points) or the membrane's elements;
- every field equals the VTU's: the points' (deal.II's compressed VTU in
  single precision, rounding 6e-8) to 2e-7 of each field's largest value, the membrane's
  (compressed VTU in double precision) exactly.
ParaView 5.11's XDMF reader (pvbatch, not in CI) reads both series with
their times, points, cells and arrays (doc/checkpoint_and_hdf5.md).
Uses Debian's python3-h5py and python3-numpy.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "doc", "scripts"))
from read_vtu import read_vtu  # noqa: E402

failures = []


def check(name, ok):
    print(("ok   " if ok else "FAIL ") + name)
    if not ok:
        failures.append(name)


def pvd_steps(path):
    root = ET.parse(path).getroot()
    return [(float(d.get("timestep")), d.get("file"))
            for d in root.iter("DataSet")]


def xdmf_steps(path):
    """[(time, {name: (h5 file, dataset, dims)}, topology type)] per step."""
    root = ET.parse(path).getroot()
    steps = []
    for grid in root.iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        items = {}
        for kind in ("Geometry", "Topology"):
            item = grid.find(kind).find("DataItem")
            items[kind] = item
        for attribute in grid.findall("Attribute"):
            items[attribute.get("Name")] = attribute.find("DataItem")
        parsed = {}
        for name, item in items.items():
            h5, dataset = item.text.strip().split(":/")
            dims = tuple(int(d) for d in item.get("Dimensions").split())
            parsed[name] = (h5, dataset, dims)
        steps.append((float(grid.find("Time").get("Value")), parsed,
                      grid.find("Topology").get("TopologyType")))
    return steps


def compare(vtu, h5, membrane_topology):
    """Check the XDMF series in h5 against the VTU series in vtu."""
    for series in ("particles", "membrane"):
        pvd = pvd_steps(os.path.join(vtu, series + ".pvd"))
        xdmf = xdmf_steps(os.path.join(h5, series + ".xdmf"))
        check(f"{series}: {len(xdmf)} steps at the VTU's times",
              len(pvd) == len(xdmf) > 1
              # The PVD carries 6 digits.
              and all(abs(a[0] - b[0]) <= 1e-5 * max(1, abs(b[0]))
                      for a, b in zip(pvd, xdmf)))
        worst = 0.0
        dims_ok = True
        for (t, vtu_file), (_, items, topology) in zip(pvd, xdmf):
            data = {}
            for name, (h5_file, dataset, dims) in items.items():
                with h5py.File(os.path.join(h5, h5_file), "r") as f:
                    values = f[dataset][()]
                # "N 1" (one node per point) is stored as N values.
                dims_ok = (dims_ok and values.shape[0] == dims[0]
                           and values.size == int(np.prod(dims)))
                data[name] = values.reshape(dims)
            n = data["Geometry"].shape[0]
            if series == "particles":
                ref = read_vtu(os.path.join(vtu, vtu_file))
                dims_ok = dims_ok and topology == "Polyvertex" and np.array_equal(
                    data["Topology"].ravel(), np.arange(n))
                pairs = [("Points", "Geometry")] + [
                    (k, k) for k in data if k not in ("Geometry", "Topology")]
            else:
                ref = read_vtu(os.path.join(vtu, vtu_file))
                dims_ok = (dims_ok and topology == membrane_topology
                           and np.array_equal(data["Topology"].ravel(),
                                              ref["connectivity"].astype(int)))
                pairs = [("Points", "Geometry"), ("tension", "tension"),
                         ("stretch", "stretch"), ("velocity", "velocity")]
            for vtu_name, h5_name in pairs:
                a = np.asarray(ref[vtu_name], dtype=float).ravel()
                b = np.asarray(data[h5_name], dtype=float).ravel()
                if a.size != b.size:
                    worst = np.inf
                    continue
                scale = max(np.abs(a).max(), 1e-300)
                worst = max(worst, np.abs(a - b).max() / scale)
        check(f"{series}: every dataset the XDMF names exists with its "
              f"dimensions and topology ({membrane_topology if series == 'membrane' else 'Polyvertex'})",
              dims_ok)
        tolerance = 2e-7 if series == "particles" else 0.0
        check(f"{series}: fields equal the VTU's (largest difference "
              f"{worst:.2e} of each field's maximum, tolerance {tolerance})",
              worst <= tolerance)
    size = lambda d, ext: sum(os.path.getsize(os.path.join(d, f))
                              for f in os.listdir(d) if f.endswith(ext))
    # Not asserted: the VTU files are compressed single precision, the HDF5
    # files uncompressed doubles.
    print(f"     VTU files {size(vtu, '.vtu')} bytes, HDF5 files "
          f"{size(h5, '.h5')} bytes")


def main(exe, source):
    work = tempfile.mkdtemp()
    cases = {
        # 2D: cables (Polyline).
        "2d": (["geotube_A5.56.prm", "Simulation/End time=2"], "Polyline"),
        # 3D: triangles, one cell thick.
        "3d": (["geotube_A5.56_3d.prm", "Simulation/End time=0.5",
                "Grid/Extrusion thickness=0.32"], "Triangle"),
    }
    for case, (settings, topology) in cases.items():
        cmd = [exe, os.path.join(source, "prm", settings[0]),
               "--set", "Grid/Cell size=0.32",
               "--set", "Output/Output interval=0.25",
               "--set", "Output/Quiet=true"]
        for s in settings[1:]:
            cmd += ["--set", s]
        for fmt in ("vtu", "hdf5"):
            subprocess.run(cmd + ["--set", f"Output/Format={fmt}", "--set",
                                  f"Output/Directory={work}/{case}_{fmt}"],
                           check=True)
        print(f"-- {case}")
        compare(f"{work}/{case}_vtu", f"{work}/{case}_hdf5", topology)
    shutil.rmtree(work)
    print(f"hdf5 output: {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
