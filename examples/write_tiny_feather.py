#!/usr/bin/env python3
"""Writes examples/tiny_feather.ply: a minimal feather in Columba's feather PLY format.

A worked example of an exporter (see docs/feather-ply.md): a straight rachis along +y and four
curved barbs on each side, every barb a polyline of exactly 64 vertices from its base to its
tip, with the vane normal (+z) and per-vertex barbule values in the file's convention
(H 0.5, mu 0.35, cortex thickness in micrometres). Run it from anywhere; it writes next to itself.
"""
import math
import os

VERTICES_PER_BARB = 64  # the format's fixed barb length (63 segments)
BARBS_PER_SIDE = 4
BARB_SPACING = 0.1       # along the rachis, in file units
BARB_ANGLE = math.radians(40)  # between the barb's base and the rachis, toward the tip
BARB_CURL = math.radians(25)   # how far a barb turns toward the tip from base to end
BARB_LENGTH = 0.45


def barb(side, index):
    """The 64 (x, y, z, H, mu, height, nx, ny, nz) rows of one barb, base first."""
    y0 = -0.2 + index * BARB_SPACING
    x, y = 0.0, y0
    step = BARB_LENGTH / (VERTICES_PER_BARB - 1)
    height = 0.60 if side < 0 else 0.52  # green barbs on the left, purple on the right
    rows = []
    for k in range(VERTICES_PER_BARB):
        rows.append((x, y, 0.0, 0.5, 0.35, height, 0.0, 0.0, 1.0))
        heading = BARB_ANGLE - BARB_CURL * (k + 0.5) / (VERTICES_PER_BARB - 1)
        x += side * step * math.sin(heading)
        y += step * math.cos(heading)
    return rows


def main():
    barbs = [barb(side, i) for side in (-1, 1) for i in range(BARBS_PER_SIDE)]
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "tiny_feather.ply")
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\n")
        f.write("comment a tiny feather: 8 barbs of 64 vertices, base first (see docs/feather-ply.md)\n")
        # Neighbouring barbs lie 0.064 apart at their bases and 0.026 at their tips: strips 0.07
        # wide at the base (tapering to 0.3 of that) meet over most of their length.
        f.write("comment barbwidth 0.07\n")
        f.write(f"element vertex {len(barbs) * VERTICES_PER_BARB}\n")
        for name in ("x", "y", "z", "H", "mu", "height", "out1", "out2", "out3"):
            f.write(f"property float {name}\n")
        f.write(f"element face {len(barbs)}\n")
        f.write("property list uchar int vertex_indices\nend_header\n")
        for rows in barbs:
            for row in rows:
                f.write(" ".join(f"{v:.4g}" for v in row) + "\n")
        for b in range(len(barbs)):
            first = b * VERTICES_PER_BARB
            f.write(f"{VERTICES_PER_BARB} " + " ".join(str(first + k) for k in range(VERTICES_PER_BARB)) + "\n")


if __name__ == "__main__":
    main()
