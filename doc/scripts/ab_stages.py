#!/usr/bin/env python3
"""A/B of two fsgmpm builds on one scene: runs them alternately (A B B A ...)
so that the machine's drift falls on both, and prints the median particle
updates per second and the median time per step of every stage from each
run's summary.json (doc/performance.md).

  python3 doc/scripts/ab_stages.py OLD/fsgmpm NEW/fsgmpm scene.prm \
      --threads 1 2 --pairs 3 [--set "Grid/Subdivisions=480, 200" ...]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile


def run(exe, prm, threads, extra, out):
    args = [exe, prm, "--set", f"Simulation/Number of threads={threads}",
            "--set", f"Output/Directory={out}",
            "--set", "Output/Output interval=0",
            "--set", "Output/Write particles=false",
            "--set", "Output/Quiet=true"]
    for s in extra:
        args += ["--set", s]
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("prm")
    p.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    p.add_argument("--pairs", type=int, default=3)
    p.add_argument("--set", action="append", default=[])
    args = p.parse_args()
    with tempfile.TemporaryDirectory(prefix="ab_stages_") as out:
        compare(args, out)


def compare(args, out):
    for t in args.threads:
        results = {"a": [], "b": []}
        for i in range(args.pairs):
            order = ("a", "b") if i % 2 == 0 else ("b", "a")
            for which in order:
                exe = args.a if which == "a" else args.b
                results[which].append(run(exe, args.prm, t, args.set, out))
        steps = results["a"][0]["steps"]
        print(f"threads={t} steps={steps} runs={args.pairs} each, medians")
        print("| | A | B | B/A |")
        print("| --- | --- | --- | --- |")
        ua = statistics.median(r["particle_updates_per_second"]
                               for r in results["a"]) / 1e6
        ub = statistics.median(r["particle_updates_per_second"]
                               for r in results["b"]) / 1e6
        print(f"| M updates/s | {ua:.2f} | {ub:.2f} | {ub / ua:.2f} |")
        for stage in results["a"][0]["stage_seconds"]:
            sa = statistics.median(r["stage_seconds"][stage] / r["steps"]
                                   for r in results["a"]) * 1e3
            sb = statistics.median(r["stage_seconds"][stage] / r["steps"]
                                   for r in results["b"]) * 1e3
            if max(sa, sb) < 0.01:
                continue
            print(f"| {stage} (ms/step) | {sa:.3f} | {sb:.3f} | "
                  f"{sb / sa if sa > 0 else float('nan'):.2f} |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
