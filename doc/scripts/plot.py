#!/usr/bin/python3
"""Plot an fsgmpm run: one entry point for every scene.

Usage: plot.py RUN_DIR [-o OUT.png] [--list] [scene options]

Reads RUN_DIR/monitors.csv and RUN_DIR/summary.json, tells the scene from
the monitor columns and draws it against the scene's reference with the
scene's own script:

  dam_break     front_position, column_height: water-column collapse against
                Martin & Moyce (1952), plot_dam_break.py
                options: --w0 A (column width, m), --n2 N (h0/w0), --g G,
                --others (Koshizuka & Oka and the smaller column too)
  deposit       runout, final_height: granular-collapse deposit surface,
                plot_deposit.py (needs the particles_*.vtu)
                options: --L0 L (initial column width, m), --bin W (m)
  geotube       height, width, max_tension: final shape against the analytic
                geotube (Leshchinsky et al. 1996), plot_geotube.py
                options: --area A (nominal area, m^2), --circumference C (m),
                --geotube-shape EXE (tests/reference/geotube_shape, built as
                build/tests/geotube_shape)
  geocontainer  container_velocity_y: sinking velocity against the
                experiment and the drag balance, plot_geocontainer.py
  energy        any other run: kinetic, strain and potential energy,
                external work and the booked losses over time, and the
                balance's residual (no reference)

The column width, n^2, nominal area and circumference default to the run's
own parameters.prm where it has them. OUT.png defaults to RUN_DIR/plot.png.
--list prints the detected scene and the columns it plots, and draws
nothing. A run that ends before the reference's range gets a warning on
standard error; nothing is extrapolated past its end.
Exit status: 0 done, 2 bad use (no RUN_DIR, no monitors.csv, an option of
another scene). Uses Debian's /usr/bin/python3 with python3-numpy and
python3-matplotlib.
"""
import argparse
import json
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
# The scene scripts are imported from the source tree: leave no
# __pycache__ in it.
sys.dont_write_bytecode = True
import monitors_csv  # noqa: E402

PROG = "plot.py"

# Scene name -> (description, columns that identify it, columns it plots,
# its own options). Detection takes the first scene whose identifying
# columns are all present, in this order (a geocontainer also has
# max_tension, so it comes before the geotube).
SCENES = [
    ("geocontainer",
     "geocontainer drop (sinking velocity against the experiment, "
     "Bezuijen et al.)",
     ["container_velocity_y"], ["time", "container_velocity_y"], []),
    ("dam_break",
     "water-column collapse (dam break) against Martin & Moyce (1952)",
     ["front_position", "column_height"],
     ["time", "front_position", "column_height"],
     ["w0", "n2", "g", "others"]),
    ("deposit",
     "granular column collapse deposit",
     ["runout", "final_height"], ["time", "runout"], ["L0", "bin"]),
    ("geotube",
     "geotube shape against the analytic geotube (Leshchinsky et al. 1996)",
     ["height", "width", "max_tension"],
     ["membrane_length", "enclosed_area", "height", "width", "max_tension"],
     ["area", "circumference", "geotube_shape"]),
]
ENERGIES = ["kinetic_energy", "strain_energy", "potential_energy",
            "external_work"]
LOSSES = ["dissipated_energy", "material_dissipation",
          "numerical_dissipation", "outflow_energy"]
GENERIC = ("energy",
           "no scene reference: energies, booked losses and the energy "
           "balance", [], ["time"] + ENERGIES + LOSSES, [])


def fail(message):
    print("%s: %s" % (PROG, message), file=sys.stderr)
    sys.exit(2)


def warn(message):
    print("%s: warning: %s" % (PROG, message), file=sys.stderr)


