#!/usr/bin/env python3
"""Sweep the keratin cortex (film) thickness of the barbule model and show what an imaging
scatterometer records for light at 30 degrees: one hemisphere image per thickness, as a grid.

    python3 thickness_sweep.py [-o OUT_DIR] [--res 96] [--theta 30]

Writes thickness_sweep.png.
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import columba  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("-o", "--out", type=pathlib.Path, default=pathlib.Path("."))
parser.add_argument("--res", type=int, default=96)
parser.add_argument("--theta", type=float, default=30.0)
args = parser.parse_args()
args.out.mkdir(parents=True, exist_ok=True)

heights = np.round(np.arange(0.40, 0.801, 0.05), 2)
images = [columba.BarbuleBSDF(height=h).scatterometer_image(args.theta, resolution=args.res) for h in heights]
scale = max(np.percentile(image, 99.5) for image in images)  # one exposure for all

columns = 3
rows = (len(heights) + columns - 1) // columns
fig, axes = plt.subplots(rows, columns, figsize=(3 * columns, 3.2 * rows))
for ax in axes.flat:
    ax.axis("off")
for ax, h, image in zip(axes.flat, heights, images):
    ax.imshow(columba.to_srgb(image / scale))
    ax.set_title(f"height {h:.2f} µm")
fig.suptitle(f"Barbule scatterometer images, light at {args.theta:g}°")
fig.tight_layout()
fig.savefig(args.out / "thickness_sweep.png", dpi=80)
print(f"wrote {args.out / 'thickness_sweep.png'}")
