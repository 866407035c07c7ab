#!/usr/bin/python3
"""Plot material points from SlideWave's particle output (.pvtu/.vtu, as written by
deal.II: binary, zlib-compressed, base64), coloured by one of their properties.

  scripts/plot_particles.py OUTPUT_DIR/particles/particles_00020.pvtu --field velocity \
      --out figure.png [--title T] [--xlim a b] [--ylim a b] [--initial]

--initial also draws the points' initial positions in light grey. Needs only numpy and
matplotlib (Debian: python3-numpy, python3-matplotlib)."""
import argparse
import base64
import os
import re
import struct
import zlib

import numpy as np


def decode_array(text, dtype):
    """One deal.II binary DataArray: a base64 header of UInt32 block counts and sizes, then
    the base64 zlib-compressed blocks."""
    text = "".join(text.split())
    first = base64.b64decode(text[:24])
    n_blocks = struct.unpack("<I", first[:4])[0]
    header_bytes = (3 + n_blocks) * 4
    header_chars = 4 * ((header_bytes + 2) // 3)
    header = struct.unpack("<%dI" % (3 + n_blocks), base64.b64decode(text[:header_chars])[:header_bytes])
    sizes = header[3:]
    data = base64.b64decode(text[header_chars:])
    raw, offset = b"", 0
    for size in sizes:
        raw += zlib.decompress(data[offset:offset + size])
        offset += size
    return np.frombuffer(raw, dtype=dtype)


def read_vtu(path):
    """Points (n x 3) and point data {name: array (n) or (n x 3)} of one piece."""
    content = open(path).read()
    arrays = {}
    points = None
    pattern = re.compile(r'<DataArray ([^>]*)>(.*?)</DataArray>', re.S)
    for match in pattern.finditer(content):
        attributes, body = match.group(1), match.group(2)
        kind = re.search(r'type="(\w+)"', attributes).group(1)
        dtype = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "UInt8": "u1"}[kind]
        components = re.search(r'NumberOfComponents="(\d+)"', attributes)
        name = re.search(r'Name="([^"]+)"', attributes)
        values = decode_array(body, dtype)
        if components:
            values = values.reshape(-1, int(components.group(1)))
        if name is None:
            if points is None:
                points = values
        else:
            arrays[name.group(1)] = values
    return points, arrays


def read_particles(path):
    """All pieces of a .pvtu (or a single .vtu)."""
    if path.endswith(".pvtu"):
        directory = os.path.dirname(path)
        pieces = re.findall(r'<Piece Source="([^"]+)"', open(path).read())
        parts = [read_vtu(os.path.join(directory, p)) for p in pieces]
    else:
        parts = [read_vtu(path)]
    parts = [p for p in parts if p[0] is not None and len(p[0])]
    points = np.concatenate([p[0] for p in parts])
    names = parts[0][1].keys()
    data = {n: np.concatenate([p[1][n] for p in parts]) for n in names}
    return points, data


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("--field", default="velocity")
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", default="")
    parser.add_argument("--xlim", nargs=2, type=float)
    parser.add_argument("--ylim", nargs=2, type=float)
    parser.add_argument("--initial", action="store_true")
    parser.add_argument("--size", type=float, default=2.0, help="marker size")
    args = parser.parse_args()

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    points, data = read_particles(args.file)
    values = data[args.field]
    label = args.field
    if values.ndim == 2:
        values = np.linalg.norm(values, axis=1)
        label = "|" + args.field + "|"
    fig, ax = plt.subplots(figsize=(8, 4))
    if args.initial and "initial_x" in data:
        ax.scatter(data["initial_x"], data["initial_y"], s=args.size, c="0.85", lw=0)
    sc = ax.scatter(points[:, 0], points[:, 1], s=args.size, c=values, cmap="viridis", lw=0)
    fig.colorbar(sc, ax=ax, label=label, shrink=0.8)
    ax.set_aspect("equal")
    if args.xlim:
        ax.set_xlim(*args.xlim)
    if args.ylim:
        ax.set_ylim(*args.ylim)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(args.title)
    fig.tight_layout()
    fig.savefig(args.out, dpi=130)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