def read_run(run_dir):
    """{column: [float or nan]}, {column: unit} and summary.json ({} if
    absent) of a run directory; exits with 2 where there is no run."""
    if not os.path.isdir(run_dir):
        fail("%s is not a directory (give the Output/Directory of a run)"
             % run_dir)
    path = os.path.join(run_dir, "monitors.csv")
    if not os.path.isfile(path):
        fail("%s holds no monitors.csv: not the output directory of an "
             "fsgmpm run, or the run has not written its first row yet"
             % run_dir)
    with open(path) as f:
        reader = monitors_csv.DictReader(f)
        if not reader.fieldnames:
            fail("%s is empty" % path)
        columns = {k: [] for k in reader.fieldnames}
        for row in reader:
            for k in reader.fieldnames:
                value = row.get(k)
                columns[k].append(float(value) if value else float("nan"))
    if not columns.get("time"):
        fail("%s has no rows" % path)
    units = monitors_csv.units(path)
    summary = {}
    summary_path = os.path.join(run_dir, "summary.json")
    if os.path.isfile(summary_path):
        with open(summary_path) as f:
            summary = json.load(f)
    else:
        warn("%s holds no summary.json: the run is still going or was "
             "killed; plotting the rows written so far" % run_dir)
    return columns, units, summary


def read_parameters(run_dir):
    """{"Section/Sub/Entry": value} from RUN_DIR/parameters.prm ({} if
    absent)."""
    path = os.path.join(run_dir, "parameters.prm")
    values, sections = {}, []
    if not os.path.isfile(path):
        return values
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                sections.append(line[len("subsection "):].strip())
            elif line == "end" and sections:
                sections.pop()
            elif line.startswith("set ") and "=" in line:
                name, value = line[4:].split("=", 1)
                values["/".join(sections + [name.strip()])] = value.strip()
    return values


def detect(columns):
    for scene in SCENES:
        if all(c in columns for c in scene[2]):
            return scene
    return GENERIC


def column_label(name, units):
    unit = units.get(name, "")
    return "%s[%s]" % (name, unit) if unit else name


def dam_break_geometry(params):
    """Width and n^2 = h0/w0 of Body 0 when it is a box, else None."""
    if params.get("Bodies/Body 0/Shape") != "box":
        return None, None
    try:
        lo = [float(x) for x in params["Bodies/Body 0/Box lower corner"].split(",")]
        hi = [float(x) for x in params["Bodies/Body 0/Box upper corner"].split(",")]
    except (KeyError, ValueError):
        return None, None
    w0, h0 = hi[0] - lo[0], hi[1] - lo[1]
    return (w0, h0 / w0) if w0 > 0 and h0 > 0 else (None, None)


def plot_dam_break(args, run_dir, columns, summary, params, output):
    import plot_dam_break
    w0, n2 = dam_break_geometry(params)
    w0 = args.w0 if args.w0 is not None else (w0 or 0.114)
    n2 = args.n2 if args.n2 is not None else (n2 or 2.0)
    g = args.g if args.g is not None else 9.81
    if abs(n2 - 2) > 1e-6:
        warn("the column's n^2 = %g; the reference is Martin & Moyce's "
             "n^2 = 2 (the curves are drawn, the errors are not a "
             "validation)" % n2)
    plot_dam_break.plot(output, [(run_dir, args.label)], w0=w0, g=g,
                        n2=n2, others=args.others,
                        err=_Prefixed(sys.stderr))


class _Prefixed:
    """A stream that puts "plot.py: " before each line written to it."""

    def __init__(self, stream):
        self.stream = stream

    def write(self, text):
        if text.strip():
            self.stream.write("%s: %s" % (PROG, text))
        else:
            self.stream.write(text)

    def flush(self):
        self.stream.flush()


def plot_deposit(args, run_dir, columns, summary, params, output):
    import plot_deposit
    L0 = args.L0
    if L0 is None:
        try:
            L0 = float(params["Bodies/Body 0/Column width"])
        except (KeyError, ValueError):
            L0 = 0.2
    termination = summary.get("termination")
    if termination not in (None, "at_rest"):
        warn("the run ended by %s at t = %.4g s, not at rest: the deposit "
             "may still be moving (the reference run-out is the final one)"
             % (termination, columns["time"][-1]))
    try:
        plot_deposit.plot(output, [(run_dir, args.label)], L0=L0,
                          bin_width=args.bin if args.bin else 0.01)
    except FileNotFoundError as e:
        fail("%s (the deposit plot needs the particle output: "
             "Output/Write particles = true)" % e)


