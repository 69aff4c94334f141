#!/bin/bash
# The membrane's tension tensor (Output/Membrane output = finite elements)
# read by doc/scripts/membrane_tension_components.py, on the shipped 3D
# geotube slab (degree 1, slip) after 300 steps. The slip gives the nodes
# stacked along z one x-y position and the z walls keep the rings in their
# planes, so the membrane is in plane strain: no in-plane shear (measured
# 9e-9 of the hoop tension: the file's single precision) and an axial
# tension nu / lambda_t^2 of the hoop one (nu = 0.3, lambda_t - 1 = 2e-6;
# measured 0.299999), which the script must recover from the cells'
# normals and the tensor. About 3 s.
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
assert abs(c["major mean"] / hoop - 1) < 1e-9, "major = hoop"
print("ok: hoop, axial and shear parts of the slab's tension")
PY
