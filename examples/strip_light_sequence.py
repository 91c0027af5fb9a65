#!/usr/bin/env python3
"""A strip light swings over a single feather, as in a gonio-photographic measurement
(scenes/feather_linear_light.xml): render a frame per light angle and plot the feather's colour
against the angle.

    python3 strip_light_sequence.py [-o OUT_DIR] [--res 128] [--spp 16] [--angles -40 -20 0 20 40]

Writes strip_light_sequence.png (the frames and the colour curve) and one EXR per angle.
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import columba  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
SCENE = HERE.parent / "scenes" / "feather_linear_light.xml"  # the source tree and share/columba alike

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("-o", "--out", type=pathlib.Path, default=pathlib.Path("."))
parser.add_argument("--res", type=int, default=128)
parser.add_argument("--spp", type=int, default=16)
parser.add_argument("--angles", type=float, nargs="+", default=[-45, -30, -15, 0, 15, 30, 45])
args = parser.parse_args()
args.out.mkdir(parents=True, exist_ok=True)

feather = args.out / "feather.ply"
columba.generate_feathers(feather, binary=True)

frames, colours = [], []
for angle in args.angles:
    scene = columba.load_file(SCENE, feather=feather.resolve(), angle=angle, res=args.res, spp=args.spp)
    image = columba.render(scene, seed=1)
    columba.write_image(args.out / f"strip_light_{angle:g}.exr", image)
    # The feather covers the middle of the frame; its mean colour there, normalised to unit sum.
    h, w, _ = image.shape
    centre = image[h // 3: 2 * h // 3, w // 3: 2 * w // 3].reshape(-1, 3).mean(axis=0)
    colours.append(centre)
    frames.append(image)
    print(f"light at {angle:+5.1f} deg: mean RGB {np.array2string(centre, precision=4)}")

colours = np.array(colours)
fig = plt.figure(figsize=(2 * len(frames), 5.2))
for i, (angle, image) in enumerate(zip(args.angles, frames)):
    ax = fig.add_subplot(2, len(frames), i + 1)
    ax.imshow(columba.to_srgb(image / max(image.max(), 1e-6)))
    ax.set_title(f"{angle:g}°")
    ax.axis("off")
ax = fig.add_subplot(2, 1, 2)
chroma = colours / colours.sum(axis=1, keepdims=True)
for k, (name, c) in enumerate(zip("RGB", ("tab:red", "tab:green", "tab:blue"))):
    ax.plot(args.angles, chroma[:, k], "o-", color=c, label=f"{name} / (R+G+B)")
ax.set_xlabel("strip light angle (degrees)")
ax.set_ylabel("chromaticity of the feather")
ax.legend()
fig.tight_layout()
fig.savefig(args.out / "strip_light_sequence.png", dpi=80)
print(f"wrote {args.out / 'strip_light_sequence.png'}")
