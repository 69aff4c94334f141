#!/usr/bin/python3
"""The energy balance of a run, booked (doc/stability.md).

Usage: energy_booking.py <output directory or monitors.csv> [...]

Prints, for the last row of each monitors.csv, the external work, the
booked losses (damping, material, numerical, outflow) and the residual
kinetic + strain - initial - work + every booked loss, also without the
booked losses other than damping (the balance before they were booked), as
a markdown table row.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402


def row(path):
    if os.path.isdir(path):
        path = os.path.join(path, "monitors.csv")
    rows = list(monitors_csv.DictReader(open(path)))
    f = lambda r, k: float(r[k])
    first, last = rows[0], rows[-1]
    e0 = f(first, "kinetic_energy") + f(first, "strain_energy")
    stored = f(last, "kinetic_energy") + f(last, "strain_energy")
    work = f(last, "external_work")
    losses = [f(last, k) for k in ("dissipated_energy", "material_dissipation",
                                   "numerical_dissipation", "outflow_energy")]
    residual = stored - (e0 + work - sum(losses))
    before = stored - (e0 + work - losses[0])
    share = lambda x: "%.3g (%+.1f %%)" % (x, 100 * x / work) if work else "%.3g" % x
    return "| %s (to %.3g s) | %.4g | %s |" % (
        os.path.basename(os.path.dirname(os.path.abspath(path))),
        f(last, "time"), work,
        " | ".join([share(x) for x in losses] + [share(residual), share(before)]))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        print(__doc__)
        sys.exit(2)
    for p in sys.argv[1:]:
        print(row(p))
