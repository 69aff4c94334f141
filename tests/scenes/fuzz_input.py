#!/usr/bin/python3
"""Bad input, fuzzed (doc/stability.md, "Bad input, fuzzed").

Takes every parameter that `fsgmpm --print-parameters` prints and, one at a
time, gives it hostile values chosen from the type in its "allowed:" line
(empty, non-numeric, NaN, inf, negative, zero, 1e-300, 1e300, wrong list
lengths, missing files, files that are not meshes, self-intersecting or
outside polygons, ...) on a small scene (tests/scenes/fuzz/*.prm: a water
column with an elastic block, a Mohr-Coulomb column, a geotube), with the
other parameters that the fuzzed one needs to be read at all (e.g. Shape =
polygon for Polygon vertices).

Every case must either
  - exit with status 1, a message "fsgmpm: error: ..." naming the parameter,
    and no output directory (input is validated before anything is written),
    unless the value is an end of the range that its printed pattern says
    is inclusive (the printed patterns equal the checks),
  - or run: exit 0, or exit 3 (detected instability, with a diagnosis and
    termination = unstable in summary.json), with complete output: no
    leftover temporary file, monitors.csv with whole rows of finite numbers
    (empty only for the undefined Eq. (30) ratios), a summary.json that
    parses and holds no NaN, inf or null number, and .vtu/.pvd files that
    parse and hold only finite numbers (and positive point masses and
    volumes).
A crash (signal, exit status other than 0, 1, 3, a stack trace), a hang
(more than --timeout s) or any of the above is a failure.

Usage: fuzz_input.py <fsgmpm executable> <tests source dir>
                     [--server fuzz_server] [--workers N] [--timeout S]
                     [--filter REGEX] [--list] [--verbose]
Prints the number of cases tried and passed and every failure (parameter,
value, exit status, reason); exits 1 if any case failed.
"""

import argparse
import base64
import concurrent.futures
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import threading
import time
import xml.etree.ElementTree as ET
import zlib

CRASH_PATTERNS = re.compile(
    r"Stacktrace|Segmentation|Aborted|terminate called|core dumped|"
    r"An error occurred in line|ExcInternalError|std::bad_alloc")


# ---------------------------------------------------------------------------
# The parameter list.

def read_parameters(exe, scene):
    """(path, allowed) of every parameter, from --print-parameters."""
    out = subprocess.run([exe, scene, "--print-parameters"],
                         capture_output=True, text=True, check=True).stdout
    params, sections, allowed = [], [], None
    for line in out.splitlines():
        s = line.strip()
        m = re.match(r"# Default: .*; allowed: (.*)$", s)
        if m:
            allowed = m.group(1)
        elif s.startswith("subsection "):
            sections.append(s[len("subsection "):])
        elif s == "end":
            sections.pop()
        elif s.startswith("set "):
            name = s[4:].split("=", 1)[0].strip()
            params.append(("/".join(sections + [name]), allowed))
            allowed = None
    return params


# ---------------------------------------------------------------------------
# Hostile values by type.

def number_range(allowed):
    m = re.search(r"\[(?:Double|Integer(?: range)?) (\S+?)\.\.\.(\S+?) ",
                  allowed)
    if not m:
        return None, None
    def conv(t):
        if "MAX_DOUBLE" in t or "MAX_INT" in t:
            return -math.inf if t.startswith("-") else math.inf
        return float(t)
    return conv(m.group(1)), conv(m.group(2))


def fmt(x):
    return repr(int(x)) if float(x).is_integer() else repr(x)


def inclusive_edges(allowed):
    """The finite ends of a Double pattern that it prints as inclusive:
    "[Double 0...1 (inclusive)]" both, "[Double 0...0.5 (0 inclusive, 0.5
    exclusive)]" the first."""
    if not allowed.startswith("[Double"):
        return []
    lo, hi = number_range(allowed)
    mixed = re.search(r"\((\S+) (inclusive|exclusive), (\S+) "
                      r"(inclusive|exclusive)\)", allowed)
    ends = []
    for k, b in enumerate((lo, hi)):
        if b is None or not math.isfinite(b):
            continue
        if mixed is None or mixed.group(2 + 2 * k) == "inclusive":
            ends.append(fmt(b))
    return ends