def plot_geotube(args, run_dir, columns, summary, params, output):
    import plot_geotube
    area = args.area
    if area is None:
        area = params.get("Membrane/Enclosed area")
    circumference = args.circumference
    if circumference is None:
        try:
            circumference = float(params["Membrane/Circumference"])
        except (KeyError, ValueError):
            circumference = 9.2
    exe = args.geotube_shape
    if exe is None:
        for candidate in (os.path.join(HERE, "..", "..", "build", "tests",
                                       "geotube_shape"),
                          shutil.which("geotube_shape")):
            if candidate and os.access(candidate, os.X_OK):
                exe = candidate
                break
    elif not os.access(exe, os.X_OK):
        fail("--geotube-shape %s is not an executable" % exe)
    if not os.path.isfile(os.path.join(run_dir, "membrane_shape.csv")):
        fail("%s holds no membrane_shape.csv (written at the end of a "
             "geotube run)" % run_dir)
    if exe is None:
        warn("no geotube_shape executable (build/tests/geotube_shape; "
             "give it with --geotube-shape): drawing the run's shape "
             "without the analytic one")
    elif area is None:
        fail("the nominal area is not in %s/parameters.prm: give --area"
             % run_dir)
    termination = summary.get("termination")
    if termination not in (None, "dr_converged"):
        ratio = columns.get("dr_force_ratio", [float("nan")])[-1]
        warn("the run ended by %s at t = %.4g s, not by dynamic-relaxation "
             "convergence (force ratio %.3g): the analytic shape is the "
             "equilibrium, which the run may not have reached"
             % (termination, columns["time"][-1], ratio))
    label = args.label or os.path.basename(os.path.normpath(run_dir))
    plot_geotube.plot(exe, output, area, [(label, run_dir)],
                      circumference=circumference)


def plot_geocontainer(args, run_dir, columns, summary, params, output):
    import plot_geocontainer
    t_end = columns["time"][-1]
    if t_end < plot_geocontainer.EXPERIMENT_TIME:
        warn("the run ends at t = %.4g s, before the experiment's point "
             "(%.2g m/s at %.2g s): the velocity is not extrapolated to it"
             % (t_end, plot_geocontainer.EXPERIMENT_VELOCITY,
                plot_geocontainer.EXPERIMENT_TIME))
    else:
        t = columns["time"]
        v = [-x for x in columns["container_velocity_y"]]
        k = min(range(len(t)),
                key=lambda i: abs(t[i] - plot_geocontainer.EXPERIMENT_TIME))
        print("%s: downward velocity %.3f m/s at t = %.3f s (experiment "
              "%.2g m/s at %.2g s)"
              % (args.label or os.path.basename(os.path.normpath(run_dir)),
                 v[k], t[k], plot_geocontainer.EXPERIMENT_VELOCITY,
                 plot_geocontainer.EXPERIMENT_TIME))
    label = args.label or os.path.basename(os.path.normpath(run_dir))
    plot_geocontainer.plot(output,
                           [(label, os.path.join(run_dir, "monitors.csv"))])


