#!/usr/bin/env bash
# Renders the paper's figures with Columba's own scenes into out/figures/ and a contact sheet.
# QUALITY=draft renders small and fast; the default is full size.
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
columba="$build/columba"
out="$root/out/figures"
mkdir -p "$out"

if [ "${QUALITY:-final}" = draft ]; then
  vis=(-D res=256 -D spp=32); la=(-D res=256 -D spp=32); neck=(-D width=512 -D height=384 -D spp=16)
else
  vis=(-D res=512 -D spp=128); la=(-D res=512 -D spp=64); neck=(-D width=1024 -D height=768 -D spp=32)
fi

"$columba" feather --single --binary -o "$out/feather.ply"
"$columba" feather --neck --binary -o "$out/neck.ply"

# Every tile of the contact sheet is captioned with what it reproduces.
images=()
captions=()
declare -A visCaption=(
  [bsdf_visualization_normal]="Paper, 'Measurement': scatterometer image, light near the normal (emitter sampling)"
  [bsdf_visualization_oblique]="Paper, 'Measurement': scatterometer image, oblique light (emitter sampling)"
  [bsdf_visualization_sampled]="Paper, 'Measurement': scatterometer image under uniform light (BSDF sampling)")
for scene in bsdf_visualization_normal bsdf_visualization_oblique bsdf_visualization_sampled; do
  "$columba" render "$root/scenes/$scene.xml" "${vis[@]}" -o "$out/$scene.exr"
  images+=("$out/$scene.png")
  captions+=("${visCaption[$scene]}")
done
# The strip-light sequence is one sweep (la-10, la000, ..., la060); its manifest lists the frames.
"$columba" render "$root/scenes/feather_linear_light.xml" -D feather="$out/feather.ply" "${la[@]}" \
  --sweep angle=-10:60:10 --frames "$out/la{angle:03}.exr" --manifest "$out/strip_light.json"
while IFS=$'\t' read -r image angle; do
  images+=("$image")
  captions+=("Paper, 'Rendering': one feather under a strip light at $angle deg")
done < <(/usr/bin/python3 -c '
import json, sys
for frame in json.load(open(sys.argv[1]))["frames"]:
    print(frame["output"][:-len(".exr")] + ".png", frame["defines"]["angle"], sep="\t")' "$out/strip_light.json")
declare -A neckCaption=(
  [neck_omnidirectional]="Paper, 'Rendering' (b): neck under omnidirectional light"
  [neck_direction1]="Paper, 'Rendering' (c): neck under directional light, set-up 1"
  [neck_direction2]="Paper, 'Rendering' (d): neck under directional light, set-up 2")
for scene in neck_omnidirectional neck_direction1 neck_direction2; do
  "$columba" render "$root/scenes/$scene.xml" -D feathers="$out/neck.ply" "${neck[@]}" -o "$out/$scene.exr"
  images+=("$out/$scene.png")
  captions+=("${neckCaption[$scene]}")
done
# The barbule model's spectra: reflectance factor in the mirror direction and directional
# reflectance, for green and purple barbules.
for preset in dove-green dove-purple; do
  mkdir -p "$out/bsdf-$preset"
  "$columba" bsdf --preset "$preset" --mode specular,spectra -o "$out/bsdf-$preset" > "$out/bsdf-$preset/table.txt"
  images+=("$out/bsdf-$preset/bsdf_specular.png" "$out/bsdf-$preset/bsdf_spectra.png")
  captions+=("Barbule BSDF ($preset): reflectance factor in the mirror direction, light at 0-60 deg"
             "Barbule BSDF ($preset): directional reflectance of R and TRT, light at 0-60 deg")
done
printf '%s\n' "${captions[@]}" > "$out/captions.txt"
"$columba" montage -o "$out/contact_sheet.png" --columns 4 --tile 320 --labels "$out/captions.txt" \
  --title "Columba: the rock dove barbule BSDF, a feather and a neck, as in Huang et al. 2022" "${images[@]}"
echo "Figures in $out (contact sheet: $out/contact_sheet.png)"
