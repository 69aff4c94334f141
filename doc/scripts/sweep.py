#!/usr/bin/python3
"""Accuracy against cost: run one scene over its settings, measure error and
wall time, and print and plot the Pareto front (doc/accuracy_vs_cost.md §3).

Usage: sweep.py SCENE FSGMPM SOURCE_DIR WORK_DIR [--threads 2] [--plot OUT.png]
SCENE: dam_break (n^2 = 2 water column) or granular (a = 3 sand column).

Each setting is one run of the scene's prm with --set overrides (one at a
time around the shipped setting, plus mesh ladders), run one after the other
with --threads threads, so that the wall times are comparable. A run that
exists (a summary.json of a finished or unstable run) is not run again. For each
run it reports the error against the experiment, the difference from the
finest run (the discretisation error), the wall time and the steps, then the
Pareto front (no other run is both cheaper and more accurate) and the
cheapest run within 1%, 5% and 10% of the finest result. Results go to
WORK_DIR/sweep.csv. Exit status 1 if a run fails other than by instability
(instability is a result: the setting is past the stable limit).
"""
import csv
import json
import math
import os
import subprocess
import sys

G = 9.81


# The reference data and the interpolation of doc/scripts/front_error.py.
from front_error import interpolate, read_reference  # noqa: E402


def variants(base, runs):
    """add(name, Section__Sub__Name_with_spaces=value, ...): a run with the
    base settings and these changes ('__' is '/', '_' is ' ')."""
    def add(name, **changes):
        s = dict(base)
        for key, value in changes.items():
            s[key.replace("__", "/").replace("_", " ")] = value
        runs[name] = s
    return add


# ---- the dam break (n^2 = 2, prm/water_column_collapse_n2.prm) ------------
def dam_break_settings():
    k = "Bodies/Body 0/Newtonian fluid/Bulk modulus"
    base = {"Grid/Cell size": "0.0057", k: "2.5e6"}
    cells = {"10": "0.0114", "20": "0.0057", "40": "0.00285"}
    runs = {}
    add = variants(base, runs)

    for n, h in cells.items():
        add(f"cells{n}", Grid__Cell_size=h)
        add(f"cells{n}_apic", Grid__Cell_size=h,
            Simulation__Velocity_transfer="APIC")
        add(f"cells{n}_projection", Grid__Cell_size=h,
            Simulation__Stress_integration="nodal projection",
            **{"Bodies__Body 0__Volumetric_smoothing": "none"})
    for ppc in ("1", "16"):
        add(f"ppc{ppc}", **{"Bodies__Body 0__Particles_per_cell": ppc})
    for c in ("0.1", "0.25", "0.75", "1"):
        add(f"courant{c}", Simulation__Courant_number=c)
    for smoothing in ("none", "NMD", "ANP"):
        add(f"smoothing_{smoothing}",
            **{"Bodies__Body 0__Volumetric_smoothing": smoothing})
    runs["K2.13e7"] = dict(base, **{k: "2.13e7"})
    runs["K2.13e8"] = dict(base, **{k: "2.13e8"})
    runs["K2.13e9"] = dict(base, **{k: "2.13e9"})
    # The finest run: the reference of the discretisation error.
    add("finest", Grid__Cell_size="0.00285", Simulation__Courant_number="0.25",
        **{"Bodies__Body 0__Particles_per_cell": "16"})
    return runs


def dam_break_result(run_dir, source):
    """The front Z(T) and its RMS error against Martin & Moyce (T <= 3.3,
    no shift, as the ctest)."""
    a = 0.114
    scale = math.sqrt(2 * G / a)
    with open(os.path.join(run_dir, "monitors.csv")) as f:
        rows = list(csv.DictReader(f))
    front = [(float(r["time"]) * scale, float(r["front_position"]) / a)
             for r in rows]
    mm = read_reference("martin_moyce_1952_n2.csv")["front"]
    mm = [p for p in mm if p[0] <= 3.3 + 1e-9]
    e_exp = math.sqrt(sum((interpolate(front, T) - Z) ** 2 for T, Z in mm)
                      / len(mm))
    return front, e_exp


