#!/usr/bin/python3
"""Compare the point fields of two particle VTU files written by fsgmpm.

Usage: compare_vtu.py <reference.vtu> <result.vtu> [--skip NAME]...

Decodes every binary (zlib-compressed, base64) DataArray and requires the
bytes to be identical, except the arrays named with --skip. Exits 1 and
names the arrays that differ or are missing.
"""
import base64
import re
import struct
import sys
import zlib


def arrays(path):
    text = open(path).read()
    found = {}
    pattern = (r'<DataArray type="(\w+)"(?: Name="([^"]*)")?[^>]*'
               r'format="binary">\s*(\S+)\s*</DataArray>')
    for i, m in enumerate(re.finditer(pattern, text)):
        kind, name, data = m.groups()
        # vtkZLibDataCompressor: a base64 header of uint32 (blocks, block
        # size, last block size, compressed sizes), then the base64 blocks.
        n_blocks = struct.unpack("<I", base64.b64decode(data[:8])[:4])[0]
        header_chars = ((4 * (3 + n_blocks) + 2) // 3) * 4
        header = base64.b64decode(data[:header_chars])
        sizes = struct.unpack("<%dI" % n_blocks, header[12:12 + 4 * n_blocks])
        body = base64.b64decode(data[header_chars:])
        raw, offset = b"", 0
        for size in sizes:
            raw += zlib.decompress(body[offset:offset + size])
            offset += size
        found[name or "%s array %d" % (kind, i)] = raw
    return found


def main(argv):
    skip = [argv[i + 1] for i in range(len(argv) - 1) if argv[i] == "--skip"]
    files = [a for i, a in enumerate(argv[1:], 1)
             if a != "--skip" and argv[i - 1] != "--skip"]
    reference, result = arrays(files[0]), arrays(files[1])
    bad = [k for k in reference if k not in skip and reference[k] != result.get(k)]
    if bad:
        print("  %s: differs in %s" % (files[1], ", ".join(bad)))
        return 1
    print("  %s: %d arrays identical" % (files[1].split("/")[-1],
                                        len([k for k in reference if k not in skip])))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
