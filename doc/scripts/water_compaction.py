"""Geometric compaction of a body's point cloud (doc/geocontainer_validation.md).

    /usr/bin/python3 doc/scripts/water_compaction.py DIR [H [BODY]]

For every DIR/particles_NNNNN.vtu: bins the points of body BODY (default 1,
the water of the geocontainer scenes) into squares of side H (default
0.08 m, two 4 cm cells), keeps the interior squares (all eight neighbours
hold a point of the body) and prints the mean over them of
sum(reference volume) / H^2 and of sum(volume) / H^2, with the 10th and 90th
percentiles of the first. A value of 1 means the points fill their square
as their reference volumes say; 1.14 means 14% more reference volume is
packed into the square than fits: the cloud has compacted although the
points' volumes (and so the pressure) do not show it. Reference volume =
mass / density, density given by --density (default 1000).
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from read_vtu import particle_files, read_vtu  # noqa: E402

args = [a for a in sys.argv[1:] if not a.startswith("--density=")]
density = 1000.
for a in sys.argv[1:]:
    if a.startswith("--density="):
        density = float(a.split("=", 1)[1])
if not args:
    sys.exit(__doc__)
directory = args[0]
h = float(args[1]) if len(args) > 1 else 0.08
body = int(args[2]) if len(args) > 2 else 1
files = particle_files(directory)
if not files:
    sys.exit("no particles_*.vtu in " + directory)
print("file  interior_squares  ref_volume/H^2 (p10 p90)  volume/H^2")
for name in files:
    f = read_vtu(name)
    w = f["body_id"] == body
    i = (f["Points"][w, 0] / h).astype(int)
    j = (f["Points"][w, 1] / h).astype(int)
    i -= i.min() - 1
    j -= j.min() - 1
    shape = (i.max() + 2, j.max() + 2)
    ref, cur, count = np.zeros(shape), np.zeros(shape), np.zeros(shape)
    np.add.at(ref, (i, j), f["mass"][w] / density)
    np.add.at(cur, (i, j), f["volume"][w])
    np.add.at(count, (i, j), 1)
    inner = count > 0
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            inner &= np.roll(np.roll(count > 0, di, 0), dj, 1)
    if not inner.any():
        print("%s  0" % name.rsplit("/", 1)[1])
        continue
    r = ref[inner] / h**2
    print("%s  %d  %.3f (%.3f %.3f)  %.3f"
          % (name.rsplit("/", 1)[1], inner.sum(), r.mean(),
             np.percentile(r, 10), np.percentile(r, 90),
             (cur[inner] / h**2).mean()))
