#!/usr/bin/env bash
# The strip of docs/gallery/feather-colours.png ("Change a feather's colour" in docs/feather-ply.md):
# one generated feather at cortex thicknesses 0.45-0.70 um (`columba feather --height`) under the
# strip light of scenes/feather_linear_light.xml, each tile labelled with its thickness and the
# mean sRGB colour (at full brightness) of its most colourful 1 % of pixels.
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
columba="$build/columba"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

images=()
labels=()
for h in 0.45 0.50 0.55 0.60 0.65 0.70; do
  "$columba" feather --single --binary --height "$h" -o "$out/feather$h.ply" > /dev/null
  "$columba" render "$root/scenes/feather_linear_light.xml" -D feather="$out/feather$h.ply" -D angle=20 \
    -D res=160 -D spp=16 -o "$out/h$h.exr" > /dev/null
  colour=$(PYTHONPATH="$build/python" /usr/bin/python3 -c '
import sys, numpy as np, columba
rgb = columba.read_image(sys.argv[1]).reshape(-1, 3)
chroma = rgb.max(axis=1) - rgb.min(axis=1)
mean = rgb[chroma >= np.percentile(chroma, 99)].mean(axis=0)  # the feather, not the grey backplate
print("#%02x%02x%02x" % tuple(int(c) for c in columba.to_srgb(mean / mean.max())))' "$out/h$h.exr")
  images+=("$out/h$h.png")
  labels+=(--label "$h um: $colour")
done
mkdir -p "$root/docs/gallery"
"$columba" montage -o "$root/docs/gallery/feather-colours.png" --columns 6 --tile 160 \
  --title "One feather, cortex thickness 0.45-0.70 um" "${labels[@]}" "${images[@]}"
