#!/usr/bin/python3
"""Draws docs/measurement-geometry.svg: the angles `columba fit --spectra` and `columba bsdf` use.

Left, the plane of incidence seen from the side: theta from the vane normal, the light at theta_i,
its mirror direction at theta_i on the other side (phi_o = phi_i + 180), the retro direction back
along the light (phi_o = phi_i). Right, the vane seen from above: phi from the axis across the
barbules. Run: /usr/bin/python3 scripts/measurement-geometry.py [OUT.svg]
"""
import math
import sys

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.fonttype"] = "none"  # text stays text
matplotlib.rcParams["font.family"] = "DejaVu Sans"
import matplotlib.pyplot as plt  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "docs/measurement-geometry.svg"
theta = math.radians(30.0)
phi = math.radians(25.0)
light, mirror, retro = "#d4a000", "#1a9bb0", "#b03a2e"

fig, (side, top) = plt.subplots(1, 2, figsize=(10, 4.4))

# The plane of incidence, from the side.
side.plot([-1.3, 1.3], [0, 0], color="#7a6f5d", lw=3)
side.text(1.28, -0.12, "vane", ha="right", va="top")
side.annotate("", xy=(0, 1.25), xytext=(0, 0), arrowprops=dict(arrowstyle="-|>", color="#333"))
side.text(0.04, 1.25, "normal (theta = 0)", va="center")
lx, ly = -math.sin(theta), math.cos(theta)
side.annotate("", xy=(0, 0), xytext=(1.1 * lx, 1.1 * ly), arrowprops=dict(arrowstyle="-|>", color=light, lw=2))
side.text(1.15 * lx, 1.15 * ly, "light\n(theta_i, phi_i)", color=light, ha="center", va="bottom")
side.annotate("", xy=(1.1 * -lx, 1.1 * ly), xytext=(0, 0), arrowprops=dict(arrowstyle="-|>", color=mirror, lw=2))
side.text(1.15 * -lx, 1.15 * ly, "mirror direction\n(theta_i, phi_i + 180)", color=mirror, ha="center", va="bottom")
side.annotate("", xy=(0.75 * lx - 0.14, 0.75 * ly + 0.02), xytext=(-0.14, 0.02),
              arrowprops=dict(arrowstyle="-|>", color=retro, lw=1.5, ls="--"))
side.text(0.75 * lx - 0.2, 0.45 * ly, "retro\n(theta_i, phi_i)", color=retro, ha="right", va="center", fontsize=9)
arc = [math.radians(a) for a in range(0, 31)]
side.plot([-0.45 * math.sin(a) for a in arc], [0.45 * math.cos(a) for a in arc], color="#333", lw=1)
side.plot([0.45 * math.sin(a) for a in arc], [0.45 * math.cos(a) for a in arc], color="#333", lw=1)
side.text(-0.2, 0.5, "theta_i", ha="right")
side.text(0.2, 0.5, "theta_o", ha="left")
side.set_title("Side view: the plane of incidence")

# The vane from above.
for x in (-0.9, -0.45, 0.0, 0.45, 0.9):  # barbules run along y; phi = 0 points across them
    top.plot([x, x], [-1.0, 1.0], color="#c9bfae", lw=6, solid_capstyle="round", zorder=0)
top.text(-1.2, -1.2, "barbules (phi = 90 runs along them)", fontsize=9, color="#7a6f5d")
top.annotate("", xy=(1.25, 0), xytext=(0, 0), arrowprops=dict(arrowstyle="-|>", color="#333"))
top.text(1.27, 0.0, "phi = 0\n(across the\nbarbules)", va="center")
top.annotate("", xy=(0, 1.12), xytext=(0, 0), arrowprops=dict(arrowstyle="-|>", color="#333"))
top.text(0.05, 1.14, "phi = 90", va="center")
r = math.sin(theta) * 1.6
top.annotate("", xy=(0, 0), xytext=(r * math.cos(phi), r * math.sin(phi)),
             arrowprops=dict(arrowstyle="-|>", color=light, lw=2))
top.text(r * math.cos(phi), r * math.sin(phi) + 0.05, "light, phi_i", color=light, ha="center", va="bottom")
top.annotate("", xy=(-r * math.cos(phi), -r * math.sin(phi)), xytext=(0, 0),
             arrowprops=dict(arrowstyle="-|>", color=mirror, lw=2))
top.text(-r * math.cos(phi), -r * math.sin(phi) - 0.06, "mirror, phi_i + 180", color=mirror, ha="center", va="top")
arc = [phi * k / 20 for k in range(21)]
top.plot([0.35 * math.cos(a) for a in arc], [0.35 * math.sin(a) for a in arc], color="#333", lw=1)
top.text(0.42, 0.08, "phi_i", fontsize=9)
top.set_title("Top view: the vane, normal toward you")

for ax in (side, top):
    ax.set_aspect("equal")
    ax.axis("off")
side.set_xlim(-1.5, 1.5)
side.set_ylim(-0.5, 1.65)
top.set_xlim(-1.4, 1.7)
top.set_ylim(-1.3, 1.3)
fig.suptitle("Angles of columba fit --spectra and columba bsdf (degrees)", fontsize=12)
fig.tight_layout()
fig.savefig(out, metadata={"Date": None})
print("wrote", out)