# path -> the values at the ends its printed pattern includes: a check that
# refuses one of them disagrees with what --print-parameters promises.
INCLUSIVE_EDGES = {}
# Ends refused for what they mean together with another entry of the fuzz
# scene (a valid value on its own): (path regex, message regex).
EDGE_INTERPLAY = [
    (r"Newtonian fluid/Bulk modulus$", r"too small for the initial pressure"),
    (r"^Membrane/(Circumference|Enclosed area)$", r"cannot enclose"),
    (r"Mohr-Coulomb/Friction angle$", r"Cohesion are both 0"),
    (r"^Damping/Local damping coefficient$", r"Mass scaling is a dynamic"),
]


def double_values(allowed):
    lo, hi = number_range(allowed)
    values = ["", "abc", "nan", "inf", "-1", "0", "1e-300", "1e300"]
    if lo is not None and lo < 0:
        values.append("-1e300")
    for b in (lo, hi):
        if b is not None and math.isfinite(b) and fmt(b) not in values:
            values.append(fmt(b))
    return values


def integer_values(allowed):
    lo, hi = number_range(allowed)
    values = ["", "abc", "1.5", "-1", "0", "1e300", "99999999999999999999"]
    for v in (lo - 1 if lo is not None and math.isfinite(lo) else None,
              hi if hi is not None and math.isfinite(hi) else None,
              hi + 1 if hi is not None and math.isfinite(hi) else None,
              1000000000):
        if v is not None and fmt(v) not in values:
            values.append(fmt(v))
    return values


def list_values(allowed):
    if "Integer" in allowed:
        return ["", "abc", "1", "1, 2, 3", "0, 0", "-1, 4", "1.5, 2",
                "100000, 100000", "4294967296, 1"]
    return ["", "abc", "1", "1, 2, 3", "1, 2, 3, 4", "nan, 0", "inf, 0",
            "0, 0", "-1, -1", "1e-300, 1e-300", "1e300, 1e300",
            "-1e300, -1e300", "1,, 2"]


def selection_values(allowed, multiple):
    body = re.search(r"Selection (.*?) ?\]", allowed).group(1)
    options = [o.strip() for o in body.split("|")]
    values = ["", "bogus"] + options
    if multiple:
        values += [options[0] + ", " + options[0], options[0] + ", bogus",
                   ", ".join(options)]
    return values


NUMBER_OR_WORD = ["", "abc", "nan", "inf", "-inf", "-1", "0", "1e-300",
                  "1e300", "-1e300"]


def anything_values(path, fixtures):
    name = path.split("/")[-1]
    if name == "Mesh file":
        return ["", "does_not_exist.msh",
                os.path.join(fixtures, "not_a_mesh.msh"),
                os.path.join(fixtures, "empty.msh"),
                os.path.join(fixtures, "truncated.msh"), fixtures,
                os.path.join(fixtures, "square_triangles.msh"),
                os.path.join(fixtures, "cube_tetrahedra.msh")]
    if name == "Polygon vertices":
        common = ["", "abc", "0.1, 0.1; 0.2, 0.1", "nan, 0; 1, 0; 0, 1",
                  "inf, 0; 1, 0; 0, 1", "1e300, 0; 1e300, 1; 0, 1",
                  "0.1, 0.1, 0.1; 0.2, 0.1, 0; 0.1, 0.2, 0",
                  "0.1, 0.1;; 0.2, 0.1; 0.1, 0.2", "0.1 0.1; 0.2 0.1; 0.1 0.2"]
        if path.startswith("Membrane"):
            return common + [
                "1, 0.1; 2, 0.1; 2, 1; 1, 1",            # legal
                "1, 1; 2, 1; 2, 0.1; 1, 0.1",            # legal, clockwise
                "1, 1; 2, 2; 2, 1; 1, 2",                # self-intersecting
                "10, 10; 11, 10; 11, 11",                # outside the mesh
                "2.5, 1; 3.5, 1; 3, 1.5",                # partly outside
                "1, 1; 2, 1; 3, 1",                      # collinear
                "1, 1; 1, 1; 1, 1",                      # one point
                "1, 1; 2, 1; 2, 1; 1, 2",                # repeated vertex
                "1, 1; 1.0000000001, 1; 1, 1.0000000001"]  # tiny
        return common + [
            "0.05, 0.02; 0.15, 0.02; 0.1, 0.12",          # legal
            "0.05, 0.02; 0.1, 0.12; 0.15, 0.02",          # legal, clockwise
            "0.05, 0.05; 0.15, 0.15; 0.15, 0.05; 0.05, 0.15",  # self-inters.
            "1, 1; 2, 1; 2, 2",                           # outside
            "0.3, 0.1; 0.6, 0.1; 0.45, 0.2",              # partly outside
            "0.05, 0.05; 0.1, 0.05; 0.15, 0.05",          # collinear
            "0.1, 0.1; 0.1, 0.1; 0.1, 0.1",               # one point
            "0.05, 0.02; 0.15, 0.02; 0.15, 0.02; 0.1, 0.12",  # repeated
            "0.1, 0.1; 0.1000000001, 0.1; 0.1, 0.1000000001"]  # tiny
    if name == "Boundary conditions":
        return ["", "abc", "0: sticky", "0 roller", "0: roller: 1",
                "-1: fixed", "255: fixed", "99999999999: fixed", "x: fixed",
                "0: friction", "0: friction -1", "0: friction nan",
                "0: friction inf", "0: friction 1e300", "0: friction 0.5 1",
                "0: slip 0.3", "0: slip, 1: slip, 2: slip, 3: slip",
                "0: roller, 0: fixed", "0: fixed, 1: fixed, 2: fixed, 3: fixed",
                "0: free, 1: free, 2: free, 3: free", "7: fixed"]
    if name == "Directory":
        return ["", "nan", "-1", "1e300", ".", "a_file/sub", "a_file",
                "out/sub/deeper", "out/../out2"]
    if name == "Ground level":
        return NUMBER_OR_WORD + ["none", "10", "0.5", "-0.3"]
    if path.startswith("Monitors/"):
        return NUMBER_OR_WORD + ["auto", "1 2"]
    return NUMBER_OR_WORD


