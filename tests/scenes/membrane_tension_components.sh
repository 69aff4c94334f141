#!/bin/bash
# The membrane's tension tensor (Output/Membrane output = finite elements)
# read by doc/scripts/membrane_tension_components.py, on the shipped 3D
# geotube slab (degree 1, slip) after 300 steps. The slip gives the nodes
# stacked along z one x-y position and the z walls keep the rings in their
# planes, so the membrane is in plane strain: no in-plane shear (measured
# 9e-9 of the hoop tension: the file's single precision) and an axial
# tension nu / lambda_t^2 of the hoop one (nu = 0.3, lambda_t - 1 = 2e-6;
# measured 0.299999; the major tension the hoop one within 1.7e-9), which
# the script must recover from the cells' normals and the tensor. Then the 2D geotube (cables, 200 steps): DataOut
# pads each cable's 2x2 tensor to 3x3, which must be T t t^T (t the cable's
# direction from its end points in the file) with zero z row and column,
# trace T, minor tension 0. About 5 s.
# Usage: membrane_tension_components.sh <fsgmpm> <source dir>
set -eu
exe=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$exe" "$src/prm/geotube_A5.56_3d.prm" \
  --set "Simulation/Maximum number of steps=300" \
  --set "Output/Membrane output=finite elements" \
  --set "Output/Write particles=false" --set "Output/Quiet=true" \
  --set "Output/Directory=$work/out"
/usr/bin/python3 - "$src/doc/scripts" "$work/out/membrane_00001.vtu" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from membrane_tension_components import components

c = components(sys.argv[2])
hoop, axial = c["hoop mean"], c["axial mean"]
print(f"measured: {c['cells']} cells, hoop {hoop:.4f} N/m, axial/hoop "
      f"{axial / hoop:.6f}, largest |shear|/hoop {c['|shear| max'] / hoop:.2e}, "
      f"|major/hoop - 1| {abs(c['major mean'] / hoop - 1):.1e}")
assert c["cells"] == 1656, "the slab's membrane has 1656 triangles"
assert hoop > 10, "the membrane carries tension after 300 steps"
assert abs(axial / hoop - 0.3) < 1e-5, "plane strain: axial = 0.3 hoop"
assert c["|shear| max"] < 1e-7 * hoop, "no in-plane shear with the slip"
assert abs(c["major mean"] / hoop - 1) < 1e-8, "major = hoop"
print("ok: hoop, axial and shear parts of the slab's tension")
PY
"$exe" "$src/prm/geotube_A5.56.prm" \
  --set "Simulation/Maximum number of steps=200" \
  --set "Output/Membrane output=finite elements" \
  --set "Output/Write particles=false" --set "Output/Quiet=true" \
  --set "Output/Directory=$work/out_2d"
/usr/bin/python3 - "$src/doc/scripts" "$work/out_2d/membrane_00001.vtu" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
import numpy as np
from read_vtu import read_vtu

f = read_vtu(sys.argv[2])
assert set(int(t) for t in f["types"]) == {3}, "2D: VTK lines of 2 points"
points = f["Points"].astype(np.float64)
n = len(points) // 2
ends = points.reshape(n, 2, 3)
t = ends[:, 1] - ends[:, 0]
t /= np.linalg.norm(t, axis=1)[:, None]
sigma = f["tension_tensor"].astype(np.float64).reshape(n, 2, 3, 3)[:, 0]
T = f["tension"].astype(np.float64).reshape(n, 2)[:, 0]
minor = f["minor_tension"].astype(np.float64)
cable = np.abs(sigma - T[:, None, None] * np.einsum("ci,cj->cij", t, t)).max()
trace = np.abs(np.trace(sigma, axis1=1, axis2=2) - T).max()
print(f"measured: {n} cables, T {T.min():.4f}-{T.max():.4f} N/m, "
      f"|sigma - T t t^T| {cable / T.max():.1e} and |trace - T| "
      f"{trace / T.max():.1e} of the largest T")
assert T.min() > 10, "the cables carry tension after 200 steps"
assert np.all(sigma[:, 2, :] == 0) and np.all(sigma[:, :, 2] == 0), \
    "no z row or column in 2D"
assert np.all(minor == 0), "a cable has no minor tension"
# Measured 1.0e-5 (t from single-precision end points 6 cm apart) and
# 8.3e-8 (single precision).
assert cable < 1e-4 * T.max(), "sigma = T t t^T"
assert trace < 1e-6 * T.max(), "trace sigma = T"
print("ok: the 2D cables' tension tensor is T t t^T")
PY
