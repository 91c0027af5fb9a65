#!/usr/bin/env python3
"""The R and TRT lobes of green and purple rock dove barbules in the mirror direction (the
reflectance factor pi f a microspectrophotometer measures) against wavelength, for light
from 0 to 60 degrees.

    python3 mirror_spectra.py [-o OUT_DIR]

Writes mirror_spectra.png and mirror_spectra.csv, and prints where the R lobe peaks: the highest
of its maxima between 400 and 700 nm. The film's interference orders make R rise and fall several
times over the spectrum, to nearly the same height, so the highest value of the whole range is
often at its violet end, or a value at the end of the range that is no maximum at all.
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
args = parser.parse_args()
args.out.mkdir(parents=True, exist_ok=True)



def visible_maxima(wavelengths, r, lowest=400.0, highest=700.0):
    """Indices of r's local maxima between `lowest` and `highest` nm, highest first. A maximum is
    a sample above its neighbours on both sides, so the ends of the range never count."""
    k = np.flatnonzero((r[1:-1] >= r[:-2]) & (r[1:-1] > r[2:])) + 1
    k = k[(wavelengths[k] >= lowest) & (wavelengths[k] <= highest)]
    return k[np.argsort(-r[k], kind="stable")]


angles = [0, 15, 30, 45, 60]
wavelengths = np.arange(380, 781, 2, dtype=np.float32)
fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
table = [wavelengths]
columns = ["wavelength_nm"]
for row, preset in enumerate(["dove-green", "dove-purple"]):
    bsdf = columba.BarbuleBSDF(preset=preset)
    for angle, colour in zip(angles, plt.cm.viridis(np.linspace(0, 0.9, len(angles)))):
        s = bsdf.specular_spectra(angle, wavelengths=wavelengths)
        for col, lobe in enumerate(["R", "TRT"]):
            axes[row, col].plot(s["wavelengths"], s[lobe], color=colour, label=f"{angle}°")
            table.append(s[lobe])
            columns.append(f"{preset}_{lobe}_theta{angle}")
        maxima = visible_maxima(s["wavelengths"], s["R"])
        if len(maxima) == 0:
            print(f"{preset:12s} light {angle:2d} deg: R has no maximum between 400 and 700 nm")
            continue
        orders = ", ".join(f"{s['wavelengths'][k]:.0f} nm ({s['R'][k]:.2f})" for k in sorted(maxima))
        print(f"{preset:12s} light {angle:2d} deg: R peaks at {s['wavelengths'][maxima[0]]:.0f} nm; "
              f"its maxima in 400-700 nm: {orders}")
    for col, lobe in enumerate(["R", "TRT"]):
        axes[row, col].set_title(f"{preset}: {lobe}")
        axes[row, col].set_ylabel("reflectance factor π f")
axes[0, 0].legend(title="light")
for ax in axes[1]:
    ax.set_xlabel("wavelength (nm)")
fig.tight_layout()
fig.savefig(args.out / "mirror_spectra.png", dpi=80)
np.savetxt(args.out / "mirror_spectra.csv", np.array(table).T, delimiter=",", header=",".join(columns), comments="")
print(f"wrote {args.out / 'mirror_spectra.png'} and mirror_spectra.csv")
