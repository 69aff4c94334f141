"""Sub-cell pressure pattern of the water in a geocontainer run
(doc/accuracy_vs_cost.md, section 1).

    /usr/bin/python3 doc/scripts/pressure_pattern.py RUN_DIR [water_level]

For every particles_NNNNN.vtu of RUN_DIR, over the water points (body 1)
far from the bag (|x - 1| > 0.4 m) and below y = 0.5 m, prints the time,
the number of points and the mean and standard deviation (kPa) of the
points' own `pressure` and of `projected_pressure` (the field the grid
integrates) minus the hydrostatic pressure rho g (water_level - y),
water_level 0.8 m unless given. Uses Debian's python3-numpy.
"""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from read_vtu import read_vtu  # noqa: E402

if len(sys.argv) < 2:
    sys.exit(__doc__)
directory = sys.argv[1]
level = float(sys.argv[2]) if len(sys.argv) > 2 else 0.8
try:
    pvd = open(os.path.join(directory, "particles.pvd")).read()
except OSError as e:
    sys.exit("pressure_pattern.py: %s (run with Output/Write particles = "
             "true)" % e)
print("time  points  pressure_mean  pressure_std  projected_mean  "
      "projected_std  (kPa, minus hydrostatic)")
for time, name in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd):
    fields = read_vtu(os.path.join(directory, name))
    if "projected_pressure" not in fields:
        sys.exit("pressure_pattern.py: %s has no projected_pressure (written "
                 "by an older fsgmpm)" % name)
    x = fields["Points"]
    water = ((fields["body_id"] == 1) & (x[:, 1] < 0.5)
             & (np.abs(x[:, 0] - 1.0) > 0.4))
    if not water.any():
        continue
    hydrostatic = 1000 * 9.81 * (level - x[water, 1])
    own = 1e-3 * (fields["pressure"][water] - hydrostatic)
    projected = 1e-3 * (fields["projected_pressure"][water] - hydrostatic)
    print("%.3f  %d  %.3f  %.3f  %.3f  %.3f"
          % (float(time), water.sum(), own.mean(), own.std(),
             projected.mean(), projected.std()))
