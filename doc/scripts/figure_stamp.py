#!/usr/bin/python3
"""Stamp a PNG with the fsgmpm version that made it.

Usage: figure_stamp.py --software VERSION [--footer] -- SCRIPT [ARGS ...]
       figure_stamp.py --software VERSION PNG [PNG ...]
       figure_stamp.py --read PNG [PNG ...]

The first form runs the plotting script SCRIPT with ARGS (as
`/usr/bin/python3 SCRIPT ARGS`, in this process) with every PNG it saves
through matplotlib given the tEXt chunk Software = VERSION (matplotlib
writes its own name there otherwise) and, with --footer, VERSION as a
small grey text in the figure's lower right corner. The second form
rewrites the Software tEXt chunk of existing PNGs (pure Python, the image
data untouched); the third prints each PNG's Software text. A plotting
script may also call set_software(path, version) after saving.
doc/scripts/make_figures.py stamps every figure this way, VERSION being
what `fsgmpm --version` prints.
"""
import os
import runpy
import struct
import sys
import zlib

SIGNATURE = b"\x89PNG\r\n\x1a\n"
KEY = "Software"


def chunks(data):
    """[(type, body), ...] of the PNG bytes data; ValueError if it is not
    a complete PNG."""
    if not data.startswith(SIGNATURE):
        raise ValueError("not a PNG (no PNG signature)")
    result, i = [], len(SIGNATURE)
    while i < len(data):
        if i + 8 > len(data):
            raise ValueError("truncated PNG chunk header at byte %d" % i)
        length, kind = struct.unpack(">I4s", data[i:i + 8])
        body = data[i + 8:i + 8 + length]
        if len(body) != length or i + 12 + length > len(data):
            raise ValueError("truncated PNG chunk %r" % kind)
        crc, = struct.unpack(">I", data[i + 8 + length:i + 12 + length])
        if crc != zlib.crc32(kind + body) & 0xffffffff:
            raise ValueError("bad CRC in PNG chunk %r" % kind)
        result.append((kind, body))
        i += 12 + length
    if not result or result[0][0] != b"IHDR" or result[-1][0] != b"IEND":
        raise ValueError("PNG does not start with IHDR and end with IEND")
    return result


def _key_of(kind, body):
    if kind in (b"tEXt", b"zTXt", b"iTXt"):
        return body.split(b"\0", 1)[0].decode("latin-1")
    return None


def text(path):
    """{key: text} of the tEXt (and uncompressed iTXt) chunks of a PNG."""
    with open(path, "rb") as f:
        data = f.read()
    result = {}
    for kind, body in chunks(data):
        if kind == b"tEXt":
            key, _, value = body.partition(b"\0")
            result[key.decode("latin-1")] = value.decode("latin-1")
        elif kind == b"iTXt":
            key, _, rest = body.partition(b"\0")
            if rest[:1] == b"\0":  # not compressed
                _, _, rest = rest[2:].partition(b"\0")  # language tag
                _, _, value = rest.partition(b"\0")  # translated keyword
                result[key.decode("latin-1")] = value.decode("utf-8")
    return result


def _chunk(kind, body):
    return (struct.pack(">I", len(body)) + kind + body
            + struct.pack(">I", zlib.crc32(kind + body) & 0xffffffff))


def set_software(path, version):
    """Rewrite the PNG at path with one tEXt chunk Software = version, right
    after IHDR, in place of any Software text chunk it had."""
    with open(path, "rb") as f:
        data = f.read()
    body = KEY.encode("latin-1") + b"\0" + version.encode("latin-1")
    out = [SIGNATURE]
    for kind, chunk_body in chunks(data):
        if _key_of(kind, chunk_body) == KEY:
            continue
        out.append(_chunk(kind, chunk_body))
        if kind == b"IHDR":
            out.append(_chunk(b"tEXt", body))
    tmp = path + ".stamp.tmp"
    with open(tmp, "wb") as f:
        f.write(b"".join(out))
    os.replace(tmp, path)


def add_footer(fig, version):
    """version in small grey type in the figure's lower right corner (once)."""
    if not getattr(fig, "_fsgmpm_footer", False):
        fig.text(0.995, 0.005, version, ha="right", va="bottom", fontsize=6,
                 color="0.5")
        fig._fsgmpm_footer = True


def patch_savefig(version, footer):
    """Make matplotlib's Figure.savefig (and so pyplot.savefig) write
    Software = version into PNGs, and add the footer when footer is true."""
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    original = Figure.savefig

    def savefig(self, fname, *args, **kwargs):
        if footer:
            add_footer(self, version)
        fmt = kwargs.get("format")
        if fmt is None and isinstance(fname, (str, os.PathLike)):
            fmt = os.path.splitext(os.fspath(fname))[1][1:]
        if (fmt or "png").lower() == "png":
            kwargs["metadata"] = dict(kwargs.get("metadata") or {},
                                      **{KEY: version})
        return original(self, fname, *args, **kwargs)

    Figure.savefig = savefig


def run_script(version, footer, script, args):
    """Run a plotting script as __main__ with savefig patched."""
    patch_savefig(version, footer)
    sys.argv = [script] + list(args)
    sys.path.insert(0, os.path.dirname(os.path.abspath(script)))
    runpy.run_path(script, run_name="__main__")


def main(argv):
    if len(argv) >= 2 and argv[0] == "--read":
        for path in argv[1:]:
            print("%s: %s" % (path, text(path).get(KEY, "(no Software text)")))
        return 0
    if len(argv) < 3 or argv[0] != "--software":
        sys.exit(__doc__)
    version, rest = argv[1], argv[2:]
    footer = False
    if rest and rest[0] == "--footer":
        footer, rest = True, rest[1:]
    if rest and rest[0] == "--":
        if len(rest) < 2:
            sys.exit(__doc__)
        run_script(version, footer, rest[1], rest[2:])
        return 0
    for path in rest:
        set_software(path, version)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