def dam_break_difference(front, finest):
    """Relative RMS difference of Z(T) from the finest run, T in [0.5, 3.3]."""
    Ts = [0.5 + 0.05 * i for i in range(57)]
    return math.sqrt(sum(((interpolate(front, T) - interpolate(finest, T))
                          / interpolate(finest, T)) ** 2 for T in Ts)
                     / len(Ts))


# ---- the granular collapse (a = 3, prm/granular_column_collapse.prm) -----
ASPECT = 3.0


def granular_settings():
    a = "Bodies/Body 0/Column aspect ratio"
    base = {a: str(ASPECT)}
    cells = {"10": "0.02", "20": "0.01", "40": "0.005"}
    runs = {}
    add = variants(base, runs)

    for n, h in cells.items():
        add(f"cells{n}", Grid__Cell_size=h)
        add(f"cells{n}_projection", Grid__Cell_size=h,
            Simulation__Stress_integration="nodal projection")
    # FLIP (known to run out 50-90% too far, doc/soil_validation.md).
    add("flip", Simulation__Velocity_transfer="FLIP")
    for ppc in ("1", "16"):
        add(f"ppc{ppc}", **{"Bodies__Body 0__Particles_per_cell": ppc})
    for c in ("0.1", "0.25", "0.75", "1"):
        add(f"courant{c}", Simulation__Courant_number=c)
    # The finest run affordable here: 40 cells across L0, Courant 0.25.
    add("finest", Grid__Cell_size="0.005", Simulation__Courant_number="0.25")
    return runs


def granular_result(run_dir, source):
    """The run-out (m) and its relative error against Lube et al. (2005):
    (L - L0)/L0 = 1.9 a^(2/3) for a > 2.8."""
    with open(os.path.join(run_dir, "monitors.csv")) as f:
        rows = list(csv.DictReader(f))
    runout = float(rows[-1]["runout"])
    L0 = 0.2
    lube = 1.9 * ASPECT ** (2 / 3) if ASPECT > 2.8 else 1.2 * ASPECT
    return runout, abs((runout - L0) / L0 - lube) / lube


def granular_difference(runout, finest):
    return abs(runout - finest) / finest


SCENES = {
    "dam_break": ("water_column_collapse_n2.prm", dam_break_settings,
                  dam_break_result, dam_break_difference,
                  "front RMS in Z vs Martin & Moyce, no shift"),
    "granular": ("granular_column_collapse.prm", granular_settings,
                 granular_result, granular_difference,
                 "relative run-out error vs Lube et al. (2005), a = 3"),
}