def plot_energy(args, run_dir, columns, summary, params, output, units):
    """Energies and booked losses over time, and the balance's residual
    kinetic + strain - (initial + external work - booked losses)."""
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    t = np.array(columns["time"])
    unit = next((units[c] for c in ENERGIES if units.get(c)), "")
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for name in ENERGIES:
        if name == "potential_energy" and name in columns:
            # Its level is set by the mesh's lowest corner: drawn from its
            # initial value, so that the others stay readable beside it.
            e = np.array(columns[name])
            ax1.plot(t, e - e[0], label="%s - %.4g (initial)" % (name, e[0]))
        elif name in columns:
            ax1.plot(t, columns[name], label=name)
    for name in LOSSES:
        if name in columns:
            ax1.plot(t, columns[name], "--", label=name)
    have = [c for c in ["kinetic_energy", "strain_energy", "external_work"]
            if c in columns]
    if len(have) == 3:
        stored = np.array(columns["kinetic_energy"]) + \
            np.array(columns["strain_energy"])
        losses = sum(np.array(columns[c]) for c in LOSSES if c in columns)
        residual = stored - (stored[0] + np.array(columns["external_work"])
                             - losses)
        ax2.plot(t, residual, "k-")
        ax2.set_title("energy balance residual (+: created)", fontsize=9,
                      pad=14)
        print("%s: energy balance residual at t = %.4g s: %.4g %s"
              % (args.label or os.path.basename(os.path.normpath(run_dir)),
                 t[-1], residual[-1], unit))
    ax1.set_xlabel("time (s)")
    ax2.set_xlabel("time (s)")
    ax1.set_ylabel("energy (%s)" % unit if unit else "energy")
    ax2.set_ylabel("kinetic + strain - (initial + work - losses)%s"
                   % (" (%s)" % unit if unit else ""), fontsize=8)
    ax1.legend(fontsize=7, loc="upper left")
    for ax in (ax1, ax2):
        ax.grid(True, alpha=0.3)
    fig.suptitle("%s: energies (termination: %s)"
                 % (args.label or os.path.basename(os.path.normpath(run_dir)),
                    summary.get("termination", "unknown")))
    fig.tight_layout()
    fig.savefig(output, dpi=110)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog=PROG, usage="%(prog)s RUN_DIR [-o OUT.png] [--list] "
        "[scene options]",
        description=__doc__.split("\n\n", 2)[2].split("\n\nThe column")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="scenes: " + ", ".join(s[0] for s in SCENES + [GENERIC]))
    parser.add_argument("run_dir", metavar="RUN_DIR",
                        help="the Output/Directory of a run")
    parser.add_argument("-o", "--output", metavar="OUT.png",
                        help="the figure (default RUN_DIR/plot.png)")
    parser.add_argument("--list", action="store_true",
                        help="print the detected scene and the columns it "
                        "plots, draw nothing")
    parser.add_argument("--label", default="",
                        help="the run's name in the legend (default: the "
                        "directory's name)")
    group = parser.add_argument_group("dam_break")
    group.add_argument("--w0", type=float, help="column width a (m; default "
                       "from parameters.prm, else 0.114)")
    group.add_argument("--n2", type=float, help="n^2 = h0/w0 (default from "
                       "parameters.prm, else 2)")
    group.add_argument("--g", type=float, help="gravity (default 9.81)")
    group.add_argument("--others", action="store_true", default=None,
                       help="add Martin & Moyce's smaller column and "
                       "Koshizuka & Oka")
    group = parser.add_argument_group("deposit")
    group.add_argument("--L0", type=float, help="initial column width (m; "
                       "default Column width of parameters.prm, else 0.2)")
    group.add_argument("--bin", type=float, help="bin width of the surface "
                       "(m; default 0.01)")
    group = parser.add_argument_group("geotube")
    group.add_argument("--area", help="nominal area (m^2; default the "
                       "Membrane/Enclosed area of parameters.prm)")
    group.add_argument("--circumference", type=float, help="nominal "
                       "circumference (m; default from parameters.prm, else "
                       "9.2)")
    group.add_argument("--geotube-shape", metavar="EXE", help="the analytic "
                       "shape's program (default build/tests/geotube_shape)")
    args = parser.parse_args(argv)

    columns, units, summary = read_run(args.run_dir)
    name, description, _, plotted, options = detect(columns)
    scene_of = {o: s[0] for s in SCENES for o in s[4]}
    for option, scene in scene_of.items():
        if getattr(args, option) is not None and option not in options:
            fail("--%s is an option of the %s plot; the run in %s is "
                 "scene %s (%s), detected from its monitor columns"
                 % (option.replace("_", "-"), scene, args.run_dir, name,
                    description))
    plotted = [c for c in plotted if c in columns]
    if args.list:
        print("scene: %s (%s)" % (name, description))
        print("columns: " + ", ".join(column_label(c, units)
                                      for c in plotted))
        print("rows: %d, t = %.6g to %.6g s, termination: %s"
              % (len(columns["time"]), columns["time"][0],
                 columns["time"][-1], summary.get("termination", "unknown")))
        if options:
            print("options: " + " ".join("--" + o.replace("_", "-")
                                         for o in options))
        return 0
    output = args.output or os.path.join(args.run_dir, "plot.png")
    directory = os.path.dirname(os.path.abspath(output))
    if not os.path.isdir(directory) or not os.access(directory, os.W_OK):
        fail("cannot write %s: %s is not a writable directory"
             % (output, directory))
    params = read_parameters(args.run_dir)
    if name == "energy":
        plot_energy(args, args.run_dir, columns, summary, params, output,
                    units)
    else:
        {"dam_break": plot_dam_break, "deposit": plot_deposit,
         "geotube": plot_geotube, "geocontainer": plot_geocontainer}[name](
            args, args.run_dir, columns, summary, params, output)
    print("%s: %s plot written to %s" % (PROG, name, output))
    return 0


if __name__ == "__main__":
    sys.exit(main())
