#!/usr/bin/python3
"""Table rows of the geotube mesh study (doc/membrane_validation.md).

Usage: geotube_table.py <geotube_shape executable> <average from (s)>
                        <A>:<cell cm>:<run output directory> ...
Averages monitors.csv from the given time to the end (the relaxation's
residual sloshing moves single samples by a few per cent) and compares with
the analytic solution for the nominal circumference 9.2 m and area and for
the run's measured enclosed area and membrane length. The wall time and the
step count come from the run's summary.json. Debian's python3 only.
"""
import json
import subprocess
import sys
import os

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402


def analytic(exe, length, area):
    head = subprocess.check_output([exe, str(length), str(area)]).decode()
    words = head.splitlines()[0].lstrip("# ").split()
    return {words[i]: float(words[i + 1]) for i in range(0, len(words), 2)}


def main():
    exe, t0, runs = sys.argv[1], float(sys.argv[2]), sys.argv[3:]
    print("| A (m²) | cell (cm) | H/W | nominal H/W (error) | measured-A H/W"
          " (error) | T (kN/m) | nominal T (error) | measured-A T (error) |"
          " p_top / p_bottom (kPa) | nominal p_top / p_bottom | contact (m)"
          " (nominal) | enclosed / fluid (m²) | force ratio median (min) |"
          " steps | wall (s) |")
    print("|" + " --- |" * 15)
    for run in runs:
        area, cell, directory = run.split(":", 2)
        with open(directory + "/monitors.csv") as f:
            rows = [r for r in monitors_csv.DictReader(f)
                    if float(r["time"]) >= t0]
        # An empty field is an undefined Eq. (30) ratio (no external work).
        rows = [{k: float(v) if v else float("inf") for k, v in r.items()}
                for r in rows]
        mean = {k: sum(r[k] for r in rows) / len(rows) for k in rows[0]}
        forces = sorted(r["dr_force_ratio"] for r in rows)
        with open(directory + "/summary.json") as f:
            summary = json.load(f)
        nom = analytic(exe, 9.2, area)
        mea = analytic(exe, mean["membrane_length"], mean["enclosed_area"])
        hw = mean["height"] / mean["width"]
        T = mean["mean_tension"]
        print("| %s | %s | %.4f | %.4f (%+.4f) | %.4f (%+.4f) | %.2f |"
              " %.2f (%+.1f%%) | %.2f (%+.1f%%) | %.2f / %.2f | %.2f / %.2f |"
              " %.2f (%.2f) | %.3f / %.3f | %.3f (%.3f) | %s | %.0f |" % (
                  area, cell, hw,
                  nom["height"] / nom["width"], hw - nom["height"] / nom["width"],
                  mea["height"] / mea["width"], hw - mea["height"] / mea["width"],
                  T / 1e3, nom["tension"] / 1e3, 100 * (T / nom["tension"] - 1),
                  mea["tension"] / 1e3, 100 * (T / mea["tension"] - 1),
                  mean["top_pressure"] / 1e3, mean["bottom_pressure"] / 1e3,
                  nom["top_pressure"] / 1e3, nom["bottom_pressure"] / 1e3,
                  mean["contact_width"], nom["contact_width"],
                  mean["enclosed_area"], mean["fluid_volume"],
                  forces[len(forces) // 2], forces[0],
                  summary.get("steps", "?"), summary.get("wall_seconds", float("nan"))))


if __name__ == "__main__":
    main()
