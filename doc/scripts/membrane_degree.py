#!/usr/bin/python3
"""Membrane elements of degree 1 and 2 on the geotube
(doc/membrane_validation.md, "Quadratic membrane elements").

Usage: membrane_degree.py FSGMPM SOURCE_DIR WORK_DIR [--jobs 2] [--fine]

Runs the three geotube fillings (prm/geotube_A3.36, A5.56, A6.45) with the
paper's no-slip coupling (Membrane/Tangential coupling = no-slip, Split
length = 1, Simulation/Stress integration = nodal projection, the
weakly compressible fill K = 2.7e7 Pa) for 50 s at 16 cm cells (--fine: also
A5.56 at 8 cm), at degree 1 with elements of 0.9 cells and at degree 2 with
cells of 1.8 grid cells, so that both have the same nodes along the
membrane. Each run is one thread; --jobs runs at once. Averages the monitors
over t >= 40 s and compares H/W, the tension and the top and bottom
pressures with the analytic solution for the run's own membrane length and
enclosed area (tests/geotube_shape next to FSGMPM). Prints one row per run
and writes WORK_DIR/membrane_degree.csv. A run that has a summary.json is
not run again.
"""
import csv
import json
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import monitors_csv  # noqa: E402

END, FROM = 50.0, 40.0


def runs(fine):
    out = []
    for scene in ("A3.36", "A5.56", "A6.45"):
        out.append((scene, 0.16))
    if fine:
        out.append(("A5.56", 0.08))
    return [(s, h, d) for (s, h) in out for d in (1, 2)]


def run(exe, src, work, scene, h, degree):
    name = f"{scene}_h{h}_p{degree}"
    out = os.path.join(work, name)
    if not os.path.exists(os.path.join(out, "summary.json")):
        element = 0.9 * h * degree
        subprocess.run(
            [exe, os.path.join(src, "prm", f"geotube_{scene}.prm"),
             "--set", f"Grid/Cell size={h}",
             "--set", "Bodies/Body 0/Newtonian fluid/Bulk modulus=2.7e7",
             "--set", f"Simulation/End time={END}",
             "--set", "Simulation/Number of threads=1",
             "--set", "Simulation/Stress integration=nodal projection",
             "--set", "Membrane/Tangential coupling=no-slip",
             "--set", f"Membrane/Element size={element:.6g}",
             "--set", "Membrane/Split length=1",
             "--set", f"Membrane/Element degree={degree}",
             "--set", f"Output/Directory={out}",
             "--set", "Output/Output interval=0",
             "--set", "Output/Quiet=true"],
            check=True, stdout=subprocess.DEVNULL)
    return name, out


def result(exe, out):
    with open(os.path.join(out, "monitors.csv")) as f:
        rows = [r for r in monitors_csv.DictReader(f) if float(r["time"]) >= FROM]
    mean = {k: sum(float(r[k]) for r in rows) / len(rows)
            for k in ("height", "width", "mean_tension", "top_pressure",
                      "bottom_pressure", "membrane_length", "enclosed_area")}
    shape = os.path.join(os.path.dirname(exe), "tests", "geotube_shape")
    head = subprocess.check_output(
        [shape, f"{mean['membrane_length']:.9g}",
         f"{mean['enclosed_area']:.9g}"]).decode().splitlines()[0]
    words = head.lstrip("# ").split()
    ref = {words[i]: float(words[i + 1]) for i in range(0, len(words), 2)}
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    return {
        "hw_error": mean["height"] / mean["width"]
        - ref["height"] / ref["width"],
        "T_error": mean["mean_tension"] / ref["tension"] - 1,
        "p_top_error": (mean["top_pressure"] - ref["top_pressure"])
        / ref["bottom_pressure"],
        "p_bottom_error": mean["bottom_pressure"] / ref["bottom_pressure"]
        - 1,
        "wall_s": summary["wall_seconds"],
        "steps": summary["steps"],
        "termination": summary["termination"],
    }


def main():
    args = sys.argv[1:]
    jobs = 2
    if "--jobs" in args:
        i = args.index("--jobs")
        jobs = int(args[i + 1])
        del args[i:i + 2]
    fine = "--fine" in args
    args = [a for a in args if a != "--fine"]
    exe, src, work = (os.path.abspath(a) for a in args[:3])
    os.makedirs(work, exist_ok=True)
    todo = runs(fine)
    with ThreadPoolExecutor(jobs) as pool:
        done = list(pool.map(lambda r: run(exe, src, work, *r), todo))
    rows = []
    print(f"{'run':20} {'H/W error':>10} {'T error':>9} {'p_top':>8} "
          f"{'p_bottom':>9} {'wall s':>8} {'steps':>7}")
    for (scene, h, degree), (name, out) in zip(todo, done):
        r = result(exe, out)
        r.update(scene=scene, cell=h, degree=degree)
        rows.append(r)
        print(f"{name:20} {r['hw_error']:+10.4f} {100 * r['T_error']:+8.2f}% "
              f"{100 * r['p_top_error']:+7.2f}% "
              f"{100 * r['p_bottom_error']:+8.2f}% {r['wall_s']:8.1f} "
              f"{r['steps']:7d}")
    with open(os.path.join(work, "membrane_degree.csv"), "w") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
