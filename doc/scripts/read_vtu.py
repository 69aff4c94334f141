"""Read the point data of an fsgmpm/deal.II VTU file (zlib-compressed,
base64-encoded binary arrays) into numpy arrays, without VTK.

    from read_vtu import read_vtu
    fields = read_vtu("output/run/particles_00010.vtu")
    x, y = fields["Points"][:, 0], fields["Points"][:, 1]

A .pvtu file (the points of an MPI run: one piece per process) is read
as its pieces one after the other, as if they were one file.

Uses Debian's /usr/bin/python3 with python3-numpy.
"""
import base64
import os
import re
import struct
import zlib

import numpy as np

_TYPES = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32,
          "UInt32": np.uint32, "Int64": np.int64, "UInt8": np.uint8}


def _decode(text, dtype):
    # Header: number of blocks, block size, last block size, then the
    # compressed size of every block (uint32), base64-encoded on its own.
    first = base64.b64decode(text[:8])
    n_blocks = struct.unpack("<I", first[:4])[0]
    header_len = 4 * (3 + n_blocks)
    header_chars = ((header_len + 2) // 3) * 4
    header = base64.b64decode(text[:header_chars])
    sizes = struct.unpack("<%dI" % n_blocks, header[12:12 + 4 * n_blocks])
    body = base64.b64decode(text[header_chars:])
    raw, offset = b"", 0
    for size in sizes:
        raw += zlib.decompress(body[offset:offset + size])
        offset += size
    return np.frombuffer(raw, dtype=dtype)


def read_vtu(path):
    """Map of array name ("Points" for the coordinates) to numpy array."""
    if path.endswith(".pvtu"):
        return _read_pvtu(path)
    with open(path) as f:
        text = f.read()
    fields = {}
    for match in re.finditer(r"<DataArray([^>]*)>\s*([^<]*)</DataArray>",
                             text):
        attributes, data = match.group(1), match.group(2).strip()
        if not data:  # an empty piece (a process without points)
            continue
        if 'format="binary"' not in attributes:
            raise ValueError(path + ": only binary VTU arrays are supported")
        name = re.search(r'Name="([^"]*)"', attributes)
        name = name.group(1) if name else "Points"
        components = re.search(r'NumberOfComponents="(\d+)"', attributes)
        components = int(components.group(1)) if components else 1
        dtype = _TYPES[re.search(r'type="([^"]*)"', attributes).group(1)]
        values = _decode(data, dtype)
        fields[name] = values.reshape(-1, components) if components > 1 \
            else values
    return fields


def particle_files(directory):
    """The points' file of every output step of a run, in order:
    particles_NNNNN.vtu, or particles_NNNNN.pvtu of an MPI run (not its
    pieces particles_NNNNN.R.vtu)."""
    names = [n for n in os.listdir(directory)
             if re.fullmatch(r"particles_\d+\.p?vtu", n)]
    return [os.path.join(directory, n) for n in sorted(names)]


def _read_pvtu(path):
    """The pieces of a .pvtu record, concatenated in their order; the
    cells' connectivity and offsets renumbered as in one file."""
    with open(path) as f:
        sources = re.findall(r'<Piece\s+Source="([^"]*)"', f.read())
    directory = os.path.dirname(path)
    pieces = [read_vtu(os.path.join(directory, s)) for s in sources]
    fields, n_points, n_connectivity = {}, 0, 0
    for piece in pieces:
        if not piece:
            continue
        for name, values in piece.items():
            if name == "connectivity":
                values = values + n_points
            elif name == "offsets":
                values = values + n_connectivity
            fields.setdefault(name, []).append(values)
        n_points += len(piece["Points"])
        n_connectivity += len(piece.get("connectivity", []))
    return {name: np.concatenate(parts) for name, parts in fields.items()}
