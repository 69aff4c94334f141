#!/usr/bin/python3
"""Compare the point fields of two particle VTU files written by fsgmpm.

Usage: compare_vtu.py <reference.vtu> <result.vtu> [--skip NAME]... [--quiet]

Reads every array with doc/scripts/read_vtu.py and requires the values to
be identical (bit for bit, as written), except the arrays named with
--skip. Exits 1 and names the arrays that differ or are missing; with
--quiet prints nothing if all agree.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "doc", "scripts"))
from read_vtu import read_vtu  # noqa: E402


def main(argv):
    skip = [argv[i + 1] for i in range(len(argv) - 1) if argv[i] == "--skip"]
    quiet = "--quiet" in argv
    files = [a for i, a in enumerate(argv[1:], 1)
             if a not in ("--skip", "--quiet") and argv[i - 1] != "--skip"]
    reference, result = read_vtu(files[0]), read_vtu(files[1])
    compared = [k for k in reference if k not in skip]
    bad = [k for k in compared
           if k not in result
           or reference[k].tobytes() != result[k].tobytes()
           or reference[k].dtype != result[k].dtype]
    if bad:
        print("  %s: differs in %s" % (files[1], ", ".join(bad)))
        return 1
    if not quiet:
        print("  %s: %d arrays identical" % (os.path.basename(files[1]),
                                            len(compared)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
