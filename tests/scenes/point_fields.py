#!/usr/bin/python3
"""The points' derived output fields, against independent values.

Usage: point_fields.py FSGMPM SOURCE_DIR

- displacement: the elastic block of prm/elastic_block_drop.prm falls
  freely (stress free) until it meets the floor at 0.202 s; at 0.1 s every
  point has moved by -g t^2 / 2 (to the explicit steps' own offset, measured
  0.24 %) and not sideways; at the start by nothing. A scene of
  water alone writes no displacement (its points do not keep their start).
- plastic_strain, yielding: none for an elastic body; the granular column
  at rest (K0) has not yielded, collapsing (0.05 s) some points yield, and
  those have a positive accumulated plastic strain (the value itself is
  tested against simple shear in the Mohr-Coulomb unit test).
- stress: one 3 x 3 tensor array per point (VTK's tensor layout), symmetric,
  with plane strain's sigma_zz; pressure its -trace/3; ids and flags Int32.
- von_mises: q = sqrt(3 J2) of the whole stress (sigma_zz included), against
  the stress components of the same VTU file, on the K0 column of
  prm/granular_column_collapse.prm (q = (1 - K0) sigma_v at rest: not zero).
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(sys.argv[2], "doc", "scripts"))
from read_vtu import read_vtu  # noqa: E402

exe, source = sys.argv[1], sys.argv[2]
failures = []


def check(name, ok, detail=""):
    print(("ok   " if ok else "FAIL ") + name + (" " + detail if detail else ""))
    if not ok:
        failures.append(name)


work = tempfile.mkdtemp()
run = lambda prm, out, *extra: subprocess.run(
    [exe, os.path.join(source, "prm", prm), "--set", "Output/Quiet=true",
     "--set", "Output/Directory=" + os.path.join(work, out)] + list(extra),
    check=True)

run("elastic_block_drop.prm", "block", "--set", "Simulation/End time=0.1")
start = read_vtu(os.path.join(work, "block", "particles_00000.vtu"))
late = read_vtu(os.path.join(work, "block", "particles_00005.vtu"))
check("displacement zero at the start", np.all(start["displacement"] == 0))
t, g = 0.1, 9.81
u = late["displacement"]
exact = -0.5 * g * t * t
error = np.max(np.abs(u[:, 1] / exact - 1))
check("free fall: displacement_y = -g t^2/2 within 0.6 %", error < 6e-3,
      "(measured %.2e, %d points)" % (error, len(u)))
check("free fall: no sideways displacement",
      np.max(np.abs(u[:, 0])) < 1e-6 * abs(exact),
      "(%.1e m)" % np.max(np.abs(u[:, 0])))
check("von_mises of a stress-free fall is zero",
      np.max(late["von_mises"]) < 1e-6, "(%.1e Pa)" % np.max(late["von_mises"]))

run("default_dam_break.prm", "water", "--set", "Simulation/End time=0.002")
water = read_vtu(os.path.join(work, "water", "particles_00000.vtu"))
check("water alone: no displacement field", "displacement" not in water)

check("an elastic body: no plastic state",
      "plastic_strain" not in late and "yielding" not in late)

run("granular_column_collapse.prm", "soil",
    "--set", "Simulation/End time=0.05", "--set", "Output/Output interval=0.05")
soil = read_vtu(os.path.join(work, "soil", "particles_00000.vtu"))
collapsing = read_vtu(os.path.join(work, "soil", "particles_00001.vtu"))
check("soil at rest (K0) has not yielded",
      np.all(soil["plastic_strain"] == 0) and np.all(soil["yielding"] == 0))
ep, flag = collapsing["plastic_strain"], collapsing["yielding"]
check("collapsing soil: yield flags 0 or 1, some points yielding",
      set(np.unique(flag)) <= {0, 1} and np.count_nonzero(flag) > 0,
      "(%d of %d yielding at 0.05 s)" % (np.count_nonzero(flag), len(flag)))
check("collapsing soil: plastic strain >= 0, > 0 where yielding",
      np.all(ep >= 0) and np.all(ep[flag == 1] > 0),
      "(largest %.3g)" % ep.max())
stress = soil["stress"].reshape(-1, 3, 3)
check("stress: one 3 x 3 tensor per point, symmetric, sigma_zz of plane "
      "strain present, no out-of-plane shear",
      soil["stress"].shape == (len(soil["Points"]), 9)
      and np.array_equal(stress, np.transpose(stress, (0, 2, 1)))
      and np.all(stress[:, 2, 2] < 0) and np.all(stress[:, 0, 2] == 0)
      and np.all(stress[:, 1, 2] == 0),
      "(sigma_zz from %.3g to %.3g Pa)" % (stress[:, 2, 2].min(),
                                           stress[:, 2, 2].max()))
check("pressure = -trace(stress)/3",
      np.max(np.abs(soil["pressure"] + np.trace(stress, axis1=1, axis2=2) / 3))
      <= 1e-6 * np.max(np.abs(soil["pressure"])))
integers = ("material_id", "body_id", "free_surface", "yielding")
check("ids and flags are Int32",
      all(soil[k].dtype == np.int32 for k in integers),
      "(" + ", ".join("%s %s" % (k, soil[k].dtype) for k in integers) + ")")
sxx, syy, szz, sxy = stress[:, 0, 0], stress[:, 1, 1], stress[:, 2, 2], \
    stress[:, 0, 1]
mean = (sxx + syy + szz) / 3
q = np.sqrt(1.5 * ((sxx - mean) ** 2 + (syy - mean) ** 2 + (szz - mean) ** 2
                   + 2 * sxy ** 2))
scale = np.max(q)
difference = np.max(np.abs(soil["von_mises"] - q)) / scale
check("von_mises = sqrt(3 J2) of the stress components to 2e-7 (float32)",
      scale > 0 and difference < 2e-7,
      "(largest q %.4g Pa, difference %.1e of it)" % (scale, difference))

print("point fields: %d failed" % len(failures))
sys.exit(1 if failures else 0)
