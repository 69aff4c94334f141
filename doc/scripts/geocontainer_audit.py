"""Energy audit of a geocontainer drop (doc/geocontainer_validation.md, §5).

    /usr/bin/python3 doc/scripts/geocontainer_audit.py RUN_DIR [t1 t2 ...]

Reads RUN_DIR/monitors.csv (the scene monitors of prm/geocontainer_*.prm)
and prints, at each time t (default 0.2 0.4 0.8 and the run's end), the
sand's downward velocity, its centre height, the work gravity has done on
everything (external_work) and what that work says about the water:

    W = m_s g d_s + M_w g d_w        (d: fall of each centre of mass)
    rise of the water = -(W - m_s g d_s) / (M_w g)

Water that keeps its volume rises by rho_w A d_s / M_w once the bag
(sand area A) is under water, because the bag displaces it; a point cloud
that compacts falls instead and feeds the sinking with its own potential
energy. The membrane's own weight (0.5% of the sand's) is left out: it
moves the water's figure by about 0.04 mm in the shipped scene. The rows
use the first monitor row at or after each time.
"""
import sys
import os

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402

G = 9.81
RHO_W = 1000.0


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    path = sys.argv[1].rstrip("/") + "/monitors.csv"
    try:
        with open(path) as f:
            rows = list(monitors_csv.DictReader(f))
    except OSError as e:
        sys.exit("geocontainer_audit.py: cannot read %s (%s)" % (path, e))
    needed = ["time", "external_work", "container_centre_y",
              "container_velocity_y", "soil_area", "body_mass_0",
              "body_mass_1"]
    if not rows or any(k not in rows[0] for k in needed):
        sys.exit("geocontainer_audit.py: %s needs the columns %s (the "
                 "scene monitors of prm/geocontainer_*.prm)"
                 % (path, ", ".join(needed)))
    try:
        times = [float(t) for t in sys.argv[2:]] or [0.2, 0.4, 0.8]
    except ValueError as e:
        sys.exit("geocontainer_audit.py: the times must be numbers in "
                 "seconds (%s)" % e)
    end = float(rows[-1]["time"])
    if not sys.argv[2:] and end not in times:
        times.append(end)
    first = rows[0]
    m_s = float(first["body_mass_0"])
    m_w = float(first["body_mass_1"])
    area = float(first["soil_area"])
    y0 = float(first["container_centre_y"])
    print("time  v_down(m/s)  y_c(m)  gravity_work(J)  sand_share(J)  "
          "water_rise(mm)  displaced_rise(mm)")
    for t in times:
        row = next((r for r in rows
                    if float(r["time"]) >= t * (1 - 1e-12)), None)
        if row is None:
            print("%.3f  (after the run's end, %.4f s)" % (t, end))
            continue
        d_s = y0 - float(row["container_centre_y"])
        work = float(row["external_work"])
        rise = -(work - m_s * G * d_s) / (m_w * G)
        displaced = RHO_W * area * d_s / m_w
        print("%.3f  %.3f  %.4f  %.1f  %.1f  %.2f  %.2f"
              % (float(row["time"]), -float(row["container_velocity_y"]),
                 float(row["container_centre_y"]), work, m_s * G * d_s,
                 1e3 * rise, 1e3 * displaced))


main()