def values_for(path, allowed, fixtures):
    if allowed.startswith("[Double"):
        return double_values(allowed)
    if allowed.startswith("[Integer"):
        return integer_values(allowed)
    if allowed.startswith("[List"):
        return list_values(allowed)
    if allowed.startswith("[Bool"):
        return ["", "maybe", "1", "true", "false"]
    if allowed.startswith("[MultipleSelection"):
        return selection_values(allowed, True)
    if allowed.startswith("[Selection"):
        return selection_values(allowed, False)
    return anything_values(path, fixtures)


# ---------------------------------------------------------------------------
# The scene in which a parameter is read, and what else it needs.

def small_box(j):
    """A one-cell box of its own for extra body j >= 2 of the water scene
    (0.4 x 0.25 m, 5 cm cells): bodies fill in order, so a body entirely
    inside an earlier one is refused, and each needs room of its own."""
    i = j - 2
    x, y = 0.15 + 0.05 * (i % 5), 0.15 + 0.05 * (i // 5)
    return ["Box lower corner=%g, %g" % (x, y),
            "Box upper corner=%g, %g" % (x + 0.05, y + 0.05)]


def context(path):
    """(scene, [--set overrides]) under which the parameter is read."""
    p = path
    three_d = ["Simulation/Dimension=3", "Grid/Type=extruded box",
               "Grid/Extrusion thickness=0.05",
               "Bodies/Body 0/Box lower corner=0, 0, 0",
               "Bodies/Body 0/Box upper corner=0.1, 0.15, 0.05",
               "Bodies/Body 0/Particles per cell=8",
               "Bodies/Body 1/Box lower corner=0.3, 0, 0",
               "Bodies/Body 1/Box upper corner=0.35, 0.05, 0.05",
               "Bodies/Body 1/Particles per cell=8"]
    membrane_3d = ["Simulation/Dimension=3", "Grid/Type=extruded box",
                   "Grid/Extrusion thickness=0.16",
                   "Grid/Boundary conditions=2: roller, 4: roller, 5: roller",
                   "Bodies/Body 0/Particles per cell=8"]
    if p == "Membrane/Mesh file":
        return "membrane", membrane_3d + [
            "Membrane/Shape=gmsh", "Membrane/Tangential coupling=no-slip",
            "Bodies/Body 0/Shape=box",
            "Bodies/Body 0/Box lower corner=1, 0.1, 0",
            "Bodies/Body 0/Box upper corner=2, 0.5, 0.16"]
    if p == "Membrane/Polygon vertices":
        return "membrane", ["Membrane/Shape=polygon"]
    if p == "Membrane/Poisson ratio":
        return "membrane", membrane_3d
    if p.startswith("Membrane/") or p.startswith("Damping/"):
        return "membrane", []
    if p in ("Monitors/Contact tolerance", "Monitors/Pressure strip width"):
        return "membrane", []
    if p == "Simulation/Rest tolerance":
        return "soil", []
    if p == "Grid/Mesh file":
        return "water", ["Grid/Type=gmsh"]
    if p == "Grid/Extrusion thickness":
        return "water", [s for s in three_d
                         if not s.startswith("Grid/Extrusion")]
    if p == "Grid/Cell size":
        return "water", []
    m = re.match(r"Bodies/Body (\d+)/(.*)", p)
    if not m:
        return "water", []
    k, rest = int(m.group(1)), m.group(2)
    b = "Bodies/Body %d/" % k
    if k == 0 and (rest.startswith("Mohr-Coulomb/") or rest == "K0"):
        return "soil", []
    sets = []
    if k >= 2:
        sets.append("Bodies/Number of bodies=%d" % (k + 1))
        for j in range(2, k + 1):
            sets += ["Bodies/Body %d/%s" % (j, s) for s in small_box(j)]
    if rest.startswith("Column"):
        sets += [b + "Shape=column", b + "Column base corner=0.15, 0",
                 b + "Column width=0.05", b + "Column aspect ratio=1"]
    elif rest.startswith("Ellipse"):
        sets += [b + "Shape=ellipse", b + "Ellipse center=0.2, 0.12",
                 b + "Ellipse semi-axes=0.03, 0.03"]
    elif rest == "Polygon vertices":
        sets += [b + "Shape=polygon"]
    elif rest.startswith("Linear elastic/"):
        sets += [b + "Material model=linear elastic",
                 b + "Initial stress=none"]
    elif rest == "Newtonian fluid/Power-law exponent":
        sets += [b + "Material model=Newtonian fluid",
                 b + "Newtonian fluid/Pressure law=power"]
    elif rest.startswith("Newtonian fluid/"):
        sets += [b + "Material model=Newtonian fluid"]
    elif rest.startswith("Mohr-Coulomb/"):
        sets += [b + "Material model=Mohr-Coulomb"]
    elif rest == "K0":
        sets += [b + "Initial stress=geostatic"]
    elif rest == "Free surface threshold":
        sets += [b + "Free surface detection=true"]
    return "water", sets


# Exit status 1 with a message that names another parameter is right for
# these: the value is legal, but it switches on parameters that the scene
# does not set for it (e.g. Shape = polygon needs Polygon vertices).
# (path regex, value regex, regex the message must match instead).
OTHER_NAMES = [
    (r"Simulation/Dimension$", r"3", r"Grid/(Upper|Lower) corner"),
    (r"Bodies/Number of bodies$", r".*", r"Body \d"),
    (r"Bodies/Body \d+/Shape$", r".*", r"Body \d+"),
    (r"Bodies/Body \d+/Material model$", r"Mohr-Coulomb",
     r"Bodies/Body \d+/Mohr-Coulomb/"),
    (r"Bodies/Body \d+/Initial stress$", r"geostatic",
     r"Bodies/Body \d+/K0"),
    (r"Membrane/Shape$", r".*", r"Membrane/"),
    (r"Membrane/Enabled$", r"false", r"Shape = membrane needs a membrane"),
    (r"Grid/Type$", r".*", r"Grid/(Mesh file|Type)"),
]


def other_names(path, value):
    for p, v, accept in OTHER_NAMES:
        if re.search(p, path) and re.fullmatch(v, value):
            return accept
    return None


# ---------------------------------------------------------------------------
# Output checks.

def finite_numbers(text):
    bad = re.search(r"(?i)\b(nan|inf|infinity)\b", text)
    return bad is None


def check_vtu(path):
    root = ET.parse(path).getroot()
    compressed = root.get("compressor") is not None
    header = root.get("header_type", "UInt32")
    hsize = 8 if header == "UInt64" else 4
    hfmt = "<Q" if hsize == 8 else "<I"
    for da in root.iter("DataArray"):
        text = (da.text or "").strip()
        fmt_ = da.get("format", "ascii")
        typ = da.get("type", "Float64")
        if fmt_ == "ascii":
            if not finite_numbers(text):
                return "non-finite value in %s/%s" % (
                    os.path.basename(path), da.get("Name"))
            if da.get("Name") in ("mass", "volume") and \
                    not all(float(v) > 0 for v in text.split()):
                return "non-positive %s in %s" % (da.get("Name"),
                                                 os.path.basename(path))
            continue
        if fmt_ != "binary" or not typ.startswith("Float"):
            continue
        size = 8 if typ == "Float64" else 4
        if compressed:
            # deal.II: a base64 header (n_blocks, block size, last size,
            # compressed sizes), then the base64 zlib data.
            hlen = 4 * hsize
            henc = 4 * ((hlen + 2) // 3)
            head = base64.b64decode(text[:henc])
            n_blocks = struct.unpack(hfmt, head[:hsize])[0]
            full_hlen = (3 + n_blocks) * hsize
            henc = 4 * ((full_hlen + 2) // 3)
            head = base64.b64decode(text[:henc])
            sizes = [struct.unpack(hfmt, head[(3 + i) * hsize:
                                              (4 + i) * hsize])[0]
                     for i in range(n_blocks)]
            raw = base64.b64decode(text[henc:])
            data, pos = b"", 0
            for s in sizes:
                data += zlib.decompress(raw[pos:pos + s])
                pos += s
        else:
            raw = base64.b64decode(text)
            data = raw[hsize:]
        values = struct.unpack("<%d%s" % (len(data) // size,
                                          "d" if size == 8 else "f"),
                               data[:len(data) // size * size])
        if not all(math.isfinite(v) for v in values):
            return "non-finite value in %s/%s" % (os.path.basename(path),
                                                  da.get("Name"))
        if da.get("Name") in ("mass", "volume") and \
                not all(v > 0 for v in values):
            return "non-positive %s in %s" % (da.get("Name"),
                                             os.path.basename(path))
    return None


def reject_constant(name):
    raise ValueError("non-finite number %s" % name)


def check_output(case_dir, out_dir, status):
    """None, or the reason the output of a run is broken."""
    for root, _, files in os.walk(case_dir):
        for f in files:
            if ".tmp" in f:
                return "leftover temporary file %s" % f
    if not os.path.isdir(out_dir):
        return "no output directory"
    monitors = os.path.join(out_dir, "monitors.csv")
    if not os.path.isfile(monitors):
        return "no monitors.csv"
    with open(monitors) as f:
        lines = f.read().split("\n")
    if lines[-1] != "":
        return "monitors.csv: last row not complete"
    header = lines[0].split(",")
    for i, line in enumerate(lines[1:-1]):
        cells = line.split(",")
        if len(cells) != len(header):
            return "monitors.csv row %d: %d columns, header has %d" % (
                i + 1, len(cells), len(header))
        for h, c in zip(header, cells):
            if c == "" and h in ("dr_energy_ratio", "dr_force_ratio"):
                continue  # undefined before any external work or force
            try:
                v = float(c)
            except ValueError:
                return "monitors.csv row %d: %s = <%s> is not a number" % (
                    i + 1, h, c)
            if not math.isfinite(v):
                return "monitors.csv row %d: %s = %s" % (i + 1, h, c)
    summary = os.path.join(out_dir, "summary.json")
    if not os.path.isfile(summary):
        return "no summary.json"
    try:
        with open(summary) as f:
            s = json.load(f, parse_constant=reject_constant)
    except ValueError as e:
        return "summary.json does not parse: %s" % e
    for k, v in s.items():
        if v is None:
            return "summary.json: %s is null (non-finite)" % k
    termination = s.get("termination")
    if status == 3 and termination != "unstable":
        return "exit 3 but termination = %s" % termination
    if status == 3 and not s.get("diagnosis"):
        return "exit 3 without a diagnosis"
    if status == 0 and termination in ("unstable", "error"):
        return "exit 0 but termination = %s" % termination
    for f in sorted(os.listdir(out_dir)):
        p = os.path.join(out_dir, f)
        try:
            if f.endswith(".vtu"):
                reason = check_vtu(p)
                if reason:
                    return reason
            elif f.endswith(".pvd"):
                ET.parse(p)
        except Exception as e:  # a file that does not parse
            return "%s does not parse: %s" % (f, e)
    return None


# ---------------------------------------------------------------------------
# Running one case.

class Runner:
    """Runs the fsgmpm command line in a working directory: directly, or
    (with a fork server, tests/scenes/fuzz_server.cc) in a child forked
    from a process that has loaded the libraries already. One per worker
    thread. Returns (exit status or -signal or None for a hang, stdout,
    stderr)."""

    def __init__(self, exe, server):
        self.exe, self.server, self.proc = exe, server, None

    def __call__(self, args, cwd, timeout):
        if not self.server:
            try:
                r = subprocess.run([self.exe] + args, cwd=cwd,
                                   capture_output=True, text=True,
                                   timeout=timeout)
            except subprocess.TimeoutExpired:
                return None, "", ""
            return r.returncode, r.stdout, r.stderr
        if self.proc is None or self.proc.poll() is not None:
            self.proc = subprocess.Popen([self.server], stdin=subprocess.PIPE,
                                         stdout=subprocess.PIPE, text=True)
        self.proc.stdin.write("%g\n%s\n%d\n" % (timeout, cwd, len(args))
                              + "".join(a + "\n" for a in args))
        self.proc.stdin.flush()
        reply = self.proc.stdout.readline().split()
        def read(name):
            try:
                with open(os.path.join(cwd, name), errors="replace") as f:
                    return f.read()
            except OSError:
                return ""
        out, err = read("stdout.txt"), read("stderr.txt")
        for name in ("stdout.txt", "stderr.txt"):
            if os.path.exists(os.path.join(cwd, name)):
                os.remove(os.path.join(cwd, name))
        if not reply or reply[0] not in ("exit", "signal", "timeout"):
            raise RuntimeError("fork server failed: %s" % reply)
        if reply[0] == "timeout":
            return None, out, err
        return (int(reply[1]) if reply[0] == "exit" else -int(reply[1]),
                out, err)

    def close(self):
        if self.proc is not None:
            self.proc.stdin.close()
            self.proc.wait()


RUNNERS = threading.local()
ALL_RUNNERS = []


def run_case(case, exe, server, scenes, work, timeout):
    if not hasattr(RUNNERS, "runner"):
        RUNNERS.runner = Runner(exe, server)
        ALL_RUNNERS.append(RUNNERS.runner)
    runner = RUNNERS.runner
    path, value, scene, sets, accept = case
    case_dir = tempfile.mkdtemp(dir=work)
    try:
        open(os.path.join(case_dir, "a_file"), "w").close()
        args = [scenes[scene]]
        for s in sets + ["%s=%s" % (path, value)]:
            args += ["--set", s]
        out_dir = os.path.join(case_dir, value if path == "Output/Directory"
                               else "out")
        t0 = time.time()
        status, out, err = runner(args, case_dir, timeout)
        wall = time.time() - t0
        if status is None:
            return case, None, "hang (no exit within %g s)" % timeout, wall
        msg = out + err
        if status < 0:
            return case, status, "crash (signal %d): %s" % (
                -status, msg.strip()[-300:]), wall
        if status not in (0, 1, 3):
            return case, status, "crash (exit status %d): %s" % (
                status, msg.strip()[-300:]), wall
        if CRASH_PATTERNS.search(msg):
            return case, status, "crash message: %s" % msg.strip()[-300:], wall
        if status == 1:
            # Warnings (e.g. a body in a few cells) may come first.
            err = "\n".join(
                line for line in err.strip().splitlines()
                if not line.startswith("fsgmpm: warning:")).strip()
            if not err.startswith("fsgmpm: error:"):
                return case, status, "no error message: " + msg[-300:], wall
            name = re.escape(path.split("/")[-1])
            if not re.search(name, err, re.IGNORECASE) and not (
                    accept and re.search(accept, err)):
                return case, status, "message does not name %s: %s" % (
                    path, err[:300]), wall
            if value in INCLUSIVE_EDGES.get(path, ()) and not any(
                    re.search(p, path) and re.search(m, err)
                    for p, m in EDGE_INTERPLAY):
                return case, status, ("the printed pattern includes %s, "
                                      "the check refuses it: %s"
                                      % (value, err[:300])), wall
            if os.path.exists(out_dir) and path != "Output/Directory":
                return case, status, "exit 1 after writing output: " + \
                    err[:300], wall
            return case, status, None, wall, err
        reason = check_output(case_dir, out_dir, status)
        if reason:
            return case, status, reason + " | " + msg.strip()[-200:], wall
        return case, status, None, wall, msg.strip()
    finally:
        shutil.rmtree(case_dir, ignore_errors=True)


def make_fixtures(fixtures, tests_dir):
    os.makedirs(fixtures)
    with open(os.path.join(fixtures, "not_a_mesh.msh"), "w") as f:
        f.write("this is not a mesh\n1 2 3\n")
    open(os.path.join(fixtures, "empty.msh"), "w").close()
    src = os.path.join(tests_dir, "meshes", "square_triangles.msh")
    with open(src) as f:
        text = f.read()
    with open(os.path.join(fixtures, "truncated.msh"), "w") as f:
        f.write(text[:len(text) // 2])
    for m in ("square_triangles.msh", "cube_tetrahedra.msh"):
        shutil.copy(os.path.join(tests_dir, "meshes", m), fixtures)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("exe")
    ap.add_argument("tests_dir")
    ap.add_argument("--server", default="",
                    help="fork server (fuzz_server): run the cases in "
                         "children of it instead of starting the executable "
                         "each time (same main(), no start-up cost)")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=20)
    ap.add_argument("--filter", default="",
                    help="only parameters whose path matches this regex")
    ap.add_argument("--list", action="store_true",
                    help="list the cases, do not run them")
    ap.add_argument("--verbose", action="store_true",
                    help="print every case: exit status and message")
    a = ap.parse_args()
    exe = os.path.abspath(a.exe)
    server = os.path.abspath(a.server) if a.server else ""
    scenes = {s: os.path.join(os.path.abspath(a.tests_dir), "scenes", "fuzz",
                              s + ".prm")
              for s in ("water", "soil", "membrane")}
    t_start = time.time()
    work = tempfile.mkdtemp(prefix="fsgmpm_fuzz_")
    try:
        fixtures = os.path.join(work, "fixtures")
        make_fixtures(fixtures, os.path.abspath(a.tests_dir))
        params = read_parameters(exe, scenes["water"])
        cases = []
        for path, allowed in params:
            if not re.search(a.filter, path):
                continue
            scene, sets = context(path)
            values = values_for(path, allowed, fixtures)
            INCLUSIVE_EDGES[path] = set(inclusive_edges(allowed or ""))
            m = re.match(r"Bodies/Body ([2-7])/", path)
            if m:
                # The same code as Body 1 (a loop over the subsections):
                # Bodies 2-7 share the values, each takes every sixth, so
                # that every value is tried on one of them.
                k = int(m.group(1)) - 2
                values = values[k::6] or [values[k % len(values)]]
            for v in values:
                cases.append((path, v, scene, sets, other_names(path, v)))
        if a.list:
            for c in cases:
                print("%-8s %s = <%s>" % (c[2], c[0], c[1]))
            print("%d parameters, %d cases" % (len(params), len(cases)))
            return 0
        failures, statuses = [], {}
        with concurrent.futures.ThreadPoolExecutor(a.workers) as pool:
            futures = [pool.submit(run_case, c, exe, server, scenes, work,
                                   a.timeout)
                       for c in cases]
            for f in concurrent.futures.as_completed(futures):
                case, status, reason, wall, *message = f.result()
                if a.verbose:
                    print("%-4s exit %s %5.2f s  %s = <%s>: %s" % (
                        "FAIL" if reason else "ok", status, wall, case[0],
                        case[1], (reason or (message[0] if message else ""))
                        .replace("\n", " ")[:240]), flush=True)
                statuses[status] = statuses.get(status, 0) + 1
                if reason:
                    failures.append((case, status, reason))
        failures.sort(key=lambda x: (x[0][0], x[0][1]))
        for case, status, reason in failures:
            print("FAIL %s = <%s> [%s scene]: exit %s: %s" % (
                case[0], case[1], case[2], status, reason.replace("\n", " ")))
        n_params = len(set(c[0] for c in cases))
        print("fuzzed %d parameters: %d cases tried, %d passed, %d failed "
              "(exit 0: %d, exit 1: %d, exit 3: %d), %.1f s wall, %d workers"
              % (n_params, len(cases), len(cases) - len(failures),
                 len(failures), statuses.get(0, 0), statuses.get(1, 0),
                 statuses.get(3, 0), time.time() - t_start, a.workers))
        return 1 if failures else 0
    finally:
        for r in ALL_RUNNERS:
            r.close()
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
