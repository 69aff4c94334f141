#!/usr/bin/python3
"""The source folders include only their own and lower layers.

Usage: include_layers.py SOURCE_DIR

The layers, lowest first (doc/developer.md, "Source layout"): base;
grid and materials; particles; membrane; parallel; step; run; monitors
and io; scene; the Simulator (include/fsgmpm/simulator.h, source/*.cc);
app. A file of include/fsgmpm/X/ or source/X/ may include
<fsgmpm/Y/...> only where Y's layer is not above X's. Prints each
upward include and exits 1 if there is one. The check fails on a broken
variant: a grid/ file that includes <fsgmpm/io/...>.
"""
import os
import re
import sys

LAYER = {"base": 0, "grid": 1, "materials": 1, "particles": 2,
         "membrane": 3, "parallel": 4, "step": 5, "run": 6, "monitors": 7,
         "io": 7, "scene": 8, "simulator": 9, "app": 10}


def upward_includes(root):
    found, n_files = [], 0
    for top in ("include/fsgmpm", "source"):
        base = os.path.join(root, top)
        for directory, _, files in os.walk(base):
            rel = os.path.relpath(directory, base)
            folder = "simulator" if rel == "." else rel.split(os.sep)[0]
            if folder not in LAYER:
                continue
            for name in files:
                path = os.path.join(directory, name)
                n_files += 1
                for number, line in enumerate(open(path), 1):
                    m = re.match(r"\s*#\s*include\s*<fsgmpm/([a-z_]+)/", line)
                    if m and LAYER.get(m.group(1), -1) > LAYER[folder]:
                        found.append("%s:%d: %s (layer %s above %s)" % (
                            os.path.relpath(path, root), number,
                            line.strip(), m.group(1), folder))
    return found, n_files


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__)
        sys.exit(2)
    found, n_files = upward_includes(sys.argv[1])
    for f in found:
        print(f)
    print("include layers: %d files, %d upward includes" % (n_files, len(found)))
    sys.exit(1 if found or n_files == 0 else 0)