def main(argv):
    if len(argv) < 4 or argv[0] not in SCENES:
        sys.exit(__doc__)
    scene, exe, source, work = argv[:4]
    threads, plot = "2", None
    rest = argv[4:]
    while rest:
        if rest[0] == "--threads" and len(rest) > 1:
            threads, rest = rest[1], rest[2:]
        elif rest[0] == "--plot" and len(rest) > 1:
            plot, rest = rest[1], rest[2:]
        else:
            sys.exit(f"sweep.py: unknown argument <{rest[0]}>\n" + __doc__)
    prm, settings_of, result_of, difference, error_name = SCENES[scene]
    os.makedirs(work, exist_ok=True)
    settings = settings_of()
    failed = []
    results = {}
    for name, sets in settings.items():
        run_dir = os.path.join(work, name)
        summary = os.path.join(run_dir, "summary.json")
        done = False
        if os.path.exists(summary):
            with open(summary) as f:
                done = json.load(f)["termination"] in ("end_time", "at_rest",
                                                       "unstable")
        if not done:
            cmd = [exe, os.path.join(source, "prm", prm)]
            for key, value in dict(sets, **{
                    "Simulation/Number of threads": threads,
                    "Output/Output interval": "0",
                    "Output/Quiet": "true",
                    "Output/Directory": run_dir}).items():
                cmd += ["--set", f"{key}={value}"]
            status = subprocess.run(cmd, stdout=subprocess.DEVNULL,
                                    stderr=subprocess.PIPE, text=True)
            if status.returncode not in (0, 3):
                failed.append(f"{name}: exit {status.returncode}: "
                              f"{status.stderr.strip()[-300:]}")
                continue
        with open(summary) as f:
            results[name] = json.load(f)
    finest = None
    if "finest" in results and results["finest"]["termination"] in (
            "end_time", "at_rest"):
        finest = result_of(os.path.join(work, "finest"), source)[0]
    rows = []
    for name, s in results.items():
        stable = s["termination"] in ("end_time", "at_rest")
        e_exp, e_fine = float("nan"), float("nan")
        if stable:
            result, e_exp = result_of(os.path.join(work, name), source)
            if finest is not None:
                e_fine = difference(result, finest)
        rows.append(dict(run=name, stable=stable, error=e_exp,
                         difference_from_finest=e_fine,
                         wall_seconds=s["wall_seconds"], steps=s["steps"],
                         particles=s["particles"]))
    with open(os.path.join(work, "sweep.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)

    rows.sort(key=lambda r: r["wall_seconds"])
    pareto, best = [], float("inf")
    for r in rows:
        if r["stable"] and r["difference_from_finest"] < best:
            best = r["difference_from_finest"]
            pareto.append(r["run"])
    print(f"{scene}: error = {error_name}; difference = relative difference "
          f"of the result from the finest run; * = on the Pareto front of "
          f"difference against wall time ({threads} threads)")
    print(f"{'run':22s} {'error':>7s} {'diff':>7s} {'wall_s':>8s} "
          f"{'steps':>8s} {'points':>7s}")
    for r in rows:
        mark = "*" if r["run"] in pareto else " "
        if r["stable"]:
            print(f"{r['run']:22s} {r['error']:7.3f} "
                  f"{r['difference_from_finest']:7.4f} "
                  f"{r['wall_seconds']:8.1f} {r['steps']:8d} "
                  f"{r['particles']:7d} {mark}")
        else:
            print(f"{r['run']:22s} unstable {r['wall_seconds']:8.1f} s")
    for level in (0.01, 0.05, 0.10):
        ok = [r for r in rows if r["stable"] and r["run"] != "finest"
              and r["difference_from_finest"] <= level]
        print(f"cheapest within {100 * level:.0f}% of the finest: "
              + (f"{ok[0]['run']} ({ok[0]['wall_seconds']:.1f} s)" if ok
                 else "none"))
    if plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
        stable = [r for r in rows if r["stable"]]
        for ax, key, label in (
                (axes[0], "error", error_name),
                (axes[1], "difference_from_finest",
                 "relative difference from the finest run")):
            pts = [r for r in stable if not math.isnan(r[key])]
            ax.loglog([r["wall_seconds"] for r in pts],
                      [max(r[key], 1e-4) for r in pts], "o", mfc="none")
            for r in pts:
                ax.annotate(r["run"], (r["wall_seconds"], max(r[key], 1e-4)),
                            fontsize=6)
            front = [r for r in pts if r["run"] in pareto]
            if key == "difference_from_finest":
                ax.loglog([r["wall_seconds"] for r in front],
                          [max(r[key], 1e-4) for r in front], "r-",
                          label="Pareto front")
                ax.legend(fontsize=8)
            ax.set_xlabel(f"wall time (s, {threads} threads)")
            ax.set_ylabel(label)
            ax.grid(True, which="both", alpha=0.3)
        fig.suptitle(f"Accuracy against cost: {scene}")
        fig.tight_layout()
        fig.savefig(plot, dpi=110)
    if failed:
        print("\n".join(failed))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
