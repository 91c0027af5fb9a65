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

images=()
for scene in bsdf_visualization_normal bsdf_visualization_oblique bsdf_visualization_sampled; do
  "$columba" render "$root/scenes/$scene.xml" "${vis[@]}" -o "$out/$scene.exr"
  images+=("$out/$scene.png")
done
for angle in -10 0 10 20 30 40 50 60; do
  name=$(printf 'la%03d' "$angle")
  [ "$angle" -lt 0 ] && name="la$angle"
  "$columba" render "$root/scenes/feather_linear_light.xml" -D feather="$out/feather.ply" -D angle="$angle" \
    "${la[@]}" -o "$out/$name.exr"
  images+=("$out/$name.png")
done
for scene in neck_omnidirectional neck_direction1 neck_direction2; do
  "$columba" render "$root/scenes/$scene.xml" -D feathers="$out/neck.ply" "${neck[@]}" -o "$out/$scene.exr"
  images+=("$out/$scene.png")
done
"$columba" montage -o "$out/contact_sheet.png" --columns 4 --tile 320 \
  --title "Columba: rock dove barbule BSDF, feather and neck" "${images[@]}"
echo "Figures in $out (contact sheet: $out/contact_sheet.png)"
